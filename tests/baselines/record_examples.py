"""Records what every example computes before the engine rework, in examples_before_rework.json.

Run from the repository root:  .venv/bin/python tests/baselines/record_examples.py
It rewrites tests/baselines/examples_before_rework.json (about a minute: each case is also run
16 more times, disturbed, see "Spread" below); it refuses (unless given --force) when the engine
sources (crates/, python/jointplay/) differ from the recorded commit's, because the record is of that
engine. tests/test_examples_vs_baseline.py recomputes the
same quantities with :func:`measure` and compares them with the record.

Cases: the four model files of examples/ that existed at the recorded commit, each run with its own
[simulation] table, and the models the Python examples simulate, with the options their scripts use
(:func:`cases`). Examples added later are not in this record: the parallelogram four-bars (today's
engine stops on them) and the hydraulic boom (today's engine has no hydraulic cylinder; the boom is
checked against its own expectations in tests/test_examples.py). Per case:

- ``peaks``: the peak (largest |value|) and its time of every channel the core tracks at every
  accepted step (``Results.extrema``), and ``point_accelerations``, the peak acceleration
  magnitude of every named body point;
- per clearance joint (``clearance_joints``): the number of impacts, the fraction of the run in
  contact, for a lubricated joint the thinnest film (all from ``Results.extrema``), and for a joint
  that touches, ``first_impact``: the onset time of the first contact (its first contact sample:
  the core locates an onset on the dense output and ends a step there) and the time and value of
  the first local maximum of ``<joint>.fn`` after it.

How the first local maximum is found: in the run sampled at every accepted step, walk from the
onset sample while ``fn`` grows; the maximum lies in the step before or after the last growing
sample. A second run to the end of that bracket then gives the largest ``fn`` of its whole span from
its ``extrema``, which the core finds inside every step on the dense output; ``fn`` is zero before
the first onset, so that is the first local maximum. Cutting the run changes only its last step,
which is shortened to end at the bracket's end. (On the Flores dry run it agrees with the largest
of samples every 0.1 us to 1.5e-6.)

Output sampling: every run here samples at every accepted step (``output_step`` dropped). A regular
output grid does not change the steps or the tracked extrema (``sampling_independent``: True for
each case that has a grid), except with the finite-difference Reynolds film of
``paper000_joint_models.py:hydrodynamic``: its solver starts each solution from the previous one,
so the extra evaluations at output samples move its peak film pressure by 0.3 % (today's engine).

Spread: chaotic free flight in a dry clearance makes the statistics after the first impacts depend
on the last bits of the input and on the integration error (docs/getting-started.md, "Which
numbers to trust in a dry clearance joint"). Each case is run again 16 times, disturbed: every
body's initial position scaled by 1 +- 1e-15, 1e-14, ..., 1e-9 (14 runs), and rtol halved and
doubled (2 runs, as a reworked engine changes the integration error). ``spread`` holds, for every
compared quantity, the largest deviation of those runs from the undisturbed one: relative for
continuous quantities (absolute where the recorded value is 0), absolute for impact counts.
The test derives its tolerances from it.
"""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
BASELINE = Path(__file__).with_name("examples_before_rework.json")
RECORDED_AT = "8193766"  # the commit of main the baseline was recorded at (before the engine rework)

if str(EXAMPLES) not in sys.path:
    sys.path.insert(0, str(EXAMPLES))

import jointplay as jp  # noqa: E402

#: The model files and Python examples of examples/ at the recorded commit.
MODEL_FILES = ("flores_slider_crank_dry", "flores_slider_crank_ideal", "flores_slider_crank_lubricated",
               "paper001_slider_crank_dry")
SCRIPTS = ("flores_slider_crank_dry", "flores_slider_crank_ideal", "flores_slider_crank_lubricated",
           "paper001_slider_crank_dry", "paper001_parametric_study", "paper000_joint_models")

#: Disturbances of the spread estimate: relative scalings of the initial positions, factors on rtol.
POSITION_SCALINGS = tuple(s * 10.0**-k for k in range(15, 8, -1) for s in (1, -1))
RTOL_FACTORS = (0.5, 2.0)

Case = Callable[[], tuple[jp.Model, float, dict]]


def _from_file(stem: str) -> Case:
    def build():
        model = jp.load(EXAMPLES / f"{stem}.toml")
        options = dict(model.simulation)
        return model, options.pop("t_end"), options
    return build


def _flores_dry_script():
    import flores_slider_crank_dry as ex
    # ex.main: ex.simulate with its defaults, two revolutions
    return ex.build_model(), ex.revolutions_to_time(2.0), {"rtol": 1e-6, "atol": 1e-9, "max_step": 1e-4}


def _flores_ideal_script():
    import flores_slider_crank_ideal as ex
    from flores_slider_crank_dry import revolutions_to_time
    return ex.build_ideal_model(), revolutions_to_time(2.0), {"rtol": 1e-8, "atol": 1e-11,
                                                               "output_step": revolutions_to_time(1.0) / 720}


