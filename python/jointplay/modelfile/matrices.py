"""A structure from another finite-element code for a modal body: its mass and stiffness matrices and its
nodes, from Matrix Market, NumPy or SciPy files or given inline, in the core's SI entries.

The files hold numbers only: Matrix Market text (:func:`scipy.io.mmread`), NumPy arrays read without pickles
(``allow_pickle=False``), SciPy sparse archives (:func:`scipy.sparse.load_npz`, which reads no pickles either),
plain text tables (:func:`numpy.loadtxt`). Nothing in them is executed. Units: the files share one consistent
set, time in seconds; with a length unit ``L`` and a mass unit ``m`` (to SI by ``l`` and ``f``), every entry of
coordinate ``i`` and ``j`` scales by ``f`` times ``l`` for each of ``i`` and ``j`` that is a rotation, and node
positions by ``l`` (docs/theory/modal-body.md). Each node has three coordinates ``(u_x, u_y, theta)`` (frame
elements) or two ``(u_x, u_y)`` (plane solids); the matrices' size tells which.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import scipy.io
import scipy.sparse

from ..units import UnitError, to_si

#: Suffixes of the files a matrix is read from, and of those node positions are read from.
MATRIX_SUFFIXES = (".mtx", ".npy", ".npz")
NODE_SUFFIXES = (".npy", ".mtx", ".csv", ".txt")


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
    entries ``{size, rows, columns, values}``; raises MatrixError."""
    if isinstance(source, dict):
        return _inline_matrix(source)
    if isinstance(source, (str, Path)):
        path = _path(source, base, MATRIX_SUFFIXES)
        source = _load_matrix(path)
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
            return scipy.io.mmread(path)
        if suffix == ".npz":
            return scipy.sparse.load_npz(path)
        return np.load(path, allow_pickle=False)
    except ValueError as exc:
        hint = " (an array of Python objects needs pickles, which are not read)" if "pickle" in str(exc) else ""
        raise MatrixError(f"cannot be read from {str(path)!r}: {exc}{hint}") from None
    except (OSError, KeyError, EOFError) as exc:
        raise MatrixError(f"cannot be read from {str(path)!r}: {exc}") from None


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
        try:
            if suffix == ".npy":
                source = np.load(path, allow_pickle=False)
            elif suffix == ".mtx":
                source = scipy.io.mmread(path)
                source = source.toarray() if scipy.sparse.issparse(source) else source
            else:
                source = np.loadtxt(path, delimiter="," if suffix == ".csv" else None, comments="#", ndmin=2)
        except (ValueError, OSError, EOFError) as exc:
            raise MatrixError(f"cannot be read from {str(path)!r}: {exc}") from None
    try:
        nodes = _numeric(np.asarray(source), "a list")
    except (TypeError, ValueError) as exc:
        raise MatrixError(f"must be node positions, one pair x, y per node: {exc}") from None
    if nodes.ndim != 2 or nodes.shape[1] != 2 or nodes.shape[0] == 0:
        raise MatrixError(f"must hold one row x, y per node (n x 2), got an array of shape {nodes.shape}")
    if not np.isfinite(nodes).all():
        raise MatrixError(f"node {int(np.argmax(~np.isfinite(nodes).all(axis=1)))} is not at a finite position")
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
