"""Plane-stress finite elements written for the tests, apart from the core: four-node bilinear quadrilaterals
(Q4) with the full 2 x 2 Gauss rule, two coordinates (u_x, u_y) per node, consistent mass. The textbook element
(for example T. J. R. Hughes, *The Finite Element Method*, Dover 2000, §3.5 and §3.8): strains
eps = B u with the bilinear shape functions' derivatives, stress sigma = D eps with the plane-stress matrix
D = E / (1 - nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]], K_e = sum t B^T D B det J w, and
M_e = sum rho t N^T N det J w. It stands for a planar link meshed in another finite-element code, whose
matrices a modal body reads."""

from __future__ import annotations

import numpy as np

GAUSS = (-1.0 / np.sqrt(3.0), 1.0 / np.sqrt(3.0))


def element_matrices(corners: np.ndarray, youngs: float, poisson: float, density: float, thickness: float):
    """The 8 x 8 stiffness and mass of the quadrilateral with ``corners`` (4 x 2, counter-clockwise) [m], in
    the order (u_x, u_y) of corner 0, 1, 2, 3; E [Pa], nu, rho [kg/m^3], t [m]."""
    d = youngs / (1.0 - poisson ** 2) * np.array([[1.0, poisson, 0.0], [poisson, 1.0, 0.0],
                                                   [0.0, 0.0, 0.5 * (1.0 - poisson)]])
    signs = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])
    k, m = np.zeros((8, 8)), np.zeros((8, 8))
    for xi in GAUSS:
        for eta in GAUSS:
            n = 0.25 * (1.0 + signs[:, 0] * xi) * (1.0 + signs[:, 1] * eta)
            dn = 0.25 * np.column_stack([signs[:, 0] * (1.0 + signs[:, 1] * eta), signs[:, 1] * (1.0 + signs[:, 0] * xi)])
            jacobian = dn.T @ corners  # d(x, y)/d(xi, eta)
            det = np.linalg.det(jacobian)
            dndx = dn @ np.linalg.inv(jacobian).T  # rows: dN_a/dx, dN_a/dy
            b = np.zeros((3, 8))
            b[0, 0::2], b[1, 1::2] = dndx[:, 0], dndx[:, 1]
            b[2, 0::2], b[2, 1::2] = dndx[:, 1], dndx[:, 0]
            k += thickness * b.T @ d @ b * det
            shape = np.zeros((2, 8))
            shape[0, 0::2], shape[1, 1::2] = n, n
            m += density * thickness * shape.T @ shape * det
    return k, m


def strip(length: float, depth: float, along: int, across: int, youngs: float, poisson: float, density: float,
          thickness: float):
    """A rectangular strip from (0, -depth / 2) to (length, depth / 2) of ``along`` x ``across`` elements: node
    positions (nodes row by row along x, ``along + 1`` per row, ``across + 1`` rows), mass and stiffness."""
    xs, ys = np.linspace(0.0, length, along + 1), np.linspace(-0.5 * depth, 0.5 * depth, across + 1)
    nodes = np.array([(x, y) for y in ys for x in xs])
    size = 2 * len(nodes)
    mass, stiffness = np.zeros((size, size)), np.zeros((size, size))
    for j in range(across):
        for i in range(along):
            ids = [j * (along + 1) + i, j * (along + 1) + i + 1, (j + 1) * (along + 1) + i + 1, (j + 1) * (along + 1) + i]
            k, m = element_matrices(nodes[ids], youngs, poisson, density, thickness)
            dofs = np.ravel([[2 * a, 2 * a + 1] for a in ids])
            stiffness[np.ix_(dofs, dofs)] += k
            mass[np.ix_(dofs, dofs)] += m
    return nodes, mass, stiffness


def node_at(nodes: np.ndarray, x: float, y: float) -> int:
    """The node at (x, y) [m]."""
    k = int(np.argmin(np.hypot(nodes[:, 0] - x, nodes[:, 1] - y)))
    assert np.hypot(*(nodes[k] - (x, y))) < 1e-12, (x, y)
    return k
