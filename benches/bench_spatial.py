"""Benchmark: spatial mechanisms, jointplay against Exudyn at matched accuracy, and cost against size.

Two models, each run by both codes from the same start:

1. **Haug's spatial slider-crank** (E. J. Haug, Computer-Aided Kinematics and Dynamics of Mechanical
   Systems, 1989; the data of ``tests/spatial_references.py``, ``SPATIAL_SLIDER_CRANK``): crank on a
   revolute joint, rod on a spherical and a universal joint, slider on a translational joint, gravity
   along -z, free motion from the crank pointing up at one turn a second, 0..1 s (more than a turn).
   The error of a run is the largest |slider x - the minimal-coordinate reference| over samples every
   5 ms; the reference (``slider_crank_motion``, Lagrange's equation in the crank angle at rtol 1e-12)
   is independent of both codes.
2. **Spatial chain**: N bars (0.1 m, 0.1 kg, principal inertia 1e-5, 1e-4, 1e-4 kg m^2 about the bar
   axis and across it) on spherical joints, hanging from a ground point, released horizontal along x
   while the whole chain turns about the vertical through the ground point at 2 rad/s (a rigid
   rotation, so the start satisfies the joints), gravity along -z, 0..0.5 s. The error of a run is the
   largest distance of the last bar's centre from a jointplay run at rtol 1e-11 over samples every
   10 ms (Exudyn's error against it falls as its step squared: the ladder below prints it).

Exudyn (``pip install exudyn``, an optional benchmark dependency): ``ObjectRigidBody`` on Euler-parameter
nodes (``CreateRigidBody``), ``CreateRevoluteJoint``, ``CreateSphericalJoint``, ``CreatePrismaticJoint``
and, for the universal joint, ``CreateGenericJoint`` with the rotation about the joint frame's x axis
constrained and its y axis along the slider's cross axis (global z), its z axis along the rod's y axis
(the frame that makes Exudyn's run converge to the reference: measured 2.3e-6 m at 4000 steps);
generalized-alpha at a fixed step (spectral radius 0.9, its default; it has no error-controlled method
for constrained systems). jointplay: Dormand-Prince at rtol (atol = rtol / 100), absolute coordinates
(the only formulation for spatial models).

**Matched accuracy**: before timing, each code climbs its own ladder (jointplay rtol down by sqrt(10),
Exudyn steps up by 2) until its error is at most the stated tolerance; the rung reached is the one
timed, and both errors are printed. Timing (``benches/timing.py``): both codes in this process, compiled
or assembled once, interleaved rounds with the order turned each round; CPU and wall medians with
[min-max]; the ratio Exudyn / jointplay per round (above 1: jointplay faster); the goal (5x) counts as
met in every round only when the least round meets it.

**Cost per evaluation against N**: the scaling benchmark's ``rigid_chain`` (planar, absolute and joint
coordinates) and ``spatial_chain`` series (``benches/bench_scaling.py``) at N = 2 ... 64, one table and
the fitted exponents (``bench_scaling.print_report``).

Run: python benches/bench_spatial.py [--rounds N] [--quick] [--markdown] [--part exudyn scaling]
"""

from __future__ import annotations

import argparse
import sys
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "benches"), str(ROOT / "tests")]

import jointplay as jp  # noqa: E402
import bench_scaling as scaling  # noqa: E402
import timing  # noqa: E402
from bench_spin_up_beam import EXUDYN_MISSING, exudyn  # noqa: E402
from spatial_models import floats, slider_crank_model  # noqa: E402
from spatial_references import SPATIAL_SLIDER_CRANK, slider_crank_bodies, slider_crank_motion  # noqa: E402

