"""Benchmark: the lubricated Flores slider-crank (400 cP), two crank revolutions.

In one run, with the same tolerances: the engine with the closed-form long
bearing (``hamrock_long``), the Reynolds fast mode (``reynolds_table``: the
table is built once per process at compile time; that build is timed apart and
left out of the run time), the Reynolds exact mode (``reynolds_exact``), the
engine on the dry joint, and the SciPy baseline of the closed-form model
(``solve_ivp`` RK45 on the independent minimal-coordinate model of
``tests/physics/reference_lubricated.py``). The cases are run interleaved,
repeat after repeat, so that load drift on a shared machine hits them alike;
the table gives the median wall time, accepted steps, right-hand-side
evaluations, time per evaluation, the ratio to the baseline and to the dry
case, and checks the targets of issue 4:

* closed form within 2x of the dry case, and >= 30x faster than its baseline;
* fast mode within 3x of the closed form;
* exact mode under 60 s.

Absolute times drift between machines and runs; the ratios are what is reported.

Run: python benches/bench_flores_lubricated.py [--repeats N] [--exact-repeats N] [--markdown]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "examples"), str(ROOT / "tests" / "physics")]

import flores_slider_crank_dry as flores  # noqa: E402
import reference_lubricated as reference  # noqa: E402
from jointplay import laws  # noqa: E402

VISCOSITY_CP = 400.0


def engine_model(film: str | None):
    model = flores.build_model()
    if film is not None:
        model.joint("B")["lubrication"] = laws.lubrication(film, laws.centipoise(VISCOSITY_CP))
    started = time.perf_counter()
    model.compile()
    return model, time.perf_counter() - started


class EngineCase:
    def __init__(self, name: str, film: str | None, rtol: float, atol: float):
        self.name, self.rtol, self.atol, self.lubricated = name, rtol, atol, film is not None
        self.model, self.compile_time = engine_model(film)
        self.walls: list[float] = []
        self.last = None

    def run(self) -> None:
        results = self.model.simulate(flores.revolutions_to_time(2.0), rtol=self.rtol, atol=self.atol)
        self.walls.append(results.wall_time)
        self.last = results

    def row(self) -> dict:
        r = self.last
        stats = r.statistics
        fh = film_min = float("nan")
        if self.lubricated:
            fh, film_min = float(np.max(r["B.fh"])), float(np.min(r["B.film_min"]))
        return {"name": self.name, "wall": statistics.median(self.walls), "runs": len(self.walls),
                "steps": stats["accepted_steps"], "rhs": stats["rhs_evaluations"], "peak_fh": fh,
                "film_min": film_min, "impacts": int(r.diagnostics["impacts"][0])}


class BaselineCase:
    def __init__(self, rtol: float, atol: float):
        self.name = "SciPy solve_ivp RK45, closed form (baseline)"
        self.rtol, self.atol = rtol, atol
        self.walls: list[float] = []
        self.last = None

    def run(self) -> None:
        started = time.perf_counter()
        self.last = reference.simulate_lubricated(rtol=self.rtol, atol=self.atol, method="RK45")
        self.walls.append(time.perf_counter() - started)

    def row(self) -> dict:
        r = self.last
        return {"name": self.name, "wall": statistics.median(self.walls), "runs": len(self.walls),
                "steps": r.n_steps, "rhs": r.nfev, "peak_fh": float(r.fh.max()),
                "film_min": float(r.film_min.min()), "impacts": len(r.impacts)}


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

    dry = EngineCase("jointplay, dry joint", None, args.rtol, args.atol)
    closed = EngineCase("jointplay, closed form (hamrock_long)", "hamrock_long", args.rtol, args.atol)
    table = EngineCase("jointplay, Reynolds fast mode (reynolds_table)", "reynolds_table", args.rtol, args.atol)
    exact = None if args.no_exact else EngineCase("jointplay, Reynolds exact mode (reynolds_exact)",
                                                  "reynolds_exact", args.rtol, args.atol)
    baseline = BaselineCase(args.rtol, args.atol)
    # interleave: each repeat runs every case once
    for k in range(max(args.repeats, args.baseline_repeats, args.exact_repeats)):
        for case in (dry, closed, table):
            if k < args.repeats:
                case.run()
        if k < args.baseline_repeats:
            baseline.run()
        if exact is not None and k < args.exact_repeats:
            exact.run()

    rows = [dry.row(), closed.row(), table.row()] + ([exact.row()] if exact else []) + [baseline.row()]
    base, dry_wall = rows[-1]["wall"], rows[0]["wall"]
    print(f"lubricated Flores slider-crank ({VISCOSITY_CP:g} cP, wang_improved transition), 2 crank revolutions "
          f"({flores.revolutions_to_time(2.0):.4f} s), rtol {args.rtol:g}, atol {args.atol:g}, engine dopri5; "
          f"median of {args.repeats} runs (baseline {args.baseline_repeats}, exact {args.exact_repeats}), "
          f"cases interleaved")
    print(f"Reynolds force table build (once per process, excluded from the run time): {table.compile_time:.2f} s "
          f"(closed-form compile {closed.compile_time * 1e3:.1f} ms)")
    if args.markdown:
        print("\n| case | wall time [ms] | steps | rhs evaluations | wall time / evaluation [us] | "
              "speed-up vs baseline | time vs dry | peak film force [N] | min film [um] | impacts |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for row in rows:
        speedup = base / row["wall"]
        vs_dry = row["wall"] / dry_wall
        per_eval = 1e6 * row["wall"] / row["rhs"]
        fh = "-" if not np.isfinite(row["peak_fh"]) else f"{row['peak_fh']:.0f}"
        hmin = "-" if not np.isfinite(row["film_min"]) else f"{1e6 * row['film_min']:.2f}"
        if args.markdown:
            print(f"| {row['name']} | {1e3 * row['wall']:.1f} | {row['steps']} | {row['rhs']} | {per_eval:.2f} | "
                  f"{speedup:.1f}x | {vs_dry:.2f}x | {fh} | {hmin} | {row['impacts']} |")
        else:
            print(f"{row['name']:<48} {1e3 * row['wall']:10.1f} ms {row['steps']:7d} steps {row['rhs']:8d} rhs "
                  f"{per_eval:8.2f} us/rhs {speedup:8.1f}x base {vs_dry:6.2f}x dry  Fh {fh:>6} N  "
                  f"hmin {hmin:>6} um  {row['impacts']:3d} impacts")
    c, t_ = rows[1], rows[2]
    checks = [
        ("closed form within 2x of the dry case", c["wall"] / dry_wall, "<=", 2.0),
        ("closed form >= 30x faster than the SciPy baseline", base / c["wall"], ">=", 30.0),
        ("fast mode within 3x of the closed form", t_["wall"] / c["wall"], "<=", 3.0),
    ]
    if exact is not None:
        checks.append(("exact mode under 60 s", rows[3]["wall"], "<=", 60.0))
    print("\ntargets (issue 4):")
    for label, value, op, target in checks:
        ok = value <= target if op == "<=" else value >= target
        print(f"  {'met   ' if ok else 'MISSED'} {label}: {value:.3g} ({op} {target:g})")
    return {"rows": rows, "table_build": table.compile_time, "checks": checks}


if __name__ == "__main__":
    main()
