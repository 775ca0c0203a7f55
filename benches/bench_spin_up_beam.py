"""Benchmark: the spin-up beam of Simo and Vu-Quoc, jointplay against Exudyn on the same mesh.

The beam (L = 10 m, EA = 2.8e7 N, GA = 1e7 N, EI = 1.4e4 N m^2, rho A = 1.2 kg/m, rho I = 6e-4 kg m;
undamped, no gravity) is clamped at its root, which turns by the speed ramp to 6 rad/s over 15 s and
then at 6 rad/s, over 0..20 s (``examples/spin_up_beam.py``).

- jointplay: a hub driven by the ramp, the beam clamped to it (as the example), but with *linear*
  (2-node) elements, Baumgarte stabilisation, two methods: generalized-alpha at Exudyn's step and
  spectral radius (the example's method; the comparison the goal is judged on), and the NDF of order
  up to 2 at rtol 1e-5 (error-controlled, for reference).
- Exudyn: ``ObjectBeamGeometricallyExact2D``, its linear 2-node Reissner element, on the same nodes;
  the root node's x and y held by ``CoordinateConstraint`` and its angle prescribed by a
  ``CoordinateConstraint`` with an ``offsetUserFunction`` (the ramp, a Python function, as Exudyn's
  examples do; its share of Exudyn's time is below 0.2 %); generalized-alpha (spectral radius 0.9,
  Exudyn's default) with a fixed step, Exudyn's adaptive step reduction on Newton failure left on.

The same mesh: both codes use linear Reissner elements, the same element count, consistent mass.
Matched accuracy is measured, not assumed: the error of a run is the largest difference, over the
samples every 0.02 s, of the tip's transverse deflection seen from the root's frame (peak about
0.57 m) against a jointplay run of the same mesh at rtol 1e-7 (the reference; it agrees with Exudyn
at 20 000 steps to 1.4e-5 m on 4 elements, which is the floor of this measure). Each code's
tolerance or step is an option; the defaults put both near 1e-3 m (0.2 % of the peak). The stretch
at 6 rad/s (mean over the last 2 s) is printed beside the closed form rho A w^2 L^3 / (3 EA).

Timing: both codes in this process, interleaved round after round (``benches/timing.py``); medians
and extremes of CPU and wall time, and the ratio Exudyn / jointplay per round (above 1: jointplay
faster). Exudyn is an optional benchmark dependency, not in the project's extras:
``pip install exudyn``; without it the Exudyn rows are skipped with the reason.

Run: python benches/bench_spin_up_beam.py [--elements 4 8 16] [--repeats N] [--markdown] [--quick]
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "examples"), str(ROOT / "benches")]

import jointplay as jp  # noqa: E402
from jointplay import functions as fn  # noqa: E402
from jointplay import sections  # noqa: E402
import spin_up_beam as example  # noqa: E402
import timing  # noqa: E402

try:
    import exudyn
    from exudyn import itemInterface as exi
    EXUDYN_MISSING = None
except ImportError as missing:  # an optional benchmark dependency
    exudyn = exi = None
    EXUDYN_MISSING = f"exudyn is not installed ({missing}; pip install exudyn)"

AXIAL, SHEAR, BENDING, RHO_A, RHO_I = 2.8e7, 1e7, 1.4e4, 1.2, 6e-4  # N, N, N m^2, kg/m, kg m
LENGTH, FINAL_RATE, RAMP_TIME = example.LENGTH, example.FINAL_RATE, 15.0  # m, rad/s, s
SAMPLE = 0.02  # s, the output grid of both codes
#: jointplay's reference tolerance (rtol; atol is rtol / 100).
REFERENCE_RTOL = 1e-7


def hub_angle(t: float) -> float:
    """The speed ramp's angle [rad] (docs/theory/motion-functions.md), for Exudyn's user function."""
    if t <= 0.0:
        return 0.0
    w, T = FINAL_RATE, RAMP_TIME
    if t <= T:
        return (w / T) * (0.5 * t * t + (T / (2 * math.pi)) ** 2 * (math.cos(2 * math.pi * t / T) - 1))
    return w * t - 0.5 * w * T


def build_jointplay(elements: int, order: str = "linear") -> jp.Model:
    """The example's model with ``elements`` elements of ``order`` (the example has quadratic ones)."""
    m = jp.Model("spin_up_beam", gravity=(0, 0))
    m.add_ground_point("O", (0, 0))
    m.add_body("hub", mass=1.0, inertia=1.0, points={"O": (0, 0)})
    m.add_beam("beam", (0, 0), (LENGTH, 0), section=sections.resultants(AXIAL, SHEAR, BENDING, RHO_A, RHO_I),
               order=order, elements=elements)
    m.add_revolute("axis", "ground.O", "hub.O")
    m.add_fixed("clamp", "hub.O", "beam.start")
    m.add_driver("spin", "axis", fn.speed_ramp(FINAL_RATE, RAMP_TIME))
    return m


