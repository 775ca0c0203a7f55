"""The pieces a report is made of, as data: a report is a title and a list of :class:`Section`, each a list
of blocks (:class:`Text`, :class:`Table`, :class:`Plot`, :class:`Video`). What goes into a report (the model,
a run's summary, a study's design) is decided by the modules that build sections; how it looks is decided
once, by the page (:mod:`jointplay.report.page`), which renders every block kind the same way in every
report."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Union


@dataclass
class Text:
    """A paragraph of plain text (escaped when rendered; no markup)."""

    text: str


@dataclass
class Table:
    """A table: ``columns`` headers (units in the header, e.g. ``"clearance [mm]"``), ``rows`` of cells
    (numbers are formatted by the page, strings shown as they are), and an optional caption."""

    columns: list[str]
    rows: list[list[Any]]
    caption: str = ""


@dataclass
class Plot:
    """An interactive figure: a ``plotly.graph_objects.Figure`` whose axis titles carry units, and a caption
    saying what it shows."""

    figure: Any
    caption: str = ""


@dataclass
class Video:
    """An animation embedded in the page: the encoded bytes and their MIME type (``video/mp4``,
    ``video/webm`` or ``image/gif``), and a caption stating its scales (clearance and deformation
    magnification, force arrows)."""

    data: bytes
    mime: str
    caption: str = ""


Block = Union[Text, Table, Plot, Video]


@dataclass
class Section:
    """A titled part of a report."""

    title: str
    blocks: list[Block] = field(default_factory=list)
