"""Results files: NetCDF classic (CDF-2) by default, NetCDF-4 (HDF5) compressed on request, streamed
while a run goes on, and CSV.

The NetCDF file holds a ``time`` dimension and coordinate and one variable per
channel on it (``units``, ``long_name``, ``description``) and CF-style global
attributes. It is written under a temporary name in the target folder and
renamed into place only when it is complete, so that a good file is never
replaced by a broken one; a run that stopped early goes to ``OUT.partial.nc``
instead (see :func:`partial_path`).

Why NetCDF classic by default: NetCDF-4 gives each channel an HDF5 dataset, and
HDF5 costs 0.1-0.2 ms to make one with its attributes, about as much as the dry
slider-crank takes to compute its 8196 samples for 53 channels. A classic file is
a header then the values; with ``time`` the record dimension, a block of samples is
one contiguous array written with one call (:mod:`jointplay.netcdf_classic`), and a
streamed file is the same as a saved one. ``compress=True`` writes NetCDF-4 with
gzip (:mod:`jointplay.resultslayout`), smaller and slower.
"""

from __future__ import annotations

import contextlib
import math
import os
import queue
import threading
from time import sleep
import re
import secrets
from pathlib import Path
from collections.abc import Callable
from typing import Any

import numpy as np

#: Suffixes written as NetCDF-4 and as CSV.
NETCDF_SUFFIXES = (".nc", ".nc4", ".h5")
CSV_SUFFIX = ".csv"
#: Largest output of a run with a results file, samples x channels x 8 [bytes] (uncompressed).
DEFAULT_MAX_FILE_BYTES = 2 * 1024**3
#: Largest output of a run kept in memory (no results file) [bytes].
DEFAULT_MAX_MEMORY_BYTES = 1024**3
#: Marks the NetCDF-4 files written by this module (``Results.save(..., compress=True)``; ``open_results``
#: reads files without a mark with xarray): v3 stores the channels uncompressed or gzip-compressed, v2
#: compressed them in chunks.
LAYOUT = "jointplay-netcdf4-v3"
#: Marks the NetCDF classic (CDF-2) files written by this module, the default: every channel a record
#: variable on the record dimension ``time`` (:mod:`jointplay.netcdf_classic`).
CLASSIC_LAYOUT = "jointplay-cdf2-v1"
#: Layouts whose channels :func:`~jointplay.results.open_results` reads on access (one variable per channel).
LAYOUTS_READ_ON_ACCESS = ("jointplay-netcdf4-v2", LAYOUT, CLASSIC_LAYOUT)
#: Global attributes of a streamed file until its run ends (a file whose writer was killed keeps them).
PROVISIONAL_ATTRIBUTES = {"Conventions": "CF-1.10", "jointplay_layout": CLASSIC_LAYOUT, "completed": 0,
                          "error": "the run did not finish: the file holds the samples written before it stopped"}
#: Largest block of samples read at once when results are copied [bytes].
_BUFFER_BYTES = 64 * 2**20
#: Largest block of records a save converts to big-endian and writes at once [bytes].
_RECORD_BLOCK_BYTES = 2**20
#: Wait between two looks at the writer's queue while a chunk is already waiting [s].
_QUEUE_POLL = 0.002

_SIZE = re.compile(r"^\s*(\d+(?:\.\d*)?|\.\d+)\s*([kKMGT]i?B|B)?\s*$")
_FACTORS = {None: 1, "B": 1, "kB": 10**3, "MB": 10**6, "GB": 10**9, "TB": 10**12,
            "kiB": 2**10, "KiB": 2**10, "MiB": 2**20, "GiB": 2**30, "TiB": 2**40}


#: Largest size the core counts (an unsigned 64-bit number of bytes).
MAX_SIZE = 2**64 - 1


