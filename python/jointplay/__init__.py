"""jointplay: dynamics of mechanisms with imperfect joints.

Build a mechanism with :class:`Model` (or load a model file), simulate it,
and look at named channels in SI units::

    import jointplay as jp
    m = jp.Model("pendulum", gravity=(0, -9.81))
    ...
    results = m.simulate(1.0)
    results["bar.omega"]
"""

from . import functions, laws, sections
from ._core import __version__
from .errors import ConvergenceError, JointplayError, JointplayWarning, ModelError, Problem, SimulationError
from .model import Model
from .results import Results

# Reading model files needs the unit registry and the schemas (pint, pydantic),
# and results files need xarray: those load on first use, so that
# `import jointplay` and `jointplay --help` stay fast.
_LAZY = {"load": "modelfile", "loads": "modelfile", "open_results": "results", "Study": "study",
         "load_study": "study", "open_study": "study"}


def __getattr__(name: str):
    if name in _LAZY:
        from importlib import import_module

        value = getattr(import_module(f".{_LAZY[name]}", __name__), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))

__all__ = [
    "ConvergenceError", "JointplayError", "JointplayWarning", "Model", "ModelError", "Problem", "Results",
    "SimulationError", "Study", "__version__", "functions", "laws", "load", "load_study", "loads", "open_results",
    "open_study", "sections",
]
