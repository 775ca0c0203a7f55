"""Benchmark: how the cost of a run grows with the model, and the exponent of that growth.

Six series, each timed per run and per evaluation, in both formulations where both apply:

1. **rigid chain**: N bars (0.1 m, 0.1 kg) pinned end to end, hanging from a ground pin, released
   horizontal under gravity; Dormand-Prince, 0.1 s. Joint coordinates and absolute coordinates.
2. **clearance chain**: the same chain of K bars whose K pins are all dry clearance joints
   (Lankarani-Nikravesh, bore 5 mm, clearance 0.1 mm, frictionless); Dormand-Prince, 0.05 s. Both
   formulations (no ideal joint is left, so joint coordinates are the bodies' own coordinates).
3. **beam mesh**: the spin-up beam of Simo and Vu-Quoc with E linear elements
   (``benches/bench_spin_up_beam.py``), generalized-alpha at a fixed step of 0.01 s over 1 s;
   absolute coordinates (joint coordinates hold rigid bodies only). Exudyn's
   ``ObjectBeamGeometricallyExact2D`` on the same nodes at the same step and spectral radius, with a
   reachable Newton tolerance (1e-5) so that it keeps its step.
4. **modal body**: a pendulum of one modal body (a 1 m steel bar 20 x 10 mm, 64 quadratic elements,
   M fixed-interface normal modes, up to the 40 a modal body allows) pinned at its start, released
   horizontal; BDF of order up to 2,
   0.2 s; absolute coordinates. Exudyn's ``ObjectFFRFreducedOrder`` is not the same model: it takes
   its modes and invariants from a 3D finite-element mesh of its own FEM module, where jointplay's
   modal body is planar with the modes of its own beam elements; no Exudyn row.
5. **breaker-like mechanism** (a plausible chosen model, not the values of paper 003): a crank
   driven at 600 rpm works a slider through three four-bar stages; the three couplers and the output
   rod are modal bodies (4 normal modes each) and the eight pins between moving links are dry
   clearance joints. Dormand-Prince (measured faster here than BDF or generalized-alpha: the
   impacts, not the modes, set the step), 5 ms; absolute coordinates (flexible links).
6. **spatial chain**: N spatial bars (0.1 m, 0.1 kg) on spherical joints hanging from a ground point,
   released horizontal while turning about the vertical at 2 rad/s, gravity along -z; Dormand-Prince,
   0.1 s; absolute coordinates (the joint-coordinate formulation holds planar trees).

Cost per evaluation = CPU time of the run / (right-hand-side evaluations of the integrator + the
evaluations of the summary's peak search, ``extrema["inner_evaluations"]``): both evaluate the
equations of motion. For Exudyn the divisor is its Newton iterations (each evaluates the residual). The exponent of each series is the least-squares slope of log(cost) on
log(size) over its sizes. Cases of a series run interleaved, round after round, in one process
(``benches/timing.py``), the order turned by one case each round; medians with [min-max]. Exudyn is optional (``pip install exudyn``); without
it its rows are skipped with the reason.

Run: python benches/bench_scaling.py [--rounds N] [--quick] [--markdown] [--series rigid_chain ...] [--sizes ...]
"""

from __future__ import annotations

import argparse
import math
import sys
import warnings
from collections.abc import Callable
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "examples"), str(ROOT / "benches")]

import jointplay as jp  # noqa: E402
from jointplay import functions as fn  # noqa: E402
from jointplay import laws, mechanisms, sections  # noqa: E402
import bench_spin_up_beam as spin_up  # noqa: E402
import timing  # noqa: E402

