"""The page: a title and a list of :class:`~jointplay.report.blocks.Section` rendered into one self-contained
HTML file.

Every block kind is rendered one way, by the Jinja2 templates in ``templates/`` (``page.html.j2`` and its
style sheet ``page.css``, inlined): a :class:`Text` as a paragraph, a :class:`Table` with its numbers to six
significant digits, a :class:`Plot` as plotly's ``<div class="plotly-graph-div" id="plot-<k>">`` inside a
``<div class="jp-plot-wrap">`` (plotly.js inlined once, with the first plot of the page), a :class:`Video` as
``<video class="jp-video" id="video-<k>">`` (or ``<img>`` for a GIF) whose source is a base64 ``data:`` URI. Nothing is fetched when the file is opened: no
script or style sheet by address, no web font, no MathJax.
"""

from __future__ import annotations

import base64
import math
from datetime import datetime, timezone
from pathlib import Path
from typing import Any

from .blocks import Plot, Section, Table, Text, Video

#: Significant digits of the numbers in tables.
DIGITS = 6
#: plotly's configuration of every plot: no plotly logo, no "send to the cloud" (chart studio) button.
PLOT_CONFIG = {"displaylogo": False, "responsive": True,
               "showSendToCloud": False}


def format_cell(value: Any) -> str:
    """A table cell as text: integers as they are, other numbers to :data:`DIGITS` significant digits,
    booleans as yes/no, None and NaN as an en dash, strings as they are."""
    if value is None:
        return "–"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float) or hasattr(value, "dtype"):
        number = float(value)
        return "–" if math.isnan(number) else f"{number:.{DIGITS}g}"
    return str(value)


def render_page(title: str, sections: list[Section], path, *, subtitle: str = "") -> Path:
    """Writes ``sections`` as one self-contained HTML file at ``path``; returns the path."""
    from jinja2 import Environment, PackageLoader, select_autoescape

    environment = Environment(loader=PackageLoader("jointplay.report", "templates"),
                              autoescape=select_autoescape(["html", "j2"]), trim_blocks=True, lstrip_blocks=True)
    counter = _Counter()
    rendered = [{"title": s.title, "anchor": f"section-{k + 1}", "blocks": [_block(b, counter) for b in s.blocks],
                 "side_by_side": sum(isinstance(b, Video) for b in s.blocks) > 1}
                for k, s in enumerate(sections)]
    from .. import __version__

    created = datetime.now(timezone.utc).isoformat(timespec="seconds").replace("+00:00", "Z")
    html = environment.get_template("page.html.j2").render(
        title=title, subtitle=subtitle, sections=rendered, version=__version__, created=created)
    out = Path(path)
    out.write_text(html, encoding="utf-8")
    return out


class _Counter:
    """Numbers the plots and videos of a page (their ids; plotly.js goes with plot 1)."""

    def __init__(self) -> None:
        self.plots = 0
        self.videos = 0


def _block(block, counter: _Counter) -> dict:
    if isinstance(block, Text):
        return {"kind": "text", "text": block.text}
    if isinstance(block, Table):
        return {"kind": "table", "columns": block.columns, "caption": block.caption,
                "rows": [[format_cell(cell) for cell in row] for row in block.rows],
                "numeric": [[_is_number(cell) for cell in row] for row in block.rows]}
    if isinstance(block, Plot):
        counter.plots += 1
        return {"kind": "plot", "html": _plot_html(block.figure, counter.plots), "caption": block.caption,
                "id": f"plot-{counter.plots}"}
    if isinstance(block, Video):
        counter.videos += 1
        uri = f"data:{block.mime};base64,{base64.b64encode(block.data).decode('ascii')}"
        return {"kind": "gif" if block.mime == "image/gif" else "video", "uri": uri, "mime": block.mime,
                "caption": block.caption, "id": f"video-{counter.videos}"}
    raise TypeError(f"a report block must be Text, Table, Plot or Video, got {type(block).__name__}")


def _is_number(cell: Any) -> bool:
    return not isinstance(cell, (bool, str)) and (isinstance(cell, (int, float)) or hasattr(cell, "dtype"))


def _plot_html(figure, number: int) -> str:
    """The figure as a ``<div>`` with its script; plotly.js inlined with the first plot of the page."""
    from markupsafe import Markup

    html = figure.to_html(full_html=False, include_plotlyjs=number == 1, include_mathjax=False,
                          config=PLOT_CONFIG, div_id=f"plot-{number}")
    return Markup(html)
