"""Every example script runs, and its headline numbers are sane."""

import runpy
from pathlib import Path

import numpy as np
import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def test_every_python_example_is_covered_here():
    covered = {"flores_slider_crank_dry", "flores_slider_crank_ideal", "paper001_slider_crank_dry",
               "flores_slider_crank_lubricated", "paper001_parametric_study",
               "paper000_joint_models",  # has its own tests/test_paper000_example.py
               # the physics of these two: tests/physics/test_singular_four_bar.py and
               # tests/physics/test_redundant_double_parallelogram.py
               "parallelogram_four_bar", "double_parallelogram", "hydraulic_boom",
               "spin_up_beam", "flores_flexible_rod",  # tests/test_beams.py
               "four_bar_flexible_coupler",
               "paper003_breaker",  # tests/test_paper003_breaker.py
               "spatial_slider_crank",
               "paper002_cylinder_rig", "paper002_cylinder_study"}  # tests/test_paper002_rig.py
    assert {p.stem for p in EXAMPLES.glob("*.py")} == covered


def test_flores_dry_example_runs_two_revolutions_with_impacts():
    import flores_slider_crank_dry as example

    results = example.main([])
    assert results.error is None
    assert results.time[-1] == pytest.approx(example.revolutions_to_time(2.0))
    joint = results.summary()["clearance_joints"]["B"]
    assert joint["impacts"] > 10
    assert 0.2 < joint["contact_fraction"] < 0.9


def test_flores_ideal_example_runs_and_is_periodic():
    import flores_slider_crank_ideal as example

    results = example.main([])
    x, t = results["slider.x"], results.time
    one_turn = np.searchsorted(t, t[-1] / 2)
    # a kinematically driven ideal mechanism repeats itself every revolution
    assert x[one_turn] == pytest.approx(x[0], abs=1e-9)
    assert np.max(np.abs(results["B.f"])) > 0


def test_paper001_example_runs_with_the_adams_method():
    runpy.run_path(str(EXAMPLES / "paper001_slider_crank_dry.py"), run_name="not_main")
    import paper001_slider_crank_dry as example

    results = example.main(["--revolutions", "0.5"])
    assert results.error is None
    assert results.options["method"] == "adams"
    assert results.summary()["clearance_joints"]["B"]["impacts"] >= 1


def test_flores_lubricated_example_compares_dry_and_lubricated(tmp_path):
    import flores_slider_crank_lubricated as example

    runs = example.main(["--out", str(tmp_path), "--revolutions", "1"])
    assert set(runs) == {"dry", "lubricated"}
    assert (tmp_path / "flores_dry_vs_lubricated.png").stat().st_size > 10_000
    assert runs["lubricated"]["B.film_min"].min() > 0


def test_paper001_study_writes_its_figures_and_table(tmp_path):
    import paper001_parametric_study as example

    study, rows = example.main(["--out", str(tmp_path), "--revolutions", "0.5"])
    assert len(rows) == 11 and {r["series"] for r in rows} == {"clearance", "speed", "viscosity"}
    for name in ("paper001_clearance.png", "paper001_speed.png", "paper001_viscosity.png",
                 "paper001_film_min.csv", "paper001_film_min.md"):
        assert (tmp_path / name).exists()


def test_parallelogram_four_bar_example_runs_through_its_flat_positions(tmp_path):
    import parallelogram_four_bar as example

    results = example.main(["--out", str(tmp_path), "--t-end", "2"])
    assert results.error is None
    assert results.time[-1] == pytest.approx(2.0)
    assert example.flat_passages(results) >= 2  # at about 0.71 s and 1.22 s
    assert (tmp_path / "parallelogram_four_bar.png").stat().st_size > 10_000


def test_double_parallelogram_example_runs_with_its_redundant_bar(tmp_path):
    import double_parallelogram as example

    results = example.main(["--out", str(tmp_path), "--t-end", "2"])
    assert results.error is None
    assert results.time[-1] == pytest.approx(2.0)
    assert example.flat_passages(results) >= 2
    assert (tmp_path / "double_parallelogram.png").stat().st_size > 10_000


def test_hydraulic_boom_example_is_its_model_file():
    import hydraulic_boom as example

    import jointplay as jp

    loaded = jp.load(EXAMPLES / "hydraulic_boom.toml")
    assert example.build_model().to_spec() == loaded.to_spec()
    assert loaded.simulation == {"t_end": example.T_END, "method": "dopri5", "rtol": 1e-8, "atol": 1e-10,
                                 "output_step": 1e-3}


