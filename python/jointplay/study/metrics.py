"""Responses of a study: scalar measures of one run, defined once (docs/theory/study-metrics.md).

A response is read from a table as it comes from a study file::

    { name = "acc_osc", kind = "oscillation", channel = "contact.ay", window = ["0 ms", "30 ms"], cutoff = "300 Hz" }
    { name = "FH_peak", kind = "peak", channel = "H.f", window = ["0 ms", "10 ms"] }
    { name = "contact", kind = "contact_fraction", joint = "B" }

or made from a Python function of a run (:meth:`Response.from_callable`; never from a file). Whole-run
peaks of the channels the core tracks, contact fractions, penetrations and films come from the values
tracked at every accepted step (``Results.extrema``), so they do not depend on the output step; the
others are computed on the run's output grid, which the study makes fine enough for them
(:func:`required_output_step`).
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import ModelError, Problem
from ..units import UnitError, to_si

#: Kinds computed from one channel (``channel``, optional ``window``).
CHANNEL_KINDS = ("peak", "max", "min", "mean", "rms", "peak_to_peak", "final", "oscillation")
#: Kinds read from a clearance joint's tracked statistics (``joint``), over the whole run: the key in
#: ``Results.summary()["clearance_joints"][joint]`` and the unit.
JOINT_KINDS = {"contact_fraction": ("contact_fraction", ""), "max_penetration": ("max_penetration", "m"),
               "min_film": ("min_film", "m"),
               # the motion modes of a spatial clearance joint (docs/theory/spatial-clearance-revolute.md)
               **{f"{mode}_fraction": (f"mode_fractions.{mode}", "") for mode in
                  ("free", "impact", "sliding", "sustained", "axial")}}
KINDS = CHANNEL_KINDS + tuple(JOINT_KINDS)
#: Statistics of the oscillation about the trend.
STATISTICS = ("rms", "peak", "peak_to_peak")
#: Butterworth order of the trend filter (applied forward and backward: twice this order, zero phase).
FILTER_ORDER = 4
#: Default cutoff of the trend: this many cycles over the window [1/window].
DEFAULT_CYCLES_PER_WINDOW = 10.0
#: Fewest periods of the cutoff a window must span for its trend to mean anything.
MIN_CUTOFF_PERIODS = 1.0
#: Samples per period of the cutoff the oscillation is computed with (its grid step is 1 / (this x cutoff)).
SAMPLES_PER_CUTOFF_PERIOD = 20
#: Length of the odd extension at each end of the window before filtering [periods of the cutoff].
PAD_CUTOFF_PERIODS = 3.0
#: Fewest output steps in the window of a response computed on the output grid (``required_output_step``).
STEPS_PER_WINDOW = 100
#: Relative tolerance on the run's span when a window is compared with the run's start and end.
SPAN_TOLERANCE = 1e-9
_KEYS = {"name", "kind", "channel", "joint", "window", "cutoff", "statistic", "description"}
_WHAT = {"peak": "largest |value|", "max": "largest value", "min": "smallest value", "mean": "time mean",
         "rms": "root mean square over time", "peak_to_peak": "max - min", "final": "value at the window's end"}


@dataclass(frozen=True)
class Response:
    """One scalar measure of a run (see the module doc): ``window`` (start, end) [s], a closed interval,
    or None for the whole run; ``cutoff`` [Hz] of an oscillation's trend (None: DEFAULT_CYCLES_PER_WINDOW
    cycles per window); ``units`` of a callable's value (a channel's or joint's come from the run)."""

    name: str
    kind: str
    channel: str | None = None
    joint: str | None = None
    window: tuple[float, float] | None = None
    cutoff: float | None = None
    statistic: str = "rms"
    description: str = ""
    function: Callable | None = field(default=None, compare=False)
    units: str = ""

    @classmethod
    def from_callable(cls, name: str, function: Callable, units: str = "", description: str = "") -> Response:
        """A response computed by ``function(results) -> float`` (it must be importable by name where the
        cases run: a module-level function, not a lambda, for worker processes)."""
        if not name.isidentifier():
            raise ModelError([Problem("response.name", f"must be a name of letters, digits and _, got {name!r}")])
        if not callable(function):
            raise ModelError([Problem(f"response.{name}", f"must be a function of a run, got {function!r}")])
        return cls(name, "callable", description=description or f"{getattr(function, '__name__', 'function')}"
                   "(results), a user function", function=function, units=units)

    # --- what it is --------------------------------------------------------------------------------

    @property
    def definition(self) -> str:
        """One line saying what the value is and how it is computed."""
        if self.kind == "callable":
            return self.description
        if self.kind in JOINT_KINDS:
            return f"{self.kind.replace('_', ' ')} of clearance joint {self.joint} over the run, tracked at every step"
        where = "over the run" if self.window is None else f"over [{self.window[0]:g} s, {self.window[1]:g} s]"
        if self.kind == "oscillation":
            cutoff = f"{self.cutoff:g} Hz" if self.cutoff else f"{DEFAULT_CYCLES_PER_WINDOW:g} cycles per window"
            return (f"{self.statistic} of {self.channel} about its trend (Butterworth order {FILTER_ORDER} low-pass, "
                    f"forward and backward, cutoff {cutoff}) {where}, on the study's output grid")
        grid = "on the study's output grid"
        if self.kind == "peak":
            grid = ("tracked at every step when the window covers the run and the core tracks the channel "
                    f"(forces, moments, accelerations, pressures), else {grid}")
        return f"{_WHAT[self.kind]} of {self.channel} {where}, {grid}"

    def units_in(self, results) -> str:
        """The response's units for a run (a channel's unit is the run's)."""
        if self.kind == "callable":
            return self.units
        if self.kind in JOINT_KINDS:
            return JOINT_KINDS[self.kind][1]
        return results.unit(self.channel)

    def covers_run(self, time: np.ndarray) -> bool:
        """Whether the window holds the whole span of the run's ``time`` [s]."""
        if self.window is None:
            return True
        slack = SPAN_TOLERANCE * (time[-1] - time[0])
        return self.window[0] <= time[0] + slack and self.window[1] >= time[-1] - slack

    # --- its value ---------------------------------------------------------------------------------

    def evaluate(self, results) -> float:
        """The response of a run."""
        if self.kind == "callable":
            return float(self.function(results))
        check_against([self], results)
        if self.kind in JOINT_KINDS:
            return self._joint_value(results)
        tracked = (results.extrema or {}).get("channels", {}).get(self.channel)
        if self.kind == "peak" and tracked is not None and self.covers_run(results.time):
            return float(tracked["peak"])
        time, x = window_samples(results.time, results[self.channel], self.window)
        if self.kind == "oscillation":
            cutoff = self.cutoff or DEFAULT_CYCLES_PER_WINDOW / (time[-1] - time[0])
            if cutoff * (time[-1] - time[0]) < MIN_CUTOFF_PERIODS * (1 - SPAN_TOLERANCE):
                raise ModelError([Problem(f"responses.{self.name}.cutoff", _short_window(cutoff, time[-1] - time[0]))])
            return oscillation(time, x, cutoff, self.statistic)
        return float(_REDUCTIONS[self.kind](time, x))

    def _joint_value(self, results) -> float:
        value = results.summary()["clearance_joints"][self.joint]
        for key in JOINT_KINDS[self.kind][0].split("."):
            value = value.get(key) if isinstance(value, dict) else None
        if value is None:
            if self.kind == "max_penetration":
                return 0.0  # never in contact
            raise ModelError([Problem(f"responses.{self.name}", f"joint {self.joint} has no {self.kind} "
                                      "(min_film needs a lubricated joint, the mode fractions a spatial clearance "
                                      "joint)")])
        return float(value)


