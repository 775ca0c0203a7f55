"""Planar frame structures of Euler-Bernoulli elements, written here apart from the core, to stand in for
another finite-element code: it assembles mass and stiffness matrices over the nodal (u_x, u_y, theta), node
after node, and writes them as Matrix Market files with the nodes as CSV, as such a code would export them.

Element (length ``L``, axis at angle ``a``): a bar, ``EA/L`` and the consistent mass ``rho A L/6 [2 1; 1 2]``,
plus a Hermite-cubic bending beam, stiffness ``EI/L^3 [12 6L -12 6L; ...]`` and consistent mass
``rho A L/420 [156 22L 54 -13L; ...]`` (Przemieniecki, *Theory of Matrix Structural Analysis*, McGraw-Hill,
1968, ch. 5 and 11), optionally the rotary inertia of the section ``rho I/(30 L) [36 3L -36 3L; ...]``;
turned from the element's axes into the structure's by the rotation of each node's translations.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import scipy.io
import scipy.sparse


@dataclass(frozen=True)
class Section:
    """Stiffnesses and inertias per length of a uniform member (SI, or any consistent units)."""

    ea: float
    ei: float
    rho_a: float
    rho_i: float = 0.0


def element_matrices(length: float, angle: float, s: Section) -> tuple[np.ndarray, np.ndarray]:
    """The 6 x 6 mass and stiffness of one element in the structure's axes."""
    L = length
    k = np.zeros((6, 6))
    m = np.zeros((6, 6))
    axial, bending = [0, 3], [1, 2, 4, 5]
    k[np.ix_(axial, axial)] = s.ea / L * np.array([[1.0, -1.0], [-1.0, 1.0]])
    k[np.ix_(bending, bending)] = s.ei / L**3 * np.array([
        [12.0, 6 * L, -12.0, 6 * L], [6 * L, 4 * L**2, -6 * L, 2 * L**2],
        [-12.0, -6 * L, 12.0, -6 * L], [6 * L, 2 * L**2, -6 * L, 4 * L**2]])
    m[np.ix_(axial, axial)] = s.rho_a * L / 6 * np.array([[2.0, 1.0], [1.0, 2.0]])
    m[np.ix_(bending, bending)] = s.rho_a * L / 420 * np.array([
        [156.0, 22 * L, 54.0, -13 * L], [22 * L, 4 * L**2, 13 * L, -3 * L**2],
        [54.0, 13 * L, 156.0, -22 * L], [-13 * L, -3 * L**2, -22 * L, 4 * L**2]])
    m[np.ix_(bending, bending)] += s.rho_i / (30 * L) * np.array([
        [36.0, 3 * L, -36.0, 3 * L], [3 * L, 4 * L**2, -3 * L, -L**2],
        [-36.0, -3 * L, 36.0, -3 * L], [3 * L, -L**2, -3 * L, 4 * L**2]])
    c, sn = np.cos(angle), np.sin(angle)
    r = np.array([[c, sn, 0.0], [-sn, c, 0.0], [0.0, 0.0, 1.0]])  # structure to element axes
    t = np.zeros((6, 6))
    t[:3, :3] = t[3:, 3:] = r
    return t.T @ m @ t, t.T @ k @ t


def frame(nodes: np.ndarray, members: list[tuple[int, int]], section: Section) -> tuple[np.ndarray, np.ndarray]:
    """Mass and stiffness of the frame of ``members`` (pairs of node numbers) between ``nodes`` (n x 2)."""
    n = 3 * len(nodes)
    mass, stiffness = np.zeros((n, n)), np.zeros((n, n))
    for a, b in members:
        d = nodes[b] - nodes[a]
        m, k = element_matrices(float(np.hypot(*d)), float(np.arctan2(d[1], d[0])), section)
        dofs = [3 * a, 3 * a + 1, 3 * a + 2, 3 * b, 3 * b + 1, 3 * b + 2]
        mass[np.ix_(dofs, dofs)] += m
        stiffness[np.ix_(dofs, dofs)] += k
    return mass, stiffness


def straight_member(length: float, elements: int, section: Section) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Nodes (along x from the origin), mass and stiffness of a straight member of ``elements`` elements."""
    nodes = np.column_stack([np.linspace(0.0, length, elements + 1), np.zeros(elements + 1)])
    mass, stiffness = frame(nodes, [(i, i + 1) for i in range(elements)], section)
    return nodes, mass, stiffness


def write(folder: Path, stem: str, nodes: np.ndarray, mass: np.ndarray, stiffness: np.ndarray) -> dict[str, str]:
    """``<stem>.mass.mtx``, ``<stem>.stiffness.mtx`` (coordinate, symmetric) and ``<stem>.nodes.csv`` in
    ``folder``; the model file's ``matrices`` keys naming them."""
    names = {"mass": f"{stem}.mass.mtx", "stiffness": f"{stem}.stiffness.mtx", "nodes": f"{stem}.nodes.csv"}
    for key in ("mass", "stiffness"):
        matrix = {"mass": mass, "stiffness": stiffness}[key]
        scipy.io.mmwrite(folder / names[key], scipy.sparse.coo_matrix(matrix), symmetry="symmetric",
                         precision=17)
    np.savetxt(folder / names["nodes"], nodes, delimiter=",", header="x, y", fmt="%.17g")
    return names
