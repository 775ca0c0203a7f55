"""Studies: sweeps, designs of experiments, response surfaces and optimisation over model parameters.

:class:`Study` varies model values by their ``--set`` paths (ranges, levels, ISO 286 grades and fits),
over a design (full factorial, Latin hypercube, Sobol, central composite, Box-Behnken, Saltelli, a
table), and measures each run by responses (:mod:`.metrics`). Cases run in this process, on local
worker processes or on a Dask cluster, stream to a folder as they finish (a killed study resumes where
it stopped) and end as one xarray Dataset with a ``case`` dimension. :mod:`.surface`,
:mod:`.sensitivity` and :mod:`.optimize` analyse it. User guide: ``docs/studies.md``.
"""

from .dataset import open_study
from .study import Study
from .studyfile import load_study

__all__ = ["Study", "load_study", "open_study"]
