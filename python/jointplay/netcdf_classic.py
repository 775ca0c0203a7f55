"""NetCDF classic files in the 64-bit offset variant (CDF-2): the header, records written in bulk, read back.

The format is Unidata's "NetCDF Classic and 64-bit Offset File Format"
(NetCDF Users Guide, "NetCDF File Format", https://docs.unidata.ucar.edu/nug/2.0-draft/nc3_file_formats.html;
the same BNF grammar in netCDF-C's ``docs/file_format_specifications.md``)::

    netcdf_file = header data
    header      = magic numrecs dim_list gatt_list var_list
    magic       = 'C' 'D' 'F' '\\x02'                  (64-bit offset format)
    numrecs     = NON_NEG | STREAMING                  (length of the record dimension)
    dim_list    = ABSENT | NC_DIMENSION nelems [dim ...]       dim  = name dim_length (0: the record dimension)
    gatt_list   = att_list                             att  = name nc_type nelems [values ...]
    var_list    = ABSENT | NC_VARIABLE nelems [var ...]        var  = name nelems [dimid ...] vatt_list
                                                                      nc_type vsize begin
    name        = nelems namestring                    (UTF-8, padded with zero bytes to 4)
    begin       = OFFSET                               (64 bits in CDF-2, 32 in CDF-1)

big-endian throughout; NON_NEG and nelems are 32-bit. Every variable here is a
*record variable* of 64-bit floats on the record (unlimited) dimension ``time``:
record k holds the k-th value of every variable, one after the other, so a block of
samples is one contiguous (samples x variables) big-endian array on disk, written
with one call. What the format limits (NetCDF Users Guide, "The 64-bit Offset
Format" and "Limitations of the 64-bit Offset Format"): one record's worth of each
record variable below 4 GiB (8 bytes here) and at most 2^32 - 1 records, the count
``0xFFFFFFFF`` meaning STREAMING (unknown): :data:`MAX_RECORDS`.

The data begin at an offset chosen by :func:`data_begin`: after the header and a
reserve of free space (as netCDF-C's ``h_minfree``), so that attributes known only at
the end of a run (statistics, summary, error) fit into the header written again in
place; a header that outgrows it moves the data once (:meth:`RecordFile.finish`).
"""

from __future__ import annotations

import mmap
import os
import struct
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

#: First four bytes of a CDF-2 file (of a CDF-1 file: ``CDF\x01``).
MAGIC = b"CDF\x02"
MAGICS = (b"CDF\x01", MAGIC)
NC_DIMENSION, NC_VARIABLE, NC_ATTRIBUTE = 10, 11, 12
NC_BYTE, NC_CHAR, NC_SHORT, NC_INT, NC_FLOAT, NC_DOUBLE = 1, 2, 3, 4, 5, 6
#: Big-endian numpy type of each external type.
_TYPES = {NC_BYTE: ">i1", NC_CHAR: "S1", NC_SHORT: ">i2", NC_INT: ">i4", NC_FLOAT: ">f4", NC_DOUBLE: ">f8"}
ABSENT = b"\x00" * 8
STREAMING = 0xFFFFFFFF
#: Most records a CDF-2 file counts (``numrecs`` is 32 bits and ``0xFFFFFFFF`` means STREAMING).
MAX_RECORDS = STREAMING - 1
#: The data begin at a multiple of this many bytes (a page: each block of records starts page-aligned).
ALIGN = 4096
_INT32 = (-(2**31), 2**31 - 1)


def _padded(raw: bytes) -> bytes:
    return raw + b"\x00" * (-len(raw) % 4)


def encode_name(text: str) -> bytes:
    """``name``: its length in bytes, then its UTF-8 bytes padded to 4."""
    raw = text.encode("utf-8")
    return struct.pack(">I", len(raw)) + _padded(raw)


