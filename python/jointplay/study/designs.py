"""Designs of experiments in coded units: one row per case, one column per factor.

Every design here is an array (cases, factors) of float64 in CODED units: a factor's range maps to
[-1, 1] (low -> -1, centre -> 0, high -> +1), :func:`code` and :func:`uncode` convert. The designs
(definitions and when to use each: ``docs/theory/designs-of-experiments.md``):

- :func:`full_factorial`: every combination of equally spaced levels;
- :func:`latin_hypercube`: one point in each of ``n`` equal strata of every axis (``scipy.stats.qmc``);
- :func:`sobol`: the first ``n`` points of a (scrambled) Sobol' sequence, ``n`` a power of 2;
- :func:`central_composite`: 2^k corners, 2k axial points and centre points (pyDOE3);
- :func:`box_behnken`: midpoints of the edges of the cube and centre points (pyDOE3);
- :func:`saltelli`: Saltelli's A, AB_i, B blocks for Sobol' indices (SALib);
- :func:`explicit`: a table given by the user.

Random designs are deterministic given their ``seed``. Bad input raises
:class:`~jointplay.errors.ModelError` located at ``study.design.<option>``.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from ..errors import ModelError, Problem

#: Location of a design's options in a study file (errors name it).
WHERE = "study.design"

#: Centre-face choices of a central composite design.
CCD_FACES = ("faced", "circumscribed", "inscribed")

#: Space-filling optimisations of a Latin hypercube that keep one point per stratum (scipy's
#: "random-cd" permutes the coordinates within each column). scipy's "lloyd" moves points off their
#: strata and is refused.
LHS_OPTIMIZATIONS = (None, "random-cd")


def _fail(option: str, message: str) -> ModelError:
    return ModelError([Problem(f"{WHERE}.{option}", message)])


# --- coded units -------------------------------------------------------------------------------------

def code(value, low: float, high: float):
    """Coded coordinate of ``value`` on the range [low, high]: -1 at low, +1 at high (same units; ``low``
    is the value at -1 and may exceed ``high``, as for levels listed in decreasing order)."""
    if not (math.isfinite(low) and math.isfinite(high)) or high == low:
        raise _fail("range", f"must be finite with low != high to code a value, got low={low!r}, high={high!r}")
    return -1.0 + 2.0 * (np.asarray(value, dtype=float) - low) / (high - low)


def uncode(coded, low: float, high: float):
    """Value on the range [low, high] of a coded coordinate (-1 -> low, +1 -> high; same units)."""
    if not (math.isfinite(low) and math.isfinite(high)) or high == low:
        raise _fail("range", f"must be finite with low != high to uncode a value, got low={low!r}, high={high!r}")
    return low + (np.asarray(coded, dtype=float) + 1.0) * 0.5 * (high - low)


# --- checks ----------------------------------------------------------------------------------------------

def _whole(raw: Any, option: str, least: int) -> int:
    if isinstance(raw, bool) or not isinstance(raw, (int, np.integer)) or raw < least:
        raise _fail(option, f"must be a whole number >= {least}, got {raw!r}")
    return int(raw)


def _power_of_two(n: int, option: str, kind: str) -> None:
    if n & (n - 1):
        below, above = 2 ** int(math.log2(n)), 2 ** (int(math.log2(n)) + 1)
        raise _fail(option, f"a {kind} design needs a power of 2 (its balance holds only then), got {n}; "
                            f"use {below} or {above}")


# --- the designs ---------------------------------------------------------------------------------------

def full_factorial(levels: Sequence[int]) -> np.ndarray:
    """Every combination of the factors' levels, equally spaced over [-1, 1] (``levels[j]`` levels for
    factor j; a factor with one level sits at 0). Rows in lexicographic order, the last factor fastest."""
    if isinstance(levels, (int, np.integer)) or not len(levels):
        raise _fail("levels", f"must list the number of levels of each factor, got {levels!r}")
    counts = [_whole(m, "levels", least=1) for m in levels]
    axes = [np.zeros(1) if m == 1 else np.linspace(-1.0, 1.0, m) for m in counts]
    return np.array(list(itertools.product(*axes)), dtype=float).reshape(-1, len(counts))


def latin_hypercube(n: int, k: int, seed: int = 0, optimization: str | None = None) -> np.ndarray:
    """``n`` points with exactly one in each of ``n`` equal strata of every axis, placed at random within
    its stratum (``scipy.stats.qmc.LatinHypercube``). ``optimization="random-cd"`` permutes the columns to
    lower the centred discrepancy (still one point per stratum)."""
    from scipy.stats import qmc

    n, k = _whole(n, "samples", least=2), _whole(k, "factors", least=1)
    if optimization not in LHS_OPTIMIZATIONS:
        raise _fail("optimization", f"must be one of {', '.join(map(str, LHS_OPTIMIZATIONS))}, got "
                                    f"{optimization!r}")
    if optimization is not None and k < 2:
        raise _fail("optimization", f"{optimization} needs at least 2 factors, got {k}")
    unit = qmc.LatinHypercube(d=k, optimization=optimization, rng=np.random.default_rng(seed)).random(n)
    return 2.0 * unit - 1.0


def sobol(n: int, k: int, seed: int = 0, scramble: bool = True) -> np.ndarray:
    """The first ``n`` points of the Sobol' sequence in ``k`` dimensions (``scipy.stats.qmc.Sobol``),
    scrambled (linear matrix scrambling and a digital shift, seeded) unless ``scramble=False``. ``n`` must
    be a power of 2: only then is every half, quarter, ... of each axis filled equally (the net property),
    so other counts are refused rather than warned about."""
    from scipy.stats import qmc

    n, k = _whole(n, "samples", least=2), _whole(k, "factors", least=1)
    _power_of_two(n, "samples", "sobol")
    if not isinstance(scramble, bool):
        raise _fail("scramble", f"must be true or false, got {scramble!r}")
    unit = qmc.Sobol(d=k, scramble=scramble, rng=np.random.default_rng(seed)).random(n)
    return 2.0 * unit - 1.0


def central_composite(k: int, face: str = "faced", center: tuple[int, int] = (1, 0)) -> np.ndarray:
    """Central composite design (pyDOE3 ``ccdesign``): the 2^k corners, 2k axial points and
    ``center[0] + center[1]`` centre points (in the factorial and the axial block).

    ``face``: "faced" puts the axial points on the faces (alpha = 1, three levels per factor);
    "circumscribed" puts them at the rotatable distance alpha = (2^k)^(1/4) > 1, OUTSIDE [-1, 1]: the
    caller decides whether the factors may go beyond their ranges; "inscribed" shrinks that design into
    the cube (axial points at +-1, corners at +-1/alpha). One centre point by default: a simulation run
    twice gives the same value, so replicated centres add no information."""
    from pyDOE3 import ccdesign

    if isinstance(k, (int, np.integer)) and not isinstance(k, bool) and k == 1:
        raise _fail("kind", "a central_composite design needs at least 2 factors, got 1; use a full_factorial "
                            "with 3 or 5 levels")
    k = _whole(k, "factors", least=2)
    if face not in CCD_FACES:
        raise _fail("face", f"must be one of {', '.join(CCD_FACES)}, got {face!r}")
    if isinstance(center, (int, np.integer)) or len(center) != 2:
        raise _fail("center", f"must be two whole numbers (centre points in the factorial and in the axial "
                              f"block), got {center!r}")
    counts = (_whole(center[0], "center", least=0), _whole(center[1], "center", least=0))
    return np.asarray(ccdesign(k, center=counts, alpha="rotatable", face=face), dtype=float)


def box_behnken(k: int, center: int = 1) -> np.ndarray:
    """Box-Behnken design (pyDOE3 ``bbdesign``): for every pair of factors the four points (+-1, +-1) with
    the other factors at 0 (the midpoints of the cube's edges), then ``center`` centre points. Needs
    k >= 3; never leaves the cube. pyDOE3 takes all k(k-1)/2 pairs: 4 k(k-1)/2 edge points (12 for k = 3,
    24 for k = 4, as Box and Behnken's tables; more than their balanced-block designs from k = 6)."""
    from pyDOE3 import bbdesign

    if isinstance(k, (int, np.integer)) and not isinstance(k, bool) and 1 <= k < 3:
        raise _fail("kind", f"a box_behnken design needs at least 3 factors, got {k}; use a central_composite "
                            "or a full_factorial with 3 levels")
    k = _whole(k, "factors", least=3)
    return np.asarray(bbdesign(k, center=_whole(center, "center", least=0)), dtype=float)


def saltelli(n: int, k: int, seed: int = 0) -> np.ndarray:
    """Saltelli's sample for first-order and total Sobol' indices (SALib ``sample.sobol``, no second
    order): for each of ``n`` base points (a power of 2) a block of k + 2 rows, A, AB_1 .. AB_k, B, where
    AB_i is A with column i taken from B; n (k + 2) rows in all. A and B are the two halves of a
    scrambled, seeded 2k-dimensional Sobol' point."""
    from SALib.sample import sobol as salib_sobol

    n, k = _whole(n, "samples", least=2), _whole(k, "factors", least=1)
    _power_of_two(n, "samples", "saltelli")
    problem = {"num_vars": k, "names": [f"x{j + 1}" for j in range(k)], "bounds": [[-1.0, 1.0]] * k}
    return np.asarray(salib_sobol.sample(problem, n, calc_second_order=False, scramble=True, seed=seed),
                      dtype=float)


def explicit(table, k: int | None = None) -> np.ndarray:
    """A design given as a table of coded points, one row per case (checked: 2-D, finite, k columns)."""
    try:
        array = np.asarray(table, dtype=float)
    except (TypeError, ValueError):
        raise _fail("rows", f"must be a table of numbers, one row per case, got {table!r}") from None
    if array.ndim != 2 or array.shape[0] == 0:
        raise _fail("rows", f"must be a non-empty table (cases x factors), got shape {array.shape}")
    if k is not None and array.shape[1] != k:
        raise _fail("rows", f"must have one column per factor ({k}), got {array.shape[1]}")
    if not np.all(np.isfinite(array)):
        row = int(np.flatnonzero(~np.all(np.isfinite(array), axis=1))[0])
        raise _fail(f"rows[{row}]", f"must hold finite numbers, got {array[row].tolist()}")
    return array


# --- registry ------------------------------------------------------------------------------------------

def _make_full_factorial(k: int, levels: int | Sequence[int] = 3) -> np.ndarray:
    per_factor = [levels] * k if isinstance(levels, (int, np.integer)) else list(levels)
    if len(per_factor) != k:
        raise _fail("levels", f"must give one count per factor ({k}), got {levels!r}")
    return full_factorial(per_factor)


def _make_sampled(function: Callable, k: int, samples: int | None = None, seed: int = 0, **options) -> np.ndarray:
    if samples is None:
        raise _fail("samples", "missing: this design needs its number of samples")
    return function(samples, k, seed=seed, **options)


#: Design kinds by name: each takes the number of factors and its options.
DESIGNS: dict[str, Callable[..., np.ndarray]] = {
    "full_factorial": _make_full_factorial,
    "latin_hypercube": lambda k, **o: _make_sampled(latin_hypercube, k, **o),
    "sobol": lambda k, **o: _make_sampled(sobol, k, **o),
    "saltelli": lambda k, **o: _make_sampled(saltelli, k, **o),
    "central_composite": lambda k, face="faced", center=(1, 0): central_composite(k, face, center),
    "box_behnken": lambda k, center=1: box_behnken(k, center),
    "explicit": lambda k, rows=None: explicit(rows, k),
}
DESIGNS["table"] = DESIGNS["explicit"]  # the study file's name for an explicit design

#: The options each kind takes (``seed`` only for the random ones).
OPTIONS: dict[str, tuple[str, ...]] = {
    "full_factorial": ("levels",),
    "latin_hypercube": ("samples", "seed", "optimization"),
    "sobol": ("samples", "seed", "scramble"),
    "saltelli": ("samples", "seed"),
    "central_composite": ("face", "center"),
    "box_behnken": ("center",),
    "explicit": ("rows",),
    "table": ("rows",),
}


def make_design(kind: str, k: int, **options) -> np.ndarray:
    """The design ``kind`` for ``k`` factors with its options (see :data:`OPTIONS`), in coded units."""
    if kind not in DESIGNS:
        raise _fail("kind", f"must be one of {', '.join(DESIGNS)}, got {kind!r}")
    k = _whole(k, "factors", least=1)
    unknown = sorted(set(options) - set(OPTIONS[kind]))
    if unknown:
        raise _fail(unknown[0], f"is not an option of a {kind} design (options: {', '.join(OPTIONS[kind])})")
    return DESIGNS[kind](k, **options)
