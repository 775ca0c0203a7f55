"""Checks of the independent hydraulic-cylinder reference against closed forms.

reference_hydraulic.py is what the engine's cylinder element will be compared
with, so it is checked here against things that do not come from its own
code: the closed-chamber natural frequency (Merritt 1967, the hydraulic
spring), the closed-chamber pressure law p = p0 - beta ln(V/V0) at a static
equilibrium, a conservation law with friction off, Coulomb sliding and LuGre
presliding in closed form (Canudas de Wit et al. 1995), and the fit of the
chosen Stribeck velocity to paper 002's seal friction curve.
"""

import math
from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq, minimize_scalar

from reference_hydraulic import (
    CylinderParameters,
    balanced_rod_pressure,
    closed_chamber_pressure,
    closed_chamber_stiffness,
    frictionless,
    liquid_energy,
    simulate,
    stribeck_force,
    volumes,
)

P = CylinderParameters()
# "soft hydraulics": 1 m^3 behind each port (large accumulators), so that the
# seal, not the oil, holds the load: k_oil = 3.7e4 N/m against sigma0 = 1e7 N/m
SOFT = replace(P, cap_dead_volume=1.0, rod_dead_volume=1.0)


def upward_crossings(t, x):
    """Times where x crosses zero upwards (linear interpolation)."""
    k = np.where((x[:-1] < 0.0) & (x[1:] >= 0.0))[0]
    return t[k] + (t[k + 1] - t[k]) * x[k] / (x[k] - x[k + 1])


def test_areas_volumes_and_stiffness_by_hand():
    assert P.piston_area == pytest.approx(5.026548e-3, rel=1e-6)
    assert P.rod_side_area == pytest.approx(5.026548e-3 - 1.590431e-3, rel=1e-6)
    cap, rod = volumes(P, 0.25)
    assert cap == pytest.approx(1e-4 + 0.25 * 5.026548e-3, rel=1e-6)
    assert rod == pytest.approx(1e-4 + 0.25 * 3.436117e-3, rel=1e-6)
    k = closed_chamber_stiffness(P, 0.25)
    assert k == pytest.approx(1e9 * (5.026548e-3**2 / cap + 3.436117e-3**2 / rod), rel=1e-6)
    assert k == pytest.approx(3.0936e7, rel=1e-4)


def test_liquid_energy_is_the_work_of_compression():
    # E(p) = int_0^p p' (-dV/dp') dp' with V(p') = V exp((p - p')/beta), by quadrature
    beta = P.bulk_modulus
    for pressure in (-5e4, 1e6, 2e7, 3e8):
        volume = 1.3e-3
        work, _ = quad(lambda q: q * volume * math.exp((pressure - q) / beta) / beta, 0.0, pressure)
        assert float(liquid_energy(pressure, volume, beta)) == pytest.approx(work, rel=1e-9)
    # small pressure: V p^2 / (2 beta)
    assert float(liquid_energy(1e5, 1e-3, beta)) == pytest.approx(1e-3 * 1e10 / 2e9, rel=1e-4)


def test_small_free_oscillation_has_the_closed_chamber_natural_frequency():
    # omega^2 = beta (A1^2/V1 + A2^2/V2) / m (Merritt's hydraulic spring, single-rod form)
    q = frictionless(P)
    omega = math.sqrt(closed_chamber_stiffness(q, 0.25) / q.mass)
    period = 2.0 * math.pi / omega
    t = np.linspace(0.0, 30 * period, 30 * 400 + 1)
    h = simulate(q, t[-1], initial_rate=1e-3, t_eval=t)
    assert h.success, h.message
    crossings = upward_crossings(h.t, h.stroke - 0.25)
    measured = 2.0 * math.pi * (len(crossings) - 1) / (crossings[-1] - crossings[0])
    # amplitude 0.8 um: nonlinearity and interpolation errors are ~1e-7
    assert measured == pytest.approx(omega, rel=1e-5)
    assert omega / (2 * math.pi) == pytest.approx(197.9, abs=0.1)  # Hz


def test_energy_is_conserved_with_friction_off():
    # a 0.5 m/s kick swings the pressures by MPa (the log law is exercised)
    q = frictionless(P)
    # (DOP853: no stiff seal here, and it drifts 200 times less than LSODA at equal rtol)
    h = simulate(q, 0.1, initial_rate=0.5, t_eval=np.linspace(0.0, 0.1, 2001), method="DOP853")
    energy = h.kinetic_energy + h.stored_energy
    assert np.ptp(h.p_cap) > 1e6
    # drift ~1e-8 J at rtol 1e-10 over 20 periods, against the 2.5 J kick
    assert np.max(np.abs(energy - energy[0])) < 1e-7 * h.kinetic_energy[0]


@pytest.mark.parametrize(("load", "axial_gravity"), [(-2.0e4, 0.0), (1.5e4, -9.81)])
def test_static_pressures_under_a_load_follow_the_closed_chamber_law(load, axial_gravity):
    # a damper on the mass lets it settle; at rest p_cap A1 - p_rod A2 = -(F + m g_axial)
    # with each p_i = p_i0 - beta ln(V_i/V_i0), solved here by brentq
    k = closed_chamber_stiffness(P, 0.25)
    q = replace(frictionless(P), damper=math.sqrt(k * P.mass), axial_gravity=axial_gravity)
    p10, p20 = 5e6, balanced_rod_pressure(P, 5e6)
    h = simulate(q, 0.1, applied_force=load, cap_pressure=p10, rod_pressure=p20)
    assert h.success, h.message
    cap0, rod0 = volumes(P, 0.25)

    def pressures(s):
        cap, rod = volumes(P, s)
        return (
            closed_chamber_pressure(p10, cap0, cap, P.bulk_modulus),
            closed_chamber_pressure(p20, rod0, rod, P.bulk_modulus),
        )

    target = -(load + P.mass * axial_gravity)
    s_eq = brentq(lambda s: pressures(s)[0] * P.piston_area - pressures(s)[1] * P.rod_side_area - target, 0.2, 0.3,
                  xtol=1e-14)
    p_cap, p_rod = pressures(s_eq)
    assert abs(h.rate[-1]) < 1e-8
    assert h.stroke[-1] == pytest.approx(s_eq, abs=1e-9)
    assert h.p_cap[-1] == pytest.approx(p_cap, abs=1.0)
    assert h.p_rod[-1] == pytest.approx(p_rod, abs=1.0)
    # the linear estimate -target/k is within 2 % (the chamber law is mildly nonlinear)
    assert h.stroke[-1] - 0.25 == pytest.approx(-target / k, rel=0.02)


