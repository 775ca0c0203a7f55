"""Independent reference: a mass on a hydraulic cylinder with LuGre seal friction.

Written apart from the Rust core (it imports nothing from jointplay), so that
the engine's hydraulic cylinder element can be compared with it, as the
slider-crank engine is compared with reference_slider_crank.py.  Theory:
docs/theory/hydraulic-cylinder.md and docs/theory/friction-lugre.md.

System (one translational degree of freedom along the cylinder axis):

* the barrel (cap end) is fixed; the rod end carries a mass m;
* stroke s [m], 0 fully retracted, growing as the rod extends;
* states y = (s, u, p_cap, p_rod, z): u = ds/dt [m/s], gauge pressures [Pa],
  z the mean bristle deflection of the seal [m];
* chambers: V_cap = V_cd + A1 s, V_rod = V_rd + A2 (L - s); mass continuity
  with a constant effective bulk modulus beta and no leakage gives
  dp_cap/dt = beta (Q_cap - A1 u) / V_cap, dp_rod/dt = beta (Q_rod + A2 u) / V_rod;
* seal (LuGre, damping fading with speed over v_D):
  g(u) = Fc + (Fs - Fc) exp(-(u/vs)^2),  dz/dt = u - sigma0 |u| z / g(u),
  F_f = sigma0 z + sigma1 exp(-(u/v_D)^2) dz/dt + sigma2 u;
* Newton: m du/dt = p_cap A1 - p_rod A2 - F_f + F(t) - c u + m g_axial,
  F(t) the applied force along the extension, c an optional viscous damper
  on the mass (not part of the cylinder: it lets a loaded mass settle), and
  g_axial the component of gravity along the extension (0: horizontal;
  -9.81 m/s^2 for a cylinder standing upright and extending upwards).

``simulate`` integrates this with ``scipy.integrate.solve_ivp`` (LSODA: the
seal makes the system stiff while it sticks) and returns the time history.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Callable, Optional, Union

import numpy as np
from scipy.integrate import solve_ivp

__all__ = [
    "CylinderParameters",
    "HydraulicHistory",
    "stribeck_force",
    "seal_friction",
    "liquid_energy",
    "closed_chamber_pressure",
    "closed_chamber_stiffness",
    "volumes",
    "balanced_rod_pressure",
    "simulate",
    "frictionless",
]

TimeFunction = Union[float, Callable[[float], float]]


@dataclass(frozen=True)
class CylinderParameters:
    """Mass on a cylinder, SI units.  Defaults: chosen example (bore 80 mm,
    rod 45 mm, stroke 0.5 m), seal forces from paper 002, LuGre dynamics chosen."""

    mass: float = 20.0  # m [kg], rod, piston and load
    bore: float = 0.080  # piston diameter [m]
    rod_diameter: float = 0.045  # [m]
    stroke_length: float = 0.5  # L [m]
    cap_dead_volume: float = 1.0e-4  # V_cd [m^3]
    rod_dead_volume: float = 1.0e-4  # V_rd [m^3]
    bulk_modulus: float = 1.0e9  # beta [Pa], effective
    seal: str = "lugre"  # "lugre" or "none"
    static_force: float = 385.0  # Fs [N] (paper 002)
    kinetic_force: float = 340.0  # Fc [N] (paper 002)
    stribeck_velocity: float = 3.0e-5  # vs [m/s] (chosen: fit to paper 002's curve)
    bristle_stiffness: float = 1.0e7  # sigma0 [N/m] (chosen)
    bristle_damping: float = 1.0e4  # sigma1 [N s/m] (chosen)
    viscous_coefficient: float = 0.0  # sigma2 [N s/m] (paper 002's law has none)
    damping_velocity: float = 1.0e-3  # v_D [m/s] (chosen)
    damper: float = 0.0  # c [N s/m] on the mass, outside the cylinder
    axial_gravity: float = 0.0  # g_axial [m/s^2], gravity along the extension (0: horizontal)

    @property
    def piston_area(self) -> float:
        """A1 = pi D^2 / 4 [m^2]."""
        return math.pi * self.bore**2 / 4.0

    @property
    def rod_side_area(self) -> float:
        """A2 = pi (D^2 - d^2) / 4 [m^2], the annulus."""
        return math.pi * (self.bore**2 - self.rod_diameter**2) / 4.0


@dataclass
class HydraulicHistory:
    """Time history of the reference model (arrays over ``t``)."""

    t: np.ndarray  # [s]
    stroke: np.ndarray  # s [m]
    rate: np.ndarray  # ds/dt [m/s]
    p_cap: np.ndarray  # [Pa]
    p_rod: np.ndarray  # [Pa]
    bristle: np.ndarray  # z [m]
    force: np.ndarray  # cylinder force pushing apart, p_cap A1 - p_rod A2 - F_f [N]
    friction: np.ndarray  # F_f [N], resisting ds/dt
    stored_energy: np.ndarray  # liquids (rel. gauge 0) + bristles [J]
    kinetic_energy: np.ndarray  # m u^2 / 2 [J]
    nfev: int
    success: bool
    message: str


def volumes(p: CylinderParameters, stroke):
    """Chamber volumes (V_cap, V_rod) [m^3] at the stroke s [m]."""
    cap = p.cap_dead_volume + p.piston_area * stroke
    rod = p.rod_dead_volume + p.rod_side_area * (p.stroke_length - stroke)
    return cap, rod


def balanced_rod_pressure(p: CylinderParameters, cap_pressure: float) -> float:
    """Rod pressure [Pa] for which the pressure force vanishes: p_rod A2 = p_cap A1."""
    return cap_pressure * p.piston_area / p.rod_side_area


def closed_chamber_pressure(p0, v0, v, beta):
    """p = p0 - beta ln(V/V0) [Pa]: a closed chamber taken from (p0, V0) to V."""
    return p0 - beta * np.log(v / v0)


def closed_chamber_stiffness(p: CylinderParameters, stroke: float) -> float:
    """-dF/ds = beta (A1^2/V_cap + A2^2/V_rod) [N/m] of the closed chambers."""
    cap, rod = volumes(p, stroke)
    return p.bulk_modulus * (p.piston_area**2 / cap + p.rod_side_area**2 / rod)


def liquid_energy(pressure, volume, beta):
    """Energy [J] stored in the liquid now at gauge pressure p [Pa] in V [m^3],
    relative to the same liquid at p = 0.

    Along a closed compression V(p') = V exp((p - p')/beta), so
    E = int_0^p p' (-dV/dp') dp' = (V e^{p/beta}/beta) int_0^p p' e^{-p'/beta} dp'
      = V beta (e^{p/beta} - 1 - p/beta).
    """
    x = np.asarray(pressure, dtype=float) / beta
    return volume * beta * (np.expm1(x) - x)


def stribeck_force(p: CylinderParameters, u):
    """g(u) = Fc + (Fs - Fc) exp(-(u/vs)^2) [N]."""
    return p.kinetic_force + (p.static_force - p.kinetic_force) * np.exp(-((u / p.stribeck_velocity) ** 2))


def seal_friction(p: CylinderParameters, u: float, z: float):
    """(F_f [N], dz/dt [m/s]) of the LuGre seal at speed u [m/s], deflection z [m];
    (0, 0) without a seal law."""
    if p.seal == "none":
        return 0.0, 0.0
    g = p.kinetic_force + (p.static_force - p.kinetic_force) * math.exp(-((u / p.stribeck_velocity) ** 2))
    zdot = u - p.bristle_stiffness * abs(u) * z / g
    damping = p.bristle_damping * math.exp(-((u / p.damping_velocity) ** 2))
    force = p.bristle_stiffness * z + damping * zdot + p.viscous_coefficient * u
    return force, zdot


def _as_function(value: Optional[TimeFunction]) -> Callable[[float], float]:
    if value is None:
        return lambda t: 0.0
    if callable(value):
        return value
    constant = float(value)
    return lambda t: constant


def _rhs(p: CylinderParameters, applied, q_cap, q_rod):
    a1, a2, beta, m = p.piston_area, p.rod_side_area, p.bulk_modulus, p.mass

    def rhs(t, y):
        s, u, pc, pr, z = y
        v_cap = p.cap_dead_volume + a1 * s
        v_rod = p.rod_dead_volume + a2 * (p.stroke_length - s)
        friction, zdot = seal_friction(p, u, z)
        force = pc * a1 - pr * a2 - friction
        accel = (force + applied(t) - p.damper * u) / m + p.axial_gravity
        return [u, accel, beta * (q_cap(t) - a1 * u) / v_cap, beta * (q_rod(t) + a2 * u) / v_rod, zdot]

    return rhs


def simulate(
    p: CylinderParameters,
    t_end: float,
    *,
    initial_stroke: float = 0.25,
    initial_rate: float = 0.0,
    cap_pressure: float = 5.0e6,
    rod_pressure: Optional[float] = None,
    initial_bristle: float = 0.0,
    applied_force: Optional[TimeFunction] = None,
    cap_inflow: Optional[TimeFunction] = None,
    rod_inflow: Optional[TimeFunction] = None,
    t_eval: Optional[np.ndarray] = None,
    rtol: float = 1e-10,
    atol: Optional[np.ndarray] = None,
    max_step: float = np.inf,
    method: str = "LSODA",
) -> HydraulicHistory:
    """Time history of the mass on the cylinder over [0, t_end] [s].

    ``rod_pressure`` defaults to the pressure that balances ``cap_pressure``
    (no net force at rest).  ``applied_force`` [N, along the extension] and the
    inflows [m^3/s, into each chamber] are constants or functions of t.
    ``atol`` defaults to scales of (1e-12 m, 1e-11 m/s, 1e-2 Pa, 1e-2 Pa, 1e-14 m).
    """
    if rod_pressure is None:
        rod_pressure = balanced_rod_pressure(p, cap_pressure)
    y0 = [initial_stroke, initial_rate, cap_pressure, rod_pressure, initial_bristle]
    if atol is None:
        atol = np.array([1e-12, 1e-11, 1e-2, 1e-2, 1e-14])
    applied = _as_function(applied_force)
    rhs = _rhs(p, applied, _as_function(cap_inflow), _as_function(rod_inflow))
    sol = solve_ivp(rhs, (0.0, t_end), y0, method=method, t_eval=t_eval, rtol=rtol, atol=atol, max_step=max_step)
    return _history(p, sol)


def _history(p: CylinderParameters, sol) -> HydraulicHistory:
    s, u, pc, pr, z = sol.y
    friction = np.array([seal_friction(p, ui, zi)[0] for ui, zi in zip(u, z)])
    cap, rod = volumes(p, s)
    beta = p.bulk_modulus
    bristle_energy = 0.5 * p.bristle_stiffness * z**2 if p.seal == "lugre" else np.zeros_like(z)
    stored = liquid_energy(pc, cap, beta) + liquid_energy(pr, rod, beta) + bristle_energy
    return HydraulicHistory(
        t=sol.t,
        stroke=s,
        rate=u,
        p_cap=pc,
        p_rod=pr,
        bristle=z,
        force=pc * p.piston_area - pr * p.rod_side_area - friction,
        friction=friction,
        stored_energy=stored,
        kinetic_energy=0.5 * p.mass * u**2,
        nfev=sol.nfev,
        success=bool(sol.success),
        message=str(sol.message),
    )


def frictionless(p: CylinderParameters = CylinderParameters()) -> CylinderParameters:
    """The same cylinder without seal friction."""
    return replace(p, seal="none")
