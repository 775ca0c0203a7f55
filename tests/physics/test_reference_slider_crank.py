"""Validation of the minimal-coordinate reference slider-crank itself.

The reference (reference_slider_crank.py) is what the engine is checked
against, so it gets its own checks that do not come from its own code paths:
closed-form kinematics, a work-energy balance, the restitution that the
Lankarani-Nikravesh law is built to reproduce, and sanity of the event logic.
"""

import math
from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from reference_slider_crank import (
    FloresParameters,
    _make_model,
    ambrosio_friction_factor,
    contact_fraction,
    first_impact,
    ideal_initial_state,
    ideal_slider_position,
    ln_normal_force,
    simulate_reference,
)

P = FloresParameters()


@pytest.fixture(scope="module")
def default_run():
    return simulate_reference(P)


def test_parameters_and_stiffness():
    # 1/E* = 2 (1 - nu^2)/E, R* = R_b R_j / c, K = 4/3 E* sqrt(R*)
    e_star = 207e9 / (2 * (1 - 0.09))
    r_star = 0.010 * 0.0095 / 0.0005
    assert P.stiffness == pytest.approx(4 / 3 * e_star * math.sqrt(r_star), rel=1e-14)
    assert P.stiffness == pytest.approx(6.6102e10, rel=1e-4)
    assert P.crank_speed == pytest.approx(523.5988, rel=1e-6)


def test_initial_state_matches_ideal_kinematics():
    # differentiate the closed form of the ideal mechanism numerically at t = 0
    y0 = ideal_initial_state(P)
    h = 1e-9
    xdot = (ideal_slider_position(P, h) - ideal_slider_position(P, -h)) / (2 * h)
    assert y0[3] == pytest.approx(0.0, abs=1e-12) and abs(xdot) < 1e-6
    assert y0[1] == pytest.approx(float(ideal_slider_position(P, 0.0)), rel=1e-15)
    # rod angle of the ideal mechanism: sin(phi) = -a sin(theta)/L
    phi = lambda t: math.asin(-P.crank_length * math.sin(P.crank_speed * t) / P.rod_length)
    assert y0[2] == pytest.approx((phi(h) - phi(-h)) / (2 * h), rel=1e-6)


def test_force_laws():
    K = P.stiffness
    assert ln_normal_force(-1e-6, 1.0, 1.0, K, 0.9) == 0.0
    assert ln_normal_force(1e-6, 0.0, 1.0, K, 0.9) == pytest.approx(K * 1e-9, rel=1e-12)
    # LN factor 3(1-e^2)/4 at delta_dot = delta_dot_minus
    assert ln_normal_force(1e-6, 2.0, 2.0, K, 0.9) == pytest.approx(
        K * 1e-9 * (1 + 0.75 * 0.19), rel=1e-12)
    # strongly separating: clipped at zero, never adhesive
    assert ln_normal_force(1e-6, -100.0, 1.0, K, 0.9) == 0.0
    assert ambrosio_friction_factor(0.5e-4, 1e-4, 1e-3) == 0.0
    assert ambrosio_friction_factor(5.5e-4, 1e-4, 1e-3) == pytest.approx(0.5)
    assert ambrosio_friction_factor(2e-3, 1e-4, 1e-3) == 1.0


def test_rhs_and_detail_agree():
    """The integrated right-hand side and the output path are written twice
    (one inlined for speed); they must give the same accelerations."""
    rng = np.random.default_rng(1)
    for latched in (None, 0.7):
        rhs, _event, detail = _make_model(P, latched)
        for _ in range(200):
            t = rng.uniform(0, 0.024)
            th = P.crank_speed * t
            phi = math.asin(-P.crank_length * math.sin(th) / P.rod_length) + rng.normal(0, 3e-3)
            xb = P.crank_length * math.cos(th) + P.rod_length * math.cos(phi)
            y = np.array([phi, xb + rng.normal(0, 4e-4), rng.normal(0, 200), rng.normal(0, 20)])
            f = rhs(t, y)
            d = detail(t, *y)
            assert f[2] == pytest.approx(d[0], rel=1e-12, abs=1e-9)
            assert f[3] == pytest.approx(d[1], rel=1e-12, abs=1e-9)


def test_slider_follows_ideal_kinematics():
    """Stiff contact, no gravity: the slider stays within a few clearances of
    x = a cos(theta) + sqrt(L^2 - a^2 sin^2(theta)) over two revolutions, and
    the journal never leaves the clearance circle by more than the Hertz
    penetration."""
    for k in (None, 1e12):
        p = replace(P, gravity=0.0, contact_stiffness=k)
        r = simulate_reference(p)
        dev = np.abs(r.x_s - ideal_slider_position(p, r.t)).max()
        assert dev < 2.0 * p.clearance, dev / p.clearance
        # the slider x-stroke is 2a: it must really have moved with the crank
        assert r.x_s.max() - r.x_s.min() == pytest.approx(2 * p.crank_length, abs=3 * p.clearance)
        assert r.penetration.max() < 0.2 * p.clearance


