"""Checks of the spatial references (tests/spatial_references.py) against things outside them.

- the torque-free body's Jacobi elliptic closed form against a direct integration of Euler's
  equations (solve_ivp, DOP853 at rtol 1e-13), in both cases about the intermediate-axis separatrix,
  and its period against the integrated motion;
- the heavy top's nutation bounds and period against an integration of the rigid body in rotation
  matrix and body angular velocity (not in Euler angles: nothing of Goldstein's reduction is reused),
  and the elliptic period against a quadrature of dt = du / sqrt(f(u));
- Bricard's mechanism and the spatial slider-crank: conservation of energy, closure of the loop,
  Grubler-Kutzbach counts against the mobility seen by the Jacobian;
- the hydraulic spring at a spatial angle against a direct integration of the planar reference.
"""

import math
from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp

from reference_hydraulic import CylinderParameters, frictionless, simulate
from spatial_references import (
    BRICARD,
    SPATIAL_SLIDER_CRANK,
    _BricardReduced,
    _chain,
    _closure_jacobian,
    axial_gravity,
    body_marker,
    bricard_motion,
    closed_chamber_angular_frequency,
    heavy_symmetric_top,
    slider_crank_bodies,
    slider_crank_mass,
    slider_crank_motion,
    slider_crank_pose,
    top_initial_state,
    torque_free_body,
    torque_free_period,
)

TIGHT = dict(method="DOP853", rtol=1e-13, atol=1e-14)


def euler_free(inertia):
    """Right-hand side of Euler's equations I w' = (I w) x w in the body frame."""
    inertia = np.asarray(inertia, dtype=float)
    return lambda t, w: np.cross(inertia * w, w) / inertia


def upward_crossings(t, x):
    """Times where x crosses zero upwards (linear interpolation)."""
    k = np.where((x[:-1] < 0.0) & (x[1:] >= 0.0))[0]
    return t[k] + (t[k + 1] - t[k]) * x[k] / (x[k] - x[k + 1])


# the two sides of the separatrix M^2 = 2 E I2, with components of both signs
FREE_CASES = [
    ((1.0, 2.0, 3.0), (0.3, -0.5, 2.0)),  # near the axis of I3
    ((1.0, 2.0, 3.0), (1.7, 0.6, -0.4)),  # near the axis of I1
    ((0.2, 0.5, 0.6), (-0.1, 0.2, -3.0)),
    ((0.2, 0.5, 0.6), (-2.5, -1.1, 0.3)),
    ((1.0, 2.0, 3.0), (0.1, 2.0, 0.05)),  # close to the separatrix: many flips, long period
]


def energy_and_momentum(inertia, omega):
    inertia = np.asarray(inertia)
    return np.sum(inertia * omega**2, axis=-1) / 2, np.sqrt(np.sum((inertia * omega) ** 2, axis=-1))


@pytest.mark.parametrize(("inertia", "omega0"), FREE_CASES)
def test_torque_free_closed_form_matches_euler_equations(inertia, omega0):
    period = torque_free_period(inertia, omega0)
    t = np.linspace(0.0, 5.0 * period, 2001)
    direct = solve_ivp(euler_free(inertia), (0.0, t[-1]), omega0, t_eval=t, **TIGHT)
    closed = torque_free_body(inertia, omega0, t)
    scale = np.linalg.norm(omega0)
    assert np.max(np.abs(closed - direct.y.T)) < 1e-9 * scale
    # the closed form keeps E and |L| (a check of the amplitudes independent of the integration)
    energy, momentum = energy_and_momentum(inertia, closed)
    e0, m0 = energy_and_momentum(inertia, np.asarray(omega0))
    assert np.max(np.abs(energy - e0)) < 1e-13 * e0
    assert np.max(np.abs(momentum - m0)) < 1e-13 * m0


