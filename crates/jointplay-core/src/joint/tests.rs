//! Finite-difference checks of every constraint primitive: the Jacobian
//! against `dPhi/dq`, `nu` against `-dPhi/dt`, and `gamma` against the
//! second time derivative of `Phi` along a smooth trajectory; and the loads a
//! primitive reports against `-Phi_q^T lambda` by virtual work.

use super::*;
use crate::kinematics::frames::Frames;
use crate::body::{BodyKind, PlanarRigidBody};
use crate::kinematics::marker::{BodyIndex, Marker};
use crate::kinematics::planar::{cross, Frame, Vec2};
use crate::dynamics::{Body, JacobianPattern, MarkerColumns};
use crate::motion::{Sine, TimeFunction};

const N: usize = 6; // two bodies

fn frames_at(q: &[f64], qdot: &[f64]) -> Vec<Frame> {
    vec![Frame::GROUND, Frame::from_coordinates(&q[0..3], &qdot[0..3]), Frame::from_coordinates(&q[3..6], &qdot[3..6])]
}

fn primitives() -> Vec<ConstraintKind> {
    let a = Marker::at(BodyIndex(1), Vec2::new(0.3, -0.1));
    let b = Marker::at(BodyIndex(2), Vec2::new(-0.2, 0.25));
    let g = Marker::at(BodyIndex::GROUND, Vec2::new(0.1, 0.05));
    let sine = Target::Driven(TimeFunction::Sine(Sine { offset: 0.2, amplitude: 0.3, frequency: 1.3, phase: 0.4 }));
    vec![
        ConstraintKind::PointCoincidence(PointCoincidence { first: a, second: b, offset: Vec2::new(0.01, -0.02) }),
        ConstraintKind::PointCoincidence(PointCoincidence { first: g, second: b, offset: Vec2::zeros() }),
        ConstraintKind::RelativeAngle(RelativeAngle { first: Marker::reference(BodyIndex(1)), second: Marker::reference(BodyIndex(2)), target: sine.clone() }),
        ConstraintKind::AxialProjection(AxialProjection { first: a, second: b, direction: Vec2::new(0.6, 0.8), target: sine }),
        ConstraintKind::AxialProjection(AxialProjection { first: g, second: b, direction: Vec2::new(0.0, 1.0), target: Target::Fixed(0.1) }),
    ]
}

// a smooth trajectory q(t) = q0 + v t + a t^2 / 2
const Q0: [f64; N] = [0.1, -0.2, 0.7, 0.4, 0.3, -1.1];
const V: [f64; N] = [0.5, -0.3, 2.0, -0.7, 0.2, 1.5];
const A: [f64; N] = [1.0, 0.4, -3.0, 0.6, -2.0, 4.0];

fn trajectory(t: f64) -> ([f64; N], [f64; N]) {
    let mut q = [0.0; N];
    let mut qd = [0.0; N];
    for k in 0..N {
        q[k] = Q0[k] + V[k] * t + 0.5 * A[k] * t * t;
        qd[k] = V[k] + A[k] * t;
    }
    (q, qd)
}

fn residual(c: &ConstraintKind, q: &[f64], t: f64) -> Vec<f64> {
    let mut out = vec![0.0; c.n_equations()];
    c.residual(&Frames { planar: &frames_at(q, &[0.0; N]), spatial: &[] }, t, &mut out);
    out
}

/// Two planar rigid bodies, laid out in order (three velocity coordinates each).
fn bodies() -> Vec<Body> {
    (0..2).map(|k| Body { name: format!("b{k}"), kind: BodyKind::PlanarRigid(PlanarRigidBody::new(1.0 + k as f64, 0.1)), velocity_start: crate::dynamics::VelocityStart::Approximate }).collect()
}

/// The pattern of the primitive's rows: a block per non-ground marker, over its body's three coordinates.
fn pattern_of(c: &ConstraintKind) -> JacobianPattern {
    let mut pattern = JacobianPattern::default();
    let columns = |m: Marker| (!m.body.is_ground()).then(|| {
        let first = 3 * (m.body.0 - 1);
        MarkerColumns { body: m.body.0 - 1, body_columns: first..first + 3, columns: first..first + 3 }
    });
    pattern.push_rows(c.n_equations(), c.markers().map(columns));
    pattern
}

