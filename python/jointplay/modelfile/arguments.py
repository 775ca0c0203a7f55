"""Arguments of the Python builder, converted by the model file's own field definitions.

``Model.add_body(mass="0.3 kg")``, ``add_clearance_revolute(clearance="0.5 mm")``: every physical
argument of the builder is a number (SI units), a string with a unit or a pint Quantity. Each one is
read by the validator of the matching model-file key (:mod:`.schema`), so units, ranges and messages
are defined once: ``joints.B.clearance: must be > 0, got -0.1 mm`` in a file and in Python alike.
A wrong argument raises a :class:`~jointplay.errors.ModelError` located by element name.
"""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel
from pydantic_core import PydanticCustomError

from ..errors import ModelError, Problem
from .fields import _vector, join
from .functions import function_spec


def _validator(cls: type[BaseModel], key: str):
    """The plain validator of a field of a model-file table (a quantity or a vector)."""
    for item in cls.model_fields[key].metadata:
        if hasattr(item, "func"):
            return item.func
    raise KeyError(f"{cls.__name__}.{key} has no validator")


def _fail(where: str, exc: PydanticCustomError):
    raise ModelError([Problem(where, exc.message())]) from None


def value(cls: type[BaseModel], key: str, raw: Any, where: str) -> Any:
    """``raw`` read as the key ``key`` of the table class ``cls``: a float, a list of two floats, or None
    for None; ``where`` is the element's location (``joints.B``)."""
    if raw is None:
        return None
    try:
        out = _validator(cls, key)(raw)
    except PydanticCustomError as exc:
        _fail(join(where, key), exc)
    if isinstance(out, tuple):
        return [float(v) for v in out]
    return float(out)


def point(raw: Any, where: str) -> list[float]:
    """A point ``(x, y)`` [m] of the ground or of a body."""
    try:
        x, y = _vector(raw, "length")
    except PydanticCustomError as exc:
        _fail(where, exc)
    return [float(x), float(y)]


def marker(raw: Any, where: str) -> dict:
    """A point of a spatial model, ``("x", "y", "z")`` or ``{"position": (...), "axes": <orientation>}``, as the
    core's ``{"position", "axes"}`` (axes None: the body's)."""
    from ..orientation import OrientationError
    from ..orientation import marker as read

    try:
        position, axes = read(raw)
    except OrientationError as exc:
        raise ModelError([Problem(join(where, *exc.at), exc.message)]) from None
    return {"position": position, "axes": axes}


def points(raw: dict[str, Any] | None, where: str) -> list[dict]:
    """Named points of a body, ``{"A": ("25 mm", 0)}``, as the core's list."""
    return [{"name": name, "position": point(p, join(where, "points", name))} for name, p in (raw or {}).items()]


def material(raw: dict, where: str) -> dict:
    """A material ``{"youngs_modulus": "207 GPa", "poisson_ratio": 0.3}``."""
    from .. import parameters as p
    from .schema import MaterialTable

    if not isinstance(raw, dict) or set(raw) != set(p.MATERIAL.keys()):
        raise ModelError([Problem(where, f"must be a material such as jointplay.laws.material(\"207 GPa\", 0.3), "
                                         f"got {raw!r}")])
    return {key: value(MaterialTable, key, raw[key], where) for key in p.MATERIAL.keys()}


def function(raw: Any, kind: str, where: str) -> dict:
    """A function of time (a dict from :mod:`jointplay.functions`, a number in SI units, a string with a
    unit or a pint Quantity for a constant) with its values converted to SI."""
    if isinstance(raw, (int, float)) and not isinstance(raw, bool):
        raw = float(raw)
    problems: list[Problem] = []
    spec = function_spec(raw, kind, where, problems)
    if problems or spec is None:
        raise ModelError(problems or [Problem(where, f"must be a function of time, got {raw!r}")])
    return spec


def law(raw: Any, key: str, where: str) -> dict:
    """A contact, stiffness or friction law (a dict from :mod:`jointplay.laws`, or written by hand with
    units: ``{"law": "ambrosio", "coefficient": 0.01, "v0": "0.1 mm/s"}``; None for the default law) checked
    as in a model file."""
    from .. import parameters as p
    from .build import Builder

    builder = Builder({})
    out = builder.law({} if raw is None else {key: raw}, p.CLEARANCE_REVOLUTE[key], where)
    if builder.problems or out is None:
        raise ModelError(builder.problems or [Problem(join(where, key), f"must be a law, got {raw!r}")])
    return out


def element(table, name: str, values: dict[str, Any], where: str, hint: str = "") -> dict:
    """The core's dict of an element of the Python builder: ``values`` (by key; None for the default) read
    as the table ``table`` (:mod:`jointplay.parameters`) of a model file, every problem in one ModelError.
    References to points and bodies are left to the core."""
    from .build import Builder
    from .schema import table_class

    raw = {key: value for key, value in values.items() if value is not None}
    if table.tag:
        raw = {table.tag: table.name, **raw}
    builder = Builder({}, check_references=False)
    t = builder.validate(table_class(table), raw, where, hint=hint)
    spec = None if t is None else builder.element_spec(table, name, where, t, raw)
    if builder.problems or spec is None:
        raise ModelError(builder.problems or [Problem(where, f"cannot be read: {values!r}")])
    return spec


def beam(table, name: str, values: dict[str, Any], where: str, hint: str = "") -> dict:
    """The core's dict of a beam of the Python builder (:func:`element` for the beam table): ``section`` a dict
    from :mod:`jointplay.sections`, ``material`` from :func:`jointplay.sections.material`."""
    from .build import Builder
    from .schema import BeamTable

    raw = {key: value for key, value in values.items() if value is not None}
    builder = Builder({}, check_references=False)
    stations = builder.arclengths(raw.get("points", {}), join(where, "points"))
    t = builder.validate(BeamTable, raw, where)
    spec = None if t is None else builder.beam(name, where, t, raw, stations)
    if builder.problems or spec is None:
        raise ModelError(builder.problems or [Problem(where, f"cannot be read: {values!r}")])
    return spec


def modal_body(table, name: str, values: dict[str, Any], where: str, hint: str = "") -> dict:
    """The core's dict of a modal body of the Python builder (:func:`beam` for the modal body table):
    ``interface`` and ``points`` dicts of arclengths, ``{"start": 0, "end": "300 mm"}`` (interface None: the two
    ends)."""
    from .build import Builder
    from .schema import ModalBodyTable

    raw = {key: value for key, value in values.items() if value is not None}
    builder = Builder({}, check_references=False)
    named = builder.modal_nodes(raw, where)
    t = builder.validate(ModalBodyTable, raw, where)
    spec = None if t is None else builder.modal_body(name, where, t, raw, named)
    if builder.problems or spec is None:
        raise ModelError(builder.problems or [Problem(where, f"cannot be read: {values!r}")])
    return spec
