//! `L D L^T` of a symmetric positive definite matrix that falls apart into
//! small independent groups of rows: rows in different groups never couple.
//!
//! The constraint matrix `Phi_q M^-1 Phi_q^T` of a planar mechanism usually
//! does: rows couple only through a common body, and a slider-crank's seven
//! rows form a group of five (the crank's joints and driver) and one of two
//! (the slider's guide). Each group is stored as its own small dense
//! row-major square, one after the other, and factored and solved by a
//! kernel compiled for its size, with no index lists to follow. Groups need
//! not be contiguous rows; a group keeps its rows in ascending order.
//!
//! The layout of the factor is that of
//! [`SparseCholesky`](super::SparseCholesky) within each group (unit lower
//! `L` below the diagonal, `D` on it), followed by the group's `1 / d_j` (the
//! solves multiply instead of divide); so a matrix of n rows takes up to
//! `n (n + 1)` values. The rank test is the same too: a pivot
//! `d_j` at or below [`RELATIVE_PIVOT_TOLERANCE`] times the largest diagonal
//! entry of the whole matrix reports the row as dependent.

use super::cholesky::{RankDeficiency, RELATIVE_PIVOT_TOLERANCE};

/// Largest group the dense kernels are compiled for.
pub const MAX_GROUP: usize = 8;

/// One group of coupled rows.
#[derive(Clone, Debug, PartialEq)]
struct Group {
    /// The matrix rows of the group, ascending.
    rows: Vec<usize>,
    /// Start of the group's square (then its inverse pivots) in the storage.
    offset: usize,
}

/// The groups of one pattern and where each is stored.
#[derive(Clone, Debug, PartialEq)]
pub struct BlockLdl {
    /// Matrix size n.
    n: usize,
    groups: Vec<Group>,
    /// For every row: its group and its place in the group.
    place: Vec<(usize, usize)>,
}

impl BlockLdl {
    /// The groups of the `n x n` pattern given by its lower entries `(i, j)`,
    /// `i >= j`; `None` when a group has more than [`MAX_GROUP`] rows.
    pub fn analyse(n: usize, lower: &[(usize, usize)]) -> Option<Self> {
        let mut root: Vec<usize> = (0..n).collect();
        fn find(root: &mut [usize], mut i: usize) -> usize {
            while root[i] != i {
                root[i] = root[root[i]];
                i = root[i];
            }
            i
        }
        for &(i, j) in lower {
            let (a, b) = (find(&mut root, i), find(&mut root, j));
            root[a.max(b)] = a.min(b);
        }
        let mut groups: Vec<Group> = Vec::new();
        let mut place = vec![(0, 0); n];
        let mut group_of_root = vec![usize::MAX; n];
        for row in 0..n {
            let r = find(&mut root, row);
            if group_of_root[r] == usize::MAX {
                group_of_root[r] = groups.len();
                groups.push(Group { rows: Vec::new(), offset: 0 });
            }
            let g = group_of_root[r];
            place[row] = (g, groups[g].rows.len());
            groups[g].rows.push(row);
        }
        if groups.iter().any(|g| g.rows.len() > MAX_GROUP) {
            return None;
        }
        let mut offset = 0;
        for g in &mut groups {
            g.offset = offset;
            offset += g.rows.len() * (g.rows.len() + 1);
        }
        Some(Self { n, groups, place })
    }

    /// Size n of the matrices this layout holds.
    pub fn size(&self) -> usize {
        self.n
    }

    /// Number of stored lower entries (diagonal included) of the factor.
    pub fn factor_nonzeros(&self) -> usize {
        self.groups.iter().map(|g| g.rows.len() * (g.rows.len() + 1) / 2).sum()
    }

    /// Values stored: each group's square and its inverse pivots.
    pub fn storage_len(&self) -> usize {
        self.groups.iter().map(|g| g.rows.len() * (g.rows.len() + 1)).sum()
    }

    /// Storage index of the lower entry `(i, j)`, `i >= j`, of two rows of one group.
    pub fn storage_index(&self, i: usize, j: usize) -> usize {
        let ((gi, li), (gj, lj)) = (self.place[i], self.place[j]);
        assert!(gi == gj && li >= lj, "entry ({i}, {j}) is not in the lower triangle of a group");
        let g = &self.groups[gi];
        g.offset + li * g.rows.len() + lj
    }

