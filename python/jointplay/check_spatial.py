"""What ``jointplay check`` prints of a spatial model: its bodies at the assembled start (mass, inertia tensor,
position, orientation as Euler angles of each body's sequence), its joints and drivers by kind, and its
degrees of freedom, by the engine's rank beside the Grübler-Kutzbach count (:mod:`jointplay.mobility`)."""

from __future__ import annotations

import re

import numpy as np
from rich.table import Table

from .display import table

#: Coordinates of a spatial rigid body in the state: position (3) and unit quaternion ``[w, x, y, z]`` (4).
SPATIAL_POSITIONS = 7


def kind_words(kind: str) -> str:
    """The core's element kind in words: ``SpatialJoint(Revolute)`` -> ``revolute joint``,
    ``SpatialAngleDriver`` -> ``angle driver``."""
    joint = re.fullmatch(r"SpatialJoint\((\w+)\)", kind)
    if joint:
        return f"{joint.group(1).lower()} joint"
    plain = kind.removeprefix("Spatial")
    return "".join(f" {c.lower()}" if c.isupper() else c for c in plain).strip()


def inertia_text(inertia) -> str:
    """An inertia tensor [kg m^2]: its diagonal when the off-diagonal terms are zero, else its three rows."""
    tensor = np.asarray(inertia, dtype=float)
    if not np.any(tensor - np.diag(np.diag(tensor))):
        return "diag(" + ", ".join(f"{v:.4g}" for v in np.diag(tensor)) + ") kg m^2"
    return "; ".join(", ".join(f"{v:.4g}" for v in row) for row in tensor) + " kg m^2"


def euler_angles(quaternion, sequence: str) -> np.ndarray:
    """Intrinsic Euler angles [rad] of ``sequence`` (``"ZYX"``) of the rotation of the unit quaternion
    ``[w, x, y, z]`` (scalar first), as the core's ``<body>.euler_<sequence>_1..3`` channels give them."""
    from scipy.spatial.transform import Rotation

    w, x, y, z = quaternion
    return Rotation.from_quat([x, y, z, w]).as_euler(sequence.upper())


def bodies_table(described: list[dict], q0: np.ndarray) -> Table:
    """Each spatial body: kind, mass, inertia tensor about its centre of mass (body frame), position [mm]
    and orientation (Euler angles of its sequence [deg]) at the assembled start."""
    t = table("body", "kind", "mass", "inertia (body frame)", "x, y, z (mm)", "orientation (deg)",
              title="bodies, assembled at t0")
    for body in described:
        if body["kind"] != "spatial_rigid":
            continue
        first, _ = body["coordinates"]  # position address: 7 numbers, the quaternion after the point
        position = q0[first: first + 3]
        angles = np.degrees(euler_angles(q0[first + 3: first + SPATIAL_POSITIONS], body["euler_sequence"]))
        t.add_row(body["name"], "spatial rigid", f"{body['mass']:.4g} kg", inertia_text(body["inertia"]),
                  ", ".join(f"{round(v * 1e3, 3) + 0.0:.3f}" for v in position),
                  f"{body['euler_sequence']} " + ", ".join(f"{round(a, 3) + 0.0:.3f}" for a in angles))
    return t


def freedoms_line(info: dict) -> str:
    """``velocities 18 (6 per body), constraint equations 20 of rank 17, degrees of freedom 1 (Grübler-Kutzbach
    count -2)``."""
    rank = info["n_equations"] - info["redundant_equations"]
    return (f"velocities {info['n_coordinates']} (6 per body), constraint equations {info['n_equations']} "
            f"of rank {rank}, degrees of freedom {info['degrees_of_freedom']} from the rank at the assembled "
            f"position (Grübler-Kutzbach count: {info['gruebler_kutzbach']})")


def count_note(info: dict) -> str | None:
    """Why the count and the rank disagree, when they do."""
    count, dof = info["gruebler_kutzbach"], info["degrees_of_freedom"]
    if count == dof:
        return None
    return (f"the count says {count} and the mechanism has {dof}: {info['redundant_equations']} equation(s) "
            "depend on the others at this position (a special geometry, as parallel revolute axes or "
            "Bricard's loop), which the count cannot see")

