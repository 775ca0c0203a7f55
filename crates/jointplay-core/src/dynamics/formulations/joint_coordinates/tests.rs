//! The joint-coordinate formulation against things outside it: finite
//! differences of its own placement (velocities, `R`, bias accelerations),
//! and the absolute formulation with constraints and multipliers, which shares
//! only the bodies and the force elements with it, on a tree that holds every
//! kind of edge (revolute and translational joints either way round, a fixed
//! joint, angle and displacement drivers with acceleration, a free body, a
//! joint axis that turns with its body).

use super::*;
use crate::kinematics::planar::Frame;
use crate::dynamics::{assemble, compile, simulate, Model, SimulationOptions, Workspace};
use crate::integrate::IntegratorOptions;
use crate::spec::ModelSpec;

fn model(json: &str) -> Model {
    let spec: ModelSpec = serde_json::from_str(json).expect("valid json spec");
    compile(&spec).unwrap_or_else(|e| panic!("{e}"))
}

/// Every kind of tree edge, under gravity, with springs across branches.
fn every_edge_kind() -> Model {
    model(
        r#"{
        "name": "tree", "gravity": [0, -9.81],
        "ground_points": [{"name": "O", "position": [0, 0]}, {"name": "line", "position": [-0.23, -0.1]},
                          {"name": "P", "position": [0, -0.2]}],
        "bodies": [
          {"name": "crank", "mass": 0.3, "inertia": 1e-4, "position": [0.025, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "O", "position": [-0.025, 0]}, {"name": "A", "position": [0.025, 0]}]},
          {"name": "rod", "mass": 0.21, "inertia": 2.5e-4, "position": [0.11, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "A", "position": [-0.06, 0]}, {"name": "B", "position": [0.06, 0]}, {"name": "E", "position": [0.0, 0.01]}]},
          {"name": "slider", "mass": 0.14, "inertia": 1e-4, "position": [0.17, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "B", "position": [0, 0]}]},
          {"name": "tip", "mass": 0.05, "inertia": 1e-5, "position": [0.2, 0.0], "angle": 0.3, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "T", "position": [-0.03, 0]}]},
          {"name": "sleeve", "mass": 0.02, "inertia": 1e-6, "position": [0.13, 0.01], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "S", "position": [0, 0]}]},
          {"name": "float", "mass": 0.1, "inertia": 1e-5, "position": [0.3, 0.1], "angle": 0.2, "velocity": [0.1, -0.2], "angular_velocity": 3,
            "points": [{"name": "F", "position": [0.01, 0]}]},
          {"name": "pusher", "mass": 0.4, "inertia": 1e-4, "position": [0, -0.2], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "P", "position": [0, 0]}]}
        ],
        "joints": [
          {"type": "revolute", "name": "O", "first": "ground.O", "second": "crank.O"},
          {"type": "revolute", "name": "A", "first": "rod.A", "second": "crank.A"},
          {"type": "translational", "name": "guide", "first": "slider.B", "second": "ground.line", "axis": [1, 0.25]},
          {"type": "fixed", "name": "weld", "first": "tip.T", "second": "rod.B"},
          {"type": "translational", "name": "rail", "first": "rod.E", "second": "sleeve.S", "axis": [1, 0]},
          {"type": "translational", "name": "lift", "first": "ground.P", "second": "pusher.P", "axis": [0, 1]}
        ],
        "drivers": [
          {"name": "motor", "joint": "O", "function": {"kind": "polynomial", "coefficients": [0, 20, 300]}},
          {"name": "jack", "joint": "lift", "function": {"kind": "sine", "offset": 0, "amplitude": 0.01, "frequency": 20, "phase": 0}}
        ],
        "beams": [], "sensors": [], "forces": [
          {"type": "spring_damper", "name": "link", "first": "rod.B", "second": "slider.B", "stiffness": 2000, "damping": 1, "free_length": 0},
          {"type": "spring_damper", "name": "return", "first": "rod.A", "second": "sleeve.S", "stiffness": 50, "damping": 0.01, "free_length": 0.07},
          {"type": "spring_damper", "name": "tether", "first": "ground.O", "second": "float.F", "stiffness": 100, "damping": 0, "free_length": 0.2},
          {"type": "spring_damper", "name": "bridge", "first": "pusher.P", "second": "float.F", "stiffness": 30, "damping": 0.1, "free_length": 0.3}
        ]
        }"#,
    )
}

