//! The body contract checked against what it must equal independently of
//! its code: finite differences of the marker position, the virtual work of
//! a point force, `v^T M v / 2` from the inverse mass, and the point
//! acceleration along a motion; the planar kinds' spatial answers (a rigid
//! body, a beam's section, a modal body's node) against their planar ones and
//! against finite differences and the virtual power of their embedded frames.

use super::*;
use crate::kinematics::marker::{BodyIndex, MarkerFrames, Site, SpatialMarker};
use crate::kinematics::planar::Frame;

fn bar() -> BodyKind {
    BodyKind::PlanarRigid(PlanarRigidBody::new(2.5, 0.03))
}

const Q: [f64; 3] = [0.3, -0.2, 0.7];
const V: [f64; 3] = [1.1, -0.4, 2.3];
const LOCAL: Vec2 = Vec2::new(0.12, -0.05);
const MARKER: Marker = Marker::at(BodyIndex(1), LOCAL);

fn frame_at(body: &BodyKind, q: &[f64], v: &[f64]) -> Frame {
    body.frame(q, v, &Frame::GROUND)
}

#[test]
fn the_marker_jacobian_is_the_derivative_of_the_marker_position() {
    let body = bar();
    let frame = frame_at(&body, &Q, &V);
    let (mut jx, mut jy) = ([0.0; 3], [0.0; 3]);
    body.marker_jacobian(&frame, &frame, &MARKER, 1.0, &mut jx, &mut jy);
    let h = 1e-6;
    for k in 0..3 {
        let (mut plus, mut minus) = (Q, Q);
        let mut step = [0.0; 3];
        step[k] = h;
        body.displace(&mut plus, &step);
        step[k] = -h;
        body.displace(&mut minus, &step);
        let d = (frame_at(&body, &plus, &V).point(LOCAL) - frame_at(&body, &minus, &V).point(LOCAL)) / (2.0 * h);
        assert!((d.x - jx[k]).abs() < 1e-9 && (d.y - jy[k]).abs() < 1e-9, "coordinate {k}: {d:?} vs ({}, {})", jx[k], jy[k]);
    }
    // and the marker velocity is J v
    let velocity = frame.point_velocity(LOCAL);
    let jv = Vec2::new(jx.iter().zip(&V).map(|(j, v)| j * v).sum(), jy.iter().zip(&V).map(|(j, v)| j * v).sum());
    assert!((velocity - jv).norm() < 1e-14);
}

#[test]
fn a_point_force_does_the_virtual_work_of_the_force_on_the_marker_velocity() {
    let body = bar();
    let frame = frame_at(&body, &Q, &V);
    let p = frame.point(LOCAL);
    let f = Vec2::new(-40.0, 75.0);
    let mut generalised = [0.0; 3];
    body.add_point_force(&frame, &frame, &MARKER, p, f, &mut generalised);
    let power: f64 = generalised.iter().zip(&V).map(|(g, v)| g * v).sum();
    assert!((power - f.dot(&frame.point_velocity(LOCAL))).abs() < 1e-12);
    // a moment does the work m omega
    let mut moment = [0.0; 3];
    body.add_moment(&MARKER, 4.0, &mut moment);
    assert_eq!(moment.iter().zip(&V).map(|(g, v)| g * v).sum::<f64>(), 4.0 * V[2]);
}

#[test]
fn kinetic_energy_gravity_and_the_mass_solve_agree_with_the_mass_properties() {
    let body = bar();
    let mut accelerations = [0.0; 3];
    body.solve_mass(&Q, &[5.0, -2.5, 0.06], &mut accelerations, &mut []);
    assert_eq!(accelerations, [2.0, -1.0, 2.0]);
    // T = v^T M v / 2 with M the inverse of the mass block
    let MassBlock::ConstantDiagonal(w) = body.mass_block() else { panic!("a rigid body has a diagonal mass") };
    let expected: f64 = V.iter().zip(w).map(|(v, w)| 0.5 * v * v / w).sum();
    assert!((body.kinetic_energy(&Q, &V) - expected).abs() < 1e-14);
    // the gravity force is minus the gradient of its potential
    let g = Vec3::new(0.5, -9.81, 0.0);
    let mut force = [0.0; 3];
    body.add_gravity(g, &Q, &mut force);
    let h = 1e-3;
    for k in 0..3 {
        let (mut plus, mut minus) = (Q, Q);
        plus[k] += h;
        minus[k] -= h;
        let gradient = (body.potential_energy(g, &plus) - body.potential_energy(g, &minus)) / (2.0 * h);
        assert!((force[k] + gradient).abs() < 1e-9, "coordinate {k}");
    }
}

