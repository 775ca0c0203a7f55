"""The tables of a model file as pydantic models, built from their definitions in :mod:`jointplay.parameters`.

Quantities arrive as SI floats that remember their text (:class:`~.fields.Q`). Each :class:`~jointplay.parameters.Table`
becomes one class (:func:`table_class`): a field per key, typed by its kind and range, with its default.
Tables tagged by ``type`` (joints, forces), ``law`` (contact, stiffness, friction, transition) or ``kind``
(functions of time) are dispatched by :mod:`.build`, which then validates the matching class here. Laws,
functions of time and the lubrication table are checked by :mod:`.build` on their own (their fields here
accept anything).
"""

from functools import lru_cache
from typing import Annotated, Any

from pydantic import Field, PlainValidator, create_model

from .. import parameters as p
from ..units import KINDS, Kind, per_time
from .fields import Flag, Q, Strict, choice, count, fail, quantity, text, vector, vector3

#: What a reference names, in the message of a value that is not a string.
_NAMES = {"point": "a point", "body": "a body", "joint": "a joint"}


def _output_bytes(raw: Any) -> int:
    from ..resultsfile import parse_size

    try:
        return parse_size(raw)
    except ValueError as exc:
        raise fail(str(exc)) from None


Size = Annotated[int, PlainValidator(_output_bytes)]


def _req(kind: str) -> Any:
    """A required field whose missing-value message names what is expected."""
    return Field(..., description=kind)


def unit_kind(param: p.Param, value: Kind | None = None) -> Kind | None:
    """The kind of physical quantity of a key (of its components, for a vector), None for other keys;
    ``value`` is the kind a function of time prescribes."""
    kind = param.of if param.kind in ("vector", "vector3") else param.kind
    if kind == "value":
        return value
    if kind == "rate":
        return per_time(value, 1)
    return KINDS.get(kind) if isinstance(kind, str) else None


def field_type(param: p.Param, value: Kind | None = None) -> Any:
    """The annotated type that validates a key."""
    kind = unit_kind(param, value)
    if param.kind == "vector":
        return vector(kind)
    if param.kind == "vector3":
        return vector3(param.of, **param.bounds)
    if kind is not None:
        return quantity(kind, **param.bounds)
    if param.kind in _NAMES:
        return text(_NAMES[param.kind])
    simple = {"text": lambda: text(param.of), "flag": lambda: Flag, "count": lambda: count(**param.bounds), "size": lambda: Size,
              "choice": lambda: choice(*param.of, aliases=dict(param.aliases)),
              "points": lambda: dict[str, Any], "markers": lambda: dict[str, Any]}
    if param.kind in simple:
        return simple[param.kind]()
    if param.kind == "table" and not param.apart:
        return table_class(param.of)
    return Any  # laws, variants, functions of time, lists, the grid, arclengths and tables checked apart: build.py


def _q(value: float, kind: Kind) -> Q:
    return Q(value, f"{value:g} {kind.si.replace('*', ' ')}".strip())


def field_default(param: p.Param, sparse: bool, value: Kind | None = None) -> Any:
    """The field's default: required (with what to write), None, or the definition's value."""
    if param.required:
        if value is None:
            return _req(param.example)
        return _req(param.example.format(kind=value.name, example=value.example,
                                         rate_example=per_time(value, 1).example))
    if sparse or param.default is None:
        return None
    kind = unit_kind(param, value)
    if param.kind in ("vector", "vector3"):
        return tuple(_q(v, kind) for v in param.default)
    if kind is not None:
        return _q(param.default, kind)
    if param.kind == "table" and not param.apart:
        return table_class(param.of).model_validate(param.default)
    if param.kind in ("points", "arclengths", "nodes", "markers"):
        return Field(default_factory=dict)
    return param.default


@lru_cache(maxsize=None)
def table_class(table: p.Table, value: Kind | None = None) -> type[Strict]:
    """The pydantic class of a table (of a function of time prescribing ``value``)."""
    fields: dict[str, Any] = {table.tag: (str, ...)} if table.tag else {}
    for param in table.params:
        fields[param.key] = (field_type(param, value), field_default(param, table.sparse, value))
    name = "".join(w.title() for w in table.name.split("_")) + "Table"
    return create_model(name, __base__=Strict, __doc__=table.doc, **fields)


def classes(tables: dict[str, p.Table]) -> dict[str, type[Strict]]:
    """The class of each variant of a family, aliases included."""
    return {name: table_class(t) for name, t in tables.items()}


ModelTable = table_class(p.MODEL)
GroundTable = table_class(p.GROUND)
BodyTable = table_class(p.BODY)
BeamTable = table_class(p.BEAM)
ModalBodyTable = table_class(p.MODAL_BODY)
BeamMaterialTable = table_class(p.BEAM_MATERIAL)
BEAM_SECTIONS = classes(p.BEAM_SECTIONS)
SENSORS = classes(p.SENSORS)
MaterialTable = table_class(p.MATERIAL)
ClearanceRevoluteTable = table_class(p.CLEARANCE_REVOLUTE)
TranslationalTable = table_class(p.TRANSLATIONAL)
DriverTable = table_class(p.DRIVER)
LubricationTable = table_class(p.LUBRICATION)
SimulationTable = table_class(p.SIMULATION)

SpatialModelTable = table_class(p.SPATIAL_MODEL)
SpatialBodyTable = table_class(p.SPATIAL_BODY)
SPATIAL_JOINTS = classes(p.SPATIAL_JOINTS)
SPATIAL_FORCES = classes(p.SPATIAL_FORCES)

JOINTS = classes(p.JOINTS)
FORCES = classes(p.FORCES)
CONTACT_LAWS = classes(p.CONTACT_LAWS)
STIFFNESS_LAWS = classes(p.STIFFNESS_LAWS)
FRICTION_LAWS = classes(p.FRICTION_LAWS)
TRANSITION_LAWS = classes(p.TRANSITION_LAWS)
LAWS = {key: classes(family) for key, family in p.LAWS.items()}

TOP_LEVEL = p.SECTIONS
FILM_MODELS, REYNOLDS_MODELS, REYNOLDS_ONLY_KEYS = p.FILM_MODELS, p.REYNOLDS_MODELS, p.REYNOLDS_ONLY_KEYS
