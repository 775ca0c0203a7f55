"""jointplay models of the mechanisms of tests/spatial_references.py, built with the builder from the same
data, for the validation tests and the spatial benchmark."""

from __future__ import annotations

import numpy as np

import jointplay as jp
from spatial_references import SPATIAL_SLIDER_CRANK, slider_crank_bodies


def floats(vector) -> list[float]:
    """Plain floats of a vector (numpy scalars are no model values)."""
    return [float(v) for v in vector]


def marker(position, axes=None):
    """A point of a spatial body: its position [m] and, when given, its axes (columns: x, y, z)."""
    if axes is None:
        return floats(position)
    return {"position": floats(position), "axes": {"matrix": np.asarray(axes, float).tolist()}}


def slider_crank_model(theta0: float = SPATIAL_SLIDER_CRANK["theta0"],
                       theta_dot0: float = SPATIAL_SLIDER_CRANK["theta_dot0"],
                       name: str = "spatial slider-crank") -> jp.Model:
    """The spatial slider-crank of SPATIAL_SLIDER_CRANK, its bodies placed and moving at the crank angle
    theta0 [rad] and rate theta_dot0 [rad/s] (``slider_crank_bodies``)."""
    data = SPATIAL_SLIDER_CRANK
    model = jp.Model(name, gravity=floats(data["gravity"]), kinematics="spatial")
    start = slider_crank_bodies(theta0, theta_dot0)
    points = {body: {} for body in start}
    for joint in data["joints"]:
        for side in ("first", "second"):
            body, position, axes = joint[side]
            if body == "ground":
                model.add_ground_point(joint["name"], floats(position),
                                       axes=None if axes is None else {"matrix": np.asarray(axes, float).tolist()})
            else:
                points[body][joint["name"]] = marker(position, axes)
    for body, state in start.items():
        model.add_body(body, mass=data[f"{body}_mass"], inertia={"principal": floats(data[f"{body}_inertia"])},
                       position=floats(state["position"]), orientation={"matrix": state["rotation"].tolist()},
                       velocity=floats(state["velocity"]), angular_velocity=floats(state["angular_velocity"]),
                       points=points[body])
    for joint in data["joints"]:
        add = getattr(model, f"add_{joint['type']}")
        add(joint["name"], f"{joint['first'][0]}.{joint['name']}", f"{joint['second'][0]}.{joint['name']}")
    return model
