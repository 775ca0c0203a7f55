"""Validation of the finite-difference Reynolds solver against closed forms.

Frame and conventions: crates/jointplay-core/src/lubrication/film.rs. The
journal is displaced along +x (h = c (1 - eps cos theta)); pressures are
compared through the force on the journal, F = -integral p u R dtheta dz.
References:
- Ocvirk short bearing and Sommerfeld / half-Sommerfeld long bearing:
  DESIGN.md section 4; Hamrock, Schmid and Jacobson, Fundamentals of Fluid Film
  Lubrication (2004), ch. 10 (long) and ch. 11 (short);
- short-bearing pressure with squeeze: p = (L^2/4 - z^2) g(theta),
  g = -(6 mu W dh/dtheta + 12 mu dh/dt) / (2 h^3), integrated here by
  quadrature over the region where g > 0 (Gümbel) or everywhere (full film);
- short-bearing pure squeeze, full film: F = pi mu R L^3 eps_dot (1 + 2 eps^2) / (c^2 (1 - eps^2)^(5/2))
  (integral of cos^2 / (1 - eps cos)^3 over a turn = pi (1 + 2 eps^2) / (1 - eps^2)^(5/2));
- long-bearing pure squeeze, full film: F / L = 12 pi mu R^3 eps_dot / (c^2 (1 - eps^2)^(3/2)).
Full films are obtained by raising the ambient pressure far above the
hydrodynamic pressures (the equation is linear, so p - p_a is the full-film solution).
"""

import math

import numpy as np
import pytest

from jointplay import bearing

R, C, MU = 0.01, 1e-5, 0.04
HIGH = 1e12  # ambient pressure that keeps the film full [Pa]


def solve(lod, eps, spin=0.0, eps_rate=0.0, whirl_rate=0.0, cavitation="gumbel", ambient=0.0, grid=(144, 32), **kw):
    return bearing.pressure_field(
        R, 2 * R * lod, C, MU, (eps * C, 0.0), eccentricity_rate=(eps_rate * C, whirl_rate * C),
        journal_spin=spin, cavitation=cavitation, ambient_pressure=ambient,
        n_circumferential=grid[0], n_axial=grid[1], **kw)


def short_force(lod, eps, spin, eps_rate, half):
    """Short-bearing force (x, y) by quadrature of g(theta) (positive part if half)."""
    length = 2 * R * lod
    theta = np.linspace(0, 2 * math.pi, 200001)
    h = C * (1 - eps * np.cos(theta))
    dh = C * eps * np.sin(theta)
    hdot = -C * eps_rate * np.cos(theta)
    g = -(6 * MU * spin * dh + 12 * MU * hdot) / (2 * h**3)
    if half:
        g = np.maximum(g, 0.0)
    k = -R * length**3 / 6
    return np.array([k * np.trapezoid(g * np.cos(theta), theta), k * np.trapezoid(g * np.sin(theta), theta)])


def long_pressure(eps, spin, eps_rate, theta):
    """Long-bearing full-film pressure at `theta` from the 1-D equation, with integral h^3 p = 0."""
    t = np.linspace(0, 2 * math.pi, 400001)
    h = C * (1 - eps * np.cos(t))
    src = R**2 * (6 * MU * spin * C * eps * np.sin(t) - 12 * MU * C * eps_rate * np.cos(t))
    cum = lambda f: np.concatenate([[0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(t))])
    i = cum(src)
    c1 = -np.trapezoid(i / h**3, t) / np.trapezoid(1 / h**3, t)
    p = cum((i + c1) / h**3)
    p -= np.trapezoid(h**3 * p, t) / np.trapezoid(h**3, t)
    return np.interp(theta, t, p)


