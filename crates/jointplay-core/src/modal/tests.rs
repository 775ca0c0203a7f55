//! The modal body checked against what it must equal independently of its
//! code: the beam mesh it is reduced from (natural frequencies, static
//! response, kinetic energy of its nodes), Lagrange's equations formed by
//! finite differences of its kinetic energy, the gradient of its potential,
//! finite differences of its markers' positions and the virtual work of a
//! point force.

use nalgebra::DMatrix;

use crate::beam::{BeamSection, ElementOrder};
use crate::body::{BeamBody, BeamMesh, BodyKind, BodyModel, ModalBody};
use crate::kinematics::marker::{BodyIndex, Marker, ModalNodeSite, Site};
use crate::kinematics::planar::{Frame, Vec2};
use crate::kinematics::spatial::Vec3;
use crate::modal::{FrameReference, NodalCoordinates};

/// A 1 m beam (EI = 100 N m^2, rho A = 2 kg/m) of `elements` quadratic elements, placed at an angle.
fn beam(elements: usize) -> BeamBody {
    let section = BeamSection { axial_stiffness: 2.0e6, shear_stiffness: 8.0e5, bending_stiffness: 100.0, mass_per_length: 2.0, rotary_inertia_per_length: 1.0e-4 };
    BeamBody::straight(Vec2::new(0.3, -0.2), Vec2::new(0.3 + 0.6, -0.2 + 0.8), section, BeamMesh { order: ElementOrder::Quadratic, elements }, 0.0).unwrap()
}

/// The beam's modal body with both ends as interface nodes and `normal` fixed-interface modes.
fn modal(elements: usize, normal: usize) -> ModalBody {
    let b = beam(elements);
    let last = b.n_nodes() - 1;
    ModalBody::from_beam(&b, &[0, last], FrameReference::Clamped, normal, 0.0).unwrap().0
}

/// The 3-element, 4-mode modal body as a body kind, at the positions and velocities of [`state`].
fn moving_body() -> (BodyKind, Vec<f64>, Vec<f64>) {
    let body = modal(3, 4);
    let (q, v) = state(&body);
    (BodyKind::Modal(Box::new(body)), q, v)
}

/// A state of the modal body away from every special value.
fn state(body: &ModalBody) -> (Vec<f64>, Vec<f64>) {
    let n = body.n_coordinates();
    let q: Vec<f64> = (0..n).map(|k| if k < 3 { [0.4, -0.3, 0.9][k] } else { 0.01 * (1.3 * k as f64).sin() }).collect();
    let v: Vec<f64> = (0..n).map(|k| if k < 3 { [1.2, -0.7, 2.5][k] } else { 0.3 * (0.7 * k as f64).cos() }).collect();
    (q, v)
}

fn relative_errors(got: &[f64], reference: &[f64]) -> Vec<f64> {
    got.iter().zip(reference).map(|(g, r)| (g / r - 1.0).abs()).collect()
}