@pytest.mark.parametrize(("inertia", "omega0"), FREE_CASES)
def test_torque_free_period_is_the_period_of_the_integrated_motion(inertia, omega0):
    period = torque_free_period(inertia, omega0)
    direct = solve_ivp(euler_free(inertia), (0.0, 3.0 * period), omega0, dense_output=True, **TIGHT)
    for n in (1, 2, 3):
        assert np.allclose(direct.sol(n * period), omega0, rtol=0.0, atol=1e-9 * np.linalg.norm(omega0))
    # and not a shorter one: the component that changes sign (the sn one) crosses zero twice a period
    t = np.linspace(0.0, 3.0 * period, 30001)
    w2 = direct.sol(t)[1]
    crossings = upward_crossings(t, w2)
    assert np.diff(crossings) == pytest.approx(period, rel=1e-7)


def test_torque_free_closed_form_at_a_hand_value():
    # near the axis of I3 with omega2(0) = 0: omega1 = A1 cn, omega3 = A3 dn, tau0 = 0, so at the
    # quarter period omega1 = 0, omega2 = A2 and omega3 = A3 sqrt(1 - k^2)
    inertia, omega0 = (1.0, 2.0, 3.0), (0.3, 0.0, 2.0)
    m2, e2 = (0.3**2 + 36.0), (0.09 + 12.0)
    a2 = math.sqrt((e2 * 3 - m2) / (2.0 * 1.0))
    k2 = (2 - 1) * (e2 * 3 - m2) / ((3 - 2) * (m2 - e2 * 1))
    quarter = torque_free_period(inertia, omega0) / 4
    w = torque_free_body(inertia, omega0, [quarter])[0]
    assert w == pytest.approx([0.0, a2, 2.0 * math.sqrt(1 - k2)], abs=1e-12)


def test_torque_free_refuses_the_separatrix_and_unsorted_inertia():
    with pytest.raises(ValueError, match="separatrix"):
        torque_free_period((1.0, 2.0, 3.0), (1.0, 0.0, math.sqrt(1.0 / 3.0)))  # M^2 = 2 E I2 = 2
    with pytest.raises(ValueError, match="I1 < I2 < I3"):
        torque_free_period((2.0, 1.0, 3.0), (1.0, 0.0, 1.0))


# ---------------------------------------------------------------------------------------------
# heavy symmetric top
# ---------------------------------------------------------------------------------------------


