"""Field types of model files: quantities with units, vectors, references, choices.

Each validator turns what the user wrote into SI data and, when it cannot,
raises a pydantic error whose message names the offending value as written
(``must be > 0, got -0.1 mm``). :func:`problems_from` turns a pydantic
``ValidationError`` into jointplay :class:`~jointplay.errors.Problem`\\ s with
dotted locations in the user's terms.
"""

from __future__ import annotations

import difflib
import math
from functools import lru_cache
from typing import Annotated, Any

from pydantic import BaseModel, ConfigDict, PlainValidator, ValidationError
from pydantic_core import PydanticCustomError

from ..errors import Problem
from ..units import KINDS, Kind, UnitError, format_value, to_si


class Q(float):
    """A float in SI units that remembers how the user wrote it (``.text``), for messages."""

    text: str

    def __new__(cls, value: float, text: str | None = None):
        obj = float.__new__(cls, value)
        obj.text = text if text is not None else repr(float(value))
        return obj


class Strict(BaseModel):
    """Base of every table of a model file: unknown keys are errors."""

    model_config = ConfigDict(extra="forbid", frozen=True)


def fail(message: str) -> PydanticCustomError:
    """A pydantic error carrying ``message`` verbatim."""
    return PydanticCustomError("jointplay", "{message}", {"message": message})


def _kind(kind: str | Kind) -> Kind:
    return KINDS[kind] if isinstance(kind, str) else kind


def convert(raw: Any, kind: str | Kind, *, gt: float | None = None, ge: float | None = None,
            lt: float | None = None, le: float | None = None, interval: str | None = None) -> Q:
    """``raw`` converted to SI and range-checked; raises a pydantic error for the user."""
    spec = _kind(kind)
    try:
        value = to_si(raw, spec)
    except UnitError as exc:
        raise fail(str(exc)) from None
    text = format_value(raw, spec)
    bounds_ok = ((gt is None or value > gt) and (ge is None or value >= ge)
                 and (lt is None or value < lt) and (le is None or value <= le))
    if not bounds_ok:
        if interval is not None:
            raise fail(f"must lie in {interval}, got {text}")
        unit = spec.si.replace("*", " ")

        def bound(b: float) -> str:  # a bound other than zero in the SI unit of the kind
            return f"{b:g} {unit}" if b != 0 and unit else f"{b:g}"

        rule = " and ".join(r for r in [
            f"> {bound(gt)}" if gt is not None else "", f">= {bound(ge)}" if ge is not None else "",
            f"< {bound(lt)}" if lt is not None else "", f"<= {bound(le)}" if le is not None else ""] if r)
        raise fail(f"must be {rule}, got {text}")
    return Q(value, text)


def quantity(kind: str | Kind, **bounds) -> Any:
    """An annotated field type: a quantity of ``kind`` (number in SI or string with a unit)."""
    return Annotated[float, PlainValidator(lambda raw: convert(raw, kind, **bounds))]


def _vector(raw: Any, kind: str | Kind) -> tuple[Q, Q]:
    if not isinstance(raw, (list, tuple)) or len(raw) != 2:
        example = _kind(kind).example
        raise fail(f"must be a pair [x, y] (e.g. [\"{example}\", 0]), got {_show(raw)}")
    out = []
    for k, component in enumerate(raw):
        try:
            out.append(convert(component, kind))
        except PydanticCustomError as exc:
            message = exc.message()
            glue = ": " if message.startswith("a bare number") else " "
            raise fail(f"{'xy'[k]} component{glue}{message}") from None
    return out[0], out[1]


def vector(kind: str | Kind) -> Any:
    """An annotated field type: a pair ``[x, y]`` of quantities of ``kind``."""
    return Annotated[tuple[float, float], PlainValidator(lambda raw: _vector(raw, kind))]


def _vector3(raw: Any, kind: str, bounds: dict[str, Any]) -> tuple[float, float, float]:
    from ..orientation import OrientationError
    from ..orientation import vector3 as read

    try:
        return tuple(read(raw, kind, **bounds))
    except OrientationError as exc:
        raise fail(exc.message) from None


def vector3(kind: str, **bounds: Any) -> Any:
    """An annotated field type: three quantities ``[x, y, z]`` of ``kind`` (spatial models)."""
    return Annotated[tuple[float, float, float], PlainValidator(lambda raw: _vector3(raw, kind, bounds))]


def _name_text(raw: Any, what: str) -> str:
    if not isinstance(raw, str):
        raise fail(f"must be a string naming {what}, got {_show(raw)}")
    return raw


def text(what: str) -> Any:
    """An annotated field type: a string (a name or a reference)."""
    return Annotated[str, PlainValidator(lambda raw: _name_text(raw, what))]


