"""Independent minimal-coordinate reference for the dry-clearance slider-crank.

This module is deliberately written apart from the Rust engine: the engine uses
absolute coordinates with Lagrange multipliers, this reference uses the two
minimal coordinates of the mechanism with a prescribed crank,

    q = (phi, x_s)   rod angle, slider position,

and integrates them with ``scipy.integrate.solve_ivp``.  It serves two
purposes (see docs/theory/reference-slider-crank.md):

* a cross-check for the engine's physics tests (tests/physics/), and
* the SciPy baseline timed next to the engine in ``benches/``.  The
  right-hand side therefore works on Python floats with ``math`` (no small
  NumPy arrays), so the baseline is a competent one.

Mechanism (Flores-Ambrosio benchmark, dry revolute clearance joint between the
connecting rod end B and the slider):

* crank O-A, length a, pinned at the origin, driven at constant speed
  omega: theta = omega t;
* rod A-B, length L, ideal revolute at A; rod angle phi measured from +x;
* slider on the line y = 0, no rotation; its bore (bearing, radius R_b) is
  centred at P_b = (x_s, 0);
* the rod end is a journal of radius R_j = R_b - c centred at
  P_j = A + L (cos phi, sin phi).

Contact: e = P_j - P_b, delta = |e| - c, n = e/|e|, t = (-n_y, n_x).  The
Lankarani-Nikravesh normal force and the Ambrosio modified Coulomb friction act
on the journal as F = -F_n n + F_t t at Q_j = P_j + R_j n; the slider gets -F
at Q_b = P_b + R_b n (only its x component moves the slider).

The impact velocity ``delta_dot_minus`` is discrete state: it is latched at
contact onset (located by a terminal event on delta, direction +1) and cleared
at separation (terminal event, direction -1); each phase is integrated as a
separate ``solve_ivp`` call that restarts at the event.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import List, Optional

import numpy as np
from scipy.integrate import solve_ivp

__all__ = [
    "FloresParameters",
    "ReferenceResult",
    "simulate_reference",
    "first_impact",
    "contact_fraction",
    "ideal_slider_position",
    "ln_normal_force",
    "ambrosio_friction_factor",
]

RPM = 2.0 * math.pi / 60.0


@dataclass(frozen=True)
class FloresParameters:
    """Parameters of the benchmark, SI units throughout."""

    crank_length: float = 0.05  # a [m]
    rod_length: float = 0.12  # L [m]
    crank_mass: float = 0.30  # [kg]
    rod_mass: float = 0.21  # [kg]
    slider_mass: float = 0.14  # [kg]
    crank_inertia: float = 1.0e-4  # centroidal [kg m^2]
    rod_inertia: float = 2.5e-4  # centroidal [kg m^2]
    slider_inertia: float = 1.0e-4  # centroidal [kg m^2] (slider cannot rotate: unused)
    crank_speed: float = 5000.0 * RPM  # omega [rad/s], constant
    gravity: float = 9.81  # [m/s^2], acts in -y
    bearing_radius: float = 0.010  # R_b [m]
    clearance: float = 0.5e-3  # radial clearance c [m]; journal radius R_j = R_b - c
    bearing_length: float = 0.040  # [m] (not used by the Hertz-type stiffness)
    youngs_modulus: float = 207.0e9  # [Pa], journal and bearing
    poisson_ratio: float = 0.3  # journal and bearing
    restitution: float = 0.9  # e in the Lankarani-Nikravesh law (1.0 -> pure Hertz)
    friction_coefficient: float = 0.01  # mu
    v0: float = 1.0e-4  # [m/s] dead band of the modified Coulomb law
    v1: float = 1.0e-3  # [m/s] full friction above this sliding speed
    onset_velocity_floor: float = 1.0e-4  # [m/s] floor of the latched impact velocity
    contact_stiffness: Optional[float] = None  # [N/m^1.5]; None -> Hertz-type K below
    contact_exponent: float = 1.5

    @property
    def journal_radius(self) -> float:
        return self.bearing_radius - self.clearance

    @property
    def effective_modulus(self) -> float:
        """E* with 1/E* = (1-nu^2)/E + (1-nu^2)/E (same material for both)."""
        return 1.0 / (2.0 * (1.0 - self.poisson_ratio**2) / self.youngs_modulus)

    @property
    def effective_radius(self) -> float:
        """R* = R_b R_j / (R_b - R_j) (internal contact, R_b - R_j = c)."""
        rb, rj = self.bearing_radius, self.journal_radius
        return rb * rj / (rb - rj)

    @property
    def stiffness(self) -> float:
        """K = (4/3) E* sqrt(R*), unless ``contact_stiffness`` overrides it."""
        if self.contact_stiffness is not None:
            return float(self.contact_stiffness)
        return 4.0 / 3.0 * self.effective_modulus * math.sqrt(self.effective_radius)

    @property
    def crank_period(self) -> float:
        return 2.0 * math.pi / self.crank_speed


@dataclass
class ReferenceResult:
    """Trajectory of the reference model.

    ``t`` holds every accepted step of the restarted pieces (event times once,
    not twice), or the requested dense grid.  Per-point channels are evaluated
    with the latched impact velocity of the piece the point belongs to.
    """

    t: np.ndarray
    phi: np.ndarray
    x_s: np.ndarray
    phidot: np.ndarray
    x_sdot: np.ndarray
    slider_ax: np.ndarray  # slider acceleration [m/s^2]
    fn: np.ndarray  # normal contact force magnitude [N]
    ft: np.ndarray  # tangential force on the journal along t [N]
    penetration: np.ndarray  # delta = |e| - c [m] (negative: free flight)
    ex: np.ndarray  # eccentricity P_j - P_b [m]
    ey: np.ndarray
    contact: np.ndarray  # bool, penetration > 0
    nfev: int  # total right-hand side evaluations (all pieces)
    n_steps: int  # accepted steps, sum over pieces of len(sol.t) - 1
    impacts: List[float]  # contact onset times (events, direction +1)
    wall_time: float  # [s] integration + post-processing
    separations: List[float] = field(default_factory=list)  # separation event times
    onset_velocities: List[float] = field(default_factory=list)  # latched delta_dot_minus
    torque: Optional[np.ndarray] = None  # crank driving torque [N m]
    theta: Optional[np.ndarray] = None  # crank angle [rad]
    t_end: float = 0.0
    params: Optional[FloresParameters] = None


# --------------------------------------------------------------------------
# force laws (pure functions, used by the right-hand side and by the tests)
# --------------------------------------------------------------------------


def ln_normal_force(delta, delta_dot, delta_dot_minus, stiffness, restitution, exponent=1.5):
    """Lankarani-Nikravesh: F_n = max(0, K delta^n (1 + 3(1-e^2)/4 delta_dot/delta_dot_minus)).

    Returns 0 for delta <= 0.  ``delta_dot_minus`` must be > 0.
    """
    if delta <= 0.0:
        return 0.0
    f = stiffness * delta**exponent * (
        1.0 + 0.75 * (1.0 - restitution * restitution) * delta_dot / delta_dot_minus
    )
    return f if f > 0.0 else 0.0


def ambrosio_friction_factor(vt_abs, v0, v1):
    """Dynamic correction c_d of the modified Coulomb law (0, linear, 1)."""
    if vt_abs < v0:
        return 0.0
    if vt_abs < v1:
        return (vt_abs - v0) / (v1 - v0)
    return 1.0


# --------------------------------------------------------------------------
# right-hand side
# --------------------------------------------------------------------------


def _make_model(p: FloresParameters, latched: Optional[float]):
    """Build ``rhs(t, y)`` and ``detail(t, y)`` closures for one piece.

    ``latched`` is the impact velocity latched for this piece (None in a free
    flight piece: a stage that nevertheless sees delta > 0 uses
    max(delta_dot, floor)).
    """
    a = p.crank_length
    L = p.rod_length
    hL = 0.5 * L
    w = p.crank_speed
    aw = a * w
    aww = a * w * w
    m2 = p.rod_mass
    m3 = p.slider_mass
    J = p.rod_inertia + m2 * hL * hL  # rod inertia about the crank pin A
    g = p.gravity
    c = p.clearance
    Rj = p.journal_radius
    K = p.stiffness
    nexp = p.contact_exponent
    damp = 0.75 * (1.0 - p.restitution * p.restitution)
    mu = p.friction_coefficient
    v0 = p.v0
    v1 = p.v1
    dv = v1 - v0
    floor = p.onset_velocity_floor
    have_latch = latched is not None
    dm_latched = float(latched) if have_latch else 0.0
    cos = math.cos
    sin = math.sin
    sqrt = math.sqrt
    c_inert = m2 * hL * aww  # coefficient of sin(theta - phi) (pin acceleration)
    c_grav = m2 * g * hL  # coefficient of cos(phi) (rod weight)
    hertz = nexp == 1.5

    def contact(t, phi, xs, phid, xsd):
        """Returns (Q_phi contact, F_x, F_y on journal, fn, ft, delta, ex, ey)."""
        th = w * t
        ct = cos(th)
        st = sin(th)
        cp = cos(phi)
        sp = sin(phi)
        ex = a * ct + L * cp - xs
        ey = a * st + L * sp
        r = sqrt(ex * ex + ey * ey)
        delta = r - c
        if delta <= 0.0:
            return 0.0, 0.0, 0.0, 0.0, 0.0, delta, ex, ey
        nx = ex / r
        ny = ey / r
        # Q_j - A = L u + R_j n ; velocity of Q_j = A_dot + phid k x (Q_j - A)
        rx = L * cp + Rj * nx
        ry = L * sp + Rj * ny
        vx = -aw * st - phid * ry - xsd
        vy = aw * ct + phid * rx
        dd = vx * nx + vy * ny
        vt = vy * nx - vx * ny
        if have_latch:
            dm = dm_latched
        else:
            dm = dd if dd > floor else floor
        pw = delta * sqrt(delta) if hertz else delta**nexp
        fn = K * pw * (1.0 + damp * dd / dm)
        if fn < 0.0:
            fn = 0.0
        avt = vt if vt >= 0.0 else -vt
        if avt < v0 or mu == 0.0:
            ft = 0.0
        else:
            cd = 1.0 if avt >= v1 else (avt - v0) / dv
            ft = -cd * mu * fn if vt > 0.0 else cd * mu * fn
        fx = -fn * nx - ft * ny
        fy = -fn * ny + ft * nx
        return rx * fy - ry * fx, fx, fy, fn, ft, delta, ex, ey

    def rhs(t, y):
        phi, xs, phid, xsd = y.tolist()
        th = w * t
        ct = cos(th)
        st = sin(th)
        cp = cos(phi)
        sp = sin(phi)
        q = c_inert * (st * cp - ct * sp) - c_grav * cp
        ex = a * ct + L * cp - xs
        ey = a * st + L * sp
        r2 = ex * ex + ey * ey
        if r2 <= c * c:
            return [phid, xsd, q / J, 0.0]
        r = sqrt(r2)
        delta = r - c
        nx = ex / r
        ny = ey / r
        rx = L * cp + Rj * nx
        ry = L * sp + Rj * ny
        vx = -aw * st - phid * ry - xsd
        vy = aw * ct + phid * rx
        dd = vx * nx + vy * ny
        if have_latch:
            dm = dm_latched
        else:
            dm = dd if dd > floor else floor
        pw = delta * sqrt(delta) if hertz else delta**nexp
        fn = K * pw * (1.0 + damp * dd / dm)
        if fn <= 0.0:
            return [phid, xsd, q / J, 0.0]
        vt = vy * nx - vx * ny
        avt = vt if vt >= 0.0 else -vt
        if avt < v0 or mu == 0.0:
            ft = 0.0
        else:
            cd = 1.0 if avt >= v1 else (avt - v0) / dv
            ft = -cd * mu * fn if vt > 0.0 else cd * mu * fn
        fx = -fn * nx - ft * ny
        fy = -fn * ny + ft * nx
        return [phid, xsd, (q + rx * fy - ry * fx) / J, -fx / m3]

    def event(t, y):
        phi, xs = y[0], y[1]
        th = w * t
        ex = a * cos(th) + L * cos(phi) - xs
        ey = a * sin(th) + L * sin(phi)
        return sqrt(ex * ex + ey * ey) - c

    def detail(t, phi, xs, phid, xsd):
        """All per-point outputs: phidd, xsdd, fn, ft, delta, ex, ey, torque."""
        qc, fx, fy, fn, ft, delta, ex, ey = contact(t, phi, xs, phid, xsd)
        th = w * t
        ct = cos(th)
        st = sin(th)
        cp = cos(phi)
        sp = sin(phi)
        q = c_inert * (st * cp - ct * sp) - c_grav * cp + qc
        phidd = q / J
        xsdd = -fx / m3
        # rod Newton: m2 G_dd = F_A + F_contact + m2 g  ->  pin force F_A on the rod
        gddx = -aww * ct - hL * phidd * sp - hL * phid * phid * cp
        gddy = -aww * st + hL * phidd * cp - hL * phid * phid * sp
        fax = m2 * gddx - fx
        fay = m2 * gddy + m2 * g - fy
        # crank: torque + A x (-F_A) - m1 g (a/2) cos(theta) = I_O theta_dd = 0
        torque = a * ct * fay - a * st * fax + p.crank_mass * g * 0.5 * a * ct
        return phidd, xsdd, fn, ft, delta, ex, ey, torque

    return rhs, event, detail


def _onset_velocity(p: FloresParameters, t: float, y) -> float:
    """Normal approach velocity delta_dot = (v_Qj - v_Qb) . n at state y."""
    a, L, w, Rj = p.crank_length, p.rod_length, p.crank_speed, p.journal_radius
    phi, xs, phid, xsd = (float(v) for v in y)
    th = w * t
    ex = a * math.cos(th) + L * math.cos(phi) - xs
    ey = a * math.sin(th) + L * math.sin(phi)
    r = math.hypot(ex, ey)
    nx, ny = ex / r, ey / r
    rx = L * math.cos(phi) + Rj * nx
    ry = L * math.sin(phi) + Rj * ny
    vx = -a * w * math.sin(th) - phid * ry - xsd
    vy = a * w * math.cos(th) + phid * rx
    return vx * nx + vy * ny


def ideal_initial_state(p: FloresParameters) -> np.ndarray:
    """phi = 0, journal centred (x_s = a + L), ideal-mechanism velocities at theta = 0.

    From y_B = a sin(theta) + L sin(phi) = 0: phid = -omega a cos(theta)/(L cos(phi))
    = -omega a / L; from x_B = a cos(theta) + L cos(phi): x_s_dot = -a omega sin(theta)
    - L sin(phi) phid = 0.
    """
    a, L, w = p.crank_length, p.rod_length, p.crank_speed
    return np.array([0.0, a + L, -w * a / L, 0.0])


def ideal_slider_position(p: FloresParameters, t):
    """Closed form of the ideal slider-crank: x = a cos(theta) + sqrt(L^2 - a^2 sin^2(theta))."""
    th = p.crank_speed * np.asarray(t, dtype=float)
    a, L = p.crank_length, p.rod_length
    return a * np.cos(th) + np.sqrt(L * L - (a * np.sin(th)) ** 2)


@dataclass
class Pieces:
    """A run integrated in pieces between contact onsets and separations, sampled."""

    t: np.ndarray  # sample times [s]
    y: np.ndarray  # states (4 x n): phi, x_s, phidot, x_sdot
    details: np.ndarray  # the model's detail outputs (n_details x n)
    nfev: int
    n_steps: int
    impacts: List[float]
    separations: List[float]
    onset_velocities: List[float]


def output_grid(p: FloresParameters, t_end: float, dense) -> Optional[np.ndarray]:
    """None (every accepted step), a grid of 3600 intervals per revolution (True), or the given times."""
    if dense is True:
        n = max(2, int(round(3600 * t_end / p.crank_period)))
        return np.linspace(0.0, t_end, n + 1)
    if dense is not False and dense is not None:
        return np.asarray(dense, dtype=float)
    return None


def integrate_in_pieces(p: FloresParameters, make_model, t_end: float, rtol: float, atol: float, max_step: float,
                        method: str, dense, max_pieces: int, n_details: int) -> Pieces:
    """Integrates from the ideal initial state with ``solve_ivp``, one piece per contact state.

    ``make_model(latched)`` returns ``(rhs, event, detail)`` for the latched onset velocity (None while the
    journal is free). The event (|e| = c) is terminal: at an onset the normal approach velocity is latched
    (floored), at a separation it is cleared, and integration restarts from the event state.
    ``detail(t, phi, x_s, phid, x_sd)`` gives ``n_details`` outputs per sample.
    """
    grid = output_grid(p, t_end, dense)
    t0, y0 = 0.0, ideal_initial_state(p)
    latched: Optional[float] = None
    pieces = []  # (t array, y array, detail, OdeSolution or None)
    impacts: List[float] = []
    separations: List[float] = []
    onset_velocities: List[float] = []
    nfev = n_steps = 0
    while True:
        rhs, event, detail = make_model(latched)
        event.terminal = True
        event.direction = 1.0 if latched is None else -1.0
        sol = solve_ivp(rhs, (t0, t_end), y0, method=method, rtol=rtol, atol=atol, max_step=max_step,
                        events=event, dense_output=grid is not None)
        if sol.status < 0:
            raise RuntimeError(f"solve_ivp failed at t = {sol.t[-1]!r}: {sol.message}")
        nfev += int(sol.nfev)
        n_steps += len(sol.t) - 1
        pieces.append((sol.t, sol.y, detail, sol.sol))
        if sol.status != 1:
            break
        t0 = float(sol.t_events[0][0])
        y0 = np.array(sol.y_events[0][0], dtype=float)
        if latched is None:
            latched = max(_onset_velocity(p, t0, y0), p.onset_velocity_floor)
            impacts.append(t0)
            onset_velocities.append(latched)
        else:
            latched = None
            separations.append(t0)
        if len(pieces) >= max_pieces:
            raise RuntimeError(f"more than {max_pieces} contact pieces before t = {t0}")
        if t0 >= t_end:
            break

    # samples: every accepted step of every piece, or the grid from each piece's dense output
    ts, ys, ks = [], [], []
    if grid is None:
        for k, (t, y, _detail, _sol) in enumerate(pieces):
            s = 0 if k == 0 else 1  # piece k starts at the event that ended piece k-1
            ts.append(t[s:])
            ys.append(y[:, s:])
            ks.append(np.full(len(t) - s, k))
    else:
        starts = np.array([pc[0][0] for pc in pieces])
        idx = np.clip(np.searchsorted(starts, grid, side="right") - 1, 0, len(pieces) - 1)
        for k, pc in enumerate(pieces):
            sel = grid[idx == k]
            if sel.size:
                ts.append(sel)
                ys.append(np.atleast_2d(pc[3](sel)).reshape(4, -1))
                ks.append(np.full(sel.size, k))
    t_all = np.concatenate(ts)
    y_all = np.concatenate(ys, axis=1)
    k_all = np.concatenate(ks)
    details = np.empty((n_details, t_all.size))
    for i, (ti, yi, ki) in enumerate(zip(t_all.tolist(), y_all.T.tolist(), k_all.tolist())):
        details[:, i] = pieces[ki][2](ti, *yi)
    return Pieces(t_all, y_all, details, nfev, n_steps, impacts, separations, onset_velocities)


def simulate_reference(
    params: FloresParameters = FloresParameters(),
    t_end: Optional[float] = None,
    rtol: float = 1e-6,
    atol: float = 1e-9,
    max_step: float = np.inf,
    method: str = "RK45",
    dense=False,
    max_pieces: int = 100000,
) -> ReferenceResult:
    """Integrate the clearance slider-crank from the ideal initial state.

    t_end: default two crank revolutions (4 pi / omega).
    dense: False -> output at every accepted step of every piece; True ->
    uniform grid with 3600 intervals per crank revolution; an array -> those
    times (within [0, t_end]).  Dense values come from each piece's own dense
    output.  ``nfev``/``n_steps`` are summed over pieces in all cases.
    """
    p = params
    t_end = float(2.0 * p.crank_period if t_end is None else t_end)
    wall0 = time.perf_counter()
    run = integrate_in_pieces(p, lambda latched: _make_model(p, latched), t_end, rtol, atol, max_step, method,
                              dense, max_pieces, n_details=8)
    wall = time.perf_counter() - wall0
    out, y_all, t_all = run.details, run.y, run.t
    pen = out[4]
    return ReferenceResult(
        t=t_all,
        phi=y_all[0].copy(),
        x_s=y_all[1].copy(),
        phidot=y_all[2].copy(),
        x_sdot=y_all[3].copy(),
        slider_ax=out[1].copy(),
        fn=out[2].copy(),
        ft=out[3].copy(),
        penetration=pen.copy(),
        ex=out[5].copy(),
        ey=out[6].copy(),
        contact=pen > 0.0,
        nfev=run.nfev,
        n_steps=run.n_steps,
        impacts=run.impacts,
        wall_time=wall,
        separations=run.separations,
        onset_velocities=run.onset_velocities,
        torque=out[7].copy(),
        theta=p.crank_speed * t_all,
        t_end=t_end,
        params=p,
    )


def first_impact(result: ReferenceResult) -> dict:
    """First contact period, from the first onset event to the next separation event
    (or the end of the run).  Returns time (onset), the peak normal contact force
    and the peak |slider acceleration| over the output points in that period,
    plus its end time and duration."""
    if not result.impacts:
        return dict(time=None, peak_contact_force=0.0, peak_slider_acceleration=0.0,
                    end=None, duration=0.0)
    t_on = result.impacts[0]
    later = [s for s in result.separations if s > t_on]
    t_off = later[0] if later else float(result.t[-1])
    m = (result.t >= t_on) & (result.t <= t_off)
    return dict(
        time=t_on,
        peak_contact_force=float(result.fn[m].max()) if m.any() else 0.0,
        peak_slider_acceleration=float(np.abs(result.slider_ax[m]).max()) if m.any() else 0.0,
        end=t_off,
        duration=t_off - t_on,
    )


def contact_fraction(result: ReferenceResult) -> float:
    """Fraction of [t_0, t_N] of the output grid during which penetration > 0.

    Definition: the penetration delta(t) is taken piecewise linear between the
    output points; the fraction is (1/(t_N - t_0)) * measure{t : delta(t) > 0},
    each interval contributing its full length if both ends are positive,
    nothing if both are <= 0, and the part up to/after the linear zero crossing
    otherwise.  On the default step grid the event times are output points with
    delta ~ 0, so this is essentially sum(contact piece durations)/t_end.
    """
    t = np.asarray(result.t, dtype=float)
    d = np.asarray(result.penetration, dtype=float)
    if t.size < 2 or t[-1] <= t[0]:
        return float(d[0] > 0) if d.size else 0.0
    d0, d1 = d[:-1], d[1:]
    dt = np.diff(t)
    p0, p1 = d0 > 0, d1 > 0
    w = np.where(p0 & p1, 1.0, 0.0)
    mixed = p0 != p1
    with np.errstate(divide="ignore", invalid="ignore"):
        frac_pos = np.where(p0, d0, d1) / np.abs(d1 - d0)
    w = np.where(mixed, frac_pos, w)
    return float(np.sum(w * dt) / (t[-1] - t[0]))
