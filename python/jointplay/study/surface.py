"""Quadratic response surface in coded units, fitted by least squares, with its quality stated.

The full quadratic model in k coded factors x_1 .. x_k (each -1 .. +1 over its range) is

    y = b_0 + sum_i b_i x_i + sum_{i<j} b_ij x_i x_j + sum_i b_ii x_i^2,

p = (k + 1)(k + 2) / 2 terms (``degree=1``: the constant and the k linear terms, with the interactions
if asked). Coefficients solve min ||y - X b|| through the QR factorisation X = QR. Its quality: R^2,
adjusted R^2, and leave-one-out cross-validation in closed form from the hat matrix H = Q Q^T,
PRESS = sum_i (e_i / (1 - h_ii))^2, Q^2 = 1 - PRESS / SS_tot, RMSE_cv = sqrt(PRESS / n). A surface is
"trustworthy" when Q^2 >= 0.5 and adjusted R^2 >= 0.8, otherwise "poor" (Myers, Montgomery and
Anderson-Cook, *Response Surface Methodology*, 4th ed., Wiley 2016, ch. 2 and 6;
``docs/theory/response-surface.md``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ModelError, Problem

#: Least Q^2 (leave-one-out) of a trustworthy surface: it predicts unseen cases better than half the spread.
TRUSTWORTHY_Q2 = 0.5
#: Least adjusted R^2 of a trustworthy surface: it explains 80 % of the variance, counted per term.
TRUSTWORTHY_R2_ADJUSTED = 0.8
#: A case whose leverage h_ii is this close to 1 fixes a term by itself: leaving it out is undefined.
_LEVERAGE_ONE = 1e-10

_WHERE = "surface"


@dataclass(frozen=True)
class QuadraticSurface:
    """A fitted polynomial surface in coded factors: its terms, coefficients and quality.

    ``exponents[t, j]`` is the power of factor j in term t; ``coefficients`` are in the response's units.
    ``n_cases`` finished cases were fitted, ``n_failed`` cases were left out (their response was NaN).
    ``r2``, ``r2_adjusted`` and ``q2`` are unitless; ``press`` is in units^2, ``rmse`` (residual,
    sqrt(SS_res / n)) and ``rmse_cv`` (leave-one-out, sqrt(PRESS / n)) in the response's units.
    ``omitted_terms``: square terms of factors with only two levels in the cases (not estimable)."""

    factor_names: tuple[str, ...]
    exponents: np.ndarray
    coefficients: np.ndarray
    n_cases: int
    n_failed: int
    r2: float
    r2_adjusted: float
    press: float
    q2: float
    rmse: float
    rmse_cv: float
    degree: int = 2
    omitted_terms: tuple[str, ...] = ()
    response: str = ""
    units: str = ""
    notes: tuple[str, ...] = ()

    @property
    def n_terms(self) -> int:
        return len(self.coefficients)

    @property
    def term_names(self) -> list[str]:
        """Terms by the factors' names: "1", "a", "a*b", "a^2"."""
        return [term_name(e, self.factor_names) for e in self.exponents]

    def predict(self, coded) -> np.ndarray:
        """The surface at coded points (cases, factors) -> (cases,), in the response's units."""
        return model_matrix(self._points(coded), self.exponents) @ self.coefficients

    def gradient(self, coded) -> np.ndarray:
        """d y / d x_j at coded points (cases, factors) -> (cases, factors), response units per coded unit
        (divide by half a factor's range for per-SI-unit slopes)."""
        x = self._points(coded)
        out = np.empty_like(x)
        for j in range(x.shape[1]):
            powers = self.exponents[:, j]
            lowered = self.exponents.copy()
            lowered[:, j] = np.maximum(powers - 1, 0)
            out[:, j] = (model_matrix(x, lowered) * powers) @ self.coefficients
        return out

    @property
    def verdict(self) -> str:
        """"trustworthy" when Q^2 >= 0.5 and adjusted R^2 >= 0.8, else "poor"."""
        ok = self.q2 >= TRUSTWORTHY_Q2 and self.r2_adjusted >= TRUSTWORTHY_R2_ADJUSTED
        return "trustworthy" if ok else "poor"

    def verdict_text(self) -> str:
        """One line: the verdict and the numbers that decided it."""
        rule = (f"Q^2 = {self.q2:.3g} {'>=' if self.q2 >= TRUSTWORTHY_Q2 else '<'} {TRUSTWORTHY_Q2}, adjusted "
                f"R^2 = {self.r2_adjusted:.3g} {'>=' if self.r2_adjusted >= TRUSTWORTHY_R2_ADJUSTED else '<'} "
                f"{TRUSTWORTHY_R2_ADJUSTED}")
        text = f"{self.verdict}: {rule} ({self.n_cases} cases, {self.n_terms} terms)"
        return "; ".join([text, *self.notes])

    def quality(self) -> dict:
        """The surface's quality as plain data (numbers and the verdict)."""
        return {"response": self.response, "cases": self.n_cases, "failed": self.n_failed, "terms": self.n_terms,
                "r2": self.r2, "r2_adjusted": self.r2_adjusted, "press": self.press, "q2": self.q2,
                "rmse": self.rmse, "rmse_cv": self.rmse_cv, "verdict": self.verdict,
                "verdict_text": self.verdict_text(), "omitted_terms": list(self.omitted_terms)}

    def _points(self, coded) -> np.ndarray:
        x = np.asarray(coded, dtype=float)
        x = x.reshape(1, -1) if x.ndim == 1 else x
        if x.ndim != 2 or x.shape[1] != len(self.factor_names):
            raise ModelError([Problem(_WHERE, f"points must be (cases, {len(self.factor_names)}) coded values "
                                              f"({', '.join(self.factor_names)}), got shape {np.shape(coded)}")])
        return x