#[test]
fn the_modal_frequencies_converge_to_the_beam_meshs_as_modes_are_added() {
    // reference: the full mesh (40 quadratic elements, 243 coordinates), clamped-free and free-free
    let mesh = beam(40);
    let (free, clamped) = mesh.natural_frequencies(3).unwrap();
    let mut previous = (f64::INFINITY, f64::INFINITY);
    for normal in [1, 2, 4, 8, 16] {
        let body = ModalBody::from_beam(&mesh, &[0, mesh.n_nodes() - 1], FrameReference::Clamped, normal, 0.0).unwrap().0;
        let reduced_clamped: Vec<f64> = body.held_frequencies().iter().take(3).map(|w| w / (2.0 * std::f64::consts::PI)).collect();
        let reduced_free = body.free_frequencies().unwrap();
        let worst_clamped = relative_errors(&reduced_clamped, &clamped).into_iter().fold(0.0, f64::max);
        let worst_free = relative_errors(&reduced_free[..3], &free).into_iter().fold(0.0, f64::max);
        // Rayleigh-Ritz: never below the mesh, and closer with every mode added
        for (r, m) in reduced_clamped.iter().zip(&clamped).chain(reduced_free.iter().zip(&free)) {
            assert!(*r >= m * (1.0 - 1e-9), "{normal} modes: {r} Hz below the mesh's {m} Hz");
        }
        assert!(worst_clamped <= previous.0 * (1.0 + 1e-9) && worst_free <= previous.1 * (1.0 + 1e-9), "{normal} modes: {worst_clamped:.2e}, {worst_free:.2e} after {previous:?}");
        previous = (worst_clamped, worst_free);
    }
    // with 3 constraint modes and 16 normal modes, the three lowest of each within 1e-4
    // (seen: 1.4e-5 clamped-free, 8.3e-5 free-free; with 8 normal modes 1.3e-4 and 6.1e-4)
    assert!(previous.0 < 1e-4 && previous.1 < 1e-4, "{previous:?}");
    // the first bending frequency for the spin warning: the clamped-free one
    let body = ModalBody::from_beam(&mesh, &[0, mesh.n_nodes() - 1], FrameReference::Clamped, 8, 0.0).unwrap().0;
    assert!((body.first_bending_frequency().unwrap() / clamped[0] - 1.0).abs() < 1e-6);
}

#[test]
fn a_chord_frame_spans_the_clamped_frames_motions_and_holds_the_link_simply_supported() {
    // the same interface nodes give the same span of motions (rigid motions plus the static
    // shapes of all six interface coordinates plus the normal modes), whichever three the frame
    // holds: the free-free frequencies agree to rounding
    let mesh = beam(20);
    let ends = [0, mesh.n_nodes() - 1];
    let chord = ModalBody::from_beam(&mesh, &ends, FrameReference::Chord, 8, 0.0).unwrap();
    let clamped = ModalBody::from_beam(&mesh, &ends, FrameReference::Clamped, 8, 0.0).unwrap().0;
    let (a, b) = (chord.0.free_frequencies().unwrap(), clamped.free_frequencies().unwrap());
    for (x, y) in a.iter().zip(&b).take(6) {
        assert!((x / y - 1.0).abs() < 1e-9, "free-free {x} Hz (chord) vs {y} Hz (clamped)");
    }
    // the frame's angle is the chord's (the beam runs along (0.6, 0.8)) and the first interface
    // node its origin
    assert!((chord.1[2] - 0.8_f64.atan2(0.6)).abs() < 1e-12 && (chord.1[0] - 0.3).abs() < 1e-12 && (chord.1[1] + 0.2).abs() < 1e-12, "{:?}", chord.1);
    // held at its reference conditions the link is simply supported: Euler-Bernoulli
    // f_n = (n pi)^2 sqrt(EI / rho A) / (2 pi L^2), lowered by rotary inertia and shear to first
    // order by (n pi / L)^2 (rho I / rho A + EI / k G A) / 2 (Timoshenko, "On the correction for
    // shear of the differential equation for transverse vibrations of prismatic bars", 1921);
    // seen: 8.6e-4, 3.4e-3, 7.5e-3 below Euler-Bernoulli, within 2e-4 of the corrected value
    let held: Vec<f64> = chord.0.held_frequencies().iter().map(|w| w / (2.0 * std::f64::consts::PI)).collect();
    for (n, f) in held.iter().take(3).enumerate() {
        let k = (n + 1) as f64 * std::f64::consts::PI;
        let euler_bernoulli = k * k * (100.0_f64 / 2.0).sqrt() / (2.0 * std::f64::consts::PI);
        let timoshenko = euler_bernoulli * (1.0 - 0.5 * k * k * (1.0e-4 / 2.0 + 100.0 / 8.0e5));
        assert!((f / timoshenko - 1.0).abs() < 3e-4, "mode {}: {f} Hz vs {timoshenko} Hz", n + 1);
    }
    // a chord frame needs two interface nodes, apart
    assert!(ModalBody::from_beam(&mesh, &[0], FrameReference::Chord, 2, 0.0).unwrap_err().contains("second interface node"));
}

