"""Responses of a study: scalar measures of one run, defined once (docs/theory/study-metrics.md).

A response is read from a table as it comes from a study file::

    { name = "acc_osc", kind = "oscillation", channel = "contact.ay", window = ["0 ms", "30 ms"], cutoff = "300 Hz" }
    { name = "FH_peak", kind = "peak", channel = "H.f", window = ["0 ms", "10 ms"] }
    { name = "contact", kind = "contact_fraction", joint = "B" }

or made from a Python function of a run (:meth:`Response.from_callable`; never from a file). Whole-run
peaks of the channels the core tracks, contact fractions, penetrations and films come from the values
tracked at every accepted step (``Results.extrema``), so they do not depend on the output step; the
others are computed on the run's samples, which the study takes on a grid fine enough for them
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

#: Kinds computed from one channel's samples (``channel``, optional ``window``).
CHANNEL_KINDS = ("peak", "max", "min", "mean", "rms", "peak_to_peak", "final", "oscillation")
#: Kinds read from a clearance joint's tracked statistics (``joint``), over the whole run.
JOINT_KINDS = {"contact_fraction": ("contact_fraction", ""), "max_penetration": ("max_penetration", "m"),
               "min_film": ("min_film", "m")}
KINDS = CHANNEL_KINDS + tuple(JOINT_KINDS)
#: Statistics of the oscillation about the trend.
STATISTICS = ("rms", "peak", "peak_to_peak")
#: Butterworth order of the trend filter (applied forward and backward: twice this order, zero phase).
FILTER_ORDER = 4
#: Default cutoff of the trend: this many cycles over the window [1/window].
DEFAULT_CYCLES_PER_WINDOW = 10.0
#: Samples per period of the cutoff the oscillation is computed with (its grid step is 1 / (this x cutoff)).
SAMPLES_PER_CUTOFF_PERIOD = 20
#: Length of the odd extension at each end of the window before filtering [periods of the cutoff].
PAD_CUTOFF_PERIODS = 3.0
_KEYS = {"name", "kind", "channel", "joint", "window", "cutoff", "statistic", "description"}


@dataclass(frozen=True)
class Response:
    """One scalar measure of a run (see the module doc); ``window`` (start, end) [s] or None for the
    whole run, ``cutoff`` [Hz] of an oscillation's trend (None: :data:`DEFAULT_CYCLES_PER_WINDOW` cycles
    per window)."""

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
        return cls(name, "callable", description=description or f"{getattr(function, '__name__', 'function')}"
                   "(results), a user function", function=function, units=units)

    # --- what it is --------------------------------------------------------------------------------

    @property
    def definition(self) -> str:
        """One line saying what the value is."""
        if self.kind == "callable":
            return self.description
        if self.kind in JOINT_KINDS:
            return f"{self.kind.replace('_', ' ')} of clearance joint {self.joint} over the run, tracked at every step"
        where = "over the run" if self.window is None else f"over {self.window[0]:g} s .. {self.window[1]:g} s"
        exact = " (tracked at every step)" if self.exact_peak else " (on the run's samples)"
        if self.kind == "oscillation":
            cutoff = f"{self.cutoff:g} Hz" if self.cutoff else f"{DEFAULT_CYCLES_PER_WINDOW:g} cycles per window"
            return (f"{self.statistic} of {self.channel} about its trend (Butterworth order {FILTER_ORDER} low-pass, "
                    f"forward and backward, cutoff {cutoff}) {where}")
        named = {"peak": "largest |value|", "peak_to_peak": "max - min", "final": "value at the end"}
        return f"{named.get(self.kind, self.kind)} of {self.channel} {where}{exact}"

    @property
    def exact_peak(self) -> bool:
        return self.kind == "peak" and self.window is None

    def units_in(self, results) -> str:
        """The response's units for a run (a channel's unit is the run's)."""
        if self.kind == "callable":
            return self.units
        if self.kind in JOINT_KINDS:
            return JOINT_KINDS[self.kind][1]
        return results.unit(self.channel)

    # --- its value ---------------------------------------------------------------------------------

    def evaluate(self, results) -> float:
        """The response of a run."""
        if self.kind == "callable":
            return float(self.function(results))
        if self.kind in JOINT_KINDS:
            return self._joint_value(results)
        check_against([self], results)
        tracked = (results.extrema or {}).get("channels", {}).get(self.channel)
        if self.exact_peak and tracked is not None:
            return float(tracked["peak"])
        time, x = self._samples(results)
        if self.kind == "oscillation":
            return oscillation(time, x, self.cutoff or DEFAULT_CYCLES_PER_WINDOW / (time[-1] - time[0]),
                               self.statistic)
        return float(_REDUCTIONS[self.kind](time, x))

    def _joint_value(self, results) -> float:
        joints = results.summary()["clearance_joints"]
        if self.joint not in joints:
            raise ModelError([Problem(f"responses.{self.name}.joint", f"no clearance joint {self.joint!r} in the run"
                                      f" (clearance joints: {', '.join(joints) or 'none'})")])
        value = joints[self.joint].get(JOINT_KINDS[self.kind][0])
        if value is None:
            if self.kind == "max_penetration":
                return 0.0  # never in contact
            raise ModelError([Problem(f"responses.{self.name}", f"joint {self.joint} has no {self.kind} "
                                      "(min_film needs a lubricated joint)")])
        return float(value)

    def _samples(self, results) -> tuple[np.ndarray, np.ndarray]:
        time, x = results.time, results[self.channel]
        if self.window is None:
            return time, x
        start, end = self.window
        if time.size == 0 or start > time[-1] or end < time[0]:
            raise ModelError([Problem(f"responses.{self.name}.window", f"[{start:g} s, {end:g} s] lies outside "
                                      f"the run ({time[0] if time.size else 0:g} s .. {time[-1] if time.size else 0:g} s)")])
        inside = (time >= start) & (time <= end)
        if np.count_nonzero(inside) < 2:
            raise ModelError([Problem(f"responses.{self.name}.window", f"holds fewer than 2 samples of the run; "
                                      "make the window longer or the output step shorter")])
        return time[inside], x[inside]


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
    """The ``statistic`` of ``x`` about its trend: x resampled linearly on a uniform grid over
    [time[0], time[-1]] as fine as its samples (their mean spacing) and never coarser than
    1 / (SAMPLES_PER_CUTOFF_PERIOD cutoff); the trend its zero-phase Butterworth low-pass at ``cutoff``
    [Hz] (``scipy.signal.sosfiltfilt``, odd extension of PAD_CUTOFF_PERIODS periods at each end, or the
    whole window if shorter); the oscillation the difference."""
    from scipy.signal import butter, sosfiltfilt

    span = float(time[-1] - time[0])
    h = min(1.0 / (SAMPLES_PER_CUTOFF_PERIOD * cutoff), span / max(len(time) - 1, 1))
    n = max(int(math.ceil(span / h)) + 1, 2)
    grid = time[0] + np.arange(n) * (span / (n - 1))
    sos = butter(FILTER_ORDER, cutoff, fs=(n - 1) / span, output="sos")
    minimum = 3 * (2 * len(sos) + 1)
    if n <= minimum:
        raise ModelError([Problem("oscillation", f"the window holds {n} grid points at the cutoff {cutoff:g} Hz; "
                                                 f"the trend filter needs more than {minimum}: raise the cutoff or "
                                                 "lengthen the window")])
    y = np.interp(grid, time, x)
    # the ends extended by PAD_CUTOFF_PERIODS periods of the cutoff (odd extension): the same span of time
    # whatever the grid, so that the ends' treatment does not depend on the samples
    pad = min(n - 1, int(round(PAD_CUTOFF_PERIODS * (n - 1) / (span * cutoff))))
    wiggle = y - sosfiltfilt(sos, y, padtype="odd", padlen=pad)
    if statistic == "rms":
        return float(np.sqrt(np.mean(np.square(wiggle))))
    if statistic == "peak":
        return float(np.max(np.abs(wiggle)))
    return float(np.ptp(wiggle))


