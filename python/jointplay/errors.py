"""Exceptions and warnings of jointplay.

``JointplayError`` is the base of every error jointplay raises on purpose:
``ModelError`` for a bad model description (one entry per problem, each with
its location), ``SimulationError`` for a run that stopped early (it keeps the
results computed up to that point), and ``ConvergenceError`` for an
iteration that did not converge.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .results import Results


class JointplayError(Exception):
    """Base class of jointplay's errors."""


@dataclass(frozen=True)
class Problem:
    """One problem in a model description."""

    location: str
    message: str

    def __str__(self) -> str:
        return f"{self.location}: {self.message}"


class ModelError(JointplayError, ValueError):
    """A model description is invalid. ``problems`` lists every problem found."""

    def __init__(self, problems: list[Problem] | list[tuple[str, str]]):
        self.problems = [p if isinstance(p, Problem) else Problem(*p) for p in problems]
        super().__init__("\n".join(str(p) for p in self.problems))


class SimulationError(JointplayError):
    """A simulation stopped early.

    Attributes: ``time`` [s] where it stopped, ``element`` it names (or None),
    ``kind`` (e.g. ``StepSizeUnderflow``), ``cause`` (the message) and
    ``results``: everything recorded up to that time.
    """

    def __init__(self, record: dict[str, Any], results: Results | None = None, stage: str = "integration"):
        self.kind: str = record.get("kind", "")
        self.cause: str = record.get("message", "")
        self.time: float = float(record.get("time", float("nan")))
        self.element: str | None = record.get("element")
        self.stage = stage
        self.results = results
        where = "while assembling the initial configuration" if stage == "assembly" else "during the simulation"
        super().__init__(f"{where}: {self.cause}")


class ConvergenceError(JointplayError):
    """An iteration (assembly, a Newton solve) did not converge."""


class JointplayWarning(UserWarning):
    """Something worth knowing that is not an error (soft contact, deep penetration)."""
