"""Figures of a study: main effects and interactions from its cases, contours of a fitted surface.

Each function returns a matplotlib Figure (made with the Agg backend's canvas, no window) titled with
what it shows: the response with its units, the factors, and what was held or binned. Factor values are
in SI, as in the study Dataset (its ``case`` coordinates carry ``units`` and ``long_name``).

- :func:`main_effects`: the mean response at each level of each factor (averaged over the others);
- :func:`interactions`: the mean response over one factor's levels, one line per level of another
  (parallel lines: no interaction);
- :func:`contour`: a surface over two factors in their real units, the others held.

A factor with more than ``max_levels`` distinct values (a Latin hypercube, a Sobol' design) is binned
into ``bins`` equal-width intervals of its values, plotted at the intervals' centres; the title says so.
"""

from __future__ import annotations

import numpy as np

from ..errors import ModelError, Problem
from .designs import code, uncode

#: A factor with at most this many distinct values is plotted at its levels, otherwise binned.
MAX_LEVELS = 7
#: Equal-width intervals of a binned factor in a main-effect plot.
MAIN_EFFECT_BINS = 5
#: Equal-width intervals of a binned factor drawn as separate lines in an interaction plot.
INTERACTION_BINS = 3


def _figure(n_axes: int = 1, width: float = 4.0, height: float = 3.6):
    from matplotlib.figure import Figure

    fig = Figure(figsize=(max(5.0, width * n_axes), height), layout="constrained")
    return fig, [fig.add_subplot(1, n_axes, j + 1) for j in range(n_axes)]


def _label(ds, name: str) -> str:
    """"name [units]" of a Dataset variable or coordinate."""
    units = str(ds[name].attrs.get("units", ""))
    return f"{name} [{units}]" if units else name


def _factors(ds) -> list[str]:
    return [str(f) for f in ds["factor"].values]


def _check(ds, response: str, factors=()) -> None:
    if response not in ds.data_vars:
        raise ModelError([Problem("plot.response", f"must name a response of the study, got {response!r}")])
    for f in factors:
        if f not in _factors(ds):
            raise ModelError([Problem("plot.factor", f"must name a factor of the study ({', '.join(_factors(ds))}), "
                                                     f"got {f!r}")])


def groups(values, max_levels: int = MAX_LEVELS, bins: int = MAIN_EFFECT_BINS) -> tuple[np.ndarray, np.ndarray, bool]:
    """(positions, group of each case, binned): the distinct values when at most ``max_levels``, else
    ``bins`` equal-width intervals between the smallest and largest value (positions at their centres)."""
    v = np.asarray(values, dtype=float)
    levels = np.unique(v)
    if levels.size <= max_levels:
        return levels, np.searchsorted(levels, v), False
    edges = np.linspace(levels[0], levels[-1], bins + 1)
    return 0.5 * (edges[:-1] + edges[1:]), np.digitize(v, edges[1:-1]), True


def group_means(y: np.ndarray, group: np.ndarray, n_groups: int) -> np.ndarray:
    """Mean of the finite ``y`` in each group (NaN for a group without any)."""
    finite = np.isfinite(y)
    sums = np.bincount(group[finite], weights=y[finite], minlength=n_groups)
    counts = np.bincount(group[finite], minlength=n_groups)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(counts > 0, sums / np.maximum(counts, 1), np.nan)


def _tick_labels(ax, ds, factor: str, positions: np.ndarray, binned: bool) -> None:
    """A discrete factor's level names (``<factor>_label``) as tick labels."""
    label_name = f"{factor}_label"
    if binned or label_name not in ds.coords:
        return
    values, labels = np.asarray(ds[factor].values, dtype=float), ds[label_name].values
    names = [str(labels[np.flatnonzero(values == p)[0]]) for p in positions]
    ax.set_xticks(positions, names)


