//! Initial velocities of a mechanism with flexible bodies: every flexible
//! body starts in a rigid motion (no strain rate), found from the joints and
//! drivers exactly as a rigid link's velocities are.
//!
//! The velocity coordinates are restricted to `v = v0 + T w`: a rigid body's
//! three coordinates are free (`T` the identity), a flexible body with no
//! velocities given moves rigidly (three columns: the velocity of its
//! reference point and its angular velocity, [`BodyKind::rigid_motion_velocities`]),
//! and a flexible body whose rigid motion was given is held (no column). The
//! correction `w` is the smallest in the kinetic-energy metric `W = T^T M T`
//! that satisfies `Phi_q (v0 + T w) = nu`: with `A = Phi_q T` and `W = L L^T`,
//! `w = L^-T pinv(A L^-T) r`, `r = nu - Phi_q v0`, the pseudo-inverse (by a
//! singular value decomposition) taking redundant joints in its stride. With
//! no flexible body this is the projection of rigid bodies' velocities
//! (`projection.rs`); only the metric and the subspace differ.

use nalgebra::{DMatrix, DVector};

use crate::dynamics::formulations::absolute::equations::jacobian_times;
use crate::kinematics::planar::Vec2;
use crate::dynamics::model::mechanism::VelocityStart;
use crate::dynamics::formulations::absolute::projection::velocity_residuals;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::body::{BodyKind, BodyModel};
use crate::error::SimulationError;

/// Singular values of `A L^-T` below this fraction of the largest are dropped
/// (redundant joints); well above rounding, well below any real lever ratio.
const RANK_TOLERANCE: f64 = 1e-10;

/// Velocity residual, relative to the velocity scale of the mechanism, above
/// which the joints contradict the held velocities [-].
const CONTRADICTION_TOLERANCE: f64 = 1e-8;

/// One column of `T`: a body and its velocity coordinates in a unit rigid motion.
struct Column {
    /// Index of the body in [`Model::bodies`].
    body: usize,
    /// The body's velocity coordinates in this motion [m/s, rad/s per unit of `w`].
    rates: Vec<f64>,
}

/// Whether assembly needs the rigid-motion start: some body is flexible.
pub(crate) fn needs_rigid_motion_start(model: &Model) -> bool {
    model.bodies.iter().any(|b| b.velocity_start != VelocityStart::Approximate)
}

/// Corrects `qdot` (approximate initial velocities, flexible bodies in the
/// rigid motion given or zero) onto the joints and drivers at `(t, q)`, as the
/// module describes; fails naming the bodies whose given velocities the joints contradict.
pub(crate) fn start_in_rigid_motion(model: &Model, t: f64, q: &[f64], qdot: &mut [f64], ws: &mut Workspace) -> Result<(), SimulationError> {
    let initial = qdot.to_vec();
    correct(model, t, q, qdot, ws, false);
    let (residual, _) = velocity_residuals(model, model.constraints.len(), t, q, qdot, ws);
    let scale = velocity_scale(&initial);
    let held: Vec<usize> = (0..model.bodies.len()).filter(|&b| model.bodies[b].velocity_start == VelocityStart::Given).collect();
    if residual <= CONTRADICTION_TOLERANCE * scale || held.is_empty() {
        return Ok(());
    }
    // the held bodies contradict the joints if freeing them satisfies them
    let mut freed = initial;
    correct(model, t, q, &mut freed, ws, true);
    let (residual_freed, _) = velocity_residuals(model, model.constraints.len(), t, q, &freed, ws);
    if residual_freed > CONTRADICTION_TOLERANCE * scale {
        return Ok(()); // locked whatever the held bodies do: the caller's check reports it
    }
    Err(contradiction(model, t, qdot, &freed, &held))
}

/// Corrects `qdot` onto the joints at `(t, q)` with every flexible body, held
/// ones too, moving rigidly: after the start's positions moved by a strain,
/// the rigid motion found (or given and checked) at the assembled positions
/// is adjusted to them by the order of that strain.
pub(crate) fn follow_rigid_motion(model: &Model, t: f64, q: &[f64], qdot: &mut [f64], ws: &mut Workspace) {
    correct(model, t, q, qdot, ws, true);
}

