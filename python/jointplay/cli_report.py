"""``jointplay report``: one self-contained HTML report of a run, of several runs compared, or of a study
(:func:`jointplay.report.write_report`).

The report goes to ``-o FILE`` (an ``.html`` file), by default ``report.html`` next to the first results file
or inside the study folder. Progress goes to stderr; exit code 2 for bad input (a missing or unreadable
file, a folder that is not a study, an output that is not an ``.html`` file in an existing folder).
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from .cli import _bad_input, app, err, out
from .errors import ModelError

#: The options of the embedded animation, by the name the animation's problems give them.
_VIDEO_OPTIONS = {"size": "--video-size", "fps": "--video-fps", "duration": "--video-duration"}
#: The report's file name when ``-o`` is not given.
DEFAULT_NAME = "report.html"


@app.command()
def report(sources: Annotated[list[Path], typer.Argument(help="Results files (one: a run report; several: a "
                                                         "comparison) or a study folder.", show_default=False)],
           output: Annotated[Path | None, typer.Option("-o", "--output", help="The report, an .html file "
                                                       "[default: report.html next to the first results file, or "
                                                       "in the study folder].", show_default=False)] = None,
           title: Annotated[str | None, typer.Option("--title", help="Title of the report.")] = None,
           no_animation: Annotated[bool, typer.Option("--no-animation", help="Leave the animation of the "
                                                      "mechanism out (faster).")] = False,
           video_size: Annotated[str | None, typer.Option("--video-size", help="Frame size of the embedded "
                                                          "animation, WIDTHxHEIGHT [default: 1280x720].")] = None,
           video_fps: Annotated[float | None, typer.Option("--video-fps", help="Frames per second of the "
                                                           "embedded animation [default: 25].")] = None,
           video_duration: Annotated[str | None, typer.Option(
               "--video-duration", help='Length of the embedded animation, e.g. "5 s" [default: the run at real '
                                        "speed, kept within 5 to 10 s].")] = None) -> None:
    """Write a self-contained HTML report of a run, a comparison or a study.

    One results file gives the report of the run: the model with its
    parameters in units, the run's options and statistics, its summary,
    interactive plots of the standard channels and an animation of the
    mechanism. Several results files give their comparison side by side;
    a study folder (from jointplay sweep) the study's report. The file
    works offline: nothing is fetched when it is opened.
    """
    from .cli_animate import _seconds, _size
    from .report import write_report

    video = {"size": _size(video_size, "--video-size") if video_size else None, "fps": video_fps,
             "duration": _seconds(video_duration, "--video-duration")}
    animation = not no_animation and ({k: v for k, v in video.items() if v is not None} or True)
    target = output if output is not None else default_output(sources[0])
    try:
        written = write_report(sources, target, title=title, animation=animation,
                               progress=lambda message: err.print(f"{message} ...", markup=False, highlight=False))
    except ModelError as exc:  # one line per problem, located at its path or the option
        problems = [f"{_VIDEO_OPTIONS[p.location]}: {p.message}" if p.location in _VIDEO_OPTIONS else p
                    for p in exc.problems]
        if len(problems) == 1:
            raise _bad_input(str(problems[0]), []) from None
        raise _bad_input(f"{len(problems)} problems", problems) from None
    out.print(f"wrote {written}", markup=False, highlight=False)


def default_output(first: Path) -> Path:
    """``report.html`` in the study folder ``first``, or next to the results file ``first``."""
    return first / DEFAULT_NAME if first.is_dir() else first.parent / DEFAULT_NAME
