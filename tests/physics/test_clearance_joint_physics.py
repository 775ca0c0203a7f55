"""Physics of the dry clearance joint through the whole engine:

- energy is conserved with an elastic (Hertz), frictionless joint;
- a single journal-in-bore impact rebounds as an independent one-degree-of-freedom
  integration of the same force law says, and as the restitution coefficient
  the law was built to reproduce says (within the law's known accuracy);
- as the clearance shrinks, the clearance slider-crank approaches the ideal one.
"""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import flores_slider_crank_dry as flores
import jointplay as jp
from jointplay import laws

E, NU = 207e9, 0.3
BEARING_RADIUS, CLEARANCE = 0.010, 0.5e-3


def hertz_cylinder_stiffness():
    """K = (4/3) E* sqrt(R*) for two steel bodies (written here independently of the core)."""
    e_star = 1.0 / (2.0 * (1.0 - NU**2) / E)
    rj = BEARING_RADIUS - CLEARANCE
    r_star = BEARING_RADIUS * rj / (BEARING_RADIUS - rj)
    return 4.0 / 3.0 * e_star * math.sqrt(r_star)


def test_energy_is_conserved_with_an_elastic_frictionless_clearance_joint():
    # the Flores mechanism with the motor removed, no gravity, Hertz contact, no friction:
    # the crank spins freely and the journal bounces in the bore
    model = flores.build_model()
    spec = model.to_spec()
    spec["drivers"] = []
    spec["gravity"] = [0.0, 0.0]
    joint = next(j for j in spec["joints"] if j["name"] == "B")
    joint["contact"], joint["friction"] = laws.hertz(), laws.frictionless()
    spec["bodies"][0]["angular_velocity"] = 300.0  # crank, rad/s; assembly makes the rest consistent
    free = jp.Model.from_spec(spec)
    results = free.simulate(0.03, rtol=1e-10, atol=1e-13, max_step=1e-4)
    energy = results["system.energy"]
    assert results.summary()["clearance_joints"]["B"]["impacts"] >= 5
    assert np.max(results["B.penetration"]) > 1e-6  # real impacts, not grazing
    drift = np.max(np.abs(energy - energy[0])) / energy[0]
    assert drift < 1e-6, f"relative energy drift {drift:.2e}"


def impact_model(contact: dict, speed: float, mass: float) -> jp.Model:
    """A free journal of `mass` crossing a bore fixed to the ground at `speed`, no gravity."""
    m = jp.Model("single impact")
    m.add_ground_point("C", (0.0, 0.0))
    m.add_body("journal", mass=mass, inertia=1e-4, velocity=(speed, 0.0), points={"P": (0.0, 0.0)})
    m.add_clearance_revolute("B", "ground.C", "journal.P", bearing_radius=BEARING_RADIUS, clearance=CLEARANCE,
                             contact=contact, lock_at_assembly=False)
    return m


def one_dof_rebound(damping_factor: float, speed: float, mass: float) -> float:
    """Independent rebound speed: m x'' = -K x^1.5 (1 + D x'/v_in) from contact to separation."""
    k = hertz_cylinder_stiffness()

    def rhs(_, y):
        x, v = y
        force = max(0.0, k * max(x, 0.0) ** 1.5 * (1.0 + damping_factor * v / speed))
        return [v, -force / mass]

    def separated(_, y):
        return y[0]

    separated.terminal, separated.direction = True, -1
    sol = solve_ivp(rhs, (0.0, 1e-2), [1e-15, speed], events=separated, rtol=1e-11, atol=1e-16, max_step=1e-7)
    return -sol.y_events[0][0][1]


# law, restitution, published damping factor D(e), accuracy of the law in reproducing e
# (measured for these laws on a Hertz contact; see docs/theory/contact-*.md)
CASES = [
    (laws.lankarani_nikravesh, 0.9, lambda e: 3 * (1 - e**2) / 4, 0.02),
    (laws.hunt_crossley, 0.9, lambda e: 3 * (1 - e) / 2, 0.02),
    (laws.flores, 0.8, lambda e: 8 * (1 - e) / (5 * e), 0.03),
    (laws.flores, 0.5, lambda e: 8 * (1 - e) / (5 * e), 0.07),
    (laws.gonthier, 0.7, lambda e: (1 - e**2) / e, 0.05),
    (laws.hu_guo, 0.7, lambda e: 3 * (1 - e) / (2 * e), 0.01),
]


@pytest.mark.parametrize("law, restitution, factor, accuracy", CASES, ids=lambda v: getattr(v, "__name__", str(v)))
def test_single_impact_rebound_matches_independent_model_and_restitution(law, restitution, factor, accuracy):
    speed, mass = 0.5, 0.5
    results = impact_model(law(restitution), speed, mass).simulate(2.5e-3, rtol=1e-10, atol=1e-14, max_step=1e-5)
    contact = results["B.contact"]
    assert results.summary()["clearance_joints"]["B"]["impacts"] == 1
    after = results.time > results.time[np.nonzero(contact)[0][-1]]
    rebound = -results["journal.vx"][after][0]
    expected = one_dof_rebound(factor(restitution), speed, mass)
    assert rebound / speed == pytest.approx(expected / speed, abs=2e-4)
    assert rebound / speed == pytest.approx(restitution, rel=accuracy)


def test_clearance_slider_crank_approaches_the_ideal_one_as_the_clearance_shrinks():
    period = flores.revolutions_to_time(1.0)
    options = dict(rtol=1e-8, atol=1e-11, output_step=period / 2000, max_step=1e-4)
    ideal = flores.build_model().idealized().simulate(period, **options)
    velocity_error, force_error = [], []
    for clearance in (0.5e-3, 0.2e-3, 0.05e-3, 0.01e-3):
        results = flores.build_model(clearance=clearance).simulate(period, **options)
        deviation = np.max(np.abs(results["slider.x"] - ideal["slider.x"]))
        assert deviation < 2.5 * clearance  # the slider is off by about the clearance plus penetration
        velocity_error.append(np.sqrt(np.mean((results["slider.vx"] - ideal["slider.vx"]) ** 2)))
        force_error.append(np.sqrt(np.mean((results["B.f"] - ideal["B.f"]) ** 2)))
    assert all(a > b for a, b in zip(velocity_error, velocity_error[1:])), velocity_error
    assert all(a > b for a, b in zip(force_error, force_error[1:])), force_error
    ideal_speed = np.sqrt(np.mean(ideal["slider.vx"] ** 2))
    assert velocity_error[-1] < 0.01 * ideal_speed