/// The free motions, at positions `q`, of the mechanism with every flexible
/// body rigid: the rigid motions `T w` with `Phi_q T w = 0` (`w` spanning the
/// null space of `Phi_q T`, its columns equilibrated), as velocity-coordinate vectors.
pub(crate) fn free_rigid_motions(model: &Model, t: f64, q: &[f64], ws: &mut Workspace) -> Vec<Vec<f64>> {
    let n = model.constraints.len();
    let rows = model.row_offsets[n];
    velocity_residuals(model, n, t, q, &vec![0.0; model.layout.nv], ws);
    let columns = columns(model, q, true);
    let mut a = constrained_rates(model, rows, &columns, ws);
    let scales: Vec<f64> = columns.iter().map(|c| c.rates.iter().fold(0.0_f64, |m, r| m.max(r.abs())).max(f64::MIN_POSITIVE)).collect();
    for (k, scale) in scales.iter().enumerate() {
        a.column_mut(k).scale_mut(1.0 / scale);
    }
    let gram = a.transpose() * &a;
    let eigen = gram.symmetric_eigen();
    let largest = eigen.eigenvalues.amax().max(f64::MIN_POSITIVE);
    let mut motions = Vec::new();
    for (k, value) in eigen.eigenvalues.iter().enumerate() {
        // (squared singular values: 1e-16 is a singular value of 1e-8 of the largest)
        if rows > 0 && *value > FREE_MOTION_TOLERANCE * largest {
            continue;
        }
        let mut motion = vec![0.0; model.layout.nv];
        for ((column, scale), w) in columns.iter().zip(&scales).zip(eigen.eigenvectors.column(k).iter()) {
            for (m, r) in motion[model.layout.bodies[column.body].v_range()].iter_mut().zip(&column.rates) {
                *m += w / scale * r;
            }
        }
        motions.push(motion);
    }
    motions
}

/// Eigenvalue of `(Phi_q T)^T (Phi_q T)`, relative to the largest, below which a rigid motion is free [-].
const FREE_MOTION_TOLERANCE: f64 = 1e-16;

/// `qdot += T w` with the correction `w` of the module's doc (`free_held`: the
/// held bodies move rigidly too); leaves `qdot` as it is when nothing is constrained.
fn correct(model: &Model, t: f64, q: &[f64], qdot: &mut [f64], ws: &mut Workspace, free_held: bool) {
    let n = model.constraints.len();
    let rows = model.row_offsets[n];
    if rows == 0 {
        return;
    }
    velocity_residuals(model, n, t, q, qdot, ws);
    let r = DVector::from_iterator(rows, ws.multipliers[..rows].iter().map(|x| -x));
    let columns = columns(model, q, free_held);
    if columns.is_empty() {
        return;
    }
    let a = constrained_rates(model, rows, &columns, ws);
    let Some(w) = smallest_correction(&a, &kinetic_metric(model, q, &columns), &r) else { return };
    for (column, wk) in columns.iter().zip(w.iter()) {
        let range = model.layout.bodies[column.body].v_range();
        for (v, rate) in qdot[range].iter_mut().zip(&column.rates) {
            *v += wk * rate;
        }
    }
}

/// The columns of `T` at positions `q`.
fn columns(model: &Model, q: &[f64], free_held: bool) -> Vec<Column> {
    let mut columns = Vec::new();
    for (b, (body, address)) in model.bodies.iter().zip(&model.layout.bodies).enumerate() {
        let moves = match body.velocity_start {
            VelocityStart::Approximate | VelocityStart::RigidMotion => true,
            VelocityStart::Given => free_held,
        };
        if !moves {
            continue;
        }
        for unit in [(Vec2::new(1.0, 0.0), 0.0), (Vec2::new(0.0, 1.0), 0.0), (Vec2::zeros(), 1.0)] {
            let mut rates = vec![0.0; address.nv];
            body.kind.rigid_motion_velocities(&q[address.q_range()], unit.0, unit.1, &mut rates);
            columns.push(Column { body: b, rates });
        }
    }
    columns
}

