"""The model of a run as report tables, read from the results file's model (``results.spec``, SI units).

Each element's parameters are listed with their units, taken from the definition of each table in
:mod:`jointplay.parameters` (the kind of each key) and :mod:`jointplay.units` (the SI unit of each kind):
lengths are shown in mm and angles in degrees (:data:`SHOWN`), every other quantity in its SI unit, and each
row states its unit. Keys the definition does not know are shown as they are, without a unit.
"""

from __future__ import annotations

import math
from typing import Any

from .. import parameters as P
from ..units import KINDS, per_time
from .blocks import Section, Table, Text

#: Kinds shown in another unit than SI: kind -> (unit, factor from SI).
SHOWN = {"length": ("mm", 1e3), "angle": ("deg", 180.0 / math.pi)}
#: The tables of the elements of each section of the core's model (the tag of each entry picks its variant).
ELEMENT_TABLES = {"joints": P.JOINTS, "forces": P.FORCES, "sensors": P.SENSORS,
                  "spatial_joints": P.SPATIAL_JOINTS, "spatial_clearance_joints": P.SPATIAL_JOINTS,
                  "spatial_forces": P.SPATIAL_FORCES}
#: Plain tables (one definition for every entry of the section).
PLAIN_TABLES = {"drivers": P.DRIVER, "beams": P.BEAM, "modal_bodies": P.MODAL_BODY, "bodies": P.BODY,
                "spatial_bodies": P.SPATIAL_BODY}
#: Titles of the sections of the model, in the order they are shown.
TITLES = {"bodies": "Model: bodies", "spatial_bodies": "Model: bodies (spatial)", "beams": "Model: beams",
          "modal_bodies": "Model: modal bodies", "joints": "Model: joints", "spatial_joints": "Model: joints (spatial)",
          "spatial_clearance_joints": "Model: clearance joints (spatial)", "drivers": "Model: drivers",
          "forces": "Model: forces", "spatial_forces": "Model: forces (spatial)", "sensors": "Model: sensors"}
#: What one entry of each section is called in a caption.
SINGULAR = {"beams": "Beam", "modal_bodies": "Modal body", "joints": "Joint", "spatial_clearance_joints": "Joint",
            "drivers": "Driver", "forces": "Force", "spatial_forces": "Force", "sensors": "Sensor"}
#: Joint types that are clearance joints (each gets its own table of parameters).
CLEARANCE_TYPES = ("clearance_revolute", "spatial_clearance_revolute")
#: Keys that name an entry rather than describe it.
NAMING_KEYS = ("name", "type")


def quantity(value: Any, kind: str) -> tuple[Any, str]:
    """``(value shown, unit)`` of a value in SI units of ``kind`` (a number or a list of numbers)."""
    spec = KINDS.get(kind)
    if spec is None:
        return value, ""
    unit, factor = SHOWN.get(kind, (spec.si.replace("*", " "), 1.0))
    if isinstance(value, (list, tuple)):
        return "(" + ", ".join(_number(v, factor) for v in value) + ")", unit
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return float(value) * factor, unit
    return value, unit


def _number(value: Any, factor: float) -> str:
    if isinstance(value, (list, tuple)):
        return "(" + ", ".join(_number(v, factor) for v in value) + ")"
    return f"{float(value) * factor:.6g}" if isinstance(value, (int, float)) else str(value)


def parameter_rows(table: P.Table | None, entry: dict, prefix: str = "", value_kind: str | None = None) -> list[list]:
    """Rows ``[parameter, value, unit]`` of one element (``entry``, as in the core's model) by the definition
    ``table``; nested laws and tables follow with dotted names (``contact.restitution``). ``value_kind`` is the
    kind of a function's ``value`` (the coordinate a driver prescribes)."""
    rows: list[list] = []
    known = {p.key: p for p in table.params} if table is not None else {}
    for key, value in entry.items():
        if key in NAMING_KEYS and not prefix:
            continue
        param = known.get(key)
        name = prefix + key
        if param is None:
            rows.append([name, _plain(value), ""])
        elif value is None:
            rows.append([name, param.default_text or "none", ""])
        else:
            rows += _param_rows(param, name, value, value_kind)
    return rows