#: The 5x goal of the comparison with Exudyn (Exudyn CPU time / jointplay CPU time).
GOAL = 5.0
SLIDER_T_END, SLIDER_SAMPLE = 1.0, 0.005  # s, s
CHAIN_T_END, CHAIN_SAMPLE = 0.5, 0.01  # s, s
#: Bars of the chain compared with Exudyn.
CHAIN_BARS = 8
#: Largest error [m] of the compared channel that both codes must reach (slider crank: 0.01 % of its
#: 105 mm stroke; chain: 0.01 mm on a last bar that moves about 0.5 m).
TOLERANCE = {"slider_crank": 1e-5, "chain": 1e-5}
#: jointplay's rtol of the chain's reference run.
REFERENCE_RTOL = 1e-11
JOINTPLAY_RTOLS = [10.0 ** (-k / 2) for k in range(6, 21)]  # 1e-3 ... 1e-10
EXUDYN_STEPS = [2**k * 100 for k in range(10)]  # 100 ... 51 200 steps over the run
SCALING_SIZES = ([2, 4, 8, 16, 32, 64], [2, 4])  # full, quick


# -- Haug's spatial slider-crank --------------------------------------------------------------------

def slider_crank_jointplay() -> jp.Model:
    """The slider-crank of ``SPATIAL_SLIDER_CRANK`` at its start (crank angle, rate) in jointplay."""
    data = SPATIAL_SLIDER_CRANK
    return slider_crank_model(data["theta0"], data["theta_dot0"], name="spatial_slider_crank_free")


def slider_crank_exudyn(mbs):
    """Builds the same slider-crank in Exudyn's system ``mbs``; returns the slider's body number."""
    data = SPATIAL_SLIDER_CRANK
    start = slider_crank_bodies(data["theta0"], data["theta_dot0"])
    ground = mbs.CreateGround()
    body = {name: exudyn_body(mbs, data[f"{name}_mass"], data[f"{name}_inertia"], s["position"], s["rotation"],
                              s["velocity"], s["angular_velocity"], data["gravity"]) for name, s in start.items()}
    crank_end = start["crank"]["position"] + start["crank"]["rotation"] @ np.array([0.0, 0.5 * data["crank_length"], 0])
    slider = start["slider"]["position"]
    rod_y = start["rod"]["rotation"][:, 1]  # the rod's cross axis, horizontal
    cross = np.asarray(data["universal_slider_axis"], float)  # the slider's cross axis
    universal_frame = np.stack([np.cross(cross, rod_y), cross, rod_y], axis=1)
    mbs.CreateRevoluteJoint(itemNumbers=[ground, body["crank"]], position=data["crank_pivot"], axis=[1, 0, 0])
    mbs.CreateSphericalJoint(itemNumbers=[body["crank"], body["rod"]], position=crank_end)
    mbs.CreateGenericJoint(itemNumbers=[body["slider"], body["rod"]], position=slider,
                           rotationMatrixAxes=universal_frame, constrainedAxes=[1, 1, 1, 1, 0, 0])
    mbs.CreatePrismaticJoint(itemNumbers=[ground, body["slider"]], position=slider, axis=[1, 0, 0])
    return body["slider"]


def slider_crank_error(time, slider_x) -> float:
    """Largest |slider x - reference| [m] at the given times [s]."""
    return float(np.max(np.abs(slider_x - slider_crank_motion(time).slider)))


# -- spatial chain -----------------------------------------------------------------------------------

def chain_exudyn(mbs, bars: int):
    """Builds the spatial chain of ``bench_scaling.spatial_chain`` in Exudyn's ``mbs``; returns the last bar."""
    ground = mbs.CreateGround()
    spin = np.array([0.0, 0.0, scaling.CHAIN_SPIN])
    previous = ground
    for k in range(bars):
        centre = np.array([(k + 0.5) * scaling.BAR_LENGTH, 0.0, 0.0])
        bar = exudyn_body(mbs, scaling.BAR_MASS, scaling.SPATIAL_BAR_INERTIA, centre, np.eye(3), np.cross(spin, centre),
                          spin, scaling.SPATIAL_GRAVITY)
        mbs.CreateSphericalJoint(itemNumbers=[previous, bar], position=[k * scaling.BAR_LENGTH, 0.0, 0.0])
        previous = bar
    return previous


