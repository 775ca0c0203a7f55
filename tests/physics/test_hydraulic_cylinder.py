"""The engine's hydraulic cylinder element from Python, against things outside the engine.

- A mass on a horizontal slider pushed by a cylinder with the LuGre seal, fed by a cap inflow ramp
  (and the matching rod outflow), against the independent SciPy model reference_hydraulic.py:
  stroke, chamber pressures and seal friction over time, for the example cylinder of
  docs/theory/hydraulic-cylinder.md (stiff oil: the piston follows the flow) and for the same
  cylinder behind 1 m^3 accumulators (soft oil: the seal sticks while the pressure builds, breaks
  away and slides).
- An upright cylinder holding a mass under gravity with closed chambers settles where
  p_cap A1 - p_rod A2 = m g, each pressure on its closed-chamber law p0 - beta ln(V/V0).
- Bad cylinder input in a model file gives one located message per problem; a stroke past the end of
  the cylinder stops the run with a SimulationError naming it and keeps what was computed.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

import jointplay as jp
from jointplay import functions as fn
from jointplay import laws
from reference_hydraulic import (
    CylinderParameters,
    balanced_rod_pressure,
    closed_chamber_pressure,
    closed_chamber_stiffness,
    simulate,
    volumes,
)
from test_model_files import problems  # a model file's ModelError messages, one per problem

BOOM = Path(__file__).resolve().parents[2] / "examples" / "hydraulic_boom.toml"
P = CylinderParameters()  # bore 80 mm, rod 45 mm, stroke 0.5 m, 0.1 L dead volumes, 1 GPa, 20 kg, paper 002 seal
S0 = 0.25  # initial stroke [m]
L0 = 0.6  # distance of the attachments at stroke 0 [m]


def cylinder_model(p: CylinderParameters, *, gravity=(0.0, 0.0), axis=(1.0, 0.0), seal: bool = True,
                   pressures=(0.0, 0.0), inflows=(None, None), damping: float = 0.0) -> jp.Model:
    """A mass ``p.mass`` on a slider along ``axis`` through the ground point O, pushed by the cylinder
    ``p`` from O (stroke S0 at the start); a damper to ground when ``damping`` [N s/m] > 0."""
    position = (axis[0] * (L0 + S0), axis[1] * (L0 + S0))
    m = jp.Model("mass on a cylinder", gravity=gravity)
    m.add_ground_point("O", (0.0, 0.0))
    m.add_body("mass", mass=p.mass, inertia=1.0, position=position, points={"P": (0.0, 0.0)})
    m.add_translational("slide", "ground.O", "mass.P", axis=axis)
    m.add_hydraulic_cylinder(
        "cyl", "ground.O", "mass.P", piston_area=p.piston_area, rod_side_area=p.rod_side_area,
        stroke_length=p.stroke_length, cap_dead_volume=p.cap_dead_volume, rod_dead_volume=p.rod_dead_volume,
        initial_stroke=S0, cap_pressure=pressures[0], rod_pressure=pressures[1], bulk_modulus=p.bulk_modulus,
        seal_friction=laws.lugre_seal(p.static_force, p.kinetic_force, p.stribeck_velocity, p.bristle_stiffness,
                                      p.bristle_damping, p.viscous_coefficient, p.damping_velocity) if seal else None,
        cap_inflow=inflows[0], rod_inflow=inflows[1])
    if damping > 0:
        m.add_spring_damper("damper", "ground.O", "mass.P", damping=damping, free_length=0.0)
    return m


def cubic_step(t: float, t_start: float, t_end: float) -> float:
    """0 before ``t_start``, 1 after ``t_end``, s^2 (3 - 2 s) between: the reference's copy of the ramp."""
    s = min(max((t - t_start) / (t_end - t_start), 0.0), 1.0)
    return s * s * (3.0 - 2.0 * s)


