"""The sections of a spatial model file (``[model] kinematics = "spatial"``) and the core's spec they give.

A spatial model has spatial rigid bodies (``[bodies.NAME]`` with an inertia tensor, a 3-vector position and an
orientation), ground points and body points with frames, spatial joints and force elements; the keys are
defined in :mod:`jointplay.parameters` (``SPATIAL_*``) and read by :mod:`jointplay.orientation`. The core's spec
(all SI) holds them under ``spatial_bodies``, ``spatial_joints`` and ``spatial_forces``; ``bodies``, ``beams``,
``joints``, ``forces`` and ``sensors`` stay empty, and ``gravity`` has three components. Planar-only tables (a
clearance joint, a rotational spring, beams, modal bodies, sensors) get one located message each.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .. import parameters as p
from ..orientation import OrientationError, inertia_tensor, marker, quaternion, rotation_matrix
from . import schema as s
from .fields import did_you_mean, join
from .functions import function_spec

#: The sections of a spatial model's spec, besides those a planar model has (which stay empty).
SPATIAL_SECTIONS = ("spatial_bodies", "spatial_joints", "spatial_forces", "spatial_clearance_joints")


def empty_spec(name: str) -> dict[str, Any]:
    """The core's spec of a spatial model with nothing in it yet."""
    return {"name": name, "gravity": [0.0, 0.0, 0.0], "ground_points": [], "bodies": [], "beams": [], "joints": [],
            "drivers": [], "forces": [], "sensors": [], **{section: [] for section in SPATIAL_SECTIONS}}


def is_spatial(spec: dict) -> bool:
    """Whether a core spec describes a spatial model."""
    return spec.get("spatial_bodies") is not None


def kinematics_of(doc: dict) -> str:
    """``"spatial"`` when the document's ``[model] kinematics`` says so, else ``"planar"`` (a wrong word is
    reported by the planar ``[model]`` table)."""
    model = doc.get("model")
    raw = model.get("kinematics") if isinstance(model, dict) else None
    return "spatial" if isinstance(raw, str) and raw.strip().lower() == "spatial" else "planar"


def two_component_gravity(raw: Any) -> str:
    """The message for a planar gravity ``[gx, gy]`` in a spatial model, ``""`` for anything else."""
    if isinstance(raw, (list, tuple)) and len(raw) == 2:
        return (f'gravity needs 3 components in a spatial model, [gx, gy, gz] (e.g. [0, 0, "-9.81 m/s^2"]), got '
                f"{list(raw)!r}")
    return ""


# values of the spatial kinds ------------------------------------------------

def read_value(builder, param: p.Param, value: Any, location: str) -> Any:
    """The core's value of a key of a spatial kind (:data:`jointplay.parameters.SPATIAL_KINDS`), or None after
    adding located problems to ``builder``."""
    if param.kind == "vector3":
        return [float(v) for v in value]
    if param.kind == "function3":
        return _functions(builder, param, value, location)
    if param.kind == "markers":
        return marker_table(builder, value, location)
    if param.kind == "orientation" and value is param.default:
        return list(value)
    reader = {"orientation": quaternion, "inertia_tensor": inertia_tensor}[param.kind]
    try:
        return reader(value)
    except OrientationError as exc:
        builder.problem(join(location, *exc.at), exc.message)
        return None


def _functions(builder, param: p.Param, value: Any, location: str) -> list[dict] | None:
    if not isinstance(value, (list, tuple)) or len(value) != 3:
        example = p.unit(param) or "1"
        builder.problem(location, f'must be three components [x, y, z], each a quantity or a function of time (e.g. '
                                  f'["10 {example}", 0, 0]), got {value!r}')
        return None
    out = [function_spec(item, param.of, join(location, k), builder.problems) for k, item in enumerate(value)]
    return None if None in out else out


