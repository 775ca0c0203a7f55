"""Benchmark: the lubricated Flores slider-crank (400 cP), two crank revolutions.

In one run, with the same tolerances: the engine with the closed-form long
bearing (``hamrock_long``), the Reynolds fast mode (``reynolds_table``: the
table is built once per process at compile time; that build is timed apart and
left out of the run time) and the Reynolds exact mode (``reynolds_exact``),
each with the implicit NDF method (``bdf``) and, for the closed form, also with
Dormand-Prince (``dopri5``); the engine on the dry joint (``dopri5``, the
method for impacts); and SciPy on the independent minimal-coordinate model of
``tests/physics/reference_lubricated.py`` with the same closed-form film:
``solve_ivp`` RK45 (the baseline of the targets, as for the dry benchmark) and,
for comparison within the implicit class, LSODA and BDF.

The squeeze film makes this model stiff, so method choice decides the cost;
and the implicit method's error is controlled per step without local
extrapolation. So every row also shows its error against a tight reference
(the SciPy model at rtol 1e-9): relative errors of the peak film force and of
the minimum film thickness (for the closed-form rows: the Reynolds film is a
finite bearing, another model), and the closed form runs once more with the
NDF at 1/100 of the tolerances, to show its cost at an accuracy like
Dormand-Prince's.

The cases are run interleaved, round after round, so that load drift on a
shared machine hits them alike; the table gives the median CPU and wall time
with their quartiles, accepted steps, right-hand-side evaluations, CPU time per
evaluation, the ratio to the baseline and to the dry case (medians of
per-round ratios, ``benches/timing.py``), and checks the targets of issue 4
with the engine's fastest method for each case, a target being met only when
the median meets it:

* closed form within 2x of the dry case, and >= 30x faster than its baseline;
* fast mode within 3x of the closed form;
* exact mode under 60 s.

Absolute times drift between machines and runs; the ratios are what is reported.

Run: python benches/bench_flores_lubricated.py [--repeats N] [--exact-repeats N] [--no-exact] [--markdown]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "examples"), str(ROOT / "tests" / "physics"), str(ROOT / "benches")]

import flores_slider_crank_dry as flores  # noqa: E402
import reference_lubricated as reference  # noqa: E402
import timing  # noqa: E402
from jointplay import laws  # noqa: E402

VISCOSITY_CP = 400.0


def engine_model(film: str | None):
    model = flores.build_model()
    if film is not None:
        model.joint("B")["lubrication"] = laws.lubrication(film, laws.centipoise(VISCOSITY_CP))
    started = time.perf_counter()
    model.compile()
    return model, time.perf_counter() - started


def engine_case(name: str, film: str | None, method: str, rtol: float, atol: float) -> timing.Case:
    """The engine on the model with ``film`` (None: dry), timed apart from its compilation."""
    model, compile_time = engine_model(film)
    t_end = flores.revolutions_to_time(2.0)
    case = timing.Case(name, lambda: model.simulate(t_end, method=method, rtol=rtol, atol=atol))
    # the tight reference is the closed-form model: errors against it only mean something for that film
    case.same_model, case.lubricated, case.compile_time = film == "hamrock_long", film is not None, compile_time
    return case


def scipy_case(method: str, rtol: float, atol: float) -> timing.Case:
    role = "baseline" if method == "RK45" else "comparison"
    case = timing.Case(f"SciPy solve_ivp {method}, closed form ({role})",
                       lambda: reference.simulate_lubricated(rtol=rtol, atol=atol, method=method))
    case.same_model, case.lubricated = True, True
    return case


def row(case: timing.Case) -> dict:
    """Median times with their quartiles, counts and the film results of the last run of ``case``."""
    r = case.last
    if hasattr(r, "statistics"):  # the engine
        steps, rhs, impacts = r.statistics["accepted_steps"], r.statistics["rhs_evaluations"], r.diagnostics["impacts"][0]
        fh = film_min = float("nan")
        if case.lubricated:
            fh, film_min = float(np.max(r["B.fh"])), float(np.min(r["B.film_min"]))
    else:
        steps, rhs, impacts = r.n_steps, r.nfev, len(r.impacts)
        fh, film_min = float(r.fh.max()), float(r.film_min.min())
    return {"name": case.name, "cpu": timing.Spread.of(case.values("cpu")),
            "wall": timing.Spread.of(case.values("wall")), "runs": len(case.values("cpu")), "steps": steps,
            "rhs": rhs, "peak_fh": fh, "film_min": film_min, "impacts": int(impacts), "same_model": case.same_model}


def tight_reference() -> tuple[float, float]:
    """Peak film force [N] and minimum film [m] of the SciPy model at rtol 1e-9, atol 1e-12."""
    r = reference.simulate_lubricated(rtol=1e-9, atol=1e-12, method="RK45")
    return float(r.fh.max()), float(r.film_min.min())


def relative(value: float, exact: float) -> str:
    return "-" if not np.isfinite(value) else f"{abs(value / exact - 1):.1e}"


def main(argv: list[str] | None = None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7, help="runs of the fast cases (median reported)")
    parser.add_argument("--baseline-repeats", type=int, default=3)
    parser.add_argument("--exact-repeats", type=int, default=1)
    parser.add_argument("--no-exact", action="store_true", help="skip the Reynolds exact mode")
    parser.add_argument("--rtol", type=float, default=1e-6)
    parser.add_argument("--atol", type=float, default=1e-9)
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    args = parser.parse_args(argv)
    tol = (args.rtol, args.atol)

    dry = engine_case("jointplay dopri5, dry joint", None, "dopri5", *tol)
    closed = engine_case("jointplay bdf, closed form (hamrock_long)", "hamrock_long", "bdf", *tol)
    closed_explicit = engine_case("jointplay dopri5, closed form (hamrock_long)", "hamrock_long", "dopri5", *tol)
    tight = (1e-2 * args.rtol, 1e-2 * args.atol)
    closed_tight = engine_case(f"jointplay bdf at rtol {tight[0]:g}, closed form (hamrock_long)", "hamrock_long",
                               "bdf", *tight)
    table = engine_case("jointplay bdf, Reynolds fast mode (reynolds_table)", "reynolds_table", "bdf", *tol)
    exact = None if args.no_exact else engine_case("jointplay bdf, Reynolds exact mode (reynolds_exact)",
                                                   "reynolds_exact", "bdf", *tol)
    baseline = scipy_case("RK45", *tol)
    comparisons = [scipy_case("LSODA", *tol), scipy_case("BDF", *tol)]
    fast_cases = [dry, closed, closed_tight, closed_explicit, table]
    cases = fast_cases + comparisons + [baseline] + ([exact] if exact else [])
    repeats = {**{c.name: args.repeats for c in fast_cases + comparisons}, baseline.name: args.baseline_repeats}
    if exact is not None:
        repeats[exact.name] = args.exact_repeats
    # interleave: each round runs every case that still has repeats to do
    timing.interleave(cases, max(repeats.values()), lambda case, k: k < repeats[case.name])
    exact_fh, exact_film = tight_reference()

    rows = [row(case) for case in fast_cases] + ([row(exact)] if exact else []) + [row(baseline)]
    rows += [row(case) for case in comparisons]
    speedup = {c.name: timing.ratio(baseline, c) for c in cases}
    vs_dry = {c.name: timing.ratio(c, dry) for c in cases}
    print(f"lubricated Flores slider-crank ({VISCOSITY_CP:g} cP, wang_improved transition), 2 crank revolutions "
          f"({flores.revolutions_to_time(2.0):.4f} s), rtol {args.rtol:g}, atol {args.atol:g}; "
          f"{args.repeats} interleaved rounds (SciPy RK45 in the first {args.baseline_repeats}, exact in the first "
          f"{args.exact_repeats}); CPU time, median [interquartile range]; ratios are medians of per-round ratios")
    print(f"Reynolds force table build (once per process, excluded from the run time): {table.compile_time:.2f} s "
          f"(closed-form compile {closed.compile_time * 1e3:.1f} ms)")
    print(f"tight reference (SciPy model, rtol 1e-9): peak film force {exact_fh:.1f} N, "
          f"minimum film {1e6 * exact_film:.3f} um")
    if args.markdown:
        print("\n| case | CPU time [ms] | wall time [ms] | steps | rhs evaluations | CPU time / evaluation [us] | "
              "speed-up vs baseline | time vs dry | peak film force [N] | min film [um] | "
              "error of peak force | error of min film | impacts |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        per_eval = 1e6 * r["cpu"].median / r["rhs"]
        fh = "-" if not np.isfinite(r["peak_fh"]) else f"{r['peak_fh']:.0f}"
        hmin = "-" if not np.isfinite(r["film_min"]) else f"{1e6 * r['film_min']:.2f}"
        efh = ehmin = "-"  # a finite-length Reynolds film is another model than the reference's
        if r["same_model"]:
            efh, ehmin = relative(r["peak_fh"], exact_fh), relative(r["film_min"], exact_film)
        s_base, s_dry = speedup[r["name"]], vs_dry[r["name"]]
        base_text = f"{s_base.text()}x" if s_base.n else "-"
        dry_text = f"{s_dry.text()}x" if s_dry.n else "-"
        if args.markdown:
            print(f"| {r['name']} | {r['cpu'].text(1e3)} | {r['wall'].text(1e3)} | {r['steps']} | {r['rhs']} | "
                  f"{per_eval:.2f} | {base_text} | {dry_text} | {fh} | {hmin} | {efh} | {ehmin} | {r['impacts']} |")
        else:
            print(f"{r['name']:<52} CPU {r['cpu'].text(1e3):>22} ms {r['steps']:6d} steps {r['rhs']:7d} rhs "
                  f"{per_eval:8.2f} us/rhs {base_text:>18} base {dry_text:>18} dry  Fh {fh:>5} N ({efh})  "
                  f"hmin {hmin:>6} um ({ehmin})  {r['impacts']:2d} impacts")
    checks = [
        ("closed form within 2x of the dry case", vs_dry[closed.name].median, "<=", 2.0),
        ("closed form >= 30x faster than the SciPy baseline", speedup[closed.name].median, ">=", 30.0),
        ("fast mode within 3x of the closed form", timing.ratio(table, closed).median, "<=", 3.0),
    ]
    if exact is not None:
        checks.append(("exact mode under 60 s", exact.median("wall"), "<=", 60.0))
    print("\ntargets (issue 4), engine with bdf, medians:")
    for label, value, op, target in checks:
        print(f"  {timing.verdict(value, op, target)} {label}: {value:.3g} ({op} {target:g})")
    return {"rows": rows, "table_build": table.compile_time, "checks": checks,
            "reference": {"peak_fh": exact_fh, "film_min": exact_film}}


if __name__ == "__main__":
    main()
