"""The engine against an independent implementation of one flexible mechanism: a slider-crank whose
connecting rod is a geometrically exact beam (tests/physics/reference_flexible_slider_crank.py, written
from docs/theory/beam.md and Simo and Vu-Quoc (1986), not from the engine's code).

Mechanism (chosen values, see the reference's docstring): crank 50 mm driven from rest through a speed
ramp to 150 rad/s in 40 ms, then at constant speed; steel rod 300 mm long, 10 mm x 8 mm section, undamped,
4 quadratic elements (and, as a second case, 2 linear ones); slider 0.5 kg; no gravity; 90 ms, that is the
ramp and 1.2 revolutions at full speed. The crank's mass and inertia and the slider's inertia (chosen 0.3 kg,
1e-4 kg m^2, 1e-4 kg m^2) do not enter: the crank's motion is prescribed and the slider cannot turn.

Both sides integrate the same discrete model (same shape functions, reduced rule, consistent mass), the
engine in absolute coordinates with joints and multipliers (NDF of order up to 2, Baumgarte terms), the
reference with the joints eliminated by hand (Radau, rtol 1e-9). Their differences are then integration
error, and the tolerances come from it (all measured, largest of the two cases; "of the peak" is of the
reference's peak over the run):

- the reference at rtol 1e-9 differs from itself at rtol 1e-10 by 1.4e-11 m in position, 6e-9 of the peak
  in deflection, 9e-7 in axial force and 2.2e-6 in the slider's acceleration;
- the engine at rtol 1e-9, atol 1e-9 differs from the reference by 8e-8 m in the nodes' and the slider's
  positions, 2.8e-7 rad in the section angles, 9e-7 of the peak in the slider's velocity, 2e-5 in its
  acceleration and in the axial force, 7e-6 in the mid-span deflection and 8e-6 in the bending moment,
  1.1e-5 in the surface fibre's strain; :data:`TOLERANCES` are three to four times these;
- at the engine's default tolerances (rtol 1e-6, atol 1e-9) the differences are 38 to 97 times larger:
  they fall with the engine's tolerance, as integration error does and a difference of model would not.

What the tolerances can see (measured on the quadratic case by changing the reference): a lumped
(row-sum) mass changes the deflection and the bending moment by 1.2e-4 of their peaks, half the rotary
inertia by 4e-5, E by 0.1 % the deflection by 1.1e-3, the slider's mass by 1 % the axial force by 8e-3; a
2 % smaller shear stiffness (k = 5/6 instead of Cowper's 0.85) changes the deflection by 4e-5 only (the rod
is slender), so the section's stiffnesses are also compared directly. The slider's acceleration hardly
depends on the rod's flexibility (a rigid rod changes it by 4e-4 of its peak): the deflection, the moment
and the axial force carry the check.
"""

from __future__ import annotations

import time

import numpy as np
import pytest

import jointplay as jp
import reference_flexible_slider_crank as ref
from jointplay import functions as fn
from jointplay import sections

T_END = 0.09  # s: the 40 ms ramp (3 rad) and 7.5 rad at 150 rad/s
OUTPUT_STEP = 5e-4  # s
GAUGE = 0.1  # m: at xi = -1/3 of the second quadratic element (75 mm), inside the first linear one (150 mm)
TIGHT = {"rtol": 1e-9, "atol": 1e-9}  # the engine's run that is compared
DEFAULT = {"rtol": 1e-6, "atol": 1e-9}  # the engine's default tolerances: the convergence check
CASES = {"quadratic": ref.Parameters(order=2, elements=4), "linear": ref.Parameters(order=1, elements=2)}

# largest differences allowed at TIGHT: positions [m] and angles [rad] absolute, the rest as a fraction of
# the reference's peak; about three times the largest difference measured in either case
TOLERANCES = {"position": 3e-7, "angle": 1e-6, "slider_v": 3e-6, "slider_a": 6e-5, "deflection": 2.5e-5,
              "axial_force": 6e-5, "bending_moment": 2.5e-5, "fibre_strain": 3.5e-5}


