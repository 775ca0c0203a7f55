//! `L D L^T` factorisation of a symmetric positive definite matrix whose
//! sparsity pattern is known before its values: the pattern of the factor,
//! fill-in included, is found once (symbolic analysis), and every
//! factorisation and solve then visits only the factor's structural
//! non-zeros, stored compactly (one value each, column by column), so that
//! clearing, factoring and solving all cost in proportion to them, not to `n^2`.
//!
//! The constraint matrix `Phi_q M^-1 Phi_q^T` of a mechanism is such a
//! matrix: two constraint rows couple only when they act on a common body,
//! so a slider-crank's 7 x 7 matrix splits into a 5 x 5 and a 2 x 2 block,
//! and a chain of N bodies gives a band of width about 4.
//! `L D L^T` rather than `L L^T`: the pivots need no square root, which
//! shortens the chain of dependent operations through the factor. In place:
//! the strict lower entries become the unit lower triangular `L`, the
//! diagonal `D`; fill-in entries must be zero on input. A pivot `d_j` at or
//! below [`RELATIVE_PIVOT_TOLERANCE`] times the largest diagonal entry reports
//! the row as dependent, like [`cholesky_factor`](super::cholesky_factor)
//! (whose pivot `l_jj^2` is `d_j`).

use super::cholesky::{RankDeficiency, RELATIVE_PIVOT_TOLERANCE};

/// One entry of the factor and the products subtracted to form it.
#[derive(Clone, Debug, PartialEq)]
struct FactorEntry {
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
    /// Storage index of the entry.
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
    /// Entries of the factor in computation order (column by column, pivot
    /// first); entry k is stored at index k.
    entries: Vec<FactorEntry>,
    /// Storage index triples `(ik, jk, kk)` of the products `l_ik l_jk d_k`
    /// subtracted from an entry `(i, j)`.
    products: Vec<(usize, usize, usize)>,
    /// Strict-lower entries of the factor, column by column.
    lower: Vec<LowerEntry>,
    /// Storage index of each pivot `d_j`.
    diagonal: Vec<usize>,
    /// Entries of row i: `(column, storage index)` in `row_entries[row_start[i]..row_start[i + 1]]`, columns ascending.
    row_start: Vec<usize>,
    row_entries: Vec<(usize, usize)>,
}

impl SparseCholesky {
    /// Analyses the pattern of an `n x n` symmetric matrix given by the
    /// positions `(i, j)`, `i >= j`, of its possibly non-zero lower entries
    /// (the diagonal is always included).
    pub fn analyse(n: usize, lower: &[(usize, usize)]) -> Self {
        let columns = factor_columns(n, lower);
        // storage index of (i, j): its place in the column-by-column order
        let mut rows_of: Vec<Vec<(usize, usize)>> = vec![Vec::new(); n];
        let mut diagonal = vec![0; n];
        let mut next = 0;
        for (j, column) in columns.iter().enumerate() {
            for &i in column {
                rows_of[i].push((j, next));
                if i == j {
                    diagonal[j] = next;
                }
                next += 1;
            }
        }
        let (mut row_start, mut row_entries) = (vec![0], Vec::with_capacity(next));
        for row in &rows_of {
            row_entries.extend_from_slice(row); // columns ascending: filled column by column
            row_start.push(row_entries.len());
        }
        let mut program = Self { n, entries: Vec::with_capacity(next), products: Vec::new(), lower: Vec::new(), diagonal, row_start, row_entries };
        for (j, column) in columns.iter().enumerate() {
            for &i in column {
                let first_product = program.products.len();
                let products = program.common_columns(i, j).map(|(ik, jk, k)| (ik, jk, program.diagonal[k])).collect::<Vec<_>>();
                program.products.extend(products);
                program.entries.push(FactorEntry { column: j, diagonal: i == j, first_product, end_product: program.products.len() });
                if i != j {
                    let index = program.storage_index(i, j);
                    program.lower.push(LowerEntry { index, row: i, column: j });
                }
            }
        }
        program
    }

