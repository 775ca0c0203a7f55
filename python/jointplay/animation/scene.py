"""The scene of an animation: its frame times, the geometry of each frame, the scales of magnification
and what the picture states about them (pure numpy, no drawing).

Scales left as None are chosen from the run, as round numbers (1, 2 or 5 x 10^k):
- clearance: the magnified radial clearance about 30 % of the bore radius (the smallest such factor
  over the clearance joints, so no joint's gap exceeds it);
- deformation: the largest magnified deformation of a beam or modal body about 5 % of the
  mechanism's size, never below 1 (a deformation already that large is drawn as it is);
- force [m per N]: the largest force arrow about 15 % of the mechanism's size, stated as a round
  force per a round length ("force 100 N per 10 mm").
"""

from __future__ import annotations

import math
from typing import Sequence

import numpy as np

from ..errors import ModelError
from .frame import FrameGeometry
from .planar import PlanarModel
from .sampling import Sampled, default_duration, frame_times, time_window
from .spatial import PROJECTIONS, SpatialModel

#: Target of the automatic clearance scale: the magnified clearance as a share of the bore radius.
CLEARANCE_SHARE = 0.3
#: Target of the automatic deformation scale: the largest magnified deformation as a share of the size.
DEFORMATION_SHARE = 0.05
#: Target of the automatic force scale: the longest force arrow as a share of the mechanism's size.
FORCE_SHARE = 0.15
#: Side of the square drawn for a body with a single point, as a share of the mechanism's size.
BLOCK_SHARE = 0.04
#: Length of a translational joint's guide, as a share of the mechanism's size.
GUIDE_SHARE = 0.3


def round_125(value: float) -> float:
    """The number of the form 1, 2 or 5 x 10^k nearest to ``value`` > 0 on a logarithmic scale."""
    exponent = math.floor(math.log10(value))
    mantissa = value / 10.0**exponent
    best = min((1.0, 2.0, 5.0, 10.0), key=lambda m: abs(math.log(mantissa / m)))
    return best * 10.0**exponent