/// The primitive's Jacobian, `nu` and `gamma` at `(q, qd, t)`, the Jacobian dense (m x N).
fn linearised(c: &ConstraintKind, q: &[f64], qd: &[f64], t: f64) -> (DenseJacobian, Vec<f64>, Vec<f64>) {
    let m = c.n_equations();
    let pattern = pattern_of(c);
    let bodies = bodies();
    let mut values = vec![0.0; pattern.n_values()];
    let (mut nu, mut gamma) = (vec![0.0; m], vec![0.0; m]);
    let rows = ConstraintRows { jacobian: &mut values, pattern: &pattern, bodies: &bodies, row: 0, nu: &mut nu, gamma: &mut gamma };
    c.linearise(&Frames { planar: &frames_at(q, qd), spatial: &[] }, t, rows);
    let jac = DenseJacobian((0..m).map(|r| std::array::from_fn(|k| pattern.entry(&values, r, k))).collect());
    (jac, nu, gamma)
}

struct DenseJacobian(Vec<[f64; N]>);

impl DenseJacobian {
    fn get(&self, r: usize, col: usize) -> f64 {
        self.0[r][col]
    }
}

#[test]
fn jacobian_nu_and_gamma_match_finite_differences() {
    let t = 0.37;
    for (k, c) in primitives().iter().enumerate() {
        let m = c.n_equations();
        let (q, qd) = trajectory(t);
        let (jac, nu, gamma) = linearised(c, &q, &qd, t);
        // jacobian column by column
        let h = 1e-6;
        for col in 0..N {
            let (mut qp, mut qm) = (q, q);
            qp[col] += h;
            qm[col] -= h;
            let (rp, rm) = (residual(c, &qp, t), residual(c, &qm, t));
            for r in 0..m {
                let fd = (rp[r] - rm[r]) / (2.0 * h);
                assert!((jac.get(r, col) - fd).abs() < 1e-8, "primitive {k} row {r} col {col}: {} vs {fd}", jac.get(r, col));
            }
        }
        // nu: dPhi/dt along the trajectory = J qdot - nu
        let ht = 1e-5;
        let phi = |tt: f64| residual(c, &trajectory(tt).0, tt);
        let (pp, p0, pm) = (phi(t + ht), phi(t), phi(t - ht));
        for r in 0..m {
            let jqd: f64 = (0..N).map(|col| jac.get(r, col) * qd[col]).sum();
            let jqdd: f64 = (0..N).map(|col| jac.get(r, col) * A[col]).sum();
            let d1 = (pp[r] - pm[r]) / (2.0 * ht);
            let d2 = (pp[r] - 2.0 * p0[r] + pm[r]) / (ht * ht);
            assert!((jqd - nu[r] - d1).abs() < 1e-7, "primitive {k} row {r}: nu {}", jqd - nu[r] - d1);
            assert!((jqdd - gamma[r] - d2).abs() < 2e-4, "primitive {k} row {r}: gamma {} vs {}", jqdd - gamma[r], d2);
        }
    }
}

#[test]
fn the_loads_of_a_primitive_are_minus_its_jacobian_transpose_times_the_multipliers() {
    let t = 0.37;
    let (q, qd) = trajectory(t);
    let frames = frames_at(&q, &qd);
    for (k, c) in primitives().iter().enumerate() {
        let (jac, _, _) = linearised(c, &q, &qd, t);
        let lambda: Vec<f64> = (0..c.n_equations()).map(|r| 1.7 - 2.3 * r as f64).collect();
        let loads = c.loads(&Frames { planar: &frames, spatial: &[] }, &lambda);
        for (slot, marker) in c.markers().iter().enumerate() {
            if marker.body.is_ground() {
                continue;
            }
            // the generalised force of the load on the body: force, and its moment about the centre of mass
            let (load, frame) = (&loads[slot], &frames[marker.frame]);
            let generalised = [load.force.x, load.force.y, load.moment + cross(load.point - frame.position, load.force)];
            for (i, g) in generalised.iter().enumerate() {
                let col = 3 * (marker.body.0 - 1) + i;
                let expected: f64 = -(0..c.n_equations()).map(|r| jac.get(r, col) * lambda[r]).sum::<f64>();
                assert!((g - expected).abs() < 1e-12, "primitive {k} slot {slot} coordinate {i}: {g} vs {expected}");
            }
        }
    }
}
