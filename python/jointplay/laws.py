"""Contact, stiffness and friction laws of a clearance joint, as plain data.

See ``docs/theory/`` for the equation, units and source of each law. Every
physical argument is a number in SI units, a string with a unit (``"0.1 mm/s"``,
``"400 cP"``) or a pint Quantity, converted here by :func:`jointplay.units.to_si`;
a wrong one raises :class:`~jointplay.errors.ModelError` naming the law's key.
"""

from __future__ import annotations

from typing import Any


def _si(raw: Any, kind: str, where: str) -> float:
    """``raw`` in the SI unit of ``kind``; a ModelError located at ``where`` when it is not one."""
    from .errors import ModelError, Problem
    from .units import UnitError, to_si

    try:
        return to_si(raw, kind)
    except UnitError as exc:
        raise ModelError([Problem(where, str(exc))]) from None

STEEL = {"youngs_modulus": 207e9, "poisson_ratio": 0.3}
"""Structural steel, E = 207 GPa, nu = 0.3 (the value the Flores papers use)."""


def material(youngs_modulus: float, poisson_ratio: float) -> dict:
    """An elastic material: Young's modulus [Pa], Poisson's ratio [-]."""
    return {"youngs_modulus": _si(youngs_modulus, "pressure", "material.youngs_modulus"),
            "poisson_ratio": _si(poisson_ratio, "dimensionless", "material.poisson_ratio")}


# normal force laws ---------------------------------------------------------

def hertz() -> dict:
    """Elastic Hertz contact, no dissipation."""
    return {"law": "hertz"}


def hunt_crossley(restitution: float) -> dict:
    """Hunt-Crossley, D = 3(1-e)/2."""
    return {"law": "hunt_crossley", "restitution": _si(restitution, "dimensionless", "contact.restitution")}


def lankarani_nikravesh(restitution: float) -> dict:
    """Lankarani-Nikravesh, D = 3(1-e^2)/4 (accurate for e near 1)."""
    return {"law": "lankarani_nikravesh", "restitution": _si(restitution, "dimensionless", "contact.restitution")}


def flores(restitution: float) -> dict:
    """Flores et al. 2011, D = 8(1-e)/(5e) (for any e)."""
    return {"law": "flores", "restitution": _si(restitution, "dimensionless", "contact.restitution")}


def gonthier(restitution: float) -> dict:
    """Gonthier et al. 2004."""
    return {"law": "gonthier", "restitution": _si(restitution, "dimensionless", "contact.restitution")}


def hu_guo(restitution: float) -> dict:
    """Hu and Guo 2015."""
    return {"law": "hu_guo", "restitution": _si(restitution, "dimensionless", "contact.restitution")}


# stiffness laws ------------------------------------------------------------

def hertz_cylinder(exponent: float | None = None) -> dict:
    """K delta^n with K = (4/3) E* sqrt(R*); n = 1.5 unless given."""
    if exponent is None:
        return {"law": "hertz_cylinder"}
    return {"law": "hertz_cylinder_exponent", "exponent": _si(exponent, "dimensionless", "stiffness.exponent")}


def johnson_line() -> dict:
    """Johnson / ESDU line contact of a cylinder in a bore (needs the bearing length)."""
    return {"law": "johnson_line"}


def rogers_andrews() -> dict:
    """Rogers-Andrews logarithmic law (needs the bearing length)."""
    return {"law": "rogers_andrews"}


# friction laws -------------------------------------------------------------

def frictionless() -> dict:
    """No friction."""
    return {"law": "none"}


def coulomb(coefficient: float, velocity_tolerance: float = 1e-3) -> dict:
    """Coulomb friction regularised by tanh(v / velocity_tolerance)."""
    return {"law": "coulomb", "coefficient": _si(coefficient, "dimensionless", "friction.coefficient"),
            "velocity_tolerance": _si(velocity_tolerance, "velocity", "friction.velocity_tolerance")}


def ambrosio(coefficient: float, v0: float = 1e-4, v1: float = 1e-3) -> dict:
    """Modified Coulomb law of Ambrosio: none below v0, full above v1, linear between [m/s]."""
    return {"law": "ambrosio", "coefficient": _si(coefficient, "dimensionless", "friction.coefficient"),
            "v0": _si(v0, "velocity", "friction.v0"), "v1": _si(v1, "velocity", "friction.v1")}