def midplane_force_per_length(field, ambient=0.0):
    mid = field.pressure[:, field.z.size // 2] - ambient
    dtheta = 2 * math.pi / field.theta.size
    return -R * dtheta * np.array([np.sum(mid * np.cos(field.theta)), np.sum(mid * np.sin(field.theta))])


def test_reynolds_matches_ocvirk_at_small_l_over_d_and_spins_add():
    # Ocvirk (half-Sommerfeld film) with omega = omega_j + omega_b: no factor 2
    eps, w, lod = 0.6, 100.0, 1 / 16
    length = 2 * R * lod
    fr = MU * w * R * length**3 * eps**2 / (C**2 * (1 - eps**2) ** 2)
    ft = math.pi * MU * w * R * length**3 * eps / (4 * C**2 * (1 - eps**2) ** 1.5)
    for split in (1.0, 0.0, 0.3):
        f = bearing.pressure_field(R, length, C, MU, (eps * C, 0), journal_spin=split * w, bearing_spin=(1 - split) * w,
                                   cavitation="gumbel", n_circumferential=144, n_axial=32)
        fx, fy = f.outputs["force_on_journal"]
        assert fx == pytest.approx(-fr, rel=0.015)  # radial: back towards the centre
        assert fy == pytest.approx(ft, rel=0.01)  # tangential: along the rotation
        assert f.outputs["attitude_angle"] == pytest.approx(math.atan2(ft, fr), abs=0.01)


def test_reynolds_matches_sommerfeld_full_and_half_at_the_midplane_of_a_long_bearing():
    eps, w = 0.5, 100.0
    full = solve(8.0, eps, spin=w, ambient=HIGH, grid=(240, 64))
    theta = full.theta
    ref = long_pressure(eps, w, 0.0, theta)
    closed = 6 * MU * w * R**2 / C**2 * eps * (-np.sin(theta)) * (2 - eps * np.cos(theta)) / ((2 + eps**2) * (1 - eps * np.cos(theta)) ** 2)
    assert np.max(np.abs(ref - closed)) < 1e-6 * np.max(closed)  # the 1-D reference is Sommerfeld's solution
    mid = full.pressure[:, full.z.size // 2] - HIGH
    assert np.max(np.abs(mid - closed)) < 0.01 * np.max(closed)
    w_sommerfeld = 12 * math.pi * MU * w * R**3 * eps / (C**2 * (2 + eps**2) * math.sqrt(1 - eps**2))
    fx, fy = midplane_force_per_length(full, HIGH)
    assert fy == pytest.approx(w_sommerfeld, rel=0.005) and abs(fx) < 0.005 * fy  # attitude 90 degrees
    half = solve(8.0, eps, spin=w, grid=(240, 64))
    fx, fy = midplane_force_per_length(half)
    fr = 12 * MU * w * R**3 * eps**2 / (C**2 * (2 + eps**2) * (1 - eps**2))
    ft = 6 * math.pi * MU * w * R**3 * eps / (C**2 * (2 + eps**2) * math.sqrt(1 - eps**2))
    assert fx == pytest.approx(-fr, rel=0.01)
    assert fy == pytest.approx(ft, rel=0.01)


@pytest.mark.parametrize("eps", [0.3, 0.7])
def test_short_bearing_pure_squeeze_full_and_half_film(eps):
    lod, rate = 1 / 16, 50.0  # eps_dot [1/s], journal approaching the thin side
    length = 2 * R * lod
    closed = math.pi * MU * R * length**3 * rate * (1 + 2 * eps**2) / (C**2 * (1 - eps**2) ** 2.5)
    assert short_force(lod, eps, 0.0, rate, half=False)[0] == pytest.approx(-closed, rel=1e-6)
    full = solve(lod, eps, eps_rate=rate, ambient=HIGH)
    assert full.outputs["force_on_journal"][0] == pytest.approx(-closed, rel=0.01)
    assert abs(full.outputs["force_on_journal"][1]) < 1e-6 * closed
    for cav in ("gumbel", "swift_stieber"):
        half = solve(lod, eps, eps_rate=rate, cavitation=cav)
        ref = short_force(lod, eps, 0.0, rate, half=True)
        assert half.outputs["force_on_journal"][0] == pytest.approx(ref[0], rel=0.015)
        # pressure only where the film is being squeezed (cos theta > 0 here)
        squeezing = np.cos(half.theta) > 0.05
        assert np.all(half.pressure[~squeezing & (np.cos(half.theta) < -0.05)] == 0.0)
        assert np.all(half.pressure[squeezing, half.z.size // 2] > 0.0)


def test_long_bearing_pure_squeeze_full_film():
    eps, rate = 0.5, 50.0
    per_length = 12 * math.pi * MU * R**3 * rate / (C**2 * (1 - eps**2) ** 1.5)
    theta = np.linspace(0, 2 * math.pi, 2001)
    p = long_pressure(eps, 0.0, rate, theta)
    assert -R * np.trapezoid(p * np.cos(theta), theta) == pytest.approx(-per_length, rel=1e-5)
    full = solve(8.0, eps, eps_rate=rate, ambient=HIGH, grid=(240, 64))
    fx, fy = midplane_force_per_length(full, HIGH)
    assert fx == pytest.approx(-per_length, rel=0.005) and abs(fy) < 1e-3 * per_length


@pytest.mark.parametrize("ratio", [-2.0, -0.5, 0.5, 2.0])
def test_gumbel_region_moves_with_the_squeeze_to_wedge_ratio(ratio):
    # eps_dot = ratio * eps * omega / 2: the positive region is where g > 0, not [0, pi]
    lod, eps, w = 1 / 16, 0.5, 100.0
    rate = ratio * eps * w / 2
    ref = short_force(lod, eps, w, rate, half=True)
    f = np.array(solve(lod, eps, spin=w, eps_rate=rate).outputs["force_on_journal"])
    assert np.linalg.norm(f - ref) < 0.015 * np.linalg.norm(ref)
    wedge_only = short_force(lod, eps, w, 0.0, half=True)
    assert np.linalg.norm(ref - wedge_only) > 0.1 * np.linalg.norm(wedge_only)  # the region really moved


def test_elrod_adams_conserves_mass_and_lies_below_the_reynolds_force():
    kw = dict(spin=100.0, supply_pressure=2e5, grid=(120, 32))
    ea = solve(1.0, 0.6, cavitation="elrod_adams", **kw).outputs
    ss = solve(1.0, 0.6, cavitation="swift_stieber", **kw).outputs
    gu = solve(1.0, 0.6, cavitation="gumbel", **kw).outputs
    assert ea["groove_inflow"] == pytest.approx(ea["side_leakage"], rel=1e-5)
    f = {k: math.hypot(*v["force_on_journal"]) for k, v in (("ea", ea), ("ss", ss), ("gu", gu))}
    # a mid-length groove feeds the rupture zone only partly: the JFO film carries less than the Reynolds film
    assert f["ea"] < f["ss"] and f["ea"] > 0.5 * f["ss"]
    assert f["gu"] < f["ss"]


def test_swift_stieber_keeps_pressure_nonnegative_and_complementary():
    f = solve(1.0, 0.8, spin=80.0, eps_rate=20.0, whirl_rate=-30.0, cavitation="swift_stieber", grid=(120, 16))
    assert f.pressure.min() >= 0.0
    assert f.outputs["complementarity_residual"] < 1e-5


def test_groove_supply_alone_gives_linear_axial_profile_and_no_force():
    ps = 3e5
    for eps in (0.0, 0.5):
        f = solve(1.0, eps, supply_pressure=ps, cavitation="swift_stieber", grid=(72, 16))
        mid = f.z.size // 2
        assert np.allclose(f.pressure[:, mid], ps)
        assert np.allclose(f.pressure[:, 0], 0.0) and np.allclose(f.pressure[:, -1], 0.0)
        expected = ps * (1 - np.abs(f.z) / (R))  # L/2 = R for L/D = 1
        assert np.allclose(f.pressure, expected[None, :], rtol=1e-5, atol=1e-3 * ps)
        assert np.hypot(*f.outputs["force_on_journal"]) < 1e-6 * ps * R * R
