"""Plausibility warnings: legal values that are almost certainly mistakes, each from a mutated example."""

from __future__ import annotations

import importlib
import math
import warnings
from pathlib import Path

import pytest
from typer.testing import CliRunner

import jointplay as jp
from jointplay.cli import app
from jointplay.modelfile import plausibility
from jointplay.modelfile.plausibility import contact_stiffness, function_rate

ROOT = Path(__file__).resolve().parents[1]
DRY = ROOT / "examples" / "flores_slider_crank_dry.toml"
SPRINGS = ['forces.soft={ type = "spring_damper", first = "ground.O", second = "slider.B", stiffness = "100 N/m", '
           'free_length = "170 mm" }',
           'forces.hard={ type = "spring_damper", first = "ground.O", second = "rod.A", stiffness = "1e9 N/m", '
           'free_length = "50 mm" }']
CONTACT = ('joints.C={ type = "clearance_revolute", bearing = "crank.O", journal = "ground.line", '
           'bearing_radius = "10 mm", clearance = "0.5 mm", contact = "hertz", '
           'bearing_material = { youngs_modulus = "2 MPa", poisson_ratio = 0.45 }, '
           'journal_material = { youngs_modulus = "2 MPa", poisson_ratio = 0.45 } }')


def warned(overrides: list[str], path: Path = DRY) -> list[str]:
    return [str(p) for p in plausibility(jp.load(path, overrides, check=False).to_spec())]


@pytest.mark.parametrize("override, message", [
    ("joints.B.clearance=2.5 mm", "joints.B.clearance: 2.5 mm is 25 % of the bearing radius 10 mm; radial "
                                  "clearances of real joints are a few percent at most: check the units"),
    ("joints.B.bearing_radius=100 mm", "joints.B.bearing_radius: 100 mm is larger than the links of the mechanism "
                                       "(largest centre-to-point distance 60 mm): check the units"),
    ("bodies.rod.mass=5000 kg", "bodies.rod.mass: 5e+03 kg is 1.67e+04 times the typical value of the bodies "
                                "(0.3 kg): check the units"),
    ("bodies.rod.mass=1e-5 kg", "bodies.rod.mass: 1e-05 kg is 1/1.4e+04 of the typical value of the bodies "
                                "(0.14 kg): check the units"),
    ("bodies.slider.inertia=1 kg m^2", "bodies.slider.inertia: 1 kg m^2 with a mass of 0.14 kg gives a radius of "
                                       "gyration of 2.67e+03 mm, 44.5 times the largest centre-to-point distance "
                                       "(60 mm): check the units (kg m^2, not kg mm^2)"),
    ("joints.B.bearing_material.youngs_modulus=207 kPa",
     "joints.B.bearing_material.youngs_modulus: 2.07e+05 Pa is outside the range of solids (1 MPa for soft rubber "
     "to 1.2 TPa for diamond): check the units"),
    ("joints.B.onset_velocity_floor=100 m/s",
     "joints.B.onset_velocity_floor: 100 m/s is above the speeds in the model (about 31.4 m/s from the drivers' "
     "rates times the link size, the initial velocities and free fall): the floor is meant for grazing contacts, "
     "far below impact speeds"),
    ('bodies.slider.position=["170 m", 0]', "bodies.slider.position: is 170 m from the middle of the mechanism, "
                                            "2.83e+03 times the largest centre-to-point distance (60 mm): "
                                            "check the units"),
])
def test_each_implausible_value_gives_its_warning(override, message):
    assert warned([override])[0] == message  # a tiny mass also gives a large radius of gyration


def test_a_bulk_modulus_in_the_wrong_unit_gives_a_warning():
    boom = ROOT / "examples" / "hydraulic_boom.toml"
    assert warned(["forces.lift.bulk_modulus=1.5 MPa"], boom) == [
        "forces.lift.bulk_modulus: 1.5e+06 Pa is outside the range of hydraulic liquids (10 MPa with much entrained "
        "air to 5 GPa; mineral oil 1.5-1.8 GPa): check the units"]
    assert warned(["forces.lift.bulk_modulus=1 GPa"], boom) == []


BOOM = ROOT / "examples" / "hydraulic_boom.toml"
LUBRICATED = ROOT / "examples" / "flores_slider_crank_lubricated.toml"