def build_model(p: ref.Parameters) -> jp.Model:
    """The mechanism in the engine: a driven rigid crank, the rod as a beam, a guided slider."""
    a, length = p.crank_length, p.rod_length
    m = jp.Model("flexible_slider_crank", gravity=(0.0, 0.0))
    m.add_ground_point("O", (0.0, 0.0))
    m.add_ground_point("line", (0.0, 0.0))
    m.add_body("crank", mass=0.3, inertia=1e-4, position=(a / 2, 0.0), points={"O": (-a / 2, 0.0), "A": (a / 2, 0.0)})
    m.add_beam("rod", (a, 0.0), (a + length, 0.0), section=sections.rectangle(p.width, p.depth),
               material=sections.material(p.youngs_modulus, p.density, poisson_ratio=p.poisson_ratio),
               order={1: "linear", 2: "quadratic"}[p.order], elements=p.elements, points={"G": GAUGE})
    m.add_body("slider", mass=p.slider_mass, inertia=1e-4, position=(a + length, 0.0), points={"B": (0.0, 0.0)})
    m.add_revolute("O", "ground.O", "crank.O")
    m.add_revolute("A", "crank.A", "rod.start")
    m.add_revolute("B", "rod.end", "slider.B")
    m.add_translational("guide", "ground.line", "slider.B", axis=(1.0, 0.0))
    m.add_driver("motor", "O", fn.speed_ramp(p.crank_speed, p.ramp_time))
    m.add_strain_gauge("gauge", "rod.G", fibre=p.depth / 2)  # the surface fibre on the left of A -> B
    return m


def run(model: jp.Model, tolerances: dict) -> jp.Results:
    return model.simulate(T_END, method="bdf", max_order=2, stabilization="baumgarte", output_step=OUTPUT_STEP,
                          **tolerances)


@pytest.fixture(scope="module", params=list(CASES))
def case(request):
    p = CASES[request.param]
    started = time.perf_counter()
    reference = ref.simulate(p, t_end=T_END, output_step=OUTPUT_STEP, gauge=GAUGE)
    reference_time = time.perf_counter() - started
    model = build_model(p)
    return {"name": request.param, "p": p, "model": model, "reference": reference, "reference_time": reference_time,
            "tight": run(model, TIGHT), "default": run(model, DEFAULT)}


def nodes(results: jp.Results, p: ref.Parameters) -> np.ndarray:
    """The engine's nodal coordinates, samples x (x, y, theta of node 0, node 1, ...)."""
    return np.column_stack([results[f"rod.node{k}_{c}"] for k in range(p.nodes) for c in ("x", "y", "angle")])


def midspan(q: np.ndarray, p: ref.Parameters) -> np.ndarray:
    last, mid = p.nodes - 1, (p.nodes - 1) // 2
    return ref.midspan_deflection(q[:, 0], q[:, 1], q[:, 3 * mid], q[:, 3 * mid + 1], q[:, 3 * last],
                                  q[:, 3 * last + 1])


def differences(results: jp.Results, reference: ref.Reference, p: ref.Parameters) -> dict[str, float]:
    """Largest differences engine - reference, in the units of :data:`TOLERANCES`."""
    assert np.allclose(results.time, reference.time, rtol=0.0, atol=1e-12)

    def relative(engine, expected):
        return float(np.max(np.abs(engine - expected)) / np.max(np.abs(expected)))

    q = nodes(results, p)
    translations = np.ones(3 * p.nodes, dtype=bool)
    translations[2::3] = False
    fibre = reference.N / p.EA - (p.depth / 2) * reference.M / p.EI  # Gamma_1 - y kappa
    return {
        "position": float(max(np.max(np.abs(q[:, translations] - reference.q[:, translations])),
                              np.max(np.abs(results["slider.x"] - reference.slider_x)))),
        "angle": float(np.max(np.abs(q[:, ~translations] - reference.q[:, ~translations]))),
        "slider_v": relative(results["slider.vx"], reference.slider_v),
        "slider_a": relative(results["slider.ax"], reference.slider_a),
        "deflection": relative(midspan(q, p), reference.midspan_deflection()),
        "axial_force": relative(results["gauge.axial_force"], reference.N),
        "bending_moment": relative(results["gauge.bending_moment"], reference.M),
        "fibre_strain": relative(results["gauge.axial_strain"], fibre),
    }


def test_the_engine_builds_the_reference_section_and_constraints(case):
    p, info = case["p"], case["model"].check()
    rod = next(b for b in info["bodies"] if b["name"] == "rod")
    assert rod["mass"] == pytest.approx(p.rhoA * p.rod_length, rel=1e-12)
    assert rod["axial_stiffness"] == pytest.approx(p.EA, rel=1e-12)
    assert rod["shear_stiffness"] == pytest.approx(p.kGA, rel=1e-12)  # Cowper's factor of a rectangle
    assert rod["bending_stiffness"] == pytest.approx(p.EI, rel=1e-12)
    assert (rod["nodes"], rod["order"]) == (p.nodes, {1: "linear", 2: "quadratic"}[p.order])
    # the reference's free coordinates are the mechanism's degrees of freedom: all nodal ones but x_0, y_0, y_n
    assert info["degrees_of_freedom"] == 3 * p.nodes - 3