def _energy(p, t, y):
    """Mechanical energy of rod + slider, Hertz potential, and the gravity
    potential of rod and crank (the crank's kinetic energy is constant)."""
    a, L, w, g = p.crank_length, p.rod_length, p.crank_speed, p.gravity
    phi, xs, phid, xsd = y
    th = w * t
    gvx = -a * w * math.sin(th) - 0.5 * L * phid * math.sin(phi)
    gvy = a * w * math.cos(th) + 0.5 * L * phid * math.cos(phi)
    kin = 0.5 * p.rod_mass * (gvx**2 + gvy**2) + 0.5 * p.rod_inertia * phid**2 \
        + 0.5 * p.slider_mass * xsd**2
    gy = a * math.sin(th) + 0.5 * L * math.sin(phi)
    pot_g = p.rod_mass * g * gy + p.crank_mass * g * 0.5 * a * math.sin(th)
    ex = a * math.cos(th) + L * math.cos(phi) - xs
    ey = a * math.sin(th) + L * math.sin(phi)
    delta = math.hypot(ex, ey) - p.clearance
    pot_c = p.stiffness * delta**2.5 / 2.5 if delta > 0 else 0.0
    return kin + pot_g + pot_c


def test_work_energy_balance():
    """Hertz contact (e = 1 makes the LN damping vanish), no friction: the
    energy of rod + slider + contact spring + gravity changes exactly by the
    work of the driving torque, W = int tau omega dt (the driven crank turns
    at constant speed).  The work is integrated as a fifth state alongside the
    motion, so the balance holds to the integration tolerance."""
    p = replace(P, restitution=1.0, friction_coefficient=0.0)
    rhs, _event, detail = _make_model(p, None)
    w = p.crank_speed

    def aug(t, y):
        f = rhs(t, y[:4])
        tau = detail(t, *y[:4].tolist())[7]
        return [f[0], f[1], f[2], f[3], tau * w]

    y0 = np.append(ideal_initial_state(p), 0.0)
    t_end = 2 * p.crank_period
    sol = solve_ivp(aug, (0, t_end), y0, method="DOP853", rtol=1e-11, atol=1e-13)
    assert sol.status == 0
    e0 = _energy(p, 0.0, y0[:4])
    e = np.array([_energy(p, t, y[:4]) for t, y in zip(sol.t, sol.y.T)])
    resid = e - e0 - sol.y[4]
    scale = e.max()
    # the check is not vacuous: there were impacts and the energy moved a lot
    pen = np.array([detail(t, *y[:4])[4] for t, y in zip(sol.t, sol.y.T)])
    assert pen.max() > 1e-5
    assert np.ptp(e) > 0.2 * scale
    assert np.abs(resid).max() < 1e-8 * scale, np.abs(resid).max() / scale


@pytest.mark.parametrize("e", [0.9, 0.95])
def test_ln_restitution_single_impact(e):
    """One normal impact of a point mass on the LN law, delta_dot_minus latched
    at the approach velocity: the exit velocity gives e within 2 %."""
    K, m, v = P.stiffness, P.slider_mass, 1.5

    def f(t, y):
        return [y[1], -ln_normal_force(y[0], y[1], v, K, e) / m]

    def out(t, y):
        return y[0]

    out.terminal = True
    out.direction = -1
    sol = solve_ivp(f, (0, 1e-2), [0.0, v], method="DOP853", rtol=1e-11, atol=1e-15,
                    events=out)
    assert sol.status == 1
    e_eff = -sol.y_events[0][0][1] / v
    assert e_eff == pytest.approx(e, rel=0.02)
    assert e_eff < 1.0


def test_first_impact_and_contact_fraction(default_run):
    r = default_run
    fi = first_impact(r)
    period = P.crank_period
    assert 0 < fi["time"] < period
    # closed-form estimate of the first onset: the slider coasts at x_s = a + L
    # (no force in free flight, x_sdot(0) = 0) while the journal follows the
    # crank; the gap closes when a (1 - cos th) + L (1 - cos phi) = c.
    th = np.linspace(0, 1, 200001)
    phi = np.arcsin(-P.crank_length * np.sin(th) / P.rod_length)
    ex = P.crank_length * np.cos(th) + P.rod_length * np.cos(phi) - (P.crank_length + P.rod_length)
    ey = P.crank_length * np.sin(th) + P.rod_length * np.sin(phi)
    # phi is not exactly the ideal angle (the rod is free too), so compare loosely
    th_on = th[np.argmax(np.hypot(ex, ey) > P.clearance)]
    assert fi["time"] == pytest.approx(th_on / P.crank_speed, rel=0.02)
    assert fi["peak_contact_force"] > 0 and fi["peak_slider_acceleration"] > 0
    # in contact the slider's only x force is the contact force
    assert fi["peak_slider_acceleration"] <= fi["peak_contact_force"] / P.slider_mass * (1 + 1e-12)
    cf = contact_fraction(r)
    assert 0.0 < cf < 1.0