def last_bar(results: jp.Results, bars: int) -> np.ndarray:
    return np.stack([results[f"bar{bars}.{c}"] for c in "xyz"], axis=-1)


def chain_error(time, position, reference) -> float:
    """Largest distance [m] of the last bar's centre from the reference's at the samples both have."""
    ref_time, ref_position = reference
    k = np.rint(time / CHAIN_SAMPLE).astype(int)
    ok = (np.abs(k * CHAIN_SAMPLE - time) < 1e-9) & (k < len(ref_time))
    return float(np.max(np.linalg.norm(position[ok] - ref_position[k[ok]], axis=-1)))


# -- the two codes -----------------------------------------------------------------------------------

def exudyn_body(mbs, mass, principal, position, rotation, velocity, angular_velocity, gravity):
    """An ``ObjectRigidBody`` on an Euler-parameter node; velocities global [m/s, rad/s]."""
    from exudyn.utilities import RigidBodyInertia

    inertia = RigidBodyInertia(mass=float(mass), inertiaTensor=np.diag(floats(principal)))
    return mbs.CreateRigidBody(inertia=inertia, referencePosition=floats(position),
                               referenceRotationMatrix=np.asarray(rotation, float), initialVelocity=floats(velocity),
                               initialAngularVelocity=floats(angular_velocity), gravity=floats(gravity))


def exudyn_runner(build, t_end: float, steps: int, sample: float):
    """Builds and assembles an Exudyn system (``build(mbs)`` returns the body whose position is the channel);
    returns a function that solves it once at ``steps`` fixed generalized-alpha steps and returns
    (time [s], position (n, 3) [m], statistics)."""
    from exudyn import itemInterface as exi

    container = exudyn.SystemContainer()
    mbs = container.AddSystem()
    body = build(mbs)
    sensor = mbs.AddSensor(exi.SensorBody(bodyNumber=body, outputVariableType=exudyn.OutputVariableType.Position,
                                          storeInternal=True, writeToFile=False))
    mbs.Assemble()
    settings = exudyn.SimulationSettings()
    ti = settings.timeIntegration
    ti.endTime, ti.numberOfSteps, ti.verboseMode = t_end, steps, 0
    ti.generalizedAlpha.spectralRadius = 0.9
    settings.solution.file.write = False
    settings.solution.sensors.writePeriod = sample

    def run():
        mbs.SolveDynamic(settings, storeSolver=True)
        it = mbs.sys["dynamicSolver"].it
        data = mbs.GetSensorStoredData(sensor)
        stats = {"steps": int(it.currentStepIndex), "newton_iterations": int(it.newtonStepsCount),
                 "jacobians": int(it.newtonJacobiCount)}
        return data[:, 0], data[:, 1:4], stats
    return run


def jointplay_runner(model: jp.Model, t_end: float, rtol: float, sample: float, channel):
    """A function running the compiled ``model`` once (Dormand-Prince, atol = rtol / 100); returns
    (time [s], channel(results), statistics)."""
    model.compile()

    def run():
        r = model.simulate(t_end, method="dopri5", rtol=rtol, atol=rtol / 100, output_step=sample)
        return r.time, channel(r), {**r.statistics, "inner_evaluations": (r.extrema or {}).get("inner_evaluations", 0)}
    return run


class Comparison:
    """One model in both codes: the calibrated setting of each, its error, and the timed cases."""

    def __init__(self, name: str, tolerance: float):
        self.name, self.tolerance = name, tolerance
        self.ladder: list[tuple[str, str, float]] = []  # (code, setting, error)
        self.cases: dict[str, timing.Case] = {}
        self.settings: dict[str, str] = {}
        self.errors: dict[str, float] = {}

    def calibrate(self, code: str, settings: list, make, error) -> None:
        """Climbs ``settings`` until ``error(make(s)())`` is within the tolerance; keeps that rung's case.
        Raises when no rung reaches it (then the two codes cannot be compared at this accuracy)."""
        for setting in settings:
            run = make(setting)
            err = error(run())
            self.ladder.append((code, f"{setting:g}", err))
            if err <= self.tolerance:
                self.cases[code] = timing.Case(f"{self.name} {code}", run)
                self.settings[code], self.errors[code] = f"{setting:g}", err
                return
        raise RuntimeError(f"{self.name}: {code} does not reach {self.tolerance:g} m on its ladder")


