"""Geometry of a spatial model at each frame, projected on a plane (pure numpy).

Bodies are posed from their ``x``, ``y``, ``z`` and unit quaternion ``qw``, ``qx``, ``qy``, ``qz``
channels (the interpolated quaternion normalised); a marker's axes are the columns of its ``axes``
matrix in its body's frame. A spatial clearance joint's offsets ``e_a_x``, ``e_a_y`` (rim A, s = -L/2)
and ``e_b_x``, ``e_b_y`` (rim B, s = +L/2) are in the bearing marker's frame [m]; its force on the
journal ``fx``, ``fy``, ``fz`` is global [N].
"""

from __future__ import annotations

import numpy as np

from .frame import FrameGeometry, block, convex_outline
from .planar import drawn_radii
from .sampling import Sampled

#: Points of a drawn circle (the first repeated at the end).
CIRCLE_POINTS = 48

#: Rows: the drawing plane's horizontal and vertical axes in global coordinates, per projection.
#: ``iso`` looks from (1, 1, 1) towards the origin with z up.
PROJECTIONS = {
    "xy": np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]),
    "xz": np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]),
    "yz": np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]),
    "iso": np.array([[-1.0, 1.0, 0.0], [-1.0, -1.0, 2.0]]) / np.array([[np.sqrt(2.0)], [np.sqrt(6.0)]]),
}


def quaternion_matrix(q: np.ndarray) -> np.ndarray:
    """Rotation matrix of the quaternion ``(w, x, y, z)``, normalised first."""
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


class SpatialModel:
    """Draws a spatial model's frames projected by ``projection`` (a key of :data:`PROJECTIONS`)."""

    def __init__(self, spec: dict, sampled: Sampled, projection: str):
        self.spec = spec
        self.sampled = sampled
        self.plane = PROJECTIONS[projection]
        self.ground = {p["name"]: p for p in spec.get("ground_points", [])}
        self.bodies = {b["name"]: b for b in spec.get("spatial_bodies", [])}
        self.clearance = list(spec.get("spatial_clearance_joints", []))

    def pose(self, k: int, body: str) -> tuple[np.ndarray, np.ndarray]:
        """Position [m] and rotation matrix of the body at frame k (identity for the ground)."""
        if body == "ground":
            return np.zeros(3), np.eye(3)
        at = self.sampled.at
        r = np.array([at(k, f"{body}.{c}") for c in "xyz"])
        return r, quaternion_matrix([at(k, f"{body}.q{c}") for c in "wxyz"])

    def marker(self, k: int, ref: str) -> tuple[np.ndarray, np.ndarray]:
        """Global position [m] of the point ``"body.point"`` at frame k and its axes (columns, global)."""
        owner, _, name = ref.partition(".")
        entry = self.ground[name] if owner == "ground" else \
            next(p for p in self.bodies[owner]["points"] if p["name"] == name)
        r, rotation = self.pose(k, owner)
        axes = np.eye(3) if entry.get("axes") is None else np.asarray(entry["axes"], dtype=float)
        return r + rotation @ np.asarray(entry["position"], dtype=float), rotation @ axes

    def project(self, points: np.ndarray) -> np.ndarray:
        """Global points (n, 3) or (3,) [m] on the drawing plane."""
        return np.asarray(points, dtype=float) @ self.plane.T

    def frame(self, k: int, scales: dict) -> FrameGeometry:
        """Everything drawn at frame k, projected."""
        g = FrameGeometry(time=float(self.sampled.times[k]))
        for name, body in self.bodies.items():
            r, rotation = self.pose(k, name)
            local = np.array([p["position"] for p in body.get("points", [])], dtype=float).reshape(-1, 3)
            outline = convex_outline(self.project(r + local @ rotation.T))
            g.bodies[name] = outline if len(outline) > 1 else block(
                outline[0] if len(outline) else self.project(r), 0.0, scales["block"])
        g.ground = self.project(np.array([p["position"] for p in self.ground.values()], dtype=float).reshape(-1, 3))
        self._joints(k, g, scales)
        for force in self.spec.get("spatial_forces", []):
            ends = [force.get("first"), force.get("second")]
            if all(isinstance(end, str) and "." in end for end in ends):
                g.forces[force["name"]] = self.project(np.vstack([self.marker(k, end)[0] for end in ends]))
        for joint in self.clearance:
            self._clearance(k, joint, g, scales)
        return g

    def _joints(self, k: int, g: FrameGeometry, scales: dict) -> None:
        pins = []
        for joint in self.spec.get("spatial_joints", []):
            first, axes = self.marker(k, joint["first"])
            if joint["type"] in ("translational", "cylindrical"):
                second = self.marker(k, joint["second"])[0]
                axis = axes[:, 2]
                foot = first + np.dot(second - first, axis) * axis
                half = 0.5 * scales["guide"] * axis
                g.guides[joint["name"]] = self.project(np.vstack([foot - half, foot + half]))
            else:
                pins.append(self.project(first))
        g.pins = np.array(pins).reshape(-1, 2)

    def _clearance(self, k: int, joint: dict, g: FrameGeometry, scales: dict) -> None:
        """The bore's axis from rim A to rim B and its circles there, the journal's axis through the rims'
        offset centres with the offsets magnified by the clearance scale and its circles there (the drawn gap
        the clearance times the same scale), and the joint's force at the journal's middle."""
        name, at = joint["name"], self.sampled.at
        centre, axes = self.marker(k, joint["bearing"])
        half = 0.5 * joint["bearing_length"] * axes[:, 2]
        rims = np.vstack([centre - half, centre + half])
        offsets = np.array([[at(k, f"{name}.e_{end}_x"), at(k, f"{name}.e_{end}_y")] for end in "ab"])
        journal = rims + scales["clearance"] * offsets @ axes[:, :2].T
        g.bore_axes[name] = self.project(rims)
        g.journal_axes[name] = self.project(journal)
        bore, journal_radius = drawn_radii(joint["bore_radius"], joint["clearance"], scales["clearance"])
        g.bore_rims[name] = self._circles(rims, bore, axes)
        g.journal_rims[name] = self._circles(journal, journal_radius, axes)
        force = np.array([at(k, f"{name}.f{c}") for c in "xyz"])
        g.arrows[name] = (self.project(journal.mean(axis=0)), scales["force"] * self.project(force))

    def _circles(self, centres: np.ndarray, radius: float, axes: np.ndarray) -> np.ndarray:
        """Circles of ``radius`` [m] about each of ``centres`` (global), in the plane of the bearing marker's x
        and y ``axes`` (columns), projected; one closed polyline each, separated by a row of NaN."""
        angles = np.linspace(0.0, 2.0 * np.pi, CIRCLE_POINTS + 1)
        ring = radius * (np.outer(np.cos(angles), axes[:, 0]) + np.outer(np.sin(angles), axes[:, 1]))
        gap = np.full((1, 2), np.nan)
        return np.vstack([part for centre in centres for part in (self.project(centre + ring), gap)][:-1])
