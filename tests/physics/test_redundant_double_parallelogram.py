"""A double parallelogram: three parallel bars under one coupler (examples/double_parallelogram.toml).

One of its twelve constraint equations depends on the others at every configuration, so the
constraint Jacobian never has full rank and the multipliers (the joint reactions) are not unique:
any split of the load between the three bars that has the right total balances the motion. The
engine is to report the multipliers of least Euclidean norm (the lead engineer's stated choice);
the reactions here are computed independently for that choice, from the engine's own recorded state,
by least squares on the absolute-coordinate equations assembled in tests/physics/parallelogram_reference.py.
What does not depend on the choice is checked against the one-degree-of-freedom motion:

    theta_ddot = -(7 g / (6 L)) cos(theta)     (3 bars of m, L; a coupler of 2 m, 2 L)

and the total force of the ground on the mechanism, which must give its centres of mass their
accelerations: sum of the ground pins' forces = sum m_k (a_k - g).

Today's engine (8193766) stops at t = 0 with a SimulationError ("singular constraint Jacobian ...
near B2: its equations became dependent on the others"), and `jointplay check` says nothing about
the redundancy; these tests are meant to fail until the engine handles it.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import jointplay as jp
import parallelogram_reference as ref
from jointplay.cli import app

MODEL = Path(__file__).resolve().parents[2] / "examples" / "double_parallelogram.toml"
L, M, M_COUPLER = 1.0, 1.0, 2.0  # m, kg, kg
THETA0, OMEGA0 = math.pi / 2, -1.0  # rad, rad/s
K = ref.theta_ddot_factor(n_bars=3, bar_mass=M, coupler_mass=M_COUPLER)  # 7/6
BARS = ("left", "middle", "right")
GROUND_PINS = ("A0", "A1", "A2")

# Motion against the one-dof solution: as for the four-bar (tests/physics/test_singular_four_bar.py):
# integrated to rtol 1e-8 (engine, as the model file) and 1e-10 (reference) over 10 s (about 5 turns); 1e-5 rad catches a period error of 3e-7.
ANGLE_TOLERANCE = 1e-5
BRANCH_TOLERANCE = 1e-5
# Reactions: both sides are computed from the same recorded state, so they differ only by the linear
# algebra (round-off times the conditioning of the least-squares problem, which stays below 1e3 here:
# the least-norm multipliers stay bounded, about 30 N, even through the flat position). 1e-6 of the
# weight of the mechanism (5 m g = 49 N) is 5e-5 N; another choice of multipliers moves the shares by
# newtons (dropping the redundant pair of rows of one bar moves a third of the load).
FORCE_TOLERANCE = 1e-6 * (3 * M + M_COUPLER) * ref.G


def bodies() -> list[ref.Body]:
    h = L / 2
    bars = [ref.Body(bar, M, M * L**2 / 12, {f"A{k}": (-h, 0.0), f"B{k}": (h, 0.0)}) for k, bar in enumerate(BARS)]
    coupler = ref.Body("coupler", M_COUPLER, M_COUPLER * (2 * L)**2 / 12,
                       {f"B{k}": ((k - 1) * L, 0.0) for k in range(3)})
    return bars + [coupler]


def absolute_model() -> ref.AbsoluteModel:
    """The mechanism as the test assembles it, independently of the model file's reader."""
    ground = {f"A{k}": (k * L, 0.0) for k in range(3)}
    joints = [ref.Joint(f"A{k}", f"ground.A{k}", f"{bar}.A{k}") for k, bar in enumerate(BARS)]
    joints += [ref.Joint(f"B{k}", f"{bar}.B{k}", f"coupler.B{k}") for k, bar in enumerate(BARS)]
    return ref.AbsoluteModel(bodies(), ground, joints)


def run() -> jp.Results:
    return ref.run_model_file(MODEL)


def reference():
    return ref.one_dof_to_end_of(MODEL, K, L, THETA0, OMEGA0)


def test_model_file_and_python_example_are_the_same_model():
    assert ref.example_builds_the_model_file("double_parallelogram", MODEL)
    assert K == pytest.approx(7 / 6, rel=1e-15)


