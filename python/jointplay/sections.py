"""Cross-sections and materials of flexible links (:meth:`jointplay.Model.add_beam`), as plain data.

Each helper returns the table a model file writes (``section = { shape = "rectangle", ... }``,
``material = { youngs_modulus = ..., ... }``). Values are numbers in SI units, strings with a unit
(``"10 mm"``) or pint Quantities; the builder reads them as the model file's keys (units, ranges, messages).
The shapes, their keys and the shear factors they imply: ``docs/model-file-reference.md`` and
``docs/theory/beam.md``.
"""

from __future__ import annotations

from typing import Any

Quantity = Any  # a number in SI units, a string with a unit ("10 mm") or a pint Quantity


def _value(x: Any) -> Any:
    if isinstance(x, (int, float)) and not isinstance(x, bool):
        return float(x)
    return x


def rectangle(width: Quantity, height: Quantity) -> dict:
    """Solid rectangle: ``width`` out of the plane of motion, ``height`` in the plane of bending [m]."""
    return {"shape": "rectangle", "width": _value(width), "height": _value(height)}


def circle(diameter: Quantity) -> dict:
    """Solid circle of ``diameter`` [m]."""
    return {"shape": "circle", "diameter": _value(diameter)}


def tube(outer_diameter: Quantity, inner_diameter: Quantity) -> dict:
    """Circular tube [m]."""
    return {"shape": "tube", "outer_diameter": _value(outer_diameter), "inner_diameter": _value(inner_diameter)}


def properties(area: Quantity, second_moment: Quantity, shear_factor: float) -> dict:
    """Any section by its area [m^2], second moment about the bending axis [m^4] and shear factor k."""
    return {"shape": "properties", "area": _value(area), "second_moment": _value(second_moment),
            "shear_factor": _value(shear_factor)}


def resultants(axial_stiffness: Quantity, shear_stiffness: Quantity, bending_stiffness: Quantity,
               mass_per_length: Quantity, rotary_inertia_per_length: Quantity) -> dict:
    """The section's E A [N], k G A [N], E I [N m^2], rho A [kg/m] and rho I [kg m] directly (no material)."""
    return {"shape": "resultants", "axial_stiffness": _value(axial_stiffness),
            "shear_stiffness": _value(shear_stiffness), "bending_stiffness": _value(bending_stiffness),
            "mass_per_length": _value(mass_per_length), "rotary_inertia_per_length": _value(rotary_inertia_per_length)}


def material(youngs_modulus: Quantity, density: Quantity, poisson_ratio: float | None = None,
             shear_modulus: Quantity | None = None) -> dict:
    """An isotropic elastic material: E [Pa], density [kg/m^3] and exactly one of nu and G [Pa]."""
    return {key: _value(value) for key, value in (("youngs_modulus", youngs_modulus), ("density", density),
                                                  ("poisson_ratio", poisson_ratio), ("shear_modulus", shear_modulus))
            if value is not None}


#: Structural steel: E = 207 GPa, nu = 0.3, 7850 kg/m^3.
STEEL = material(207e9, 7850.0, poisson_ratio=0.3)
