//! Beams in the engine, checked against what must hold independently of
//! their code: the marker contract against finite differences and virtual
//! work, the mass solve against the assembled element masses, conservation of
//! energy and momentum in free flight, the centrifugal stretch of the
//! spin-up beam (Simo and Vu-Quoc 1986) against its closed form, and a stiff
//! beam against the same mechanism with a rigid link.

use super::*;
use crate::body::{BodyKind, BodyModel};
use crate::kinematics::marker::Site;
use crate::kinematics::planar::{Frame, Vec2};
use crate::kinematics::spatial::Vec3;
use crate::integrate::{IntegratorOptions, Method};
use crate::spec::ModelSpec;

pub(crate) fn model(json: serde_json::Value) -> Model {
    let spec: ModelSpec = serde_json::from_value(json).expect("valid spec");
    compile(&spec).unwrap_or_else(|e| panic!("{e}"))
}

/// A free beam of `elements` quadratic elements, 2 m long, with a rigid spin `omega` [rad/s].
pub(super) fn free_beam(elements: usize, omega: f64) -> Model {
    model(serde_json::json!({
        "name": "free beam", "gravity": [0, 0], "ground_points": [], "bodies": [],
        "beams": [{"name": "beam", "start": [0.0, 0.0], "end": [2.0, 0.0],
                   "section": {"type": "resultants", "axial_stiffness": 2.0e5, "shear_stiffness": 8.0e4, "bending_stiffness": 60.0,
                               "mass_per_length": 1.5, "rotary_inertia_per_length": 2.0e-4},
                   "mesh": {"order": "quadratic", "elements": elements, "element_length": null},
                   "damping_time": 0.0, "velocity": [0.3, -1.0 * omega], "angular_velocity": omega,
                   "points": [{"name": "P", "arclength": 0.7}]}],
        "joints": [], "drivers": [], "forces": [], "sensors": []
    }))
}

fn beam_of(model: &Model) -> &crate::body::BeamBody {
    match &model.bodies[0].kind {
        BodyKind::Beam(b) => b,
        _ => panic!("body 0 is a beam"),
    }
}

/// A deformed configuration and velocities of the free beam (not a rigid motion).
pub(super) fn deformed(model: &Model) -> (Vec<f64>, Vec<f64>) {
    let mut q = model.initial_coordinates.clone();
    let mut v = model.initial_velocities.clone();
    for (k, (node, rate)) in q.chunks_exact_mut(3).zip(v.chunks_exact_mut(3)).enumerate() {
        let s = k as f64;
        node[1] += 0.05 * (0.9 * s).sin();
        node[2] += 0.1 * (0.6 * s).cos();
        rate[0] += 0.2 * (1.3 * s).cos();
        rate[2] += -0.4 * (0.5 * s).sin();
    }
    (q, v)
}

