"""Assembly that tells the truth (docs/model-files.md, "How a run starts"): a loop closed only by
straining a flexible body is refused as a rigid one is; matrix files need their units; plausibility
findings come before, and independently of, the assembly; a failed assembly says what it found; a
driver that moves the linkage away from its given angles is noted; a run stopped by the start position
or by a toggle position says so."""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import pytest
from typer.testing import CliRunner

import jointplay as jp
from jointplay.cli import app
from jointplay.errors import JointplayWarning, ModelError, SimulationError

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
sys.path.insert(0, str(EXAMPLES))

import four_bar_flexible_coupler as four_bar  # noqa: E402

runner = CliRunner()

BEAM_LOOP = """
[model]
name = "beam_loop"
gravity = [0, 0]
[ground]
points = {{ O = ["0 mm", "0 mm"], P = ["{reach}", "50 mm"] }}
[bodies.crank]
mass = "0.1 kg"
inertia = "1e-5 kg m^2"
position = ["0 mm", "25 mm"]
angle = "90 deg"
points = {{ O = ["-25 mm", "0 mm"], A = ["25 mm", "0 mm"] }}
[beams.rod]
start = ["0 mm", "50 mm"]
end = ["100 mm", "50 mm"]
section = {{ shape = "rectangle", width = "10 mm", height = "5 mm" }}
material = {{ youngs_modulus = "207 GPa", density = "7850 kg/m^3", poisson_ratio = 0.3 }}
elements = 4
[joints.O]
type = "revolute"
first = "ground.O"
second = "crank.O"
[joints.A]
type = "revolute"
first = "crank.A"
second = "rod.start"
[joints.B]
type = "revolute"
first = "rod.end"
second = "ground.P"
[drivers.motor]
joint = "O"
function = {{ kind = "constant_speed", rate = "0 rad/s", initial = "90 deg" }}
"""


def write(tmp_path: Path, text: str, name: str = "model.toml") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def test_a_beam_stretched_from_100_to_119_mm_by_assembly_is_refused_at_check_with_its_strain(tmp_path):
    path = write(tmp_path, BEAM_LOOP.format(reach="119 mm"))
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 2, result.output
    assert "the initial configuration cannot be assembled" in result.output
    assert ("beams.rod: rod cannot start as assembled at t = 0.000000e0 s: closing the loops stretches it from 100 mm "
            "to 119 mm between rod.start and rod.end, a strain of 19.0 %") in result.output
    with pytest.raises(ModelError, match="a rigid link of its given shape, which could not close the loop"):
        jp.load(path)


def test_a_beam_preloaded_by_a_fifth_of_a_percent_is_noted_at_check_and_run(tmp_path):
    path = write(tmp_path, BEAM_LOOP.format(reach="100.2 mm"))
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 0, result.output
    assert ("warning: beams.rod: closing the loops stretches it from 100.0 mm to 100.2 mm between rod.start and "
            "rod.end, a strain of 0.200 %: assembly preloads it") in " ".join(result.output.split())
    model = jp.load(path)
    with pytest.warns(JointplayWarning, match="beams.rod: closing the loops stretches it from 100.0 mm to 100.2 mm"):
        info = model.check()
    assert [p.location for p in info["assembly_notes"]] == ["beams.rod"]


def short_rocker_four_bar(factor: float) -> jp.Model:
    """The example's four-bar with its modal coupler (base 240 mm) and its rocker ``factor`` times 180 mm long."""
    model = four_bar.build_model(flexible=True)
    spec = model.to_spec()
    rocker = next(b for b in spec["bodies"] if b["name"] == "rocker")
    for point in rocker["points"]:
        point["position"] = [factor * point["position"][0], point["position"][1]]
    return jp.Model.from_spec(spec)


