"""The standard figures of a run of a spatial model (docs/getting-started.md, "Results of spatial models").

- the centre-of-mass paths of the bodies in three projections (x-y, x-z, y-z, in mm, equal scales);
- per body, its orientation as the Euler angles of its sequence (``<body>.euler_<seq>_1..3``, as recorded,
  in degrees) and its angular velocity about the global axes (``<body>.wx_global..wz_global``);
- per ideal joint, its reaction on the second body: the force (``fx, fy, fz`` and the magnitude ``f``) and the
  moment about the second marker's point (``mx, my, mz``), in global components;
- per spatial clearance joint, the journal's trajectories in the bore and its point cloud over the bore's
  length (:mod:`jointplay.plots_spatial_clearance`).

Each figure is built by a ``*_figure`` function (a matplotlib Figure, which the tests read back) and written
by :func:`spatial_figures`.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from .plots import _figure, _save, _time_scale, _title, sampling_note, set_titles, stopped_note
from .results import Results

#: The projections of the path figure: (horizontal, vertical) axis of each panel.
PROJECTIONS = (("x", "y"), ("x", "z"), ("y", "z"))
#: Angular velocity channels about the global axes.
GLOBAL_RATES = ("wx_global", "wy_global", "wz_global")


def spatial_bodies(results: Results) -> list[str]:
    """Names of the spatial rigid bodies recorded in ``results`` (those with a quaternion channel)."""
    return [name[: -len(".qw")] for name in results.channels if name.endswith(".qw")]


def spatial_joints(results: Results) -> list[str]:
    """Names of the spatial ideal joints recorded in ``results`` (those with a global reaction moment)."""
    return [name[: -len(".mx")] for name in results.channels
            if name.endswith(".mx") and f"{name[: -len('.mx')]}.joint_mx" in results]


def euler_channels(results: Results, body: str) -> list[str]:
    """The three Euler-angle channels of ``body``, ``<body>.euler_<sequence>_1..3``."""
    pattern = re.compile(rf"{re.escape(body)}\.euler_[a-z]{{3}}_[123]")
    return sorted(name for name in results.channels if pattern.fullmatch(name))


def paths_figure(results: Results) -> Figure:
    """Centre-of-mass paths [mm] of every body in three projections, a dot at each start."""
    fig = _figure(11.0, 4.2)
    axes = fig.subplots(1, 3)
    for ax, (h, v) in zip(axes, PROJECTIONS):
        for k, body in enumerate(spatial_bodies(results)):
            colour = f"C{k % 10}"
            x, y = results[f"{body}.{h}"] * 1e3, results[f"{body}.{v}"] * 1e3
            ax.plot(x, y, lw=0.9, color=colour, label=body)
            ax.plot(x[:1], y[:1], "o", ms=3, color=colour)
        ax.set_xlabel(f"{h} [mm]")
        ax.set_ylabel(f"{v} [mm]")
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    set_titles(fig, f"{_title(results)}: centre-of-mass paths of the bodies, projected on the x-y, x-z and "
                    f"y-z planes (dots: start); {sampling_note(results)}", [stopped_note(results)])
    return fig


def orientation_figure(results: Results, body: str) -> Figure:
    """Euler angles [deg] of ``body`` (its sequence, intrinsic, as recorded) and its angular velocity about
    the global axes [rad/s] against time."""
    fig = _figure(7.5, 5.0)
    top, bottom = fig.subplots(2, 1, sharex=True)
    scale, unit = _time_scale(results)
    t = results.time * scale
    names = euler_channels(results, body)
    sequence = names[0].split("_")[-2].upper() if names else ""
    for k, name in enumerate(names, start=1):
        top.plot(t, np.degrees(results[name]), lw=0.9, label=f"angle {k} ({name})")
    top.set_ylabel(f"Euler angles {sequence}\n[deg]", fontsize=8)
    for name in GLOBAL_RATES:
        bottom.plot(t, results[f"{body}.{name}"], lw=0.9, label=f"{body}.{name}")
    bottom.set_ylabel("angular velocity,\nglobal axes [rad/s]", fontsize=8)
    bottom.set_xlabel(f"time [{unit}]")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper right")
    set_titles(fig, f"{_title(results)}: orientation of {body} (intrinsic {sequence} Euler angles, each in "
                    f"(-180, 180] deg) and its angular velocity about the global axes", [stopped_note(results)])
    return fig


def reactions_figure(results: Results, joint: str) -> Figure:
    """The reaction of ``joint`` on its second body against time: force components and magnitude [N], moment
    about the second marker's point [N m], global axes."""
    fig = _figure(7.5, 5.0)
    top, bottom = fig.subplots(2, 1, sharex=True)
    scale, unit = _time_scale(results)
    t = results.time * scale
    for quantity in ("fx", "fy", "fz", "f"):
        style = {"color": "black", "ls": "--", "lw": 1.0} if quantity == "f" else {"lw": 0.9}
        top.plot(t, results[f"{joint}.{quantity}"], label=f"{joint}.{quantity}", **style)
    for quantity in ("mx", "my", "mz"):
        bottom.plot(t, results[f"{joint}.{quantity}"], lw=0.9, label=f"{joint}.{quantity}")
    top.set_ylabel(f"force [{results.unit(f'{joint}.fx')}]", fontsize=8)
    bottom.set_ylabel(f"moment [{results.unit(f'{joint}.mx')}]", fontsize=8)
    bottom.set_xlabel(f"time [{unit}]")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper right")
    set_titles(fig, f"{_title(results)}: reaction of joint {joint} on its second body, force and moment about "
                    "its point, global axes", [stopped_note(results)])
    return fig


def spatial_figures(results: Results, out: Path, fmt: str) -> list[Path]:
    """Writes the figures of the spatial bodies and joints of ``results`` into the folder ``out``: ``paths``,
    ``orientation_<body>``, ``reactions_<joint>`` and, per spatial clearance joint, ``trajectories_<joint>`` and
    ``point_cloud_<joint>``; returns their paths (none for a planar run)."""
    bodies = spatial_bodies(results)
    if not bodies:
        return []
    paths = [_save(paths_figure(results), out / f"paths.{fmt}")]
    for body in bodies:
        paths.append(_save(orientation_figure(results, body), out / f"orientation_{body}.{fmt}"))
    for joint in spatial_joints(results):
        paths.append(_save(reactions_figure(results, joint), out / f"reactions_{joint}.{fmt}"))
    from .plots_spatial_clearance import spatial_clearance_figures

    return paths + spatial_clearance_figures(results, out, fmt)