#[test]
fn a_beam_marker_moves_as_its_jacobian_says_and_a_point_force_does_its_virtual_work() {
    let m = free_beam(3, 0.0);
    let kind = &m.bodies[0].kind;
    let (q, v) = deformed(&m);
    let (_, marker) = m.points.iter().find(|(name, _)| name == "beam.P").unwrap().clone();
    let marker = crate::kinematics::marker::Marker { local: Vec2::new(0.02, -0.015), ..marker };
    let Site::Section(site) = marker.site else { panic!("a beam point has a section") };
    let point_at = |q: &[f64]| kind.site_frame(&marker.site, q, &v, &Frame::GROUND).point(marker.local);
    let frame = kind.site_frame(&marker.site, &q, &v, &Frame::GROUND);
    let block = kind.marker_coordinates(&marker);
    assert_eq!(block.len(), 9, "a section of a quadratic element moves with its three nodes");
    let (mut jx, mut jy) = (vec![0.0; 9], vec![0.0; 9]);
    kind.marker_jacobian(&Frame::GROUND, &frame, &marker, 1.0, &mut jx, &mut jy);
    let h = 1e-6;
    for (i, c) in block.clone().enumerate() {
        let (mut plus, mut minus) = (q.clone(), q.clone());
        plus[c] += h;
        minus[c] -= h;
        let d = (point_at(&plus) - point_at(&minus)) / (2.0 * h);
        assert!((d.x - jx[i]).abs() < 1e-8 && (d.y - jy[i]).abs() < 1e-8, "coordinate {c}: {d:?} vs ({}, {})", jx[i], jy[i]);
    }
    // the marker's velocity is J v, and its frame's angle the interpolated angle
    let jv = Vec2::new(jx.iter().zip(&v[block.clone()]).map(|(j, v)| j * v).sum(), jy.iter().zip(&v[block.clone()]).map(|(j, v)| j * v).sum());
    assert!((frame.point_velocity(marker.local) - jv).norm() < 1e-12);
    let expected_angle: f64 = (0..3).map(|a| site.weights[a] * q[site.first as usize + 3 * a + 2]).sum();
    assert!((frame.angle - expected_angle).abs() < 1e-15);
    // a force at the point and a moment: Q . v equals f . v_P + m omega
    let (f, moment) = (Vec2::new(3.0, -7.0), 0.8);
    let mut generalised = vec![0.0; q.len()];
    kind.add_point_force(&Frame::GROUND, &frame, &marker, frame.point(marker.local), f, &mut generalised);
    kind.add_moment(&marker, moment, &mut generalised);
    let power: f64 = generalised.iter().zip(&v).map(|(g, v)| g * v).sum();
    let expected = f.dot(&frame.point_velocity(marker.local)) + moment * frame.angular_velocity;
    assert!((power - expected).abs() < 1e-12 * expected.abs().max(1.0), "{power} vs {expected}");
    // the acceleration of the point from coordinate accelerations: bias plus J a
    let a: Vec<f64> = (0..q.len()).map(|k| (0.37 * k as f64).sin()).collect();
    let got = kind.marker_acceleration(&Frame::GROUND, &frame, &a, &marker);
    let ja = Vec2::new(jx.iter().zip(&a[block.clone()]).map(|(j, a)| j * a).sum(), jy.iter().zip(&a[block]).map(|(j, a)| j * a).sum());
    assert!((got - (ja + kind.marker_bias_acceleration(&Frame::GROUND, &frame, &marker))).norm() < 1e-12);
}

#[test]
fn the_mass_solve_inverts_the_assembled_element_masses_and_gives_the_kinetic_energy() {
    let m = free_beam(3, 0.0);
    let beam = beam_of(&m);
    let n = beam.n_coordinates();
    // the consistent mass, assembled here from the elements' own matrices
    let mut dense = vec![0.0; n * n];
    for (e, element) in beam.elements.iter().enumerate() {
        let mut me = [0.0; 81];
        element.add_mass_matrix(&mut me);
        for i in 0..9 {
            for j in 0..9 {
                dense[(6 * e + i) * n + 6 * e + j] += me[i * 9 + j];
            }
        }
    }
    let (_, v) = deformed(&m);
    let mv: Vec<f64> = (0..n).map(|i| (0..n).map(|j| dense[i * n + j] * v[j]).sum()).collect();
    let mut solved = vec![0.0; n];
    m.bodies[0].kind.solve_mass(&m.initial_coordinates, &mv, &mut solved, &mut []);
    for (s, v) in solved.iter().zip(&v) {
        assert!((s - v).abs() < 1e-10 * v.abs().max(1.0), "{s} vs {v}");
    }
    let kinetic: f64 = 0.5 * v.iter().zip(&mv).map(|(v, f)| v * f).sum::<f64>();
    assert!((m.bodies[0].kind.kinetic_energy(&m.initial_coordinates, &v) - kinetic).abs() < 1e-12 * kinetic);
    assert!((beam.mass() - 1.5 * 2.0).abs() < 1e-12);
    // gravity: its generalised force is minus the gradient of its potential energy
    let (q, _) = deformed(&m);
    let g = Vec3::new(0.5, -9.81, 0.0);
    let mut weight = vec![0.0; n];
    m.bodies[0].kind.add_gravity(g, &q, &mut weight);
    let h = 1e-6;
    for c in 0..n {
        let (mut plus, mut minus) = (q.clone(), q.clone());
        plus[c] += h;
        minus[c] -= h;
        let gradient = (beam.gravity_potential_energy(g, &plus) - beam.gravity_potential_energy(g, &minus)) / (2.0 * h);
        assert!((gradient + weight[c]).abs() < 1e-7, "coordinate {c}");
    }
}