#[test]
fn the_marker_acceleration_is_the_derivative_of_its_velocity_along_a_motion() {
    // constant accelerations a from (q, v): the marker velocity at t = +-h by the body's own kinematics
    let body = bar();
    let a = [3.0, -1.5, 40.0];
    let state = |t: f64| {
        let q: Vec<f64> = (0..3).map(|k| Q[k] + V[k] * t + 0.5 * a[k] * t * t).collect();
        let v: Vec<f64> = (0..3).map(|k| V[k] + a[k] * t).collect();
        frame_at(&body, &q, &v).point_velocity(LOCAL)
    };
    let h = 1e-5;
    let expected = (state(h) - state(-h)) / (2.0 * h);
    let frame = frame_at(&body, &Q, &V);
    let got = body.marker_acceleration(&frame, &frame, &a, &MARKER);
    assert!((got - expected).norm() < 1e-6 * expected.norm(), "{got:?} vs {expected:?}");
    // q_dot = v
    let mut qdot = [0.0; 3];
    body.position_rates(&Q, &V, &mut qdot);
    assert_eq!(qdot, V);
}

/// Euler-Bernoulli `beta L` of a clamped-free and a free-free uniform beam
/// (Blevins, Formulas for Natural Frequency and Mode Shape, 1979, table 8-1).
const CLAMPED_FREE_BETA_L: [f64; 3] = [1.875_104_07, 4.694_091_13, 7.854_757_44];
const FREE_FREE_BETA_L: [f64; 3] = [4.730_040_74, 7.853_204_62, 10.995_607_84];

#[test]
fn a_slender_beam_body_has_the_euler_bernoulli_natural_frequencies() {
    use crate::beam::{BeamMaterial, BeamSection, ElementOrder, SectionShape};
    // L/h = 100: shear and rotary inertia lower the third clamped-free frequency by about 1e-3
    let steel = BeamMaterial { youngs_modulus: 207e9, poisson_ratio: 0.3, density: 7850.0 };
    let section = BeamSection::of(&SectionShape::Rectangle { width: 0.02, height: 0.01 }, &steel).unwrap();
    let length = 1.0;
    let mesh = BeamMesh { order: ElementOrder::Quadratic, elements: 12 };
    let beam = BeamBody::straight(Vec2::new(0.2, -0.1), Vec2::new(0.2 + 0.6 * length, -0.1 + 0.8 * length), section, mesh, 0.0).unwrap();
    let (free, clamped) = beam.natural_frequencies(3).unwrap();
    let unit = (section.bending_stiffness / section.mass_per_length).sqrt() / (length * length) / (2.0 * std::f64::consts::PI);
    // the beam's axial modes lie far above its first three bending modes at L/h = 100
    for (k, beta) in CLAMPED_FREE_BETA_L.iter().enumerate() {
        assert!((clamped[k] / (beta * beta * unit) - 1.0).abs() < 2e-3, "clamped-free mode {}: {} Hz", k + 1, clamped[k]);
    }
    for (k, beta) in FREE_FREE_BETA_L.iter().enumerate() {
        assert!((free[k] / (beta * beta * unit) - 1.0).abs() < 2e-3, "free-free mode {}: {} Hz", k + 1, free[k]);
    }
}

/// One planar kind with a spatial marker on one of its sites, at a state away
/// from special values: positions `q`, velocities `v`, accelerations `a`.
struct EmbeddedCase {
    name: &'static str,
    kind: BodyKind,
    marker: SpatialMarker,
    q: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
}

/// A marker 0.04 m above the plane with axes turned off the body's.
fn spatial_marker(site: Site, local: Vec2) -> SpatialMarker {
    let axes = *nalgebra::Rotation3::from_axis_angle(&nalgebra::Vector3::y_axis(), 0.4).matrix();
    SpatialMarker { body: BodyIndex(1), frame: 1, site, local: Vec3::new(local.x, local.y, 0.04), axes }
}

