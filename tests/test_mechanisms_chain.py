"""The hanging-chain template (`jointplay.mechanisms.hanging_chain`): its structure, and its motion
against a closed form and the conservation of energy."""

from __future__ import annotations

import numpy as np
import pytest

from jointplay import laws, mechanisms


def test_a_chain_has_its_bars_and_pins_end_to_end():
    m = mechanisms.hanging_chain(3, bar_length=0.2)
    check = m.check()
    assert check["formulation"] == "joint_coordinates"  # 3 joint coordinates: within the measured rule
    results = m.simulate(1e-4)
    # the pins sit at the bars' ends: bar k's centre at (0.2 k + 0.1, 0) before it falls
    for k in range(3):
        assert results[f"bar{k}.x"][0] == pytest.approx(0.2 * k + 0.1, abs=1e-12)
        assert results[f"bar{k}.y"][0] == pytest.approx(0.0, abs=1e-12)


def test_one_bar_falls_as_a_compound_pendulum():
    """A bar released horizontal about its end: the angular acceleration at release is
    m g (L/2) / (I + m (L/2)^2) (moments about the pin), and its energy stays constant."""
    length, mass, inertia = 0.1, 0.1, 1e-4
    results = mechanisms.hanging_chain(1, bar_length=length, bar_mass=mass, bar_inertia=inertia).simulate(
        0.2, rtol=1e-9, atol=1e-12)
    alpha = mass * 9.81 * (length / 2) / (inertia + mass * (length / 2) ** 2)
    assert abs(results["bar0.alpha"][0]) == pytest.approx(alpha, rel=1e-6)
    x, y, omega = (np.asarray(results[f"bar0.{q}"]) for q in ("x", "y", "omega"))
    vx, vy = (np.asarray(results[f"bar0.{q}"]) for q in ("vx", "vy"))
    energy = 0.5 * mass * (vx ** 2 + vy ** 2) + 0.5 * inertia * omega ** 2 + mass * 9.81 * y
    assert np.max(np.abs(energy - energy[0])) < 1e-8 * mass * 9.81 * length
    assert np.min(y) < -0.04  # it fell: the test is not of a body at rest


def test_a_clearance_chain_puts_a_clearance_joint_at_every_pin():
    pin = dict(bearing_radius="5 mm", clearance="0.1 mm", contact=laws.lankarani_nikravesh(0.9),
               friction=laws.frictionless())
    check = mechanisms.hanging_chain(2, clearance=pin).check()
    assert check["formulation"] == "absolute"
    assert check["formulation_reason"].startswith("no ideal joint to remove")


def test_a_chain_needs_a_bar():
    with pytest.raises(ValueError, match="at least one bar"):
        mechanisms.hanging_chain(0)
