"""What the command line shows: times in the unit that fits, and tables that never cut a number.

- :func:`time_unit` picks the unit in which times of a run read best (ns to h), from the run's
  length; :func:`format_time` writes a time in it, :func:`format_duration` a wall-clock duration
  (``12 s``, ``3 min 05 s``, ``1 h 20 min``).
- :func:`table` builds a rich table whose cells fold instead of being cut with an ellipsis;
  :func:`print_table` prints it so that no word of a cell (a number, a unit) is ever split:
  each column is at least as wide as its longest word, and a table that cannot fit the terminal
  that way is printed as a list, one ``column: value`` line per cell.
"""

from __future__ import annotations

import math
import textwrap

from rich.cells import cell_len
from rich.console import Console
from rich.progress import ProgressColumn, Task
from rich.table import Table
from rich.text import Text

#: Units of time, smallest first: (name, seconds).
TIME_UNITS = (("ns", 1e-9), ("µs", 1e-6), ("ms", 1e-3), ("s", 1.0), ("min", 60.0), ("h", 3600.0))
#: A span reads in a unit from this many of it: 1 ms up to 1 s reads in ms, but 1 s up to 2 min in s,
#: 2 min up to 2 h in min (90 s reads better than 1.5 min).
_FROM = {"ns": 0.0, "µs": 1.0, "ms": 1.0, "s": 1.0, "min": 2.0, "h": 2.0}


def time_unit(span: float) -> tuple[str, float]:
    """The unit in which times up to ``span`` [s] read best, and its length [s]: ``(name, seconds)``."""
    span = abs(span) if span is not None and math.isfinite(span) else 0.0
    if span == 0:
        return ("s", 1.0)
    chosen = TIME_UNITS[0]
    for name, seconds in TIME_UNITS:
        if span >= _FROM[name] * seconds:
            chosen = (name, seconds)
    return chosen


def format_time(t: float | None, span: float | None = None, digits: int = 4) -> str:
    """``t`` [s] with ``digits`` significant digits in the unit that fits ``span`` [s] (default: ``t``
    itself), or in its own unit if the span's would need a power of ten: ``format_time(2.514e-4)`` is
    ``"251.4 µs"``, ``format_time(2.514e-4, 0.024)`` ``"0.2514 ms"``, ``format_time(1e-9, 0.024)`` ``"1 ns"``."""
    if t is None or (isinstance(t, float) and math.isnan(t)):
        return ""
    name, seconds = time_unit(t if span is None else span)
    text = f"{t / seconds:.{digits}g}"
    if "e" in text and span is not None:
        return format_time(t, None, digits)
    return f"{text} {name}"


def format_duration(seconds: float | None) -> str:
    """A wall-clock duration: ``"0.4 s"``, ``"12 s"``, ``"3 min 05 s"``, ``"1 h 20 min"``; ``""`` if unknown."""
    if seconds is None or not math.isfinite(seconds):
        return ""
    if seconds < 10:
        return f"{seconds:.1f} s"
    whole = int(round(seconds))
    if whole < 60:
        return f"{whole} s"
    if whole < 3600:
        return f"{whole // 60} min {whole % 60:02d} s"
    return f"{whole // 3600} h {whole % 3600 // 60:02d} min"


class WallTimeColumn(ProgressColumn):
    """``(12 s elapsed, about 1 min 40 s left)``: the wall time, and the rest estimated from the recent
    rate of progress."""

    def render(self, task: Task) -> Text:
        elapsed = format_duration(task.elapsed or 0.0)
        if task.finished:
            return Text(f"({elapsed} elapsed)")
        remaining = task.time_remaining
        left = "estimating the time left" if remaining is None else f"about {format_duration(remaining)} left"
        return Text(f"({elapsed} elapsed, {left})")


# tables ------------------------------------------------------------------------

def table(*headers: str, title: str | None = None) -> Table:
    """A table whose cells fold rather than being cut (print it with :func:`print_table`)."""
    t = Table(title=title)
    for header in headers:
        t.add_column(header, overflow="fold")
    return t


def _plain(cell) -> str:
    return cell.plain if isinstance(cell, Text) else str(cell)


def _texts(column) -> list[str]:
    return [_plain(column.header), *(_plain(cell) for cell in column.cells)]


def min_widths(t: Table) -> list[int]:
    """Each column's longest word (header or cell): the narrowest it can be without splitting one."""
    return [max(cell_len(word) for text in _texts(c) for word in [*text.split(), ""]) for c in t.columns]


def max_widths(t: Table) -> list[int]:
    """Each column's longest line (header or cell): its width when nothing wraps."""
    return [max(cell_len(line) for text in _texts(c) for line in [*text.splitlines(), ""]) for c in t.columns]


def _overhead(t: Table) -> int:
    """Borders and padding (one space each side of a cell) of ``t``."""
    return 3 * len(t.columns) + 1


def column_widths(t: Table, width: int) -> list[int] | None:
    """Widths of the columns of ``t`` (padding and borders excluded) on a console ``width`` wide: the
    widest columns narrowed to a common cap, as far as the console needs, but none below its longest
    word; None when the longest words alone do not fit."""
    low, high = min_widths(t), max_widths(t)
    room = width - _overhead(t)
    if sum(low) > room:
        return None

    def capped(cap: int) -> list[int]:
        return [max(lo, min(h, cap)) for lo, h in zip(low, high)]

    cap = max(high)
    while cap > 0 and sum(capped(cap)) > room:
        cap -= 1
    return capped(cap)


def print_table(console: Console, t: Table) -> None:
    """Prints ``t`` with no number (no word of a cell) cut or split: as a table whose columns are
    each at least as wide as their longest word when that fits the console, else as a list, one
    ``header: value`` line per cell."""
    widths = column_widths(t, console.width)
    if widths is not None:
        for column, w in zip(t.columns, widths):
            column.width = w
        console.print(t)
        return
    lines = textwrap.wrap(_plain(t.title), console.width) if t.title else []
    headers = [_plain(c.header) for c in t.columns]
    for row in zip(*(c.cells for c in t.columns)):
        for k, (header, cell) in enumerate(zip(headers, row)):
            lead = "- " if k == 0 else "    "
            indent = "  " if k == 0 else " " * 6
            lines += textwrap.wrap(f"{lead}{header}: {_plain(cell)}", console.width, subsequent_indent=indent,
                                   break_long_words=False, break_on_hyphens=False)
    for line in lines:  # wrapped here, between words only: a word wider than the console stays whole
        console.print(line, markup=False, highlight=False, soft_wrap=True)
