"""The independent lubricated slider-crank reference (reference_lubricated.py):
(a) its film force against closed forms and against a brute-force fixed-frame
integration of the long-bearing Reynolds equation; (b) the engine against it
on the lubricated Flores slider-crank (hamrock_long, 400 cP, wang_improved).

See docs/theory/reference-lubricated.md for the tolerances.
"""

import math

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid

import reference_lubricated as rl
from reference_slider_crank import FloresParameters

R, LB, C, MU = 9.5e-3, 0.040, 0.5e-3, 0.400  # journal radius, length, clearance, 400 cP


def split(fx, fy, angle):
    """(radial, tangential) components in the line-of-centres frame at ``angle``."""
    n = (math.cos(angle), math.sin(angle))
    return fx * n[0] + fy * n[1], -fx * n[1] + fy * n[0]


# --------------------------------------------------------------------------
# (a) the reference's film force
# --------------------------------------------------------------------------


@pytest.mark.parametrize("eps", [1e-3, 0.1, 0.5, 0.8, 0.95, 0.99, 0.999])
@pytest.mark.parametrize("angle", [0.0, 2.3, -1.7])
def test_steady_limit_is_the_gumbel_long_bearing(eps, angle):
    omega = 218.0
    e = eps * C * np.array([math.cos(angle), math.sin(angle)])
    fx, fy, _ = rl.long_bearing_film(e[0], e[1], 0.0, 0.0, omega, 0.0, R, LB, C, MU)
    fr, ft = split(fx, fy, angle)
    fr_ref, ft_ref = rl.gumbel_long_steady(eps, omega, R, LB, C, MU)
    assert fr == pytest.approx(-fr_ref, rel=1e-9)  # towards the centre
    assert ft == pytest.approx(ft_ref, rel=1e-9)  # along +t for a positive spin


def test_steady_limit_with_reversed_spin_reverses_the_tangential_force_only():
    e = (0.6 * C, 0.0)
    fx1, fy1, t1 = rl.long_bearing_film(*e, 0.0, 0.0, 300.0, 0.0, R, LB, C, MU)
    fx2, fy2, t2 = rl.long_bearing_film(*e, 0.0, 0.0, -300.0, 0.0, R, LB, C, MU)
    assert fx2 == pytest.approx(fx1, rel=1e-12)
    assert fy2 == pytest.approx(-fy1, rel=1e-12)
    assert t2 == pytest.approx(-t1, rel=1e-12)


def brute_force_long_bearing(ex, ey, exd, eyd, wj, wb, n=400_001):
    """Fixed-frame long-bearing film with no line-of-centres frame, no whirl rate and no
    Sommerfeld substitution: h(theta) = c - e.u, Reynolds integrated once,
        h^3 dp/dtheta = R^2 [6 mu (wj + wb) h + 12 mu G(theta)] + C0,
        G = int dh/dt dtheta = -exd sin(theta) + eyd cos(theta),
    on the arc where the source 6 mu (wj + wb) dh/dtheta + 12 mu dh/dt is negative (a half
    turn), C0 such that p = 0 at both ends.  Force -R L int p u dtheta, shear torque on the
    journal R^2 L int tau dtheta with tau = mu R (wb - wj)/h - (h / 2R) dp/dtheta (pressure
    part only where the film carries pressure).  Trapezoid on n points."""
    # source = A cos(theta) + B sin(theta)
    A = 6 * MU * (wj + wb) * (-ey) - 12 * MU * exd
    B = 6 * MU * (wj + wb) * ex - 12 * MU * eyd
    centre = math.atan2(-B, -A)
    th = np.linspace(centre - math.pi / 2, centre + math.pi / 2, n)
    h = C - ex * np.cos(th) - ey * np.sin(th)
    G = -exd * np.sin(th) + eyd * np.cos(th)
    a_part = R**2 * (6 * MU * (wj + wb) * h + 12 * MU * G) / h**3
    b_part = 1.0 / h**3
    C0 = -np.trapezoid(a_part, th) / np.trapezoid(b_part, th)
    dp = a_part + C0 * b_part
    p = cumulative_trapezoid(dp, th, initial=0.0)
    fx = -R * LB * np.trapezoid(p * np.cos(th), th)
    fy = -R * LB * np.trapezoid(p * np.sin(th), th)
    full = np.linspace(0.0, 2 * math.pi, n)
    hf = C - ex * np.cos(full) - ey * np.sin(full)
    couette = R**2 * LB * np.trapezoid(MU * R * (wb - wj) / hf, full)
    pressure = R**2 * LB * np.trapezoid(-h / (2 * R) * dp, th)
    return fx, fy, couette + pressure, p.min() / max(p.max(), 1e-300)


