"""Independent references for the spatial engine: closed forms and minimal-coordinate models.

Written apart from the Rust core (numpy and scipy only, nothing from jointplay), so that the
engine's spatial bodies, joints and force elements can be compared with them.  Each reference is
itself checked in tests/test_spatial_references.py against something outside it (a direct
integration, a conservation law, a published value).

Contents, all in SI units:

* ``torque_free_body``, ``torque_free_period``: Euler's free rigid body, Jacobi elliptic closed form
  (Landau & Lifshitz, Mechanics, 3rd ed., 1976, section 37).
* ``heavy_symmetric_top``: nutation bounds and period of Lagrange's top (Goldstein, Poole & Safko,
  Classical Mechanics, 3rd ed., 2002, section 5.7).
* ``BRICARD``, ``bricard_motion``: Bricard's mechanism of the IFToMM multibody benchmark library
  (problem A04), in one joint coordinate, its loop closed by Newton's method.
* ``SPATIAL_SLIDER_CRANK``, ``slider_crank_motion``: Haug's spatial slider-crank in the crank angle.
* ``closed_chamber_angular_frequency``, ``axial_gravity``: the hydraulic spring of a closed cylinder
  at any angle (the planar reference tests/physics/reference_hydraulic.py gives the stiffness).

Conventions: rotation matrices are active, body -> global (columns are the body axes in global
coordinates); angular velocities of the free body are in the body frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp
from scipy.special import ellipj, ellipk, ellipkinc

__all__ = [
    "BRICARD",
    "BricardMotion",
    "bricard_motion",
    "body_marker",
    "SPATIAL_SLIDER_CRANK",
    "SliderCrankMotion",
    "slider_crank_pose",
    "slider_crank_bodies",
    "slider_crank_mass",
    "slider_crank_motion",
    "closed_chamber_angular_frequency",
    "axial_gravity",
    "torque_free_body",
    "torque_free_period",
    "TopNutation",
    "heavy_symmetric_top",
    "top_initial_state",
    "rotation_zxz",
]


# ---------------------------------------------------------------------------------------------
# torque-free asymmetric body (Landau & Lifshitz, Mechanics, section 37)
# ---------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class _JacobiForm:
    """omega_i(t) = sign_i A_i f_i(lambda t + tau0 | m), f = (cn, sn, dn) in an order fixed by the case."""

    amplitudes: np.ndarray  # A_i [rad/s], >= 0
    signs: np.ndarray  # +-1 per component
    functions: tuple  # per component: 0 = sn, 1 = cn, 2 = dn
    rate: float  # lambda [1/s], d tau / dt
    parameter: float  # m = k^2 [-]
    tau0: float  # phase at t = 0 [-]


def _jacobi_form(inertia_principal, omega0) -> _JacobiForm:
    """Landau's closed form fitted to the body-frame angular velocity omega0 [rad/s] at t = 0.

    With M^2 = sum (I_i omega_i)^2 and 2E = sum I_i omega_i^2, for M^2 > 2 E I2 (Landau 37.10):
      omega1 = A1 cn, omega2 = A2 sn, omega3 = A3 dn,
      A1 = sqrt((2E I3 - M^2)/(I1 (I3 - I1))), A2 = sqrt((2E I3 - M^2)/(I2 (I3 - I2))),
      A3 = sqrt((M^2 - 2E I1)/(I3 (I3 - I1))), lambda = sqrt((I3 - I2)(M^2 - 2E I1)/(I1 I2 I3)),
      k^2 = (I2 - I1)(2E I3 - M^2) / ((I3 - I2)(M^2 - 2E I1));
    for M^2 < 2 E I2 the suffixes 1 and 3 exchange (omega1 ~ dn, omega3 ~ cn).  Euler's equations
    are unchanged when two components change sign together; that fixes the signs, and the phase
    tau0 = F(am, k) with am = atan2(sn, cn) at t = 0.
    """
    i1, i2, i3 = (float(v) for v in inertia_principal)
    if not i1 < i2 < i3:
        raise ValueError(f"principal inertias must be I1 < I2 < I3, got {inertia_principal}")
    w = np.asarray(omega0, dtype=float)
    m2 = float(np.sum((np.array([i1, i2, i3]) * w) ** 2))
    two_e = float(np.sum(np.array([i1, i2, i3]) * w**2))
    high, low = two_e * i3 - m2, m2 - two_e * i1  # both >= 0
    if abs(m2 - two_e * i2) <= 1e-12 * m2:
        raise ValueError("M^2 = 2 E I2: on the separatrix the angular velocity has no period")
    if m2 > two_e * i2:  # spin about the axis of I3 (dn on omega3)
        a = np.sqrt([high / (i1 * (i3 - i1)), high / (i2 * (i3 - i2)), low / (i3 * (i3 - i1))])
        rate = math.sqrt((i3 - i2) * low / (i1 * i2 * i3))
        parameter = (i2 - i1) * high / ((i3 - i2) * low)
        functions, keep, cos_axis = (1, 0, 2), 2, 0
    else:  # spin about the axis of I1 (dn on omega1)
        a = np.sqrt([high / (i1 * (i3 - i1)), low / (i2 * (i2 - i1)), low / (i3 * (i3 - i1))])
        rate = math.sqrt((i2 - i1) * high / (i1 * i2 * i3))
        parameter = (i3 - i2) * low / ((i2 - i1) * high)
        functions, keep, cos_axis = (2, 0, 1), 0, 2
    sigma = 1.0 if w[keep] >= 0 else -1.0
    signs = np.ones(3)
    signs[keep] = sigma
    signs[1] = sigma  # omega2 (sn) flips together with the dn component
    amplitude = math.atan2(sigma * w[1] / a[1], w[cos_axis] / a[cos_axis])
    return _JacobiForm(a, signs, functions, rate, parameter, float(ellipkinc(amplitude, parameter)))


def torque_free_body(inertia_principal, omega0, t) -> np.ndarray:
    """Body-frame angular velocity [rad/s] of a torque-free rigid body at times t [s].

    ``inertia_principal`` = (I1, I2, I3) [kg m^2], I1 < I2 < I3; ``omega0`` [rad/s] the body-frame
    angular velocity at t = 0 along those principal axes.  Returns an array of shape (len(t), 3).
    Source: Landau & Lifshitz, Mechanics, section 37 (Jacobi elliptic functions, scipy.special.ellipj).
    """
    form = _jacobi_form(inertia_principal, omega0)
    tau = form.rate * np.atleast_1d(np.asarray(t, dtype=float)) + form.tau0
    sn, cn, dn, _ = ellipj(tau, form.parameter)
    values = (sn, cn, dn)
    columns = [form.signs[i] * form.amplitudes[i] * values[form.functions[i]] for i in range(3)]
    return np.stack(columns, axis=-1)


def torque_free_period(inertia_principal, omega0) -> float:
    """Period [s] of the body-frame angular velocity of a torque-free body: 4 K(k) / lambda
    (Landau & Lifshitz, Mechanics, section 37; sn and cn have the period 4K in lambda t)."""
    form = _jacobi_form(inertia_principal, omega0)
    return 4.0 * float(ellipk(form.parameter)) / form.rate


# ---------------------------------------------------------------------------------------------
# heavy symmetric top (Goldstein, Classical Mechanics, 3rd ed., section 5.7)
# ---------------------------------------------------------------------------------------------


def rotation_zxz(phi: float, theta: float, psi: float) -> np.ndarray:
    """R = Rz(phi) Rx(theta) Rz(psi), body -> global, for the 3-1-3 Euler angles [rad] (Goldstein 4.46)."""

    def rz(a):
        c, s = math.cos(a), math.sin(a)
        return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])

    c, s = math.cos(theta), math.sin(theta)
    rx = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    return rz(phi) @ rx @ rz(psi)


def top_initial_state(theta0, theta_dot0, phi_dot0, psi_dot0):
    """(R, omega_body) of the top at phi = psi = 0: rotation body -> global and body angular
    velocity [rad/s], omega_body = (phi' sin th sin psi + th' cos psi, phi' sin th cos psi - th' sin psi,
    phi' cos th + psi') (Goldstein 4.87)."""
    s, c = math.sin(theta0), math.cos(theta0)
    return rotation_zxz(0.0, theta0, 0.0), np.array([theta_dot0, phi_dot0 * s, phi_dot0 * c + psi_dot0])


@dataclass(frozen=True)
class TopNutation:
    """Nutation of the heavy symmetric top (angles from the upward vertical through the fixed point)."""

    theta_min: float  # [rad]
    theta_max: float  # [rad]
    period: float  # time from theta_min to theta_min [s]
    roots: tuple  # u1 <= u2 <= u3 of f(u) = 0, u = cos theta [-]
    coefficients: tuple  # (alpha [1/s^2], beta [1/s^2], a [1/s], b [1/s]) of f(u)


def heavy_symmetric_top(i1, i3, m, g, l, theta0, theta_dot0, phi_dot0, psi_dot0) -> TopNutation:
    """Nutation bounds and period of a heavy symmetric top on a fixed point.

    i1 = I2 [kg m^2] about a transverse axis through the FIXED POINT, i3 [kg m^2] about the symmetry
    axis, m [kg], g [m/s^2], l [m] from the fixed point to the centre of mass along the symmetry
    axis (above it when theta = 0); theta0 [rad] from the upward vertical, rates [rad/s] of the 3-1-3
    angles (precession phi, nutation theta, spin psi).  Goldstein section 5.7: with u = cos theta,
      u'^2 = f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2,
      alpha = (2E - I3 w3^2)/I1, beta = 2 m g l / I1, a = I3 w3 / I1, b = p_phi / I1,
    f = beta (u - u1)(u - u2)(u - u3) with u1 <= u2 <= 1 <= u3, and the period
      T = 2 int_{u1}^{u2} du / sqrt(f) = 4 K(k) / sqrt(beta (u3 - u1)),  k^2 = (u2 - u1)/(u3 - u1)
    (Gradshteyn & Ryzhik 3.131.5).
    """
    u0, s0 = math.cos(theta0), math.sin(theta0)
    w3 = psi_dot0 + phi_dot0 * u0
    a = i3 * w3 / i1
    b = (i1 * phi_dot0 * s0**2 + i3 * w3 * u0) / i1
    beta = 2.0 * m * g * l / i1
    alpha = theta_dot0**2 + phi_dot0**2 * s0**2 + beta * u0
    # f(u) = beta u^3 - (alpha + a^2) u^2 + (2 a b - beta) u + alpha - b^2
    roots = np.sort(np.roots([beta, -(alpha + a * a), 2.0 * a * b - beta, alpha - b * b]).real)
    u1, u2, u3 = (float(r) for r in roots)
    k2 = (u2 - u1) / (u3 - u1)
    period = 4.0 * float(ellipk(k2)) / math.sqrt(beta * (u3 - u1))
    return TopNutation(math.acos(min(u2, 1.0)), math.acos(max(u1, -1.0)), period, (u1, u2, u3),
                       (alpha, beta, a, b))


# ---------------------------------------------------------------------------------------------
# Bricard's mechanism (IFToMM benchmark A04)
# ---------------------------------------------------------------------------------------------

GRAVITY_BRICARD = np.array([0.0, -9.81, 0.0])  # [m/s^2], "gravity acting towards the negative y direction"
_E = np.eye(3)


def _rod_inertia(mass, length, side, direction):
    """Inertia tensor [kg m^2] about the centre of a square rod along the unit ``direction``:
    m (L^2 + s^2)/12 across it, m s^2/6 along it (a solid cuboid L x s x s)."""
    d = np.outer(direction, direction)
    return mass * (length**2 + side**2) / 12.0 * (np.eye(3) - d) + mass * side**2 / 6.0 * d


def _bricard_data(length=1.0, mass=1.0, side=0.1):
    """Geometry and inertia of A04 in its initial configuration (all global vectors) and in body frames.

    Five rods of 1 m and 1 kg with a 0.1 m square cross-section, six revolute joints, gravity -y
    (IFToMM library of computational benchmark problems, problem A04 "Bricard mechanism",
    lim.ii.udc.es/mbsbenchmark/dist/A04/A04_specification.xml; M. Gonzalez, D. Dopico, U. Lugris,
    J. Cuadrado, "A benchmarking system for MBS simulation software", Multibody System Dynamics 16,
    2006; properties as listed at rehabenggroup.github.io/MBSbenchmarksInOpenSim/benchmarks/
    A04_BricardsMechanism.html: rod length 1 m, mass 1 kg, square cross-section 0.1 m, 10 s).
    Joint points and axes of the initial configuration as in the A04 models of Exudyn
    (TestModels/bricardMechanism.py) and simEngine3D (simEngine3D_BricardMechanism.m), which both
    cite it: joints at P0..P5 = (0,0,0), (L,0,0), (L,-L,0), (L,-L,L), (0,-L,L), (0,0,L) about the global
    y, z, x, y, z, x axes; rod k runs from P(k-1) to Pk; ground holds the joints at P0 and P5.  Both
    models release it from rest.
    """
    points = length * np.array([[0, 0, 0], [1, 0, 0], [1, -1, 0], [1, -1, 1], [0, -1, 1], [0, 0, 1]], float)
    axes = _E[[1, 2, 0, 1, 2, 0]]
    rods, joints = [], []
    for k in range(5):
        x = (points[k + 1] - points[k]) / length
        rotation = np.column_stack([x, axes[k], np.cross(x, axes[k])])  # body x along the rod, y the first axis
        centre = 0.5 * (points[k] + points[k + 1])
        rods.append({"name": f"rod{k + 1}", "mass": mass, "length": length, "side": side,
                     "position": centre, "rotation": rotation,
                     "inertia_principal": np.array([mass * side**2 / 6.0] + 2 * [mass * (length**2 + side**2) / 12.0]),
                     "inertia": _rod_inertia(mass, length, side, x)})
    bodies = ["ground"] + [r["name"] for r in rods] + ["ground"]
    for k in range(6):
        joints.append({"name": f"J{k}", "first": bodies[k], "second": bodies[k + 1],
                       "point": points[k], "axis": axes[k]})
    return {"gravity": GRAVITY_BRICARD, "points": points, "axes": axes, "rods": rods, "joints": joints}


def body_marker(body: dict | None, point, axis):
    """(position [m], axes 3x3) in the frame of ``body`` (None: ground) of a joint marker at the global
    ``point`` whose z axis is the global unit ``axis``.  The marker's x axis is the global axis most
    perpendicular to ``axis``, projected off it, y = z x x: the two markers of a joint then coincide
    in the initial configuration."""
    rotation = np.eye(3) if body is None else body["rotation"]
    origin = np.zeros(3) if body is None else body["position"]
    z = np.asarray(axis, float)
    seed = _E[int(np.argmin(np.abs(z)))]
    x = seed - z * (seed @ z)
    x /= np.linalg.norm(x)
    axes = np.column_stack([x, np.cross(z, x), z])
    return rotation.T @ (np.asarray(point, float) - origin), rotation.T @ axes


BRICARD = _bricard_data()
"""A04 data: ``gravity`` [m/s^2]; ``points`` (6, 3) and ``axes`` (6, 3) of the joints J0..J5 [m, -];
``rods``: name, mass [kg], length [m], side [m], position of the centre [m], rotation body -> global
(x along the rod from its first to its second joint, y the first joint's axis), inertia_principal about
the body axes [kg m^2], inertia (global tensor) [kg m^2]; ``joints``: name, first, second (body names),
point and axis (global).  ``body_marker`` turns a joint into a marker in a body frame."""


@dataclass
class _ChainState:
    """Kinematics of the open chain ground - rod1 - ... - rod5 at joint angles q (global vectors)."""

    joint_points: np.ndarray  # p_k (6, 3): joint k's point; p_5 is the point of rod5 meeting ground at J5
    rotations: np.ndarray  # R_k (5, 3, 3): rotation of rod k from its initial pose
    axes: np.ndarray  # n_k (5, 3): axis of joint k (k = 0..4)
    centres: np.ndarray  # c_k (5, 3)


def _chain(q, data=BRICARD) -> _ChainState:
    """Positions of the chain cut at J5; q_k [rad] rotates rod k+1 about joint k relative to its parent."""
    ref = data["points"]
    rotation = np.eye(3)
    point = ref[0].copy()
    points, rotations, axes, centres = [point], [], [], []
    for k in range(5):
        n = rotation @ data["axes"][k]
        rotation = _rotation(n, q[k]) @ rotation
        span = rotation @ (ref[k + 1] - ref[k])
        axes.append(n)
        rotations.append(rotation)
        centres.append(point + 0.5 * span)
        point = point + span
        points.append(point)
    return _ChainState(np.array(points), np.array(rotations), np.array(axes), np.array(centres))


def _rotation(axis, angle):
    """Rodrigues' rotation matrix about the unit ``axis`` [-] by ``angle`` [rad]."""
    k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + math.sin(angle) * k + (1.0 - math.cos(angle)) * (k @ k)


def _closure(s: _ChainState, data=BRICARD):
    """Closure residual (5) at J5: rod5's joint point on the ground point, rod5's joint axis (the rotated
    global x) perpendicular to the ground's y and z axes."""
    axis = s.rotations[4] @ data["axes"][5]
    return np.concatenate([s.joint_points[5] - data["points"][5], [axis[1], axis[2]]])


def _closure_jacobian(s: _ChainState, data=BRICARD):
    """d closure / dq (5 x 5): joint k moves p_5 by n_k x (p_5 - p_k) and turns rod5's axis by n_k x a."""
    axis = s.rotations[4] @ data["axes"][5]
    g = np.empty((5, 5))
    for k in range(5):
        g[:3, k] = np.cross(s.axes[k], s.joint_points[5] - s.joint_points[k])
        g[3:, k] = np.cross(s.axes[k], axis)[1:]
    return g


def _rates(s: _ChainState, qd, qdd, data=BRICARD):
    """Angular velocities, accelerations and centre velocities, accelerations of the rods (global),
    and the closure's second derivative, by the recursion over the chain:
    w_k = w_(k-1) + n_k qd_k, a_k = a_(k-1) + n_k qdd_k + w_(k-1) x n_k qd_k, and for a point r from
    joint k on rod k: v = v_k + w_k x r, acc = acc_k + a_k x r + w_k x (w_k x r)."""
    w, alpha = np.zeros(3), np.zeros(3)
    v_joint, a_joint = np.zeros(3), np.zeros(3)
    out = {"w": [], "alpha": [], "v": [], "a": []}
    for k in range(5):
        n = s.axes[k]
        alpha = alpha + n * qdd[k] + np.cross(w, n) * qd[k]
        w = w + n * qd[k]
        r = s.joint_points[k + 1] - s.joint_points[k]
        half = 0.5 * r
        out["w"].append(w)
        out["alpha"].append(alpha)
        out["v"].append(v_joint + np.cross(w, half))
        out["a"].append(a_joint + np.cross(alpha, half) + np.cross(w, np.cross(w, half)))
        v_joint = v_joint + np.cross(w, r)
        a_joint = a_joint + np.cross(alpha, r) + np.cross(w, np.cross(w, r))
    result = {key: np.array(value) for key, value in out.items()}
    axis = s.rotations[4] @ data["axes"][5]
    turn = np.cross(alpha, axis) + np.cross(w, np.cross(w, axis))
    result["closure_acceleration"] = np.concatenate([a_joint, turn[1:]])
    return result


@dataclass
class BricardMotion:
    """Trajectory of A04 (arrays over ``t``)."""

    t: np.ndarray  # [s]
    joint_angles: np.ndarray  # (n, 5) q_k [rad] of joints J0..J4, 0 in the initial configuration
    joint_points: np.ndarray  # (n, 6, 3) [m], J0..J5 (J5 on rod5)
    centres: np.ndarray  # (n, 5, 3) rod centres [m]
    kinetic_energy: np.ndarray  # [J]
    potential_energy: np.ndarray  # [J], -sum m g . c
    closure_residual: np.ndarray  # max |closure| [m or -] at each t


class _BricardReduced:
    """A04 in one joint coordinate theta = q_i; the other four follow from the loop closure."""

    def __init__(self, independent: int = 0):
        self.independent = independent
        self.dependent = [k for k in range(5) if k != independent]
        self.q = np.zeros(5)  # last closed configuration: the start of the next Newton solve
        self.masses = np.array([rod["mass"] for rod in BRICARD["rods"]])
        self.inertia0 = np.array([rod["inertia"] for rod in BRICARD["rods"]])

    def close(self, theta: float) -> _ChainState:
        """Solve the closure for the dependent angles by Gauss-Newton (5 equations, 4 unknowns, one of
        them redundant; quadratic convergence because the equations are consistent)."""
        q = self.q.copy()
        q[self.independent] = theta
        for _ in range(30):
            s = _chain(q)
            residual = _closure(s)
            if np.max(np.abs(residual)) < 1e-14:
                break
            g = _closure_jacobian(s)[:, self.dependent]
            q[self.dependent] -= np.linalg.lstsq(g, residual, rcond=None)[0]
        else:
            raise RuntimeError(f"Bricard closure did not converge at theta = {theta}")
        self.q = q
        return s

    def velocity_map(self, s: _ChainState):
        """(B, c): qd = B theta', qdd = B theta'' + c theta'^2 on the closed loop."""
        g = _closure_jacobian(s)
        b = np.zeros(5)
        b[self.independent] = 1.0
        b[self.dependent] = -np.linalg.lstsq(g[:, self.dependent], g[:, self.independent], rcond=None)[0]
        bias = _rates(s, b, np.zeros(5))["closure_acceleration"]
        c = np.zeros(5)
        c[self.dependent] = -np.linalg.lstsq(g[:, self.dependent], bias, rcond=None)[0]
        return b, c

    def inertia(self, s: _ChainState):
        """Global inertia tensors R_k I0_k R_k^T [kg m^2] of the rods."""
        return np.einsum("kij,kjl,kml->kim", s.rotations, self.inertia0, s.rotations)

    def rhs(self, t, y):
        """Lagrange's equation in theta: sum over rods of the virtual power of
        (m a_c - m g) . dc/dtheta + (I alpha + w x I w) . dw/dtheta = 0."""
        theta, rate = y
        s = self.close(theta)
        b, c = self.velocity_map(s)
        unit = _rates(s, b, np.zeros(5))  # dc/dtheta (v), dw/dtheta (w)
        free = _rates(s, b * rate, c * rate**2)  # accelerations with theta'' = 0
        inertia = self.inertia(s)
        iw = np.einsum("kij,kj->ki", inertia, free["w"])
        force = self.masses[:, None] * (BRICARD["gravity"] - free["a"])
        moment = -(np.einsum("kij,kj->ki", inertia, free["alpha"]) + np.cross(free["w"], iw))
        generalized = np.sum(force * unit["v"]) + np.sum(moment * unit["w"])
        mass = np.sum(self.masses * np.sum(unit["v"] ** 2, axis=1)) + np.einsum(
            "ki,kij,kj->", unit["w"], inertia, unit["w"])
        return [rate, generalized / mass]

    def energies(self, theta, rate):
        """(kinetic, potential) [J] at theta [rad], theta' [rad/s]."""
        s = self.close(theta)
        b, _ = self.velocity_map(s)
        motion = _rates(s, b * rate, np.zeros(5))
        inertia = self.inertia(s)
        kinetic = 0.5 * np.sum(self.masses * np.sum(motion["v"] ** 2, axis=1)) + 0.5 * np.einsum(
            "ki,kij,kj->", motion["w"], inertia, motion["w"])
        potential = -np.sum(self.masses * (s.centres @ BRICARD["gravity"]))
        return kinetic, potential


def bricard_motion(t, rate0: float = 0.0, independent: int = 0, rtol: float = 1e-11) -> BricardMotion:
    """Motion of A04 from its initial configuration at the times t [s] (t[0] = 0).

    ``rate0`` [rad/s] is the initial rate of the independent joint angle q_independent (0: released
    from rest, as in the benchmark).  Minimal coordinates: the angle of one joint (J0 by default)
    is integrated with DOP853; at every evaluation the four other angles close the loop by Newton's
    method, their rates and accelerations follow from the closure's Jacobian (rank 4 of 5: one closure
    equation is redundant, Bricard's mechanism moves although Grubler counts 6 - 6 = 0 degrees of
    freedom).  Independent of the engine: joint coordinates instead of bodies with constraints.
    """
    model = _BricardReduced(independent)
    t = np.asarray(t, dtype=float)
    sol = solve_ivp(model.rhs, (0.0, t[-1]), [0.0, rate0], method="DOP853", t_eval=t, rtol=rtol,
                    atol=rtol * 1e-1)
    if not sol.success:
        raise RuntimeError(sol.message)
    model.q = np.zeros(5)
    rows = []
    for theta, rate in sol.y.T:
        s = model.close(theta)
        rows.append((model.q.copy(), s, *model.energies(theta, rate), np.max(np.abs(_closure(s)))))
    return BricardMotion(sol.t, np.array([r[0] for r in rows]), np.array([r[1].joint_points for r in rows]),
                         np.array([r[1].centres for r in rows]), np.array([r[2] for r in rows]),
                         np.array([r[3] for r in rows]), np.array([r[4] for r in rows]))


# ---------------------------------------------------------------------------------------------
# Haug's spatial slider-crank
# ---------------------------------------------------------------------------------------------

SPATIAL_SLIDER_CRANK = {
    # E. J. Haug, Computer-Aided Kinematics and Dynamics of Mechanical Systems, Allyn and Bacon, 1989,
    # the spatial slider-crank (data as transcribed in the simEngine3D course model
    # "sliderCrankMechanism.m, taken from ch. 12.2"); values marked (chosen) are not from that source.
    "gravity": np.array([0.0, 0.0, -9.81]),  # [m/s^2]
    "crank_pivot": np.array([0.0, 0.1, 0.12]),  # O, revolute to ground about the global x axis [m]
    "crank_length": 0.08,  # O to the spherical joint B [m]; the crank's centre of mass halfway
    "crank_mass": 0.12,  # [kg]
    "crank_inertia": np.array([1e-4, 1e-5, 1e-4]),  # about its centre; x the pivot axis, y along the crank [kg m^2]
    "rod_length": 0.3,  # B to the universal joint C [m]; centre of mass halfway
    "rod_mass": 0.5,  # [kg]
    "rod_inertia": np.array([4e-4, 4e-3, 4e-3]),  # about its centre; x along the rod [kg m^2]
    "slider_mass": 2.0,  # [kg], translates along the global x axis through the origin
    "slider_inertia": np.array([1e-4, 1e-4, 1e-4]),  # [kg m^2] (irrelevant: the slider does not turn)
    # universal joint C: the cross turns about the global z axis fixed in the slider and about the rod's
    # y axis, so the rod's y axis stays horizontal (chosen; the source's rod-slider joint is a
    # revolute-cylindrical composite)
    "universal_slider_axis": np.array([0.0, 0.0, 1.0]),
    "theta0": math.pi / 2,  # crank angle from the global +y axis about +x: the crank points up [rad] (chosen)
    "theta_dot0": 2 * math.pi,  # [rad/s], one turn a second as the source's driver (chosen as a free start)
    # joints as markers (body, point in the body frame [m], axes: columns x, y, z in the body frame);
    # body frames: crank x the pivot axis, y from O to B; rod x from B to C; slider and ground global
    "joints": [
        {"type": "revolute", "name": "crank_pivot",
         "first": ("ground", [0.0, 0.1, 0.12], [[0, 0, 1], [1, 0, 0], [0, 1, 0]]),
         "second": ("crank", [0.0, -0.04, 0.0], [[0, 0, 1], [1, 0, 0], [0, 1, 0]])},
        {"type": "spherical", "name": "crank_rod",
         "first": ("crank", [0.0, 0.04, 0.0], None), "second": ("rod", [-0.15, 0.0, 0.0], None)},
        {"type": "universal", "name": "rod_slider",  # cross axes: slider's global z, the rod's y
         "first": ("slider", [0.0, 0.0, 0.0], [[0, 1, 0], [0, 0, 1], [1, 0, 0]]),
         "second": ("rod", [0.15, 0.0, 0.0], None)},
        {"type": "translational", "name": "slider_guide",
         "first": ("ground", [0.0, 0.0, 0.0], [[0, 0, 1], [1, 0, 0], [0, 1, 0]]),
         "second": ("slider", [0.0, 0.0, 0.0], [[0, 0, 1], [1, 0, 0], [0, 1, 0]])},
    ],
}
"""Haug's spatial slider-crank: crank (revolute about x at O), rod (spherical at B, universal at C),
slider (translational along x).  ``slider_crank_pose`` gives the bodies' poses at a crank angle."""


def _jet_mul(a, b):
    """Product of truncated Taylor series (value, d/dtheta, d2/dtheta2) along the last axis."""
    return np.stack([a[..., 0] * b[..., 0], a[..., 1] * b[..., 0] + a[..., 0] * b[..., 1],
                     a[..., 2] * b[..., 0] + 2 * a[..., 1] * b[..., 1] + a[..., 0] * b[..., 2]], axis=-1)


def _jet_sqrt(a):
    s0 = np.sqrt(a[..., 0])
    s1 = a[..., 1] / (2 * s0)
    return np.stack([s0, s1, (a[..., 2] - 2 * s1**2) / (2 * s0)], axis=-1)


def _jet_inverse(a):
    r0 = 1.0 / a[..., 0]
    r1 = -a[..., 1] * r0 * r0
    return np.stack([r0, r1, -(a[..., 2] * r0 + 2 * a[..., 1] * r1) * r0], axis=-1)


def _jet_cross(u, v):
    """Cross product of 3-vectors of jets, shape (3, 3): (component, order)."""
    return np.stack([_jet_mul(u[1], v[2]) - _jet_mul(u[2], v[1]), _jet_mul(u[2], v[0]) - _jet_mul(u[0], v[2]),
                     _jet_mul(u[0], v[1]) - _jet_mul(u[1], v[0])])


def _jet_normalize(u):
    return _jet_mul(u, _jet_inverse(_jet_sqrt(np.sum(_jet_mul(u, u), axis=0)))[None, :])


def slider_crank_pose(theta: float, data=SPATIAL_SLIDER_CRANK) -> dict:
    """Poses of the spatial slider-crank at the crank angle theta [rad], each with its first and second
    derivative in theta (last axis: value, d/dtheta, d2/dtheta2).

    B = O + a (0, cos theta, sin theta); the slider's C = (s, 0, 0) with |C - B| = L gives
    s = B_x + sqrt(L^2 - B_y^2 - B_z^2) (the branch ahead of B); the rod's x axis is (C - B)/L, its
    y axis the unit a1 x x_rod (perpendicular to the universal joint's slider axis a1), z = x x y.
    Keys: crank_centre, rod_centre, slider (3, 3) [m]; rod_rotation (3, 3, 3) body -> global (columns
    the body axes); crank_rotation (3, 3) value only.
    """
    c, s = math.cos(theta), math.sin(theta)
    radial = np.array([[0.0, 0.0, 0.0], [c, -s, -c], [s, c, -s]])  # (0, cos, sin) with its derivatives
    pivot = np.zeros((3, 3))
    pivot[:, 0] = data["crank_pivot"]
    b = pivot + data["crank_length"] * radial
    length = data["rod_length"]
    offset = np.array([length**2, 0.0, 0.0]) - _jet_mul(b[1], b[1]) - _jet_mul(b[2], b[2])
    slider = np.zeros((3, 3))
    slider[0] = b[0] + _jet_sqrt(offset)
    x_rod = (slider - b) / length
    a1 = np.zeros((3, 3))
    a1[:, 0] = data["universal_slider_axis"]
    y_rod = _jet_normalize(_jet_cross(a1, x_rod))
    z_rod = _jet_cross(x_rod, y_rod)
    crank_rotation = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    return {"crank_centre": pivot + 0.5 * data["crank_length"] * radial, "rod_centre": 0.5 * (b + slider),
            "slider": slider, "rod_rotation": np.stack([x_rod, y_rod, z_rod], axis=1),
            "crank_rotation": crank_rotation, "joint_b": b}


def slider_crank_bodies(theta: float, theta_dot: float, data=SPATIAL_SLIDER_CRANK) -> dict:
    """Per body (crank, rod, slider): centre position [m], rotation body -> global, centre velocity [m/s]
    and GLOBAL angular velocity [rad/s] at the crank angle theta [rad] and rate theta_dot [rad/s]
    (w = vee(R' R^T) theta_dot), the initial state of a body-and-joint model of the same mechanism."""
    pose = slider_crank_pose(theta, data)
    rod = pose["rod_rotation"]
    bodies = {"crank": (pose["crank_centre"], pose["crank_rotation"], np.array([theta_dot, 0.0, 0.0])),
              "rod": (pose["rod_centre"], rod[..., 0], _vee(rod[..., 1] @ rod[..., 0].T) * theta_dot),
              "slider": (pose["slider"], np.eye(3), np.zeros(3))}
    return {name: {"position": centre[:, 0], "rotation": rotation, "velocity": centre[:, 1] * theta_dot,
                   "angular_velocity": w} for name, (centre, rotation, w) in bodies.items()}


def _vee(skew_matrix):
    return np.array([skew_matrix[2, 1], skew_matrix[0, 2], skew_matrix[1, 0]])


def slider_crank_mass(theta: float, data=SPATIAL_SLIDER_CRANK):
    """(m, dm/dtheta, dV/dtheta) of the reduced model T = m(theta) theta'^2 / 2 [kg m^2, kg m^2/rad, N m].

    m = J_c + m_c |c_c'|^2 + m_r |c_r'|^2 + w_b . I_r w_b + m_s s'^2, with the rod's body angular
    velocity per crank rate w_b = vee(R^T R') and its derivative vee(R'^T R' + R^T R''); J_c the crank's
    moment of inertia about the pivot axis through its centre (the centre's motion carries the rest)."""
    pose = slider_crank_pose(theta, data)
    rot = pose["rod_rotation"]
    w_body = _vee(rot[..., 0].T @ rot[..., 1])
    w_body_rate = _vee(rot[..., 1].T @ rot[..., 1] + rot[..., 0].T @ rot[..., 2])
    inertia = data["rod_inertia"]
    mass, rate = data["crank_inertia"][0] + w_body @ (inertia * w_body), 2.0 * w_body @ (inertia * w_body_rate)
    gravity_gradient = 0.0
    for key, m in (("crank_centre", data["crank_mass"]), ("rod_centre", data["rod_mass"]),
                   ("slider", data["slider_mass"])):
        centre = pose[key]
        mass += m * centre[:, 1] @ centre[:, 1]
        rate += 2.0 * m * centre[:, 1] @ centre[:, 2]
        gravity_gradient -= m * data["gravity"] @ centre[:, 1]
    return mass, rate, gravity_gradient


@dataclass
class SliderCrankMotion:
    """Trajectory of the spatial slider-crank (arrays over ``t``)."""

    t: np.ndarray  # [s]
    theta: np.ndarray  # crank angle [rad]
    theta_dot: np.ndarray  # [rad/s]
    slider: np.ndarray  # slider position along x [m]
    energy: np.ndarray  # kinetic + potential (gravity, 0 at z = 0) [J]


def slider_crank_motion(t, theta0=None, theta_dot0=None, torque=0.0, data=SPATIAL_SLIDER_CRANK,
                        rtol: float = 1e-12) -> SliderCrankMotion:
    """Free motion of the spatial slider-crank under gravity and a constant crank torque [N m] about +x.

    Lagrange's equation in the crank angle: m(theta) theta'' + m'(theta) theta'^2 / 2 + V'(theta) = torque,
    integrated by DOP853 (Haug 1989's mechanism; an independent minimal-coordinate model: the engine
    uses bodies and joint constraints).  Defaults: theta0, theta_dot0 of ``data``.
    """
    theta0 = data["theta0"] if theta0 is None else theta0
    theta_dot0 = data["theta_dot0"] if theta_dot0 is None else theta_dot0

    def rhs(_, y):
        mass, rate, gradient = slider_crank_mass(y[0], data)
        return [y[1], (torque - gradient - 0.5 * rate * y[1] ** 2) / mass]

    t = np.asarray(t, dtype=float)
    sol = solve_ivp(rhs, (t[0], t[-1]), [theta0, theta_dot0], method="DOP853", t_eval=t, rtol=rtol,
                    atol=rtol * 1e-2)
    if not sol.success:
        raise RuntimeError(sol.message)
    slider, energy = [], []
    for theta, rate in sol.y.T:
        pose = slider_crank_pose(theta, data)
        mass = slider_crank_mass(theta, data)[0]
        height = sum(data[m] * pose[k][2, 0] for k, m in (("crank_centre", "crank_mass"), ("rod_centre", "rod_mass"),
                                                         ("slider", "slider_mass")))
        slider.append(pose["slider"][0, 0])
        energy.append(0.5 * mass * rate**2 - data["gravity"][2] * height)
    return SliderCrankMotion(sol.t, sol.y[0], sol.y[1], np.array(slider), np.array(energy))


# ---------------------------------------------------------------------------------------------
# closed-chamber hydraulic spring at a spatial angle
# ---------------------------------------------------------------------------------------------


def closed_chamber_angular_frequency(p, stroke: float) -> float:
    """omega = sqrt(beta (A1^2/V1 + A2^2/V2) / m) [rad/s] of a mass m on a cylinder with both chambers
    closed (Merritt, Hydraulic Control Systems, 1967, the hydraulic spring; for equal areas A it is
    omega^2 = beta A^2 (1/V1 + 1/V2) / m).  ``p`` is a reference_hydraulic.CylinderParameters, whose
    ``closed_chamber_stiffness`` gives the stiffness; stroke [m].  The frequency does not depend on the
    cylinder's direction in space: gravity only moves the equilibrium stroke (see ``axial_gravity``)."""
    from reference_hydraulic import closed_chamber_stiffness

    return math.sqrt(closed_chamber_stiffness(p, stroke) / p.mass)


def axial_gravity(axis, gravity) -> float:
    """Component [m/s^2] of the gravity vector [m/s^2] along the cylinder's unit extension ``axis``
    (a non-unit axis is normalised): the ``axial_gravity`` of reference_hydraulic.CylinderParameters."""
    axis = np.asarray(axis, dtype=float)
    return float(np.asarray(gravity, dtype=float) @ axis / np.linalg.norm(axis))