#[test]
fn a_tip_load_deflects_the_reduced_body_exactly_as_the_mesh_and_as_timoshenko() {
    // constraint modes make a static load at an interface node exact (Craig and Bampton 1968):
    // K_ee eta = Phi^T f reproduces the mesh's clamped response, whatever the normal modes
    let mesh = beam(10);
    let body = ModalBody::from_beam(&mesh, &[0, mesh.n_nodes() - 1], FrameReference::Clamped, 2, 0.0).unwrap().0;
    let kind = BodyKind::Modal(Box::new(body.clone()));
    let tip = Marker { body: BodyIndex(1), frame: 2, site: Site::ModalNode(ModalNodeSite { node: (mesh.n_nodes() - 1) as u32 }), local: Vec2::zeros() };
    let n = body.n_coordinates();
    // the body at rest with its frame on the x axis
    let (q0, v0) = (vec![0.0; n], vec![0.0; n]);
    let (frame, tip_frame) = (kind.frame(&q0, &v0, &Frame::GROUND), kind.site_frame(&tip.site, &q0, &v0, &Frame::GROUND));
    let force = Vec2::new(0.0, -10.0);
    let mut load = vec![0.0; n];
    kind.add_point_force(&frame, &tip_frame, &tip, tip_frame.position, force, &mut load);
    let m = body.n_modes();
    let k = DMatrix::from_row_slice(m, m, body.modal_stiffness());
    let eta = k.cholesky().unwrap().solve(&nalgebra::DVector::from_column_slice(&load[3..]));
    let mut q = q0.clone();
    q[3..].copy_from_slice(eta.as_slice());
    let deflection = kind.site_frame(&tip.site, &q, &v0, &Frame::GROUND).position - tip_frame.position;
    // Timoshenko: P L^3 / (3 EI) + P L / (k G A)
    let (length, p): (f64, f64) = (1.0, 10.0);
    let expected = p * length.powi(3) / (3.0 * 100.0) + p * length / 8.0e5;
    assert!((deflection.y + expected).abs() < 1e-6 * expected, "{} m vs {expected} m", deflection.y);
    assert!(deflection.x.abs() < 1e-12, "a transverse load does not stretch the linear model: {}", deflection.x);
}

#[test]
fn the_modal_kinetic_energy_is_the_beam_meshs_for_the_same_nodal_velocities() {
    // the nodes' velocities from the modal body's own node frames, then v^T M v / 2 with
    // the beam's consistent mass in the inertial frame (a beam's mass is constant there)
    let mesh = beam(3);
    let body = ModalBody::from_beam(&mesh, &[0, mesh.n_nodes() - 1], FrameReference::Clamped, 4, 0.0).unwrap().0;
    let kind = BodyKind::Modal(Box::new(body.clone()));
    let (q, v) = state(&body);
    let mut nodal = Vec::new();
    for a in 0..body.n_nodes() {
        let frame = kind.site_frame(&Site::ModalNode(ModalNodeSite { node: a as u32 }), &q, &v, &Frame::GROUND);
        nodal.extend([frame.velocity.x, frame.velocity.y, frame.angular_velocity]);
    }
    let (mass, _) = mesh.dense_mass_and_stiffness(&mesh.reference_coordinates());
    let w = nalgebra::DVector::from_vec(nodal);
    let expected = 0.5 * w.dot(&(&mass * &w));
    let got = kind.kinetic_energy(&q, &v);
    assert!((got - expected).abs() < 1e-12 * expected, "{got} J vs {expected} J");
    assert!((body.mass() - 2.0).abs() < 1e-12);
}