    /// `(storage of (i, k), storage of (j, k), k)` for every column `k < j` where rows i and j both have an entry.
    fn common_columns(&self, i: usize, j: usize) -> impl Iterator<Item = (usize, usize, usize)> + '_ {
        let row_j = &self.row_entries[self.row_start[j]..self.row_start[j + 1]];
        self.row_entries[self.row_start[i]..self.row_start[i + 1]]
            .iter()
            .take_while(move |&&(k, _)| k < j)
            .filter_map(move |&(k, ik)| row_j.binary_search_by_key(&k, |&(c, _)| c).ok().map(|p| (ik, row_j[p].1, k)))
    }

    /// Size n of the matrices this program factors.
    pub fn size(&self) -> usize {
        self.n
    }

    /// Number of structural non-zeros of the factor (fill-in included): the values it stores.
    pub fn factor_nonzeros(&self) -> usize {
        self.entries.len()
    }

    /// Where the lower entry `(i, j)`, `i >= j`, of the factor's pattern is stored.
    ///
    /// # Panics
    /// When `(i, j)` is outside the pattern given to [`Self::analyse`]: the caller's own
    /// declaration of where its matrix has entries (made when a model is compiled, from
    /// the model's structure), never a value of the model.
    pub fn storage_index(&self, i: usize, j: usize) -> usize {
        let row = &self.row_entries[self.row_start[i]..self.row_start[i + 1]];
        match row.binary_search_by_key(&j, |&(c, _)| c) {
            Ok(p) => row[p].1,
            Err(_) => panic!("entry ({i}, {j}) is not in the pattern of the factor"),
        }
    }

    /// Factors the matrix stored in `a` (its [`SparseCholesky::factor_nonzeros`]
    /// values at their [`SparseCholesky::storage_index`]) in place into `L D L^T`
    /// (see the module documentation).
    pub fn factor(&self, a: &mut [f64]) -> Result<(), RankDeficiency> {
        assert!(a.len() >= self.entries.len(), "matrix buffer shorter than the factor's non-zeros");
        let scale = self.diagonal.iter().fold(0.0_f64, |m, &d| if a[d].abs() > m { a[d].abs() } else { m }).max(f64::MIN_POSITIVE);
        // 1 / d_j of the column being computed (its pivot comes first)
        let mut inverse_pivot = 0.0;
        for (index, entry) in self.entries.iter().enumerate() {
            let mut s = a[index];
            for &(ik, jk, kk) in &self.products[entry.first_product..entry.end_product] {
                s -= a[ik] * a[jk] * a[kk];
            }
            if entry.diagonal {
                if !(s > RELATIVE_PIVOT_TOLERANCE * scale) {
                    return Err(RankDeficiency { row: entry.column, relative_pivot: s / scale });
                }
                a[index] = s;
                inverse_pivot = 1.0 / s;
            } else {
                a[index] = s * inverse_pivot;
            }
        }
        Ok(())
    }

    /// Solves `L D L^T x = b` in place (`b` becomes `x`, length n) with the factor from [`SparseCholesky::factor`].
    pub fn solve(&self, factor: &[f64], b: &mut [f64]) {
        // L z = b: column j is final once the columns before it are applied
        for e in &self.lower {
            b[e.row] -= factor[e.index] * b[e.column];
        }
        for (bj, &d) in b[..self.n].iter_mut().zip(&self.diagonal) {
            *bj /= factor[d];
        }
        // L^T x = z, columns in reverse
        for e in self.lower.iter().rev() {
            b[e.column] -= factor[e.index] * b[e.row];
        }
    }
}