def parse_size(raw: Any) -> int:
    """A number of bytes from a whole number or a string such as ``"500 MB"`` or ``"2 GiB"``;
    raises ValueError naming the value."""
    if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
        raise ValueError(f'must be a size in bytes, e.g. 2147483648 or "2 GiB", got {raw!r}')
    if isinstance(raw, (int, float)):
        if not (np.isfinite(raw) and raw > 0):
            raise ValueError(f"must be a size > 0 bytes, got {raw!r}")
        return _at_most_max(int(raw), raw)
    match = _SIZE.match(raw) if len(raw) < 40 else None
    if match is None or match.group(2) not in _FACTORS:
        raise ValueError(f'must be a size such as "500 MB" or "2 GiB" (units B, kB, MB, GB, TB, KiB, MiB, GiB, '
                         f"TiB), got {raw!r}")
    value = int(float(match.group(1)) * _FACTORS[match.group(2)])
    if value <= 0:
        raise ValueError(f"must be a size > 0 bytes, got {raw!r}")
    return _at_most_max(value, raw)


def _at_most_max(value: int, raw: Any) -> int:
    if value > MAX_SIZE:
        raise ValueError(f"must be at most 2^64 - 1 bytes (16 EiB, the largest size the core counts), got {raw!r}")
    return value


def format_size(n: float) -> str:
    """``2147483648`` -> ``"2 GiB"``; ``4.2e9`` -> ``"3.91 GiB"``."""
    for unit, factor in (("TiB", 2**40), ("GiB", 2**30), ("MiB", 2**20), ("KiB", 2**10)):
        if n >= factor:
            return f"{n / factor:.3g} {unit}"
    return f"{int(n)} B"


def partial_path(path: str | os.PathLike) -> Path:
    """Where the results of a run that stopped early go: ``out.nc`` -> ``out.partial.nc``."""
    path = Path(path)
    return path.with_name(f"{path.stem}.partial{path.suffix}")


def temporary_path(path: str | os.PathLike) -> Path:
    """A fresh hidden name in the folder of ``path``, unique to this writer."""
    path = Path(path)
    return path.with_name(f".{path.name}.{os.getpid()}-{secrets.token_hex(4)}.tmp")


#: Exit status of a run stopped by SIGTERM while it wrote a file (128 + 15, as a shell reports it).
TERMINATED_STATUS = 143


@contextlib.contextmanager
def terminate_as_exit():
    """While a file is written: SIGTERM (``kill``, a batch system's time limit) raises
    ``SystemExit(143)`` in the main thread instead of ending the process at once, so that the writer
    removes its temporary file on the way out (a running simulation sees it within its watch interval).
    Nothing changes outside the main thread or when the program has a SIGTERM handler of its own."""
    import signal

    if threading.current_thread() is not threading.main_thread() or signal.getsignal(signal.SIGTERM) != signal.SIG_DFL:
        yield
        return

    def terminate(_signum, _frame):
        raise SystemExit(TERMINATED_STATUS)

    previous = signal.signal(signal.SIGTERM, terminate)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def remove_stale_temporaries(path: str | os.PathLike) -> list[Path]:
    """Removes the temporary files of ``path`` (hidden ``.NAME.PID-<8 hex digits>.tmp`` beside it, see
    :func:`temporary_path`) whose writing process is gone: killed with SIGKILL, or the machine stopped.
    Returns what was removed."""
    path = Path(path)
    pattern = re.compile(rf"^\.{re.escape(path.name)}\.(\d+)-[0-9a-f]{{8}}\.tmp$")
    try:
        entries = list(path.parent.iterdir())
    except OSError:
        return []
    removed = []
    for entry in entries:
        match = pattern.match(entry.name)
        if match and not _process_alive(int(match.group(1))):
            with contextlib.suppress(OSError):
                entry.unlink()
                removed.append(entry)
    return removed


def _process_alive(pid: int) -> bool:
    """Whether a process ``pid`` exists (True when that cannot be told)."""
    if pid == os.getpid() or os.name != "posix":
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:
        return True
    return True


