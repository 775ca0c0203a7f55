"""The Python builder with units: strings and pint quantities, errors by element name, as in model files."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import flores_slider_crank_dry as flores
import jointplay as jp
from jointplay import laws
from jointplay.units import registry

DRY = Path(__file__).resolve().parents[1] / "examples" / "flores_slider_crank_dry.toml"


def flores_with_units() -> jp.Model:
    """The Flores dry slider-crank written with units, as examples/flores_slider_crank_dry.toml."""
    q = registry().Quantity
    m = jp.Model("flores_slider_crank_dry", gravity=(0, "-9.81 m/s^2"))
    m.add_ground_point("O", ("0 mm", "0 mm"))
    m.add_ground_point("line", (0, 0))
    m.add_body("crank", mass="0.30 kg", inertia="1e-4 kg m^2", position=("25 mm", 0),
               points={"O": ("-25 mm", 0), "A": ("25 mm", 0)})
    m.add_body("rod", mass=q(0.21, "kg"), inertia=q(2.5e-4, "kg m^2"), position=(q(110, "mm"), 0),
               points={"A": ("-60 mm", 0), "B": ("60 mm", 0)})
    m.add_body("slider", mass="140 g", inertia="1e-4 kg m^2", position=("170 mm", 0), points={"B": (0, 0)})
    m.add_revolute("O", "ground.O", "crank.O")
    m.add_revolute("A", "crank.A", "rod.A")
    m.add_translational("guide", "ground.line", "slider.B", axis=(1, 0))
    m.add_clearance_revolute("B", "slider.B", "rod.B", bearing_radius="10 mm", clearance="0.5 mm", length="40 mm",
                             bearing_material={"youngs_modulus": "207 GPa", "poisson_ratio": 0.3},
                             journal_material=laws.material(207e9, 0.3),
                             contact=laws.lankarani_nikravesh(0.9), stiffness=laws.hertz_cylinder(),
                             friction=laws.ambrosio(0.01, 1e-4, 1e-3))
    m.add_driver("motor", "O", {"kind": "constant_rate", "initial": 0, "rate": "5000 rpm"})
    return m


def test_builder_with_units_gives_the_model_file_spec():
    built, loaded = flores_with_units().to_spec(), jp.load(DRY).to_spec()
    for spec in (built, loaded):
        for body in spec["bodies"]:
            body["position"] = None  # approximate initial guesses
    for key in ("bearing_radius", "clearance", "length"):
        assert built["joints"][3][key] == pytest.approx(loaded["joints"][3][key], rel=1e-12)
    assert built["bodies"][2]["mass"] == pytest.approx(0.14, rel=1e-12)
    assert built["drivers"][0]["function"]["rate"] == pytest.approx(5000 * 2 * math.pi / 60, rel=1e-12)
    assert flores_with_units().check()["degrees_of_freedom"] == 2


def test_numbers_stay_si_in_the_builder():
    assert flores.build_model().joint("B")["clearance"] == 0.5e-3


@pytest.mark.parametrize("call, message", [
    (lambda m: m.add_clearance_revolute("B2", "slider.B", "rod.B", bearing_radius="10 mm", clearance="-0.1 mm",
                                        contact=laws.hertz()),
     "joints.B2.clearance: must be > 0, got -0.1 mm"),
    (lambda m: m.add_clearance_revolute("B2", "slider.B", "rod.B", bearing_radius="10 mm", clearance=float("nan"),
                                        contact=laws.hertz()),
     "joints.B2.clearance: must be finite, got nan"),
    (lambda m: m.add_body("extra", mass="5 mm", inertia=1.0),
     "bodies.extra.mass: must be a mass (e.g. \"0.3 kg\"), got '5 mm', which is a length"),
    (lambda m: m.add_body("extra", mass=1.0, inertia=1.0, points={"P": ("1 mm",)}),
     "bodies.extra.points.P: must be a pair [x, y] (e.g. [\"0.5 mm\", 0]), got ('1 mm',)"),
    (lambda m: m.add_ground_point("Q", ("1 kg", 0)),
     "ground.points.Q: x component must be a length (e.g. \"0.5 mm\"), got '1 kg', which is a mass"),
    (lambda m: m.add_spring_damper("s", "crank.A", "slider.B", free_length="10 N/m"),
     "forces.s.free_length: must be a length (e.g. \"0.5 mm\"), got '10 N/m', which is a stiffness"),
    (lambda m: m.add_torque("t", "crank", "10**10**8 N m"),
     "forces.t.torque: cannot be read as a number with a unit (e.g. \"0.5 mm\"), got '10**10**8 N m'"),
    (lambda m: m.add_driver("d", "guide", {"kind": "constant_rate", "rate": "3 rpm"}),
     "drivers.d.function.rate: must be a velocity (e.g. \"1e-3 m/s\"), got an angular quantity '3 rpm'"),
    (lambda m: m.add_clearance_revolute("B2", "slider.B", "rod.B", bearing_radius="10 mm", clearance="0.1 mm",
                                        contact=laws.hertz(),
                                        bearing_material={"youngs_modulus": "207 kg", "poisson_ratio": 0.3}),
     "joints.B2.bearing_material.youngs_modulus: must be a pressure (e.g. \"207 GPa\"), got '207 kg', "
     "which is a mass"),
])
def test_bad_builder_arguments_are_errors_by_element_name(call, message):
    with pytest.raises(jp.ModelError) as info:
        call(flores_with_units())
    assert [str(p) for p in info.value.problems] == [message]


def test_laws_written_by_hand_take_units_and_are_checked():
    m = flores_with_units()
    m.add_clearance_revolute("B2", "slider.B", "rod.B", bearing_radius="10 mm", clearance="0.1 mm",
                             contact={"law": "flores", "restitution": 0.5},
                             friction={"law": "ambrosio", "coefficient": 0.01, "v0": "0.1 mm/s", "v1": "1 mm/s"},
                             stiffness={"law": "hertz_cylinder", "exponent": 1.2})
    joint = m.joint("B2")
    assert joint["friction"] == {"law": "ambrosio", "coefficient": 0.01, "v0": pytest.approx(1e-4, rel=1e-12),
                                 "v1": pytest.approx(1e-3, rel=1e-12)}
    assert joint["stiffness"] == {"law": "hertz_cylinder_exponent", "exponent": 1.2}
    with pytest.raises(jp.ModelError) as info:
        m.add_clearance_revolute("B3", "slider.B", "rod.B", bearing_radius="10 mm", clearance="0.1 mm",
                                 contact=laws.lankarani_nikravesh(1.5))
    assert [str(p) for p in info.value.problems] == ["joints.B3.contact.restitution: must lie in [0, 1], got 1.5"]


def test_nan_gives_the_same_message_in_python_and_in_a_file():
    with pytest.raises(jp.ModelError) as in_file:
        jp.load(DRY, ["joints.B.clearance=nan"])
    with pytest.raises(jp.ModelError) as in_python:
        flores.build_model(clearance=float("nan"))
    assert [str(p) for p in in_python.value.problems] == [str(p) for p in in_file.value.problems] == [
        "joints.B.clearance: must be finite, got nan"]


def test_core_errors_name_the_element_not_its_index():
    m = flores.build_model()
    m.joint("B")["clearance"] = -1e-4  # edited in place: only the core sees it
    with pytest.raises(jp.ModelError) as info:
        m.compile()
    assert str(info.value.problems[0]) == "joints.B.clearance: must be > 0, got -0.0001 m"
    assert {p.location for p in info.value.problems} == {"joints.B.clearance", "joints.B.stiffness"}


def test_law_and_function_helpers_take_units():
    from jointplay import functions as fn

    q = registry().Quantity
    assert laws.ambrosio(0.01, "0.1 mm/s", q(1, "mm/s")) == {"law": "ambrosio", "coefficient": 0.01,
                                                             "v0": pytest.approx(1e-4), "v1": pytest.approx(1e-3)}
    assert laws.material("207 GPa", 0.3)["youngs_modulus"] == pytest.approx(207e9)
    assert laws.lubrication("hamrock_short", "400 cP")["viscosity"] == pytest.approx(0.4)
    assert laws.wang_transition("2 um")["safe_film_thickness"] == pytest.approx(2e-6)
    m = flores_with_units()
    m.add_torque("load", "crank", fn.cubic_step("0 ms", "10 ms", 0, "2 N m"))
    spec = m.to_spec()
    assert spec["forces"][0]["torque"] == {"kind": "cubic_step", "t_start": 0.0, "t_end": pytest.approx(0.01),
                                           "value_start": 0.0, "value_end": pytest.approx(2.0)}
    m2 = flores_with_units()
    m2._spec["drivers"].clear()
    m2.add_driver("motor", "O", fn.constant_speed("5000 rpm"))
    assert m2.to_spec()["drivers"][0]["function"]["rate"] == pytest.approx(5000 * 2 * math.pi / 60, rel=1e-12)


def test_law_helpers_name_the_key_of_a_wrong_unit():
    with pytest.raises(jp.ModelError, match=r"friction.v0: must be a velocity .*got '0.1 mm'"):
        laws.ambrosio(0.01, "0.1 mm")
    with pytest.raises(jp.ModelError, match=r"lubrication.viscosity: must be a viscosity"):
        laws.lubrication("hamrock_short", "400 kg")


def test_function_helper_with_a_wrong_unit_is_reported_at_the_driver():
    from jointplay import functions as fn

    m = flores_with_units()
    m._spec["drivers"].clear()
    with pytest.raises(jp.ModelError, match=r"drivers.motor.function.rate: must be an angular velocity"):
        m.add_driver("motor", "O", fn.constant_speed("5 m/s"))


def test_reynolds_only_arguments_of_a_closed_form_film_are_an_error():
    with pytest.raises(jp.ModelError, match=r"lubrication.cavitation: applies only to the Reynolds models "
                                            r"\(reynolds_exact, reynolds_table\), not to hamrock_short"):
        laws.lubrication("hamrock_short", "400 cP", cavitation="gumbel")
    assert laws.lubrication("reynolds_table", "400 cP")["reynolds"]["cavitation"] == "swift_stieber"
