//! Engine checks against closed forms: slider-crank kinematics, static
//! reactions, a pendulum's period, and the errors for locked or redundant
//! mechanisms.

use super::*;
use crate::dynamics::formulations::absolute::{constraint_solution, equations, redundancy};
use crate::dynamics::model::channels;
use crate::integrate::IntegratorOptions;
use crate::spec::ModelSpec;
use std::f64::consts::PI;

/// [`accelerations`] at positions `q` and velocities `v` (no element states).
fn accelerations_at(model: &Model, memory: &[crate::element::ElementMemory], t: f64, q: &[f64], v: &[f64], stabilization: Stabilization, ws: &mut Workspace) -> Result<(), crate::SimulationError> {
    let y: Vec<f64> = q.iter().chain(v).chain(&model.initial_element_states).copied().collect();
    accelerations(model, memory, t, &y, stabilization, ws)
}

fn model(json: &str) -> Model {
    let spec: ModelSpec = serde_json::from_str(json).expect("valid json spec");
    compile(&spec).unwrap_or_else(|e| panic!("{e}"))
}

/// Ideal slider-crank: crank a = 0.05 m, rod l = 0.12 m, driven at `omega` [rad/s].
fn slider_crank(omega: f64, gravity: f64) -> Model {
    model(&format!(
        r#"{{
        "name": "slider-crank", "gravity": [0, {gravity}],
        "ground_points": [{{"name": "O", "position": [0, 0]}}, {{"name": "line", "position": [0, 0]}}],
        "bodies": [
          {{"name": "crank", "mass": 0.3, "inertia": 1e-4, "position": [0.025, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{{"name": "O", "position": [-0.025, 0]}}, {{"name": "A", "position": [0.025, 0]}}]}},
          {{"name": "rod", "mass": 0.21, "inertia": 2.5e-4, "position": [0.11, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{{"name": "A", "position": [-0.06, 0]}}, {{"name": "B", "position": [0.06, 0]}}]}},
          {{"name": "slider", "mass": 0.14, "inertia": 1e-4, "position": [0.17, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{{"name": "B", "position": [0, 0]}}]}}
        ],
        "joints": [
          {{"type": "revolute", "name": "O", "first": "ground.O", "second": "crank.O"}},
          {{"type": "revolute", "name": "A", "first": "crank.A", "second": "rod.A"}},
          {{"type": "revolute", "name": "B", "first": "rod.B", "second": "slider.B"}},
          {{"type": "translational", "name": "guide", "first": "ground.line", "second": "slider.B", "axis": [1, 0]}}
        ],
        "drivers": [{{"name": "motor", "joint": "O", "function": {{"kind": "constant_rate", "initial": 0, "rate": {omega}}}}}],
        "beams": [], "sensors": [], "forces": []
        }}"#
    ))
}

/// Closed-form slider position, velocity and acceleration for crank angle `theta`.
fn slider_closed_form(a: f64, l: f64, omega: f64, theta: f64) -> (f64, f64, f64) {
    let (s, c) = theta.sin_cos();
    let root = (l * l - a * a * s * s).sqrt();
    let x = a * c + root;
    let v = -a * omega * s - a * a * omega * s * c / root;
    // d/dt of v with theta_dot = omega
    let h = 1e-6;
    let v_at = |th: f64| {
        let (s, c) = th.sin_cos();
        -a * omega * s - a * a * omega * s * c / (l * l - a * a * s * s).sqrt()
    };
    let acc = (v_at(theta + h) - v_at(theta - h)) / (2.0 * h) * omega;
    (x, v, acc)
}

