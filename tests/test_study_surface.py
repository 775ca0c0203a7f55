"""The quadratic response surface: a known quadratic recovered exactly, coefficients under noise within
the least-squares standard error, the closed-form leave-one-out PRESS equal to refitting n times, R^2 and
adjusted R^2 against their formulas, and clear errors (docs/theory/response-surface.md)."""

from __future__ import annotations

import numpy as np
import pytest

from jointplay.errors import ModelError
from jointplay.study import designs
from jointplay.study.surface import fit_quadratic, fit_response

NAMES = ["a", "b", "c"]
#: y = 2 + a - 3 b + 0.5 c + 0.7 a b - 0.2 a c + 1.1 b c + 0.4 a^2 - 0.9 b^2 + 0.3 c^2, by term name.
TRUE = {"1": 2.0, "a": 1.0, "b": -3.0, "c": 0.5, "a*b": 0.7, "a*c": -0.2, "b*c": 1.1,
        "a^2": 0.4, "b^2": -0.9, "c^2": 0.3}


def true_quadratic(x: np.ndarray) -> np.ndarray:
    a, b, c = x.T
    return (2.0 + a - 3.0 * b + 0.5 * c + 0.7 * a * b - 0.2 * a * c + 1.1 * b * c
            + 0.4 * a**2 - 0.9 * b**2 + 0.3 * c**2)


def full_quadratic_matrix(x: np.ndarray) -> np.ndarray:
    """Columns 1, a, b, c, ab, ac, bc, a^2, b^2, c^2, written out here."""
    a, b, c = x.T
    return np.column_stack([np.ones(len(x)), a, b, c, a * b, a * c, b * c, a**2, b**2, c**2])


def test_a_noise_free_quadratic_is_recovered_exactly():
    x = designs.central_composite(3, face="faced", center=(1, 0))
    surface = fit_quadratic(x, true_quadratic(x), NAMES)
    assert surface.term_names == ["1", "a", "b", "c", "a*b", "a*c", "b*c", "a^2", "b^2", "c^2"]
    for name, coefficient in zip(surface.term_names, surface.coefficients, strict=True):
        assert coefficient == pytest.approx(TRUE[name], abs=1e-10)
    assert surface.r2 == pytest.approx(1.0, abs=1e-12) and surface.n_cases == 15 and surface.n_terms == 10
    probe = designs.latin_hypercube(20, 3, seed=1)
    np.testing.assert_allclose(surface.predict(probe), true_quadratic(probe), atol=1e-10)
    assert surface.verdict == "trustworthy"


def test_the_gradient_is_the_derivative_of_the_quadratic():
    x = designs.box_behnken(3, center=1)
    surface = fit_quadratic(x, true_quadratic(x), NAMES)
    p = np.array([[0.3, -0.6, 0.8]])
    a, b, c = p[0]
    exact = [1.0 + 0.7 * b - 0.2 * c + 0.8 * a, -3.0 + 0.7 * a + 1.1 * c - 1.8 * b, 0.5 - 0.2 * a + 1.1 * b + 0.6 * c]
    np.testing.assert_allclose(surface.gradient(p)[0], exact, atol=1e-10)


def test_coefficients_under_noise_lie_within_four_standard_errors():
    """Noise of known sigma: each coefficient's least-squares standard error is sigma sqrt((X^T X)^-1_tt)."""
    sigma = 0.05
    x = designs.full_factorial([5, 5, 5])
    y = true_quadratic(x) + np.random.default_rng(7).normal(0.0, sigma, len(x))
    surface = fit_quadratic(x, y, NAMES)
    matrix = full_quadratic_matrix(x)
    standard_error = sigma * np.sqrt(np.diag(np.linalg.inv(matrix.T @ matrix)))
    truth = np.array([TRUE[n] for n in surface.term_names])
    assert np.all(np.abs(surface.coefficients - truth) < 4.0 * standard_error)
    assert 0.99 < surface.r2 < 1.0
    assert surface.rmse == pytest.approx(sigma, rel=0.25)  # sqrt(SS_res / n) -> sigma sqrt((n - p) / n)


def test_r2_and_adjusted_r2_follow_their_formulas():
    x = designs.latin_hypercube(30, 3, seed=4)
    y = true_quadratic(x) + np.sin(4.0 * x[:, 0])  # not quadratic: R^2 < 1
    surface = fit_quadratic(x, y, NAMES)
    residuals = y - surface.predict(x)
    ss_res, ss_tot = np.sum(residuals**2), np.sum((y - y.mean()) ** 2)
    n, p = 30, 10
    assert surface.r2 == pytest.approx(1.0 - ss_res / ss_tot, rel=1e-12)
    assert surface.r2_adjusted == pytest.approx(1.0 - (1.0 - surface.r2) * (n - 1) / (n - p), rel=1e-12)
    assert surface.rmse == pytest.approx(np.sqrt(ss_res / n), rel=1e-12)


