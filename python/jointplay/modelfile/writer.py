"""Writing a model description back to model-file TOML.

Numbers are written in SI units with the unit spelled out (``"0.025 m"``)
and with every digit (``repr``), so that loading the text again gives the
same floats and therefore the same simulation, bit for bit.
"""

from __future__ import annotations

import math
import re
from typing import Any

from .. import parameters as p
from ..units import KINDS, per_time

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")
FUNCTION_VALUE = {"revolute": "angle", "translational": "length"}


def _key(key: str) -> str:
    return key if _BARE_KEY.match(key) else _string(key)


def _string(text: str) -> str:
    out = text.replace("\\", "\\\\").replace('"', '\\"')
    out = "".join(c if ord(c) >= 0x20 and c != "\x7f" else f"\\u{ord(c):04x}" for c in out)
    return f'"{out}"'


def _number(value: float) -> str:
    value = float(value)
    if math.isnan(value):
        return "nan"
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    return repr(value)


class Raw(str):
    """Text written as it is (an already formatted TOML value)."""


def quantity(value: float, kind: str | Any) -> Raw:
    """``"0.025 m"``: an SI value with its unit, or a plain number for dimensionless kinds."""
    spec = KINDS[kind] if isinstance(kind, str) else kind
    unit = spec.si.replace("*", " ")
    if not unit:
        return Raw(_number(value))
    return Raw(_string(f"{_number(value)} {unit}"))


def _value(value: Any) -> str:
    if isinstance(value, Raw):
        return str(value)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return _number(value)
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value(v) for v in value) + "]"
    if isinstance(value, dict):  # keys without a value are left out
        given = {k: v for k, v in value.items() if v is not None}
        return "{ " + ", ".join(f"{_key(k)} = {_value(v)}" for k, v in given.items()) + " }" if given else "{}"
    raise TypeError(f"cannot write {value!r} to TOML")


def _table(header: str, entries: dict[str, Any]) -> str:
    lines = [f"[{header}]"] + [f"{_key(k)} = {_value(v)}" for k, v in entries.items() if v is not None]
    return "\n".join(lines)


def vec(values, kind: str) -> list[Raw]:
    return [quantity(v, kind) for v in values]


def _points(points: list[dict]) -> dict:
    return {p["name"]: vec(p["position"], "length") for p in points}


def function(f: dict, kind: str) -> dict:
    """A function of time with the units of what it prescribes (its keys' kinds from the definitions)."""
    table = p.FUNCTIONS[f["kind"]]
    out: dict[str, Any] = {"kind": f["kind"]}
    for key, value in f.items():
        if key == "kind":
            continue
        param = table[key]
        if param.kind == "list":
            of = param.of
            out[key] = [quantity(v, per_time(kind, k) if of == "powers" else kind if of == "value" else of)
                        for k, v in enumerate(value)]
        else:
            out[key] = quantity(value, {"value": kind, "rate": per_time(kind, 1)}.get(param.kind, param.kind))
    return out


def _law(law: dict | str, family: str) -> dict:
    """A law's table; the core's ``hertz_cylinder_exponent`` is ``hertz_cylinder`` with ``exponent``, and an
    untagged law (the core's seal friction) gets its tag."""
    law = {"law": law} if isinstance(law, str) else p.tagged_law(dict(law), family)
    table = p.LAWS[family][law["law"]]
    law["law"] = table.name
    return {key: (value if key == "law" else _value_of(table[key], value)) for key, value in law.items()}


def _lubrication(lub: dict) -> dict:
    """The lubrication table: the core's ``reynolds`` options are keys of the table (the grid a pair)."""
    table = p.LUBRICATION
    out = {key: _value_of(table[key], lub.get(key, table.default(key))) for key in ("model", "viscosity", "transition")}
    reynolds = lub.get("reynolds")
    if lub["model"] in p.REYNOLDS_MODELS and reynolds:
        n = (reynolds.get("n_circumferential"), reynolds.get("n_axial"))
        given = {**reynolds, "grid": None if None in n else [int(n[0]), int(n[1])]}
        for key in p.REYNOLDS_ONLY_KEYS:
            out[key] = _value_of(table[key], given.get(key, table.default(key)))
    return out


def _value_of(param: p.Param, value: Any) -> Any:
    """The TOML value of one key of the core's spec (None: the key is left out)."""
    if param.kind == "law" and (value is not None or param.default is not None):
        return _law(param.default if value is None else value, param.of)
    if value is None:
        return None
    if param.kind == "vector":
        return vec(value, param.of)
    if param.kind in KINDS:
        return quantity(value, param.kind)
    if param.kind == "function":
        return function(value, param.of) if isinstance(value, dict) else quantity(value, param.of)
    if param.kind == "table" and param.of is p.LUBRICATION:
        return _lubrication(value)
    if param.kind == "table":
        return {sub.key: _value_of(sub, value.get(sub.key, sub.default)) for sub in param.of.params}
    if param.kind == "points":
        return _points(value)
    if param.kind == "arclengths":
        return {name: quantity(arclength, "length") for name, arclength in value.items()}
    if param.kind == "nodes":  # by arclength on a beam, by node number (a whole number) with matrices
        return {name: v if isinstance(v, int) else quantity(v, "length") for name, v in value.items()}
    if param.kind == "flag":
        return bool(value)
    if param.kind in p.SPATIAL_KINDS:
        return _spatial_value(param, value)
    return value