# --- reading responses --------------------------------------------------------------------------------

def parse_responses(entries: list, where: str = "study.responses") -> list[Response]:
    """Responses from their tables; one located problem per mistake."""
    out, problems = [], []
    if not isinstance(entries, list):
        raise ModelError([Problem(where, f"must be a list of response tables, got {entries!r}")])
    for k, entry in enumerate(entries):
        try:
            out.append(parse_response(entry, f"{where}[{k}]"))
        except ModelError as exc:
            problems.extend(exc.problems)
    names = [r.name for r in out]
    problems += [Problem(f"{where}[{k}].name", f"repeats the response name {n!r}")
                 for k, n in enumerate(names) if names.index(n) != k]
    if problems:
        raise ModelError(problems)
    return out


def parse_response(entry: Any, where: str) -> Response:
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
    if not isinstance(raw, list) or len(raw) != 2:
        problems.append(Problem(where, f"must be two times [start, end], e.g. [\"0 ms\", \"10 ms\"], got {raw!r}"))
        return None
    try:
        start, end = (to_si(t, "time") for t in raw)
    except UnitError as exc:
        problems.append(Problem(where, str(exc)))
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


def check_against(responses: list[Response], results) -> None:
    """A located error for each response naming a channel the run does not have (with close matches)."""
    problems = []
    for r in responses:
        if r.channel is not None and r.channel not in results:
            close = difflib.get_close_matches(r.channel, results.channels, n=3)
            hint = f"; did you mean {', '.join(close)}?" if close else ""
            problems.append(Problem(f"responses.{r.name}.channel", f"no channel {r.channel!r} in the run{hint}"))
    if problems:
        raise ModelError(problems)


def required_output_step(responses: list, t_end: float) -> float | None:
    """The largest output step [s] the responses need (an oscillation: half its grid step, so that its linear
    resampling follows the run's own curve), or None."""
    steps = []
    for r in responses:
        if getattr(r, "kind", None) == "oscillation":
            span = (r.window[1] - r.window[0]) if r.window else t_end
            cutoff = r.cutoff or DEFAULT_CYCLES_PER_WINDOW / span
            steps.append(0.5 / (SAMPLES_PER_CUTOFF_PERIOD * cutoff))
    return min(steps) if steps else None