/// Values of `n` coordinates away from special values, of amplitude `scale`.
fn wavy(n: usize, phase: f64, scale: f64) -> Vec<f64> {
    (0..n).map(|k| scale * (phase + 1.7 * k as f64).sin()).collect()
}

/// A rigid body, a section of a beam within its second element and a node of a modal body.
fn embedded_cases() -> Vec<EmbeddedCase> {
    use crate::beam::{BeamSection, ElementOrder};
    use crate::kinematics::marker::ModalNodeSite;
    use crate::modal::FrameReference;
    let section = BeamSection { axial_stiffness: 2.0e6, shear_stiffness: 8.0e5, bending_stiffness: 100.0, mass_per_length: 2.0, rotary_inertia_per_length: 1.0e-4 };
    let mesh = BeamMesh { order: ElementOrder::Quadratic, elements: 3 };
    let beam = BeamBody::straight(Vec2::new(0.3, -0.2), Vec2::new(0.9, 0.6), section, mesh, 0.0).unwrap();
    let site = beam.site_at(0.47).unwrap();
    // (the beam's nodes moved off the straight line, so that its sections turn and stretch)
    let beam_q: Vec<f64> = beam.reference_coordinates().iter().zip(wavy(beam.n_coordinates(), 0.3, 0.02)).map(|(q, d)| q + d).collect();
    let n_beam = beam.n_coordinates();
    let (modal, pose) = ModalBody::from_beam(&beam, &[0, beam.n_nodes() - 1], FrameReference::Chord, 3, 0.0).unwrap();
    let n_modal = modal.n_coordinates();
    let mut modal_q = wavy(n_modal, 0.9, 0.005);
    for (q, p) in modal_q.iter_mut().zip(pose) {
        *q += p;
    }
    vec![
        EmbeddedCase { name: "rigid", kind: bar(), marker: spatial_marker(Site::Reference, LOCAL), q: Q.to_vec(), v: V.to_vec(), a: vec![3.0, -1.5, 40.0] },
        EmbeddedCase { name: "beam section", kind: BodyKind::Beam(beam), marker: spatial_marker(Site::Section(site), Vec2::new(0.01, -0.02)), q: beam_q, v: wavy(n_beam, 1.1, 1.5), a: wavy(n_beam, 2.0, 30.0) },
        EmbeddedCase {
            name: "modal node",
            kind: BodyKind::Modal(Box::new(modal)),
            marker: spatial_marker(Site::ModalNode(ModalNodeSite { node: 3 }), Vec2::new(-0.01, 0.03)),
            q: modal_q,
            v: wavy(n_modal, 0.2, 1.2),
            a: wavy(n_modal, 1.4, 25.0),
        },
    ]
}

impl EmbeddedCase {
    /// The planar body and site frames at `(q, v)`.
    fn planar_frames(&self, q: &[f64], v: &[f64]) -> (Frame, Frame) {
        (self.kind.frame(q, v, &Frame::GROUND), self.kind.site_frame(&self.marker.site, q, v, &Frame::GROUND))
    }

    /// The body and site frames in space at `(q, v)`.
    fn spatial_frames(&self, q: &[f64], v: &[f64]) -> (SpatialFrame, SpatialFrame) {
        let (body, site) = self.planar_frames(q, v);
        (self.kind.spatial_site_frame(&Site::Reference, q, v, &body), self.kind.spatial_site_frame(&self.marker.site, q, v, &site))
    }

    /// The marker's own spatial frame at `(q, v)`: its point, axes and their velocities.
    fn marker_frame(&self, q: &[f64], v: &[f64]) -> SpatialFrame {
        self.marker.frame_on(&self.spatial_frames(q, v).1)
    }

    /// The positions `q` displaced by `dv`.
    fn displaced(&self, dv: &[f64]) -> Vec<f64> {
        let mut q = self.q.clone();
        self.kind.displace(&mut q, dv);
        q
    }

    /// The unit velocity of coordinate `k`.
    fn unit(&self, k: usize, length: f64) -> Vec<f64> {
        let mut e = vec![0.0; self.kind.nv()];
        e[k] = length;
        e
    }

