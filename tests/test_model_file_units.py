"""Model files: the units rule (bare numbers, the [units] table) and inputs that must never crash."""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

import jointplay as jp
from jointplay.cli import app

ROOT = Path(__file__).resolve().parents[1]
DRY = ROOT / "examples" / "flores_slider_crank_dry.toml"
LUBRICATED = ROOT / "examples" / "flores_slider_crank_lubricated.toml"
UNITS_MM = '[units]\nlength = "mm"\n\n'


def problems(text: str, overrides: list[str] | None = None) -> list[str]:
    with pytest.raises(jp.ModelError) as info:
        jp.loads(text, overrides)
    return [str(p) for p in info.value.problems]


def dry_text(old: str, new: str) -> str:
    text = DRY.read_text()
    assert old in text
    return text.replace(old, new)


# bare numbers ----------------------------------------------------------------

def test_bare_number_in_a_length_is_an_error_naming_the_unit_expected():
    text = dry_text('bearing_radius = "10 mm"\nclearance = "0.5 mm"', "bearing_radius = 10\nclearance = 0.5")
    assert problems(text) == [
        'joints.B.bearing_radius: a bare number needs a unit, e.g. "10 mm" (or declare [units] length = "mm"), got 10',
        'joints.B.clearance: a bare number needs a unit, e.g. "0.5 mm" (or declare [units] length = "mm"), got 0.5']


@pytest.mark.parametrize("override, message", [
    ("joints.B.clearance=0.1", 'joints.B.clearance: a bare number needs a unit, e.g. "0.1 mm" '
                               '(or declare [units] length = "mm"), got 0.1'),
    ("bodies.crank.mass=0.3", 'bodies.crank.mass: a bare number needs a unit, e.g. "0.3 kg" '
                              '(or declare [units] mass = "kg"), got 0.3'),
    ("bodies.rod.points.B=[60, 0]", 'bodies.rod.points.B: x component: a bare number needs a unit, e.g. "60 mm" '
                                    '(or declare [units] length = "mm"), got 60'),
    ("model.gravity=[0, -9.81]", 'model.gravity: y component: a bare number needs a unit, e.g. "-9.81 m/s^2" '
                                 '(or declare [units] acceleration = "m/s^2"), got -9.81'),
    ("drivers.motor.function.rate=523.6", 'drivers.motor.function.rate: a bare number needs a unit, e.g. '
                                          '"523.6 rpm" (or declare [units] angular_velocity = "rpm"), got 523.6'),
    ('joints.B.bearing_material.youngs_modulus="207e9"',
     'joints.B.bearing_material.youngs_modulus: a bare number needs a unit, e.g. "207e9 GPa" '
     '(or declare [units] pressure = "GPa"), got 207e9'),
    ("simulation.max_step=1e-4", 'simulation.max_step: a bare number needs a unit, e.g. "0.0001 ms" '
                                 '(or declare [units] time = "ms"), got 0.0001'),
    ('forces.f={ type = "point_force", point = "rod.B", fx = { kind = "table", times = ["0 s", 1e-3], '
     'values = ["0 N", "5 N"] } }', 'forces.f.fx.times[1]: a bare number needs a unit, e.g. "0.001 ms" '
                                    '(or declare [units] time = "ms"), got 0.001'),
])
def test_bare_numbers_are_errors_everywhere_including_overrides(override, message):
    assert problems(DRY.read_text(), [override])[0] == message


def test_bare_number_in_a_lubrication_key_is_an_error():
    text = LUBRICATED.read_text().replace('viscosity = "400 cP"', "viscosity = 0.4")
    assert problems(text) == ['joints.B.lubrication.viscosity: a bare number needs a unit, e.g. "0.4 cP" '
                              '(or declare [units] viscosity = "cP"), got 0.4']


def test_zero_and_plain_numbers_need_no_unit():
    model = jp.loads(DRY.read_text(), ["joints.B.initial_eccentricity=[0, 0]", "bodies.crank.angle=0",
                                       "joints.B.contact.restitution=0.8"])
    assert model.joint("B")["initial_eccentricity"] == [0.0, 0.0]


# the [units] table ---------------------------------------------------------------

def test_declared_length_unit_reads_bare_lengths_and_gives_the_same_model():
    text = dry_text('bearing_radius = "10 mm"\nclearance = "0.5 mm"', "bearing_radius = 10\nclearance = 0.5")
    declared = jp.loads(UNITS_MM + text)
    assert declared.to_spec() == jp.load(DRY).to_spec()
    override = jp.loads(UNITS_MM + DRY.read_text(), ["joints.B.clearance=0.1"])
    assert override.joint("B")["clearance"] == pytest.approx(1e-4, rel=1e-12)


def test_declared_units_do_not_derive_other_kinds():
    # a declared length and time leave velocities (and everything else) needing a unit
    text = '[units]\nlength = "mm"\ntime = "ms"\n\n' + DRY.read_text()
    assert problems(text, ["joints.B.onset_velocity_floor=1e-4"]) == [
        'joints.B.onset_velocity_floor: a bare number needs a unit, e.g. "0.0001 m/s" '
        '(or declare [units] velocity = "m/s"), got 0.0001']


