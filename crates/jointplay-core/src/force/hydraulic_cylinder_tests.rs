//! The cylinder element in the engine, against closed forms: the closed-chamber
//! natural frequency of a mass on a cylinder, the energy balance with friction
//! off, the static pressures under a load (force balance and the constant-beta
//! pressure-volume law), stick below the static friction and slip above it.

use crate::dynamics::{assemble, compile, simulate, Model, SimulationOptions, Workspace};
use crate::integrate::IntegratorOptions;
use crate::spec::ModelSpec;
use crate::SimulationError;

/// Piston and annulus areas [m^2], stroke [m], dead volumes [m^3], initial stroke [m].
const A1: f64 = 2e-3;
const A2: f64 = 1e-3;
const STROKE: f64 = 0.2;
const DEAD: f64 = 1e-4;
const S0: f64 = 0.1;
/// Distance of the attachments at stroke 0 [m].
const L0: f64 = 0.5;

/// A mass on a horizontal slider driven by a cylinder from the ground, with
/// an optional point load [N] on it, a viscous damper [N s/m] to ground and a seal.
struct Rig {
    mass: f64,
    velocity: f64,
    bulk_modulus: f64,
    dead_volume: f64,
    pressures: (f64, f64),
    load: f64,
    load_rate: f64,
    damping: f64,
    seal: &'static str,
}

impl Rig {
    fn model(&self) -> Model {
        compile(&self.spec()).unwrap_or_else(|e| panic!("{e}"))
    }

    fn spec(&self) -> ModelSpec {
        let json = format!(
            r#"{{
            "name": "mass on a cylinder", "gravity": [0, 0],
            "ground_points": [{{"name": "O", "position": [0, 0]}}],
            "bodies": [{{"name": "mass", "mass": {m}, "inertia": 1.0, "position": [{x0}, 0], "angle": 0,
                         "velocity": [{v0}, 0], "angular_velocity": 0, "points": [{{"name": "P", "position": [0, 0]}}]}}],
            "joints": [{{"type": "translational", "name": "slide", "first": "ground.O", "second": "mass.P", "axis": [1, 0]}}],
            "drivers": [],
            "beams": [], "sensors": [], "forces": [
              {{"type": "hydraulic_cylinder", "name": "cyl", "first": "ground.O", "second": "mass.P",
                "piston_area": {A1}, "rod_side_area": {A2}, "stroke_length": {STROKE},
                "cap_dead_volume": {dead}, "rod_dead_volume": {dead}, "initial_stroke": {S0},
                "cap_pressure": {p1}, "rod_pressure": {p2}, "bulk_modulus": {beta},
                "seal_friction": {seal}, "cap_inflow": null, "rod_inflow": null}},
              {{"type": "point_force", "name": "load", "point": "mass.P",
                "fx": {{"kind": "constant_rate", "initial": {load}, "rate": {load_rate}}}, "fy": {{"kind": "constant", "value": 0}}}},
              {{"type": "spring_damper", "name": "damper", "first": "ground.O", "second": "mass.P",
                "stiffness": 0, "damping": {c}, "free_length": 0}}
            ]}}"#,
            m = self.mass,
            x0 = L0 + S0,
            v0 = self.velocity,
            dead = self.dead_volume,
            p1 = self.pressures.0,
            p2 = self.pressures.1,
            beta = self.bulk_modulus,
            seal = self.seal,
            load = self.load,
            load_rate = self.load_rate,
            c = self.damping,
        );
        serde_json::from_str(&json).expect("valid spec")
    }

    fn run(&self, t_end: f64, output_step: f64) -> crate::dynamics::Trajectory {
        let model = self.model();
        let mut ws = Workspace::new(&model);
        let mut state = assemble(&model, 0.0, &mut ws).unwrap();
        let integrator = IntegratorOptions { rtol: 1e-9, atol: 1e-12, output_step: Some(output_step), ..Default::default() };
        let outcome = simulate(&model, &mut state, t_end, &SimulationOptions { integrator, ..Default::default() }, None);
        assert!(outcome.error.is_none(), "{:?}", outcome.error);
        outcome.trajectory
    }
}

/// Paper 002's seal (static 385 N, kinetic 340 N) with the chosen LuGre constants of the theory page.
const SEAL: &str = r#"{"static_force": 385, "kinetic_force": 340, "stribeck_velocity": 3e-5, "bristle_stiffness": 1e7,
    "bristle_damping": 1e4, "viscous_coefficient": 0, "damping_velocity": 1e-3, "stick_velocity": 1e-5}"#;

