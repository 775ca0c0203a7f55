//! Finite-difference solution of the Reynolds equation for a journal bearing
//! of finite length, and the dimensionless force tables built from it.
//!
//! - [`options`]: grid, cavitation model, end and groove pressures;
//! - [`solver`]: [`ReynoldsSolver`], set up once per bearing and solved per state;
//! - [`sweep`]: the relaxation sweeps (SOR, projected SOR, Elrod-Adams);
//! - [`outputs`]: force, torque, flows and peak pressure from a converged field;
//! - [`table`]: [`ForceTable`], the fast mode interpolating precomputed forces.
//!
//! Conventions are those of [`crate::lubrication::film`]; the theory page is
//! `docs/theory/reynolds-solver.md`.

pub mod options;
pub mod outputs;
pub mod solver;
pub mod sweep;
pub mod table;

pub use options::{Cavitation, Groove, ReynoldsOptions, MAX_GRID_NODES};
pub use outputs::FilmSolution;
pub use solver::ReynoldsSolver;
pub use table::{ForceTable, ForceTableOptions, MAX_TABLE_NODES};

#[cfg(test)]
mod tests;
