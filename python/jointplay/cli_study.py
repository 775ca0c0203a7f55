"""``jointplay sweep`` and ``jointplay optimize``: a study file run on this machine or a Dask cluster.

``sweep`` runs every case of the study's design (resuming a killed study with ``--resume``), saves the
Dataset to ``DIR/study.nc``, prints the failures, the best cases per response and the quality of each
response's fitted surface, and writes the figures to ``DIR/figures``. ``optimize`` runs the design
the same way (resuming what ``DIR`` already holds), optimises the responses named in
``[study.optimize]`` on the surfaces (or on the simulator) and verifies the optimum by a real run.
Exit codes: 0 done, 1 some cases failed (their errors are in the Dataset), 2 a bad study file.
"""

from __future__ import annotations

import json
import math
import os
from pathlib import Path
from typing import Annotated

import typer

from .cli import EXIT_FAILED, _bad_input, app, err, out
from .display import print_table, table
from .errors import ModelError

OutOption = Annotated[Path, typer.Option("-o", "--output", help="Folder of the study: one file per finished case, "
                                                                "study.nc and figures.")]
WorkersOption = Annotated[int | None, typer.Option("--workers", "-w", min=1, show_default=False,
                                                   help="Local worker processes [default: one per core of this "
                                                        "machine; 1 runs the cases in this process].")]
SchedulerOption = Annotated[str | None, typer.Option("--scheduler", help="Address of a Dask scheduler "
                                                     "(tcp://host:8786): run the cases on that cluster.")]


