"""Flexible links from Python and from model files: the builder and the file give the same beam, every
problem is reported at its place, the writer round-trips every section shape, `check` gives the natural
frequencies of Euler-Bernoulli theory, and the spin-up example stretches as the closed form says."""

from __future__ import annotations

import math
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp
from jointplay import functions as fn
from jointplay import plots, sections

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
sys.path.insert(0, str(EXAMPLES))

STEEL = sections.material("207 GPa", "7850 kg/m^3", poisson_ratio=0.3)

PENDULUM = """
[model]
name = "flexible_pendulum"
gravity = [0, "-9.81 m/s^2"]
[ground]
points = { O = ["0 m", "0 m"] }
[beams.rod]
start = ["0 m", "0 m"]
end = ["1 m", "0 m"]
section = { shape = "rectangle", width = "20 mm", height = "10 mm" }
material = { youngs_modulus = "207 GPa", density = "7850 kg/m^3", poisson_ratio = 0.3 }
elements = 4
points = { E = "250 mm" }
[joints.pin]
type = "revolute"
first = "ground.O"
second = "rod.start"
[sensors.gauge]
type = "strain_gauge"
point = "rod.E"
fibre = "5 mm"
"""


def flexible_pendulum() -> jp.Model:
    m = jp.Model("flexible_pendulum", gravity=(0, "-9.81 m/s^2"))
    m.add_ground_point("O", (0, 0))
    m.add_beam("rod", (0, 0), ("1 m", 0), section=sections.rectangle("20 mm", "10 mm"), material=STEEL, elements=4,
               points={"E": "250 mm"})
    m.add_revolute("pin", "ground.O", "rod.start")
    m.add_strain_gauge("gauge", "rod.E", fibre="5 mm")
    return m


def test_builder_and_model_file_give_the_same_beam():
    assert flexible_pendulum().to_spec() == jp.loads(PENDULUM).to_spec()


def test_spin_up_example_python_and_model_file_are_the_same_model():
    import spin_up_beam

    built, loaded = spin_up_beam.build_model(), jp.load(EXAMPLES / "spin_up_beam.toml")
    assert built.to_spec() == loaded.to_spec()
    assert built.simulation == loaded.simulation


@pytest.mark.parametrize("section", [
    sections.rectangle("20 mm", "10 mm"), sections.circle("12 mm"), sections.tube("20 mm", "16 mm"),
    sections.properties("2 cm^2", "1.2 cm^4", 0.833)])
def test_the_writer_round_trips_every_section_shape(section):
    m = jp.Model("shapes")
    m.add_beam("b", (0, 0), (1, 0), section=section, material=STEEL, element_length="0.3 m", damping_time="1 ms")
    again = jp.loads(m.to_toml())
    assert again.to_spec() == m.to_spec()
    assert m.to_spec()["beams"][0]["mesh"] == {"order": "quadratic", "elements": None, "element_length": 0.3}


def problems(text: str) -> list[str]:
    with pytest.raises(jp.ModelError) as info:
        jp.loads(text)
    return [str(p) for p in info.value.problems]


def edited(old: str, new: str) -> str:
    assert old in PENDULUM
    return PENDULUM.replace(old, new)


@pytest.mark.parametrize("old, new, expected", [
    ('material = { youngs_modulus = "207 GPa", density = "7850 kg/m^3", poisson_ratio = 0.3 }\n', "",
     "beams.rod.material: missing required value: a rectangle section needs a material"),
    ("poisson_ratio = 0.3 }", 'poisson_ratio = 0.3, shear_modulus = "80 GPa" }',
     "beams.rod.material.poisson_ratio: give exactly one of poisson_ratio or shear_modulus, got both"),
    ("elements = 4", 'elements = 4\nelement_length = "10 cm"',
     "beams.rod.elements: give exactly one of elements or element_length, got both"),
    ("elements = 4", "", "beams.rod.elements: give exactly one of elements or element_length, got neither"),
    ('E = "250 mm"', 'E = "1.2 m"', "beams.rod.points.E: must lie on the beam, from 0 to its length 1000 mm, "
                                    "got 1200 mm"),
    ('E = "250 mm"', 'start = "250 mm"', "beams.rod.points.start: 'start' names the beam's first end already"),
    ('height = "10 mm"', 'height = "10 kg"', "beams.rod.section.height: must be a length"),
    ('shape = "rectangle"', 'shape = "square"', "beams.rod.section.shape: must be one of rectangle, circle, tube, "
                                                "properties, resultants, got 'square'"),
    ('end = ["1 m", "0 m"]', 'end = ["0 m", "0 m"]', "beams.rod.end: must differ from start"),
    ('point = "rod.E"', 'point = "rod.F"', "sensors.gauge.point: body 'rod' has no point 'F'"),
    ("elements = 4", "elements = 0", "beams.rod.elements: must be a positive whole number"),
])
def test_a_bad_beam_is_reported_at_its_place(old, new, expected):
    found = problems(edited(old, new))
    assert any(p.startswith(expected) for p in found), found


