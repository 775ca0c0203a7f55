"""The formulation option from Python: a tree of ideal joints runs in joint coordinates by default and
gives what the absolute formulation gives (the core's tests compare every channel of a tree with every
kind of joint, `dynamics/formulations/joint_coordinates/tests.rs`); here the Flores dry slider-crank up to and through
its first impact, and the options' errors. The comparisons with the independent SciPy model
(tests/physics/reference_slider_crank.py, test_engine_vs_reference.py) run the default, joint coordinates."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp

ROOT = Path(__file__).resolve().parents[2]
sys.path[:0] = [str(ROOT / "examples"), str(ROOT / "tests" / "physics")]

import flores_slider_crank_dry as flores  # noqa: E402

DRY = ROOT / "examples" / "flores_slider_crank_dry.toml"
IDEAL = ROOT / "examples" / "flores_slider_crank_ideal.toml"


def first_impact(results: jp.Results) -> tuple[float, float]:
    """Time [s] and peak normal force [N] of the first contact period of joint B."""
    contact = results["B.contact"] > 0.5
    start = int(np.argmax(contact))
    end = start + int(np.argmax(~contact[start:]))
    return float(results.time[start]), float(np.max(results["B.fn"][start:end]))


@pytest.fixture(scope="module")
def runs() -> dict[str, jp.Results]:
    t_end = flores.revolutions_to_time(0.5)
    options = dict(rtol=1e-10, atol=1e-13, max_step=1e-5, output_step=1e-6)
    return {f: flores.build_model().simulate(t_end, formulation=f, **options) for f in ("auto", "absolute")}


def test_a_tree_runs_in_joint_coordinates_by_default_and_says_so(runs):
    assert runs["auto"].statistics["formulation"] == "joint_coordinates"
    assert runs["absolute"].statistics["formulation"] == "absolute"
    ideal = jp.load(IDEAL)
    assert ideal.simulate(1e-3, output_step=1e-4).statistics["formulation"] == "absolute"


def test_the_reason_for_the_formulation_is_kept_in_the_results_file(runs, tmp_path):
    # the core's rule says why; a saved and reopened run still says so
    reasons = {f: r.statistics["formulation_reason"] for f, r in runs.items()}
    assert reasons == {"auto": "the ideal joints form a tree of 2 joint coordinates (at most 8), so no constraint "
                               "equation is solved", "absolute": "requested"}
    runs["auto"].save(tmp_path / "run.nc")
    again = jp.open_results(tmp_path / "run.nc")
    assert again.statistics["formulation"] == "joint_coordinates"
    assert again.statistics["formulation_reason"] == reasons["auto"]
    ideal = jp.load(IDEAL).simulate(1e-3, output_step=1e-4).statistics["formulation_reason"]
    assert "closes a loop of ideal joints" in ideal


def test_both_formulations_agree_up_to_the_first_impact(runs):
    # before the first impact the motion is smooth and both runs are converged: positions, the
    # slider's acceleration and the reaction of the guide agree to integration accuracy
    t_impact, _ = first_impact(runs["absolute"])
    before = runs["auto"].time < t_impact - 1e-5
    for name, scale in (("rod.angle", 1.0), ("slider.x", 0.1), ("slider.ax", 1e3), ("guide.f", 10.0),
                        ("motor.torque", 1.0), ("B.ex", 1e-4)):
        a, b = runs["auto"][name][before], runs["absolute"][name][before]
        assert np.max(np.abs(a - b)) < 1e-7 * max(scale, np.max(np.abs(b))), name
    # and the first impact itself: its time and peak force
    (ta, fa), (tb, fb) = first_impact(runs["auto"]), first_impact(runs["absolute"])
    assert abs(ta - tb) < 2e-6 and abs(fa - fb) < 1e-3 * fb


def test_joint_coordinates_asked_of_a_closed_loop_raise_naming_the_joint():
    # an option the core would refuse at the start of the run: refused before it, at its key
    model = jp.load(IDEAL)
    with pytest.raises(jp.ModelError) as info:
        model.simulate(1e-3, formulation="joint_coordinates")
    [problem] = info.value.problems
    assert problem.location == "simulation.formulation"
    assert "closes a loop of ideal joints" in problem.message and "absolute" in problem.message


def test_an_unknown_formulation_is_a_located_model_error():
    with pytest.raises(jp.ModelError) as info:
        jp.load(DRY).simulate(1e-3, formulation="minimal")
    assert [str(p) for p in info.value.problems] == [
        "simulation.formulation: must be one of ['auto', 'absolute', 'joint_coordinates'], got 'minimal'"]
