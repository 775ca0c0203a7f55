//! A start for the assembly of a mechanism with flexible bodies in which each
//! body is moved as a whole: the least change of the bodies' poses (translation
//! and rotation of each body, its shape kept) that satisfies the joints and
//! drivers, by Gauss-Newton on the poses. The assembly's Newton, weighted by the
//! masses, moves a flexible body's nodes one by one; from a sketch far off (a
//! beam given 600 mm from the pin that holds it, a driver's start value 90 deg
//! from the given angles) it would close the equations by deforming the body,
//! where moving it closes them unstrained.

use crate::dynamics::formulations::absolute::equations::{constraint_residuals, update_frames};
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::body::BodyKind;
use nalgebra::{DMatrix, DVector};

/// Gauss-Newton iterations on the poses: from a sketch far off it needs a handful;
/// the assembly's own Newton finishes in any case.
const POSE_ITERATIONS: usize = 30;

/// Constraint residual at which the poses are close enough to hand over [m or rad].
const POSE_TOLERANCE: f64 = 1e-10;

/// Step of the finite differences of the residuals in the poses [m, or rad times the size].
const DIFFERENCE_STEP: f64 = 1e-7;

/// Positions `q` moved from the given coordinates by whole-body motions only, so that the
/// first `n_constraints` constraints hold at `t` as nearly as such motions allow.
pub(crate) fn place_bodies_rigidly(model: &Model, n_constraints: usize, t: f64, size: f64, ws: &mut Workspace) -> Vec<f64> {
    let n = 3 * model.bodies.len();
    let size = if size > 0.0 { size } else { 1.0 };
    let mut poses = DVector::<f64>::zeros(n);
    let mut q = placed(model, &poses, size);
    for _ in 0..POSE_ITERATIONS {
        let residual = residuals(model, n_constraints, t, &q, ws);
        if residual.amax() <= POSE_TOLERANCE || !residual.iter().all(|r| r.is_finite()) {
            break;
        }
        let mut jacobian = DMatrix::<f64>::zeros(residual.len(), n);
        for c in 0..n {
            let mut moved = poses.clone();
            moved[c] += DIFFERENCE_STEP;
            let column = (residuals(model, n_constraints, t, &placed(model, &moved, size), ws) - &residual) / DIFFERENCE_STEP;
            jacobian.set_column(c, &column);
        }
        // the least change of the poses (minimum-norm Gauss-Newton step)
        let Ok(step) = jacobian.svd(true, true).solve(&residual, 1e-12) else { break };
        poses -= step;
        q = placed(model, &poses, size);
    }
    q
}

/// The constraint residuals at positions `q`.
fn residuals(model: &Model, n_constraints: usize, t: f64, q: &[f64], ws: &mut Workspace) -> DVector<f64> {
    let zero = vec![0.0; model.n_velocities()];
    update_frames(model, q, &zero, &mut ws.frames, &mut ws.spatial_frames);
    constraint_residuals(model, n_constraints, t, ws);
    DVector::from_column_slice(&ws.residual[..model.row_offsets[n_constraints]])
}

/// The given coordinates with body `k` moved by `(poses[3k], poses[3k + 1])` [m] and turned by
/// `poses[3k + 2] / size` [rad] about its first position (a rigid body's centre, a beam's first
/// node, a modal body's frame), its shape kept.
fn placed(model: &Model, poses: &DVector<f64>, size: f64) -> Vec<f64> {
    let mut q = model.initial_coordinates.clone();
    for (k, (body, address)) in model.bodies.iter().zip(&model.layout.bodies).enumerate() {
        let q = &mut q[address.q_range()];
        let (tx, ty, turn) = (poses[3 * k], poses[3 * k + 1], poses[3 * k + 2] / size);
        let (s, c) = turn.sin_cos();
        let (px, py) = (q[0], q[1]);
        // every (x, y, angle) triple of the body: the one of a rigid body or a modal body's frame, all of a beam's nodes
        let triples = match body.kind {
            BodyKind::Beam(_) => q.len() / 3,
            BodyKind::PlanarRigid(_) | BodyKind::Modal(_) => 1,
            // (planar whole-body motions; a spatial body stays where it was given)
            BodyKind::SpatialRigid(_) => 0,
        };
        for node in q.chunks_exact_mut(3).take(triples) {
            let (dx, dy) = (node[0] - px, node[1] - py);
            node[0] = px + c * dx - s * dy + tx;
            node[1] = py + s * dx + c * dy + ty;
            node[2] += turn;
        }
    }
    q
}