def _notes(binned: list[str], n_failed: int, bins: int) -> str:
    notes = []
    if binned:
        notes.append(f"{', '.join(binned)} binned into {bins} equal-width intervals (continuous design)")
    if n_failed:
        notes.append(f"{n_failed} failed cases left out")
    return ("\n" + "; ".join(notes)) if notes else ""


def main_effects(ds, response: str, max_levels: int = MAX_LEVELS, bins: int = MAIN_EFFECT_BINS):
    """One panel per factor: the mean of ``response`` over the cases at each of its levels (or bins)."""
    _check(ds, response)
    y = np.asarray(ds[response].values, dtype=float)
    factors = _factors(ds)
    fig, axes = _figure(len(factors))
    binned = []
    for ax, factor in zip(axes, factors, strict=True):
        positions, group, was_binned = groups(ds[factor].values, max_levels, bins)
        means = group_means(y, group, len(positions))
        ax.plot(positions, means, "o-")
        ax.set_xlabel(_label(ds, factor))
        _tick_labels(ax, ds, factor, positions, was_binned)
        if was_binned:
            binned.append(factor)
    axes[0].set_ylabel(f"mean {_label(ds, response)}")
    n_failed = int(np.count_nonzero(~np.isfinite(y)))
    fig.suptitle(f"Main effects on {_label(ds, response)}{_notes(binned, n_failed, bins)}")
    return fig


def interactions(ds, response: str, f1: str, f2: str, max_levels: int = MAX_LEVELS,
                 bins: tuple[int, int] = (MAIN_EFFECT_BINS, INTERACTION_BINS)):
    """Mean ``response`` against ``f1``'s levels, one line per level of ``f2`` (parallel lines: the two
    factors do not interact)."""
    _check(ds, response, (f1, f2))
    if f1 == f2:
        raise ModelError([Problem("plot.factor", f"an interaction needs two different factors, got {f1!r} twice")])
    y = np.asarray(ds[response].values, dtype=float)
    x_positions, x_group, x_binned = groups(ds[f1].values, max_levels, bins[0])
    line_positions, line_group, line_binned = groups(ds[f2].values, max_levels, bins[1])
    fig, (ax,) = _figure(1, width=6.0, height=4.2)
    units = str(ds[f2].attrs.get("units", ""))
    for m, level in enumerate(line_positions):
        chosen = line_group == m
        means = group_means(y[chosen], x_group[chosen], len(x_positions))
        shown = f"{f2} {'~ ' if line_binned else '= '}{level:.4g} {units}".strip()
        ax.plot(x_positions, means, "o-", label=shown)
    ax.set_xlabel(_label(ds, f1))
    ax.set_ylabel(f"mean {_label(ds, response)}")
    _tick_labels(ax, ds, f1, x_positions, x_binned)
    ax.legend(fontsize="small")
    binned = [f for f, b in ((f1, x_binned), (f2, line_binned)) if b]
    n_failed = int(np.count_nonzero(~np.isfinite(y)))
    fig.suptitle(f"Interaction of {f1} and {f2} on {_label(ds, response)}{_notes(binned, n_failed, bins[0])}")
    return fig


def factor_ends(ds, factor: str) -> tuple[float, float] | None:
    """The factor's values at coded -1 and +1, when its values are linear in its coded coordinate over the
    cases (a continuous factor, or equally spaced levels), else None."""
    j = _factors(ds).index(factor)
    coded = np.asarray(ds["coded"].values, dtype=float)[:, j]
    values = np.asarray(ds[factor].values, dtype=float)
    if np.ptp(coded) == 0:
        return None
    slope, intercept = np.polyfit(coded, values, 1)
    scale = max(np.max(np.abs(values)), np.finfo(float).tiny)
    if np.max(np.abs(intercept + slope * coded - values)) > 1e-9 * scale:
        return None
    return float(intercept - slope), float(intercept + slope)