# Two rigs, each with a cap inflow ramped smoothly from 0 to A1 U over [t_start, t_end] and the rod
# outflow A2 U that goes with it (a valve matched to the cylinder), so that the piston is commanded to U:
# - stiff: the example cylinder (0.1 L dead volumes, 3e7 N/m of oil), pressurised and balanced at 5 MPa,
#   ramped to 20 mm/s in 0.1 s: the oil pushes the piston along with the flow, the seal's bristles load
#   up to the kinetic force, the pressures swing by 0.4 bar;
# - soft: 1 m^3 behind each port (accumulators, 3.7e4 N/m of oil), unpressurised, ramped to 1 mm/s in 1 s:
#   the seal sticks (below 0.01 mm/s) for the first 7 s while the pressures build at 37 N/s, creeps
#   (LuGre presliding), breaks away at about 9.5 s and slides, ringing on the soft oil.
RIGS = {
    "stiff": dict(p=P, pressures=(5e6, balanced_rod_pressure(P, 5e6)), speed=0.02, ramp=(0.01, 0.11),
                  t_end=0.2, output_step=1e-4),
    "soft": dict(p=replace(P, cap_dead_volume=1.0, rod_dead_volume=1.0), pressures=(0.0, 0.0), speed=1e-3,
                 ramp=(0.0, 1.0), t_end=11.0, output_step=1e-3),
}

# Tolerances. Engine (Dormand-Prince, rtol 1e-10) and reference (LSODA, rtol 1e-10) integrate the same
# equations, so they differ by their integration errors: measured at most 4e-12 m, 0.014 Pa and 7e-6 N
# (stiff) and 8e-11 m, 4e-4 Pa and 3e-6 N (soft). The tolerances leave 13 to 300 times that, and still fail
# for a change of the model far smaller than anything a user would notice, measured on the reference:
# a bulk modulus 1e-4 higher moves the stiff rig's stroke by 1.1e-9 m and its pressures by 0.3 Pa, the
# soft rig's stroke by 9e-7 m; a kinetic force 0.1 N higher moves the friction by 0.1 N and the pressures
# by 12 Pa; a Stribeck velocity 1 % higher moves the soft rig's pressures by 1.4 Pa and its friction by
# 0.01 N; a bristle damping 1 % higher moves the stiff rig's friction by 0.03 N and the soft rig's stroke
# by 2e-9 m.
TOLERANCES = {"stiff": {"stroke": 1e-10, "p_cap": 0.2, "p_rod": 0.2, "friction": 1e-3},
              "soft": {"stroke": 1e-9, "p_cap": 0.01, "p_rod": 0.01, "friction": 1e-3}}


@pytest.fixture(scope="module", params=sorted(RIGS))
def rig_runs(request):
    rig = RIGS[request.param]
    p, (t_start, t_end), speed = rig["p"], rig["ramp"], rig["speed"]
    inflows = (fn.cubic_step(t_start, t_end, 0.0, p.piston_area * speed),
               fn.cubic_step(t_start, t_end, 0.0, -p.rod_side_area * speed))
    engine = cylinder_model(p, gravity=(0.0, -9.81), pressures=rig["pressures"], inflows=inflows).simulate(
        rig["t_end"], rtol=1e-10, atol=1e-12, output_step=rig["output_step"])
    reference = simulate(p, rig["t_end"], initial_stroke=S0, cap_pressure=rig["pressures"][0],
                         rod_pressure=rig["pressures"][1], t_eval=engine.time,
                         cap_inflow=lambda t: p.piston_area * speed * cubic_step(t, t_start, t_end),
                         rod_inflow=lambda t: -p.rod_side_area * speed * cubic_step(t, t_start, t_end))
    assert reference.success, reference.message
    return request.param, engine, reference


def test_mass_on_a_cylinder_fed_by_a_ramp_matches_the_scipy_reference(rig_runs):
    name, engine, reference = rig_runs
    measured = {"stroke": reference.stroke, "p_cap": reference.p_cap, "p_rod": reference.p_rod,
                "friction": reference.friction}
    for quantity, expected in measured.items():
        error = np.max(np.abs(engine[f"cyl.{quantity}"] - expected))
        assert error < TOLERANCES[name][quantity], f"{name} {quantity}: off by {error:.3g}"


