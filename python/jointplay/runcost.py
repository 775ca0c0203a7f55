"""What a run will cost: estimates before it starts where they can be made, and a projection from its
pace while it goes (docs/model-files.md, "What a run costs").

- **A Reynolds film solved at every evaluation** (``model = "reynolds_exact"``): a cold solve takes about
  :data:`NODE_SWEEP_SECONDS` per node and relaxation sweep, and the sweeps grow with the grid, about as
  nodes^:data:`SWEEP_EXPONENT` (measured at eps 0.6, L/D 1: 110 sweeps on 1 080 nodes, 545 on 15 840,
  1 724 to 4 750 on 62 000, at 7.6 to 10 ns per node and sweep). A grid whose solve takes more than
  :data:`SLOW_SOLVE` is warned of with the estimate, and with the run's total when its evaluations have a
  lower bound (a ``max_step``, or generalized-alpha's ``step``).
- **The pace of the run**: after :data:`PROJECT_AFTER` of wall time, a run whose pace so far projects more
  than :data:`LONG_RUN` to its end is warned of once, with the projection (and, for a results file with a
  sample at every step, the size it would write), so that a run never costs hours without saying so.
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Callable

from .errors import JointplayWarning, Problem

#: Wall time of one node in one relaxation sweep of a cold Reynolds solve [s] (measured: 7.6 to 10 ns).
NODE_SWEEP_SECONDS = 1e-8
#: Sweeps of a cold Reynolds solve, about nodes ** SWEEP_EXPONENT (a fit within a factor 2 of 1 080 to 62 000 nodes).
SWEEP_EXPONENT = 0.7
#: A Reynolds solve estimated above this is warned of [s]: a run of a few thousand steps then takes hours.
SLOW_SOLVE = 0.1
#: Evaluations of the right-hand side per step, at least, of each method.
EVALUATIONS_PER_STEP = {"dopri5": 6, "adams": 2, "bdf": 1, "generalized_alpha": 2}
#: Wall time after which the pace of a run is projected [s].
PROJECT_AFTER = 2.0
#: A run projected to take longer than this is warned of [s].
LONG_RUN = 3600.0


def duration(seconds: float) -> str:
    """``0.25 s``, ``12 min``, ``3.1 h``, ``4.2e+03 years``: the unit that fits."""
    for unit, size in (("years", 365.25 * 86400), ("days", 86400), ("h", 3600), ("min", 60)):
        if seconds >= 2 * size:
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.2g} s"


def reynolds_solve_seconds(n_circumferential: int, n_axial: int) -> float:
    """Estimated wall time of one cold Reynolds solve on the grid [s] (see the module docstring)."""
    nodes = n_circumferential * (n_axial // 2 + 1)
    return NODE_SWEEP_SECONDS * nodes * nodes**SWEEP_EXPONENT


def reynolds_cost(spec: dict, options: dict, t0: float, t_end: float) -> list[Problem]:
    """A warning per lubricated joint whose Reynolds solve at every evaluation is estimated to be slow."""
    from . import parameters as p

    method = options.get("method", "dopri5")
    per_step = EVALUATIONS_PER_STEP.get(method, 1)
    longest = options.get("step") if method == "generalized_alpha" else options.get("max_step")
    evaluations = math.ceil((t_end - t0) / longest) * per_step if longest else None
    out = []
    for joint in spec.get("joints", []):
        lubrication = joint.get("lubrication") or {}
        if lubrication.get("model") != "reynolds_exact":
            continue
        reynolds = lubrication.get("reynolds") or {}
        n_c = reynolds.get("n_circumferential") or p.REYNOLDS_GRID[0]
        n_a = reynolds.get("n_axial") or p.REYNOLDS_GRID[1]
        solve = reynolds_solve_seconds(n_c, n_a)
        if solve <= SLOW_SOLVE:
            continue
        nodes = n_c * (n_a // 2 + 1)
        total = (f"; this run takes at least {evaluations} evaluations ({method}, {per_step} per step of at most "
                 f"{longest:g} s), about {duration(evaluations * solve)}") if evaluations else ""
        out.append(Problem(f"joints.{joint['name']}.lubrication.grid",
                           f"{n_c} x {n_a} ({nodes} nodes on the half length): one Reynolds solve takes about "
                           f"{duration(solve)}, and the film is solved at every evaluation ({per_step} or more per "
                           f"step of {method}){total}; the default {p.REYNOLDS_GRID[0]} x {p.REYNOLDS_GRID[1]} "
                           "gives the force within about 0.3 %, and model = \"reynolds_table\" interpolates "
                           "precomputed forces"))
    return out


class Pace:
    """Called with the simulated time at each progress report: once the run has gone on for
    :data:`PROJECT_AFTER`, a run whose pace projects more than :data:`LONG_RUN` to its end is warned of,
    once. ``samples_written()`` (when given) tells the samples written so far, for the projected size of a
    run that records every step; ``clock`` is the wall clock [s]."""

    def __init__(self, t0: float, t_end: float, *, bytes_per_sample: int = 0,
                 samples_written: Callable[[], int] | None = None, budget: int | None = None,
                 clock: Callable[[], float] = time.perf_counter):
        self.t0, self.t_end, self.clock = t0, t_end, clock
        self.bytes_per_sample, self.samples_written, self.budget = bytes_per_sample, samples_written, budget
        self.started = clock()
        self.warned = False

    def __call__(self, t: float) -> None:
        if self.warned:
            return
        elapsed = self.clock() - self.started
        if elapsed < PROJECT_AFTER or not t > self.t0:
            return
        share = (t - self.t0) / (self.t_end - self.t0)
        remaining = elapsed * (1.0 - share) / share
        if remaining <= LONG_RUN:
            return
        self.warned = True
        message = (f"at its pace so far (t = {t:.4g} s of {self.t_end:.4g} s after {duration(elapsed)}), the run "
                   f"needs about {duration(remaining)} more")
        if self.samples_written is not None and self.bytes_per_sample:
            from .resultsfile import format_size

            size = self.samples_written() * self.bytes_per_sample / share
            message += f" and would write about {format_size(size)} (a sample at every step)"
            if self.budget is not None and size > self.budget:
                message += f"; max_output_bytes = {format_size(self.budget)} stops it before"
        message += ("; Ctrl-C stops it and keeps what was computed (a shorter t_end, a coarser model or looser "
                    "tolerances shorten it)")
        warnings.warn(str(Problem("simulation.t_end", message)), JointplayWarning, stacklevel=2)
