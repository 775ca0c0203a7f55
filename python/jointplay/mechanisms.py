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


def hanging_chain(n_bars: int, *, bar_length: float = 0.1, bar_mass: float = 0.1, bar_inertia: float = 1e-4,
                  clearance: dict | None = None, gravity: float = 9.81, name: str = "chain") -> Model:
    """``n_bars`` bars [m, kg, kg m^2 about the centre] pinned end to end from a ground pin ``O``,
    released horizontal along +x under gravity [m/s^2]: the chain whose size is the model's size.

    Bars ``bar0``... with points ``a`` (start) and ``b`` (end); pins ``pin0`` (ground to ``bar0.a``),
    ``pink`` (``bar{k-1}.b`` to ``bark.a``). With ``clearance`` (the keyword arguments of
    :meth:`Model.add_clearance_revolute` except name and points), every pin is a clearance joint with the
    bearing on the earlier link; otherwise every pin is ideal.
    """
    if n_bars < 1:
        raise ValueError(f"a chain needs at least one bar, got {n_bars}")
    m = Model(name, gravity=(0.0, -gravity))
    m.add_ground_point("O", (0.0, 0.0))
    half = bar_length / 2
    previous = "ground.O"
    for k in range(n_bars):
        m.add_body(f"bar{k}", bar_mass, bar_inertia, position=(bar_length * k + half, 0.0),
                   points={"a": (-half, 0.0), "b": (half, 0.0)})
        if clearance is None:
            m.add_revolute(f"pin{k}", previous, f"bar{k}.a")
        else:
            m.add_clearance_revolute(f"pin{k}", previous, f"bar{k}.a", **clearance)
        previous = f"bar{k}.b"
    return m
