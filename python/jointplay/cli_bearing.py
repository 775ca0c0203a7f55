"""``jointplay bearing``: steady operating point and design chart of a full journal bearing.

A thin front to :mod:`jointplay.bearing` (Raimondi and Boyd's bearing:
360 degrees, fed at ambient pressure along the thickest film, ends at
ambient pressure, Swift-Stieber cavitation; theory in
docs/theory/steady-bearing.md). Options with units are read by
:func:`jointplay.units.to_si`; every problem with the options is reported
(one line each, exit code 2) before anything is computed.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated

import typer
from rich.table import Table

from . import bearing as _bearing
from . import parameters as p
from ._core import MAX_REYNOLDS_GRID_NODES
from .display import print_table, table

_GRID = f"{p.REYNOLDS_GRID[0]}x{p.REYNOLDS_GRID[1]}"
from .cli import EXIT_BAD_INPUT, app, err, out

HELP = """Steady operating point of a full (360 degree) journal bearing, and its design chart.

Give L/D and either the eccentricity ratio or the load. With the load, also
give the journal radius (or diameter), the radial clearance, the viscosity
and the speed; with the eccentricity ratio they are optional and add
dimensional results (load, film thickness, pressures, torque, power, flows).
Quantities take units: "20 mm", "0.02 mm", "40 cP", "3000 rpm", "2 kN".

Printed: eccentricity ratio, attitude angle (from the load line to the line
of centres, in the direction of rotation), Sommerfeld number
S = (R/c)^2 mu N / P (N in rev/s, P = load / (L D)), minimum film
thickness, peak pressure, friction variable (R/c) f, flow variable
Q / (R c N L), side-flow ratio Q_s / Q and mean-to-peak pressure ratio
P / p_max. The bearing is Raimondi and Boyd's (1958): fed at ambient
pressure along the thickest film, ends at ambient pressure, Swift-Stieber
(Reynolds) cavitation, solved by jointplay's finite-difference Reynolds
solver (docs/theory/steady-bearing.md).

\b
Examples:
    jointplay bearing --l-over-d 1 --eccentricity 0.6
    jointplay bearing --l-over-d 1 --load "1.6 kN" --diameter "20 mm" \\
        --clearance "0.02 mm" --viscosity "40 cP" --speed "3000 rpm"
    jointplay bearing --l-over-d 0.5 --eccentricity 0.6 --chart chart.png