def _choice(raw: Any, choices: tuple[str, ...], aliases: dict[str, str]) -> str:
    if isinstance(raw, str):
        key = raw.strip().lower()
        if key in choices:
            return key
        if key in aliases:
            return aliases[key]
    raise fail(f"must be one of {', '.join(choices)}, got {_show(raw)}{did_you_mean(raw, [*choices, *aliases])}")


def choice(*choices: str, aliases: dict[str, str] | None = None) -> Any:
    """An annotated field type: one of a few words."""
    return Annotated[str, PlainValidator(lambda raw: _choice(raw, choices, aliases or {}))]


def _flag(raw: Any) -> bool:
    if not isinstance(raw, bool):
        raise fail(f"must be true or false, got {_show(raw)}")
    return raw


Flag = Annotated[bool, PlainValidator(_flag)]


def _count(raw: Any, most: float | None = None) -> int:
    if isinstance(raw, bool) or not isinstance(raw, int) or raw <= 0:
        range_text = f" from 1 to {most:g}" if most is not None else ""
        raise fail(f"must be a positive whole number{range_text}, got {_show(raw)}")
    if most is not None and raw > most:
        raise fail(f"must be a whole number from 1 to {most:g}, got {_show(raw)}")
    return raw


Count = Annotated[int, PlainValidator(_count)]


def count(le: float | None = None, **_: Any) -> Any:
    """An annotated field type: a positive whole number, at most ``le`` when given."""
    return Count if le is None else Annotated[int, PlainValidator(lambda raw: _count(raw, le))]


def _show(raw: Any) -> str:
    if isinstance(raw, str):
        return repr(raw)
    if isinstance(raw, bool):
        return str(raw).lower()
    if isinstance(raw, float) and not math.isfinite(raw):
        return str(raw)
    if isinstance(raw, dict):
        return "a table"
    return repr(raw)


def did_you_mean(word: Any, options) -> str:
    """`` (did you mean "x"?)`` when a close option exists, else ``""``."""
    if not isinstance(word, str):
        return ""
    close = difflib.get_close_matches(word, list(options), n=1, cutoff=0.6)
    return f" (did you mean \"{close[0]}\"?)" if close else ""


def join(*parts: Any) -> str:
    """A dotted location; keys that are not plain words are quoted as in TOML. (Kept per parts: a model
    file's reader forms the location of every value before it knows whether a message needs it.)"""
    try:
        return _joined(*parts)
    except TypeError:  # a part that cannot be a key of the cache (a list)
        return _joined.__wrapped__(*parts)


@lru_cache(maxsize=8192, typed=True)
def _joined(*parts: Any) -> str:
    out = []
    for p in parts:
        if p is None or p == "":
            continue
        if isinstance(p, int):
            out.append(f"[{p}]")
            continue
        p = str(p)
        word = p if p.replace("_", "").replace("-", "").isalnum() or "." in p and all(
            s and s.replace("_", "").replace("-", "").isalnum() for s in p.split(".")) else f'"{p}"'
        out.append(word)
    return ".".join(out).replace(".[", "[")


def problems_from(error: ValidationError, where: str, cls: type[BaseModel], kind_hint: str = "") -> list[Problem]:
    """One Problem per pydantic error, located under ``where``."""
    problems = []
    for e in error.errors(include_url=False):
        loc = [p for p in e["loc"] if p not in ("function-plain",)]
        location = join(where, *loc)
        etype = e["type"]
        if etype == "extra_forbidden":
            fields = _fields_at(cls, loc[:-1])
            hint = did_you_mean(loc[-1], fields)
            allowed = f"; {kind_hint}allowed: {', '.join(fields)}" if not hint and fields else ""
            problems.append(Problem(location, f"unknown key{hint}{allowed}"))
        elif etype == "missing":
            problems.append(Problem(location, f"missing required value{_expected(cls, loc)}"))
        elif etype == "jointplay":
            problems.append(Problem(location, e["msg"]))
        elif etype in ("model_type", "model_attributes_type", "dict_type"):
            problems.append(Problem(location, f"must be a table, got {_show(e.get('input'))}"))
        else:
            problems.append(Problem(location, f"{e['msg']}, got {_show(e.get('input'))}"))
    return problems


def _fields_at(cls: type[BaseModel], loc) -> list[str]:
    for part in loc:
        field = cls.model_fields.get(part) if isinstance(part, str) else None
        sub = getattr(field, "annotation", None) if field else None
        if isinstance(sub, type) and issubclass(sub, BaseModel):
            cls = sub
        else:
            return []
    return list(cls.model_fields)


def _expected(cls: type[BaseModel], loc) -> str:
    if len(loc) != 1 or not isinstance(loc[0], str):
        return ""
    field = cls.model_fields.get(loc[0])
    desc = field.description if field is not None else None
    return f" ({desc})" if desc else ""