def window_samples(time: np.ndarray, x: np.ndarray,
                   window: tuple[float, float] | None) -> tuple[np.ndarray, np.ndarray]:
    """The samples of ``x(time)`` in the closed ``window`` [s] (None: all), with the curve's values at the
    window's ends (linear between samples) added where they fall between samples."""
    if window is None:
        return time, x
    start, end = max(window[0], time[0]), min(window[1], time[-1])
    inside = (time > start) & (time < end)
    t = np.concatenate(([start], time[inside], [end]))
    return t, np.concatenate(([np.interp(start, time, x)], x[inside], [np.interp(end, time, x)]))


def _time_mean(t: np.ndarray, x: np.ndarray) -> float:
    """Mean over time of the piecewise-linear curve through the samples (trapezoids), whatever their spacing."""
    return float(np.trapezoid(x, t) / (t[-1] - t[0]))


_REDUCTIONS: dict[str, Callable[[np.ndarray, np.ndarray], float]] = {
    "peak": lambda t, x: np.max(np.abs(x)),
    "max": lambda t, x: np.max(x),
    "min": lambda t, x: np.min(x),
    "mean": _time_mean,
    "rms": lambda t, x: math.sqrt(_time_mean(t, np.square(x))),
    "peak_to_peak": lambda t, x: np.ptp(x),
    "final": lambda t, x: x[-1],
}


