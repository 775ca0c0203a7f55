"""The sections of a comparison report, from several :class:`~jointplay.Results` side by side: a table of
each run's options and summary with one column per run, the differences between their models, and the
channels they share overlaid in one plot per channel (a trace per run), chosen as ``jointplay compare``
chooses them (:func:`jointplay.compare.default_compare_channels`).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..errors import ModelError
from ..results import Results
from .blocks import Plot, Section, Table, Text
from .figures import THINNING, overlay_figure
from .run import JOINT_UNITS, OPTION_UNITS, animation_block, animation_options, run_label

#: Marks a value a run does not have in the comparison tables.
ABSENT = "–"


def run_labels(runs: Sequence[Results]) -> list[str]:
    """Each run's label (:func:`~jointplay.report.run.run_label`), numbered where two would read alike."""
    labels = [run_label(r) for r in runs]
    return [f"{label} ({k + 1})" if labels.count(label) > 1 else label for k, label in enumerate(labels)]


def compare_sections(runs: Sequence[Results], *, animation: bool | dict = False) -> list[Section]:
    """Every section of the comparison of ``runs``; with ``animation`` (True, or a dict of
    :func:`jointplay.animation.animate`'s options) the runs' animations side by side."""
    labels = run_labels(runs)
    sections = [runs_section(runs, labels), differences_section(runs, labels), summary_section(runs, labels)]
    if animation:
        sections.append(animations_section(runs, labels, animation_options(animation)))
    return sections + [overlay_section(runs, labels)]


def animations_section(runs: Sequence[Results], labels: Sequence[str], options: dict) -> Section:
    """Each run's animation, side by side, labelled, drawn at one clearance magnification and one force scale
    (:func:`common_scales`) so that the pictures compare."""
    options = common_scales(runs, options)
    return Section("Animations", [animation_block(run, options, label) for run, label in zip(runs, labels)])


def common_scales(runs: Sequence[Results], options: dict) -> dict:
    """``options`` with the clearance and force scales the runs' animations share where ``options`` leave them
    unset: the smallest of the runs' own automatic scales (of the runs with clearance joints), so that every
    run's journals and arrows fit. Deformation scales stay each run's own (stated in each picture)."""
    from ..animation.scene import Scene

    scene_options = {k: v for k, v in options.items() if k not in ("size", "progress")}
    try:
        scenes = [Scene(run, **scene_options) for run in runs]
    except ModelError:
        return dict(options)  # each animation then says what is wrong with it
    shared = dict(options)
    for key in ("clearance", "force"):
        own = [scene.scales[key] for scene in scenes if scene.has_clearance_joints]
        if options.get(f"{key}_scale") is None and own:
            shared[f"{key}_scale"] = min(own)
    return shared


def runs_section(runs: Sequence[Results], labels: Sequence[str]) -> Section:
    """The runs side by side: model, status, time span, options and statistics, a column per run."""
    rows: list[list[Any]] = [
        ["model", "", *((r.spec or {}).get("name", ABSENT) for r in runs)],
        ["model file", "", *(r.model_file or ABSENT for r in runs)],
        ["status", "", *("completed" if r.error is None else f"stopped early: {r.error.get('message', '')}"
                         for r in runs)],
        ["end time", "s", *(float(r.time[-1]) if r.time.size else ABSENT for r in runs)],
        ["saved samples", "", *(len(r) for r in runs)],
        ["wall time", "s", *(r.wall_time for r in runs)],
    ]
    option_keys = list(dict.fromkeys([*OPTION_UNITS, *(k for r in runs for k in r.options)]))
    rows += [[f"option {key}", OPTION_UNITS.get(key, ""), *(_value(r.options, key) for r in runs)]
             for key in option_keys if any(r.options.get(key) is not None for r in runs)]
    statistic_keys = list(dict.fromkeys(k for r in runs for k in r.statistics))
    rows += [[f"statistic {key}", "", *(_value(r.statistics, key) for r in runs)] for key in statistic_keys]
    return Section("Runs", [Table(["", "unit", *labels], rows, "The runs compared, one column each")])


def _value(values: dict, key: str) -> Any:
    value = values.get(key)
    return ABSENT if value is None else value