#: Sizes of each series, full and quick.
SIZES = {
    "rigid_chain": ([4, 8, 16, 32, 64, 128], [2, 4]),
    "clearance_chain": ([1, 2, 4, 8, 16], [1, 2]),
    "beam_mesh": ([8, 16, 32, 64, 128], [2, 4]),
    "modal_body": ([4, 8, 16, 32, 40], [2, 4]),
    "breaker": ([8], [8]),
    "spatial_chain": ([4, 8, 16, 32, 64, 128], [2, 4]),
}
#: Largest rigid chain run in joint coordinates (their cost grows as N^2.3: 128 bars would take
#: most of the benchmark's time).
MAX_JOINT_CHAIN = 64
BAR_LENGTH, BAR_MASS, BAR_INERTIA = 0.1, 0.1, 1e-4  # m, kg, kg m^2
BEAM_STEP, BEAM_T_END = 0.01, 1.0  # s, s
#: Exudyn's Newton tolerances: relative as in ``bench_spin_up_beam``; absolute 1e-4, because its default
#: 1e-10 (and 1e-6) is not reached while the ramp starts, and Exudyn then halves its step (measured:
#: 2743 steps instead of 100 at 8 elements, 40807 at 64).
EXUDYN_NEWTON_RTOL, EXUDYN_NEWTON_ATOL = 1e-5, 1e-4
#: The spatial chain's bars: principal inertia about the bar's axis and across it [kg m^2] (a rod of
#: 14 mm radius: m r^2 / 2 = 1e-5), gravity [m/s^2] and the chain's start turn about the vertical [rad/s].
SPATIAL_BAR_INERTIA = (1e-5, BAR_INERTIA, BAR_INERTIA)
SPATIAL_GRAVITY = (0.0, 0.0, -9.81)
CHAIN_SPIN = 2.0
STEEL = sections.material("207 GPa", "7850 kg/m^3", poisson_ratio=0.3)


#: The clearance joint of every pin of a clearance chain.
CLEARANCE_PIN = dict(bearing_radius="5 mm", clearance="0.1 mm", contact=laws.lankarani_nikravesh(0.9),
                     friction=laws.frictionless())


def chain(n: int, clearance: bool = False) -> jp.Model:
    """N bars pinned end to end from a ground pin, horizontal; every pin a clearance joint if asked."""
    return mechanisms.hanging_chain(n, bar_length=BAR_LENGTH, bar_mass=BAR_MASS, bar_inertia=BAR_INERTIA,
                                    clearance=CLEARANCE_PIN if clearance else None, name=f"chain{n}")


def spatial_chain(n: int) -> jp.Model:
    """N spatial bars on spherical joints from a ground point, horizontal along x, the whole chain turning
    about the vertical through the ground point at ``CHAIN_SPIN`` (a rigid turn: the joints hold at the start)."""
    m = jp.Model(f"spatial_chain{n}", gravity=SPATIAL_GRAVITY, kinematics="spatial")
    m.add_ground_point("O", (0.0, 0.0, 0.0))
    half = BAR_LENGTH / 2
    for k in range(1, n + 1):
        x = (k - 0.5) * BAR_LENGTH
        m.add_body(f"bar{k}", mass=BAR_MASS, inertia={"principal": list(SPATIAL_BAR_INERTIA)}, position=(x, 0.0, 0.0),
                   velocity=(0.0, CHAIN_SPIN * x, 0.0), angular_velocity=(0.0, 0.0, CHAIN_SPIN),
                   points={"A": [-half, 0.0, 0.0], "B": [half, 0.0, 0.0]})
        m.add_spherical(f"J{k}", "ground.O" if k == 1 else f"bar{k - 1}.B", f"bar{k}.A")
    return m


def modal_pendulum(modes: int) -> jp.Model:
    """A 1 m steel bar as a modal body with ``modes`` normal modes, pinned at its start."""
    m = jp.Model("modal_pendulum", gravity=(0.0, -9.81))
    m.add_ground_point("O", (0.0, 0.0))
    m.add_modal_body("bar", (0, 0), ("1 m", 0), section=sections.rectangle("20 mm", "10 mm"), material=STEEL,
                     elements=64, normal_modes=modes, interface={"start": 0})
    m.add_revolute("pin", "ground.O", "bar.start")
    return m


