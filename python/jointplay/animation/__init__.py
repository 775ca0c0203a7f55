"""Animations of a mechanism from its results alone: the bodies, beams and modal bodies at their
channels' positions, clearance joints with the journal in its magnified clearance, contact forces as
arrows, and chosen channels over time beside it.

    animate(results, "run.mp4")          # or .webm, .gif, .png (one still at ``start``)
    data = video_bytes(results, mime="video/mp4")

Frames are :mod:`~jointplay.animation.scene` (geometry, pure numpy), drawn by
:mod:`~jointplay.animation.render` (matplotlib Agg) and written by :mod:`~jointplay.animation.encode`.
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Callable, Sequence

from ..errors import ModelError
from .encode import FORMATS

__all__ = ["animate", "video_bytes", "FORMATS"]

#: Smallest frame, pixels (width, height): below it the text does not fit.
SMALLEST_SIZE = (160, 120)
#: Largest frame, pixels (width, height): 8K UHD.
LARGEST_SIZE = (7680, 4320)
#: Most memory the frames of a GIF may take before it is written [bytes] (one byte a pixel).
GIF_MAX_BYTES = 2**30


def animate(results, path, *, start: float | None = None, end: float | None = None, fps: float = 25,
            duration: float | None = None, clearance_scale: float | None = None,
            deformation_scale: float | None = None, force_scale: float | None = None,
            channels: Sequence[str] | None = None, projection: str = "xy", size: tuple[int, int] = (1280, 720),
            progress: Callable[[int, int], None] | None = None) -> Path:
    """Writes an animation of ``results`` to ``path``: MP4 (``.mp4``, H.264 in yuv420p), WebM (``.webm``,
    VP9), GIF (``.gif``) or one still PNG frame at ``start`` (``.png``, drawn with the scales the
    whole video would have); returns the path.

    Drawn from the results alone (``results.spec``, the channels, ``results.geometry``): a rigid body
    as the line through its points (two points), their convex hull (three or more) or a small square
    (one), at its pose channels; beams through their nodes; modal bodies as their mesh; ground points
    as triangles; joints as small circles at their first point, a translational joint as a dashed
    guide along its axis; force elements between two points as lines; each clearance joint as its
    bore and its journal (planar) or the bore's and the journal's axes and their circles at both rims
    (spatial), with its force as an arrow. The frames of a GIF are held in memory (one byte a pixel) until it is written.

    - ``start``, ``end`` [s]: the part of the run shown (default: all of it).
    - ``fps`` [1/s] and ``duration`` [s] of the video: ``round(fps * duration)`` frames at times spread
      evenly over [start, end], both included. Default duration: the run at real speed when that
      lasts 5 to 10 s, else slowed down to 5 s or sped up to 10 s; the picture states the speed.
      Channels are interpolated linearly between the saved samples at the frame times.
    - ``clearance_scale`` [-]: the eccentricity of each clearance joint is magnified by it (the
      journal's centre drawn at bearing centre + scale * e, the drawn gap scale * clearance);
      ``deformation_scale`` [-]: beams' deformation from their chord and modal bodies' modal
      displacements magnified by it (at 1 every node is where its channels put it);
      ``force_scale`` [m per N]: the force f of a clearance joint on its journal is drawn as an arrow of
      length scale * |f| ending at the contact point on the drawn bore (spatial: starting at the middle
      of the journal's axis, projected). None: chosen automatically as
      round numbers (see :mod:`jointplay.animation.scene`); every scale in use is stated in the picture.
    - ``channels``: channel names drawn over time beside the mechanism with a cursor at the frame's
      time (default: the force of the first clearance joint on its journal, ``<joint>.f``, else the
      first body's angle; of a spatial model without clearance joints, the coordinate of the first
      body's centre that moves most).
    - ``projection``: ``"xy"``, ``"xz"``, ``"yz"`` or ``"iso"`` (isometric, from (1, 1, 1), z up) for a
      spatial model; a planar model is drawn in its plane, ``"xy"``.
    - ``size``: (width, height) of the frames in pixels, each rounded up to an even number (H.264 in
      yuv420p needs it), at least 160 x 120.
    - ``progress(done, total)``: called after each frame is encoded.

    Bad values (an unknown suffix or channel, a time outside the run, a scale <= 0, a bad
    projection) raise a ModelError listing each problem.
    """
    from .render import Renderer
    from .scene import Scene

    path = Path(path)
    _check_path(path)
    size = _even_size(size)
    scene = Scene(results, start=start, end=end, fps=fps, duration=duration, clearance_scale=clearance_scale,
                  deformation_scale=deformation_scale, force_scale=force_scale, channels=channels,
                  projection=projection)
    if path.suffix.lower() == ".gif" and len(scene) * size[0] * size[1] > GIF_MAX_BYTES:
        raise ModelError([("size", f"a GIF of {len(scene)} frames of {size[0]} x {size[1]} is held in memory until "
                                   f"written, {len(scene) * size[0] * size[1] / 2**30:.1f} GiB, more than "
                                   f"{GIF_MAX_BYTES / 2**30:g} GiB: write .mp4, or fewer or smaller frames")])
    renderer = Renderer(scene, size, still=path.suffix.lower() == ".png")
    try:
        from .encode import write_frames

        frames = (renderer.rgb(k) for k in range(len(scene)))
        return write_frames(path, frames, len(scene), size, scene.fps, progress)
    finally:
        renderer.close()


def video_bytes(results, *, mime: str = "video/mp4", **options) -> bytes:
    """The animation of ``results`` as bytes of the format ``mime`` (``video/mp4``, ``video/webm``,
    ``image/gif``, ``image/png``), for embedding; ``options`` as :func:`animate` takes them."""
    suffixes = {m: s for s, m in FORMATS.items()}
    if mime not in suffixes:
        raise ModelError([("mime", f"must be one of {', '.join(suffixes)}, got {mime!r}")])
    with tempfile.TemporaryDirectory() as folder:
        path = animate(results, Path(folder) / f"animation{suffixes[mime]}", **options)
        return path.read_bytes()


def _check_path(path: Path) -> None:
    if path.suffix.lower() not in FORMATS:
        raise ModelError([(str(path), f"unknown animation format {path.suffix or '(no suffix)'!r}; "
                                      f"give one of {', '.join(FORMATS)}")])
    if not path.parent.is_dir():
        raise ModelError([(str(path), f"no folder {path.parent}")])
    if path.is_dir():
        raise ModelError([(str(path), "is a folder, not a file")])


def _even_size(size) -> tuple[int, int]:
    try:
        width, height = (int(v) for v in size)
    except (TypeError, ValueError):
        raise ModelError([("size", f"must be (width, height) in pixels, got {size!r}")]) from None
    if width < SMALLEST_SIZE[0] or height < SMALLEST_SIZE[1]:
        raise ModelError([("size", f"must be at least {SMALLEST_SIZE[0]} x {SMALLEST_SIZE[1]} pixels, "
                                   f"got {width} x {height}")])
    if width > LARGEST_SIZE[0] or height > LARGEST_SIZE[1]:
        raise ModelError([("size", f"must be at most {LARGEST_SIZE[0]} x {LARGEST_SIZE[1]} pixels, "
                                   f"got {width} x {height}")])
    return width + width % 2, height + height % 2