def _spatial_value(param: p.Param, value: Any) -> Any:
    """The TOML value of a key of a spatial kind: an orientation as its quaternion and an inertia as its tensor
    (both exactly as the spec holds them), a point with axes as its position and rotation matrix."""
    if param.kind == "vector3":
        return vec(value, param.of)
    if param.kind == "orientation":
        return {"quaternion": [float(v) for v in value]}
    if param.kind == "inertia_tensor":
        return {"tensor": [vec(row, "inertia") for row in value]}
    if param.kind == "function3":
        return [function(f, param.of) if isinstance(f, dict) else quantity(f, param.of) for f in value]
    return _markers(value)


def _markers(points: list[dict]) -> dict:
    """Named points of a spatial model: a 3-vector, or a position with the marker's axes as a matrix."""
    out = {}
    for point in points:
        position = vec(point["position"], "length")
        axes = point.get("axes")
        out[point["name"]] = position if axes is None else {"position": position, "axes": {"matrix": axes}}
    return out


def _beam(beam: dict) -> dict:
    """A beam's table: the core's ``section`` is the model file's ``section`` (its shape) and ``material``, its
    ``mesh`` the keys ``order``, ``elements``, ``element_length``, its points a table of arclengths."""
    values = {**_beam_geometry(beam), "damping_time": beam["damping_time"],
              "velocity": beam["velocity"], "angular_velocity": beam["angular_velocity"],
              "points": {point["name"]: point["arclength"] for point in beam["points"]}}
    return _in_order(p.BEAM, values)


def _modal_body(body: dict) -> dict:
    """A modal body's table: a beam's section, material and mesh, its points a table of arclengths; or the
    matrices of a structure written out in SI units (a model file that needs no other file), its points a
    table of node numbers."""
    structure = body["structure"]
    if structure["from"] == "beam":
        geometry = _beam_geometry(structure)
        where = "arclength"
    else:
        matrices = {"mass": structure["mass"], "stiffness": structure["stiffness"], "nodes": structure["nodes"],
                    "length_unit": "m", "mass_unit": "kg"}
        geometry = {"matrices": matrices, "position": structure["position"], "angle": structure["angle"],
                    "order": None}
        where = "node"
    values = {**geometry, "interface": {node["name"]: node[where] for node in body["interface"]},
              "points": {point["name"]: point[where] for point in body.get("points", [])},
              "frame": body.get("frame"), "normal_modes": body["normal_modes"], "damping_ratio": body["damping_ratio"],
              "damping_time": body.get("damping_time", 0.0),
              "velocity": body["velocity"], "angular_velocity": body["angular_velocity"]}
    return _in_order(p.MODAL_BODY, values)


def _beam_geometry(beam: dict) -> dict:
    """The ends, the section (its shape), the material and the mesh keys of a beam's or modal body's spec."""
    section = dict(beam["section"])
    shape = section.pop("type")
    material = section.pop("material", None)
    shape_table = p.BEAM_SECTIONS[shape]
    return {"start": beam["start"], "end": beam["end"],
            "section": {"shape": shape, **{key: _value_of(shape_table[key], v) for key, v in section.items()}},
            "material": material, **beam["mesh"]}


def _in_order(table: p.Table, values: dict) -> dict:
    """``values`` as the file writes them, in the order of the table's keys that the core reads."""
    out = {}
    for param in table.params:
        if param.in_spec:
            value = values.get(param.key)
            out[param.key] = value if param.kind == "variant" else _value_of(param, value)
    return out


def _element(table: p.Table, entry: dict) -> dict:
    """The table of an element of the core's spec: every key of its definition that the core reads, in
    order; a key the spec lacks is written with its default."""
    out: dict[str, Any] = {table.tag: table.name} if table.tag else {}
    for param in table.params:
        if param.in_spec:
            value = entry[param.key] if param.required else entry.get(param.key, param.default)
            out[param.key] = _value_of(param, value)
    return out