#[test]
fn slider_crank_kinematics_match_the_closed_form() {
    let omega = 5000.0 * 2.0 * PI / 60.0;
    let m = slider_crank(omega, 0.0);
    let mut ws = Workspace::new(&m);
    let mut state = assemble(&m, 0.0, &mut ws).unwrap();
    // one crank revolution; the mechanism has no freedom, so every channel is kinematic
    let period = 2.0 * PI / omega;
    let options = SimulationOptions {
        integrator: IntegratorOptions { output_step: Some(period / 50.0), ..Default::default() },
        position_tolerance: Some(1e-12),
        ..Default::default()
    };
    let outcome = simulate(&m, &mut state, period, &options, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    let tr = &outcome.trajectory;
    let (x, v, a) = (tr.channel("slider.x").unwrap(), tr.channel("slider.vx").unwrap(), tr.channel("slider.ax").unwrap());
    assert!(tr.time.len() >= 50);
    for (k, &t) in tr.time.iter().enumerate() {
        let (xe, ve, ae) = slider_closed_form(0.05, 0.12, omega, omega * t);
        assert!((x[k] - xe).abs() < 1e-10, "t={t}: x {} vs {xe}", x[k]);
        assert!((v[k] - ve).abs() < 1e-8 * omega, "t={t}: v {} vs {ve}", v[k]);
        assert!((a[k] - ae).abs() < 1e-5 * ae.abs().max(omega * omega * 0.05), "t={t}: a {} vs {ae}", a[k]);
    }
}

#[test]
fn recorded_samples_are_rows_and_channels_their_columns() {
    let m = hanging_chain(1);
    let mut ws = Workspace::new(&m);
    let mut state = assemble(&m, 0.0, &mut ws).unwrap();
    let outcome = simulate(&m, &mut state, 0.05, &SimulationOptions::default(), None);
    let tr = &outcome.trajectory;
    let (channels, samples) = (tr.channels.len(), tr.len());
    assert!(channels > 5 && samples > 3);
    let all = tr.samples();
    assert_eq!(all.len(), channels * samples);
    for c in 0..channels {
        let column = tr.channel(&tr.channels[c].name).unwrap();
        assert_eq!(column, (0..samples).map(|k| all[k * channels + c]).collect::<Vec<_>>());
        assert_eq!(column[samples - 1], tr.value(c, samples - 1));
    }
    // the falling bar: its angle moves, so the columns are not all alike
    assert_ne!(tr.channel("bar0.angle").unwrap()[0], tr.channel("bar0.angle").unwrap()[samples - 1]);
}

#[test]
fn baumgarte_and_unstabilised_runs_follow_the_slider_crank_closed_form() {
    // without projection the constraints are held only by the acceleration equations
    // (and Baumgarte's feedback); over one revolution the drift stays far below the tolerance used
    let omega = 5000.0 * 2.0 * PI / 60.0;
    let m = slider_crank(omega, 0.0);
    let period = 2.0 * PI / omega;
    for stabilization in [Stabilization::Baumgarte { alpha: 500.0, beta: 500.0 }, Stabilization::None] {
        let mut ws = Workspace::new(&m);
        let mut state = assemble(&m, 0.0, &mut ws).unwrap();
        let options = SimulationOptions {
            integrator: IntegratorOptions { rtol: 1e-9, atol: 1e-12, output_step: Some(period / 50.0), ..Default::default() },
            stabilization,
            ..Default::default()
        };
        let outcome = simulate(&m, &mut state, period, &options, None);
        assert!(outcome.error.is_none(), "{stabilization:?}: {:?}", outcome.error);
        let tr = &outcome.trajectory;
        let (x, a) = (tr.channel("slider.x").unwrap(), tr.channel("slider.ax").unwrap());
        for (k, &t) in tr.time.iter().enumerate() {
            let (xe, _, ae) = slider_closed_form(0.05, 0.12, omega, omega * t);
            assert!((x[k] - xe).abs() < 1e-8, "{stabilization:?}, t={t}: x {} vs {xe}", x[k]);
            assert!((a[k] - ae).abs() < 1e-4 * omega * omega * 0.05, "{stabilization:?}, t={t}: a {} vs {ae}", a[k]);
        }
    }
}

#[test]
fn horizontal_bar_held_by_a_driver_carries_its_weight_at_the_pin() {
    // bar of 2 kg and 0.8 m pinned at one end, held horizontal: pin force m g up, driver torque m g l/2
    let m = model(
        r#"{"name": "bar", "gravity": [0, -9.81], "ground_points": [{"name": "O", "position": [0, 0]}],
            "bodies": [{"name": "bar", "mass": 2.0, "inertia": 0.1067, "position": [0.4, 0],
                        "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
                        "points": [{"name": "O", "position": [-0.4, 0]}]}],
            "joints": [{"type": "revolute", "name": "pin", "first": "ground.O", "second": "bar.O"}],
            "drivers": [{"name": "hold", "joint": "pin", "function": {"kind": "constant", "value": 0}}],
            "beams": [], "sensors": [], "forces": []}"#,
    );
    let mut ws = Workspace::new(&m);
    let state = assemble(&m, 0.0, &mut ws).unwrap();
    let outcome = simulate(&m, &mut state.clone(), 1e-3, &SimulationOptions::default(), None);
    assert!(outcome.error.is_none());
    let tr = &outcome.trajectory;
    let last = |name: &str| *tr.channel(name).unwrap().last().unwrap();
    assert!((last("pin.fx")).abs() < 1e-9);
    assert!((last("pin.fy") - 2.0 * 9.81).abs() < 1e-9, "{}", last("pin.fy"));
    assert!((last("hold.torque") - 2.0 * 9.81 * 0.4).abs() < 1e-9, "{}", last("hold.torque"));
}

