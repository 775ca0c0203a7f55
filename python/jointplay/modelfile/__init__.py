"""Model files: a mechanism described in TOML with units.

``load(path)`` reads a file (``tomllib`` only: nothing in it is executed),
applies ``--set`` style overrides, validates every table (units, ranges,
unknown keys, references, geometry), compiles the mechanism in the core and
assembles its initial configuration. Every problem found comes back in one
:class:`~jointplay.errors.ModelError`, located in the file's own terms
(``joints.B.clearance``). A bare number in a dimensional key is an error
unless the file's ``[units]`` table declares the unit of its kind.
``plausibility(spec)`` lists legal but suspicious values (warnings, not
errors). ``to_toml(model)`` writes a model back, every unit spelled out;
loading that text gives the same model. The keys are defined in :mod:`jointplay.parameters` and listed
in ``docs/model-file-reference.md``.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path
from typing import Any

from ..errors import ModelError, Problem, SimulationError
from ..parameters import DEFAULT_NAME
from .build import Builder
from .overrides import apply_overrides, parse_assignment
from .plausibility import plausibility
from .writer import to_toml as _spec_to_toml

__all__ = ["apply_overrides", "load", "loads", "parse_assignment", "plausibility", "read_document", "read_spec",
           "spec_of_document", "to_toml"]


def read_document(path: str | Path) -> dict:
    """The parsed TOML of a model file; a missing or unreadable file is a ModelError."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        raise ModelError([Problem(str(path), "no such file")]) from None
    except OSError as exc:  # a folder, no permission, a device...
        raise ModelError([Problem(str(path), f"cannot be read: {exc.strerror or exc}")]) from None
    return parse_text(_text(data, str(path)), str(path))


def _text(data: bytes, where: str) -> str:
    """The UTF-8 text of a model file; a binary file (NUL bytes, not UTF-8) is a ModelError."""
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        _raise(where, "is UTF-16 text (it starts with a UTF-16 byte-order mark); a model file is TOML text in "
                      "UTF-8: save it as UTF-8")
    nul = data.find(b"\x00")
    if nul >= 0:
        _raise(where, f"is a binary file (a NUL byte at offset {nul}), not a TOML model file")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        return _raise(where, f"is not UTF-8 text (byte 0x{data[exc.start]:02x} at offset {exc.start}); "
                             "a model file is TOML text in UTF-8")


def parse_text(text: str, where: str = "model file") -> dict:
    """TOML text to a dict; a syntax error is a ModelError naming the line."""
    if text.startswith("\ufeff"):
        _raise(where, "starts with a UTF-8 byte-order mark (BOM, the bytes EF BB BF), which TOML does not allow; "
                      "save the file as UTF-8 without BOM")
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        return _raise(where, f"is not valid TOML: {exc}")
    except RecursionError:
        return _raise(where, f"is nested too deeply to be read: arrays or inline tables inside one another hundreds "
                             f"of levels deep (a model file needs at most {MAX_DEPTH})")
    check_depth(doc, where)
    return doc


#: Most levels of tables and arrays inside one another in a model file; the deepest a model needs is about 6
#: (``modal_bodies.link.matrices.mass.values[k]``).
MAX_DEPTH = 32


def check_depth(doc: Any, where: str = "model file") -> None:
    """ModelError when tables and arrays in ``doc`` are nested more than :data:`MAX_DEPTH` levels deep (the
    readers after this one recurse through them), naming the key where it goes too deep."""
    stack: list[tuple[Any, int, tuple]] = [(doc, 0, ())]
    while stack:
        node, depth, path = stack.pop()
        if depth > MAX_DEPTH:
            from .fields import join

            _raise(join(*path[:3]) or where, f"holds tables and arrays nested more than {MAX_DEPTH} levels deep; a "
                                             "model file needs at most a few levels")
        if isinstance(node, dict):
            stack.extend((value, depth + 1, (*path, key)) for key, value in node.items())
        elif isinstance(node, list):
            stack.extend((value, depth + 1, (*path, k)) for k, value in enumerate(node))


def _raise(location: str, message: str):
    raise ModelError([Problem(location, message)])


def load(path: str | Path, overrides: list[str] | dict[str, Any] | None = None, *, check: bool = True):
    """A :class:`~jointplay.Model` from a model file, with ``overrides`` (``["joints.B.clearance=0.1 mm"]``
    or ``{"joints.B.clearance": "0.1 mm"}``) applied first. With ``check`` the initial configuration is
    assembled too, so an impossible geometry is reported here. Raises ModelError."""
    doc = read_document(path)
    model = from_document(doc, overrides, name=Path(path).stem, check=check, base=Path(path).parent)
    model.source_file = str(path)  # for the results file's model_file attribute
    return model


def loads(text: str, overrides: list[str] | dict[str, Any] | None = None, *, name: str = DEFAULT_NAME,
          check: bool = True):
    """Like :func:`load`, from TOML text."""
    return from_document(parse_text(text), overrides, name=name, check=check)