class Scene:
    """Frames of an animation of ``results`` between ``start`` and ``end`` [s] (see :func:`jointplay.animation.animate`
    for the options). ``times`` are the frame times [s], ``frame(k)`` the geometry of frame k,
    ``scales`` the magnifications used, ``notes`` the lines the picture states, ``limits`` the view
    (xmin, xmax, ymin, ymax) [m] holding every frame."""

    def __init__(self, results, *, start: float | None = None, end: float | None = None, fps: float = 25,
                 duration: float | None = None, clearance_scale: float | None = None,
                 deformation_scale: float | None = None, force_scale: float | None = None,
                 channels: Sequence[str] | None = None, projection: str = "xy"):
        spec = results.spec
        if not spec:
            raise ModelError([("results", "carry no model (model_json): nothing to draw")])
        self.results = results
        self.spatial = bool(spec.get("spatial_bodies"))
        _check_options(self.spatial, fps, duration, projection,
                       {"clearance_scale": clearance_scale, "deformation_scale": deformation_scale,
                        "force_scale": force_scale})
        self.start, self.end = time_window(results, start, end)
        self.fps = float(fps)
        self.duration = float(duration) if duration is not None else default_duration(self.end - self.start)
        self.times = frame_times(self.start, self.end, self.fps, self.duration)
        self.sampled = Sampled(results, self.times)
        self.projection = projection
        self.model = SpatialModel(spec, self.sampled, projection) if self.spatial else \
            PlanarModel(spec, results.geometry, self.sampled)
        self.channels = self._channels(channels)
        self.scales = self._scales(clearance_scale, deformation_scale, force_scale)
        self.limits = self._limits()

    def frame(self, k: int) -> FrameGeometry:
        """The geometry of frame k."""
        return self.model.frame(k, self.scales)

    def __len__(self) -> int:
        return self.times.size

    # channels ---------------------------------------------------------------

    def _channels(self, chosen: Sequence[str] | None) -> list[str]:
        """The channels drawn beside the mechanism: the chosen ones (a ModelError naming an unknown
        one, with a did-you-mean), or the force of the first clearance joint, else the first body's
        angle (of a spatial model: the coordinate of its centre that moves most)."""
        if chosen:
            problems = []
            for name in chosen:
                if name not in self.results:
                    try:
                        self.results[name]
                    except KeyError as exc:
                        problems.append(("channels", str(exc.args[0])))
            if problems:
                raise ModelError(problems)
            return list(chosen)
        joints = self._clearance_joints()
        candidates = [f"{joints[0]['name']}.f"] if joints else []
        spec = self.results.spec
        bodies = [b["name"] for key in ("bodies", "modal_bodies") for b in spec.get(key, [])]
        candidates += [f"{b}.angle" for b in bodies]
        found = [c for c in candidates if c in self.results]
        return found[:1] or self._moving_coordinate()

    def _moving_coordinate(self) -> list[str]:
        """The x, y or z of the first spatial body that moves most over the window (none if no such channel)."""
        spatial = self.results.spec.get("spatial_bodies", [])
        names = [f"{spatial[0]['name']}.{c}" for c in "xyz"] if spatial else []
        names = [n for n in names if n in self.results]
        if not names:
            return []
        return [max(names, key=lambda n: float(np.ptp(self.sampled[n])))]

    def _clearance_joints(self) -> list[dict]:
        return self.model.clearance

    # scales -----------------------------------------------------------------

    def _scales(self, clearance: float | None, deformation: float | None, force: float | None) -> dict:
        provisional = {"clearance": 1.0, "deformation": 1.0, "force": 0.0, "block": 0.0, "guide": 0.0}
        self.size = _size(np.vstack([self.model.frame(k, provisional).points() for k in range(len(self))]))
        scales = dict(provisional, block=BLOCK_SHARE * self.size, guide=GUIDE_SHARE * self.size)
        scales["clearance"] = clearance if clearance is not None else self._auto_clearance()
        scales["deformation"] = deformation if deformation is not None else self._auto_deformation()
        self.force_length = round_125(0.1 * self.size)  # [m] the length the force statement quotes
        scales["force"] = force if force is not None else self._auto_force()
        return scales

    @property
    def has_clearance_joints(self) -> bool:
        """Whether the model has a clearance joint (drawn magnified, with its force)."""
        return bool(self._clearance_joints())

    def _auto_clearance(self) -> float:
        shares = [CLEARANCE_SHARE * j.get("bearing_radius", j.get("bore_radius")) / j["clearance"]
                  for j in self._clearance_joints()]
        return round_125(min(shares)) if shares else 1.0

    def _auto_deformation(self) -> float:
        largest = self._largest_deformation()
        if largest <= 1e-12 * self.size:
            return 1.0
        return max(1.0, round_125(DEFORMATION_SHARE * self.size / largest))

    def _largest_deformation(self) -> float:
        """The largest deformation of a beam (from its moved chord) or a modal body over the frames [m]."""
        if self.spatial:
            return 0.0
        model, largest = self.model, 0.0
        for k in range(len(self)):
            for name in model.beams:
                offset = model.beam_nodes_drawn(k, name, 1.0) - model.beam_nodes_drawn(k, name, 0.0)
                largest = max(largest, float(np.max(np.hypot(*offset.T), initial=0.0)))
            for name in model.modal_geometry:
                offset = model.modal_nodes_drawn(k, name, 1.0) - model.modal_nodes_drawn(k, name, 0.0)
                largest = max(largest, float(np.max(np.hypot(*offset.T), initial=0.0)))
        return largest

    def largest_force(self) -> float:
        """The largest force of a clearance joint on its journal at the frames [N]."""
        largest = 0.0
        for joint in self._clearance_joints():
            components = [self.sampled[f"{joint['name']}.f{c}"] for c in ("xyz" if self.spatial else "xy")]
            largest = max(largest, float(np.max(np.linalg.norm(np.vstack(components), axis=0))))
        return largest

    def _auto_force(self) -> float:
        """[m per N]: a round force per :attr:`force_length` such that the largest arrow is about
        FORCE_SHARE of the size."""
        largest = self.largest_force()
        if largest <= 0.0:
            return self.force_length / 1.0
        return self.force_length / round_125(largest * self.force_length / (FORCE_SHARE * self.size))

    # view and statements ----------------------------------------------------

    def _limits(self) -> tuple[float, float, float, float]:
        points = np.vstack([self.frame(k).points() for k in range(len(self))])
        low, high = points.min(axis=0), points.max(axis=0)
        pad = 0.08 * max(float(np.max(high - low)), 1e-3)
        return low[0] - pad, high[0] + pad, low[1] - pad, high[1] + pad

    @property
    def time_scale(self) -> float:
        """Seconds of video per second of run (1: real time; below 1: sped up)."""
        span = self.end - self.start
        return self.duration / span if span > 0 else float("inf")

    def notes(self, still: bool = False) -> list[str]:
        """What the picture states: the sampling and speed (of a ``still``: that it is one frame), and
        each magnification in use."""
        from ..display import format_time

        if still:
            lines = [f"the mechanism at t = {format_time(self.start)}, scales chosen for "
                     f"{format_time(self.start)} to {format_time(self.end)}"]
        else:
            lines = [f"{format_time(self.end - self.start) or '0 s'} of run in {len(self)} frames at "
                     f"{_number(self.fps)} fps ({self._speed()}), channels interpolated linearly between samples"]
        scales = []
        if self._clearance_joints():
            scales.append(f"clearance x {_number(self.scales['clearance'])}")
        if not self.spatial and (self.model.beams or self.model.modal_geometry):
            scales.append(f"deformation x {_number(self.scales['deformation'])}")
        if self._clearance_joints():
            newtons = self.force_length / self.scales["force"]
            scales.append(f"force {_force(newtons)} per {_length(self.force_length)}")
        if scales:
            lines.append(", ".join(scales))
        return lines


    def _speed(self) -> str:
        """``real time``, ``slowed x 500`` or ``sped up x 10``: the video's pace against the run's."""
        scale = self.time_scale
        if not math.isfinite(scale):
            return "one instant"
        if math.isclose(scale, 1.0, rel_tol=1e-6):
            return "real time"
        return f"slowed x {_number(scale)}" if scale > 1 else f"sped up x {_number(1 / scale)}"


