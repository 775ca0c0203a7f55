"""A structure from another finite-element code for a modal body: its mass and stiffness matrices and its
nodes, from Matrix Market, NumPy or SciPy files or given inline, in the core's SI entries.

The files hold numbers only: Matrix Market text (:func:`scipy.io.mmread`), NumPy arrays read without pickles
(``allow_pickle=False``), SciPy sparse archives (:func:`scipy.sparse.load_npz`, which reads no pickles either),
plain text tables (:func:`numpy.loadtxt`). Nothing in them is executed. Units: the files share one consistent
set, time in seconds; with a length unit ``L`` and a mass unit ``m`` (to SI by ``l`` and ``f``), every entry of
coordinate ``i`` and ``j`` scales by ``f`` times ``l`` for each of ``i`` and ``j`` that is a rotation, and node
positions by ``l`` (docs/theory/modal-body.md). Each node has three coordinates ``(u_x, u_y, theta)`` (frame
elements) or two ``(u_x, u_y)`` (plane solids); the matrices' size tells which.

Before a file is read, the size its header declares (a ``.npy`` header, the arrays of a ``.npz`` archive, a
Matrix Market size line) is checked against the most the core takes (:data:`MAX_MATRIX_SIZE`), so a small file
declaring a huge matrix costs nothing; a text file of nodes is read only up to :data:`MAX_TEXT_BYTES`. An
entry that is not a finite number is named with its file and place; a text file starting with a byte-order
mark is named as such.
"""

from __future__ import annotations

import zipfile
from pathlib import Path
from typing import Any

import numpy as np
import scipy.io
import scipy.sparse

from .._core import MAX_STRUCTURE_NODES
from ..units import UnitError, to_si

#: Suffixes of the files a matrix is read from, and of those node positions are read from.
MATRIX_SUFFIXES = (".mtx", ".npy", ".npz")
NODE_SUFFIXES = (".npy", ".mtx", ".csv", ".txt")
#: Largest matrix of a structure: three coordinates for each of the core's most nodes (its reduction is dense).
MAX_MATRIX_SIZE = 3 * MAX_STRUCTURE_NODES
#: Largest text file of node positions read [bytes]: far more than the core's most nodes need.
MAX_TEXT_BYTES = 16 * 2**20
_UTF8_BOM = b"\xef\xbb\xbf"


class MatrixError(ValueError):
    """What is wrong with one matrix or node list (its location is the caller's)."""


def unit_factor(unit: Any, kind: str) -> float:
    """The SI value of one ``unit`` (``"mm"``) of ``kind`` (``"length"``, ``"mass"``); raises MatrixError."""
    if not isinstance(unit, str) or not unit.strip():
        raise MatrixError(f"must be a unit of {kind} as a string, e.g. \"{'mm' if kind == 'length' else 't'}\", "
                          f"got {unit!r}")
    try:
        value = to_si(f"1 {unit.strip()}", kind)
    except UnitError as exc:
        raise MatrixError(f"must be a unit of {kind}: {exc}") from None
    if not (np.isfinite(value) and value > 0):
        raise MatrixError(f"must be a unit of {kind}, got {unit!r}")
    return value


def _path(source: str | Path, base: Path, suffixes: tuple[str, ...]) -> Path:
    path = Path(source)
    path = path if path.is_absolute() else base / path
    if path.suffix.lower() not in suffixes:
        raise MatrixError(f"must be a file ending in {', '.join(suffixes)}, got {str(source)!r}")
    if not path.is_file():
        raise MatrixError(f"no such file: {str(path)!r}")
    return path


def _numeric(array: np.ndarray, what: str) -> np.ndarray:
    if not (np.issubdtype(array.dtype, np.floating) or np.issubdtype(array.dtype, np.integer)):
        raise MatrixError(f"must hold real numbers, got {what} of {array.dtype}")
    return array.astype(float)