MIXED = {
    # name: (ex, ey [m], exd, eyd [m/s], wj, wb [rad/s])
    "approach": (3e-4, 1e-4, 0.05, 0.02, 218.0, 0.0),
    "recess": (2e-4, -2.5e-4, -0.04, 0.06, 150.0, 0.0),
    "oblique_whirl": (-3.5e-4, 1.5e-4, 0.08, 0.09, 218.0, 0.0),
    "squeeze_dominated": (1e-4, 4e-4, -0.3, -0.9, 20.0, 0.0),
    "reverse_spin": (4.2e-4, 0.0, 0.01, -0.05, -218.0, 0.0),
    "turning_bearing": (1.5e-4, 3e-4, 0.02, -0.03, 100.0, 80.0),
    "high_eps": (0.0, -4.85e-4, 0.01, 0.002, 218.0, 0.0),
    "near_centre": (1e-9, -2e-9, 0.02, 0.01, 218.0, 0.0),
}


@pytest.mark.parametrize("name", sorted(MIXED))
def test_mixed_motion_matches_brute_force_fixed_frame_integration(name):
    """Moving Guembel half, wedge speed wj + wb - 2 gamma_dot and the shear torque, checked
    against an integration that never forms gamma_dot (it uses h(theta, t) directly)."""
    state = MIXED[name]
    fx, fy, tj = rl.long_bearing_film(*state, R, LB, C, MU)
    bx, by, bt, pmin_ratio = brute_force_long_bearing(*state)
    scale = math.hypot(bx, by)
    assert pmin_ratio > -1e-6  # the pressure found on the moving half is indeed non-negative
    assert math.hypot(fx - bx, fy - by) <= 1e-8 * scale
    assert tj == pytest.approx(bt, rel=1e-8)


def test_whirl_equals_steady_state_at_spin_minus_twice_the_whirl_rate():
    # e on x, whirling at gamma_dot (edot = c eps gamma_dot along t), journal spin wj:
    # same force as the steady state with spin wj - 2 gamma_dot.
    eps, wj, gd = 0.7, 218.0, 40.0
    fx, fy, _ = rl.long_bearing_film(eps * C, 0.0, 0.0, C * eps * gd, wj, 0.0, R, LB, C, MU)
    sx, sy, _ = rl.long_bearing_film(eps * C, 0.0, 0.0, 0.0, wj - 2 * gd, 0.0, R, LB, C, MU)
    assert (fx, fy) == pytest.approx((sx, sy), rel=1e-12)


def test_torque_is_petroff_at_the_centre_and_the_journal_spin_is_resisted():
    fx, fy, tj = rl.long_bearing_film(0.0, 0.0, 0.0, 0.0, 218.0, 0.0, R, LB, C, MU)
    assert (fx, fy) == (0.0, 0.0)
    assert tj == pytest.approx(-2 * math.pi * MU * R**3 * LB * 218.0 / C, rel=1e-12)


def test_transition_weight_and_safe_film_of_the_flores_joint():
    p, f = FloresParameters(), rl.FilmParameters()
    # paper 001's rule: D is the bearing (bore) diameter, 20 mm -> h_safe 3 um
    assert f.h_safe(p) == pytest.approx(3.0e-6, rel=1e-12)
    eps0 = f.lubricated_limit(p)
    assert eps0 == pytest.approx(1 - 3.0e-6 / 0.5e-3, rel=1e-12)
    assert rl.film_weight(eps0, eps0) == 1.0
    assert rl.film_weight(1.0, eps0) == 0.0
    assert rl.film_weight(0.5 * (1 + eps0), eps0) == pytest.approx(0.5, abs=1e-12)
    x = 1e-3  # zero slope at both ends
    assert 1 - rl.film_weight(eps0 + x * (1 - eps0), eps0) <= 3 * x * x
    assert rl.film_weight(1 - x * (1 - eps0), eps0) <= 3 * x * x


# --------------------------------------------------------------------------
# (b) the engine against the reference
# --------------------------------------------------------------------------

RTOL, ATOL = 1e-9, 1e-12


@pytest.fixture(scope="module")
def engine():
    import flores_slider_crank_dry as flores
    from jointplay import laws

    m = flores.build_model()
    m.joint("B")["lubrication"] = laws.lubrication("hamrock_long", laws.centipoise(400))
    return m.simulate(2 * FloresParameters().crank_period, rtol=RTOL, atol=ATOL)


@pytest.fixture(scope="module")
def reference(engine):
    return rl.simulate_lubricated(rtol=RTOL, atol=ATOL, dense=np.asarray(engine.time))


def test_reference_stays_lubricated_with_a_thick_film(reference):
    # 400 cP at 5000 rpm: the film never thins into the transition band (eps0 = 0.9943)
    assert len(reference.impacts) == 0
    assert reference.eps.max() < reference.film.lubricated_limit(reference.params)
    assert 10e-6 < reference.film_min.min() < 20e-6


def test_engine_and_reference_agree_on_contact(engine, reference):
    engine_contact = bool(np.any(np.asarray(engine["B.mode"]) >= 2))
    assert engine_contact == bool(np.any(reference.mode >= 2))
    engine_transition = bool(np.any(np.asarray(engine["B.mode"]) >= 1))
    assert engine_transition == bool(np.any(reference.mode >= 1))