def test_the_rigs_exercise_what_they_are_meant_to(rig_runs):
    # so that the comparison above means something: both slide at the commanded speed against the kinetic
    # force in the end; the soft rig sticks first (below paper 002's 0.01 mm/s) while its pressures build
    name, engine, reference = rig_runs
    last = reference.t > 0.9 * reference.t[-1]
    assert np.mean(reference.rate[last]) == pytest.approx(RIGS[name]["speed"], rel=1e-2)
    assert reference.friction[last] == pytest.approx(P.kinetic_force, rel=1e-3)
    sticking = np.abs(reference.rate) < 1e-5
    if name == "soft":
        assert 0.5 < np.mean(sticking) < 0.8
        assert np.all(engine["cyl.stick"][sticking & (np.abs(reference.rate) < 0.5e-5)] == 1.0)
        assert np.ptp(reference.p_cap) > 1e4
    else:
        assert np.ptp(reference.p_cap) > 1e4  # the oil spring and the seal's load move the pressures


def test_upright_cylinder_with_closed_chambers_settles_where_the_pressures_carry_the_weight():
    # a 500 kg mass on the cylinder standing upright; the pressures start balanced (no net force), so the
    # mass sinks until p_cap A1 - p_rod A2 = m g, each chamber on its closed-chamber law
    # p = p0 - beta ln(V/V0); a critically damped damper settles it (seal off: with friction any stroke
    # within the seal's band would be a rest position)
    mass = 500.0
    p = replace(P, mass=mass)
    p10, p20 = 5e6, balanced_rod_pressure(p, 5e6)
    damping = 2.0 * math.sqrt(closed_chamber_stiffness(p, S0) * mass)
    results = cylinder_model(p, gravity=(0.0, -9.81), axis=(0.0, 1.0), seal=False, pressures=(p10, p20),
                             damping=damping).simulate(0.2, rtol=1e-10, atol=1e-12, output_step=1e-3)
    cap0, rod0 = volumes(p, S0)

    def pressures(s):
        cap, rod = volumes(p, s)
        return (closed_chamber_pressure(p10, cap0, cap, p.bulk_modulus),
                closed_chamber_pressure(p20, rod0, rod, p.bulk_modulus))

    weight = mass * 9.81
    s_eq = brentq(lambda s: pressures(s)[0] * p.piston_area - pressures(s)[1] * p.rod_side_area - weight,
                  0.2, S0, xtol=1e-15)
    p_cap, p_rod = results["cyl.p_cap"][-1], results["cyl.p_rod"][-1]
    # the mass sinks 159 um, the pressures go to 5.59 and 6.75 MPa; after 0.2 s (50 time constants of the
    # damped oil spring) it has settled there to round-off (measured 1e-16 m, 5e-7 Pa), while a bulk modulus
    # 1e-4 off would move the rest stroke by 1.6e-8 m: 1e-12 m and 1e-3 Pa
    assert abs(results["cyl.rate"][-1]) < 1e-12
    assert S0 - results["cyl.stroke"][-1] > 1e-4
    assert results["cyl.stroke"][-1] == pytest.approx(s_eq, abs=1e-12)
    assert p_cap == pytest.approx(pressures(s_eq)[0], abs=1e-3)
    assert p_rod == pytest.approx(pressures(s_eq)[1], abs=1e-3)
    assert p_cap * p.piston_area - p_rod * p.rod_side_area == pytest.approx(weight, rel=1e-9)
    assert results["cyl.force"][-1] == pytest.approx(weight, rel=1e-9)


# bad input ---------------------------------------------------------------------

