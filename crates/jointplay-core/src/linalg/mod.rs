//! Small dense and patterned linear algebra used inside the right-hand side.
//!
//! The systems solved per evaluation are tiny (the constraint count of a
//! planar mechanism, typically below 50), change every evaluation, and must
//! be solved without allocating. nalgebra's decompositions consume or
//! allocate their matrices, so the factorisations the hot loop needs live
//! here, in caller-owned buffers: `L D L^T` of the symmetric positive
//! definite `Phi_q M^-1 Phi_q^T` by groups of coupled rows or by a sparse
//! elimination program (chosen from its pattern, [`PatternLdl`]), a dense
//! Cholesky for the assembly, and the LU factorisation of the implicit
//! integrator's iteration matrix. nalgebra is used for fixed-size 2D vectors
//! and, in tests, as the independent check.

pub mod block_ldl;
mod cholesky;
mod lu;
mod pattern_ldl;
mod sparse_cholesky;

pub use cholesky::{cholesky_factor, cholesky_solve, RankDeficiency};
pub use lu::{lu_factor, lu_solve, SingularMatrix};
pub use block_ldl::BlockLdl;
pub use pattern_ldl::PatternLdl;
pub use sparse_cholesky::SparseCholesky;
