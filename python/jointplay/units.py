"""Physical quantities written with units, converted to SI with pint.

A quantity is a string with a unit: ``"0.5 mm"``, ``"5000 rpm"``,
``"207 GPa"``, ``"0.034 kg m^2"``, ``"400 cP"``. :func:`to_si` converts one
to a float in the SI unit of its kind and raises :class:`UnitError` with a
message fit for the user when the text is not a quantity or has the wrong
dimension (``"5 kg"`` for a length).

The number is read here, by a strict decimal pattern; pint sees only the
unit text, which may hold unit names, spaces, ``*``, ``/``, parentheses and
``^`` or ``**`` followed by a small integer. Nothing else reaches pint, so a
quantity string is never arithmetic (``"10**10**8 kg"`` is refused at once).

Bare numbers: in Python (the :class:`~jointplay.Model` builder, CLI options)
a bare number is in SI units. In a model file (inside
:func:`model_file_units`) a bare number in a dimensional field is an error
unless the file declares the unit of that kind in its ``[units]`` table;
zero and dimensionless numbers need no unit.

Angles are in rad (``"deg"``, ``"rev"`` accepted); angular speeds in rad/s
(``"rpm"`` is revolutions per minute, 2 pi / 60 rad/s). ``Hz`` is refused
for an angular speed because it is ambiguous (cycles or radians per second);
a ``frequency`` in Hz given in ``rpm`` or ``rad/s`` is converted as cycles.
"""

from __future__ import annotations

import math
import re
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass
from functools import lru_cache
from typing import Any


class UnitError(ValueError):
    """A value is not a quantity of the expected kind; the message is meant for the user."""


@dataclass(frozen=True)
class Kind:
    """A kind of physical quantity: its name in messages, SI unit, and an example."""

    name: str
    si: str
    example: str
    angular: bool = False

    @property
    def key(self) -> str:
        """The kind's key in a model file's ``[units]`` table (``angular_velocity``)."""
        return self.name.replace(" ", "_")

    @property
    def example_unit(self) -> str:
        """The unit of the example (``"mm"`` for ``"0.5 mm"``)."""
        return self.example.partition(" ")[2]


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
    Kind("area", "m^2", "20 cm^2"),
    Kind("volume", "m^3", "0.1 L"),
    Kind("volume flow", "m^3/s", "10 L/min"),
    Kind("pressure", "Pa", "207 GPa"),
    Kind("viscosity", "Pa*s", "400 cP"),
    Kind("frequency", "Hz", "10 Hz"),
    Kind("density", "kg/m^3", "7850 kg/m^3"),
    Kind("second moment of area", "m^4", "1.2 cm^4"),
    Kind("bending stiffness", "N*m^2", "1.4e4 N m^2"),
    Kind("mass per length", "kg/m", "1.2 kg/m"),
    Kind("rotary inertia per length", "kg*m", "6e-4 kg m"),
    Kind("dimensionless", "", "0.9"),
]}

#: Kinds whose default unit a model file may declare in ``[units]`` (by key: ``angular_velocity``).
#: Every dimensional kind can be declared; none follows from another (see docs/model-files.md).
DECLARABLE = {k.key: k for k in KINDS.values() if k.si}

_ANGLE_UNITS = {"radian", "degree", "revolution", "turn", "arcminute", "arcsecond", "revolutions_per_minute",
                "gradian", "grade", "milliradian", "cycle"}
_HERTZ_UNITS = {"hertz", "kilohertz", "megahertz"}

#: Longest quantity text read [characters] and longest unit text: far above any real quantity, small
#: enough to read at once.
MAX_TEXT, MAX_UNIT_TEXT = 1000, 100
#: Distinct unit texts whose parse is kept (:func:`_parsed_units`).
_CACHED_UNITS = 512
#: Distinct quantity texts whose SI value is kept (:func:`_text_to_si`).
_CACHED_TEXTS = 4096
_NUMBER = re.compile(r"[+-]?(?:(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?|nan|inf(?:inity)?)", re.IGNORECASE)
# unit names, spaces, * and /, parentheses, ^ or ** with an exponent of at most two digits, "1/" as in "1/s"
_UNIT_TEXT = re.compile(r"(?:\s+|[^\W\d]+|(?:\^|\*\*)\s*[+-]?\d{1,2}(?!\d)|\*|/|\(|\)|%|1(?=\s*/))*")
_POWER_OF_POWER = re.compile(r"(?:\^|\*\*)\s*[+-]?\d+\s*(?:\^|\*\*)")

#: Units declared by the model file being read: kind key -> (unit text, SI value of one unit).
_DECLARED: ContextVar[dict[str, tuple[str, float]] | None] = ContextVar("jointplay_declared_units", default=None)


