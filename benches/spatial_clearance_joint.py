"""Benchmark: the spatial clearance joint's cost per evaluation against the planar clearance joint's.

The dry Flores slider-crank (``examples/flores_slider_crank_dry.toml``: crank 50 mm, rod 120 mm at
5000 rpm, bore 10 mm, clearance 0.5 mm, length 40 mm, steel on steel, Lankarani-Nikravesh, Ambrosio
friction) in three builds, the core tests' twins (``crates/jointplay-core/src/dynamics/
spatial_clearance_tests.rs``, ``spatial_twin`` and ``spatial_joint_twin``) written as JSON specs here:

(a) the planar model with the planar clearance joint (``clearance_revolute``);
(b) the spatial twin with the planar clearance joint: spatial bodies in the plane z = 0, spatial
    revolute joints about z, a spatial translational guide along x (out-of-plane inertias 1 % and
    100 % of the planar one);
(c) the spatial twin with the spatial clearance joint (``spatial_clearance_revolute``, same bore,
    clearance, length, materials, laws and friction; axial clearance 1 mm, flange 15 mm, face 16 mm)
    in place of the planar one, every body with equal principal inertias (the redundant equations
    of the spatial loop are solved at assembly only when the inertias are within about two orders
    of magnitude: docs/theory/spatial-clearance-revolute.md, "Limits").

With aligned axes (the mechanism keeps them aligned) the spatial joint's slices sum to the planar
joint's law, so (b) and (c) follow the same motion (the core test above checks onset, peak and
contact fraction of the first impacts); the run here checks that they made the same impacts (peak
normal force within 1e-3) before reporting a cost.

Every case runs 0..5 ms (the first impacts and the contact after them), Dormand-Prince at the
example's tolerances (rtol 1e-6, atol 1e-9, max step 0.1 ms), samples at the accepted steps, in
absolute coordinates (the only formulation of a spatial model); (a) once more in joint coordinates,
the planar engine's default for this tree, as a note. The cost of an evaluation is the run's CPU
time over ``statistics["rhs_evaluations"]``, the integrator's and the event location's (the brief
of the benchmark); beside it, as the scaling benchmark counts (``benches/bench_scaling.py``), over those
and the summary's peak search's (``extrema["inner_evaluations"]``, which evaluate the model at the
samples between steps where a peak is sought and which the integrator does not count). The joint's
cost on the same spatial mechanism is (c)/(b), against the planar model (c)/(a), each as the median
of the per-round ratios of the costs per evaluation with their extremes (``benches/timing.py``). The
goal (3x) is met only when the largest round meets it.

Where the time goes (``--where``): the same builds at a largest step of 1 us, so that evaluations,
not the start of a run, make the cost: over the first 0.2 ms, before the first impact (0.23 ms), where
the journal flies free in the bore and no candidate is in contact, against 0..5 ms (in contact about a
fifth of the time; at the example's adaptive steps the contacts hold three fifths of the steps); and a
run over 1 us, the fixed cost of a run (assembly, setup, results). The free window's (c)/(b) is the
joint's free-flight cost (its candidates' gaps, event functions and channels); what the 5 ms window
adds to it is what contact costs.

Run: python benches/spatial_clearance_joint.py [--rounds N] [--t-end S] [--where] [--output PATH]
(``--output results.json`` also writes ``results.md`` beside it, the Markdown tables).
"""

from __future__ import annotations

import argparse
import copy
import json
import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "benches")]

import jointplay as jp  # noqa: E402
import timing  # noqa: E402

#: The goal of the spatial joint's cost per evaluation over the planar joint's (issue 36).
GOAL = 3.0
MODEL_FILE = ROOT / "examples" / "flores_slider_crank_dry.toml"
#: The example's integrator settings; ``formulation`` set per case.
SETTINGS = {"method": "dopri5", "rtol": 1e-6, "atol": 1e-9, "max_step": 1e-4}
#: Simulated window [s]: the first impacts and the contact after them.
T_END = 5e-3
#: Window before the first impact (0.23 ms) [s]: the journal flies free.
FREE_T_END = 2e-4
#: Largest step of the ``--where`` windows [s]: the evaluations outweigh a run's fixed cost.
WHERE_MAX_STEP = 1e-6
#: A window of a single step [s]: a run's fixed cost.
FIXED_T_END = 1e-6
#: Largest relative difference of the peak normal force over the window between (b) and (c).
SAME_MOTION = 1e-3
#: Marker axes whose z is the global x (columns: x -> global y, y -> global z, z -> global x).
AXES_ALONG_X = [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]