def attribute_values(value: Any) -> tuple[int, int, bytes]:
    """(nc_type, nelems, padded big-endian values) of an attribute: a text as NC_CHAR (UTF-8 bytes), an
    integer (or a bool, or an array of them) as NC_INT when every value fits 32 bits, else as NC_DOUBLE
    (exact below 2^53: CDF-2 has no 64-bit integers), a float or an array of floats as NC_DOUBLE. An
    empty array is NC_INT with no values."""
    if isinstance(value, str):
        raw = value.encode("utf-8")
        return NC_CHAR, len(raw), _padded(raw)
    array = np.atleast_1d(np.asarray(value))
    if array.dtype.kind in "biu" or array.size == 0:
        ints = array.astype(np.int64)
        if array.size == 0 or (ints.min() >= _INT32[0] and ints.max() <= _INT32[1]):
            return NC_INT, array.size, ints.astype(">i4").tobytes()
    if array.dtype.kind not in "biuf":
        raise TypeError(f"a NetCDF classic attribute is a text or numbers, got {value!r}")
    return NC_DOUBLE, array.size, array.astype(">f8").tobytes()


def encode_attributes(attributes: list[tuple[str, Any]] | dict[str, Any]) -> bytes:
    """``att_list``: ABSENT, or NC_ATTRIBUTE, their count and each attribute."""
    items = list(attributes.items()) if isinstance(attributes, dict) else list(attributes)
    if not items:
        return ABSENT
    parts = [struct.pack(">II", NC_ATTRIBUTE, len(items))]
    for key, value in items:
        kind, count, values = attribute_values(value)
        parts += [encode_name(key), struct.pack(">II", kind, count), values]
    return b"".join(parts)


@dataclass
class Layout:
    """What a header says: record count, dimensions, global attributes and variables (with their
    ``begin`` offsets and ``vsize``), and the header's own length [bytes]."""

    version: int
    numrecs: int
    dimensions: list[tuple[str, int]]
    attributes: dict[str, Any]
    variables: dict[str, dict] = field(default_factory=dict)
    header_bytes: int = 0

    @property
    def record_bytes(self) -> int:
        """Bytes of one record: the ``vsize`` of every record variable."""
        return sum(v["vsize"] for v in self.variables.values() if v["record"])


class RecordHeader:
    """The header of a file whose variables are float64 record variables on the dimension ``time``
    (the first one is ``time`` itself): the variables' part encoded once, the global attributes and
    the data's offset given at each :meth:`encode`."""

    def __init__(self, names: list[str], attributes: list[list[tuple[str, Any]]]):
        self.count = len(names)
        parts = []
        for name, attrs in zip(names, attributes):
            # name, one dimension (id 0, the record dimension), attributes, NC_DOUBLE, vsize = 8
            parts.append(encode_name(name) + struct.pack(">II", 1, 0) + encode_attributes(attrs)
                         + struct.pack(">II", NC_DOUBLE, 8))
        self._variables = parts
        self._dimensions = struct.pack(">II", NC_DIMENSION, 1) + encode_name("time") + struct.pack(">I", 0)
        self._fixed = 8 + len(self._dimensions) + 8 + sum(len(p) + 8 for p in parts)

    @property
    def record_bytes(self) -> int:
        return 8 * self.count

    def length(self, attributes: bytes) -> int:
        """Bytes of the header with the encoded global ``attributes``."""
        return self._fixed + len(attributes)

    def encode(self, numrecs: int, attributes: bytes, begin: int) -> bytes:
        """The header: ``numrecs`` records, global ``attributes`` (from :func:`encode_attributes`), data at
        ``begin`` (variable k of each record at ``begin + 8 k``)."""
        parts = [MAGIC, struct.pack(">I", numrecs), self._dimensions, attributes,
                 struct.pack(">II", NC_VARIABLE, self.count)]
        for k, variable in enumerate(self._variables):
            parts += [variable, struct.pack(">Q", begin + 8 * k)]
        return b"".join(parts)


def data_begin(planned_header: int, header: int, reserve: int) -> int:
    """Where the data begin [bytes]: after the header of what is known when the file is made
    (``planned_header`` bytes) and ``reserve`` bytes of room, page-aligned; or, when the final
    header (``header`` bytes) outgrows that, right after it, page-aligned. A streamed file and a
    saved one of the same content get the same offset."""
    planned = _round_up(planned_header + reserve, ALIGN)
    return planned if header <= planned else _round_up(header, ALIGN)