def threlfall(coefficient: float, v0: float = 1e-3) -> dict:
    """Threlfall: mu F_n (1 - exp(-3|v|/v0))."""
    return {"law": "threlfall", "coefficient": _si(coefficient, "dimensionless", "friction.coefficient"),
            "v0": _si(v0, "velocity", "friction.v0")}


def stiction(static_coefficient: float, kinetic_coefficient: float,
             stiction_velocity: float = 1e-4, transition_velocity: float = 1e-3) -> dict:
    """Static and kinetic coefficients with velocity tolerances [m/s]."""
    return {"law": "stiction", "static_coefficient": _si(static_coefficient, "dimensionless", "friction.static_coefficient"),
            "kinetic_coefficient": _si(kinetic_coefficient, "dimensionless", "friction.kinetic_coefficient"),
            "stiction_velocity": _si(stiction_velocity, "velocity", "friction.stiction_velocity"),
            "transition_velocity": _si(transition_velocity, "velocity", "friction.transition_velocity")}


# lubrication ---------------------------------------------------------------

FILM_MODELS = ("squeeze_film_short", "squeeze_film_long", "hamrock_short", "hamrock_long", "frene_short",
               "frene_long", "pinkus_sternlicht_long", "reynolds_exact", "reynolds_table")


def centipoise(value: float) -> float:
    """Viscosity in cP to Pa s (1 cP = 1e-3 Pa s)."""
    return float(value) * 1e-3


def lubrication(model: str, viscosity: float, transition: dict | None = None, *, cavitation: str | None = None,
                n_circumferential: int | None = None, n_axial: int | None = None, ambient_pressure: Any = None,
                groove_supply_pressure: Any = None) -> dict:
    """A lubricant film for a clearance joint: ``model`` one of :data:`FILM_MODELS`, ``viscosity`` [Pa s]
    (a number, or ``"400 cP"``; see :func:`centipoise`), ``transition`` from :func:`wang_transition`
    (default), :func:`flores_transition` or :func:`switch_transition`. Only the Reynolds models
    (``reynolds_exact``, ``reynolds_table``) take the cavitation condition (``gumbel``,
    ``swift_stieber`` by default, ``elrod_adams``), the grid, the ambient pressure at the ends [Pa]
    (0 by default) and the supply pressure of a circumferential groove at mid-length [Pa]; giving one
    of them to a closed-form model is a ModelError, as in a model file."""
    from .errors import ModelError, Problem

    if model not in FILM_MODELS:
        raise ValueError(f"unknown film model {model!r}; choose one of {', '.join(FILM_MODELS)}")
    spec = {"model": model, "viscosity": _si(viscosity, "viscosity", "lubrication.viscosity"),
            "transition": transition or wang_transition()}
    reynolds_only = {"cavitation": cavitation, "n_circumferential": n_circumferential, "n_axial": n_axial,
                     "ambient_pressure": ambient_pressure, "groove_supply_pressure": groove_supply_pressure}
    if not model.startswith("reynolds"):
        given = [key for key, value in reynolds_only.items() if value is not None]
        if given:
            raise ModelError([Problem(f"lubrication.{key}", f"applies only to the Reynolds models (reynolds_exact, "
                                                            f"reynolds_table), not to {model}") for key in given])
        return spec
    spec["reynolds"] = {"cavitation": cavitation or "swift_stieber", "n_circumferential": n_circumferential,
                        "n_axial": n_axial,
                        "ambient_pressure": _si(ambient_pressure or 0.0, "pressure", "lubrication.ambient_pressure"),
                        "groove_supply_pressure": None if groove_supply_pressure is None else
                        _si(groove_supply_pressure, "pressure", "lubrication.groove_supply_pressure")}
    return spec


def wang_transition(safe_film_thickness: float | None = None) -> dict:
    """Paper 001's transition: squeeze and wedge film faded out from the safe film thickness [m]
    (default 0.00015 of the diameter) to contact."""
    if safe_film_thickness is None:
        return {"law": "wang_improved"}
    return {"law": "wang_improved", "safe_film_thickness": _si(safe_film_thickness, "length",
                                                                    "transition.safe_film_thickness")}


def flores_transition(lubricated_limit: float = 0.95) -> dict:
    """Flores et al.: squeeze film only, faded out between eccentricity ratio ``lubricated_limit`` and contact."""
    return {"law": "flores", "lubricated_limit": _si(lubricated_limit, "dimensionless",
                                                               "transition.lubricated_limit")}


def switch_transition() -> dict:
    """Film force until contact, contact force after (paper 000's squeeze-film joint)."""
    return {"law": "switch"}
