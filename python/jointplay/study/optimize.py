"""Optimisation of a study's responses: on fitted surfaces or directly on the simulator, verified by a run.

Objectives name responses to minimise (or maximise) with weights. Several objectives are scalarised
as ``J = sum_i w_i s_i y_i / scale_i`` (``s_i`` = +1 to minimise, -1 to maximise; ``scale_i`` the spread
of response i over the study's finished cases, or its value at the centre run on the simulator, so
that weights compare unitless numbers), or kept apart as a Pareto front. Continuous factors are
searched over their ranges (coded -1 .. +1) by differential evolution (``scipy.optimize``, seeded),
discrete factors (levels, ISO grades and fits) over every combination of their levels. Whatever finds
it, the optimum is run once more for real and reported beside the surface's prediction
(docs/theory/response-surface.md, "Optimisation").
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import ModelError, Problem

GOALS = ("minimize", "maximize")


@dataclass(frozen=True)
class Objective:
    """A response to minimise or maximise, with its weight in a weighted sum."""

    response: str
    goal: str = "minimize"
    weight: float = 1.0

    @property
    def sign(self) -> float:
        return 1.0 if self.goal == "minimize" else -1.0


@dataclass
class Optimum:
    """The best point found: factor values [SI] by name, its coded point, the predicted responses (surface)
    and the responses of the verifying run, with the relative differences."""

    values: dict[str, float]
    coded: np.ndarray
    method: str
    predicted: dict[str, float] = field(default_factory=dict)
    verified: dict[str, float] = field(default_factory=dict)
    labels: dict[str, str] = field(default_factory=dict)
    objective: float = math.nan
    evaluations: int = 0
    #: What limits trust in the optimum (a surface that fits poorly), one line each.
    notes: list[str] = field(default_factory=list)

    def differences(self) -> dict[str, float]:
        """(verified - predicted) / |verified| per response with both."""
        return {k: (self.verified[k] - p) / abs(self.verified[k]) if self.verified.get(k) else math.nan
                for k, p in self.predicted.items() if k in self.verified}


def parse_objectives(entries: Any, responses: list[str], where: str = "study.optimize.objectives") -> list[Objective]:
    """Objectives from ``[{ response = "acc_osc", goal = "minimize", weight = 1 }, ...]``."""
    if not isinstance(entries, list) or not entries:
        raise ModelError([Problem(where, "must list the responses to optimise, e.g. "
                                         "[{ response = \"peak_force\", goal = \"minimize\" }]")])
    out, problems = [], []
    for k, entry in enumerate(entries):
        at = f"{where}[{k}]"
        if not isinstance(entry, dict) or entry.get("response") not in responses:
            got = entry.get("response") if isinstance(entry, dict) else entry
            problems.append(Problem(f"{at}.response", f"must name a response of the study ({', '.join(responses)}), "
                                                      f"got {got!r}"))
            continue
        unknown = set(entry) - {"response", "goal", "weight"}
        goal, weight = entry.get("goal", "minimize"), entry.get("weight", 1.0)
        if unknown:
            problems.append(Problem(f"{at}.{sorted(unknown)[0]}", "is not a key of an objective (response, goal, weight)"))
        if goal not in GOALS:
            problems.append(Problem(f"{at}.goal", f"must be minimize or maximize, got {goal!r}"))
        if isinstance(weight, bool) or not isinstance(weight, (int, float)) or not weight > 0:
            problems.append(Problem(f"{at}.weight", f"must be a number > 0, got {weight!r}"))
        else:
            out.append(Objective(entry["response"], goal, float(weight)))
    if problems:
        raise ModelError(problems)
    return out


# --- on the surfaces ----------------------------------------------------------------------------------

def fit_surfaces(dataset, responses: list[str], degree: int = 2) -> dict:
    """A quadratic surface in coded units for each response, fitted on the finished cases."""
    from .surface import fit_response

    return {r: fit_response(dataset, r, degree=degree) for r in responses}


def scales(dataset, objectives: list[Objective]) -> dict[str, float]:
    """Spread (max - min) of each objective's response over the finished cases (1 when it does not vary)."""
    out = {}
    for o in objectives:
        y = np.asarray(dataset[o.response].values, dtype=float)
        y = y[np.isfinite(y)]
        spread = float(y.max() - y.min()) if y.size else 0.0
        out[o.response] = spread if spread > 0 else 1.0
    return out