/// The rows of the factor's structural non-zeros in each column (ascending,
/// the diagonal first): the matrix pattern plus the fill-in of eliminating
/// column after column. Symbolic elimination on sorted row sets: eliminating
/// column j adds its rows below j to the column of its first such row (the
/// parent in the elimination tree), which is all fill-in (Davis, *Direct
/// Methods for Sparse Linear Systems*, SIAM 2006, ch. 4).
fn factor_columns(n: usize, lower: &[(usize, usize)]) -> Vec<Vec<usize>> {
    let mut columns: Vec<std::collections::BTreeSet<usize>> = (0..n).map(|d| std::iter::once(d).collect()).collect();
    for &(i, j) in lower {
        assert!(i >= j && i < n, "pattern entry ({i}, {j}) is not in the lower triangle of a {n} x {n} matrix");
        columns[j].insert(i);
    }
    for j in 0..n {
        let below: Vec<usize> = columns[j].range(j + 1..).copied().collect();
        if let Some(&parent) = below.first() {
            columns[parent].extend(below.iter().copied());
        }
    }
    columns.into_iter().map(|c| c.into_iter().collect()).collect()
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

    /// The lower entries of the pattern of a row-major n x n matrix `a`, stored as `program` stores them.
    fn stored(program: &SparseCholesky, a: &[f64]) -> Vec<f64> {
        let n = program.size();
        let mut out = vec![0.0; program.factor_nonzeros()];
        for i in 0..n {
            for j in 0..=i {
                if a[i * n + j] != 0.0 {
                    out[program.storage_index(i, j)] = a[i * n + j];
                }
            }
        }
        out
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
        let (mut sparse, mut dense) = (stored(&program, &matrix(7, &lower)), matrix(7, &lower));
        program.factor(&mut sparse).unwrap();
        cholesky_factor(&mut dense, 7).unwrap();
        // L D L^T and L L^T of one matrix: d_j = l_jj^2 and l_ij (LDL) = l_ij / l_jj (LL);
        // the dense kernel keeps 1 / l_jj on its diagonal
        for i in 0..7 {
            for j in 0..=i {
                let Some(ldl) = (lower.contains(&(i, j)) || i == j).then(|| sparse[program.storage_index(i, j)]) else { continue };
                let inverse_ljj = dense[j * 7 + j];
                let expected = if i == j { (1.0 / inverse_ljj).powi(2) } else { dense[i * 7 + j] * inverse_ljj };
                assert!((ldl - expected).abs() <= 1e-14 * expected.abs().max(1.0), "entry ({i}, {j}): {ldl} vs {expected}");
            }
        }
        // entries between the two blocks are not stored (no fill-in): the dense factor has zeros there
        assert!((5..7).all(|i| (0..5).all(|j| dense[i * 7 + j] == 0.0)));
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
        let mut factor = stored(&program, &a);
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
        let (mut sparse, mut dense) = (stored(&program, &a), a.clone());
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
        let program = SparseCholesky::analyse(2, &lower);
        let sparse = program.factor(&mut stored(&program, &a));
        let dense = cholesky_factor(&mut a, 2);
        assert_eq!(sparse.unwrap_err().row, 1);
        assert_eq!(dense.unwrap_err().row, 1);
    }

    #[test]
    fn a_long_band_stores_and_solves_like_the_dense_kernel() {
        // the pattern of a chain's constraint matrix: two rows per joint, coupled with the next joint's
        // two rows; 400 rows store about 7 values each (no fill-in along a band), not 400^2 / 2
        let n: usize = 400;
        let lower: Vec<(usize, usize)> = (0..n).flat_map(|i| (i.saturating_sub(3)..i).map(move |j| (i, j))).collect();
        let program = SparseCholesky::analyse(n, &lower);
        assert_eq!(program.factor_nonzeros(), n + lower.len());
        let a = matrix(n, &lower);
        let (mut sparse, mut dense) = (stored(&program, &a), a.clone());
        program.factor(&mut sparse).unwrap();
        cholesky_factor(&mut dense, n).unwrap();
        let b: Vec<f64> = (0..n).map(|i| ((i * 13) % 7) as f64 - 3.0).collect();
        let (mut x_sparse, mut x_dense) = (b.clone(), b.clone());
        program.solve(&sparse, &mut x_sparse);
        cholesky_solve(&dense, n, &mut x_dense);
        let residual = times(&a, n, &x_sparse);
        for i in 0..n {
            assert!((x_sparse[i] - x_dense[i]).abs() < 1e-13 * (1.0 + x_dense[i].abs()), "x[{i}]: {} vs {}", x_sparse[i], x_dense[i]);
            assert!((residual[i] - b[i]).abs() < 1e-11, "row {i} of A x - b");
        }
    }

    #[test]
    fn fill_in_of_a_nested_pattern_matches_dense_elimination() {
        // fill found through the elimination tree equals the fill of eliminating densely, column by column
        let lower = [(3, 0), (5, 0), (2, 1), (4, 1), (4, 2), (5, 3), (6, 4), (6, 5)];
        let n = 7;
        let mut dense = vec![false; n * n];
        for &(i, j) in &lower {
            dense[i * n + j] = true;
        }
        for j in 0..n {
            for i in (j + 1)..n {
                for k in (j + 1)..=i {
                    if dense[i * n + j] && dense[k * n + j] {
                        dense[i * n + k] = true;
                    }
                }
            }
        }
        let program = SparseCholesky::analyse(n, &lower);
        let expected = (0..n).map(|i| (0..i).filter(|&j| dense[i * n + j]).count() + 1).sum::<usize>();
        assert_eq!(program.factor_nonzeros(), expected);
        for i in 0..n {
            for j in (0..i).filter(|&j| dense[i * n + j]) {
                program.storage_index(i, j); // panics when not stored
            }
        }
    }
}
