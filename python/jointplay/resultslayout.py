"""The HDF5 objects of a NetCDF-4 results file, made with h5py's low-level API.

Written by ``Results.save(..., compress=True)``; a results file is otherwise NetCDF
classic (:mod:`jointplay.netcdf_classic`), which costs no HDF5 object per channel.

A NetCDF-4 file holds one HDF5 dataset per channel (NetCDF-4 has no other way to
give each channel its own variable), so what it costs to write is mostly what each
dataset costs: its object header, its link in the root group, its four attributes
(``units``, ``long_name``, ``description``, ``DIMENSION_LIST``) and its compressed
chunks. Here each of these is one call into HDF5 with property lists, types and
attribute values made once per file (h5py's high-level ``create_dataset`` and
``attrs[...] =`` rebuild them at every call: about three times the cost). The
``time`` dimension is fixed-size, its ``REFERENCE_LIST`` written once
(:meth:`FileLayout.close_with`).

What xarray (h5netcdf) and netCDF-C read is the NetCDF-4 data model on HDF5: a
dimension scale (``CLASS = "DIMENSION_SCALE"``, ``NAME``, ``_Netcdf4Dimid``)
referenced by each variable's ``DIMENSION_LIST`` (NetCDF-4 format specification,
https://docs.unidata.ucar.edu/netcdf-c/current/file_format_specifications.html,
"NetCDF-4 Format"; HDF5 Dimension Scale specification, H5DS).
"""

from __future__ import annotations

import os
from functools import lru_cache
from typing import Any

import numpy as np

#: Samples per HDF5 chunk of a compressed channel (32 KiB of float64).
CHUNK_SAMPLES = 4096
#: gzip level of a compressed file (``Results.save(..., compress=True)``), the cheapest.
GZIP_LEVEL = 1
#: HDF5 chunk cache of each compressed dataset while writing [bytes]: two chunks, so that memory stays
#: bounded (the default cache of 1 MiB per dataset ends up holding the whole file until closed).
_CHUNK_CACHE_BYTES = 2 * CHUNK_SAMPLES * 8


@lru_cache(maxsize=1)
def _h5():
    """The HDF5 types and spaces every file shares, made once (h5py imported on first use)."""
    import h5py

    text = h5py.h5t.py_create(h5py.string_dtype(), logical=True)  # variable-length UTF-8, as h5py writes str
    references = h5py.h5t.py_create(h5py.vlen_dtype(h5py.ref_dtype), logical=True)
    return h5py, text, references, h5py.h5s.create(h5py.h5s.SCALAR), h5py.h5s.create_simple((1,))