def oscillation(time: np.ndarray, x: np.ndarray, cutoff: float, statistic: str = "rms") -> float:
    """The ``statistic`` (``rms``, ``peak``, ``peak_to_peak``) of ``x`` about its trend: x resampled
    linearly on a uniform grid over [time[0], time[-1]] [s] as fine as its samples (their mean spacing)
    and never coarser than 1 / (SAMPLES_PER_CUTOFF_PERIOD cutoff); the trend its zero-phase Butterworth
    low-pass at ``cutoff`` [Hz] (``scipy.signal.sosfiltfilt``, odd extension of PAD_CUTOFF_PERIODS periods
    at each end, or the whole window if shorter); the oscillation the difference. Same units as ``x``."""
    from scipy.signal import butter, sosfiltfilt

    span = float(time[-1] - time[0])
    if not (cutoff > 0 and span * cutoff >= MIN_CUTOFF_PERIODS * (1 - SPAN_TOLERANCE)):
        raise ValueError(_short_window(cutoff, span))
    if statistic not in STATISTICS:
        raise ValueError(f"statistic must be one of {', '.join(STATISTICS)}, got {statistic!r}")
    h = min(1.0 / (SAMPLES_PER_CUTOFF_PERIOD * cutoff), span / max(len(time) - 1, 1))
    n = int(math.ceil(span / h * (1 - SPAN_TOLERANCE))) + 1
    grid = time[0] + np.arange(n) * (span / (n - 1))
    sos = butter(FILTER_ORDER, cutoff, fs=(n - 1) / span, output="sos")
    y = np.interp(grid, time, x)
    # each end extended by PAD_CUTOFF_PERIODS periods of the cutoff (odd extension): the same span of time
    # whatever the grid, so that the ends' treatment does not depend on the samples
    pad = min(n - 1, int(round(PAD_CUTOFF_PERIODS * (n - 1) / (span * cutoff))))
    wiggle = y - sosfiltfilt(sos, y, padtype="odd", padlen=pad)
    if statistic == "rms":
        return math.sqrt(_time_mean(grid, np.square(wiggle)))
    if statistic == "peak":
        return float(np.max(np.abs(wiggle)))
    return float(np.ptp(wiggle))


def _short_window(cutoff: float, span: float) -> str:
    return (f"the window ({span:g} s) spans {span * cutoff:.3g} periods of the cutoff {cutoff:g} Hz; the trend "
            f"needs at least {MIN_CUTOFF_PERIODS:g}: raise the cutoff to at least {MIN_CUTOFF_PERIODS / span:.4g} Hz "
            "or lengthen the window")


# --- reading responses --------------------------------------------------------------------------------