#[test]
fn statically_loaded_slider_crank_balances_by_virtual_work() {
    // crank held at theta by the driver, a constant force P pushes the slider: T = -P dx/dtheta
    let mut spec: ModelSpec = serde_json::from_str(&serde_json::to_string(&slider_crank_spec_json()).unwrap()).unwrap();
    let theta: f64 = 0.7;
    spec.drivers[0].function = crate::spec::FunctionSpec::Constant { value: theta };
    spec.bodies[0].angle = theta;
    spec.forces.push(crate::spec::ForceSpec::PointForce {
        name: "load".into(),
        point: "slider.B".into(),
        fx: crate::spec::FunctionSpec::Constant { value: -100.0 },
        fy: crate::spec::FunctionSpec::Constant { value: 0.0 },
    });
    let m = compile(&spec).unwrap();
    let mut ws = Workspace::new(&m);
    let state = assemble(&m, 0.0, &mut ws).unwrap();
    let outcome = simulate(&m, &mut state.clone(), 1e-4, &SimulationOptions::default(), None);
    let torque = outcome.trajectory.channel("motor.torque").unwrap()[0];
    let (a, l) = (0.05, 0.12);
    let dx_dtheta = -a * theta.sin() - a * a * theta.sin() * theta.cos() / (l * l - a * a * theta.sin().powi(2)).sqrt();
    assert!((torque - (-(-100.0) * dx_dtheta)).abs() < 1e-9, "{torque} vs {}", 100.0 * dx_dtheta);
    // the guide carries the vertical load; the slider has no vertical acceleration
    assert!(outcome.trajectory.channel("slider.ay").unwrap()[0].abs() < 1e-9);
}

pub(crate) fn slider_crank_spec_json() -> serde_json::Value {
    let m = slider_crank(0.0, 0.0);
    let _ = m;
    serde_json::from_str(
        r#"{"name": "slider-crank", "gravity": [0, 0],
        "ground_points": [{"name": "O", "position": [0, 0]}, {"name": "line", "position": [0, 0]}],
        "bodies": [
          {"name": "crank", "mass": 0.3, "inertia": 1e-4, "position": [0.025, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "O", "position": [-0.025, 0]}, {"name": "A", "position": [0.025, 0]}]},
          {"name": "rod", "mass": 0.21, "inertia": 2.5e-4, "position": [0.11, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "A", "position": [-0.06, 0]}, {"name": "B", "position": [0.06, 0]}]},
          {"name": "slider", "mass": 0.14, "inertia": 1e-4, "position": [0.17, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "B", "position": [0, 0]}]}],
        "joints": [
          {"type": "revolute", "name": "O", "first": "ground.O", "second": "crank.O"},
          {"type": "revolute", "name": "A", "first": "crank.A", "second": "rod.A"},
          {"type": "revolute", "name": "B", "first": "rod.B", "second": "slider.B"},
          {"type": "translational", "name": "guide", "first": "ground.line", "second": "slider.B", "axis": [1, 0]}],
        "drivers": [{"name": "motor", "joint": "O", "function": {"kind": "constant", "value": 0}}],
        "beams": [], "sensors": [], "forces": []}"#,
    )
    .unwrap()
}

/// Complete elliptic integral of the first kind K(k) by the arithmetic-geometric mean.
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0, (1.0 - k * k).sqrt());
    while (a - b).abs() > 1e-15 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    PI / (2.0 * a)
}

