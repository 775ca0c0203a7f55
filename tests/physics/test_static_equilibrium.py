"""Static equilibrium (Model.equilibrium, jointplay static) against closed forms
(docs/theory/static-equilibrium.md).

- A cantilever beam under a tip load: the inextensible elastica, shot here with SciPy (an implementation of its
  own) and checked against Bisshopp and Drucker's tip deflection, 0.3017 L at P L^2 / EI = 1 (Q. Appl. Math. 3
  (1945) 272-275).
- A cantilever beam under an end moment M: the circle of radius EI / M (the roll-up).
- A modal cantilever under a small tip load: P L^3 / (3 EI) + P L / (k G A) (Timoshenko).
- A preloaded spring holding a mass under gravity: k (l - l0) = m g.
- A pendulum held by a closed hydraulic cylinder: the angle where the cylinder's moment, its pressures following
  their volumes as p = p0 - beta ln(V / V0), balances gravity's (a scalar root found here with SciPy).
- A free body under gravity has no equilibrium: the message names it.
- A run started at the equilibrium stays there.
"""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

import jointplay as jp
from jointplay import sections

EI, LENGTH = 1.0, 1.0
# stiff in tension and shear (1e7 EI / L^2), so that the inextensible elastica applies
STIFF = sections.resultants(axial_stiffness=1e7, shear_stiffness=1e7, bending_stiffness=EI, mass_per_length=1.0,
                            rotary_inertia_per_length=1e-4)


def elastica_tip(alpha: float) -> tuple[float, float]:
    """Tip (x, y) of a cantilever of unit length and stiffness under a downward tip load alpha = P L^2 / EI:
    theta'' = -alpha cos(theta) along s from the clamp, theta(0) = 0, theta'(1) = 0, shot on theta'(0)."""
    def shoot(curvature: float):
        return solve_ivp(lambda s, y: [y[1], alpha * math.cos(y[0]), math.cos(y[0]), math.sin(y[0])], (0.0, 1.0),
                         [0.0, curvature, 0.0, 0.0], rtol=1e-12, atol=1e-12).y[:, -1]

    root = brentq(lambda k: shoot(k)[1], -alpha, 0.0, xtol=1e-14)
    end = shoot(root)
    return float(end[2]), float(end[3])


def cantilever(tip_load: float | None = None, moment: float | None = None, elements: int = 16) -> jp.Model:
    """A beam along x. With ``tip_load`` (downward, at its end) clamped at its start; with ``moment`` clamped at
    its end, the moment acting on its first section (the body's reference section), then free."""
    m = jp.Model("cantilever", gravity=(0, 0))
    m.add_ground_point("O", (0, 0))
    m.add_ground_point("E", (LENGTH, 0))
    m.add_beam("arm", (0, 0), (LENGTH, 0), section=STIFF, elements=elements)
    if tip_load is not None:
        m.add_fixed("clamp", "ground.O", "arm.start")
        m.add_point_force("tip", "arm.end", fy=-tip_load)
    else:
        m.add_fixed("clamp", "ground.E", "arm.end")
        m.add_torque("moment", "arm", moment)
    return m


def test_the_shooting_reproduces_bisshopp_and_drucker():
    assert -elastica_tip(1.0)[1] == pytest.approx(0.3017, abs=5e-5)


@pytest.mark.parametrize("alpha", [1.0, 3.0])
def test_a_tip_load_bends_a_cantilever_beam_to_the_elastica(alpha):
    found = cantilever(tip_load=alpha * EI / LENGTH**2).equilibrium()
    x, y = elastica_tip(alpha)
    # 16 quadratic elements: within 2e-5 L of the elastica (crates' beam tests, the element's own static solve)
    assert found.coordinates[-3:-1] == pytest.approx([x, y], abs=3e-5)
    # the clamp carries the load
    assert abs(found["clamp.fy"]) == pytest.approx(alpha, rel=1e-6)
    assert found.iterations < 40


def test_an_end_moment_rolls_a_cantilever_beam_into_a_circle():
    # a quarter circle: M = (pi / 2) EI / L, radius R = EI / M
    moment = 0.5 * math.pi * EI / LENGTH
    radius = EI / moment
    first = cantilever(moment=moment).equilibrium().coordinates[:3]
    # clamped at (L, 0) along x, the free first section lies L of arc back along the circle
    assert first[0] == pytest.approx(LENGTH - radius * math.sin(LENGTH / radius), abs=1e-5)
    assert abs(first[1]) == pytest.approx(radius * (1.0 - math.cos(LENGTH / radius)), abs=1e-5)
    assert abs(first[2]) == pytest.approx(LENGTH / radius, abs=1e-5)