def read_spec(path: str | Path, overrides: list[str] | dict[str, Any] | None = None) -> tuple[dict, dict]:
    """The core's spec (plain data in SI units, as :meth:`jointplay.Model.to_spec` gives and
    :meth:`jointplay.Model.to_json` sends to the core) and the ``[simulation]`` defaults of a model file, every
    table checked but nothing compiled; raises ModelError."""
    return spec_of_document(read_document(path), overrides, name=Path(path).stem, base=Path(path).parent)


def spec_of_document(doc: dict, overrides=None, *, name: str = DEFAULT_NAME,
                     base: Path | None = None) -> tuple[dict, dict]:
    """:func:`read_spec` of an already parsed document."""
    check_depth(doc, "the model")
    if overrides:
        doc = apply_overrides(doc, overrides)
        check_depth(doc, "the model")
    return Builder(doc, default_name=name, base=base).run().result()


def from_document(doc: dict, overrides=None, *, name: str = DEFAULT_NAME, check: bool = True,
                  base: Path | None = None):
    """A Model from an already parsed document; files it names (a modal body's matrices) are found from
    ``base`` (default: the working folder)."""
    from ..model import Model

    spec, simulation = spec_of_document(doc, overrides, name=name, base=base)
    model = Model.from_spec(spec)
    model.simulation = simulation
    description = doc.get("model", {}).get("description") if isinstance(doc.get("model"), dict) else None
    model.description = description if isinstance(description, str) else ""
    try:
        model.compile()
    except ModelError as exc:
        raise ModelError([Problem(core_location(p.location, spec), p.message) for p in exc.problems]) from None
    _check_formulation(model)
    if check:
        try:
            model._assembled()
        except SimulationError as exc:
            raise assembly_error(exc, spec) from None
    return model


def assembly_error(exc: SimulationError, spec: dict) -> ModelError:
    """A failed assembly as a ModelError located at its element, followed by the plausibility findings
    (made independently of the assembly: a unit slip in a mass is often what made it fail)."""
    from .plausibility import plausibility

    where = body_location(exc.element, spec)
    if where == "model":
        where = element_location(exc.element, spec)
    found = plausibility(spec)
    problems = [Problem(where, exc.cause)]
    problems += [Problem(p.location, f"(plausibility, may explain the above) {p.message}") for p in found]
    return ModelError(problems)


def _check_formulation(model) -> None:
    """``[simulation] formulation = "joint_coordinates"`` needs a tree of ideal joints (the core refuses it at
    the start of a run otherwise)."""
    if model.simulation.get("formulation") != "joint_coordinates":
        return
    described = model.compile().describe()
    if described.get("joint_coordinates") is None:
        _raise("simulation.formulation", "joint_coordinates needs a tree of ideal joints, but "
                                         f"{described.get('absolute_because')}; use \"auto\" or \"absolute\"")


def to_toml(model, header: str | None = None) -> str:
    """Model-file text for a Model (with its ``simulation`` defaults) or a plain spec dict."""
    if isinstance(model, dict):
        return _spec_to_toml(model, None, header)
    return _spec_to_toml(model.to_spec(), getattr(model, "simulation", None), header)


_INDEXED = re.compile(r"^(ground_points|bodies|beams|modal_bodies|joints|drivers|forces|sensors|spatial_bodies"
                      r"|spatial_joints|spatial_forces|spatial_clearance_joints)\[(\d+)\](?:\.(points|interface)\[(\d+)\])?")
#: The file's section of each section of a spatial model's spec.
_FILE_SECTION = {"spatial_bodies": "bodies", "spatial_joints": "joints", "spatial_forces": "forces",
                 "spatial_clearance_joints": "joints"}


def core_location(location: str, spec: dict) -> str:
    """``joints[2].clearance`` (the core's index) to ``joints.B.clearance`` (the file's names)."""
    from .fields import join

    match = _INDEXED.match(location)
    if not match:
        return location
    section, index, points, point = match.group(1), int(match.group(2)), match.group(3), match.group(4)
    try:
        entry = spec[section][index]
        if section == "ground_points":
            head = join("ground", "points", entry["name"])
        else:
            head = join(_FILE_SECTION.get(section, section), entry["name"])
            if point is not None:
                head = join(head, points, entry[points][int(point)]["name"])
    except (KeyError, IndexError):
        return location
    rest = location[match.end():]
    return head + rest


def body_location(name: str | None, spec: dict) -> str:
    """The table of a named body, beam or modal body (``bodies.crank``); ``model`` when unknown."""
    from .fields import join

    for section in ("bodies", "beams", "modal_bodies", "spatial_bodies"):
        if name and any(e["name"] == name for e in spec.get(section) or []):
            return join(_FILE_SECTION.get(section, section), name)
    return "model"


def element_location(element: str | None, spec: dict) -> str:
    """The table of a named element (``B (assembly lock)`` -> ``joints.B``); ``model`` when unknown."""
    from .fields import join

    if not element:
        return "model"
    name = element.removesuffix(" (assembly lock)")
    for section in ("joints", "drivers", "forces", "sensors", "bodies", "beams", "modal_bodies", *_FILE_SECTION):
        if any(e["name"] == name for e in spec.get(section) or []):
            return join(_FILE_SECTION.get(section, section), name)
    return "model"