def contour(surface, f1: str, f2: str, fixed: dict[str, float] | None = None, *, dataset=None,
            ends: dict[str, tuple[float, float]] | None = None, units: dict[str, str] | None = None,
            points: int = 61):
    """Filled contours of a fitted surface over factors ``f1`` and ``f2`` in their real units, every other
    factor held at ``fixed[name]`` [SI] (default: its centre, coded 0). Each factor's values at coded -1
    and +1 come from ``ends`` or from the study ``dataset`` (whose cases are overlaid), units likewise; a
    factor with neither is drawn in coded units."""
    names = list(surface.factor_names)
    for f in (f1, f2, *(fixed or {})):
        if f not in names:
            raise ModelError([Problem("plot.factor", f"must name a factor of the surface ({', '.join(names)}), "
                                                     f"got {f!r}")])
    ends, units = _axes_of(names, dataset, ends, units)
    centre = np.zeros(len(names))
    held = []
    for name, value in (fixed or {}).items():
        j = names.index(name)
        centre[j] = code(value, *ends[name]) if name in ends else value
    for j, name in enumerate(names):
        if name not in (f1, f2):
            held.append(_held_text(name, centre[j], ends, units))
    grid = np.linspace(-1.0, 1.0, points)
    c1, c2 = np.meshgrid(grid, grid)
    at = np.tile(centre, (c1.size, 1))
    at[:, names.index(f1)], at[:, names.index(f2)] = c1.ravel(), c2.ravel()
    z = surface.predict(at).reshape(c1.shape)
    x, y = (_real(c, f, ends) for c, f in ((c1, f1), (c2, f2)))
    fig, (ax,) = _figure(1, width=6.0, height=4.8)
    filled = ax.contourf(x, y, z, levels=15)
    ax.contour(x, y, z, levels=15, colors="k", linewidths=0.4)
    response = f"{surface.response} [{surface.units}]" if surface.units else (surface.response or "response")
    fig.colorbar(filled, ax=ax, label=response)
    if dataset is not None:  # the cases where the axes put them (real units, or coded for a factor without ends)
        coded = np.asarray(dataset["coded"].values, dtype=float)
        ax.plot(*(_real(coded[:, names.index(f)], f, ends) for f in (f1, f2)), "k.", label="cases", clip_on=False)
    ax.set_xlabel(_axis_label(f1, ends, units))
    ax.set_ylabel(_axis_label(f2, ends, units))
    from matplotlib.ticker import MaxNLocator

    ax.xaxis.set_major_locator(MaxNLocator(5))
    title = f"{response}: quadratic surface over {f1} and {f2}"
    held_text = f"\nheld: {', '.join(held)}" if held else ""
    fig.suptitle(f"{title}\n({surface.verdict}, Q^2 = {surface.q2:.3g}){held_text}", fontsize=10)
    return fig


def _axes_of(names, dataset, ends, units) -> tuple[dict, dict]:
    ends, units = dict(ends or {}), dict(units or {})
    if dataset is not None:
        for name in names:
            if name not in ends and name in dataset.coords:
                found = factor_ends(dataset, name)
                if found is not None:
                    ends[name] = found
            if name not in units and name in dataset.coords:
                units[name] = str(dataset[name].attrs.get("units", ""))
    return ends, units


def _real(coded, factor: str, ends: dict):
    return uncode(coded, *ends[factor]) if factor in ends else coded


def _axis_label(factor: str, ends: dict, units: dict) -> str:
    if factor not in ends:
        return f"{factor} (coded)"
    return f"{factor} [{units[factor]}]" if units.get(factor) else factor


def _held_text(name: str, coded: float, ends: dict, units: dict) -> str:
    where = " (centre)" if coded == 0 else ""
    if name not in ends:
        return f"{name} = {coded:.4g} (coded){where}"
    value = float(uncode(coded, *ends[name]))
    return f"{name} = {value:.4g} {units.get(name, '')}".rstrip() + where
