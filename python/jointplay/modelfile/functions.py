"""Functions of time in a model file (driver motions, loads), validated in the units they prescribe.

A driver of a revolute joint prescribes an angle (rates in rad/s or rpm), a
driver of a translational joint a length, a point force a force, a torque a
torque. A bare number or a quantity string is a constant.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

from pydantic import ValidationError

from .. import parameters as p
from ..errors import Problem
from ..units import KINDS, per_time
from .fields import Strict, convert, did_you_mean, join, problems_from
from .schema import table_class

KINDS_OF_FUNCTION = tuple(t.name for t in p.variants(p.FUNCTIONS))
ALIASES = {alias: t.name for t in p.variants(p.FUNCTIONS) for alias in t.aliases}


@lru_cache(maxsize=None)
def function_tables(kind_name: str) -> dict[str, type[Strict]]:
    """The pydantic class of each kind of function whose value is a ``kind_name``."""
    return {name: table_class(t, KINDS[kind_name]) for name, t in p.FUNCTIONS.items() if name == t.name}


def function_spec(raw: Any, kind_name: str, where: str, problems: list[Problem]) -> dict | None:
    """The core's function dict for ``raw``, or None after adding problems."""
    if not isinstance(raw, dict):
        try:
            return {"kind": "constant", "value": float(convert(raw, kind_name))}
        except Exception as exc:  # a pydantic error from convert
            problems.append(Problem(where, _message(exc)))
            return None
    tag = raw.get("kind")
    key = ALIASES.get(tag, tag) if isinstance(tag, str) else tag
    if tag is None:
        problems.append(Problem(join(where, "kind"), f"missing required value (one of {', '.join(KINDS_OF_FUNCTION)})"))
        return None
    if key not in KINDS_OF_FUNCTION:
        hint = did_you_mean(tag, [*KINDS_OF_FUNCTION, *ALIASES])
        problems.append(Problem(join(where, "kind"), f"must be one of {', '.join(KINDS_OF_FUNCTION)}, got {tag!r}{hint}"))
        return None
    cls = function_tables(kind_name)[key]
    try:
        table = cls.model_validate(raw)
    except ValidationError as exc:
        problems.extend(problems_from(exc, where, cls, kind_hint=f"{key}: "))
        return None
    data = {k: (float(v) if isinstance(v, float) else v) for k, v in table.model_dump().items()}
    data["kind"] = key
    kind = KINDS[kind_name]
    if key == "polynomial":
        data["coefficients"] = _list(raw["coefficients"], lambda k: per_time(kind, k), join(where, "coefficients"),
                                     problems, min_length=1)
    elif key == "table":
        times = _list(raw["times"], lambda k: KINDS["time"], join(where, "times"), problems, min_length=2)
        values = _list(raw["values"], lambda k: kind, join(where, "values"), problems, min_length=2)
        if times is not None and values is not None:
            if len(times) != len(values):
                problems.append(Problem(join(where, "values"), f"must have as many entries as times ({len(times)}), got {len(values)}"))
            elif any(b <= a for a, b in zip(times, times[1:])):
                problems.append(Problem(join(where, "times"), f"must be strictly increasing, got {raw['times']!r}"))
        data["times"], data["values"] = times, values
    elif key == "cubic_step" and not data["t_end"] > data["t_start"]:
        problems.append(Problem(join(where, "t_end"), f"must be greater than t_start = {table.t_start.text}, got {table.t_end.text}"))
    if any(v is None for v in data.values()):
        return None
    return data


def _list(raw: Any, kind_of, where: str, problems: list[Problem], min_length: int) -> list[float] | None:
    if not isinstance(raw, list) or len(raw) < min_length:
        problems.append(Problem(where, f"must be a list of at least {min_length} values, got {raw!r}"))
        return None
    out = []
    for k, item in enumerate(raw):
        try:
            out.append(float(convert(item, kind_of(k))))
        except Exception as exc:
            problems.append(Problem(f"{where}[{k}]", _message(exc)))
    return out if len(out) == len(raw) else None


def _message(exc: Exception) -> str:
    return exc.message() if hasattr(exc, "message") else str(exc)
