"""Benchmark: the dry-clearance Flores slider-crank, two crank revolutions.

Times the jointplay engine (by default in joint coordinates, the mechanism
being a tree once its clearance joint cuts the loop; once more in absolute
coordinates) and two baselines of the same model in the same run: what a user would script, ``solve_ivp`` (RK45) on the independent
minimal-coordinate model in ``tests/physics/reference_slider_crank.py``, and
the practical limit, a hand-written numba Dormand-Prince on the same
minimal-coordinate model (``benches/limit_slider_crank.py``), both with the
same tolerances and the same event handling (contact onsets located and the
onset velocity latched). numba is an optional benchmark dependency
(``pip install numba``, or ``make bench``); without it the limit row is
skipped and the rest runs. The limit is compiled (or loaded from numba's
cache) before anything is timed.

Runs the cases interleaved, round after round (so that drift of the machine
hits all alike), and prints for each case the median CPU and wall time with
their quartiles, accepted steps, right-hand-side evaluations, CPU time per
evaluation, the speed-up over the SciPy baseline and the time relative to the
practical limit, each as the median of the per-round ratios with their
quartiles (see ``benches/timing.py``). Absolute times drift between machines
and runs; the ratio is what is reported, and a target is met only when the
median ratio meets it.

Run: python benches/bench_flores_dry.py [--repeats N] [--rtol R] [--markdown]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "examples"), str(ROOT / "tests" / "physics"), str(ROOT / "benches")]

import flores_slider_crank_dry as flores  # noqa: E402
import timing  # noqa: E402
import reference_slider_crank as reference  # noqa: E402

try:
    import limit_slider_crank as limit
except ImportError as missing:  # numba is an optional benchmark dependency
    if missing.name != "numba":
        raise
    limit = None


#: Speed-up over the SciPy baseline the engine is to reach (issue 2).
TARGET_SPEEDUP = 30.0
#: Time relative to the practical limit the engine is to stay within (issue 10).
TARGET_LIMIT_RATIO = 2.5
LIMIT_NAME = "numba Dormand-Prince, minimal coordinates (practical limit)"


def engine_runner(method: str, rtol: float, atol: float, formulation: str = "auto"):
    """A function running the engine once (``formulation="auto"``: joint coordinates, the mechanism
    being a tree once its clearance joint cuts the loop); returns its results."""
    model = flores.build_model()
    model.compile()
    t_end = flores.revolutions_to_time(2.0)
    return lambda: model.simulate(t_end, method=method, rtol=rtol, atol=atol, formulation=formulation)


def baseline_runner(rtol: float, atol: float):
    """A function running the SciPy baseline once; returns its result."""
    return lambda: reference.simulate_reference(rtol=rtol, atol=atol, method="RK45")


def limit_runner(rtol: float, atol: float):
    """A function running the practical limit once (compiled here, before any timing); returns its result."""
    limit.warm_up()
    return lambda: limit.simulate_limit(rtol=rtol, atol=atol)


def row(case: timing.Case, baseline: timing.Case, practical: timing.Case | None, steps: int, rhs: int,
        impacts: int) -> dict:
    """One line of the table: times as medians with quartiles; speed-up over the baseline and time over
    the practical limit (None when it was skipped) per round."""
    cpu, wall = timing.Spread.of(case.values("cpu")), timing.Spread.of(case.values("wall"))
    return {"name": case.name, "cpu": cpu, "wall": wall, "steps": steps, "rhs": rhs, "impacts": impacts,
            "speedup_cpu": timing.ratio(baseline, case, "cpu"), "speedup_wall": timing.ratio(baseline, case, "wall"),
            "vs_limit_cpu": None if practical is None else timing.ratio(case, practical, "cpu")}


def spread_text(s: timing.Spread) -> str:
    return f"{s.median:.2f}x (quartiles {s.q1:.2f}x-{s.q3:.2f}x, extremes {s.low:.2f}x-{s.high:.2f}x)"


def main(argv: list[str] | None = None) -> list[dict]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=21, help="interleaved rounds (every case once per round)")
    parser.add_argument("--rtol", type=float, default=1e-6)
    parser.add_argument("--atol", type=float, default=1e-9)
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    args = parser.parse_args(argv)
    engines = [timing.Case(f"jointplay {m}", engine_runner(m, args.rtol, args.atol)) for m in ("dopri5", "adams")]
    engines.append(timing.Case("jointplay dopri5, absolute coordinates",
                               engine_runner("dopri5", args.rtol, args.atol, "absolute")))
    baseline = timing.Case("SciPy solve_ivp RK45 (baseline)", baseline_runner(args.rtol, args.atol))
    practical = None if limit is None else timing.Case(LIMIT_NAME, limit_runner(args.rtol, args.atol))
    cases = [*engines] + ([] if practical is None else [practical]) + [baseline]
    timing.interleave(cases, args.repeats)
    rows = []
    for case in engines:
        stats = case.last.statistics
        rows.append(row(case, baseline, practical, stats["accepted_steps"], stats["rhs_evaluations"],
                        case.last.diagnostics["impacts"][0]))
    if practical is not None:
        result = practical.last
        rows.append(row(practical, baseline, practical, result.accepted_steps, result.rhs_evaluations,
                        len(result.impacts)))
    result = baseline.last
    rows.append(row(baseline, baseline, practical, result.n_steps, result.nfev, len(result.impacts)))
    print(f"dry Flores slider-crank, 2 crank revolutions (0.024 s), rtol {args.rtol:g}, atol {args.atol:g}; "
          f"{args.repeats} interleaved rounds; median [interquartile range]; speed-ups and time vs the limit "
          f"are per-round ratios")
    if practical is None:
        print(f"{LIMIT_NAME}: skipped, numba is not installed (pip install numba)")
    if args.markdown:
        print("\n| integrator | CPU time [ms] | wall time [ms] | steps | rhs evaluations | CPU time / evaluation [us] "
              "| impacts | speed-up vs baseline, CPU | speed-up, wall | time vs practical limit, CPU |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    width = max(len(r["name"]) for r in rows)
    for r in rows:
        per_eval = 1e6 * r["cpu"].median / r["rhs"]
        vs_limit = "-" if r["vs_limit_cpu"] is None else f"{r['vs_limit_cpu'].text(digits=3)}x"
        cells = (r["name"], r["cpu"].text(1e3), r["wall"].text(1e3), str(r["steps"]), str(r["rhs"]), f"{per_eval:.2f}",
                 str(r["impacts"]), f"{r['speedup_cpu'].text(digits=3)}x", f"{r['speedup_wall'].text(digits=3)}x",
                 vs_limit)
        if args.markdown:
            print("| " + " | ".join(cells) + " |")
        else:
            print(f"{cells[0]:<{width}} CPU {cells[1]:>22} ms  wall {cells[2]:>22} ms {cells[3]:>6} steps {cells[4]:>7} rhs "
                  f"{cells[5]:>6} us/rhs {cells[6]:>3} impacts  speed-up CPU {cells[7]}, wall {cells[8]}; "
                  f"vs limit CPU {cells[9]}")
    engine = rows[0]
    for clock in ("cpu", "wall"):
        s = engine[f"speedup_{clock}"]
        print(f"target (issue 2), dopri5 at least {TARGET_SPEEDUP:g}x faster than the baseline, {clock.upper()} "
              f"time, median of per-round ratios: {timing.verdict(s.median, '>=', TARGET_SPEEDUP)} {s.median:.1f}x "
              f"(quartiles {s.q1:.1f}x-{s.q3:.1f}x, extremes {s.low:.1f}x-{s.high:.1f}x)")
    if practical is None:
        print(f"goal (issue 10), dopri5 at most {TARGET_LIMIT_RATIO:g}x the practical limit: not measured "
              f"(numba is not installed)")
    else:
        s, b = engine["vs_limit_cpu"], engine["speedup_cpu"]
        print(f"goal (issue 10), dopri5 at most {TARGET_LIMIT_RATIO:g}x the practical limit, CPU time, median of "
              f"per-round ratios: {timing.verdict(s.median, '<=', TARGET_LIMIT_RATIO)} {spread_text(s)}; "
              f"beside the SciPy baseline: {b.median:.1f}x faster than it")
    return rows


if __name__ == "__main__":
    main()
