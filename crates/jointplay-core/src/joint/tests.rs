//! Finite-difference checks of every constraint primitive: the Jacobian
//! against `dPhi/dq`, `nu` against `-dPhi/dt`, and `gamma` against the
//! second time derivative of `Phi` along a smooth trajectory.

use super::*;
use crate::dynamics::frame::{BodyIndex, Marker, Frame, Vec2};
use crate::motion::{Sine, TimeFunction};

const N: usize = 6; // two bodies

fn frames_at(q: &[f64], qdot: &[f64]) -> Vec<Frame> {
    vec![Frame::GROUND, Frame::from_coordinates(&q[0..3], &qdot[0..3]), Frame::from_coordinates(&q[3..6], &qdot[3..6])]
}

fn primitives() -> Vec<ConstraintKind> {
    let a = Marker { body: BodyIndex(1), local: Vec2::new(0.3, -0.1) };
    let b = Marker { body: BodyIndex(2), local: Vec2::new(-0.2, 0.25) };
    let g = Marker { body: BodyIndex::GROUND, local: Vec2::new(0.1, 0.05) };
    let sine = Target::Driven(TimeFunction::Sine(Sine { offset: 0.2, amplitude: 0.3, frequency: 1.3, phase: 0.4 }));
    vec![
        ConstraintKind::PointCoincidence(PointCoincidence { first: a, second: b, offset: Vec2::new(0.01, -0.02) }),
        ConstraintKind::PointCoincidence(PointCoincidence { first: g, second: b, offset: Vec2::zeros() }),
        ConstraintKind::RelativeAngle(RelativeAngle { first: BodyIndex(1), second: BodyIndex(2), target: sine.clone() }),
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
    c.residual(&frames_at(q, &[0.0; N]), t, &mut out);
    out
}

/// The dense m x N Jacobian from the rows' body blocks (the blocks of the ground dropped).
fn dense(c: &ConstraintKind, blocks: &[RowJacobian]) -> DenseJacobian {
    let mut jac = DenseJacobian(vec![[0.0; N]; blocks.len()]);
    for (r, row) in blocks.iter().enumerate() {
        for (slot, body) in c.bodies().iter().enumerate() {
            // (the test bodies are planar and laid out in order, three coordinates each)
            if !body.is_ground() {
                let col = 3 * (body.0 - 1);
                for i in 0..3 {
                    jac.0[r][col + i] += row[slot][i];
                }
            }
        }
    }
    jac
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
        let mut blocks = vec![[[f64::NAN; 3]; 2]; m];
        let (mut nu, mut gamma) = (vec![0.0; m], vec![0.0; m]);
        c.linearise(&frames_at(&q, &qd), t, ConstraintRows { jacobian: &mut blocks, row: 0, nu: &mut nu, gamma: &mut gamma });
        let jac = dense(c, &blocks);
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