def _round_up(n: int, step: int) -> int:
    return -(-n // step) * step


def records(times: np.ndarray, values: np.ndarray, buffer: np.ndarray | None = None) -> np.ndarray:
    """Records of ``len(times)`` samples: time, then every channel (``values`` is (samples, channels)),
    big-endian float64, one contiguous array: the first rows of ``buffer`` ((rows, 1 + channels),
    ``>f8``, reused from block to block so that no fresh memory is touched) when it is long enough."""
    n = times.size
    if buffer is None or buffer.shape[0] < n:
        buffer = np.empty((n, 1 + values.shape[1]), dtype=">f8")
    out = buffer[:n]
    out[:, 0] = times
    out[:, 1:] = values
    return out


def write_all(fd: int, data, offset: int) -> None:
    """Writes every byte of ``data`` at ``offset`` (``os.pwrite`` may write less than asked)."""
    view = memoryview(data).cast("B")
    while view.nbytes:
        written = os.pwrite(fd, view, offset)
        view, offset = view[written:], offset + written


class RecordFile:
    """A CDF-2 file of record variables being written at ``path`` (created, replacing any file):
    the header at once with ``provisional`` global attributes and room for the final ones,
    :meth:`append` block after block (``numrecs`` updated after each, so that a file cut after a
    block reads up to it), :meth:`finish` with the final global attributes."""

    def __init__(self, path: str | os.PathLike, header: RecordHeader, provisional: dict[str, Any], reserve: int):
        self.path = Path(path)
        self.header = header
        self._planned = header.length(encode_attributes(provisional))
        self.reserve = reserve
        self.begin = data_begin(self._planned, self._planned, reserve)
        self.numrecs = 0
        self.moved = False
        self.fd = os.open(self.path, os.O_RDWR | os.O_CREAT | os.O_TRUNC, 0o666)
        try:
            write_all(self.fd, self.header.encode(0, encode_attributes(provisional), self.begin).ljust(
                self.begin, b"\x00"), 0)
        except BaseException:
            self.close()
            raise

    def append(self, block: np.ndarray) -> None:
        """Writes ``block`` (records, from :func:`records`) after the last one, then the new count."""
        n = block.shape[0]
        if self.numrecs + n > MAX_RECORDS:
            raise ValueError(too_many_records(self.numrecs + n))
        if n:
            write_all(self.fd, block, self.begin + self.numrecs * self.header.record_bytes)
            self.numrecs += n
            write_all(self.fd, struct.pack(">I", self.numrecs), 4)

    def finish(self, attributes: dict[str, Any]) -> None:
        """Writes the final header (``attributes`` global) in place when it fits before the data, else
        moves the data once to just after it (:func:`data_begin`), and closes the file."""
        encoded = encode_attributes(attributes)
        begin = data_begin(self._planned, self.header.length(encoded), self.reserve)
        if begin != self.begin:
            self._move_data(begin)
            self.moved = True
        write_all(self.fd, self.header.encode(self.numrecs, encoded, begin).ljust(begin, b"\x00"), 0)
        self.close()

    def _move_data(self, begin: int, chunk: int = 16 * 2**20) -> None:
        """Moves the records from :attr:`begin` to ``begin`` (later in the file), last chunk first."""
        size = self.numrecs * self.header.record_bytes
        end = size
        while end > 0:
            start = max(0, end - chunk)
            data = os.pread(self.fd, end - start, self.begin + start)
            write_all(self.fd, data, begin + start)
            end = start
        self.begin = begin

    def close(self) -> None:
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1


def too_many_records(n: int) -> str:
    return (f"{n} samples are more than a NetCDF classic (64-bit offset) file holds ({MAX_RECORDS}, the "
            "largest record count of the format)")


def write_records_file(path: str | os.PathLike, header: RecordHeader, provisional: dict[str, Any], reserve: int,
                       attributes: dict[str, Any], n: int, blocks) -> None:
    """Writes a whole file: the final header (``attributes``, ``n`` records), then every block of records
    ``blocks`` yields, in order; the same bytes as a :class:`RecordFile` given the same content."""
    if n > MAX_RECORDS:
        raise ValueError(too_many_records(n))
    encoded = encode_attributes(attributes)
    begin = data_begin(header.length(encode_attributes(provisional)), header.length(encoded), reserve)
    fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_TRUNC, 0o666)
    try:
        write_all(fd, header.encode(n, encoded, begin).ljust(begin, b"\x00"), 0)
        offset = begin
        for block in blocks:
            write_all(fd, block, offset)
            offset += block.nbytes
    finally:
        os.close(fd)


