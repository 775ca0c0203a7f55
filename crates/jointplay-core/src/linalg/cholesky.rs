//! In-place Cholesky factorisation `A = L L^T` with rank detection.

/// The factorisation met a pivot too small for a full-rank matrix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RankDeficiency {
    /// Index of the row (constraint) whose pivot vanished.
    pub row: usize,
    /// The pivot value relative to the largest diagonal entry.
    pub relative_pivot: f64,
}

/// Relative pivot below which a row is taken as linearly dependent on the
/// rows before it. `Phi_q M^-1 Phi_q^T` of a healthy mechanism has relative
/// pivots far above this; a locked configuration drives one to round-off.
pub const RELATIVE_PIVOT_TOLERANCE: f64 = 1e-8;

/// Factors the symmetric `n x n` row-major matrix `a` in place; its lower
/// triangle becomes `L`, except that the diagonal holds `1 / l_jj` (the
/// solves then multiply instead of divide). Only the lower triangle of the
/// input is read.
pub fn cholesky_factor(a: &mut [f64], n: usize) -> Result<(), RankDeficiency> {
    assert!(a.len() >= n * n, "matrix buffer shorter than n x n");
    // sizes of planar mechanisms: loops with constant bounds unroll
    macro_rules! fixed {
        ($($size:literal)*) => {
            match n {
                $($size => factor::<$size>(a),)*
                _ => factor_dynamic(a, n),
            }
        };
    }
    fixed!(1 2 3 4 5 6 7 8 9 10 11 12)
}

#[inline(always)]
fn factor_step(a: &mut [f64], n: usize, scale: f64) -> Result<(), RankDeficiency> {
    for j in 0..n {
        // pivot: a_jj - sum_k l_jk^2
        let mut pivot = a[j * n + j];
        for k in 0..j {
            pivot -= a[j * n + k] * a[j * n + k];
        }
        if !(pivot > RELATIVE_PIVOT_TOLERANCE * scale) {
            return Err(RankDeficiency { row: j, relative_pivot: pivot / scale });
        }
        let inverse = 1.0 / pivot.sqrt();
        a[j * n + j] = inverse;
        // column below the pivot: l_ij = (a_ij - sum_k l_ik l_jk) / l_jj
        for i in (j + 1)..n {
            let mut s = a[i * n + j];
            for k in 0..j {
                s -= a[i * n + k] * a[j * n + k];
            }
            a[i * n + j] = s * inverse;
        }
    }
    Ok(())
}

/// Largest |a_ii|, at least the smallest positive normal number (NaN entries are skipped).
pub(crate) fn diagonal_scale(a: &[f64], n: usize) -> f64 {
    let largest = a.iter().step_by(n + 1).take(n).fold(0.0_f64, |m, d| if d.abs() > m { d.abs() } else { m });
    largest.max(f64::MIN_POSITIVE)
}

fn factor<const N: usize>(a: &mut [f64]) -> Result<(), RankDeficiency> {
    let a = &mut a[..N * N];
    let scale = diagonal_scale(a, N);
    factor_step(a, N, scale)
}

fn factor_dynamic(a: &mut [f64], n: usize) -> Result<(), RankDeficiency> {
    let scale = diagonal_scale(a, n);
    factor_step(&mut a[..n * n], n, scale)
}

/// Solves `L L^T x = b` in place (`b` becomes `x`) with the factor from
/// [`cholesky_factor`].
pub fn cholesky_solve(l: &[f64], n: usize, b: &mut [f64]) {
    macro_rules! fixed {
        ($($size:literal)*) => {
            match n {
                $($size => solve_step(&l[..$size * $size], $size, &mut b[..$size]),)*
                _ => solve_step(&l[..n * n], n, &mut b[..n]),
            }
        };
    }
    fixed!(1 2 3 4 5 6 7 8 9 10 11 12)
}

#[inline(always)]
fn solve_step(l: &[f64], n: usize, b: &mut [f64]) {
    // forward: L y = b
    for i in 0..n {
        let mut s = b[i];
        for k in 0..i {
            s -= l[i * n + k] * b[k];
        }
        b[i] = s * l[i * n + i];
    }
    // backward: L^T x = y
    for i in (0..n).rev() {
        let mut s = b[i];
        for k in (i + 1)..n {
            s -= l[k * n + i] * b[k];
        }
        b[i] = s * l[i * n + i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    #[test]
    fn solution_matches_nalgebra_lu_on_a_random_spd_matrix() {
        // a = b b^T + n I from a fixed pseudo-random b
        let n = 7;
        let b = DMatrix::from_fn(n, n, |i, j| ((i * 7 + j * 13) % 11) as f64 / 11.0 - 0.4);
        let a = &b * b.transpose() + DMatrix::identity(n, n) * 0.5;
        let rhs = DVector::from_fn(n, |i, _| (i as f64).sin());
        let expected = a.clone().lu().solve(&rhs).unwrap();
        let mut buf: Vec<f64> = (0..n * n).map(|k| a[(k / n, k % n)]).collect();
        cholesky_factor(&mut buf, n).unwrap();
        let mut x = rhs.as_slice().to_vec();
        cholesky_solve(&buf, n, &mut x);
        for i in 0..n {
            assert!((x[i] - expected[i]).abs() < 1e-12, "{i}: {} vs {}", x[i], expected[i]);
        }
    }

    #[test]
    fn dependent_rows_are_reported_with_their_index() {
        // rows 0 and 2 of the jacobian equal: A = J J^T is singular at row 2
        let j = [[1.0, 0.0, 2.0], [0.0, 1.0, 0.0], [1.0, 0.0, 2.0]];
        let mut a = vec![0.0; 9];
        for r in 0..3 {
            for c in 0..3 {
                a[r * 3 + c] = (0..3).map(|k| j[r][k] * j[c][k]).sum();
            }
        }
        let err = cholesky_factor(&mut a, 3).unwrap_err();
        assert_eq!(err.row, 2);
        assert!(err.relative_pivot.abs() < 1e-12);
    }
}