def read_matrix(source: Any, base: Path) -> scipy.sparse.coo_array:
    """A square matrix from a file (by its path from ``base``), an array, a SciPy sparse matrix or the
    entries ``{size, rows, columns, values}``, every entry finite; raises MatrixError."""
    if isinstance(source, dict):
        return _finite(_inline_matrix(source), "")
    origin = ""
    if isinstance(source, (str, Path)):
        path = _path(source, base, MATRIX_SUFFIXES)
        origin = f" of {str(path)!r}"
        source = _load_matrix(path)
    return _finite(_matrix(source), origin)


def _finite(matrix: scipy.sparse.coo_array, origin: str) -> scipy.sparse.coo_array:
    """``matrix`` when every stored entry is finite; MatrixError naming the first that is not (``origin``:
    `` of 'file'``)."""
    bad = ~np.isfinite(matrix.data)
    if bad.any():
        k, n = int(np.argmax(bad)), int(bad.sum())
        others = f"; {n - 1} other entr{'y is' if n == 2 else 'ies are'} not either" if n > 1 else ""
        raise MatrixError(f"entry ({int(matrix.row[k])}, {int(matrix.col[k])}){origin} is {matrix.data[k]}: every "
                          f"entry must be a finite number (rows and columns count from 0{others})")
    return matrix


def _matrix(source: Any) -> scipy.sparse.coo_array:
    if scipy.sparse.issparse(source):
        matrix = scipy.sparse.coo_array(source)
        matrix = scipy.sparse.coo_array((_numeric(matrix.data, "entries"), (matrix.row, matrix.col)),
                                        shape=matrix.shape)
    elif isinstance(source, (np.ndarray, list, tuple)):
        array = _numeric(np.asarray(source), "an array")
        if array.ndim != 2:
            raise MatrixError(f"must be a matrix (2 dimensions), got an array of shape {array.shape}")
        matrix = scipy.sparse.coo_array(array)
    else:
        raise MatrixError(f"must be a file name, an array or a SciPy sparse matrix, got {type(source).__name__}")
    if matrix.shape[0] != matrix.shape[1]:
        raise MatrixError(f"must be square, got {matrix.shape[0]} x {matrix.shape[1]}")
    return matrix


def _load_matrix(path: Path) -> Any:
    suffix = path.suffix.lower()
    try:
        if suffix == ".mtx":
            _check_mtx(path, MAX_MATRIX_SIZE, MAX_MATRIX_SIZE)
            return scipy.io.mmread(path)
        if suffix == ".npz":
            _check_npz(path)
            return scipy.sparse.load_npz(path)
        _check_npy(path, MAX_MATRIX_SIZE, MAX_MATRIX_SIZE)
        return np.load(path, allow_pickle=False)
    except MatrixError:
        raise
    except ValueError as exc:
        hint = " (an array of Python objects needs pickles, which are not read)" if "pickle" in str(exc) else ""
        raise MatrixError(f"cannot be read from {str(path)!r}: {exc}{hint}") from None
    except (OSError, KeyError, EOFError, zipfile.BadZipFile) as exc:
        raise MatrixError(f"cannot be read from {str(path)!r}: {exc}") from None


# declared sizes, checked before anything is allocated ------------------------------------------------------

def _too_large(path: Path, declared: str, rows: int, columns: int, most_rows: int, most_columns: int) -> None:
    if rows > most_rows or columns > most_columns:
        raise MatrixError(f"{str(path)!r} declares {declared}: a structure given by matrices has at most "
                          f"{MAX_STRUCTURE_NODES} nodes ({MAX_MATRIX_SIZE} x {MAX_MATRIX_SIZE} coordinates; its "
                          "reduction is dense), so it is not read; reduce the structure in its own code first")