def test_a_tube_bore_must_be_inside_and_resultants_take_no_material():
    text = edited('section = { shape = "rectangle", width = "20 mm", height = "10 mm" }',
                  'section = { shape = "tube", outer_diameter = "20 mm", inner_diameter = "25 mm" }')
    assert "beams.rod.section.inner_diameter: must be smaller than outer_diameter = 20 mm (the bore is inside the " \
           "tube), got 25 mm" in problems(text)
    text = edited('section = { shape = "rectangle", width = "20 mm", height = "10 mm" }',
                  'section = { shape = "resultants", axial_stiffness = "1 MN", shear_stiffness = "1 MN", '
                  'bending_stiffness = "10 N m^2", mass_per_length = "1 kg/m", rotary_inertia_per_length = "1e-6 kg m" }')
    assert any(p.startswith("beams.rod.material: is not used by a section given by its resultants")
               for p in problems(text))


def test_a_gauge_must_sit_on_a_beam_and_a_loose_beam_is_an_error():
    m = flexible_pendulum()
    m.add_body("block", 1.0, 0.01, points={"c": (0, 0)}, position=(1, 0))
    m.add_revolute("weld", "rod.end", "block.c")
    m.add_strain_gauge("wrong", "block.c")
    with pytest.raises(jp.ModelError) as info:
        jp.loads(m.to_toml())
    assert [str(p) for p in info.value.problems] == [
        "sensors.wrong.point: must be a point of a beam or modal body; 'block' is a rigid body (beams and modal "
        "bodies: rod)"]
    loose = PENDULUM.replace('[joints.pin]\ntype = "revolute"\nfirst = "ground.O"\nsecond = "rod.start"\n', "")
    assert "beams.rod: is connected to nothing: no joint or force element refers to it (write free = true if it " \
           "is meant to move freely)" in problems(loose)


def test_the_builder_reads_beam_arguments_as_the_file_does():
    m = jp.Model()
    with pytest.raises(jp.ModelError) as info:
        m.add_beam("b", (0, 0), (1, 0), section=sections.rectangle("-1 mm", "10 mm"), material=STEEL, elements=2)
    assert [str(p) for p in info.value.problems] == ["beams.b.section.width: must be > 0, got -1 mm"]


def test_check_lists_the_euler_bernoulli_frequencies_of_each_beam():
    # spin-up beam: L = 10 m, EI = 1.4e4 N m^2, rho A = 1.2 kg/m, 4 quadratic elements; beta L of a uniform
    # beam clamped-free 1.8751, 4.6941, free-free 4.7300 (Blevins 1979, table 8-1); shear and rotary
    # inertia (L/r = 1414) lower them by less than 1e-4; the coarse mesh raises the second clamped and the first
    # free-free one by 0.35 % (the second free-free by 2.5 %: 4 elements are few for it)
    info = jp.load(EXAMPLES / "spin_up_beam.toml").check()
    modes = info["beam_frequencies"]["beam"]
    unit = math.sqrt(1.4e4 / 1.2) / 10.0 ** 2 / (2 * math.pi)
    for computed, beta_l in zip(modes["clamped"], (1.87510407, 4.69409113)):
        assert computed == pytest.approx(beta_l ** 2 * unit, rel=5e-3)
    for computed, beta_l in zip(modes["free_free"][:1], (4.73004074,)):
        assert computed == pytest.approx(beta_l ** 2 * unit, rel=5e-3)
    assert info["degrees_of_freedom"] == 9 * 3 - 3  # the beam's nodes less the clamp (the hub is driven)