fn tree(model: &Model) -> &JointTree {
    model.joint_tree.as_ref().unwrap_or_else(|why| panic!("no tree: {why}"))
}

/// An assembled joint state `(theta, theta_dot)` of the model with nonzero rates everywhere.
fn moving_state(model: &Model) -> (Vec<f64>, Vec<f64>) {
    let tree = tree(model);
    let n = tree.n_dofs;
    let theta: Vec<f64> = (0..n).map(|k| 0.01 + 0.02 * k as f64).collect();
    let theta_dot: Vec<f64> = (0..n).map(|k| 0.7 - 0.3 * k as f64).collect();
    (theta, theta_dot)
}

#[test]
fn the_tree_holds_every_body_once_with_one_coordinate_per_free_joint() {
    let m = every_edge_kind();
    let tree = tree(&m);
    // crank driven (0), rod revolute (1), slider (1), tip fixed (0), sleeve (1), float free (3), pusher driven (0)
    assert_eq!(tree.n_dofs, 6);
    assert_eq!(tree.edges.len(), m.bodies.len());
    let mut children: Vec<usize> = tree.edges.iter().map(|e| e.child.0).collect();
    children.sort_unstable();
    assert_eq!(children, (1..=m.bodies.len()).collect::<Vec<_>>());
    // parents come first
    for (k, edge) in tree.edges.iter().enumerate() {
        assert!(edge.parent.is_ground() || tree.edges[..k].iter().any(|e| e.child == edge.parent));
    }
    let driven = tree.edges.iter().filter(|e| matches!(e.coordinate, EdgeCoordinate::Driven(_))).count();
    assert_eq!(driven, 2);
}

#[test]
fn a_joint_closing_a_loop_leaves_the_model_to_absolute_coordinates() {
    let json = r#"{
        "name": "four-bar", "gravity": [0, 0],
        "ground_points": [{"name": "A", "position": [0, 0]}, {"name": "D", "position": [0.1, 0]}],
        "bodies": [
          {"name": "crank", "mass": 1, "inertia": 1e-3, "position": [0, 0.025], "angle": 1.5707963267948966, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "A", "position": [-0.025, 0]}, {"name": "B", "position": [0.025, 0]}]},
          {"name": "coupler", "mass": 1, "inertia": 1e-3, "position": [0.05, 0.05], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "B", "position": [-0.05, 0]}, {"name": "C", "position": [0.05, 0]}]},
          {"name": "rocker", "mass": 1, "inertia": 1e-3, "position": [0.1, 0.025], "angle": 1.5707963267948966, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "D", "position": [-0.025, 0]}, {"name": "C", "position": [0.025, 0]}]}
        ],
        "joints": [
          {"type": "revolute", "name": "A", "first": "ground.A", "second": "crank.A"},
          {"type": "revolute", "name": "B", "first": "crank.B", "second": "coupler.B"},
          {"type": "revolute", "name": "C", "first": "coupler.C", "second": "rocker.C"},
          {"type": "revolute", "name": "D", "first": "ground.D", "second": "rocker.D"}
        ],
        "drivers": [], "beams": [], "sensors": [], "forces": []
    }"#;
    let m = model(json);
    let why = m.joint_tree.as_ref().expect_err("a four-bar is a loop");
    assert!(why.contains("closes a loop"), "{why}");
    // asked for joint coordinates anyway: a clear error, not a wrong run
    let mut ws = Workspace::new(&m);
    let mut state = assemble(&m, 0.0, &mut ws).unwrap();
    let options = SimulationOptions { formulation: Formulation::JointCoordinates, ..Default::default() };
    let outcome = simulate(&m, &mut state, 0.01, &options, None);
    let message = outcome.error.expect("refused").to_string();
    assert!(message.contains("closes a loop") && message.contains("absolute"), "{message}");
    // and by default it runs in absolute coordinates
    let outcome = simulate(&m, &mut state, 0.001, &SimulationOptions::default(), None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    assert_eq!(outcome.formulation, Formulation::Absolute);
}

