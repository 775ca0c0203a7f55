"""Sobol' sensitivity indices of a study's response: first-order S_i and total S_Ti (SALib).

With the factors independent and uniform over their coded ranges, the variance of the response splits
into parts due to each factor and to their interactions (Sobol' 1993). S_i = V[E(Y | x_i)] / V(Y) is the
share of factor i alone; S_Ti = E[V(Y | x_~i)] / V(Y) its share with every interaction it takes part in
(Saltelli et al., *Global Sensitivity Analysis: The Primer*, Wiley 2008). Both are estimated by
``SALib.analyze.sobol`` on Saltelli's sample (:func:`jointplay.study.designs.saltelli`):

- directly on the study's cases ("design") when its design IS such a sample and every case finished;
- otherwise on the response surface fitted to the cases ("surface"), evaluated on a Saltelli sample of
  the coded box: cheap, but only as good as the surface (its verdict is carried along).

``docs/theory/response-surface.md``, "Sobol' indices".
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ModelError, Problem
from . import designs
from .surface import QuadraticSurface, fit_response

#: Base samples of the Saltelli sample a surface is evaluated on: n (k + 2) cheap evaluations.
SURFACE_SAMPLES = 2**13
#: Bootstrap resamples of SALib's confidence intervals.
RESAMPLES = 200


@dataclass(frozen=True)
class SobolIndices:
    """First-order and total Sobol' indices per factor (unitless), with SALib's 95 % bootstrap
    half-widths; ``source`` is "design" or "surface", ``n_base`` the base samples N of the estimate."""

    factor_names: tuple[str, ...]
    first_order: np.ndarray
    total: np.ndarray
    first_order_conf: np.ndarray
    total_conf: np.ndarray
    source: str
    n_base: int
    note: str = ""

    def as_dict(self) -> dict[str, dict[str, float]]:
        """{factor: {"S1", "S1_conf", "ST", "ST_conf"}}."""
        return {name: {"S1": float(self.first_order[j]), "S1_conf": float(self.first_order_conf[j]),
                       "ST": float(self.total[j]), "ST_conf": float(self.total_conf[j])}
                for j, name in enumerate(self.factor_names)}


def saltelli_base_samples(coded) -> int | None:
    """N when ``coded`` is Saltelli's sample (blocks of k + 2 rows A, AB_1 .. AB_k, B, AB_i equal to A
    but in column i, which holds B's; A and B not all equal), else None."""
    x = np.asarray(coded, dtype=float)
    if x.ndim != 2:
        return None
    k = x.shape[1]
    if x.shape[0] == 0 or x.shape[0] % (k + 2):
        return None
    blocks = x.reshape(-1, k + 2, k)
    a, b = blocks[:, 0, :], blocks[:, -1, :]
    if np.array_equal(a, b):
        return None
    for i in range(k):
        expected = a.copy()
        expected[:, i] = b[:, i]
        if not np.array_equal(blocks[:, 1 + i, :], expected):
            return None
    return blocks.shape[0]


def indices_of_sample(coded, response, factor_names, source: str = "design", seed: int = 0,
                      note: str = "") -> SobolIndices:
    """Sobol' indices from responses at Saltelli's sample ``coded`` (its rows in SALib's order)."""
    from SALib.analyze import sobol as salib_sobol

    y = np.asarray(response, dtype=float)
    n_base = saltelli_base_samples(coded)
    names = tuple(str(n) for n in factor_names)
    if n_base is None or len(names) != np.shape(coded)[1] or y.shape != (np.shape(coded)[0],):
        raise ModelError([Problem("sensitivity", "needs Saltelli's sample (designs.saltelli), one name per factor "
                                                 "and one response per case")])
    if not np.all(np.isfinite(y)):
        raise ModelError([Problem("sensitivity", f"{int(np.count_nonzero(~np.isfinite(y)))} cases have no "
                                                 "response (failed): the estimator needs every case")])
    problem = {"num_vars": len(names), "names": list(names), "bounds": [[-1.0, 1.0]] * len(names)}
    # (SALib seeds its bootstrap only when `seed` is true, `if seed:`: a seed of 0 would leave the confidence
    # intervals to numpy's global generator and change them from call to call, hence seed + 1)
    found = salib_sobol.analyze(problem, y, calc_second_order=False, num_resamples=RESAMPLES, seed=seed + 1)
    return SobolIndices(names, np.asarray(found["S1"]), np.asarray(found["ST"]), np.asarray(found["S1_conf"]),
                        np.asarray(found["ST_conf"]), source, n_base, note)


def indices_of_surface(surface: QuadraticSurface, samples: int = SURFACE_SAMPLES, seed: int = 0) -> SobolIndices:
    """Sobol' indices of a fitted surface, its factors uniform over the coded box [-1, 1]^k."""
    points = designs.saltelli(samples, len(surface.factor_names), seed=seed)
    return indices_of_sample(points, surface.predict(points), surface.factor_names, "surface", seed,
                             note=f"on the fitted surface ({surface.verdict_text()})")


def sobol_indices(dataset, response: str, samples: int = SURFACE_SAMPLES, seed: int = 0) -> SobolIndices:
    """Sobol' indices of a study Dataset's ``response``: from the cases when the design is Saltelli's
    sample and none failed ("design"), otherwise from its quadratic surface ("surface")."""
    names = [str(n) for n in dataset["factor"].values]
    coded = np.asarray(dataset["coded"].values, dtype=float)
    y = np.asarray(dataset[response].values, dtype=float)
    if saltelli_base_samples(coded) is not None and np.all(np.isfinite(y)):
        return indices_of_sample(coded, y, names, "design", seed)
    return indices_of_surface(fit_response(dataset, response), samples, seed)
