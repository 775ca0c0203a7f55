"""A flexible slider-crank computed with the rod as a beam mesh and as a modal body of the same mesh.

The rod (chosen: steel, 300 mm, 10 mm x 10 mm, 8 quadratic elements; crank 50 mm brought from rest to
75 rad/s over 40 ms by a speed ramp; slider 0.05 kg; no gravity) is once the geometrically exact beam and
once a modal body: a chord frame through its two pins plus the Craig-Bampton modes of the same mesh
(constraint modes of the pins' free coordinates and ``n`` fixed-interface normal modes). Both carry the same
stiffness-proportional damping, the beam's strain-rate damping of retardation time tau and the modal body's
``tau K``, tau chosen for 5 % of critical in the first bending mode (819 Hz pinned-pinned), so the start's
vibration has died out (time constant 4 ms) when the comparison starts at 40 ms. A strain gauge at mid-span
reads the axial strain of the surface fibre (5 mm from the axis): the beam's from its element, the modal
body's recovered from its modes on the same element. The beam mesh itself is checked against an
independent implementation of a similar mechanism (test_independent_flexible_slider_crank.py).

Why these values: a linear modal body has no geometric stiffening, so it can converge to the geometrically
exact beam only as far as the rod's axial force is small against its buckling load (18.3 kN). With a 0.5 kg
slider at 150 rad/s the difference stops shrinking at about 2 % of the peak strain (1, 4, 8 modes: 4.8e-2,
1.9e-2, 2.2e-2; the axial force reaches some 4 % of the buckling load); at 75 rad/s with a 0.05 kg slider
it is below 0.4 %, so the truncation error of the modes shows. Seen: 1, 3, 7 normal modes 3.2e-2, 9.4e-3,
1.5e-3 of the peak strain; not monotone at every count (8 and 9 modes 3.2e-3, 10 modes 1.5e-3, 12 modes
9.7e-4). The slider's acceleration agrees to 2.0e-4 of its peak with any mode count.
"""

from __future__ import annotations

import numpy as np

import jointplay as jp
from jointplay import functions as fn
from jointplay import sections

CRANK, ROD, SPEED, RAMP = 0.05, 0.30, 75.0, 0.04  # m, m, rad/s, s
SLIDER = 0.05  # kg
SECTION = sections.rectangle("10 mm", "10 mm")
ELEMENTS = 8
DAMPING_TIME = 2 * 0.05 / (2 * np.pi * 819.0)  # s: 5 % of critical in the rod's first bending mode
T_END = 0.08  # s: the ramp and 40 ms at full speed
OPTIONS = dict(method="bdf", max_order=2, stabilization="baumgarte", rtol=1e-8, atol=1e-10, output_step=2e-4)


def slider_crank(rod: str, normal_modes: int = 0) -> jp.Model:
    """The slider-crank at rest, crank along +x; ``rod`` is "beam" or "modal"."""
    m = jp.Model(f"flexible slider-crank ({rod})", gravity=(0, 0))
    m.add_ground_point("O", (0, 0))
    m.add_ground_point("line", (0, 0))
    m.add_body("crank", mass=0.3, inertia=1e-4, position=(CRANK / 2, 0), points={"O": (-CRANK / 2, 0), "B": (CRANK / 2, 0)})
    m.add_body("slider", mass=SLIDER, inertia=1e-4, position=(CRANK + ROD, 0), points={"A": (0, 0)})
    rod_args = dict(section=SECTION, material=sections.STEEL, elements=ELEMENTS, points={"mid": ROD / 2},
                    damping_time=DAMPING_TIME)
    if rod == "beam":
        m.add_beam("rod", (CRANK, 0), (CRANK + ROD, 0), **rod_args)
    else:
        m.add_modal_body("rod", (CRANK, 0), (CRANK + ROD, 0), normal_modes=normal_modes, **rod_args)
    m.add_revolute("O", "ground.O", "crank.O")
    m.add_revolute("B", "crank.B", "rod.start")
    m.add_revolute("A", "rod.end", "slider.A")
    m.add_translational("guide", "ground.line", "slider.A", axis=(1, 0))
    m.add_driver("drive", "O", fn.speed_ramp(SPEED, RAMP))
    m.add_strain_gauge("gauge", "rod.mid", fibre="5 mm")
    return m


def test_the_modal_rods_strain_converges_to_the_beam_meshs_as_modes_are_added():
    beam = slider_crank("beam").simulate(T_END, **OPTIONS)
    after = beam.time > RAMP
    strain, acceleration = np.asarray(beam["gauge.axial_strain"]), np.asarray(beam["slider.ax"])
    # the gauge reads bending: the surface fibre's strain is mostly curvature times 5 mm
    assert np.max(np.abs(strain[after])) > 2e-5
    errors = []
    for modes in (1, 3, 7):
        modal = slider_crank("modal", modes).simulate(T_END, **OPTIONS)
        assert modal.spec["modal_bodies"][0]["frame"] is None  # the default: a chord frame through the pins
        modal_strain = np.interp(beam.time, modal.time, modal["gauge.axial_strain"])
        errors.append(np.max(np.abs(modal_strain - strain)[after]) / np.max(np.abs(strain[after])))
        modal_acceleration = np.interp(beam.time, modal.time, modal["slider.ax"])
        assert np.max(np.abs(modal_acceleration - acceleration)[after]) < 5e-4 * np.max(np.abs(acceleration[after]))
    # the tolerance shrinks as modes are added (seen: 3.2e-2, 9.4e-3, 1.5e-3)
    assert errors[1] < errors[0] / 2 and errors[2] < errors[1] / 2 and errors[2] < 5e-3, errors
