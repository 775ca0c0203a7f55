//! The body contract checked against what it must equal independently of
//! its code: finite differences of the marker position, the virtual work of
//! a point force, `v^T M v / 2` from the inverse mass, and the point
//! acceleration along a motion.

use super::*;
use crate::kinematics::marker::BodyIndex;
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