def test_inflow_moves_the_piston_at_q_over_a():
    # Q_cap = A1 U in, Q_rod = A2 U out, from rest: s = s0 + U t - (U/omega) sin(omega t)
    # (the chamber pressures stay at their initial values when s moves at exactly U)
    q = frictionless(P)
    speed = 0.01
    omega = math.sqrt(closed_chamber_stiffness(q, 0.25) / q.mass)
    t = np.linspace(0.0, 0.02, 801)
    h = simulate(q, t[-1], cap_inflow=P.piston_area * speed, rod_inflow=-P.rod_side_area * speed, t_eval=t)
    expected = 0.25 + speed * t - speed / omega * np.sin(omega * t)
    # the stroke moves 0.2 mm, so the stiffness changes by < 0.1 %: the oscillation
    # (amplitude 8 um) is matched to 1 % of its amplitude
    assert np.max(np.abs(h.stroke - expected)) < 0.01 * speed / omega


def test_seal_holds_a_slowly_loaded_mass_between_kinetic_and_static_force():
    # 370 N (F_C < 370 < F_S) reached at 1.85 N/s, then held: the seal sticks
    h = simulate(SOFT, 210.0, applied_force=lambda t: 370.0 * min(t / 200.0, 1.0), cap_pressure=0.0,
                 rod_pressure=0.0, t_eval=np.linspace(0.0, 210.0, 2101))
    assert h.success, h.message
    assert np.max(np.abs(h.rate)) < 1e-5  # paper 002's stiction tolerance, 0.01 mm/s
    # presliding displacement, slow loading: dx = dz/(1 - sigma0 z/F_S), so
    # x = -(F_S/sigma0) ln(1 - F_seal/F_S), F_seal = sigma0 z the part the seal carries
    seal_force = P.bristle_stiffness * h.bristle[-1]
    expected = -(P.static_force / P.bristle_stiffness) * math.log(1.0 - seal_force / P.static_force)
    # g(u) is ~0.3 % below F_S at the presliding speed: 2 %
    assert h.stroke[-1] - 0.25 == pytest.approx(expected, rel=0.02)
    # the oil carries the rest of the load: F = sigma0 z - (p_cap A1 - p_rod A2)
    pressure_force = h.p_cap[-1] * P.piston_area - h.p_rod[-1] * P.rod_side_area
    assert seal_force - pressure_force == pytest.approx(370.0, abs=1e-3)
    assert seal_force > P.kinetic_force


def test_seal_slips_above_the_static_force_as_coulomb_friction():
    # 420 N > F_S: the mass slides; once the bristles have saturated (x > 1 mm,
    # 30 deflection limits) and while u >> v_S the friction is F_C exactly, so
    # m u^2/2 + E_liquid + (F_C - F) x is constant
    t = np.linspace(0.0, 0.07, 7001)
    h = simulate(SOFT, t[-1], applied_force=420.0, cap_pressure=0.0, rod_pressure=0.0, t_eval=t)
    assert h.success, h.message
    x = h.stroke - 0.25
    assert np.max(x) > 100 * P.static_force / P.bristle_stiffness  # slid well beyond presliding
    sliding = (x > 1e-3) & (h.rate > 100 * P.stribeck_velocity)
    assert sliding.sum() > 1000
    assert np.allclose(h.friction[sliding], P.kinetic_force, rtol=1e-6)
    invariant = h.kinetic_energy + h.stored_energy + (P.kinetic_force - 420.0) * x
    kinetic_scale = np.max(h.kinetic_energy)
    assert np.ptp(invariant[sliding]) < 1e-5 * kinetic_scale


def test_chosen_stribeck_velocity_fits_paper_002s_friction_curve():
    # paper 002 (ADAMS-type law): F_S = 385 N at 0.01 mm/s falling by a cubic step to
    # F_C = 340 N at 0.05 mm/s; least squares of g(u) on [0.01, 0.2] mm/s gives
    # v_S = 0.032 mm/s, rounded to the chosen 0.03 mm/s
    def paper(u):
        s = np.clip((u - 1e-5) / (5e-5 - 1e-5), 0.0, 1.0)
        return 385.0 + (340.0 - 385.0) * s * s * (3.0 - 2.0 * s)

    u = np.linspace(1e-5, 2e-4, 4000)
    fit = minimize_scalar(lambda vs: np.mean((stribeck_force(replace(P, stribeck_velocity=vs), u) - paper(u)) ** 2),
                          bounds=(1e-6, 1e-4), method="bounded")
    assert fit.x == pytest.approx(3.2e-5, rel=0.02)
    # with 0.03 mm/s the curve stays within 10 N of the paper's on that range
    assert np.max(np.abs(stribeck_force(P, u) - paper(u))) < 10.0
