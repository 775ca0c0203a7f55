"""Contact, stiffness and friction laws of a clearance joint and the seal friction of a hydraulic cylinder,
as plain data.

See ``docs/theory/`` for the equation, units and source of each law. Every
physical argument is a number in SI units, a string with a unit (``"0.1 mm/s"``,
``"400 cP"``) or a pint Quantity, converted here by :func:`jointplay.units.to_si`;
a wrong one raises :class:`~jointplay.errors.ModelError` naming the law's key.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from typing import Any

from . import parameters as p


def _si(raw: Any, kind: str, where: str) -> float:
    """``raw`` in the SI unit of ``kind``; a ModelError located at ``where`` when it is not one."""
    from .errors import ModelError, Problem
    from .units import UnitError, to_si

    try:
        return to_si(raw, kind)
    except UnitError as exc:
        raise ModelError([Problem(where, str(exc))]) from None


def _helper(table: p.Table, name: str, where: str) -> Callable[..., dict]:
    """A function returning the plain data of ``table`` (a law, or a material): its keys as arguments, in
    the definition's order, with the definition's defaults (None: "not given", sent as null, what it means
    is the key's ``default_text``); each value converted to SI (errors located at ``where.<key>``), not
    range-checked (the builder does that, as in a file)."""
    signature = inspect.Signature([
        inspect.Parameter(param.key, inspect.Parameter.POSITIONAL_OR_KEYWORD,
                          default=inspect.Parameter.empty if param.required else param.default)
        for param in table.params], return_annotation="dict")

    def make(*args: Any, **kwargs: Any) -> dict:
        bound = signature.bind(*args, **kwargs)
        bound.apply_defaults()
        out = {table.tag: table.name} if table.tag else {}
        for key, value in bound.arguments.items():
            out[key] = None if value is None else _si(value, table[key].kind, f"{where}.{key}")
        return p.core_law(out) if table.tag else out

    make.__signature__ = signature  # type: ignore[attr-defined]
    make.__name__ = make.__qualname__ = name
    make.__doc__ = p.docstring(table)
    return make


STEEL = p.STEEL
"""Structural steel, E = 207 GPa, nu = 0.3 (the value the Flores papers use)."""

material = _helper(p.MATERIAL, "material", "material")

# normal force laws ---------------------------------------------------------

hertz = _helper(p.CONTACT_LAWS["hertz"], "hertz", "contact")
hunt_crossley = _helper(p.CONTACT_LAWS["hunt_crossley"], "hunt_crossley", "contact")
lankarani_nikravesh = _helper(p.CONTACT_LAWS["lankarani_nikravesh"], "lankarani_nikravesh", "contact")
flores = _helper(p.CONTACT_LAWS["flores"], "flores", "contact")
gonthier = _helper(p.CONTACT_LAWS["gonthier"], "gonthier", "contact")
hu_guo = _helper(p.CONTACT_LAWS["hu_guo"], "hu_guo", "contact")

# stiffness laws ------------------------------------------------------------

hertz_cylinder = _helper(p.STIFFNESS_LAWS["hertz_cylinder"], "hertz_cylinder", "stiffness")
johnson_line = _helper(p.STIFFNESS_LAWS["johnson_line"], "johnson_line", "stiffness")
rogers_andrews = _helper(p.STIFFNESS_LAWS["rogers_andrews"], "rogers_andrews", "stiffness")
pereira_ramalho_ambrosio = _helper(p.STIFFNESS_LAWS["pereira_ramalho_ambrosio"], "pereira_ramalho_ambrosio",
                                   "stiffness")

# friction laws -------------------------------------------------------------

frictionless = _helper(p.FRICTION_LAWS["none"], "frictionless", "friction")
coulomb = _helper(p.FRICTION_LAWS["coulomb"], "coulomb", "friction")
ambrosio = _helper(p.FRICTION_LAWS["ambrosio"], "ambrosio", "friction")
threlfall = _helper(p.FRICTION_LAWS["threlfall"], "threlfall", "friction")
stiction = _helper(p.FRICTION_LAWS["stiction"], "stiction", "friction")

# transitions from film to contact --------------------------------------------

wang_transition = _helper(p.TRANSITION_LAWS["wang_improved"], "wang_transition", "transition")
flores_transition = _helper(p.TRANSITION_LAWS["flores"], "flores_transition", "transition")
switch_transition = _helper(p.TRANSITION_LAWS["switch"], "switch_transition", "transition")


# seal friction of a hydraulic cylinder ---------------------------------------

lugre_seal = _helper(p.SEAL_FRICTION_LAWS["lugre_seal"], "lugre_seal", "seal_friction")


# lubrication ---------------------------------------------------------------

FILM_MODELS = p.FILM_MODELS


def centipoise(value: float) -> float:
    """Viscosity in cP to Pa s (1 cP = 1e-3 Pa s)."""
    return float(value) * 1e-3


def lubrication(model: str, viscosity: float, transition: dict | None = None, *, cavitation: str | None = None,
                n_circumferential: int | None = None, n_axial: int | None = None, ambient_pressure: Any = None,
                groove_supply_pressure: Any = None) -> dict:
    from .errors import ModelError, Problem

    if model not in FILM_MODELS:
        raise ValueError(f"unknown film model {model!r}; choose one of {', '.join(FILM_MODELS)}")
    spec = {"model": model, "viscosity": _si(viscosity, "viscosity", "lubrication.viscosity"),
            "transition": transition}
    reynolds_only = {"cavitation": cavitation, "n_circumferential": n_circumferential, "n_axial": n_axial,
                     "ambient_pressure": ambient_pressure, "groove_supply_pressure": groove_supply_pressure}
    if not model.startswith("reynolds"):
        given = [key for key, value in reynolds_only.items() if value is not None]
        if given:
            raise ModelError([Problem(f"lubrication.{key}", f"applies only to the Reynolds models "
                                                            f"({', '.join(p.REYNOLDS_MODELS)}), not to {model}")
                              for key in given])
    else:
        spec["reynolds"] = {key: value for key, value in reynolds_only.items() if value is not None}
        for key in ("ambient_pressure", "groove_supply_pressure"):
            if key in spec["reynolds"]:
                spec["reynolds"][key] = _si(spec["reynolds"][key], "pressure", f"lubrication.{key}")
    # the keys not given, the Reynolds options of a closed form among them, get the definition's defaults
    return p.core_lubrication(spec)


lubrication.__doc__ = p.docstring(p.LUBRICATION, summary=(
    "A lubricant film for a clearance joint, as the core reads it (``model.joint(\"B\")[\"lubrication\"] = ...`` "
    "or ``add_clearance_revolute(lubrication=...)``). ``viscosity`` [Pa s] may be ``\"400 cP\"`` (see "
    ":func:`centipoise`); ``transition`` comes from :func:`wang_transition`, :func:`flores_transition` or "
    ":func:`switch_transition`; ``n_circumferential`` and ``n_axial`` are a model file's ``grid``. Giving a "
    "key of the Reynolds models to a closed-form model is a ModelError, as in a model file."))