def test_hydraulic_boom_example_raises_the_boom_by_the_stroke_the_valve_commands(tmp_path):
    import hydraulic_boom as example

    results = example.main(["--out", str(tmp_path)])
    assert results.error is None
    assert results.time[-1] == pytest.approx(example.T_END)
    stroke = results["lift.stroke"]
    # the pistons displace what the valve delivers, less the oil compressed by the 1.2 bar the cap
    # pressure gains (V dp / beta = 3e-8 m^3, 0.01 mm of stroke)
    assert stroke[-1] - stroke[0] == pytest.approx(example.COMMANDED_STROKE, abs=0.05e-3)
    # held by the sticking seal before the valve opens (0.5 s) and after it has closed (3.5 s)
    periods = example.stick_periods(results)
    assert periods[0][0] == 0.0 and 0.5 < periods[0][1] < 0.6
    assert 3.3 < periods[-1][0] < 3.5 and periods[-1][1] == pytest.approx(example.T_END)
    # sliding at 36 mm/s while the valve is fully open (the oil's compression moves it by 6e-5), 1200
    # Stribeck velocities, where the bristle damping has faded: the kinetic force of paper 002's seal
    open_ = (results.time > 1.5) & (results.time < 2.5)
    assert results["lift.rate"][open_] == pytest.approx(example.COMMANDED_SPEED, rel=1e-3)
    assert results["lift.friction"][open_] == pytest.approx(340.0, abs=0.01)
    assert (tmp_path / "hydraulic_boom.png").stat().st_size > 10_000
    assert (tmp_path / "hydraulic_boom.nc").exists()


def test_four_bar_example_reads_its_coupler_from_matrices_and_its_rigid_twin_weighs_the_same(tmp_path):
    import four_bar_flexible_coupler as example

    runs = example.main(["--out", str(tmp_path), "--time", "0.08"])
    assert all(r.error is None for r in runs.values())
    info = example.build_model().check()
    coupler = next(b for b in info["bodies"] if b["name"] == "coupler")
    mass, inertia, _ = example.rigid_coupler()
    assert coupler["kind"] == "modal" and coupler["nodes"] == 10
    assert coupler["mass"] == pytest.approx(mass, rel=1e-12)  # the core's invariants, the example's rigid motions
    rigid, flexible = runs["rigid"], runs["flexible"]
    lag = np.interp(rigid.time, flexible.time, flexible["rocker.angle"]) - rigid["rocker.angle"]
    # a coupler whose first frequency held (about 510 Hz) is 20 times the crank's turning rate: it bends a little
    assert 1e-6 < np.max(np.abs(lag)) < 1e-3
    force = {name: np.max(np.hypot(r["B.fx"], r["B.fy"])) for name, r in runs.items()}
    assert force["flexible"] == pytest.approx(force["rigid"], rel=0.05)
    assert (tmp_path / "four_bar_flexible_coupler.png").stat().st_size > 10_000


def test_spatial_slider_crank_example_is_its_model_file():
    import spatial_slider_crank as example

    import jointplay as jp

    loaded = jp.load(EXAMPLES / "spatial_slider_crank.toml")
    assert example.build_model().to_spec() == loaded.to_spec()
    assert loaded.simulation == {"t_end": example.T_END, "method": "dopri5", "rtol": 1e-8, "atol": 1e-10,
                                 "output_step": 1e-3}


def test_spatial_slider_crank_example_moves_and_loads_as_its_geometry_and_power_balance_say(tmp_path):
    """Against tests/spatial_references.py (Haug's mechanism in the crank angle, independent of the engine):
    the slider at the crank angle theta = 90 deg + 2 pi t; the motor's torque from the power balance
    tau omega = dE/dt at constant omega, tau = m'(theta) omega^2 / 2 + V'(theta); and the ground's reactions
    (the revolute O on the crank, the guide on the slider) giving the centres of mass their accelerations,
    sum of forces = sum m (a - g) (Newton's second law for the whole mechanism)."""
    import spatial_slider_crank as example
    from spatial_references import SPATIAL_SLIDER_CRANK, slider_crank_mass, slider_crank_pose

    results = example.main(["--out", str(tmp_path)])
    assert results.error is None and results.time[-1] == pytest.approx(example.T_END)
    omega = 2 * np.pi  # 60 rpm
    theta = np.pi / 2 + omega * results.time
    slider = np.array([slider_crank_pose(angle)["slider"][0, 0] for angle in theta])
    # rtol 1e-8: measured 2e-11 m (slider) and 8e-11 N m (torque, peak 0.35 N m)
    assert np.max(np.abs(results["slider.x"] - slider)) < 1e-9
    derivatives = np.array([slider_crank_mass(angle)[1:] for angle in theta])
    torque = 0.5 * derivatives[:, 0] * omega**2 + derivatives[:, 1]
    assert np.max(np.abs(results["motor.torque"] - torque)) < 1e-8
    # the stroke the sampled run shows (1 ms samples miss the extremes by 4e-7 m) against the geometry's
    angles = np.linspace(0.0, 2 * np.pi, 3601)  # every 0.1 deg: misses the extremes by 6e-8 m
    travel = np.array([slider_crank_pose(angle)["slider"][0, 0] for angle in angles])
    assert np.ptp(results["slider.x"]) == pytest.approx(np.ptp(travel), abs=1e-6)
    ground = sum(np.stack([results[f"{joint}.f{c}"] for c in "xyz"], -1) for joint in ("O", "guide"))
    inertial = sum(SPATIAL_SLIDER_CRANK[f"{body}_mass"] * (np.stack([results[f"{body}.a{c}"] for c in "xyz"], -1)
                                                         - SPATIAL_SLIDER_CRANK["gravity"])
                   for body in ("crank", "rod", "slider"))
    assert np.max(np.abs(ground - inertial)) < 1e-9  # measured 4e-15 N of 27 N
    assert (tmp_path / "spatial_slider_crank.png").stat().st_size > 10_000
    assert (tmp_path / "spatial_slider_crank.nc").exists()