def output_kind(path: str | os.PathLike) -> str:
    """``"netcdf"`` or ``"csv"`` from the suffix; ValueError for any other suffix."""
    suffix = Path(path).suffix.lower()
    if suffix in NETCDF_SUFFIXES:
        return "netcdf"
    if suffix == CSV_SUFFIX:
        return "csv"
    raise ValueError(f"unknown results format {suffix or '(no suffix)'!r}: use .nc, .nc4 or .h5 for NetCDF, "
                     ".csv for CSV")


def output_target(path: str | os.PathLike) -> str:
    """The format (``"netcdf"`` or ``"csv"``) of a results file to be written at ``path``, checked first: a
    known suffix, a folder that exists, not a folder itself. Raises ModelError located at the user's path."""
    from .errors import ModelError

    target = Path(path)
    if target.is_dir():
        raise ModelError([(str(path), "is a folder, not a results file (give a file name such as run.nc)")])
    try:
        kind = output_kind(target)
    except ValueError as exc:
        raise ModelError([(str(path), str(exc))]) from None
    folder = target.parent
    if not folder.is_dir():
        what = "is a file, not a folder" if folder.exists() else "does not exist"
        raise ModelError([(str(path), f"cannot write the results: the folder {str(folder)!r} {what}")])
    if not os.access(folder, os.W_OK | os.X_OK):
        raise ModelError([(str(path), f"cannot write the results: no permission to write into {str(folder)!r}")])
    return kind


def results_source(path: str | os.PathLike) -> Path:
    """``path`` checked before it is read as a results file: an existing NetCDF classic or HDF5 (NetCDF-4)
    file. Raises ModelError located at the user's path (a TOML model file, a CSV file, a folder each get a
    message)."""
    import h5py

    from .errors import ModelError
    from .netcdf_classic import is_classic

    source = Path(path)
    if source.is_dir():
        raise ModelError([(str(path), "is a folder, not a results file")])
    if not source.is_file():
        raise ModelError([(str(path), "no such results file")])
    try:
        netcdf = is_classic(source) or h5py.is_hdf5(source)
    except OSError as exc:
        raise ModelError([(str(path), f"cannot be read: {exc.strerror or exc}")]) from None
    if not netcdf:
        suffix = source.suffix.lower()
        hint = {".toml": ": it is a model file (TOML); jointplay.load() reads it and `jointplay run` simulates it",
                ".csv": ": CSV results are for other programs; open_results reads the NetCDF files (.nc) that "
                        "jointplay writes"}.get(suffix, "")
        raise ModelError([(str(path), f"is not a jointplay results file (not a NetCDF file){hint}")])
    return source


def check_declared(path: str | os.PathLike, what: str, shape: tuple[int, ...], itemsize: int = 8,
                   budget: int = DEFAULT_MAX_MEMORY_BYTES) -> None:
    """ModelError at ``path`` when ``what`` of a file declares more than ``budget`` bytes of values: checked
    before they are read (a file may declare a size far beyond what it holds)."""
    from .errors import ModelError

    size = math.prod(int(n) for n in shape) * itemsize
    if size > budget:
        dims = " x ".join(str(int(n)) for n in shape)
        raise ModelError([(str(path), f"{what} declares {dims} values ({format_size(size)}), above the memory "
                                      f"budget of {format_size(budget)} for reading a file")])