def jointplay_runner(elements: int, t_end: float, rtol: float, jacobian: str = "auto", step: float | None = None,
                     spectral_radius: float = 0.9):
    """A function running jointplay once; returns (time, along, across, statistics). With ``step``:
    generalized-alpha at that step (rtol then sets its Newton iterations), else the NDF of order up to 2."""
    model = build_jointplay(elements)
    model.compile()
    method = ({"method": "generalized_alpha", "step": step, "spectral_radius": spectral_radius} if step is not None
              else {"method": "bdf", "max_order": 2})

    def run():
        r = model.simulate(t_end, stabilization="baumgarte", rtol=rtol, atol=rtol / 100, output_step=SAMPLE,
                           jacobian=jacobian, **method)
        along, across = example.tip_in_hub_frame(r)
        return r.time, along, across, r.statistics
    return run


EXUDYN_SOLVERS = ("EigenSparse", "EXUdense")


def exudyn_runner(elements: int, t_end: float, steps: int, newton_rtol: float, newton_atol: float,
                  solver: str = "EigenSparse", spectral_radius: float = 0.9):
    """A function building and running the Exudyn model once; returns (time, along, across, statistics).
    ``solver``: Exudyn's linear solver (``EigenSparse``: its sparse LU; ``EXUdense``: its default)."""

    def run():
        sc = exudyn.SystemContainer()
        mbs = sc.AddSystem()
        ground = mbs.AddMarker(exi.MarkerNodeCoordinate(nodeNumber=mbs.AddNode(exi.NodePointGround()), coordinate=0))
        le = LENGTH / elements
        nodes = [mbs.AddNode(exi.NodeRigidBody2D(referenceCoordinates=[i * le, 0, 0])) for i in range(elements + 1)]
        for a, b in zip(nodes, nodes[1:]):
            mbs.AddObject(exi.ObjectBeamGeometricallyExact2D(
                nodeNumbers=[a, b], length=le, massPerLength=RHO_A, crossSectionInertia=RHO_I,
                bendingStiffness=BENDING, axialStiffness=AXIAL, shearStiffness=SHEAR))
        # the clamped root: x, y held, the angle prescribed
        root = [mbs.AddMarker(exi.MarkerNodeCoordinate(nodeNumber=nodes[0], coordinate=c)) for c in range(3)]
        mbs.AddObject(exi.CoordinateConstraint(markerNumbers=[ground, root[0]]))
        mbs.AddObject(exi.CoordinateConstraint(markerNumbers=[ground, root[1]]))
        mbs.AddObject(exi.CoordinateConstraint(markerNumbers=[ground, root[2]],
                                               offsetUserFunction=lambda mbs, t, item, offset: hub_angle(t)))
        kind = exudyn.OutputVariableType
        tip = mbs.AddSensor(exi.SensorNode(nodeNumber=nodes[-1], outputVariableType=kind.Position,
                                           storeInternal=True, writeToFile=False))
        turn = mbs.AddSensor(exi.SensorNode(nodeNumber=nodes[0], outputVariableType=kind.Rotation,
                                            storeInternal=True, writeToFile=False))
        mbs.Assemble()
        settings = exudyn.SimulationSettings()
        ti = settings.timeIntegration
        ti.endTime, ti.numberOfSteps = t_end, steps
        ti.generalizedAlpha.spectralRadius = spectral_radius
        ti.newton.relativeTolerance = newton_rtol
        # (an absolute tolerance below the residual's round-off makes Newton fail and Exudyn halve its step)
        ti.newton.absoluteTolerance = newton_atol
        settings.linearSolver.solverType = getattr(exudyn.LinearSolverType, solver)
        settings.linearSolver.reuseAnalyzedPattern = True
        ti.verboseMode = 0
        settings.solution.file.write = False
        settings.solution.sensors.writePeriod = SAMPLE
        try:
            mbs.SolveDynamic(settings, storeSolver=True)
        except exudyn.SolverError:  # reported in the row (failed), left out of the comparison
            nan = np.array([np.nan])
            return np.array([0.0]), nan, nan, {"steps": 0, "newton_iterations": 1, "jacobians": 0, "failed": True}
        it = mbs.sys["dynamicSolver"].it
        p, r = mbs.GetSensorStoredData(tip), mbs.GetSensorStoredData(turn)
        x, y, a = p[:, 1], p[:, 2], r[:, -1]
        stats = {"steps": int(it.currentStepIndex), "newton_iterations": int(it.newtonStepsCount),
                 "jacobians": int(it.newtonJacobiCount)}
        return p[:, 0], x * np.cos(a) + y * np.sin(a), -x * np.sin(a) + y * np.cos(a), stats
    return run