#[test]
fn pendulum_period_matches_the_elliptic_integral_at_large_amplitude() {
    // uniform bar, 1 kg, 0.5 m, pinned at one end, released from 60 degrees below horizontal...
    let (mass, length, g) = (1.0, 0.5, 9.81);
    let inertia = mass * length * length / 12.0;
    let theta0: f64 = 1.2; // amplitude from the downward vertical [rad]
    let angle = -PI / 2.0 + theta0;
    let (cx, cy) = (0.5 * length * angle.cos(), 0.5 * length * angle.sin());
    let m = model(&format!(
        r#"{{"name": "pendulum", "gravity": [0, -{g}], "ground_points": [{{"name": "O", "position": [0, 0]}}],
            "bodies": [{{"name": "bar", "mass": {mass}, "inertia": {inertia}, "position": [{cx}, {cy}], "angle": {angle},
                        "velocity": [0, 0], "angular_velocity": 0, "points": [{{"name": "O", "position": [-{h}, 0]}}]}}],
            "joints": [{{"type": "revolute", "name": "pin", "first": "ground.O", "second": "bar.O"}}],
            "drivers": [], "beams": [], "sensors": [], "forces": []}}"#,
        h = 0.5 * length
    ));
    let mut ws = Workspace::new(&m);
    let mut state = assemble(&m, 0.0, &mut ws).unwrap();
    let options = SimulationOptions {
        integrator: IntegratorOptions { rtol: 1e-10, atol: 1e-12, output_step: Some(1e-4), ..Default::default() },
        ..Default::default()
    };
    let outcome = simulate(&m, &mut state, 3.0, &options, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    // period from successive downward crossings of omega through zero (turning points at +theta0)
    let (t, w) = (&outcome.trajectory.time, outcome.trajectory.channel("bar.omega").unwrap());
    let crossings: Vec<f64> = (1..t.len())
        .filter(|&k| w[k - 1] > 0.0 && w[k] <= 0.0)
        .map(|k| t[k - 1] + (t[k] - t[k - 1]) * w[k - 1] / (w[k - 1] - w[k]))
        .collect();
    assert!(crossings.len() >= 2, "{crossings:?}");
    let period = crossings[1] - crossings[0];
    let pivot_inertia = inertia + mass * (0.5 * length).powi(2);
    let expected = 4.0 * (pivot_inertia / (mass * g * 0.5 * length)).sqrt() * elliptic_k((theta0 / 2.0).sin());
    // linear interpolation of omega on a 1e-4 s grid limits the crossing time to ~1e-7 s
    assert!((period - expected).abs() < 1e-6, "period {period} vs {expected}");
    // and energy is conserved
    let e = outcome.trajectory.channel("system.energy").unwrap();
    let drift = e.iter().map(|v| (v - e[0]).abs()).fold(0.0, f64::max);
    assert!(drift < 1e-8 * mass * g * length, "energy drift {drift}");
}

/// A chain of `links` uniform bars (1 kg, 0.2 m) hanging from the ground, all joints revolute,
/// started horizontal: its 2 `links` constraint rows form one group.
fn hanging_chain(links: usize) -> Model {
    let bodies: Vec<String> = (0..links)
        .map(|k| {
            format!(
                r#"{{"name": "bar{k}", "mass": 1.0, "inertia": 0.00333333, "position": [{x}, 0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
                    "points": [{{"name": "L", "position": [-0.1, 0]}}, {{"name": "R", "position": [0.1, 0]}}]}}"#,
                x = 0.1 + 0.2 * k as f64
            )
        })
        .collect();
    let joints: Vec<String> = (0..links)
        .map(|k| {
            let first = if k == 0 { "ground.O".to_string() } else { format!("bar{}.R", k - 1) };
            format!(r#"{{"type": "revolute", "name": "pin{k}", "first": "{first}", "second": "bar{k}.L"}}"#)
        })
        .collect();
    model(&format!(
        r#"{{"name": "chain", "gravity": [0, -9.81], "ground_points": [{{"name": "O", "position": [0, 0]}}], "bodies": [{}], "joints": [{}],
            "drivers": [], "beams": [], "sensors": [], "forces": []}}"#,
        bodies.join(","),
        joints.join(",")
    ))
}

#[test]
fn a_chain_conserves_energy_with_group_kernels_and_with_the_sparse_program() {
    // 4 links: 8 coupled rows, one dense group; 6 links: 12 rows, the elimination program
    for (links, grouped) in [(4, true), (6, false)] {
        let m = hanging_chain(links);
        assert_eq!(matches!(m.schur_factor, crate::linalg::PatternLdl::Groups(_)), grouped, "{links} links");
        let mut ws = Workspace::new(&m);
        let mut state = assemble(&m, 0.0, &mut ws).unwrap();
        let options = SimulationOptions { integrator: IntegratorOptions { rtol: 1e-10, atol: 1e-12, ..Default::default() }, ..Default::default() };
        let outcome = simulate(&m, &mut state, 0.5, &options, None);
        assert!(outcome.error.is_none(), "{:?}", outcome.error);
        let e = outcome.trajectory.channel("system.energy").unwrap();
        let drop = 9.81 * links as f64 * 0.2 * links as f64 / 2.0; // scale of the potential energy released [J]
        let drift = e.iter().map(|v| (v - e[0]).abs()).fold(0.0, f64::max);
        assert!(drift < 1e-9 * drop, "{links} links: energy drift {drift} J");
        // and the chain did swing down
        let last = outcome.trajectory.channel(&format!("bar{}.y", links - 1)).unwrap();
        assert!(*last.last().unwrap() < -0.1, "{links} links: end bar at y = {}", last.last().unwrap());
    }
}