# -- the three builds ------------------------------------------------------------------------------

def planar_spec() -> dict:
    """The spec of the example (a)."""
    return jp.load(MODEL_FILE).to_spec()


def in_space(v) -> list[float]:
    return [v[0], v[1], 0.0]


def spatial_twin(planar: dict) -> dict:
    """(b): ``planar`` (rigid bodies at angle 0, revolute joints, a guide along x, a clearance joint and a
    driver) from spatial bodies in the plane z = 0; the clearance joint and the driver as they are."""
    spec = copy.deepcopy(planar)
    spec["gravity"] = in_space(planar["gravity"])
    spec["ground_points"] = [{"name": p["name"], "position": in_space(p["position"]),
                              "axes": AXES_ALONG_X if p["name"] == "line" else None} for p in planar["ground_points"]]
    bodies = []
    for b in planar["bodies"]:
        assert b["angle"] == 0.0, "the twin turns no body"
        i = b["inertia"]
        points = [{"name": p["name"], "position": in_space(p["position"]),
                   "axes": AXES_ALONG_X if b["name"] == "slider" else None} for p in b["points"]]
        bodies.append({"name": b["name"], "mass": b["mass"], "inertia": [[i / 100, 0, 0], [0, i, 0], [0, 0, i]],
                       "position": in_space(b["position"]), "orientation": [1.0, 0.0, 0.0, 0.0],
                       "velocity": in_space(b["velocity"]), "angular_velocity": [0.0, 0.0, b["angular_velocity"]],
                       "points": points, "euler_sequence": "zyx"})
    spec["spatial_bodies"], spec["bodies"] = bodies, []
    ideal = [{k: j[k] for k in ("type", "name", "first", "second")} for j in planar["joints"]
             if j["type"] in ("revolute", "translational")]
    spec["spatial_joints"] = ideal
    spec["joints"] = [j for j in planar["joints"] if j["type"] == "clearance_revolute"]
    spec["spatial_forces"] = []
    return spec


def spatial_joint_twin(planar: dict) -> dict:
    """(c): the twin (b) with equal principal inertias and the spatial clearance joint in the planar one's
    place, its bore marker at the slider's point B with the slider's axes (z along global z)."""
    spec = spatial_twin(planar)
    for body in spec["spatial_bodies"]:
        body["inertia"][0][0] = body["inertia"][1][1]
    (joint,) = spec["joints"]
    assert joint["bearing"] == "slider.B", "the twin's bearing is the slider's point B"
    slider = next(b for b in spec["spatial_bodies"] if b["name"] == "slider")
    at = next(p for p in slider["points"] if p["name"] == "B")["position"]
    slider["points"].append({"name": "bore", "position": list(at)})
    spec["joints"] = []
    spec["spatial_clearance_joints"] = [{
        "type": "spatial_clearance_revolute", "name": joint["name"], "bearing": "slider.bore",
        "journal": joint["journal"], "bore_radius": joint["bearing_radius"], "clearance": joint["clearance"],
        "bearing_length": joint["length"], "axial_clearance": 1e-3, "flange_radius": 0.015, "face_radius": 0.016,
        "bearing_material": joint["bearing_material"], "journal_material": joint["journal_material"],
        "contact": joint["contact"], "stiffness": joint["stiffness"], "axial_stiffness": None,
        "friction": joint["friction"], "lock_at_assembly": True, "onset_velocity_floor": joint["onset_velocity_floor"],
        "max_penetration": None, "mode_impact_speed": 1e-3, "mode_impact_duration": 1e-3, "mode_sliding_speed": 5e-5}]
    return spec


def builds() -> dict[str, dict]:
    planar = planar_spec()
    return {"a": planar, "b": spatial_twin(planar), "c": spatial_joint_twin(planar)}


#: (label, build, formulation) of each case; (a) in joint coordinates is a note, not a term of the ratios.
CASES = [("(a) planar model, planar joint", "a", "absolute"),
         ("(b) spatial twin, planar joint", "b", "absolute"),
         ("(c) spatial twin, spatial joint", "c", "absolute"),
         ("(a') planar model, planar joint, joint coordinates", "a", "auto")]