def parse_responses(entries: list, where: str = "study.responses") -> list[Response]:
    """Responses from their tables (as read from TOML: units in strings, a bare number SI); one located
    problem per mistake, all of them in one ModelError."""
    out, problems = [], []
    if not isinstance(entries, list):
        raise ModelError([Problem(where, f"must be a list of response tables, got {entries!r}")])
    seen: dict[str, int] = {}
    for k, entry in enumerate(entries):
        try:
            out.append(parse_response(entry, f"{where}[{k}]"))
        except ModelError as exc:
            problems.extend(exc.problems)
        name = entry.get("name") if isinstance(entry, dict) else None
        if isinstance(name, str) and name in seen:
            problems.append(Problem(f"{where}[{k}].name",
                                    f"repeats the response name {name!r} of {where}[{seen[name]}]"))
        elif isinstance(name, str):
            seen[name] = k
    if problems:
        raise ModelError(problems)
    return out


def parse_response(entry: Any, where: str) -> Response:
    """One response from its table; problems located under ``where``."""
    if not isinstance(entry, dict):
        raise ModelError([Problem(where, f"must be a table such as {{ name = \"peak_force\", kind = \"peak\", "
                                         f"channel = \"B.f\" }}, got {entry!r}")])
    problems = [Problem(f"{where}.{key}", f"is not a key of a response (keys: {', '.join(sorted(_KEYS))})")
                for key in entry if key not in _KEYS]
    name, kind = entry.get("name"), entry.get("kind")
    if not isinstance(name, str) or not name.isidentifier():
        problems.append(Problem(f"{where}.name", f"must be a name of letters, digits and _, got {name!r}"))
    if kind not in KINDS:
        problems.append(Problem(f"{where}.kind", f"must be one of {', '.join(KINDS)}, got {kind!r}"))
    if problems:
        raise ModelError(problems)
    if kind in JOINT_KINDS:
        return _joint_response(entry, name, kind, where)
    return _channel_response(entry, name, kind, where)


def _joint_response(entry: dict, name: str, kind: str, where: str) -> Response:
    problems = [Problem(f"{where}.{key}", f"does not apply to {kind} (a whole-run statistic of a joint)")
                for key in ("channel", "window", "cutoff", "statistic") if key in entry]
    joint = entry.get("joint")
    if not isinstance(joint, str) or not joint:
        problems.append(Problem(f"{where}.joint", f"must name a clearance joint, got {joint!r}"))
    if problems:
        raise ModelError(problems)
    return Response(name, kind, joint=joint, description=str(entry.get("description", "")))


def _channel_response(entry: dict, name: str, kind: str, where: str) -> Response:
    problems = []
    channel = entry.get("channel")
    if not isinstance(channel, str) or "." not in channel:
        problems.append(Problem(f"{where}.channel", f"must name a channel \"<element>.<quantity>\", got {channel!r}"))
    if "joint" in entry:
        problems.append(Problem(f"{where}.joint", f"does not apply to {kind}; name a channel"))
    window = _window(entry.get("window"), f"{where}.window", problems)
    cutoff, statistic = None, "rms"
    if kind == "oscillation":
        if "cutoff" in entry:
            cutoff = _positive(entry["cutoff"], "frequency", f"{where}.cutoff", problems)
        if cutoff is not None and window is not None and cutoff * (window[1] - window[0]) < MIN_CUTOFF_PERIODS:
            problems.append(Problem(f"{where}.cutoff", _short_window(cutoff, window[1] - window[0])))
        statistic = entry.get("statistic", "rms")
        if statistic not in STATISTICS:
            problems.append(Problem(f"{where}.statistic", f"must be one of {', '.join(STATISTICS)}, got {statistic!r}"))
    else:
        problems += [Problem(f"{where}.{key}", "applies to oscillation only") for key in ("cutoff", "statistic")
                     if key in entry]
    if problems:
        raise ModelError(problems)
    return Response(name, kind, channel=channel, window=window, cutoff=cutoff, statistic=statistic,
                    description=str(entry.get("description", "")))


