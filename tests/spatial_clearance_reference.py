"""Independent reference for the spatial clearance revolute joint: one free journal in a bore fixed to the ground.

Written from the theory pages alone (docs/theory/spatial-clearance-revolute.md and
docs/theory/spatial-clearance-geometry.md), with math, numpy and scipy, nothing from jointplay, so that the
engine's element can be compared with a second reading of the same law.  SI units throughout.

The bore is fixed to the ground: bearing marker at the origin, its axes the global ones (z the bore axis).
The journal marker is the journal body's centre of mass, its axes the body's principal axes (z the journal
axis).  The body moves by Newton-Euler: centre of mass velocity in global coordinates, angular velocity in
body coordinates, unit quaternion (w, x, y, z) body -> global, ``q' = q (x) (0, w) / 2`` (Sola 2017, eq. 214).

The law, as the pages state it and computed here by a separate route:

* radial: a bore section at ``s`` penetrates the journal's cylinder by ``delta(s) = R_j - min_phi dist(Q(phi),
  axis)``, the minimum over the section circle found by Newton on ``d(dist^2)/dphi`` from the direction of the
  axis' offset (from 64 samples when the offset is small against the tilt's ellipse); each half of the bore
  carries per unit length ``F_el(delta(s))/L`` with the Lankarani-Nikravesh factor of its own rate and the half's
  latched onset rate, and stiction friction against its own sliding velocity; the penetrated part of a half
  (from its end values, the root by Brent's method) is integrated by 8-point Gauss-Legendre, after ``s = s0 +
  (s1 - s0) v^2`` from the root ``s0`` when one end touches;
* axial: the flange ring ``R_b..r_o`` penetrates the face's plane by a linear function of the point; the
  pressure ``k_a delta / A`` (with its own damping factor and friction) is integrated over the part of the ring
  that touches, exactly in angle (the touching arc of each radius, Gauss-Legendre inside it) and by
  Gauss-Legendre in radius;
* each candidate's onset rate is the penetration rate at its deepest point when its deepest penetration crosses
  zero upwards, located by ``solve_ivp``'s events (the run restarts there), floored at the onset floor.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

__all__ = ["Journal", "ReferenceRun", "simulate", "rotation", "section", "candidates"]

GAUSS_RADIAL = np.polynomial.legendre.leggauss(8)
GAUSS_RING_R = np.polynomial.legendre.leggauss(12)
GAUSS_RING_ANGLE = np.polynomial.legendre.leggauss(16)


@dataclass(frozen=True)
class Journal:
    """The case: dimensions [m], materials [Pa, -], laws, the body [kg, kg m^2] and its start."""

    bore_radius: float = 0.010
    clearance: float = 0.5e-3
    bearing_length: float = 0.020
    axial_clearance: float = 0.4e-3
    flange_radius: float = 0.015
    face_radius: float = 0.016
    youngs_modulus: float = 207e9
    poisson_ratio: float = 0.3
    restitution: float = 0.9
    static_coefficient: float = 0.15
    kinetic_coefficient: float = 0.10
    stiction_velocity: float = 1e-5
    transition_velocity: float = 5e-5
    onset_floor: float = 1e-4
    mass: float = 1.0
    inertia: tuple = (1e-3, 1e-3, 5e-4)
    gravity: tuple = (0.0, -9.81, 0.0)
    velocity: tuple = (0.0, 0.0, 0.010)
    angular_velocity: tuple = (2.0, 0.0, 30.0)

    @property
    def journal_radius(self) -> float:
        return self.bore_radius - self.clearance

    @property
    def plane_strain_modulus(self) -> float:
        """E* of two equal materials [Pa]: 1/E* = 2 (1 - nu^2)/E."""
        return self.youngs_modulus / (2.0 * (1.0 - self.poisson_ratio ** 2))

    @property
    def hertz_stiffness(self) -> float:
        """K = (4/3) E* sqrt(R*), R* = R_b R_j / c [N/m^1.5] (stiffness-hertz-cylinder.md)."""
        r_star = self.bore_radius * self.journal_radius / self.clearance
        return 4.0 / 3.0 * self.plane_strain_modulus * math.sqrt(r_star)

    @property
    def ring_outer_radius(self) -> float:
        return min(self.flange_radius, self.face_radius)

    @property
    def ring_area(self) -> float:
        return math.pi * (self.ring_outer_radius ** 2 - self.bore_radius ** 2)

    @property
    def axial_stiffness(self) -> float:
        """Flat punch of the ring's area on a half-space, 2 E* sqrt(A/pi) [N/m] (Johnson 1985, 3.8)."""
        return 2.0 * self.plane_strain_modulus * math.sqrt(self.ring_area / math.pi)

    @property
    def hysteresis(self) -> float:
        """Lankarani-Nikravesh D = 3 (1 - e^2)/4."""
        return 0.75 * (1.0 - self.restitution ** 2)


