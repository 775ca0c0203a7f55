"""Writing rendered frames to a file: MP4 (H.264, yuv420p) and WebM (VP9) through the ffmpeg that
imageio-ffmpeg ships (no system ffmpeg needed), GIF through Pillow, one PNG still through Pillow.

Each file is written under a temporary name beside ``path`` and renamed into place when complete.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Callable, Iterator

import numpy as np

#: Formats by suffix, and their MIME types.
FORMATS = {".mp4": "video/mp4", ".webm": "video/webm", ".gif": "image/gif", ".png": "image/png"}
#: ffmpeg's arguments per video format: codec and quality (constant rate factor; VP9 needs -b:v 0 for it).
_VIDEO = {".mp4": ("libx264", ["-crf", "20", "-preset", "medium", "-movflags", "+faststart"]),
          ".webm": ("libvpx-vp9", ["-crf", "32", "-b:v", "0", "-row-mt", "1"])}


def write_frames(path: Path, frames: Iterator[np.ndarray], count: int, size: tuple[int, int], fps: float,
                 progress: Callable[[int, int], None] | None = None) -> Path:
    """Writes ``count`` frames (height, width, 3 uint8 images of ``size`` (width, height)) to ``path``
    in the format of its suffix (a key of :data:`FORMATS`); ``progress(done, count)`` after each."""
    suffix = path.suffix.lower()
    partial = path.with_name(f".{path.stem}.partial{suffix}")
    try:
        if suffix in _VIDEO:
            _video(partial, frames, count, size, fps, suffix, progress)
        elif suffix == ".gif":
            _gif(partial, frames, count, fps, progress)
        else:
            _png(partial, next(iter(frames)))
            if progress:
                progress(1, 1)
        os.replace(partial, path)
    finally:
        if partial.exists():
            partial.unlink()
    return path


def _video(path: Path, frames, count: int, size: tuple[int, int], fps: float, suffix: str, progress) -> None:
    import imageio_ffmpeg

    codec, parameters = _VIDEO[suffix]
    writer = imageio_ffmpeg.write_frames(str(path), size, fps=fps, codec=codec, pix_fmt_in="rgb24",
                                         pix_fmt_out="yuv420p", quality=None, macro_block_size=2,
                                         ffmpeg_log_level="error", output_params=parameters)
    writer.send(None)  # starts ffmpeg
    try:
        for done, image in enumerate(frames, start=1):
            writer.send(np.ascontiguousarray(image).tobytes())
            if progress:
                progress(done, count)
    finally:
        writer.close()


def _gif(path: Path, frames, count: int, fps: float, progress) -> None:
    """An endlessly looping GIF; each frame reduced to its own 256-colour palette as it comes (one byte a
    pixel held). GIF counts frame times in hundredths of a second: a frame lasts round(100 / fps) / 100 s."""
    from PIL import Image

    images = []
    for done, image in enumerate(frames, start=1):
        images.append(Image.fromarray(image).quantize(colors=256, method=Image.Quantize.MEDIANCUT))
        if progress:
            progress(done, count)
    hundredths = max(1, round(100.0 / fps))
    images[0].save(path, format="GIF", save_all=True, append_images=images[1:], duration=10 * hundredths,
                   loop=0, optimize=False)


def _png(path: Path, image: np.ndarray) -> None:
    from PIL import Image

    Image.fromarray(image).save(path, format="PNG")
