"""Independent minimal-coordinate reference for the LUBRICATED Flores slider-crank.

The mechanism, its parameters, the coordinates ``q = (phi, x_s)``, the initial
state and the dry contact law are those of the dry reference
(``reference_slider_crank.py``, imported, not copied).  This module adds a
lubricant film in the rod-end / slider clearance joint, written from the
formulas of the literature and of docs/theory/reference-lubricated.md, not from
the engine's Rust code:

* film: Hamrock's infinitely LONG journal bearing with squeeze and wedge
  action and a moving Guembel (pi-film) region: the positive-pressure region is
  the half of the film where the Reynolds source term is negative, which turns
  with the ratio of squeeze to wedge action; p = 0 at both of its ends.  The
  force integrals are closed forms (Sommerfeld substitution).
* conventions (film.rs): e = P_j - P_b, h = c - e . u(theta), surface speeds
  R omega_j, R omega_b along +theta, force on the journal F = -int p u dA.
  The rod end is the journal (omega_j = phi_dot), the slider the bearing
  (omega_b = 0).  R is the JOURNAL radius (R_b - c), as in the engine.
* the film force acts through the journal centre on the rod; the film's shear
  torque T_j acts on the rod (the slider cannot rotate: its share goes to the
  guide).
* transition (paper 001, "wang_improved"): F = w_h(eps) F_film + F_contact,
  w_h = 1 below eps0 = 1 - h_safe/c, 0 from contact (eps >= 1), smoothstep in
  between; h_safe = 0.00015 D.  The dry contact force is the dry reference's
  (Lankarani-Nikravesh + Ambrosio friction, latched onset velocity, event
  driven pieces); it is zero for |e| <= c, so its smoothstep weight is moot.

Right-hand side on Python floats with ``math``: this is the SciPy baseline of
benches/bench_flores_lubricated.py, so it is meant to be competent.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import List, Optional

import numpy as np

import reference_slider_crank as dry
from reference_slider_crank import FloresParameters

__all__ = [
    "FilmParameters",
    "LubricatedResult",
    "long_bearing_film",
    "gumbel_long_steady",
    "film_weight",
    "simulate_lubricated",
]

SAFE_FILM_PER_DIAMETER = 0.00015  # paper 001's design rule h_safe = 0.00015 D


@dataclass(frozen=True)
class FilmParameters:
    """Lubricant and transition, SI units."""

    viscosity: float = 0.400  # mu [Pa s] (400 cP)
    # h_safe [m]; None -> 0.00015 * D with D the bearing (bore) diameter 2 R_b,
    # as paper 001's rule reads (20 mm -> 3 um for the Flores joint).
    safe_film_thickness: Optional[float] = None
    film_torque: bool = True  # apply the shear torque T_j on the rod

    def h_safe(self, p: FloresParameters) -> float:
        if self.safe_film_thickness is not None:
            return float(self.safe_film_thickness)
        return SAFE_FILM_PER_DIAMETER * 2.0 * p.bearing_radius

    def lubricated_limit(self, p: FloresParameters) -> float:
        """eps0 = 1 - h_safe / c."""
        return 1.0 - self.h_safe(p) / p.clearance


# --------------------------------------------------------------------------
# film force (pure functions)
# --------------------------------------------------------------------------

_PI = math.pi
_TWO_PI = 2.0 * math.pi
_HALF_PI = 0.5 * math.pi


def long_bearing_film(ex, ey, exd, eyd, wj, wb, R, L, c, mu):
    """Hamrock long-bearing film with the moving Guembel half.  Returns (Fx, Fy, T_j).

    ex, ey: eccentricity P_j - P_b [m]; exd, eyd: its rate [m/s]; wj, wb: absolute
    spins of journal and bearing [rad/s]; R: film radius, L: length, c: radial
    clearance [m]; mu [Pa s].  (Fx, Fy): force on the journal [N]; T_j: shear torque
    on the journal about its centre, counter-clockwise [N m].

    Line-of-centres frame n = e/|e|, t = perp(n), phi = theta - gamma.  h = c D,
    D = 1 - eps cos(phi).  Long-bearing Reynolds, integrated once:
        dp/dphi = (6 mu R^2 / c^2) N(phi) / D^3,
        N = -W cos(phi) - 2 epsd sin(phi) + K,
        W = eps (wj + wb) - 2 (edot . t) / c   (= eps (wj + wb - 2 gamma_dot)),
        epsd = (edot . n) / c.
    Film (p > 0) on the half where the source W sin(phi) - 2 epsd cos(phi) < 0:
    [phi0 - pi/2, phi0 + pi/2], phi0 = atan2(-W, 2 epsd); p = 0 at both ends
    fixes K (int N / D^3 = 0).  By parts, F_n = k int N sin/D^3,
    F_t = -k int N cos/D^3, k = 6 mu R^3 L / c^2.
    Shear torque (Couette over the whole film + pressure part -e x F / 2):
        T_j = 2 pi mu R^3 L (wb - wj) / (c sqrt(1 - eps^2)) - eps c F_t / 2.
    """
    r = math.sqrt(ex * ex + ey * ey)
    if r > 1e-300:
        nx = ex / r
        ny = ey / r
    else:  # centred: the frame follows the approach velocity (or x at rest)
        v = math.sqrt(exd * exd + eyd * eyd)
        if v > 0.0:
            nx, ny = exd / v, eyd / v
        else:
            nx, ny = 1.0, 0.0
    eps = r / c
    if eps > 1.0 - 1e-9:
        eps = 1.0 - 1e-9
    epsd = (exd * nx + eyd * ny) / c
    W = eps * (wj + wb) - 2.0 * (eyd * nx - exd * ny) / c
    b = 1.0 - eps * eps
    sb = math.sqrt(b)
    kR3L = mu * R * R * R * L
    couette = _TWO_PI * kR3L * (wb - wj) / (c * sb)
    if W == 0.0 and epsd == 0.0:
        return 0.0, 0.0, couette
    phi0 = math.atan2(-W, 2.0 * epsd)
    p1 = phi0 - _HALF_PI
    p2 = phi0 + _HALF_PI
    # Sommerfeld angle psi(phi): cos psi = (cos phi - eps)/D, sin psi = sb sin phi / D,
    # continuous in phi and within pi of it.
    d = math.atan2(sb * math.sin(p1), math.cos(p1) - eps) - p1
    psi1 = p1 + (d + _PI) % _TWO_PI - _PI
    d = math.atan2(sb * math.sin(p2), math.cos(p2) - eps) - p2
    psi2 = p2 + (d + _PI) % _TWO_PI - _PI
    s1 = math.sin(psi1)
    c1 = math.cos(psi1)
    s2 = math.sin(psi2)
    c2 = math.cos(psi2)
    dpsi = psi2 - psi1
    C1 = s2 - s1  # int cos psi
    S1 = c1 - c2  # int sin psi
    CC = 0.5 * dpsi + 0.5 * (s2 * c2 - s1 * c1)  # int cos^2 psi
    SS = dpsi - CC  # int sin^2 psi
    SC = 0.5 * (s2 * s2 - s1 * s1)  # int sin psi cos psi
    # int cos^a phi sin^b phi / D^3 dphi = b^((b+1)/2 - 3) int (cos psi + eps)^a sin^b psi (1 + eps cos psi)^(2-a-b) dpsi
    b52 = 1.0 / (b * b * sb)
    b2 = 1.0 / (b * b)
    J0 = b52 * (dpsi + 2.0 * eps * C1 + eps * eps * CC)
    Jc = b52 * (eps * dpsi + (1.0 + eps * eps) * C1 + eps * CC)
    Js = b2 * (S1 + eps * SC)
    Jcc = b52 * (CC + 2.0 * eps * C1 + eps * eps * dpsi)
    Jss = SS / (b * sb)
    Jsc = b2 * (SC + eps * S1)
    sq = 2.0 * epsd
    K = (W * Jc + sq * Js) / J0
    k = 6.0 * kR3L / (c * c)
    fn = k * (-W * Jsc - sq * Jss + K * Js)
    ft = -k * (-W * Jcc - sq * Jsc + K * Jc)
    return fn * nx - ft * ny, fn * ny + ft * nx, couette - 0.5 * eps * c * ft


def gumbel_long_steady(eps, omega, R, L, c, mu):
    """Closed-form Guembel (half-Sommerfeld) long bearing, steady, journal spin omega,
    fixed bearing: returns (F_r, F_t) with F_r = 12 mu omega R^3 L eps^2/(c^2 (2+eps^2)(1-eps^2))
    (magnitude, towards the centre) and F_t = 6 pi mu omega R^3 L eps/(c^2 (2+eps^2) sqrt(1-eps^2))."""
    k = mu * omega * R**3 * L / c**2
    fr = 12.0 * k * eps**2 / ((2.0 + eps**2) * (1.0 - eps**2))
    ft = 6.0 * math.pi * k * eps / ((2.0 + eps**2) * math.sqrt(1.0 - eps**2))
    return fr, ft


def film_weight(eps, eps0):
    """Share w_h of the film force: 1 for eps <= eps0, 0 for eps >= 1, 1 - x^2 (3 - 2x) between,
    x = (eps - eps0)/(1 - eps0)."""
    if eps <= eps0:
        return 1.0
    if eps >= 1.0:
        return 0.0
    x = (eps - eps0) / (1.0 - eps0)
    return 1.0 - x * x * (3.0 - 2.0 * x)


# --------------------------------------------------------------------------
# model
# --------------------------------------------------------------------------


@dataclass
class LubricatedResult:
    """Time histories on the output grid (SI)."""

    t: np.ndarray
    phi: np.ndarray
    x_s: np.ndarray
    phidot: np.ndarray
    x_sdot: np.ndarray
    slider_ax: np.ndarray  # slider acceleration [m/s^2]
    fhx: np.ndarray  # film force on the journal after the transition weight [N]
    fhy: np.ndarray
    fh: np.ndarray  # its magnitude [N]
    film_torque: np.ndarray  # weighted shear torque on the journal [N m]
    fn: np.ndarray  # dry normal contact force [N]
    film_min: np.ndarray  # c - |e|, 0 in contact [m]
    eps: np.ndarray  # |e| / c
    weight: np.ndarray  # w_h
    mode: np.ndarray  # 0 hydrodynamic, 1 transition, 2 contact
    torque: np.ndarray  # crank driving torque [N m]
    nfev: int
    n_steps: int
    impacts: List[float]
    separations: List[float]
    wall_time: float
    t_end: float = 0.0
    params: Optional[FloresParameters] = None
    film: Optional[FilmParameters] = None
    onset_velocities: List[float] = field(default_factory=list)

    @property
    def contact(self) -> np.ndarray:
        return self.mode == 2


def _make_model(p: FloresParameters, f: FilmParameters, latched: Optional[float]):
    """rhs(t, y), event(t, y), detail(t, phi, xs, phid, xsd) for one piece (see the dry reference)."""
    a = p.crank_length
    L = p.rod_length
    hL = 0.5 * L
    w = p.crank_speed
    aw = a * w
    aww = a * w * w
    m2 = p.rod_mass
    m3 = p.slider_mass
    J = p.rod_inertia + m2 * hL * hL
    g = p.gravity
    c = p.clearance
    c2 = c * c
    Rj = p.journal_radius
    K = p.stiffness
    nexp = p.contact_exponent
    hertz = nexp == 1.5
    damp = 0.75 * (1.0 - p.restitution * p.restitution)
    mu_f = p.friction_coefficient
    v0 = p.v0
    v1 = p.v1
    dv = v1 - v0
    floor = p.onset_velocity_floor
    have_latch = latched is not None
    dm_latched = float(latched) if have_latch else 0.0
    mu = f.viscosity
    Lb = p.bearing_length
    eps0 = f.lubricated_limit(p)
    span = 1.0 - eps0
    use_torque = 1.0 if f.film_torque else 0.0
    film = long_bearing_film
    cos = math.cos
    sin = math.sin
    sqrt = math.sqrt
    c_inert = m2 * hL * aww
    c_grav = m2 * g * hL

    def forces(t, phi, xs, phid, xsd):
        """(Q_phi of the joint forces, F_x and F_y on the journal (film or contact),
        weighted film Fx, Fy, T_j, contact F_n, eps, w_h)."""
        th = w * t
        ct = cos(th)
        st = sin(th)
        cp = cos(phi)
        sp = sin(phi)
        ex = a * ct + L * cp - xs
        ey = a * st + L * sp
        r2 = ex * ex + ey * ey
        if r2 < c2:
            r = sqrt(r2)
            eps = r / c
            if eps <= eps0:
                wh = 1.0
            else:
                x = (eps - eps0) / span
                wh = 1.0 - x * x * (3.0 - 2.0 * x)
            # journal centre velocity A_dot + phid k x L u ; bearing centre (xsd, 0)
            exd = -aw * st - phid * L * sp - xsd
            eyd = aw * ct + phid * L * cp
            fx, fy, tj = film(ex, ey, exd, eyd, phid, 0.0, Rj, Lb, c, mu)
            fx *= wh
            fy *= wh
            tj *= wh * use_torque
            # the film force acts at P_j: moment about A is (L u) x F
            return L * cp * fy - L * sp * fx + tj, fx, fy, fx, fy, tj, 0.0, eps, wh
        # contact (w_h = 0): the dry reference's law
        r = sqrt(r2)
        delta = r - c
        nx = ex / r
        ny = ey / r
        rx = L * cp + Rj * nx
        ry = L * sp + Rj * ny
        vx = -aw * st - phid * ry - xsd
        vy = aw * ct + phid * rx
        dd = vx * nx + vy * ny
        dm = dm_latched if have_latch else (dd if dd > floor else floor)
        pw = delta * sqrt(delta) if hertz else delta**nexp
        fn = K * pw * (1.0 + damp * dd / dm)
        if fn <= 0.0:
            return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, r / c, 0.0
        vt = vy * nx - vx * ny
        avt = vt if vt >= 0.0 else -vt
        if avt < v0 or mu_f == 0.0:
            ft = 0.0
        else:
            cd = 1.0 if avt >= v1 else (avt - v0) / dv
            ft = -cd * mu_f * fn if vt > 0.0 else cd * mu_f * fn
        fx = -fn * nx - ft * ny
        fy = -fn * ny + ft * nx
        return rx * fy - ry * fx, fx, fy, 0.0, 0.0, 0.0, fn, r / c, 0.0

    def rhs(t, y):
        phi, xs, phid, xsd = y.tolist()
        res = forces(t, phi, xs, phid, xsd)
        return [phid, xsd, (c_inert * sin(w * t - phi) - c_grav * cos(phi) + res[0]) / J, -res[1] / m3]

    def event(t, y):
        phi, xs = y[0], y[1]
        th = w * t
        ex = a * cos(th) + L * cos(phi) - xs
        ey = a * sin(th) + L * sin(phi)
        return sqrt(ex * ex + ey * ey) - c

    def detail(t, phi, xs, phid, xsd):
        """phidd, xsdd, film Fx, Fy, T_j (weighted), F_n, film_min, eps, w_h, mode, crank torque."""
        qc, fx, fy, hx, hy, tj, fn, eps, wh = forces(t, phi, xs, phid, xsd)
        th = w * t
        ct = cos(th)
        st = sin(th)
        cp = cos(phi)
        sp = sin(phi)
        phidd = (c_inert * sin(th - phi) - c_grav * cp + qc) / J
        xsdd = -fx / m3
        mode = 0.0 if eps <= eps0 else (1.0 if eps < 1.0 else 2.0)
        film_min = c * (1.0 - eps) if eps < 1.0 else 0.0
        # crank torque: rod Newton m2 G_dd = F_A + F_j + m2 g (F_j the journal force)
        gddx = -aww * ct - hL * phidd * sp - hL * phid * phid * cp
        gddy = -aww * st + hL * phidd * cp - hL * phid * phid * sp
        fax = m2 * gddx - fx
        fay = m2 * gddy + m2 * g - fy
        torque = a * ct * fay - a * st * fax + p.crank_mass * g * 0.5 * a * ct
        return phidd, xsdd, hx, hy, tj, fn, film_min, eps, wh, mode, torque

    return rhs, event, detail


def simulate_lubricated(
    params: FloresParameters = FloresParameters(),
    film: FilmParameters = FilmParameters(),
    t_end: Optional[float] = None,
    rtol: float = 1e-6,
    atol: float = 1e-9,
    max_step: float = np.inf,
    method: str = "RK45",
    dense=False,
    max_pieces: int = 100000,
) -> LubricatedResult:
    """Integrate the lubricated slider-crank from the ideal initial state (journal centred).

    t_end: default two crank revolutions.  dense: False -> every accepted step of every
    piece; True -> 3600 intervals per revolution; an array -> those times.  Contact
    onsets / separations (|e| = c) are terminal events, as in the dry reference: the
    onset velocity is latched for the Lankarani-Nikravesh damping.
    """
    p = params
    t_end = float(2.0 * p.crank_period if t_end is None else t_end)
    wall0 = time.perf_counter()
    run = dry.integrate_in_pieces(p, lambda latched: _make_model(p, film, latched), t_end, rtol, atol, max_step,
                                  method, dense, max_pieces, n_details=11)
    wall = time.perf_counter() - wall0
    t_all, y_all, out = run.t, run.y, run.details
    nfev, n_steps, impacts = run.nfev, run.n_steps, run.impacts
    separations, onset_velocities = run.separations, run.onset_velocities
    return LubricatedResult(
        t=t_all, phi=y_all[0].copy(), x_s=y_all[1].copy(), phidot=y_all[2].copy(), x_sdot=y_all[3].copy(),
        slider_ax=out[1].copy(), fhx=out[2].copy(), fhy=out[3].copy(), fh=np.hypot(out[2], out[3]),
        film_torque=out[4].copy(), fn=out[5].copy(), film_min=out[6].copy(), eps=out[7].copy(),
        weight=out[8].copy(), mode=out[9].astype(int), torque=out[10].copy(),
        nfev=nfev, n_steps=n_steps, impacts=impacts, separations=separations, wall_time=wall,
        t_end=t_end, params=p, film=film, onset_velocities=onset_velocities,
    )
