"""Micro-models and helpers shared by the tests of checked input (tests/ is on the path: tests/conftest.py)."""

from __future__ import annotations

import pytest

import jointplay as jp


def pendulum() -> jp.Model:
    """A bar of 1 kg, 0.5 m, pinned at one end to the ground, under gravity."""
    m = jp.Model("pendulum", gravity=(0, -9.81))
    m.add_ground_point("O", (0, 0))
    m.add_body("bar", mass=1.0, inertia=0.02, position=(0.25, 0), points={"O": (-0.25, 0)})
    m.add_revolute("pin", "ground.O", "bar.O")
    return m


def problems_of(call) -> list[tuple[str, str]]:
    """The (location, message) pairs of the ModelError that ``call()`` raises."""
    with pytest.raises(jp.ModelError) as caught:
        call()
    return [(p.location, p.message) for p in caught.value.problems]