/// Linear momentum `integral rho A r_dot dS` [kg m/s] of the free beam from its nodes' rates.
fn linear_momentum(beam: &crate::body::BeamBody, v: &[f64]) -> Vec2 {
    let mut momentum = Vec2::zeros();
    let mut weight = vec![0.0; v.len()];
    beam.add_gravity(Vec3::new(1.0, 0.0, 0.0), &[], &mut weight);
    for (node, w) in v.chunks_exact(3).zip(weight.chunks_exact(3)) {
        // (the x-weight of a node is its share of the mass)
        momentum += Vec2::new(node[0], node[1]) * w[0];
    }
    momentum
}

#[test]
fn an_undamped_beam_spinning_and_vibrating_in_free_flight_keeps_its_energy_and_momentum() {
    let m = free_beam(4, 3.0);
    let mut ws = Workspace::new(&m);
    let mut state = assemble(&m, 0.0, &mut ws).unwrap();
    // a bending vibration on top of the spin
    let nq = m.layout.nq;
    for (k, rate) in state.y[nq..].chunks_exact_mut(3).enumerate() {
        let s = k as f64 / 8.0;
        rate[1] += 0.4 * (std::f64::consts::PI * s).sin();
        rate[0] += 0.1 * (2.0 * std::f64::consts::PI * s).cos();
    }
    let start = state.clone();
    let options = SimulationOptions {
        integrator: IntegratorOptions { rtol: 1e-9, atol: 1e-12, output_step: Some(0.05), ..IntegratorOptions::default() },
        ..SimulationOptions::default()
    };
    let outcome = simulate(&m, &mut state, 1.5, &options, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    let energy = outcome.trajectory.channel("system.energy").unwrap();
    let strain = energy[0] - outcome.trajectory.channel("system.kinetic_energy").unwrap()[0];
    let (low, high) = energy.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), e| (l.min(*e), h.max(*e)));
    assert!((high - low) < 1e-7 * energy[0], "energy {} J varies by {} J", energy[0], high - low);
    // kinetic and strain energy are exchanged (the beam does vibrate)
    let kinetic = outcome.trajectory.channel("system.kinetic_energy").unwrap();
    let (kl, kh) = kinetic.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), e| (l.min(*e), h.max(*e)));
    assert!(kh - kl > 1e-3 * energy[0] && strain.abs() < 1e-12, "kinetic energy from {kl} to {kh} J");
    let beam = beam_of(&m);
    let (before, after) = (linear_momentum(beam, start.velocities()), linear_momentum(beam, state.velocities()));
    assert!((before - after).norm() < 1e-10, "{before:?} vs {after:?}");
}

