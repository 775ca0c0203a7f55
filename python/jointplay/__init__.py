"""jointplay: dynamics of mechanisms with imperfect joints.

Build a mechanism with :class:`Model` (or load a model file), simulate it,
and look at named channels in SI units::

    import jointplay as jp
    m = jp.Model("pendulum", gravity=(0, -9.81))
    ...
    results = m.simulate(1.0)
    results["bar.omega"]
"""

from . import functions, laws
from ._core import __version__
from .errors import ConvergenceError, JointplayError, JointplayWarning, ModelError, Problem, SimulationError
from .model import Model
from .modelfile import load, loads
from .results import Results, open_results

__all__ = [
    "ConvergenceError", "JointplayError", "JointplayWarning", "Model", "ModelError", "Problem", "Results",
    "SimulationError", "__version__", "functions", "laws", "load", "loads", "open_results",
]