def _flores_lubricated_script():
    import flores_slider_crank_lubricated as ex
    from flores_slider_crank_dry import revolutions_to_time
    # ex.compare's lubricated run (its dry run is the dry script's); recorded at rtol 1e-6, atol 1e-9,
    # compared since the joint-coordinate formulation at the example's 3e-7, 3e-10 (the model file says why)
    return ex.build_model(), revolutions_to_time(2.0), {**ex.LUBRICATED_TOLERANCES, "max_step": 1e-4,
                                                        "method": ex.LUBRICATED_METHOD,
                                                        "output_step": revolutions_to_time(1.0) / 720}


def _paper001_dry_script():
    import paper001_slider_crank_dry as ex
    t_end = 2 * 2 * np.pi / ex.CRANK_SPEED  # two revolutions, as ex.main
    return ex.build_model(0.5e-3), t_end, {"method": "adams", "rtol": 1e-8, "atol": 1e-11, "max_step": 1e-4,
                                           "output_step": t_end / 2000}


def _paper001_study_case(case) -> Case:
    def build():
        import paper001_parametric_study as ex
        t_end = 2 * 60.0 / case.speed_rpm  # ex.run_case: two revolutions
        return ex.build_model(case), t_end, {"rtol": 1e-7, "atol": 1e-10, "max_step": 1e-4,
                                             "output_step": t_end / 1440}
    return build


def _paper000_case(joint: str) -> Case:
    def build():
        import paper000_joint_models as ex
        # ex.simulate, to the example's own end time ex.T_END (7 ms)
        return ex.build_model(joint, "rigid"), ex.T_END, {"rtol": 1e-6, "atol": 1e-10, "max_step": 2e-6, "output_step": 1e-6}
    return build


def cases() -> dict[str, Case]:
    """Case name -> function returning (model, t_end [s], simulate options)."""
    out: dict[str, Case] = {f"{stem}.toml": _from_file(stem) for stem in MODEL_FILES}
    out["flores_slider_crank_dry.py"] = _flores_dry_script
    out["flores_slider_crank_ideal.py"] = _flores_ideal_script
    out["flores_slider_crank_lubricated.py"] = _flores_lubricated_script
    out["paper001_slider_crank_dry.py"] = _paper001_dry_script
    import paper001_parametric_study as study
    distinct = []
    for series in study.SERIES.values():
        distinct += [c for c in series if c not in distinct]
    for c in distinct:
        name = f"paper001_parametric_study.py:c{c.clearance * 1e3:g}mm_{c.speed_rpm:g}rpm_{c.viscosity_cp:g}cP"
        out[name] = _paper001_study_case(c)
    import paper000_joint_models as p0
    for joint in p0.JOINT_MODELS:
        out[f"paper000_joint_models.py:{joint}"] = _paper000_case(joint)
    return out


def simulate(model: jp.Model, t_end: float, options: dict) -> jp.Results:
    """Runs ``model`` to ``t_end`` with ``options``, sampled at every accepted step."""
    return model.simulate(t_end, **{k: v for k, v in options.items() if k != "output_step"})


def first_impact(model: jp.Model, options: dict, results: jp.Results, joint: str) -> dict | None:
    """Onset [s] of the first contact of ``joint`` and the time [s] and value [N] of the first local
    maximum of ``<joint>.fn`` after it (see the module docstring); None if it never touches."""
    t, fn, contact = results.time, results[f"{joint}.fn"], results[f"{joint}.contact"] > 0.5
    if not contact.any():
        return None
    k = onset = int(np.argmax(contact))
    while k + 1 < t.size and fn[k + 1] >= fn[k]:
        k += 1
    if k + 1 >= t.size:
        raise RuntimeError(f"{joint}: fn still growing at the end of the run")
    cut = simulate(model, float(t[k + 1]), options)
    peak = cut.extrema["channels"][f"{joint}.fn"]
    if not t[max(k - 1, onset)] <= peak["time"] <= t[k + 1]:
        raise RuntimeError(f"{joint}: first peak at {peak['time']} s outside its bracket [{t[k - 1]}, {t[k + 1]}] s")
    return {"onset_time": float(t[onset]), "peak_time": float(peak["time"]), "peak": float(peak["peak"])}


def measure_model(model: jp.Model, t_end: float, options: dict) -> dict:
    """The recorded quantities of one run of ``model`` to ``t_end`` [s] with ``options``."""
    results = simulate(model, t_end, options)
    if results.error is not None:
        raise RuntimeError(f"{model.name}: {results.error}")
    extrema = results.extrema
    record = {
        "peaks": {n: {"peak": float(c["peak"]), "time": float(c["time"]), "unit": c["unit"]}
                  for n, c in extrema["channels"].items()},
        "point_accelerations": {n: {"peak": float(p["peak"]), "time": float(p["time"])}
                                for n, p in extrema["point_accelerations"].items()},
        "clearance_joints": {},
    }
    for joint, stats in extrema["clearance_joints"].items():
        entry = {"impacts": int(stats["impacts"]), "contact_fraction": float(stats["contact_fraction"]),
                 "first_impact": first_impact(model, options, results, joint)}
        if "min_film" in stats:
            entry["min_film"] = float(stats["min_film"])
            entry["min_film_time"] = float(stats["min_film_time"])
        record["clearance_joints"][joint] = entry
    return record


