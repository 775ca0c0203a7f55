"""``jointplay.Study``: a model, factors by their ``--set`` paths, a design and responses; run anywhere.

    study = jp.Study("examples/flores_slider_crank_dry.toml",
                     factors=[{"name": "clearance", "path": "joints.B.clearance", "range": ["0.1 mm", "0.5 mm"]}],
                     design={"kind": "full_factorial", "levels": 5},
                     responses=[{"name": "peak_force", "kind": "peak", "channel": "B.f"}],
                     t_end="20 ms")
    ds = study.run("out/clearance_sweep", workers=2)   # an xarray Dataset with a `case` dimension

A study file (``[study]`` in TOML, :func:`load_study`) describes the same. The model is kept as its
model-file document (a Python :class:`~jointplay.Model` is written to one first), so a case is data
that any worker turns into a compiled model itself.
"""

from __future__ import annotations

import math
import os
import time as _time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import ModelError, Problem
from . import execute
from .factors import Factor
from .store import StudyStore, fingerprint
from .worker import DONE, FAILED, Recipe

Progress = Callable[[int, int], None]


class Study:
    """A designed set of runs of one model (see the module doc).

    ``model``: a model file's path, a :class:`~jointplay.Model` or a parsed model document; ``factors``,
    ``design`` and ``responses``: the tables of a study file (or Factor and Response objects); ``t_end``
    and ``options``: the run's end time and options over the model's ``[simulation]`` table;
    ``channels`` kept per case every ``channel_step``; ``fixed``: ``--set`` overrides of every case;
    ``seed`` of random designs. ``file_values``: the values come from a study file, so a bare number of
    a time needs a unit as in a model file (from Python a bare time is in seconds)."""

    def __init__(self, model, factors: Sequence[Factor | dict], design: str | dict = "full_factorial",
                 responses: Sequence = (), *, t_end: float | str | None = None, options: dict | None = None,
                 channels: Sequence[str] = (), channel_step: float | str | None = None,
                 fixed: dict[str, Any] | None = None, name: str | None = None, seed: int = 0,
                 file_values: bool = False):
        from .design_spec import build_design
        from .studyfile import parse_factors

        self.document, self.base, self.model_name, self.model_source = _model_document(model)
        self.factors: list[Factor] = parse_factors(list(factors), "study.factors")
        self.design_spec = {"kind": design} if isinstance(design, str) else dict(design)
        self.seed = int(seed)
        self.coded, self.values = build_design(self.design_spec, self.factors, self.seed, "study.design")
        self.responses = tuple(_responses(responses))
        self.fixed = dict(fixed or {})
        self.name = name or f"{self.model_name}_study"
        self.t_end, self.options = _run_options(self.document, self.base, t_end, options, self.responses, file_values)
        self.channels = tuple(channels)
        self.grid = _grid(self.t_end, channel_step, self.options, self.channels)
        if self.channels:
            self.options["output_step"] = min(self.options.get("output_step") or math.inf, self.grid[1] - self.grid[0])

    # --- what the study is ------------------------------------------------------------------------

    def __len__(self) -> int:
        return len(self.values)

    def overrides(self, index: int) -> dict[str, Any]:
        """The ``--set`` overrides of case ``index`` (SI text with every digit)."""
        return {f.path: f.override(v) for f, v in zip(self.factors, self.values[index], strict=True)}

    def recipe(self) -> Recipe:
        return Recipe(self.document, str(self.base) if self.base else None, self.model_name, self.t_end,
                      dict(self.options), self.responses, self.channels, tuple(self.grid), dict(self.fixed))

    def definition(self) -> dict:
        """Everything that decides the cases' results, as plain data (its fingerprint guards a resume)."""
        return {"model": self.document, "fixed": self.fixed, "t_end": self.t_end, "options": self.options,
                "factors": [f.to_dict() for f in self.factors], "design": self.design_spec, "seed": self.seed,
                "values": self.values, "responses": [r.definition for r in self.responses],
                "channels": list(self.channels), "grid": list(self.grid)}

    def manifest(self) -> dict:
        definition = self.definition()
        return {"study": self.name, "model": self.model_source, "fingerprint": fingerprint(definition),
                "cases": len(self), "factors": definition["factors"], "design": self.design_spec,
                "responses": [r.name for r in self.responses]}

    def table(self) -> list[dict]:
        """The design as rows: case index and each factor's value as a user reads it."""
        return [{"case": k, **{f.name: f.label(v) for f, v in zip(self.factors, row, strict=True)}}
                for k, row in enumerate(self.values)]

    # --- running -------------------------------------------------------------------------------------

    def run(self, folder: str | Path | None = None, *, workers: int = 1, client=None, scheduler: str | None = None,
            resume: bool = False, progress: bool | Progress = False, batch_size: int | None = None):
        """Runs every case not yet done and returns the study's Dataset (also saved as ``folder/study.nc``).

        ``workers`` > 1 runs on that many local processes; ``client`` (a ``dask.distributed.Client``) or
        ``scheduler`` (its address) runs on a Dask cluster. With ``folder`` each case is saved as it
        finishes and ``resume`` runs only the cases missing there. ``progress``: True for a progress
        bar with the time remaining, or a callable ``(done, total)``."""
        from .dataset import assemble

        store = StudyStore(folder) if folder is not None else None
        records: dict[int, dict] = {}
        done = store.open(self.manifest(), resume=resume) if store else set()
        jobs = [(k, self.overrides(k)) for k in range(len(self)) if k not in done]

        def keep(record: dict) -> None:
            if store:
                store.write(record)
            else:
                records[record["case"]] = record

        with _reporter(progress, len(self), len(done)) as report:
            def on_record(record: dict) -> None:
                keep(record)
                report(record)

            self._execute(jobs, on_record, workers, client, scheduler, batch_size)
        if store:
            records = {k: store.read(k) for k in range(len(self))}
        dataset = assemble(self, [records[k] for k in range(len(self))])
        if store:
            from .dataset import save

            save(dataset, store.folder / "study.nc")
        return dataset

    def _execute(self, jobs, on_record, workers: int, client, scheduler: str | None, batch_size: int | None):
        recipe = self.recipe()
        if client is None and scheduler is not None:
            client = execute.connect(scheduler)
            try:
                execute.run_dask(recipe, jobs, on_record, client, batch_size)
            finally:
                client.close()
        elif client is not None:
            execute.run_dask(recipe, jobs, on_record, client, batch_size)
        elif workers > 1:
            execute.run_processes(recipe, jobs, on_record, workers, batch_size)
        else:
            execute.run_serial(recipe, jobs, on_record)

    def run_point(self, values: dict[str, float]):
        """One run of the model at factor values [SI] given by name (the others at their range's middle,
        or their first level): the :class:`~jointplay.Results`. Used to verify an optimum."""
        from .worker import simulate

        unknown = set(values) - {f.name for f in self.factors}
        if unknown:
            raise ModelError([Problem("values", f"no factor {sorted(unknown)} in this study (factors: "
                                                f"{', '.join(f.name for f in self.factors)})")])
        point = {f.path: f.override(values.get(f.name, f.value(0.0))) for f in self.factors}
        return simulate(self.recipe(), point)


