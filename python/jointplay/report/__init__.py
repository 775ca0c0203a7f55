"""Reports: one self-contained HTML file of a run, of several runs compared, or of a study.

``write_report(sources, path)`` decides which from ``sources`` (:mod:`jointplay.report.write`); the
sections of each kind of report are built by :mod:`~jointplay.report.run`, :mod:`~jointplay.report.compare`
and :mod:`~jointplay.report.study`, and rendered by :func:`jointplay.report.page.render_page`. Heavy
libraries (plotly, Jinja2) load when a report is written, not on import.
"""

from __future__ import annotations

from .write import write_report

__all__ = ["write_report"]
