//! Rank of the constraint equations at a configuration: how many are
//! redundant (linearly dependent on the others, as the third bar of a double
//! parallelogram or a shaft in two bearings) and which elements own them.
//! `jointplay check` reports it; the simulation handles dependent equations
//! anyway (`constraint_solution.rs`), with the reactions of the dependent
//! directions chosen by minimum norm.

use nalgebra::{DMatrix, SymmetricEigen};

use super::equations::{linearise_constraints, update_frames};
use super::{Model, State, Workspace};

/// A singular value of `Phi_q` below this fraction of the largest counts as zero:
/// the same relative level at which the constraint solution takes its singular path
/// (its pivots are squares of singular values, so the square root of its tolerance).
const RELATIVE_SINGULAR_VALUE: f64 = 1e-5;

/// A row whose weight in a dependent combination of rows exceeds this takes part in it.
const PARTICIPATION: f64 = 1e-6;

/// Rank of the constraint equations and the elements of the dependent ones.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ConstraintRank {
    /// Equations active during the simulation.
    pub n_equations: usize,
    /// Their rank at the configuration.
    pub rank: usize,
    /// Names of the elements whose equations take part in a dependency (model order).
    pub dependent_elements: Vec<String>,
}

impl ConstraintRank {
    /// Equations that are linearly dependent on the others.
    pub fn n_redundant(&self) -> usize {
        self.n_equations - self.rank
    }
}

/// Rank of the dynamic constraint equations of `model` at `state`.
pub fn constraint_rank(model: &Model, state: &State, ws: &mut Workspace) -> ConstraintRank {
    let n = model.n_coordinates();
    let (q, qdot) = state.y[..2 * n].split_at(n);
    update_frames(model, q, qdot, &mut ws.frames);
    let rows = linearise_constraints(model, model.n_dynamic_constraints, state.time, ws);
    let jacobian = DMatrix::from_fn(rows, n, |r, k| jacobian_entry(model, ws, r, k));
    // Phi_q Phi_q^T: its eigenvalues are the squared singular values, its null vectors the dependencies
    let eigen = SymmetricEigen::new(&jacobian * jacobian.transpose());
    let largest = eigen.eigenvalues.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let threshold = RELATIVE_SINGULAR_VALUE * RELATIVE_SINGULAR_VALUE * largest;
    let mut rank = 0;
    let mut dependent_rows = vec![false; rows];
    for (i, value) in eigen.eigenvalues.iter().enumerate() {
        if *value > threshold {
            rank += 1;
            continue;
        }
        for (r, weight) in eigen.eigenvectors.column(i).iter().enumerate() {
            dependent_rows[r] |= weight.abs() > PARTICIPATION;
        }
    }
    let mut owners: Vec<usize> = (0..rows).filter(|&r| dependent_rows[r]).map(|r| model.row_owner[r]).collect();
    owners.dedup();
    owners.sort_unstable();
    owners.dedup();
    ConstraintRank { n_equations: rows, rank, dependent_elements: owners.into_iter().map(|e| model.elements[e].name.clone()).collect() }
}

/// Entry (r, k) of the constraint Jacobian, from the row's body blocks.
fn jacobian_entry(model: &Model, ws: &Workspace, r: usize, k: usize) -> f64 {
    ws.jacobian[r].iter().zip(model.row_bodies[r]).filter(|&(_, body)| body == k / 3).map(|(block, _)| block[k % 3]).sum()
}
