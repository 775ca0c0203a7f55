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
# tolerance of the drift control (1e-11 m, a tenth of the model file's atol) leaves free near the flat
# position, where those equations only fix the difference of the bar angles to about 1e-11 / (2 |theta|):
# 1e-5 rad at 5e-7 rad from flat.
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


# Work-precision through the flat positions (issue 32, item 6). The projection after each step once
# worked to a fixed 1e-10 m: above a tight atol, its moves near the flat position reached the step
# control, which cut the steps to 1e-13 s and still ended off the one-dof solution. It now works to a
# tenth of atol (docs/theory/planar-formulation.md, "Projection tolerance").
WORK_PRECISION_END = 1.5  # s: through the flat positions at 0.6 s and 1.2 s (crank at 0 and -180 deg)
TOLERANCES = [10.0**-k for k in range(6, 13)]


def run_at(tolerance: float, t_end: float, atol: float | None = None) -> jp.Results:
    options = dict(jp.load(MODEL).simulation, rtol=tolerance, atol=tolerance if atol is None else atol)
    options.pop("t_end")
    return jp.load(MODEL).simulate(t_end, **options)


def test_error_falls_with_the_tolerances_at_the_cost_of_a_regular_problem():
    """rtol = atol from 1e-6 to 1e-12 over two flat passages: the crank angle's error at the end against
    the one-dof solution (SciPy, rtol 1e-13) falls with the tolerance (measured 2.7e-6 ... 1.0e-12 rad, within
    a factor 3 of the tolerance), and the cost grows as Dormand-Prince's on a regular problem,
    tol^(-1/5): 10^(6/5) = 16 times over six decades (measured 158 to 2 984 evaluations, 19 times). With
    the fixed 1e-10 m projection the run at 1e-12 took 12 656 evaluations (80 times) and ended 5e-5 rad off."""
    exact = ref.one_dof_solution(K, L, THETA0, OMEGA0, WORK_PRECISION_END, rtol=1e-13, atol=1e-15)(WORK_PRECISION_END)[0]
    errors, costs = [], []
    for tolerance in TOLERANCES:
        results = run_at(tolerance, WORK_PRECISION_END)
        errors.append(abs(float(ref.wrapped(results["crank.angle"][-1] - exact))))
        costs.append(results.statistics["rhs_evaluations"])
    ratios = np.array(errors) / np.array(TOLERANCES)
    assert np.all((ratios > 0.1) & (ratios < 10.0)), dict(zip(TOLERANCES, errors))
    assert costs == sorted(costs)
    assert costs[-1] / costs[0] < 2 * 10 ** (6 / 5), costs


def test_a_tight_atol_stays_on_the_one_dof_solution_over_ten_passages():
    """The issue's case: rtol 1e-10, atol 1e-12 over 10 s. Measured: 2.4e-9 rad and 11 906 evaluations
    (before: 0.5 rad off after 61 652, with steps down to 1e-13 s); the projection works to 1e-13 m."""
    results = run_at(1e-10, 10.0, atol=1e-12)
    theta, _ = ref.one_dof_solution(K, L, THETA0, OMEGA0, 10.0, rtol=1e-13, atol=1e-15)(results.time)
    assert np.max(np.abs(ref.wrapped(results["crank.angle"] - theta))) < 1e-7
    assert results.diagnostics["projection_tolerance"] == pytest.approx(1e-13, rel=1e-12)
    assert results.diagnostics["max_projection_residual"] <= 1e-13
    assert results.statistics["smallest_step"] > 1e-10


def test_an_atol_below_round_off_is_named_after_the_run():
    with pytest.warns(jp.JointplayWarning, match=r"simulation\.atol: 1e-16 asks the constraint projection for "
                                                 r"residuals below 1e-17 m, under the round-off of the coordinates; "
                                                 r"it works to 1e-14 m, so the joints are not held to atol"):
        run_at(1e-10, 0.01, atol=1e-16)


def test_a_projection_that_stalls_above_atol_is_named_with_its_time():
    from jointplay.model import _projection_advice

    advice = _projection_advice({"atol": 1e-12}, {"projection_tolerance": 1e-13, "max_projection_residual": 4e-11,
                                                  "max_projection_residual_time": 0.61})
    assert [str(a) for a in advice] == [
        "simulation.atol: the constraint projection left joint residuals up to 4e-11 m (at t = 0.61 s: a singular "
        "position, where Newton on the joints stalls), above atol = 1e-12: the requested accuracy was not met there"]
    # nothing when every projection met its tolerance, or when nothing was projected
    assert _projection_advice({"atol": 1e-12}, {"projection_tolerance": 1e-13, "max_projection_residual": 1e-13}) == []
    assert _projection_advice({"atol": 1e-12}, {"projection_tolerance": 1e-13, "max_projection_residual": 0.0}) == []