def test_out_of_range_bare_value_is_shown_in_the_declared_unit():
    assert problems(UNITS_MM + DRY.read_text(), ["joints.B.clearance=-0.1"]) == [
        "joints.B.clearance: must be > 0, got -0.1 mm"]


@pytest.mark.parametrize("units, message", [
    ('lenght = "mm"', 'units.lenght: unknown kind of quantity (did you mean "length"?); kinds: length, mass, '
                      'inertia, time, angle, angular_velocity, angular_acceleration, velocity, acceleration, force, '
                      'torque, stiffness, damping, rotational_stiffness, rotational_damping, area, volume, '
                      'volume_flow, pressure, viscosity, frequency, density, second_moment_of_area, '
                      'bending_stiffness, mass_per_length, rotary_inertia_per_length'),
    ('length = "kg"', "units.length: must be a length (e.g. \"0.5 mm\"), got 'kg', which is a mass"),
    ('mass = "1 kg"', "units.mass: must be a unit without a number, e.g. \"kg\", got '1 kg'"),
    ("time = 0.001", 'units.time: must be a unit of time as a string, e.g. "ms", got 0.001'),
    ('angle = "rpm"', "units.angle: must be an angle (e.g. \"90 deg\"), got 'rpm', which is a frequency"),
])
def test_units_table_is_validated(units, message):
    assert problems(f"[units]\n{units}\n\n" + DRY.read_text()) == [message]


def test_units_table_must_be_a_table():
    assert problems('units = "mm"\n' + DRY.read_text()) == ["units: must be a table ([units]), got 'mm'"]


def test_written_model_keeps_units_and_loads_back():
    model = jp.loads(UNITS_MM + dry_text('clearance = "0.5 mm"', "clearance = 0.5"))
    text = model.to_toml()
    assert 'clearance = "0.0005 m"' in text and "[units]" not in text
    assert jp.loads(text).to_spec() == model.to_spec()


# other inputs that are errors, not crashes --------------------------------------

@pytest.mark.parametrize("key, value", [("cavitation", '"gumbel"'), ("grid", "[20, 8]"),
                                        ("ambient_pressure", '"1 bar"'), ("groove_supply_pressure", '"2 bar"')])
def test_reynolds_keys_on_a_closed_form_model_are_errors(key, value):
    text = LUBRICATED.read_text().replace('viscosity = "400 cP"', f'viscosity = "400 cP", {key} = {value}')
    assert problems(text) == [f"joints.B.lubrication.{key}: applies only to the reynolds_exact and reynolds_table "
                              "models, not to model = 'pinkus_sternlicht_long'; remove it or choose a Reynolds model"]


def test_reynolds_keys_are_accepted_on_a_reynolds_model():
    text = LUBRICATED.read_text().replace('model = "pinkus_sternlicht_long", viscosity = "400 cP"',
                                          'model = "reynolds_exact", viscosity = "400 cP", cavitation = "gumbel", '
                                          'grid = [24, 8], ambient_pressure = "0 Pa"')
    reynolds = jp.loads(text).joint("B")["lubrication"]["reynolds"]
    assert (reynolds["cavitation"], reynolds["n_circumferential"], reynolds["n_axial"]) == ("gumbel", 24, 8)


EMPTY = ("the model has no bodies: describe at least one as a [bodies.NAME] table with its mass and inertia "
         "(or a flexible link as a [beams.NAME] table)")


@pytest.mark.parametrize("text", ["", '[model]\nname = "nothing"\n', "[bodies]\n"])
def test_model_without_bodies_is_an_error(text):
    assert problems(text) == [f"bodies: {EMPTY}"]


@pytest.mark.parametrize("data, message", [
    (b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR", "is a binary file (a NUL byte at offset 8), not a TOML model file"),
    (b'[model]\nname = "caf\xe9"\n', "is not UTF-8 text (byte 0xe9 at offset 19); a model file is TOML text in UTF-8"),
])
def test_binary_model_file_is_a_clear_error(tmp_path, data, message):
    path = tmp_path / "model.toml"
    path.write_bytes(data)
    with pytest.raises(jp.ModelError) as info:
        jp.load(path)
    assert [str(p) for p in info.value.problems] == [f"{path}: {message}"]


@pytest.mark.parametrize("content, message", [
    (b"\x00\x01\x02", "is a binary file (a NUL byte at offset 0), not a TOML model file"),
    (b"", f"bodies: {EMPTY}"),
    (b'[model]\nname = "m"\n[bodies.a]\nmass = 1\ninertia = "1 kg m^2"\nfree = true\n',
     'bodies.a.mass: a bare number needs a unit, e.g. "1 kg" (or declare [units] mass = "kg"), got 1'),
    (LUBRICATED.read_bytes().replace(b'viscosity = "400 cP"', b'viscosity = "400 cP", cavitation = "gumbel"'),
     "joints.B.lubrication.cavitation: applies only to the reynolds_exact and reynolds_table models"),
])
@pytest.mark.parametrize("command", ["check", "run"])
def test_cli_exits_2_with_one_line_per_problem(tmp_path, content, message, command):
    path = tmp_path / "model.toml"
    path.write_bytes(content)
    output = ["-o", str(tmp_path / "out.nc")] if command == "run" else []
    result = CliRunner().invoke(app, [command, str(path), *output])
    assert result.exit_code == 2, result.output
    assert message in result.stderr
    assert "Traceback" not in result.output