def slider_crank_comparison() -> Comparison:
    comparison = Comparison("slider-crank", TOLERANCE["slider_crank"])
    model = slider_crank_jointplay()
    error = lambda out: slider_crank_error(out[0], out[1])  # noqa: E731
    comparison.calibrate("jointplay", JOINTPLAY_RTOLS,
                         lambda rtol: jointplay_runner(model, SLIDER_T_END, rtol, SLIDER_SAMPLE,
                                                       lambda r: r["slider.x"]), error)
    if exudyn is not None:
        comparison.calibrate("Exudyn", EXUDYN_STEPS,
                             lambda steps: exudyn_runner(slider_crank_exudyn, SLIDER_T_END, steps, SLIDER_SAMPLE),
                             lambda out: slider_crank_error(out[0], out[1][:, 0]))
    return comparison


def chain_comparison(bars: int) -> Comparison:
    comparison = Comparison(f"spatial chain of {bars} bars", TOLERANCE["chain"])
    model = scaling.spatial_chain(bars)
    channel = lambda r: last_bar(r, bars)  # noqa: E731
    time, position, _ = jointplay_runner(model, CHAIN_T_END, REFERENCE_RTOL, CHAIN_SAMPLE, channel)()
    reference = (time, position)
    comparison.calibrate("jointplay", JOINTPLAY_RTOLS,
                         lambda rtol: jointplay_runner(model, CHAIN_T_END, rtol, CHAIN_SAMPLE, channel),
                         lambda out: chain_error(out[0], out[1], reference))
    if exudyn is not None:
        comparison.calibrate("Exudyn", EXUDYN_STEPS,
                             lambda steps: exudyn_runner(lambda mbs: chain_exudyn(mbs, bars), CHAIN_T_END, steps,
                                                         CHAIN_SAMPLE),
                             lambda out: chain_error(out[0], out[1], reference))
    return comparison


def time_rounds(cases: list[timing.Case], rounds: int) -> None:
    """Interleaved rounds, the order turned by one case each round (as ``bench_scaling``)."""
    for case in cases:  # one untimed run each: first-call costs stay out of the rounds
        case.run()
    for k in range(rounds):
        timing.interleave(cases[k % len(cases):] + cases[:k % len(cases)], 1)


def work(code: str, stats: dict) -> str:
    if code == "Exudyn":
        return f"{stats['steps']} steps, {stats['newton_iterations']} Newton iterations, {stats['jacobians']} jacobians"
    return (f"{stats['accepted_steps']} steps, {stats['rhs_evaluations']} rhs evaluations "
            f"+ {stats['inner_evaluations']} of the summary's peak search")


