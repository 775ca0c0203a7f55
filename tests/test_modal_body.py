"""Modal bodies from Python: the builder's description compiles, the first bending frequency is Euler-Bernoulli's,
a clamped modal cantilever settles at Timoshenko's tip deflection, free flight keeps its energy, a driver spinning
a modal body past its first bending frequency is warned of, and bad arguments are reported at their place."""

from __future__ import annotations

import math

import pytest

import jointplay as jp
from jointplay import functions as fn
from jointplay import sections

# EA, kGA, EI, rho A, rho I of a 1 m link
SECTION = sections.resultants("2e6 N", "8e5 N", "100 N m^2", "2 kg/m", "1e-4 kg m")


def cantilever(load: float = 10.0, points: dict | None = None) -> jp.Model:
    """A modal body clamped at its start (its frame too), a load down at its end, every mode critically damped; a
    spring of no stiffness from (1, -1) to the tip measures the tip's height (its length is y + 1 while x stays 1)."""
    m = jp.Model("modal cantilever", gravity=(0, 0))
    m.add_ground_point("O", (0, 0))
    m.add_ground_point("below", ("1 m", "-1 m"))
    m.add_modal_body("arm", (0, 0), ("1 m", 0), section=SECTION, elements=6, normal_modes=2, damping_ratio=1.0,
                     frame="clamped", points=points)
    m.add_fixed("clamp", "ground.O", "arm.start")
    m.add_point_force("load", "arm.end", fx=0.0, fy=-load)
    m.add_spring_damper("probe", "ground.below", "arm.end", stiffness=0.0, damping=0.0, free_length=0.0)
    return m


def test_check_lists_the_first_bending_frequency_of_euler_bernoulli():
    # clamped-free: f1 = 1.8751^2 sqrt(EI / (rho A L^4)) / (2 pi) = 3.9554 Hz (shear lowers it by 1e-4)
    info = cantilever().check()
    (name, frequency), = info["modal_bending_frequencies"].items()
    expected = 1.875_104_07**2 * math.sqrt(100.0 / 2.0) / (2.0 * math.pi)
    assert name == "arm" and frequency == pytest.approx(expected, rel=1e-3)
    body = next(b for b in info["bodies"] if b["name"] == "arm")
    assert body["kind"] == "modal" and body["modes"] == 3 + 2 and body["mass"] == pytest.approx(2.0, rel=1e-12)


def test_a_link_with_two_interface_nodes_is_held_simply_supported_by_default():
    # the chord frame: f1 = pi^2 sqrt(EI / (rho A L^4)) / (2 pi) = 11.107 Hz (shear and rotary inertia lower it
    # by 9e-4)
    m = jp.Model("modal link", gravity=(0, 0))
    m.add_modal_body("arm", (0, 0), ("1 m", 0), section=SECTION, elements=6, normal_modes=2)
    (name, frequency), = m.check()["modal_bending_frequencies"].items()
    assert frequency == pytest.approx(math.pi**2 * math.sqrt(100.0 / 2.0) / (2.0 * math.pi), rel=1e-3)


def test_a_clamped_modal_cantilever_settles_at_the_timoshenko_deflection():
    r = cantilever().simulate(2.0, method="bdf", max_order=2, rtol=1e-8, atol=1e-11, output_step=0.05)
    expected = 10.0 / (3.0 * 100.0) + 10.0 / 8e5  # P L^3 / (3 EI) + P L / (k G A) [m]
    assert r["probe.length"][-1] - 1.0 == pytest.approx(-expected, rel=1e-5)
    assert r["clamp.fy"][-1] == pytest.approx(10.0, rel=1e-6)
    assert "arm.eta1" in r.channels and "arm.angle" in r.channels


def test_strains_recovered_from_the_modes_are_the_cantilevers_statics():
    # at rest under the tip load P: N = 0, Q = P, M = P (L - s) at the arclength s (statics of the cantilever),
    # fibre strain -y M / EI; the gauge at mid-span is at a node (the modal body's points are nodes)
    m = cantilever(points={"mid": "0.5 m"})
    m.add_strain_gauge("gauge", "arm.mid", fibre="10 mm")
    r = m.simulate(2.0, method="bdf", max_order=2, rtol=1e-8, atol=1e-11, output_step=0.05)
    moment = r["gauge.bending_moment"][-1]
    assert abs(moment) == pytest.approx(10.0 * 0.5, rel=1e-6)
    assert abs(r["gauge.shear_force"][-1]) == pytest.approx(10.0, rel=1e-6)
    assert abs(r["gauge.axial_force"][-1]) < 1e-6
    assert r["gauge.axial_strain"][-1] == pytest.approx(-0.01 * moment / 100.0, rel=1e-6)