def marker_table(builder, raw: Any, where: str) -> list[dict]:
    """Named points, each ``["x", "y", "z"]`` or ``{ position = [...], axes = <orientation> }``, as the core's
    list ``{"name", "position", "axes"}``."""
    out = []
    for name, location, value in builder.named_points(raw, where, 'points, e.g. { A = ["0 mm", "10 mm", "5 mm"] }'):
        try:
            position, axes = marker(value)
        except OrientationError as exc:
            builder.problem(join(location, *exc.at), exc.message)
            continue
        out.append({"name": name, "position": position, "axes": axes})
    return out


# sections ---------------------------------------------------------------------

class SpatialSections:
    """Reads the sections of a spatial model file into ``builder.spec`` (a :class:`~.build.Builder`, whose
    helpers, names and problems it shares)."""

    def __init__(self, builder):
        self.b = builder

    def run(self) -> None:
        b = self.b
        b.spec = empty_spec(b.default_name)
        self.model_table()
        self.ground()
        self.bodies()
        self.planar_sections()
        self.joints()
        self.drivers()
        self.forces()
        b.simulation_table()
        self.connectivity()
        fill_free_lengths(b.spec)

    def model_table(self) -> None:
        b = self.b
        raw = dict(b.table("model"))
        pair = two_component_gravity(raw.get("gravity"))
        if pair:
            b.problem("model.gravity", pair)
            del raw["gravity"]
        table = b.validate(s.SpatialModelTable, raw, "model")
        if table is not None:
            b.spec["name"] = table.name if table.name is not None else b.default_name
            b.spec["gravity"] = [float(g) for g in table.gravity]

    def ground(self) -> None:
        b = self.b
        raw = b.table("ground")
        for key in raw:
            if key != "points":
                b.problem(join("ground", key), f"unknown key{did_you_mean(key, ['points'])}; allowed: points")
        given = raw.get("points", {})
        b.spec["ground_points"] = marker_table(b, given, "ground.points")
        b.points["ground"] = list(given) if isinstance(given, dict) else []

    def bodies(self) -> None:
        b = self.b
        for name, where, raw in b.entries("bodies"):
            b.claim(name, where)
            given = raw.get("points", {})
            points = marker_table(b, given, join(where, "points"))
            # every named point is known to references, read or not (its own message says what is wrong)
            b.points.setdefault(name, list(given) if isinstance(given, dict) else [])
            table = b.validate(s.SpatialBodyTable, raw, where, hint="spatial body: ")
            if table is None:
                continue
            if table.free:
                b.free.add(name)
            body = b.element_spec(p.SPATIAL_BODY, name, where, table, raw, {"points": points})
            if body is not None:
                b.spec["spatial_bodies"].append(body)

    def planar_sections(self) -> None:
        """Beams, modal bodies and sensors: one message for each entry."""
        b = self.b
        what = {"beams": "beams", "modal_bodies": "modal bodies", "sensors": "sensors (strain gauges of beams and "
                                                                             "modal bodies)"}
        for section, words in what.items():
            for name in b.table(section):
                b.problem(join(section, name), f"{words} are not available in spatial models")

    def planar_only(self, section: str, raw: dict, where: str) -> bool:
        """True, after a problem, for an element of a type that only planar models have."""
        kind = raw.get("type")
        if isinstance(kind, str) and kind in p.PLANAR_ONLY[section]:
            self.b.problem(join(where, "type"), f"{kind!r} is not available in spatial models".replace("'", '"'))
            return True
        return False

    def joints(self) -> None:
        self.elements("joints", s.SPATIAL_JOINTS, p.SPATIAL_JOINTS, "spatial_joints", " joint")

    def drivers(self) -> None:
        b = self.b
        for name, where, raw in b.entries("drivers"):
            b.claim(name, where)
            table = b.validate(s.DriverTable, raw, where)
            if table is None:
                continue
            kind = b.joint_types.get(table.joint)
            driven = p.SPATIAL_DRIVEN.get(kind)
            if driven is None:
                if kind is None:
                    b.problem(join(where, "joint"), f"no joint named {table.joint!r}"
                                                    f"{did_you_mean(table.joint, b.joint_types)}")
                else:
                    b.problem(join(where, "joint"), f"joint {table.joint!r} is a {kind} joint; only revolute, "
                                                    "cylindrical and translational joints can be driven")
                continue
            function = function_spec(table.function, driven, join(where, "function"), b.problems)
            if function is not None:
                b.spec["drivers"].append({"name": name, "joint": table.joint, "function": function})

    def forces(self) -> None:
        self.elements("forces", s.SPATIAL_FORCES, p.SPATIAL_FORCES, "spatial_forces", "")

    def elements(self, section: str, schemas: dict, tables: dict, spec_key: str, word: str) -> None:
        """The entries of ``section`` (``joints``, ``forces``), each validated by the schema of its ``type`` and
        added to the core's ``spec_key``; a planar-only type gets its message (joints' types are remembered for
        the drivers)."""
        b = self.b
        for name, where, raw in b.entries(section):
            b.claim(name, where)
            if self.planar_only(section, raw, where):
                continue
            kind = b.tagged(raw, "type", schemas, where)
            if kind is None:
                continue
            if section == "joints":
                b.joint_types[name] = kind
            table = b.validate(schemas[kind], raw, where, hint=f"{kind}{word}: ")
            element = None if table is None else b.element_spec(tables[kind], name, where, table, raw)
            if element is not None:
                b.spec[p.SPATIAL_JOINT_SECTIONS.get(kind, spec_key)].append(element)

    def connectivity(self) -> None:
        """A model without bodies, or a body that nothing refers to (unless ``free = true``), is a mistake."""
        b = self.b
        if not b.table("bodies"):
            b.problem("bodies", "the model has no bodies: describe at least one as a [bodies.NAME] table with its "
                                "mass and inertia tensor")
            return
        if any(problem.location.startswith(("joints", "forces")) for problem in b.problems):
            return  # references are incomplete; do not pile on
        for body in b.spec["spatial_bodies"]:
            if body["name"] not in b.referenced and body["name"] not in b.free:
                b.problem(join("bodies", body["name"]), "is connected to nothing: no joint or force element refers "
                                                        "to it (write free = true if it is meant to move freely)")