def rotation(q) -> np.ndarray:
    """Active rotation body -> global of the quaternion (w, x, y, z), normalised first."""
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def friction_coefficient(j: Journal, speed: float) -> float:
    """Stiction law's coefficient at a sliding speed >= 0 (friction-stiction.md, ADAMS STEP)."""
    def step(x, x0, h0, x1, h1):
        s = min(max((x - x0) / (x1 - x0), 0.0), 1.0)
        return h0 + (h1 - h0) * s * s * (3.0 - 2.0 * s)
    if speed <= j.stiction_velocity:
        return step(speed, -j.stiction_velocity, -j.static_coefficient, j.stiction_velocity, j.static_coefficient)
    if speed < j.transition_velocity:
        return step(speed, j.stiction_velocity, j.static_coefficient, j.transition_velocity, j.kinetic_coefficient)
    return j.kinetic_coefficient


def _squared_distance_terms(phi, rb, p, u, s):
    """d^2 of the section point at phi from the axis (p, u), with its first and second phi-derivatives."""
    c, sn = math.cos(phi), math.sin(phi)
    w = (rb * c - p[0], rb * sn - p[1], s - p[2])
    t = (-rb * sn, rb * c, 0.0)
    a = (-rb * c, -rb * sn, 0.0)
    wu = w[0] * u[0] + w[1] * u[1] + w[2] * u[2]
    tu = t[0] * u[0] + t[1] * u[1]
    au = a[0] * u[0] + a[1] * u[1]
    g = w[0] ** 2 + w[1] ** 2 + w[2] ** 2 - wu * wu
    g1 = 2.0 * (w[0] * t[0] + w[1] * t[1]) - 2.0 * wu * tu
    g2 = 2.0 * (rb * rb + w[0] * a[0] + w[1] * a[1]) - 2.0 * (tu * tu + wu * au)
    return g, g1, g2


def _closest_angle(rb, p, u, s):
    """Angle of the section circle's point nearest the journal axis: Newton on d(d^2)/dphi."""
    mu = -p[0] * u[0] - p[1] * u[1] + (s - p[2]) * u[2]
    fx, fy = p[0] + mu * u[0], p[1] + mu * u[1]
    tilt2 = u[0] ** 2 + u[1] ** 2
    if math.hypot(fx, fy) > 2.0 * rb * tilt2:
        phi = math.atan2(fy, fx)
    else:
        grid = np.linspace(0.0, 2.0 * math.pi, 64, endpoint=False)
        phi = float(grid[np.argmin([_squared_distance_terms(a, rb, p, u, s)[0] for a in grid])])
    for _ in range(30):
        _, g1, g2 = _squared_distance_terms(phi, rb, p, u, s)
        step = g1 / g2 if g2 > 0.0 else 0.05 * math.copysign(1.0, g1)
        step = max(-0.2, min(0.2, step))
        phi -= step
        if abs(step) < 1e-15:
            break
    return phi


def section(j: Journal, p, u, s: float):
    """Penetration delta [m], journal point P, normal n (global) of the bore section at s, for the journal axis
    through p along u (bearing = global frame)."""
    rb = j.bore_radius
    phi = _closest_angle(rb, p, u, s)
    q = np.array([rb * math.cos(phi), rb * math.sin(phi), s])
    w = q - p
    foot = p + (w @ u) * u
    radial = q - foot
    dist = float(np.linalg.norm(radial))
    n = radial / dist
    return j.journal_radius - dist, foot + j.journal_radius * n, n


def _flange_frame(j: Journal, k: int, r, rot):
    """Flange k's centre, the penetration at its centre, and (rho, theta0) of delta = dc + r rho cos(th - th0)."""
    centre = r + k * 0.5 * (j.bearing_length + j.axial_clearance) * rot[:, 2]
    dc = 0.5 * j.bearing_length - k * centre[2]
    ax, ay = -k * rot[2, 0], -k * rot[2, 1]
    return centre, dc, math.hypot(ax, ay), math.atan2(ay, ax)


@dataclass
class State:
    """The body's pose and velocities unpacked from the integration state."""

    r: np.ndarray
    rot: np.ndarray
    v: np.ndarray
    w_body: np.ndarray

    @property
    def w_global(self):
        return self.rot @ self.w_body

    def point_velocity(self, point):
        return self.v + np.cross(self.w_global, point - self.r)