class ResultsWriter:
    """Streams channels into a NetCDF classic (CDF-2) file: :meth:`append` chunk after chunk, then
    :meth:`finish` with the global attributes (renames into place) or :meth:`abort` (removes the
    temporary file).

    The file's header goes first, with room for the global attributes known only at the end
    (:data:`PROVISIONAL_ATTRIBUTES` until then); each chunk is then one block of records (time and
    every channel at each sample, big-endian) written with one call, and the header's record count
    updated after it, so that a file cut after a chunk reads up to that chunk. Each chunk is
    converted and written by a background thread while the caller goes on: the simulation, which
    runs with the GIL released, computes the next chunk meanwhile. At most one chunk waits while
    another is written (their copies are the only extra memory), and an error of a background write
    is raised by the next call. An append names the index of its first sample: the same chunk
    appended again (after a Ctrl-C interrupted the call) is written once."""

    def __init__(self, path: str | os.PathLike, names: list[str], units: list[str], descriptions: list[str]):
        from .netcdf_classic import RecordFile

        self.path = Path(path)
        self.names = list(names)
        header = classic_header(self.names, units, descriptions)  # checks the names first
        self.temporary = temporary_path(self.path)
        #: Samples written to the file.
        self.samples = 0
        self._queue: queue.SimpleQueue = queue.SimpleQueue()  # (first sample, times, values); None ends
        self._write_error: BaseException | None = None
        #: Samples handed to the background writer.
        self._offered = 0
        #: The times appended, kept in memory: the results hold them anyway.
        self._time_parts: list[np.ndarray] = []
        self._writer: threading.Thread | None = None
        self._buffer: np.ndarray | None = None  # the records of the last chunk written, reused for the next
        self._file = RecordFile(self.temporary, header, PROVISIONAL_ATTRIBUTES, header_reserve(len(self.names)))
        self._writer = threading.Thread(target=self._write_queued, name="jointplay results writer", daemon=True)
        self._writer.start()

    def append(self, times: np.ndarray, values: np.ndarray, start: int | None = None) -> None:
        """Appends ``len(times)`` samples, the first of index ``start`` (default: the next one);
        ``values`` has shape (samples, channels). Returns once a copy is handed to the background
        writer; a chunk whose ``start`` was handed over already is ignored.

        Every step before the hand-over can be interrupted (Ctrl-C) and the call repeated: the
        hand-over itself is one ``put``, and the writer drops a chunk it has taken already."""
        start = self._offered if start is None else int(start)
        if start < self._offered:
            return
        self._raise_write_error()
        times = np.array(times, dtype=float)  # copies: the caller may reuse its buffers
        values = np.array(values, dtype=float).reshape(times.size, len(self.names))
        while self._queue.qsize() >= 1:  # one chunk waits at most, while another is written
            sleep(_QUEUE_POLL)
            self._raise_write_error()
        self._queue.put((start, times, values))
        self._offered = start + times.size

    def _write_queued(self) -> None:
        """The background writer: takes the queued chunks in order until ``None``."""
        from .netcdf_classic import records

        while (item := self._queue.get()) is not None:
            start, times, values = item
            if start < self.samples or self._write_error is not None:
                continue  # taken already (handed over again after an interrupt), or writing failed
            try:
                if self._buffer is None or self._buffer.shape[0] < times.size:
                    self._buffer = np.empty((times.size, len(self.names) + 1), dtype=">f8")
                self._file.append(records(times, values, self._buffer))
                self._time_parts.append(times)
                self.samples += times.size
            except BaseException as exc:  # raised by the next call, in the appending thread
                self._write_error = exc

    def _raise_write_error(self) -> None:
        if self._write_error is not None:
            error, self._write_error = self._write_error, None
            raise error

    def _wait(self) -> None:
        """Lets the background writer take what is queued and stop, then raises its error if any."""
        if self._writer is not None:
            self._queue.put(None)
            self._writer.join()
            self._writer = None
        self._raise_write_error()

    def times(self) -> np.ndarray:
        """The times appended so far [s]."""
        self._wait()
        if len(self._time_parts) != 1:
            self._time_parts = [np.concatenate(self._time_parts) if self._time_parts else np.empty(0)]
        return self._time_parts[0]

    def finish(self, attrs: dict[str, Any], *, complete: bool = True) -> Path:
        """Writes the final header with the global attributes (in place when they fit the room left for
        them, otherwise moving the samples once), closes the file and renames it to the target path
        (complete) or to :func:`partial_path` (a run that stopped early). Returns the path."""
        try:
            self._wait()
            self._file.finish(_global_attributes(attrs, CLASSIC_LAYOUT))
        except BaseException:
            self.abort()
            raise
        target = self.path if complete else partial_path(self.path)
        os.replace(self.temporary, target)
        return target

    def abort(self) -> None:
        """Closes and removes the temporary file (a good file at the target path stays as it was)."""
        try:
            try:
                self._wait()
            except BaseException:  # the file is removed anyway
                pass
            self._file.close()
        finally:
            self.temporary.unlink(missing_ok=True)


