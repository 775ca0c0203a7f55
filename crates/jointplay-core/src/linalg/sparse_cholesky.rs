//! `L D L^T` factorisation of a symmetric positive definite matrix whose
//! sparsity pattern is known before its values: the pattern of the factor,
//! fill-in included, is found once (symbolic analysis), and every
//! factorisation and solve then visits only the factor's structural
//! non-zeros.
//!
//! The constraint matrix `Phi_q M^-1 Phi_q^T` of a mechanism is such a
//! matrix: two constraint rows couple only when they act on a common body,
//! so a slider-crank's 7 x 7 matrix splits into a 5 x 5 and a 2 x 2 block.
//! `L D L^T` rather than `L L^T`: the pivots need no square root, which
//! shortens the chain of dependent operations through the factor. In place:
//! the strict lower triangle becomes the unit lower triangular `L`, the
//! diagonal `D`; entries outside the pattern must be zero on input and stay
//! zero. A pivot `d_j` at or below [`RELATIVE_PIVOT_TOLERANCE`] times the
//! largest diagonal entry reports the row as dependent, like
//! [`cholesky_factor`](super::cholesky_factor) (whose pivot `l_jj^2` is `d_j`).

use super::cholesky::{diagonal_scale, RankDeficiency, RELATIVE_PIVOT_TOLERANCE};

/// One entry of the factor and the products subtracted to form it.
#[derive(Clone, Debug, PartialEq)]
struct FactorEntry {
    /// Row-major index `i n + j` of the entry (`i >= j`).
    index: usize,
    /// Column j, the row reported when its pivot vanishes.
    column: usize,
    /// Whether the entry is the pivot `d_j`.
    diagonal: bool,
    /// Range in [`SparseCholesky::products`].
    first_product: usize,
    end_product: usize,
}

/// One strict-lower entry of the factor, for the solves.
#[derive(Clone, Copy, Debug, PartialEq)]
struct LowerEntry {
    /// Row-major index `i n + j`.
    index: usize,
    /// Row i.
    row: usize,
    /// Column j.
    column: usize,
}

/// The elimination program of one sparsity pattern.
#[derive(Clone, Debug, PartialEq)]
pub struct SparseCholesky {
    /// Matrix size n.
    n: usize,
    /// Entries of the factor in computation order: column by column, pivot first.
    entries: Vec<FactorEntry>,
    /// Index triples `(i n + k, j n + k, k n + k)` of the products `l_ik l_jk d_k`
    /// subtracted from entry `(i, j)`.
    products: Vec<(usize, usize, usize)>,
    /// Strict-lower entries of the factor, column by column.
    lower: Vec<LowerEntry>,
}

impl SparseCholesky {
    /// Analyses the pattern of an `n x n` symmetric matrix given by the
    /// positions `(i, j)`, `i >= j`, of its possibly non-zero lower entries
    /// (the diagonal is always included).
    pub fn analyse(n: usize, lower: &[(usize, usize)]) -> Self {
        let pattern = factor_pattern(n, lower);
        let nonzero = |i: usize, j: usize| pattern[i * n + j];
        let mut entries = Vec::new();
        let mut products = Vec::new();
        let mut strict_lower = Vec::new();
        for j in 0..n {
            for i in (j..n).filter(|&i| nonzero(i, j)) {
                let first_product = products.len();
                products.extend((0..j).filter(|&k| nonzero(i, k) && nonzero(j, k)).map(|k| (i * n + k, j * n + k, k * n + k)));
                entries.push(FactorEntry { index: i * n + j, column: j, diagonal: i == j, first_product, end_product: products.len() });
                if i != j {
                    strict_lower.push(LowerEntry { index: i * n + j, row: i, column: j });
                }
            }
        }
        Self { n, entries, products, lower: strict_lower }
    }

    /// Size n of the matrices this program factors.
    pub fn size(&self) -> usize {
        self.n
    }

    /// Number of structural non-zeros of the factor (fill-in included).
    pub fn factor_nonzeros(&self) -> usize {
        self.entries.len()
    }

    /// Factors the row-major `n x n` matrix `a` in place into `L D L^T`
    /// (see the module documentation). Only the lower triangle is read.
    pub fn factor(&self, a: &mut [f64]) -> Result<(), RankDeficiency> {
        let n = self.n;
        assert!(a.len() >= n * n, "matrix buffer shorter than n x n");
        let scale = diagonal_scale(a, n);
        // 1 / d_j of the column being computed (its pivot comes first)
        let mut inverse_pivot = 0.0;
        for entry in &self.entries {
            let mut s = a[entry.index];
            for &(ik, jk, kk) in &self.products[entry.first_product..entry.end_product] {
                s -= a[ik] * a[jk] * a[kk];
            }
            if entry.diagonal {
                if !(s > RELATIVE_PIVOT_TOLERANCE * scale) {
                    return Err(RankDeficiency { row: entry.column, relative_pivot: s / scale });
                }
                a[entry.index] = s;
                inverse_pivot = 1.0 / s;
            } else {
                a[entry.index] = s * inverse_pivot;
            }
        }
        Ok(())
    }

    /// Solves `L D L^T x = b` in place (`b` becomes `x`, length n) with the factor from [`SparseCholesky::factor`].
    pub fn solve(&self, factor: &[f64], b: &mut [f64]) {
        let n = self.n;
        // L z = b: column j is final once the columns before it are applied
        for e in &self.lower {
            b[e.row] -= factor[e.index] * b[e.column];
        }
        for (j, bj) in b[..n].iter_mut().enumerate() {
            *bj /= factor[j * n + j];
        }
        // L^T x = z, columns in reverse
        for e in self.lower.iter().rev() {
            b[e.column] -= factor[e.index] * b[e.row];
        }
    }
}