def _npy_header(fileobj, path: Path) -> tuple[tuple[int, ...], np.dtype]:
    """Shape and type declared by the header of a NumPy array file (nothing else is read)."""
    from numpy.lib import format as npy

    major, _ = npy.read_magic(fileobj)
    shape, _, dtype = (npy.read_array_header_1_0 if major == 1 else npy.read_array_header_2_0)(fileobj)
    if dtype.hasobject:
        raise MatrixError(f"cannot be read from {str(path)!r}: it holds Python objects (an array of Python objects "
                          "needs pickles, which are not read)")
    return tuple(int(n) for n in shape), dtype


def _check_npy(path: Path, most_rows: int, most_columns: int) -> None:
    with open(path, "rb") as fileobj:
        shape, _ = _npy_header(fileobj, path)
    elements = int(np.prod(shape, dtype=float))
    if len(shape) == 2:
        _too_large(path, f"a {shape[0]} x {shape[1]} array", shape[0], shape[1], most_rows, most_columns)
    elif elements > most_rows * most_columns:
        _too_large(path, f"an array of shape {shape}", elements, 1, most_rows * most_columns, 1)


def _check_npz(path: Path) -> None:
    """A SciPy sparse archive: its declared shape and the length of each of its arrays."""
    with zipfile.ZipFile(path) as archive:
        for info in archive.infolist():
            if not info.filename.endswith(".npy"):
                continue
            with archive.open(info) as member:
                shape, dtype = _npy_header(member, path)
                if info.filename == "shape.npy" and len(shape) == 1 and shape[0] == 2:
                    declared = np.frombuffer(member.read(2 * dtype.itemsize), dtype=dtype)
                    if declared.size == 2:
                        rows, columns = (int(n) for n in declared)
                        _too_large(path, f"a {rows} x {columns} matrix", rows, columns, MAX_MATRIX_SIZE,
                                   MAX_MATRIX_SIZE)
            elements = int(np.prod(shape, dtype=float))
            if elements > MAX_MATRIX_SIZE**2 + 1:
                _too_large(path, f"{elements} values in {info.filename}", elements, 1, MAX_MATRIX_SIZE**2 + 1, 1)


def _check_mtx(path: Path, most_rows: int, most_columns: int) -> None:
    """A Matrix Market file: its header's size and number of entries."""
    _check_text(path)
    rows, columns, entries, *_ = scipy.io.mminfo(path)
    _too_large(path, f"a {rows} x {columns} matrix", rows, columns, most_rows, most_columns)
    if entries > rows * columns:
        raise MatrixError(f"{str(path)!r} declares {entries} entries in a {rows} x {columns} matrix, more than it "
                          "has places for")


def _check_text(path: Path) -> None:
    """A text file that does not start with a byte-order mark (numbers are read from its first byte)."""
    with open(path, "rb") as fileobj:
        head = fileobj.read(3)
    if head == _UTF8_BOM:
        raise MatrixError(f"{str(path)!r} starts with a UTF-8 byte-order mark (BOM, the bytes EF BB BF), which is "
                          "not read as a number; save the file as UTF-8 without BOM")


def _inline_matrix(entries: dict) -> scipy.sparse.coo_array:
    keys = {"size", "rows", "columns", "values"}
    if set(entries) != keys:
        raise MatrixError(f"must have the keys {', '.join(sorted(keys))}, got {', '.join(sorted(entries)) or 'none'}")
    size = entries["size"]
    if isinstance(size, bool) or not isinstance(size, int) or size < 1:
        raise MatrixError(f"size must be a positive whole number, got {size!r}")
    try:
        rows = np.asarray(entries["rows"], dtype=np.int64)
        columns = np.asarray(entries["columns"], dtype=np.int64)
        values = np.asarray(entries["values"], dtype=float)
    except (TypeError, ValueError) as exc:
        raise MatrixError(f"rows and columns must be whole numbers and values numbers: {exc}") from None
    if not rows.ndim == columns.ndim == values.ndim == 1 or not rows.size == columns.size == values.size:
        raise MatrixError(f"rows, columns and values must be lists of one length, got {rows.size}, {columns.size} "
                          f"and {values.size}")
    outside = (rows < 0) | (rows >= size) | (columns < 0) | (columns >= size)
    if outside.any():
        k = int(np.argmax(outside))
        raise MatrixError(f"entry ({rows[k]}, {columns[k]}) is outside a {size} x {size} matrix (rows and columns "
                          "count from 0)")
    return scipy.sparse.coo_array((values, (rows, columns)), shape=(size, size))