def test_a_free_modal_body_keeps_its_energy_while_spinning():
    m = jp.Model("free modal body", gravity=(0, 0))
    m.add_modal_body("arm", (0, 0), ("1 m", 0), section=SECTION, elements=4, normal_modes=3, velocity=(0.3, -1.5),
                     angular_velocity="3 rad/s")
    r = m.simulate(1.0, rtol=1e-10, atol=1e-12, output_step=0.01)
    energy = r["system.energy"]
    assert energy.max() - energy.min() < 1e-8 * energy[0]


def test_a_driver_spinning_a_modal_body_past_its_first_bending_frequency_is_warned_of():
    m = jp.Model("spin-up", gravity=(0, 0))
    m.add_ground_point("O", (0, 0))
    m.add_body("hub", mass=1.0, inertia=1.0, position=(0, 0), points={"O": (0, 0)})
    m.add_modal_body("arm", (0, 0), ("10 m", 0), section=sections.resultants("2.8e7 N", "1e7 N", "1.4e4 N m^2",
                     "1.2 kg/m", "6e-4 kg m"), elements=4, interface={"start": 0}, normal_modes=3)
    m.add_revolute("axis", "ground.O", "hub.O")
    m.add_fixed("clamp", "hub.O", "arm.start")
    m.add_driver("spin", "axis", fn.speed_ramp("6 rad/s", 15.0))
    with pytest.warns(jp.JointplayWarning, match=r"modal body arm \(0\.604 Hz = 3\.8 rad/s\)"):
        m.simulate(1.0, output_step=0.1)


@pytest.mark.parametrize(("arguments", "location", "text"), [
    ({"interface": {"start": 0, "mid": "0.3 m"}}, "modal_bodies.arm.interface.mid.arclength", "every 0.25 m"),
    ({"damping_ratio": -0.1}, "modal_bodies.arm.damping_ratio", "must be >= 0"),
    ({"frame": "mean_axis"}, "modal_bodies.arm.frame", "chord"),
    ({"frame": "chord", "interface": {"start": 0}}, "modal_bodies.arm", "second interface node"),
    ({"normal_modes": -1}, "modal_bodies.arm.normal_modes", ""),
    ({"interface": {"start": "-1 m"}}, "modal_bodies.arm.interface.start", ""),
])
def test_a_bad_modal_body_is_reported_at_its_place(arguments, location, text):
    m = jp.Model("bad", gravity=(0, 0))
    with pytest.raises(jp.ModelError) as caught:
        m.add_modal_body("arm", (0, 0), ("1 m", 0), section=SECTION, elements=2, **{"normal_modes": 1, **arguments})
        m.check()
    message = str(caught.value)
    assert location in message and text in message


CANTILEVER_TOML = """
[model]
name = "modal cantilever"
gravity = [0, 0]
[ground]
points = { O = [0, 0], below = ["1 m", "-1 m"] }
[modal_bodies.arm]
start = [0, 0]
end = ["1 m", 0]
section = { shape = "resultants", axial_stiffness = "2e6 N", shear_stiffness = "8e5 N", bending_stiffness = "100 N m^2", mass_per_length = "2 kg/m", rotary_inertia_per_length = "1e-4 kg m" }
elements = 6
frame = "clamped"
normal_modes = 2
damping_ratio = 1.0
[joints.clamp]
type = "fixed"
first = "ground.O"
second = "arm.start"
[forces.load]
type = "point_force"
point = "arm.end"
fx = 0
fy = "-10 N"
[forces.probe]
type = "spring_damper"
first = "ground.below"
second = "arm.end"
stiffness = 0
damping = 0
free_length = 0
"""


def test_builder_and_model_file_give_the_same_modal_body_and_the_writer_round_trips_it():
    assert jp.loads(CANTILEVER_TOML).to_spec() == cantilever().to_spec()
    assert jp.loads(cantilever().to_toml()).to_spec() == cantilever().to_spec()


def test_a_modal_body_that_nothing_refers_to_is_an_error_unless_free():
    text = CANTILEVER_TOML.split("[joints.clamp]")[0]
    with pytest.raises(jp.ModelError, match="modal_bodies.arm: is connected to nothing"):
        jp.loads(text)
    jp.loads(text.replace("damping_ratio = 1.0", "damping_ratio = 1.0\nfree = true"))


def test_results_of_a_modal_body_are_saved_and_read_back(tmp_path):
    r = cantilever().simulate(0.2, method="bdf", max_order=2, output_step=0.05)
    back = jp.open_results(r.save(tmp_path / "cantilever.nc"))
    assert back["arm.eta2"] == pytest.approx(r["arm.eta2"], rel=0, abs=0)
    assert back.spec["modal_bodies"][0]["name"] == "arm"


def test_check_command_prints_the_modal_table(tmp_path):
    from typer.testing import CliRunner

    from jointplay.cli import app

    path = tmp_path / "cantilever.toml"
    path.write_text(CANTILEVER_TOML, encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 0, result.output
    assert "held" in result.output and "beam" in result.output
    assert "3.956" in result.output and "24.77" in result.output  # clamped-free: 1.8751^2 and 4.6941^2 ratios
    assert "5 elastic of the modal bodies" in result.output
