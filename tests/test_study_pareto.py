"""The non-dominated filter against the definition applied pair by pair (every objective minimised)."""

from __future__ import annotations

import numpy as np
import pytest

from jointplay.errors import ModelError
from jointplay.study.pareto import non_dominated


def brute_force(y: np.ndarray) -> np.ndarray:
    """Row i is kept when no row j has y_j <= y_i everywhere and y_j < y_i somewhere (and it has no NaN)."""
    n = len(y)
    keep = np.ones(n, dtype=bool)
    for i in range(n):
        if np.any(np.isnan(y[i])):
            keep[i] = False
            continue
        for j in range(n):
            if j != i and not np.any(np.isnan(y[j])) and np.all(y[j] <= y[i]) and np.any(y[j] < y[i]):
                keep[i] = False
                break
    return keep


@pytest.mark.parametrize(("n", "m", "seed"), [(200, 2, 0), (150, 3, 1), (120, 4, 2), (60, 1, 3)])
def test_non_dominated_matches_brute_force_on_random_points(n, m, seed):
    y = np.random.default_rng(seed).normal(size=(n, m))
    np.testing.assert_array_equal(non_dominated(y), brute_force(y))


def test_ties_and_duplicates_follow_the_definition():
    """Coarse integer points: many ties in one objective and repeated rows (both copies stay)."""
    y = np.random.default_rng(4).integers(0, 5, size=(120, 2)).astype(float)
    y = np.vstack([y, y[:10]])
    mask = non_dominated(y)
    np.testing.assert_array_equal(mask, brute_force(y))
    assert mask.sum() >= 2


def test_a_known_front():
    y = np.array([[1.0, 4.0], [2.0, 2.0], [4.0, 1.0], [3.0, 3.0], [2.0, 5.0], [np.nan, 0.0]])
    assert non_dominated(y).tolist() == [True, True, True, False, False, False]


def test_a_bad_shape_is_refused():
    with pytest.raises(ModelError, match=r"pareto: needs an array \(points, objectives\), got shape \(2, 2, 2\)"):
        non_dominated(np.zeros((2, 2, 2)))