fn rig() -> Rig {
    // balanced pressures: p_cap A1 = p_rod A2
    Rig { mass: 100.0, velocity: 0.0, bulk_modulus: 1.5e9, dead_volume: DEAD, pressures: (1e6, 2e6), load: 0.0, load_rate: 0.0, damping: 0.0, seal: "null" }
}

/// Times at which `values` crosses zero upwards (linear interpolation).
fn upward_crossings(time: &[f64], values: &[f64]) -> Vec<f64> {
    (1..values.len()).filter(|&k| values[k - 1] < 0.0 && values[k] >= 0.0).map(|k| time[k - 1] + (time[k] - time[k - 1]) * values[k - 1] / (values[k - 1] - values[k])).collect()
}

#[test]
fn a_mass_on_closed_chambers_oscillates_at_the_hydraulic_natural_frequency() {
    let rig = Rig { velocity: 0.01, ..rig() };
    let (v1, v2) = (DEAD + A1 * S0, DEAD + A2 * (STROKE - S0));
    let omega = (rig.bulk_modulus * (A1 * A1 / v1 + A2 * A2 / v2) / rig.mass).sqrt();
    let period = 2.0 * std::f64::consts::PI / omega;
    let trajectory = rig.run(10.0 * period, period / 200.0);
    let rate = trajectory.channel("cyl.rate").unwrap();
    let crossings = upward_crossings(&trajectory.time, &rate);
    assert!(crossings.len() >= 9, "{} crossings", crossings.len());
    let measured = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    // amplitude v0/omega = 19 um: the nonlinearity of the volumes is below 1e-4 of the period
    assert!((measured / period - 1.0).abs() < 2e-4, "period {measured:e} s vs {period:e} s");
    // the stroke channel is the slider displacement from the retracted length
    let (stroke, x) = (trajectory.channel("cyl.stroke").unwrap(), trajectory.channel("mass.x").unwrap());
    for (s, x) in stroke.iter().zip(&x) {
        assert!((s - (x - L0)).abs() < 1e-12);
    }
}

#[test]
fn without_friction_kinetic_plus_stored_liquid_energy_is_conserved() {
    let rig = Rig { velocity: 0.1, pressures: (1e7, 2e7), ..rig() };
    let trajectory = rig.run(0.05, 1e-4);
    let (energy, kinetic) = (trajectory.channel("system.energy").unwrap(), trajectory.channel("system.kinetic_energy").unwrap());
    let swing = kinetic.iter().cloned().fold(0.0, f64::max);
    assert!(swing > 0.4, "the kinetic energy swings ({swing} J)");
    for e in &energy {
        assert!((e - energy[0]).abs() < 1e-6 * swing, "energy drift {:e} J of {swing} J", e - energy[0]);
    }
}

#[test]
fn under_a_load_the_chambers_settle_at_the_force_balance_and_the_pressure_volume_law() {
    // a 2 kN push compresses the cap chamber; a damper settles the motion
    let rig = Rig { load: -2000.0, damping: 2e4, ..rig() };
    let trajectory = rig.run(0.5, 1e-3);
    let last = |name: &str| *trajectory.channel(name).unwrap().last().unwrap();
    let (p1, p2, s, rate) = (last("cyl.p_cap"), last("cyl.p_rod"), last("cyl.stroke"), last("cyl.rate"));
    assert!(rate.abs() < 1e-9, "settled: rate {rate:e}");
    assert!((p1 * A1 - p2 * A2 - 2000.0).abs() < 1e-6 * 2000.0, "force balance {} N", p1 * A1 - p2 * A2);
    // closed chambers with constant beta: p - p0 = -beta ln(V / V0)
    let (beta, (p10, p20)) = (rig.bulk_modulus, rig.pressures);
    let cap = p10 - beta * ((DEAD + A1 * s) / (DEAD + A1 * S0)).ln();
    let rod = p20 - beta * ((DEAD + A2 * (STROKE - s)) / (DEAD + A2 * (STROKE - S0))).ln();
    assert!((p1 - cap).abs() < 1e-6 * p1 && (p2 - rod).abs() < 1e-6 * p2, "p_cap {p1:e} vs {cap:e}, p_rod {p2:e} vs {rod:e}");
    assert!(s < S0, "the push retracts the rod");
}

/// The seal rig: a 10 kg mass on unpressurised chambers of a soft (gas-like,
/// beta = 1e5 Pa) liquid in large dead volumes, so that the chambers resist the
/// motion by under 1 N, pushed by a load rising at 5 N/s, with a 20 kN s/m
/// damper that holds the sliding speed to mm/s. The LuGre law creeps under a
/// load: the presliding rate is (dF/dt / sigma0) / (1 - F / F_S), and the seal
/// breaks away where it reaches about v_S, at 1 - F / F_S = (5 N/s / 1e7 N/m) /
/// 0.03 mm/s = 1.7 %: a slow ramp is what finds the static force.
fn seal_rig() -> Rig {
    Rig { mass: 10.0, bulk_modulus: 1e5, dead_volume: 1e-2, pressures: (0.0, 0.0), load_rate: 5.0, damping: 2e4, seal: SEAL, ..rig() }
}

