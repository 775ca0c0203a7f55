"""Paper 000's four joint models on its spring-loaded slider-crank (examples/paper000_joint_models.py).

The example is run once (module fixture) with a short end time; the numbers
asserted were observed on that run, with margins noted at each assertion.
"""

import math

import numpy as np
import pytest

import paper000_joint_models as example

T_END = 0.004  # s: release, the first flight across the clearance and the impacts after it


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    out = tmp_path_factory.mktemp("paper000")
    runs, rows = example.main(["--out", str(out), "--t-end", str(T_END)])
    return out, runs, {row["joint"]: row for row in rows}


def test_the_four_joint_models_build_and_run_to_the_end(study):
    _, runs, _ = study
    assert list(runs) == list(example.JOINT_MODELS)
    for joint, results in runs.items():
        assert results.error is None, joint
        assert results.time[-1] == pytest.approx(T_END)


def test_the_spring_neutral_position_is_106_degrees_from_the_start():
    model = example.build_model("ideal")
    spring = next(f for f in model.to_spec()["forces"] if f["name"] == "spring")
    theta = example.INITIAL_CRANK_ANGLE - math.radians(106.0)
    length = example.SPRING_ANCHOR - example.slider_position(theta)
    assert spring["free_length"] == pytest.approx(length, rel=1e-12)


def test_released_crank_swings_clockwise(study):
    _, runs, _ = study
    ideal = runs["ideal"]
    turn = np.degrees(ideal["BC.angle"][-1] - ideal["BC.angle"][0])
    # the spring drives the crank clockwise from rest; by 4 ms it has turned tens of degrees
    assert ideal["BC.omega"][0] == pytest.approx(0.0, abs=1e-9)
    assert turn < -20.0
    assert np.all(ideal["BC.omega"][1:] < 0.0)


def test_clearance_changes_the_crank_response(study):
    _, _, rows = study
    ideal_peak = rows["ideal"]["peak_omega"]
    # observed at 4 ms: the dry joint departs from the ideal one by 25 rad/s, 9 % of the crank's peak speed
    assert rows["clearance"]["peak_omega_deviation"] > 0.05 * ideal_peak
    assert rows["clearance"]["impacts"] >= 1
    assert rows["ideal"]["peak_omega_deviation"] == 0.0


def test_lubrication_smooths_the_crank_response(study):
    _, _, rows = study
    dry = rows["clearance"]["peak_omega_deviation"]
    # observed at 4 ms: 4.2 (squeeze) and 6.4 (hydrodynamic) against 25 rad/s (dry)
    assert rows["squeeze_film"]["peak_omega_deviation"] < 0.4 * dry
    assert rows["hydrodynamic"]["peak_omega_deviation"] < 0.4 * dry


def test_lubrication_lowers_the_peak_joint_force(study):
    _, _, rows = study
    dry = rows["clearance"]["peak_force"]
    # observed at 4 ms: 74 N (squeeze) and 145 N (hydrodynamic) against 686 N (dry impacts);
    # above the ideal pin's reaction: 8 N and 74 N against 623 N
    assert rows["squeeze_film"]["peak_force"] < 0.4 * dry
    assert rows["hydrodynamic"]["peak_force"] < 0.4 * dry
    assert rows["squeeze_film"]["peak_force_excess"] < 0.2 * rows["clearance"]["peak_force_excess"]
    assert rows["hydrodynamic"]["peak_force_excess"] < 0.2 * rows["clearance"]["peak_force_excess"]


@pytest.mark.parametrize("joint", ["squeeze_film", "hydrodynamic"])
def test_lubricated_journal_stays_off_the_wall_most_of_the_time(study, joint):
    _, runs, rows = study
    results = runs[joint]
    film = results["B.film_min"]
    # observed at 4 ms: no contact at all; smallest film 3.3 um (squeeze), 1.2 um (hydrodynamic) of 25 um
    assert np.mean(film > 0.0) > 0.9
    assert rows[joint]["contact_fraction"] < 0.05
    assert rows[joint]["film_min"] > 0.02 * example.CLEARANCE


def test_comparison_figures_are_written(study):
    out, _, _ = study
    for name in ("paper000_crank_angular_velocity.png", "paper000_joint_force_and_orbits.png"):
        path = out / name
        assert path.exists() and path.stat().st_size > 10_000