def _responses(responses) -> list:
    """Response objects as given, and response tables (dicts) parsed together (so that a name given twice
    is found and every bad table reported)."""
    from .metrics import parse_responses

    responses = list(responses)
    if all(isinstance(r, dict) for r in responses):
        return parse_responses(responses, "study.responses")
    out = []
    for k, r in enumerate(responses):
        out.extend([r] if hasattr(r, "evaluate") else parse_responses([r], f"study.responses[{k}]"))
    names = [r.name for r in out]
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise ModelError([Problem("study.responses", f"repeats the response name(s) {', '.join(repeated)}")])
    return out


def _model_document(model) -> tuple[dict, Path | None, str, str]:
    """(document, base folder, name, source) of a model file path, a parsed document or a Model."""
    from ..model import Model
    from ..modelfile import parse_text, read_document, to_toml

    if isinstance(model, (str, Path)):
        path = Path(os.path.normpath(model))
        return read_document(path), path.parent.resolve(), path.stem, str(path)
    if isinstance(model, Model):
        doc = parse_text(to_toml(model), "the study's model")
        name = model.to_spec().get("name") or "model"
        return doc, None, name, f"Model {name!r}"
    if isinstance(model, dict):
        return model, None, "model", "a model document"
    raise ModelError([Problem("study.model", f"must be a model file, a Model or a model document, got "
                                             f"{type(model).__name__}")])