# --- terms ----------------------------------------------------------------------------------------------

def term_name(exponents, names) -> str:
    """A term's name from its exponents: "1", "a", "a*b", "a^2"."""
    parts = [name if p == 1 else f"{name}^{p}" for name, p in zip(names, exponents, strict=True) if p]
    return "*".join(parts) or "1"


def model_matrix(x: np.ndarray, exponents: np.ndarray) -> np.ndarray:
    """X[c, t] = prod_j x[c, j] ** exponents[t, j] (0 ** 0 = 1)."""
    return np.prod(x[:, None, :] ** exponents[None, :, :], axis=2)


def quadratic_terms(k: int, degree: int = 2, interactions: bool = True, squared=None) -> np.ndarray:
    """Exponents of the model's terms (terms, k): the constant, the linear terms, the interactions
    x_i x_j (i < j) if ``interactions``, the squares x_i^2 if degree 2 (for the factors ``squared`` says,
    all by default)."""
    eye = np.eye(k, dtype=int)
    terms = [np.zeros(k, dtype=int), *eye]
    if interactions:
        terms += [eye[i] + eye[j] for i in range(k) for j in range(i + 1, k)]
    if degree == 2:
        terms += [2 * eye[i] for i in range(k) if squared is None or squared[i]]
    return np.array(terms, dtype=int).reshape(-1, k)


# --- fit -----------------------------------------------------------------------------------------------

def fit_quadratic(coded, response, factor_names=None, degree: int = 2, interactions: bool | None = None, *,
                  response_name: str = "", units: str = "") -> QuadraticSurface:
    """Least-squares surface of ``response`` (cases,) over ``coded`` points (cases, factors).

    ``degree`` 2 (full quadratic; ``interactions`` default True) or 1 (linear; ``interactions`` default
    False). Cases whose response is NaN (failed) are left out and counted. A factor with two levels among
    the cases loses its square term (listed in ``omitted_terms``). Raises ModelError when a factor never
    varies, when there are fewer distinct cases than terms, or when terms cannot be told apart."""
    x, y, names = _inputs(coded, response, factor_names)
    if degree not in (1, 2):
        raise ModelError([Problem(f"{_WHERE}.degree", f"must be 1 (linear) or 2 (quadratic), got {degree!r}")])
    interactions = (degree == 2) if interactions is None else bool(interactions)
    finite = np.isfinite(y)
    x, y, n_failed = x[finite], y[finite], int(np.count_nonzero(~finite))
    levels = [np.unique(x[:, j]).size for j in range(x.shape[1])]
    _check_varied(names, levels, x)
    squared = [m >= 3 for m in levels]
    exponents = quadratic_terms(len(names), degree, interactions, squared)
    omitted = tuple(f"{n}^2" for n, s in zip(names, squared, strict=True) if degree == 2 and not s)
    _check_enough_cases(x, exponents, names, degree, n_failed)
    matrix = model_matrix(x, exponents)
    _check_rank(matrix, exponents, names)
    coefficients, leverage = _least_squares(matrix, y)
    stats, notes = _quality(y, matrix @ coefficients, leverage, len(coefficients))
    if omitted:
        notes.append(f"{', '.join(omitted)} left out (two levels only)")
    return QuadraticSurface(tuple(names), exponents, coefficients, len(y), n_failed, degree=degree,
                            omitted_terms=omitted, response=response_name, units=units, notes=tuple(notes), **stats)


def fit_response(dataset, response: str, degree: int = 2, interactions: bool | None = None) -> QuadraticSurface:
    """The surface of the study Dataset's ``response`` over its ``coded`` points, named and with units."""
    if response not in dataset.data_vars:
        raise ModelError([Problem(f"{_WHERE}.response", f"must name a response of the study, got {response!r}")])
    names = [str(n) for n in dataset["factor"].values]
    return fit_quadratic(dataset["coded"].values, dataset[response].values, names, degree, interactions,
                         response_name=response, units=str(dataset[response].attrs.get("units", "")))


