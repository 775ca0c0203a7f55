"""Interactive figures of a report (plotly), drawn from a run's saved samples.

A browser slows down with traces of hundreds of thousands of points, so a long run is drawn thinned by
:func:`keep_indices`: at most :data:`MAX_POINTS` points per trace, each of ``MAX_POINTS / 2`` equal spans of
samples keeping its smallest and largest value, so that peaks show at their true height (:data:`THINNING`
says so in each caption). The numbers of a report (its summary) never come from the thinned data.

Times are drawn in the unit that fits the run (:func:`jointplay.display.time_unit`); every axis title carries
its unit.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..display import time_unit
from ..results import Results

#: Points per trace at most in a report's plots.
MAX_POINTS = 4000
#: Spans a thinned trace is cut into: each keeps two points, and the first and last samples are kept too.
SPANS = (MAX_POINTS - 2) // 2
#: What a caption says of a plot thinned by :func:`keep_indices`.
THINNING = (f"Runs with more than {MAX_POINTS} saved samples are drawn with at most {MAX_POINTS} points per "
            f"trace: each of {SPANS} equal spans of samples keeps its smallest and largest value (and the first "
            "and last samples are kept), so peaks show at their true height.")


def keep_indices(arrays: Sequence[np.ndarray], max_points: int = MAX_POINTS) -> np.ndarray:
    """Indices of the samples drawn: all of them when there are at most ``max_points``; else, in each of
    ``(max_points - 2) // (2 * len(arrays))`` equal spans of samples (:data:`SPANS` for one array), those of the
    smallest and largest value of every array (the union, in order), and the first and last samples."""
    n = len(arrays[0]) if arrays else 0
    if n <= max_points:
        return np.arange(n)
    spans = max(1, (max_points - 2) // (2 * len(arrays)))
    edges = np.linspace(0, n, spans + 1).astype(int)
    keep = {0, n - 1}
    for array in arrays:
        values = np.asarray(array, dtype=float)
        for start, stop in zip(edges[:-1], edges[1:]):
            if stop > start:
                piece = values[start:stop]
                if np.all(np.isnan(piece)):
                    continue
                keep.add(start + int(np.nanargmin(piece)))
                keep.add(start + int(np.nanargmax(piece)))
    return np.array(sorted(keep))


def thinned(results: Results, channels: Sequence[str]) -> tuple[np.ndarray, bool]:
    """The indices of the samples to draw for ``channels`` together, and whether any was left out."""
    rows = keep_indices([results[c] for c in channels]) if channels else np.arange(len(results))
    return rows, rows.size < len(results)


def time_scale(*runs: Results) -> tuple[float, str]:
    """The unit of time that fits the longest of ``runs``: (factor from seconds, unit)."""
    end = max((float(np.max(np.abs(r.time[[0, -1]]))) for r in runs if r.time.size), default=0.0)
    unit, seconds = time_unit(end)
    return 1.0 / seconds, unit


def axis_label(name: str, unit: str) -> str:
    """``"B.fn [N]"``; ``"[-]"`` for a plain number."""
    return f"{name} [{unit or '-'}]"


def history_figure(results: Results, title: str, panels: Sequence[Sequence[str]]):
    """Time histories: one panel per entry of ``panels`` (channels of one unit, overlaid), a shared time
    axis; the y axis of a panel titled with its channels' unit. Returns (figure, thinned)."""
    from plotly.subplots import make_subplots

    panels = [list(p) for p in panels if p]
    fig = make_subplots(rows=len(panels), cols=1, shared_xaxes=True, vertical_spacing=0.06)
    scale, unit = time_scale(results)
    any_thinned = False
    for k, panel in enumerate(panels, start=1):
        for name in panel:
            rows, was_thinned = thinned(results, [name])
            any_thinned |= was_thinned
            fig.add_scatter(x=results.time[rows] * scale, y=results[name][rows], mode="lines", name=name,
                            row=k, col=1, line={"width": 1.2})
        _tracked_peaks(fig, results, panel, scale, k)
        units = sorted({results.unit(c) for c in panel})
        label = ", ".join(panel) if len(panel) <= 3 else "value"
        fig.update_yaxes(title_text=axis_label(label, " / ".join(units)), row=k, col=1)
    fig.update_xaxes(title_text=f"time [{unit}]", row=len(panels), col=1)
    _layout(fig, title, height=200 + 190 * len(panels))
    return fig, any_thinned


