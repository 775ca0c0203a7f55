//! The spatial clearance revolute joint in motion, against closed forms and
//! independent one-degree-of-freedom integrations: energy conserved with an
//! elastic law and no friction, a flange striking its face, stick and slip
//! under an axial load.

use super::*;
use crate::integrate::IntegratorOptions;
use crate::spec::ModelSpec;
use serde_json::{json, Value};

/// Journal mass [kg] and principal inertias [kg m^2].
const MASS: f64 = 1.0;
const INERTIA: [f64; 3] = [1e-3, 1e-3, 5e-4];
/// Axial stiffness of a flange ring [N/m].
const AXIAL_STIFFNESS: f64 = 2e9;

/// A free journal (1 kg) in a bore on the ground: 10 mm bore, 0.5 mm radial and 0.4 mm axial clearance,
/// 20 mm long; the journal starts centred with `velocity` and `angular_velocity` (global), under
/// `gravity`, with the normal force law `contact`, the friction `friction` and an axial force `push` [N].
fn journal_in_bore(gravity: [f64; 3], velocity: [f64; 3], angular_velocity: [f64; 3], contact: Value, friction: Value, push: f64) -> Value {
    journal_at([0.0; 3], gravity, velocity, angular_velocity, contact, friction, push)
}

/// [`journal_in_bore`] with the journal starting at `position` [m].
fn journal_at(position: [f64; 3], gravity: [f64; 3], velocity: [f64; 3], angular_velocity: [f64; 3], contact: Value, friction: Value, push: f64) -> Value {
    let constant = |value: f64| json!({"kind": "constant", "value": value});
    json!({
        "name": "journal_in_bore", "gravity": gravity, "ground_points": [{"name": "P", "position": [0.0, 0.0, 0.0]}],
        "bodies": [], "beams": [], "joints": [], "drivers": [], "forces": [], "sensors": [],
        "spatial_bodies": [{"name": "pin", "mass": MASS, "inertia": [[INERTIA[0], 0.0, 0.0], [0.0, INERTIA[1], 0.0], [0.0, 0.0, INERTIA[2]]],
            "position": position, "orientation": [1.0, 0.0, 0.0, 0.0], "velocity": velocity, "angular_velocity": angular_velocity,
            "points": [{"name": "J", "position": [0.0, 0.0, 0.0]}], "euler_sequence": "zyx"}],
        "spatial_joints": [],
        "spatial_forces": [{"type": "point_force", "name": "push", "point": "pin.J", "force": [constant(0.0), constant(0.0), constant(push)], "frame": "global"}],
        "spatial_clearance_joints": [{
            "type": "spatial_clearance_revolute", "name": "play", "bearing": "ground.P", "journal": "pin.J",
            "bore_radius": 0.010, "clearance": 5e-4, "bearing_length": 0.020, "axial_clearance": 4e-4,
            "flange_radius": 0.015, "face_radius": 0.016,
            "bearing_material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3}, "journal_material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3},
            "contact": contact, "stiffness": {"law": "hertz_cylinder"}, "axial_stiffness": AXIAL_STIFFNESS, "friction": friction,
            "lock_at_assembly": false, "onset_velocity_floor": 1e-4, "max_penetration": null,
            "mode_impact_speed": 1e-3, "mode_impact_duration": 1e-3, "mode_sliding_speed": 5e-5,
        }],
    })
}