def test_the_test_model_is_redundant_everywhere_and_its_reference_reproduces_the_one_dof_motion():
    """The test's own absolute-coordinate model: rank 11 of 12 rows off the flat position (10 on it),
    and its accelerations are those of the one-dof equation (checks the reference, not the engine)."""
    model = absolute_model()
    for theta, omega in ((THETA0, OMEGA0), (0.3, -4.0), (-2.0, -6.5), (0.0, -5.0)):
        c, s = math.cos(theta), math.sin(theta)
        q = np.array([v for k in range(3) for v in (k * L + L / 2 * c, L / 2 * s, theta)] + [L + L * c, L * s, 0.0])
        qd = np.array([v for _ in range(3) for v in (-L / 2 * s * omega, L / 2 * c * omega, omega)]
                      + [-L * s * omega, L * c * omega, 0.0])
        qdd, _, rank = model.minimum_norm_solution(q, qd)
        assert rank == (10 if theta == 0.0 else 11)
        alpha = -K * ref.G / L * c
        assert qdd[2] == pytest.approx(alpha, abs=1e-9)
        assert qdd[10] == pytest.approx(L * (c * alpha - s * omega**2), abs=1e-9)  # coupler centre, y


def test_runs_to_the_end():
    results = run()
    assert results.error is None
    assert results.time[-1] == pytest.approx(jp.load(MODEL).simulation["t_end"])


def test_motion_follows_the_one_degree_of_freedom_equation_on_the_parallelogram_branch():
    results = run()
    theta, theta_dot = reference()(results.time)
    assert results.time.size > 900
    for bar in BARS:
        assert np.max(np.abs(ref.wrapped(results[f"{bar}.angle"] - theta))) < ANGLE_TOLERANCE, bar
        assert np.max(np.abs(results[f"{bar}.omega"] - theta_dot)) < ANGLE_TOLERANCE * 10, bar
    assert np.max(np.abs(ref.wrapped(results["coupler.angle"]))) < BRANCH_TOLERANCE
    expected = ref.flat_passages(reference()(np.linspace(0.0, results.time[-1], 100_001))[0])
    assert ref.flat_passages(results["middle.angle"]) == expected >= 10


def sample_instants(results: jp.Results) -> list[int]:
    """About one sample a second, and the sample nearest each of the first two flat positions."""
    picks = list(range(0, results.time.size, 97))
    s = np.sin(results["left.angle"])
    crossings = np.flatnonzero(np.sign(s[1:]) != np.sign(s[:-1]))[:2]
    picks += [int(k + np.argmin(np.abs(s[k:k + 2]))) for k in crossings]
    return sorted(set(picks))


def test_reactions_are_the_least_norm_multipliers():
    results = run()
    model, body_list = absolute_model(), bodies()
    instants = sample_instants(results)
    assert len(instants) >= 12
    for k in instants:
        q, qd = ref.state_from_results(results, body_list, k)
        for joint, force in model.reactions(q, qd).items():
            engine = np.array([results[f"{joint}.fx"][k], results[f"{joint}.fy"][k]])
            assert np.max(np.abs(engine - force)) < FORCE_TOLERANCE, (joint, results.time[k], engine, force)


def test_ground_pins_share_equally_under_the_least_norm_choice():
    """What the least-norm choice means here (computed by the reference, then asserted of the engine):
    identical bars in parallel carry identical forces."""
    results = run()
    for k in sample_instants(results):
        forces = np.array([[results[f"{pin}.fx"][k], results[f"{pin}.fy"][k]] for pin in GROUND_PINS])
        assert np.max(np.abs(forces - forces.mean(axis=0))) < FORCE_TOLERANCE, results.time[k]


def test_total_ground_reaction_gives_the_centres_of_mass_their_accelerations():
    """Independent of the choice: sum of the ground pins' forces = sum m_k (a_k - g), with the
    accelerations of the one-dof motion at the engine's own angle and angular velocity, every sample."""
    results = run()
    theta, omega = results["left.angle"], results["left.omega"]
    alpha = -K * ref.G / L * np.cos(theta)
    # centres of mass: bars at half height, the coupler at the bar tops; all move with (cos, sin)(theta)
    first_moment = 3 * M * L / 2 + M_COUPLER * L  # sum m_k times the radius its centre turns on [kg m]
    ax = first_moment * (-np.sin(theta) * alpha - np.cos(theta) * omega**2)
    ay = first_moment * (np.cos(theta) * alpha - np.sin(theta) * omega**2)
    weight = (3 * M + M_COUPLER) * ref.G
    fx = sum(results[f"{pin}.fx"] for pin in GROUND_PINS)
    fy = sum(results[f"{pin}.fy"] for pin in GROUND_PINS)
    assert np.max(np.abs(fx - ax)) < FORCE_TOLERANCE
    assert np.max(np.abs(fy - (ay + weight))) < FORCE_TOLERANCE


def test_check_notes_the_redundant_constraint():
    result = CliRunner().invoke(app, ["check", str(MODEL)])
    assert result.exit_code == 0, result.output
    assert "redundant" in result.output.lower()