def test_the_engine_matches_the_independent_implementation(case):
    found = differences(case["tight"], case["reference"], case["p"])
    print(f"\n{case['name']}: reference {case['reference_time']:.2f} s ({case['reference'].nfev} right-hand sides), "
          f"engine {case['tight'].wall_time:.2f} s; differences "
          + ", ".join(f"{k} {v:.2e}" for k, v in found.items()))
    assert all(found[k] <= TOLERANCES[k] for k in TOLERANCES), found


def test_the_differences_are_integration_error(case):
    # at the engine's default tolerances the same differences are larger by a factor of 38 to 97 (measured):
    # they shrink as the engine's tolerance does; a difference of model would stay
    tight = differences(case["tight"], case["reference"], case["p"])
    default = differences(case["default"], case["reference"], case["p"])
    ratios = {k: default[k] / tight[k] for k in tight}
    assert all(r > 10.0 for r in ratios.values()), ratios


def test_the_rod_bends_enough_for_the_comparison_to_see_it(case):
    p, reference = case["p"], case["reference"]
    deflection = reference.midspan_deflection()
    # the mid-span moves up to 0.26 mm (2 linear elements) or 0.43 mm (4 quadratic ones) off the chord; the
    # tolerance on it is about 1e-8 m
    assert 2e-4 < np.max(np.abs(deflection)) < 1e-3
    # a rigid rod moves the slider by up to 14 um less (47 times the position tolerance); its acceleration
    # differs by 3.5e-4 to 4e-4 of the peak only (6 times the tolerance): the slider's motion is nearly
    # kinematic, the rod's axial modes (above 1.7 kHz) far above the crank's harmonics
    x, _, acceleration = ref.rigid_slider(reference.time, p)
    assert np.max(np.abs(reference.slider_x - x)) > 30 * TOLERANCES["position"]
    rigid_gap = np.max(np.abs(reference.slider_a - acceleration)) / np.max(np.abs(reference.slider_a))
    assert rigid_gap > 5 * TOLERANCES["slider_a"]
    # and the engine's rod is no closer to the rigid one than the reference's
    engine = case["tight"]
    assert np.max(np.abs(engine["slider.x"] - x)) == pytest.approx(np.max(np.abs(reference.slider_x - x)), rel=0.05)


#: Largest differences allowed with generalized-alpha at a 25 us step (rho_inf 0.9), in the units of
#: :data:`TOLERANCES`: about three times the largest measured in either case (quadratic: 1.4e-7 m, 5.8e-7 rad,
#: 1.3e-6, 9.1e-6, 2.7e-5, 8.9e-6, 3.1e-5, 3.2e-5; linear: 1.4e-7 m, 5.4e-7 rad, 1.3e-6, 8.6e-6, 2.3e-5,
#: 8.9e-6, 2.3e-5, 2.3e-5).
ALPHA_TOLERANCES = {"position": 5e-7, "angle": 2e-6, "slider_v": 5e-6, "slider_a": 3e-5, "deflection": 1e-4,
                    "axial_force": 3e-5, "bending_moment": 1e-4, "fibre_strain": 1e-4}


def test_generalized_alpha_converges_to_the_independent_implementation(case):
    # the same mechanism with generalized-alpha (fixed steps of 50 and 25 us, docs/theory/
    # integrator-generalized-alpha.md): within ALPHA_TOLERANCES at 25 us, and the differences in the
    # positions, the deflection and the moment fall about four times with the step (measured 3.97 to 4.25):
    # a second-order method's error, not a difference of model
    found = {}
    for step in (5e-5, 2.5e-5):
        results = case["model"].simulate(T_END, method="generalized_alpha", step=step, stabilization="baumgarte",
                                         output_step=OUTPUT_STEP, rtol=1e-8, atol=1e-10)
        found[step] = differences(results, case["reference"], case["p"])
    fine = found[2.5e-5]
    assert all(fine[k] <= ALPHA_TOLERANCES[k] for k in ALPHA_TOLERANCES), fine
    for key in ("position", "angle", "deflection", "bending_moment"):
        assert 3.0 < found[5e-5][key] / fine[key] < 5.5, (key, found)
