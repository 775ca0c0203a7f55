//! Products with the small dense vectors and matrices a modal body evaluates at
//! every right-hand side (up to [`crate::body::MAX_MODES`] long), written so
//! that the compiler vectorises them: a dot product summed in four
//! independent lanes, and the two triangular solves with a Cholesky factor
//! whose rows are read contiguously.

/// Lanes of [`dot`]: four partial sums break the chain of dependent additions.
const LANES: usize = 4;

/// `a . b` over the shorter of the two, summed in [`LANES`] lanes.
#[inline]
pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let mut lanes = [0.0; LANES];
    let (a_chunks, b_chunks) = (a.chunks_exact(LANES), b.chunks_exact(LANES));
    let (a_rest, b_rest) = (a_chunks.remainder(), b_chunks.remainder());
    for (x, y) in a_chunks.zip(b_chunks) {
        for k in 0..LANES {
            lanes[k] += x[k] * y[k];
        }
    }
    let rest: f64 = a_rest.iter().zip(b_rest).map(|(x, y)| x * y).sum();
    (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]) + rest
}

/// `b <- L^-1 b` with `L` lower triangular (n x n row-major, the diagonal
/// holding `1 / l_ii`, the layout of [`crate::linalg::cholesky_factor`]).
#[inline]
pub(crate) fn solve_lower(lower: &[f64], n: usize, b: &mut [f64]) {
    for i in 0..n {
        let row = &lower[i * n..i * n + i];
        b[i] = (b[i] - dot(row, &b[..i])) * lower[i * n + i];
    }
}

/// `b <- U^-1 b` with `U = L^T` upper triangular (n x n row-major, the
/// diagonal holding `1 / u_ii`).
#[inline]
pub(crate) fn solve_upper(upper: &[f64], n: usize, b: &mut [f64]) {
    for i in (0..n).rev() {
        let row = &upper[i * n + i + 1..(i + 1) * n];
        b[i] = (b[i] - dot(row, &b[i + 1..n])) * upper[i * n + i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lane_dot_product_is_the_plain_sum_of_products() {
        // integers: every sum is exact whatever the order
        for n in 0..11 {
            let a: Vec<f64> = (0..n).map(|k| (k as f64) - 3.0).collect();
            let b: Vec<f64> = (0..n + 2).map(|k| 2.0 * k as f64 + 1.0).collect();
            let plain: f64 = a.iter().zip(&b).map(|(x, y)| x * y).sum();
            assert_eq!(dot(&a, &b), plain, "n = {n}");
        }
    }

    #[test]
    fn the_triangular_solves_invert_a_factor_and_its_transpose() {
        // L = [[2, 0, 0], [1, 4, 0], [-3, 5, 0.5]] stored with inverse diagonal
        let lower = [0.5, 0.0, 0.0, 1.0, 0.25, 0.0, -3.0, 5.0, 2.0];
        let upper = [0.5, 1.0, -3.0, 0.0, 0.25, 5.0, 0.0, 0.0, 2.0];
        let x = [1.5, -2.0, 4.0];
        // L x and L^T x by hand
        let mut lx = [2.0 * 1.5, 1.5 - 8.0, -4.5 - 10.0 + 2.0];
        let mut ux = [3.0 - 2.0 - 12.0, -8.0 + 20.0, 2.0];
        solve_lower(&lower, 3, &mut lx);
        solve_upper(&upper, 3, &mut ux);
        assert_eq!(lx, x);
        assert_eq!(ux, x);
    }
}