def test_check_command_prints_the_beam_table(capsys):
    from jointplay.cli import app
    from typer.testing import CliRunner

    result = CliRunner().invoke(app, ["check", str(EXAMPLES / "spin_up_beam.toml")])
    assert result.exit_code == 0, result.output
    assert "flexible links" in result.output and "0.6045" in result.output
    assert "24 elastic of the beams" in result.output


def test_max_order_reaches_the_integrator_and_is_checked():
    m = jp.load(EXAMPLES / "spin_up_beam.toml")
    with pytest.raises(jp.ModelError, match=r"simulation.max_order: must be a whole number from 1 to 5, got 6"):
        m.simulate(0.1, method="bdf", max_order=6)
    with pytest.raises(jp.ModelError, match=r"simulation.max_order: must be a whole number from 1 to 5"):
        jp.loads(PENDULUM + "\n[simulation]\nmax_order = 7\n")
    # order 1 (backward Euler) damps the beam's vibration that order 2 keeps: a measurable difference
    runs = {order: m.simulate(1.0, method="bdf", max_order=order, stabilization="baumgarte", rtol=1e-4,
                              output_step=0.01) for order in (1, 2)}
    assert runs[1].options["max_order"] == 1
    assert not np.array_equal(runs[1]["root.bending_moment"], runs[2]["root.bending_moment"])


def test_speed_ramp_helper_matches_its_closed_form():
    m = jp.Model("ramp")
    m.add_ground_point("O", (0, 0))
    m.add_body("disc", 1.0, 0.1, points={"O": (0, 0)})
    m.add_revolute("axis", "ground.O", "disc.O")
    m.add_driver("spin", "axis", fn.speed_ramp("60 rpm", "2 s"))
    r = m.simulate(3.0, output_step=0.25)
    w, ramp = 2 * math.pi, 2.0
    t = r.time
    expected = np.where(t <= ramp, w / ramp * (t ** 2 / 2 + (ramp / (2 * math.pi)) ** 2 * (np.cos(2 * math.pi * t / ramp) - 1)),
                        w * t - w * ramp / 2)
    assert np.allclose(r["disc.angle"], expected, atol=1e-9)
    assert jp.loads(m.to_toml()).to_spec() == m.to_spec()


def test_plausibility_warns_of_a_density_slip_and_a_stubby_beam():
    text = edited('density = "7850 kg/m^3"', 'density = "7.85 kg/m^3"')
    text = text.replace('end = ["1 m", "0 m"]', 'end = ["15 mm", "0 mm"]').replace('E = "250 mm"', 'E = "5 mm"')
    from jointplay.modelfile import plausibility

    found = [str(p) for p in plausibility(jp.loads(text).to_spec())]
    assert any(p.startswith("beams.rod.material.density: 7.85 kg/m^3 is outside the range of solids") for p in found)
    assert any(p.startswith("beams.rod.section: the section is 10 mm deep and the beam 15 mm long") for p in found)


def test_rigid_fit_recovers_a_rigid_motion_exactly():
    rng = np.random.default_rng(3)
    reference = rng.normal(size=(7, 2))
    c, s = math.cos(0.7), math.sin(0.7)
    moved = reference @ np.array([[c, s], [-s, c]]) + (0.3, -1.2)
    assert np.allclose(plots.rigid_fit(reference, moved), moved, atol=1e-12)


def test_a_flexible_pendulum_swings_with_its_strain_gauge_and_figures(tmp_path):
    m = flexible_pendulum()
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a steel link is plausible
        r = m.simulate(0.3, method="bdf", max_order=2, stabilization="baumgarte", rtol=1e-6, output_step=1e-3)
    # the gauge's fibre strain is the axis strain less fibre x curvature
    assert np.allclose(r["gauge.axial_strain"], r["gauge.axis_strain"] - 0.005 * r["gauge.curvature"], atol=1e-15)
    # a bar released horizontally bends under its weight: the bending moment at a quarter length, in the
    # quasi-static limit of a pinned bar in free fall about its pin, is of order rho A g L^2 / 10 (about 0.3 N m)
    assert 0.05 < np.max(np.abs(r["gauge.bending_moment"])) < 2.0
    paths = plots.standard_figures(r, tmp_path)
    names = {p.name for p in paths}
    assert {"shapes_rod.png", "strain_gauge.png"} <= names
    assert all(p.stat().st_size > 10_000 for p in paths)


