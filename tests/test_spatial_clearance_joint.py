"""The spatial clearance revolute joint from the Python API and model files: its channels, the motion-mode
fractions of the summary (independent of the output sampling), located errors for bad dimensions, the ideal
variant, and the model-file round trip. The physics is validated in the core's tests
(``crates/jointplay-core/src/joint/spatial_clearance_revolute_tests.rs``,
``crates/jointplay-core/src/dynamics/spatial_clearance_joint_tests.rs``, ``spatial_clearance_tests.rs``)."""

from __future__ import annotations

import numpy as np
import pytest

import jointplay as jp
from jointplay.errors import ModelError
from jointplay.modelfile import loads, to_toml

MODES = ("free", "impact", "sliding", "sustained", "axial")


def journal_in_bore(**joint) -> jp.Model:
    """A 1 kg journal dropped in a 10 mm bore fixed to the ground, turning about the bore's x axis and its own,
    drifting along its axis: it bounces, tilts, slides and strikes a flange."""
    m = jp.Model("journal_in_bore", kinematics="spatial")
    m.set_gravity((0, "-9.81 m/s^2", 0))
    m.add_ground_point("P", (0, 0, 0))
    m.add_body("pin", mass="1 kg", inertia={"principal": ["1e-3 kg m^2", "1e-3 kg m^2", "5e-4 kg m^2"]},
               position=(0, 0, 0), velocity=(0, 0, "10 mm/s"), angular_velocity=("1 rad/s", 0, "20 rad/s"),
               points={"J": (0, 0, 0)})
    keys = dict(bore_radius="10 mm", clearance="0.5 mm", bearing_length="20 mm", axial_clearance="0.4 mm",
                flange_radius="15 mm", face_radius="16 mm", lock_at_assembly=False,
                contact={"law": "lankarani_nikravesh", "restitution": 0.8},
                friction={"law": "stiction", "static_coefficient": 0.15, "kinetic_coefficient": 0.1,
                          "stiction_velocity": "0.01 mm/s", "transition_velocity": "0.05 mm/s"})
    keys.update(joint)
    m.add_spatial_clearance_revolute("play", "ground.P", "pin.J", **keys)
    return m


@pytest.fixture(scope="module")
def run() -> jp.Results:
    return journal_in_bore().simulate(t_end=0.1, output_step=1e-4)


def test_the_joint_reports_its_candidates_measures_wrench_and_mode(run):
    for quantity in ("e_a_x", "e_m_y", "e_b_y", "tilt", "axial_position", "axial_gap_a", "penetration_a",
                     "penetration_fb", "fn_a", "fn_fa", "ft_b", "fx", "fy", "fz", "mx", "my", "mz", "f", "mode",
                     "axial_contact"):
        assert f"play.{quantity}" in run.channels, quantity
    assert run.unit("play.tilt") == "rad" and run.unit("play.fn_a") == "N" and run.unit("play.mx") == "N m"
    # the journal lands on the bottom of the bore: the eccentricities reach the clearance there
    assert run["play.e_m_y"].min() == pytest.approx(-5e-4, abs=2e-5)
    assert set(np.unique(run["play.mode"])) <= {0.0, 1.0, 2.0, 3.0}
    # the joint's force is the sum of its candidates' along the normals: at least the largest normal force
    total = run["play.fn_a"] + run["play.fn_b"]
    assert np.all(run["play.f"] >= 0.99 * np.maximum(run["play.fn_a"], run["play.fn_b"]) - 1e-9)
    assert total.max() > 0


def test_the_summary_gives_the_mode_fractions_whatever_the_output_sampling(run):
    joint = run.summary()["clearance_joints"]["play"]
    fractions = joint["mode_fractions"]
    assert set(fractions) == set(MODES)
    assert sum(fractions[m] for m in MODES[:4]) == pytest.approx(1.0, abs=1e-12)
    assert fractions["free"] > 0 and fractions["impact"] > 0 and fractions["sustained"] + fractions["sliding"] > 0
    assert joint["contact_fraction"] == pytest.approx(1.0 - fractions["free"], abs=1e-12)
    coarse = journal_in_bore().simulate(t_end=0.1, output_step=5e-3)
    assert coarse.summary()["clearance_joints"]["play"]["mode_fractions"] == fractions


