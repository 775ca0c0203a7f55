"""``jointplay animate``: an animation of a results file (:func:`jointplay.animation.animate`).

Exit code 2, with one line per problem, for a missing or unreadable results file, an unknown format,
channel or projection, or a bad option value.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from .cli import _bad_input, _open, app, err, out
from .errors import ModelError

#: The CLI's name of each option of :func:`jointplay.animation.animate`, for the messages.
_OPTION_NAMES = {"start": "--start", "end": "--end", "fps": "--fps", "duration": "--duration",
                 "clearance_scale": "--clearance-scale", "deformation_scale": "--deformation-scale",
                 "force_scale": "--force-scale", "channels": "--channel", "projection": "--projection",
                 "size": "--size"}
#: Frames from which an encode shows a progress bar.
_PROGRESS_FROM = 30


@app.command()
def animate(
        results: Annotated[Path, typer.Argument(help="Results file written by `jointplay run`.", show_default=False)],
        output: Annotated[Path, typer.Option("-o", "--output", help="Animation file: .mp4 (H.264), .webm (VP9), "
                                             ".gif, or .png (one still frame at --start).", show_default=False)],
        start: Annotated[str | None, typer.Option("--start", help='First time shown, e.g. "10 ms" or 0.01 '
                                                  "(seconds) [default: the run's start].")] = None,
        end: Annotated[str | None, typer.Option("--end", help="Last time shown [default: the run's end].")] = None,
        fps: Annotated[float, typer.Option("--fps", help="Frames per second of the video.")] = 25.0,
        duration: Annotated[str | None, typer.Option(
            "--duration", help='Length of the video, e.g. "8 s" [default: the run at real speed, kept within '
                               "5 to 10 s].")] = None,
        clearance_scale: Annotated[float | None, typer.Option(
            "--clearance-scale", help="Magnification of the clearance joints' eccentricity [default: a round "
                                      "number making the gap about 30 % of the bore radius].")] = None,
        deformation_scale: Annotated[float | None, typer.Option(
            "--deformation-scale", help="Magnification of beams' and modal bodies' deformation [default: "
                                        "a round number, at least 1].")] = None,
        force_scale: Annotated[str | None, typer.Option(
            "--force-scale", help='Length of a force arrow per newton, e.g. "1 mm/N" or 0.001 (m per N) '
                                  "[default: a round number making the largest arrow about 15 % of the "
                                  "mechanism].")] = None,
        channel: Annotated[list[str], typer.Option(
            "--channel", "-c", help="Channel drawn over time beside the mechanism (repeatable) [default: the force "
                                    "of the first clearance joint, else the first body's angle].")] = [],  # noqa: B006
        projection: Annotated[str, typer.Option("--projection", help="Plane a spatial model is drawn on: xy, xz, "
                                                "yz or iso.")] = "xy",
        size: Annotated[str, typer.Option("--size", help="Frame size in pixels, WIDTHxHEIGHT.")] = "1280x720",
        quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar.")] = False) -> None:
    """Animate the mechanism of a results file.

    Bodies, beams and modal bodies at their channels' positions (deformation
    magnified), each clearance joint's journal in its bore with the clearance
    magnified and its force as an arrow, and the chosen channels over time
    beside it; the time, the speed of the video and every magnification are
    stated in the picture. Channels are interpolated linearly between the
    saved samples at the frame times.
    """
    from .animation import animate as write_animation

    options = {"start": _seconds(start, "--start"), "end": _seconds(end, "--end"), "fps": fps,
               "duration": _seconds(duration, "--duration"), "clearance_scale": clearance_scale,
               "deformation_scale": deformation_scale, "force_scale": _force_scale(force_scale),
               "channels": channel or None, "projection": projection, "size": _size(size)}
    _check_output(output)
    r = _open(results)
    try:
        if quiet:
            path = write_animation(r, output, **options)
        else:
            path = _with_progress(write_animation, r, output, options)
    except ModelError as exc:
        problems = [f"{_OPTION_NAMES.get(p.location, p.location)}: {p.message}" for p in exc.problems]
        raise _bad_input(problems[0], problems[1:]) from None
    except OSError as exc:
        raise _bad_input(f"-o {output}: cannot write the animation ({exc.strerror or exc})", []) from None
    out.print(f"wrote {path}")


def _with_progress(write, results, output: Path, options: dict) -> Path:
    """``write(results, output, **options)`` with a progress bar on stderr once it has many frames."""
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

    bar = Progress(TextColumn("encoding"), BarColumn(), MofNCompleteColumn(), TextColumn("frames"),
                   TimeRemainingColumn(), console=err, transient=True)
    task = None

    def progress(done: int, total: int) -> None:
        nonlocal task
        if total < _PROGRESS_FROM:
            return
        if task is None:  # started at the first frame, so that a refused option prints no bar
            bar.start()
            task = bar.add_task("encode", total=total)
        bar.update(task, completed=done)

    try:
        return write(results, output, progress=progress, **options)
    finally:
        if task is not None:
            bar.stop()


def _check_output(output: Path) -> None:
    from .animation import FORMATS

    if output.suffix.lower() not in FORMATS:
        raise _bad_input(f"-o {output}: unknown animation format {output.suffix or '(no suffix)'!r}; give one of "
                         f"{', '.join(FORMATS)}", [])
    if not output.parent.is_dir():
        raise _bad_input(f"-o {output}: no folder {output.parent}", [])
    if output.is_dir():
        raise _bad_input(f"-o {output}: is a folder, not a file", [])


def _seconds(text: str | None, option: str) -> float | None:
    """A time option [s]: a quantity with its unit ("10 ms") or a number of seconds; at least 0."""
    return _quantity(text, option, "time")


def _force_scale(text: str | None) -> float | None:
    return _quantity(text, "--force-scale", "length per force")


def _quantity(text: str | None, option: str, kind: str) -> float | None:
    """``text`` as a float in SI units: a bare number, or a quantity of ``kind`` with its unit."""
    if text is None:
        return None
    try:
        return float(text)
    except ValueError:
        pass
    from .units import Kind, UnitError, to_si

    spec = Kind("length per force", "m/N", "1 mm/N") if kind == "length per force" else kind
    try:
        return float(to_si(text, spec))
    except UnitError as exc:
        raise _bad_input(f"{option}: {exc}", []) from None


def _size(text: str, option: str = "--size") -> tuple[int, int]:
    """``WIDTHxHEIGHT`` in pixels."""
    width, sep, height = text.lower().partition("x")
    if not (sep and width.strip().isdigit() and height.strip().isdigit()):
        raise _bad_input(f"{option}: must be WIDTHxHEIGHT in pixels, e.g. 1280x720, got {text!r}", [])
    return int(width), int(height)