def _referenced_bodies(spec: dict) -> set[str]:
    """The bodies that a joint or force element refers to (by a point or by name)."""
    out = set()
    for section, tables in (("joints", p.JOINTS), ("forces", p.FORCES), ("spatial_joints", p.SPATIAL_JOINTS),
                            ("spatial_forces", p.SPATIAL_FORCES),
                            ("spatial_clearance_joints", p.SPATIAL_JOINTS)):  # not sensors: they only observe
        for entry in spec.get(section, []):
            for param in tables[entry["type"]].params:
                value = entry.get(param.key)
                if param.kind == "point" and isinstance(value, str):
                    out.add(value.partition(".")[0])
                elif param.kind == "body" and isinstance(value, str):
                    out.add(value)
    return out


def _spatial_blocks(spec: dict) -> list[str]:
    """The tables of a spatial model (``kinematics = "spatial"``), from ``[model]`` to ``[forces]``."""
    model = {**_element(p.SPATIAL_MODEL, {"name": p.DEFAULT_NAME, **spec}), "kinematics": "spatial"}
    blocks = [_table("model", model)]
    if spec.get("ground_points"):
        blocks.append(_table("ground", {"points": _markers(spec["ground_points"])}))
    referenced = _referenced_bodies(spec)
    for b in spec["spatial_bodies"]:
        free = {"free": True} if b["name"] not in referenced else {}
        blocks.append(_table(f"bodies.{_key(b['name'])}", {**_element(p.SPATIAL_BODY, b), **free}))
    joint_types = {j["name"]: j["type"] for j in spec.get("spatial_joints", [])}
    for j in spec.get("spatial_joints", []):
        blocks.append(_table(f"joints.{_key(j['name'])}", _element(p.SPATIAL_JOINTS[j["type"]], j)))
    for j in spec.get("spatial_clearance_joints", []):
        blocks.append(_table(f"joints.{_key(j['name'])}", _element(p.SPATIAL_CLEARANCE_REVOLUTE, j)))
    for d in spec.get("drivers", []):
        kind = p.SPATIAL_DRIVEN.get(joint_types.get(d["joint"], "revolute"), "angle")
        blocks.append(_table(f"drivers.{_key(d['name'])}", {"joint": d["joint"], "function": function(d["function"], kind)}))
    for f in spec.get("spatial_forces", []):
        blocks.append(_table(f"forces.{_key(f['name'])}", _element(p.SPATIAL_FORCES[f["type"]], f)))
    return blocks


def to_toml(spec: dict, simulation: dict | None = None, header: str | None = None) -> str:
    """Model-file text for a core spec (as ``Model.to_spec()`` returns) and simulation defaults."""
    blocks = []
    if header:
        blocks.append("\n".join(f"# {line}".rstrip() for line in header.splitlines()))
    if spec.get("spatial_bodies") is not None:
        return _finish(blocks + _spatial_blocks(spec), simulation)
    blocks.append(_table("model", _element(p.MODEL, {"name": p.DEFAULT_NAME, **spec})))
    if spec.get("ground_points"):
        blocks.append(_table("ground", {"points": _points(spec["ground_points"])}))
    referenced = _referenced_bodies(spec)
    for b in spec.get("bodies", []):
        free = {"free": True} if b["name"] not in referenced else {}  # not in the spec: read from the elements
        blocks.append(_table(f"bodies.{_key(b['name'])}", {**_element(p.BODY, b), **free}))
    for b in spec.get("beams", []):
        free = {"free": True} if b["name"] not in referenced else {}
        blocks.append(_table(f"beams.{_key(b['name'])}", {**_beam(b), **free}))
    for b in spec.get("modal_bodies", []):
        free = {"free": True} if b["name"] not in referenced else {}
        blocks.append(_table(f"modal_bodies.{_key(b['name'])}", {**_modal_body(b), **free}))
    joint_types = {j["name"]: j["type"] for j in spec.get("joints", [])}
    for j in spec.get("joints", []):
        blocks.append(_table(f"joints.{_key(j['name'])}", _element(p.JOINTS[j["type"]], j)))
    for d in spec.get("drivers", []):
        kind = FUNCTION_VALUE.get(joint_types.get(d["joint"], "revolute"), "angle")
        blocks.append(_table(f"drivers.{_key(d['name'])}", {"joint": d["joint"], "function": function(d["function"], kind)}))
    for f in spec.get("forces", []):
        blocks.append(_table(f"forces.{_key(f['name'])}", _element(p.FORCES[f["type"]], f)))
    for sensor in spec.get("sensors", []):
        blocks.append(_table(f"sensors.{_key(sensor['name'])}", _element(p.SENSORS[sensor["type"]], sensor)))
    return _finish(blocks, simulation)


def _finish(blocks: list[str], simulation: dict | None) -> str:
    """The text of ``blocks`` with the ``[simulation]`` table of the defaults ``simulation``."""
    sim = {key: _value_of(p.SIMULATION[key], value) for key, value in (simulation or {}).items()}
    if any(v is not None for v in sim.values()):
        blocks.append(_table("simulation", sim))
    return "\n\n".join(blocks) + "\n"