def test_the_mode_channel_agrees_with_the_tally(run):
    # the sampled channel, each sample held to the next, against the core's tally at every step
    fractions = run.summary()["clearance_joints"]["play"]["mode_fractions"]
    mode, dt = run["play.mode"], np.diff(run.time)
    for k, name in enumerate(MODES[:4]):
        sampled = float(np.sum(dt * (mode[:-1] == k)) / (run.time[-1] - run.time[0]))
        assert sampled == pytest.approx(fractions[name], abs=0.02), name


@pytest.mark.parametrize(("keys", "where", "words"), [
    ({"clearance": "10 mm"}, "joints.play.clearance", "smaller than bore_radius"),
    ({"flange_radius": "9 mm"}, "joints.play.flange_radius", "greater than bore_radius"),
    ({"face_radius": "-1 mm"}, "joints.play.face_radius", "> 0"),
    ({"bearing_length": 0}, "joints.play.bearing_length", "> 0"),
    ({"mode_impact_duration": "-1 ms"}, "joints.play.mode_impact_duration", "> 0"),
])
def test_a_bad_dimension_gets_its_located_message(keys, where, words):
    with pytest.raises(ModelError) as caught:
        journal_in_bore(**keys).check()
    messages = [(p.location, p.message) for p in caught.value.problems]
    assert any(location == where and words in message for location, message in messages), messages


def test_a_planar_model_refuses_it_by_name():
    m = jp.Model("flat")
    with pytest.raises(ModelError, match="spatial_clearance_revolute.*spatial models"):
        m.add_spatial_clearance_revolute("j", "ground.A", "b.A", bore_radius="10 mm", clearance="0.5 mm",
                                         bearing_length="20 mm", axial_clearance="0.4 mm", flange_radius="15 mm",
                                         face_radius="16 mm", contact={"law": "hertz"})


def test_the_ideal_variant_holds_the_journal_on_an_ideal_revolute_joint():
    ideal = journal_in_bore().idealized()
    spec = ideal.to_spec()
    assert not spec.get("spatial_clearance_joints")
    assert {"type": "revolute", "name": "play", "first": "ground.P", "second": "pin.J"} in spec["spatial_joints"]


def test_a_model_file_round_trips_the_joint():
    model = journal_in_bore()
    text = to_toml(model)
    assert 'type = "spatial_clearance_revolute"' in text
    rebuilt = loads(text, name="again")
    assert rebuilt.to_spec()["spatial_clearance_joints"] == model.to_spec()["spatial_clearance_joints"]


def test_jointplay_run_prints_the_mode_fractions_and_the_results_file_keeps_them(tmp_path):
    from typer.testing import CliRunner

    from jointplay.cli import app

    path, out = tmp_path / "journal.toml", tmp_path / "journal.nc"
    path.write_text(to_toml(journal_in_bore()), encoding="utf-8")
    result = CliRunner().invoke(app, ["run", str(path), "--t-end", "0.05", "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "motion modes" in result.output and "axial contact" in result.output
    saved = jp.open_results(out).summary()["clearance_joints"]["play"]["mode_fractions"]
    assert sum(saved[m] for m in MODES[:4]) == pytest.approx(1.0, abs=1e-12)


@pytest.mark.parametrize("model", ["hamrock_short", "reynolds_exact"])
def test_a_lubricated_joint_reports_its_film(model):
    lubricated = journal_in_bore(lubrication={"model": model, "viscosity": "400 cP", "grid": [24, 8]}
                                 if model == "reynolds_exact" else {"model": model, "viscosity": "400 cP"})
    r = lubricated.simulate(t_end=0.005, output_step=1e-4, method="bdf")
    for quantity in ("film_min", "film_fx", "film_fy", "film_fz", "film_f", "peak_pressure", "film_weight", "film_mode"):
        assert f"play.{quantity}" in r.channels
    assert r["play.film_f"].max() > 0 and r["play.film_min"].min() < 5e-4
    # the dry joint has none of them
    assert "play.film_f" not in journal_in_bore().simulate(t_end=1e-3).channels


def test_a_lubricated_joint_needs_a_known_film_model():
    with pytest.raises(ModelError) as caught:
        journal_in_bore(lubrication={"model": "honey", "viscosity": "400 cP"}).check()
    assert any(p.location == "joints.play.lubrication.model" for p in caught.value.problems), caught.value.problems


def test_a_study_response_reads_a_mode_fraction(run):
    from jointplay.study.metrics import Response

    for mode in MODES:
        response = Response(name=f"{mode}_share", kind=f"{mode}_fraction", joint="play")
        assert response.evaluate(run) == run.summary()["clearance_joints"]["play"]["mode_fractions"][mode]