#: Attributes of the coordinate ``time`` (CF).
TIME_ATTRIBUTES = [("units", "s"), ("long_name", "time"), ("standard_name", "time"), ("axis", "T"),
                   ("description", "time")]


def channel_attributes(names: list[str], units: list[str], descriptions: list[str]) -> list[list[tuple[str, str]]]:
    """The text attributes of each channel's variable, in order: ``channel`` (its name, when the
    variable's differs), ``units``, ``long_name`` (the description, or the name) and ``description``.
    Raises ValueError when two channels would have one variable (checked before a file is made)."""
    variables = [variable_name(name) for name in names]
    if len(set(variables)) != len(variables):
        seen: set[str] = set()
        twice = next(v for v in variables if v in seen or seen.add(v))
        raise ValueError(f"two channels are named {twice!r}: a results file holds one variable per name")
    attributes = []
    for name, variable, unit, description in zip(names, variables, units, descriptions):
        attrs = [("channel", name)] if variable != name else []
        attrs += [("units", unit), ("long_name", description or name), ("description", description)]
        attributes.append(attrs)
    return attributes


def _global_attributes(attrs: dict[str, Any], layout: str) -> dict[str, Any]:
    """The global attributes as stored, ``jointplay_layout`` saying which layout the file has."""
    out = {key: _attribute(value) for key, value in attrs.items() if value is not None}
    out["jointplay_layout"] = layout
    return out


def classic_header(names: list[str], units: list[str], descriptions: list[str]):
    """The variables of a NetCDF classic results file: ``time`` then one per channel, with their attributes
    (:func:`channel_attributes`, which checks the names first)."""
    from .netcdf_classic import RecordHeader

    attributes = channel_attributes(names, units, descriptions)
    return RecordHeader(["time", *(variable_name(n) for n in names)], [TIME_ATTRIBUTES, *attributes])


def header_reserve(n_channels: int) -> int:
    """Room left in a NetCDF classic file's header for the global attributes known only at the end of a run
    [bytes]: the model (JSON and TOML), statistics, diagnostics and the summary of every channel took 8 kB for
    the 53 channels of the dry slider-crank and 90 kB for the 771 of a chain of 64 bars; this leaves 32 KiB
    and 192 bytes a channel (41 kB and 180 kB)."""
    return 32 * 1024 + 192 * n_channels


def save_netcdf(path: str | os.PathLike, time: np.ndarray, names: list[str], units: list[str],
                descriptions: list[str], block: Callable[[int, int], np.ndarray], attrs: dict[str, Any],
                compress: bool = False) -> Path:
    """Writes a results file at ``path``: ``time`` [s], one variable per channel with the values
    ``block(start, stop)`` gives (channels x samples, asked for block after block of
    :func:`rows_per_block` samples) and the global attributes ``attrs``. A NetCDF classic (CDF-2)
    file whose records are written in bulk (the layout a streamed run writes, byte for byte), or with
    ``compress`` NetCDF-4 with every channel gzip-compressed after the shuffle filter; more samples
    than a classic file counts go to NetCDF-4 too, with a warning. Written under a temporary name,
    renamed into place when complete."""
    from .netcdf_classic import MAX_RECORDS

    if not compress and len(time) > MAX_RECORDS:
        import warnings

        warnings.warn(f"{len(time)} samples are more than a NetCDF classic file holds ({MAX_RECORDS}): "
                      f"{path} is written as NetCDF-4 instead", RuntimeWarning, stacklevel=3)
        compress = True
    path = Path(path)
    temporary = temporary_path(path)
    try:
        if compress:
            _save_netcdf4(temporary, time, names, units, descriptions, block, attrs)
        else:
            _save_classic(temporary, time, names, units, descriptions, block, attrs)
        os.replace(temporary, path)
    except BaseException:
        temporary.unlink(missing_ok=True)
        raise
    return path


