"""Writing a model description back to model-file TOML.

Numbers are written in SI units with the unit spelled out (``"0.025 m"``)
and with every digit (``repr``), so that loading the text again gives the
same floats and therefore the same simulation, bit for bit.
"""

from __future__ import annotations

import math
import re
from typing import Any

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
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_value(v)}" for k, v in value.items()) + " }" if value else "{}"
    raise TypeError(f"cannot write {value!r} to TOML")


def _table(header: str, entries: dict[str, Any]) -> str:
    lines = [f"[{header}]"] + [f"{_key(k)} = {_value(v)}" for k, v in entries.items() if v is not None]
    return "\n".join(lines)


def vec(values, kind: str) -> list[Raw]:
    return [quantity(v, kind) for v in values]


def _points(points: list[dict]) -> dict:
    return {p["name"]: vec(p["position"], "length") for p in points}


def function(f: dict, kind: str) -> dict:
    """A function of time with the units of what it prescribes."""
    out: dict[str, Any] = {"kind": f["kind"]}
    time = "time"
    for key, value in f.items():
        if key == "kind":
            continue
        if key in ("value", "initial", "offset", "amplitude", "value_start", "value_end"):
            out[key] = quantity(value, kind)
        elif key == "rate":
            out[key] = quantity(value, per_time(kind, 1))
        elif key in ("t_start", "t_end"):
            out[key] = quantity(value, time)
        elif key == "frequency":
            out[key] = quantity(value, "frequency")
        elif key == "phase":
            out[key] = quantity(value, "angle")
        elif key == "coefficients":
            out[key] = [quantity(c, per_time(kind, k)) for k, c in enumerate(value)]
        elif key == "times":
            out[key] = [quantity(t, time) for t in value]
        elif key == "values":
            out[key] = [quantity(v, kind) for v in value]
        else:
            out[key] = value
    if out["kind"] == "constant":
        return out
    return out


LAW_KINDS = {"restitution": "dimensionless", "exponent": "dimensionless", "coefficient": "dimensionless",
             "static_coefficient": "dimensionless", "kinetic_coefficient": "dimensionless",
             "velocity_tolerance": "velocity", "v0": "velocity", "v1": "velocity",
             "stiction_velocity": "velocity", "transition_velocity": "velocity"}


def _law(law: dict) -> dict:
    out = dict(law)
    if out.get("law") == "hertz_cylinder_exponent":
        out["law"] = "hertz_cylinder"
    return {k: (quantity(v, LAW_KINDS[k]) if k in LAW_KINDS else v) for k, v in out.items()}


def _material(m: dict) -> dict:
    return {"youngs_modulus": quantity(m["youngs_modulus"], "pressure"),
            "poisson_ratio": quantity(m["poisson_ratio"], "dimensionless")}


def _joint(j: dict) -> dict:
    if j["type"] != "clearance_revolute":
        out = {"type": j["type"], "first": j["first"], "second": j["second"]}
        if "axis" in j:
            out["axis"] = [float(a) for a in j["axis"]]
        return out
    return {
        "type": j["type"], "bearing": j["bearing"], "journal": j["journal"],
        "bearing_radius": quantity(j["bearing_radius"], "length"), "clearance": quantity(j["clearance"], "length"),
        "length": None if j.get("length") is None else quantity(j["length"], "length"),
        "contact": _law(j["contact"]), "stiffness": _law(j.get("stiffness") or {"law": "hertz_cylinder"}),
        "friction": _law(j.get("friction") or {"law": "none"}),
        "bearing_material": _material(j["bearing_material"]), "journal_material": _material(j["journal_material"]),
        "initial_eccentricity": vec(j.get("initial_eccentricity", (0.0, 0.0)), "length"),
        "lock_at_assembly": bool(j.get("lock_at_assembly", True)),
        "onset_velocity_floor": quantity(j.get("onset_velocity_floor", 1e-4), "velocity"),
        "max_penetration": None if j.get("max_penetration") is None else quantity(j["max_penetration"], "length"),
        "lubrication": None if j.get("lubrication") is None else _lubrication(j["lubrication"]),
    }