class FileLayout:
    """A NetCDF-4 results file being written at ``path`` (created, replacing any file there)."""

    def __init__(self, path: str | os.PathLike):
        h5py, _, _, _, _ = _h5()
        self._h5py = h5py
        order = h5py.h5p.CRT_ORDER_TRACKED | h5py.h5p.CRT_ORDER_INDEXED  # as h5py's track_order=True
        create = h5py.h5p.create(h5py.h5p.FILE_CREATE)
        create.set_link_creation_order(order)
        create.set_attr_creation_order(order)
        access = h5py.h5p.create(h5py.h5p.FILE_ACCESS)
        # HDF5 1.8 object headers (as netCDF-C writes): attributes beyond 64 KiB (the reference list of
        # more than 5461 channels) go to dense storage
        access.set_libver_bounds(h5py.h5f.LIBVER_V18, h5py.h5f.LIBVER_LATEST)
        cache = access.get_cache()
        access.set_cache(cache[0], cache[1], _CHUNK_CACHE_BYTES, cache[3])
        access.set_fclose_degree(h5py.h5f.CLOSE_STRONG)  # closing the file closes its variables too
        self.id = h5py.h5f.create(os.fsencode(path), h5py.h5f.ACC_TRUNC, fcpl=create, fapl=access)
        self._texts: dict[str, np.ndarray] = {}

    # channels ------------------------------------------------------------------

    def channels(self, names: list[str], attributes: list[list[tuple[str, str]]], samples: int) -> list:
        """One float64 variable of ``samples`` values per name on ``time``, with its text attributes (name,
        value) in order, chunked and compressed (gzip after shuffle). Their ``DIMENSION_LIST`` is written by
        :meth:`close_with`."""
        h5py = self._h5py
        properties = h5py.h5p.create(h5py.h5p.DATASET_CREATE)
        properties.set_fill_time(h5py.h5d.FILL_TIME_NEVER)  # every value is written
        properties.set_obj_track_times(False)  # no modification times, as h5py writes
        if samples:  # (HDF5 refuses a chunk longer than a fixed dimension, so an empty variable is contiguous)
            properties.set_chunk((min(CHUNK_SAMPLES, samples),))
            properties.set_shuffle()
            properties.set_deflate(GZIP_LEVEL)
        space = h5py.h5s.create_simple((samples,), (samples,))
        float64 = h5py.h5t.IEEE_F64LE
        made = []
        for name, attrs in zip(names, attributes):
            dataset = h5py.h5d.create(self.id, name.encode(), float64, space, dcpl=properties)
            for key, value in attrs:
                self.text_attribute(dataset, key, value)
            made.append(dataset)
        return made

    def write(self, datasets: list, start: int, rows: np.ndarray) -> None:
        """Writes ``rows[k]`` (one row per dataset, float64) at samples ``start:start + n`` of each."""
        h5py = self._h5py
        n = rows.shape[1]
        if n == 0:
            return
        memory = h5py.h5s.create_simple((n,))
        rows = np.ascontiguousarray(rows, dtype=np.float64)  # one transposing copy of a (samples, channels) view
        for dataset, row in zip(datasets, rows):
            space = dataset.get_space()
            space.select_hyperslab((start,), (n,))
            dataset.write(memory, space, row)

    def text_attribute(self, target, key: str, value: str) -> None:
        """A scalar variable-length UTF-8 string attribute (what h5py writes for a Python ``str``)."""
        _, text, _, scalar, _ = _h5()
        array = self._texts.get(value)
        if array is None:
            array = self._texts[value] = np.array(value, dtype=self._h5py.string_dtype())
        self._h5py.h5a.create(target, key.encode(), text, scalar).write(array)

    # time and the dimension ------------------------------------------------------

    def time(self, times: np.ndarray, attributes: list[tuple[str, str]]):
        """The coordinate and dimension ``time`` [s], fixed-size (an unlimited one makes readers slow)."""
        h5py = self._h5py
        n = times.size
        space = h5py.h5s.create_simple((n,), (n,))
        properties = h5py.h5p.create(h5py.h5p.DATASET_CREATE)
        properties.set_layout(h5py.h5d.CONTIGUOUS)
        properties.set_obj_track_times(False)
        dataset = h5py.h5d.create(self.id, b"time", h5py.h5t.IEEE_F64LE, space, dcpl=properties)
        if n:
            dataset.write(h5py.h5s.ALL, h5py.h5s.ALL, np.ascontiguousarray(times, dtype=np.float64))
        for key, value in attributes:
            self.text_attribute(dataset, key, value)
        h5py.h5ds.set_scale(dataset, b"time")
        dimension_id = h5py.h5a.create(dataset, b"_Netcdf4Dimid", h5py.h5t.STD_I32LE, _h5()[3])
        dimension_id.write(np.array(0, dtype=np.int32))
        return dataset

    def close_with(self, time, datasets: list, attrs: dict[str, Any]) -> None:
        """Writes the ``DIMENSION_LIST`` of every variable and the ``REFERENCE_LIST`` of ``time``, each
        written once (h5py's ``attach_scale`` rewrites the reference list at every call), then the global
        attributes (``attrs``, of the types h5py gives their values), and closes the file."""
        h5py, _, references, _, one = _h5()
        time_reference = h5py.h5r.create(self.id, b"time", h5py.h5r.OBJECT)
        dimension_list = np.empty((1,), dtype=object)
        dimension_list[0] = np.array([time_reference], dtype=h5py.ref_dtype)
        for dataset in datasets:
            h5py.h5a.create(dataset, b"DIMENSION_LIST", references, one).write(dimension_list)
        if datasets:
            listed = np.empty(len(datasets), dtype=[("dataset", h5py.ref_dtype), ("dimension", np.int32)])
            listed["dataset"] = [h5py.h5r.create(dataset, b".", h5py.h5r.OBJECT) for dataset in datasets]
            listed["dimension"] = 0
            h5py.AttributeManager(h5py.Dataset(time)).create("REFERENCE_LIST", listed)
        root = h5py.h5g.open(self.id, b"/")
        for key, value in attrs.items():
            self.attribute(root, key, value)
        self.close()

    def attribute(self, target, key: str, value: Any) -> None:
        """An attribute of the type h5py gives a Python value: a text, a number, an array of numbers."""
        if isinstance(value, str):
            self.text_attribute(target, key, value)
            return
        h5py = self._h5py
        array = np.asarray(value)
        if array.dtype.kind not in "biuf":
            h5py.AttributeManager(h5py.Group(target) if isinstance(target, h5py.h5g.GroupID)
                                  else h5py.Dataset(target))[key] = value
            return
        space = _h5()[3] if array.ndim == 0 else h5py.h5s.create_simple(array.shape)
        kind = h5py.h5t.py_create(array.dtype)
        h5py.h5a.create(target, key.encode(), kind, space).write(np.ascontiguousarray(array), mtype=kind)

    def close(self) -> None:
        """Closes the file (whatever was written stays as it is)."""
        if self.id.valid:
            self.id.close()
