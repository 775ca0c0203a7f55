"""The practical limit for the dry Flores slider-crank: a hand-written compiled program (numba).

The same model as the SciPy reference ``tests/physics/reference_slider_crank.py``
(minimal coordinates q = (phi, x_s): rod angle and slider position, crank
prescribed at constant speed; Lankarani-Nikravesh contact with the Hertz-type
cylinder stiffness, Ambrosio's modified Coulomb friction, onset velocity
latched), written a second time for speed: one ``numba.njit`` function holds
the whole run (right-hand side, Dormand-Prince 5(4) with FSAL and its dense
output, step-size control, contact-onset location, output recording) and
works on floats and preallocated arrays only, with no Python object in the
loop. It takes its numbers from ``FloresParameters`` and nothing else from the
reference. It is what a careful programmer would write by hand for this one
mechanism, so the engine's time over its time measures what the engine's
generality costs (docs/theory/reference-slider-crank.md, "The practical limit").

Numerics:

* Dormand-Prince 5(4), Hairer's coefficients (``dopri5``), FSAL: an accepted
  step costs six evaluations. Error norm RMS of err_i / (atol + rtol
  max(|y_i|, |y_new_i|)); Hairer's PI controller (beta 0.04, safety 0.9,
  factors 0.2..10, no growth right after a rejection); Hairer's starting step
  heuristic (one evaluation); the last step lands on t_end (the 1.01 rule).
* Contact onset: the penetration delta = |e| - c is checked for a rise
  through zero in every accepted step. A step whose end values have the same
  sign and lie farther from zero than the step could move them
  (min(|g0|, |g1|) > h (|g0'| + |g1'|), with the rates d|e|/dt at the ends) is
  not looked into; any other step is sampled at 7 interior points of the dense
  output (Shampine's 4th-order interpolant) and the first sub-interval with a
  rise is solved by the Illinois method to 4 eps |t| + 1e-15 s, taking the
  right end of the bracket (delta > 0 there). The step is cut at the onset,
  the impact velocity latched as max(delta_dot, floor) and the method restarts
  there (one evaluation).
* The latch is cleared at an accepted step end with delta <= 0. A stage that
  sees delta > 0 with nothing latched uses max(delta_dot, floor), which is
  also the value latched at an onset, so the restart evaluation at the onset is
  the same with and without the latch.
* Output: every accepted step end (and each onset), or the times of a given
  grid from the dense output; recorded arrays grow by doubling.

``warm_up()`` compiles the function (or loads it from numba's cache) before
anything is timed.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numba import njit

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "physics"))
from reference_slider_crank import FloresParameters, ideal_initial_state  # noqa: E402

__all__ = ["LimitResult", "parameter_vector", "simulate_limit", "first_impact", "warm_up"]

# --- Dormand-Prince 5(4) (Hairer, Norsett, Wanner, ODE I, Table II.5.2; dopri5) ---
C2, C3, C4, C5 = 0.2, 0.3, 0.8, 8.0 / 9.0
A21 = 0.2
A31, A32 = 3.0 / 40.0, 9.0 / 40.0
A41, A42, A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
A51, A52, A53, A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
A61, A62, A63, A64, A65 = 9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0
A71, A73, A74, A75, A76 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
E1, E3, E4, E5, E6, E7 = (71.0 / 57600.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0,
                          -1.0 / 40.0)
D1, D3, D4 = -12715105075.0 / 11282082432.0, 87487479700.0 / 32700410799.0, -10690763975.0 / 1880347072.0
D5, D6, D7 = 701980252875.0 / 199316789632.0, -1453857185.0 / 822651844.0, 69997945.0 / 29380423.0

SAFETY, BETA, FAC_MIN, FAC_MAX, ERR_OLD_FLOOR = 0.9, 0.04, 0.2, 10.0, 1e-4
EXPO1 = 0.2 - 0.75 * BETA
EPS = 2.220446049250313e-16

# indices of the parameter vector
(P_A, P_L, P_W, P_CI, P_CG, P_J, P_M3, P_C, P_RJ, P_K, P_N, P_DAMP, P_MU, P_V0, P_V1, P_FLOOR) = range(16)

#: status codes returned in ``stats[4]``
STATUS = {0: "finished", 1: "step size underflow", 2: "too many steps"}


def parameter_vector(p: FloresParameters) -> np.ndarray:
    """The numbers the compiled run needs, derived from the benchmark parameters."""
    half = 0.5 * p.rod_length
    vec = np.zeros(16)
    vec[P_A], vec[P_L], vec[P_W] = p.crank_length, p.rod_length, p.crank_speed
    vec[P_CI] = p.rod_mass * half * p.crank_length * p.crank_speed**2  # times sin(theta - phi)
    vec[P_CG] = p.rod_mass * p.gravity * half  # times cos(phi)
    vec[P_J] = p.rod_inertia + p.rod_mass * half * half  # rod inertia about the crank pin
    vec[P_M3] = p.slider_mass
    vec[P_C], vec[P_RJ], vec[P_K], vec[P_N] = p.clearance, p.journal_radius, p.stiffness, p.contact_exponent
    vec[P_DAMP] = 0.75 * (1.0 - p.restitution**2)
    vec[P_MU], vec[P_V0], vec[P_V1] = p.friction_coefficient, p.v0, p.v1
    vec[P_FLOOR] = p.onset_velocity_floor
    return vec


@njit(cache=True, error_model="numpy")
def _rhs(t, phi, xs, phid, xsd, latch, P):
    """Accelerations (phi_dd, x_s_dd), penetration, its rate and the normal force at one state.

    ``latch`` is the latched impact velocity, or 0 when nothing is latched (then a
    penetrating state uses max(delta_dot, floor)).
    """
    a, L, w = P[P_A], P[P_L], P[P_W]
    th = w * t
    ct, st = math.cos(th), math.sin(th)
    cp, sp = math.cos(phi), math.sin(phi)
    q = P[P_CI] * (st * cp - ct * sp) - P[P_CG] * cp
    ex = a * ct + L * cp - xs
    ey = a * st + L * sp
    # velocity of the journal centre relative to the bore centre
    aw = a * w
    edx = -aw * st - phid * L * sp - xsd
    edy = aw * ct + phid * L * cp
    r = math.sqrt(ex * ex + ey * ey)
    g = r - P[P_C]
    if r > 0.0:
        gdot = (ex * edx + ey * edy) / r
    else:  # journal exactly centred: no direction; the speed bounds the rate
        gdot = math.sqrt(edx * edx + edy * edy)
    J = P[P_J]
    if g <= 0.0:
        return q / J, 0.0, g, gdot, 0.0
    nx, ny = ex / r, ey / r
    dm = latch
    if dm <= 0.0:
        dm = gdot if gdot > P[P_FLOOR] else P[P_FLOOR]
    n = P[P_N]
    pw = g * math.sqrt(g) if n == 1.5 else g**n
    fn = P[P_K] * pw * (1.0 + P[P_DAMP] * gdot / dm)
    if fn <= 0.0:
        return q / J, 0.0, g, gdot, 0.0
    # contact point on the journal relative to the crank pin, and its velocity relative to the bore
    Rj = P[P_RJ]
    rx = L * cp + Rj * nx
    ry = L * sp + Rj * ny
    vx = edx - phid * Rj * ny
    vy = edy + phid * Rj * nx
    vt = vy * nx - vx * ny
    avt = abs(vt)
    mu, v0, v1 = P[P_MU], P[P_V0], P[P_V1]
    ft = 0.0
    if avt >= v0 and mu != 0.0:
        cd = 1.0 if avt >= v1 else (avt - v0) / (v1 - v0)
        ft = -cd * mu * fn if vt > 0.0 else cd * mu * fn
    fx = -fn * nx - ft * ny
    fy = -fn * ny + ft * nx
    return (q + rx * fy - ry * fx) / J, -fx / P[P_M3], g, gdot, fn


@njit(cache=True, error_model="numpy")
def _penetration(t, phi, xs, P):
    a, L = P[P_A], P[P_L]
    th = P[P_W] * t
    ex = a * math.cos(th) + L * math.cos(phi) - xs
    ey = a * math.sin(th) + L * math.sin(phi)
    return math.sqrt(ex * ex + ey * ey) - P[P_C]


@njit(cache=True, error_model="numpy")
def _grow(times, Y, FN, G):
    n = times.shape[0]
    t2, Y2, FN2, G2 = np.empty(2 * n), np.empty((2 * n, 4)), np.empty(2 * n), np.empty(2 * n)
    for i in range(n):
        t2[i], FN2[i], G2[i] = times[i], FN[i], G[i]
        for j in range(4):
            Y2[i, j] = Y[i, j]
    return t2, Y2, FN2, G2


@njit(cache=True, error_model="numpy")
def _run(P, y0, t0, t_end, rtol, atol, t_out, max_steps, min_step):
    """The whole run. Returns (times, states (n x 4), normal force, penetration, impact times,
    stats [accepted, rejected, rhs evaluations, impacts, status], peak normal force)."""
    grid = t_out.shape[0] > 0
    cap = 4096
    times, Y, FN, G = np.empty(cap), np.empty((cap, 4)), np.empty(cap), np.empty(cap)
    impacts = np.empty(64)
    n_imp = 0
    y = np.empty(4)
    yn = np.empty(4)
    yt = np.empty(4)
    k = np.empty((7, 4))
    r = np.empty((5, 4))  # dense output coefficients of the last step
    latch = 0.0
    t = t0
    for i in range(4):
        y[i] = y0[i]
    nfev = 0
    accepted = 0
    rejected = 0
    status = 0

    # f at the start (k1) with penetration and rate
    d2, d3, g_t, gd_t, fn_t = _rhs(t, y[0], y[1], y[2], y[3], latch, P)
    nfev += 1
    k[0, 0], k[0, 1], k[0, 2], k[0, 3] = y[2], y[3], d2, d3
    n_out = 0
    i_out = 0
    if grid:
        while i_out < t_out.shape[0] and t_out[i_out] <= t:
            times[n_out] = t_out[i_out]
            for i in range(4):
                Y[n_out, i] = y[i]
            FN[n_out], G[n_out] = fn_t, g_t
            n_out += 1
            i_out += 1
    else:
        times[0] = t
        for i in range(4):
            Y[0, i] = y[i]
        FN[0], G[0] = fn_t, g_t
        n_out = 1

    # Hairer's starting step
    dnf = 0.0
    dny = 0.0
    for i in range(4):
        sk = atol + rtol * abs(y[i])
        dnf += (k[0, i] / sk) ** 2
        dny += (y[i] / sk) ** 2
    h = 1e-6 if (dnf <= 1e-10 or dny <= 1e-10) else 0.01 * math.sqrt(dny / dnf)
    h = min(h, t_end - t)
    for i in range(4):
        yt[i] = y[i] + h * k[0, i]
    e2, e3, _g, _gd, _fn = _rhs(t + h, yt[0], yt[1], yt[2], yt[3], latch, P)
    nfev += 1
    der2 = ((yt[2] - k[0, 0]) / (atol + rtol * abs(y[0]))) ** 2 + ((yt[3] - k[0, 1]) / (atol + rtol * abs(y[1]))) ** 2
    der2 += ((e2 - k[0, 2]) / (atol + rtol * abs(y[2]))) ** 2 + ((e3 - k[0, 3]) / (atol + rtol * abs(y[3]))) ** 2
    der2 = math.sqrt(der2) / h
    der12 = max(abs(der2), math.sqrt(dnf))
    h1 = max(1e-6, abs(h) * 1e-3) if der12 <= 1e-15 else (0.01 / der12) ** 0.2
    h = min(100.0 * h, h1, t_end - t)

    err_old = ERR_OLD_FLOOR
    last_rejected = False
    while t < t_end:
        if accepted + rejected >= max_steps:
            status = 2
            break
        if h < min_step or t + h == t:
            status = 1
            break
        last = False
        if t + 1.01 * h >= t_end:
            h = t_end - t
            last = True
        # stages 2..6
        for i in range(4):
            yt[i] = y[i] + h * A21 * k[0, i]
        a2, a3, _g, _gd, _fn = _rhs(t + C2 * h, yt[0], yt[1], yt[2], yt[3], latch, P)
        k[1, 0], k[1, 1], k[1, 2], k[1, 3] = yt[2], yt[3], a2, a3
        for i in range(4):
            yt[i] = y[i] + h * (A31 * k[0, i] + A32 * k[1, i])
        a2, a3, _g, _gd, _fn = _rhs(t + C3 * h, yt[0], yt[1], yt[2], yt[3], latch, P)
        k[2, 0], k[2, 1], k[2, 2], k[2, 3] = yt[2], yt[3], a2, a3
        for i in range(4):
            yt[i] = y[i] + h * (A41 * k[0, i] + A42 * k[1, i] + A43 * k[2, i])
        a2, a3, _g, _gd, _fn = _rhs(t + C4 * h, yt[0], yt[1], yt[2], yt[3], latch, P)
        k[3, 0], k[3, 1], k[3, 2], k[3, 3] = yt[2], yt[3], a2, a3
        for i in range(4):
            yt[i] = y[i] + h * (A51 * k[0, i] + A52 * k[1, i] + A53 * k[2, i] + A54 * k[3, i])
        a2, a3, _g, _gd, _fn = _rhs(t + C5 * h, yt[0], yt[1], yt[2], yt[3], latch, P)
        k[4, 0], k[4, 1], k[4, 2], k[4, 3] = yt[2], yt[3], a2, a3
        for i in range(4):
            yt[i] = y[i] + h * (A61 * k[0, i] + A62 * k[1, i] + A63 * k[2, i] + A64 * k[3, i] + A65 * k[4, i])
        t_new = t + h
        a2, a3, _g, _gd, _fn = _rhs(t_new, yt[0], yt[1], yt[2], yt[3], latch, P)
        k[5, 0], k[5, 1], k[5, 2], k[5, 3] = yt[2], yt[3], a2, a3
        for i in range(4):
            yn[i] = y[i] + h * (A71 * k[0, i] + A73 * k[2, i] + A74 * k[3, i] + A75 * k[4, i] + A76 * k[5, i])
        a2, a3, g_n, gd_n, fn_n = _rhs(t_new, yn[0], yn[1], yn[2], yn[3], latch, P)
        k[6, 0], k[6, 1], k[6, 2], k[6, 3] = yn[2], yn[3], a2, a3
        nfev += 6
        err = 0.0
        for i in range(4):
            ei = h * (E1 * k[0, i] + E3 * k[2, i] + E4 * k[3, i] + E5 * k[4, i] + E6 * k[5, i] + E7 * k[6, i])
            sk = atol + rtol * max(abs(y[i]), abs(yn[i]))
            err += (ei / sk) ** 2
        err = math.sqrt(err / 4.0)
        if not (err <= 1.0):  # rejected (also NaN)
            rejected += 1
            if err != err or err == math.inf:
                h *= FAC_MIN
            else:
                h /= min(1.0 / FAC_MIN, (err**EXPO1) / SAFETY)
            last_rejected = True
            continue
        # accepted: the controller's next step
        fac = (err**EXPO1) / (err_old**BETA) / SAFETY
        fac = max(1.0 / FAC_MAX, min(1.0 / FAC_MIN, fac))
        h_next = h / fac
        if last_rejected:
            h_next = min(h_next, h)
        last_rejected = False
        err_old = max(err, ERR_OLD_FLOOR)
        accepted += 1

        # contact onset inside the step: a rise of the penetration through zero
        t_stop = t_new
        onset = False
        skip = (g_t > 0.0) == (g_n > 0.0) and min(abs(g_t), abs(g_n)) > h * (abs(gd_t) + abs(gd_n))
        if not skip or grid:
            for i in range(4):
                r[0, i] = y[i]
                r[1, i] = yn[i] - y[i]
                r[2, i] = h * k[0, i] - r[1, i]
                r[3, i] = r[1, i] - h * k[6, i] - r[2, i]
                r[4, i] = h * (D1 * k[0, i] + D3 * k[2, i] + D4 * k[3, i] + D5 * k[4, i] + D6 * k[5, i]
                               + D7 * k[6, i])
        if not skip:
            ga = g_t
            ta = t
            tb = t_new
            gb = g_n
            for j in range(1, 9):
                if j < 8:
                    s = j / 8.0
                    u = 1.0 - s
                    tj = t + s * h
                    p0 = r[0, 0] + s * (r[1, 0] + u * (r[2, 0] + s * (r[3, 0] + u * r[4, 0])))
                    p1 = r[0, 1] + s * (r[1, 1] + u * (r[2, 1] + s * (r[3, 1] + u * r[4, 1])))
                    gj = _penetration(tj, p0, p1, P)
                else:
                    tj = t_new
                    gj = g_n
                if ga <= 0.0 < gj:
                    tb = tj
                    gb = gj
                    onset = True
                    break
                ta = tj
                ga = gj
            if onset:
                # Illinois: keep the bracket ga <= 0 < gb, end at its right side
                tol = 4.0 * EPS * abs(tb) + 1e-15
                side = 0
                for _it in range(200):
                    if tb - ta <= tol:
                        break
                    tm = (ta * gb - tb * ga) / (gb - ga)
                    if not (ta < tm < tb):
                        tm = 0.5 * (ta + tb)
                    s = (tm - t) / h
                    u = 1.0 - s
                    p0 = r[0, 0] + s * (r[1, 0] + u * (r[2, 0] + s * (r[3, 0] + u * r[4, 0])))
                    p1 = r[0, 1] + s * (r[1, 1] + u * (r[2, 1] + s * (r[3, 1] + u * r[4, 1])))
                    gm = _penetration(tm, p0, p1, P)
                    if gm > 0.0:
                        tb, gb = tm, gm
                        if side == 1:
                            ga *= 0.5
                        side = 1
                    else:
                        ta, ga = tm, gm
                        if side == -1:
                            gb *= 0.5
                        side = -1
                t_stop = tb
                s = (t_stop - t) / h
                u = 1.0 - s
                for i in range(4):
                    yt[i] = r[0, i] + s * (r[1, i] + u * (r[2, i] + s * (r[3, i] + u * r[4, i])))

        # grid output inside the step, with the latch in force during the step
        if grid:
            while i_out < t_out.shape[0] and t_out[i_out] <= t_stop:
                s = (t_out[i_out] - t) / h
                u = 1.0 - s
                for i in range(4):
                    yt2 = r[0, i] + s * (r[1, i] + u * (r[2, i] + s * (r[3, i] + u * r[4, i])))
                    Y[n_out, i] = yt2
                _a, _b, gg, _gd, ff = _rhs(t_out[i_out], Y[n_out, 0], Y[n_out, 1], Y[n_out, 2], Y[n_out, 3], latch, P)
                times[n_out], FN[n_out], G[n_out] = t_out[i_out], ff, gg
                n_out += 1
                i_out += 1
                if n_out == times.shape[0]:
                    times, Y, FN, G = _grow(times, Y, FN, G)

        if onset:
            # cut the step at the onset, latch max(delta_dot, floor), restart there
            t = t_stop
            for i in range(4):
                y[i] = yt[i]
            a2, a3, g_t, gd_t, fn_t = _rhs(t, y[0], y[1], y[2], y[3], 0.0, P)
            nfev += 1
            latch = gd_t if gd_t > P[P_FLOOR] else P[P_FLOOR]
            k[0, 0], k[0, 1], k[0, 2], k[0, 3] = y[2], y[3], a2, a3
            if n_imp == impacts.shape[0]:
                more = np.empty(2 * n_imp)
                for i in range(n_imp):
                    more[i] = impacts[i]
                impacts = more
            impacts[n_imp] = t
            n_imp += 1
            err_old = ERR_OLD_FLOOR
        else:
            t = t_new
            if last:
                t = t_end
            for i in range(4):
                y[i] = yn[i]
                k[0, i] = k[6, i]
            g_t, gd_t, fn_t = g_n, gd_n, fn_n
            if g_t <= 0.0:
                latch = 0.0
        if not grid:
            times[n_out] = t
            for i in range(4):
                Y[n_out, i] = y[i]
            FN[n_out], G[n_out] = fn_t, g_t
            n_out += 1
            if n_out == times.shape[0]:
                times, Y, FN, G = _grow(times, Y, FN, G)
        h = min(h_next, t_end - t)

    stats = np.array([accepted, rejected, nfev, n_imp, status], dtype=np.int64)
    peak = 0.0
    for i in range(n_out):
        if FN[i] > peak:
            peak = FN[i]
    return times[:n_out].copy(), Y[:n_out].copy(), FN[:n_out].copy(), G[:n_out].copy(), impacts[:n_imp].copy(), \
        stats, peak


@dataclass
class LimitResult:
    """A run of the compiled model: samples, impact (onset) times and counters."""

    t: np.ndarray
    y: np.ndarray  # (n, 4): phi, x_s, phi_dot, x_s_dot
    fn: np.ndarray  # normal contact force [N]
    penetration: np.ndarray  # delta = |e| - c [m]
    impacts: np.ndarray  # located contact onset times [s]
    accepted_steps: int
    rejected_steps: int
    rhs_evaluations: int
    peak_contact_force: float  # over the samples [N]

    @property
    def phi(self) -> np.ndarray:
        return self.y[:, 0]

    @property
    def x_s(self) -> np.ndarray:
        return self.y[:, 1]


def simulate_limit(params: FloresParameters = FloresParameters(), t_end: float | None = None, rtol: float = 1e-6,
                   atol: float = 1e-9, t_out=None, max_steps: int = 10_000_000,
                   min_step: float = 1e-14) -> LimitResult:
    """Runs the compiled model from the ideal initial state (the reference's) to ``t_end`` (default: two
    crank revolutions). ``t_out``: sample times (sorted, within [0, t_end]); default every accepted step."""
    t_end = float(2.0 * params.crank_period if t_end is None else t_end)
    grid = np.empty(0) if t_out is None else np.ascontiguousarray(t_out, dtype=float)
    t, y, fn, pen, impacts, stats, peak = _run(parameter_vector(params), ideal_initial_state(params), 0.0, t_end,
                                               float(rtol), float(atol), grid, int(max_steps), float(min_step))
    if stats[4] != 0:
        raise RuntimeError(f"the compiled run stopped at t = {t[-1]!r}: {STATUS[int(stats[4])]}")
    return LimitResult(t, y, fn, pen, impacts, int(stats[0]), int(stats[1]), int(stats[2]), float(peak))


def first_impact(result: LimitResult) -> tuple[float, float]:
    """Time of the first located onset and the peak normal force over the samples from it to the
    first later sample out of contact."""
    t_on = float(result.impacts[0])
    start = int(np.searchsorted(result.t, t_on))
    out = np.nonzero(result.penetration[start:] <= 0.0)[0]
    end = start + (int(out[0]) if out.size else result.t.size - start)
    return t_on, float(result.fn[start:end].max())


def warm_up() -> None:
    """Compiles the run (or loads it from numba's cache) with a short run, so that timing excludes it."""
    simulate_limit(t_end=1e-4)