def breaker() -> jp.Model:
    """The breaker-like mechanism: crank, three four-bar stages and an output slider (see the module doc)."""
    m = jp.Model("breaker_like", gravity=(0.0, -9.81))
    section = sections.rectangle("12 mm", "6 mm")
    # ground pivots of the crank and the three rockers, and the slider's line [m]
    pivots = {"O": (0.0, 0.0), "P1": (0.20, 0.0), "P2": (0.40, 0.0), "P3": (0.60, 0.0)}
    for name, at in pivots.items():
        m.add_ground_point(name, at)
    m.add_ground_point("line", (0.80, 0.05))
    m.add_body("crank", 0.2, 2e-4, position=(0.0, 0.025), angle=math.pi / 2,
               points={"O": (-0.025, 0.0), "A": (0.025, 0.0)})
    m.add_revolute("O", "ground.O", "crank.O")
    m.add_driver("motor", "O", fn.constant_speed("600 rpm"))
    tops = [(0.0, 0.05)]
    for k, pivot in enumerate(("P1", "P2", "P3"), start=1):
        px, py = pivots[pivot]
        top = (px, py + 0.05)
        m.add_body(f"rocker{k}", 0.2, 2e-4, position=(px, py + 0.025), angle=math.pi / 2,
                   points={"P": (-0.025, 0.0), "T": (0.025, 0.0), "U": (0.025, 0.0)})
        m.add_revolute(f"P{k}", f"ground.{pivot}", f"rocker{k}.P")
        m.add_modal_body(f"coupler{k}", tops[-1], top, section=section, material=STEEL, elements=8,
                         normal_modes=4)
        first = "crank.A" if k == 1 else f"rocker{k - 1}.U"
        joint = dict(bearing_radius="6 mm", clearance="0.05 mm", contact=laws.lankarani_nikravesh(0.9),
                     friction=laws.frictionless())
        m.add_clearance_revolute(f"J{2 * k - 1}", first, f"coupler{k}.start", **joint)
        m.add_clearance_revolute(f"J{2 * k}", f"coupler{k}.end", f"rocker{k}.T", **joint)
        tops.append(top)
    m.add_body("slider", 0.3, 1e-4, position=(0.80, 0.05), points={"S": (0.0, 0.0)})
    m.add_modal_body("rod", tops[-1], (0.80, 0.05), section=section, material=STEEL, elements=8, normal_modes=4)
    joint = dict(bearing_radius="6 mm", clearance="0.05 mm", contact=laws.lankarani_nikravesh(0.9),
                 friction=laws.frictionless())
    m.add_clearance_revolute("J7", "rocker3.U", "rod.start", **joint)
    m.add_clearance_revolute("J8", "rod.end", "slider.S", **joint)
    m.add_translational("guide", "ground.line", "slider.S", axis=(1.0, 0.0))
    return m


class Row:
    """One timed case of a series (a plain class: the benchmark is also loaded from its file, outside
    ``sys.modules``, where dataclasses cannot resolve their annotations)."""

    def __init__(self, series: str, size: int, variant: str, case: timing.Case, chosen: str = "yes",
                 reference: tuple | None = None):
        self.series, self.size, self.variant, self.case = series, size, variant, case
        #: Whether ``auto`` chooses this row's formulation for its model ("-" for a peer code).
        self.chosen = chosen
        #: The beam's tip motion from jointplay at rtol 1e-7, (time, along, across, statistics), for the error.
        self.reference = reference

    def tip_error(self) -> float | None:
        """Largest |tip deflection - reference's| [m] (beam rows), else None."""
        if self.reference is None:
            return None
        last = self.case.last
        return spin_up.tip_error(last if isinstance(last, tuple) else beam_tip(last), self.reference)

    def evaluations(self) -> int:
        """Right-hand-side evaluations of the last run (the summary's peak search included)."""
        last = self.case.last
        if isinstance(last, tuple):  # Exudyn: Newton iterations
            return last[3]["newton_iterations"]
        return last.statistics["rhs_evaluations"] + (last.extrema or {}).get("inner_evaluations", 0)

    def per_evaluation(self, clock: str = "cpu") -> timing.Spread:
        n = max(1, self.evaluations())
        return timing.Spread.of([v / n for v in self.case.values(clock)])


def jointplay_case(model: jp.Model, t_end: float, **options) -> Callable[[], jp.Results]:
    """A function running ``model`` (compiled now) to ``t_end`` [s] with ``options``."""
    model.compile()
    return lambda: model.simulate(t_end, **options)


