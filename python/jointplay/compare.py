"""Comparing runs: the same channels of several results overlaid, and a table of their peaks.

The usual comparison is ideal joint vs dry clearance vs lubricated joint of
one mechanism; channels that a run does not have (an ideal joint records no
``B.fn``) are left out of that run's curve.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from .plots import (FORMATS, _figure, _save, clearance_joints, crank_angle_deg, default_channels, figure_folder,
                    sampling_note, tracked_peak_point)
from .results import Results


def default_compare_channels(runs: Sequence[Results]) -> list[str]:
    """Channels worth overlaying: the first run's key channels and the joint forces
    (``<joint>.f``) of its clearance joints, kept when at least two runs have them."""
    first = runs[0]
    candidates = default_channels(first)
    for run in runs:
        candidates += [f"{j}.f" for j in clearance_joints(run)]
    need = min(2, len(runs))
    return list(dict.fromkeys(c for c in candidates if sum(c in r for r in runs) >= need))


def overlay(runs: Sequence[Results], labels: Sequence[str], channel: str, path: Path,
            crank: str | None = None) -> Path:
    """One channel of every run that has it, against time [ms] or the crank angle [deg]: the saved
    samples, and a dot in the run's colour at its extremum tracked over every accepted step."""
    fig = _figure(7.5, 3.6)
    ax = fig.subplots()
    unit, marked = "", False
    for run, label in zip(runs, labels):
        if channel not in run:
            continue
        unit = run.unit(channel)
        x = crank_angle_deg(run, crank) if crank else run.time * 1e3
        line, = ax.plot(x, run[channel], lw=0.8, label=f"{label} ({sampling_note(run)})")
        peak = tracked_peak_point(run, channel)
        if peak is not None and run.time.size > 1:
            at = np.interp(peak[0], run.time, x) if crank else peak[0] * 1e3
            ax.plot(at, peak[1], "o", ms=4, color=line.get_color())
            marked = True
    ax.set_xlabel(f"crank angle ({crank}.angle) [deg]" if crank else "time [ms]")
    ax.set_ylabel(f"{channel} [{unit}]")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    ax.set_title(channel + ("; dots: extrema over every accepted step" if marked else ""), fontsize=10)
    return _save(fig, path)


def compare_figures(runs: Sequence[Results], labels: Sequence[str], out_dir, channels: Sequence[str] | None = None,
                    fmt: str = "png", crank: str | None = None) -> list[Path]:
    """Writes one overlay figure per channel into ``out_dir``; returns the paths."""
    if fmt not in FORMATS:
        raise ValueError(f"format must be one of {', '.join(FORMATS)}, got {fmt!r}")
    names = list(channels) if channels else default_compare_channels(runs)
    for name in names:
        if not any(name in run for run in runs):
            runs[0][name]  # KeyError with a did-you-mean hint
    if crank is not None:
        for k, run in enumerate(runs):
            if f"{crank}.angle" not in run:
                raise ValueError(f"crank: run {k} ({labels[k]}) has no body {crank!r} (no channel {crank}.angle)")
    out = figure_folder(out_dir)
    return [overlay(runs, labels, name, out / f"compare_{name.replace('.', '_')}.{fmt}", crank) for name in names]


def peak_table(runs: Sequence[Results], channels: Sequence[str]) -> list[list[str]]:
    """Rows ``[channel, unit, peak |value| of each run]`` (``-`` where a run lacks the channel).

    Peaks of force, moment, acceleration and pressure channels and the penetration and eccentricity
    ratio of clearance joints come from :attr:`Results.extrema`, tracked at every accepted step
    whatever the output step. Other channels (positions, velocities) and results files written before
    the extrema were tracked use the saved samples, and such a peak is marked ``(samples)``: it may
    miss what happens between two samples.
    """
    rows = []
    for name in channels:
        unit = next((r.unit(name) for r in runs if name in r), "")
        rows.append([name, unit, *(_peak_cell(r, name) for r in runs)])
    return rows


def _peak_cell(run: Results, name: str) -> str:
    """Peak |value| of one channel of one run, as text."""
    if name not in run or not len(run):
        return "-"
    tracked = tracked_peak(run, name)
    if tracked is not None:
        return f"{tracked:.4g}"
    return f"{np.max(np.abs(run[name])):.4g} (samples)"


def tracked_peak(run: Results, name: str) -> float | None:
    """The peak |value| of a channel tracked at every accepted step, if the run has it."""
    if run.extrema is None:
        return None
    channel = run.extrema.get("channels", {}).get(name)
    if channel is not None:
        return float(channel["peak"])
    element, _, quantity = name.rpartition(".")
    joint = run.extrema.get("clearance_joints", {}).get(element)
    key = {"penetration": "max_penetration", "eccentricity_ratio": "max_eccentricity_ratio"}.get(quantity)
    if joint is not None and joint.get(key) is not None:
        return float(joint[key])
    return None