def _param_rows(param: P.Param, name: str, value: Any, value_kind: str | None) -> list[list]:
    kind = param.kind
    if kind == "law" and isinstance(value, dict):
        law = P.tagged_law(value, param.of)
        definition = P.LAWS[param.of].get(law.get("law"))
        return [[f"{name}.law", law.get("law", ""), ""],
                *parameter_rows(definition, {k: v for k, v in law.items() if k != "law"}, f"{name}.")]
    if kind == "table" and isinstance(value, dict) and isinstance(param.of, P.Table):
        return parameter_rows(param.of, value, f"{name}.")
    if kind == "variant" and isinstance(value, dict):
        tables = P.VARIANTS.get(param.of, {})
        tag = next((t.tag for t in tables.values()), None)
        tag = tag if tag in value else next((k for k in ("type", "kind") if k in value), tag)  # the core's key
        definition = tables.get(value.get(tag)) if tag else None
        return [[f"{name}.{tag}", value.get(tag, ""), ""],
                *parameter_rows(definition, {k: v for k, v in value.items() if k != tag}, f"{name}.")]
    if kind == "function" and isinstance(value, dict):
        definition = P.FUNCTIONS.get(value.get("kind"))
        rows = [[f"{name}.kind", value.get("kind", ""), ""]]
        for key, item in value.items():
            if key == "kind":
                continue
            sub = definition[key] if definition is not None and key in definition.keys() else None
            rows.append([f"{name}.{key}", *_function_value(sub, item, value_kind)])
        return rows
    if kind in ("vector", "vector3", "list") and isinstance(param.of, str) and param.of in KINDS:
        return [[name, *quantity(value, param.of)]]
    if kind in KINDS:
        return [[name, *quantity(value, kind)]]
    return [[name, _plain(value), ""]]


def _function_value(param: P.Param | None, value: Any, value_kind: str | None) -> tuple[Any, str]:
    """A parameter of a function of time: ``value`` and ``rate`` in the units of the prescribed coordinate."""
    if param is None or value_kind is None:
        return _plain(value), ""
    kind = {"value": value_kind, "rate": per_time(value_kind, 1).name}.get(param.kind, param.kind)
    if param.kind == "list" and param.of in ("time", "value"):
        kind = value_kind if param.of == "value" else "time"
    if kind in KINDS:
        return quantity(value, kind)
    return _plain(value), ""


def _plain(value: Any) -> Any:
    """A value without a unit: numbers stay numbers, lists and tables as compact text."""
    if isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {_plain(v)}" for k, v in value.items()) + " }"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(str(_plain(v)) for v in value) + "]"
    return str(value)


def model_sections(spec: dict | None, geometry: dict | None = None) -> list[Section]:
    """The model: its gravity and ground points, then each section of elements with their parameters."""
    if not spec:
        return [Section("Model", [Text("The results carry no model description.")])]
    blocks = [Text(f"Model {spec.get('name', '')!r}: lengths in mm and angles in degrees, every other quantity "
                   "in SI units, each row with its unit.")]
    gravity, unit = quantity(spec.get("gravity", []), "acceleration")
    blocks.append(Table(["quantity", "value", "unit"], [["gravity", gravity, unit]], "Gravity"))
    ground = spec.get("ground_points", [])
    if ground:
        blocks.append(Table(["ground point", "position [mm]"],
                            [[g["name"], quantity(g["position"], "length")[0]] for g in ground], "Ground points"))
    sections = [Section("Model", blocks)]
    for key, title in TITLES.items():
        entries = [e for e in spec.get(key, []) if isinstance(e, dict)]
        if entries:
            sections.append(Section(title, _element_tables(key, entries, spec)))
    meshes = (geometry or {}).get("modal_bodies") or {}
    if meshes:
        sections.append(Section("Model: modal meshes", [_meshes_table(meshes)]))
    return sections