def optimize_surface(study, dataset, objectives: list[Objective], *, verify: bool = True, seed: int = 0) -> Optimum:
    """The weighted optimum of the fitted surfaces over the factors' ranges and levels, verified by a run."""
    surfaces = fit_surfaces(dataset, [o.response for o in objectives])
    scale = scales(dataset, objectives)

    def objective(coded: np.ndarray) -> float:
        return sum(o.weight * o.sign * float(surfaces[o.response].predict(coded[None, :])[0]) / scale[o.response]
                   for o in objectives)

    coded, value, evaluations = _search(study.factors, objective, seed)
    optimum = _optimum(study, coded, "surface", value, evaluations)
    optimum.predicted = {r: float(s.predict(coded[None, :])[0]) for r, s in surfaces.items()}
    optimum.notes = [f"the surface of {r} is {s.verdict} ({s.verdict_text()}): its prediction is a rough guide, the "
                     "verifying run is what counts" for r, s in surfaces.items() if s.verdict != "trustworthy"]
    if verify:
        _verify(study, optimum)
    return optimum


def best_case(study, dataset, objectives: list[Objective]) -> Optimum:
    """The finished case with the best weighted objective (scales as :func:`optimize_surface`): a point that
    was run, whatever the surfaces' quality."""
    scale = scales(dataset, objectives)
    value = sum(o.weight * o.sign * np.asarray(dataset[o.response].values, dtype=float) / scale[o.response]
                for o in objectives)
    value = np.where(np.isfinite(value), value, np.inf)
    k = int(np.argmin(value))
    optimum = _optimum(study, np.asarray(dataset["coded"].values[k], dtype=float), f"best case of the design (case {k})",
                       float(value[k]), len(value))
    optimum.values = {f.name: float(dataset[f.name].values[k]) for f in study.factors}
    optimum.labels = {f.name: point_label(f, optimum.values[f.name]) for f in study.factors}
    optimum.verified = {r.name: float(dataset[r.name].values[k]) for r in study.responses}
    return optimum


def pareto_front(study, dataset, objectives: list[Objective], samples: int = 4096, seed: int = 0):
    """The non-dominated points of the surfaces over the factor space (a Sobol sample of the continuous
    factors crossed with every combination of the discrete levels): (coded points, predicted objectives
    with their goal's sign, so that every column is minimised)."""
    from scipy.stats import qmc

    from .pareto import non_dominated

    surfaces = fit_surfaces(dataset, [o.response for o in objectives])
    points = _candidates(study.factors, qmc.Sobol(d=max(1, len(study.factors)), seed=seed).random(samples))
    predicted = np.column_stack([o.sign * surfaces[o.response].predict(points) for o in objectives])
    mask = non_dominated(predicted)
    return points[mask], predicted[mask] * np.array([o.sign for o in objectives])


def front_optima(study, points: np.ndarray, objectives: list[Objective], dataset, count: int = 3) -> list[Optimum]:
    """Up to ``count`` points of a Pareto front, verified by runs: the best of each objective and the
    weighted best (by the objectives' weights over the study's spreads)."""
    surfaces = fit_surfaces(dataset, [o.response for o in objectives])
    scale = scales(dataset, objectives)
    predicted = {o.response: surfaces[o.response].predict(points) for o in objectives}
    weighted = sum(o.weight * o.sign * predicted[o.response] / scale[o.response] for o in objectives)
    picks = [int(np.argmin(o.sign * predicted[o.response])) for o in objectives] + [int(np.argmin(weighted))]
    chosen = list(dict.fromkeys(picks))[-count:] if len(set(picks)) > count else list(dict.fromkeys(picks))
    out = []
    for k in chosen:
        optimum = _optimum(study, points[k], "surface, Pareto front", float(weighted[k]), len(points))
        optimum.predicted = {r: float(p[k]) for r, p in predicted.items()}
        _verify(study, optimum)
        out.append(optimum)
    return out


