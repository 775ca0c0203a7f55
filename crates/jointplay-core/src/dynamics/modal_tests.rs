//! Modal bodies in the engine, checked against what must hold independently
//! of their code: conservation of energy and momentum in free flight, the
//! Timoshenko cantilever under a tip load, and the spin-up beam of Simo and
//! Vu-Quoc (1986) against the geometrically exact beam mesh while slow, and
//! the divergence of a linear modal body (no geometric stiffening) once the
//! spin passes its first bending frequency (Kane, Ryan and Banerjee,
//! "Dynamics of a cantilever beam attached to a moving base", J. Guidance 10(2),
//! 1987, 139-151).

use super::beam_tests::{model, run_slider_crank, spin_up_beam};
use super::*;
use crate::body::{BodyKind, BodyModel};
use crate::kinematics::marker::{ModalNodeSite, Site};
use crate::kinematics::planar::{Frame, Vec2};
use crate::integrate::{IntegratorOptions, Method};

/// The section of the free-flight and cantilever tests: EA, GA, EI, rho A, rho I.
pub(super) const SECTION: [f64; 5] = [2.0e6, 8.0e5, 100.0, 2.0, 1.0e-4];

fn section_json(s: [f64; 5]) -> serde_json::Value {
    serde_json::json!({"type": "resultants", "axial_stiffness": s[0], "shear_stiffness": s[1], "bending_stiffness": s[2],
                       "mass_per_length": s[3], "rotary_inertia_per_length": s[4]})
}

/// A modal body `arm` from (0, 0) to (`length`, 0) of `elements` quadratic elements.
pub(super) fn arm_json(length: f64, section: [f64; 5], elements: usize, interface: serde_json::Value, normal_modes: usize, damping_ratio: f64, angular_velocity: f64) -> serde_json::Value {
    serde_json::json!({"name": "arm", "structure": {"from": "beam", "start": [0.0, 0.0], "end": [length, 0.0], "section": section_json(section),
                       "mesh": {"order": "quadratic", "elements": elements, "element_length": null}},
                       "interface": interface, "normal_modes": normal_modes, "damping_ratio": damping_ratio, "damping_time": 0.0, "points": [],
                       "velocity": [0.3, 0.0], "angular_velocity": angular_velocity})
}

/// The frame of node `node` of the modal body `body` at the positions `q` of the whole model (at rest).
fn node_frame(m: &Model, body: usize, q: &[f64], node: u32) -> Frame {
    let address = &m.layout.bodies[body];
    let zeros = vec![0.0; address.nv];
    m.bodies[body].kind.site_frame(&Site::ModalNode(ModalNodeSite { node }), &q[address.q_range()], &zeros, &Frame::GROUND)
}

/// The tip (node `last`) of the modal body `body` at the positions `q` of the whole model [m].
fn tip(m: &Model, body: usize, q: &[f64], last: u32) -> Vec2 {
    node_frame(m, body, q, last).position
}