def _save_classic(path: Path, time, names, units, descriptions, block, attrs) -> None:
    from .netcdf_classic import records, write_records_file

    header = classic_header(names, units, descriptions)
    # records converted and written 1 MiB at a time: a buffer that stays in the cache, no fresh pages
    n, rows = len(time), max(1, min(rows_per_block(len(names)), _RECORD_BLOCK_BYTES // (8 * (len(names) + 1))))
    buffer = np.empty((min(n, rows), len(names) + 1), dtype=">f8")
    blocks = (records(time[start:min(n, start + rows)], block(start, min(n, start + rows)).T, buffer)
              for start in range(0, n, rows))
    write_records_file(path, header, PROVISIONAL_ATTRIBUTES, header_reserve(len(names)),
                       _global_attributes(attrs, CLASSIC_LAYOUT), n, blocks)


def _save_netcdf4(path: Path, time, names, units, descriptions, block, attrs) -> None:
    """NetCDF-4 (HDF5) with gzip-compressed channels (:mod:`jointplay.resultslayout`)."""
    from .resultslayout import FileLayout

    attributes = channel_attributes(names, units, descriptions)
    layout = FileLayout(path)
    try:
        n = len(time)
        channels = layout.channels([variable_name(name) for name in names], attributes, n)
        rows = rows_per_block(len(names))
        for start in range(0, n, rows):
            stop = min(n, start + rows)
            layout.write(channels, start, block(start, stop))
        layout.close_with(layout.time(time, TIME_ATTRIBUTES), channels, _global_attributes(attrs, LAYOUT))
    except BaseException:
        layout.close()
        raise


def variable_name(channel: str) -> str:
    """The file's name of a channel: ``/`` (a group separator in HDF5) becomes ``%2F``; the channel's
    own name is then kept in the variable's ``channel`` attribute."""
    return channel.replace("/", "%2F")


def _attribute(value: Any):
    """A value HDF5 stores as a NetCDF attribute (lists as arrays, an empty list as an empty int array)."""
    if isinstance(value, (list, tuple, np.ndarray)):
        return np.asarray(value) if len(value) else np.zeros(0, dtype=np.int64)
    if isinstance(value, bool):
        return int(value)
    return value


class FileChannels:
    """Channel values read from a results file on access (nothing kept in memory): from a NetCDF
    classic file through a memory map of its records, from a NetCDF-4 file through h5py."""

    def __init__(self, path: str | os.PathLike, names: list[str]):
        self.path = Path(path)
        self.names = list(names)
        self._records: tuple | None = None  # (file stamp, memory map of the records or None)

    def _classic(self) -> np.ndarray | None:
        """The records of a classic file as a memory map, (samples, 1 + channels) big-endian, mapped again
        when the file changed (the map stays between accesses: its pages are the file's, which the system
        drops when it needs the memory); None for a NetCDF-4 file."""
        from .netcdf_classic import is_classic, read_layout

        status = os.stat(self.path)
        stamp = (status.st_mtime_ns, status.st_size, status.st_ino)
        if self._records is None or self._records[0] != stamp:
            mapped = None
            if is_classic(self.path):
                layout = read_layout(self.path)
                begin, width = layout.variables["time"]["begin"], layout.record_bytes // 8
                mapped = (np.memmap(self.path, dtype=">f8", mode="r", offset=begin, shape=(layout.numrecs, width))
                          if layout.numrecs else np.empty((0, width), dtype=">f8"))
            self._records = (stamp, mapped)
        return self._records[1]

    def __getitem__(self, k: int) -> np.ndarray:
        classic = self._classic()
        if classic is not None:
            return np.array(classic[:, 1 + k], dtype=float)
        import h5py

        with h5py.File(self.path, "r") as f:
            dataset = f[variable_name(self.names[k])]
            check_declared(self.path, f"channel {self.names[k]!r}", dataset.shape)
            return np.asarray(dataset[()], dtype=float)

    def block(self, start: int, stop: int) -> np.ndarray:
        """Values of every channel for samples ``start:stop``, shape (channels, samples)."""
        classic = self._classic()
        if classic is not None:
            return np.array(classic[start:stop, 1:].T, dtype=float)
        import h5py

        with h5py.File(self.path, "r") as f:
            return np.array([f[variable_name(name)][start:stop] for name in self.names],
                            dtype=float).reshape(len(self.names), -1)


def is_streamed_layout(path: str | os.PathLike) -> bool:
    """Whether ``path`` was written by this module (rather than by xarray before it)."""
    from .netcdf_classic import is_classic, read_layout

    if is_classic(path):
        return read_layout(path).attributes.get("jointplay_layout") == CLASSIC_LAYOUT
    import h5py

    with h5py.File(path, "r") as f:
        layout = f.attrs.get("jointplay_layout", "")
    return (layout.decode() if isinstance(layout, bytes) else str(layout)) in LAYOUTS_READ_ON_ACCESS


def read_file(path: str | os.PathLike) -> tuple[np.ndarray, list[str], list[str], list[str], dict[str, Any]]:
    """``(time, names, units, descriptions, global attributes)`` of a file written by this module."""
    from .netcdf_classic import is_classic

    if is_classic(path):
        return _read_classic(path)
    import h5py

    with h5py.File(path, "r") as f:
        check_declared(path, "time", f["time"].shape)
        time = np.asarray(f["time"][()], dtype=float)
        variables = [name for name in f if name != "time"]
        names = [_text(f[name].attrs.get("channel", name)) for name in variables]
        units = [_text(f[name].attrs.get("units", "")) for name in variables]
        descriptions = [_text(f[name].attrs.get("description", "")) for name in variables]
        attrs = {key: _plain(value) for key, value in f.attrs.items()}
    return time, names, units, descriptions, attrs


def _read_classic(path) -> tuple[np.ndarray, list[str], list[str], list[str], dict[str, Any]]:
    from .netcdf_classic import read_layout

    layout = read_layout(path)
    variables = [(name, v) for name, v in layout.variables.items() if name != "time"]
    if list(layout.variables)[:1] != ["time"] or any(not v["record"] or v["vsize"] != 8 or v["type"] != 6
                                                     for _, v in [("time", layout.variables["time"]), *variables]):
        raise ValueError("its variables are not the float64 records on time that jointplay writes")
    check_declared(path, "time", (layout.numrecs,))
    begin, width = layout.variables["time"]["begin"], layout.record_bytes // 8
    time = (np.array(np.memmap(path, dtype=">f8", mode="r", offset=begin, shape=(layout.numrecs, width))[:, 0],
                     dtype=float) if layout.numrecs else np.empty(0))
    names = [str(v["attrs"].get("channel", name)) for name, v in variables]
    units = [str(v["attrs"].get("units", "")) for _, v in variables]
    descriptions = [str(v["attrs"].get("description", "")) for _, v in variables]
    return time, names, units, descriptions, dict(layout.attributes)


def _text(value: Any) -> str:
    return value.decode() if isinstance(value, bytes) else str(value)


def _plain(value: Any) -> Any:
    if isinstance(value, bytes):
        return value.decode()
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    return value


def check_budget(t0: float, t_end: float, output_step: float | None, n_channels: int, budget: int,
                 longest_step: float | None = None) -> str | None:
    """A message when a run on the regular grid ``output_step`` would write more than ``budget`` bytes
    (``(t_end - t0) / output_step + 1`` samples x channels x 8 bytes), or a run with a sample at every
    step at least that (steps of at most ``longest_step``: ``max_step``, or generalized-alpha's ``step``);
    None when it fits or the sample count has no bound before the run (then the run stops when it reaches
    the budget, and its pace is projected while it goes)."""
    if output_step is None and longest_step is None:
        return None
    spacing = output_step if output_step is not None else longest_step
    samples = math.ceil((t_end - t0) / spacing) + 1  # the grid points (or shortest steps) before t_end, and t_end
    size = samples * n_channels * 8
    if size <= budget:
        return None
    count = f"{samples}" if samples < 10**12 else f"{samples:.3g}"
    if output_step is None:
        return (f"the run would write at least {count} samples (one at every step, each of at most "
                f"{longest_step:g} s) x {n_channels} channels x 8 bytes = {format_size(size)}, above "
                f"max_output_bytes = {format_size(budget)}; set an output_step, raise max_output_bytes or "
                "shorten t_end")
    return (f"the run would write {count} samples x {n_channels} channels x 8 bytes = {format_size(size)}, "
            f"above max_output_bytes = {format_size(budget)}; raise max_output_bytes, set a coarser output_step "
            "or a shorter t_end")


def rows_per_block(n_channels: int) -> int:
    """Samples read at once when copying results: at most 65536, and at most :data:`_BUFFER_BYTES` of values."""
    return max(1, min(65536, _BUFFER_BYTES // (8 * (n_channels + 1))))


def write_csv(results, path: str | os.PathLike) -> Path:
    """Writes ``time`` and one column per channel to a CSV file, header ``name [unit]``, block after
    block (a file-backed ``results`` is never read whole); temporary name, then renamed into place."""
    path = Path(path)
    remove_stale_temporaries(path)
    temporary = temporary_path(path)
    names = results.channels
    header = ",".join(["time [s]", *(f"{name} [{results.unit(name)}]" for name in names)])
    block = rows_per_block(len(names))
    try:
        with terminate_as_exit(), open(temporary, "w", encoding="utf-8", newline="") as f:
            f.write(header + "\n")
            for start in range(0, len(results), block):
                stop = min(len(results), start + block)
                rows = np.vstack([results.time[start:stop], results.channel_block(start, stop)]).T
                np.savetxt(f, rows, delimiter=",", fmt="%.17g")
        os.replace(temporary, path)
    except BaseException:
        temporary.unlink(missing_ok=True)
        raise
    return path


def budget_option(raw: Any, to_file: bool) -> int:
    """``max_output_bytes`` in bytes: ``raw`` (a number or ``"2 GiB"``) or the default for a run with a
    results file (:data:`DEFAULT_MAX_FILE_BYTES`) or in memory (:data:`DEFAULT_MAX_MEMORY_BYTES`);
    raises ModelError at ``simulation.max_output_bytes``."""
    from .errors import ModelError

    if raw is None:
        return DEFAULT_MAX_FILE_BYTES if to_file else DEFAULT_MAX_MEMORY_BYTES
    try:
        return parse_size(raw)
    except ValueError as exc:
        raise ModelError([("simulation.max_output_bytes", str(exc))]) from None


def stream_run(path: str | os.PathLike, channels: dict, run, make_results):
    """Runs ``run(sink)`` with a :class:`ResultsWriter` on ``path`` as its sink and returns
    ``(results, raw)``: ``make_results(raw)`` with its channels read from the finished file (``path``,
    or :func:`partial_path` when the run stopped early). Any exception (from the run, the sink or an
    interrupt) removes the temporary file and leaves ``path`` as it was; so does SIGTERM
    (:func:`terminate_as_exit`). Temporary files of ``path`` left by killed runs are removed first."""
    remove_stale_temporaries(path)
    with terminate_as_exit():
        writer = ResultsWriter(path, channels["names"], channels["units"], channels["descriptions"])
        try:
            raw = run(writer.append)
            results = make_results(raw)
            results.time = writer.times()
            target = writer.finish(results.file_attributes(), complete=raw["error"] is None)
        except BaseException:
            writer.abort()
            raise
    results.read_from(target)
    return results, raw
