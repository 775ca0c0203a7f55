"""The standard figures of a run, written to PNG or SVG files.

- time histories of chosen channels (one panel each, shared time axis in the unit that fits the run);
- the journal-centre orbit of each clearance joint inside its clearance circle
  (eccentricity in mm, circle of radius c);
- the contact force of each clearance joint against the crank angle
  (degrees, unwrapped from the start so that two revolutions read 0-720);
- the deformed shape of each beam at chosen times, its deformation (from the
  rigid motion that best fits its nodes) magnified by a factor the figure
  states; and the histories of each strain gauge;
- for a spatial model, the centre-of-mass paths, orientations, angular
  velocities and joint reactions of :mod:`jointplay.plots_spatial`.

Every figure of a run that stopped early (a ``.partial.nc``) says so in red
above its axes: ``run stopped at t = 0.0123 s: <cause>``. Titles are broken
between words to fit the figure's width. Times are in the unit that fits the
run's length (:func:`jointplay.display.time_unit`).

Figures are built with matplotlib's object API on the Agg canvas: no display
is needed and no global pyplot state is touched.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties

from .display import format_time, time_unit
from .results import Results

FORMATS = ("png", "svg")
MAX_DEFAULT_CHANNELS = 8


def _figure(width: float = 7.0, height: float = 4.0) -> Figure:
    fig = Figure(figsize=(width, height), layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def _save(fig: Figure, path: Path) -> Path:
    fig.savefig(path, dpi=130)
    return path


def wrap_to_width(fig: Figure, text: str, fontsize: float, fraction: float = 0.96) -> str:
    """``text`` with each line broken between words so that it is at most ``fraction`` of the
    figure's width at ``fontsize`` [pt], measured with the figure's renderer."""
    renderer = fig.canvas.get_renderer()
    font = FontProperties(size=fontsize)
    limit = fraction * fig.bbox.width

    def width(line: str) -> float:
        return renderer.get_text_width_height_descent(line, font, ismath=False)[0]

    lines = []
    for paragraph in text.split("\n"):
        line = ""
        for word in paragraph.split(" "):
            trial = f"{line} {word}" if line else word
            if line and width(trial) > limit:
                lines.append(line)
                line = word
            else:
                line = trial
        lines.append(line)
    return "\n".join(lines)


def stopped_note(results: Results, label: str | None = None) -> str | None:
    """``"run stopped at t = 0.0123 s: <cause>"`` for results of a run that stopped early (a
    ``.partial.nc``), else None; ``label`` names the run among several."""
    if results.error is None:
        return None
    error = results.error
    when = error.get("time")
    if when is None and results.time.size:
        when = float(results.time[-1])
    at = f" at t = {float(when):.6g} s" if when is not None else ""
    cause = str(error.get("message") or error.get("kind") or "unknown cause")
    return f"{'run ' + label if label else 'run'} stopped{at}: {cause}"


def set_titles(fig: Figure, title: str, notes: Sequence[str | None] = (), fontsize: float = 9) -> None:
    """The figure's title (wrapped to its width) and, above the axes in red, the note of each run
    that stopped early."""
    fig.suptitle(wrap_to_width(fig, title, fontsize), fontsize=fontsize)
    stopped = [note for note in notes if note]
    if stopped:
        top = max(fig.axes, key=lambda ax: ax.get_position().y1)
        # the axes sit right of their y labels: the note, centred on them, kept to 0.72 of the width
        top.set_title(wrap_to_width(fig, "\n".join(stopped), 8, 0.72), fontsize=8, color="tab:red")


def figure_folder(out_dir) -> Path:
    """``out_dir`` as a folder, created if needed; ``NotADirectoryError`` when it is a file."""
    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise NotADirectoryError(f"{out} is a file; figures are written into a folder")
    out.mkdir(parents=True, exist_ok=True)
    return out


def clearance_joints(results: Results) -> list[str]:
    """Names of the clearance joints recorded in ``results``."""
    return [n.rsplit(".", 1)[0] for n in results.channels if n.endswith(".contact")]


def guess_crank(results: Results) -> str | None:
    """The body turned by the first driver of a revolute joint to the ground, if any."""
    spec = results.spec or {}
    joints = {j["name"]: j for j in spec.get("joints", [])}
    for driver in spec.get("drivers", []):
        joint = joints.get(driver["joint"])
        if joint and joint["type"] == "revolute":
            first, second = joint["first"].split(".")[0], joint["second"].split(".")[0]
            body = second if first == "ground" else first if second == "ground" else second
            if f"{body}.angle" in results:
                return body
    return None


def default_channels(results: Results) -> list[str]:
    """Key channels: slider accelerations, clearance-joint contact forces and eccentricity ratios (with the
    film force and minimum film thickness of a lubricated joint), hydraulic-cylinder pressures and strokes,
    ideal joint reactions, driver efforts (at most eight)."""
    spec = results.spec or {}
    chosen: list[str] = []
    for joint in [*spec.get("joints", []), *spec.get("spatial_joints", [])]:
        if joint["type"] == "translational":
            chosen.append(f"{joint['second'].split('.')[0]}.ax")
    for joint in clearance_joints(results):
        if f"{joint}.fh" in results:
            chosen += [f"{joint}.fh", f"{joint}.film_min"]
        chosen += [f"{joint}.fn", f"{joint}.eccentricity_ratio"]
    for force in spec.get("forces", []):
        if force["type"] == "hydraulic_cylinder":
            chosen += [f"{force['name']}.p_cap", f"{force['name']}.p_rod", f"{force['name']}.stroke"]
    chosen += [f"{g['name']}.axial_strain" for g in spec.get("sensors", [])]
    chosen += [f"{j['name']}.f" for j in [*spec.get("joints", []), *spec.get("spatial_joints", [])]
               if j["type"] != "clearance_revolute"]
    for driver in spec.get("drivers", []):
        chosen += [f"{driver['name']}.torque", f"{driver['name']}.force"]
    if not chosen:
        chosen = [f"{b['name']}.ax" for b in [*spec.get("bodies", []), *spec.get("spatial_bodies", [])]]
    out = list(dict.fromkeys(c for c in chosen if c in results))
    return out[:MAX_DEFAULT_CHANNELS]


def crank_angle_deg(results: Results, crank: str) -> np.ndarray:
    """Crank angle [deg], unwrapped, as recorded (``<crank>.angle``)."""
    return np.degrees(np.unwrap(results[f"{crank}.angle"]))


def _time_scale(*runs: Results) -> tuple[float, str]:
    """The unit of time that fits the longest of ``runs`` (µs, ms, s, min or h): (factor from
    seconds, unit)."""
    end = max((float(np.max(np.abs(r.time[[0, -1]]))) for r in runs if r.time.size), default=0.0)
    unit, seconds = time_unit(end)
    return 1.0 / seconds, unit


def time_histories(results: Results, channels: Sequence[str], path: Path, label: str | None = None) -> Path:
    """One panel per channel against time (in the unit that fits the run): the saved samples, and a dot at
    the peak tracked over every accepted step (:attr:`Results.extrema`), which coarse samples can miss."""
    fig = _figure(7.5, 1.9 * len(channels) + 0.8)
    axes = fig.subplots(len(channels), 1, sharex=True, squeeze=False)[:, 0]
    scale, unit = _time_scale(results)
    t = results.time * scale
    marked = False
    for ax, name in zip(axes, channels):
        ax.plot(t, results[name], lw=0.9)
        peak = tracked_peak_point(results, name)
        if peak is not None:
            ax.plot(peak[0] * scale, peak[1], "o", ms=4, color="tab:red")
            marked = True
        ax.set_ylabel(f"{name}\n[{results.unit(name)}]", fontsize=8)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel(f"time [{unit}]")
    note = sampling_note(results) + ("; dots: peaks over every accepted step" if marked else "")
    set_titles(fig, f"{label or _title(results)}\n{note}", [stopped_note(results)])
    return _save(fig, path)


def tracked_peak_point(results: Results, name: str) -> tuple[float, float] | None:
    """Time [s] and signed value of the extremum of channel ``name`` tracked at every accepted step, if
    the results have it: the peak of a force, moment, acceleration or pressure channel; the deepest
    penetration, largest eccentricity ratio or thinnest film of a clearance joint."""
    extrema = results.extrema or {}
    channel = extrema.get("channels", {}).get(name)
    if channel is not None:
        return None if channel.get("time") is None else (float(channel["time"]), float(channel["value"]))
    element, _, quantity = name.rpartition(".")
    joint = extrema.get("clearance_joints", {}).get(element)
    if joint is None:
        return None
    # the largest gap |e| - c: deepest penetration when the journal touched, else thinnest film
    at = joint.get("max_penetration_time") if joint.get("max_penetration_time") is not None else joint.get("min_film_time")
    value = {"penetration": joint.get("max_penetration"), "eccentricity_ratio": joint.get("max_eccentricity_ratio"),
             "film_min": joint.get("min_film")}.get(quantity)
    return None if at is None or value is None else (float(at), float(value))


def sampling_note(results: Results) -> str:
    """What the curves are: ``"1 001 samples saved every 1 ms"`` or ``"a sample at each of 1 832 accepted steps"``."""
    n = f"{len(results):,}".replace(",", " ")
    step = (results.options or {}).get("output_step")
    return f"{n} samples saved every {format_time(step)}" if step else f"{n} samples, one per accepted step"


def orbit(results: Results, joint: str, path: Path) -> Path:
    """Journal-centre path (eccentricity, mm) inside the clearance circle of radius c."""
    clearance = _clearance(results, joint)
    fig = _figure(5.2, 5.0)
    ax = fig.subplots()
    ex, ey = results[f"{joint}.ex"] * 1e3, results[f"{joint}.ey"] * 1e3
    ax.plot(ex, ey, lw=0.7, color="tab:blue", label="journal centre")
    contact = results[f"{joint}.contact"] > 0.5
    ax.plot(ex[contact], ey[contact], ".", ms=2, color="tab:red", label="in contact")
    if ex.size:
        ax.plot(ex[:1], ey[:1], "o", color="black", ms=4, label="start")
    if clearance is not None:
        theta = np.linspace(0, 2 * np.pi, 361)
        c = clearance * 1e3
        ax.plot(c * np.cos(theta), c * np.sin(theta), "k--", lw=0.8, label=f"clearance c = {c:g} mm")
        ax.set_xlim(-1.25 * c, 1.25 * c)
        ax.set_ylim(-1.25 * c, 1.25 * c)
    ax.set_aspect("equal")
    ax.set_xlabel(f"{joint}.ex [mm]")
    ax.set_ylabel(f"{joint}.ey [mm]")
    ax.legend(fontsize=7, loc="upper right")
    ax.grid(alpha=0.3)
    set_titles(fig, f"{_title(results)}: journal-centre orbit in {joint}", [stopped_note(results)])
    return _save(fig, path)


def force_vs_crank(results: Results, joint: str, crank: str, path: Path) -> Path:
    """Contact force of a clearance joint against the crank angle [deg]."""
    fig = _figure(7.0, 3.6)
    ax = fig.subplots()
    angle = crank_angle_deg(results, crank)
    ax.plot(angle, results[f"{joint}.fn"], lw=0.8)
    peak = tracked_peak_point(results, f"{joint}.fn")
    if peak is not None and results.time.size > 1:
        # the crank angle at the peak's time, interpolated between the samples around it
        ax.plot(np.interp(peak[0], results.time, angle), peak[1], "o", ms=4, color="tab:red",
                label="peak over every accepted step")
        ax.legend(fontsize=7, loc="upper right")
    ax.set_xlabel(wrap_to_width(fig, f"crank angle ({crank}.angle) [deg]; {sampling_note(results)}", 10))
    ax.set_ylabel(f"{joint}.fn [{results.unit(f'{joint}.fn')}]")
    ax.grid(alpha=0.3)
    set_titles(fig, f"{_title(results)}: contact force in {joint}", [stopped_note(results)])
    return _save(fig, path)


def beams(results: Results) -> list[dict]:
    """The beams of the model recorded in ``results`` (their spec entries)."""
    return [b for b in (results.spec or {}).get("beams", []) if f"{b['name']}.node0_x" in results]


def strain_gauges(results: Results) -> list[str]:
    """Names of the strain gauges recorded in ``results``."""
    return [g["name"] for g in (results.spec or {}).get("sensors", []) if f"{g['name']}.axial_strain" in results]


def beam_nodes(results: Results, beam: str) -> tuple[np.ndarray, np.ndarray]:
    """Node positions [m] of a beam at every sample: arrays x, y of shape (samples, nodes)."""
    count = sum(1 for name in results.channels if name.startswith(f"{beam}.node") and name.endswith("_x"))
    x = np.column_stack([results[f"{beam}.node{k}_x"] for k in range(count)])
    y = np.column_stack([results[f"{beam}.node{k}_y"] for k in range(count)])
    return x, y


def rigid_fit(reference: np.ndarray, current: np.ndarray) -> np.ndarray:
    """The rigid motion of ``reference`` (points, shape (n, 2)) that best fits ``current`` in least squares
    (Kabsch 1976): the moved reference points."""
    ref_mid, cur_mid = reference.mean(axis=0), current.mean(axis=0)
    a, b = reference - ref_mid, current - cur_mid
    angle = np.arctan2(np.sum(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]), np.sum(a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1]))
    c, s = np.cos(angle), np.sin(angle)
    return cur_mid + a @ np.array([[c, s], [-s, c]])


def deformed_shapes(results: Results, beam: dict, path: Path, times: Sequence[float] | None = None,
                    magnify: float | None = None) -> Path:
    """The nodes of ``beam`` (its spec entry) at ``times`` [s] (default: six, evenly spread), each drawn as
    the rigid motion that best fits its nodes plus ``magnify`` times the deformation from it (default: the
    largest deformation drawn at 10 % of the beam's length); the factor is in the title."""
    x, y = beam_nodes(results, beam["name"])
    t = results.time
    times = np.linspace(t[0], t[-1], 6) if times is None else np.asarray(times, dtype=float)
    rows = np.clip(np.searchsorted(t, times), 0, t.size - 1)
    start, end = np.asarray(beam["start"], float), np.asarray(beam["end"], float)
    reference = start + np.outer(np.linspace(0.0, 1.0, x.shape[1]), end - start)  # equally spaced nodes
    length = float(np.hypot(*(end - start)))
    current = [np.column_stack([x[r], y[r]]) for r in rows]
    rigid = [rigid_fit(reference, c) for c in current]
    largest = max(float(np.max(np.hypot(*(c - r).T))) for c, r in zip(current, rigid))
    if magnify is None:
        magnify = 0.1 * length / largest if largest > 0 else 1.0
    fig = _figure(6.5, 5.0)
    ax = fig.subplots()
    scale, unit = _time_scale(results)
    for row, c, r in zip(rows, current, rigid):
        shown = r + magnify * (c - r)
        ax.plot(shown[:, 0], shown[:, 1], ".-", lw=1.2, ms=3, label=f"t = {t[row] * scale:.4g} {unit}")
        ax.plot(r[:, 0], r[:, 1], color="0.7", lw=0.6)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    set_titles(fig, f"{_title(results)}: beam {beam['name']}, nodes at the saved samples nearest the times\n"
                    f"deformation from the best-fit rigid motion (grey) x {magnify:.3g} (largest deformation "
                    f"{largest * 1e3:.3g} mm)", [stopped_note(results)])
    return _save(fig, path)


def strain_histories(results: Results, gauge: str, path: Path) -> Path:
    """A strain gauge's fibre strain, axial force and bending moment against time."""
    channels = [f"{gauge}.{q}" for q in ("axial_strain", "axial_force", "bending_moment")]
    return time_histories(results, channels, path, label=f"{_title(results)}: strain gauge {gauge}")


def standard_figures(results: Results, out_dir, crank: str | None = None, fmt: str = "png",
                     channels: Sequence[str] | None = None) -> list[Path]:
    """Writes the standard figures into ``out_dir`` (created if needed); returns their paths.

    ``channels``: time histories to draw (default :func:`default_channels`); ``crank``: the body whose
    angle is the abscissa of the contact-force figure (default :func:`guess_crank`); ``fmt``: png or svg.
    """
    if fmt not in FORMATS:
        raise ValueError(f"format must be one of {', '.join(FORMATS)}, got {fmt!r}")
    out = figure_folder(out_dir)
    if results.time.size == 0:
        return []
    names = list(channels) if channels else default_channels(results)
    for name in names:
        results[name]  # KeyError with a did-you-mean hint for an unknown channel
    paths = []
    if names:
        paths.append(time_histories(results, names, out / f"time_histories.{fmt}"))
    crank = crank or guess_crank(results)
    for joint in clearance_joints(results):
        paths.append(orbit(results, joint, out / f"orbit_{joint}.{fmt}"))
        if crank is not None:
            paths.append(force_vs_crank(results, joint, crank, out / f"contact_force_{joint}.{fmt}"))
    for beam in beams(results):
        paths.append(deformed_shapes(results, beam, out / f"shapes_{beam['name']}.{fmt}"))
    from .plots_spatial import spatial_figures

    paths += spatial_figures(results, out, fmt)
    for gauge in strain_gauges(results):
        paths.append(strain_histories(results, gauge, out / f"strain_{gauge}.{fmt}"))
    return paths


def _clearance(results: Results, joint: str) -> float | None:
    for j in (results.spec or {}).get("joints", []):
        if j["name"] == joint and j["type"] == "clearance_revolute":
            return float(j["clearance"])
    return None


def _title(results: Results) -> str:
    return (results.spec or {}).get("name", "") or "jointplay"
