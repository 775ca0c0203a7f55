"""The sections of a run report, from one :class:`~jointplay.Results`: the model with its parameters in units,
the run's options and statistics, its summary (:meth:`Results.summary`, tracked at every accepted step), the
interactive plots of its standard channels and the animation of the mechanism.

Which channels are plotted follows the figures of ``jointplay plot`` (:mod:`jointplay.plots`,
:mod:`jointplay.plots_spatial`, :mod:`jointplay.plots_spatial_clearance`): their key channels, the orbit of
each clearance joint, and so on. The plots draw the saved samples (thinned for the browser, see
:mod:`jointplay.report.figures`); the numbers of the summary are never read from them.
"""

from __future__ import annotations

from ..results import Results
from .blocks import Section, Table, Text, Video
from .model import model_sections
from .plots import plot_sections

#: Options of a run shown, in order, with their units (those not set are left out).
OPTION_UNITS = {"method": "", "rtol": "", "atol": "", "max_step": "s", "output_step": "s", "initial_step": "s",
                "min_step": "s", "max_steps": "", "step": "s", "spectral_radius": "", "stabilization": "",
                "formulation": "", "jacobian": "", "initial": "", "max_output_bytes": "bytes"}
#: Units of the summary's figures of a clearance joint, and the factor from SI to them.
JOINT_UNITS = {"impacts": ("", 1.0), "contact_time": ("s", 1.0), "contact_fraction": ("-", 1.0),
               "max_penetration": ("mm", 1e3), "max_penetration_time": ("s", 1.0),
               "max_eccentricity_ratio": ("-", 1.0), "min_film": ("mm", 1e3), "min_film_time": ("s", 1.0),
               "peak_film_pressure": ("Pa", 1.0), "peak_film_pressure_time": ("s", 1.0)}


def run_label(results: Results) -> str:
    """The run's name in a report: its results file's name, else its model's name."""
    if results.path is not None:
        return results.path.name
    return (results.spec or {}).get("name") or "run"


def run_sections(results: Results, *, animation: bool | dict = True, progress=None) -> list[Section]:
    """Every section of the report of one run; ``animation`` False leaves the animation out, a dict gives
    its options (:func:`jointplay.animation.animate`'s). ``progress`` (a function of a message) hears of
    the slow steps."""
    sections = [*model_sections(results.spec, results.geometry), options_section(results), summary_section(results)]
    if animation:
        if progress:
            progress("rendering the animation")
        sections.append(animation_section(results, animation_options(animation)))
    if progress:
        progress("drawing the plots")
    return sections + plot_sections(results)


def options_section(results: Results) -> Section:
    """How the run was made: its status, options, integrator statistics and wall time."""
    status = "completed" if results.error is None else f"stopped early: {results.error.get('message', '')}"
    end = float(results.time[-1]) if results.time.size else 0.0
    run = [["results", run_label(results), ""], ["status", status, ""],
           ["time span", f"{float(results.time[0]) if results.time.size else 0.0:g} to {end:g}", "s"],
           ["saved samples", len(results), ""], ["wall time", results.wall_time, "s"]]
    if results.model_file:
        run.insert(1, ["model file", results.model_file, ""])
    options = [[key, results.options[key], unit] for key, unit in OPTION_UNITS.items()
               if results.options.get(key) is not None]
    options += [[key, value, ""] for key, value in results.options.items()
                if key not in OPTION_UNITS and value is not None]
    statistics = [[key, value] for key, value in results.statistics.items()]
    blocks = [Table(["", "value", "unit"], run, "The run"),
              Table(["option", "value", "unit"], options, "Options of the run (those not set take their defaults)"),
              Table(["statistic", "value"], statistics, "Integrator statistics")]
    if results.description:
        blocks.insert(0, Text(results.description))
    return Section("Run", blocks)


def summary_section(results: Results) -> Section:
    """The summary of :meth:`Results.summary`: peaks with their times, clearance joints, point accelerations."""
    summary = results.summary()
    source = summary["extrema_source"]
    how = (f"tracked at every one of the {summary['steps']} accepted steps, whatever the output step"
           if source == "accepted steps" else "read from the saved samples (a results file written before the "
           "extrema were tracked at every step): they may miss what happens between two samples")
    blocks = [Text(f"Peaks and clearance-joint figures {how}.")]
    peaks = [[name, results.unit(name) if name in results else "", value, summary["peak_times"].get(name)]
             for name, value in summary["peaks"].items()]
    if peaks:
        blocks.append(Table(["channel", "unit", "peak |value|", "time [s]"], peaks, "Peaks of forces, moments, "
                            "accelerations and pressures"))
    joints = summary["clearance_joints"]
    if joints:
        blocks.append(_joints_table(joints))
        blocks += _mode_tables(joints)
    points = summary.get("point_accelerations") or {}
    if points:
        rows = [[name, value, summary["point_acceleration_times"].get(name)] for name, value in points.items()]
        blocks.append(Table(["point", "peak |acceleration| [m/s^2]", "time [s]"], rows,
                            "Peak acceleration magnitude of every named point of a moving body"))
    return Section("Summary", blocks)


def _joints_table(joints: dict) -> Table:
    keys = [k for k in JOINT_UNITS if any(k in j for j in joints.values())]
    columns = ["clearance joint", *(f"{k} [{JOINT_UNITS[k][0]}]" if JOINT_UNITS[k][0] else k for k in keys)]
    rows = [[name, *(_scaled(joint.get(k), JOINT_UNITS[k][1]) for k in keys)] for name, joint in joints.items()]
    return Table(columns, rows, "Clearance joints: impacts, time and fraction of time in contact, deepest "
                                "penetration, largest eccentricity ratio; thinnest film and peak film pressure "
                                "when lubricated (lengths in mm)")


def _mode_tables(joints: dict) -> list[Table]:
    rows = [[name, key, value] for name, joint in joints.items()
            for key, value in (joint.get("mode_fractions") or {}).items()]
    if not rows:
        return []
    return [Table(["clearance joint", "motion mode", "fraction of time [-]"], rows,
                  "Time fractions of the motion modes (free, impact, sliding, sustained sum to 1; axial: a flange "
                  "touches)")]


def _scaled(value, factor: float):
    if value is None or isinstance(value, (bool, int)) or factor == 1.0:
        return value
    return float(value) * factor


def animation_options(animation: bool | dict) -> dict:
    """The options of a report's animation: ``animation`` itself when it is a dict, else the defaults."""
    return dict(animation) if isinstance(animation, dict) else {}


def animation_section(results: Results, options: dict | None = None) -> Section:
    """The animation of the mechanism (:func:`jointplay.animation.video_bytes`, MP4, with ``options``), or
    why there is none."""
    return Section("Animation", [animation_block(results, options)])


def animation_block(results: Results, options: dict | None = None, label: str = "") -> Video | Text:
    """One run's animation as a video block captioned with ``label``, or a text saying why there is none."""
    from ..animation import video_bytes
    from ..errors import ModelError

    try:
        data = video_bytes(results, mime="video/mp4", **(options or {}))
    except ModelError as exc:
        if any(problem.location in (options or {}) for problem in exc.problems):
            raise  # a bad option of the caller's: said, not written into the report
        return Text(f"No animation{f' of {label}' if label else ''}: {exc}")
    return Video(data, "video/mp4", f"{label + ': ' if label else ''}the mechanism drawn from the results "
                 "file at its saved samples; the magnification of the clearances and deformations and the scale "
                 "of the force arrows are stated in the picture.")
