"""Frame times of an animation and the channels at those times (pure numpy).

Frames sample the run evenly between ``start`` and ``end``; every channel is interpolated linearly
between the saved samples at the frame times (a frame between two samples shows the straight-line
blend of the two, not what the integrator computed in between).
"""

from __future__ import annotations

import numpy as np

from ..errors import ModelError

#: Shortest default video [s]: a run shorter than this is slowed down to last this long.
SHORTEST_VIDEO = 5.0
#: Longest default video [s]: a run longer than this is sped up to last this long.
LONGEST_VIDEO = 10.0


def time_window(results, start: float | None, end: float | None) -> tuple[float, float]:
    """``(start, end)`` [s] of the animation: the run's first and last saved times by default; a
    ModelError when the results hold no samples or the window lies outside the run or is empty."""
    if results.time.size == 0:
        raise ModelError([("results", "hold no samples: nothing to animate")])
    first, last = float(results.time[0]), float(results.time[-1])
    start = first if start is None else float(start)
    end = last if end is None else float(end)
    problems = []
    if not first <= start <= last:
        problems.append(("start", f"must lie within the run [{first:.6g}, {last:.6g}] s, got {start:.6g} s"))
    if not first <= end <= last:
        problems.append(("end", f"must lie within the run [{first:.6g}, {last:.6g}] s, got {end:.6g} s"))
    if not problems and end < start:
        problems.append(("end", f"must not come before start ({start:.6g} s), got {end:.6g} s"))
    if problems:
        raise ModelError(problems)
    return start, end


def default_duration(span: float) -> float:
    """Length of the video [s] for ``span`` seconds of run: the run at real speed when that lasts
    between :data:`SHORTEST_VIDEO` and :data:`LONGEST_VIDEO`, else slowed down or sped up to the
    nearer of the two."""
    return min(max(span, SHORTEST_VIDEO), LONGEST_VIDEO)


def frame_times(start: float, end: float, fps: float, duration: float) -> np.ndarray:
    """``round(fps * duration)`` times (at least one) spread evenly over [start, end] [s], both ends
    included."""
    count = max(1, int(round(fps * duration)))
    if count == 1 or end == start:
        return np.full(count, start)
    return np.linspace(start, end, count)


class Sampled:
    """The channels of ``results`` interpolated linearly at ``times``, read once each on first use.

    ``sampled["crank.angle"]`` is an array over the frames; ``sampled.at(k, name)`` its value at frame k.
    """

    def __init__(self, results, times: np.ndarray):
        self.results = results
        self.times = np.asarray(times, dtype=float)
        self._cache: dict[str, np.ndarray] = {}

    def __contains__(self, name: str) -> bool:
        return name in self.results

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self._cache:
            self._cache[name] = np.interp(self.times, self.results.time, self.results[name])
        return self._cache[name]

    def at(self, k: int, name: str) -> float:
        """Value of channel ``name`` at frame ``k``."""
        return float(self[name][k])