Exit codes: 0 success, 2 bad input (one line per problem)."""

_FIGURE_SUFFIXES = (".png", ".svg", ".pdf")


@dataclass
class _Inputs:
    """The options in SI units (speed in rev/s), after validation."""

    length_over_diameter: float
    eccentricity_ratio: float | None
    load: float | None
    radius: float | None
    clearance: float | None
    viscosity: float | None
    speed: float | None
    grid: tuple[int, int]

    def geometry(self) -> dict:
        return {"radius": self.radius, "clearance": self.clearance, "viscosity": self.viscosity, "speed": self.speed}


def _quantity(option: str, text: str | None, kind: str, problems: list[str]) -> float | None:
    """``text`` in SI units, or None; a problem is recorded for a bad or non-positive value."""
    if text is None:
        return None
    from .units import UnitError, to_si

    try:
        value = to_si(text, kind)
    except UnitError as exc:
        problems.append(f"{option}: {exc}")
        return None
    if not value > 0.0:
        problems.append(f"{option}: must be > 0, got {text}")
        return None
    return value


def _ratio(option: str, text: str | None, problems: list[str]) -> float | None:
    """A plain positive number, fractions allowed ("1/2")."""
    if text is None:
        return None
    try:
        num, _, den = text.partition("/")
        value = float(num) / float(den) if den else float(num)
    except (ValueError, ZeroDivisionError):
        problems.append(f"{option}: must be a plain number such as 0.5 or 1/2, got {text!r}")
        return None
    if not (math.isfinite(value) and value > 0.0):
        problems.append(f"{option}: must be > 0, got {text}")
        return None
    return value


def _grid(text: str, problems: list[str]) -> tuple[int, int]:
    try:
        n_t, n_a = (int(v) for v in text.lower().split("x"))
    except ValueError:
        n_t, n_a = 0, 0
    if n_t < 8 or n_a < 2 or n_a % 2:
        problems.append(f"--grid: must be N_CIRCUMFERENTIAL x N_AXIAL with N_CIRCUMFERENTIAL >= 8 and N_AXIAL even "
                        f">= 2, e.g. {_GRID}, got {text!r}")
        return p.REYNOLDS_GRID
    nodes = n_t * (n_a // 2 + 1)
    if nodes > MAX_REYNOLDS_GRID_NODES:
        problems.append(f"--grid: {n_t}x{n_a} has {nodes} nodes on the half length, more than the limit of "
                        f"{MAX_REYNOLDS_GRID_NODES} (N_CIRCUMFERENTIAL x (N_AXIAL/2 + 1)), got {text!r}")
        return p.REYNOLDS_GRID
    return n_t, n_a


def _figure(option: str, path: Path | None, problems: list[str]) -> None:
    if path is None:
        return
    if path.suffix.lower() not in _FIGURE_SUFFIXES:
        problems.append(f"{option}: the file name must end in {', '.join(_FIGURE_SUFFIXES)}, got {str(path)!r}")
    elif not path.parent.is_dir():
        problems.append(f"{option}: no folder {path.parent}")
    elif path.is_dir():
        problems.append(f"{option}: {path} is a folder, not a figure file")
    elif not os.access(path.parent, os.W_OK | os.X_OK):
        problems.append(f"{option}: cannot write into the folder {path.parent} (permission denied)")


def _read(l_over_d, eccentricity, load, radius, diameter, clearance, viscosity, speed, grid, chart,
          pressure) -> _Inputs:
    """All options checked at once; raises typer.Exit(2) listing every problem."""
    problems: list[str] = []
    lod = _ratio("--l-over-d", l_over_d, problems)
    if l_over_d is None:
        problems.append("--l-over-d: missing; give the length over diameter of the bearing, e.g. --l-over-d 1")
    eps = None
    if eccentricity is not None:
        eps = _ratio("--eccentricity", eccentricity, problems)
        if eps is not None and not eps < 1.0:
            problems.append(f"--eccentricity: must be between 0 and 1 (exclusive), got {eccentricity}")
            eps = None
    w = _quantity("--load", load, "force", problems)
    if radius is not None and diameter is not None:
        problems.append("--radius, --diameter: give one of them, not both")
    r = _quantity("--radius", radius, "length", problems)
    d = _quantity("--diameter", diameter, "length", problems)
    r = r if r is not None else (None if d is None else 0.5 * d)
    c = _quantity("--clearance", clearance, "length", problems)
    mu = _quantity("--viscosity", viscosity, "viscosity", problems)
    omega = _quantity("--speed", speed, "angular velocity", problems)
    n = None if omega is None else omega / (2.0 * math.pi)
    if eccentricity is None and load is None and chart is None:
        problems.append("--eccentricity, --load: give one of them (the operating point by eccentricity ratio or by "
                        "load), or only --chart")
    elif eccentricity is not None and load is not None:
        problems.append("--eccentricity, --load: give one of them, not both")
    given = {"--radius (or --diameter)": radius or diameter, "--clearance": clearance, "--viscosity": viscosity,
             "--speed": speed}
    missing = [name for name, v in given.items() if v is None]
    if load is not None and eccentricity is None and missing:
        problems.append(f"--load: needs the journal radius, clearance, viscosity and speed; missing {', '.join(missing)}")
    elif eccentricity is not None and 0 < len(missing) < len(given):
        problems.append("dimensional results need --radius (or --diameter), --clearance, --viscosity and --speed; "
                        f"missing {', '.join(missing)}")
    if r is not None and c is not None and not c < r:
        problems.append(f"--clearance: must be smaller than the journal radius, got {clearance} for a radius of "
                        f"{r * 1e3:g} mm")
    n_grid = _grid(grid, problems)
    _figure("--chart", chart, problems)
    _figure("--pressure", pressure, problems)
    if pressure is not None and missing and load is None:
        problems.append("--pressure: the pressure field needs --radius (or --diameter), --clearance, --viscosity "
                        "and --speed")
    if problems:
        raise _bad_options(problems)
    return _Inputs(lod, eps, w, r, c, mu, n, n_grid)


def _bad_options(problems: list[str]) -> typer.Exit:
    if len(problems) == 1:
        err.print("[bold red]error:[/] ", end="")
        err.print(problems[0], markup=False)
    else:
        err.print(f"[bold red]error:[/] {len(problems)} problems with the options")
        for p in problems:
            err.print(f"  {p}", markup=False)
    return typer.Exit(EXIT_BAD_INPUT)


def _fmt(value: float, scale: float = 1.0) -> str:
    return f"{value * scale:.4g}"


def _table(p: _bearing.SteadyBearing) -> Table:
    """The dimensionless operating point (Raimondi and Boyd's variables)."""
    t = table("quantity", "symbol", "value",
              title=f"full journal bearing, L/D = {p.length_over_diameter:g} (Raimondi-Boyd conditions)")
    t.add_row("eccentricity ratio", "eps = e/c", _fmt(p.eccentricity_ratio))
    t.add_row("attitude angle (deg)", "phi", _fmt(math.degrees(p.attitude_angle)))
    t.add_row("Sommerfeld number", "S = (R/c)^2 mu N / P", _fmt(p.sommerfeld_number))
    t.add_row("minimum film thickness", "h0/c", _fmt(p.min_film_thickness_ratio))
    t.add_row("peak pressure", "p_max/P", _fmt(1.0 / p.pressure_ratio))
    t.add_row("peak pressure angle (deg)", "from h0, against rotation", _fmt(math.degrees(p.peak_pressure_angle)))
    t.add_row("friction variable", "(R/c) f", _fmt(p.friction_variable))
    t.add_row("flow variable", "Q/(R c N L)", _fmt(p.flow_variable))
    t.add_row("side-flow ratio", "Q_s/Q", _fmt(p.side_flow_ratio))
    t.add_row("mean-to-peak pressure ratio", "P/p_max", _fmt(p.pressure_ratio))
    return t


def _dimensional_table(p: _bearing.SteadyBearing) -> Table:
    """The same point for the bearing given (SI values shown in engineering units)."""
    t = table("quantity", "symbol", "value", "unit", title="dimensional")
    rows = [
        ("load", "W", p.load, 1e-3, "kN"),
        ("mean pressure", "P = W/(L D)", p.mean_pressure, 1e-6, "MPa"),
        ("minimum film thickness", "h0", p.min_film_thickness, 1e6, "um"),
        ("peak pressure", "p_max", p.peak_pressure, 1e-6, "MPa"),
        ("friction coefficient", "f", p.friction_coefficient, 1.0, ""),
        ("friction torque", "T", p.friction_torque, 1.0, "N m"),
        ("power loss", "T 2 pi N", p.power_loss, 1.0, "W"),
        ("flow into the film", "Q", p.flow, 6e7, "ml/min"),
        ("side flow", "Q_s", p.side_flow, 6e7, "ml/min"),
    ]
    for name, symbol, value, scale, unit in rows:
        t.add_row(name, symbol, _fmt(value, scale), unit)
    return t


@app.command(help=HELP, no_args_is_help=True)
def bearing(
    l_over_d: Annotated[str | None, typer.Option("--l-over-d", metavar="L/D",
                                                 help="Length over diameter of the bearing, e.g. 1 or 1/2.")] = None,
    eccentricity: Annotated[str | None, typer.Option("--eccentricity", "-e", metavar="EPS",
                                                     help="Eccentricity ratio e/c, between 0 and 1.")] = None,
    load: Annotated[str | None, typer.Option("--load", "-w", metavar="FORCE",
                                             help='Load on the journal, e.g. "2 kN".')] = None,
    radius: Annotated[str | None, typer.Option("--radius", metavar="LENGTH",
                                               help='Journal radius R, e.g. "10 mm".')] = None,
    diameter: Annotated[str | None, typer.Option("--diameter", metavar="LENGTH",
                                                 help='Journal diameter D = 2R (instead of --radius), '
                                                      'e.g. "20 mm".')] = None,
    clearance: Annotated[str | None, typer.Option("--clearance", "-c", metavar="LENGTH",
                                                  help='Radial clearance c, e.g. "0.02 mm".')] = None,
    viscosity: Annotated[str | None, typer.Option("--viscosity", metavar="VISCOSITY",
                                                  help='Dynamic viscosity mu, e.g. "40 cP" or "0.04 Pa s".')] = None,
    speed: Annotated[str | None, typer.Option("--speed", metavar="SPEED",
                                              help='Journal speed N (bearing fixed), e.g. "3000 rpm" '
                                                   'or "50 rev/s".')] = None,
    chart: Annotated[Path | None, typer.Option("--chart", metavar="PATH", help="Also draw the Raimondi-Boyd chart "
                                               "for this L/D against S (eps, attitude, (R/c) f, flow, side flow, "
                                               "P/p_max); .png, .svg or .pdf.")] = None,
    pressure: Annotated[Path | None, typer.Option("--pressure", metavar="PATH", help="Also draw the film "
                                                  "pressure p(theta, z) at the operating point (needs the "
                                                  "geometry); .png, .svg or .pdf.")] = None,
    grid: Annotated[str, typer.Option("--grid", metavar="NTxNZ", help="Reynolds grid: nodes around x intervals "
                                      "along the length (even).")] = _GRID,
) -> None:
    inputs = _read(l_over_d, eccentricity, load, radius, diameter, clearance, viscosity, speed, grid, chart, pressure)
    n_t, n_a = inputs.grid
    if inputs.eccentricity_ratio is None and inputs.load is None:  # the chart alone
        _bearing.chart(inputs.length_over_diameter, chart, n_circumferential=n_t, n_axial=n_a)
        out.print(f"wrote {chart}")
        return
    geometry = {k: v for k, v in inputs.geometry().items() if v is not None}
    try:
        point = _bearing.steady(inputs.length_over_diameter, eccentricity_ratio=inputs.eccentricity_ratio,
                                load=inputs.load, n_circumferential=n_t, n_axial=n_a, **geometry)
    except ValueError as exc:  # a load outside the range of eccentricity ratios solved
        message = str(exc)
        raise _bad_options([f"--load: {message}" if message.startswith("load ") else message]) from None
    print_table(out, _table(point))
    if point.load is not None:
        print_table(out, _dimensional_table(point))
    if chart is not None:
        _bearing.chart(inputs.length_over_diameter, chart, n_circumferential=n_t, n_axial=n_a)
        out.print(f"wrote {chart}")
    if pressure is not None:
        angle = _pressure_figure(inputs, point, pressure)
        out.print(f"wrote {pressure} (load along -y, journal turning counter-clockwise, thinnest film at "
                  f"theta = {math.degrees(angle) % 360:.1f} deg)")


def _pressure_figure(inputs: _Inputs, point: _bearing.SteadyBearing, path: Path) -> float:
    """Draws the film pressure at the operating point (load along -y, journal spinning counter-clockwise);
    returns the angle of the line of centres from the x axis [rad]."""
    c, r = inputs.clearance, inputs.radius
    phi = point.attitude_angle  # from the load line (-y) to the line of centres, counter-clockwise
    e = point.eccentricity_ratio * c
    n_t, n_a = inputs.grid
    _bearing.pressure_field(r, 2.0 * r * inputs.length_over_diameter, c, inputs.viscosity,
                            (e * math.sin(phi), -e * math.cos(phi)), journal_spin=2.0 * math.pi * inputs.speed,
                            cavitation=p.LUBRICATION.default("cavitation"), feed_at_thickest_film=True,
                            n_circumferential=n_t, n_axial=n_a, path=path)
    return phi - 0.5 * math.pi