    /// Factors the groups stored in `a` (lower triangles filled, see
    /// [`BlockLdl::storage_index`]) in place into `L D L^T`.
    pub fn factor(&self, a: &mut [f64]) -> Result<(), RankDeficiency> {
        // largest |a_ii| of the whole matrix (NaN skipped), as in the other kernels
        let mut scale = f64::MIN_POSITIVE;
        for g in &self.groups {
            for d in 0..g.rows.len() {
                scale = scale.max(a[g.offset + d * (g.rows.len() + 1)].abs());
            }
        }
        for g in &self.groups {
            let block = &mut a[g.offset..g.offset + g.rows.len() * (g.rows.len() + 1)];
            dispatch_factor(block, g.rows.len(), scale).map_err(|(local, relative_pivot)| RankDeficiency { row: g.rows[local], relative_pivot })?;
        }
        Ok(())
    }

    /// Solves `L D L^T x = b` in place (length n) with the factor from [`BlockLdl::factor`].
    pub fn solve(&self, factor: &[f64], b: &mut [f64]) {
        let mut local = [0.0; MAX_GROUP];
        for g in &self.groups {
            let size = g.rows.len();
            for (x, &row) in local.iter_mut().zip(&g.rows) {
                *x = b[row];
            }
            dispatch_solve(&factor[g.offset..g.offset + size * (size + 1)], size, &mut local[..size]);
            for (x, &row) in local.iter().zip(&g.rows) {
                b[row] = *x;
            }
        }
    }
}

/// `kernel::<size>(args)` for a group size from 1 to [`MAX_GROUP`].
macro_rules! by_size {
    ($size:expr, $kernel:ident($($arg:expr),*)) => {
        match $size {
            1 => $kernel::<1>($($arg),*),
            2 => $kernel::<2>($($arg),*),
            3 => $kernel::<3>($($arg),*),
            4 => $kernel::<4>($($arg),*),
            5 => $kernel::<5>($($arg),*),
            6 => $kernel::<6>($($arg),*),
            7 => $kernel::<7>($($arg),*),
            _ => $kernel::<MAX_GROUP>($($arg),*),
        }
    };
}

/// Calls the factor kernel compiled for `size` (1 to [`MAX_GROUP`]).
fn dispatch_factor(a: &mut [f64], size: usize, scale: f64) -> Result<(), (usize, f64)> {
    by_size!(size, factor(a, scale))
}

/// Calls the solve kernel compiled for `size` (1 to [`MAX_GROUP`]).
fn dispatch_solve(a: &[f64], size: usize, x: &mut [f64]) {
    by_size!(size, solve(a, x))
}

/// Dense `L D L^T` of the row-major `N x N` block at the start of `a` (lower triangle
/// read), with `1 / d_j` stored in the N values after it; the error names the local row
/// whose pivot fell below the tolerance and its relative pivot.
#[inline(always)]
fn factor<const N: usize>(a: &mut [f64], scale: f64) -> Result<(), (usize, f64)> {
    let a = &mut a[..N * (N + 1)];
    for j in 0..N {
        // w_k = l_jk d_k, then d_j = a_jj - sum_k l_jk w_k
        let mut w = [0.0; N];
        let mut pivot = a[j * N + j];
        for k in 0..j {
            w[k] = a[j * N + k] * a[k * N + k];
            pivot -= a[j * N + k] * w[k];
        }
        if !(pivot > RELATIVE_PIVOT_TOLERANCE * scale) {
            return Err((j, pivot / scale));
        }
        a[j * N + j] = pivot;
        let inverse = 1.0 / pivot;
        a[N * N + j] = inverse;
        for i in (j + 1)..N {
            let mut s = a[i * N + j];
            for k in 0..j {
                s -= a[i * N + k] * w[k];
            }
            a[i * N + j] = s * inverse;
        }
    }
    Ok(())
}