@pytest.mark.parametrize("override, message", [
    ("joints.B.lubrication.viscosity=1e9 cP",
     "joints.B.lubrication.viscosity: 1e+06 Pa s (1e+09 cP) is outside the range of lubricants (1e-05 Pa s for air to "
     "100 Pa s for a cold heavy gear oil; engine oils 0.01-1 Pa s): check the units (1 cP = 1 mPa s)"),
    ("joints.B.lubrication.viscosity=400 Pa s",  # "400 cP" in the wrong unit
     "joints.B.lubrication.viscosity: 400 Pa s (4e+05 cP) is outside the range of lubricants (1e-05 Pa s for air to "
     "100 Pa s for a cold heavy gear oil; engine oils 0.01-1 Pa s): check the units (1 cP = 1 mPa s)"),
    ("joints.B.lubrication.viscosity=0.004 cP",
     "joints.B.lubrication.viscosity: 4e-06 Pa s (0.004 cP) is outside the range of lubricants (1e-05 Pa s for air to "
     "100 Pa s for a cold heavy gear oil; engine oils 0.01-1 Pa s): check the units (1 cP = 1 mPa s)"),
])
def test_a_viscosity_outside_the_range_of_lubricants_warns(override, message):
    assert warned([override], LUBRICATED) == [message]


def test_viscosities_of_real_lubricants_do_not_warn():
    for viscosity in ("0.018 cP", "1 cP", "400 cP", "90 Pa s"):  # air, water, the example's oil, a cold gear oil
        assert warned([f"joints.B.lubrication.viscosity={viscosity}"], LUBRICATED) == []


@pytest.mark.parametrize("override, message", [
    ("forces.lift.cap_pressure=18.118 GPa",  # "18.118 bar" in the wrong unit
     "forces.lift.cap_pressure: 1.81e+04 MPa (1.81e+05 bar) is far above the rating of any hydraulic system "
     "(industrial hydraulics: 35-70 MPa): check the units"),
    ("forces.lift.rod_pressure=1000 MPa",
     "forces.lift.rod_pressure: 1e+03 MPa (1e+04 bar) is far above the rating of any hydraulic system "
     "(industrial hydraulics: 35-70 MPa): check the units"),
    ("forces.lift.second=ground.O",  # the cylinder from ground point C to ground point O
     "forces.lift.second: ground.O is on the ground, like the first end ground.C: the element's length never "
     "changes and its force acts on nothing; attach one end to a moving body"),
])
def test_an_implausible_hydraulic_cylinder_warns(override, message):
    assert warned([override], BOOM) == [message]


def test_chamber_pressures_of_real_hydraulics_do_not_warn():
    assert warned(["forces.lift.cap_pressure=700 bar", "forces.lift.rod_pressure=100 MPa"], BOOM) == []


def test_a_lubricant_supply_far_above_any_rating_warns():
    text = LUBRICATED.read_text(encoding="utf-8")
    model = jp.load(LUBRICATED, ['joints.B.lubrication.model=reynolds_exact',
                                 'joints.B.lubrication.groove_supply_pressure=3000 bar'], check=False)
    assert [str(p) for p in plausibility(model.to_spec())] == [
        "joints.B.lubrication.groove_supply_pressure: 300 MPa (3e+03 bar) is far above the rating of any hydraulic "
        "system (industrial hydraulics: 35-70 MPa): check the units"]
    assert "groove_supply_pressure" not in text


def test_a_spring_within_one_body_warns():
    assert warned(['forces.inner={ type = "spring_damper", first = "rod.A", second = "rod.B", stiffness = "100 N/m", '
                   'free_length = "170 mm" }']) == [
        "forces.inner.second: rod.B is on the body rod, like the first end rod.A: the element's length never changes "
        "and its force acts on nothing; attach one end to a moving body"]


def test_springs_far_from_the_other_springs_warn_but_not_against_contacts():
    assert warned(SPRINGS) == ["forces.hard.stiffness: 1e+09 N/m is 1e+07 times the typical value of the springs "
                               "(100 N/m): check the units"]
    assert warned(SPRINGS[:1]) == []  # a soft spring beside a steel contact is normal


def test_contact_far_from_the_other_contacts_warns():
    assert warned([CONTACT, "joints.A.type=fixed"]) == [
        "joints.B.stiffness: contact stiffness 2.22e+08 N/m is 9.07e+04 times the typical value of the contacts "
        "(2.44e+03 N/m): check the units"]


def test_inertia_far_from_the_others_warns_about_both_size_and_spread():
    found = warned(["bodies.rod.inertia=2500 kg m^2"])
    assert found[0] == ("bodies.rod.inertia: 2.5e+03 kg m^2 is 2.5e+07 times the typical value of the bodies "
                        "(0.0001 kg m^2): check the units")
    assert found[1].startswith("bodies.rod.inertia: 2.5e+03 kg m^2 with a mass of 0.21 kg gives a radius of gyration")