def tip_error(result, reference) -> float:
    """Largest |deflection - reference's| [m] at the samples both have on the 0.02 s grid."""
    t, _, across, _ = result
    k = np.rint(t / SAMPLE).astype(int)
    ok = (np.abs(k * SAMPLE - t) < 1e-9) & (k < len(reference[2]))
    return float(np.max(np.abs(across[ok] - reference[2][k[ok]])))


def stretch(result, last: float = 2.0) -> float:
    """Mean stretch of the tip along the root's direction over the last ``last`` seconds [m]."""
    t, along, _, _ = result
    return float(np.mean(along[t >= t[-1] - last] - LENGTH))


def exponent(sizes: list[int], costs: list[float]) -> float:
    """Least-squares slope of log(cost) against log(size)."""
    return float(np.polyfit(np.log(sizes), np.log(costs), 1)[0])


def print_exponents(rows: list[dict]) -> None:
    """Cost exponents over element counts of every series: median CPU time per step, and per
    evaluation (jointplay: right-hand side; Exudyn: Newton iteration), over all meshes and the last doubling."""
    series: dict[str, list[dict]] = {}
    for r in rows:
        series.setdefault(r["name"].rsplit(",", 1)[0], []).append(r)
    for name, rs in series.items():
        if len(rs) < 2:
            continue
        sizes = [r["elements"] for r in rs]
        for label, key in (("per step", "steps"), ("per evaluation", "evaluations")):
            costs = [r["cpu"].median / r[key] for r in rs]
            last = math.log(costs[-1] / costs[-2]) / math.log(sizes[-1] / sizes[-2])
            print(f"{name}: CPU time {label} ~ N^{exponent(sizes, costs):.2f} over {sizes[0]}-{sizes[-1]} elements, "
                  f"{last:.2f} over the last step ({sizes[-2]}-{sizes[-1]}); "
                  f"{', '.join(f'{1e6 * c:.3g} us' for c in costs)}")


