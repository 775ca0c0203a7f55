"""From a study's ``[study.design]`` table and its factors to the cases: coded points and SI values.

Designs come in coded units (:mod:`jointplay.study.designs`); each factor turns a coded coordinate into
its value (a continuous factor linearly over its range, a discrete one to its nearest level, whose
coded coordinate the case then takes, so that coded points and values always agree).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import ModelError, Problem
from .factors import Factor

#: Design kinds and the options each takes (besides ``kind``).
OPTIONS = {
    "full_factorial": {"levels"},
    "latin_hypercube": {"samples", "optimization"},
    "sobol": {"samples", "scramble"},
    "central_composite": {"face", "center"},
    "box_behnken": {"center"},
    "saltelli": {"samples"},
    "table": {"rows"},
}


def build_design(spec: dict, factors: list[Factor], seed: int, where: str) -> tuple[np.ndarray, np.ndarray]:
    """``(coded, values)``, each (cases, factors): the design's points and the factors' SI values there."""
    kind = spec.get("kind")
    if kind not in OPTIONS:
        raise ModelError([Problem(f"{where}.kind", f"must be one of {', '.join(OPTIONS)}, got {kind!r}")])
    unknown = set(spec) - OPTIONS[kind] - {"kind"}
    if unknown:
        raise ModelError([Problem(f"{where}.{sorted(unknown)[0]}", f"is not an option of a {kind} design "
                                                                   f"(options: {', '.join(sorted(OPTIONS[kind])) or 'none'})")])
    if not factors:
        raise ModelError([Problem("study.factors", "must list at least one factor")])
    if kind == "table":
        return _table(spec.get("rows"), factors, f"{where}.rows")
    coded = _coded(kind, spec, factors, seed, where)
    values = np.array([[f.value(c) for f, c in zip(factors, row, strict=True)] for row in coded], dtype=float)
    snapped = np.array([[f.coded(v) if f.discrete else c for f, c, v in zip(factors, row, vrow, strict=True)]
                        for row, vrow in zip(coded, values, strict=True)], dtype=float)
    return snapped, values


def _coded(kind: str, spec: dict, factors: list[Factor], seed: int, where: str) -> np.ndarray:
    from . import designs

    k = len(factors)
    if kind == "full_factorial":
        default = _count(spec.get("levels", 3), f"{where}.levels", least=1)
        return designs.full_factorial([len(f.levels) if f.discrete else default for f in factors])
    if kind in ("latin_hypercube", "sobol", "saltelli"):
        if "samples" not in spec:
            raise ModelError([Problem(f"{where}.samples", f"missing: a {kind} design needs its number of samples")])
        n = _count(spec["samples"], f"{where}.samples", least=2)
        extra = {key: spec[key] for key in ("optimization", "scramble") if key in spec}
        return getattr(designs, kind)(n, k, seed=seed, **extra)
    if kind == "central_composite":
        center = _count(spec.get("center", 1), f"{where}.center", least=0)
        return designs.central_composite(k, face=spec.get("face", "faced"), center=(center, 0))
    center = _count(spec.get("center", 1), f"{where}.center", least=0)
    return designs.box_behnken(k, center=center)


def _count(raw: Any, where: str, least: int) -> int:
    if isinstance(raw, bool) or not isinstance(raw, int) or raw < least:
        raise ModelError([Problem(where, f"must be a whole number >= {least}, got {raw!r}")])
    return raw


def _table(rows: Any, factors: list[Factor], where: str) -> tuple[np.ndarray, np.ndarray]:
    """An explicit design: one row per case, one value with units per factor, in the factors' order."""
    from .factors import quantity_kind

    if not isinstance(rows, list) or not rows:
        raise ModelError([Problem(where, "must list the cases, one row of factor values each, e.g. "
                                         "[[\"0.1 mm\", \"500 rpm\"], ...]")])
    problems, values = [], []
    for r, row in enumerate(rows):
        if not isinstance(row, list) or len(row) != len(factors):
            problems.append(Problem(f"{where}[{r}]", f"must hold {len(factors)} values (one per factor: "
                                                     f"{', '.join(f.name for f in factors)}), got {row!r}"))
            continue
        out = []
        for f, raw in zip(factors, row, strict=True):
            try:
                kind, (value,) = quantity_kind([raw], f"{where}[{r}]")
            except ModelError as exc:
                problems.extend(exc.problems)
                continue
            if kind.name != f.kind:
                problems.append(Problem(f"{where}[{r}]", f"{f.name} is a {f.kind}, got {raw!r}"))
            out.append(value)
        values.append(out)
    if problems:
        raise ModelError(problems)
    values = np.array(values, dtype=float)
    coded = np.array([[f.coded(v) for f, v in zip(factors, row, strict=True)] for row in values], dtype=float)
    return coded, values