# Tolerances. At rtol 1e-9 both integrators are accurate to about 1e-6 of the signal
# (observed: peak film force 2e-9, minimum film 4e-10, slider acceleration 2.7e-6 of its
# range, film force 4e-6 of its peak, slider position 7e-13 m). The tolerances below
# leave a margin of 5-10x over that and stay below the effect of the film's shear
# torque (6e-5 of the acceleration range, 4e-5 of the minimum film), so the comparison
# would catch an engine that dropped or mis-signed the torque
# (test_comparison_is_sensitive_to_the_shear_torque).
ACC_TOL = 2e-5  # of the slider-acceleration range
FH_TOL = 5e-5  # of the peak film force, pointwise


def test_engine_matches_reference_peak_film_force(engine, reference):
    assert np.max(engine["B.fh"]) == pytest.approx(reference.fh.max(), rel=1e-6)


def test_engine_matches_reference_minimum_film(engine, reference):
    assert np.min(engine["B.film_min"]) == pytest.approx(reference.film_min.min(), rel=1e-5)


def test_engine_matches_reference_slider_history(engine, reference):
    a_engine = np.asarray(engine["slider.ax"])
    assert np.max(np.abs(a_engine - reference.slider_ax)) <= ACC_TOL * np.ptp(reference.slider_ax)
    assert np.max(np.abs(np.asarray(engine["slider.x"]) - reference.x_s)) <= 1e-9  # [m], c = 5e-4
    assert np.max(np.abs(np.asarray(engine["B.fh"]) - reference.fh)) <= FH_TOL * reference.fh.max()


def test_comparison_is_sensitive_to_the_shear_torque(engine):
    """The reference without the film's shear torque on the rod is outside the tolerance:
    the engine applies the torque, and ACC_TOL is tight enough to tell."""
    no_torque = rl.simulate_lubricated(film=rl.FilmParameters(film_torque=False), rtol=RTOL, atol=ATOL,
                                       dense=np.asarray(engine.time))
    diff = np.max(np.abs(np.asarray(engine["slider.ax"]) - no_torque.slider_ax))
    assert diff > 2 * ACC_TOL * np.ptp(no_torque.slider_ax)


# --------------------------------------------------------------------------
# (c) the implicit NDF method of the engine against the reference
# --------------------------------------------------------------------------

# The film's squeeze damping makes this model stiff: Dormand-Prince needs about 3500 steps at
# any tolerance, the NDF about 400 at rtol 1e-6 and 950 at 1e-8. Its error is controlled per
# step without local extrapolation, so at equal rtol it is larger than Dormand-Prince's; at
# rtol 1e-8 it was observed at 1.4e-5 of the acceleration range, 2.2e-5 of the peak film force
# pointwise, 4e-5 of the minimum film and 2e-9 m in slider position. The tolerances leave 3-5x.
NDF_RTOL = 1e-8
NDF_SAMPLES = 2000


@pytest.fixture(scope="module")
def ndf_runs():
    import flores_slider_crank_dry as flores
    from jointplay import laws

    m = flores.build_model()
    m.joint("B")["lubrication"] = laws.lubrication("hamrock_long", laws.centipoise(400))
    t_end = 2 * FloresParameters().crank_period
    engine = m.simulate(t_end, method="bdf", rtol=NDF_RTOL, atol=1e-3 * NDF_RTOL, output_step=t_end / NDF_SAMPLES)
    reference = rl.simulate_lubricated(rtol=RTOL, atol=ATOL, dense=np.asarray(engine.time))
    return engine, reference


def test_ndf_engine_matches_the_reference(ndf_runs):
    engine, reference = ndf_runs
    assert len(engine.time) == NDF_SAMPLES + 1
    a_engine = np.asarray(engine["slider.ax"])
    assert np.max(np.abs(a_engine - reference.slider_ax)) <= 5e-5 * np.ptp(reference.slider_ax)
    assert np.max(np.abs(np.asarray(engine["B.fh"]) - reference.fh)) <= 1e-4 * reference.fh.max()
    assert np.max(np.abs(np.asarray(engine["slider.x"]) - reference.x_s)) <= 1e-8  # [m], c = 5e-4
    assert np.min(engine["B.film_min"]) == pytest.approx(reference.film_min.min(), rel=2e-4)


def test_ndf_engine_takes_far_fewer_steps_than_dormand_prince(ndf_runs, engine):
    stats = ndf_runs[0].statistics
    assert stats["jacobian_evaluations"] >= 1 and stats["factorizations"] >= stats["jacobian_evaluations"]
    # Dormand-Prince here ran at rtol 1e-9; at any tolerance it needs over 3000 steps on this model
    assert 3 * stats["accepted_steps"] < engine.statistics["accepted_steps"]