def unpack(y) -> State:
    return State(np.asarray(y[0:3]), rotation(y[3:7]), np.asarray(y[7:10]), np.asarray(y[10:13]))


def deepest(j: Journal, st: State):
    """Deepest penetration of the four candidates (half A, half B, flange A, flange B) and each one's rate there."""
    u = st.rot[:, 2]
    out = []
    ends = {s: section(j, st.r, u, s) for s in (-0.5 * j.bearing_length, 0.0, 0.5 * j.bearing_length)}
    for a, b in ((-0.5 * j.bearing_length, 0.0), (0.0, 0.5 * j.bearing_length)):
        d, p, n = max(ends[a], ends[b], key=lambda e: e[0])
        out.append((d, float(n @ st.point_velocity(p))))
    for k in (-1, 1):
        centre, dc, rho, th0 = _flange_frame(j, k, st.r, st.rot)
        ro = j.ring_outer_radius
        point = centre + ro * (math.cos(th0) * st.rot[:, 0] + math.sin(th0) * st.rot[:, 1])
        n = np.array([0.0, 0.0, -float(k)])
        out.append((dc + ro * rho, float(n @ st.point_velocity(point))))
    return out


def _loads(j: Journal, st: State, points, normals, elastic, weights, onset):
    """Force, moment about the centre of mass, normal and friction force [N, N m, N, N] of points carrying
    ``elastic`` per unit length or area along ``-normals``, with quadrature ``weights``: the Lankarani-Nikravesh
    factor of each point's own rate, clamped at zero, and stiction friction against its own sliding velocity."""
    vp = st.v + np.cross(st.w_global, points - st.r)
    rate = np.einsum("ij,ij->i", normals, vp)
    fn = np.maximum(elastic * (1.0 + j.hysteresis * rate / onset), 0.0)
    vt = vp - rate[:, None] * normals
    speed = np.linalg.norm(vt, axis=1)
    mu = np.array([friction_coefficient(j, v) for v in speed])
    direction = vt / np.where(speed > 0.0, speed, 1.0)[:, None]
    force = -(fn * weights)[:, None] * normals - (mu * fn * weights)[:, None] * direction
    moment = np.cross(points - st.r, force)
    return force.sum(axis=0), moment.sum(axis=0), float(fn @ weights), float((mu * fn) @ weights)


NOTHING = (np.zeros(3), np.zeros(3), 0.0, 0.0)


def _half_load(j: Journal, st: State, a: float, b: float, onset: float):
    """Loads of one bore half: its penetrated part by 8-point Gauss-Legendre."""
    u = st.rot[:, 2]
    da, db = section(j, st.r, u, a)[0], section(j, st.r, u, b)[0]
    if not (math.isfinite(da) and math.isfinite(db)):
        # a trial stage far outside the bore: non-finite loads make the integrator reject the step
        return np.full(3, np.nan), np.full(3, np.nan), math.nan, math.nan
    if da <= 0.0 and db <= 0.0:
        return NOTHING
    nodes, weights = GAUSS_RADIAL
    x = 0.5 * (nodes + 1.0)
    if da > 0.0 and db > 0.0:
        where, w = a + (b - a) * x, 0.5 * (b - a) * weights
    else:
        root = brentq(lambda s: section(j, st.r, u, s)[0], a, b, xtol=1e-15 * j.bearing_length)
        end = b if db > 0.0 else a
        where, w = root + (end - root) * x * x, abs(end - root) * x * weights
    slices = [section(j, st.r, u, s) for s in where]
    delta = np.array([max(d, 0.0) for d, _, _ in slices])
    points = np.array([p for _, p, _ in slices])
    normals = np.array([n for _, _, n in slices])
    elastic = j.hertz_stiffness * delta ** 1.5 / j.bearing_length
    return _loads(j, st, points, normals, elastic, w, onset)


def _flange_load(j: Journal, st: State, k: int, onset: float):
    """Loads of flange k over the touching part of its ring: the touching arc of each radius exactly, Gauss-Legendre
    in angle inside it and in radius."""
    centre, dc, rho, th0 = _flange_frame(j, k, st.r, st.rot)
    rb, ro = j.bore_radius, j.ring_outer_radius
    if dc + ro * rho <= 0.0:
        return NOTHING
    r_in = rb if dc > 0.0 or rho == 0.0 else max(rb, -dc / rho)
    rn, rw = GAUSS_RING_R
    an, aw = GAUSS_RING_ANGLE
    radius = r_in + 0.5 * (rn + 1.0) * (ro - r_in)
    ratio = np.divide(-dc, rho * radius, out=np.full_like(radius, -2.0 if dc > 0 else 2.0), where=rho > 0.0)
    half = np.arccos(np.clip(ratio, -1.0, 1.0))
    rr = np.repeat(radius, an.size)
    th = th0 + np.outer(half, an).ravel()
    weight = (np.outer(0.5 * (ro - r_in) * rw * radius * half, aw)).ravel()
    points = centre + rr[:, None] * (np.cos(th)[:, None] * st.rot[:, 0] + np.sin(th)[:, None] * st.rot[:, 1])
    delta = np.maximum(dc + rr * rho * np.cos(th - th0), 0.0)
    normals = np.tile([0.0, 0.0, -float(k)], (rr.size, 1))
    return _loads(j, st, points, normals, j.axial_stiffness / j.ring_area * delta, weight, onset)


