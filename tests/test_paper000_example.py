"""Paper 000 complete: the four joint models on its spring-loaded slider-crank with flexible links
(examples/paper000_joint_models.py).

The example is run once (module fixture) with a short end time; the numbers
asserted were observed on that run, with margins noted at each assertion.
"""

import math

import numpy as np
import pytest

import jointplay as jp
import paper000_joint_models as example

T_END = 0.004  # s: release, the first flight across the clearance and the impacts after it


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    out = tmp_path_factory.mktemp("paper000")
    runs, rows = example.main(["--out", str(out), "--t-end", str(T_END)])
    return out, runs, {row["joint"]: row for row in rows}


def test_the_four_joint_models_build_and_run_to_the_end_with_flexible_links(study):
    _, runs, _ = study
    assert list(runs) == list(example.JOINT_MODELS)
    for joint, results in runs.items():
        assert results.error is None, joint
        assert results.time[-1] == pytest.approx(T_END)
        assert "E.axial_strain" in results and "BC.node0_x" in results, joint


def test_the_links_are_beams_of_three_node_elements_with_the_rigid_links_masses():
    beams = {b["name"]: b for b in example.build_model("ideal").to_spec()["beams"]}
    assert set(beams) == {"AB", "BC"}
    for name, length in (("BC", example.CRANK), ("AB", example.COUPLER)):
        beam = beams[name]
        assert beam["mesh"]["order"] == "quadratic"  # paper 000: 3-node isoparametric elements
        section = beam["section"]
        mass = section["material"]["density"] * section["width"] * section["height"] * length
        assert mass == pytest.approx(example.MASSES[name], rel=1e-12)


def test_the_spring_neutral_position_is_106_degrees_from_the_start():
    model = example.build_model("ideal")
    spring = next(f for f in model.to_spec()["forces"] if f["name"] == "spring")
    theta = example.INITIAL_CRANK_ANGLE - math.radians(106.0)
    length = example.SPRING_ANCHOR - example.slider_position(theta)
    assert spring["free_length"] == pytest.approx(length, rel=1e-12)


def test_released_crank_swings_clockwise(study):
    _, runs, _ = study
    ideal = runs["ideal"]
    omega = example.crank_angular_velocity(ideal)
    # the spring drives the crank clockwise from rest; by 4 ms it has turned tens of degrees (39 observed)
    assert omega[0] == pytest.approx(0.0, abs=1e-9)
    assert example.crank_turn(ideal) < -20.0
    assert np.all(omega[1:] < 0.0)


def test_coupler_is_in_compression_at_e(study):
    # paper 000 (Fig. 11): with ideal joints "the axial strain remains negative"; observed -9.6e-6 at its
    # most, and 0 only at the unstressed start
    _, runs, _ = study
    strain = runs["ideal"]["E.axial_strain"]
    assert strain[0] == 0.0
    assert np.max(strain[1:]) < 0.0
    assert np.min(strain) < -5e-6


def test_clearance_changes_the_crank_response(study):
    _, _, rows = study
    ideal_peak = rows["ideal"]["peak_omega"]
    # observed at 4 ms: the dry joint departs from the ideal one by 17.8 rad/s, 6 % of the crank's peak speed
    assert rows["clearance"]["peak_omega_deviation"] > 0.04 * ideal_peak
    assert rows["clearance"]["impacts"] >= 1
    assert rows["ideal"]["peak_omega_deviation"] == 0.0
    # ... and the strain at E: down to -29.7e-6 against -9.6e-6 with the ideal pin
    assert rows["clearance"]["strain_min"] < 2.0 * rows["ideal"]["strain_min"]


def test_lubrication_smooths_the_crank_response(study):
    _, _, rows = study
    dry = rows["clearance"]["peak_omega_deviation"]
    # observed at 4 ms: 3.6 (squeeze) and 6.6 (hydrodynamic) against 17.8 rad/s (dry)
    assert rows["squeeze_film"]["peak_omega_deviation"] < 0.5 * dry
    assert rows["hydrodynamic"]["peak_omega_deviation"] < 0.5 * dry


