"""What one frame of an animation shows, as plain arrays in the drawing plane [m] (pure numpy).

A planar model is drawn in its own plane; a spatial one projected on the chosen plane
(:mod:`jointplay.animation.spatial`). Every array is in metres of the drawing plane, (n, 2).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass
class FrameGeometry:
    """The drawn shapes of one frame, keyed by the name of the element they show."""

    #: time of the frame [s]
    time: float
    #: outline of each rigid body through its points (a closed polygon when it has three or more)
    bodies: dict[str, np.ndarray] = field(default_factory=dict)
    #: polyline through each beam's drawn nodes (deformation magnified)
    beams: dict[str, np.ndarray] = field(default_factory=dict)
    #: drawn nodes of each modal body (deformation magnified); its mesh lines are in :attr:`Scene.edges`
    meshes: dict[str, np.ndarray] = field(default_factory=dict)
    #: ground points
    ground: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    #: points of the joints drawn as small circles (revolute, spherical, universal, fixed ...)
    pins: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    #: guide line of each translational joint, its two ends
    guides: dict[str, np.ndarray] = field(default_factory=dict)
    #: line of each force element between its two points
    forces: dict[str, np.ndarray] = field(default_factory=dict)
    #: bore of each planar clearance joint: (centre (2,), drawn radius)
    bores: dict[str, tuple[np.ndarray, float]] = field(default_factory=dict)
    #: journal of each planar clearance joint: (centre (2,) offset by the magnified eccentricity, drawn radius)
    journals: dict[str, tuple[np.ndarray, float]] = field(default_factory=dict)
    #: axis of the bore of each spatial clearance joint, from rim A to rim B
    bore_axes: dict[str, np.ndarray] = field(default_factory=dict)
    #: axis of the journal of each spatial clearance joint at rims A and B, offsets magnified
    journal_axes: dict[str, np.ndarray] = field(default_factory=dict)
    #: the bore's circles at rims A and B of each spatial clearance joint, projected: two closed polylines
    #: separated by a row of NaN (the drawn radius, as a planar joint's bore)
    bore_rims: dict[str, np.ndarray] = field(default_factory=dict)
    #: the journal's circles at rims A and B, centred on :attr:`journal_axes`' ends, drawn gap
    #: ``clearance_scale * clearance`` (two closed polylines separated by a row of NaN)
    journal_rims: dict[str, np.ndarray] = field(default_factory=dict)
    #: force of each clearance joint on its journal: (start (2,), drawn vector (2,) = force_scale * f); planar:
    #: the tip at the contact point on the drawn bore, spatial: the start at the middle of the journal's axis
    arrows: dict[str, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)

    def points(self) -> np.ndarray:
        """Every drawn point of the frame, (n, 2): what the view must hold."""
        parts = [*self.bodies.values(), *self.beams.values(), *self.meshes.values(), self.ground, self.pins,
                 *self.guides.values(), *self.forces.values(), *self.bore_axes.values(), *self.journal_axes.values(),
                 *self.bore_rims.values(), *self.journal_rims.values()]
        for centre, radius in [*self.bores.values(), *self.journals.values()]:
            parts.append(centre + radius * np.array([[1.0, 1.0], [-1.0, -1.0]]))
        for start, vector in self.arrows.values():
            parts.append(np.vstack([start, start + vector]))
        parts = [np.reshape(p, (-1, 2)) for p in parts if np.size(p)]
        points = np.vstack(parts) if parts else np.zeros((0, 2))
        return points[~np.isnan(points).any(axis=1)]  # (the NaN rows that separate two polylines)


def convex_outline(points: np.ndarray) -> np.ndarray:
    """The outline of a body through its drawn points (n, 2): the points themselves when there are at
    most two distinct ones (in the given order); else their convex hull, closed (first point repeated),
    counter-clockwise (Andrew's monotone chain)."""
    distinct = _distinct(points)
    if len(distinct) <= 2:
        return distinct
    order = sorted(range(len(distinct)), key=lambda k: (distinct[k, 0], distinct[k, 1]))
    ordered = distinct[order]

    def half(sequence):
        chain: list[np.ndarray] = []
        for p in sequence:
            while len(chain) >= 2 and _cross(chain[-2], chain[-1], p) <= 0.0:
                chain.pop()
            chain.append(p)
        return chain

    lower, upper = half(ordered), half(ordered[::-1])
    hull = np.array(lower[:-1] + upper[:-1])
    return hull if len(hull) <= 2 else np.vstack([hull, hull[:1]])


def _distinct(points: np.ndarray) -> np.ndarray:
    """``points`` without repeats (first occurrences, in order); points closer than 1e-9 of the largest
    coordinate count as one."""
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    tolerance = 1e-9 * max(1.0, float(np.max(np.abs(points)))) if len(points) else 0.0
    kept: list[np.ndarray] = []
    for p in points:
        if all(np.max(np.abs(p - q)) > tolerance for q in kept):
            kept.append(p)
    return np.array(kept).reshape(-1, 2)


def _cross(o: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    return float((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]))


def block(centre: np.ndarray, angle: float, side: float) -> np.ndarray:
    """A closed square of side ``side`` [m] centred on ``centre``, turned by ``angle`` [rad]: how a body
    with a single point is drawn."""
    corners = 0.5 * side * np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0]])
    return np.asarray(centre) + corners @ rotation(angle).T


def rotation(angle: float) -> np.ndarray:
    """The planar rotation matrix of ``angle`` [rad]."""
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s], [s, c]])