@lru_cache(maxsize=1)
def registry():
    """The one pint registry jointplay uses (with ``rev`` for revolution, as in ``"10 rev/s"``).
    pint is imported here, on first use, so that ``import jointplay`` does not load it."""
    import pint

    ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    ureg.define("rev = revolution")
    return ureg


@contextmanager
def model_file_units(declared: dict[str, tuple[str, float]]):
    """While reading a model file: a bare number in a dimensional field needs a unit declared in
    ``declared`` (from :func:`declare_units`), except zero."""
    token = _DECLARED.set(dict(declared))
    try:
        yield
    finally:
        _DECLARED.reset(token)


def declare_unit(key: str, unit: Any) -> tuple[str, float]:
    """One entry of a ``[units]`` table checked: (unit text, SI value of one unit); raises UnitError."""
    kind = DECLARABLE[key]
    if not isinstance(unit, str):
        raise UnitError(f"must be a unit of {kind.name} as a string, e.g. \"{kind.example_unit}\", "
                        f"got {format_value(unit)}")
    number, _ = _split(unit)
    if number:
        raise UnitError(f"must be a unit without a number, e.g. \"{kind.example_unit}\", got {unit!r}")
    value = _convert(_quantity(1.0, unit.strip(), unit), kind, unit)
    if not (math.isfinite(value) and value > 0):
        raise UnitError(f"must be a unit of {kind.name} (e.g. \"{kind.example_unit}\"), got {unit!r}")
    return unit.strip(), value


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


def _short(raw: int) -> str:
    digits = str(raw)
    return digits if len(digits) <= 20 else f"{digits[:12]}... (an integer of {len(digits.lstrip('-'))} digits)"


def format_value(raw: object, kind: str | Kind | None = None) -> str:
    """The value as the user wrote it: strings as they are, bare numbers followed by the unit they are
    read in (SI, or the unit a model file declares)."""
    if isinstance(raw, str):
        return raw if len(raw) <= 60 else _quoted(raw)
    if isinstance(raw, bool):
        return repr(raw).lower()
    if isinstance(raw, (int, float)):
        spec = KINDS.get(kind) if isinstance(kind, str) else kind
        unit = _bare_unit(spec) if spec is not None else ""
        if isinstance(raw, int):
            return f"{_short(raw)} {unit}".strip() if abs(raw) < 10**20 else _short(raw)
        return f"{raw:g} {unit}".strip() if math.isfinite(raw) else f"{raw}"
    if _is_quantity(raw):
        return f"{raw.magnitude:g} {raw.units:~}".strip()
    return repr(raw)


def _quoted(text: str) -> str:
    """``text`` quoted for a message, shortened when long."""
    return repr(text) if len(text) <= 60 else repr(text[:40]) + f"... ({len(text)} characters)"


def _bare_unit(spec: Kind) -> str:
    declared = _DECLARED.get()
    if declared is not None and spec.key in declared:
        return declared[spec.key][0]
    return spec.si.replace("*", " ")


def _split(text: str) -> tuple[str, str]:
    """``"0.5 mm"`` -> ("0.5", "mm"): the leading number (may be empty) and the rest, stripped."""
    text = text.strip()
    match = _NUMBER.match(text)
    if match is None:
        return "", text
    return match.group(0), text[match.end():].strip()


def _quantity(value: float, unit: str, text: str):
    """A pint Quantity of ``value`` in ``unit``, the unit text checked before pint reads it; ``text`` is
    what the user wrote, for messages."""
    import pint

    unreadable = f"cannot be read as a number with a unit (e.g. \"0.5 mm\"), got {_quoted(text)}"
    if len(unit) > MAX_UNIT_TEXT or not _UNIT_TEXT.fullmatch(unit) or _POWER_OF_POWER.search(unit):
        raise UnitError(unreadable)
    try:
        units = _parsed_units(unit)
    except pint.UndefinedUnitError as exc:
        names = exc.unit_names if isinstance(exc.unit_names, (list, tuple)) else [exc.unit_names]
        raise UnitError(f"has an unknown unit {', '.join(map(repr, names))}, got {_quoted(text)}") from None
    except Exception:  # pint's parser raises many types (DefinitionSyntaxError, TypeError...)
        raise UnitError(unreadable) from None
    return registry().Quantity(value, units)


@lru_cache(maxsize=_CACHED_UNITS)
def _parsed_units(unit: str):
    """pint's reading of a unit text, kept: the parser costs about 0.1 ms a call, and a model file
    repeats a few units (``mm``, ``kg``) many times. (A text pint refuses raises each time, as it is
    not kept.)"""
    return registry().parse_units(unit)