#: The name of the markers of the peaks tracked at every accepted step.
PEAKS_NAME = "peak over every accepted step"


def _tracked_peaks(fig, results: Results, panel: Sequence[str], scale: float, row: int) -> None:
    """Markers at the extrema of ``panel``'s channels tracked at every accepted step (which saved samples can
    miss), one trace for the panel."""
    from ..plots import tracked_peak_point

    points = [p for p in (tracked_peak_point(results, name) for name in panel) if p is not None]
    if points:
        shown = any(trace.name == PEAKS_NAME for trace in fig.data)
        fig.add_scatter(x=[p[0] * scale for p in points], y=[p[1] for p in points], mode="markers",
                        name=PEAKS_NAME, legendgroup="peaks", showlegend=not shown,
                        marker={"color": "crimson", "size": 7, "symbol": "circle-open"}, row=row, col=1)


def orbit_figure(results: Results, joint: str, clearance: float | None):
    """The journal centre's path (``<joint>.ex``, ``.ey`` in mm) inside the clearance circle of radius
    ``clearance`` [m], equal scales. Returns (figure, thinned)."""
    import plotly.graph_objects as go

    rows, was_thinned = thinned(results, [f"{joint}.ex", f"{joint}.ey"])
    ex, ey = results[f"{joint}.ex"][rows] * 1e3, results[f"{joint}.ey"][rows] * 1e3
    fig = go.Figure()
    fig.add_scatter(x=ex, y=ey, mode="lines", name="journal centre", line={"width": 1})
    if clearance is not None:
        theta = np.linspace(0.0, 2.0 * np.pi, 361)
        c = clearance * 1e3
        fig.add_scatter(x=c * np.cos(theta), y=c * np.sin(theta), mode="lines", name=f"clearance c = {c:g} mm",
                        line={"dash": "dash", "color": "black", "width": 1})
    if ex.size:
        fig.add_scatter(x=ex[:1], y=ey[:1], mode="markers", name="start", marker={"color": "black", "size": 7})
    fig.update_xaxes(title_text=f"{joint}.ex [mm]")
    fig.update_yaxes(title_text=f"{joint}.ey [mm]", scaleanchor="x", scaleratio=1)
    _layout(fig, f"Journal-centre orbit in {joint} (eccentricity, mm)", height=560, width=620)
    return fig, was_thinned


def overlay_figure(runs: Sequence[Results], labels: Sequence[str], channel: str):
    """One channel of every run that has it against time, a trace per run. Returns (figure, thinned)."""
    import plotly.graph_objects as go

    fig = go.Figure()
    scale, unit = time_scale(*runs)
    any_thinned = False
    for run, label in zip(runs, labels):
        if channel not in run:
            continue
        rows, was_thinned = thinned(run, [channel])
        any_thinned |= was_thinned
        fig.add_scatter(x=run.time[rows] * scale, y=run[channel][rows], mode="lines", name=label,
                        line={"width": 1.2})
    channel_unit = next((r.unit(channel) for r in runs if channel in r), "")
    fig.update_xaxes(title_text=f"time [{unit}]")
    fig.update_yaxes(title_text=axis_label(channel, channel_unit))
    _layout(fig, f"{channel}, each run", height=420)
    return fig, any_thinned


def bars_figure(title: str, categories: Sequence[str], series: dict[str, Sequence[float]], y_title: str):
    """Bars of ``series`` (name -> a value per category), side by side per category."""
    import plotly.graph_objects as go

    fig = go.Figure()
    for name, values in series.items():
        fig.add_bar(x=list(categories), y=list(values), name=name, text=[f"{v:.3f}" for v in values])
    fig.update_yaxes(title_text=y_title)
    _layout(fig, title, height=420)
    fig.update_layout(barmode="group")
    return fig


def _layout(fig, title: str, height: int, width: int | None = None) -> None:
    fig.update_layout(title={"text": title, "x": 0.02}, height=height, width=width, template="plotly_white",
                      margin={"l": 70, "r": 20, "t": 60, "b": 50}, legend={"font": {"size": 11}})