def test_a_modal_cantilever_deflects_as_timoshenko_says():
    ea, kga, ei, load = 1e7, 1e5, 10.0, 1e-3
    m = jp.Model("modal cantilever", gravity=(0, 0))
    m.add_ground_point("O", (0, 0))
    section = sections.resultants(axial_stiffness=ea, shear_stiffness=kga, bending_stiffness=ei, mass_per_length=1.0,
                                  rotary_inertia_per_length=1e-4)
    m.add_modal_body("arm", (0, 0), (LENGTH, 0), section=section, elements=8, frame="clamped")
    m.add_fixed("clamp", "ground.O", "arm.start")
    m.add_point_force("tip", "arm.end", fy=-load)
    found = m.equilibrium()
    # in the clamped frame the first modes are the end node's interface displacements (x, y, rotation)
    assert -found["arm.eta2"] == pytest.approx(load * LENGTH**3 / (3 * ei) + load * LENGTH / kga, rel=1e-6)
    assert -found["arm.eta3"] == pytest.approx(load * LENGTH**2 / (2 * ei), rel=1e-6)


def hanging_mass(mass: float = 2.0, k: float = 500.0, free: float = 0.3) -> jp.Model:
    m = jp.Model("hanging mass", gravity=(0, -9.81))
    m.add_ground_point("top", (0, 0))
    m.add_ground_point("rail", (0, -0.2))
    m.add_body("mass", mass=mass, inertia=0.01, position=(0, -0.2), points={"P": (0, 0)})
    m.add_translational("guide", "ground.rail", "mass.P", axis=(0, 1))
    m.add_spring_damper("spring", "ground.top", "mass.P", stiffness=k, free_length=free)
    return m


def test_a_preloaded_spring_holds_a_mass_under_gravity():
    mass, k, free = 2.0, 500.0, 0.3
    found = hanging_mass(mass, k, free).equilibrium()
    # the spring stretched by m g / k beyond its free length
    assert found["mass.y"] == pytest.approx(-(free + mass * 9.81 / k), rel=1e-9)
    assert found["spring.force"] == pytest.approx(mass * 9.81, rel=1e-9)
    assert found.force_residual < 1e-9


# the pendulum and its cylinder: a bar of 1 m pivoted at O, the cylinder from C = (0.2, -0.6) to R on the bar
PENDULUM = dict(mass=50.0, length=1.0, lever=0.6, base=(0.2, -0.6), a1=2e-3, a2=1.2e-3, stroke=0.4, dead=2e-3,
                beta=2e8, p0=1e6)


def pendulum_with_cylinder() -> jp.Model:
    c = PENDULUM
    m = jp.Model("pendulum on a cylinder", gravity=(0, -9.81))
    m.add_ground_point("O", (0, 0))
    m.add_ground_point("C", c["base"])
    m.add_body("bar", mass=c["mass"], inertia=c["mass"] * c["length"] ** 2 / 12, position=(c["length"] / 2, 0),
               points={"O": (-c["length"] / 2, 0), "R": (c["lever"] - c["length"] / 2, 0)})
    m.add_revolute("pivot", "ground.O", "bar.O")
    retracted = math.dist(c["base"], (c["lever"], 0.0)) - 0.2  # the assembled stroke is 0.2 m
    assert retracted > 0
    m.add_hydraulic_cylinder("lift", "ground.C", "bar.R", piston_area=c["a1"], rod_side_area=c["a2"],
                             stroke_length=c["stroke"], cap_dead_volume=c["dead"], rod_dead_volume=c["dead"],
                             initial_stroke=0.2, cap_pressure=c["p0"], rod_pressure=c["p0"], bulk_modulus=c["beta"])
    return m


def pendulum_angle() -> float:
    """The bar's angle at rest, from the balance of moments about O with closed chambers."""
    c = PENDULUM
    base = np.array(c["base"])
    start_length = math.dist(c["base"], (c["lever"], 0.0))
    retracted = start_length - 0.2

    def moment(angle: float) -> float:
        r = c["lever"] * np.array([math.cos(angle), math.sin(angle)])
        d = r - base
        stroke = np.linalg.norm(d) - retracted
        v_cap, v_rod = c["dead"] + c["a1"] * stroke, c["dead"] + c["a2"] * (c["stroke"] - stroke)
        v_cap0, v_rod0 = c["dead"] + c["a1"] * 0.2, c["dead"] + c["a2"] * (c["stroke"] - 0.2)
        p_cap = c["p0"] - c["beta"] * math.log(v_cap / v_cap0)
        p_rod = c["p0"] - c["beta"] * math.log(v_rod / v_rod0)
        force = (p_cap * c["a1"] - p_rod * c["a2"]) * d / np.linalg.norm(d)  # on the bar, pushing it away from C
        gravity = -c["mass"] * 9.81 * (c["length"] / 2) * math.cos(angle)
        return float(r[0] * force[1] - r[1] * force[0] + gravity)

    return brentq(moment, -0.3, 0.3, xtol=1e-15)