/// `M(q)` from the kinetic energy by polarisation: `M_ij = T(e_i + e_j) - T(e_i) - T(e_j)`.
fn mass_from_energy(kind: &BodyKind, q: &[f64]) -> DMatrix<f64> {
    let n = q.len();
    let unit = |i: usize, j: usize| (0..n).map(|k| if k == i || k == j { 1.0 } else { 0.0 }).collect::<Vec<f64>>();
    let t = |v: &[f64]| kind.kinetic_energy(q, v);
    DMatrix::from_fn(n, n, |i, j| if i == j { 2.0 * t(&unit(i, i)) } else { t(&unit(i, j)) - t(&unit(i, i)) - t(&unit(j, j)) })
}

#[test]
fn the_mass_solve_inverts_the_mass_of_the_kinetic_energy() {
    let (kind, q, v) = moving_body();
    let mass = mass_from_energy(&kind, &q);
    let f = &mass * nalgebra::DVector::from_column_slice(&v);
    let mut solved = vec![0.0; v.len()];
    let mut scratch = vec![0.0; kind.mass_scratch_len()];
    kind.solve_mass(&q, f.as_slice(), &mut solved, &mut scratch);
    for (s, v) in solved.iter().zip(&v) {
        assert!((s - v).abs() < 1e-9 * v.abs().max(1.0), "{s} vs {v}");
    }
}

#[test]
fn the_body_forces_are_lagranges_velocity_terms_minus_the_elastic_force() {
    // Q_v = dT/dq - (dM/dq . q_dot) q_dot by central differences of the kinetic energy
    // (Lagrange's equations M q_ddot = Q_v + Q), and K eta the gradient of the strain energy
    let (kind, q, v) = moving_body();
    let n = q.len();
    let h = 1e-6;
    let shifted = |k: usize, d: f64| {
        let mut p = q.clone();
        p[k] += d;
        p
    };
    let along = |d: f64| q.iter().zip(&v).map(|(q, v)| q + d * v).collect::<Vec<f64>>();
    let m_dot_v = (mass_from_energy(&kind, &along(h)) - mass_from_energy(&kind, &along(-h))) / (2.0 * h) * nalgebra::DVector::from_column_slice(&v);
    let mut got = vec![0.0; n];
    kind.add_body_forces(&q, &v, &mut got);
    for k in 0..n {
        let kinetic = (kind.kinetic_energy(&shifted(k, h), &v) - kind.kinetic_energy(&shifted(k, -h), &v)) / (2.0 * h);
        let strain = (kind.potential_energy(Vec3::zeros(), &shifted(k, h)) - kind.potential_energy(Vec3::zeros(), &shifted(k, -h))) / (2.0 * h);
        let expected = kinetic - m_dot_v[k] - strain;
        assert!((got[k] - expected).abs() < 1e-5 * expected.abs().max(1.0), "coordinate {k}: {} vs {expected}", got[k]);
    }
}

#[test]
fn gravity_is_minus_the_gradient_of_its_potential() {
    let (kind, q, _) = moving_body();
    let g = Vec3::new(0.5, -9.81, 0.0);
    let mut weight = vec![0.0; q.len()];
    kind.add_gravity(g, &q, &mut weight);
    let h = 1e-6;
    for k in 0..q.len() {
        let (mut plus, mut minus) = (q.clone(), q.clone());
        plus[k] += h;
        minus[k] -= h;
        let gravity = |q: &[f64]| kind.potential_energy(g, q) - kind.potential_energy(Vec3::zeros(), q);
        let gradient = (gravity(&plus) - gravity(&minus)) / (2.0 * h);
        assert!((gradient + weight[k]).abs() < 1e-7, "coordinate {k}: {} vs {}", weight[k], -gradient);
    }
    // the weight on the frame is m g
    assert!((weight[1] - 2.0 * -9.81).abs() < 1e-12);
}