/// Frames placed at `(t, theta, theta_dot)`.
fn placed(tree: &JointTree, m: &Model, t: f64, theta: &[f64], theta_dot: &[f64]) -> Vec<Frame> {
    let mut frames = vec![Frame::GROUND; m.bodies.len() + 1];
    tree.place(t, theta, theta_dot, &mut frames);
    frames
}

/// `theta + h theta_dot`.
fn advanced(theta: &[f64], theta_dot: &[f64], h: f64) -> Vec<f64> {
    theta.iter().zip(theta_dot).map(|(x, v)| x + h * v).collect()
}

#[test]
fn placed_velocities_are_the_time_derivative_of_placed_positions() {
    let m = every_edge_kind();
    let tree = tree(&m);
    let (theta, theta_dot) = moving_state(&m);
    let (t, h) = (0.013, 1e-6);
    let frames = placed(tree, &m, t, &theta, &theta_dot);
    let ahead = placed(tree, &m, t + h, &advanced(&theta, &theta_dot, h), &theta_dot);
    let behind = placed(tree, &m, t - h, &advanced(&theta, &theta_dot, -h), &theta_dot);
    for b in 1..frames.len() {
        let velocity = (ahead[b].position - behind[b].position) / (2.0 * h);
        let omega = (ahead[b].angle - behind[b].angle) / (2.0 * h);
        assert!((velocity - frames[b].velocity).norm() < 1e-7, "body {b}: {velocity:?} vs {:?}", frames[b].velocity);
        assert!((omega - frames[b].angular_velocity).abs() < 1e-7, "body {b}");
    }
}

#[test]
fn the_velocity_map_and_bias_match_finite_differences_of_the_placement() {
    let m = every_edge_kind();
    let tree = tree(&m);
    let (theta, theta_dot) = moving_state(&m);
    let (n, nv, t, h) = (tree.n_dofs, m.layout.nv, 0.013, 1e-6);
    let mut frames = vec![Frame::GROUND; m.bodies.len() + 1];
    let (mut r, mut bias) = (vec![0.0; nv * n], vec![0.0; nv]);
    tree.place_and_linearise(t, &theta, &theta_dot, &mut frames, &mut r, &mut bias);
    let velocities = |frames: &[Frame]| -> Vec<f64> {
        frames[1..].iter().flat_map(|f| [f.velocity.x, f.velocity.y, f.angular_velocity]).collect()
    };
    // column k of R: the body velocities of a unit rate of coordinate k at frozen time (drivers at rest)
    for k in 0..n {
        let mut unit = vec![0.0; n];
        unit[k] = 1.0;
        let at_rest = velocities(&placed(tree, &m, t, &theta, &vec![0.0; n]));
        let moved = velocities(&placed(tree, &m, t, &theta, &unit));
        for row in 0..nv {
            let column = moved[row] - at_rest[row];
            assert!((column - r[row * n + k]).abs() < 1e-12, "R[{row}][{k}] = {} vs {column}", r[row * n + k]);
        }
    }
    // b: the body accelerations along theta(t) = theta + t theta_dot (no joint acceleration)
    let ahead = velocities(&placed(tree, &m, t + h, &advanced(&theta, &theta_dot, h), &theta_dot));
    let behind = velocities(&placed(tree, &m, t - h, &advanced(&theta, &theta_dot, -h), &theta_dot));
    for row in 0..nv {
        let fd = (ahead[row] - behind[row]) / (2.0 * h);
        assert!((fd - bias[row]).abs() < 1e-5 * (1.0 + fd.abs()), "b[{row}] = {} vs {fd}", bias[row]);
    }
}

#[test]
fn the_joint_state_of_placed_frames_is_the_state_placed() {
    let m = every_edge_kind();
    let tree = tree(&m);
    let (theta, theta_dot) = moving_state(&m);
    let frames = placed(tree, &m, 0.02, &theta, &theta_dot);
    let (mut back, mut back_dot) = (vec![0.0; tree.n_dofs], vec![0.0; tree.n_dofs]);
    tree.joint_state(&frames, &mut back, &mut back_dot);
    for k in 0..tree.n_dofs {
        assert!((back[k] - theta[k]).abs() < 1e-14 && (back_dot[k] - theta_dot[k]).abs() < 1e-13, "coordinate {k}");
    }
}

