"""Simulation options read where they are given, every check of the core made first, with its key.

``Model.simulate(...)``, ``jointplay run`` and a model file's ``[simulation]`` table read the same options
(:data:`jointplay.parameters.SIMULATION`): quantities through the model file's own validators (a number in
SI units, a string with a unit or a pint Quantity; ``simulation.max_step: must be > 0, got -1 ms``), and the
bounds between keys as the table's relations, with the core's defaults standing in for keys not given
(``simulation.max_step: must be greater than min_step = 1e-14 s (its value when not given ...)``). What the
core's ``IntegratorOptions::validate`` refuses is refused here first, as a :class:`~jointplay.errors.ModelError`
located at ``simulation.<key>``: the core's own check stays as a second line (its ValueError would otherwise
reach the user as a traceback naming a field of its own).
"""

from __future__ import annotations

import math
import re
from numbers import Integral, Real
from typing import Any

from . import parameters as p
from .errors import ModelError, Problem

_TABLE = p.SIMULATION
#: Option names accepted for each method, stabilization and formulation.
METHODS = {**{m: m for m in p.METHODS}, **dict(p.METHOD_ALIASES)}
#: Largest count the core holds (an unsigned 64-bit number).
MAX_COUNT = 2**64 - 1
#: Quantities read by the model file's validators (number in SI, string with a unit, pint Quantity).
_QUANTITIES = ("rtol", "atol", "max_step", "output_step", "initial_step", "min_step", "step")
_NEEDS_STEP = ("generalized_alpha integrates with a fixed nominal step and needs one, for example step=1e-3 (s); "
               "its accuracy is that step's")


def read(t0: Any, t_end: Any, given: dict[str, Any]) -> dict:
    """The core's options from ``given`` (keys of ``[simulation]``; None: not given) for a run from ``t0``
    to ``t_end`` [s]; raises ModelError with one problem per bad option."""
    problems: list[Problem] = []
    values = {key: _quantity(key, given.get(key), problems) for key in _QUANTITIES}
    for key in ("rtol", "atol"):
        if given.get(key) is None:
            problems.append(Problem(f"simulation.{key}", "must be a number, got None"))
    _end_time(_start_time(t0, problems), t_end, problems)
    choices, counts = _choices(given, problems), _counts(given, problems)
    options = {"method": choices["method"], **{key: values[key] for key in _QUANTITIES[:-1]},
               "max_steps": counts.pop("max_steps", None), "stabilization": choices["stabilization"],
               "formulation": choices["formulation"], "jacobian": choices["jacobian"], **counts,
               "step": values["step"]}
    if options["method"] == "generalized_alpha" and given.get("step") is None:
        problems.append(Problem("simulation.step", _NEEDS_STEP))
    radius = given.get("spectral_radius")
    if isinstance(radius, bool) or not isinstance(radius, (int, float)) or not 0 <= radius <= 1:
        problems.append(Problem("simulation.spectral_radius", f"must be from 0 to 1, got {radius!r}"))
    else:
        options["spectral_radius"] = float(radius)
    problems += relation_problems(values)
    if problems:
        raise ModelError(problems)
    return options


def _choices(given: dict[str, Any], problems: list[Problem]) -> dict[str, Any]:
    """``method`` (its aliases mapped), ``stabilization``, ``formulation`` and ``jacobian``."""
    method = str(given.get("method")).lower()
    if method not in METHODS:
        problems.append(Problem("simulation.method", f"must be one of {sorted(set(METHODS.values()))}, "
                                                     f"got {given.get('method')!r}"))
    out = {"method": METHODS.get(method, _TABLE.default("method"))}
    for key, words in (("stabilization", p.STABILIZATIONS), ("formulation", p.FORMULATIONS),
                       ("jacobian", p.JACOBIANS)):
        if given.get(key) not in words:
            problems.append(Problem(f"simulation.{key}", f"must be one of {list(words)}, got {given.get(key)!r}"))
        out[key] = given.get(key)
    return out


def _counts(given: dict[str, Any], problems: list[Problem]) -> dict[str, int]:
    """``max_order`` (1 to 5) and ``max_steps`` (what the core's unsigned count holds), those given."""
    out = {}
    max_order = given.get("max_order")
    if max_order is not None:
        most = _TABLE["max_order"].le
        if not _whole(max_order) or not 1 <= max_order <= most:
            problems.append(Problem("simulation.max_order", f"must be a whole number from 1 to {most:g}, "
                                                            f"got {max_order!r}"))
        else:
            out["max_order"] = int(max_order)
    max_steps = given.get("max_steps")
    if max_steps is not None:
        if not _whole(max_steps) or max_steps <= 0:
            problems.append(Problem("simulation.max_steps", f"must be a positive integer, got {max_steps!r}"))
        elif max_steps > MAX_COUNT:
            problems.append(Problem("simulation.max_steps", f"must be at most 2^64 - 1 (the largest count the core "
                                                            f"holds), got {max_steps!r}"))
        else:
            out["max_steps"] = int(max_steps)
    return out


def relation_problems(values: dict[str, Any]) -> list[Problem]:
    """The bounds between options (:attr:`jointplay.parameters.SIMULATION`'s relations) that ``values`` (SI,
    None for a key not given or not valid) break, each at the key to change."""
    out = []
    for relation in _TABLE.relations:
        found = relation.violation(values.get, _show)
        if found is not None:
            out.append(Problem(f"simulation.{found[0]}", found[1]))
    return out


def _show(key: str, value: float) -> str:
    unit = p.unit(_TABLE[key])
    return f"{value:g} {unit}" if unit else f"{value:g}"


def _quantity(key: str, raw: Any, problems: list[Problem]) -> float | None:
    """``raw`` read as the ``[simulation]`` key ``key``; None when not given or wrong (a problem added)."""
    from .modelfile import arguments, schema

    try:
        return arguments.value(schema.SimulationTable, key, raw, "simulation")
    except ModelError as exc:
        problems.extend(exc.problems)
        return None


def _start_time(t0: Any, problems: list[Problem]) -> float | None:
    """``t0``, a finite number of seconds (it goes to the core as given); None after a problem."""
    if not (_number(t0) and math.isfinite(t0)):
        problems.append(Problem("simulation.t0", f"must be a finite number of seconds, got {t0!r}"))
        return None
    return float(t0)


def _end_time(t0: float | None, t_end: Any, problems: list[Problem]) -> None:
    if not _number(t_end):
        problems.append(Problem("simulation.t_end", f"must be a number of seconds, got {t_end!r}"))
    elif t0 is not None and not (math.isfinite(t_end) and t_end > t0):
        problems.append(Problem("simulation.t_end", f"must be greater than t0 = {t0} s, got {t_end!r}"))


def _number(value: Any) -> bool:
    return isinstance(value, Real) and not isinstance(value, bool)


def _whole(value: Any) -> bool:
    return isinstance(value, Integral) and not isinstance(value, bool)


#: One problem of the core's ``IntegratorOptions::validate``: ``rtol: must be >= 2.2e-14 and finite, got 1e-20``.
_CORE_PROBLEM = re.compile(r"^(\w+): (must be .*)$")


def core_refusal(error: ValueError) -> ModelError | None:
    """The core's refusal of options (a check not mirrored above: the second line) as a ModelError located at
    ``simulation.<field>``; None when ``error`` is not such a refusal."""
    parts = [_CORE_PROBLEM.match(part.strip()) for part in str(error).split("; ")]
    if not parts or not all(parts):
        return None
    return ModelError([Problem(f"simulation.{m.group(1)}", m.group(2)) for m in parts])
