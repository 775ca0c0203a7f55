"""Physical quantities written with units, converted to SI with pint.

A model file writes every physical quantity either as a bare number (SI
units) or as a string with a unit: ``"0.5 mm"``, ``"5000 rpm"``,
``"207 GPa"``, ``"0.034 kg m^2"``, ``"400 cP"``. :func:`to_si` converts one
to a float in the SI unit of its kind and raises :class:`UnitError` with a
message fit for the user when the text is not a quantity or has the wrong
dimension (``"5 kg"`` for a length).

Angles are in rad (``"deg"``, ``"rev"`` accepted); angular speeds in rad/s
(``"rpm"`` is revolutions per minute, 2 pi / 60 rad/s). ``Hz`` is refused
for an angular speed because it is ambiguous (cycles or radians per second);
a ``frequency`` in Hz given in ``rpm`` or ``rad/s`` is converted as cycles.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import pint


class UnitError(ValueError):
    """A value is not a quantity of the expected kind; the message is meant for the user."""


@dataclass(frozen=True)
class Kind:
    """A kind of physical quantity: its name in messages, SI unit, and an example."""

    name: str
    si: str
    example: str
    angular: bool = False


KINDS: dict[str, Kind] = {k.name: k for k in [
    Kind("length", "m", "0.5 mm"),
    Kind("mass", "kg", "0.3 kg"),
    Kind("inertia", "kg*m^2", "1e-4 kg m^2"),
    Kind("time", "s", "24 ms"),
    Kind("angle", "rad", "90 deg", angular=True),
    Kind("angular velocity", "rad/s", "5000 rpm", angular=True),
    Kind("angular acceleration", "rad/s^2", "10 rad/s^2", angular=True),
    Kind("velocity", "m/s", "1e-3 m/s"),
    Kind("acceleration", "m/s^2", "9.81 m/s^2"),
    Kind("force", "N", "100 N"),
    Kind("torque", "N*m", "2 N m"),
    Kind("stiffness", "N/m", "1e4 N/m"),
    Kind("damping", "N*s/m", "10 N s/m"),
    Kind("rotational stiffness", "N*m/rad", "50 N m/rad", angular=True),
    Kind("rotational damping", "N*m*s/rad", "0.1 N m s/rad", angular=True),
    Kind("pressure", "Pa", "207 GPa"),
    Kind("viscosity", "Pa*s", "400 cP"),
    Kind("frequency", "Hz", "10 Hz"),
    Kind("dimensionless", "", "0.9"),
]}

_ANGLE_UNITS = {"radian", "degree", "revolution", "turn", "arcminute", "arcsecond", "revolutions_per_minute",
                "gradian", "grade", "milliradian", "cycle"}
_HERTZ_UNITS = {"hertz", "kilohertz", "megahertz"}


@lru_cache(maxsize=1)
def registry() -> pint.UnitRegistry:
    """The one pint registry jointplay uses (with ``rev`` for revolution, as in ``"10 rev/s"``)."""
    ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    ureg.define("rev = revolution")
    return ureg


def _unit_names(q) -> set[str]:
    return {str(name) for name, _ in q.unit_items()}


def describe_dimension(q) -> str:
    """The kind of a quantity in words, for messages (``"a mass"``)."""
    dims = q.dimensionality
    for kind in KINDS.values():
        if kind.name in ("dimensionless", "angle") or kind.angular:
            continue
        if registry().Quantity(1, kind.si).dimensionality == dims:
            return f"a {kind.name}"
    if dims == registry().Quantity(1, "1/s").dimensionality:
        return "a rate (1/s)"
    if not dims:
        return "a plain number"
    return f"a quantity of dimension {dims}"


def format_value(raw: object, kind: str | Kind | None = None) -> str:
    """The value as the user wrote it: strings as they are, bare numbers followed by the SI unit."""
    if isinstance(raw, str):
        return raw
    if isinstance(raw, bool):
        return repr(raw).lower()
    if isinstance(raw, (int, float)):
        spec = KINDS.get(kind) if isinstance(kind, str) else kind
        unit = spec.si.replace("*", " ") if spec is not None else ""
        return f"{raw:g} {unit}".strip() if isinstance(raw, float) else f"{raw} {unit}".strip()
    return repr(raw)


def parse(text: str):
    """A pint Quantity from text; raises UnitError."""
    try:
        q = registry().Quantity(text.strip())
    except pint.UndefinedUnitError as exc:
        raise UnitError(f"has an unknown unit {', '.join(map(repr, exc.unit_names))}, got {text!r}") from None
    except Exception:  # pint's tokenizer raises many types (AssertionError, SyntaxError, TypeError...)
        raise UnitError(f"cannot be read as a number with a unit (e.g. \"0.5 mm\"), got {text!r}") from None
    if not isinstance(q, registry().Quantity):  # e.g. a plain number parsed from a string
        q = registry().Quantity(float(q), "")
    return q


def per_time(kind: str | Kind, power: int) -> Kind:
    """The kind of ``kind`` divided by time**power (the rate of an angle is an angular velocity)."""
    base = KINDS[kind] if isinstance(kind, str) else kind
    if power == 0:
        return base
    named = {("angle", 1): "angular velocity", ("angle", 2): "angular acceleration", ("length", 1): "velocity",
             ("length", 2): "acceleration"}
    if (base.name, power) in named:
        return KINDS[named[(base.name, power)]]
    si = f"{base.si}/s^{power}" if base.si else f"1/s^{power}"
    example_unit = si.replace("*", " ")
    return Kind(f"{base.name} per s^{power}", si, f"1 {example_unit}", base.angular)


def to_si(raw: object, kind: str | Kind) -> float:
    """``raw`` (a number in SI units or a string with a unit) as a float in the SI unit of ``kind``."""
    spec = KINDS[kind] if isinstance(kind, str) else kind
    if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
        raise UnitError(f"must be a number or a string with a unit (e.g. \"{spec.example}\"), got {format_value(raw)}")
    if isinstance(raw, (int, float)):
        value = float(raw)
    else:
        q = parse(raw)
        if not _unit_names(q):  # a number written as a string: SI, like a bare number
            value = float(q.magnitude)
        else:
            value = _convert(q, spec, raw)
    if not math.isfinite(value):
        raise UnitError(f"must be finite, got {format_value(raw, spec)}")
    return value


def _convert(q, spec: Kind, raw: str) -> float:
    names = _unit_names(q)
    if spec.name == "angular velocity" and names & _HERTZ_UNITS:
        raise UnitError(f"Hz is ambiguous for an angular speed; write rpm, rev/s or rad/s, got {raw!r}")
    if not spec.angular and spec.name != "frequency" and names & _ANGLE_UNITS:
        raise UnitError(f"must be {_article(spec.name)} (e.g. \"{spec.example}\"), got an angular quantity {raw!r}")
    target = registry().Quantity(1, spec.si) if spec.si else registry().Quantity(1, "")
    if q.dimensionality != target.dimensionality:
        raise UnitError(f"must be {_article(spec.name)} (e.g. \"{spec.example}\"), got {raw!r}, "
                        f"which is {describe_dimension(q)}")
    value = float(q.to(target.units).magnitude)
    if spec.name == "frequency" and names & _ANGLE_UNITS:
        value /= 2.0 * math.pi  # rad/s or rpm given for a frequency: count cycles
    return value


def _article(name: str) -> str:
    if name == "dimensionless":
        return "a plain number"
    return f"an {name}" if name[0] in "aeiou" else f"a {name}"


def si_text(value: float, kind: str) -> str | float:
    """``value`` in SI units written as a model-file string (``"0.0005 m"``); plain numbers stay numbers."""
    unit = KINDS[kind].si.replace("*", " ")
    return f"{float(value)!r} {unit}" if unit else float(value)
