"""Study files: a ``[study]`` table in TOML naming a model file, factors, a design and responses.

    [study]
    name = "clearance sweep"
    model = "flores_slider_crank_dry.toml"     # relative to this file
    t_end = "20 ms"
    set = { "joints.B.contact.restitution" = 0.9 }   # fixed for every case
    channels = ["slider.ax"]                          # kept per case on a common grid
    channel_step = "0.1 ms"

    [study.simulation]            # over the model's own [simulation] table
    method = "dopri5"

    [[study.factors]]
    name = "clearance"
    path = "joints.B.clearance"    # the --set path
    range = ["0.1 mm", "0.5 mm"]   # or levels = [...], or ISO 286: grades / grade_levels / fits

    [study.design]
    kind = "full_factorial"
    levels = 5

    [[study.responses]]
    name = "peak_force"
    kind = "peak"
    channel = "B.f"

    [study.optimize]               # for `jointplay optimize`
    objectives = [{ response = "peak_force", weight = 1.0 }]

Nothing in a study file is executed. Every problem found comes back in one ModelError, located in the
file's terms (``study.factors[1].range``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..errors import ModelError, Problem
from ..units import UnitError, to_si
from .factors import Factor, continuous, discrete

#: Keys of the ``[study]`` table.
STUDY_KEYS = {"name", "model", "t_end", "set", "simulation", "channels", "channel_step", "factors", "design",
              "responses", "optimize", "seed", "description"}
#: Keys of one factor: its name and path, and exactly one way of giving its values.
FACTOR_KEYS = {"name", "path", "description", "nominal", "at"}
FACTOR_VALUES = ("range", "levels", "grades", "grade_levels", "fits")


def load_study(path: str | Path):
    """A :class:`~jointplay.study.Study` from a study file; raises ModelError with every problem located."""
    from ..modelfile import read_document
    from .study import Study

    path = Path(path)
    doc = read_document(path)
    table = doc.get("study")
    if not isinstance(table, dict):
        raise ModelError([Problem(str(path), "has no [study] table (a study file names its model, factors, design "
                                             "and responses under [study])")])
    problems = [Problem(f"study.{key}", f"is not a key of [study] (keys: {', '.join(sorted(STUDY_KEYS))})")
                for key in table if key not in STUDY_KEYS]
    problems += [Problem(key, "is not allowed beside [study] in a study file") for key in doc if key != "study"]
    model = table.get("model")
    if not isinstance(model, str) or not model:
        problems.append(Problem("study.model", f"must name the model file (a path relative to the study file), "
                                               f"got {model!r}"))
    elif not (path.parent / model).is_file():
        problems.append(Problem("study.model", f"no model file {model!r} next to {path.name} "
                                               f"(looked for {path.parent / model})"))
    for key, kind in (("set", dict), ("simulation", dict), ("design", dict), ("optimize", dict), ("channels", list),
                      ("factors", list), ("responses", list)):
        if key in table and not isinstance(table[key], kind):
            problems.append(Problem(f"study.{key}", f"must be {'a table' if kind is dict else 'a list'}, "
                                                    f"got {table[key]!r}"))
    if problems:
        raise ModelError(problems)
    study = Study(path.parent / model, table.get("factors", []), table.get("design", {"kind": "full_factorial"}),
                  table.get("responses", []), t_end=table.get("t_end"), options=table.get("simulation"),
                  channels=table.get("channels", []), channel_step=table.get("channel_step"),
                  fixed=table.get("set"), name=table.get("name") or path.stem, seed=_seed(table.get("seed", 0)),
                  file_values=True)
    study.optimize_spec = dict(table.get("optimize") or {})
    study.source = str(path)
    return study


def _seed(raw: Any) -> int:
    if isinstance(raw, bool) or not isinstance(raw, int) or raw < 0:
        raise ModelError([Problem("study.seed", f"must be a whole number >= 0, got {raw!r}")])
    return raw


def parse_factors(entries: list, where: str) -> list[Factor]:
    """Factors from their tables (or Factor objects); one located problem per bad entry."""
    factors, problems = [], []
    for k, entry in enumerate(entries):
        at = f"{where}[{k}]"
        if isinstance(entry, Factor):
            factors.append(entry)
            continue
        try:
            factors.append(parse_factor(entry, at))
        except ModelError as exc:
            problems.extend(exc.problems)
    names = [f.name for f in factors]
    paths = [f.path for f in factors]
    problems += [Problem(f"{where}[{k}].name", f"repeats the factor name {n!r}")
                 for k, n in enumerate(names) if names.index(n) != k]
    problems += [Problem(f"{where}[{k}].path", f"repeats the path {p!r} of another factor")
                 for k, p in enumerate(paths) if paths.index(p) != k]
    if problems:
        raise ModelError(problems)
    return factors


def parse_factor(entry: Any, where: str) -> Factor:
    """One factor from its table."""
    from ..modelfile import parse_assignment

    if not isinstance(entry, dict):
        raise ModelError([Problem(where, f"must be a table with name, path and range or levels, got {entry!r}")])
    unknown = set(entry) - FACTOR_KEYS - set(FACTOR_VALUES)
    if unknown:
        raise ModelError([Problem(f"{where}.{sorted(unknown)[0]}", "is not a key of a factor (keys: "
                                  f"{', '.join(sorted(FACTOR_KEYS | set(FACTOR_VALUES)))})")])
    path = entry.get("path")
    if not isinstance(path, str) or not path:
        raise ModelError([Problem(f"{where}.path", "must be the --set path of a model value, e.g. "
                                                   f"\"joints.B.clearance\", got {path!r}")])
    parse_assignment(f"{path}=0")
    name = entry.get("name", path.replace(".", "_"))
    if not isinstance(name, str) or not name.isidentifier():
        raise ModelError([Problem(f"{where}.name", f"must be a name of letters, digits and _ , got {name!r}")])
    given = [key for key in FACTOR_VALUES if key in entry]
    if len(given) != 1:
        raise ModelError([Problem(where, "must give its values in exactly one way: " + " or ".join(FACTOR_VALUES)
                                  + (f" (got {', '.join(given)})" if given else ""))])
    key, description = given[0], str(entry.get("description", ""))
    value = entry[key]
    if key == "range":
        if not isinstance(value, list) or len(value) != 2:
            raise ModelError([Problem(f"{where}.range", f"must be [low, high], got {value!r}")])
        return continuous(name, path, value[0], value[1], where, description)
    if key == "levels":
        if not isinstance(value, list):
            raise ModelError([Problem(f"{where}.levels", f"must be a list of values, got {value!r}")])
        return discrete(name, path, value, where, description)
    return iso_factor(key, name, path, entry, where, description)


def iso_factor(key: str, name: str, path: str, entry: dict, where: str, description: str) -> Factor:
    """A clearance joint's RADIAL clearance from ISO 286 grades or fits (docs/theory/iso-286-fits.md)."""
    from . import iso286

    value = entry[key]
    if key == "fits":
        if not isinstance(value, list) or not value:
            raise ModelError([Problem(f"{where}.fits", f"must list fits such as [\"12 H7/g6\"], got {value!r}")])
        at = _choice(entry.get("at", "mean"), ("min", "mean", "max"), f"{where}.at")
        fits = [iso286.parse_fit(text, f"{where}.fits") for text in value]
        levels = [fit.radial_clearance(at) for fit in fits]
        return _iso(discrete(name, path, [f"{c!r} m" for c in levels], where, description,
                             labels=[str(t) for t in value]), None)
    nominal = _nominal(entry, where)
    if key == "grades":
        if not isinstance(value, list) or len(value) != 2:
            raise ModelError([Problem(f"{where}.grades", f"must be [lowest, highest] grades such as [\"IT6\", \"IT8\"], "
                                                         f"got {value!r}")])
        low, high = iso286.grade_range(value[0], value[1], nominal)
        return _iso(continuous(name, path, f"{low / 2!r} m", f"{high / 2!r} m", where,
                               description or f"radial clearance over {value[0]}..{value[1]} at "
                                              f"{nominal * 1e3:g} mm (paper 003's grade bands)"), nominal)
    if not isinstance(value, list) or not value:
        raise ModelError([Problem(f"{where}.grade_levels", f"must list grades such as [\"IT6\", \"IT7\"], got {value!r}")])
    at = _choice(entry.get("at", "middle"), ("low", "middle", "high"), f"{where}.at")
    levels = []
    for grade in value:
        low, high = iso286.grade_band(grade, nominal)
        diametral = {"low": low, "middle": 0.5 * (low + high), "high": high}[at]
        levels.append(f"{diametral / 2!r} m")
    return _iso(discrete(name, path, levels, where, description, labels=[str(g) for g in value]), nominal)


def _iso(factor: Factor, nominal: float | None) -> Factor:
    from dataclasses import replace

    return replace(factor, nominal=nominal)


def _nominal(entry: dict, where: str) -> float:
    if "nominal" not in entry:
        raise ModelError([Problem(f"{where}.nominal", "missing: grades need the nominal diameter, e.g. \"12 mm\"")])
    try:
        value = to_si(entry["nominal"], "length")
    except UnitError as exc:
        raise ModelError([Problem(f"{where}.nominal", str(exc))]) from None
    return value


def _choice(raw: Any, choices: tuple[str, ...], where: str) -> str:
    if raw not in choices:
        raise ModelError([Problem(where, f"must be one of {', '.join(choices)}, got {raw!r}")])
    return raw