def flatten(value: Any, prefix: str = "") -> dict[str, Any]:
    """A model (nested dicts and lists of named entries) as ``{dotted path: value}``: entries of a list
    are named by their ``name`` (``joints.B.clearance``), other list items by their index."""
    if isinstance(value, dict):
        out: dict[str, Any] = {}
        for key, item in value.items():
            out.update(flatten(item, f"{prefix}{key}."))
        return out
    if isinstance(value, list) and value and all(isinstance(v, dict) and "name" in v for v in value):
        out = {}
        for item in value:
            out.update(flatten({k: v for k, v in item.items() if k != "name"}, f"{prefix}{item['name']}."))
        return out
    return {prefix.rstrip("."): value}


def model_differences(runs: Sequence[Results]) -> list[list[Any]]:
    """Rows ``[parameter, value in each run]`` of the model parameters (SI units) that differ between the
    runs, or that some runs have and others do not."""
    flat = [flatten(r.spec or {}) for r in runs]
    keys = list(dict.fromkeys(k for f in flat for k in f))
    rows = []
    for key in keys:
        values = [f.get(key, ABSENT) for f in flat]
        if any(v != values[0] for v in values[1:]):
            rows.append([key, *(_shown(v) for v in values)])
    return rows


def _shown(value: Any) -> Any:
    if value is None:
        return "none"  # given as not set, unlike a parameter the model does not have
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(str(_shown(v)) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {_shown(v)}" for k, v in value.items()) + " }"
    return value


def differences_section(runs: Sequence[Results], labels: Sequence[str]) -> Section:
    """The parameters of the models that differ between the runs."""
    rows = model_differences(runs)
    if not rows:
        return Section("Model differences", [Text("The runs' models are the same.")])
    return Section("Model differences", [
        Text("Parameters of the models that differ between the runs, as the results files hold them (SI units: "
             "lengths in m, angles in rad); \"none\" where a run's model leaves it unset, a dash where it has no such "
             "parameter."),
        Table(["parameter", *labels], rows, "Model parameters that differ")])


def summary_section(runs: Sequence[Results], labels: Sequence[str]) -> Section:
    """Each run's summary (:meth:`Results.summary`) side by side: peaks and clearance-joint figures."""
    summaries = [r.summary() for r in runs]
    peak_names = list(dict.fromkeys(n for s in summaries for n in s["peaks"]))
    rows = [[f"peak |{name}|", _unit(runs, name), *(s["peaks"].get(name, ABSENT) for s in summaries)]
            for name in peak_names]
    joint_names = list(dict.fromkeys(j for s in summaries for j in s["clearance_joints"]))
    for joint in joint_names:
        for key, (unit, factor) in JOINT_UNITS.items():
            cells = [s["clearance_joints"].get(joint, {}).get(key) for s in summaries]
            if any(c is not None for c in cells):
                rows.append([f"{joint} {key}", unit, *(_scaled(c, factor) for c in cells)])
    sources = ", ".join(sorted({s["extrema_source"] for s in summaries}))
    return Section("Summaries", [Table(["quantity", "unit", *labels], rows,
                                       f"Each run's summary, one column per run (from the {sources}; lengths of "
                                       "clearance joints in mm)")])


def _unit(runs: Sequence[Results], name: str) -> str:
    return next((r.unit(name) for r in runs if name in r), "")


def _scaled(value: Any, factor: float) -> Any:
    if value is None:
        return ABSENT
    if isinstance(value, (bool, int)) or factor == 1.0:
        return value
    return float(value) * factor


def overlay_section(runs: Sequence[Results], labels: Sequence[str]) -> Section:
    """The channels the runs share overlaid, one plot per channel, a trace per run."""
    from ..compare import default_compare_channels, nothing_to_compare
    from ..plots import sampling_note, stopped_note

    names = default_compare_channels(runs)
    if not names:
        return Section("Channels overlaid", [Text(f"Nothing to overlay: {nothing_to_compare(runs, labels)}.")])
    sampling = "; ".join(f"{label}: {sampling_note(r)}" for r, label in zip(runs, labels))
    stopped = " ".join(f"{note[0].upper()}{note[1:]}." for note in (stopped_note(r, label) for r, label in
                                                                      zip(runs, labels)) if note)
    blocks = []
    for name in names:
        figure, was_thinned = overlay_figure(runs, labels, name)
        missing = [label for r, label in zip(runs, labels) if name not in r]
        note = f" Runs without this channel: {', '.join(missing)}." if missing else ""
        thinning = f" {THINNING}" if was_thinned else ""
        text = f"{name} of each run against time ({sampling}).{note}{thinning}"
        blocks.append(Plot(figure, f"{text} {stopped}" if stopped else text))
    return Section("Channels overlaid", blocks)