/// `m` from its assembled start to `t_end` [s] by NDF of order 2 at `tolerances` (rtol, atol), sampled
/// every `output_step` [s]: the final state and the trajectory (the run must not fail).
fn settle(m: &Model, t_end: f64, tolerances: (f64, f64), output_step: f64) -> (State, Trajectory) {
    let mut ws = Workspace::new(m);
    let mut state = assemble(m, 0.0, &mut ws).unwrap();
    let (rtol, atol) = tolerances;
    let options = SimulationOptions {
        integrator: IntegratorOptions { method: Method::NumericalDifferentiation, max_order: 2, rtol, atol, output_step: Some(output_step), ..IntegratorOptions::default() },
        ..SimulationOptions::default()
    };
    let outcome = simulate(m, &mut state, t_end, &options, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    (state, outcome.trajectory)
}

#[test]
fn an_undamped_modal_body_spinning_and_vibrating_in_free_flight_keeps_its_energy_and_momentum() {
    let interface = serde_json::json!([{"name": "start", "arclength": 0.0}, {"name": "end", "arclength": 1.0}]);
    let m = model(serde_json::json!({
        "name": "free modal body", "gravity": [0, 0], "ground_points": [], "bodies": [], "beams": [],
        "modal_bodies": [arm_json(1.0, SECTION, 4, interface, 3, 0.0, 3.0)],
        "joints": [], "drivers": [], "forces": [], "sensors": []
    }));
    let mut ws = Workspace::new(&m);
    let mut state = assemble(&m, 0.0, &mut ws).unwrap();
    // a vibration of every mode on top of the spin
    let nq = m.layout.nq;
    for (j, rate) in state.y[nq + 3..].iter_mut().enumerate() {
        *rate = 0.5 * (1.0 + j as f64).recip();
    }
    let momentum = |state: &State| {
        // the linear momentum: generalised momentum of (x, y), the first rows of M v
        let (q, v) = (state.coordinates(), state.velocities());
        let kind = &m.bodies[0].kind;
        let h = 1e-6;
        let mut p = Vec2::zeros();
        for c in 0..2 {
            let (mut plus, mut minus) = (v.to_vec(), v.to_vec());
            plus[c] += h;
            minus[c] -= h;
            p[c] = (kind.kinetic_energy(q, &plus) - kind.kinetic_energy(q, &minus)) / (2.0 * h);
        }
        p
    };
    let before = momentum(&state);
    let options = SimulationOptions {
        integrator: IntegratorOptions { rtol: 1e-10, atol: 1e-12, output_step: Some(0.01), ..IntegratorOptions::default() },
        ..SimulationOptions::default()
    };
    let outcome = simulate(&m, &mut state, 1.0, &options, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    let energy = outcome.trajectory.channel("system.energy").unwrap();
    let (low, high) = energy.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), e| (l.min(*e), h.max(*e)));
    assert!((high - low) < 1e-8 * energy[0], "energy {} J varies by {} J", energy[0], high - low);
    // kinetic and strain energy are exchanged (the body does vibrate)
    let kinetic = outcome.trajectory.channel("system.kinetic_energy").unwrap();
    let (kl, kh) = kinetic.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), e| (l.min(*e), h.max(*e)));
    assert!(kh - kl > 1e-3 * energy[0], "kinetic energy from {kl} to {kh} J");
    let after = momentum(&state);
    assert!((before - after).norm() < 1e-8 * before.norm().max(1.0), "{before:?} vs {after:?}");
}

#[test]
fn an_undamped_modal_pendulum_under_gravity_keeps_its_energy() {
    // pinned at its frame node by an ideal revolute joint (no work), released horizontal: the
    // exchange of gravity, kinetic and strain energy through the eta-dependent mass and weight
    let interface = serde_json::json!([{"name": "start", "arclength": 0.0}, {"name": "end", "arclength": 1.0}]);
    let mut arm = arm_json(1.0, SECTION, 4, interface, 3, 0.0, 0.0);
    arm["velocity"] = serde_json::json!([0.0, 0.0]);
    let m = model(serde_json::json!({
        "name": "modal pendulum", "gravity": [0, -9.81], "ground_points": [{"name": "O", "position": [0, 0]}], "bodies": [], "beams": [],
        "modal_bodies": [arm],
        "joints": [{"type": "revolute", "name": "pin", "first": "ground.O", "second": "arm.start"}],
        "drivers": [], "forces": [], "sensors": []
    }));
    let mut ws = Workspace::new(&m);
    let mut state = assemble(&m, 0.0, &mut ws).unwrap();
    let options = SimulationOptions {
        integrator: IntegratorOptions { rtol: 1e-10, atol: 1e-12, output_step: Some(0.01), ..IntegratorOptions::default() },
        ..SimulationOptions::default()
    };
    let outcome = simulate(&m, &mut state, 1.0, &options, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    let tr = &outcome.trajectory;
    let (energy, kinetic) = (tr.channel("system.energy").unwrap(), tr.channel("system.kinetic_energy").unwrap());
    // the swing turns m g L / 2 = 9.81 J of potential energy into kinetic energy by the bottom
    let swing = kinetic.iter().fold(0.0_f64, |a, k| a.max(*k));
    let (low, high) = energy.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), e| (l.min(*e), h.max(*e)));
    assert!(swing > 5.0 && (high - low) < 1e-8 * swing, "energy varies by {} J over a swing of {swing} J", high - low);
    // the body bends under its own inertia: some modal amplitude is not zero
    assert!(tr.channel("arm.eta4").unwrap().iter().any(|e| e.abs() > 1e-5));
}

