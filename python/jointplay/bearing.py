"""Journal bearings: steady operating point, design charts and pressure fields.

The steady analysis follows Raimondi and Boyd (1958): a full 360 degree
bearing fed at ambient pressure along the line of largest film thickness,
ends at ambient pressure, Swift-Stieber (Reynolds) cavitation, journal
spinning at ``speed`` rev/s in a fixed bearing. All numbers are SI; angles in
radians. Theory: ``docs/theory/steady-bearing.md`` and
``docs/theory/reynolds-solver.md``.

    >>> from jointplay import bearing
    >>> p = bearing.steady(length_over_diameter=1.0, eccentricity_ratio=0.6)
    >>> round(p.sommerfeld_number, 3)
    0.121
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import _core
from . import parameters as p

_CAVITATION = p.CAVITATIONS


@dataclass(frozen=True)
class SteadyBearing:
    """A steady operating point. Dimensional fields are None without geometry and speed."""

    length_over_diameter: float
    """L/D [-]."""
    eccentricity_ratio: float
    """eps = e / c [-]."""
    attitude_angle: float
    """From the load line to the line of centres, in the direction of rotation [rad]."""
    sommerfeld_number: float
    """S = (R/c)^2 mu N / P, N in rev/s, P = W / (L D) [-]."""
    min_film_thickness_ratio: float
    """h0 / c = 1 - eps [-]."""
    friction_variable: float
    """(R/c) f, f = friction force / load, friction force = torque / R [-]."""
    flow_variable: float
    """Q / (R c N L), Q the flow into the film at its thickest line [-]."""
    side_flow_ratio: float
    """Q_s / Q, side leakage over inflow [-]."""
    pressure_ratio: float
    """P / p_max, mean over peak pressure [-]."""
    peak_pressure_angle: float
    """Angle of the peak pressure ahead of the minimum film (against the rotation) [rad]."""
    load: float | None = None
    """W [N]."""
    mean_pressure: float | None = None
    """P = W / (L D) [Pa]."""
    min_film_thickness: float | None = None
    """h0 [m]."""
    peak_pressure: float | None = None
    """p_max [Pa]."""
    friction_torque: float | None = None
    """Friction torque on the journal [N m]."""
    friction_coefficient: float | None = None
    """f [-]."""
    power_loss: float | None = None
    """Torque times spin [W]."""
    flow: float | None = None
    """Inflow Q [m^3/s]."""
    side_flow: float | None = None
    """Side leakage Q_s [m^3/s]."""


@dataclass(frozen=True)
class PressureField:
    """One Reynolds solve over the full length: ``pressure[i, j]`` at ``theta[i]``, ``z[j]``."""

    theta: np.ndarray
    """Angles from the global x axis [rad]."""
    z: np.ndarray
    """Axial positions, 0 at the mid-plane [m]."""
    pressure: np.ndarray
    """Gauge pressure [Pa]."""
    fill_fraction: np.ndarray
    """Film fill fraction (Elrod-Adams; 1 otherwise) [-]."""
    outputs: dict
    """Force, peak pressure, attitude, torques, power loss, flows (see ``FilmSolution`` in the Rust core)."""


def _positive(name: str, value) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a positive number, got {value!r}") from None
    if not (math.isfinite(v) and v > 0.0):
        raise ValueError(f"{name} must be a positive finite number, got {value!r}")
    return v


def _grid(n_circumferential, n_axial) -> tuple[int, int]:
    if int(n_circumferential) != n_circumferential or n_circumferential < 8:
        raise ValueError(f"n_circumferential must be an integer >= 8, got {n_circumferential!r}")
    if int(n_axial) != n_axial or n_axial < 2 or n_axial % 2:
        raise ValueError(f"n_axial must be an even integer >= 2, got {n_axial!r}")
    return int(n_circumferential), int(n_axial)


def steady(length_over_diameter, eccentricity_ratio=None, load=None, radius=None, clearance=None,
           viscosity=None, speed=None, n_circumferential=p.REYNOLDS_GRID[0],
           n_axial=p.REYNOLDS_GRID[1]) -> SteadyBearing:
    """Steady operating point of a full journal bearing.

    Give ``eccentricity_ratio`` (dimensionless result; dimensional fields too
    if ``radius``, ``clearance``, ``viscosity`` [Pa s] and ``speed`` [rev/s]
    are all given), or ``load`` [N] with ``radius`` [m], ``clearance`` [m],
    ``viscosity`` [Pa s] and ``speed`` [rev/s] (the eccentricity ratio that
    carries the load is found by bisection, 1e-4 <= eps <= 0.97).
    ``n_circumferential`` x ``n_axial`` is the Reynolds grid.
    """
    lod = _positive("length_over_diameter", length_over_diameter)
    n_t, n_a = _grid(n_circumferential, n_axial)
    if (eccentricity_ratio is None) == (load is None):
        raise ValueError("give exactly one of eccentricity_ratio and load")
    geometry = {"radius": radius, "clearance": clearance, "viscosity": viscosity, "speed": speed}
    given = {k: _positive(k, v) for k, v in geometry.items() if v is not None}
    if eccentricity_ratio is not None:
        eps = float(eccentricity_ratio)
        if not (0.0 < eps < 1.0):
            raise ValueError(f"eccentricity_ratio must be in (0, 1), got {eccentricity_ratio!r}")
        if 0 < len(given) < 4:
            missing = ", ".join(k for k in geometry if k not in given)
            raise ValueError(f"dimensional results need radius, clearance, viscosity and speed; missing: {missing}")
    else:
        _positive("load", load)
        missing = [k for k in geometry if k not in given]
        if missing:
            raise ValueError(f"load requires radius, clearance, viscosity and speed; missing: {', '.join(missing)}")
    if "radius" in given and "clearance" in given and given["clearance"] >= given["radius"]:
        raise ValueError(f"clearance must be smaller than radius, got clearance={clearance!r}, radius={radius!r}")
    record = _core.steady_bearing(lod, eccentricity_ratio=None if eccentricity_ratio is None else float(eccentricity_ratio),
                                  load=None if load is None else float(load), n_circumferential=n_t, n_axial=n_a,
                                  **{k: given.get(k) for k in geometry})
    return SteadyBearing(**record)


def pressure_field(radius, length, clearance, viscosity, eccentricity, eccentricity_rate=(0.0, 0.0),
                   journal_spin=0.0, bearing_spin=0.0, cavitation=p.LUBRICATION.default("cavitation"),
                   ambient_pressure=p.LUBRICATION.default("ambient_pressure"), supply_pressure=None,
                   groove_width=0.0, feed_at_thickest_film=False, n_circumferential=p.REYNOLDS_GRID[0],
                   n_axial=p.REYNOLDS_GRID[1], path=None) -> PressureField:
    """Solves the Reynolds equation for one state and returns p(theta, z) over the full length.

    ``eccentricity`` = journal centre - bearing centre [m] and its rate [m/s]
    as (x, y); spins [rad/s] counter-clockwise; ``cavitation`` one of
    'gumbel', 'swift_stieber', 'elrod_adams'; ``supply_pressure`` [Pa] adds a
    mid-length groove of ``groove_width`` [m]. With ``path`` a contour plot is written there.
    """
    for name, v in (("radius", radius), ("length", length), ("clearance", clearance), ("viscosity", viscosity)):
        _positive(name, v)
    if cavitation not in _CAVITATION:
        raise ValueError(f"cavitation must be one of {_CAVITATION}, got {cavitation!r}")
    n_t, n_a = _grid(n_circumferential, n_axial)
    e = tuple(float(v) for v in eccentricity)
    if math.hypot(*e) >= clearance:
        raise ValueError(f"eccentricity must be shorter than the clearance {clearance!r}, got {eccentricity!r}")
    out = _core.reynolds_solve(float(radius), float(length), float(clearance), float(viscosity), e,
                               tuple(float(v) for v in eccentricity_rate), float(journal_spin), float(bearing_spin),
                               n_circumferential=n_t, n_axial=n_a, cavitation=cavitation,
                               ambient_pressure=float(ambient_pressure),
                               supply_pressure=None if supply_pressure is None else float(supply_pressure),
                               groove_width=float(groove_width), feed_at_thickest_film=bool(feed_at_thickest_film))
    shape = out.pop("shape")
    half_p = out.pop("pressure").reshape(shape)
    half_f = out.pop("fill_fraction").reshape(shape)
    z_half = out.pop("z")
    # mirror the half length about the mid-plane
    z = np.concatenate([-z_half[:0:-1], z_half])
    field = PressureField(theta=out.pop("theta"), z=z,
                          pressure=np.concatenate([half_p[:, :0:-1], half_p], axis=1),
                          fill_fraction=np.concatenate([half_f[:, :0:-1], half_f], axis=1), outputs=out)
    if path is not None:
        _plot_field(field, Path(path))
    return field


def _plot_field(field: PressureField, path: Path) -> None:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7, 4))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    cs = ax.contourf(np.degrees(field.theta), field.z * 1e3, field.pressure.T / 1e6, levels=30)
    fig.colorbar(cs, ax=ax, label="p [MPa]")
    ax.set_xlabel("theta [deg] from global x")
    ax.set_ylabel("z [mm]")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def chart(length_over_diameter, path, n_points=24, eccentricity_range=(0.03, 0.95),
          n_circumferential=p.REYNOLDS_GRID[0], n_axial=p.REYNOLDS_GRID[1]) -> list[SteadyBearing]:
    """Draws the Raimondi-Boyd design chart for one L/D into ``path`` (PNG, PDF, SVG by suffix).

    Six panels against the Sommerfeld number (log axis): eccentricity ratio
    (and h0/c), attitude angle, (R/c) f, Q/(R c N L), Q_s/Q and P/p_max.
    Returns the points drawn.
    """
    lod = _positive("length_over_diameter", length_over_diameter)
    lo, hi = (float(v) for v in eccentricity_range)
    if not (0.0 < lo < hi <= 0.97):
        raise ValueError(f"eccentricity_range must satisfy 0 < low < high <= 0.97, got {eccentricity_range!r}")
    if int(n_points) != n_points or n_points < 2:
        raise ValueError(f"n_points must be an integer >= 2, got {n_points!r}")
    # points uniform in -ln(1 - eps): denser towards heavy loads
    s = np.linspace(-math.log1p(-lo), -math.log1p(-hi), int(n_points))
    points = [steady(lod, eccentricity_ratio=float(1.0 - math.exp(-v)), n_circumferential=n_circumferential,
                     n_axial=n_axial) for v in s]
    _plot_chart(lod, points, Path(path))
    return points


def _plot_chart(lod: float, points: list[SteadyBearing], path: Path) -> None:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    S = [p.sommerfeld_number for p in points]
    panels = [
        ("eccentricity ratio eps (h0/c dashed)", [p.eccentricity_ratio for p in points], [p.min_film_thickness_ratio for p in points]),
        ("attitude angle [deg]", [math.degrees(p.attitude_angle) for p in points], None),
        ("friction variable (R/c) f", [p.friction_variable for p in points], None),
        ("flow variable Q/(R c N L)", [p.flow_variable for p in points], None),
        ("side-flow ratio Q_s/Q", [p.side_flow_ratio for p in points], None),
        ("pressure ratio P/p_max", [p.pressure_ratio for p in points], None),
    ]
    fig = Figure(figsize=(10, 9))
    FigureCanvasAgg(fig)
    for k, (label, y, y2) in enumerate(panels):
        ax = fig.add_subplot(3, 2, k + 1)
        ax.semilogx(S, y, "o-", ms=3)
        if y2 is not None:
            ax.semilogx(S, y2, "--")
        if label.startswith("friction"):
            ax.set_yscale("log")
        ax.set_ylabel(label)
        ax.set_xlabel("Sommerfeld number S = (R/c)^2 mu N / P")
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle(f"Full journal bearing, L/D = {lod:g} (Reynolds solver, Swift-Stieber; cf. Raimondi and Boyd 1958)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
