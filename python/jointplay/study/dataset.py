"""The study's result: one xarray Dataset with a ``case`` dimension, and its NetCDF file.

Coordinates: ``case``; one per factor (SI values, attributes ``units``, ``path``, ``long_name``;
a discrete factor's level names in ``<factor>_label``); ``factor`` (names) and ``time`` (the grid of the
kept channels). Variables: ``coded`` (case, factor); one per response (NaN where the case failed);
``status`` ("done" or "failed") and ``error`` (one line, "" when done); ``steps`` (accepted) and
``rhs_evaluations`` of each run; each kept channel (case, time). Attributes: the study's name, model,
design, seed and jointplay version. Timings are not in it: the Dataset is the same to the last bit
however and wherever its cases ran.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from .worker import DONE


def assemble(study, records: list[dict]):
    """The Dataset of ``study`` from its cases' records (in case order)."""
    import xarray as xr

    from .. import __version__

    n = len(records)
    coords = {"case": ("case", np.arange(n, dtype=np.int32)),
              "factor": ("factor", np.array([f.name for f in study.factors], dtype=str))}
    for j, f in enumerate(study.factors):
        coords[f.name] = ("case", study.values[:, j].copy(),
                          {"units": f.units, "path": f.path, "long_name": f.description or f.path})
        if f.discrete and f.labels:
            coords[f"{f.name}_label"] = ("case", np.array([f.label(v) for v in study.values[:, j]], dtype=str))
    data = {"coded": (("case", "factor"), study.coded.copy(), {"long_name": "design point in coded units "
                                                                            "(range low -1, high +1)"})}
    units = _response_units(study, records)
    for r in study.responses:
        values = np.array([rec["responses"].get(r.name, np.nan) for rec in records], dtype=np.float64)
        data[r.name] = ("case", values, {"units": units.get(r.name, ""), "long_name": r.name,
                                         "definition": r.definition})
    data["status"] = ("case", np.array([rec["status"] for rec in records], dtype=str))
    data["error"] = ("case", np.array([rec["error"] for rec in records], dtype=str))
    data["steps"] = ("case", np.array([rec["steps"] for rec in records], dtype=np.int32))
    data["rhs_evaluations"] = ("case", np.array([rec["rhs_evaluations"] for rec in records], dtype=np.int32))
    if study.channels:
        coords["time"] = ("time", np.asarray(study.grid, dtype=float), {"units": "s"})
        for name in study.channels:
            block = np.full((n, len(study.grid)), np.nan)
            for k, rec in enumerate(records):
                if name in rec["channels"]:
                    block[k] = rec["channels"][name]
            data[name] = (("case", "time"), block, {"long_name": name})
    attrs = {"study": study.name, "model": study.model_source, "design": json.dumps(study.design_spec),
             "seed": study.seed, "t_end": study.t_end, "jointplay_version": __version__,
             "factors": json.dumps([f.to_dict() for f in study.factors])}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _response_units(study, records: list[dict]) -> dict[str, str]:
    """Each response's units as its first finished case found them (a channel's unit is the run's)."""
    for rec in records:
        if rec["status"] == DONE and rec.get("units"):
            return dict(rec["units"])
    return {r.name: getattr(r, "units", "") or "" for r in study.responses}


def save(dataset, path: str | Path) -> Path:
    """The study's Dataset as NetCDF (classic 64-bit offset format, written the same to the last byte every
    time), through a temporary name so that a file at ``path`` is always whole."""
    import os

    path = Path(path)
    temporary = path.with_suffix(".nc.tmp")
    dataset.to_netcdf(temporary, engine="scipy", format="NETCDF3_64BIT")
    os.replace(temporary, path)
    return path


def open_study(path: str | Path):
    """A study's Dataset from its NetCDF file (or the folder holding ``study.nc``)."""
    import xarray as xr

    path = Path(path)
    if path.is_dir():
        path = path / "study.nc"
    with xr.open_dataset(path, engine="scipy") as ds:
        return ds.load()