/// A bar pinned to the ground at its end, once or twice at the same point, under gravity.
fn pinned_bar(pins: usize) -> Model {
    let joints: Vec<String> =
        (0..pins).map(|k| format!(r#"{{"type": "revolute", "name": "pin{k}", "first": "ground.O", "second": "bar.O"}}"#)).collect();
    model(&format!(
        r#"{{"name": "pinned bar", "gravity": [0, -9.81], "ground_points": [{{"name": "O", "position": [0, 0]}}],
            "bodies": [{{"name": "bar", "mass": 1, "inertia": 0.1, "position": [0.3, 0.01], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
                        "points": [{{"name": "O", "position": [-0.3, 0]}}]}}],
            "joints": [{}], "drivers": [], "beams": [], "sensors": [], "forces": []}}"#,
        joints.join(", ")
    ))
}

#[test]
fn a_redundant_pin_runs_and_shares_the_reaction_by_minimum_norm() {
    // the bar starts off its pin, so assembly iterates on dependent rows too
    let (single, double) = (pinned_bar(1), pinned_bar(2));
    let mut ws1 = Workspace::new(&single);
    let mut ws2 = Workspace::new(&double);
    let s1 = assemble(&single, 0.0, &mut ws1).unwrap();
    let s2 = assemble(&double, 0.0, &mut ws2).unwrap();
    for (a, b) in s1.y.iter().zip(&s2.y) {
        assert!((a - b).abs() < 1e-12, "{a} vs {b}");
    }
    let n = single.n_velocities();
    accelerations_at(&single, &[], 0.0, &s1.y[..n], &s1.y[n..], Stabilization::Projection, &mut ws1).unwrap();
    accelerations_at(&double, &[], 0.0, &s2.y[..n], &s2.y[n..], Stabilization::Projection, &mut ws2).unwrap();
    assert!(ws2.singular_solves > 0, "the dependent rows take the singular path");
    // same motion; the single pin's reaction split equally (the minimum-norm multipliers)
    for k in 0..n {
        assert!((ws1.accelerations[k] - ws2.accelerations[k]).abs() < 1e-9, "coordinate {k}");
    }
    for r in 0..2 {
        let (whole, first, second) = (ws1.multipliers[r], ws2.multipliers[r], ws2.multipliers[r + 2]);
        assert!((first - 0.5 * whole).abs() < 1e-6 * whole.abs(), "row {r}: {first} vs half of {whole}");
        assert!((second - 0.5 * whole).abs() < 1e-6 * whole.abs(), "row {r}: {second} vs half of {whole}");
    }
}

#[test]
fn a_mechanism_driven_against_its_lock_is_reported_naming_the_element() {
    // a bar pinned at its end and driven in rotation, and also welded to the ground: no motion can satisfy both
    let m = model(
        r#"{"name": "locked", "gravity": [0, 0], "ground_points": [{"name": "O", "position": [0, 0]}],
            "bodies": [{"name": "bar", "mass": 1, "inertia": 0.1, "position": [0.3, 0], "angle": 0, "velocity": [0, 0],
                        "angular_velocity": 0, "points": [{"name": "O", "position": [-0.3, 0]}]}],
            "joints": [{"type": "revolute", "name": "pin", "first": "ground.O", "second": "bar.O"},
                       {"type": "fixed", "name": "weld", "first": "ground.O", "second": "bar.O"}],
            "drivers": [{"name": "motor", "joint": "pin", "function": {"kind": "constant_rate", "initial": 0, "rate": 10.0}}],
            "beams": [], "sensors": [], "forces": []}"#,
    );
    let mut ws = Workspace::new(&m);
    match assemble(&m, 0.0, &mut ws) {
        Err(crate::SimulationError::SingularConfiguration { cause, element, .. }) => {
            assert!(cause.contains("locked"), "{cause}");
            assert!(["pin", "weld", "motor"].contains(&element.as_str()), "{element}");
        }
        other => panic!("expected a locked mechanism, got {other:?}"),
    }
}