def test_thresholds_are_not_hit_just_below_them():
    assert warned(["joints.B.clearance=1.9 mm", "bodies.rod.mass=2000 kg", "joints.B.onset_velocity_floor=30 m/s",
                   "joints.B.bearing_material.youngs_modulus=2 MPa"]) == []


def test_mechanism_that_nothing_moves_warns():
    text = """
[bodies.bar]
mass = "1 kg"
inertia = "0.02 kg m^2"
free = true
"""
    assert [str(p) for p in plausibility(jp.loads(text).to_spec())] == [
        "model: nothing moves the mechanism: no driver, force element, gravity or initial velocity; "
        "the run will show it at rest"]
    moving = jp.loads(text + 'velocity = ["1 m/s", 0]\n').to_spec()
    assert plausibility(moving) == []


def test_contact_stiffness_matches_the_hertz_cylinder_law_by_hand():
    joint = jp.load(DRY).joint("B")
    e_star = 207e9 / (2 * (1 - 0.3**2))
    r_star = 0.01 * 0.0095 / 0.0005
    k = 4 / 3 * e_star * r_star**0.5
    assert contact_stiffness(joint) == pytest.approx(1.5 * k * (0.01 * 0.0005) ** 0.5, rel=1e-12)


@pytest.mark.parametrize("function, rate", [
    ({"kind": "constant", "value": 3.0}, 0.0),
    ({"kind": "constant_rate", "initial": 0.0, "rate": -52.0}, 52.0),
    ({"kind": "sine", "offset": 0.0, "amplitude": 0.1, "frequency": 5.0, "phase": 0.0}, 0.1 * 2 * math.pi * 5),
    ({"kind": "cubic_step", "t_start": 0.0, "t_end": 0.5, "value_start": 0.0, "value_end": 1.0}, 3.0),
    ({"kind": "table", "times": [0.0, 1.0, 1.5], "values": [0.0, 1.0, 3.0]}, 4.0),
    ({"kind": "polynomial", "coefficients": [1.0, -2.0, 7.0]}, 2.0),
])
def test_driver_rates_are_estimated_from_each_kind_of_function(function, rate):
    assert function_rate(function) == pytest.approx(rate, rel=1e-12)


@pytest.mark.parametrize("path", sorted((ROOT / "examples").glob("*.toml")), ids=lambda p: p.stem)
def test_shipped_model_files_give_no_warning(path):
    assert plausibility(jp.load(path).to_spec()) == []


def _example_models():
    p001 = importlib.import_module("paper001_parametric_study")
    p000 = importlib.import_module("paper000_joint_models")
    yield importlib.import_module("flores_slider_crank_dry").build_model()
    yield importlib.import_module("flores_slider_crank_lubricated").build_model()
    yield importlib.import_module("flores_slider_crank_ideal").build_ideal_model()
    yield from (p001.build_model(case) for cases in p001.SERIES.values() for case in cases)
    yield from (p000.build_model(joint) for joint in p000.JOINT_MODELS)


def test_shipped_python_examples_give_no_warning():
    for model in _example_models():
        assert plausibility(model.to_spec()) == [], model.name


def test_simulate_issues_warnings_and_runs_on():
    model = jp.load(DRY, ["joints.B.clearance=2.5 mm"])
    with pytest.warns(jp.JointplayWarning, match=r"^joints.B.clearance: 2.5 mm is 25 % of the bearing radius"):
        results = model.simulate(2e-4)
    assert results.time[-1] == pytest.approx(2e-4, rel=1e-12)
    with warnings.catch_warnings():
        warnings.simplefilter("error", jp.JointplayWarning)
        jp.load(DRY).simulate(1e-4)  # a plausible model warns nothing


def test_cli_check_and_run_print_warnings_and_exit_0(tmp_path):
    runner = CliRunner()
    checked = runner.invoke(app, ["check", str(DRY), "--set", "joints.B.clearance=2.5 mm"])
    assert checked.exit_code == 0
    assert "warning: joints.B.clearance: 2.5 mm is 25 % of the bearing radius 10 mm" in checked.stderr
    ran = runner.invoke(app, ["run", str(DRY), "--set", "joints.B.clearance=2.5 mm", "--t-end", "0.2 ms", "-q",
                              "-o", str(tmp_path / "r.nc")])
    assert ran.exit_code == 0, ran.output
    assert ran.stderr.count("warning: joints.B.clearance: 2.5 mm") == 1
    plain = runner.invoke(app, ["check", str(DRY)])
    assert "warning" not in plain.stderr