@app.command()
def sweep(study_file: Annotated[Path, typer.Argument(help="Study file (TOML with a [study] table).",
                                                     show_default=False)],
          output: OutOption, workers: WorkersOption = None, scheduler: SchedulerOption = None,
          resume: Annotated[bool, typer.Option("--resume", help="Run only the cases the folder is missing.")] = False,
          quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar.")] = False) -> None:
    """Run every case of a study's design and summarise it.

    Cases are saved as they finish; a study stopped at any point and run
    again with --resume runs only what is missing and ends with the same
    study.nc. A failing case is recorded with its error and the others go
    on. Prints the best cases of each response and how well a quadratic
    surface fits each (R^2, adjusted R^2, cross-validated Q^2).
    """
    study = _study(study_file)
    dataset = _run(study, output, workers, scheduler, resume, quiet)
    print_summary(study, dataset, output)
    if (dataset["status"].values != "done").any():
        raise typer.Exit(EXIT_FAILED)


@app.command()
def optimize(study_file: Annotated[Path, typer.Argument(help="Study file with a [study.optimize] table.",
                                                        show_default=False)],
             output: OutOption, workers: WorkersOption = None, scheduler: SchedulerOption = None,
             quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar.")] = False) -> None:
    """Optimise a study's responses and verify the optimum by a run.

    Runs the design (what the folder already holds is kept), fits a
    quadratic surface to each objective, finds the weighted optimum over the
    factors' ranges and levels ([study.optimize] on = "surface", the
    default) or searches with the simulator itself (on = "simulator"), runs
    the model at the optimum and prints the prediction beside the run.
    """
    from .study.optimize import best_case, optimize_simulator, optimize_surface, parse_objectives

    study = _study(study_file)
    spec = dict(getattr(study, "optimize_spec", {}))
    try:
        objectives = parse_objectives(spec.get("objectives"), [r.name for r in study.responses])
        on = spec.get("on", "surface")
        if on not in ("surface", "simulator"):
            raise ModelError([("study.optimize.on", f"must be surface or simulator, got {on!r}")])
    except ModelError as exc:
        raise _bad_input(f"{study_file}: bad [study.optimize]", exc.problems) from None
    if on == "surface":
        dataset = _run(study, output, workers, scheduler, True, quiet)
        print_summary(study, dataset, output)
        if spec.get("front"):
            _print_front(study, dataset, objectives, output)
        print_optimum(study, best_case(study, dataset, objectives), objectives)
        found = optimize_surface(study, dataset, objectives, seed=study.seed)
    else:
        output.mkdir(parents=True, exist_ok=True)
        found = optimize_simulator(study, objectives, method=spec.get("method", "differential_evolution"),
                                   budget=int(spec.get("budget", 60)), seed=study.seed)
    print_optimum(study, found, objectives)
    path = output / "optimum.json"
    path.write_text(json.dumps({"method": found.method, "values": found.values, "labels": found.labels,
                                "predicted": found.predicted, "verified": found.verified,
                                "objective": found.objective}, indent=1))
    out.print(f"wrote {path}")


def cores() -> int:
    """Cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def _study(path: Path):
    from .study import load_study

    try:
        return load_study(path)
    except ModelError as exc:
        n = len(exc.problems)
        raise _bad_input(f"{path}: {n} problem{'s' if n != 1 else ''}", exc.problems) from None


def _run(study, output: Path, workers: int | None, scheduler: str | None, resume: bool, quiet: bool):
    workers = workers or min(len(study), cores())
    out.print(f"[bold]{study.name}[/]: {len(study)} cases of {study.model_source}, {len(study.factors)} factors, "
              f"{study.design_spec.get('kind')} design")
    try:
        return study.run(output, workers=workers, scheduler=scheduler, resume=resume, progress=not quiet)
    except ModelError as exc:
        raise _bad_input(f"{output}: cannot run the study", exc.problems) from None


def print_summary(study, dataset, output: Path) -> None:
    """Failures, the best cases per response, the surfaces' quality, Sobol indices, and the figures."""
    from .study import summary

    failed = summary.failures(dataset)
    out.print(f"{len(study) - len(failed)} cases done, {len(failed)} failed; wrote {output / 'study.nc'}")
    for case, error in failed[:5]:
        err.print(f"  case {case}: {error}", markup=False)
    if len(failed) > 5:
        err.print(f"  ... and {len(failed) - 5} more (the Dataset's `error` variable holds them all)")
    names = [r.name for r in study.responses]
    for response in names:
        t = table("case", *[f.name for f in study.factors], response, title=f"best cases: smallest {response}")
        units = dataset[response].attrs.get("units", "")
        for k in summary.best_cases(dataset, response):
            t.add_row(str(k), *[f.label(float(dataset[f.name].values[k])) for f in study.factors],
                      f"{float(dataset[response].values[k]):.6g} {units}".strip())
        print_table(out, t)
    fitted = summary.surfaces(dataset, names)
    t = table("response", "cases", "terms", "R^2", "adj. R^2", "Q^2 (LOO)", "verdict",
              title="quadratic response surfaces (coded factors)")
    for response, surface in fitted.items():
        if isinstance(surface, str):
            t.add_row(response, "-", "-", "-", "-", "-", f"not fitted: {surface}")
            continue
        q = surface.quality()
        t.add_row(response, str(q["cases"]), str(q["terms"]), _fmt(q["r2"]), _fmt(q["r2_adjusted"]), _fmt(q["q2"]),
                  q["verdict"])
    print_table(out, t)
    _print_sensitivities(dataset, fitted)
    for path in summary.figures(dataset, fitted, output / "figures"):
        out.print(f"wrote {path}")


def _print_sensitivities(dataset, fitted: dict) -> None:
    """Sobol indices of each response: from the cases of a Saltelli design, else from a trustworthy surface."""
    from .study.sensitivity import saltelli_base_samples, sobol_indices

    factors = [str(f) for f in dataset["factor"].values]
    saltelli = saltelli_base_samples(dataset["coded"].values) is not None
    t = table("response", *[f"{f} S1 / ST" for f in factors], "from", title="Sobol sensitivity indices")
    for response, surface in fitted.items():
        trusted = not isinstance(surface, str) and surface.verdict == "trustworthy"
        if not (trusted or (saltelli and dataset[response].notnull().all())):
            continue
        found = sobol_indices(dataset, response)
        t.add_row(response, *[f"{found.first_order[j]:.2f} / {found.total[j]:.2f}" for j in range(len(factors))],
                  found.source)
    if t.row_count:
        print_table(out, t)


def print_optimum(study, found, objectives) -> None:
    """The optimum's factor values (with ISO grades), the surface's prediction beside the verifying run."""
    goals = ", ".join(f"{o.goal} {o.response} (weight {o.weight:g})" for o in objectives)
    out.print(f"[bold]optimum[/] by {found.method}: {goals}")
    t = table("factor", "value", title="optimum")
    for f in study.factors:
        t.add_row(f.name, found.labels.get(f.name, f.label(found.values[f.name])))
    print_table(out, t)
    t = table("response", "predicted (surface)", "run", "difference", title="the optimum verified by a run")
    differences = found.differences()
    for r in study.responses:
        predicted = found.predicted.get(r.name, math.nan)
        run = found.verified.get(r.name, math.nan)
        t.add_row(r.name, _fmt(predicted), _fmt(run), f"{100 * differences.get(r.name, math.nan):+.1f} %"
                  if r.name in differences else "-")
    print_table(out, t)
    for note in found.notes:
        out.print(f"note: {note}", markup=False)


def _print_front(study, dataset, objectives, output: Path) -> None:
    """The Pareto front of the objectives on their surfaces, a figure of it, and three of its points run."""
    from .study.optimize import front_optima, pareto_front
    from .study.summary import front_figure

    points, values = pareto_front(study, dataset, objectives, seed=study.seed)
    out.print(f"Pareto front on the surfaces: {len(points)} non-dominated points")
    verified = front_optima(study, points, objectives, dataset)
    t = table(*[f.name for f in study.factors], *[f"{o.response} predicted / run" for o in objectives],
              title="points of the front verified by runs")
    for o in verified:
        t.add_row(*[o.labels[f.name] for f in study.factors],
                  *[f"{_fmt(o.predicted[x.response])} / {_fmt(o.verified[x.response])}" for x in objectives])
    print_table(out, t)
    path = front_figure(values, objectives, verified, dataset, output / "figures" / "pareto_front.png")
    out.print(f"wrote {path}")


def _fmt(value) -> str:
    return "-" if value is None or (isinstance(value, float) and math.isnan(value)) else f"{value:.4g}"