def _run_options(document: dict, base: Path | None, t_end, options: dict | None, responses,
                 file_values: bool) -> tuple[float, dict]:
    """End time [s] and simulate options [SI]: the model file's ``[simulation]`` table with the study's
    entries over it, read (units, names, ranges) by the model-file reader itself; the output step no
    coarser than the responses need. Builds the base model once, so a bad model fails here. Values from
    a study file (``file_values``) follow the model-file rules (a bare time needs a unit); from Python, a
    bare time is in seconds."""
    from ..modelfile import from_document
    from .metrics import required_output_step

    given = dict(options or {}, **({} if t_end is None else {"t_end": t_end}))
    if not file_values:
        given = {k: _python_value(k, v) for k, v in given.items()}
    simulation = {**(document.get("simulation") or {}), **given}
    if simulation.get("t_end") is None:
        raise ModelError([Problem("study.t_end", "missing: give the end time here or in the model's "
                                                 "[simulation] table (e.g. t_end = \"30 ms\")")])
    try:
        run = dict(from_document({**document, "simulation": simulation}, check=False, base=base).simulation)
    except ModelError as exc:  # say where the study, not the model file, gave the value
        raise ModelError([_study_location(p, t_end, options) for p in exc.problems]) from None
    end = run.pop("t_end")
    needed = required_output_step(list(responses), end)
    if needed is not None and math.isfinite(needed):
        run["output_step"] = min(run.get("output_step") or math.inf, needed)
    return end, run


def _study_location(problem: Problem, t_end, options: dict | None) -> Problem:
    key = problem.location.removeprefix("simulation.").split(".")[0]
    if problem.location.startswith("simulation.") and key == "t_end" and t_end is not None:
        return Problem("study.t_end", problem.message)
    if problem.location.startswith("simulation.") and key in (options or {}):
        return Problem(f"study.{problem.location}", problem.message)
    return problem


def _python_value(key: str, value):
    """A run option given in Python: a bare number of a time option is in seconds (as everywhere in Python),
    written with its unit for the model-file reader."""
    from ..parameters import SIMULATION

    kinds = {param.key: param.kind for param in SIMULATION.params}
    if kinds.get(key) == "time" and isinstance(value, (int, float)) and not isinstance(value, bool):
        return f"{float(value)!r} s"
    return value


def _grid(t_end: float, step, options: dict, channels) -> np.ndarray:
    """The common time grid [s] of the kept channels: 0, step, ..., t_end."""
    if not channels:
        return np.zeros(0)
    from ..units import UnitError, to_si

    if step is None:
        step = options.get("output_step") or t_end / 500
    try:
        h = to_si(step, "time")
    except UnitError as exc:
        raise ModelError([Problem("study.channels.step", str(exc))]) from None
    if not 0 < h <= t_end:
        raise ModelError([Problem("study.channels.step", f"must be > 0 and at most t_end, got {step}")])
    n = int(math.floor(t_end / h + 1e-9))
    return np.arange(n + 1) * h


class _reporter:
    """A progress display for a study: a rich bar with the time remaining, a callback, or nothing."""

    def __init__(self, progress, total: int, already: int):
        self.progress, self.total, self.count = progress, total, already
        self.failed = 0
        self.bar = None

    def __enter__(self):
        if self.progress is True:
            from rich.progress import (BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn,
                                       TimeRemainingColumn)

            self.bar = Progress(TextColumn("cases"), BarColumn(), MofNCompleteColumn(),
                                TextColumn("{task.fields[failed]}"), TimeElapsedColumn(), TextColumn("left"),
                                TimeRemainingColumn(), transient=False)
            self.bar.start()
            self.task = self.bar.add_task("cases", total=self.total, completed=self.count, failed="")
        self.started = _time.perf_counter()
        return self.report

    def report(self, record: dict) -> None:
        self.count += 1
        self.failed += record["status"] == FAILED
        if self.bar is not None:
            self.bar.update(self.task, completed=self.count,
                            failed=f"{self.failed} failed" if self.failed else "")
        elif callable(self.progress):
            self.progress(self.count, self.total)

    def __exit__(self, *exc):
        if self.bar is not None:
            self.bar.stop()
        return False


__all__ = ["DONE", "FAILED", "Study"]