def test_spin_up_example_stretches_as_the_closed_form_says(tmp_path):
    import spin_up_beam

    results = spin_up_beam.main(["--out", str(tmp_path)])
    s = spin_up_beam.steady_state(results)
    # Simo and Vu-Quoc (1986): at a steady 6 rad/s a bar stretches rho A w^2 L^3 / (3 EA) = 0.514 mm and its root
    # carries rho A w^2 L^2 / 2 = 2160 N; the mesh of 4 quadratic elements and the vibration the ramp leaves
    # (averaged over the last 2 s) keep the stretch within 1 %, the root force (recovered at the end of an
    # element, extrapolated from its Gauss points) within 2 %
    assert s["stretch"] == pytest.approx(s["stretch_closed_form"], rel=0.01)
    assert s["root_force"] == pytest.approx(s["root_force_closed_form"], rel=0.02)
    assert (tmp_path / "spin_up_beam.png").stat().st_size > 10_000
    assert (tmp_path / "spin_up_beam_shapes.png").stat().st_size > 10_000


def test_the_structured_jacobian_spends_fewer_right_hand_sides_and_agrees():
    m = jp.load(EXAMPLES / "spin_up_beam.toml")
    options = {k: v for k, v in m.simulation.items() if k != "t_end"}
    runs = {how: m.simulate(3.0, **options, jacobian=how) for how in ("finite_difference", "structured")}
    fd, structured = (runs[k].statistics for k in ("finite_difference", "structured"))
    # a finite-difference Jacobian costs n + 1 = 61 right-hand sides, a structured one 1 (plus force passes)
    assert fd["jacobian_rhs_evaluations"] == 61 * fd["jacobian_evaluations"]
    assert structured["jacobian_rhs_evaluations"] == structured["jacobian_evaluations"]
    assert structured["rhs_evaluations"] < fd["rhs_evaluations"]
    # both follow the same motion to within the integration tolerance (rtol 1e-5 of the 10 m beam, times the
    # growth of the error over 3 s of vibration): the tip within 1 mm
    tip = [np.hypot(*[runs[k][f"beam.node8_{c}"] for c in "xy"]) for k in ("finite_difference", "structured")]
    assert np.max(np.abs(tip[0] - tip[1])) < 1e-3
    with pytest.raises(jp.ModelError, match="simulation.jacobian: must be one of"):
        m.simulate(0.1, method="bdf", jacobian="analytic")


def test_flexible_rod_example_runs_beside_the_rigid_one(tmp_path):
    import flores_flexible_rod as example

    runs = example.main(["--out", str(tmp_path), "--revolutions", "0.5"])
    assert all(r.error is None for r in runs.values())
    # the same rod: its mass as a beam is the rigid rod's
    bodies = {b["name"]: b for b in example.build_model().check()["bodies"]}
    assert bodies["rod"]["kind"] == "beam" and bodies["rod"]["mass"] == pytest.approx(0.21, rel=1e-12)
    rows = example.compare(runs)
    # up to the first impact the motion is smooth and the same (the rod barely bends before the journal
    # crosses the clearance), so the first impact comes at the same sample; the rod's compliance in series
    # with the contact softens that impact, so its peak force is lower than with the rigid rod
    assert rows["flexible"]["first_impact_time"] == rows["rigid"]["first_impact_time"]
    first = {}
    for name, results in runs.items():
        contact = results["B.contact"] > 0.5
        onset = int(np.argmax(contact))
        end = onset + int(np.argmax(~contact[onset:]))
        first[name] = results["B.fn"][onset:end].max()
    assert first["flexible"] < first["rigid"]
    assert (tmp_path / "flores_flexible_rod.png").stat().st_size > 10_000


def test_options_that_integrate_a_beam_badly_are_warned_of():
    m = flexible_pendulum()
    with pytest.warns(jp.JointplayWarning) as caught:
        m.simulate(1e-4, method="bdf")
    messages = [str(w.message) for w in caught]
    assert any(s.startswith("simulation.max_order: orders above 2 are not A-stable") for s in messages)
    assert any(s.startswith("simulation.stabilization: a projection after each step strains the beam") for s in messages)
    with pytest.warns(jp.JointplayWarning, match=r"simulation.method: dopri5 with a beam"):
        m.simulate(1e-5)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        m.simulate(1e-4, method="bdf", max_order=2, stabilization="baumgarte")
