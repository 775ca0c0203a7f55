"""Timing of interleaved benchmark runs, reported the same way by every benchmark.

Each case is timed in wall time (``time.perf_counter``) and in CPU time of the
process (``time.process_time``; the engine releases the GIL but runs in the
calling thread, so the process's CPU time is the run's). The cases are run in
rounds, each round running every case once, so that drift of a shared machine
hits all of them alike. A ratio between two cases is formed round by round
(baseline of round k over engine of round k) and reported as the median of those
per-round ratios with its spread (the interquartile range, and the extremes):
a target counts as met only when the median meets it.
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any


@dataclass
class Case:
    """A benchmark case: a function running it once, and what the rounds measured (``None`` for a
    round in which the case did not run)."""

    name: str
    run: Callable[[], Any]
    walls: list[float | None] = field(default_factory=list)
    cpus: list[float | None] = field(default_factory=list)
    last: Any = None

    def time_once(self) -> None:
        wall0, cpu0 = time.perf_counter(), time.process_time()
        self.last = self.run()
        self.walls.append(time.perf_counter() - wall0)
        self.cpus.append(time.process_time() - cpu0)

    def skip(self) -> None:
        self.walls.append(None)
        self.cpus.append(None)

    def values(self, clock: str) -> list[float]:
        """The times [s] measured on ``clock`` (``"wall"`` or ``"cpu"``)."""
        return [v for v in (self.walls if clock == "wall" else self.cpus) if v is not None]

    def median(self, clock: str = "cpu") -> float:
        """Median time [s] on ``clock``."""
        return statistics.median(self.values(clock))


def interleave(cases: list[Case], rounds: int, runs_in_round: Callable[[Case, int], bool] | None = None) -> None:
    """Runs ``rounds`` rounds of every case (a case runs in round k when ``runs_in_round(case, k)``)."""
    for k in range(rounds):
        for case in cases:
            if runs_in_round is None or runs_in_round(case, k):
                case.time_once()
            else:
                case.skip()


@dataclass(frozen=True)
class Spread:
    """Median of some values with their quartiles and extremes."""

    median: float
    q1: float
    q3: float
    low: float
    high: float
    n: int

    @classmethod
    def of(cls, values: list[float]) -> Spread:
        values = sorted(values)
        if len(values) >= 2:
            q1, _, q3 = statistics.quantiles(values, n=4, method="inclusive")
        else:
            q1 = q3 = values[0]
        return cls(statistics.median(values), q1, q3, values[0], values[-1], len(values))

    def text(self, scale: float = 1.0, digits: int = 3) -> str:
        """``median [q1-q3]`` scaled (e.g. by 1e3 for ms)."""
        f = lambda v: f"{scale * v:.{digits}g}"  # noqa: E731
        return f"{f(self.median)} [{f(self.q1)}-{f(self.q3)}]"


def ratio(numerator: Case, denominator: Case, clock: str = "cpu") -> Spread:
    """Per-round ratios numerator / denominator on ``clock``, over the rounds in which both ran."""
    num = numerator.walls if clock == "wall" else numerator.cpus
    den = denominator.walls if clock == "wall" else denominator.cpus
    pairs = [a / b for a, b in zip(num, den) if a is not None and b is not None and b > 0]
    return Spread.of(pairs)


def verdict(value: float, op: str, target: float) -> str:
    """``met`` or ``MISSED`` for a median ``value`` against ``target`` (``op`` is ``>=`` or ``<=``)."""
    ok = value >= target if op == ">=" else value <= target
    return "met   " if ok else "MISSED"
