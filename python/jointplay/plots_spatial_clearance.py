"""Figures of a spatial revolute joint with radial and axial clearance (``spatial_clearance_revolute``), as
paper 002 draws them (its Figs. 15-16, 18, 20 and 24):

- the journal's axis in the bore, projected on the bore's section: where it crosses the bore's end
  planes s = -L/2 (``e_a``) and s = +L/2 (``e_b``) and its middle (``e_m``), in the bearing marker's x, y [mm],
  each inside the clearance circle, the samples coloured by the joint's motion mode;
- the journal centre (``e_m``) as a point cloud over the bore's length: section x, y against the axial
  position, inside the cylinder of radius c and the axial range of the flanges;
- the time fractions of the motion modes (free flight, impact, sliding, sustained contact, and axial
  contact apart), from the joint's statistics tracked at every accepted step
  (``Results.summary()["clearance_joints"][joint]["mode_fractions"]``).

Each figure is built by a ``*_figure`` function from a :class:`~jointplay.Results` and a joint name (a
matplotlib Figure, which the tests read back); :func:`spatial_clearance_figures` writes the first two for
every spatial clearance joint of a run (``jointplay plot`` calls it through :mod:`jointplay.plots_spatial`).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from .plots import _figure, _save, _title, sampling_note, set_titles, stopped_note
from .results import Results

#: The element's type in a model.
JOINT_TYPE = "spatial_clearance_revolute"
#: The joint's ``mode`` channel: value -> (name, colour), as paper 002's Fig. 18 colours them where it
#: does (free blue, sliding red, sustained contact green).
MODES = {0: ("free", "tab:blue"), 1: ("impact", "tab:orange"), 2: ("sliding", "tab:red"),
         3: ("sustained", "tab:green")}
#: Keys of the summary's ``mode_fractions``, in the order the bars are drawn.
FRACTION_KEYS = ("free", "impact", "sliding", "sustained", "axial")
#: The three sections of the trajectory figure: (title, prefix of the x and y eccentricity channels).
SECTIONS = (("end A, s = -L/2", "e_a"), ("middle, s = 0", "e_m"), ("end B, s = +L/2", "e_b"))
#: Samples of the point cloud at most (paper 002's Fig. 20 shows one sample in twenty).
CLOUD_POINTS = 4000


def spatial_clearance_joints(results: Results) -> list[str]:
    """Names of the spatial clearance joints recorded in ``results`` (those with a middle eccentricity)."""
    return [name[: -len(".e_m_x")] for name in results.channels if name.endswith(".e_m_x")]


def joint_spec(results: Results, joint: str) -> dict:
    """The joint's entry in the run's model description (empty when the run has none)."""
    for entries in (results.spec or {}).values():
        if isinstance(entries, list):
            for entry in entries:
                if isinstance(entry, dict) and entry.get("name") == joint and entry.get("type") == JOINT_TYPE:
                    return entry
    return {}


def radial_clearance(results: Results, joint: str) -> float | None:
    """The joint's radial clearance c = R_b - R_j [m] from the run's model, None when it does not say."""
    spec = joint_spec(results, joint)
    if spec.get("clearance") is not None:
        return float(spec["clearance"])
    if spec.get("bore_radius") is not None and spec.get("journal_radius") is not None:
        return float(spec["bore_radius"]) - float(spec["journal_radius"])
    return None


def axial_limits(results: Results, joint: str) -> tuple[float, float] | None:
    """The axial positions [mm] where a flange touches its face, -+ half the axial clearance (the journal
    centred between its flanges at 0), from the run's model; None when it does not say."""
    spec = joint_spec(results, joint)
    if spec.get("axial_clearance") is None:
        return None
    half = 0.5e3 * float(spec["axial_clearance"])
    return -half, half