fn run(m: &Model, formulation: Formulation) -> crate::dynamics::SimulationOutcome {
    let mut ws = Workspace::new(m);
    let mut state = assemble(m, 0.0, &mut ws).unwrap();
    let integrator = IntegratorOptions { rtol: 1e-11, atol: 1e-13, output_step: Some(1e-3), ..Default::default() };
    let options = SimulationOptions { integrator, position_tolerance: Some(1e-13), formulation, ..Default::default() };
    let outcome = simulate(m, &mut state, 0.06, &options, None);
    assert!(outcome.error.is_none(), "{formulation:?}: {:?}", outcome.error);
    outcome
}

#[test]
fn joint_coordinates_reproduce_the_absolute_formulation_channel_by_channel() {
    // independent check: the absolute formulation solves constraints with multipliers;
    // the two share only the bodies and force elements
    let m = every_edge_kind();
    let joint = run(&m, Formulation::Auto);
    let absolute = run(&m, Formulation::Absolute);
    assert_eq!(joint.formulation, Formulation::JointCoordinates);
    assert_eq!(absolute.formulation, Formulation::Absolute);
    let (a, b) = (&joint.trajectory, &absolute.trajectory);
    assert_eq!(a.time, b.time);
    for info in m.channel_infos() {
        let (x, y) = (a.channel(&info.name).unwrap(), b.channel(&info.name).unwrap());
        let scale = y.iter().fold(0.0_f64, |s, v| s.max(v.abs()));
        let difference = x.iter().zip(&y).fold(0.0_f64, |d, (p, q)| d.max((p - q).abs()));
        // both integrate to rtol 1e-11: agreement to 1e-7 of the channel's range, measured
        // 4e-10 at worst (a reaction, a driver effort or an acceleration off by a term differs
        // by percent); 1e-9 absolute for channels that are zero up to round-off
        assert!(difference <= 1e-7 * scale + 1e-9, "{}: differs by {difference:e} (range {scale:e})", info.name);
    }
    // the reactions are not trivially zero: the motor works, the jack pushes, the weld carries the tip
    for name in ["motor.torque", "jack.force", "weld.moment", "guide.f", "rail.f", "A.f"] {
        let peak = a.channel(name).unwrap().iter().fold(0.0_f64, |s, v| s.max(v.abs()));
        assert!(peak > 1e-3, "{name} peak {peak}");
    }
}

#[test]
fn a_free_tree_conserves_energy_in_joint_coordinates() {
    // the same tree without drivers or dampers: total energy is constant
    let json = r#"{
        "name": "double pendulum and slider", "gravity": [0, -9.81],
        "ground_points": [{"name": "O", "position": [0, 0]}, {"name": "line", "position": [0, -0.5]}],
        "bodies": [
          {"name": "upper", "mass": 1.0, "inertia": 0.01, "position": [0.15, 0.0], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "O", "position": [-0.15, 0]}, {"name": "K", "position": [0.15, 0]}]},
          {"name": "lower", "mass": 0.5, "inertia": 0.004, "position": [0.3, -0.1], "angle": -1.5707963267948966, "velocity": [0, 0], "angular_velocity": 2,
            "points": [{"name": "K", "position": [-0.1, 0]}]},
          {"name": "cart", "mass": 2.0, "inertia": 0.1, "position": [0.1, -0.5], "angle": 0, "velocity": [0.5, 0], "angular_velocity": 0,
            "points": [{"name": "C", "position": [0, 0]}]}
        ],
        "joints": [
          {"type": "revolute", "name": "O", "first": "ground.O", "second": "upper.O"},
          {"type": "revolute", "name": "K", "first": "upper.K", "second": "lower.K"},
          {"type": "translational", "name": "track", "first": "ground.line", "second": "cart.C", "axis": [1, 0]}
        ],
        "drivers": [],
        "beams": [], "sensors": [], "forces": [{"type": "spring_damper", "name": "coupling", "first": "lower.K", "second": "cart.C", "stiffness": 200, "damping": 0, "free_length": 0.4}]
    }"#;
    let m = model(json);
    let outcome = run(&m, Formulation::JointCoordinates);
    let energy = outcome.trajectory.channel("system.energy").unwrap();
    let kinetic = outcome.trajectory.channel("system.kinetic_energy").unwrap();
    let swing = kinetic.iter().fold(0.0_f64, |s, v| s.max(*v));
    let drift = energy.iter().fold(0.0_f64, |d, e| d.max((e - energy[0]).abs()));
    assert!(swing > 0.1, "the mechanism moves ({swing} J)");
    assert!(drift < 1e-8 * swing, "energy drifts by {drift:e} J of {swing} J");
}