#[test]
fn compile_reports_every_problem_with_its_location() {
    let spec: ModelSpec = serde_json::from_str(
        r#"{"name": "faulty", "gravity": [0, 0], "ground_points": [],
            "bodies": [{"name": "bar", "mass": -1, "inertia": 0.1, "position": [0, 0], "angle": 0, "velocity": [0, 0],
                        "angular_velocity": 0, "points": [{"name": "O", "position": [0, 0]}]}],
            "joints": [{"type": "revolute", "name": "pin", "first": "ground.X", "second": "bar.O"},
                       {"type": "clearance_revolute", "name": "B", "bearing": "bar.O", "journal": "nobody.P",
                        "bearing_radius": 0.01, "clearance": 0.02, "length": null,
                        "bearing_material": {"youngs_modulus": 2e11, "poisson_ratio": 0.3},
                        "journal_material": {"youngs_modulus": 2e11, "poisson_ratio": 0.3},
                        "contact": {"law": "lankarani_nikravesh", "restitution": 1.5},
                        "stiffness": {"law": "hertz_cylinder"}, "friction": {"law": "none"},
                        "initial_eccentricity": [0, 0], "lock_at_assembly": true, "onset_velocity_floor": 1e-4,
                        "max_penetration": null, "lubrication": null}],
            "drivers": [], "beams": [], "sensors": [], "forces": []}"#,
    )
    .unwrap();
    let errors = compile(&spec).unwrap_err().to_string();
    for expected in [
        "bodies[0].mass: must be > 0, got -1 kg",
        "joints[0].first: unknown point \"ground.X\" (body \"ground\" has no such point)",
        "joints[1].journal: unknown point \"nobody.P\" (no body named \"nobody\")",
        "joints[1].clearance: must be smaller than the bearing radius 0.01 m (the journal radius would be <= 0), got 0.02 m",
        "joints[1].contact.restitution: must lie in [0, 1], got 1.5",
    ] {
        assert!(errors.contains(expected), "missing {expected:?} in\n{errors}");
    }
}




/// The Flores dry clearance joint B between rod and slider (bore 10 mm, clearance 0.5 mm, steel,
/// Lankarani-Nikravesh contact at restitution 0.9) with `friction`, held at assembly when `lock`.
pub(super) fn clearance_joint_b_json(friction: serde_json::Value, lock: bool) -> serde_json::Value {
    serde_json::json!({
        "type": "clearance_revolute", "name": "B", "bearing": "slider.B", "journal": "rod.B",
        "bearing_radius": 0.01, "clearance": 0.0005, "length": 0.04,
        "bearing_material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3},
        "journal_material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3},
        "contact": {"law": "lankarani_nikravesh", "restitution": 0.9}, "stiffness": {"law": "hertz_cylinder"},
        "friction": friction, "initial_eccentricity": [0.0, 0.0], "lock_at_assembly": lock,
        "onset_velocity_floor": 1e-4, "max_penetration": null, "lubrication": null})
}

/// The Flores slider-crank with the dry clearance joint between rod and
/// slider (Lankarani-Nikravesh, Ambrosio friction), crank at 5000 rpm.
pub(super) fn clearance_slider_crank() -> Model {
    let mut spec = slider_crank_spec_json();
    spec["gravity"] = serde_json::json!([0.0, -9.81]);
    spec["joints"][2] = clearance_joint_b_json(serde_json::json!({"law": "ambrosio", "coefficient": 0.01, "v0": 1e-4, "v1": 1e-3}), true);
    spec["drivers"][0]["function"] = serde_json::json!({"kind": "constant_rate", "initial": 0.0, "rate": 5000.0 * PI / 30.0});
    model(&spec.to_string())
}