def read_nodes(source: Any, base: Path) -> np.ndarray:
    """Node positions ``(n, 2)`` from a file (by its path from ``base``) or a list of pairs; raises MatrixError."""
    if isinstance(source, (str, Path)):
        path = _path(source, base, NODE_SUFFIXES)
        suffix = path.suffix.lower()
        origin = f" of {str(path)!r}"
        try:
            if suffix == ".npy":
                _check_npy(path, MAX_STRUCTURE_NODES, 2 * MAX_MATRIX_SIZE)
                source = np.load(path, allow_pickle=False)
            elif suffix == ".mtx":
                _check_mtx(path, MAX_STRUCTURE_NODES, 2 * MAX_MATRIX_SIZE)
                source = scipy.io.mmread(path)
                source = source.toarray() if scipy.sparse.issparse(source) else source
            else:
                _check_text(path)
                size = path.stat().st_size
                if size > MAX_TEXT_BYTES:
                    raise MatrixError(f"{str(path)!r} holds {size} bytes, more than the {MAX_TEXT_BYTES} bytes a list "
                                      f"of at most {MAX_STRUCTURE_NODES} nodes needs, so it is not read")
                source = np.loadtxt(path, delimiter="," if suffix == ".csv" else None, comments="#", ndmin=2)
        except (ValueError, OSError, EOFError) as exc:
            if isinstance(exc, MatrixError):
                raise
            raise MatrixError(f"cannot be read from {str(path)!r}: {exc}") from None
    else:
        origin = ""
    try:
        nodes = _numeric(np.asarray(source), "a list")
    except (TypeError, ValueError) as exc:
        raise MatrixError(f"must be node positions, one pair x, y per node: {exc}") from None
    if nodes.ndim != 2 or nodes.shape[1] != 2 or nodes.shape[0] == 0:
        raise MatrixError(f"must hold one row x, y per node (n x 2), got an array of shape {nodes.shape}")
    if not np.isfinite(nodes).all():
        k = int(np.argmax(~np.isfinite(nodes).all(axis=1)))
        raise MatrixError(f"node {k}{origin} is not at a finite position, got {nodes[k].tolist()}")
    return nodes


def in_si(matrix: scipy.sparse.coo_array, length: float, mass: float, per_node: int = 3) -> scipy.sparse.coo_array:
    """``matrix`` over nodal (u_x, u_y, theta) (``per_node`` 3) or (u_x, u_y) (2) in SI units, from units whose
    length and mass are ``length`` m and ``mass`` kg (time in seconds): entry (i, j) times ``mass`` and
    ``length`` per rotation among i, j."""
    if per_node == 3:
        rotations = (matrix.row % 3 == 2).astype(int) + (matrix.col % 3 == 2).astype(int)
    else:
        rotations = np.zeros(matrix.data.shape, dtype=int)
    return scipy.sparse.coo_array((matrix.data * mass * length ** rotations, (matrix.row, matrix.col)),
                                  shape=matrix.shape)


def core_entries(matrix: scipy.sparse.coo_array) -> dict:
    """The core's ``{size, rows, columns, values}`` of a square matrix (repeated entries added)."""
    matrix = scipy.sparse.coo_array(matrix.tocsr())  # adds repeated entries, sorts by row
    return {"size": int(matrix.shape[0]), "rows": [int(i) for i in matrix.row],
            "columns": [int(j) for j in matrix.col], "values": [float(v) for v in matrix.data]}