#[test]
fn the_seal_sticks_below_the_static_friction_and_slips_above_it() {
    let trajectory = seal_rig().run(90.0, 0.1);
    let channel = |name: &str| trajectory.channel(name).unwrap();
    let (load, stroke, rate, stick, friction) = (channel("load.fx"), channel("cyl.stroke"), channel("cyl.rate"), channel("cyl.stick"), channel("cyl.friction"));
    let (static_force, kinetic_force, bristle_stiffness) = (385.0, 340.0, 1e7);
    for k in 0..load.len() {
        if load[k] < 0.9 * static_force {
            assert!((friction[k] - load[k]).abs() < 1e-2 * static_force, "friction {} N holds the load {} N", friction[k], load[k]);
        }
        if load[k] < 0.8 * static_force {
            // presliding: loaded slowly (v << v_S, so g(v) = F_S) from z = 0, the
            // bristles follow dz/dx = 1 - sigma0 z / F_S: x = -(F_S / sigma0) ln(1 - F / F_S)
            // (the bristle damping lags the motion by sigma1 / sigma0 = 1 ms: 5 nm)
            let presliding = -(static_force / bristle_stiffness) * (1.0 - load[k] / static_force).ln();
            assert!((stroke[k] - S0 - presliding).abs() <= 0.02 * presliding + 1e-8, "presliding {:e} m at {} N, expected {presliding:e}", stroke[k] - S0, load[k]);
        }
        if load[k] < 0.9 * static_force {
            // the presliding rate (5 N/s / sigma0) / (1 - F / F_S) is below the stick velocity
            assert_eq!(stick[k], 1.0, "stick at {} N", load[k]);
        }
        if load[k] > 1.1 * static_force {
            assert_eq!(stick[k], 0.0, "slip at {} N", load[k]);
        }
    }
    // breakaway (the rate first exceeds ten stick velocities): the creep runs away once
    // the load exceeds the Stribeck curve g(v) at the creep rate, so between
    // g(v_S) = F_C + (F_S - F_C) / e and F_S
    let breakaway = (0..load.len()).find(|&k| rate[k] > 1e-4).map(|k| load[k]).expect("breaks away");
    let lowest = kinetic_force + (static_force - kinetic_force) / std::f64::consts::E;
    assert!(breakaway > lowest && breakaway <= static_force, "breakaway at {breakaway} N, not in [{lowest}, {static_force}] N");
    // sliding at mm/s, far above v_S: the friction is F_C, the acceleration from the force balance
    let last = load.len() - 1;
    assert!(rate[last] > 1e-3, "slides at {} m/s", rate[last]);
    assert!((friction[last] - kinetic_force).abs() < 1.0, "kinetic friction {} N", friction[last]);
    let a = *channel("mass.ax").last().unwrap();
    let chambers = channel("cyl.p_cap")[last] * A1 - channel("cyl.p_rod")[last] * A2;
    let damper = channel("damper.force")[last];
    let expected = (load[last] + chambers - friction[last] - damper) / 10.0;
    assert!((a - expected).abs() < 1e-6 * (1.0 + expected.abs()), "a = {a} m/s^2, expected {expected}");
}

#[test]
fn a_stroke_beyond_the_end_stops_the_run_naming_the_cylinder() {
    // closed chambers cannot push 0.1 m: let the cap chamber fill with a large inflow instead
    let mut spec = rig().spec();
    if let crate::spec::ForceSpec::HydraulicCylinder(c) = &mut spec.forces[0] {
        c.cap_inflow = Some(crate::spec::FunctionSpec::Constant { value: 1e-3 });
    }
    let model = compile(&spec).unwrap();
    let mut ws = Workspace::new(&model);
    let mut state = assemble(&model, 0.0, &mut ws).unwrap();
    let outcome = simulate(&model, &mut state, 1.0, &SimulationOptions::default(), None);
    match outcome.error {
        Some(SimulationError::ElementOutOfRange { element, cause, time }) => {
            assert_eq!(element, "cyl");
            assert!(cause.contains("stroke"), "{cause}");
            assert!(time > 0.0 && time < 1.0);
        }
        other => panic!("expected ElementOutOfRange, got {other:?}"),
    }
    assert!(!outcome.trajectory.time.is_empty(), "what was computed is kept");
}
