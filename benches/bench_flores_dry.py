"""Benchmark: the dry-clearance Flores slider-crank, two crank revolutions.

Times the jointplay engine and a SciPy baseline of the same model in the same
run: ``solve_ivp`` (RK45) on the independent minimal-coordinate model in
``tests/physics/reference_slider_crank.py``, with the same tolerances and the
same event handling (contact onsets located and the onset velocity latched).
Runs the cases interleaved (so that drift of the machine hits all alike) and
prints the fastest wall time of the repeats with the median beside it,
accepted steps, right-hand-side evaluations, wall time per evaluation and the
ratio to the baseline. Absolute
times drift between machines and runs; the ratio is what is reported.

Run: python benches/bench_flores_dry.py [--repeats N] [--rtol R] [--markdown]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "examples"), str(ROOT / "tests" / "physics")]

import flores_slider_crank_dry as flores  # noqa: E402
import reference_slider_crank as reference  # noqa: E402


#: Speed-up over the SciPy baseline the engine is to reach (issue 2).
TARGET_SPEEDUP = 30.0


def engine_runner(method: str, rtol: float, atol: float):
    """A function running the engine once; returns (wall time [s], results)."""
    model = flores.build_model()
    model.compile()
    t_end = flores.revolutions_to_time(2.0)

    def run():
        results = model.simulate(t_end, method=method, rtol=rtol, atol=atol)
        return results.wall_time, results

    return run


def baseline_runner(rtol: float, atol: float):
    """A function running the SciPy baseline once; returns (wall time [s], result)."""

    def run():
        started = time.perf_counter()
        result = reference.simulate_reference(rtol=rtol, atol=atol, method="RK45")
        return time.perf_counter() - started, result

    return run


def measure(runners: dict, repeats: int) -> dict:
    """Runs every case ``repeats`` times, interleaved so that drift of the machine hits all alike;
    returns the walls and the last output of each case."""
    walls = {name: [] for name in runners}
    last = {}
    for _ in range(repeats):
        for name, run in runners.items():
            wall, last[name] = run()
            walls[name].append(wall)
    return {name: (walls[name], last[name]) for name in runners}


def row(name: str, walls: list[float], steps: int, rhs: int, impacts: int) -> dict:
    return {"name": name, "wall": min(walls), "median": statistics.median(walls), "steps": steps, "rhs": rhs,
            "impacts": impacts}


def main(argv: list[str] | None = None) -> list[dict]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=15)
    parser.add_argument("--rtol", type=float, default=1e-6)
    parser.add_argument("--atol", type=float, default=1e-9)
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    args = parser.parse_args(argv)
    runs = measure({"dopri5": engine_runner("dopri5", args.rtol, args.atol),
                    "adams": engine_runner("adams", args.rtol, args.atol),
                    "baseline": baseline_runner(args.rtol, args.atol)}, args.repeats)
    rows = []
    for method in ("dopri5", "adams"):
        walls, results = runs[method]
        stats = results.statistics
        rows.append(row(f"jointplay {method}", walls, stats["accepted_steps"], stats["rhs_evaluations"],
                        results.diagnostics["impacts"][0]))
    walls, result = runs["baseline"]
    baseline = row("SciPy solve_ivp RK45 (baseline)", walls, result.n_steps, result.nfev, len(result.impacts))
    rows.append(baseline)
    print(f"dry Flores slider-crank, 2 crank revolutions (0.024 s), rtol {args.rtol:g}, atol {args.atol:g}; "
          f"{args.repeats} interleaved runs per case, fastest (median in parentheses)")
    if args.markdown:
        print("\n| integrator | wall time [ms] | steps | rhs evaluations | wall time / evaluation [us] | impacts | speed-up vs baseline |")
        print("|---|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        ratio, median_ratio = baseline["wall"] / r["wall"], baseline["median"] / r["median"]
        per_eval = 1e6 * r["wall"] / r["rhs"]
        if args.markdown:
            print(f"| {r['name']} | {1e3 * r['wall']:.2f} ({1e3 * r['median']:.2f}) | {r['steps']} | {r['rhs']} | "
                  f"{per_eval:.2f} | {r['impacts']} | {ratio:.1f}x ({median_ratio:.1f}x) |")
        else:
            print(f"{r['name']:<34} {1e3 * r['wall']:9.2f} ms ({1e3 * r['median']:.2f}) {r['steps']:7d} steps "
                  f"{r['rhs']:8d} rhs {per_eval:8.2f} us/rhs {r['impacts']:4d} impacts {ratio:7.1f}x ({median_ratio:.1f}x)")
    engine = rows[0]
    for label, ratio in (("fastest against fastest", baseline["wall"] / engine["wall"]),
                         ("median against median", baseline["median"] / engine["median"])):
        verdict = "met   " if ratio >= TARGET_SPEEDUP else "missed"
        print(f"target (issue 2), dopri5 at least {TARGET_SPEEDUP:g}x faster than the baseline, {label}: "
              f"{verdict} {ratio:.1f}x")
    return rows


if __name__ == "__main__":
    main()