#[test]
fn a_node_marker_moves_as_its_jacobian_says_and_a_point_force_does_its_virtual_work() {
    let (kind, q, v) = moving_body();
    let n = q.len();
    let marker = Marker { body: BodyIndex(1), frame: 2, site: Site::ModalNode(ModalNodeSite { node: 4 }), local: Vec2::new(0.02, -0.03) };
    let frames = |q: &[f64], v: &[f64]| (kind.frame(q, v, &Frame::GROUND), kind.site_frame(&marker.site, q, v, &Frame::GROUND));
    let (body_frame, frame) = frames(&q, &v);
    let (mut jx, mut jy) = (vec![0.0; n], vec![0.0; n]);
    assert_eq!(kind.marker_coordinates(&marker), 0..n);
    kind.marker_jacobian(&body_frame, &frame, &marker, 1.0, &mut jx, &mut jy);
    let h = 1e-6;
    for c in 0..n {
        let (mut plus, mut minus) = (q.clone(), q.clone());
        plus[c] += h;
        minus[c] -= h;
        let d = (frames(&plus, &v).1.point(marker.local) - frames(&minus, &v).1.point(marker.local)) / (2.0 * h);
        assert!((d.x - jx[c]).abs() < 1e-8 && (d.y - jy[c]).abs() < 1e-8, "coordinate {c}: {d:?} vs ({}, {})", jx[c], jy[c]);
        // the angle Jacobian
        let mut angle = vec![0.0; n];
        kind.add_marker_angle_jacobian(&marker, 1.0, &mut angle);
        let da = (frames(&plus, &v).1.angle - frames(&minus, &v).1.angle) / (2.0 * h);
        assert!((da - angle[c]).abs() < 1e-8, "angle by coordinate {c}");
    }
    // the marker's velocity is J v, and add_marker_jacobian is along . J
    let jv = Vec2::new(jx.iter().zip(&v).map(|(j, v)| j * v).sum(), jy.iter().zip(&v).map(|(j, v)| j * v).sum());
    assert!((frame.point_velocity(marker.local) - jv).norm() < 1e-12);
    let along = Vec2::new(0.6, -0.8);
    let mut projected = vec![0.0; n];
    kind.add_marker_jacobian(&body_frame, &frame, &marker, along, &mut projected);
    for c in 0..n {
        assert!((projected[c] - (along.x * jx[c] + along.y * jy[c])).abs() < 1e-14);
    }
    // a force at the point and a moment: Q . v equals f . v_P + m omega_P
    let (f, moment) = (Vec2::new(3.0, -7.0), 0.8);
    let mut generalised = vec![0.0; n];
    kind.add_point_force(&body_frame, &frame, &marker, frame.point(marker.local), f, &mut generalised);
    kind.add_moment(&marker, moment, &mut generalised);
    let power: f64 = generalised.iter().zip(&v).map(|(g, v)| g * v).sum();
    let expected = f.dot(&frame.point_velocity(marker.local)) + moment * frame.angular_velocity;
    assert!((power - expected).abs() < 1e-12 * expected.abs().max(1.0), "{power} vs {expected}");
}

