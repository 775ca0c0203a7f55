"""``jointplay static``: the static equilibrium of a model file (:meth:`jointplay.Model.equilibrium`).

Prints where the bodies rest, the reactions of the joints and drivers, the forces of the force elements and the
state of each clearance joint, and the residual left; exit code 1 when there is no equilibrium (the message names
the body whose load nothing carries), 2 for a bad model file.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated

import typer

from .cli import EXIT_FAILED, SetOption, _bad_input, _load, _printed_warnings, app, err, out
from .display import print_table, table
from .errors import ModelError, SimulationError

#: Quantities of force elements and clearance joints printed, with their units and how to show them.
_SHOWN = {"fx": ("N", 1.0), "fy": ("N", 1.0), "moment": ("N m", 1.0), "force": ("N", 1.0), "torque": ("N m", 1.0),
          "fn": ("N", 1.0), "penetration": ("um", 1e6), "ex": ("mm", 1e3), "ey": ("mm", 1e3),
          "p_cap": ("bar", 1e-5), "p_rod": ("bar", 1e-5), "stroke": ("mm", 1e3), "length": ("mm", 1e3)}


@app.command()
def static(model: Annotated[Path, typer.Argument(help="Model file (TOML).", show_default=False)],
           set_: SetOption = [],  # noqa: B006 (typer reads the default)
           t0: Annotated[str | None, typer.Option("--t0", help='Time at which the drivers are held, e.g. "10 ms" '
                                                  "or 0.01 (seconds) [default: simulation.t0, or 0].")] = None) -> None:
    """Find the static equilibrium of a model file and print it.

    The mechanism at rest under gravity, springs, loads and closed hydraulic
    chambers, its drivers held at their values at t0; clearance joints with
    the journal resting in its bore at the contact law's static penetration.
    Prints the bodies' positions, the reactions of joints and drivers, the
    forces of the force elements and the residual
    (docs/theory/static-equilibrium.md).
    """
    from .cli import _time_option

    m = _load(model, set_)
    start = _time_option(t0, "--t0") if t0 is not None else m.simulation.get("t0", 0.0)
    try:
        with _printed_warnings():
            found = m.equilibrium(start)
    except ModelError as exc:
        raise _bad_input(f"{model}: cannot compute the equilibrium", exc.problems) from None
    except SimulationError as exc:
        err.print(exc.cause, markup=False, style="bold red")
        raise typer.Exit(EXIT_FAILED) from None
    out.print(f"[bold]{m.name}[/]  ({model}): static equilibrium at t0 = {start:g} s, "
              f"{found.iterations} Newton iterations, force residual {found.force_residual:.3g} N, "
              f"constraint residual {found.constraint_residual:.3g} m")
    _print_bodies(m, found)
    _print_elements(m, found)


def _print_bodies(m, found) -> None:
    spec = m.to_spec()
    bodies = table("body", "x (mm)", "y (mm)", "angle (deg)", title="bodies at rest")
    for b in spec["bodies"]:
        name = b["name"]
        bodies.add_row(name, f"{found[f'{name}.x'] * 1e3:.4f}", f"{found[f'{name}.y'] * 1e3:.4f}",
                       f"{math.degrees(found[f'{name}.angle']):.4f}")
    if spec["bodies"]:
        print_table(out, bodies)


def _print_elements(m, found) -> None:
    spec = m.to_spec()
    names = [j["name"] for j in spec["joints"]] + [d["name"] for d in spec["drivers"]] + \
            [f["name"] for f in spec["forces"]]
    rows = table("element", "quantity", "value", "unit", title="reactions and element forces at rest")
    shown = False
    for name in names:
        for quantity, (unit, scale) in _SHOWN.items():
            channel = f"{name}.{quantity}"
            if channel in found.values:
                rows.add_row(name, quantity, f"{found[channel] * scale:.6g}", unit)
                shown = True
    if shown:
        print_table(out, rows)