def main(argv: list[str] | None = None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--elements", type=int, nargs="+", default=[8, 16, 32, 64, 128],
                        help="meshes (linear elements)")
    parser.add_argument("--repeats", type=int, default=5, help="interleaved rounds")
    parser.add_argument("--t-end", type=float, default=20.0, help="end time [s]")
    parser.add_argument("--jp-rtol", type=float, default=1e-5, help="jointplay rtol (atol = rtol / 100)")
    parser.add_argument("--jp-step", type=float, default=None,
                        help="jointplay's generalized-alpha step [s] (default: Exudyn's step)")
    parser.add_argument("--jacobian", default="auto", help="jointplay's Newton Jacobian")
    parser.add_argument("--exu-step", type=float, default=0.01, help="Exudyn's fixed step [s]")
    parser.add_argument("--exu-newton-rtol", type=float, default=1e-5,
                        help="Exudyn's Newton relative tolerance (its default 1e-8 stalls at round-off here)")
    parser.add_argument("--exu-newton-atol", type=float, default=1e-6,
                        help="Exudyn's Newton absolute tolerance (its default 1e-10 is below the residual's round-off "
                             "on the finer meshes: Newton fails and Exudyn halves its step)")
    parser.add_argument("--exu-solver", nargs="+", default=list(EXUDYN_SOLVERS), choices=EXUDYN_SOLVERS,
                        help="Exudyn linear solvers to time (the comparison takes the fastest per mesh)")
    parser.add_argument("--reference-step", type=float, default=None,
                        help="reference by generalized-alpha at this step [s] instead of the NDF at rtol 1e-7 "
                             "(cheaper on fine meshes; its error falls with the square of the step)")
    parser.add_argument("--no-ndf", action="store_true", help="skip jointplay's NDF rows")
    parser.add_argument("--quick", action="store_true", help="2 elements, 1 s, 1 round: checks that it runs")
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    args = parser.parse_args(argv)
    if args.quick:
        args.elements, args.t_end, args.repeats = [2], 1.0, 1
    steps = max(1, round(args.t_end / args.exu_step))
    jp_step = args.exu_step if args.jp_step is None else args.jp_step
    rows, verdicts = [], []
    print(f"spin-up beam, 0..{args.t_end:g} s, linear elements; jointplay baumgarte, generalized-alpha rho_inf 0.9 "
          f"step {jp_step:g} s and bdf max_order 2, rtol {args.jp_rtol:g} atol {args.jp_rtol / 100:g} jacobian "
          f"{args.jacobian}; Exudyn "
          f"{'-' if exudyn is None else exudyn.__version__} generalized-alpha rho_inf 0.9, step {args.exu_step:g} s, "
          f"Newton rtol {args.exu_newton_rtol:g} atol {args.exu_newton_atol:g}, solvers {' '.join(args.exu_solver)}; "
          f"{args.repeats} interleaved rounds; error = max |tip deflection "
          f"across the root frame - jointplay at rtol {REFERENCE_RTOL:g}| on the 0.02 s grid")
    if exudyn is None:
        print(f"Exudyn rows: skipped, {EXUDYN_MISSING}")
    closed = RHO_A * FINAL_RATE ** 2 * LENGTH ** 3 / (3 * AXIAL)
    for n in args.elements:
        reference = (jointplay_runner(n, args.t_end, REFERENCE_RTOL)() if args.reference_step is None else
                     jointplay_runner(n, args.t_end, REFERENCE_RTOL, step=args.reference_step)())
        engine = timing.Case(f"jointplay generalized-alpha, {n} linear elements",
                             jointplay_runner(n, args.t_end, args.jp_rtol, args.jacobian, step=jp_step))
        ndf = timing.Case(f"jointplay NDF, {n} linear elements",
                          jointplay_runner(n, args.t_end, args.jp_rtol, args.jacobian))
        cases = [engine] if args.no_ndf else [engine, ndf]
        peers = []
        if exudyn is not None:
            peers = [timing.Case(f"Exudyn {solver}, {n} linear elements",
                                 exudyn_runner(n, args.t_end, steps, args.exu_newton_rtol, args.exu_newton_atol, solver))
                     for solver in args.exu_solver]
        timing.interleave(cases + peers, args.repeats)
        # the comparison is against Exudyn's fastest solver on this mesh (median CPU time)
        working = [c for c in peers if not c.last[3].get("failed")]
        peer = min(working, key=lambda c: timing.Spread.of(c.values("cpu")).median) if working else None
        for case in cases + peers:
            s = case.last[3]
            work = (f"{s['accepted_steps']} steps, {s['rhs_evaluations']} rhs, {s['jacobian_evaluations']} jacobians "
                    f"({s['jacobian_force_evaluations']} force evaluations), {s['factorizations']} factorizations "
                    f"({s.get('sparse_factorizations', 0)} sparse)"
                    if case not in peers else
                    ("FAILED (SolveDynamic terminated)" if s.get("failed") else
                     f"{s['steps']} steps, {s['newton_iterations']} Newton iterations, {s['jacobians']} jacobians"))
            steps_taken = s["accepted_steps"] if case not in peers else s["steps"]
            evaluations = s["rhs_evaluations"] if case not in peers else s["newton_iterations"]
            row = {"name": case.name, "elements": n, "cpu": timing.Spread.of(case.values("cpu")),
                   "steps": steps_taken, "evaluations": evaluations, "peer": case in peers,
                   "wall": timing.Spread.of(case.values("wall")), "error": tip_error(case.last, reference),
                   "stretch": stretch(case.last), "work": work, "ratio_cpu": None, "ratio_wall": None}
            if peer is not None and case not in peers:
                row["ratio_cpu"], row["ratio_wall"] = timing.ratio(peer, case, "cpu"), timing.ratio(peer, case, "wall")
            rows.append(row)
        print(f"{n} elements done", flush=True)
        if peer is not None:
            for clock in ("cpu", "wall"):
                s = timing.ratio(peer, engine, clock)
                verdicts.append((n, clock, s))
    if args.markdown:
        print("\n| case | CPU time [s] median [min-max] | wall time [s] median [min-max] | tip error [mm] "
              "| stretch [mm] | Exudyn / jointplay, CPU [min-max] | wall [min-max] | work |")
        print("|---|---:|---:|---:|---:|---:|---:|---|")
    for r in rows:
        ratios = ["-" if s is None else f"{s.median:.3g}x [{s.low:.3g}-{s.high:.3g}]"
                  for s in (r["ratio_cpu"], r["ratio_wall"])]
        cells = (r["name"], f"{r['cpu'].median:.3g} [{r['cpu'].low:.3g}-{r['cpu'].high:.3g}]",
                 f"{r['wall'].median:.3g} [{r['wall'].low:.3g}-{r['wall'].high:.3g}]", f"{1e3 * r['error']:.3g}",
                 f"{1e3 * r['stretch']:.4g}", *ratios, r["work"])
        if args.markdown:
            print("| " + " | ".join(cells) + " |")
        else:
            print(f"{cells[0]:<28} CPU {cells[1]:>22} s  wall {cells[2]:>22} s  error {cells[3]:>7} mm  "
                  f"stretch {cells[4]:>7} mm  Exudyn/jointplay CPU {cells[5]}, wall {cells[6]}; {cells[7]}")
    print_exponents(rows)
    print(f"closed-form stretch at 6 rad/s: {1e3 * closed:.4g} mm (a run shorter than 17 s has not reached it)")
    for n, clock, s in verdicts:
        for label, target in (("goal, generalized-alpha faster than Exudyn", 1.0), ("stretch, 10x faster", 10.0)):
            every = "in every round" if s.low >= target else ("in no round" if s.high < target else "in some rounds")
            print(f"{label}, {n} elements, {clock.upper()} time, median of per-round ratios: "
                  f"{timing.verdict(s.median, '>=', target)} {s.median:.3g}x (extremes {s.low:.3g}x-{s.high:.3g}x, "
                  f"met {every})")
    return {"rows": rows, "verdicts": verdicts, "exudyn": None if exudyn is None else exudyn.__version__}


if __name__ == "__main__":
    main()
