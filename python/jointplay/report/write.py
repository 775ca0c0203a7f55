"""Writing a report: one run, several runs compared, or a study, to one self-contained HTML file.

Bad input (a missing file, a file that is not a results file, a folder that is not a study, an output path
that is not an ``.html`` file in an existing folder) raises :class:`~jointplay.errors.ModelError`, each
problem located at the path concerned.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from ..errors import ModelError, Problem

#: The file of a study folder that marks it as one (written by ``jointplay sweep``).
STUDY_FILE = "study.json"


def write_report(sources: Any, path, *, title: str | None = None, animation: bool | dict = True,
                 progress: Callable[[str], None] | None = None) -> Path:
    """Writes the report of ``sources`` to ``path`` (an ``.html`` file) and returns its path.

    ``sources``: one :class:`~jointplay.Results` or results-file path (a run report), several (a comparison,
    one column per run), or a study folder holding ``study.json`` (a study report). ``title`` replaces the
    report's title; ``animation`` False leaves the animations of the runs out, a dict gives their options
    (:func:`jointplay.animation.animate`'s, e.g. ``{"size": (640, 360), "fps": 15}``). ``progress`` (a function of a
    message) hears of the slow steps."""
    items = _as_list(sources)
    out = Path(path)
    problems = _output_problems(out) + _source_problems(items)
    if problems:
        raise ModelError(problems)
    say = progress or (lambda message: None)
    folders = [Path(s) for s in items if not _is_results(s) and Path(s).is_dir()]
    if folders:
        from .study import study_sections

        say(f"reading the study in {folders[0]}")
        default_title, sections = study_sections(folders[0])
        subtitle = f"Study folder {folders[0]}"
    else:
        runs = [_open(s, say) for s in items]
        default_title, subtitle, sections = _run_or_comparison(runs, animation, say)
    from .page import render_page

    say(f"writing {out}")
    return render_page(title or default_title, sections, out, subtitle=subtitle)


def _as_list(sources: Any) -> list:
    if _is_results(sources) or isinstance(sources, (str, Path)):
        return [sources]
    return list(sources)


def _is_results(source: Any) -> bool:
    from ..results import Results

    return isinstance(source, Results)


def _output_problems(out: Path) -> list[Problem]:
    """What is wrong with the output path: not ``.html``, a folder, or in a folder that does not exist."""
    if out.suffix.lower() != ".html":
        return [Problem(str(out), "a report is an HTML file: its name must end in .html")]
    if out.is_dir():
        return [Problem(str(out), "is a folder; give the report's file name, ending in .html")]
    if not out.parent.is_dir():
        return [Problem(str(out), f"the folder {out.parent} does not exist")]
    return []


def _source_problems(items: list) -> list[Problem]:
    """What is wrong with the sources: none, a missing path, a folder that is not a study, or a study folder
    among other sources."""
    if not items:
        return [Problem("sources", "give a results file, several, or a study folder")]
    problems = []
    paths = [Path(s) for s in items if not _is_results(s)]
    for p in paths:
        if not p.exists():
            problems.append(Problem(str(p), "no such results file or study folder"))
        elif p.is_dir() and not (p / STUDY_FILE).is_file():
            problems.append(Problem(str(p), f"is a folder without {STUDY_FILE}: not a study folder (a study "
                                            "written by jointplay sweep holds one)"))
        elif p.is_dir() and len(items) > 1:
            problems.append(Problem(str(p), "a study folder is reported on its own, not with other sources"))
    return problems


def _open(source: Any, say: Callable[[str], None]):
    """Results from a results object or a results file (a ModelError located at the path if it is none)."""
    if _is_results(source):
        return source
    from ..results import open_results

    say(f"reading {source}")
    return open_results(source)


def _run_or_comparison(runs: Sequence, animation: bool | dict, say: Callable[[str], None]) -> tuple[str, str, list]:
    """(title, subtitle, sections) of the report of one run or of the comparison of several."""
    if len(runs) == 1:
        from .run import run_label, run_sections

        run = runs[0]
        name = (run.spec or {}).get("name", "")
        subtitle = run.description or (f"Model {name}" if name else "")
        return f"Run report: {run_label(run)}", subtitle, run_sections(run, animation=animation, progress=say)
    from .compare import compare_sections, run_labels

    say("comparing the runs" + (" and rendering their animations" if animation else ""))
    return f"Comparison of {len(runs)} runs", ", ".join(run_labels(runs)), compare_sections(runs, animation=animation)