# reading -------------------------------------------------------------------------

def is_classic(path: str | os.PathLike) -> bool:
    """Whether ``path`` starts as a NetCDF classic file (CDF-1 or CDF-2)."""
    with open(path, "rb") as f:
        return f.read(4) in MAGICS


class _Reader:
    """Reads a header from the bytes of a file (a memory map), checking each length against the file."""

    def __init__(self, data, path):
        self.data, self.at, self.path = data, 0, path

    def take(self, n: int) -> bytes:
        if n < 0 or self.at + n > len(self.data):
            raise ValueError(f"the NetCDF header of {self.path} ends before its declared content")
        out = self.data[self.at:self.at + n]
        self.at += n
        return out

    def uint(self) -> int:
        return struct.unpack(">I", self.take(4))[0]

    def name(self) -> str:
        n = self.uint()
        raw = self.take(n)
        self.take(-n % 4)
        return raw.decode("utf-8")

    def attributes(self) -> dict[str, Any]:
        tag, count = self.uint(), self.uint()
        if tag == 0 and count == 0:
            return {}
        if tag != NC_ATTRIBUTE:
            raise ValueError(f"{self.path} has no attribute list where its NetCDF header needs one")
        out = {}
        for _ in range(count):
            key = self.name()
            kind, n = self.uint(), self.uint()
            if kind not in _TYPES:
                raise ValueError(f"attribute {key!r} of {self.path} has an unknown NetCDF type {kind}")
            size = n * np.dtype(_TYPES[kind]).itemsize
            raw = self.take(size)
            self.take(-size % 4)
            if kind == NC_CHAR:
                out[key] = raw.rstrip(b"\x00").decode("utf-8", "replace")
            else:
                values = np.frombuffer(raw, dtype=_TYPES[kind]).astype(_TYPES[kind][1:])
                out[key] = values[0].item() if n == 1 else values.tolist()
        return out


def read_layout(path: str | os.PathLike) -> Layout:
    """The header of a CDF-1 or CDF-2 file. A count of records of STREAMING (unknown) is taken from the
    file's length; so is a count beyond what the file holds (a file cut short)."""
    with open(path, "rb") as f:
        size = os.fstat(f.fileno()).st_size
        if size < 8:
            raise ValueError(f"{path} is too short for a NetCDF file")
        with mmap.mmap(f.fileno(), 0, access=mmap.ACCESS_READ) as data:
            reader = _Reader(data, path)
            magic = reader.take(4)
            if magic not in MAGICS:
                raise ValueError(f"{path} is not a NetCDF classic file")
            version = magic[3]
            numrecs = reader.uint()
            tag, count = reader.uint(), reader.uint()
            if tag not in (0, NC_DIMENSION) or (tag == 0 and count):
                raise ValueError(f"{path}: the NetCDF header has no dimension list")
            dimensions = [(reader.name(), reader.uint()) for _ in range(count)]
            attributes = reader.attributes()
            tag, count = reader.uint(), reader.uint()
            if tag not in (0, NC_VARIABLE) or (tag == 0 and count):
                raise ValueError(f"{path}: the NetCDF header has no variable list")
            variables = {}
            for _ in range(count):
                name = reader.name()
                dimids = [reader.uint() for _ in range(reader.uint())]
                if any(d >= len(dimensions) for d in dimids):
                    raise ValueError(f"variable {name!r} of {path} names a dimension the file does not have")
                attrs = reader.attributes()
                kind, vsize = reader.uint(), reader.uint()
                begin = struct.unpack(">Q" if version == 2 else ">I", reader.take(8 if version == 2 else 4))[0]
                record = bool(dimids) and dimensions[dimids[0]][1] == 0
                shape = [dimensions[d][1] for d in dimids]
                variables[name] = {"dims": [dimensions[d][0] for d in dimids], "shape": shape, "attrs": attrs,
                                   "type": kind, "vsize": vsize, "begin": begin, "record": record}
            layout = Layout(version, numrecs, dimensions, attributes, variables, reader.at)
    recsize = layout.record_bytes
    if recsize:
        begin = min((v["begin"] for v in variables.values() if v["record"]), default=0)
        held = max(0, size - begin) // recsize
        layout.numrecs = held if numrecs == STREAMING else min(numrecs, held)
    return layout
