"""Results, results files, the summary and the standard figures of a spatial run.

The model: a crank turned at one revolution a second about the global z axis (revolute joint and angle
driver), a bob hung from its end by a spherical joint and swinging under gravity, and a slider moved
along the global x axis by a sine driver of a translational joint. References outside the code under
test: the centripetal acceleration omega^2 r of a point of a crank turning at constant speed, the slider's
acceleration, the second derivative of its sine, and SciPy's rotations for the Euler angles of the recorded
quaternions.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from matplotlib.lines import Line2D
from typer.testing import CliRunner

import jointplay as jp
from jointplay import functions
from jointplay.cli import app
from jointplay.plots import default_channels, standard_figures
from jointplay.plots_spatial import (euler_channels, orientation_figure, paths_figure, reactions_figure,
                                     spatial_bodies, spatial_joints)
from jointplay.results import open_results

runner = CliRunner()

OMEGA = 2 * math.pi  # crank speed [rad/s]
CRANK_RADIUS = 0.1  # O to B [m]
STROKE, FREQUENCY = 0.02, 2.0  # slider's sine amplitude [m] and frequency [Hz]
GUIDE = {"matrix": [[0, 0, 1], [1, 0, 0], [0, 1, 0]]}  # marker z along the global x axis


def crank_bob_slider() -> jp.Model:
    m = jp.Model("crank_bob_slider", gravity=[0, 0, -9.81], kinematics="spatial")
    m.add_ground_point("O", [0.0, 0.0, 0.0])
    m.add_ground_point("S", [0.0, 0.3, 0.0], axes=GUIDE)
    m.add_body("crank", mass=0.2, inertia={"principal": [1e-5, 2e-4, 2e-4]}, position=[0.05, 0.0, 0.0],
               points={"O": [-0.05, 0.0, 0.0], "B": [0.05, 0.0, 0.0]})
    m.add_body("bob", mass=0.5, inertia={"principal": [2e-3, 2e-3, 1e-4]}, position=[0.1, 0.0, -0.2],
               orientation={"euler": ["20 deg", "10 deg", "5 deg"], "sequence": "ZXZ"}, euler_sequence="ZXZ",
               velocity=[0.0, 0.3, 0.0], points={"B": [0.0, 0.0, 0.2]})
    m.add_body("slider", mass=1.0, inertia={"principal": [1e-4, 1e-4, 1e-4]}, position=[0.0, 0.3, 0.0],
               points={"S": {"position": [0.0, 0.0, 0.0], "axes": GUIDE}})
    m.add_revolute("O", "ground.O", "crank.O")
    m.add_spherical("B", "crank.B", "bob.B")
    m.add_translational("guide", "ground.S", "slider.S")
    m.add_driver("motor", "O", functions.constant_speed(OMEGA))
    m.add_driver("push", "guide", functions.sine(STROKE, FREQUENCY))
    return m


@pytest.fixture(scope="module")
def run() -> jp.Results:
    return crank_bob_slider().simulate(0.5, rtol=1e-9, atol=1e-11, output_step=0.005)


def test_every_spatial_channel_and_its_unit_survive_the_results_file(run, tmp_path):
    kinds = {"x": "m", "qw": "-", "vx": "m/s", "wx": "rad/s", "ax": "m/s^2", "alpha_x": "rad/s^2",
             "wx_global": "rad/s", "euler_zxz_1": "rad"}
    for quantity, unit in kinds.items():
        assert run.unit(f"bob.{quantity}") == unit
    assert {run.unit(f"B.{q}") for q in ("fx", "f", "joint_fz")} == {"N"}
    assert {run.unit(f"B.{q}") for q in ("mx", "joint_mz")} == {"N m"}
    assert run.unit("motor.torque") == "N m" and run.unit("push.force") == "N"
    for name, options in (("classic.nc", {}), ("compressed.nc", {"compress": True})):
        back = open_results(run.save(tmp_path / name, **options))
        assert back.channels == run.channels
        written, kept = back.to_xarray(), run.to_xarray()
        for channel in run.channels:
            assert back.unit(channel) == run.unit(channel)
            assert written[channel].attrs["description"] == kept[channel].attrs["description"] != ""
            np.testing.assert_array_equal(back[channel], run[channel])
        assert back.spec == run.spec  # the spatial model, bit for bit
    csv = tmp_path / "run.csv"
    run.save(csv)
    header = csv.read_text().splitlines()[0]
    assert "bob.qw [-]" in header and "bob.euler_zxz_3 [rad]" in header and "B.joint_mx [N m]" in header


def test_euler_channels_are_the_intrinsic_angles_of_the_recorded_quaternions(run):
    from scipy.spatial.transform import Rotation

    quaternion = np.column_stack([run[f"bob.q{c}"] for c in "xyzw"])
    expected = Rotation.from_quat(quaternion).as_euler("ZXZ")
    recorded = np.column_stack([run[name] for name in euler_channels(run, "bob")])
    assert np.max(np.abs(np.angle(np.exp(1j * (recorded - expected))))) < 1e-12


def test_point_acceleration_of_a_crank_turning_at_constant_speed_is_centripetal(run):
    ax, ay, az = run.point_acceleration("crank.B")
    # omega^2 r towards O, about 3.95 m/s^2 (measured within 2e-13 relative, the constraint residual)
    assert np.allclose(np.sqrt(ax**2 + ay**2 + az**2), OMEGA**2 * CRANK_RADIUS, rtol=1e-9)
    angle = OMEGA * run.time
    assert np.allclose(ax, -OMEGA**2 * CRANK_RADIUS * np.cos(angle), rtol=0, atol=1e-9)
    ax_slider, _, _ = run.point_acceleration("slider.S")
    omega_s = 2 * math.pi * FREQUENCY
    assert np.allclose(ax_slider, -STROKE * omega_s**2 * np.sin(omega_s * run.time), rtol=0, atol=1e-9)


def test_summary_reports_spatial_peaks_and_point_accelerations(run):
    s = run.summary()
    assert set(s["peak_forces"]) == {"O.f", "B.f", "guide.f", "motor.torque", "push.force"}
    # the core tracks the crank point's acceleration at every step: omega^2 r
    assert s["point_accelerations"]["crank.B"] == pytest.approx(OMEGA**2 * CRANK_RADIUS, rel=1e-9)
    assert s["clearance_joints"] == {}


def test_summary_from_samples_gives_the_same_point_acceleration(run):
    sampled = jp.Results(run.time, run.channels, [run.unit(n) for n in run.channels],
                         [""] * len(run.channels), run.channel_block(0, len(run)),
                         run.statistics, run.diagnostics, spec=run.spec, options=run.options)
    s = sampled.summary()
    assert s["extrema_source"] == "samples"
    assert s["point_accelerations"]["crank.B"] == pytest.approx(OMEGA**2 * CRANK_RADIUS, rel=1e-9)


def lines(fig) -> list[Line2D]:
    return [line for ax in fig.axes for line in ax.get_lines()]


def test_path_figure_draws_the_centre_of_mass_channels_in_mm(run):
    fig = paths_figure(run)
    assert "centre-of-mass paths" in fig._suptitle.get_text()
    curves = {(ax.get_xlabel(), ax.get_ylabel(), line.get_label()): line for ax in fig.axes
              for line in ax.get_lines() if not line.get_label().startswith("_")}
    assert len(curves) == 3 * 3  # three projections of three bodies
    np.testing.assert_array_equal(curves[("x [mm]", "z [mm]", "bob")].get_xdata(), run["bob.x"] * 1e3)
    np.testing.assert_array_equal(curves[("y [mm]", "z [mm]", "bob")].get_xdata(), run["bob.y"] * 1e3)
    np.testing.assert_array_equal(curves[("y [mm]", "z [mm]", "bob")].get_ydata(), run["bob.z"] * 1e3)


def test_orientation_figure_draws_euler_angles_in_degrees_and_global_rates(run):
    fig = orientation_figure(run, "bob")
    assert "orientation of bob (intrinsic ZXZ Euler angles" in fig._suptitle.get_text().replace("\n", " ")
    drawn = {line.get_label(): line.get_ydata() for line in lines(fig)}
    np.testing.assert_array_equal(drawn["angle 2 (bob.euler_zxz_2)"], np.degrees(run["bob.euler_zxz_2"]))
    np.testing.assert_array_equal(drawn["bob.wz_global"], run["bob.wz_global"])


def test_reaction_figure_draws_the_joint_force_and_moment(run):
    fig = reactions_figure(run, "B")
    assert "reaction of joint B" in fig._suptitle.get_text()
    drawn = {line.get_label(): line.get_ydata() for line in lines(fig)}
    for quantity in ("fx", "fy", "fz", "f", "mx", "my", "mz"):
        np.testing.assert_array_equal(drawn[f"B.{quantity}"], run[f"B.{quantity}"])
    assert [ax.get_ylabel() for ax in fig.axes] == ["force [N]", "moment [N m]"]


def test_standard_figures_of_a_spatial_run(run, tmp_path):
    assert spatial_bodies(run) == ["crank", "bob", "slider"]
    assert spatial_joints(run) == ["O", "B", "guide"]
    assert default_channels(run) == ["slider.ax", "O.f", "B.f", "guide.f", "motor.torque", "push.force"]
    written = standard_figures(run, tmp_path, fmt="svg")
    assert sorted(p.name for p in written) == sorted(
        ["time_histories.svg", "paths.svg", "orientation_crank.svg", "orientation_bob.svg",
         "orientation_slider.svg", "reactions_O.svg", "reactions_B.svg", "reactions_guide.svg"])
    assert all(p.stat().st_size > 0 for p in written)


def test_plot_command_on_a_spatial_results_file(run, tmp_path):
    path = run.save(tmp_path / "run.nc")
    result = runner.invoke(app, ["plot", str(path), "-o", str(tmp_path / "figures")])
    assert result.exit_code == 0, result.output
    assert (tmp_path / "figures" / "paths.png").is_file() and (tmp_path / "figures" / "reactions_B.png").is_file()
    refused = runner.invoke(app, ["plot", str(path), "--crank", "crank"])
    assert refused.exit_code == 2
    assert "'crank' in" in refused.output and "is a spatial body" in " ".join(refused.output.split())


def test_point_acceleration_of_the_ball_is_the_same_seen_from_either_body(run):
    # the spherical joint holds crank.B and bob.B together: one point, one acceleration, whatever the bob's
    # turning (its alpha x r and omega x (omega x r) terms are far from zero)
    crank, bob = np.array(run.point_acceleration("crank.B")), np.array(run.point_acceleration("bob.B"))
    assert np.max(np.abs(run["bob.alpha_x"])) > 1.0 and np.max(np.abs(run["bob.wx"])) > 1.0
    # measured 8e-12 m/s^2 of 3.9 m/s^2 (the constraint's residual at rtol 1e-9)
    assert np.max(np.abs(crank - bob)) < 1e-9 * np.max(np.abs(bob))
