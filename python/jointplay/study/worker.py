"""One case of a study, run where it is sent: a local process, a Dask worker, or this process.

What travels is data: the model file's parsed document (a dict), the folder its relative file names
are read from, the case's overrides (``--set`` paths to values), the run options and the response
definitions. The worker builds and compiles the model itself; no compiled object is ever shipped. A
case that fails (a bad value, a simulation that stops) comes back as a record with its error, so the
study goes on. What comes back is what the study needs: the responses, a few integrator counts, and
the chosen channels on the study's time grid, never whole result arrays.
"""

from __future__ import annotations

import math
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

#: Result of a case that ran to its end / that did not.
DONE, FAILED = "done", "failed"


@dataclass(frozen=True)
class Recipe:
    """What every case of a study shares: the model as data and how to run and measure it."""

    document: dict
    #: Folder the model file's relative file names (a modal body's matrices) are read from.
    base: str | None
    model_name: str
    t_end: float
    #: Options of ``Model.simulate`` (``output_step`` included), SI.
    options: dict
    #: :class:`jointplay.study.metrics.Response` objects, evaluated on each run.
    responses: tuple
    #: Channels kept per case, sampled on ``grid`` [s].
    channels: tuple[str, ...] = ()
    grid: tuple[float, ...] = ()
    #: Overrides applied to every case before its own (``--set`` paths to values).
    fixed: dict = field(default_factory=dict)


def run_case(recipe: Recipe, index: int, overrides: dict[str, Any]) -> dict:
    """Builds, runs and measures one case; never raises for a problem of the case itself."""
    record: dict[str, Any] = {"case": index, "status": FAILED, "error": "", "responses": {}, "units": {},
                              "channels": {}, "steps": 0, "rhs_evaluations": 0}
    started = time.perf_counter()
    try:
        results = simulate(recipe, overrides)
        record["responses"] = {r.name: _float(r.evaluate(results)) for r in recipe.responses}
        record["units"] = {r.name: r.units_in(results) for r in recipe.responses}
        record["channels"] = sampled_channels(results, recipe.channels, np.asarray(recipe.grid))
        record["steps"] = int(results.statistics.get("accepted_steps", 0))
        record["rhs_evaluations"] = int(results.statistics.get("rhs_evaluations", 0))
        record["status"] = DONE
    except Exception as exc:  # noqa: BLE001 (a case's failure is data: recorded, the study goes on)
        record["error"] = describe_error(exc)
        record["responses"] = {r.name: math.nan for r in recipe.responses}
    record["seconds"] = time.perf_counter() - started  # for sizing batches; not part of the study's results
    return record


def run_batch(recipe: Recipe, jobs: list[tuple[int, dict]]) -> list[dict]:
    """Several cases in one call (short cases sent one by one cost more in messages than in runs)."""
    return [run_case(recipe, index, overrides) for index, overrides in jobs]


def simulate(recipe: Recipe, overrides: dict[str, Any]):
    """The case's model built from the document and run to ``t_end``. A case that sets a ``simulation.*``
    path (its end time, a tolerance) runs with the value the model file reader gives it."""
    from ..modelfile import from_document

    merged = {**recipe.fixed, **overrides}
    base = Path(recipe.base) if recipe.base else None
    model = from_document(recipe.document, merged, name=recipe.model_name, base=base)
    options, t_end = dict(recipe.options), recipe.t_end
    for key in {path.split(".")[1] for path in merged if path.startswith("simulation.") and path.count(".") >= 1}:
        if key == "t_end":
            t_end = model.simulation["t_end"]
        elif key in model.simulation:
            options[key] = model.simulation[key]
    return model.simulate(t_end, **options)


def sampled_channels(results, names: tuple[str, ...], grid: np.ndarray) -> dict[str, np.ndarray]:
    """Each named channel linearly interpolated at the grid's times (the run's output grid is the study's,
    so the values are the run's own samples wherever the times coincide); NaN past the run's end."""
    end = results.time[-1] if len(results.time) else -math.inf
    return {name: np.where(grid <= end * (1 + 1e-12), np.interp(grid, results.time, results[name]), np.nan)
            for name in names}


def describe_error(exc: BaseException) -> str:
    """One line for a failed case: the kind of failure, where and why."""
    from ..errors import ModelError, SimulationError

    if isinstance(exc, SimulationError):
        where = f" in {exc.element}" if exc.element else ""
        kind = f" ({exc.kind})" if exc.kind else ""
        return f"SimulationError{kind} at t = {exc.time:.6g} s{where}: {exc.cause}"
    if isinstance(exc, ModelError):
        return "ModelError: " + "; ".join(str(p) for p in exc.problems)
    last = traceback.extract_tb(exc.__traceback__)[-1:] if exc.__traceback__ else []
    at = f" ({Path(last[0].filename).name}:{last[0].lineno})" if last else ""
    return f"{type(exc).__name__}{at}: {exc}"


def _float(value: Any) -> float:
    return float(value) if value is not None else math.nan
