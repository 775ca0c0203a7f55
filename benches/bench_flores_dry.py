"""Benchmark: the dry-clearance Flores slider-crank, two crank revolutions.

Times the jointplay engine and a SciPy baseline of the same model in the same
run: ``solve_ivp`` (RK45) on the independent minimal-coordinate model in
``tests/physics/reference_slider_crank.py``, with the same tolerances and the
same event handling (contact onsets located and the onset velocity latched).
Prints wall time (median of the repeats), accepted steps, right-hand-side
evaluations, wall time per evaluation and the ratio to the baseline. Absolute
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


def time_engine(method: str, rtol: float, atol: float, repeats: int) -> dict:
    model = flores.build_model()
    model.compile()
    t_end = flores.revolutions_to_time(2.0)
    walls, results = [], None
    for _ in range(repeats):
        results = model.simulate(t_end, method=method, rtol=rtol, atol=atol)
        walls.append(results.wall_time)
    stats = results.statistics
    return {"name": f"jointplay {method}", "wall": statistics.median(walls), "steps": stats["accepted_steps"],
            "rhs": stats["rhs_evaluations"], "impacts": results.diagnostics["impacts"][0]}


def time_baseline(rtol: float, atol: float, repeats: int) -> dict:
    walls, result = [], None
    for _ in range(repeats):
        started = time.perf_counter()
        result = reference.simulate_reference(rtol=rtol, atol=atol, method="RK45")
        walls.append(time.perf_counter() - started)
    return {"name": "SciPy solve_ivp RK45 (baseline)", "wall": statistics.median(walls), "steps": result.n_steps,
            "rhs": result.nfev, "impacts": len(result.impacts)}


def main(argv: list[str] | None = None) -> list[dict]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--rtol", type=float, default=1e-6)
    parser.add_argument("--atol", type=float, default=1e-9)
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    args = parser.parse_args(argv)
    baseline = time_baseline(args.rtol, args.atol, max(1, args.repeats // 2))
    rows = [time_engine("dopri5", args.rtol, args.atol, args.repeats),
            time_engine("adams", args.rtol, args.atol, args.repeats), baseline]
    print(f"dry Flores slider-crank, 2 crank revolutions (0.024 s), rtol {args.rtol:g}, atol {args.atol:g}, "
          f"median of {args.repeats} runs (baseline {max(1, args.repeats // 2)})")
    if args.markdown:
        print("\n| integrator | wall time [ms] | steps | rhs evaluations | wall time / evaluation [us] | impacts | speed-up vs baseline |")
        print("|---|---:|---:|---:|---:|---:|---:|")
    for row in rows:
        ratio = baseline["wall"] / row["wall"]
        per_eval = 1e6 * row["wall"] / row["rhs"]
        if args.markdown:
            print(f"| {row['name']} | {1e3 * row['wall']:.2f} | {row['steps']} | {row['rhs']} | {per_eval:.2f} | "
                  f"{row['impacts']} | {ratio:.1f}x |")
        else:
            print(f"{row['name']:<34} {1e3 * row['wall']:9.2f} ms {row['steps']:7d} steps {row['rhs']:8d} rhs "
                  f"{per_eval:8.2f} us/rhs {row['impacts']:4d} impacts {ratio:7.1f}x")
    return rows


if __name__ == "__main__":
    main()
