//! In-place LU factorisation with partial pivoting, for the iteration
//! matrix `I - c J` of the implicit integrator (a general, unsymmetric
//! matrix of the size of the state).

/// The factorisation met an exactly zero (or non-finite) pivot column.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SingularMatrix {
    /// Column whose pivot vanished.
    pub column: usize,
}

/// Factors the `n x n` row-major matrix `a` in place into `P A = L U`
/// (unit lower `L` below the diagonal, `U` on and above it); `pivots[k]` is
/// the row swapped with row k at step k.
pub fn lu_factor(a: &mut [f64], n: usize, pivots: &mut [usize]) -> Result<(), SingularMatrix> {
    assert!(a.len() >= n * n && pivots.len() >= n, "buffers shorter than n x n / n");
    for k in 0..n {
        let pivot_row = largest_in_column(a, n, k);
        let pivot = a[pivot_row * n + k];
        if pivot == 0.0 || !pivot.is_finite() {
            return Err(SingularMatrix { column: k });
        }
        pivots[k] = pivot_row;
        if pivot_row != k {
            for j in 0..n {
                a.swap(k * n + j, pivot_row * n + j);
            }
        }
        eliminate_below(a, n, k);
    }
    Ok(())
}

/// Row index (>= k) of the entry of largest magnitude in column k.
fn largest_in_column(a: &[f64], n: usize, k: usize) -> usize {
    let mut best = k;
    for i in (k + 1)..n {
        if a[i * n + k].abs() > a[best * n + k].abs() {
            best = i;
        }
    }
    best
}

/// Stores the multipliers of column k and updates the trailing rows.
fn eliminate_below(a: &mut [f64], n: usize, k: usize) {
    let inverse = 1.0 / a[k * n + k];
    let (upper, lower) = a.split_at_mut((k + 1) * n);
    let pivot_row = &upper[k * n..(k + 1) * n];
    for row in lower.chunks_exact_mut(n) {
        let factor = row[k] * inverse;
        row[k] = factor;
        if factor != 0.0 {
            for j in (k + 1)..n {
                row[j] -= factor * pivot_row[j];
            }
        }
    }
}

/// Solves `A x = b` in place (b becomes x) with the factors of [`lu_factor`].
pub fn lu_solve(lu: &[f64], n: usize, pivots: &[usize], b: &mut [f64]) {
    for (k, &pivot_row) in pivots[..n].iter().enumerate() {
        b.swap(k, pivot_row);
    }
    // forward substitution with the unit lower factor
    for i in 1..n {
        let row = &lu[i * n..i * n + i];
        let s: f64 = row.iter().zip(&b[..i]).map(|(l, x)| l * x).sum();
        b[i] -= s;
    }
    // back substitution with the upper factor
    for i in (0..n).rev() {
        let row = &lu[i * n..(i + 1) * n];
        let s: f64 = row[i + 1..].iter().zip(&b[i + 1..n]).map(|(u, x)| u * x).sum();
        b[i] = (b[i] - s) / row[i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};

    /// Deterministic, non-symmetric, well-conditioned test matrix that needs pivoting.
    fn matrix(n: usize) -> Vec<f64> {
        let mut a = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                a[i * n + j] = ((i * 7 + j * 3) % 11) as f64 - 5.0 + if i == (j + 1) % n { 20.0 } else { 0.0 };
            }
        }
        a
    }

    #[test]
    fn solves_like_nalgebra_for_sizes_up_to_20() {
        for n in 1..=20 {
            let a = matrix(n);
            let b: Vec<f64> = (0..n).map(|i| (i as f64).sin() + 0.5).collect();
            let expected = DMatrix::from_row_slice(n, n, &a).lu().solve(&DVector::from_vec(b.clone())).unwrap();
            let (mut lu, mut pivots, mut x) = (a.clone(), vec![0; n], b.clone());
            lu_factor(&mut lu, n, &mut pivots).unwrap();
            lu_solve(&lu, n, &pivots, &mut x);
            for i in 0..n {
                assert!((x[i] - expected[i]).abs() <= 1e-12 * (1.0 + expected[i].abs()), "n {n}, x[{i}] {} vs {}", x[i], expected[i]);
            }
        }
    }

    #[test]
    fn a_zero_first_entry_is_handled_by_pivoting() {
        let mut a = vec![0.0, 1.0, 1.0, 0.0];
        let mut pivots = [0; 2];
        lu_factor(&mut a, 2, &mut pivots).unwrap();
        let mut x = [3.0, 4.0];
        lu_solve(&a, 2, &pivots, &mut x);
        assert_eq!(x, [4.0, 3.0]);
    }

    #[test]
    fn a_singular_matrix_names_its_column() {
        let mut a = vec![1.0, 2.0, 2.0, 4.0];
        let mut pivots = [0; 2];
        assert_eq!(lu_factor(&mut a, 2, &mut pivots), Err(SingularMatrix { column: 1 }));
    }
}