#[test]
fn step_end_samples_equal_a_fresh_evaluation_of_the_recorded_state() {
    // samples at step ends reuse the integrator's last-stage evaluation: every recorded
    // channel must equal what a fresh workspace computes at the recorded state
    let model = clearance_slider_crank();
    let mut ws = Workspace::new(&model);
    let mut state = assemble(&model, 0.0, &mut ws).unwrap();
    let outcome = simulate(&model, &mut state, 0.012, &SimulationOptions::default(), None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    let trajectory = &outcome.trajectory;
    let n = model.n_velocities();
    let contact_channel = trajectory.channels.iter().position(|c| c.name == "B.contact").expect("B.contact");
    let (mut checked, mut in_contact) = (0, 0);
    for k in 0..trajectory.time.len() {
        if trajectory.value(contact_channel, k) != 0.0 {
            in_contact += 1; // the contact force depends on the latched onset velocity, not recorded
            continue;
        }
        let mut y = vec![0.0; model.layout.len()];
        for (c, channel) in model.channels.iter().enumerate() {
            match channel.source {
                channels::Source::Coordinate(i) => y[i] = trajectory.value(c, k),
                channels::Source::Velocity(i) => y[n + i] = trajectory.value(c, k),
                _ => {}
            }
        }
        let t = trajectory.time[k];
        let mut fresh_ws = Workspace::new(&model);
        let memory = model.initial_memory();
        accelerations(&model, &memory, t, &y, Stabilization::Projection, &mut fresh_ws).unwrap();
        let mut fresh = Trajectory::new(&model);
        fresh.push(&model, t, &y, &mut fresh_ws).unwrap();
        for (c, info) in trajectory.channels.iter().enumerate() {
            let (recorded, expected) = (trajectory.value(c, k), fresh.value(c, 0));
            assert!(
                (recorded - expected).abs() <= 1e-9 * (1.0 + expected.abs()),
                "{} at t = {t:e}: recorded {recorded:e}, fresh {expected:e}",
                info.name
            );
        }
        checked += 1;
    }
    assert!(checked > 100 && in_contact > 10, "checked {checked}, in contact {in_contact}");
}

#[test]
fn a_kept_constraint_factor_is_reused_only_at_the_same_time_and_positions() {
    let model = clearance_slider_crank();
    let n = model.n_velocities();
    let mut ws = Workspace::new(&model);
    let state = assemble(&model, 0.0, &mut ws).unwrap();
    let memory = model.initial_memory();
    let fresh = |t: f64, q: &[f64], v: &[f64]| {
        let mut ws = Workspace::new(&model);
        accelerations_at(&model, &memory, t, q, v, Stabilization::Projection, &mut ws).unwrap();
        ws.accelerations
    };
    let (q, v) = (state.y[..n].to_vec(), state.y[n..].to_vec());
    let mut moved = q.clone();
    moved[3] += 1e-3; // the rod's x: another configuration at the same time
    let slower: Vec<f64> = v.iter().map(|x| 0.5 * x).collect();
    // same time and positions, other velocities: the factor is reused, and the result is exact
    accelerations_at(&model, &memory, 1e-3, &q, &v, Stabilization::Projection, &mut ws).unwrap();
    accelerations_at(&model, &memory, 1e-3, &q, &slower, Stabilization::Projection, &mut ws).unwrap();
    assert_eq!(ws.factored_at, Some((1e-3, model.row_offsets[model.n_dynamic_constraints])));
    assert_eq!(ws.accelerations, fresh(1e-3, &q, &slower));
    // same time, other positions: factored anew
    accelerations_at(&model, &memory, 1e-3, &moved, &v, Stabilization::Projection, &mut ws).unwrap();
    assert_eq!(ws.accelerations, fresh(1e-3, &moved, &v));
    assert_eq!(ws.factored_positions, moved);
}

/// Entry (r, k) of the dense constraint Jacobian, from the row's body blocks.
#[test]
fn the_slider_crank_constraint_matrix_factors_without_fill_in_and_solves_like_the_dense_kernel() {
    // rows O (2), A (2) and the driver share the crank; the guide's two rows only the slider
    let model = clearance_slider_crank();
    let rows = model.row_offsets[model.n_dynamic_constraints];
    assert_eq!((rows, model.schur_factor.size()), (7, 7));
    assert_eq!(model.schur_factor.factor_nonzeros(), 15 + 3);
    assert!(matches!(model.schur_factor, crate::linalg::PatternLdl::Groups(_)), "a group of 5 rows and one of 2");
    let mut ws = Workspace::new(&model);
    let state = assemble(&model, 0.0, &mut ws).unwrap();
    let n = model.n_velocities();
    update_frames(&model, state.coordinates(), state.velocities(), &mut ws.frames, &mut ws.spatial_frames);
    equations::linearise_constraints(&model, model.n_dynamic_constraints, 0.0, &mut ws);
    assert_eq!(constraint_solution::factor(&model, rows, state.coordinates(), &mut ws).unwrap(), constraint_solution::FactorKind::Pattern);
    let sparse = ws.schur[..rows * (rows + 1)].to_vec();
    // the same matrix formed densely from the Jacobian and factored by the dense kernel
    // (M^-1 column by column through the body kinds' solves)
    let mut inverse_mass = vec![0.0; n * n];
    for k in 0..n {
        let mut unit = vec![0.0; n];
        unit[k] = 1.0;
        model.solve_mass(state.coordinates(), &unit, &mut inverse_mass[k * n..(k + 1) * n], &mut []);
    }
    let entry = |r: usize, k: usize| redundancy::jacobian_entry(&model, &ws, r, k);
    let mut dense = vec![0.0; rows * rows];
    for a in 0..rows {
        for b in 0..=a {
            dense[a * rows + b] = (0..n).flat_map(|k| (0..n).map(move |l| (k, l))).map(|(k, l)| entry(a, k) * inverse_mass[l * n + k] * entry(b, l)).sum();
        }
    }
    crate::linalg::cholesky_factor(&mut dense, rows).unwrap();
    let b: Vec<f64> = (0..rows).map(|r| 1.0 + r as f64).collect();
    let (mut x_sparse, mut x_dense) = (b.clone(), b);
    model.schur_factor.solve(&sparse, &mut x_sparse);
    crate::linalg::cholesky_solve(&dense, rows, &mut x_dense);
    for r in 0..rows {
        let (x, y) = (x_sparse[r], x_dense[r]);
        assert!((x - y).abs() <= 1e-12 * (1.0 + y.abs()), "row {r}: {x:e} vs {y:e}");
    }
}

/// The constraint matrix through the body kinds' own mass solves (the path of a
/// body with a full or configuration-dependent mass block) equals the diagonal fast path.
#[test]
fn the_general_mass_solve_path_gives_the_accelerations_of_the_diagonal_fast_path() {
    let diagonal = clearance_slider_crank();
    let mut general = diagonal.clone();
    general.diagonal_inverse_mass = None;
    let mut ws = Workspace::new(&diagonal);
    let state = assemble(&diagonal, 0.0, &mut ws).unwrap();
    let memory = diagonal.initial_memory();
    let n = diagonal.layout.nq;
    let (q, v) = (state.y[..n].to_vec(), state.y[n..].to_vec());
    let mut results = Vec::new();
    for model in [&diagonal, &general] {
        let mut ws = Workspace::new(model);
        accelerations_at(model, &memory, 1e-3, &q, &v, Stabilization::Projection, &mut ws).unwrap();
        results.push((ws.accelerations.clone(), ws.multipliers.clone()));
    }
    for (a, b) in results[0].0.iter().zip(&results[1].0).chain(results[0].1.iter().zip(&results[1].1)) {
        assert!((a - b).abs() <= 1e-12 * (1.0 + a.abs()), "{a:e} vs {b:e}");
    }
}

/// A chain of `n` bars (0.1 kg, 0.1 m) pinned end to end from a ground pin `O`, released
/// horizontal under gravity; the first `clearance` pins are clearance joints (joint B's
/// geometry, no friction) instead.
pub(super) fn bar_chain_spec(n: usize, clearance: usize) -> serde_json::Value {
    let bodies: Vec<serde_json::Value> = (0..n)
        .map(|k| {
            serde_json::json!({"name": format!("bar{k}"), "mass": 0.1, "inertia": 1e-4, "position": [0.1 * k as f64 + 0.05, 0.0],
                "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
                "points": [{"name": "a", "position": [-0.05, 0]}, {"name": "b", "position": [0.05, 0]}]})
        })
        .collect();
    let joints: Vec<serde_json::Value> = (0..n)
        .map(|k| {
            let (first, second) = (if k == 0 { "ground.O".to_string() } else { format!("bar{}.b", k - 1) }, format!("bar{k}.a"));
            if k < clearance {
                let mut joint = clearance_joint_b_json(serde_json::json!({"law": "none"}), false);
                joint["name"] = serde_json::json!(format!("pin{k}"));
                joint["bearing"] = serde_json::json!(first);
                joint["journal"] = serde_json::json!(second);
                joint
            } else {
                serde_json::json!({"type": "revolute", "name": format!("pin{k}"), "first": first, "second": second})
            }
        })
        .collect();
    serde_json::json!({
        "name": "chain", "gravity": [0, -9.81], "ground_points": [{"name": "O", "position": [0, 0]}],
        "bodies": bodies, "joints": joints, "beams": [], "drivers": [], "forces": [], "sensors": []
    })
}