def test_closed_form_press_equals_refitting_without_each_case():
    x = designs.latin_hypercube(25, 3, seed=9)
    y = true_quadratic(x) + np.cos(3.0 * x[:, 1] * x[:, 2])
    surface = fit_quadratic(x, y, NAMES)
    matrix = full_quadratic_matrix(x)
    brute = 0.0
    for i in range(len(x)):  # refit without case i by numpy's own least squares, predict case i
        keep = np.arange(len(x)) != i
        coefficients = np.linalg.lstsq(matrix[keep], y[keep], rcond=None)[0]
        brute += (y[i] - matrix[i] @ coefficients) ** 2
    assert surface.press == pytest.approx(brute, rel=1e-9)
    assert surface.q2 == pytest.approx(1.0 - brute / np.sum((y - y.mean()) ** 2), rel=1e-9)
    assert surface.rmse_cv == pytest.approx(np.sqrt(brute / len(x)), rel=1e-9)


def test_a_surface_that_misses_the_response_is_judged_poor():
    x = designs.latin_hypercube(24, 2, seed=2)
    y = np.sin(6.0 * x[:, 0]) * np.cos(5.0 * x[:, 1])
    surface = fit_quadratic(x, y, ["a", "b"])
    assert surface.verdict == "poor"
    assert surface.verdict_text().startswith(f"poor: Q^2 = {surface.q2:.3g} < 0.5")
    quality = surface.quality()
    assert quality["verdict"] == "poor" and quality["cases"] == 24 and quality["terms"] == 6


def test_failed_cases_are_left_out_and_counted():
    x = designs.full_factorial([3, 3, 3])
    y = true_quadratic(x)
    y[[2, 11]] = np.nan
    surface = fit_quadratic(x, y, NAMES)
    assert surface.n_cases == 25 and surface.n_failed == 2
    assert surface.coefficients[0] == pytest.approx(2.0, abs=1e-10)


def test_a_factor_with_two_levels_loses_its_square_term():
    x = designs.full_factorial([3, 2])
    surface = fit_quadratic(x, 1.0 + x[:, 0] ** 2 - 2.0 * x[:, 1], ["a", "b"])
    assert surface.term_names == ["1", "a", "b", "a*b", "a^2"] and surface.omitted_terms == ("b^2",)
    assert "b^2 left out (two levels only)" in surface.verdict_text()


def test_a_linear_surface_with_and_without_interactions():
    x = designs.full_factorial([2, 2, 2])
    y = 1.0 + 2.0 * x[:, 0] - x[:, 2] + 0.5 * x[:, 0] * x[:, 1]
    linear = fit_quadratic(x, y, NAMES, degree=1)
    assert linear.term_names == ["1", "a", "b", "c"] and linear.r2 < 1.0
    with_interactions = fit_quadratic(x, y, NAMES, degree=1, interactions=True)
    assert with_interactions.term_names == ["1", "a", "b", "c", "a*b", "a*c", "b*c"]
    assert with_interactions.r2 == pytest.approx(1.0, abs=1e-12)


def test_too_few_cases_are_refused_with_the_counts():
    x = designs.full_factorial([3, 3])[[0, 2, 4, 6, 8]]  # corners and centre: three levels per factor
    with pytest.raises(ModelError, match=r"surface: 5 distinct finished cases cannot fit the 6 terms of a "
                                         r"degree-2 surface in 2 factors; use degree=1 \(3 terms\) or a larger design"):
        fit_quadratic(x, x[:, 0], ["a", "b"])


def test_failed_cases_count_in_the_too_few_message():
    x = designs.full_factorial([3, 3])
    y = x[:, 0].copy()
    y[[1, 3, 5, 7]] = np.nan  # the edge midpoints failed: corners and centre remain
    with pytest.raises(ModelError, match=r"5 distinct finished cases \(4 failed\) cannot fit the 6 terms"):
        fit_quadratic(x, y, ["a", "b"])


def test_a_factor_never_varied_is_named():
    x = np.column_stack([designs.full_factorial([3, 3]), np.full(9, 0.5)])
    with pytest.raises(ModelError, match=r"surface: factor c \(always 0.5\) never varies among the finished cases"):
        fit_quadratic(x, x[:, 0], NAMES, degree=1)


def test_an_aliased_term_is_named():
    x = designs.latin_hypercube(12, 2, seed=0)
    x = np.column_stack([x, -x[:, 0]])  # c = -a: the design cannot tell them apart
    with pytest.raises(ModelError, match=r"surface: the design cannot tell term c from the terms before it"):
        fit_quadratic(x, x[:, 1], NAMES, degree=1)


def test_a_surface_fitted_from_a_study_dataset_carries_the_response_and_its_units():
    import xarray as xr

    x = designs.full_factorial([3, 3])
    ds = xr.Dataset({"coded": (("case", "factor"), x), "peak_force": ("case", 5.0 + x[:, 0] ** 2, {"units": "N"})},
                    coords={"case": np.arange(9), "factor": ["a", "b"]})
    surface = fit_response(ds, "peak_force")
    assert surface.response == "peak_force" and surface.units == "N" and surface.factor_names == ("a", "b")
    with pytest.raises(ModelError, match=r"surface.response: must name a response of the study, got 'force'"):
        fit_response(ds, "force")
