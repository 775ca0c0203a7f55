"""Comparing runs: the same channels of several results overlaid, and a table of their peaks.

The usual comparison is ideal joint vs dry clearance vs lubricated joint of
one mechanism; channels that a run does not have (an ideal joint records no
``B.fn``) are left out of that run's curve. Runs with no channel to overlay
are refused with a message saying what each run has.

The runs are drawn in order, each with a narrower line and another dash
pattern than the one before, so that where two curves coincide the first
shows on both sides of the later ones and between their dashes.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from .plots import (FORMATS, _figure, _save, _time_scale, clearance_joints, crank_angle_deg, default_channels,
                    figure_folder, sampling_note, set_titles, stopped_note, tracked_peak_point)
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


def shared_channels(runs: Sequence[Results]) -> list[str]:
    """Channels that at least two of ``runs`` have (all of them for a single run), in the runs' order."""
    names = list(dict.fromkeys(n for run in runs for n in run.channels))
    return [n for n in names if sum(n in run for run in runs) >= min(2, len(runs))]


def nothing_to_compare(runs: Sequence[Results], labels: Sequence[str]) -> str:
    """Why :func:`default_compare_channels` found nothing: no channel in common, or none of the key
    channels among those in common; what each run has, and how to choose channels."""
    def has(run: Results, label: str) -> str:
        first = ", ".join(run.channels[:4])
        more = ", ..." if len(run.channels) > 4 else ""
        n = len(run.channels)
        return f"{label}: {n} channel{'s' if n != 1 else ''} ({first}{more})"

    shared = shared_channels(runs)
    each = "; ".join(has(run, label) for run, label in zip(runs, labels))
    if not shared:
        return f"the runs have no channel in common, nothing to overlay ({each})"
    listed = ", ".join(shared[:6]) + (", ..." if len(shared) > 6 else "")
    return (f"none of the key channels of {labels[0]} is in another run; the runs share {len(shared)} other "
            f"channel(s) ({listed}): choose them with --channel")


#: Line of the k-th run drawn: dash pattern (cycled); the first run's line is the widest.
LINE_STYLES = ("-", "--", "-.", ":")


def run_style(k: int, n: int) -> dict:
    """Matplotlib line properties of run ``k`` of ``n``: each run narrower than the one before (the last
    0.8 pt, the first at most 2.9 pt), with its own dash pattern, and drawn above it, so that no run hides
    an earlier one where they coincide."""
    return {"lw": 0.8 + 0.7 * min(n - 1 - k, 3), "ls": LINE_STYLES[k % len(LINE_STYLES)], "zorder": 2 + k}


def overlay(runs: Sequence[Results], labels: Sequence[str], channel: str, path: Path,
            crank: str | None = None) -> Path:
    """One channel of every run that has it, against time (in the unit that fits the longest run) or the
    crank angle [deg]: the saved samples (styles from :func:`run_style`), and a dot in the run's colour at
    its extremum tracked over every accepted step. Runs that stopped early are named above the axes."""
    fig = _figure(7.5, 3.6)
    ax = fig.subplots()
    unit, marked = "", False
    scale, time_unit = _time_scale(*runs)
    for k, (run, label) in enumerate(zip(runs, labels)):
        if channel not in run:
            continue
        unit = run.unit(channel)
        x = crank_angle_deg(run, crank) if crank else run.time * scale
        line, = ax.plot(x, run[channel], label=f"{label} ({sampling_note(run)})", color=f"C{k % 10}",
                        **run_style(k, len(runs)))
        peak = tracked_peak_point(run, channel)
        if peak is not None and run.time.size > 1:
            at = np.interp(peak[0], run.time, x) if crank else peak[0] * scale
            ax.plot(at, peak[1], "o", ms=4 + 2 * (len(runs) - 1 - k), color=line.get_color(), zorder=2 + len(runs))
            marked = True
    ax.set_xlabel(f"crank angle ({crank}.angle) [deg]" if crank else f"time [{time_unit}]")
    ax.set_ylabel(f"{channel} [{unit}]")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    notes = [stopped_note(run, label) for run, label in zip(runs, labels)]
    set_titles(fig, channel + ("; dots: extrema over every accepted step" if marked else ""), notes, fontsize=10)
    return _save(fig, path)


def compare_figures(runs: Sequence[Results], labels: Sequence[str], out_dir, channels: Sequence[str] | None = None,
                    fmt: str = "png", crank: str | None = None) -> list[Path]:
    """Writes one overlay figure per channel into ``out_dir``; returns the paths."""
    if fmt not in FORMATS:
        raise ValueError(f"format must be one of {', '.join(FORMATS)}, got {fmt!r}")
    names = list(channels) if channels else default_compare_channels(runs)
    if not names:
        raise ValueError(f"nothing to compare: {nothing_to_compare(runs, labels)}")
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
