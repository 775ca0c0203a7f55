//! Mass-weighted projection of positions and velocities onto the
//! constraint manifold: the minimum-norm (in the metric of `M`) corrections
//! `dq = -M^-1 Phi_q^T (Phi_q M^-1 Phi_q^T)^-1 Phi` (Newton on the
//! constraints, with the driver equations held) and
//! `dv = -M^-1 Phi_q^T (Phi_q M^-1 Phi_q^T)^-1 (Phi_q v - nu)`.

use super::equations::{
    constraint_residuals, factor_constraint_matrix_at, jacobian_times, jacobian_transpose_times, linearise_constraints, solve_in_multipliers, update_frames,
};
use super::constraint_solution::FactorKind;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;

/// Newton iterations allowed once a projection met a singular position, where
/// the convergence is linear: halving per iteration takes 1e-3 to 1e-12 in 30.
const SINGULAR_ITERATIONS: usize = 40;

/// Factor on the position tolerance a projection at a singular position may leave (see [`singular_stagnation`]).
const SINGULAR_TOLERANCE_FACTOR: f64 = 1e3;
use crate::body::BodyModel;
use crate::error::SimulationError;

/// Newton on `Phi(q, t) = 0` for the first `n_constraints` constraints.
/// Returns the number of iterations taken and the largest |residual| left [m or rad].
pub(crate) fn project_positions(
    model: &Model,
    n_constraints: usize,
    t: f64,
    q: &mut [f64],
    tolerance: f64,
    max_iterations: usize,
    ws: &mut Workspace,
) -> Result<(usize, f64), SimulationError> {
    let rows = model.row_offsets[n_constraints];
    if rows == 0 {
        return Ok((0, 0.0));
    }
    let mut allowed = max_iterations;
    let mut iteration = 0;
    let mut previous = f64::INFINITY;
    loop {
        ws.scratch.fill(0.0);
        update_frames(model, q, &ws.scratch, &mut ws.frames, &mut ws.spatial_frames);
        let (largest, row) = constraint_residuals(model, n_constraints, t, ws);
        if largest <= tolerance || singular_stagnation(ws, largest, previous, tolerance) {
            return Ok((iteration, largest));
        }
        previous = largest;
        if iteration >= allowed || !largest.is_finite() {
            return Err(SimulationError::ConstraintViolation {
                time: t,
                element: model.elements[model.row_owner[row]].name.clone(),
                residual: largest,
            });
        }
        linearise_constraints(model, n_constraints, t, ws);
        factor_constraint_matrix_at(model, rows, t, q, ws)?;
        ws.multipliers[..rows].copy_from_slice(&ws.residual[..rows]);
        solve_in_multipliers(model, rows, ws);
        jacobian_transpose_times(model, rows, &ws.jacobian, &ws.multipliers, &mut ws.scratch);
        // the step -M^-1 Phi_q^T lambda in velocity coordinates, taken by each body
        for s in ws.scratch.iter_mut() {
            *s = -*s;
        }
        model.solve_mass(q, &ws.scratch, &mut ws.correction, &mut ws.mass_matrix);
        for (body, address) in model.bodies.iter().zip(&model.layout.bodies) {
            body.kind.displace(&mut q[address.q_range()], &ws.correction[address.v_range()]);
        }
        if ws.factor_kind == FactorKind::Spectral {
            // at a singular position Newton converges only linearly (by about half per step)
            allowed = allowed.max(SINGULAR_ITERATIONS);
        }
        iteration += 1;
    }
}

/// Whether a Newton projection at a singular position has stopped improving
/// with its residual within [`SINGULAR_TOLERANCE_FACTOR`] of the tolerance: the
/// part left lies along the dependent direction, where the equations vanish to
/// second order and no first-order step reaches it; the next steps, away from the
/// singular position, remove it.
fn singular_stagnation(ws: &Workspace, largest: f64, previous: f64, tolerance: f64) -> bool {
    ws.factor_kind == FactorKind::Spectral && largest > 0.5 * previous && largest <= SINGULAR_TOLERANCE_FACTOR * tolerance
}

/// Corrects `q_dot` so that `Phi_q q_dot = nu` for the first `n_constraints`
/// constraints, unless every velocity residual is already within `tolerance` [m/s or rad/s].
pub(crate) fn project_velocities(
    model: &Model,
    n_constraints: usize,
    t: f64,
    q: &[f64],
    qdot: &mut [f64],
    tolerance: f64,
    ws: &mut Workspace,
) -> Result<(), SimulationError> {
    let rows = model.row_offsets[n_constraints];
    if rows == 0 {
        return Ok(());
    }
    let (largest, _) = velocity_residuals(model, n_constraints, t, q, qdot, ws);
    if largest <= tolerance {
        return Ok(());
    }
    factor_constraint_matrix_at(model, rows, t, q, ws)?;
    solve_in_multipliers(model, rows, ws);
    jacobian_transpose_times(model, rows, &ws.jacobian, &ws.multipliers, &mut ws.scratch);
    model.solve_mass(q, &ws.scratch, &mut ws.correction, &mut ws.mass_matrix);
    for (v, correction) in qdot.iter_mut().zip(&ws.correction) {
        *v -= correction;
    }
    Ok(())
}

/// The velocity residuals `Phi_q q_dot - nu` of the first `n_constraints` constraints
/// into `ws.multipliers`; returns the largest |residual| [m/s or rad/s] and its row.
pub(crate) fn velocity_residuals(model: &Model, n_constraints: usize, t: f64, q: &[f64], qdot: &[f64], ws: &mut Workspace) -> (f64, usize) {
    update_frames(model, q, qdot, &mut ws.frames, &mut ws.spatial_frames);
    let rows = linearise_constraints(model, n_constraints, t, ws);
    let residual = &mut ws.multipliers;
    jacobian_times(model, rows, &ws.jacobian, qdot, residual);
    let mut largest = (0.0, 0);
    for (row, (r, nu)) in residual[..rows].iter_mut().zip(&ws.nu).enumerate() {
        *r -= nu;
        if r.abs() > largest.0 {
            largest = (r.abs(), row);
        }
    }
    largest
}