/// The spin-up beam of Simo and Vu-Quoc (1986): a hub driven through the
/// speed ramp to `rate` [rad/s] over 15 s, the beam clamped to it.
pub(super) fn spin_up_beam(rate: f64, elements: usize, damping_time: f64) -> Model {
    model(serde_json::json!({
        "name": "spin-up beam", "gravity": [0, 0], "ground_points": [{"name": "O", "position": [0, 0]}],
        "bodies": [{"name": "hub", "mass": 1.0, "inertia": 1.0, "position": [0, 0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
                    "points": [{"name": "O", "position": [0, 0]}]}],
        "beams": [{"name": "beam", "start": [0.0, 0.0], "end": [10.0, 0.0],
                   "section": {"type": "resultants", "axial_stiffness": 2.8e7, "shear_stiffness": 1.0e7, "bending_stiffness": 1.4e4,
                               "mass_per_length": 1.2, "rotary_inertia_per_length": 6.0e-4},
                   "mesh": {"order": "quadratic", "elements": elements, "element_length": null},
                   "damping_time": damping_time, "velocity": [0, 0], "angular_velocity": 0, "points": []}],
        "joints": [{"type": "revolute", "name": "axis", "first": "ground.O", "second": "hub.O"},
                   {"type": "fixed", "name": "clamp", "first": "hub.O", "second": "beam.start"}],
        "drivers": [{"name": "spin", "joint": "axis", "function": {"kind": "speed_ramp", "ramp_time": 15.0, "final_rate": rate}}],
        "forces": [],
        "sensors": [{"type": "strain_gauge", "name": "root", "point": "beam.start", "fibre": 0.0}]
    }))
}

#[test]
fn the_spin_up_beam_stretches_as_the_centrifugal_closed_form_says() {
    // at a steady 6 rad/s, N(s) = rho A w^2 (L^2 - s^2)/2, so the tip moves out by
    // u = rho A w^2 L^3 / (3 EA) = 5.14e-4 m and the root carries rho A w^2 L^2 / 2 = 2160 N
    let (rate, length, rho_a, ea) = (6.0, 10.0, 1.2, 2.8e7);
    let m = spin_up_beam(rate, 4, 0.0);
    assert!(m.joint_tree.is_err(), "a beam runs in absolute coordinates");
    let mut ws = Workspace::new(&m);
    let mut state = assemble(&m, 0.0, &mut ws).unwrap();
    // the stiff beam with an A-stable implicit method (orders 1 and 2), constraints
    // stabilised by Baumgarte terms (a projection after each step would disturb the
    // formulas' history with elastic corrections)
    let options = SimulationOptions {
        integrator: IntegratorOptions { method: Method::NumericalDifferentiation, rtol: 1e-5, atol: 1e-7, output_step: Some(0.02), max_order: 2, ..IntegratorOptions::default() },
        stabilization: Stabilization::Baumgarte { alpha: 10.0, beta: 10.0 },
        ..SimulationOptions::default()
    };
    let outcome = simulate(&m, &mut state, 17.0, &options, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    let tr = &outcome.trajectory;
    let tip = m.bodies[1].kind.position_channels().len() / 3 - 1;
    let (x, y) = (tr.channel(&format!("beam.node{tip}_x")).unwrap(), tr.channel(&format!("beam.node{tip}_y")).unwrap());
    let angle = tr.channel("hub.angle").unwrap();
    // the stretch along the hub's direction over the last 2 s (steady spin), averaged over the vibration the ramp left
    let from = x.len() - 100;
    let stretch: f64 = (from..x.len()).map(|k| x[k] * angle[k].cos() + y[k] * angle[k].sin() - length).sum::<f64>() / 100.0;
    let expected = rho_a * rate * rate * length.powi(3) / (3.0 * ea);
    assert!((stretch - expected).abs() < 0.02 * expected, "stretch {stretch:.4e} m vs {expected:.4e} m");
    let root: f64 = tr.channel("root.axial_force").unwrap()[from..].iter().sum::<f64>() / 100.0;
    // the clamp's reaction moment on the beam, about the beam's first end (its marker's
    // frame), balances the bending moment at the root during the ramp
    let (clamp, bending) = (tr.channel("clamp.moment").unwrap(), tr.channel("root.bending_moment").unwrap());
    let during = 10.0_f64.div_euclid(0.02) as usize;
    // (the gauge's moment is extrapolated to the element's end from its Gauss points: 4 % here)
    assert!((clamp[during] + bending[during]).abs() < 0.06 * clamp[during].abs(), "clamp {} N m, root {} N m", clamp[during], bending[during]);
    let expected_root = 0.5 * rho_a * rate * rate * length * length;
    assert!((root - expected_root).abs() < 0.03 * expected_root, "root force {root} N vs {expected_root} N");
}

/// A slider-crank whose rod is a beam (`Some(elements)`) or a rigid body (`None`).
pub(crate) fn slider_crank(rod: Option<usize>) -> Model {
    // a 15 x 15 mm bar with the density of steel and 100 times its stiffness (E = 2.1e13 Pa);
    // the rigid rod has the beam's mass and inertia (its sections' rotary inertia included)
    let (l, rho_a, rho_i) = (0.12, 1.75, 3.3e-5);
    // (the rod's initial velocities are those of the crank turning at 150 rad/s from 0 rad)
    let rod_json = serde_json::json!([{"name": "rod", "mass": rho_a * l, "inertia": rho_a * l * l * l / 12.0 + rho_i * l, "position": [0.11, 0], "angle": 0,
                                        "velocity": [0, 3.75], "angular_velocity": -62.5, "points": [{"name": "start", "position": [-0.06, 0]}, {"name": "end", "position": [0.06, 0]}]}]);
    let beam_json = |elements: usize| serde_json::json!([{"name": "rod", "start": [0.05, 0.0], "end": [0.17, 0.0],
        "section": {"type": "resultants", "axial_stiffness": 4.7e9, "shear_stiffness": 1.6e9, "bending_stiffness": 8.9e4,
                    "mass_per_length": rho_a, "rotary_inertia_per_length": rho_i},
        "mesh": {"order": "quadratic", "elements": elements, "element_length": null},
        "damping_time": 2.0e-6, "velocity": [0, 7.5], "angular_velocity": -62.5, "points": []}]);
    let crank = serde_json::json!({"name": "crank", "mass": 0.3, "inertia": 1e-4, "position": [0.025, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
        "points": [{"name": "O", "position": [-0.025, 0]}, {"name": "A", "position": [0.025, 0]}]});
    let slider = serde_json::json!({"name": "slider", "mass": 0.14, "inertia": 1e-4, "position": [0.17, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
        "points": [{"name": "B", "position": [0, 0]}]});
    let (mut bodies, beams) = match rod {
        Some(n) => (vec![crank, slider], beam_json(n)),
        None => (vec![crank, slider], serde_json::json!([])),
    };
    if rod.is_none() {
        bodies.insert(1, rod_json[0].clone());
    }
    model(serde_json::json!({
        "name": "slider-crank", "gravity": [0, 0],
        "ground_points": [{"name": "O", "position": [0, 0]}, {"name": "line", "position": [0, 0]}],
        "bodies": bodies, "beams": beams,
        "joints": [{"type": "revolute", "name": "O", "first": "ground.O", "second": "crank.O"},
                   {"type": "revolute", "name": "A", "first": "crank.A", "second": "rod.start"},
                   {"type": "revolute", "name": "B", "first": "rod.end", "second": "slider.B"},
                   {"type": "translational", "name": "guide", "first": "ground.line", "second": "slider.B", "axis": [1, 0]}],
        "drivers": [{"name": "motor", "joint": "O", "function": {"kind": "constant_rate", "initial": 0, "rate": 150.0}}],
        "forces": [], "sensors": []
    }))
}

#[test]
fn a_very_stiff_beam_rod_reproduces_the_rigid_slider_crank() {
    // the beam starts unstressed, so its axial vibration (about 1e5 rad/s) starts
    // with the motion; its strain-rate damping (2 us) and the L-stable second-order
    // formula remove it within a few milliseconds, after which the two agree
    let run = |m: &Model, integrator: IntegratorOptions, stabilization: Stabilization| {
        let trajectory = run_slider_crank(m, integrator, stabilization);
        (trajectory.channel("slider.x").unwrap(), trajectory.channel("slider.ax").unwrap())
    };
    let explicit = IntegratorOptions { rtol: 1e-9, atol: 1e-12, ..IntegratorOptions::default() };
    let implicit = IntegratorOptions { method: Method::NumericalDifferentiation, max_order: 2, rtol: 1e-8, atol: 1e-11, ..IntegratorOptions::default() };
    let (x_rigid, a_rigid) = run(&slider_crank(None), explicit, Stabilization::Projection);
    let (x_beam, a_beam) = run(&slider_crank(Some(2)), implicit, Stabilization::Baumgarte { alpha: 50.0, beta: 50.0 });
    let peak = a_rigid.iter().fold(0.0_f64, |m, a| m.max(a.abs()));
    for k in 5..x_rigid.len() {
        assert!((x_rigid[k] - x_beam[k]).abs() < 1e-6, "sample {k}: x {} vs {}", x_rigid[k], x_beam[k]);
        // (the stiff rod's accelerations carry its vibration at the level of the tolerances:
        // 1.4 m/s^2 of 1600 at rtol 1e-8, 0.07 at 1e-9)
        assert!((a_rigid[k] - a_beam[k]).abs() < 2e-3 * peak, "sample {k}: ax {} vs {}", a_rigid[k], a_beam[k]);
    }
}

/// Runs a slider-crank test model from its assembled start to 0.05 s, samples every 1 ms; panics on an error.
pub(super) fn run_slider_crank(m: &Model, integrator: IntegratorOptions, stabilization: Stabilization) -> Trajectory {
    let mut ws = Workspace::new(m);
    let mut state = assemble(m, 0.0, &mut ws).unwrap();
    let options = SimulationOptions { integrator: IntegratorOptions { output_step: Some(1e-3), ..integrator }, stabilization, ..SimulationOptions::default() };
    let outcome = simulate(m, &mut state, 0.05, &options, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    outcome.trajectory
}