def test_lubrication_lowers_the_peak_joint_force(study):
    _, _, rows = study
    dry = rows["clearance"]["peak_force"]
    # observed at 4 ms: 91 N (squeeze) and 112 N (hydrodynamic) against 316 N (dry impacts);
    # above the ideal pin's reaction: 12 N and 32 N against 250 N
    assert rows["squeeze_film"]["peak_force"] < 0.4 * dry
    assert rows["hydrodynamic"]["peak_force"] < 0.4 * dry
    assert rows["squeeze_film"]["peak_force_excess"] < 0.2 * rows["clearance"]["peak_force_excess"]
    assert rows["hydrodynamic"]["peak_force_excess"] < 0.2 * rows["clearance"]["peak_force_excess"]


@pytest.mark.parametrize("joint", ["squeeze_film", "hydrodynamic"])
def test_lubricated_journal_stays_off_the_wall_most_of_the_time(study, joint):
    _, runs, rows = study
    results = runs[joint]
    film = results["B.film_min"]
    # observed at 4 ms: no contact at all; smallest film 3.3 um (squeeze), 1.3 um (hydrodynamic) of 25 um
    assert np.mean(film > 0.0) > 0.9
    assert rows[joint]["contact_fraction"] < 0.05
    assert rows[joint]["film_min"] > 0.02 * example.CLEARANCE


def test_link_compliance_softens_the_dry_impacts(study):
    # the links' compliance in series with the contact: observed at 4 ms, peak joint force 316 N with
    # flexible links against 685 N with rigid links of the same masses, 4 impacts against 22
    _, _, rows = study
    rigid = example.compare({joint: example.simulate(example.build_model(joint, "rigid"), T_END)
                             for joint in ("ideal", "clearance")})[1]
    assert rows["clearance"]["peak_force"] < 0.7 * rigid["peak_force"]


def _rigid_limit() -> jp.Model:
    """The rigid-link mechanism whose links have the inertia of the beams' rectangles, m (L^2 + h^2) / 12
    (a beam's section carries rotary inertia rho I; a rigid bar of the example has m L^2 / 12)."""
    spec = example.build_model("ideal", "rigid").to_spec()
    for body in spec["bodies"]:
        if body["name"] in example.MASSES and body["name"] != "slider":
            length = example.CRANK if body["name"] == "BC" else example.COUPLER
            body["inertia"] = example.MASSES[body["name"]] * (length**2 + example.DEPTH**2) / 12
    return jp.Model.from_spec(spec)


def test_very_stiff_links_reproduce_the_rigid_mechanism():
    # the beams' Young's modulus raised 100 and 10 000 times: the crank's angular velocity converges to
    # the rigid mechanism's, the difference falling about as 1/E (observed over the 7 ms window: 1.22,
    # 0.038 and 0.00067 rad/s of a 610 rad/s peak)
    rigid = example.simulate(_rigid_limit())
    reference = example.crank_angular_velocity(rigid)
    errors = []
    for factor in (1.0, 1e2, 1e4):
        spec = example.build_model("ideal").to_spec()
        for beam in spec["beams"]:
            beam["section"]["material"]["youngs_modulus"] *= factor
        model = jp.Model.from_spec(spec)
        if factor == 1.0:
            results = example.simulate(model)
        else:  # deliberately stiffer than any solid
            with pytest.warns(jp.JointplayWarning, match="outside the range of solids"):
                results = example.simulate(model)
        omega = np.interp(rigid.time, results.time, example.crank_angular_velocity(results))
        errors.append(np.max(np.abs(omega - reference)))
    peak = np.max(np.abs(reference))
    assert errors[0] > 1e-3 * peak  # the links as chosen do bend
    assert errors[1] < errors[0] / 10 and errors[2] < errors[1] / 10
    assert errors[2] < 1e-5 * peak


def test_comparison_figures_are_written(study):
    out, _, _ = study
    for name in ("paper000_crank_velocity_and_strain.png", "paper000_joint_force_and_orbits.png"):
        path = out / name
        assert path.exists() and path.stat().st_size > 10_000