@pytest.mark.parametrize("override, message", [
    ("forces.lift.rod_side_area=31.17 cm^2",
     "forces.lift.rod_side_area: must be smaller than piston_area = 31.17 cm^2 (it is the annulus, the piston area "
     "less the rod's), got 31.17 cm^2"),
    ("forces.lift.rod_side_area=40 cm^2",
     "forces.lift.rod_side_area: must be smaller than piston_area = 31.17 cm^2 (it is the annulus, the piston area "
     "less the rod's), got 40 cm^2"),
    ("forces.lift.cap_dead_volume=-0.1 L", "forces.lift.cap_dead_volume: must be > 0, got -0.1 L"),
    ("forces.lift.piston_area=20 bar",
     "forces.lift.piston_area: must be an area (e.g. \"20 cm^2\"), got '20 bar', which is a pressure"),
    ("forces.lift.initial_stroke=600 mm",
     "forces.lift.initial_stroke: must be at most stroke_length = 500 mm (the rod cannot be beyond full "
     "extension), got 600 mm"),
    ("forces.lift.seal_friction.static_force=300 N",
     "forces.lift.seal_friction.static_force: must be at least kinetic_force = 340 N (the break-away force is not "
     "below the sliding force), got 300 N"),
    ("forces.lift.cap_pressure=-2 bar", "forces.lift.cap_pressure: must be >= -101325 Pa, got -2 bar"),
    # a bound only the core knows (the seal's dissipativity), located at its key
    ("forces.lift.seal_friction.bristle_damping=1e7 N s/m",
     "forces.lift.seal_friction.bristle_damping: bristle damping must be <= 4 sqrt(2e) F_C / v_D = 3.171036e6 N s/m "
     "for the law to dissipate energy, got 10000000 N s/m"),
    ("forces.lift.cap_inflow.values.3=1 L",
     "forces.lift.cap_inflow.values[3]: must be a volume flow (e.g. \"10 L/min\"), got '1 L', which is a volume"),
])
def test_bad_cylinder_input_gives_one_located_message(override, message):
    assert problems([override], BOOM) == [message]


def test_a_missing_bulk_modulus_says_what_is_expected(tmp_path):
    path = tmp_path / "boom.toml"
    path.write_text(BOOM.read_text().replace('bulk_modulus = "1.5 GPa"\n', ""))
    assert problems([], path) == ['forces.lift.bulk_modulus: missing required value (a bulk modulus, e.g. "1.5 GPa")']


@pytest.mark.parametrize("seal", ["none", '{ law = "none" }'])
def test_seal_friction_none_means_frictionless_seals_as_when_left_out(seal):
    assert jp.load(BOOM, [f"forces.lift.seal_friction={seal}"]).to_spec()["forces"][0]["seal_friction"] is None


def test_the_same_bad_input_in_python_gives_the_same_message():
    m = jp.load(BOOM).to_spec()["forces"][0]
    keys = {k: v for k, v in m.items() if k not in ("type", "name", "first", "second")}
    with pytest.raises(jp.ModelError) as info:
        jp.Model().add_hydraulic_cylinder("lift", "ground.C", "boom.R", **{**keys, "cap_dead_volume": "-0.1 L",
                                                                            "piston_area": "20 bar"})
    assert [str(problem) for problem in info.value.problems] == [
        "forces.lift.piston_area: must be an area (e.g. \"20 cm^2\"), got '20 bar', which is a pressure",
        "forces.lift.cap_dead_volume: must be > 0, got -0.1 L"]


def test_a_stroke_past_the_end_stops_the_run_naming_the_cylinder_and_keeps_the_results():
    # the boom's valve commands 81 mm from 100 mm: a 150 mm cylinder runs out at about 2.26 s
    model = jp.load(BOOM, ["forces.lift.stroke_length=150 mm"])
    options = dict(model.simulation)
    with pytest.raises(jp.SimulationError) as info:
        model.simulate(options.pop("t_end"), **options)
    error = info.value
    assert (error.kind, error.element) == ("ElementOutOfRange", "lift")
    assert "lift left the range of its law" in str(error) and "stroke" in error.cause
    assert 2.0 < error.time < 2.5
    kept = error.results
    assert kept is not None and kept.error is not None
    assert kept.time[-1] <= error.time and kept.time[-1] > error.time - 2e-3  # samples every ms up to the stop
    assert np.all(kept["lift.stroke"] <= 0.15) and kept["lift.stroke"][-1] > 0.149