def candidates(j: Journal, st: State, onsets):
    """Loads of the four candidates: lists of (force, moment about the centre of mass, fn, ft)."""
    half = 0.5 * j.bearing_length
    return [_half_load(j, st, -half, 0.0, onsets[0]), _half_load(j, st, 0.0, half, onsets[1]),
            _flange_load(j, st, -1, onsets[2]), _flange_load(j, st, 1, onsets[3])]


def derivative(j: Journal, y, onsets):
    """Newton-Euler with the joint's wrench: r' = v, q' = q (x) (0, w)/2, m v' = m g + F, J w' = M - w x J w."""
    with np.errstate(over="ignore", invalid="ignore"):
        return _derivative(j, y, onsets)


def _derivative(j: Journal, y, onsets):
    st = unpack(y)
    force, moment = j.mass * np.asarray(j.gravity), np.zeros(3)
    for f, m, _, _ in candidates(j, st, onsets):
        force += f
        moment += m
    inertia = np.asarray(j.inertia)
    w = st.w_body
    dw = (st.rot.T @ moment - np.cross(w, inertia * w)) / inertia
    qw, qx, qy, qz = y[3:7]
    dq = 0.5 * np.array([-qx * w[0] - qy * w[1] - qz * w[2],
                         qw * w[0] + qy * w[2] - qz * w[1],
                         qw * w[1] + qz * w[0] - qx * w[2],
                         qw * w[2] + qx * w[1] - qy * w[0]])
    return np.concatenate([st.v, dq, force / j.mass, dw])


@dataclass
class ReferenceRun:
    """Pieces of dense output with the onset rates in force over each, and the onsets located [s, -, m/s]."""

    pieces: list = field(default_factory=list)
    onsets: list = field(default_factory=list)

    def state(self, t: float):
        for t0, t1, sol, latched in self.pieces:
            if t0 <= t <= t1:
                return sol(t), latched
        raise ValueError(f"time {t} outside the run")

    def states(self, times):
        return np.array([self.state(t)[0] for t in times])


def simulate(j: Journal, t_end: float, rtol: float = 1e-10, atol: float = 1e-13) -> ReferenceRun:
    """Integrates the journal from centred and aligned at rest position with its start velocities to t_end [s]
    by DOP853, restarting at every contact onset to latch the candidate's onset rate."""
    y = np.concatenate([np.zeros(3), [1.0, 0.0, 0.0, 0.0], j.velocity, j.angular_velocity])
    t, latched = 0.0, [j.onset_floor] * 4
    shift = [0.0] * 4
    run = ReferenceRun()

    def event(k):
        def g(t, yy):
            return deepest(j, unpack(yy))[k][0] + shift[k]
        g.terminal, g.direction = True, 1.0
        return g

    events = [event(k) for k in range(4)]
    while t < t_end:
        # a trial stage of a too-long step may throw the body far out: its non-finite derivative is rejected
        sol = solve_ivp(lambda tt, yy: derivative(j, yy, latched), (t, t_end), y, method="DOP853", rtol=rtol,
                        atol=atol, dense_output=True, events=events)
        if sol.status < 0:
            raise RuntimeError(sol.message)
        run.pieces.append((t, float(sol.t[-1]), sol.sol, list(latched)))
        t, y = float(sol.t[-1]), sol.y[:, -1]
        if sol.status == 1:
            now = deepest(j, unpack(y))
            for k in range(4):
                if len(sol.t_events[k]) and abs(sol.t_events[k][0] - t) <= 1e-14:
                    latched[k] = max(now[k][1], j.onset_floor)
                    shift[k] = max(0.0, -now[k][0]) + 1e-15
                    run.onsets.append((t, k, latched[k]))
            for k in range(4):
                if not (len(sol.t_events[k]) and abs(sol.t_events[k][0] - t) <= 1e-14):
                    shift[k] = 0.0
    return run