/// Row-major flags of the factor's structural non-zeros (lower triangle):
/// the matrix pattern plus the fill-in of eliminating column after column.
fn factor_pattern(n: usize, lower: &[(usize, usize)]) -> Vec<bool> {
    let mut pattern = vec![false; n * n];
    for &(i, j) in lower {
        assert!(i >= j && i < n, "pattern entry ({i}, {j}) is not in the lower triangle of a {n} x {n} matrix");
        pattern[i * n + j] = true;
    }
    for d in 0..n {
        pattern[d * n + d] = true;
    }
    // eliminating column j updates (i, k) for every pair i >= k > j of its non-zeros
    for j in 0..n {
        for i in (j + 1)..n {
            if pattern[i * n + j] {
                for k in (j + 1)..=i {
                    if pattern[k * n + j] {
                        pattern[i * n + k] = true;
                    }
                }
            }
        }
    }
    pattern
}

#[cfg(test)]
mod tests {
    use super::super::{cholesky_factor, cholesky_solve};
    use super::*;
    use crate::linalg::test_matrices::patterned_spd as matrix;

    /// The slider-crank's constraint coupling: rows 0-4 share the crank, 5-6 the slider.
    fn slider_crank_pattern() -> Vec<(usize, usize)> {
        let mut lower = Vec::new();
        for i in 0..5 {
            for j in 0..=i {
                lower.push((i, j));
            }
        }
        lower.extend([(5, 5), (6, 5), (6, 6)]);
        lower
    }

    /// `A x` for a row-major n x n matrix.
    fn times(a: &[f64], n: usize, x: &[f64]) -> Vec<f64> {
        (0..n).map(|i| (0..n).map(|j| a[i * n + j] * x[j]).sum()).collect()
    }

    #[test]
    fn block_pattern_is_the_dense_cholesky_without_fill_in() {
        let lower = slider_crank_pattern();
        let program = SparseCholesky::analyse(7, &lower);
        assert_eq!(program.factor_nonzeros(), 15 + 3);
        let (mut sparse, mut dense) = (matrix(7, &lower), matrix(7, &lower));
        program.factor(&mut sparse).unwrap();
        cholesky_factor(&mut dense, 7).unwrap();
        // L D L^T and L L^T of one matrix: d_j = l_jj^2 and l_ij (LDL) = l_ij / l_jj (LL);
        // the dense kernel keeps 1 / l_jj on its diagonal
        for i in 0..7 {
            for j in 0..=i {
                let (inverse_ljj, ldl) = (dense[j * 7 + j], sparse[i * 7 + j]);
                let expected = if i == j { (1.0 / inverse_ljj).powi(2) } else { dense[i * 7 + j] * inverse_ljj };
                assert!((ldl - expected).abs() <= 1e-14 * expected.abs().max(1.0), "entry ({i}, {j}): {ldl} vs {expected}");
            }
        }
        // entries between the two blocks stay zero
        assert!((5..7).all(|i| (0..5).all(|j| sparse[i * 7 + j] == 0.0)));
    }

    #[test]
    fn fill_in_is_found_and_the_solve_is_exact() {
        // an arrow pointing up-left fills in completely; a chain does not
        let arrow: Vec<(usize, usize)> = (1..6).map(|i| (i, 0)).collect();
        let program = SparseCholesky::analyse(6, &arrow);
        assert_eq!(program.factor_nonzeros(), 21);
        let chain: Vec<(usize, usize)> = (1..6).map(|i| (i, i - 1)).collect();
        assert_eq!(SparseCholesky::analyse(6, &chain).factor_nonzeros(), 11);
        let a = matrix(6, &arrow);
        let mut factor = a.clone();
        program.factor(&mut factor).unwrap();
        let x_true: Vec<f64> = (0..6).map(|i| 1.0 + i as f64).collect();
        let mut b = times(&a, 6, &x_true);
        program.solve(&factor, &mut b);
        for i in 0..6 {
            assert!((b[i] - x_true[i]).abs() < 1e-12, "x[{i}] = {}", b[i]);
        }
    }

    #[test]
    fn sparse_solve_agrees_with_the_dense_kernel_on_the_block_pattern() {
        let lower = slider_crank_pattern();
        let program = SparseCholesky::analyse(7, &lower);
        let a = matrix(7, &lower);
        let (mut sparse, mut dense) = (a.clone(), a.clone());
        program.factor(&mut sparse).unwrap();
        cholesky_factor(&mut dense, 7).unwrap();
        let b: Vec<f64> = (0..7).map(|i| (i as f64 - 3.0) * 0.7).collect();
        let (mut x_sparse, mut x_dense) = (b.clone(), b.clone());
        program.solve(&sparse, &mut x_sparse);
        cholesky_solve(&dense, 7, &mut x_dense);
        let residual = times(&a, 7, &x_sparse);
        for i in 0..7 {
            assert!((x_sparse[i] - x_dense[i]).abs() < 1e-13, "x[{i}]: {} vs {}", x_sparse[i], x_dense[i]);
            assert!((residual[i] - b[i]).abs() < 1e-12, "row {i} of A x - b");
        }
    }

    #[test]
    fn a_dependent_row_is_reported_like_the_dense_kernel() {
        // rows 0 and 1 of the 2 x 2 block equal: the second pivot vanishes
        let lower = [(1, 0)];
        let mut a = vec![2.0, 2.0, 2.0, 2.0];
        let sparse = SparseCholesky::analyse(2, &lower).factor(&mut a.clone());
        let dense = cholesky_factor(&mut a, 2);
        assert_eq!(sparse.unwrap_err().row, 1);
        assert_eq!(dense.unwrap_err().row, 1);
    }
}
