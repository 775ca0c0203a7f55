//! Modal bodies given by matrices (as from another finite-element code): the
//! same structure handed over as matrices in turned and shifted axes moves as
//! the modal body reduced from the beam directly, and matrices that do not fit
//! their nodes are refused with their location.

use super::beam_tests::model;
use super::*;
use crate::body::{BodyKind, BodyModel};
use crate::kinematics::marker::{ModalNodeSite, Site};
use crate::kinematics::planar::{Frame, Vec2};
use crate::integrate::{IntegratorOptions, Method};
use nalgebra::DMatrix;

/// The arm's section by its resultants: EA, GA, EI, rho A, rho I.
fn section() -> serde_json::Value {
    serde_json::json!({"type": "resultants", "axial_stiffness": 2.0e6, "shear_stiffness": 8.0e5, "bending_stiffness": 100.0,
                       "mass_per_length": 2.0, "rotary_inertia_per_length": 1.0e-4})
}

/// The interface of the arm: both ends, in each kind of description.
fn interface(by_node: bool) -> serde_json::Value {
    if by_node {
        serde_json::json!([{"name": "start", "node": 0}, {"name": "end", "node": 8}])
    } else {
        serde_json::json!([{"name": "start", "arclength": 0.0}, {"name": "end", "arclength": 1.0}])
    }
}

/// A free model of the one modal body `arm` of structure `structure`, spinning at 3 rad/s.
fn free_arm(structure: serde_json::Value, interface: serde_json::Value) -> serde_json::Value {
    serde_json::json!({
        "name": "free arm", "gravity": [0, 0], "ground_points": [], "bodies": [], "beams": [],
        "modal_bodies": [{"name": "arm", "structure": structure, "interface": interface, "points": [], "normal_modes": 3,
                          "damping_ratio": 0.0, "damping_time": 0.0, "velocity": [0.3, 0.0], "angular_velocity": 3.0}],
        "joints": [], "drivers": [], "forces": [], "sensors": []
    })
}

/// The arm from (0, 0) to (1, 0) of 4 quadratic elements, as a beam structure.
fn beam_structure() -> serde_json::Value {
    serde_json::json!({"from": "beam", "start": [0.0, 0.0], "end": [1.0, 0.0], "section": section(),
                       "mesh": {"order": "quadratic", "elements": 4, "element_length": null}})
}

/// The arm's mass and stiffness in the model's axes and its nodes [m], from the beam mesh.
fn arm_matrices() -> (DMatrix<f64>, DMatrix<f64>, Vec<[f64; 2]>) {
    let m = model(serde_json::json!({
        "name": "arm", "gravity": [0, 0], "ground_points": [], "bodies": [],
        "beams": [{"name": "arm", "start": [0.0, 0.0], "end": [1.0, 0.0], "section": section(),
                   "mesh": {"order": "quadratic", "elements": 4, "element_length": null}, "damping_time": 0.0,
                   "velocity": [0, 0], "angular_velocity": 0, "points": []}],
        "joints": [], "drivers": [], "forces": [], "sensors": []
    }));
    let BodyKind::Beam(beam) = &m.bodies[0].kind else { unreachable!("the arm is a beam") };
    let q = beam.reference_coordinates();
    let (mass, stiffness) = beam.dense_mass_and_stiffness(&q);
    (mass, stiffness, q.chunks_exact(3).map(|p| [p[0], p[1]]).collect())
}

/// Every entry of `a` in coordinate form.
fn entries(a: &DMatrix<f64>) -> serde_json::Value {
    let (mut rows, mut columns, mut values) = (vec![], vec![], vec![]);
    for i in 0..a.nrows() {
        for j in 0..a.ncols() {
            if a[(i, j)] != 0.0 {
                rows.push(i);
                columns.push(j);
                values.push(a[(i, j)]);
            }
        }
    }
    serde_json::json!({"size": a.nrows(), "rows": rows, "columns": columns, "values": values})
}

/// The arm as matrices in axes turned by `angle` [rad] and with their origin at
/// `position` [m] in the model (the matrices and nodes expressed in those axes).
fn matrices_structure(angle: f64, position: [f64; 2], scale_nodes: f64) -> serde_json::Value {
    let (mass, stiffness, nodes) = arm_matrices();
    let (sin, cos) = angle.sin_cos();
    let n = mass.nrows();
    // model axes to structure axes: u_structure = R(-angle) u_model, node by node
    let turn = DMatrix::from_fn(n, n, |i, j| match (i / 3 == j / 3, i % 3, j % 3) {
        (true, 0, 0) | (true, 1, 1) => cos,
        (true, 0, 1) => sin,
        (true, 1, 0) => -sin,
        (true, 2, 2) => 1.0,
        _ => 0.0,
    });
    let local = |a: &DMatrix<f64>| &turn * a * turn.transpose();
    let nodes: Vec<[f64; 2]> = nodes
        .iter()
        .map(|p| {
            let (dx, dy) = (p[0] - position[0], p[1] - position[1]);
            [scale_nodes * (cos * dx + sin * dy), scale_nodes * (-sin * dx + cos * dy)]
        })
        .collect();
    serde_json::json!({"from": "matrices", "mass": entries(&local(&mass)), "stiffness": entries(&local(&stiffness)), "nodes": nodes,
                       "position": position, "angle": angle})
}