def test_a_modal_coupler_bent_to_close_a_loop_no_rigid_coupler_closes_is_refused():
    # a rocker of 72 mm: from the crank pin A (60, 0) mm to the rocker's pivot (190, 0) mm is 130 mm, less than
    # 240 - 72 mm, so no rigid coupler closes the loop (before: assembled bent, meganewtons at t = 0)
    with pytest.raises(SimulationError) as caught:
        short_rocker_four_bar(0.4).simulate(1e-3, method="dopri5")
    assert caught.value.stage == "assembly" and caught.value.element == "coupler"
    assert ("coupler cannot start as assembled at t = 0.000000e0 s: closing the loops compresses it from 240 mm to "
            "166 mm between coupler.A and coupler.B, a strain of 30.9 %") in caught.value.cause


def test_a_rocker_20_percent_short_is_closed_by_turning_the_links_not_by_bending_the_coupler():
    # 144 mm still closes the loop with rigid links, turned: the mass-weighted Newton alone bent the coupler
    # (a modal coordinate of -2 and 1.1 MN at B in the first millisecond); now the links turn, and say so
    model = short_rocker_four_bar(0.8)
    with pytest.warns(JointplayWarning) as caught:
        info = model.check()
    notes = {p.location: p.message for p in info["assembly_notes"]}
    assert notes["modal_bodies.coupler"].startswith("assembly moved it 0 mm and turned it -17.1 deg")
    assert notes["bodies.rocker"].startswith("assembly moved it 35.6 mm and turned it -22.0 deg")
    assert any(str(w.message).startswith("modal_bodies.coupler: assembly moved it") for w in caught)
    coupler = next(b for b in info["bodies"] if b["name"] == "coupler")
    first, n = coupler["coordinates"]
    assert max(abs(v) for v in info["initial_coordinates"][first + 3: first + n]) < 1e-9  # no modal amplitude
    with pytest.warns(JointplayWarning):
        results = model.simulate(1e-3, method="dopri5", rtol=1e-7, atol=1e-10)
    assert max((results["B.fx"] ** 2 + results["B.fy"] ** 2) ** 0.5) < 10.0  # N (before: 1.1e6)


def test_matrix_files_without_their_units_are_refused_at_each_unit_key(tmp_path):
    files = {key: str(Path(value)) for key, value in four_bar.FILES.items()}
    text = f"""
[modal_bodies.coupler]
matrices = {{ mass = "{files['mass']}", stiffness = "{files['stiffness']}", nodes = "{files['nodes']}" }}
interface = {{ A = 0, B = 6 }}
free = true
"""
    with pytest.raises(ModelError) as caught:
        jp.load(write(tmp_path, text))
    found = {p.location: p.message for p in caught.value.problems}
    assert found["modal_bodies.coupler.matrices.length_unit"] == (
        'missing required value: a unit of length, e.g. "mm"; the numbers in the files carry no unit, so the length '
        'unit they are written in must be given ("m" and "kg" for SI)')
    assert found["modal_bodies.coupler.matrices.mass_unit"].startswith(
        'missing required value: a unit of mass, e.g. "t" (with "mm") or "kg" (with "m")')


def test_the_coupler_in_mm_read_as_m_is_refused_by_assembly_too():
    # the second guard of the same slip: files in mm and t declared "m" and "kg" give a coupler 240 m long,
    # which the 190 mm loop would squeeze to 240 mm (before: exit 0 and 1.4e7 N)
    spec = four_bar.build_model(flexible=True).to_spec()
    a, angle = four_bar.coupler_pose()
    read_as_si = jp.Model("read_as_si")
    read_as_si.add_modal_body("coupler", matrices={**four_bar.FILES, "length_unit": "m", "mass_unit": "kg"},
                              position=a, angle=angle, interface={"A": 0, "B": 6}, points={"C": 8}, normal_modes=4)
    spec["modal_bodies"][0]["structure"] = read_as_si.to_spec()["modal_bodies"][0]["structure"]
    with pytest.raises(SimulationError, match=r"compresses it from 240000 mm to 250 mm between coupler\.A and "
                                              r"coupler\.B, a strain of 99\.9 %"):
        jp.Model.from_spec(spec).check()


FLORES = EXAMPLES / "flores_slider_crank_dry.toml"