def exudyn_case(elements: int, t_end: float) -> Callable[[], tuple]:
    """A function building and running Exudyn's spin-up beam once (``bench_spin_up_beam.exudyn_runner``,
    its sparse solver, at this benchmark's step and a reachable absolute Newton tolerance); returns
    (time, along, across, stats)."""
    return spin_up.exudyn_runner(elements, t_end, round(t_end / BEAM_STEP), EXUDYN_NEWTON_RTOL, EXUDYN_NEWTON_ATOL)


def beam_tip(results) -> tuple:
    """(time, along, across, statistics) of the beam's tip in the hub's frame [s, m, m] from jointplay's results."""
    along, across = spin_up.example.tip_in_hub_frame(results)
    return results.time, along, across, results.statistics


def series_rows(series: str, sizes: list[int], chain_time: float | None = None) -> list[Row]:
    """The cases of one series (not yet run); ``chain_time`` [s] instead of the chains' own end times."""
    rows = []
    for n in sizes:
        if series in ("rigid_chain", "clearance_chain"):
            clearance = series == "clearance_chain"
            t_end = chain_time or (0.05 if clearance else 0.1)
            auto = chain(n, clearance).check()["formulation"]
            for formulation in ("joint_coordinates", "absolute"):
                if formulation == "joint_coordinates" and not clearance and n > MAX_JOINT_CHAIN:
                    continue
                run = jointplay_case(chain(n, clearance), t_end, formulation=formulation, output_step=t_end / 10)
                rows.append(Row(series, n, formulation, timing.Case(f"{series} {n} {formulation}", run),
                                "yes" if formulation == auto else "no"))
        elif series == "beam_mesh":
            model = spin_up.build_jointplay(n)
            run = jointplay_case(model, BEAM_T_END, method="generalized_alpha", step=BEAM_STEP, spectral_radius=0.9,
                                 stabilization="baumgarte", rtol=1e-5, atol=1e-7, output_step=spin_up.SAMPLE)
            rows.append(Row(series, n, "absolute", timing.Case(f"{series} {n} jointplay", run)))
            rows[-1].reference = spin_up.jointplay_runner(n, BEAM_T_END, spin_up.REFERENCE_RTOL)()
            if spin_up.exudyn is not None:
                rows.append(Row(series, n, "Exudyn", timing.Case(f"{series} {n} Exudyn", exudyn_case(n, BEAM_T_END)),
                                "-", rows[-1].reference))
        elif series == "spatial_chain":
            # spatial models run in absolute coordinates (the joint-coordinate formulation holds planar trees)
            t_end = chain_time or 0.1
            run = jointplay_case(spatial_chain(n), t_end, formulation="absolute", output_step=t_end / 10)
            rows.append(Row(series, n, "absolute", timing.Case(f"{series} {n} absolute", run)))
        elif series == "modal_body":
            run = jointplay_case(modal_pendulum(n), 0.2, method="bdf", max_order=2, rtol=1e-5, atol=1e-8,
                                 output_step=0.01)
            rows.append(Row(series, n, "absolute", timing.Case(f"{series} {n} jointplay", run)))
        else:
            run = jointplay_case(breaker(), 0.005, method="dopri5", rtol=1e-5, atol=1e-8, output_step=1e-3)
            rows.append(Row(series, n, "absolute", timing.Case(f"{series} {n} jointplay", run)))
    return rows


def exponent(rows: list[Row], per_evaluation: bool) -> float | None:
    """Least-squares slope of log(median CPU cost) on log(size); None with fewer than two sizes."""
    if len(rows) < 2:
        return None
    cost = [(r.per_evaluation().median if per_evaluation else r.case.median()) for r in rows]
    return float(np.polyfit(np.log([r.size for r in rows]), np.log(cost), 1)[0])


