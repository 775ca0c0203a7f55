"""Parametric templates of common mechanisms, built with :class:`~jointplay.Model`.

Each returns an ordinary model that can be changed further (``add_...``,
``joint(name)``) before it is simulated.
"""

from __future__ import annotations

from .functions import constant_speed
from .model import Model


def slider_crank(*, crank_length: float, rod_length: float, masses: tuple[float, float, float],
                 inertias: tuple[float, float, float], crank_speed: float, gravity: float = 9.81,
                 clearance: dict | None = None, name: str = "slider_crank") -> Model:
    """An in-line slider-crank: crank pinned at the origin and driven at ``crank_speed`` [rad/s],
    connecting rod, slider on the x axis; masses [kg] and centroidal inertias [kg m^2] in the order
    crank, rod, slider; centres of mass at the link mid-points and at the slider pin. Crank and rod
    start along +x.

    Joint names: ``O`` (crank to ground), ``A`` (crank to rod), ``B`` (rod to slider), ``guide``
    (slider to ground), driver ``motor``. With ``clearance`` (the keyword arguments of
    :meth:`Model.add_clearance_revolute` except name and points), ``B`` is a clearance joint with the
    bearing in the slider and the journal on the rod; otherwise it is ideal.
    """
    a, l = crank_length, rod_length
    m = Model(name, gravity=(0.0, -gravity))
    m.add_ground_point("O", (0.0, 0.0))
    m.add_ground_point("line", (0.0, 0.0))
    m.add_body("crank", mass=masses[0], inertia=inertias[0], position=(a / 2, 0.0),
               points={"O": (-a / 2, 0.0), "A": (a / 2, 0.0)})
    m.add_body("rod", mass=masses[1], inertia=inertias[1], position=(a + l / 2, 0.0),
               points={"A": (-l / 2, 0.0), "B": (l / 2, 0.0)})
    m.add_body("slider", mass=masses[2], inertia=inertias[2], position=(a + l, 0.0), points={"B": (0.0, 0.0)})
    m.add_revolute("O", "ground.O", "crank.O")
    m.add_revolute("A", "crank.A", "rod.A")
    m.add_translational("guide", "ground.line", "slider.B", axis=(1.0, 0.0))
    if clearance is None:
        m.add_revolute("B", "slider.B", "rod.B")
    else:
        m.add_clearance_revolute("B", "slider.B", "rod.B", **clearance)
    m.add_driver("motor", "O", constant_speed(crank_speed))
    return m