#[test]
fn a_modal_cantilever_under_a_tip_load_settles_at_the_timoshenko_deflection() {
    // clamped at its frame node by a fixed joint, 10 N down at the free end, every mode
    // critically damped: the rest deflection is P L^3 / (3 EI) + P L / (k G A) = 33.346 mm;
    // the frame clamped at the clamp, as a link clamped at one end wants
    let interface = serde_json::json!([{"name": "start", "arclength": 0.0}, {"name": "end", "arclength": 1.0}]);
    let mut arm = arm_json(1.0, SECTION, 6, interface, 2, 1.0, 0.0);
    arm["frame"] = serde_json::json!("clamped");
    // (clamped: it starts at rest, the rigid motion the clamp gives it)
    arm["velocity"] = serde_json::Value::Null;
    arm["angular_velocity"] = serde_json::Value::Null;
    let m = model(serde_json::json!({
        "name": "modal cantilever", "gravity": [0, 0], "ground_points": [{"name": "O", "position": [0, 0]}], "bodies": [], "beams": [],
        "modal_bodies": [arm],
        "joints": [{"type": "fixed", "name": "clamp", "first": "ground.O", "second": "arm.start"}],
        "drivers": [],
        "forces": [{"type": "point_force", "name": "load", "point": "arm.end", "fx": {"kind": "constant", "value": 0.0}, "fy": {"kind": "constant", "value": -10.0}}],
        "sensors": []
    }));
    let (state, tr) = settle(&m, 2.0, (1e-8, 1e-11), 0.05);
    let (p, length, ei, ga) = (10.0, 1.0, SECTION[2], SECTION[1]);
    let expected = p * length * length * length / (3.0 * ei) + p * length / ga;
    let deflection = tip(&m, 0, state.coordinates(), 12);
    assert!((deflection.y + expected).abs() < 1e-5 * expected, "tip at {deflection:?} m, expected -{expected} m");
    assert!((deflection.x - length).abs() < 1e-9, "a linear modal body does not shorten under bending: {}", deflection.x);
    // the clamp carries the load and its moment P L
    let (fy, moment) = (tr.channel("clamp.fy").unwrap(), tr.channel("clamp.moment").unwrap());
    assert!((fy.last().unwrap() - p).abs() < 1e-6 * p && (moment.last().unwrap() - p * length).abs() < 1e-6 * p * length, "reaction {fy:?} N, {moment:?} N m", fy = fy.last(), moment = moment.last());
}

