"""Cost of one right-hand side of a modal body against its number of modes.

The model: a pendulum of one modal link (a 1 m beam of 32 quadratic elements reduced to Craig-Bampton modes, chord
frame, interface nodes at both ends: 3 constraint modes plus ``modes - 3`` fixed-interface normal modes), pinned to
the ground by a revolute joint at its first end and released horizontal under gravity, integrated by Dormand-Prince
for a time that gives about ``--evaluations`` right-hand sides (the step is held by the highest mode's
frequency, so the time is calibrated per mode count in a first run). The cost per evaluation is the run's CPU time
over its right-hand-side evaluations (the integrator's and those the run makes inside steps to locate the peaks of
its channels): it holds the constraint solve and the integrator's own work too, which do not grow with the modes.

Several builds of jointplay can be timed side by side in this one process (``--baseline DIR``: a directory holding
another build's package under another name, made by ``--snapshot DIR`` from the build installed now), their cases
interleaved round by round, so that the ratio of two builds comes from the same rounds. The exponent of the cost
against the modes is fitted by least squares on log-log axes, over all sizes and over the last doubling.

    .venv/bin/python benches/bench_modal_modes.py --snapshot target/modal-baseline      # before a change
    .venv/bin/python benches/bench_modal_modes.py --baseline target/modal-baseline      # after it
"""

from __future__ import annotations

import argparse
import importlib
import math
import os
import shutil
import statistics
import sys
from pathlib import Path

sys.path.insert(0, os.path.dirname(__file__))

import numpy as np  # noqa: E402
from timing import Case, Spread, interleave, ratio  # noqa: E402

import jointplay  # noqa: E402

#: Total modes of the link (3 constraint modes plus the normal modes).
MODES = (4, 8, 16, 32, 64)
#: Name under which a snapshot of a build is imported.
BASELINE_PACKAGE = "jointplay_baseline"


def pendulum(jp, modes: int):
    """The modal pendulum with ``modes`` modes in the package ``jp``."""
    section = jp.sections.resultants("2e6 N", "8e5 N", "100 N m^2", "2 kg/m", "1e-4 kg m")
    m = jp.Model(f"modal pendulum, {modes} modes", gravity=(0.0, -9.81))
    m.add_ground_point("O", (0, 0))
    m.add_modal_body("link", (0, 0), ("1 m", 0), section=section, elements=32, normal_modes=modes - 3)
    m.add_revolute("pin", "ground.O", "link.start")
    return m


def snapshot(target: Path) -> None:
    """Copies the package installed now (with its built extension) to ``target`` under :data:`BASELINE_PACKAGE`."""
    source = Path(jointplay.__file__).parent
    destination = target / BASELINE_PACKAGE
    if destination.exists():
        shutil.rmtree(destination)
    shutil.copytree(source, destination, ignore=shutil.ignore_patterns("__pycache__"))
    print(f"copied {source} to {destination}")


def runner(jp, modes: int, evaluations: int):
    """A function running the pendulum for about ``evaluations`` right-hand sides; it returns its statistics."""
    model = pendulum(jp, modes)

    def run_to(t_end: float) -> dict:
        results = model.simulate(t_end, rtol=1e-6, atol=1e-9, output_step=t_end)
        return {"evaluations": evaluations_of(results), **results.statistics}

    # (the step settles at the highest mode's stability limit after a start-up: scale the time twice)
    t_end = 2e-4
    for _ in range(3):
        t_end *= evaluations / run_to(t_end)["evaluations"]
    return lambda: run_to(t_end)


def evaluations_of(results) -> int:
    """Right-hand sides a run evaluated: the integrator's, and those inside steps that locate the peaks."""
    return results.statistics["rhs_evaluations"] + (results.extrema or {}).get("inner_evaluations", 0)


def exponent(sizes: list[int], costs: list[float]) -> float:
    """Least-squares slope of log(cost) against log(size)."""
    return float(np.polyfit(np.log(sizes), np.log(costs), 1)[0])


def per_evaluation(case: Case, clock: str) -> Spread:
    """The CPU (or wall) time per right-hand side of each round [s]."""
    times = case.cpus if clock == "cpu" else case.walls
    evaluations = case.last["evaluations"]
    return Spread.of([t / evaluations for t in times if t is not None])


def main(argv: list[str] | None = None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--evaluations", type=int, default=3000, help="right-hand sides per run, about")
    parser.add_argument("--modes", type=int, nargs="+", default=list(MODES))
    parser.add_argument("--baseline", type=Path, help="directory of a snapshot to time beside the build installed")
    parser.add_argument("--snapshot", type=Path, help="copy the build installed to this directory and stop")
    args = parser.parse_args(argv)
    if args.snapshot:
        snapshot(args.snapshot)
        return {}
    builds = {"this build": jointplay}
    if args.baseline:
        sys.path.insert(0, str(args.baseline.resolve()))
        builds = {"baseline": importlib.import_module(BASELINE_PACKAGE), **builds}
    cases, refused = {}, {}
    for n in args.modes:
        for build, jp in builds.items():
            try:
                cases[(build, n)] = Case(f"{build}, {n} modes", runner(jp, n, args.evaluations))
            except jp.JointplayError as e:  # (a build with fewer modes allowed)
                refused[(build, n)] = str(e).splitlines()[0]
    for case in cases.values():  # warm-up, and the statistics of every case
        case.time_once()
        case.walls.clear()
        case.cpus.clear()
    interleave(list(cases.values()), args.rounds)
    print(f"CPU time per right-hand side [us], median [quartiles] [min-max] of {args.rounds} interleaved rounds")
    header = f"{'modes':>5} | " + " | ".join(f"{b:^34}" for b in builds)
    if args.baseline:
        header += " | baseline / this build"
    print(header)
    out: dict = {}
    for n in args.modes:
        row = f"{n:>5} | "
        cells = []
        for build in builds:
            if (build, n) in refused:
                cells.append("refused")
                continue
            case = cases[(build, n)]
            s = per_evaluation(case, "cpu")
            out[(build, n)] = s.median
            cells.append(f"{s.text(1e6)} [{1e6 * s.low:.3g}-{1e6 * s.high:.3g}] ({case.last['evaluations']})")
        row += " | ".join(f"{c:^34}" for c in cells)
        if args.baseline and ("baseline", n) in cases:
            r = ratio(cases[("baseline", n)], cases[("this build", n)])
            # (the two runs of a round may differ in evaluations: the ratio is per evaluation)
            scale = cases[("this build", n)].last["evaluations"] / cases[("baseline", n)].last["evaluations"]
            row += f" | {scale * r.median:.3g} [{scale * r.low:.3g}-{scale * r.high:.3g}]"
        print(row)
    for build in builds:
        sizes = [n for n in args.modes if (build, n) in out]
        costs = [out[(build, n)] for n in sizes]
        last = math.log(costs[-1] / costs[-2]) / math.log(sizes[-1] / sizes[-2])
        print(f"{build}: exponent of cost per evaluation against modes {exponent(sizes, costs):.2f} over {sizes} "
              f"(last step {sizes[-2]} to {sizes[-1]}: exponent {last:.2f}, cost ratio {costs[-1] / costs[-2]:.2f})")
    for (build, n), reason in refused.items():
        print(f"{build}, {n} modes: refused ({reason})")
    print(f"load: {os.getloadavg()[0]:.2f} {os.getloadavg()[1]:.2f} {os.getloadavg()[2]:.2f} (1, 5, 15 min)")
    return out


if __name__ == "__main__":
    main()
