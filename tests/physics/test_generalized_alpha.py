"""Generalized-alpha (docs/theory/integrator-generalized-alpha.md) on mechanisms, against references
outside its own code.

- The spin-up beam of Simo and Vu-Quoc (1986) on 4 linear elements, at 10 ms and 5 ms steps: the stretch
  at 6 rad/s against the closed form rho A w^2 L^3 / (3 EA) of a steadily spinning bar, and the tip's
  deflection seen from the hub against the NDF at rtol 1e-7 (an error-controlled method that resolves
  every vibration: the reference of benches/bench_spin_up_beam.py). Measured: stretch 0.5143 and
  0.5141 mm (closed form 0.5143 mm); tip deflection 0.89 and 0.22 mm from the reference (peak about
  570 mm), falling 4.1 times with the step, as a second-order method's error does.
- The dry Flores slider-crank's first impact, against the independent minimal-coordinate SciPy model
  (tests/physics/reference_slider_crank.py): the contact onset is located on the method's dense output
  (measured 6.8e-7 and 1.4e-7 of the onset time at steps of 2.5 and 1.25 us) and the peak contact force
  (from the extrema tracked at every step) converges at second order (measured -2.3e-3, then -4.7e-4).

- A pendulum swinging through 180 degrees in joint coordinates and in absolute coordinates (the two
  ways the mechanism declares its positions) against Dormand-Prince at rtol 1e-12: errors fall 4.1 and
  4.0 times with the step.
- The hydraulic cylinder's "stiff" rig of test_hydraulic_cylinder.py (chamber pressures and the LuGre
  bristle deflection are element states, integrated by the rates' rule) against its independent SciPy
  model: stroke, pressures and friction within that test's tolerances at 10 us, the pressure error
  falling 3.7 times from 20 us.

The flexible slider-crank against its independent implementation, with this method, is in
tests/physics/test_independent_flexible_slider_crank.py.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import flores_slider_crank_dry as flores
import jointplay as jp
import test_hydraulic_cylinder as hydraulic
import reference_slider_crank as ref
from jointplay import functions as fn
from jointplay import sections
from test_engine_vs_reference import first_impact

# the spin-up beam (Simo and Vu-Quoc 1986, Part II, section 5.1)
LENGTH, AXIAL, SHEAR, BENDING, RHO_A, RHO_I = 10.0, 2.8e7, 1e7, 1.4e4, 1.2, 6e-4  # m, N, N, N m^2, kg/m, kg m
RATE, RAMP = 6.0, 15.0  # rad/s, s
SAMPLE = 0.02  # s


def spin_up_model() -> jp.Model:
    m = jp.Model("spin_up_beam", gravity=(0, 0))
    m.add_ground_point("O", (0, 0))
    m.add_body("hub", mass=1.0, inertia=1.0, points={"O": (0, 0)})
    m.add_beam("beam", (0, 0), (LENGTH, 0), section=sections.resultants(AXIAL, SHEAR, BENDING, RHO_A, RHO_I),
               order="linear", elements=4)
    m.add_revolute("axis", "ground.O", "hub.O")
    m.add_fixed("clamp", "hub.O", "beam.start")
    m.add_driver("spin", "axis", fn.speed_ramp(RATE, RAMP))
    return m


def tip_in_hub_frame(results: jp.Results) -> tuple[np.ndarray, np.ndarray]:
    x, y, a = results["beam.node4_x"], results["beam.node4_y"], results["hub.angle"]
    return x * np.cos(a) + y * np.sin(a), -x * np.sin(a) + y * np.cos(a)


@pytest.fixture(scope="module")
def spin_up():
    model = spin_up_model()
    common = {"stabilization": "baumgarte", "output_step": SAMPLE}
    reference = model.simulate(20.0, method="bdf", max_order=2, rtol=1e-7, atol=1e-9, **common)
    runs = {step: model.simulate(20.0, method="generalized_alpha", step=step, rtol=1e-5, atol=1e-7, **common)
            for step in (0.01, 0.005)}
    return reference, runs


def test_spin_up_beam_stretches_as_the_closed_form_says(spin_up):
    _, runs = spin_up
    closed = RHO_A * RATE ** 2 * LENGTH ** 3 / (3 * AXIAL)  # 0.514 mm
    for step, results in runs.items():
        along, _ = tip_in_hub_frame(results)
        steady = results.time >= 18.0
        # the mesh and the vibration left by the ramp (averaged over the last 2 s): within 0.2 %
        assert np.mean(along[steady] - LENGTH) == pytest.approx(closed, rel=2e-3), step
        assert results.options["method"] == "generalized_alpha" and results.options["step"] == step


def test_spin_up_beam_deflection_converges_at_second_order_to_the_error_controlled_reference(spin_up):
    reference, runs = spin_up
    _, expected = tip_in_hub_frame(reference)
    errors = {}
    for step, results in runs.items():
        assert np.allclose(results.time, reference.time, rtol=0, atol=1e-9)
        _, across = tip_in_hub_frame(results)
        errors[step] = float(np.max(np.abs(across - expected)))
    assert np.max(np.abs(expected)) > 0.5  # the deflection peaks near 570 mm
    assert errors[0.01] < 2e-3  # measured 0.89 mm
    assert 3.0 < errors[0.01] / errors[0.005] < 5.5  # measured 4.1: order two
    # a fixed step: 2000 steps, none cut by a Newton failure on this model
    assert runs[0.01].statistics["accepted_steps"] == 2000
    assert runs[0.01].statistics["jacobian_evaluations"] > 0


def test_contact_onset_is_located_and_the_impact_converges_at_second_order():
    model = flores.build_model()
    end = 2.6e-4  # s: the first impact starts at 0.227 ms
    expected = ref.first_impact(ref.simulate_reference(rtol=1e-9, atol=1e-12, max_step=1e-4, t_end=end))
    force_errors = []
    for step in (2.5e-6, 1.25e-6):
        results = model.simulate(end, method="generalized_alpha", step=step, rtol=1e-8, atol=1e-11)
        onset, _, _ = first_impact(results)
        assert onset == pytest.approx(expected["time"], rel=5e-6), step  # measured 6.8e-7, 1.4e-7
        assert results.statistics["events"] == 1
        force_errors.append(results.summary()["peaks"]["B.fn"] / expected["peak_contact_force"] - 1.0)
    assert abs(force_errors[0]) < 5e-3  # measured -2.3e-3
    assert abs(force_errors[1]) < abs(force_errors[0]) / 3.0  # measured -4.7e-4: order two


def test_generalized_alpha_options_are_checked_at_their_keys():
    model = spin_up_model()
    with pytest.raises(jp.ModelError, match=r"simulation.step: generalized_alpha integrates with a fixed nominal "
                                             r"step and needs one"):
        model.simulate(1.0, method="generalized_alpha")
    with pytest.raises(jp.ModelError, match=r"simulation.spectral_radius: must be from 0 to 1, got 1.5"):
        model.simulate(1.0, method="generalized_alpha", step=0.01, spectral_radius=1.5)
    with pytest.raises(jp.ModelError, match=r"simulation.step: must be > 0, got -0.01"):
        model.simulate(1.0, method="generalized_alpha", step=-0.01)
    with pytest.raises(jp.ModelError) as info:
        jp.loads(model.to_toml() + '\n[simulation]\nmethod = "generalised_alpha"\nstep = "-1 ms"\n'
                 "spectral_radius = 2\n")
    assert {p.location for p in info.value.problems} >= {"simulation.step", "simulation.spectral_radius"}


def test_generalized_alpha_keys_round_trip_through_a_model_file(tmp_path):
    model = spin_up_model()
    model.simulation = {"t_end": 0.05, "method": "generalized_alpha", "step": 0.01, "spectral_radius": 0.6,
                        "stabilization": "baumgarte"}
    path = tmp_path / "spin.toml"
    model.save(path)
    loaded = jp.load(path)
    assert loaded.simulation == model.simulation
    options = dict(loaded.simulation)
    results = loaded.simulate(options.pop("t_end"), **options)
    assert results.options["spectral_radius"] == 0.6
    assert results.statistics["accepted_steps"] == 5


def test_flexible_advice_accepts_generalized_alpha_and_still_warns_of_projection():
    model = spin_up_model()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model.simulate(0.02, method="generalized_alpha", step=0.01, stabilization="baumgarte")
        quiet = [str(w.message) for w in caught if issubclass(w.category, jp.JointplayWarning)]
    assert quiet == []
    with pytest.warns(jp.JointplayWarning, match="simulation.stabilization: a projection after each step"):
        model.simulate(0.02, method="generalized_alpha", step=0.01, stabilization="projection")
    with pytest.warns(jp.JointplayWarning, match='use method="generalized_alpha" with a step'):
        model.simulate(1e-4, method="dopri5", stabilization="baumgarte")


def test_peaks_come_from_the_step_ends_and_samples_are_step_ends():
    # inside a step the state is the Hermite interpolant of its ends; the beam's stiff shear-rotation
    # terms (GA / rho I = 1.7e10 1/s^2) turn its interpolation error into node accelerations of
    # 33 000 rad/s^2 where the step ends have 0.8 rad/s^2 (measured before the peaks were restricted
    # to step ends). The summary's peaks are therefore the step ends' extremes
    model = spin_up_model()
    every = model.simulate(20.0, method="generalized_alpha", step=0.01, stabilization="baumgarte")
    summary = every.summary()
    for name, peak in summary["peaks"].items():
        assert peak == pytest.approx(np.max(np.abs(every[name])), rel=1e-12, abs=1e-300), name
    assert summary["peaks"]["beam.node1_alpha"] < 1.0  # rad/s^2
    # an output step of two steps changes nothing but rounding (its step ends are the grid times
    # t0 + k 0.02 s instead of sums of 0.01 s): the samples are those step ends
    gridded = model.simulate(20.0, method="generalized_alpha", step=0.01, stabilization="baumgarte",
                             output_step=0.02)
    assert gridded.statistics["accepted_steps"] == every.statistics["accepted_steps"] == 2000
    assert np.allclose(gridded["beam.node4_x"], every["beam.node4_x"][::2], rtol=0, atol=1e-9)
    # (the nodes' angular accelerations carry the stiff shear-rotation terms, which turn those rounding
    # differences into 1e-5 of their peak: measured 9e-6)
    for name, peak in gridded.summary()["peaks"].items():
        assert peak == pytest.approx(summary["peaks"][name], rel=1e-4, abs=1e-9), name
    # one that is not a whole number of steps is warned of: the steps are cut at the output times
    with pytest.warns(jp.JointplayWarning, match="simulation.output_step: generalized_alpha records its step ends"):
        cut = model.simulate(0.3, method="generalized_alpha", step=0.01, stabilization="baumgarte",
                             output_step=0.015)
    assert cut.statistics["accepted_steps"] == 40
    # a step given to a method that sets its own is ignored, and said so
    with pytest.warns(jp.JointplayWarning, match="simulation.step: only generalized_alpha takes a fixed step"):
        model.simulate(0.01, method="bdf", max_order=2, step=0.01, stabilization="baumgarte")


@pytest.mark.parametrize("formulation", ["joint_coordinates", "absolute"])
def test_pendulum_converges_at_second_order_in_both_formulations(formulation):
    m = jp.Model("pendulum", gravity=(0, -9.81))
    m.add_ground_point("O", (0, 0))
    m.add_body("rod", mass=2.0, inertia=0.1, position=(0.3, 0.0), points={"O": (-0.3, 0.0)})
    m.add_revolute("O", "ground.O", "rod.O")  # released horizontal: it swings through 180 degrees
    stabilization = "baumgarte" if formulation == "absolute" else "projection"
    reference = m.simulate(2.0, rtol=1e-12, atol=1e-14, output_step=0.01, formulation=formulation,
                           stabilization=stabilization)
    assert np.ptp(reference["rod.angle"]) == pytest.approx(math.pi, rel=1e-4)
    errors = []
    for step in (0.01, 0.005):
        results = m.simulate(2.0, method="generalized_alpha", step=step, output_step=0.01, formulation=formulation,
                             stabilization=stabilization)
        assert results.statistics["formulation"] == formulation
        errors.append(float(np.max(np.abs(results["rod.angle"] - reference["rod.angle"]))))
    assert errors[0] < 5e-3  # rad; measured 1.5e-3 (joint coordinates), 2.3e-3 (absolute)
    assert 3.5 < errors[0] / errors[1] < 4.5  # measured 4.1, 4.0


def test_hydraulic_cylinder_states_converge_to_the_independent_model():
    rig = hydraulic.RIGS["stiff"]
    p, (t_start, t_end), speed = rig["p"], rig["ramp"], rig["speed"]
    inflows = (fn.cubic_step(t_start, t_end, 0.0, p.piston_area * speed),
               fn.cubic_step(t_start, t_end, 0.0, -p.rod_side_area * speed))
    model = hydraulic.cylinder_model(p, gravity=(0.0, -9.81), pressures=rig["pressures"], inflows=inflows)
    runs = {step: model.simulate(rig["t_end"], method="generalized_alpha", step=step, rtol=1e-10, atol=1e-12,
                                 output_step=rig["output_step"]) for step in (2e-5, 1e-5)}
    reference = hydraulic.simulate(
        p, rig["t_end"], initial_stroke=hydraulic.S0, cap_pressure=rig["pressures"][0],
        rod_pressure=rig["pressures"][1], t_eval=runs[1e-5].time,
        cap_inflow=lambda t: p.piston_area * speed * hydraulic.cubic_step(t, t_start, t_end),
        rod_inflow=lambda t: -p.rod_side_area * speed * hydraulic.cubic_step(t, t_start, t_end))
    assert reference.success, reference.message
    errors = {step: {q: float(np.max(np.abs(r[f"cyl.{q}"] - getattr(reference, q))))
                     for q in ("stroke", "p_cap", "p_rod", "friction")} for step, r in runs.items()}
    # at 10 us within the Dormand-Prince comparison's tolerances (measured 1.5e-11 m, 0.056 Pa, 0.056 Pa,
    # 1.5e-5 N); from 20 us the errors fall 3.7 times (pressures) to 3.9 (friction): second order
    for quantity, tolerance in hydraulic.TOLERANCES["stiff"].items():
        assert errors[1e-5][quantity] < tolerance, (quantity, errors)
    for quantity in ("p_cap", "p_rod", "friction"):
        assert errors[2e-5][quantity] / errors[1e-5][quantity] > 3.0, (quantity, errors)


def test_a_damped_beam_settling_under_gravity_never_halves_its_converged_step():
    """Issue 32, item 6: a step is halved only when Newton fails. A steel cantilever (1 m, 20 x 10 mm, 8
    quadratic elements, strain-rate damping tau 10 ms) falls from straight under gravity at rtol 1e-10,
    atol 1e-12: the engine halved its 1 ms step 49 times in the first 200 steps (Hairer's prediction of
    slow convergence stopped iterations that were converging, and round-off stalled iterations that had
    converged). Now every step is taken whole, and the tip ends where the same run at half the step puts
    it (measured -5.834 mm, 0.6 um apart)."""
    m = jp.Model("damped_cantilever", gravity=(0, -9.81))
    m.add_ground_point("O", (0, 0))
    m.add_beam("beam", (0, 0), (1.0, 0), section={"shape": "rectangle", "width": 0.02, "height": 0.01},
               material=sections.material(2.1e11, 7850, 0.3), elements=8, damping_time=0.01)
    m.add_fixed("clamp", "ground.O", "beam.start")
    runs = {step: m.simulate(0.2, method="generalized_alpha", step=step, rtol=1e-10, atol=1e-12,
                             stabilization="baumgarte", output_step=0.001) for step in (0.001, 0.0005)}
    coarse = runs[0.001].statistics
    assert (coarse["accepted_steps"], coarse["rejected_steps"]) == (200, 0)
    assert runs[0.0005].statistics["rejected_steps"] == 0
    tips = [r["beam.node16_y"][-1] for r in runs.values()]
    assert tips[0] == pytest.approx(tips[1], abs=1e-5)