def runner(spec: dict, t_end: float, formulation: str, max_step: float):
    """A function running the compiled model once over ``t_end`` [s] at the largest step ``max_step`` [s];
    returns its results."""
    model = jp.Model.from_spec(spec)
    model.compile()
    settings = {**SETTINGS, "max_step": max_step}
    return lambda: model.simulate(t_end, formulation=formulation, **settings)


def normal_force(results: jp.Results, build: str):
    """The joint's normal force [N]: the planar joint's, or the sum over the spatial joint's bore halves."""
    return results["B.fn_a"] + results["B.fn_b"] if build == "c" else results["B.fn"]


# -- measuring -------------------------------------------------------------------------------------

def per_evaluation(case: timing.Case, evaluations: int, clock: str) -> list[float | None]:
    """The round-by-round cost per evaluation [s] on ``clock`` (every run of a case makes the same steps)."""
    times = case.cpus if clock == "cpu" else case.walls
    return [None if t is None else t / evaluations for t in times]


def ratios_of_costs(num: list, den: list) -> list[float]:
    """The per-round ratios of two cases' costs, over the rounds in which both ran."""
    return [a / b for a, b in zip(num, den) if a is not None and b is not None]


def measure(t_end: float, rounds: int, max_step: float = SETTINGS["max_step"]) -> dict:
    """Times the cases of ``CASES`` over ``t_end`` [s] in ``rounds`` interleaved rounds; rows and ratios."""
    specs = builds()
    cases = [timing.Case(label, runner(specs[build], t_end, formulation, max_step))
             for label, build, formulation in CASES]
    for case in cases:  # a first run of each, left out of the table: caches warm
        case.time_once()
    for case in cases:
        case.walls.clear()
        case.cpus.clear()
    timing.interleave(cases, rounds)
    rows, costs = [], {}
    for (label, build, formulation), case in zip(CASES, cases):
        stats = case.last.statistics
        n, peak_search = stats["rhs_evaluations"], (case.last.extrema or {}).get("inner_evaluations", 0)
        costs[label] = {clock: per_evaluation(case, n, clock) for clock in ("cpu", "wall")}
        costs[label]["cpu, all"] = per_evaluation(case, n + peak_search, "cpu")
        force = normal_force(case.last, build)
        rows.append({"case": label, "formulation": stats["formulation"],
                     "cpu_ms": timing.Spread.of(case.values("cpu")), "wall_ms": timing.Spread.of(case.values("wall")),
                     "steps": stats["accepted_steps"], "rejected": stats["rejected_steps"], "evaluations": n,
                     "peak_search_evaluations": peak_search,
                     "cpu_per_evaluation": timing.Spread.of(costs[label]["cpu"]),
                     "wall_per_evaluation": timing.Spread.of(costs[label]["wall"]),
                     "cpu_per_evaluation_all": timing.Spread.of(costs[label]["cpu, all"]),
                     "peak_force": float(force.max()), "contact_fraction": float((force > 0).mean())})
    a, b, c = (costs[label] for label, *_ in CASES[:3])
    per_round = {f"{name} {clock}": ratios_of_costs(num[clock], den[clock])
                 for name, num, den in (("(c)/(b)", c, b), ("(c)/(a)", c, a), ("(b)/(a)", b, a))
                 for clock in ("cpu", "wall", "cpu, all")}
    return {"t_end": t_end, "max_step": max_step, "rounds": rounds, "rows": rows, "per_round": per_round,
            "ratios": {key: timing.Spread.of(values) for key, values in per_round.items()}}


def check_same_motion(result: dict) -> str:
    """(b) and (c) made the same impacts: their peak normal forces agree within ``SAME_MOTION``."""
    rows = {row["case"][:3]: row for row in result["rows"]}
    fb, fc = rows["(b)"]["peak_force"], rows["(c)"]["peak_force"]
    if fb == 0.0 and fc == 0.0:
        return "no contact in the window in (b) nor (c)"
    if abs(fc - fb) > SAME_MOTION * max(fb, fc):
        raise SystemExit(f"(b) and (c) did not make the same impacts: peak normal force {fb} N against {fc} N")
    return f"peak normal force (b) {fb:.1f} N, (c) {fc:.1f} N"


# -- reporting -------------------------------------------------------------------------------------

def us(s: timing.Spread) -> str:
    return f"{1e6 * s.median:.2f} [{1e6 * s.low:.2f}-{1e6 * s.high:.2f}]"