/// `A = Phi_q T` from the constraint Jacobian linearised in `ws`.
fn constrained_rates(model: &Model, rows: usize, columns: &[Column], ws: &Workspace) -> DMatrix<f64> {
    let mut a = DMatrix::zeros(rows, columns.len());
    let mut v = vec![0.0; model.layout.nv];
    let mut out = vec![0.0; rows];
    for (k, column) in columns.iter().enumerate() {
        let range = model.layout.bodies[column.body].v_range();
        v[range.clone()].copy_from_slice(&column.rates);
        jacobian_times(model, rows, &ws.jacobian, &v, &mut out);
        a.column_mut(k).copy_from_slice(&out);
        v[range].fill(0.0);
    }
    a
}

/// `W = T^T M T`, block by body, from the kinetic energy `T(v) = v^T M v / 2`
/// (exact: `a^T M b = T(a + b) - T(a) - T(b)`) [kg, kg m, kg m^2].
fn kinetic_metric(model: &Model, q: &[f64], columns: &[Column]) -> DMatrix<f64> {
    let mut w = DMatrix::zeros(columns.len(), columns.len());
    let energy = |body: usize, v: &[f64]| {
        let kind: &BodyKind = &model.bodies[body].kind;
        kind.kinetic_energy(&q[model.layout.bodies[body].q_range()], v)
    };
    for (i, ci) in columns.iter().enumerate() {
        for (j, cj) in columns.iter().enumerate().skip(i) {
            if ci.body != cj.body {
                continue;
            }
            let sum: Vec<f64> = ci.rates.iter().zip(&cj.rates).map(|(a, b)| a + b).collect();
            let value = energy(ci.body, &sum) - energy(ci.body, &ci.rates) - energy(cj.body, &cj.rates);
            w[(i, j)] = value;
            w[(j, i)] = value;
        }
    }
    w
}

/// The `w` of smallest `w^T W w` with `A w = r` (least squares where no `w`
/// satisfies it); None if `W` is not positive definite (a massless body).
fn smallest_correction(a: &DMatrix<f64>, metric: &DMatrix<f64>, r: &DVector<f64>) -> Option<DVector<f64>> {
    let factor = metric.clone().cholesky()?;
    // B = A L^-T, i.e. B^T = L^-1 A^T
    let b = factor.l().solve_lower_triangular(&a.transpose())?.transpose();
    let svd = b.svd(true, true);
    let largest = svd.singular_values.max();
    let scaled = svd.solve(r, RANK_TOLERANCE * largest.max(f64::MIN_POSITIVE)).ok()?;
    factor.l().transpose().solve_upper_triangular(&scaled)
}

/// Largest velocity of the description, floored at 1 m/s or rad/s: the scale of a contradiction.
fn velocity_scale(qdot: &[f64]) -> f64 {
    qdot.iter().fold(1.0_f64, |m, v| m.max(v.abs()))
}

/// The error naming the held bodies whose rigid motion the joints change, with
/// what they need: the velocity of the reference point and the angular velocity.
fn contradiction(model: &Model, t: f64, held: &[f64], freed: &[f64], bodies: &[usize]) -> SimulationError {
    let mut names = Vec::new();
    let mut needs = Vec::new();
    for &b in bodies {
        let range = model.layout.bodies[b].v_range();
        let (given, needed) = (&held[range.clone()], &freed[range]);
        let change = given.iter().zip(needed).fold(0.0_f64, |m, (g, n)| m.max((g - n).abs()));
        if change <= CONTRADICTION_TOLERANCE * velocity_scale(held) {
            continue;
        }
        names.push(model.bodies[b].name.clone());
        // (the first three velocity coordinates of a beam and a modal body: its reference point's velocity and angle rate)
        let [nx, ny, nw, gx, gy, gw] = [needed[0], needed[1], needed[2], given[0], given[1], given[2]].map(rounded);
        needs.push(format!("{} needs about ({nx}, {ny}) m/s at its first end and {nw} rad/s, given ({gx}, {gy}) m/s and {gw} rad/s", model.bodies[b].name));
    }
    SimulationError::ContradictoryVelocities {
        time: t,
        element: names.join(", "),
        cause: format!("{}; leave the velocities out to start in the rigid motion the joints give", needs.join("; ")),
    }
}

/// `x` with four decimals, a rounded negative zero without its sign.
fn rounded(x: f64) -> String {
    let text = format!("{x:.4}");
    match text.strip_prefix('-') {
        Some(magnitude) if magnitude.chars().all(|c| c == '0' || c == '.') => magnitude.to_string(),
        _ => text,
    }
}