# geometry of the description ------------------------------------------------------

def point_position(spec: dict, ref: str) -> np.ndarray | None:
    """The global position [m] of the point ``"body.point"`` as described (before assembly); None when the
    body or point is not in the spec."""
    body_name, _, point_name = ref.partition(".")
    if body_name == "ground":
        found = [pt for pt in spec.get("ground_points", []) if pt["name"] == point_name]
        return np.array(found[0]["position"], dtype=float) if found else None
    for body in spec.get("spatial_bodies") or []:
        if body["name"] == body_name:
            found = [pt for pt in body["points"] if pt["name"] == point_name]
            if not found:
                return None
            rotation = rotation_matrix(body["orientation"])
            return np.array(body["position"], dtype=float) + rotation @ np.array(found[0]["position"], dtype=float)
    return None


def fill_free_lengths(spec: dict) -> None:
    """Gives each spatial spring without a ``free_length`` the distance of its two points as described (the
    contract of the core's spec: the front end sends every value); one whose points are unknown is left for the
    core to report."""
    for force in spec.get("spatial_forces") or []:
        if force.get("type") != "spring_damper" or force.get("free_length") is not None:
            continue
        first, second = point_position(spec, force["first"]), point_position(spec, force["second"])
        if first is not None and second is not None:
            force["free_length"] = float(math.dist(first, second))


__all__ = ["SPATIAL_SECTIONS", "SpatialSections", "empty_spec", "fill_free_lengths", "is_spatial",
           "kinematics_of", "marker_table", "point_position", "read_value", "two_component_gravity"]