#[test]
fn a_node_markers_acceleration_is_the_derivative_of_its_velocity_along_a_motion() {
    // constant coordinate accelerations a from (q, v): the point's velocity at t = +-h by the body's own kinematics
    let (kind, q, v) = moving_body();
    let n = q.len();
    let a: Vec<f64> = (0..n).map(|k| if k < 3 { [3.0, -1.5, 4.0][k] } else { 0.5 * (0.9 * k as f64).cos() }).collect();
    let marker = Marker { body: BodyIndex(1), frame: 2, site: Site::ModalNode(ModalNodeSite { node: 6 }), local: Vec2::new(-0.01, 0.04) };
    let velocity = |t: f64| {
        let q: Vec<f64> = (0..n).map(|k| q[k] + v[k] * t + 0.5 * a[k] * t * t).collect();
        let v: Vec<f64> = (0..n).map(|k| v[k] + a[k] * t).collect();
        kind.site_frame(&marker.site, &q, &v, &Frame::GROUND).point_velocity(marker.local)
    };
    let h = 1e-5;
    let expected = (velocity(h) - velocity(-h)) / (2.0 * h);
    let (body_frame, frame) = (kind.frame(&q, &v, &Frame::GROUND), kind.site_frame(&marker.site, &q, &v, &Frame::GROUND));
    let got = kind.marker_acceleration(&body_frame, &frame, &a, &marker);
    assert!((got - expected).norm() < 1e-6 * expected.norm(), "{got:?} vs {expected:?}");
    // and the bias is the acceleration at a = 0
    let bias = kind.marker_bias_acceleration(&body_frame, &frame, &marker);
    assert!((kind.marker_acceleration(&body_frame, &frame, &vec![0.0; n], &marker) - bias).norm() < 1e-12);
}

#[test]
fn bad_structures_are_refused_with_a_reason() {
    let mesh = beam(2);
    let err = |interface: &[usize], normal: usize, zeta: f64| ModalBody::from_beam(&mesh, interface, FrameReference::Clamped, normal, zeta).unwrap_err();
    assert!(err(&[], 2, 0.0).contains("at least one interface node"));
    assert!(err(&[0, 9], 2, 0.0).contains("interface node 9 is not a node"));
    assert!(err(&[0, 4, 4], 2, 0.0).contains("listed twice"));
    assert!(err(&[0], 2, -0.1).contains("damping ratio"));
    assert!(err(&[0, 4], 100, 0.0).contains("normal modes"));
    let (m, k) = mesh.dense_mass_and_stiffness(&mesh.reference_coordinates());
    let nodes = vec![Vec2::zeros(); 4];
    assert!(ModalBody::from_finite_elements(&m, &k, NodalCoordinates::TranslationsAndRotation, &nodes, &[0], FrameReference::Clamped, 1, 0.0).unwrap_err().contains("one finite position per node"));
    let mut skew = k.clone();
    skew[(3, 4)] += 1.0;
    let nodes: Vec<Vec2> = (0..mesh.n_nodes()).map(|a| Vec2::new(0.25 * a as f64, 0.0)).collect();
    assert!(ModalBody::from_finite_elements(&m, &skew, NodalCoordinates::TranslationsAndRotation, &nodes, &[0], FrameReference::Clamped, 1, 0.0).unwrap_err().contains("stiffness matrix must be symmetric"));
}

#[test]
fn a_plane_solids_nodes_have_two_coordinates_and_no_section_angle_to_clamp() {
    use crate::modal::rigid_motions;
    assert_eq!(NodalCoordinates::of_size(12, 4), Some(NodalCoordinates::TranslationsAndRotation));
    assert_eq!(NodalCoordinates::of_size(8, 4), Some(NodalCoordinates::Translations));
    assert_eq!((NodalCoordinates::of_size(10, 4), NodalCoordinates::of_size(8, 0)), (None, None));
    // the chord frame holds node 1's two translations and node 3's u_y; a clamped frame has no angle to hold
    assert_eq!(FrameReference::Chord.held_coordinates(&[1, 3], NodalCoordinates::Translations), Ok([2, 3, 7]));
    assert!(FrameReference::Clamped.held_coordinates(&[1, 3], NodalCoordinates::Translations).unwrap_err().contains("use the chord frame"));
    // the rotation about the origin moves each node by (-y, x) and has no angle row
    let [_, _, (_, rotation)] = rigid_motions(&[[1.0, 0.0], [0.0, 2.0]], NodalCoordinates::Translations);
    assert_eq!(rotation.as_slice(), &[-0.0, 1.0, -2.0, 0.0]);
}