def ms(s: timing.Spread) -> str:
    return f"{1e3 * s.median:.3g} [{1e3 * s.low:.3g}-{1e3 * s.high:.3g}]"


def x(s: timing.Spread) -> str:
    return f"{s.median:.2f} [{s.low:.2f}-{s.high:.2f}]"


def markdown(result: dict) -> str:
    lines = [f"Window 0-{1e3 * result['t_end']:g} ms, largest step {1e6 * result['max_step']:g} us, {result['rounds']} "
             "interleaved rounds; median [min-max].", "",
             "| case | formulation | CPU [ms] | wall [ms] | steps (rejected) | evaluations | peak-search evaluations "
             "| CPU / evaluation [us] | wall / evaluation [us] | CPU / (evaluation + peak-search evaluation) [us] "
             "| contact fraction of steps | peak normal force [N] |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in result["rows"]:
        lines.append(f"| {r['case']} | {r['formulation']} | {ms(r['cpu_ms'])} | {ms(r['wall_ms'])} | "
                     f"{r['steps']} ({r['rejected']}) | {r['evaluations']} | {r['peak_search_evaluations']} | "
                     f"{us(r['cpu_per_evaluation'])} | {us(r['wall_per_evaluation'])} | "
                     f"{us(r['cpu_per_evaluation_all'])} | {r['contact_fraction']:.2f} | {r['peak_force']:.1f} |")
    lines += ["", "| ratio of the cost per evaluation, per round | CPU | wall | CPU, peak search counted |",
              "|---|---:|---:|---:|"]
    for name in ("(c)/(b)", "(c)/(a)", "(b)/(a)"):
        cells = " | ".join(x(result["ratios"][f"{name} {clock}"]) for clock in ("cpu", "wall", "cpu, all"))
        lines.append(f"| {name} | {cells} |")
    return "\n".join(lines)


def verdicts(result: dict) -> list[str]:
    """The goal (at most ``GOAL``) on the CPU ratios: met only when every round meets it."""
    out = []
    for name in ("(c)/(b)", "(c)/(a)"):
        s = result["ratios"][f"{name} cpu"]
        ratios = result["per_round"][f"{name} cpu"]
        met = sum(v <= GOAL for v in ratios)
        state = "met in every round" if met == len(ratios) else f"MISSED (met in {met} of {len(ratios)} rounds)"
        out.append(f"goal: at most {GOAL:g}x per evaluation, {name}, CPU: {state}; {x(s)}")
    return out


def plain(value):
    """``value`` with every Spread as a dict, for JSON."""
    if isinstance(value, timing.Spread):
        return {"median": value.median, "min": value.low, "max": value.high, "q1": value.q1, "q3": value.q3,
                "n": value.n}
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, list):
        return [plain(v) for v in value]
    return value


def main(argv: list[str] | None = None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=15, help="interleaved rounds (every case once per round)")
    parser.add_argument("--t-end", type=float, default=T_END, help="simulated window [s]")
    parser.add_argument("--where", action="store_true",
                        help="also the windows at a largest step of 1 us: free flight, contact, a single step")
    parser.add_argument("--output", type=Path, help="JSON file of the results (and the Markdown beside it)")
    args = parser.parse_args(argv)
    load = os.getloadavg()
    report = {"load_average_before": load, "cores": os.cpu_count(), "windows": []}
    windows = [(args.t_end, SETTINGS["max_step"])]
    if args.where:
        windows += [(FREE_T_END, WHERE_MAX_STEP), (args.t_end, WHERE_MAX_STEP), (FIXED_T_END, WHERE_MAX_STEP)]
    text = [f"dry Flores slider-crank, Dormand-Prince rtol {SETTINGS['rtol']:g} atol {SETTINGS['atol']:g}; "
            f"{os.cpu_count()} cores, load average before {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}"]
    for k, (t_end, max_step) in enumerate(windows):
        result = measure(t_end, args.rounds, max_step)
        text += ["", markdown(result), "", check_same_motion(result)]
        if k == 0:
            text += verdicts(result)
        report["windows"].append(result)
    load = os.getloadavg()
    report["load_average_after"] = load
    text.append(f"load average after {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    print("\n".join(text))
    if args.output is not None:
        args.output.write_text(json.dumps(plain(report), indent=1))
        args.output.with_suffix(".md").write_text("\n".join(text) + "\n")
    return report


if __name__ == "__main__":
    main()
