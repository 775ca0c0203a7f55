"""Non-dominated (Pareto) filter of points scored by several objectives, all minimised.

Point a dominates point b when a is no worse in every objective and better in at least one:
all(a <= b) and any(a < b). The non-dominated points are those no other point dominates (Deb,
*Multi-Objective Optimization Using Evolutionary Algorithms*, Wiley 2001, ch. 2). Dominance is
transitive, so each point still standing removes every point it dominates and the survivors are the
front: O(n f) comparisons of m objectives for a front of f points.
"""

from __future__ import annotations

import numpy as np

from ..errors import ModelError, Problem


def non_dominated(objectives) -> np.ndarray:
    """Boolean mask (n,) of the non-dominated rows of ``objectives`` (n, m), every column minimised
    (negate a column to maximise it). Rows with a NaN are never on the front; equal rows all stay."""
    y = np.asarray(objectives, dtype=float)
    y = y[:, None] if y.ndim == 1 else y
    if y.ndim != 2:
        raise ModelError([Problem("pareto", f"needs an array (points, objectives), got shape {np.shape(objectives)}")])
    mask = ~np.any(np.isnan(y), axis=1)
    for i in np.flatnonzero(mask):
        if mask[i]:
            dominated = np.all(y[i] <= y, axis=1) & np.any(y[i] < y, axis=1)
            mask &= ~dominated
    return mask
