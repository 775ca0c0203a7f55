"""Independent reference for a slider-crank whose connecting rod is a geometrically exact planar beam.

Written apart from the engine, from docs/theory/beam.md and Simo and Vu-Quoc, "On the dynamics of
flexible beams under large overall motions - the plane case", J. Appl. Mech. 53 (1986) 849-863; it
imports numpy and scipy only. The engine keeps every body in absolute coordinates and the joints as
equations with Lagrange multipliers; here the joints are eliminated by hand and the rod's remaining
nodal coordinates are integrated as an ordinary differential equation with ``scipy.integrate.solve_ivp``.

Mechanism (all values chosen for this check, none from a paper):

- crank O-A of length ``a`` = 50 mm pinned at the origin, its angle prescribed: at rest until t = 0,
  then the speed ramp ``phi_dot = (w/T) (t - (T/2 pi) sin(2 pi t/T))`` to ``w`` = 150 rad/s over
  ``T`` = 40 ms (acceleration ``(w/T)(1 - cos(2 pi t/T))``, zero at both ends of the ramp), then
  constant speed (a smooth start: rate and acceleration are zero at t = 0, and no sudden load sets the
  rod's stiff modes ringing);
- connecting rod A-B: a straight, unstressed steel bar of length ``L`` = 300 mm, solid rectangular
  section 10 mm wide (out of the plane) and ``h`` = 8 mm deep (in the plane), E = 207 GPa, nu = 0.3,
  7850 kg/m^3; Cowper's shear factor of a rectangle ``k = 10 (1 + nu) / (12 + 11 nu)``,
  ``G = E / (2 (1 + nu))``; undamped; ``n`` quadratic (3-node) elements of equal length (4 by default),
  or linear (2-node) ones;
- slider of mass ``m_s`` = 0.5 kg on the x axis, pinned to the rod's far end B;
- no gravity: the straight, unstressed rod at rest with the crank along +x is an equilibrium at t = 0,
  and the crank's acceleration is zero then too; the engine starts from the same state (a beam given no
  velocity, a crank at rest), so no initial velocity field has to be matched.

Model (docs/theory/beam.md). Nodes carry ``(x, y, theta)`` in the inertial frame; position and section
angle are interpolated with the same Lagrange shape functions ``N_a(xi)``. With
``(m_1, m_2) = Lambda(theta)^T r'`` the strains are ``Gamma_1 = m_1 - 1``, ``Gamma_2 = m_2``,
``kappa = theta'`` (the reference is straight along the initial direction with ``theta_0`` its angle,
so ``Lambda(theta_0)^T r_0' = (1, 0)``), the resultants ``N = EA Gamma_1``, ``Q = kGA Gamma_2``,
``M = EI kappa``, and the internal force of node ``a`` is the virtual work

    f_a = integral [ N_a' (N cos theta - Q sin theta),
                     N_a' (N sin theta + Q cos theta),
                     N_a (N m_2 - Q m_1) + N_a' M ] dS

integrated with the reduced Gauss rule (1 point for a linear element, 2 for a quadratic one). The mass
is the consistent one, ``integral rhoA N_a N_b dS`` for x and y and ``integral rhoI N_a N_b dS`` for
theta, integrated exactly (2 and 3 Gauss points); it is constant.

Elimination of the joints. Revolute A prescribes the first node's translation,
``(x_0, y_0) = a (cos phi, sin phi)``, and leaves its section angle free; the guide and revolute B
hold the last node on the slider line, ``y_n = 0``, and make the slider's position its ``x_n``, so the
slider's kinetic energy ``m_s x_n_dot^2 / 2`` adds ``m_s`` to the mass of ``x_n``. With ``f`` the
remaining (free) coordinates and ``p`` the prescribed ones, the rows of ``M q_ddot + f_int(q) = 0``
that belong to the free coordinates (the joints' reactions act on the prescribed ones only) give

    M_ff a_f = -f_int,f(q) - M_fp a_p(t)

a constant mass matrix and the prescribed accelerations entering through the consistent mass coupling.

Stresses at a section: like the engine's strain gauge (docs/theory/beam.md, "Strain gauges"), the
resultants are taken at the points of the reduced rule (Barlow points) and interpolated along the
element by the Lagrange polynomial through them (constant over a linear element, linear over a
quadratic one).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp
from scipy.linalg import cho_factor, cho_solve

__all__ = ["Parameters", "Reference", "simulate", "speed_ramp", "rigid_slider", "midspan_deflection"]


@dataclass(frozen=True)
class Parameters:
    """The mechanism, SI units (chosen values: see the module docstring)."""

    crank_length: float = 0.05  # a [m]
    rod_length: float = 0.30  # L [m]
    crank_speed: float = 150.0  # w, final [rad/s]
    ramp_time: float = 0.04  # T [s]
    width: float = 0.010  # section, out of the plane [m]
    depth: float = 0.008  # section, in the plane of bending [m]
    youngs_modulus: float = 207e9  # [Pa]
    poisson_ratio: float = 0.3
    density: float = 7850.0  # [kg/m^3]
    slider_mass: float = 0.5  # [kg]
    elements: int = 4
    order: int = 2  # 1: linear (2-node) elements, 2: quadratic (3-node) ones

    # section resultants (docs/theory/beam.md, "Constitutive law")
    @property
    def area(self) -> float:
        return self.width * self.depth

    @property
    def second_moment(self) -> float:
        return self.width * self.depth ** 3 / 12.0

    @property
    def EA(self) -> float:
        return self.youngs_modulus * self.area

    @property
    def kGA(self) -> float:
        nu = self.poisson_ratio
        shear_factor = 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu)  # Cowper, solid rectangle
        return shear_factor * self.youngs_modulus / (2.0 * (1.0 + nu)) * self.area

    @property
    def EI(self) -> float:
        return self.youngs_modulus * self.second_moment

    @property
    def rhoA(self) -> float:
        return self.density * self.area

    @property
    def rhoI(self) -> float:
        return self.density * self.second_moment

    @property
    def nodes(self) -> int:
        return self.elements * self.order + 1

    @property
    def element_length(self) -> float:
        return self.rod_length / self.elements


def speed_ramp(t, w: float, ramp: float):
    """Crank angle, rate and acceleration of the speed ramp from rest (arrays like ``t``)."""
    t = np.asarray(t, dtype=float)
    tau = np.clip(t, 0.0, ramp)
    k = 2.0 * math.pi / ramp
    angle = (w / ramp) * (tau ** 2 / 2.0 + (np.cos(k * tau) - 1.0) / k ** 2) + w * np.maximum(t - ramp, 0.0)
    rate = (w / ramp) * (tau - np.sin(k * tau) / k) + 0.0 * t
    acceleration = np.where((t >= 0.0) & (t <= ramp), (w / ramp) * (1.0 - np.cos(k * tau)), 0.0)
    return angle, rate, acceleration


def rigid_slider(t, p: Parameters):
    """Slider position [m], velocity [m/s] and acceleration [m/s^2] of the same crank motion with a rigid rod
    of length L, for the check that the rod's flexibility matters: ``x = a cos phi + sqrt(L^2 - s^2)``,
    ``s = a sin phi``."""
    phi, dphi, ddphi = speed_ramp(t, p.crank_speed, p.ramp_time)
    a, length = p.crank_length, p.rod_length
    s, ds = a * np.sin(phi), a * np.cos(phi) * dphi
    dds = -a * np.sin(phi) * dphi ** 2 + a * np.cos(phi) * ddphi
    r = np.sqrt(length ** 2 - s ** 2)
    dr = -s * ds / r
    ddr = -(ds ** 2 + s * dds) / r - (s * ds) ** 2 / r ** 3
    x = a * np.cos(phi) + r
    v = -a * np.sin(phi) * dphi + dr
    acc = -a * np.cos(phi) * dphi ** 2 - a * np.sin(phi) * ddphi + ddr
    return x, v, acc


def midspan_deflection(x0, y0, xm, ym, xn, yn):
    """Transverse deflection [m] of the mid-span point from the chord joining the ends, positive to the
    left of the chord's direction (first end to last)."""
    cx, cy = xn - x0, yn - y0
    chord = np.hypot(cx, cy)
    return (-(cy / chord) * (xm - 0.5 * (x0 + xn)) + (cx / chord) * (ym - 0.5 * (y0 + yn)))