def _lubrication(lub: dict) -> dict:
    transition = dict(lub.get("transition") or {"law": "wang_improved"})
    if transition.get("safe_film_thickness") is not None:
        transition["safe_film_thickness"] = quantity(transition["safe_film_thickness"], "length")
    out = {"model": lub["model"], "viscosity": quantity(lub["viscosity"], "viscosity"),
           "transition": {k: v for k, v in transition.items() if v is not None}}
    reynolds = lub.get("reynolds")
    if lub["model"].startswith("reynolds") and reynolds:
        out["cavitation"] = reynolds.get("cavitation", "swift_stieber")
        if reynolds.get("n_circumferential") is not None and reynolds.get("n_axial") is not None:
            out["grid"] = [int(reynolds["n_circumferential"]), int(reynolds["n_axial"])]
        out["ambient_pressure"] = quantity(reynolds.get("ambient_pressure", 0.0), "pressure")
        if reynolds.get("groove_supply_pressure") is not None:
            out["groove_supply_pressure"] = quantity(reynolds["groove_supply_pressure"], "pressure")
    return out


def _force(f: dict) -> dict:
    t = f["type"]
    if t == "spring_damper":
        return {"type": t, "first": f["first"], "second": f["second"], "stiffness": quantity(f["stiffness"], "stiffness"),
                "damping": quantity(f["damping"], "damping"), "free_length": quantity(f["free_length"], "length")}
    if t == "rotational_spring_damper":
        return {"type": t, "first": f["first"], "second": f["second"],
                "stiffness": quantity(f["stiffness"], "rotational stiffness"),
                "damping": quantity(f["damping"], "rotational damping"), "free_angle": quantity(f["free_angle"], "angle")}
    if t == "point_force":
        return {"type": t, "point": f["point"], "fx": function(f["fx"], "force"), "fy": function(f["fy"], "force")}
    return {"type": t, "body": f["body"], "torque": function(f["torque"], "torque")}


SIMULATION_KINDS = {"t_end": "time", "t0": "time", "max_step": "time", "output_step": "time", "initial_step": "time",
                    "min_step": "time", "rtol": "dimensionless", "atol": "dimensionless"}


def to_toml(spec: dict, simulation: dict | None = None, header: str | None = None) -> str:
    """Model-file text for a core spec (as ``Model.to_spec()`` returns) and simulation defaults."""
    blocks = []
    if header:
        blocks.append("\n".join(f"# {line}".rstrip() for line in header.splitlines()))
    blocks.append(_table("model", {"name": spec.get("name", "mechanism"), "gravity": vec(spec.get("gravity", (0, 0)), "acceleration")}))
    if spec.get("ground_points"):
        blocks.append(_table("ground", {"points": _points(spec["ground_points"])}))
    for b in spec.get("bodies", []):
        blocks.append(_table(f"bodies.{_key(b['name'])}", {
            "mass": quantity(b["mass"], "mass"), "inertia": quantity(b["inertia"], "inertia"),
            "position": vec(b.get("position", (0, 0)), "length"), "angle": quantity(b.get("angle", 0.0), "angle"),
            "velocity": vec(b.get("velocity", (0, 0)), "velocity"),
            "angular_velocity": quantity(b.get("angular_velocity", 0.0), "angular velocity"),
            "points": _points(b.get("points", [])),
        }))
    joint_types = {j["name"]: j["type"] for j in spec.get("joints", [])}
    for j in spec.get("joints", []):
        blocks.append(_table(f"joints.{_key(j['name'])}", _joint(j)))
    for d in spec.get("drivers", []):
        kind = FUNCTION_VALUE.get(joint_types.get(d["joint"], "revolute"), "angle")
        blocks.append(_table(f"drivers.{_key(d['name'])}", {"joint": d["joint"], "function": function(d["function"], kind)}))
    for f in spec.get("forces", []):
        blocks.append(_table(f"forces.{_key(f['name'])}", _force(f)))
    sim = {k: (quantity(v, SIMULATION_KINDS[k]) if k in SIMULATION_KINDS else v)
           for k, v in (simulation or {}).items() if v is not None}
    if sim:
        blocks.append(_table("simulation", sim))
    return "\n\n".join(blocks) + "\n"
