"""A parallelogram four-bar through its flat position (IFToMM benchmark A02 with N = 1;
examples/parallelogram_four_bar.toml, whose .py says what is the benchmark's and what is chosen).

At crank angles 0 and 180 deg the three bars lie on the ground line: the constraint Jacobian loses
a rank there and the parallelogram branch crosses the crossed (anti-parallelogram) one. The
engine must pass through without stopping and stay on the parallelogram branch, where the motion
obeys one equation (tests/physics/parallelogram_reference.py derives it from T and V):

    theta_ddot = -(6 g / (5 L)) cos(theta),   theta(0) = 90 deg, theta_dot(0) = -1 rad/s,

which SciPy integrates here to rtol 1e-10; the engine runs the model file's settings (dopri5,
rtol 1e-8). Before the robust constraint solution (8193766) the engine stopped at the first flat
position with a SimulationError ("singular constraint Jacobian ... dependent").
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp
import parallelogram_reference as ref

MODEL = Path(__file__).resolve().parents[2] / "examples" / "parallelogram_four_bar.toml"
L, M = 1.0, 1.0  # m, kg: every bar
THETA0, OMEGA0 = math.pi / 2, -1.0  # rad, rad/s
K = ref.theta_ddot_factor(n_bars=2, bar_mass=M, coupler_mass=M)  # 6/5

# Crank angle against the one-dof solution: 1e-5 rad. Integrated to rtol 1e-8 (engine) and 1e-10
# (reference) over 10 s (about 5 turns, 31 rad), their own errors are of order 1e-7 rad (seen: 4e-7); a relative error of the
# period of 3e-7 (a wrong effective inertia or gravity term, or a kick at each flat passage)
# accumulates to 31 rad x 3e-7 = 1e-5 rad, and a branch switch or a lost passage to radians.
ANGLE_TOLERANCE = 1e-5
# Off the parallelogram branch: the crossed branch turns the coupler by radians within a fraction of
# a turn. On the branch the coupler angle and rocker - crank are zero up to what the position
# tolerance of the drift control (1e-10 m) leaves free near the flat position, where those equations
# only fix the difference of the bar angles to about 1e-10 / (2 |theta|): 1e-5 rad at 5e-6 rad from flat.
BRANCH_TOLERANCE = 1e-5
# Energy: no dissipation; with rtol 1e-8 a drift of 1e-6 of the energy (20.45 J) is 2e-5 J, a
# hundred times what the integration error should leave; a passage that loses or gains energy at
# the flat position shows at once.
ENERGY_TOLERANCE = 1e-6


def run() -> jp.Results:
    return ref.run_model_file(MODEL)


def reference():
    return ref.one_dof_to_end_of(MODEL, K, L, THETA0, OMEGA0)


def test_model_file_and_python_example_are_the_same_model():
    assert ref.example_builds_the_model_file("parallelogram_four_bar", MODEL)
    assert K == pytest.approx(6 / 5, rel=1e-15)


def test_runs_to_the_end_through_the_flat_positions():
    results = run()
    assert results.error is None
    assert results.time[-1] == pytest.approx(jp.load(MODEL).simulation["t_end"])


def test_crank_angle_follows_the_one_degree_of_freedom_equation():
    results = run()
    theta, theta_dot = reference()(results.time)
    assert results.time.size > 900  # compared every 10 ms
    assert np.max(np.abs(ref.wrapped(results["crank.angle"] - theta))) < ANGLE_TOLERANCE
    # the angular velocity too, at the scale of its range (1 to 7 rad/s)
    assert np.max(np.abs(results["crank.omega"] - theta_dot)) < ANGLE_TOLERANCE * 10


def test_passes_the_flat_position_twice_per_turn():
    results = run()
    expected = ref.flat_passages(reference()(np.linspace(0.0, results.time[-1], 100_001))[0])
    assert expected == 10  # 10 s: from 90 deg to -1739 deg, about 5 turns
    assert ref.flat_passages(results["crank.angle"]) == expected


def test_stays_on_the_parallelogram_branch():
    results = run()
    assert np.max(np.abs(ref.wrapped(results["coupler.angle"]))) < BRANCH_TOLERANCE
    assert np.max(np.abs(ref.wrapped(results["rocker.angle"] - results["crank.angle"]))) < BRANCH_TOLERANCE
    # the coupler translates with the crank tip: its centre is half a ground link to the right of it
    theta = results["crank.angle"]
    assert np.max(np.abs(results["coupler.x"] - (L * np.cos(theta) + L / 2))) < BRANCH_TOLERANCE * L
    assert np.max(np.abs(results["coupler.y"] - L * np.sin(theta))) < BRANCH_TOLERANCE * L


def test_energy_is_conserved():
    results = run()
    energy = results["system.energy"]
    # T0 = (1/2)(2 m L^2/3 + m L^2) theta_dot^2, V0 = m g (L/2 + L + L/2) with the datum at y = 0
    expected = 0.5 * (2 * M * L**2 / 3 + M * L**2) * OMEGA0**2 + 2 * M * ref.G * L * math.sin(THETA0)
    assert energy[0] == pytest.approx(expected, rel=1e-9)
    assert np.max(np.abs(energy - energy[0])) / abs(energy[0]) < ENERGY_TOLERANCE