def test_a_unit_slip_in_an_inertia_is_shown_first_and_not_called_locking():
    # 250 kg m^2 for 250 kg mm^2: before, "the mechanism is locked" and no plausibility warning
    result = runner.invoke(app, ["check", str(FLORES), "--set", "bodies.rod.inertia=250 kg m^2"])
    assert result.exit_code == 2, result.output
    output = " ".join(result.output.split())
    warning = output.index("warning: bodies.rod.inertia: 250 kg m^2 is 2.5e+06 times the typical value")
    failure = output.index("the initial configuration cannot be assembled")
    assert warning < failure
    assert ("bodies.rod: rod cannot start as assembled at t = 0.000000e0 s: its mass or inertia makes the start's "
            "velocities impossible to solve for, though the mechanism is not locked") in output
    assert "rod's inertia: 250 kg m^2, 6.94e4 kg at its 60.0 mm" in output
    assert "is locked" not in output
    # loading from Python gives the same finding with the plausibility findings after it
    with pytest.raises(ModelError) as caught:
        jp.load(FLORES, ["bodies.rod.inertia=250 kg m^2"])
    locations = [p.location for p in caught.value.problems]
    assert locations[0] == "bodies.rod" and "bodies.rod.inertia" in locations[1:]
    assert caught.value.problems[1].message.startswith("(plausibility, may explain the above)")


def test_a_140_tonne_slider_is_shown_by_plausibility_before_the_assembly_says_what_it_found():
    result = runner.invoke(app, ["check", str(FLORES), "--set", "bodies.slider.mass=140000 kg"])
    assert result.exit_code == 2, result.output
    output = " ".join(result.output.split())
    assert output.index("warning: bodies.slider.mass: 1.4e+05 kg is 4.67e+05 times") < output.index(
        "the initial configuration cannot be assembled")
    assert ("bodies.slider: slider cannot start as assembled at t = 0.000000e0 s: its mass or inertia makes the "
            "start's velocities impossible to solve for, though the mechanism is not locked") in output
    assert "slider's mass: 1.40e5 kg; a ratio of 2.02e6" in output and "is locked" not in output
    # from Python: the plausibility warning first, then the error
    model = jp.load(FLORES, ["bodies.slider.mass=140000 kg"], check=False)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with pytest.raises(SimulationError, match="though the mechanism is not locked"):
            model.check()
    assert str(caught[0].message).startswith("bodies.slider.mass: 1.4e+05 kg is")


def test_a_driver_starting_at_90_deg_against_a_crank_given_at_0_deg_is_noted_with_what_moved():
    model = jp.load(FLORES, ["drivers.motor.function.initial=90 deg"])
    with pytest.warns(JointplayWarning) as caught:
        info = model.check()
    messages = {p.location: p.message for p in info["assembly_notes"]}
    assert messages["drivers.motor"].startswith(
        "its value at the start (t = 0.000000 s) differs by 90.0 deg from the relative angle its joint has between "
        "the bodies as given; assembly moved the linkage to the driver's value")
    assert messages["bodies.crank"].startswith("assembly moved it 35.4 mm and turned it 90.0 deg")
    assert "bodies.slider" in messages and "bodies.rod" in messages
    assert any(str(w.message).startswith("drivers.motor: its value at the start") for w in caught)
    # the examples as given are not noted
    assert jp.load(FLORES)._assembled()["assembly_notes"] == []


def test_a_journal_started_outside_its_clearance_is_refused_as_a_start_position(tmp_path):
    # before: the run stopped at t = 0 with "the contact is too soft or the step too large"
    overrides = ["joints.B.lock_at_assembly=false", 'bodies.slider.position=["175 mm", "0 mm"]']
    result = runner.invoke(app, ["check", str(FLORES), *sum((["--set", o] for o in overrides), [])])
    assert result.exit_code == 2, result.output
    output = " ".join(result.output.split())
    assert ("joints.B: B cannot start as assembled at t = 0.000000e0 s: the start position puts the journal 4.50 mm "
            "into its bearing (eccentricity 5.00 mm, clearance 0.500 mm), beyond the bound 0.475 mm a run allows: "
            "the joint's initial_eccentricity or the bodies' given positions place it there") in output
    assert "too soft" not in output