    /// Calls `check` with the marker's frames at `(q, v)`.
    fn with_frames<R>(&self, check: impl FnOnce(MarkerFrames<'_>) -> R) -> R {
        let (body, site) = self.planar_frames(&self.q, &self.v);
        let (body3, site3) = self.spatial_frames(&self.q, &self.v);
        check(MarkerFrames { body: &body, site: &site, body3: &body3, site3: &site3 })
    }
}

/// `vee(W)`: the vector of a skew-symmetric matrix `W = [w]x`.
fn vee(w: &crate::kinematics::spatial::Mat3) -> Vec3 {
    Vec3::new(w[(2, 1)] - w[(1, 2)], w[(0, 2)] - w[(2, 0)], w[(1, 0)] - w[(0, 1)]) / 2.0
}

#[test]
fn embedded_jacobians_are_the_planar_ones_and_the_derivatives_of_the_embedded_marker_frame() {
    let h = 1e-6;
    for case in embedded_cases() {
        let block = case.kind.marker_coordinates(&case.marker.planar());
        let planar = case.marker.planar();
        for (axis, along) in [Vec3::x(), Vec3::y(), Vec3::z(), Vec3::new(0.3, -0.8, 0.5)].into_iter().enumerate() {
            let (mut point, mut angular) = (vec![0.0; block.len()], vec![0.0; block.len()]);
            case.with_frames(|at| {
                case.kind.add_spatial_point_jacobian(at, &case.marker, along, &mut point);
                case.kind.add_spatial_angular_jacobian(at, &case.marker, along, &mut angular);
            });
            // against the planar Jacobians: the in-plane direction, and the z part of the turn
            let (mut planar_point, mut planar_angle) = (vec![0.0; block.len()], vec![0.0; block.len()]);
            let (body, site) = case.planar_frames(&case.q, &case.v);
            case.kind.add_marker_jacobian(&body, &site, &planar, Vec2::new(along.x, along.y), &mut planar_point);
            case.kind.add_marker_angle_jacobian(&planar, along.z, &mut planar_angle);
            assert_eq!((&point, &angular), (&planar_point, &planar_angle), "{}: direction {axis}", case.name);
            // against central differences of the embedded marker frame's point and axes
            for (k, coordinate) in block.clone().enumerate() {
                let (plus, minus) = (case.displaced(&case.unit(coordinate, h)), case.displaced(&case.unit(coordinate, -h)));
                let (up, down) = (case.marker_frame(&plus, &case.v), case.marker_frame(&minus, &case.v));
                let velocity = (up.position - down.position) / (2.0 * h);
                let turn = vee(&(up.rotation * down.rotation.transpose())) / (2.0 * h);
                assert!((along.dot(&velocity) - point[k]).abs() < 1e-8, "{}: point, coordinate {coordinate}: {} vs {}", case.name, along.dot(&velocity), point[k]);
                assert!((along.dot(&turn) - angular[k]).abs() < 1e-8, "{}: angle, coordinate {coordinate}: {} vs {}", case.name, along.dot(&turn), angular[k]);
            }
            // and J v is the marker frame's velocity and angular velocity
            let frame = case.marker_frame(&case.q, &case.v);
            let times_v = |row: &[f64]| row.iter().zip(&case.v[block.clone()]).map(|(j, v)| j * v).sum::<f64>();
            assert!((times_v(&point) - along.dot(&frame.velocity)).abs() < 1e-12, "{}", case.name);
            assert!((times_v(&angular) - along.dot(&frame.angular_velocity)).abs() < 1e-12, "{}", case.name);
        }
    }
}

#[test]
fn embedded_accelerations_are_the_planar_ones_and_the_derivatives_of_the_marker_frame_along_a_motion() {
    for case in embedded_cases() {
        let planar = case.marker.planar();
        let zero = vec![0.0; case.kind.nv()];
        let ((point, angular), (bias, angular_bias)) =
            case.with_frames(|at| (case.kind.spatial_marker_acceleration(at, &case.marker, &case.a), case.kind.spatial_bias_acceleration(at, &case.marker)));
        let (body, site) = case.planar_frames(&case.q, &case.v);
        let planar_point = case.kind.marker_acceleration(&body, &site, &case.a, &planar);
        let planar_bias = case.kind.marker_bias_acceleration(&body, &site, &planar);
        assert_eq!(point, Vec3::new(planar_point.x, planar_point.y, 0.0), "{}", case.name);
        assert_eq!(bias, Vec3::new(planar_bias.x, planar_bias.y, 0.0), "{}", case.name);
        assert_eq!(angular_bias, Vec3::zeros(), "{}", case.name);
        // along q(t) = q + v t + a t^2 / 2 (q_dot = v): central differences of the marker frame's velocities
        for (accelerations, (point, angular)) in [(&case.a, (point, angular)), (&zero, (bias, angular_bias))] {
            let at = |t: f64| {
                let dv: Vec<f64> = case.v.iter().zip(accelerations).map(|(v, a)| v * t + 0.5 * a * t * t).collect();
                let v: Vec<f64> = case.v.iter().zip(accelerations).map(|(v, a)| v + a * t).collect();
                case.marker_frame(&case.displaced(&dv), &v)
            };
            let h = 1e-5;
            let (later, earlier) = (at(h), at(-h));
            let expected_point = (later.velocity - earlier.velocity) / (2.0 * h);
            let expected_angular = (later.angular_velocity - earlier.angular_velocity) / (2.0 * h);
            let scale = 1.0 + expected_point.norm();
            assert!((point - expected_point).norm() < 1e-6 * scale, "{}: {point:?} vs {expected_point:?}", case.name);
            assert!((angular - expected_angular).norm() < 1e-6 * (1.0 + expected_angular.norm()), "{}: {angular:?} vs {expected_angular:?}", case.name);
        }
    }
}

#[test]
fn an_embedded_wrench_does_the_virtual_work_of_its_force_and_moment_on_the_marker_frame() {
    use crate::kinematics::wrench::Wrench;
    // out of the plane parts included: they do no work on a body moving in the plane
    let wrench = Wrench { force: Vec3::new(-40.0, 75.0, 12.0), moment: Vec3::new(3.0, -2.0, 4.0) };
    for case in embedded_cases() {
        let n = case.kind.nv();
        let point = case.marker_frame(&case.q, &case.v).position;
        let mut generalised = vec![0.0; n];
        case.with_frames(|at| case.kind.add_wrench(at, &case.marker, point, &wrench, &mut generalised));
        // each coordinate's unit velocity: the power of the wrench on the marker frame moving with it
        for k in 0..n {
            let moving = case.marker_frame(&case.q, &case.unit(k, 1.0));
            let power = wrench.force.dot(&moving.velocity) + wrench.moment.dot(&moving.angular_velocity);
            assert!((generalised[k] - power).abs() < 1e-12 * (1.0 + power.abs()), "{}: coordinate {k}: {} vs {power}", case.name, generalised[k]);
        }
        // and the planar point force with the moment about z
        let (body, site) = case.planar_frames(&case.q, &case.v);
        let mut planar = vec![0.0; n];
        case.kind.add_point_force(&body, &site, &case.marker.planar(), Vec2::new(point.x, point.y), Vec2::new(wrench.force.x, wrench.force.y), &mut planar);
        case.kind.add_moment(&case.marker.planar(), wrench.moment.z, &mut planar);
        assert_eq!(generalised, planar, "{}", case.name);
    }
}

#[test]
fn positions_difference_is_the_increment_displace_applies() {
    for case in embedded_cases() {
        let dv = wavy(case.kind.nv(), 0.5, 0.1);
        let moved = case.displaced(&dv);
        let mut back = vec![0.0; dv.len()];
        case.kind.difference(&case.q, &moved, &mut back);
        assert!(back.iter().zip(&dv).all(|(b, d)| (b - d).abs() < 1e-15), "{}", case.name);
        let mut normalised = moved.clone();
        case.kind.normalise_positions(&mut normalised);
        assert_eq!(normalised, moved, "{}: planar positions are always valid", case.name);
        assert_eq!((case.kind.position_channels().len(), case.kind.velocity_channels().len()), (case.kind.nq(), case.kind.nv()), "{}", case.name);
    }
}