def _candidates(factors, unit: np.ndarray) -> np.ndarray:
    """Coded candidate points: the unit sample mapped to -1..1 for continuous factors, crossed with every
    combination of discrete levels."""
    continuous = [j for j, f in enumerate(factors) if not f.discrete]
    combos = _level_combinations(factors)
    blocks = []
    for combo in combos:
        block = np.zeros((len(unit), len(factors)))
        for j, c in combo.items():
            block[:, j] = c
        for m, j in enumerate(continuous):
            block[:, j] = 2.0 * unit[:, m] - 1.0
        blocks.append(block)
    return np.unique(np.vstack(blocks), axis=0)


def _level_combinations(factors) -> list[dict[int, float]]:
    """Every combination of the discrete factors' coded levels ({column: coded})."""
    discrete = [j for j, f in enumerate(factors) if f.discrete]
    grids = [[f.coded(v) for v in factors[j].levels] for j in discrete for f in [factors[j]]]
    return [dict(zip(discrete, combo, strict=True)) for combo in itertools.product(*grids)] if discrete else [{}]


def _search(factors, objective, seed: int, maxiter: int = 200) -> tuple[np.ndarray, float, int]:
    """Minimum of ``objective`` over coded space: differential evolution on the continuous factors for
    each combination of the discrete levels."""
    from scipy.optimize import differential_evolution

    continuous = [j for j, f in enumerate(factors) if not f.discrete]
    best, best_value, evaluations = None, math.inf, 0
    for combo in _level_combinations(factors):
        point = np.zeros(len(factors))
        for j, c in combo.items():
            point[j] = c
        if continuous:
            def restricted(x, point=point):
                full = point.copy()
                full[continuous] = x
                return objective(full)

            result = differential_evolution(restricted, [(-1.0, 1.0)] * len(continuous), seed=seed, tol=1e-10,
                                            maxiter=maxiter, polish=True)
            point[continuous] = result.x
            value, evaluations = float(result.fun), evaluations + int(result.nfev)
        else:
            value, evaluations = float(objective(point)), evaluations + 1
        if value < best_value:
            best, best_value = point.copy(), value
    return best, best_value, evaluations


def _optimum(study, coded: np.ndarray, method: str, value: float, evaluations: int) -> Optimum:
    values = {f.name: float(f.value(c)) for f, c in zip(study.factors, coded, strict=True)}
    labels = {f.name: point_label(f, values[f.name]) for f in study.factors}
    return Optimum(values, np.asarray(coded, dtype=float), method, labels=labels, objective=value,
                   evaluations=evaluations)


def point_label(factor, value: float) -> str:
    """How an optimum's value reads: the level's name, or the value with the ISO grade whose band holds it."""
    if factor.discrete:
        return factor.label(value)
    text = factor.label(value)
    if factor.nominal is not None:
        from . import iso286

        # a band holds its upper end (docs/theory/iso-286-fits.md): the low end of a grades range is named
        # by the range's own lowest grade
        diametral = 2.0 * value
        if factor.low is not None and value - factor.low <= 1e-6 * (factor.high - factor.low):
            diametral = 2.0 * factor.low + 2.0 * iso286.BAND_SLACK_UM / iso286.UM_PER_M
        try:
            text += f" ({iso286.grade_of_clearance(diametral, factor.nominal)})"
        except ModelError:
            pass
    return text