/// Solves `L D L^T x = b` in place with the block factored by [`factor`].
#[inline(always)]
fn solve<const N: usize>(a: &[f64], x: &mut [f64]) {
    let (a, x) = (&a[..N * (N + 1)], &mut x[..N]);
    for i in 0..N {
        for k in 0..i {
            x[i] -= a[i * N + k] * x[k];
        }
    }
    for i in 0..N {
        x[i] *= a[N * N + i];
    }
    for i in (0..N).rev() {
        for k in (i + 1)..N {
            x[i] -= a[k * N + i] * x[k];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{cholesky_factor, cholesky_solve};
    use super::*;
    use crate::linalg::test_matrices::patterned_spd as matrix;

    /// The groups' storage filled from a full matrix.
    fn stored(layout: &BlockLdl, a: &[f64], lower: &[(usize, usize)]) -> Vec<f64> {
        let n = layout.size();
        let mut s = vec![0.0; n * (n + 1)];
        for d in 0..n {
            s[layout.storage_index(d, d)] = a[d * n + d];
        }
        for &(i, j) in lower.iter().filter(|(i, j)| i != j) {
            s[layout.storage_index(i, j)] = a[i * n + j];
        }
        s
    }

    /// Rows {0, 2, 5}, {1, 4} and {3} coupled: three groups on interleaved rows.
    fn interleaved() -> Vec<(usize, usize)> {
        vec![(2, 0), (5, 0), (5, 2), (4, 1)]
    }

    #[test]
    fn groups_are_found_on_interleaved_rows() {
        let layout = BlockLdl::analyse(6, &interleaved()).unwrap();
        let rows: Vec<Vec<usize>> = layout.groups.iter().map(|g| g.rows.clone()).collect();
        assert_eq!(rows, vec![vec![0, 2, 5], vec![1, 4], vec![3]]);
        assert_eq!(layout.factor_nonzeros(), 6 + 3 + 1);
        // a chain longer than the largest kernel is left to the sparse program
        let chain: Vec<(usize, usize)> = (1..=MAX_GROUP).map(|i| (i, i - 1)).collect();
        assert!(BlockLdl::analyse(MAX_GROUP + 1, &chain).is_none());
        assert!(BlockLdl::analyse(MAX_GROUP, &chain[..MAX_GROUP - 1]).is_some());
    }

    #[test]
    fn solve_agrees_with_the_dense_cholesky() {
        let lower = interleaved();
        let layout = BlockLdl::analyse(6, &lower).unwrap();
        let a = matrix(6, &lower);
        let mut factor = stored(&layout, &a, &lower);
        layout.factor(&mut factor).unwrap();
        let mut dense = a.clone();
        cholesky_factor(&mut dense, 6).unwrap();
        let b: Vec<f64> = (0..6).map(|i| 1.5 - i as f64 * 0.4).collect();
        let (mut x, mut x_dense) = (b.clone(), b.clone());
        layout.solve(&factor, &mut x);
        cholesky_solve(&dense, 6, &mut x_dense);
        for i in 0..6 {
            let residual: f64 = (0..6).map(|j| a[i * 6 + j] * x[j]).sum::<f64>() - b[i];
            assert!(residual.abs() < 1e-13, "row {i}: A x - b = {residual:e}");
            assert!((x[i] - x_dense[i]).abs() < 1e-13, "x[{i}]: {} vs {}", x[i], x_dense[i]);
        }
    }

    #[test]
    fn every_kernel_size_solves_a_full_group() {
        for n in 1..=MAX_GROUP {
            let lower: Vec<(usize, usize)> = (0..n).flat_map(|i| (0..i).map(move |j| (i, j))).collect();
            let layout = BlockLdl::analyse(n, &lower).unwrap();
            let a = matrix(n, &lower);
            let mut factor = stored(&layout, &a, &lower);
            layout.factor(&mut factor).unwrap();
            let x_true: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
            let mut x: Vec<f64> = (0..n).map(|i| (0..n).map(|j| a[i * n + j] * x_true[j]).sum()).collect();
            layout.solve(&factor, &mut x);
            for i in 0..n {
                assert!((x[i] - x_true[i]).abs() < 1e-12, "size {n}, x[{i}] = {}", x[i]);
            }
        }
    }

    #[test]
    fn a_dependent_row_is_reported_by_its_matrix_row() {
        // rows 1 and 4 (one group) equal: the pivot of row 4 vanishes
        let lower = interleaved();
        let layout = BlockLdl::analyse(6, &lower).unwrap();
        let mut a = matrix(6, &lower);
        for (i, j) in [(1, 1), (4, 4), (4, 1), (1, 4)] {
            a[i * 6 + j] = 2.0;
        }
        let mut factor = stored(&layout, &a, &lower);
        let deficiency = layout.factor(&mut factor).unwrap_err();
        assert_eq!(deficiency.row, 4);
        assert!(deficiency.relative_pivot.abs() < 1e-12);
    }
}