#[test]
fn a_tree_without_coordinates_moves_as_driven_with_the_closed_form_motor_torque() {
    // a crank turned at a constant rate omega under gravity: no joint coordinate is left, the
    // accelerations are the bias alone, and the motor holds the weight, torque = m g d cos(theta)
    let (m_crank, d, omega, g) = (0.3, 0.025, 40.0, 9.81);
    let json = format!(
        r#"{{
        "name": "driven crank", "gravity": [0, -{g}],
        "ground_points": [{{"name": "O", "position": [0, 0]}}],
        "bodies": [
          {{"name": "crank", "mass": {m_crank}, "inertia": 1e-4, "position": [{d}, 0.0], "angle": 0, "velocity": [0, {v}], "angular_velocity": {omega},
            "points": [{{"name": "O", "position": [-{d}, 0]}}]}}
        ],
        "joints": [{{"type": "revolute", "name": "O", "first": "ground.O", "second": "crank.O"}}],
        "drivers": [{{"name": "motor", "joint": "O", "function": {{"kind": "polynomial", "coefficients": [0, {omega}]}}}}],
        "beams": [], "sensors": [], "forces": []
        }}"#,
        v = omega * d
    );
    let m = model(&json);
    assert_eq!(tree(&m).n_dofs, 0);
    let outcome = run(&m, Formulation::JointCoordinates);
    let trajectory = &outcome.trajectory;
    let (angle, torque) = (trajectory.channel("crank.angle").unwrap(), trajectory.channel("motor.torque").unwrap());
    let (ax, ay) = (trajectory.channel("crank.ax").unwrap(), trajectory.channel("crank.ay").unwrap());
    for (k, &t) in trajectory.time.iter().enumerate() {
        let theta = omega * t;
        assert!((angle[k] - theta).abs() < 1e-12, "angle at {t}");
        // the centre's centripetal acceleration omega^2 d towards the pivot
        assert!((ax[k] + omega * omega * d * theta.cos()).abs() < 1e-9 && (ay[k] + omega * omega * d * theta.sin()).abs() < 1e-9, "acceleration at {t}");
        let expected = m_crank * g * d * theta.cos();
        assert!((torque[k] - expected).abs() < 1e-12 + 1e-9 * expected.abs(), "torque at {t}: {} vs {expected}", torque[k]);
    }
}

#[test]
fn a_non_finite_rate_stops_the_evaluation_naming_the_first_element_it_reaches() {
    // the rate, NaN, reaches the dampers' forces and the bias accelerations (not R,
    // which depends on positions only): the check made as the bodies' accelerations
    // are formed sees it and names the first force element whose outputs are not finite
    let m = every_edge_kind();
    let tree = tree(&m);
    let (theta, theta_dot) = moving_state(&m);
    let mut ws = Workspace::new(&m);
    let memory = m.initial_memory();
    let finite: Vec<f64> = theta.iter().chain(&theta_dot).copied().collect();
    assert!(joint_accelerations(&m, tree, &memory, 0.01, &finite, &mut ws).is_ok());
    let mut y = finite.clone();
    y[tree.n_dofs] = f64::NAN;
    match joint_accelerations(&m, tree, &memory, 0.01, &y, &mut ws) {
        Err(crate::error::SimulationError::NonFinite { time, element }) => {
            assert_eq!(time, 0.01);
            assert_eq!(element, "link");
        }
        other => panic!("expected a non-finite error, got {other:?}"),
    }
}