# element shape functions on xi in [-1, 1] ------------------------------------------------------------

def _shape(order: int, xi):
    """Lagrange shape functions and their xi-derivatives at the points ``xi`` (arrays n_points x nodes)."""
    xi = np.asarray(xi, dtype=float)
    if order == 1:
        n = np.stack([(1 - xi) / 2, (1 + xi) / 2], axis=-1)
        dn = np.stack([-0.5 + 0 * xi, 0.5 + 0 * xi], axis=-1)
    elif order == 2:
        n = np.stack([xi * (xi - 1) / 2, 1 - xi ** 2, xi * (xi + 1) / 2], axis=-1)
        dn = np.stack([xi - 0.5, -2 * xi, xi + 0.5], axis=-1)
    else:
        raise ValueError(f"order must be 1 or 2, got {order}")
    return n, dn


class _Rod:
    """The rod's discrete model: consistent mass, reduced-rule internal forces, section resultants."""

    def __init__(self, p: Parameters):
        self.p = p
        self.le = p.element_length
        self.jac = self.le / 2.0  # dS / dxi
        k = p.order
        self.connect = np.array([[e * k + j for j in range(k + 1)] for e in range(p.elements)])  # (E, k+1)
        # reduced rule for the stiffness terms: k Gauss points
        self.xi_r, self.w_r = np.polynomial.legendre.leggauss(k)
        self.n_r, dn = _shape(k, self.xi_r)
        self.dn_r = dn / self.jac  # d/dS
        # consistent mass, integrated exactly (k + 1 Gauss points: degree 2k integrands)
        xi_m, w_m = np.polynomial.legendre.leggauss(k + 1)
        n_m, _ = _shape(k, xi_m)
        me = np.einsum("g,ga,gb->ab", w_m * self.jac, n_m, n_m)  # integral N_a N_b dS
        nn = p.nodes
        self.mass = np.zeros((3 * nn, 3 * nn))
        for nodes in self.connect:
            for i, a in enumerate(nodes):
                for j, b in enumerate(nodes):
                    self.mass[3 * a, 3 * b] += p.rhoA * me[i, j]
                    self.mass[3 * a + 1, 3 * b + 1] += p.rhoA * me[i, j]
                    self.mass[3 * a + 2, 3 * b + 2] += p.rhoI * me[i, j]
        # assembly: element force components (E, k+1, 3), flattened, to the global vector
        self.scatter = np.zeros((p.elements * (k + 1) * 3, 3 * nn))
        for e, nodes in enumerate(self.connect):
            for j, a in enumerate(nodes):
                for c in range(3):
                    self.scatter[(e * (k + 1) + j) * 3 + c, 3 * a + c] = 1.0

    def strains(self, q):
        """Gauss-point quantities of the reduced rule for nodal coordinates ``q`` (..., 3 x nodes), real or
        complex: (theta, m1, m2, N, Q, M), each (..., E, G)."""
        p = self.p
        nodal = q.reshape(q.shape[:-1] + (-1, 3))[..., self.connect, :]  # (..., E, k+1, 3)
        dx = nodal[..., 0] @ self.dn_r.T  # x' at the points (..., E, G)
        dy = nodal[..., 1] @ self.dn_r.T
        theta = nodal[..., 2] @ self.n_r.T
        dtheta = nodal[..., 2] @ self.dn_r.T
        c, s = np.cos(theta), np.sin(theta)
        m1 = c * dx + s * dy
        m2 = -s * dx + c * dy
        # the reference is straight along the initial direction: Lambda(theta_0)^T r_0' = (1, 0), kappa_0 = 0
        return theta, m1, m2, p.EA * (m1 - 1.0), p.kGA * m2, p.EI * dtheta

    def internal_force(self, q):
        """Internal force vector (..., 3 x nodes) of the nodal coordinates ``q`` (..., 3 x nodes)."""
        theta, m1, m2, n, qs, m = self.strains(q)
        c, s = np.cos(theta), np.sin(theta)
        w = self.w_r * self.jac  # Gauss weights times dS/dxi (G,)
        fx = (w * (n * c - qs * s)) @ self.dn_r  # (..., E, k+1)
        fy = (w * (n * s + qs * c)) @ self.dn_r
        ft = (w * (n * m2 - qs * m1)) @ self.n_r + (w * m) @ self.dn_r
        element = np.stack([fx, fy, ft], axis=-1)  # (..., E, k+1, 3)
        return element.reshape(element.shape[:-3] + (-1,)) @ self.scatter

    def stiffness(self, q, columns):
        """Columns ``columns`` of the tangent stiffness d f_int / d q at ``q``, by complex-step
        differentiation of :meth:`internal_force` (exact to round-off: f_int is analytic in q)."""
        h = 1e-30
        probe = np.repeat(q[None, :].astype(complex), len(columns), axis=0)
        probe[np.arange(len(columns)), columns] += 1j * h
        return self.internal_force(probe).imag.T / h

    def resultants_at(self, q, s):
        """(N, Q, M) at arclength ``s`` [m]: Barlow-point values interpolated by the Lagrange polynomial
        through the reduced rule's points (constant for one point, linear for two)."""
        e = min(int(s // self.le), self.p.elements - 1)
        xi = 2.0 * (s - e * self.le) / self.le - 1.0
        values = np.array(self.strains(q)[3:])[:, e, :]  # (3, G)
        pts = self.xi_r
        if len(pts) == 1:
            return tuple(values[:, 0])
        weights = np.array([(xi - pts[1]) / (pts[0] - pts[1]), (xi - pts[0]) / (pts[1] - pts[0])])
        return tuple(values @ weights)


@dataclass
class Reference:
    """Samples of the reference run at ``time`` [s]: the rod's nodal coordinates ``q`` (samples x 3 nodes:
    node after node, (x, y, theta)), their rates ``v`` and accelerations ``a``; the slider's position,
    velocity and acceleration; the section resultants at ``gauge`` [m] (``N``, ``Q``, ``M``); the
    integrator's statistics."""

    time: np.ndarray
    q: np.ndarray
    v: np.ndarray
    a: np.ndarray
    slider_x: np.ndarray
    slider_v: np.ndarray
    slider_a: np.ndarray
    gauge: float
    N: np.ndarray
    Q: np.ndarray
    M: np.ndarray
    nfev: int
    njev: int

    def node(self, k: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return self.q[:, 3 * k], self.q[:, 3 * k + 1], self.q[:, 3 * k + 2]

    def midspan_deflection(self) -> np.ndarray:
        n = self.q.shape[1] // 3
        assert n % 2 == 1, "the mid-span is a node for an even number of quadratic or linear elements"
        return midspan_deflection(*self.node(0)[:2], *self.node(n // 2)[:2], *self.node(n - 1)[:2])


def simulate(p: Parameters = Parameters(), t_end: float = 0.09, output_step: float = 5e-4, gauge: float = 0.1,
             rtol: float = 1e-9, atol_position: float = 1e-12, atol_velocity: float = 1e-6,
             method: str = "Radau") -> Reference:
    """Integrates the eliminated equations from rest (straight rod along +x, crank along +x) to ``t_end``
    [s] and samples them every ``output_step`` [s] from the solver's dense output, with the resultants at
    arclength ``gauge`` [m].

    Tolerances: ``rtol`` on every state; absolute ``atol_position`` [m, rad] on the coordinates and
    ``atol_velocity`` [m/s, rad/s] on their rates. The rates get the looser one: with 1e-12 on both, rtol
    1e-9 took 3.4 million right-hand sides (7 minutes) instead of 19 000, presumably resolving the rod's
    stiffest modes (axial and shear of one element, 2e5 to 3e6 rad/s), whose velocities exceed 1e-12 m/s
    at negligible amplitudes. With the defaults the positions agree with a run at rtol 1e-10 (absolute
    1e-13 and 1e-7) to 1.4e-11 m.

    The Newton matrix of Radau gets the exact tangent stiffness, by complex-step differentiation of the
    internal forces (:meth:`_Rod.stiffness`)."""
    rod = _Rod(p)
    nn = p.nodes
    total = 3 * nn
    mass = rod.mass.copy()
    last = nn - 1
    mass[3 * last, 3 * last] += p.slider_mass  # the slider moves with x_n
    prescribed = np.array([0, 1, 3 * last + 1])  # x_0, y_0 (crank pin), y_n (slider line)
    free = np.setdiff1d(np.arange(total), prescribed)
    m_ff = mass[np.ix_(free, free)]
    m_fp = mass[np.ix_(free, prescribed)]
    a = p.crank_length

    w, ramp = p.crank_speed, p.ramp_time
    k = 2.0 * math.pi / ramp

    def pin(t):
        # speed_ramp() on a scalar
        if t < ramp:
            phi = (w / ramp) * (t * t / 2.0 + (math.cos(k * t) - 1.0) / k ** 2)
            dphi = (w / ramp) * (t - math.sin(k * t) / k)
            ddphi = (w / ramp) * (1.0 - math.cos(k * t))
        else:
            phi, dphi, ddphi = w * t - w * ramp / 2.0, w, 0.0
        c, s = math.cos(phi), math.sin(phi)
        pos = np.array([a * c, a * s, 0.0])
        vel = np.array([-a * s * dphi, a * c * dphi, 0.0])
        acc = np.array([-a * s * ddphi - a * c * dphi ** 2, a * c * ddphi - a * s * dphi ** 2, 0.0])
        return pos, vel, acc

    nf = len(free)

    def full(t, y):
        pos, vel, acc = pin(t)
        q = np.empty(total)
        v = np.empty(total)
        q[free], q[prescribed] = y[:nf], pos
        v[free], v[prescribed] = y[nf:], vel
        return q, v, acc

    inverse_mass = cho_solve(cho_factor(m_ff), np.eye(nf))  # M_ff is constant: inverted once

    def accelerations(t, y):
        q, _, acc_p = full(t, y)
        return inverse_mass @ (-rod.internal_force(q)[free] - m_fp @ acc_p)

    def f(t, y):
        return np.concatenate([y[nf:], accelerations(t, y)])

    def jacobian(t, y):
        # d/dy of (v_f, a_f): the accelerations depend on the positions through the internal forces only
        q = full(t, y)[0]
        k_ff = rod.stiffness(q, free)[free]
        jac = np.zeros((2 * nf, 2 * nf))
        jac[:nf, nf:] = np.eye(nf)
        jac[nf:, :nf] = -inverse_mass @ k_ff
        return jac

    # the rest state: straight and unstressed from the crank pin at (a, 0) along +x
    q0 = np.zeros(total)
    q0[0::3] = a + np.linspace(0.0, p.rod_length, nn)
    y0 = np.concatenate([q0[free], np.zeros(nf)])
    times = np.arange(0.0, t_end + 0.5 * output_step, output_step)
    atol = np.concatenate([np.full(nf, atol_position), np.full(nf, atol_velocity)])
    sol = solve_ivp(f, (0.0, times[-1]), y0, method=method, rtol=rtol, atol=atol, t_eval=times,
                    jac=jacobian, first_step=1e-6)
    assert sol.success, sol.message
    qs, vs, acs, ns, qq, ms = [], [], [], [], [], []
    for t, y in zip(sol.t, sol.y.T):
        q, v, acc_p = full(t, y)
        acc = np.empty(total)
        acc[free], acc[prescribed] = accelerations(t, y), acc_p
        qs.append(q), vs.append(v), acs.append(acc)
        n_, q_, m_ = rod.resultants_at(q, gauge)
        ns.append(n_), qq.append(q_), ms.append(m_)
    qs, vs, acs = np.array(qs), np.array(vs), np.array(acs)
    return Reference(time=sol.t, q=qs, v=vs, a=acs, slider_x=qs[:, 3 * last], slider_v=vs[:, 3 * last],
                     slider_a=acs[:, 3 * last], gauge=gauge, N=np.array(ns), Q=np.array(qq), M=np.array(ms),
                     nfev=sol.nfev, njev=sol.njev)
