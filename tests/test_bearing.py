"""jointplay.bearing: steady analysis vs Raimondi-Boyd, API values vs the core, errors pinned, charts.

Raimondi and Boyd (1958), "A solution for the finite journal bearing and its
application to analysis and design", ASLE Trans. 1, parts I-III; full
(360 degree) bearing, L/D = 1, Reynolds (Swift-Stieber) conditions, film fed
at the line of largest thickness. Columns S and (R/c) f as reproduced in
https://ww2.mathworks.cn/matlabcentral/answers/707318-design-of-journal-bearing
(S_1, Rfc_1 at h0/c = 0.1 ... 0.9); attitude, Q/(R c N L), Q_s/Q and
P/p_max from the same Raimondi-Boyd table as printed in Shigley's Mechanical
Engineering Design (table "Dimensionless performance parameters for full
journal bearings with side flow"), copied by hand. Raimondi and Boyd solved
by relaxation on a coarse grid and give three significant figures, so
agreement to about 2 % (1 degree in attitude) is what one can ask.
"""

import math

import numpy as np
import pytest

from jointplay import _core, bearing

# eps: S, attitude [deg], (R/c) f, Q/(R c N L), Q_s/Q, P/p_max
RAIMONDI_BOYD_LD1 = {
    0.1: (1.33, 79.5, 26.4, 3.37, 0.150, 0.540),
    0.2: (0.631, 74.02, 12.8, 3.59, 0.280, 0.529),
    0.4: (0.264, 63.10, 5.79, 3.99, 0.497, 0.484),
    0.6: (0.121, 50.58, 3.22, 4.33, 0.680, 0.415),
    0.8: (0.0446, 36.24, 1.70, 4.62, 0.842, 0.313),
    0.9: (0.0188, 26.45, 1.05, 4.74, 0.919, 0.247),
}


@pytest.mark.parametrize("eps", sorted(RAIMONDI_BOYD_LD1))
def test_steady_bearing_matches_raimondi_boyd_for_l_over_d_one(eps):
    s, phi, f, q, qs, pr = RAIMONDI_BOYD_LD1[eps]
    p = bearing.steady(length_over_diameter=1.0, eccentricity_ratio=eps)
    assert p.sommerfeld_number == pytest.approx(s, rel=0.02)
    assert math.degrees(p.attitude_angle) == pytest.approx(phi, abs=1.0)
    assert p.friction_variable == pytest.approx(f, rel=0.02)
    assert p.flow_variable == pytest.approx(q, rel=0.01)
    assert p.side_flow_ratio == pytest.approx(qs, rel=0.02)
    assert p.pressure_ratio == pytest.approx(pr, rel=0.03)
    assert p.min_film_thickness_ratio == pytest.approx(1 - eps)


def test_steady_by_load_inverts_steady_by_eccentricity_and_scales_to_si():
    geo = dict(radius=0.02, clearance=2e-5, viscosity=0.05, speed=30.0)
    by_eps = bearing.steady(1.0, eccentricity_ratio=0.6, **geo)
    by_load = bearing.steady(1.0, load=by_eps.load, **geo)
    assert by_load.eccentricity_ratio == pytest.approx(0.6, rel=1e-6)
    assert by_load.attitude_angle == pytest.approx(by_eps.attitude_angle, rel=1e-6)
    r, c, mu, n = geo["radius"], geo["clearance"], geo["viscosity"], geo["speed"]
    mean = by_eps.load / (2 * r * 2 * r)
    assert by_eps.mean_pressure == pytest.approx(mean)
    assert by_eps.sommerfeld_number == pytest.approx((r / c) ** 2 * mu * n / mean)
    assert by_eps.min_film_thickness == pytest.approx(0.4 * c)
    assert by_eps.peak_pressure == pytest.approx(mean / by_eps.pressure_ratio)
    assert by_eps.power_loss == pytest.approx(by_eps.friction_torque * 2 * math.pi * n)
    assert by_eps.side_flow == pytest.approx(by_eps.flow * by_eps.side_flow_ratio)
    raw = _core.steady_bearing(1.0, eccentricity_ratio=0.6)
    assert raw["sommerfeld_number"] == by_eps.sommerfeld_number


