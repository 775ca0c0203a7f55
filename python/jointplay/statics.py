"""Static equilibrium of a mechanism: :meth:`jointplay.Model.equilibrium`, ``jointplay static MODEL``.

The core finds the positions at which the mechanism, at rest, stays at rest (docs/theory/static-equilibrium.md);
here its result becomes an :class:`Equilibrium` whose channels (joint reactions, spring forces, chamber
pressures, strains) are read by a run of zero length started there, so they are the same channels, in the
same units, as any run's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from .errors import ModelError, SimulationError

if TYPE_CHECKING:
    from .model import Model


@dataclass
class Equilibrium:
    """A static equilibrium found."""

    #: Position coordinates at the equilibrium (bodies' ``(x, y, phi)``, beams' nodes, ...) [m, rad].
    coordinates: np.ndarray
    #: Continuous element states (a cylinder's chamber pressures [Pa], ...).
    element_states: np.ndarray
    #: Largest force residual left [N or N m].
    force_residual: float
    #: Largest residual of the joints' and drivers' equations left [m or rad].
    constraint_residual: float
    #: Newton iterations taken.
    iterations: int
    #: Every channel at the equilibrium (``"O.fx"``, ``"spring.force"``, ``"arm.x"``...) [SI units].
    values: dict[str, float] = field(default_factory=dict)
    #: Units of the channels.
    units: dict[str, str] = field(default_factory=dict)

    def __getitem__(self, channel: str) -> float:
        try:
            return self.values[channel]
        except KeyError:
            raise KeyError(f"no channel {channel!r}; channels: {sorted(self.values)}") from None

    @property
    def reactions(self) -> dict[str, float]:
        """The joints' and drivers' reaction channels (``*.fx``, ``*.fy``, ``*.moment``, ``*.force``,
        ``*.torque`` of ideal joints and drivers) [N, N m]."""
        quantities = ("fx", "fy", "moment", "force", "torque")
        return {name: value for name, value in self.values.items()
                if name.rsplit(".", 1)[-1] in quantities and self.units.get(name) in ("N", "N m")}


def equilibrium(model: Model, t0: float, tolerance: float, max_iterations: int) -> Equilibrium:
    """The static equilibrium of ``model`` at ``t0`` (see :meth:`jointplay.Model.equilibrium`)."""
    problems = []
    if isinstance(tolerance, bool) or not (isinstance(tolerance, (int, float)) and 1e-15 <= tolerance < 1):
        problems.append(("equilibrium.tolerance", f"must be from 1e-15 to below 1, got {tolerance!r}"))
    if isinstance(max_iterations, bool) or not (isinstance(max_iterations, int) and max_iterations > 0):
        problems.append(("equilibrium.max_iterations", f"must be a positive integer, got {max_iterations!r}"))
    if not (isinstance(t0, (int, float)) and math.isfinite(t0)):
        problems.append(("equilibrium.t0", f"must be a finite time in s, got {t0!r}"))
    spec = model.to_spec()
    for element in spec.get("joints", []):
        if element.get("type") == "clearance_revolute" and not element.get("lock_at_assembly", True):
            problems.append((f"joints.{element['name']}.lock_at_assembly", "the static equilibrium finds where the "
                                                                           "journal rests from the joint held at "
                                                                           "assembly: leave lock_at_assembly true"))
    _warn_of_inflows(spec)
    if problems:
        raise ModelError(problems)
    core = model.compile()
    found = core.equilibrium(float(t0), float(tolerance), int(max_iterations))
    if found["error"] is not None:
        raise SimulationError(found["error"], stage="equilibrium")
    values, units = _channels_at_rest(model, float(t0), found)
    return Equilibrium(np.asarray(found["coordinates"]), np.asarray(found["element_states"]),
                       float(found["force_residual"]), float(found["constraint_residual"]), int(found["iterations"]),
                       values, units)


def _channels_at_rest(model: Model, t0: float, found: dict) -> tuple[dict[str, float], dict[str, str]]:
    """Every channel in the first sample of a run started at rest at the equilibrium ``found``, the state the
    core found handed over as it is (its accelerations are zero there, so the reactions are the static ones)."""
    from . import resultsfile
    from .model import _options, _run
    from .results import Results

    q = np.asarray(found["coordinates"], dtype=float)
    # (at rest: as many velocity coordinates as position coordinates, every body kind today)
    state = np.concatenate([q, np.zeros(len(q)), np.asarray(found["element_states"], dtype=float)])
    options = _options(t0, t0 + 1e-9, "dopri5", 1e-6, 1e-9, None, 1e-9, None, None, None, "projection")
    options["max_output_bytes"] = resultsfile.budget_option(None, False)
    raw = _run(model.compile(), t0, t0 + 1e-9, options, None, initial_state=state)
    if raw["error"] is not None:
        raise SimulationError(raw["error"], stage="equilibrium")
    results = Results.from_core(raw, spec=model.to_spec(), options=options, wall_time=0.0)
    values = {name: float(results[name][0]) for name in results.channels}
    units = {name: results.unit(name) for name in results.channels}
    return values, units


def _warn_of_inflows(spec: dict) -> None:
    """A cylinder fed by a flow has its chambers closed in the static analysis: say so."""
    from .errors import JointplayWarning
    import warnings

    for force in spec.get("forces", []):
        if force.get("type") == "hydraulic_cylinder" and (force.get("cap_inflow") or force.get("rod_inflow")):
            warnings.warn(JointplayWarning(f"forces.{force['name']}: the static equilibrium closes the cylinder's "
                                           "chambers; its inflows are not applied"), stacklevel=3)