/// The spin-up beam of Simo and Vu-Quoc as a modal body: the hub driven through the
/// speed ramp to 6 rad/s over 15 s, the body (4 quadratic elements, interface at its
/// root only, the `normal` lowest cantilever modes) clamped to it.
fn spin_up_modal(normal: usize) -> Model {
    let section = [2.8e7, 1.0e7, 1.4e4, 1.2, 6.0e-4];
    let interface = serde_json::json!([{"name": "start", "arclength": 0.0}]);
    let mut arm = arm_json(10.0, section, 4, interface, normal, 0.0, 0.0);
    arm["velocity"] = serde_json::json!([0.0, 0.0]);
    model(serde_json::json!({
        "name": "spin-up modal beam", "gravity": [0, 0], "ground_points": [{"name": "O", "position": [0, 0]}],
        "bodies": [{"name": "hub", "mass": 1.0, "inertia": 1.0, "position": [0, 0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
                    "points": [{"name": "O", "position": [0, 0]}]}],
        "beams": [], "modal_bodies": [arm],
        "joints": [{"type": "revolute", "name": "axis", "first": "ground.O", "second": "hub.O"},
                   {"type": "fixed", "name": "clamp", "first": "hub.O", "second": "arm.start"}],
        "drivers": [{"name": "spin", "joint": "axis", "function": {"kind": "speed_ramp", "ramp_time": 15.0, "final_rate": 6.0}}],
        "forces": [], "sensors": []
    }))
}

/// Tip deflection across the hub's direction [m] at every sample of `tr`, from the tip's position `tip_at(k)`.
fn transverse(tr: &Trajectory, tip_at: impl Fn(usize) -> Vec2) -> Vec<f64> {
    let angle = tr.channel("hub.angle").unwrap();
    (0..angle.len()).map(|k| {
        let p = tip_at(k);
        -p.x * angle[k].sin() + p.y * angle[k].cos()
    })
    .collect()
}

#[test]
fn the_linear_modal_spin_up_beam_follows_the_mesh_while_slow_and_diverges_past_its_first_bending_frequency() {
    let m = spin_up_modal(3);
    // the warning datum: the first bending frequency of the body clamped at its root, against
    // Euler-Bernoulli 1.8751^2 sqrt(EI / (rho A L^4)) / (2 pi) = 0.6044 Hz (shear lowers it slightly)
    let frequencies = m.modal_bending_frequencies();
    let first = frequencies[0].1;
    assert_eq!(frequencies[0].0, "arm");
    let euler_bernoulli = 1.875_104_07_f64.powi(2) * (1.4e4_f64 / (1.2 * 1e4)).sqrt() / (2.0 * std::f64::consts::PI);
    assert!((first / euler_bernoulli - 1.0).abs() < 2e-3, "{first} Hz vs {euler_bernoulli} Hz");
    let run = |m: &Model, options: SimulationOptions, t_end: f64| {
        let mut ws = Workspace::new(m);
        let mut state = assemble(m, 0.0, &mut ws).unwrap();
        let outcome = simulate(m, &mut state, t_end, &options, None);
        assert!(outcome.error.is_none(), "{:?}", outcome.error);
        outcome.trajectory
    };
    let sampled = |integrator: IntegratorOptions| SimulationOptions { integrator: IntegratorOptions { output_step: Some(0.1), ..integrator }, ..SimulationOptions::default() };
    let modal = run(&m, sampled(IntegratorOptions { rtol: 1e-8, atol: 1e-10, ..IntegratorOptions::default() }), 11.0);
    let coordinates = |k: usize| -> Vec<f64> {
        let names = ["x", "y", "angle", "eta1", "eta2", "eta3"];
        let mut q = vec![0.0; m.layout.nq];
        for (i, name) in names.iter().enumerate() {
            q[m.layout.bodies[1].q + i] = modal.channel(&format!("arm.{name}")).unwrap()[k];
        }
        q
    };
    let deflection = transverse(&modal, |k| tip(&m, 1, &coordinates(k), 8));
    // the geometrically exact mesh the modal body was reduced from, as beam_tests runs it
    let mesh = spin_up_beam(6.0, 4, 0.0);
    let integrator = IntegratorOptions { method: Method::NumericalDifferentiation, rtol: 1e-7, atol: 1e-9, output_step: Some(0.1), max_order: 2, ..IntegratorOptions::default() };
    let beam = run(&mesh, SimulationOptions { integrator, stabilization: Stabilization::Baumgarte { alpha: 10.0, beta: 10.0 }, ..SimulationOptions::default() }, 11.0);
    let (bx, by) = (beam.channel("beam.node8_x").unwrap(), beam.channel("beam.node8_y").unwrap());
    let reference = transverse(&beam, |k| Vec2::new(bx[k], by[k]));
    assert_eq!((deflection.len(), reference.len()), (111, 111));
    // while slow (t <= 3 s, spin below 0.3 rad/s, 8 % of 2 pi f_1) they agree within 1 % of the
    // peak (seen: 0.5 % at 3 s, 3 % at 4 s: the gap grows as the stiffening the modal body lacks,
    // about 1.19 omega^2 / omega_1^2 of the deflection)
    let slow = 30;
    let peak = reference[..=slow].iter().fold(0.0_f64, |a, d| a.max(d.abs()));
    let worst = (0..=slow).map(|k| (deflection[k] - reference[k]).abs()).fold(0.0, f64::max);
    assert!(worst < 0.01 * peak, "modal body and mesh differ by {worst} m (peak {peak} m) while slow");
    // past 2 pi f_1 = 3.80 rad/s (t = 8.5 s) the modal body's deflection grows without bound
    // (seen: 7.4 m at 9 s, 1900 m at 11 s), the mesh's stays below 0.6 m
    assert!(deflection[110].abs() > 100.0 * deflection[90].abs() && deflection[110].abs() > 1000.0, "modal tip deflection {} m at 9 s, {} m at 11 s", deflection[90], deflection[110]);
    assert!(reference.iter().all(|d| d.abs() < 0.6), "the mesh stays within 0.6 m: {reference:?}");
}

#[test]
fn a_modal_body_is_refused_with_its_location_when_an_interface_point_misses_the_nodes() {
    let interface = serde_json::json!([{"name": "start", "arclength": 0.0}, {"name": "mid", "arclength": 0.3}]);
    let spec: crate::spec::ModelSpec = serde_json::from_value(serde_json::json!({
        "name": "bad", "gravity": [0, 0], "ground_points": [], "bodies": [], "beams": [],
        "modal_bodies": [arm_json(1.0, SECTION, 2, interface, 1, 0.0, 0.0)],
        "joints": [], "drivers": [], "forces": [], "sensors": []
    }))
    .unwrap();
    let message = compile(&spec).unwrap_err().to_string();
    assert!(message.contains("modal_bodies[0].interface[1].arclength") && message.contains("every 0.25 m"), "{message}");
}

/// The slider-crank of `beam_tests::slider_crank` with its rod a stiff modal body (interface
/// nodes at both ends: the pins), or rigid, and the rod-slider pin ideal or with clearance.
pub(super) fn slider_crank(modal_rod: bool, clearance: bool) -> Model {
    let (l, rho_a, rho_i) = (0.12, 1.75, 3.3e-5);
    let rigid_rod = serde_json::json!({"name": "rod", "mass": rho_a * l, "inertia": rho_a * l * l * l / 12.0 + rho_i * l, "position": [0.11, 0], "angle": 0,
                                       "velocity": [0, 3.75], "angular_velocity": -62.5, "points": [{"name": "start", "position": [-0.06, 0]}, {"name": "end", "position": [0.06, 0]}]});
    let modal = serde_json::json!({"name": "rod", "structure": {"from": "beam", "start": [0.05, 0.0], "end": [0.17, 0.0],
        "section": section_json([4.7e9, 1.6e9, 8.9e4, rho_a, rho_i]), "mesh": {"order": "quadratic", "elements": 4, "element_length": null}},
        "interface": [{"name": "start", "arclength": 0.0}, {"name": "end", "arclength": l}], "normal_modes": 2, "damping_ratio": 0.2, "damping_time": 0.0, "points": [],
        "velocity": [0.0, 7.5], "angular_velocity": -62.5});
    let crank = serde_json::json!({"name": "crank", "mass": 0.3, "inertia": 1e-4, "position": [0.025, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
        "points": [{"name": "O", "position": [-0.025, 0]}, {"name": "A", "position": [0.025, 0]}]});
    let slider = serde_json::json!({"name": "slider", "mass": 0.14, "inertia": 1e-4, "position": [0.17, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
        "points": [{"name": "B", "position": [0, 0]}]});
    let b = if clearance {
        serde_json::json!({"type": "clearance_revolute", "name": "B", "bearing": "slider.B", "journal": "rod.end",
            "bearing_radius": 0.01, "clearance": 0.0005, "length": 0.04,
            "bearing_material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3}, "journal_material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3},
            "contact": {"law": "lankarani_nikravesh", "restitution": 0.9}, "stiffness": {"law": "hertz_cylinder"},
            "friction": {"law": "ambrosio", "coefficient": 0.01, "v0": 1e-4, "v1": 1e-3},
            "initial_eccentricity": [0.0, 0.0], "lock_at_assembly": true, "onset_velocity_floor": 1e-4, "max_penetration": null, "lubrication": null})
    } else {
        serde_json::json!({"type": "revolute", "name": "B", "first": "rod.end", "second": "slider.B"})
    };
    let (bodies, modal_bodies) = if modal_rod { (vec![crank, slider], vec![modal]) } else { (vec![crank, rigid_rod, slider], vec![]) };
    model(serde_json::json!({
        "name": "slider-crank", "gravity": [0, 0],
        "ground_points": [{"name": "O", "position": [0, 0]}, {"name": "line", "position": [0, 0]}],
        "bodies": bodies, "beams": [], "modal_bodies": modal_bodies,
        "joints": [{"type": "revolute", "name": "O", "first": "ground.O", "second": "crank.O"},
                   {"type": "revolute", "name": "A", "first": "crank.A", "second": "rod.start"},
                   b,
                   {"type": "translational", "name": "guide", "first": "ground.line", "second": "slider.B", "axis": [1, 0]}],
        "drivers": [{"name": "motor", "joint": "O", "function": {"kind": "constant_rate", "initial": 0, "rate": 150.0}}],
        "forces": [], "sensors": []
    }))
}

#[test]
fn a_stiff_modal_rod_reproduces_the_rigid_slider_crank_and_carries_a_clearance_joint() {
    // the rod (E 100 times steel's) starts unstressed, its axial constraint mode (about 7e5 rad/s)
    // damped at 20 % by the modal damping and the L-stable second-order formula
    let run = run_slider_crank;
    let explicit = IntegratorOptions { rtol: 1e-9, atol: 1e-12, ..IntegratorOptions::default() };
    let implicit = IntegratorOptions { method: Method::NumericalDifferentiation, max_order: 2, rtol: 1e-8, atol: 1e-11, ..IntegratorOptions::default() };
    let baumgarte = Stabilization::Baumgarte { alpha: 50.0, beta: 50.0 };
    let differences = |clearance: bool| {
        let rigid = run(&slider_crank(false, clearance), explicit.clone(), Stabilization::Projection);
        let modal = run(&slider_crank(true, clearance), implicit.clone(), baumgarte);
        let (x_rigid, a_rigid) = (rigid.channel("slider.x").unwrap(), rigid.channel("slider.ax").unwrap());
        let (x_modal, a_modal) = (modal.channel("slider.x").unwrap(), modal.channel("slider.ax").unwrap());
        let peak = a_rigid.iter().fold(0.0_f64, |m, a| m.max(a.abs()));
        let worst_x = (5..x_rigid.len()).map(|k| (x_rigid[k] - x_modal[k]).abs()).fold(0.0, f64::max);
        let worst_a = (5..x_rigid.len()).map(|k| (a_rigid[k] - a_modal[k]).abs()).fold(0.0, f64::max);
        (worst_x, worst_a / peak, modal)
    };
    // ideal pins at both interface nodes: the rigid mechanism's motion (seen: 1.5e-8 m, 3e-7 of the peak acceleration)
    let (worst_x, worst_a, _) = differences(false);
    assert!(worst_x < 1e-6 && worst_a < 2e-3, "slider x differs by {worst_x} m, ax by {worst_a} of its peak");
    // a clearance joint with the journal on the rod's end node: impacts happen, and their sequence
    // (sensitive to the rod's small flexibility) keeps the slider within the clearance of the rigid
    // rod's (seen: 0.21 mm of 0.5 mm)
    let (worst_x, _, modal) = differences(true);
    let contact = modal.channel("B.contact").unwrap();
    assert!(contact.iter().filter(|c| **c != 0.0).count() > 5, "the journal on the modal rod touches its bearing");
    assert!(worst_x < 0.0005, "slider x differs by {worst_x} m, more than the clearance");
}

/// The end slope [rad] at rest of a 1 m modal link (SECTION, 6 elements, both ends interface
/// nodes, frame `frame`) pinned to the ground at its start, its end on a light slider along x
/// pushed toward the start by `thrust` [N], bending under its own weight.
fn end_slope_of_a_pinned_link_under_thrust(frame: &str, thrust: f64) -> f64 {
    let interface = serde_json::json!([{"name": "start", "arclength": 0.0}, {"name": "end", "arclength": 1.0}]);
    let mut arm = arm_json(1.0, SECTION, 6, interface, 4, 1.0, 0.0);
    arm["frame"] = serde_json::json!(frame);
    arm["velocity"] = serde_json::json!([0.0, 0.0]);
    let m = model(serde_json::json!({
        "name": "pinned link under thrust", "gravity": [0, -9.81], "ground_points": [{"name": "O", "position": [0, 0]}, {"name": "line", "position": [0, 0]}],
        "bodies": [{"name": "slider", "mass": 0.01, "inertia": 1e-6, "position": [1.0, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0, "points": [{"name": "B", "position": [0, 0]}]}],
        "beams": [], "modal_bodies": [arm],
        "joints": [{"type": "revolute", "name": "O", "first": "ground.O", "second": "arm.start"},
                   {"type": "revolute", "name": "B", "first": "arm.end", "second": "slider.B"},
                   {"type": "translational", "name": "guide", "first": "ground.line", "second": "slider.B", "axis": [1, 0]}],
        "drivers": [],
        "forces": [{"type": "point_force", "name": "thrust", "point": "slider.B", "fx": {"kind": "constant", "value": -thrust}, "fy": {"kind": "constant", "value": 0.0}}],
        "sensors": []
    }));
    // (the link starts in its quasi-static deflection, the settled state of the damped run this test once
    // waited for; 1 s at rest confirms it)
    let (state, _) = settle(&m, 1.0, (1e-9, 1e-12), 0.1);
    let body = m.bodies.iter().position(|b| matches!(b.kind, BodyKind::Modal(_))).unwrap();
    node_frame(&m, body, state.coordinates(), 12).angle
}

#[test]
fn a_pinned_link_under_thrust_bends_as_linear_theory_says_in_the_chord_frame_not_in_the_clamped_one() {
    // simply supported under its weight q = rho A g: the end section turns by q L^3 / (24 EI)
    // (shear tilts the axis, not the section). A linear modal body has no geometric stiffening, so a thrust
    // along the pins must leave that slope alone; the geometrically exact beam-column would
    // steepen it by 3 (tan u - u) / u^3 = 1.43 at 300 N (u = L/2 sqrt(P/EI); Timoshenko and Gere).
    let q = SECTION[3] * 9.81;
    let linear = q / (24.0 * SECTION[2]);
    let chord_free = end_slope_of_a_pinned_link_under_thrust("chord", 0.0);
    let chord = end_slope_of_a_pinned_link_under_thrust("chord", 300.0);
    // (seen: 7e-12 and 2e-11: the thrust stays along the chord frame's axis)
    assert!((chord_free / linear - 1.0).abs() < 1e-8, "without thrust: {chord_free} rad vs {linear} rad");
    assert!((chord / linear - 1.0).abs() < 1e-8, "under 300 N: {chord} rad vs {linear} rad");
    // in a frame clamped at the first pin the thrust crosses the frame's axis in proportion to the
    // deflection: a false geometric stiffness, neither linear nor the beam-column
    // (seen: 0.75 of the linear slope)
    let clamped = end_slope_of_a_pinned_link_under_thrust("clamped", 300.0);
    assert!((clamped / linear - 1.0).abs() > 0.1, "clamped frame: {clamped} rad vs {linear} rad");
}