@lru_cache(maxsize=len(KINDS) + 64)
def _si_target(si: str):
    """A quantity of one SI unit ``si`` of a kind (``""``: dimensionless), the target of conversions."""
    return registry().Quantity(1, si) if si else registry().Quantity(1, "")


def parse(text: str):
    """A pint Quantity from text (a plain number gives a dimensionless one); raises UnitError."""
    if len(text) > MAX_TEXT:
        raise UnitError(f"is too long to be a quantity ({len(text)} characters), got {_quoted(text)}")
    number, unit = _split(text)
    if not number:
        raise UnitError(f"cannot be read as a number with a unit (e.g. \"0.5 mm\"), got {text!r}")
    return _quantity(float(number), unit, text)


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


def _is_quantity(raw: object) -> bool:
    return hasattr(raw, "magnitude") and hasattr(raw, "units") and hasattr(raw, "dimensionality")


def to_si(raw: object, kind: str | Kind) -> float:
    """``raw`` (a number, a string with a unit or a pint Quantity) as a float in the SI unit of ``kind``.
    A bare number is SI, except while a model file is read (:func:`model_file_units`)."""
    spec = KINDS[kind] if isinstance(kind, str) else kind
    if _is_quantity(raw):
        return _from_quantity(raw, spec)
    if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
        raise UnitError(f"must be a number or a string with a unit (e.g. \"{spec.example}\"), got {format_value(raw)}")
    if isinstance(raw, int) and abs(raw) > 10**300:
        raise UnitError(f"must be finite, got {_short(raw)}")
    if isinstance(raw, (int, float)):
        return _bare(float(raw), spec, raw)
    value, bare = _text_to_si(raw, spec)
    return _bare(value, spec, raw) if bare else value


@lru_cache(maxsize=_CACHED_TEXTS)
def _text_to_si(raw: str, spec: Kind) -> tuple[float, bool]:
    """``(value, bare)``: a quantity text in the SI unit of ``spec`` (``bare`` False), or the number of a
    text without a unit (``bare`` True, read by :func:`_bare` under the file's declared units). Kept per
    text and kind, as pint's arithmetic costs tens of microseconds a value and a model file (or a study
    loading it again) repeats its values; the value is pint's, so a kept one is the same to the last bit.
    A text that is refused raises each time (a raise is not kept)."""
    q = parse(raw)
    if not _unit_names(q):  # a number written as a string: a bare number
        return float(q.magnitude), True
    if not math.isfinite(q.magnitude):
        raise UnitError(f"must be finite, got {format_value(raw)}")
    value = _convert(q, spec, raw)
    if not math.isfinite(value):
        raise UnitError(f"must be finite, got {format_value(raw)} (beyond the range of numbers once in SI units)")
    return value, False


def _bare(value: float, spec: Kind, raw: object) -> float:
    """A bare number: SI in Python; in a model file only zero, a plain number or a declared unit."""
    if not math.isfinite(value):
        raise UnitError(f"must be finite, got {format_value(raw) if isinstance(raw, str) else value}")
    declared = _DECLARED.get()
    if declared is None or not spec.si or value == 0.0:
        return value
    if spec.key in declared:
        return value * declared[spec.key][1]
    unit = spec.example_unit
    shown = raw.strip() if isinstance(raw, str) else format_value(raw)
    hint = f" (or declare [units] {spec.key} = \"{unit}\")" if spec.key in DECLARABLE else ""
    raise UnitError(f"a bare number needs a unit, e.g. \"{shown} {unit}\"{hint}, got {shown}")


def _from_quantity(raw, spec: Kind) -> float:
    """A pint Quantity (of any registry) converted through its unit text."""
    try:
        magnitude = float(raw.magnitude)
    except (TypeError, ValueError):
        raise UnitError(f"must be a single quantity (e.g. \"{spec.example}\"), got {raw!r}") from None
    if not math.isfinite(magnitude):
        raise UnitError(f"must be finite, got {magnitude}")
    text = format_value(raw)
    q = registry().Quantity(magnitude, registry().parse_units(str(raw.units)))
    return _convert(q, spec, text)


def _convert(q, spec: Kind, raw: str) -> float:
    names = _unit_names(q)
    if spec.name == "angular velocity" and names & _HERTZ_UNITS:
        raise UnitError(f"Hz is ambiguous for an angular speed; write rpm, rev/s or rad/s, got {_quoted(raw)}")
    if not spec.angular and spec.name != "frequency" and names & _ANGLE_UNITS:
        raise UnitError(f"must be {_article(spec.name)} (e.g. \"{spec.example}\"), "
                        f"got an angular quantity {_quoted(raw)}")
    target = _si_target(spec.si)
    if q.dimensionality != target.dimensionality:
        raise UnitError(f"must be {_article(spec.name)} (e.g. \"{spec.example}\"), got {_quoted(raw)}, "
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