def main(argv: list[str] | None = None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5, help="interleaved rounds")
    parser.add_argument("--series", nargs="+", default=list(SIZES), choices=list(SIZES))
    parser.add_argument("--sizes", type=int, nargs="+", default=None,
                        help="sizes instead of the series' own (the break-even of the formulations: "
                             "--series rigid_chain clearance_chain --sizes 1 2 3 4 6 8 10 12 16)")
    parser.add_argument("--chain-time", type=float, default=None,
                        help="simulated time of the chains [s] (default 0.1 s, 0.05 s with clearance joints)")
    parser.add_argument("--quick", action="store_true", help="the two smallest sizes, one round: checks that it runs")
    parser.add_argument("--markdown", action="store_true", help="print Markdown tables")
    args = parser.parse_args(argv)
    rounds = 1 if args.quick else args.rounds
    if spin_up.exudyn is None:
        print(f"Exudyn rows: skipped, {spin_up.EXUDYN_MISSING}")
    report = {"rows": [], "exponents": [], "beam_ratios": [], "formulation_ratios": []}
    with warnings.catch_warnings():
        # long chains are far from the middle of the mechanism: the plausibility warning is expected
        warnings.simplefilter("ignore", jp.JointplayWarning)
        for series in args.series:
            rows = series_rows(series, args.sizes or SIZES[series][1 if args.quick else 0], args.chain_time)
            for r in rows:  # one untimed run each: first-call costs stay out of the rounds
                r.case.run()
            # the order turns by one case each round: no case is always first after the round's largest
            # (measured: the first case of every round ran up to 1.4x slower)
            cases = [r.case for r in rows]
            for k in range(rounds):
                timing.interleave(cases[k % len(cases):] + cases[:k % len(cases)], 1)
            report["rows"] += rows
            for size in dict.fromkeys(r.size for r in rows):
                pair = {r.variant: r.case for r in rows if r.size == size}
                if {"absolute", "Exudyn"} <= pair.keys():
                    report["beam_ratios"].append((size, timing.ratio(pair["Exudyn"], pair["absolute"])))
                if {"absolute", "joint_coordinates"} <= pair.keys():
                    report["formulation_ratios"].append(
                        (series, "", size, timing.ratio(pair["joint_coordinates"], pair["absolute"])))
            for variant in dict.fromkeys(r.variant for r in rows):
                mine = [r for r in rows if r.variant == variant]
                report["exponents"].append((series, variant, exponent(mine, False), exponent(mine, True)))
    print_report(report, rounds, args.markdown)
    return report


def print_report(report: dict, rounds: int, markdown: bool) -> None:
    """The table of cases and the table of exponents."""
    sep = "|" if markdown else " "
    print(f"\n{rounds} interleaved round(s); CPU times, median [min-max]")
    if markdown:
        print("\n| series | size | formulation or code | run [ms] | evaluations | per evaluation [us] | chosen by auto "
              "| tip error [mm] |")
        print("|---|---:|---|---:|---:|---:|---|---:|")
    for r in report["rows"]:
        run, per = timing.Spread.of(r.case.values("cpu")), r.per_evaluation()
        error = r.tip_error()
        cells = (r.series, str(r.size), r.variant, f"{run.median * 1e3:.3g} [{run.low * 1e3:.3g}-{run.high * 1e3:.3g}]",
                 str(r.evaluations()), f"{per.median * 1e6:.3g} [{per.low * 1e6:.3g}-{per.high * 1e6:.3g}]", r.chosen,
                 "-" if error is None else f"{error * 1e3:.3g}")
        print((f"| {' | '.join(cells)} |") if markdown else sep.join(c.ljust(14) for c in cells))
    if markdown:
        print("\n| series | formulation or code | exponent of run cost | exponent of cost per evaluation |")
        print("|---|---|---:|---:|")
    else:
        print("\nexponents (least squares on log-log): series, variant, run cost, cost per evaluation")
    for series, variant, whole, per in report["exponents"]:
        cells = (series, variant, "-" if whole is None else f"{whole:.2f}", "-" if per is None else f"{per:.2f}")
        print((f"| {' | '.join(cells)} |") if markdown else sep.join(c.ljust(18) for c in cells))
    for size, spread in report["beam_ratios"]:
        print(f"beam mesh, {size} elements: Exudyn / jointplay CPU time {spread.median:.3g} [{spread.low:.3g}-"
              f"{spread.high:.3g}] (above 1: jointplay faster; goal: above 1 at every size)")
    for series, variant, size, spread in report["formulation_ratios"]:
        print(f"{series}, {size}: joint coordinates / absolute CPU time {spread.median:.3g} [{spread.low:.3g}-"
              f"{spread.high:.3g}]")


if __name__ == "__main__":
    main()