def window_mask(results: Results, window: tuple[float, float] | None) -> np.ndarray:
    """The samples with time in the closed ``window`` (start, end) [s]; all of them for None."""
    t = results.time
    if window is None:
        return np.ones(t.shape, dtype=bool)
    return (t >= window[0]) & (t <= window[1])


def _window_note(window: tuple[float, float] | None) -> str:
    return "whole run" if window is None else f"t = {window[0]:g} to {window[1]:g} s"


def _clearance_circle(ax, c_mm: float) -> None:
    theta = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(c_mm * np.cos(theta), c_mm * np.sin(theta), "k--", lw=0.8, label=f"clearance c = {c_mm:g} mm")
    ax.set_xlim(-1.2 * c_mm, 1.2 * c_mm)
    ax.set_ylim(-1.2 * c_mm, 1.2 * c_mm)


def _mode_scatter(ax, x: np.ndarray, y: np.ndarray, mode: np.ndarray, size: float = 3.0,
                  zs: np.ndarray | None = None) -> None:
    """``ax.scatter`` of (x, y), or of (x, y, zs) on 3D axes, in the colour of each sample's mode, one legend
    entry per mode seen."""
    for value, (name, colour) in MODES.items():
        pick = np.rint(mode) == value
        if np.any(pick):
            depth = {} if zs is None else {"zs": zs[pick]}
            ax.scatter(x[pick], y[pick], s=size, color=colour, label=name, linewidths=0, **depth)


def trajectories_figure(results: Results, joint: str, window: tuple[float, float] | None = None,
                        note: str = "") -> Figure:
    """The journal axis in the bore of ``joint``, projected on the bore's section, at end A, the middle and
    end B [mm, bearing marker's x and y], inside the clearance circle; samples coloured by motion mode, a
    thin line joining them in time. ``window`` (start, end) [s] limits the samples; ``note`` is added to the
    title (e.g. which values were chosen)."""
    fig = _figure(12.0, 4.6)
    axes = fig.subplots(1, 3)
    pick = window_mask(results, window)
    mode = results[f"{joint}.mode"][pick]
    c = radial_clearance(results, joint)
    for ax, (where, prefix) in zip(axes, SECTIONS):
        x, y = results[f"{joint}.{prefix}_x"][pick] * 1e3, results[f"{joint}.{prefix}_y"][pick] * 1e3
        ax.plot(x, y, lw=0.3, color="0.6")
        _mode_scatter(ax, x, y, mode)
        if c is not None:
            _clearance_circle(ax, c * 1e3)
        ax.set_aspect("equal")
        ax.set_title(where, fontsize=9)
        ax.set_xlabel(f"{joint}.{prefix}_x [mm]")
        ax.set_ylabel(f"{joint}.{prefix}_y [mm]")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7, loc="upper right", markerscale=3)
    title = (f"{_title(results)}: journal axis in the bore of {joint}, on the bore's section at both ends and "
             f"the middle (bearing frame; {_window_note(window)}; {sampling_note(results)})")
    set_titles(fig, f"{title}. {note}" if note else title, [stopped_note(results)])
    return fig


