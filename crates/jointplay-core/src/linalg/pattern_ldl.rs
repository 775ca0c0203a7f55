//! The factorisation of a symmetric positive definite matrix of known
//! pattern, chosen once from that pattern: dense kernels per group of
//! coupled rows when every group is small ([`BlockLdl`]), otherwise the
//! elimination program of the whole pattern ([`SparseCholesky`]). Both are
//! `L D L^T` with the same rank test.

use super::{BlockLdl, RankDeficiency, SparseCholesky};

/// `L D L^T` of one pattern, by groups or by an elimination program.
#[derive(Clone, Debug, PartialEq)]
pub enum PatternLdl {
    /// Independent groups of at most [`super::block_ldl::MAX_GROUP`] rows.
    Groups(BlockLdl),
    /// Anything else.
    Sparse(SparseCholesky),
}

impl PatternLdl {
    /// The factorisation for the `n x n` pattern given by its lower entries `(i, j)`, `i >= j`.
    pub fn analyse(n: usize, lower: &[(usize, usize)]) -> Self {
        BlockLdl::analyse(n, lower).map_or_else(|| Self::Sparse(SparseCholesky::analyse(n, lower)), Self::Groups)
    }

    /// Size n of the matrices it factors.
    pub fn size(&self) -> usize {
        match self {
            Self::Groups(f) => f.size(),
            Self::Sparse(f) => f.size(),
        }
    }

    /// Number of stored lower entries of the factor (fill-in included).
    pub fn factor_nonzeros(&self) -> usize {
        match self {
            Self::Groups(f) => f.factor_nonzeros(),
            Self::Sparse(f) => f.factor_nonzeros(),
        }
    }

    /// Where the lower entry `(i, j)` of the matrix is stored (below [`PatternLdl::storage_len`]).
    pub fn storage_index(&self, i: usize, j: usize) -> usize {
        match self {
            Self::Groups(f) => f.storage_index(i, j),
            Self::Sparse(f) => f.storage_index(i, j),
        }
    }

    /// Values the factor stores (at most `n * (n + 1)`): what a factorisation clears and reads.
    pub fn storage_len(&self) -> usize {
        match self {
            Self::Groups(f) => f.storage_len(),
            Self::Sparse(f) => f.factor_nonzeros(),
        }
    }

    /// Factors the matrix stored in `a` ([`PatternLdl::storage_len`] values) in place (fill-in entries zero).
    pub fn factor(&self, a: &mut [f64]) -> Result<(), RankDeficiency> {
        match self {
            Self::Groups(f) => f.factor(a),
            Self::Sparse(f) => f.factor(a),
        }
    }

    /// Solves `A x = b` in place with the factor from [`PatternLdl::factor`].
    pub fn solve(&self, factor: &[f64], b: &mut [f64]) {
        match self {
            Self::Groups(f) => f.solve(factor, b),
            Self::Sparse(f) => f.solve(factor, b),
        }
    }
}