def test_pressure_field_is_the_core_solution_mirrored_over_the_length():
    f = bearing.pressure_field(0.01, 0.02, 1e-5, 0.04, (5e-6, 0.0), journal_spin=100.0, n_circumferential=48, n_axial=8)
    raw = _core.reynolds_solve(0.01, 0.02, 1e-5, 0.04, (5e-6, 0.0), (0.0, 0.0), 100.0, 0.0, n_circumferential=48, n_axial=8)
    assert f.pressure.shape == (48, 9)
    assert np.array_equal(f.pressure[:, 4:], raw["pressure"].reshape(48, 5))
    assert np.array_equal(f.pressure[:, :5], f.pressure[:, :3:-1])
    assert f.z[0] == pytest.approx(-0.01) and f.z[-1] == pytest.approx(0.01)
    assert f.outputs["force_on_journal"] == raw["force_on_journal"]


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(length_over_diameter=-1, eccentricity_ratio=0.5), "length_over_diameter must be a positive finite number, got -1"),
        (dict(length_over_diameter=1, eccentricity_ratio=1.2), "eccentricity_ratio must be in (0, 1), got 1.2"),
        (dict(length_over_diameter=1), "give exactly one of eccentricity_ratio and load"),
        (dict(length_over_diameter=1, load=100.0, radius=0.01), "load requires radius, clearance, viscosity and speed; missing: clearance, viscosity, speed"),
        (dict(length_over_diameter=1, load=100.0, radius=0.01, clearance=0.02, viscosity=0.1, speed=10),
         "clearance must be smaller than radius, got clearance=0.02, radius=0.01"),
        (dict(length_over_diameter=1, eccentricity_ratio=0.5, n_axial=7), "n_axial must be an even integer >= 2, got 7"),
        (dict(length_over_diameter=1, load=1e9, radius=0.01, clearance=1e-5, viscosity=0.01, speed=10),
         "load 1000000000 N is too heavy"),
    ],
)
def test_steady_rejects_bad_input_with_the_argument_named(kwargs, message):
    with pytest.raises(ValueError) as info:
        bearing.steady(**kwargs)
    assert str(info.value).startswith(message)


def test_pressure_field_errors_are_pinned():
    with pytest.raises(ValueError, match=r"^cavitation must be one of \('gumbel', 'swift_stieber', 'elrod_adams'\), got 'jfo'$"):
        bearing.pressure_field(0.01, 0.02, 1e-5, 0.04, (0, 0), cavitation="jfo")
    with pytest.raises(ValueError, match=r"^eccentricity must be shorter than the clearance 1e-05, got \(1e-05, 0\)$"):
        bearing.pressure_field(0.01, 0.02, 1e-5, 0.04, (1e-5, 0))
    with pytest.raises(ValueError, match=r"^the Elrod-Adams model needs a lubricant supply"):
        bearing.pressure_field(0.01, 0.02, 1e-5, 0.04, (5e-6, 0), journal_spin=10.0, cavitation="elrod_adams")


def test_chart_and_field_plots_are_written(tmp_path):
    points = bearing.chart(1.0, tmp_path / "chart.png", n_points=6, n_circumferential=48, n_axial=8)
    assert (tmp_path / "chart.png").stat().st_size > 10_000
    s = [p.sommerfeld_number for p in points]
    assert all(a > b for a, b in zip(s, s[1:]))  # heavier load, larger eps
    bearing.pressure_field(0.01, 0.02, 1e-5, 0.04, (5e-6, 0), journal_spin=100.0, path=tmp_path / "p.png",
                           n_circumferential=48, n_axial=8)
    assert (tmp_path / "p.png").stat().st_size > 5_000