def test_a_pendulum_held_by_a_closed_cylinder_rests_where_the_moments_balance():
    found = pendulum_with_cylinder().equilibrium()
    angle = pendulum_angle()
    assert found["bar.angle"] == pytest.approx(angle, abs=1e-9)
    assert found["bar.angle"] != pytest.approx(0.0, abs=1e-4)  # it did sag
    # the cap pressure followed the chamber's volume
    c = PENDULUM
    assert found["lift.p_cap"] == pytest.approx(
        c["p0"] - c["beta"] * math.log((c["dead"] + c["a1"] * found["lift.stroke"]) / (c["dead"] + c["a1"] * 0.2)),
        rel=1e-9)


def test_a_free_body_under_gravity_has_no_equilibrium():
    m = jp.Model("falling", gravity=(0, -9.81))
    m.add_body("stone", mass=1.0, inertia=0.01, position=(0, 0))
    with pytest.raises(jp.SimulationError) as caught:
        m.equilibrium()
    assert "no static equilibrium" in str(caught.value)
    assert "stone has an unbalanced load of 9.8100e0 N" in str(caught.value)


def test_a_run_from_equilibrium_stays_at_rest():
    m = hanging_mass()
    found = m.equilibrium()
    results = m.simulate(0.5, initial="equilibrium", rtol=1e-9, atol=1e-12)
    assert results["mass.y"][0] == found["mass.y"]
    assert np.max(np.abs(results["mass.y"] - found["mass.y"])) < 1e-9
    # from the description's position instead it oscillates about the equilibrium
    moving = m.simulate(0.5, rtol=1e-9, atol=1e-12)
    assert np.max(np.abs(moving["mass.y"] - found["mass.y"])) > 1e-3


def test_a_bad_start_option_is_a_located_model_error():
    with pytest.raises(jp.ModelError) as caught:
        hanging_mass().simulate(0.1, initial="rest")
    assert "simulation.initial: must be \"assembly\" or \"equilibrium\", got 'rest'" in str(caught.value)


def test_a_journal_rests_in_its_bore_at_the_hertz_laws_static_penetration():
    """A 10 kg block hung from a bore in the ground by a pin at its centre of mass: at rest the pin lies at the
    bottom of the bore, pressed in until K delta^1.5 = m g, K = (4/3) E* sqrt(R*) (docs/theory/
    stiffness-hertz-cylinder.md), steel on steel."""
    mass, radius, clearance = 10.0, 0.010, 0.5e-3
    m = jp.Model("hung block", gravity=(0, -9.81))
    m.add_ground_point("B", (0, 0))
    m.add_body("block", mass=mass, inertia=0.05, position=(0, 0), points={"B": (0, 0)})
    m.add_clearance_revolute("B", "ground.B", "block.B", bearing_radius=radius, clearance=clearance,
                             contact=jp.laws.lankarani_nikravesh(0.9), friction=jp.laws.coulomb(0.1))
    found = m.equilibrium()
    e_star = 1.0 / (2 * (1 - 0.3**2) / 207e9)
    r_star = radius * (radius - clearance) / clearance
    k = 4.0 / 3.0 * e_star * math.sqrt(r_star)
    penetration = (mass * 9.81 / k) ** (1 / 1.5)
    assert found["B.penetration"] == pytest.approx(penetration, rel=1e-6)
    assert found["B.ey"] == pytest.approx(-(clearance + penetration), rel=1e-9)
    assert found["B.ex"] == pytest.approx(0.0, abs=1e-12)
    assert found["B.fn"] == pytest.approx(mass * 9.81, rel=1e-9)


def test_the_core_refuses_a_start_state_of_the_wrong_length():
    from jointplay.model import _options, _run

    options = _options(0.0, 1e-3, "dopri5", 1e-6, 1e-9, None, None, None, None, None, "projection")
    options["max_output_bytes"] = 1 << 20
    raw = _run(hanging_mass().compile(), 0.0, 1e-3, options, None, initial_state=np.zeros(2))
    assert "an initial state of 2 values, the model has 6" in raw["error"]["message"]


def test_a_cylinder_fed_by_a_flow_is_closed_and_the_user_is_told():
    spec = pendulum_with_cylinder().to_spec()
    from jointplay.functions import as_function

    spec["forces"][0]["cap_inflow"] = as_function(1e-6)
    with pytest.warns(jp.JointplayWarning, match="forces.lift: the static equilibrium closes the cylinder's chambers; "
                                                 "its inflows are not applied"):
        found = jp.Model.from_spec(spec).equilibrium()
    # the same rest as with the chambers closed by the description
    assert found["bar.angle"] == pytest.approx(pendulum_angle(), abs=1e-9)