def print_comparisons(comparisons: list[Comparison], rounds: int, markdown: bool) -> list[tuple]:
    """The ladders, the table of timed cases and the verdicts; returns (model, clock, ratio spread)."""
    print(f"\nExudyn {exudyn.__version__ if exudyn else '-'}; {rounds} interleaved round(s); errors against the "
          "reference of each model (see the module doc)")
    for c in comparisons:
        print(f"{c.name} ladder (code, setting, error [m]): "
              + "; ".join(f"{code} {setting} {err:.3g}" for code, setting, err in c.ladder))
    if markdown:
        print("\n| model | code | setting | error [m] | CPU [ms] median [min-max] | wall [ms] median [min-max] "
              "| Exudyn / jointplay CPU [min-max] | wall [min-max] | work |")
        print("|---|---|---|---:|---:|---:|---:|---:|---|")
    verdicts = []
    for c in comparisons:
        ratios = {}
        if {"jointplay", "Exudyn"} <= c.cases.keys():
            ratios = {clock: timing.ratio(c.cases["Exudyn"], c.cases["jointplay"], clock) for clock in ("cpu", "wall")}
            verdicts += [(c.name, clock, s) for clock, s in ratios.items()]
        for code, case in c.cases.items():
            cpu, wall = (timing.Spread.of(case.values(clock)) for clock in ("cpu", "wall"))
            setting = f"rtol {c.settings[code]}" if code == "jointplay" else f"{c.settings[code]} steps"
            cells = [c.name, code, setting, f"{c.errors[code]:.3g}",
                     f"{cpu.median * 1e3:.3g} [{cpu.low * 1e3:.3g}-{cpu.high * 1e3:.3g}]",
                     f"{wall.median * 1e3:.3g} [{wall.low * 1e3:.3g}-{wall.high * 1e3:.3g}]",
                     *(f"{ratios[k].median:.3g}x [{ratios[k].low:.3g}-{ratios[k].high:.3g}]"
                       if ratios and code == "jointplay" else "-" for k in ("cpu", "wall")),
                     work(code, case.last[2])]
            print("| " + " | ".join(cells) + " |" if markdown else "  ".join(cells))
    for name, clock, s in verdicts:
        every = "in every round" if s.low >= GOAL else ("in no round" if s.high < GOAL else "in some rounds")
        print(f"goal, {name}, jointplay {GOAL:g}x faster than Exudyn, {clock.upper()} time: "
              f"{timing.verdict(s.median, '>=', GOAL)} {s.median:.3g}x (extremes {s.low:.3g}x-{s.high:.3g}x, met {every})")
    return verdicts


def scaling_report(sizes: list[int], rounds: int, markdown: bool) -> dict:
    """Cost per evaluation of planar and spatial chains of the same sizes (``bench_scaling``'s series)."""
    report = {"rows": [], "exponents": [], "beam_ratios": [], "formulation_ratios": []}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", jp.JointplayWarning)
        for series in ("rigid_chain", "spatial_chain"):
            rows = scaling.series_rows(series, sizes)
            time_rounds([r.case for r in rows], rounds)
            report["rows"] += rows
            for variant in dict.fromkeys(r.variant for r in rows):
                mine = [r for r in rows if r.variant == variant]
                report["exponents"].append((series, variant, scaling.exponent(mine, False), scaling.exponent(mine, True)))
    scaling.print_report(report, rounds, markdown)
    return report


def main(argv: list[str] | None = None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7, help="interleaved rounds")
    parser.add_argument("--part", nargs="+", default=["exudyn", "scaling"], choices=["exudyn", "scaling"])
    parser.add_argument("--bars", type=int, default=CHAIN_BARS, help="bars of the chain compared with Exudyn")
    parser.add_argument("--quick", action="store_true",
                        help="one round, a 2-bar chain, scaling at N = 2 and 4: checks that it runs")
    parser.add_argument("--markdown", action="store_true", help="print Markdown tables")
    args = parser.parse_args(argv)
    rounds = 1 if args.quick else args.rounds
    report: dict = {"comparisons": [], "verdicts": [], "scaling": None,
                    "exudyn": None if exudyn is None else exudyn.__version__}
    if exudyn is None:
        print(f"Exudyn rows: skipped, {EXUDYN_MISSING}")
    if "exudyn" in args.part:
        comparisons = [slider_crank_comparison(), chain_comparison(2 if args.quick else args.bars)]
        for c in comparisons:
            time_rounds(list(c.cases.values()), rounds)
        report["comparisons"] = comparisons
        report["verdicts"] = print_comparisons(comparisons, rounds, args.markdown)
    if "scaling" in args.part:
        report["scaling"] = scaling_report(SCALING_SIZES[1 if args.quick else 0], rounds, args.markdown)
    return report


if __name__ == "__main__":
    main()