def _meshes_table(meshes: dict) -> Table:
    """Nodes, modes and mesh lines of each modal body, as the results file carries them for drawing."""
    rows = []
    for name, mesh in meshes.items():
        shapes = mesh.get("shapes") or []
        modes = len(shapes[0][0]) if shapes and shapes[0] and shapes[0][0] else 0
        rows.append([name, len(mesh.get("nodes", [])), modes, len(mesh.get("edges", []))])
    return Table(["modal body", "nodes", "modes", "mesh lines"], rows,
                 "Meshes of the modal bodies (reference nodes in the body frame and their mode shapes)")


def _element_tables(key: str, entries: list[dict], spec: dict) -> list:
    if key in ("bodies", "spatial_bodies"):
        return [_bodies_table(entries), *(_points_table(e) for e in entries if e.get("points"))]
    if key == "joints":
        ideal = [e for e in entries if e.get("type") not in CLEARANCE_TYPES]
        blocks = [_joints_table(ideal)] if ideal else []
        return blocks + [_element_table(key, e, spec) for e in entries if e.get("type") in CLEARANCE_TYPES]
    if key == "spatial_joints":
        return [_joints_table(entries)]
    return [_element_table(key, e, spec) for e in entries]


def _bodies_table(bodies: list[dict]) -> Table:
    """Mass, inertia and initial position of each rigid body."""
    rows = []
    for body in bodies:
        inertia = body.get("inertia")
        rows.append([body["name"], body.get("mass"), inertia if not isinstance(inertia, list) else _plain(inertia),
                     quantity(body.get("position", []), "length")[0]])
    return Table(["body", "mass [kg]", "inertia about the centre of mass [kg m^2]", "initial position [mm]"], rows,
                 "Rigid bodies (the body frame at the centre of mass; the position is approximate, assembly makes "
                 "it consistent)")


def _points_table(body: dict) -> Table:
    rows = [[p["name"], quantity(p["position"], "length")[0]] for p in body.get("points", [])]
    return Table(["point", "position in the body frame [mm]"], rows, f"Named points of {body['name']}")


def _joints_table(joints: list[dict]) -> Table:
    rows = [[j["name"], j.get("type", ""), j.get("first", ""), j.get("second", ""),
             "; ".join(f"{r[0]} = {r[1]} {r[2]}".strip()
                       for r in parameter_rows(ELEMENT_TABLES["joints"].get(j.get("type")), j)
                       if r[0] not in ("first", "second"))] for j in joints]
    return Table(["joint", "type", "first", "second", "other parameters"], rows, "Ideal joints")


def _element_table(key: str, entry: dict, spec: dict) -> Table:
    """The parameters of one element, a row each with its unit."""
    definition = ELEMENT_TABLES[key].get(entry.get("type")) if key in ELEMENT_TABLES else PLAIN_TABLES.get(key)
    value_kind = _driven_kind(entry, spec) if key == "drivers" else None
    rows = parameter_rows(definition, entry, value_kind=value_kind)
    kind = f" ({entry['type']})" if entry.get("type") else ""
    return Table(["parameter", "value", "unit"], rows, f"{SINGULAR.get(key, key)} {entry.get('name', '')}{kind}")


def _driven_kind(driver: dict, spec: dict) -> str | None:
    """The kind of the coordinate a driver prescribes: an angle (revolute joint) or a length (translational)."""
    joints = {j["name"]: j for j in [*spec.get("joints", []), *spec.get("spatial_joints", [])]}
    joint_type = joints.get(driver.get("joint"), {}).get("type")
    return {"revolute": "angle", "translational": "length", "cylindrical": "length"}.get(joint_type)
