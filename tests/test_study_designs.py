"""Designs of experiments checked against their definitions (docs/theory/designs-of-experiments.md):
the product set of a full factorial, one point per stratum of a Latin hypercube, the van der Corput
construction and the balance of a Sobol' sequence, the corners, axial points and centres of a central
composite design, the edge midpoints of a Box-Behnken design, the A/AB_i/B blocks of Saltelli's sample,
and clear errors for bad input."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from jointplay.errors import ModelError
from jointplay.study import designs


def rows(array) -> set[tuple[float, ...]]:
    return {tuple(float(v) for v in r) for r in np.round(array, 12)}


# --- coded units ------------------------------------------------------------------------------------

def test_code_and_uncode_map_the_range_ends_to_minus_and_plus_one():
    assert designs.code(10e-6, 10e-6, 30e-6) == -1.0
    assert designs.code(30e-6, 10e-6, 30e-6) == 1.0
    assert designs.code(20e-6, 10e-6, 30e-6) == pytest.approx(0.0, abs=1e-15)
    values = np.array([12e-6, 17.5e-6, 29e-6])
    np.testing.assert_allclose(designs.uncode(designs.code(values, 10e-6, 30e-6), 10e-6, 30e-6), values, rtol=1e-15)
    assert designs.uncode(0.5, 100.0, 300.0) == pytest.approx(250.0)


def test_code_refuses_an_empty_range():
    with pytest.raises(ModelError, match=r"study.design.range: must be finite with low != high.*low=2.0"):
        designs.code(1.0, 2.0, 2.0)


# --- full factorial ------------------------------------------------------------------------------------

def test_full_factorial_enumerates_the_product_of_equally_spaced_levels():
    design = designs.full_factorial([2, 3, 1])
    expected = set(itertools.product([-1.0, 1.0], [-1.0, 0.0, 1.0], [0.0]))
    assert design.shape == (6, 3) and design.dtype == np.float64
    assert rows(design) == expected
    five = designs.full_factorial([5])
    np.testing.assert_allclose(five[:, 0], [-1.0, -0.5, 0.0, 0.5, 1.0], atol=1e-15)


def test_full_factorial_refuses_a_level_count_below_one():
    with pytest.raises(ModelError, match=r"study.design.levels: must be a whole number >= 1, got 0"):
        designs.full_factorial([3, 0])


# --- Latin hypercube -------------------------------------------------------------------------------------

@pytest.mark.parametrize("optimization", [None, "random-cd"])
def test_latin_hypercube_puts_exactly_one_point_in_each_stratum_of_each_axis(optimization):
    n, k = 17, 4
    design = designs.latin_hypercube(n, k, seed=3, optimization=optimization)
    assert design.shape == (n, k)
    assert np.all(design >= -1.0) and np.all(design <= 1.0)
    strata = np.floor((design + 1.0) / 2.0 * n).astype(int)
    for j in range(k):
        assert sorted(strata[:, j]) == list(range(n))


def test_latin_hypercube_is_deterministic_given_its_seed():
    np.testing.assert_array_equal(designs.latin_hypercube(8, 2, seed=5), designs.latin_hypercube(8, 2, seed=5))
    assert not np.array_equal(designs.latin_hypercube(8, 2, seed=5), designs.latin_hypercube(8, 2, seed=6))


def test_latin_hypercube_refuses_an_optimisation_that_breaks_the_strata():
    with pytest.raises(ModelError, match=r"study.design.optimization: must be one of .*random-cd, got 'lloyd'"):
        designs.latin_hypercube(8, 2, seed=0, optimization="lloyd")


# --- Sobol' --------------------------------------------------------------------------------------------

def van_der_corput(i: int) -> float:
    """The radical inverse of i in base 2: the first coordinate of the Sobol' sequence (Sobol' 1967)."""
    value, weight = 0.0, 0.5
    while i:
        value += weight * (i & 1)
        i >>= 1
        weight /= 2
    return value


def test_unscrambled_sobol_starts_with_the_van_der_corput_sequence():
    design = designs.sobol(16, 3, seed=0, scramble=False)
    expected_gray_order = {van_der_corput(i) for i in range(16)}  # the same 16 points, in Gray-code order
    first = (design[:, 0] + 1.0) / 2.0
    assert set(np.round(first, 15)) == {round(v, 15) for v in expected_gray_order}
    assert first[0] == 0.0 and first[1] == 0.5
    # the first four points of the first two axes, in Gray-code order (Joe and Kuo 2008 direction numbers)
    np.testing.assert_array_equal((design[:4, :2] + 1.0) / 2.0, [[0.0, 0.0], [0.5, 0.5], [0.75, 0.25], [0.25, 0.75]])


@pytest.mark.parametrize("scramble", [False, True])
def test_sobol_fills_every_half_and_quarter_of_each_axis_equally(scramble):
    n, k = 32, 3
    design = designs.sobol(n, k, seed=11, scramble=scramble)
    assert design.shape == (n, k) and np.all(np.abs(design) <= 1.0)
    for parts in (2, 4):
        cells = np.floor((design + 1.0) / 2.0 * parts).astype(int)
        for j in range(k):
            assert np.bincount(cells[:, j], minlength=parts).tolist() == [n // parts] * parts


def test_sobol_refuses_a_count_that_is_not_a_power_of_two():
    with pytest.raises(ModelError, match=r"study.design.samples: a sobol design needs a power of 2 .* got 100; "
                                         r"use 64 or 128"):
        designs.sobol(100, 2, seed=0)


# --- central composite -------------------------------------------------------------------------------------

def split_ccd(design: np.ndarray, corner: float, alpha: float):
    """Rows that are corners (every coordinate +-corner), axial (one coordinate +-alpha) and centres."""
    k = design.shape[1]
    nonzero = np.count_nonzero(np.abs(design) > 1e-12, axis=1)
    corners = design[np.all(np.isclose(np.abs(design), corner, rtol=0, atol=1e-12), axis=1)]
    axial = design[(nonzero == 1) & np.isclose(np.abs(design).max(axis=1), alpha, rtol=0, atol=1e-12)]
    centres = design[nonzero == 0]
    assert len(corners) + len(axial) + len(centres) == len(design)
    assert rows(corners) == rows(list(itertools.product([-corner, corner], repeat=k)))
    assert rows(axial) == rows([s * alpha * e for e in np.eye(k) for s in (-1.0, 1.0)])
    return len(corners), len(axial), len(centres)


@pytest.mark.parametrize("k", [2, 3, 4])
def test_circumscribed_ccd_has_corners_and_rotatable_axial_points(k):
    alpha = (2.0**k) ** 0.25  # rotatable: Box and Hunter 1957
    counts = split_ccd(designs.central_composite(k, face="circumscribed", center=(2, 1)), 1.0, alpha)
    assert counts == (2**k, 2 * k, 3)


def test_faced_ccd_puts_axial_points_on_the_faces():
    assert split_ccd(designs.central_composite(3, face="faced", center=(1, 0)), 1.0, 1.0) == (8, 6, 1)


def test_inscribed_ccd_stays_in_the_cube():
    alpha = 2.0**0.75  # (2^3)^(1/4)
    assert split_ccd(designs.central_composite(3, face="inscribed", center=(0, 0)), 1.0 / alpha, 1.0) == (8, 6, 0)


def test_ccd_errors_name_the_option():
    with pytest.raises(ModelError, match=r"study.design.face: must be one of faced, circumscribed, inscribed, "
                                         r"got 'ccc'"):
        designs.central_composite(2, face="ccc")
    with pytest.raises(ModelError, match=r"study.design.center: must be two whole numbers"):
        designs.central_composite(2, center=3)
    with pytest.raises(ModelError, match=r"study.design.kind: a central_composite design needs at least 2 factors"):
        designs.central_composite(1)


# --- Box-Behnken -----------------------------------------------------------------------------------------

@pytest.mark.parametrize(("k", "edges"), [(3, 12), (4, 24)])  # Box and Behnken (1960), tables 3 and 4
def test_box_behnken_points_are_edge_midpoints_and_centres(k, edges):
    design = designs.box_behnken(k, center=2)
    nonzero = np.count_nonzero(design, axis=1)
    edge_points = design[nonzero == 2]
    assert len(edge_points) == edges and np.count_nonzero(nonzero == 0) == 2
    assert len(design) == edges + 2
    assert np.all(np.abs(edge_points[edge_points != 0]) == 1.0)
    expected = set()
    for i, j in itertools.combinations(range(k), 2):
        for si, sj in itertools.product((-1.0, 1.0), repeat=2):
            point = np.zeros(k)
            point[i], point[j] = si, sj
            expected.add(tuple(point))
    assert rows(edge_points) == rows(list(expected))


def test_box_behnken_needs_three_factors():
    with pytest.raises(ModelError, match=r"study.design.kind: a box_behnken design needs at least 3 factors, got 2"):
        designs.box_behnken(2)


# --- Saltelli and explicit -----------------------------------------------------------------------------------

def test_saltelli_blocks_are_a_ab_i_b():
    n, k = 8, 3
    design = designs.saltelli(n, k, seed=2)
    assert design.shape == (n * (k + 2), k) and np.all(np.abs(design) <= 1.0)
    blocks = design.reshape(n, k + 2, k)
    a, b = blocks[:, 0], blocks[:, -1]
    for i in range(k):
        expected = a.copy()
        expected[:, i] = b[:, i]
        np.testing.assert_array_equal(blocks[:, 1 + i], expected)
    assert len(rows(np.vstack([a, b]))) == 2 * n


def test_explicit_checks_the_table():
    np.testing.assert_array_equal(designs.explicit([[0, 1], [-1, 0.5]], k=2), [[0.0, 1.0], [-1.0, 0.5]])
    with pytest.raises(ModelError, match=r"study.design.rows: must have one column per factor \(3\), got 2"):
        designs.explicit([[0, 1]], k=3)
    with pytest.raises(ModelError, match=r"study.design.rows\[1\]: must hold finite numbers"):
        designs.explicit([[0, 1], [np.nan, 0]])


# --- registry ------------------------------------------------------------------------------------------------

def test_make_design_dispatches_by_kind():
    np.testing.assert_array_equal(designs.make_design("full_factorial", 2, levels=3), designs.full_factorial([3, 3]))
    np.testing.assert_array_equal(designs.make_design("sobol", 2, samples=8, seed=4), designs.sobol(8, 2, seed=4))
    assert designs.make_design("box_behnken", 3, center=0).shape == (12, 3)
    assert set(designs.DESIGNS) == set(designs.OPTIONS)


def test_make_design_errors_name_the_kind_and_the_option():
    with pytest.raises(ModelError, match=r"study.design.kind: must be one of full_factorial, .* got 'taguchi'"):
        designs.make_design("taguchi", 3)
    with pytest.raises(ModelError, match=r"study.design.face: is not an option of a sobol design "
                                         r"\(options: samples, seed, scramble\)"):
        designs.make_design("sobol", 2, samples=8, face="faced")
    with pytest.raises(ModelError, match=r"study.design.samples: missing"):
        designs.make_design("latin_hypercube", 2)
    with pytest.raises(ModelError, match=r"study.design.levels: must give one count per factor \(3\), got \[2, 2\]"):
        designs.make_design("full_factorial", 3, levels=[2, 2])