def _inputs(coded, response, factor_names) -> tuple[np.ndarray, np.ndarray, list[str]]:
    x = np.asarray(coded, dtype=float)
    y = np.asarray(response, dtype=float)
    if x.ndim != 2 or y.ndim != 1 or x.shape[0] != y.shape[0]:
        raise ModelError([Problem(_WHERE, f"needs coded points (cases, factors) and one response per case, got "
                                          f"shapes {x.shape} and {y.shape}")])
    names = [f"x{j + 1}" for j in range(x.shape[1])] if factor_names is None else [str(n) for n in factor_names]
    if len(names) != x.shape[1]:
        raise ModelError([Problem(_WHERE, f"needs one name per factor ({x.shape[1]}), got {names}")])
    if not np.all(np.isfinite(x)):
        raise ModelError([Problem(f"{_WHERE}.coded", "must be finite at every case")])
    return x, y, names


def _check_varied(names: list[str], levels: list[int], x: np.ndarray) -> None:
    if x.shape[0] == 0:
        raise ModelError([Problem(_WHERE, "no finished case to fit (every response is NaN)")])
    fixed = [f"{n} (always {x[0, j]:g})" for j, (n, m) in enumerate(zip(names, levels, strict=True)) if m < 2]
    if fixed:
        raise ModelError([Problem(_WHERE, f"factor {', '.join(fixed)} never varies among the finished cases: its "
                                          "terms cannot be estimated; vary it or leave it out of the study")])


def _check_enough_cases(x, exponents, names, degree, n_failed) -> None:
    distinct, terms = np.unique(x, axis=0).shape[0], exponents.shape[0]
    if distinct < terms:
        failed = f" ({n_failed} failed)" if n_failed else ""
        raise ModelError([Problem(_WHERE, f"{distinct} distinct finished cases{failed} cannot fit the {terms} terms "
                                          f"of a degree-{degree} surface in {len(names)} factors; use degree=1 "
                                          f"({len(names) + 1} terms) or a larger design (central_composite, "
                                          "box_behnken, more samples)")])


def _check_rank(matrix: np.ndarray, exponents: np.ndarray, names: list[str]) -> None:
    """Names the first term that the earlier ones already explain (an aliased term)."""
    if np.linalg.matrix_rank(matrix) == matrix.shape[1]:
        return
    for t in range(1, matrix.shape[1] + 1):
        if np.linalg.matrix_rank(matrix[:, :t]) < t:
            aliased = term_name(exponents[t - 1], names)
            raise ModelError([Problem(_WHERE, f"the design cannot tell term {aliased} from the terms before it "
                                              f"(rank-deficient: {matrix.shape[1]} terms); use degree=1 or a "
                                              "design that varies the factors independently")])


def _least_squares(matrix: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Coefficients b = R^-1 Q^T y and the leverages h_ii = sum_t Q_it^2 (diagonal of the hat matrix)."""
    from scipy.linalg import solve_triangular

    q, r = np.linalg.qr(matrix)
    return solve_triangular(r, q.T @ y), np.sum(q * q, axis=1)


def _quality(y: np.ndarray, fitted: np.ndarray, leverage: np.ndarray, terms: int) -> tuple[dict, list[str]]:
    """R^2, adjusted R^2, PRESS, Q^2 and RMSEs; notes on what is undefined and why."""
    n, notes = len(y), []
    residuals = y - fitted
    ss_res = float(residuals @ residuals)
    ss_tot = float(np.sum((y - y.mean()) ** 2)) if np.ptp(y) > 0 else 0.0
    dof = n - terms
    r2 = 1.0 - ss_res / ss_tot if ss_tot > 0 else np.nan
    r2_adjusted = 1.0 - (ss_res / dof) / (ss_tot / (n - 1)) if ss_tot > 0 and dof > 0 else np.nan
    if ss_tot == 0:
        notes.append("the response does not vary over the cases: R^2 and Q^2 are undefined")
    if dof == 0:
        notes.append("as many cases as terms: the surface interpolates and cannot be checked")
    if dof > 0 and np.all(leverage < 1.0 - _LEVERAGE_ONE):
        press = float(np.sum((residuals / (1.0 - leverage)) ** 2))
    else:
        press = np.nan
        if dof > 0:
            notes.append("a case fixes a term by itself (leverage 1): leave-one-out is undefined")
    q2 = 1.0 - press / ss_tot if ss_tot > 0 else np.nan
    stats = {"r2": r2, "r2_adjusted": r2_adjusted, "press": press, "q2": q2,
             "rmse": float(np.sqrt(ss_res / n)), "rmse_cv": float(np.sqrt(press / n))}
    return stats, notes