/// Positions of the arm's nodes after 0.4 s of free flight (spinning, its
/// constraint modes set moving: the normal modes' signs are the eigensolver's) [m].
fn nodes_after_free_flight(m: &Model) -> Vec<Vec2> {
    let mut ws = Workspace::new(m);
    let mut state = assemble(m, 0.0, &mut ws).unwrap();
    let nq = m.layout.nq;
    // the chord frame's constraint modes: the far end's u_x and both ends' rotations
    for (j, rate) in state.y[nq + 3..nq + 6].iter_mut().enumerate() {
        *rate = 0.5 * (1.0 + j as f64).recip();
    }
    let options = SimulationOptions {
        integrator: IntegratorOptions { method: Method::NumericalDifferentiation, max_order: 2, rtol: 1e-10, atol: 1e-12, ..IntegratorOptions::default() },
        ..SimulationOptions::default()
    };
    let outcome = simulate(m, &mut state, 0.4, &options, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    let address = &m.layout.bodies[0];
    let zeros = vec![0.0; address.nv];
    (0..9).map(|node| m.bodies[0].kind.site_frame(&Site::ModalNode(ModalNodeSite { node }), &state.coordinates()[address.q_range()], &zeros, &Frame::GROUND).position).collect()
}

#[test]
fn matrices_in_turned_and_shifted_axes_move_as_the_beam_they_came_from() {
    let direct = nodes_after_free_flight(&model(free_arm(beam_structure(), interface(false))));
    let (angle, position) = (0.7, [-0.2, 0.35]);
    let given = nodes_after_free_flight(&model(free_arm(matrices_structure(angle, position, 1.0), interface(true))));
    // the same structure, the same modes (up to their signs): the same motion, to the integration tolerance
    let largest = direct.iter().zip(&given).map(|(a, b)| (a - b).norm()).fold(0.0, f64::max);
    assert!(largest < 1e-8, "nodes differ by {largest:e} m");
    // and it did move: the spin turned the arm by about 1.2 rad
    assert!((direct[8] - Vec2::new(1.0, 0.0)).norm() > 0.5);
}

/// The compile errors of the free arm of structure `structure` and interface `interface`.
fn refusal(structure: serde_json::Value, interface: serde_json::Value) -> String {
    let spec: crate::spec::ModelSpec = serde_json::from_value(free_arm(structure, interface)).unwrap();
    compile(&spec).unwrap_err().to_string()
}

#[test]
fn a_supported_structure_or_nodes_in_another_unit_are_refused_as_not_free() {
    let mut supported = matrices_structure(0.0, [0.0, 0.0], 1.0);
    // a spring of 1e4 N/m from node 0 to the ground
    let values = supported["stiffness"]["values"].as_array_mut().unwrap();
    values[0] = serde_json::json!(values[0].as_f64().unwrap() + 1e4);
    let message = refusal(supported, interface(true));
    assert!(message.contains("modal_bodies[0].matrices") && message.contains("resists a translation along x"), "{message}");
    // nodes written in millimetres beside matrices in metres: only the rotation sees it
    let message = refusal(matrices_structure(0.0, [0.0, 0.0], 1000.0), interface(true));
    assert!(message.contains("resists a rotation about the origin"), "{message}");
}

#[test]
fn matrices_that_do_not_fit_their_nodes_and_points_not_at_nodes_are_refused_with_their_location() {
    let mut short = matrices_structure(0.0, [0.0, 0.0], 1.0);
    short["nodes"].as_array_mut().unwrap().pop();
    let message = refusal(short, interface(true));
    assert!(message.contains("modal_bodies[0].matrices.mass") && message.contains("must be 24 x 24"), "{message}");
    assert!(message.contains("modal_bodies[0].interface[1].node") && message.contains("from 0 to 7, got 8"), "{message}");
    let mut outside = matrices_structure(0.0, [0.0, 0.0], 1.0);
    outside["stiffness"]["rows"][0] = serde_json::json!(27);
    assert!(refusal(outside, interface(true)).contains("modal_bodies[0].matrices.stiffness: entry (27, 0) is outside a 27 x 27 matrix"));
    let message = refusal(matrices_structure(0.0, [0.0, 0.0], 1.0), interface(false));
    assert!(message.contains("modal_bodies[0].interface[0].node") && message.contains("by its node number"), "{message}");
    let message = refusal(beam_structure(), interface(true));
    assert!(message.contains("modal_bodies[0].interface[0].arclength") && message.contains("by its arclength"), "{message}");
}