def _verify(study, optimum: Optimum) -> None:
    """Runs the model at the optimum and records its responses."""
    results = study.run_point(optimum.values)
    optimum.verified = {r.name: float(r.evaluate(results)) for r in study.responses}


# --- on the simulator -----------------------------------------------------------------------------------

def optimize_simulator(study, objectives: list[Objective], *, method: str = "differential_evolution",
                       budget: int = 60, seed: int = 0) -> Optimum:
    """The weighted optimum found by running the simulator itself: scipy's differential evolution over the
    coded box (discrete factors through their level index), or Optuna's TPE sampler (``method="optuna"``),
    within about ``budget`` runs. Scales are the responses at the centre run. The best run is the
    verifying run."""
    centre = np.array([f.coded(f.value(0.0)) for f in study.factors])
    baseline = _responses_at(study, centre)
    scale = {o.response: abs(baseline[o.response]) or 1.0 for o in objectives}
    history: list[tuple[float, np.ndarray, dict]] = []

    def objective(coded: np.ndarray) -> float:
        try:
            found = _responses_at(study, coded)
        except Exception:  # noqa: BLE001 (a failed run is a bad point, not the end of the search)
            return math.inf
        value = sum(o.weight * o.sign * found[o.response] / scale[o.response] for o in objectives)
        value = value if math.isfinite(value) else math.inf
        history.append((value, np.array(coded, dtype=float), found))
        return value

    if method == "optuna":
        _optuna(study.factors, objective, budget, seed)
    elif method == "differential_evolution":
        _scipy_de(study.factors, objective, budget, seed)
    else:
        raise ModelError([Problem("study.optimize.method", f"must be differential_evolution or optuna, got {method!r}")])
    if not history:
        raise ModelError([Problem("study.optimize", "no run of the search finished; see the cases' errors")])
    value, coded, found = min(history, key=lambda item: item[0])
    optimum = _optimum(study, coded, f"simulator ({method})", value, len(history) + 1)
    optimum.verified = dict(found)
    return optimum


def _responses_at(study, coded: np.ndarray) -> dict[str, float]:
    values = {f.name: float(f.value(c)) for f, c in zip(study.factors, coded, strict=True)}
    results = study.run_point(values)
    return {r.name: float(r.evaluate(results)) for r in study.responses}


def _scipy_de(factors, objective, budget: int, seed: int) -> None:
    from scipy.optimize import differential_evolution

    k = len(factors)
    popsize = max(2, min(8, budget // max(1, 4 * k)))
    maxiter = max(1, budget // (popsize * k) - 1)
    integrality = [f.discrete for f in factors]
    bounds = [(0, len(f.levels) - 1) if f.discrete else (-1.0, 1.0) for f in factors]

    def coded_of(x: np.ndarray) -> np.ndarray:
        return np.array([f.coded(f.levels[int(round(v))]) if f.discrete else v
                         for f, v in zip(factors, x, strict=True)])

    differential_evolution(lambda x: objective(coded_of(x)), bounds, seed=seed, maxiter=maxiter, popsize=popsize,
                           integrality=integrality, polish=False, tol=0.0)


def _optuna(factors, objective, budget: int, seed: int) -> None:
    try:
        import optuna
    except ImportError:
        raise ModelError([Problem("study.optimize.method", "optuna is not installed (pip install optuna); "
                                                           "use differential_evolution")]) from None
    optuna.logging.set_verbosity(optuna.logging.WARNING)

    def trial_objective(trial) -> float:
        coded = np.array([f.coded(f.levels[trial.suggest_categorical(f.name, list(range(len(f.levels))))])
                          if f.discrete else trial.suggest_float(f.name, -1.0, 1.0) for f in factors])
        return objective(coded)

    sampler = optuna.samplers.TPESampler(seed=seed)
    optuna.create_study(direction="minimize", sampler=sampler).optimize(trial_objective, n_trials=budget)