def _window(raw: Any, where: str, problems: list) -> tuple[float, float] | None:
    if raw is None:
        return None
    if not isinstance(raw, (list, tuple)) or len(raw) != 2:
        problems.append(Problem(where, f"must be two times [start, end], e.g. [\"0 ms\", \"10 ms\"], got {raw!r}"))
        return None
    try:
        start, end = (to_si(t, "time") for t in raw)
    except UnitError as exc:
        problems.append(Problem(where, f"must be two times [start, end]: {exc}"))
        return None
    if not (math.isfinite(start) and math.isfinite(end) and 0 <= start < end):
        problems.append(Problem(where, f"must be two times with 0 <= start < end, got {raw!r}"))
        return None
    return start, end


def _positive(raw: Any, kind: str, where: str, problems: list) -> float | None:
    try:
        value = to_si(raw, kind)
    except UnitError as exc:
        problems.append(Problem(where, str(exc)))
        return None
    if not (math.isfinite(value) and value > 0):
        problems.append(Problem(where, f"must be > 0, got {raw!r}"))
        return None
    return value


# --- against a run ------------------------------------------------------------------------------------

def check_against(responses: list[Response], results) -> None:
    """A located error for each response the run cannot give: a channel or clearance joint it does not
    have (with close matches), a window reaching outside the run's span."""
    problems = []
    joints: dict | None = None
    for r in responses:
        if r.channel is not None and r.channel not in results:
            problems.append(Problem(f"responses.{r.name}.channel",
                                    f"no channel {r.channel!r} in the run{_close(r.channel, results.channels)}"))
        if r.joint is not None:
            joints = results.summary()["clearance_joints"] if joints is None else joints
            if r.joint not in joints:
                problems.append(Problem(f"responses.{r.name}.joint", f"no clearance joint {r.joint!r} in the run "
                                        f"(clearance joints: {', '.join(joints) or 'none'})"
                                        f"{_close(r.joint, list(joints))}"))
        if r.window is not None:
            problems += _window_outside(r, results.time)
    if problems:
        raise ModelError(problems)


def _close(name: str, names: list[str]) -> str:
    """"; did you mean ...?" naming up to three of ``names`` close to ``name`` (case aside), or ""."""
    lower = {n.lower(): n for n in names}
    close = [lower[n] for n in difflib.get_close_matches(name.lower(), list(lower), n=3)]
    return f"; did you mean {', '.join(close)}?" if close else ""


def _window_outside(response: Response, time: np.ndarray) -> list[Problem]:
    start, end = response.window
    where = f"responses.{response.name}.window"
    if time.size < 2:
        return [Problem(where, f"[{start:g} s, {end:g} s] cannot be measured: the run holds {time.size} sample(s)")]
    slack = SPAN_TOLERANCE * (time[-1] - time[0])
    if start < time[0] - slack or end > time[-1] + slack:
        return [Problem(where, f"[{start:g} s, {end:g} s] reaches outside the run ({time[0]:g} s .. {time[-1]:g} s)")]
    return []


def required_output_step(responses: list, t_end: float | None = None) -> float | None:
    """The largest output step [s] that resolves the responses, or None when none is computed on the output
    grid. An oscillation: half its grid step, 1 / (2 SAMPLES_PER_CUTOFF_PERIOD cutoff), so that the linear
    resampling follows the run's own curve; any other response computed on the grid: STEPS_PER_WINDOW steps
    in its window. A response over the whole run needs ``t_end`` [s] (without it, it sets no step); a whole-run
    ``peak`` sets none (it is the tracked one for the channels the core tracks)."""
    steps = []
    for r in responses:
        kind = getattr(r, "kind", None)
        if kind not in CHANNEL_KINDS or (kind == "peak" and r.window is None):
            continue
        span = (r.window[1] - r.window[0]) if r.window else t_end
        if kind == "oscillation" and (r.cutoff or span):
            cutoff = r.cutoff or DEFAULT_CYCLES_PER_WINDOW / span
            steps.append(0.5 / (SAMPLES_PER_CUTOFF_PERIOD * cutoff))
        elif span:
            steps.append(span / STEPS_PER_WINDOW)
    return min(steps) if steps else None
