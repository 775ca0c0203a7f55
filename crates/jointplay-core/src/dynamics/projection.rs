//! Mass-weighted projection of positions and velocities onto the
//! constraint manifold: the minimum-norm (in the metric of `M`) corrections
//! `dq = -M^-1 Phi_q^T (Phi_q M^-1 Phi_q^T)^-1 Phi` (Newton on the
//! constraints, with the driver equations held) and
//! `dv = -M^-1 Phi_q^T (Phi_q M^-1 Phi_q^T)^-1 (Phi_q v - nu)`.

use super::equations::{
    constraint_residuals, factor_constraint_matrix, factor_constraint_matrix_at, jacobian_times, jacobian_transpose_times, linearise_constraints, singular_error, solve_constraint_matrix, update_frames,
};
use super::{Model, Workspace};
use crate::error::SimulationError;

/// Newton on `Phi(q, t) = 0` for the first `n_constraints` constraints.
/// Returns the number of iterations taken.
pub(crate) fn project_positions(
    model: &Model,
    n_constraints: usize,
    t: f64,
    q: &mut [f64],
    tolerance: f64,
    max_iterations: usize,
    ws: &mut Workspace,
) -> Result<usize, SimulationError> {
    let n = model.n_coordinates();
    let rows = model.row_offsets[n_constraints];
    if rows == 0 {
        return Ok(0);
    }
    for iteration in 0..=max_iterations {
        ws.scratch.fill(0.0);
        update_frames(model, q, &ws.scratch, &mut ws.frames);
        let (largest, row) = constraint_residuals(model, n_constraints, t, ws);
        if largest <= tolerance {
            return Ok(iteration);
        }
        if iteration == max_iterations || !largest.is_finite() {
            return Err(SimulationError::ConstraintViolation {
                time: t,
                element: model.elements[model.row_owner[row]].name.clone(),
                residual: largest,
            });
        }
        linearise_constraints(model, n_constraints, t, ws);
        factor_constraint_matrix(model, rows, ws).map_err(|d| singular_error(model, t, d))?;
        ws.multipliers[..rows].copy_from_slice(&ws.residual[..rows]);
        solve_constraint_matrix(model, rows, &ws.schur, &mut ws.multipliers);
        jacobian_transpose_times(model, rows, &ws.jacobian, &ws.multipliers, &mut ws.scratch);
        for k in 0..n {
            q[k] -= model.inverse_mass[k] * ws.scratch[k];
        }
    }
    unreachable!("the loop returns on its last iteration")
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
    let n = model.n_coordinates();
    let rows = model.row_offsets[n_constraints];
    if rows == 0 {
        return Ok(());
    }
    update_frames(model, q, qdot, &mut ws.frames);
    linearise_constraints(model, n_constraints, t, ws);
    // the velocity residuals Phi_q q_dot - nu, in the multipliers' buffer
    let residual = &mut ws.multipliers;
    jacobian_times(model, rows, &ws.jacobian, qdot, residual);
    let mut largest: f64 = 0.0;
    for (r, nu) in residual[..rows].iter_mut().zip(&ws.nu) {
        *r -= nu;
        largest = largest.max(r.abs());
    }
    if largest <= tolerance {
        return Ok(());
    }
    factor_constraint_matrix_at(model, rows, t, q, ws).map_err(|d| singular_error(model, t, d))?;
    solve_constraint_matrix(model, rows, &ws.schur, &mut ws.multipliers);
    jacobian_transpose_times(model, rows, &ws.jacobian, &ws.multipliers, &mut ws.scratch);
    for k in 0..n {
        qdot[k] -= model.inverse_mass[k] * ws.scratch[k];
    }
    Ok(())
}