fn run(spec: &Value, t_end: f64, tolerance: f64, step: f64) -> SimulationOutcome {
    let spec: ModelSpec = serde_json::from_value(spec.clone()).unwrap_or_else(|e| panic!("{e}"));
    let model = compile(&spec).unwrap_or_else(|e| panic!("{e}"));
    let mut ws = Workspace::new(&model);
    let mut state = assemble(&model, 0.0, &mut ws).unwrap_or_else(|e| panic!("{e}"));
    let integrator = IntegratorOptions { rtol: tolerance, atol: tolerance * 1e-3, output_step: Some(step), ..Default::default() };
    let outcome = simulate(&model, &mut state, t_end, &SimulationOptions { integrator, ..Default::default() }, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    outcome
}

fn channel(t: &Trajectory, name: &str) -> Vec<f64> {
    t.channel(name).unwrap_or_else(|| panic!("no channel {name}"))
}

#[test]
fn a_tilting_spinning_journal_bouncing_elastically_without_friction_keeps_its_energy() {
    // Hertz's law (no dissipation), no friction: the journal falls, tilts (it starts turning about x)
    // and strikes the bore at its rims, along its length and with its flanges; its kinetic and
    // gravitational energy is the same whenever it is free (the contact's stored energy is then zero)
    let spec = journal_in_bore([0.0, -9.81, 0.0], [0.0, 0.0, 1e-2], [2.0, 0.0, 30.0], json!({"law": "hertz"}), json!({"law": "none"}), 0.0);
    let outcome = run(&spec, 0.1, 1e-10, 1e-5);
    let t = &outcome.trajectory;
    let (v, w, y) = (["vx", "vy", "vz"].map(|c| channel(t, &format!("pin.{c}"))), ["wx", "wy", "wz"].map(|c| channel(t, &format!("pin.{c}"))), channel(t, "pin.y"));
    let energy = |k: usize| 0.5 * MASS * v.iter().map(|c| c[k] * c[k]).sum::<f64>() + 0.5 * (0..3).map(|i| INERTIA[i] * w[i][k] * w[i][k]).sum::<f64>() + MASS * 9.81 * y[k];
    let forces = ["fn_a", "fn_b", "fn_fa", "fn_fb"].map(|c| channel(t, &format!("play.{c}")));
    let free: Vec<usize> = (0..t.len()).filter(|&k| forces.iter().all(|f| f[k] == 0.0)).collect();
    let start = energy(0);
    let worst = free.iter().map(|&k| (energy(k) - start).abs()).fold(0.0, f64::max);
    let touched = |f: &Vec<f64>| f.iter().any(|&x| x > 0.0);
    assert!(forces.iter().all(touched), "every candidate struck: rims, length and both flanges");
    assert!(channel(t, "play.tilt").iter().fold(0.0_f64, |m, x| m.max(*x)) > 1e-3, "the journal tilts");
    assert!(worst < 1e-6 * start, "energy drift {worst:e} J of {start:e} J over {} free samples", free.len());
}

/// Rebound velocity [m/s] of a mass `mass` [kg] striking a spring `stiffness` [N/m] at `speed` [m/s]
/// with the Lankarani-Nikravesh damping of restitution `restitution`, `F = k x (1 + 3(1 - e^2)/4 x_dot / v0)`
/// clamped at zero, integrated independently (classical Runge-Kutta, 1e-9 s steps) until separation.
fn lankarani_nikravesh_rebound(mass: f64, stiffness: f64, speed: f64, restitution: f64) -> f64 {
    let damping = 0.75 * (1.0 - restitution * restitution);
    let acceleration = |x: f64, v: f64| -(stiffness * x * (1.0 + damping * v / speed)).max(0.0) / mass;
    let (mut x, mut v, h) = (0.0, speed, 1e-9);
    loop {
        let (k1x, k1v) = (v, acceleration(x, v));
        let (k2x, k2v) = (v + 0.5 * h * k1v, acceleration(x + 0.5 * h * k1x, v + 0.5 * h * k1v));
        let (k3x, k3v) = (v + 0.5 * h * k2v, acceleration(x + 0.5 * h * k2x, v + 0.5 * h * k2v));
        let (k4x, k4v) = (v + h * k3v, acceleration(x + h * k3x, v + h * k3v));
        x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        if x <= 0.0 {
            return v;
        }
    }
}

#[test]
fn a_flange_striking_its_face_rebounds_as_a_one_degree_of_freedom_lankarani_nikravesh_impact() {
    // no gravity, aligned axes, the journal moving along its axis at 50 mm/s: flange A strikes its face
    // over the whole ring, a linear spring k_a with the Lankarani-Nikravesh damping (restitution 0.8),
    // and rebounds at the speed the independent one-degree-of-freedom integration gives
    let (speed, restitution) = (0.05, 0.8);
    let spec = journal_in_bore([0.0; 3], [0.0, 0.0, speed], [0.0; 3], json!({"law": "lankarani_nikravesh", "restitution": restitution}), json!({"law": "none"}), 0.0);
    let outcome = run(&spec, 8e-3, 1e-10, 1e-5);
    let t = &outcome.trajectory;
    let (vz, flange) = (channel(t, "pin.vz"), channel(t, "play.fn_fa"));
    assert!(flange.iter().any(|&f| f > 0.0) && channel(t, "play.fn_fb").iter().all(|&f| f == 0.0));
    let expected = lankarani_nikravesh_rebound(MASS, AXIAL_STIFFNESS, speed, restitution);
    let rebound = *vz.last().unwrap();
    assert!((rebound - expected).abs() < 1e-6 * speed, "rebound {rebound} m/s against {expected} m/s");
    assert!(rebound < -0.5 * speed, "it rebounds: {rebound} m/s");
    // the ring pushes along the axis only: no moment, no sideways force
    let (fx, my) = (channel(t, "play.fx"), channel(t, "play.my"));
    assert!(fx.iter().chain(&my).all(|x| x.abs() < 1e-9 * AXIAL_STIFFNESS * 1e-6));
}

#[test]
fn an_axial_load_below_static_friction_sticks_and_above_it_slides_at_the_kinetic_coefficient() {
    // the journal lies at the bottom of the bore under its weight W = m g (it starts touching and settles
    // on a lossy contact);
    // an axial push of 0.5 mu_s W leaves it creeping below the stiction speed, one of 2 mu_k W
    // (above mu_s W) makes it slide with acceleration (P - mu_k W)/m (friction law: stiction,
    // mu_s = 0.15, mu_k = 0.1, speeds 0.01 and 0.05 mm/s as paper 002)
    let (g, mu_s, mu_k) = (9.81, 0.15, 0.1);
    let weight = MASS * g;
    let friction = json!({"law": "stiction", "static_coefficient": mu_s, "kinetic_coefficient": mu_k, "stiction_velocity": 1e-5, "transition_velocity": 5e-5});
    let contact = json!({"law": "flores", "restitution": 0.3});
    let (settle, slide) = (0.05, 0.01);
    let bottom = [0.0, -5e-4, 0.0];
    let stuck = run(&journal_at(bottom, [0.0, -g, 0.0], [0.0; 3], [0.0; 3], contact.clone(), friction.clone(), 0.5 * mu_s * weight), settle + slide, 1e-8, 1e-5);
    let vz = channel(&stuck.trajectory, "pin.vz");
    let tail = &vz[vz.len() / 2..];
    assert!(tail.iter().all(|v| v.abs() < 1e-5), "creeps below the stiction speed: {:e} m/s", tail.iter().fold(0.0_f64, |m, v| m.max(v.abs())));
    let push = 2.0 * mu_k * weight;
    // (15 ms: it slides 0.11 mm, short of the flange 0.2 mm away)
    let sliding = run(&journal_at(bottom, [0.0, -g, 0.0], [0.0; 3], [0.0; 3], contact, friction, push), slide + 5e-3, 1e-8, 1e-5);
    let t = &sliding.trajectory;
    let (vz, time) = (channel(t, "pin.vz"), &t.time);
    assert!(channel(t, "play.fn_fa").iter().chain(&channel(t, "play.fn_fb")).all(|&f| f == 0.0), "the flanges stay free");
    // the slope of vz over the last 5 ms
    let (a, b) = (time.iter().position(|&s| s >= slide).unwrap(), time.len() - 1);
    let acceleration = (vz[b] - vz[a]) / (time[b] - time[a]);
    let expected = (push - mu_k * weight) / MASS;
    assert!((acceleration - expected).abs() < 0.02 * expected, "slides at {acceleration} m/s^2 against {expected} m/s^2");
    let modes = channel(t, "play.mode");
    assert_eq!(*modes.last().unwrap(), 2.0, "the sliding mode");
}
