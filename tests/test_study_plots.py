"""Study figures: the plotted main effects and interactions equal group means computed here, binning of
continuous designs is said in the title, and every axis carries its units; the contour is drawn in the
factors' real units with the held values in its title."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from jointplay.errors import ModelError
from jointplay.study import designs, plots
from jointplay.study.surface import fit_response

#: Factors of the test study: name, units, value at coded -1, value at coded +1.
FACTORS = [("clearance", "m", 10e-6, 30e-6), ("speed", "rad/s", 50.0, 150.0), ("mass", "kg", 1.0, 3.0)]


def study_dataset(coded: np.ndarray, failed=()) -> xr.Dataset:
    """A Dataset as a study writes it: SI factor coordinates with units, coded points, one response."""
    coords = {"case": np.arange(len(coded)), "factor": [f[0] for f in FACTORS]}
    for j, (name, units, low, high) in enumerate(FACTORS):
        coords[name] = ("case", designs.uncode(coded[:, j], low, high), {"units": units, "path": f"p.{name}",
                                                                          "long_name": name})
    c, s, m = coded.T
    force = 100.0 + 20.0 * c + 5.0 * s**2 - 8.0 * c * s + 3.0 * m
    force[list(failed)] = np.nan
    status = np.where(np.isfinite(force), "done", "failed")
    attrs = {"units": "N", "long_name": "peak_force", "definition": "max |f|"}
    return xr.Dataset({"coded": (("case", "factor"), coded), "peak_force": ("case", force, attrs),
                       "status": ("case", status), "error": ("case", np.where(status == "done", "", "boom"))},
                      coords=coords)


def plotted(ax) -> tuple[np.ndarray, np.ndarray]:
    line = ax.get_lines()[0]
    return np.asarray(line.get_xdata(), dtype=float), np.asarray(line.get_ydata(), dtype=float)


def test_main_effects_are_the_mean_response_at_each_level():
    ds = study_dataset(designs.full_factorial([3, 3, 2]), failed=[4])
    fig = plots.main_effects(ds, "peak_force")
    y = ds["peak_force"].values
    for ax, (name, units, _, _) in zip(fig.axes, FACTORS, strict=True):
        x, means = plotted(ax)
        values = ds[name].values
        levels = sorted(set(values))
        expected = [np.mean([yk for vk, yk in zip(values, y, strict=True) if vk == level and not np.isnan(yk)])
                    for level in levels]
        np.testing.assert_allclose(x, levels, rtol=1e-15)
        np.testing.assert_allclose(means, expected, rtol=1e-12)
        assert ax.get_xlabel() == f"{name} [{units}]"
    assert fig.axes[0].get_ylabel() == "mean peak_force [N]"
    title = fig.get_suptitle()
    assert title.startswith("Main effects on peak_force [N]") and "1 failed cases left out" in title
    assert "binned" not in title


def test_main_effects_of_a_continuous_design_are_binned_and_say_so():
    ds = study_dataset(designs.latin_hypercube(40, 3, seed=2))
    fig = plots.main_effects(ds, "peak_force", bins=4)
    values, y = ds["speed"].values, ds["peak_force"].values
    edges = np.linspace(values.min(), values.max(), 5)
    expected = []
    for b in range(4):
        inside = (values >= edges[b]) & ((values < edges[b + 1]) if b < 3 else (values <= edges[b + 1]))
        expected.append(y[inside].mean())
    x, means = plotted(fig.axes[1])
    np.testing.assert_allclose(x, 0.5 * (edges[:-1] + edges[1:]), rtol=1e-12)
    np.testing.assert_allclose(means, expected, rtol=1e-12)
    assert "clearance, speed, mass binned into 4 equal-width intervals (continuous design)" in fig.get_suptitle()


def test_interaction_lines_are_means_per_pair_of_levels():
    ds = study_dataset(designs.full_factorial([3, 3, 3]))
    fig = plots.interactions(ds, "peak_force", "clearance", "speed")
    ax = fig.axes[0]
    clearance, speed, y = ds["clearance"].values, ds["speed"].values, ds["peak_force"].values
    for line, level in zip(ax.get_lines(), sorted(set(speed)), strict=True):
        expected = [y[(clearance == c) & (speed == level)].mean() for c in sorted(set(clearance))]
        np.testing.assert_allclose(line.get_ydata(), expected, rtol=1e-12)
        assert line.get_label() == f"speed = {level:.4g} rad/s"
    assert ax.get_xlabel() == "clearance [m]" and ax.get_ylabel() == "mean peak_force [N]"
    assert fig.get_suptitle() == "Interaction of clearance and speed on peak_force [N]"


def test_contour_is_drawn_in_real_units_with_the_held_values():
    ds = study_dataset(designs.central_composite(3, face="faced"))
    surface = fit_response(ds, "peak_force")
    fig = plots.contour(surface, "clearance", "speed", fixed={"mass": 2.5}, dataset=ds)
    ax = fig.axes[0]
    assert ax.get_xlabel() == "clearance [m]" and ax.get_ylabel() == "speed [rad/s]"
    assert ax.get_xlim() == pytest.approx((10e-6, 30e-6)) and ax.get_ylim() == pytest.approx((50.0, 150.0))
    title = fig.get_suptitle()
    assert title.startswith("peak_force [N]: quadratic surface over clearance and speed\n(trustworthy")
    assert title.endswith("held: mass = 2.5 kg")
    assert fig.axes[1].get_ylabel() == "peak_force [N]"  # the colour bar


def test_contour_levels_follow_the_surface():
    """The filled contours span the surface's values over the plotted box (mass held at its centre)."""
    ds = study_dataset(designs.full_factorial([3, 3, 3]))
    surface = fit_response(ds, "peak_force")
    fig = plots.contour(surface, "clearance", "speed", dataset=ds)
    grid = np.linspace(-1.0, 1.0, 61)
    c, s = np.meshgrid(grid, grid)
    exact = 100.0 + 20.0 * c + 5.0 * s**2 - 8.0 * c * s
    levels = fig.axes[0].collections[0].levels
    assert levels[0] <= exact.min() and levels[-1] >= exact.max()
    assert "held: mass = 2 kg (centre)" in fig.get_suptitle()


def test_factor_ends_come_from_the_cases():
    ds = study_dataset(designs.latin_hypercube(10, 3, seed=0))
    assert plots.factor_ends(ds, "speed") == pytest.approx((50.0, 150.0), rel=1e-12)


def test_plots_name_a_bad_response_or_factor():
    ds = study_dataset(designs.full_factorial([2, 2, 2]))
    with pytest.raises(ModelError, match=r"plot.response: must name a response of the study, got 'force'"):
        plots.main_effects(ds, "force")
    with pytest.raises(ModelError, match=r"plot.factor: must name a factor of the study .*got 'gap'"):
        plots.interactions(ds, "peak_force", "gap", "speed")
