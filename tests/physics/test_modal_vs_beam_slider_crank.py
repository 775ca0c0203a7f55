"""A flexible slider-crank computed with the rod as a beam mesh and as a modal body of the same mesh.

The rod (chosen: steel, 300 mm, 10 mm x 10 mm, 8 quadratic elements; crank 50 mm brought from rest to
150 rad/s over 40 ms by a speed ramp; slider 0.5 kg; no gravity) is once the geometrically exact beam and
once a modal body: a floating frame at the crank end plus the Craig-Bampton modes of the same mesh
(constraint modes of the mid-span and slider-end nodes and ``n`` fixed-interface normal modes). Both are
damped to 5 % of critical in the first bending mode (819 Hz pinned-pinned), so the start's vibration has
died out (time constant 4 ms) when the comparison starts at 40 ms. The beam mesh itself is checked against
an independent implementation of a similar mechanism (test_independent_flexible_slider_crank.py).

KNOWN DISCREPANCY, recorded here as a strict expected failure: the modal rod's mid-span deflection differs
from the beam mesh's by 8.5 % of its peak (0.28 mm) whatever the number of normal modes (1, 2, 4, 8: 0.0848,
0.0848, 0.0848, 0.0848), while the slider's acceleration and the force in joint A agree to 1.5e-4 of their
peaks. The difference looks like a phase shift of the bending response over the crank's turn. It is not
geometric stiffening (the axial force is 0.4 % of the rod's buckling load) and not the start's vibration
(it is damped out). The modal body alone matches the closed forms of a cantilever on a hub accelerated
along y (qL^4/8EI) and in rotation (11 q0 L^4 / 120 EI) to 0.1-0.2 %; what differs here is a rod whose
far interface node is held by a joint while the frame turns. Not yet explained.
"""

from __future__ import annotations

import numpy as np
import pytest

import jointplay as jp
from jointplay import functions as fn
from jointplay import sections

CRANK, ROD, SPEED, RAMP = 0.05, 0.30, 150.0, 0.04  # m, m, rad/s, s
SECTION = sections.rectangle("10 mm", "10 mm")
ELEMENTS = 8
DAMPING_RATIO = 0.05  # of critical, every mode of the modal body
DAMPING_TIME = 2 * DAMPING_RATIO / (2 * np.pi * 819.0)  # s: the beam's first bending mode (819 Hz pinned-pinned) as damped
T_END = 0.08  # s: the ramp and 6 rad at full speed
OPTIONS = dict(method="bdf", max_order=2, stabilization="baumgarte", rtol=1e-8, atol=1e-10, output_step=2e-4)


def slider_crank(rod: str, normal_modes: int = 0) -> jp.Model:
    """The slider-crank at rest, crank along +x; ``rod`` is "beam" or "modal"."""
    m = jp.Model(f"flexible slider-crank ({rod})", gravity=(0, 0))
    m.add_ground_point("O", (0, 0))
    m.add_ground_point("line", (0, 0))
    m.add_body("crank", mass=0.3, inertia=1e-4, position=(CRANK / 2, 0), points={"O": (-CRANK / 2, 0), "B": (CRANK / 2, 0)})
    m.add_body("slider", mass=0.5, inertia=1e-4, position=(CRANK + ROD, 0), points={"A": (0, 0)})
    ends = dict(section=SECTION, material=sections.STEEL, elements=ELEMENTS)
    if rod == "beam":
        m.add_beam("rod", (CRANK, 0), (CRANK + ROD, 0), points={"mid": ROD / 2}, damping_time=DAMPING_TIME, **ends)
    else:
        m.add_modal_body("rod", (CRANK, 0), (CRANK + ROD, 0), normal_modes=normal_modes, damping_ratio=DAMPING_RATIO,
                         interface={"start": 0.0, "end": ROD, "mid": ROD / 2}, **ends)
    m.add_revolute("O", "ground.O", "crank.O")
    m.add_revolute("B", "crank.B", "rod.start")
    m.add_revolute("A", "rod.end", "slider.A")
    m.add_translational("guide", "ground.line", "slider.A", axis=(1, 0))
    m.add_driver("drive", "O", fn.speed_ramp(SPEED, RAMP))
    for probe, first, second in (("start_mid", "start", "mid"), ("mid_end", "mid", "end"), ("chord", "start", "end")):
        # springs of no stiffness, as probes: their lengths give the mid-span deflection
        m.add_spring_damper(probe, f"rod.{first}", f"rod.{second}", stiffness=0.0, damping=0.0, free_length=0.0)
    return m


def mid_span_deflection(results: jp.Results) -> np.ndarray:
    """Distance of the rod's mid-span point from its chord [m] (Heron's formula on the probes' triangle)."""
    a, b, c = (np.asarray(results[f"{p}.length"]) for p in ("start_mid", "mid_end", "chord"))
    s = (a + b + c) / 2
    return 2.0 * np.sqrt(np.maximum(s * (s - a) * (s - b) * (s - c), 0.0)) / c


@pytest.mark.xfail(strict=True, reason="modal rod's mid-span deflection 8.5 % off the beam mesh's, not yet explained "
                                       "(module docstring)")
def test_modal_rod_converges_to_the_beam_mesh_as_modes_are_added():
    beam = slider_crank("beam").simulate(T_END, **OPTIONS)
    after = beam.time > RAMP
    reference = mid_span_deflection(beam)
    errors = []
    for modes in (1, 4):
        modal = slider_crank("modal", modes).simulate(T_END, **OPTIONS)
        deflection = np.interp(beam.time, modal.time, mid_span_deflection(modal))
        errors.append(np.max(np.abs(deflection - reference)[after]) / np.max(reference))
        acceleration = np.interp(beam.time, modal.time, modal["slider.ax"])
        assert np.max(np.abs(acceleration - beam["slider.ax"])[after]) < 3e-4 * np.max(np.abs(beam["slider.ax"]))
    assert errors[1] < errors[0] / 2 and errors[1] < 0.01
