//! Finite-difference solution of the Reynolds equation for a journal bearing
//! of finite length, and the dimensionless force tables built from it.
//!
//! - [`options`]: grid, cavitation model, end and groove pressures;
//! - [`solver`]: [`ReynoldsSolver`], set up once per bearing and solved per state;
//! - [`sweep`]: the relaxation sweeps (SOR, projected SOR, Elrod-Adams);
//! - [`outputs`]: force, torque, flows and peak pressure from a converged field;
//! - [`table`]: [`ForceTable`], the fast mode interpolating precomputed forces;
//! - [`misaligned`]: the state and result of a tilted journal (force and moment);
//! - [`full_length`]: [`FullLengthSolver`], the same equation on the full length
//!   for films that vary along the axis, with [`full_sweep`] and [`full_outputs`].
//!
//! Conventions are those of [`crate::lubrication::film`]; the theory page is
//! `docs/theory/reynolds-solver.md`.

pub mod full_length;
pub mod full_outputs;
pub mod full_sweep;
pub mod misaligned;
pub mod options;
pub mod outputs;
pub mod solver;
pub mod sweep;
pub mod table;

pub use full_length::FullLengthSolver;
pub use misaligned::{MisalignedFilmKinematics, MisalignedFilmSolution};
pub use options::{Cavitation, Groove, ReynoldsOptions, MAX_GRID_NODES};
pub use outputs::FilmSolution;
pub use solver::ReynoldsSolver;
pub use table::{ForceTable, ForceTableOptions, MAX_TABLE_NODES};

#[cfg(test)]
mod misaligned_tests;
#[cfg(test)]
mod tests;
