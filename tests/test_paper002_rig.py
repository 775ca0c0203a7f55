"""Paper 002's hydraulic cylinder rig (examples/paper002_cylinder_rig.toml and .py, and the study of
examples/paper002_cylinder_study.py): the physics it must show, checked against closed forms written here,
the figures of the spatial clearance joint from a real short run, and the study on a 2 x 2 table.

Closed forms, independent of the code under test:
- the hydraulic spring of closed chambers, k = beta (A1^2/V1 + A2^2/V2) (Merritt, Hydraulic Control Systems,
  1967; docs/theory/hydraulic-cylinder.md), with the rig's geometry: the cylinder at angle alpha to the guide
  carries F / cos(alpha) of a horizontal force F on the slider, and the slider moves ds / cos(alpha) along
  the guide for a stroke change ds;
- the statics of the barrel and rod at rest under gravity: no horizontal load, so the moments about the
  barrel pin A give the slider pin's share of the weights, B_z = (m_b g d_b + m_r g d_r) / L, and A_z the rest.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
sys.path.insert(0, str(EXAMPLES))

import paper002_cylinder_rig as rig  # noqa: E402
from jointplay.modelfile import from_document  # noqa: E402

G = 9.81  # m/s^2, the model file's gravity
#: The model file's values (its header says why each is chosen).
ALPHA = math.radians(5.0)  # inclination of the cylinder
BORE, ROD, STROKE_0, DEAD, BETA = 0.080, 0.045, 0.250, 1e-4, 1e9  # m, m, m, m^3, Pa
PIN_DISTANCE = 1.050  # m, pin A to pin B at the start
BARREL_MASS, BARREL_ARM = 16.081, 0.3060571  # kg; its centre of mass from pin A along the axis [m]
ROD_MASS, ROD_ARM = 10.643, PIN_DISTANCE - 0.3766470  # kg; its centre of mass from pin A [m]


def hydraulic_stiffness() -> float:
    """k = beta (A1^2/V1 + A2^2/V2) [N/m] at the starting stroke."""
    a1 = math.pi * BORE**2 / 4
    a2 = math.pi * (BORE**2 - ROD**2) / 4
    v1, v2 = a1 * STROKE_0 + DEAD, a2 * STROKE_0 + DEAD
    return BETA * (a1**2 / v1 + a2**2 / v2)


def weight_shares() -> tuple[float, float]:
    """Vertical pin loads (A_z, B_z) [N] carried by the barrel pin and the slider pin at rest."""
    b_z = G * (BARREL_MASS * BARREL_ARM + ROD_MASS * ROD_ARM) / PIN_DISTANCE
    return G * (BARREL_MASS + ROD_MASS) - b_z, b_z


def test_variants_change_what_they_say():
    doc = rig.document(force=1500.0, frequency=7.0, clearance=0.2e-3, axial_clearance=0.3e-3)
    sine = doc["forces"]["input"]["force"][0]
    assert (sine["amplitude"], sine["frequency"]) == ("1500.0 N", "7.0 Hz")
    ideal = rig.document(ideal=True)
    for joint in rig.JOINTS:
        assert ideal["joints"][joint]["type"] == "revolute"
    assert rig.build_model(ideal=True).check()["degrees_of_freedom"] == 1


def ramped_ideal_rig(force: float) -> dict:
    """The ideal-joint rig with frictionless seals and a horizontal force ramped smoothly to ``force`` [N]
    over 0.1 s (13 periods of the oil spring's 127 Hz: its residual vibration is about 1e-3 of the
    deflection and averages out over the window below)."""
    doc = rig.document(ideal=True)
    del doc["forces"]["cylinder"]["seal_friction"]
    doc["forces"]["input"]["force"][0] = {"kind": "cubic_step", "t_start": "0 s", "t_end": "0.1 s",
                                          "value_start": "0 N", "value_end": f"{force!r} N"}
    return doc


def test_oil_spring_deflects_the_slider_as_its_closed_form():
    runs = {}
    for force in (2000.0, -2000.0):
        model = from_document(ramped_ideal_rig(force))
        runs[force] = model.simulate(0.2, method="dopri5", rtol=1e-8, atol=1e-11, output_step=1e-4)
    window = {f: r.time >= 0.1 for f, r in runs.items()}  # after the ramp, 12.7 periods of the oil spring

    def half_difference(channel: str) -> float:
        return (np.mean(runs[2000.0][channel][window[2000.0]]) - np.mean(runs[-2000.0][channel][window[-2000.0]])) / 2

    k = hydraulic_stiffness()
    # the half difference of +-F cancels gravity and the quadratic term of the pressure law; what is left,
    # the cubic term and the angle's change, is below 1e-6 of the deflection; 1e-4 leaves room for the
    # mean of the residual vibration over a window that is not a whole number of periods
    assert half_difference("cylinder.stroke") == pytest.approx(2000.0 / (k * math.cos(ALPHA)), rel=1e-4)
    assert half_difference("slider.x") == pytest.approx(2000.0 / (k * math.cos(ALPHA) ** 2), rel=1e-4)


def test_ideal_pins_share_the_weight_as_the_statics_says():
    doc = rig.document(ideal=True)
    doc["forces"]["input"]["force"][0] = "0 N"
    results = from_document(doc).simulate(0.3, method="dopri5", rtol=1e-8, atol=1e-11, output_step=1e-3)
    a_z, b_z = weight_shares()
    # reactions on the second bodies (ground, slider): the pins push them down by the shares
    assert results["base.fz"][-1] == pytest.approx(-a_z, rel=1e-6)
    assert results["rod_end.fz"][-1] == pytest.approx(-b_z, rel=1e-6)
    assert abs(results["base.fx"][-1]) < 1e-6 * a_z
