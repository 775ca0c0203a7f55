"""Geometry of a planar model at each frame, from the results alone (pure numpy).

Rigid bodies are posed from their ``x``, ``y``, ``angle`` channels; beams from their node channels
``<beam>.node<k>_x/_y``; modal bodies from ``results.geometry`` and their ``eta<k>`` channels; clearance
joints from their eccentricity ``ex``, ``ey`` (journal centre from bearing centre, global frame [m])
and the force of the joint on the journal ``fx``, ``fy`` (global [N]).
"""

from __future__ import annotations

import numpy as np

from ..errors import ModelError
from .frame import FrameGeometry, block, convex_outline, rotation
from .sampling import Sampled


class PlanarModel:
    """Draws a planar model's frames. ``scales`` holds ``clearance`` [-], ``deformation`` [-],
    ``force`` [m per N] and ``block`` (side of a one-point body's square [m])."""

    def __init__(self, spec: dict, geometry: dict, sampled: Sampled):
        self.spec = spec
        self.sampled = sampled
        self.ground_points = {p["name"]: np.asarray(p["position"], dtype=float) for p in spec.get("ground_points", [])}
        self.bodies = {b["name"]: b for b in spec.get("bodies", [])}
        self.beams = {b["name"]: b for b in spec.get("beams", [])}
        self.modal = {b["name"]: b for b in spec.get("modal_bodies", [])}
        self.modal_geometry = {name: {key: np.asarray(value, dtype=float) for key, value in g.items()}
                               for name, g in (geometry or {}).get("modal_bodies", {}).items() if name in self.modal}
        self.edges = {name: np.asarray(g.get("edges", []), dtype=int).reshape(-1, 2)
                      for name, g in (geometry or {}).get("modal_bodies", {}).items() if name in self.modal}
        missing = [name for name in self.modal if name not in self.modal_geometry]
        if missing:
            raise ModelError([(f"modal_bodies.{name}", "the results carry no mesh of it (geometry_json; files "
                                                       "written before it existed): run the model again to "
                                                       "animate it") for name in missing])
        self.beam_nodes = {name: _node_count(sampled, name) for name in self.beams}
        self.clearance = [j for j in spec.get("joints", []) if j["type"] == "clearance_revolute"]

    # poses ------------------------------------------------------------------

    def pose(self, k: int, body: str) -> tuple[np.ndarray, float]:
        """Position of the body's frame [m] and its angle [rad] at frame k."""
        at = self.sampled.at
        return np.array([at(k, f"{body}.x"), at(k, f"{body}.y")]), at(k, f"{body}.angle")

    def body_points(self, k: int, body: str) -> np.ndarray:
        """The rigid body's points posed at frame k, in the spec's order, (n, 2) [m]."""
        r, angle = self.pose(k, body)
        local = np.array([p["position"] for p in self.bodies[body].get("points", [])], dtype=float).reshape(-1, 2)
        return r + local @ rotation(angle).T

    def beam_nodes_drawn(self, k: int, beam: str, scale: float) -> np.ndarray:
        """The beam's nodes at frame k with their deformation from the chord magnified by ``scale``:
        the straight reference beam moved rigidly so that its first-to-last chord lies on the current
        one (same first node, same direction), plus ``scale`` times each node's offset from there."""
        n = self.beam_nodes[beam]
        current = np.array([[self.sampled.at(k, f"{beam}.node{i}_x"), self.sampled.at(k, f"{beam}.node{i}_y")]
                            for i in range(n)])
        spec = self.beams[beam]
        start, end = np.asarray(spec["start"], dtype=float), np.asarray(spec["end"], dtype=float)
        reference = start + np.linspace(0.0, 1.0, n)[:, None] * (end - start)
        chord, reference_chord = current[-1] - current[0], end - start
        turn = np.arctan2(chord[1], chord[0]) - np.arctan2(reference_chord[1], reference_chord[0])
        rigid = current[0] + (reference - start) @ rotation(turn).T
        return rigid + scale * (current - rigid)

    def modal_nodes_drawn(self, k: int, body: str, scale: float) -> np.ndarray:
        """The modal body's nodes at frame k: ``r + A(angle) (node + scale * shapes @ eta)`` [m]."""
        g = self.modal_geometry[body]
        r, angle = self.pose(k, body)
        shapes = g["shapes"]  # (nodes, 2, modes)
        eta = np.array([self.sampled.at(k, f"{body}.eta{i + 1}") for i in range(shapes.shape[2])])
        local = g["nodes"] + scale * shapes @ eta if shapes.size else g["nodes"]
        return r + local @ rotation(angle).T

    # points -----------------------------------------------------------------

    def point(self, k: int, ref: str, deformation: float) -> np.ndarray:
        """Drawn position [m] of ``"body.point"`` at frame k (on a beam or a modal body: on its drawn,
        magnified shape)."""
        owner, _, name = ref.partition(".")
        if owner == "ground":
            return self.ground_points[name]
        if owner in self.bodies:
            r, angle = self.pose(k, owner)
            local = next(p["position"] for p in self.bodies[owner]["points"] if p["name"] == name)
            return r + rotation(angle) @ np.asarray(local, dtype=float)
        if owner in self.beams:
            return self._beam_point(k, owner, name, deformation)
        return self._modal_point(k, owner, name, deformation)

    def _beam_point(self, k: int, beam: str, name: str, deformation: float) -> np.ndarray:
        nodes = self.beam_nodes_drawn(k, beam, deformation)
        spec = self.beams[beam]
        length = float(np.hypot(*(np.asarray(spec["end"]) - np.asarray(spec["start"]))))
        named = {p["name"]: p["arclength"] for p in spec.get("points", [])}
        s = {"start": 0.0, "end": length}.get(name, named.get(name, 0.0))
        return _along(nodes, np.linspace(0.0, length, len(nodes)), s)

    def _modal_point(self, k: int, body: str, name: str, deformation: float) -> np.ndarray:
        nodes = self.modal_nodes_drawn(k, body, deformation)
        spec = self.modal[body]
        entry = next(p for p in [*spec.get("interface", []), *spec.get("points", [])] if p["name"] == name)
        if entry.get("node") is not None:
            return nodes[int(entry["node"])]
        reference = self.modal_geometry[body]["nodes"]
        arclength = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(reference, axis=0).T))])
        return _along(nodes, arclength, float(entry["arclength"]))

    # the frame --------------------------------------------------------------

    def frame(self, k: int, scales: dict) -> FrameGeometry:
        """Everything drawn at frame k."""
        g = FrameGeometry(time=float(self.sampled.times[k]))
        deformation = scales["deformation"]
        for name in self.bodies:
            outline = convex_outline(self.body_points(k, name))
            if len(outline) <= 1:  # one point (or none): a small block there
                r, angle = self.pose(k, name)
                outline = block(outline[0] if len(outline) else r, angle, scales["block"])
            g.bodies[name] = outline
        for name in self.beams:
            g.beams[name] = self.beam_nodes_drawn(k, name, deformation)
        for name in self.modal_geometry:
            g.meshes[name] = self.modal_nodes_drawn(k, name, deformation)
        g.ground = np.array(list(self.ground_points.values())).reshape(-1, 2)
        self._joints(k, g, scales)
        self._forces(k, g, deformation)
        self._clearance(k, g, scales)
        return g

    def _joints(self, k: int, g: FrameGeometry, scales: dict) -> None:
        pins = []
        for joint in self.spec.get("joints", []):
            if joint["type"] == "clearance_revolute":
                continue
            first = self.point(k, joint["first"], scales["deformation"])
            if joint["type"] == "translational":
                g.guides[joint["name"]] = self._guide(k, joint, first, scales)
            else:
                pins.append(first)
        g.pins = np.array(pins).reshape(-1, 2)

    def _guide(self, k: int, joint: dict, first: np.ndarray, scales: dict) -> np.ndarray:
        """The guide of a translational joint: a segment of length ``scales["guide"]`` [m] on the line
        through its first point along its axis (turned with the first body), centred at the foot of
        the second point."""
        owner = joint["first"].partition(".")[0]
        axis = np.asarray(joint.get("axis", (1.0, 0.0)), dtype=float)
        if owner in self.bodies or owner in self.modal:
            axis = rotation(self.pose(k, owner)[1]) @ axis
        axis = axis / np.hypot(*axis)
        second = self.point(k, joint["second"], scales["deformation"])
        foot = first + np.dot(second - first, axis) * axis
        return np.vstack([foot - 0.5 * scales["guide"] * axis, foot + 0.5 * scales["guide"] * axis])

    def _forces(self, k: int, g: FrameGeometry, deformation: float) -> None:
        for force in self.spec.get("forces", []):
            ends = [force.get("first"), force.get("second")]
            if all(isinstance(end, str) and "." in end for end in ends):
                g.forces[force["name"]] = np.vstack([self.point(k, end, deformation) for end in ends])

    def _clearance(self, k: int, g: FrameGeometry, scales: dict) -> None:
        for joint in self.clearance:
            name = joint["name"]
            centre = self.point(k, joint["bearing"], scales["deformation"])
            e = np.array([self.sampled.at(k, f"{name}.ex"), self.sampled.at(k, f"{name}.ey")])
            bore, journal = drawn_radii(joint["bearing_radius"], joint["clearance"], scales["clearance"])
            journal_centre = centre + scales["clearance"] * e
            g.bores[name] = (centre, bore)
            g.journals[name] = (journal_centre, journal)
            f = np.array([self.sampled.at(k, f"{name}.fx"), self.sampled.at(k, f"{name}.fy")])
            vector = scales["force"] * f  # the force on the journal, pushing it in: its tip at the contact point
            g.arrows[name] = (contact_point(centre, e, bore) - vector, vector)


def drawn_radii(bearing_radius: float, clearance: float, scale: float) -> tuple[float, float]:
    """Drawn radii [m] of a bore and its journal, their gap ``scale * clearance``: the bore at its true
    radius while the magnified gap is at most half of it, else at twice the magnified gap."""
    gap = scale * clearance
    bore = bearing_radius if gap <= 0.5 * bearing_radius else 2.0 * gap
    return bore, bore - gap


def contact_point(centre: np.ndarray, e: np.ndarray, bore: float) -> np.ndarray:
    """Where the journal meets the drawn bore along the line of centres (the bore's centre when the
    eccentricity is zero) [m]."""
    length = float(np.hypot(*e))
    return centre + (bore * e / length if length > 0.0 else 0.0)


def _node_count(sampled: Sampled, beam: str) -> int:
    count = 0
    while f"{beam}.node{count}_x" in sampled:
        count += 1
    return count


def _along(nodes: np.ndarray, arclength: np.ndarray, s: float) -> np.ndarray:
    """The point at arclength ``s`` [m] of a polyline whose nodes sit at ``arclength``, linearly between nodes."""
    return np.array([np.interp(s, arclength, nodes[:, 0]), np.interp(s, arclength, nodes[:, 1])])
