//! Small dense and patterned linear algebra used inside the right-hand side.
//!
//! The systems solved per evaluation are tiny (the constraint count of a
//! planar mechanism, typically below 50), change every evaluation, and must
//! be solved without allocating. nalgebra's decompositions consume or
//! allocate their matrices, so the factorisations the hot loop needs live
//! here, in caller-owned buffers: `L D L^T` of the symmetric positive
//! definite `Phi_q M^-1 Phi_q^T` by groups of coupled rows or by a sparse
//! elimination program (chosen from its pattern, [`PatternLdl`]), a dense
//! Cholesky for the assembly, a dense `L D L^T` for the mass matrix of joint coordinates, and the LU factorisation of the implicit
//! integrator's iteration matrix. nalgebra is used for fixed-size 2D vectors
//! and, in tests, as the independent check.

pub mod block_ldl;
mod cholesky;
mod dense_ldl;
mod lu;
mod pattern_ldl;
mod sparse_cholesky;
mod sparse_lu;

pub use cholesky::{cholesky_factor, cholesky_solve, RankDeficiency, RELATIVE_PIVOT_TOLERANCE};
pub use dense_ldl::ldl_solve_scaled;
pub use lu::{lu_factor, lu_solve, SingularMatrix};
pub use block_ldl::BlockLdl;
pub use pattern_ldl::PatternLdl;
pub use sparse_cholesky::SparseCholesky;
pub use sparse_lu::{SingularSparse, SparseLu};

/// Matrices shared by the tests of the factorisations.
#[cfg(test)]
mod test_matrices {
    /// A symmetric positive definite `n x n` matrix (row-major, both triangles) whose
    /// off-diagonal entries are non-zero exactly at the given lower positions `(i, j)`,
    /// with a dominant diagonal.
    pub(super) fn patterned_spd(n: usize, lower: &[(usize, usize)]) -> Vec<f64> {
        let mut a = vec![0.0; n * n];
        for (m, &(i, j)) in lower.iter().enumerate() {
            let v = ((m * 7 + 3) % 11) as f64 / 11.0 - 0.45;
            a[i * n + j] = v;
            a[j * n + i] = v;
        }
        for d in 0..n {
            a[d * n + d] = n as f64 + d as f64 * 0.1;
        }
        a
    }
}