def skew(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def rigid_top(inertia, m, g, l):
    """R' = R [w]x, I w' = (I w) x w + l e3 x (R^T (0, 0, -m g)), about the fixed point."""
    inertia = np.asarray(inertia, dtype=float)

    def rhs(t, y):
        rotation, w = y[:9].reshape(3, 3), y[9:]
        weight = rotation.T @ np.array([0.0, 0.0, -m * g])
        torque = np.cross([0.0, 0.0, l], weight)
        return np.concatenate([(rotation @ skew(w)).ravel(), (np.cross(inertia * w, w) + torque) / inertia])

    return rhs


# (I1 about the fixed point, I3, m, g, l, theta0, theta_dot0, phi_dot0, psi_dot0)
TOPS = [
    (0.02, 0.005, 1.0, 9.81, 0.1, 0.5, 0.0, 0.0, 60.0),  # released without precession: cusps
    (0.02, 0.005, 1.0, 9.81, 0.1, 1.0, 0.8, 2.0, 50.0),  # loops
    (0.05, 0.01, 2.0, 9.81, 0.2, 0.3, -1.0, -1.5, 120.0),
    (0.012, 0.004, 0.5, 9.81, 0.05, 2.4, 0.0, 3.0, 30.0),  # below the horizontal
]


@pytest.mark.parametrize("top", TOPS)
def test_heavy_top_nutation_matches_a_rigid_body_integration(top):
    i1, i3, m, g, l, theta0, theta_dot0, phi_dot0, psi_dot0 = top
    nutation = heavy_symmetric_top(*top)
    rotation, w = top_initial_state(theta0, theta_dot0, phi_dot0, psi_dot0)
    end = 4.0 * nutation.period
    sol = solve_ivp(rigid_top((i1, i1, i3), m, g, l), (0.0, end), np.concatenate([rotation.ravel(), w]),
                    dense_output=True, **TIGHT)
    t = np.linspace(0.0, end, 40001)
    cos_theta = sol.sol(t)[8]  # R[2, 2]: the symmetry axis against the vertical
    theta = np.arccos(np.clip(cos_theta, -1.0, 1.0))
    # extrema of a sampled smooth curve: error ~ (dt)^2 theta''/2 ~ 1e-7 rad at this sampling
    assert theta.min() == pytest.approx(nutation.theta_min, abs=1e-6)
    assert theta.max() == pytest.approx(nutation.theta_max, abs=1e-6)
    # period: the times where theta passes its mid value upwards
    mid = 0.5 * (nutation.theta_min + nutation.theta_max)
    crossings = upward_crossings(t, theta - mid)
    assert len(crossings) >= 3
    assert np.diff(crossings) == pytest.approx(nutation.period, rel=1e-7)


@pytest.mark.parametrize("top", TOPS)
def test_heavy_top_elliptic_period_equals_the_quadrature_of_dt(top):
    nutation = heavy_symmetric_top(*top)
    alpha, beta, a, b = nutation.coefficients
    u1, u2, _ = nutation.roots

    def f(u):
        return (1 - u * u) * (alpha - beta * u) - (b - a * u) ** 2

    # u = u1 + (u2 - u1) sin^2(s) removes the square-root ends: dt = 2 (u2 - u1) sin s cos s ds / sqrt(f)
    def integrand(s):
        u = u1 + (u2 - u1) * math.sin(s) ** 2
        return 2.0 * (u2 - u1) * math.sin(s) * math.cos(s) / math.sqrt(max(f(u), 1e-300))

    half, _ = quad(integrand, 0.0, math.pi / 2, epsabs=0.0, epsrel=1e-12, limit=200)
    assert 2.0 * half == pytest.approx(nutation.period, rel=1e-10)
    # f vanishes at both bounds and is positive between them
    scale = abs(alpha) + beta + a * a + b * b
    assert abs(f(u1)) < 1e-12 * scale and abs(f(u2)) < 1e-12 * scale
    assert f(0.5 * (u1 + u2)) > 0.0


def test_heavy_top_released_without_precession_starts_at_the_top_of_its_nutation():
    # theta_dot = phi_dot = 0 at t = 0 makes u0 = cos theta0 a root of f: the top only falls from there
    nutation = heavy_symmetric_top(0.02, 0.005, 1.0, 9.81, 0.1, 0.5, 0.0, 0.0, 60.0)
    assert nutation.theta_min == pytest.approx(0.5, abs=1e-12)
    # a fast top (Goldstein 5.76, 5.79): nutation amplitude ~ 2 I1 m g l sin(theta0) / (I3 w3)^2 and
    # angular frequency of the nutation ~ I3 w3 / I1, both to first order in the small amplitude
    i1, i3, mgl, w3 = 0.02, 0.005, 0.981, 600.0
    fast = heavy_symmetric_top(i1, i3, 1.0, 9.81, 0.1, 0.5, 0.0, 0.0, w3)
    amplitude = 2 * i1 * mgl * math.sin(0.5) / (i3 * w3) ** 2
    assert fast.theta_max - fast.theta_min == pytest.approx(amplitude, rel=0.01)
    assert fast.period == pytest.approx(2 * math.pi * i1 / (i3 * w3), rel=0.01)


# ---------------------------------------------------------------------------------------------
# Bricard's mechanism (IFToMM A04)
# ---------------------------------------------------------------------------------------------

BRICARD_TIMES = np.linspace(0.0, 3.0, 61)


@pytest.fixture(scope="module")
def bricard():
    return bricard_motion(BRICARD_TIMES)


def test_bricard_data_holds_the_benchmark_rods_and_joints():
    for rod in BRICARD["rods"]:
        assert rod["mass"] == 1.0 and rod["length"] == 1.0
        # solid 1 m x 0.1 m x 0.1 m cuboid: m (L^2 + s^2)/12 across, m s^2/6 along
        assert rod["inertia_principal"] == pytest.approx([0.01 / 6, 1.01 / 12, 1.01 / 12], rel=1e-15)
        rotation = rod["rotation"]
        assert rotation.T @ rotation == pytest.approx(np.eye(3), abs=1e-15)
        assert np.linalg.det(rotation) == pytest.approx(1.0)
        assert rotation @ np.diag(rod["inertia_principal"]) @ rotation.T == pytest.approx(rod["inertia"], abs=1e-15)
    bodies = {rod["name"]: rod for rod in BRICARD["rods"]}
    for joint in BRICARD["joints"]:
        # each joint's marker, put back into global coordinates from either body, is the same frame
        frames = []
        for name in (joint["first"], joint["second"]):
            body = bodies.get(name)
            position, axes = body_marker(body, joint["point"], joint["axis"])
            rotation = np.eye(3) if body is None else body["rotation"]
            origin = np.zeros(3) if body is None else body["position"]
            assert origin + rotation @ position == pytest.approx(joint["point"], abs=1e-15)
            assert rotation @ axes[:, 2] == pytest.approx(joint["axis"], abs=1e-15)
            assert axes.T @ axes == pytest.approx(np.eye(3), abs=1e-15)
            assert np.linalg.det(axes) == pytest.approx(1.0)
            frames.append(rotation @ axes)
        assert frames[0] == pytest.approx(frames[1], abs=1e-15)
        # the joint is at the end of each rod it holds
        for name in (joint["first"], joint["second"]):
            if name in bodies:
                assert abs(body_marker(bodies[name], joint["point"], joint["axis"])[0][0]) == pytest.approx(0.5)


def test_bricard_moves_with_one_degree_of_freedom_where_grubler_counts_none():
    # Grubler-Kutzbach: 6 (6 bodies - 1) - 5 x 6 revolutes = 0; the closure of the open chain of five
    # joint angles (5 equations) has rank 4 along the motion: one equation is redundant, one angle free
    assert 6 * (6 - 1) - 5 * 6 == 0
    for q in (np.zeros(5), bricard_motion(np.linspace(0.0, 1.0, 3)).joint_angles[-1]):
        singular = np.linalg.svd(_closure_jacobian(_chain(q)), compute_uv=False)
        assert singular[3] > 0.5 and singular[4] < 1e-12


def test_bricard_conserves_energy_and_keeps_its_loop_closed(bricard):
    energy = bricard.kinetic_energy + bricard.potential_energy
    assert bricard.kinetic_energy.max() > 4.0  # it swings through: P3 falls by more than 0.6 m
    assert bricard.joint_points[:, 3, 1].min() < -1.6
    assert np.max(np.abs(energy - energy[0])) < 1e-8
    assert bricard.closure_residual.max() < 1e-13
    # rods keep their length between joint points
    spans = np.linalg.norm(np.diff(bricard.joint_points, axis=1), axis=2)
    assert spans == pytest.approx(np.ones_like(spans), abs=1e-12)


def test_bricard_motion_does_not_depend_on_the_chosen_joint_angle(bricard):
    other = bricard_motion(BRICARD_TIMES, independent=2)
    assert np.max(np.abs(other.joint_points - bricard.joint_points)) < 1e-8


def test_bricard_starts_with_the_acceleration_of_the_virtual_work():
    # released from rest: theta'' = -dV/dtheta / m(theta), V by differences of the potential on closed
    # configurations and m = 2 T at theta' = 1 (energies only, not the equation of motion)
    model = _BricardReduced()
    h = 1e-4
    slope = (model.energies(h, 0.0)[1] - model.energies(-h, 0.0)[1]) / (2 * h)
    mass = 2.0 * model.energies(0.0, 1.0)[0]
    assert model.rhs(0.0, [0.0, 0.0])[1] == pytest.approx(-slope / mass, rel=1e-7)


# ---------------------------------------------------------------------------------------------
# Haug's spatial slider-crank
# ---------------------------------------------------------------------------------------------


def test_slider_crank_initial_pose_is_haugs():
    # crank up: B = (0, 0.1, 0.2); |C - B| = 0.3 puts the slider at x = 0.2 and the rod centre at
    # (0.1, 0.05, 0.1), the initial positions of Haug's slider and rod
    pose = slider_crank_pose(SPATIAL_SLIDER_CRANK["theta0"])
    assert pose["joint_b"][:, 0] == pytest.approx([0.0, 0.1, 0.2], abs=1e-15)
    assert pose["slider"][:, 0] == pytest.approx([0.2, 0.0, 0.0], abs=1e-15)
    assert pose["rod_centre"][:, 0] == pytest.approx([0.1, 0.05, 0.1], abs=1e-15)


@pytest.mark.parametrize("theta", np.linspace(0.0, 2 * math.pi, 7)[:-1] + 0.3)
def test_slider_crank_pose_keeps_its_joints(theta):
    pose = slider_crank_pose(theta)
    rotation = pose["rod_rotation"][..., 0]
    b, c = pose["joint_b"][:, 0], pose["slider"][:, 0]
    assert rotation.T @ rotation == pytest.approx(np.eye(3), abs=1e-15)
    assert np.linalg.det(rotation) == pytest.approx(1.0)
    assert np.linalg.norm(c - b) == pytest.approx(0.3, abs=1e-15)  # spherical B and universal C on the rod
    assert rotation[:, 0] == pytest.approx((c - b) / 0.3, abs=1e-15)
    assert c[1:] == pytest.approx([0.0, 0.0], abs=1e-15)  # translational along x
    assert rotation[:, 1] @ SPATIAL_SLIDER_CRANK["universal_slider_axis"] == pytest.approx(0.0, abs=1e-15)


@pytest.mark.parametrize("theta", [0.3, 1.9, 4.0])
def test_slider_crank_pose_derivatives_match_differences(theta):
    # the Taylor-jet derivatives against central differences (errors ~h^2: 1e-10 and 1e-5 here)
    h = 1e-5
    plus, mid, minus = (slider_crank_pose(theta + d) for d in (h, 0.0, -h))
    for key in ("crank_centre", "rod_centre", "slider", "rod_rotation"):
        first = (plus[key][..., 0] - minus[key][..., 0]) / (2 * h)
        second = (plus[key][..., 0] - 2 * mid[key][..., 0] + minus[key][..., 0]) / h**2
        assert np.max(np.abs(first - mid[key][..., 1])) < 1e-9
        assert np.max(np.abs(second - mid[key][..., 2])) < 1e-4
    dm = (slider_crank_mass(theta + h)[0] - slider_crank_mass(theta - h)[0]) / (2 * h)
    assert slider_crank_mass(theta)[1] == pytest.approx(dm, rel=1e-7, abs=1e-12)


def test_slider_crank_rod_spin_follows_the_universal_joint():
    # rod angular velocity per crank rate from the jets against the rotation between nearby poses
    theta, h = 1.1, 1e-6
    rot = slider_crank_pose(theta)["rod_rotation"]
    step = slider_crank_pose(theta + h)["rod_rotation"][..., 0] @ slider_crank_pose(theta - h)["rod_rotation"][..., 0].T
    w_global = np.array([step[2, 1] - step[1, 2], step[0, 2] - step[2, 0], step[1, 0] - step[0, 1]]) / (4 * h)
    skew_w = rot[..., 1] @ rot[..., 0].T
    assert np.array([skew_w[2, 1], skew_w[0, 2], skew_w[1, 0]]) == pytest.approx(w_global, abs=1e-8)


def test_slider_crank_joint_data_fit_the_poses():
    # markers put into global coordinates from the body states: points coincide, axes as the joint demands
    data = SPATIAL_SLIDER_CRANK
    for theta in (data["theta0"], 2.2):
        bodies = slider_crank_bodies(theta, 1.0)
        bodies["ground"] = {"position": np.zeros(3), "rotation": np.eye(3)}

        def marker(end):
            name, point, axes = end
            body = bodies[name]
            axes = np.eye(3) if axes is None else np.asarray(axes, float)
            assert axes.T @ axes == pytest.approx(np.eye(3)) and np.linalg.det(axes) == pytest.approx(1.0)
            return body["position"] + body["rotation"] @ point, body["rotation"] @ axes

        for joint in data["joints"]:
            (p1, a1), (p2, a2) = marker(joint["first"]), marker(joint["second"])
            if joint["type"] == "translational":
                assert p2 - p1 == pytest.approx((p2 - p1) @ a1[:, 2] * a1[:, 2], abs=1e-15)  # along the common z
                assert a2 == pytest.approx(a1, abs=1e-15)
                continue
            assert p2 == pytest.approx(p1, abs=1e-15)
            if joint["type"] == "revolute":
                assert a2[:, 2] == pytest.approx(a1[:, 2], abs=1e-15)
            if joint["type"] == "universal":
                assert a1[:, 0] @ a2[:, 1] == pytest.approx(0.0, abs=1e-15)


def test_slider_crank_body_states_carry_the_kinetic_energy_of_the_reduced_model():
    data, theta, rate = SPATIAL_SLIDER_CRANK, 2.2, 3.0
    bodies = slider_crank_bodies(theta, rate)
    kinetic = 0.0
    for name in ("crank", "rod", "slider"):
        b = bodies[name]
        inertia = b["rotation"] @ np.diag(data[f"{name}_inertia"]) @ b["rotation"].T
        kinetic += 0.5 * data[f"{name}_mass"] * b["velocity"] @ b["velocity"]
        kinetic += 0.5 * b["angular_velocity"] @ inertia @ b["angular_velocity"]
    assert kinetic == pytest.approx(0.5 * slider_crank_mass(theta)[0] * rate**2, rel=1e-14)


def test_slider_crank_conserves_energy_and_work_of_a_torque():
    t = np.linspace(0.0, 3.0, 301)
    free = slider_crank_motion(t)
    assert free.theta[-1] - free.theta[0] > 4 * 2 * math.pi  # the crank turns over
    assert free.slider.min() == pytest.approx(math.sqrt(0.09 - 0.236**2), abs=1e-3)  # crank away from the x axis
    assert np.max(np.abs(free.energy - free.energy[0])) < 1e-10 * free.energy[0]
    driven = slider_crank_motion(t, torque=0.01)
    work = 0.01 * (driven.theta - driven.theta[0])
    assert np.max(np.abs(driven.energy - driven.energy[0] - work)) < 1e-10 * driven.energy[-1]


# ---------------------------------------------------------------------------------------------
# closed-chamber hydraulic spring at a spatial angle
# ---------------------------------------------------------------------------------------------


def test_closed_chamber_frequency_at_a_spatial_angle_matches_the_integrated_cylinder():
    axis = np.array([0.3, -0.5, 0.8])  # the cylinder's extension direction in space
    g_axial = axial_gravity(axis, [0.0, 0.0, -9.81])
    assert g_axial == pytest.approx(-9.81 * 0.8 / math.sqrt(0.98), rel=1e-15)
    p = replace(frictionless(CylinderParameters()), axial_gravity=g_axial)
    # pressures that hold the weight at the stroke 0.25 m: p_cap A1 - p_rod A2 = -m g_axial
    cap = 5e6
    rod = (cap * p.piston_area + p.mass * g_axial) / p.rod_side_area
    omega = closed_chamber_angular_frequency(p, 0.25)
    period = 2 * math.pi / omega
    t = np.linspace(0.0, 30 * period, 30 * 400 + 1)
    h = simulate(p, t[-1], initial_rate=1e-3, cap_pressure=cap, rod_pressure=rod, t_eval=t)
    assert h.success, h.message
    crossings = upward_crossings(h.t, h.stroke - 0.25)
    measured = 2 * math.pi * (len(crossings) - 1) / (crossings[-1] - crossings[0])
    assert measured == pytest.approx(omega, rel=1e-5)
    # equal areas: the brief's omega^2 = B A^2 (1/V1 + 1/V2) / m
    equal = replace(p, rod_diameter=0.0)
    v1, v2 = equal.cap_dead_volume + equal.piston_area * 0.25, equal.rod_dead_volume + equal.piston_area * 0.25
    assert closed_chamber_angular_frequency(equal, 0.25) ** 2 == pytest.approx(
        equal.bulk_modulus * equal.piston_area**2 * (1 / v1 + 1 / v2) / equal.mass, rel=1e-14)