def point_cloud_figure(results: Results, joint: str, window: tuple[float, float] | None = None,
                       note: str = "", points: int = CLOUD_POINTS) -> Figure:
    """The journal centre (``e_m``) of ``joint`` as a 3D point cloud: bore-section x and y [mm] against the
    axial position [mm], inside the cylinder of radius c; at most ``points`` samples, evenly thinned,
    coloured by motion mode."""
    fig = _figure(7.5, 6.5)
    ax = fig.add_subplot(projection="3d")
    pick = np.flatnonzero(window_mask(results, window))
    pick = pick[:: max(1, int(np.ceil(pick.size / points)))]
    x, y = results[f"{joint}.e_m_x"][pick] * 1e3, results[f"{joint}.e_m_y"][pick] * 1e3
    z = results[f"{joint}.axial_position"][pick] * 1e3
    _mode_scatter(ax, z, x, results[f"{joint}.mode"][pick], size=2.0, zs=y)
    c = radial_clearance(results, joint)
    ends = axial_limits(results, joint)
    if ends is not None:
        ax.set_xlim(min(ends[0], float(z.min(initial=0.0))), max(ends[1], float(z.max(initial=0.0))))
    if c is not None and ends is not None:
        theta = np.linspace(0.0, 2.0 * np.pi, 73)
        for at in ends:
            ax.plot(np.full_like(theta, at), c * 1e3 * np.cos(theta), c * 1e3 * np.sin(theta), "k--", lw=0.6)
    ax.set_xlabel(f"{joint}.axial_position [mm]")
    ax.set_ylabel(f"{joint}.e_m_x [mm]")
    ax.set_zlabel(f"{joint}.e_m_y [mm]")
    ax.legend(fontsize=7, loc="upper left", markerscale=3)
    title = (f"{_title(results)}: journal centre in the bore of {joint} over the bore's length, "
             f"{pick.size} samples ({_window_note(window)}); dashed: clearance circle where a flange touches "
             "(axial position -+ half the axial clearance)")
    set_titles(fig, f"{title}. {note}" if note else title, [stopped_note(results)])
    return fig


def mode_fractions(results: Results, joint: str) -> dict[str, float]:
    """The joint's time fractions by motion mode over the run, tracked at every accepted step (free, impact,
    sliding, sustained sum to 1; axial: the fraction of time a flange touches)."""
    return {key: float(value) for key, value in
            results.summary()["clearance_joints"][joint]["mode_fractions"].items()}


def mode_fraction(results: Results, joint: str, mode: str) -> float:
    """One of :func:`mode_fractions` (``mode`` one of :data:`FRACTION_KEYS`): a study's response of a run,
    ``functools.partial(mode_fraction, joint=..., mode=...)``."""
    return mode_fractions(results, joint)[mode]


def mode_fractions_figure(results: Results, joints: Sequence[str] | None = None, note: str = "") -> Figure:
    """Bars of the motion-mode time fractions of each joint in ``joints`` (default: every spatial clearance
    joint of the run), side by side per mode."""
    names = list(joints) if joints is not None else spatial_clearance_joints(results)
    fig = _figure(7.5, 4.2)
    ax = fig.subplots()
    width = 0.8 / max(1, len(names))
    at = np.arange(len(FRACTION_KEYS))
    for k, joint in enumerate(names):
        fractions = mode_fractions(results, joint)
        values = [fractions.get(key, np.nan) for key in FRACTION_KEYS]
        bars = ax.bar(at + (k - (len(names) - 1) / 2) * width, values, width, label=joint)
        ax.bar_label(bars, fmt="%.3f", fontsize=7)
    ax.set_xticks(at, [f"{key}" if key != "axial" else "axial contact" for key in FRACTION_KEYS])
    ax.set_ylabel("fraction of time [-]")
    ax.set_ylim(0.0, 1.08)
    ax.grid(alpha=0.3, axis="y")
    ax.legend(fontsize=8)
    title = (f"{_title(results)}: time fractions of the motion modes over every accepted step "
             "(free, impact, sliding, sustained sum to 1; axial contact apart)")
    set_titles(fig, f"{title}. {note}" if note else title, [stopped_note(results)])
    return fig


def spatial_clearance_figures(results: Results, out: Path, fmt: str) -> list[Path]:
    """Writes, for every spatial clearance joint of ``results``, its trajectories in the bore
    (``trajectories_<joint>``) and its point cloud (``point_cloud_<joint>``) into the folder ``out``; returns
    their paths."""
    paths = []
    for joint in spatial_clearance_joints(results):
        paths.append(_save(trajectories_figure(results, joint), out / f"trajectories_{joint}.{fmt}"))
        paths.append(_save(point_cloud_figure(results, joint), out / f"point_cloud_{joint}.{fmt}"))
    return paths