def test_events_and_latching(default_run):
    r = default_run
    assert len(r.impacts) >= 3
    assert np.all(np.diff(r.impacts) > 0)
    assert all(v >= P.onset_velocity_floor for v in r.onset_velocities)
    # onsets and separations alternate
    for k, s in enumerate(r.separations):
        assert r.impacts[k] < s
        if k + 1 < len(r.impacts):
            assert s < r.impacts[k + 1]
    # the penetration at each located event is zero to rounding
    for te in r.impacts + r.separations:
        i = np.argmin(np.abs(r.t - te))
        assert r.t[i] == te and abs(r.penetration[i]) < 1e-12
    # the time grid is strictly increasing (event points are not duplicated)
    assert np.all(np.diff(r.t) > 0)
    assert r.n_steps >= len(r.t) - 1 and r.nfev > r.n_steps


def test_contact_fraction_matches_piece_durations(default_run):
    r = default_run
    seps = r.separations + ([r.t[-1]] if len(r.impacts) > len(r.separations) else [])
    pieces = sum(s - i for i, s in zip(r.impacts, seps)) / r.t[-1]
    assert contact_fraction(r) == pytest.approx(pieces, abs=1e-3)


def test_dense_output_agrees_with_steps(default_run):
    r = default_run
    d = simulate_reference(P, dense=True)
    assert d.t[0] == 0 and d.t[-1] == pytest.approx(2 * P.crank_period)
    assert d.n_steps == r.n_steps and d.nfev == r.nfev and d.impacts == r.impacts
    # dense interpolant vs step points, before the chaotic divergence matters
    m = r.t < r.impacts[1]
    assert np.interp(r.t[m], d.t, d.x_s) == pytest.approx(r.x_s[m], abs=2e-6)
    assert contact_fraction(d) == pytest.approx(contact_fraction(r), abs=5e-3)


def test_first_impact_converges_with_tolerance():
    """The first impact is deterministic (no chaos yet): tolerances 1e-6 and
    1e-9 agree on its time and peak force."""
    t_end = 3.5e-4
    a = first_impact(simulate_reference(P, t_end=t_end, rtol=1e-6, atol=1e-9))
    b = first_impact(simulate_reference(P, t_end=t_end, rtol=1e-9, atol=1e-12))
    assert a["time"] == pytest.approx(b["time"], rel=1e-7)
    assert a["peak_contact_force"] == pytest.approx(b["peak_contact_force"], rel=1e-2)


@pytest.mark.parametrize("rtol, atol, column", [(1e-6, 1e-9, 0), (1e-9, 1e-12, 1)])
def test_the_documented_numbers_are_what_the_reference_gives(rtol, atol, column, default_run):
    """docs/theory/reference-slider-crank.md, "Observed numbers": each row of its table, as printed there."""
    from pathlib import Path

    page = (Path(__file__).resolve().parents[2] / "docs" / "theory" / "reference-slider-crank.md").read_text()
    rows = {}
    for line in page.split("## Observed numbers")[1].splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 3:
            rows[cells[0]] = cells[1 + column]
    r = default_run if column == 0 else simulate_reference(P, rtol=rtol, atol=atol)
    fi = first_impact(r)
    assert float(rows["first onset"].split()[0]) == pytest.approx(fi["time"], abs=5e-10)
    assert rows["onset velocity"] == f"{r.onset_velocities[0]:.3f} m/s"
    assert rows["first-impact peak F_n"] == f"{fi['peak_contact_force'] / 1e3:.2f} kN"
    assert rows["contact fraction"] == f"{contact_fraction(r):.3f}"
    assert rows["impacts"] == str(len(r.impacts))
    documented_nfev, documented_steps = (int(x.replace(" ", "")) for x in rows["nfev / accepted steps"].split("/"))
    # (the step counts depend on SciPy's version: a few per mille)
    assert r.nfev == pytest.approx(documented_nfev, rel=0.01)
    assert r.n_steps == pytest.approx(documented_steps, rel=0.01)