def measure(name: str) -> dict:
    """The recorded quantities of the case ``name``."""
    model, t_end, options = cases()[name]()
    return measure_model(model, t_end, options)


def compared(record: dict) -> dict[str, float | int | None]:
    """The quantities the test compares, by path (``peaks/B.fn``, ``clearance_joints/B/impacts``...).
    Peak times are left out (a smooth maximum's time is ill-conditioned; a periodic run has equal
    peaks in each revolution), except the first impact's."""
    out: dict[str, float | int | None] = {}
    for section in ("peaks", "point_accelerations"):
        for name, peak in record[section].items():
            out[f"{section}/{name}"] = peak["peak"]
    for joint, stats in record["clearance_joints"].items():
        for key in ("impacts", "contact_fraction", "min_film"):
            if key in stats:
                out[f"clearance_joints/{joint}/{key}"] = stats[key]
        first = stats["first_impact"]
        for key in ("onset_time", "peak_time", "peak"):
            out[f"clearance_joints/{joint}/first_impact/{key}"] = None if first is None else first[key]
    return out


def deviation(path: str, value, base) -> float:
    """How far ``value`` is from ``base``: absolute for impact counts and where ``base`` is 0,
    relative otherwise; inf if one is missing."""
    if value is None or base is None:
        return 0.0 if value is base else float("inf")
    if path.endswith("/impacts") or base == 0:
        return float(abs(value - base))
    return float(abs(value / base - 1.0))


def disturbed(model: jp.Model, scaling: float) -> jp.Model:
    """``model`` with every body's initial position scaled by ``1 + scaling``."""
    spec = model.to_spec()
    for body in spec["bodies"]:
        body["position"] = [p * (1.0 + scaling) for p in body["position"]]
    return jp.Model.from_spec(spec)


def spread(name: str, base: dict) -> dict[str, float]:
    """Largest deviation of each compared quantity over the disturbed runs of a case."""
    model, t_end, options = cases()[name]()
    runs = [measure_model(disturbed(model, s), t_end, options) for s in POSITION_SCALINGS]
    runs += [measure_model(model, t_end, {**options, "rtol": options["rtol"] * f}) for f in RTOL_FACTORS]
    reference = compared(base)
    return {path: max(deviation(path, compared(run).get(path), value) for run in runs)
            for path, value in reference.items()}


def sampling_independent(name: str, base: dict) -> bool | None:
    """Whether the case's own output grid leaves the tracked extrema as recorded (None: no grid)."""
    model, t_end, options = cases()[name]()
    if not options.get("output_step"):
        return None
    return model.simulate(t_end, **options).extrema == simulate(model, t_end, options).extrema


def git_commit() -> str:
    try:
        return subprocess.run(["git", "rev-parse", "--short=7", "HEAD"], cwd=ROOT, capture_output=True,
                              text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def record() -> dict:
    out = {
        "recorded_at_commit": RECORDED_AT,
        "recorded_from_checkout": git_commit(),
        "jointplay_version": jp.__version__,
        "about": "What each example computed before the engine rework. How each quantity is measured and what "
                 "'spread' is: tests/baselines/record_examples.py; tolerances: tests/test_examples_vs_baseline.py.",
        "cases": {},
    }
    for name, build in cases().items():
        _, t_end, options = build()
        base = measure(name)
        out["cases"][name] = {"t_end": float(t_end), "options": {k: v for k, v in options.items() if k != "output_step"},
                              "sampling_independent": sampling_independent(name, base), **base,
                              "spread": spread(name, base)}
        print(f"  {name}: {summary_line(out['cases'][name])}", flush=True)
    return out


def summary_line(case: dict) -> str:
    joints = ", ".join(
        f"{j}: {s['impacts']} impacts, contact {s['contact_fraction']:.3f}"
        + (f", first peak {s['first_impact']['peak']:.6g} N at {s['first_impact']['peak_time']:.6g} s"
           if s["first_impact"] else "")
        + (f", min film {s['min_film']:.4g} m" if "min_film" in s else "")
        for j, s in case["clearance_joints"].items())
    return joints or "no clearance joint"


def engine_differs_from_recorded_commit() -> bool | None:
    """Whether the engine (crates/, python/jointplay/) of this checkout differs from the recorded
    commit's; None if git cannot tell."""
    try:
        done = subprocess.run(["git", "diff", "--quiet", RECORDED_AT, "--", "crates", "python/jointplay"], cwd=ROOT,
                              capture_output=True)
    except OSError:
        return None
    return {0: False, 1: True}.get(done.returncode)


if __name__ == "__main__":
    # the record is of the engine before the rework: refuse to rewrite it from another engine
    if engine_differs_from_recorded_commit() is not False and "--force" not in sys.argv[1:]:
        sys.exit(f"the engine here is not (or cannot be shown to be) that of {RECORDED_AT}; the record is of that "
                 "engine. Rerun from a checkout of it, or pass --force to record this one anyway.")
    data = record()
    BASELINE.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
    print(f"wrote {BASELINE.relative_to(ROOT)}: {len(data['cases'])} cases")