TOGGLE = """
[model]
name = "slider_pushed_through_its_dead_centre"
gravity = [0, 0]
[ground]
points = { O = ["0 mm", "0 mm"], line = ["0 mm", "0 mm"] }
[bodies.crank]
mass = "0.30 kg"
inertia = "1e-4 kg m^2"
position = ["0 mm", "25 mm"]
angle = "90 deg"
points = { O = ["-25 mm", "0 mm"], A = ["25 mm", "0 mm"] }
[bodies.rod]
mass = "0.21 kg"
inertia = "2.5e-4 kg m^2"
position = ["54.544 mm", "25 mm"]
angle = "-24.624 deg"
points = { A = ["-60 mm", "0 mm"], B = ["60 mm", "0 mm"] }
[bodies.slider]
mass = "0.14 kg"
inertia = "1e-4 kg m^2"
position = ["109.087 mm", "0 mm"]
points = { B = ["0 mm", "0 mm"] }
[joints.O]
type = "revolute"
first = "ground.O"
second = "crank.O"
[joints.A]
type = "revolute"
first = "crank.A"
second = "rod.A"
[joints.guide]
type = "translational"
first = "ground.line"
second = "slider.B"
axis = [1, 0]
[joints.B]
type = "clearance_revolute"
bearing = "slider.B"
journal = "rod.B"
bearing_radius = "10 mm"
clearance = "0.5 mm"
length = "40 mm"
bearing_material = { youngs_modulus = "207 GPa", poisson_ratio = 0.3 }
journal_material = { youngs_modulus = "207 GPa", poisson_ratio = 0.3 }
contact = { law = "lankarani_nikravesh", restitution = 0.9 }
[drivers.push]
joint = "guide"
function = { kind = "constant_speed", rate = "1 m/s", initial = "109.087 mm" }
[simulation]
t_end = "100 ms"
"""


def test_a_slider_pushed_through_its_dead_centre_is_told_as_a_toggle_position(tmp_path):
    path = write(tmp_path, TOGGLE)
    result = runner.invoke(app, ["run", str(path), "-o", str(tmp_path / "toggle.nc"), "-q"])
    assert result.exit_code == 1, result.output
    output = " ".join(result.output.split())
    # the outer dead centre (170 mm) is reached at t = 60.9 ms; the run stops just after it
    assert "simulation failed (SingularConfiguration) at t = 0.06" in output
    assert "in push" in output
    assert "the driver pushes the linkage through a toggle (singular) position at t = 0.06" in output
    assert "too soft" not in output
    time = float(output.split("simulation failed (SingularConfiguration) at t = ")[1].split()[0])
    assert 0.0609 < time < 0.065


def test_the_examples_assemble_without_a_note():
    for name in ("flores_slider_crank_dry", "flores_slider_crank_lubricated", "paper001_slider_crank_dry",
                 "double_parallelogram", "parallelogram_four_bar", "hydraulic_boom", "spin_up_beam"):
        assert jp.load(EXAMPLES / f"{name}.toml")._assembled()["assembly_notes"] == [], name
    for flexible in (False, True):
        assert four_bar.build_model(flexible)._assembled()["assembly_notes"] == []


def test_the_same_slider_with_an_ideal_pin_is_told_as_a_toggle_position_too(tmp_path):
    # before: "constraints could not be satisfied at t = 6.091340e-2 s (residual 1.017e-7 in A)"
    i, j = TOGGLE.index("[joints.B]"), TOGGLE.index("[drivers.push]")
    text = TOGGLE[:i] + '[joints.B]\ntype = "revolute"\nfirst = "slider.B"\nsecond = "rod.B"\n' + TOGGLE[j:]
    with pytest.raises(SimulationError) as caught:
        jp.loads(text).simulate(0.1)
    assert caught.value.kind == "SingularConfiguration" and caught.value.element == "push"
    assert ("the driver pushes the linkage through a toggle (singular) position at t = 0.0609 s"
            in caught.value.cause)
    assert "so the joints cannot follow the driver" in caught.value.cause
