//! In-place `L D L^T` solve of a small dense symmetric positive definite
//! system, with the rank test of the matrix scaled to a unit diagonal and no
//! square root.
//!
//! The mass matrix of joint coordinates mixes lengths and angles, so its
//! entries differ by orders of magnitude that say nothing about singularity.
//! Scaling it to a unit diagonal, `S = D^-1/2 A D^-1/2`, makes its pivots
//! comparable; the pivot of `S` at row `k` is `d_k / a_kk` (the factor of `A`
//! is that of `S` rescaled), so the test needs neither the scaled matrix nor a
//! square root. The solve is a chain of dependent operations inside every
//! right-hand side of a joint-coordinate model: without square roots and with
//! one division per row it is short.

use super::{RankDeficiency, RELATIVE_PIVOT_TOLERANCE};

/// Solves `A x = b` in place (`b` becomes `x`) for the symmetric positive
/// definite `n x n` row-major `a`, of which only the lower triangle is read; it
/// is overwritten by `L` (unit diagonal, not stored) below the diagonal and
/// `1 / d_k` on it. Fails at the first row whose pivot, relative to its
/// diagonal entry, is at most [`RELATIVE_PIVOT_TOLERANCE`] (the row depends on
/// the rows before it, or the matrix is not positive definite).
/// Inlined, so that a caller of fixed size keeps the system in registers.
#[inline(always)]
pub fn ldl_solve_scaled(a: &mut [f64], n: usize, b: &mut [f64]) -> Result<(), RankDeficiency> {
    match n {
        1 => solve::<1>(a, n, b),
        2 => solve::<2>(a, n, b),
        3 => solve::<3>(a, n, b),
        4 => solve::<4>(a, n, b),
        _ => solve::<0>(a, n, b),
    }
}

/// [`ldl_solve_scaled`] with the size known at compile time (`N = 0`: any size).
#[inline(always)]
fn solve<const N: usize>(a: &mut [f64], n: usize, b: &mut [f64]) -> Result<(), RankDeficiency> {
    let n = if N == 0 { n } else { N };
    let (a, b) = (&mut a[..n * n], &mut b[..n]);
    for j in 0..n {
        // d_j = a_jj - sum_k l_jk^2 d_k; the row holds l_jk d_k until it is scaled, the
        // diagonal before it 1 / d_k
        let diagonal = a[j * n + j];
        let mut pivot = diagonal;
        for k in 0..j {
            pivot -= a[j * n + k] * a[j * n + k] * a[k * n + k];
        }
        if !(pivot > RELATIVE_PIVOT_TOLERANCE * diagonal) {
            return Err(RankDeficiency { row: j, relative_pivot: pivot / diagonal });
        }
        let inverse = 1.0 / pivot;
        // below the pivot: (l_ij d_j) = a_ij - sum_k (l_ik d_k) l_jk
        for i in (j + 1)..n {
            let mut s = a[i * n + j];
            for k in 0..j {
                s -= a[i * n + k] * a[j * n + k] * a[k * n + k];
            }
            a[i * n + j] = s;
        }
        a[j * n + j] = inverse;
    }
    // the rows held l_ij d_j: now L proper
    for j in 0..n {
        for i in (j + 1)..n {
            a[i * n + j] *= a[j * n + j];
        }
    }
    // L y = b, D z = y, L^T x = z
    for i in 0..n {
        let mut s = b[i];
        for k in 0..i {
            s -= a[i * n + k] * b[k];
        }
        b[i] = s;
    }
    for i in (0..n).rev() {
        let mut s = b[i] * a[i * n + i];
        for k in (i + 1)..n {
            s -= a[k * n + i] * b[k];
        }
        b[i] = s;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    /// `B B^T + shift I` with entries of very different size on the rows (lengths and angles).
    fn spd(n: usize, shift: f64) -> DMatrix<f64> {
        let b = DMatrix::from_fn(n, n, |i, j| (((i * 7 + j * 13) % 11) as f64 / 11.0 - 0.4) * 10f64.powi(i as i32 - 2));
        let s = DMatrix::from_fn(n, n, |i, j| if i == j { shift * 10f64.powi(2 * i as i32 - 4) } else { 0.0 });
        &b * b.transpose() + s
    }

    #[test]
    fn solution_matches_nalgebra_for_every_size() {
        for n in 1..=7 {
            let a = spd(n, 0.5);
            let rhs = DVector::from_fn(n, |i, _| (i as f64 + 0.3).sin());
            let expected = a.clone().lu().solve(&rhs).unwrap();
            let mut buffer: Vec<f64> = (0..n * n).map(|k| a[(k / n, k % n)]).collect();
            // the upper triangle is not read
            for i in 0..n {
                for j in (i + 1)..n {
                    buffer[i * n + j] = f64::NAN;
                }
            }
            let mut x = rhs.as_slice().to_vec();
            ldl_solve_scaled(&mut buffer, n, &mut x).unwrap();
            for i in 0..n {
                assert!((x[i] - expected[i]).abs() <= 1e-11 * expected[i].abs().max(1.0), "n {n}, {i}: {} vs {}", x[i], expected[i]);
            }
        }
    }

    #[test]
    fn relative_pivot_is_that_of_the_matrix_scaled_to_a_unit_diagonal() {
        // the scaled matrix's Cholesky pivots, squared, by nalgebra
        for n in 2..=6 {
            let a = spd(n, 1e-3);
            let scale = DVector::from_fn(n, |i, _| 1.0 / a[(i, i)].sqrt());
            let scaled = DMatrix::from_fn(n, n, |i, j| a[(i, j)] * scale[i] * scale[j]);
            let l = scaled.cholesky().unwrap().l();
            let mut buffer: Vec<f64> = (0..n * n).map(|k| a[(k / n, k % n)]).collect();
            let mut x = vec![1.0; n];
            ldl_solve_scaled(&mut buffer, n, &mut x).unwrap();
            for k in 0..n {
                let pivot_of_scaled = l[(k, k)] * l[(k, k)];
                let ours = 1.0 / (buffer[k * n + k] * a[(k, k)]);
                assert!((ours - pivot_of_scaled).abs() < 1e-12, "n {n}, row {k}: {ours} vs {pivot_of_scaled}");
            }
        }
    }

    #[test]
    fn a_dependent_row_is_reported_whatever_the_units() {
        // rows 0 and 2 of J equal: A = J W J^T singular at row 2, with a weight mixing units
        let j = [[1.0, 0.0, 2.0], [0.0, 1.0, 0.0], [1.0, 0.0, 2.0]];
        let w = [1e-4, 1.0, 1e3];
        let mut a = vec![0.0; 9];
        for r in 0..3 {
            for c in 0..3 {
                a[r * 3 + c] = (0..3).map(|k| j[r][k] * w[k] * j[c][k]).sum();
            }
        }
        let error = ldl_solve_scaled(&mut a, 3, &mut [1.0, 2.0, 3.0]).unwrap_err();
        assert_eq!(error.row, 2);
        assert!(error.relative_pivot.abs() < 1e-12);
        // not positive definite
        let mut negative = vec![-1.0];
        assert_eq!(ldl_solve_scaled(&mut negative, 1, &mut [1.0]).unwrap_err(), RankDeficiency { row: 0, relative_pivot: 1.0 });
        let mut not_a_number = vec![f64::NAN];
        assert_eq!(ldl_solve_scaled(&mut not_a_number, 1, &mut [1.0]).unwrap_err().row, 0);
    }
}