def _size(points: np.ndarray) -> float:
    """The larger side of the box holding ``points`` [m] (0.1 m when they all coincide)."""
    if len(points) == 0:
        return 0.1
    side = float(np.max(points.max(axis=0) - points.min(axis=0)))
    return side if side > 0 else 0.1


def _number(value: float) -> str:
    return f"{value:.3g}"


def _force(newtons: float) -> str:
    if newtons >= 1e3:
        return f"{newtons / 1e3:.3g} kN"
    return f"{newtons:.3g} N"


def _length(metres: float) -> str:
    if metres >= 1.0:
        return f"{metres:.3g} m"
    return f"{metres * 1e3:.3g} mm"


#: Most frames of one animation: 24 minutes at 25 frames a second (each frame is drawn, about 50 ms).
MAX_FRAMES = 36_000


def _check_options(spatial: bool, fps: float, duration: float | None, projection: str, scales: dict) -> None:
    """A ModelError listing every bad option value."""
    problems = []
    fps_ok = isinstance(fps, (int, float)) and math.isfinite(fps) and fps > 0
    if not fps_ok:
        problems.append(("fps", f"must be a number of frames per second > 0, got {fps!r}"))
    if duration is not None and not (math.isfinite(duration) and duration > 0):
        problems.append(("duration", f"must be a video length > 0 s, got {duration!r}"))
    elif duration is not None and fps_ok and fps * duration > MAX_FRAMES:
        problems.append(("duration", f"{fps:g} frames a second for {duration:g} s make {fps * duration:.0f} "
                                     f"frames; at most {MAX_FRAMES} (shorten the video or lower the rate)"))
    for key, value in scales.items():
        if value is not None and not (math.isfinite(value) and value > 0):
            problems.append((key, f"must be > 0, got {value!r}"))
    if projection not in PROJECTIONS:
        problems.append(("projection", f"must be one of {', '.join(PROJECTIONS)}, got {projection!r}"))
    elif not spatial and projection != "xy":
        problems.append(("projection", f"a planar model is drawn in its plane, xy; got {projection!r}"))
    if problems:
        raise ModelError(problems)
