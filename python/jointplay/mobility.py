"""Degrees of freedom of a spatial mechanism counted by the Grübler-Kutzbach criterion.

The count is 6 per moving rigid body minus the equations each joint and driver removes:

    M = 6 n - sum(c_j)

with c_j = 3 for a spherical joint, 5 revolute, 4 universal, 4 cylindrical, 5 translational,
6 fixed, and 1 for each driver (J. J. Uicker, G. R. Pennock, J. E. Shigley, Theory of Machines and
Mechanisms, 5th ed., 2017, section 1.9, "Mobility"; the Kutzbach form for spatial linkages).

The count ignores the geometry: equations that depend on each other (a four-bar whose revolute axes are
parallel, Bricard's six-revolute loop) make the true mobility larger than the count. The engine's
degrees of freedom come from the rank of the constraint Jacobian at the assembled position
(``Model.check()["degrees_of_freedom"]``, with the redundant equations and the elements they belong
to), and ``Model.check()`` gives both for a spatial model.
"""

from __future__ import annotations

#: Freedoms of a spatial rigid body: three translations and three rotations.
BODY_FREEDOMS = 6
#: Equations each spatial joint type removes (its constraint rows).
JOINT_EQUATIONS = {"spherical": 3, "revolute": 5, "universal": 4, "cylindrical": 4, "translational": 5,
                   "fixed": 6}
#: Equations a driver removes (its one prescribed coordinate).
DRIVER_EQUATIONS = 1


def gruebler_kutzbach(spec: dict) -> int:
    """Degrees of freedom of the spatial model ``spec`` (``Model.to_spec()``) by the Grübler-Kutzbach
    count: 6 per body of ``spatial_bodies`` minus the equations of each joint of ``spatial_joints`` and of
    each driver."""
    bodies = len(spec.get("spatial_bodies", []))
    joints = sum(JOINT_EQUATIONS[j["type"]] for j in spec.get("spatial_joints", []))
    drivers = DRIVER_EQUATIONS * len(spec.get("drivers", []))
    return BODY_FREEDOMS * bodies - joints - drivers

