//! Rank of the constraint equations at a configuration: how many are
//! redundant (linearly dependent on the others, as the third bar of a double
//! parallelogram or a shaft in two bearings) and which elements own them.
//! `jointplay check` reports it; the simulation handles dependent equations
//! anyway (`constraint_solution.rs`), with the reactions of the dependent
//! directions chosen by minimum norm.

use nalgebra::{DMatrix, SymmetricEigen};

use super::equations::{linearise_constraints, update_frames};
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::model::state::State;
use crate::dynamics::formulations::workspace::Workspace;

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
    let n = model.n_velocities();
    let (q, v, _) = model.layout.split(&state.y);
    update_frames(model, q, v, &mut ws.frames, &mut ws.spatial_frames);
    let rows = linearise_constraints(model, model.n_dynamic_constraints, state.time, ws);
    if rows == 0 {
        return ConstraintRank::default();
    }
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
pub(crate) fn jacobian_entry(model: &Model, ws: &Workspace, r: usize, k: usize) -> f64 {
    model.jacobian_pattern.entry(&ws.jacobian, r, k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::{assemble, compile};

    fn rank_of(json: &str) -> ConstraintRank {
        let model = compile(&serde_json::from_str(json).unwrap()).unwrap();
        let mut ws = Workspace::new(&model);
        let state = assemble(&model, 0.0, &mut ws).unwrap();
        constraint_rank(&model, &state, &mut ws)
    }

    #[test]
    fn a_free_body_has_no_equations_and_a_doubled_pin_two_redundant_ones() {
        let free = rank_of(
            r#"{"name": "free", "gravity": [0, 0], "ground_points": [],
                "bodies": [{"name": "bar", "mass": 1, "inertia": 0.1, "position": [0, 0], "angle": 0, "velocity": [0, 0],
                            "angular_velocity": 0, "points": []}],
                "joints": [], "drivers": [], "beams": [], "sensors": [], "forces": []}"#,
        );
        assert_eq!((free.n_equations, free.rank, free.n_redundant()), (0, 0, 0));
        let pins = rank_of(
            r#"{"name": "pins", "gravity": [0, 0], "ground_points": [{"name": "O", "position": [0, 0]}],
                "bodies": [{"name": "bar", "mass": 1, "inertia": 0.1, "position": [0.3, 0], "angle": 0, "velocity": [0, 0],
                            "angular_velocity": 0, "points": [{"name": "O", "position": [-0.3, 0]}]}],
                "joints": [{"type": "revolute", "name": "pin", "first": "ground.O", "second": "bar.O"},
                           {"type": "revolute", "name": "again", "first": "ground.O", "second": "bar.O"}],
                "drivers": [], "beams": [], "sensors": [], "forces": []}"#,
        );
        assert_eq!((pins.n_equations, pins.rank, pins.n_redundant()), (4, 2, 2));
        assert_eq!(pins.dependent_elements, vec!["pin".to_string(), "again".to_string()]);
    }
}
