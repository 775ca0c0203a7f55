//! Interpolation of a function of one variable at the Chebyshev-Lobatto
//! points of an interval, the tail of its Chebyshev series as the error
//! estimate, and Clenshaw's evaluation; used to locate the peaks of many
//! channels inside one integration step from one set of shared evaluations.
//!
//! On [-1, 1] the points of degree n are `x_j = cos(pi j / n)`, j = 0..=n
//! (from 1 down to -1); those of degree n are the even points of degree 2n,
//! so doubling the degree reuses every evaluation made. The interpolant is
//! `p(x) = sum_k c_k T_k(x)` with `c_k = (2/n) sum''_j f_j cos(pi j k / n)`
//! (the sum's first and last terms halved, and c_0 and c_n halved too);
//! Trefethen, *Approximation Theory and Approximation Practice*, 2013,
//! ch. 3 and 8.

/// Highest degree of an interpolant: every point of a lower degree that
/// divides it is one of its points.
pub(crate) const MAX_DEGREE: usize = 32;

/// Position [-1..1] of Lobatto point `j` of degree `n`.
pub(crate) fn lobatto_point(j: usize, n: usize) -> f64 {
    (std::f64::consts::PI * j as f64 / n as f64).cos()
}

/// Degrees of the interpolants, each the double of the one before.
pub(crate) const DEGREES: [usize; 3] = [MAX_DEGREE / 4, MAX_DEGREE / 2, MAX_DEGREE];

/// The matrices taking the values at the Lobatto points of each degree of
/// [`DEGREES`] to the coefficients of their interpolant, computed once.
#[derive(Clone, Debug)]
pub(crate) struct CoefficientMatrices(Vec<Vec<f64>>);

impl Default for CoefficientMatrices {
    fn default() -> Self {
        Self(DEGREES.iter().map(|&n| Self::matrix(n)).collect())
    }
}

impl CoefficientMatrices {
    /// Row-major (n + 1) x (n + 1): `c_k = sum_j m[k][j] f_j`.
    fn matrix(n: usize) -> Vec<f64> {
        let mut m = vec![0.0; (n + 1) * (n + 1)];
        for k in 0..=n {
            for j in 0..=n {
                let ends = if j == 0 || j == n { 0.5 } else { 1.0 } * if k == 0 || k == n { 0.5 } else { 1.0 };
                m[k * (n + 1) + j] = ends * 2.0 / n as f64 * (std::f64::consts::PI * (j * k) as f64 / n as f64).cos();
            }
        }
        m
    }

    /// The matrix of degree n (empty unless n is one of [`DEGREES`]).
    fn of(&self, n: usize) -> &[f64] {
        self.0.iter().find(|m| m.len() == (n + 1) * (n + 1)).map_or(&[], |m| &m[..])
    }

    /// Coefficient `c_k` of the interpolant of degree n of `values[..=n]`.
    pub(crate) fn coefficient(&self, values: &[f64], n: usize, k: usize) -> f64 {
        let row = self.of(n).get(k * (n + 1)..(k + 1) * (n + 1)).unwrap_or(&[]);
        row.iter().zip(values).map(|(m, f)| m * f).sum()
    }

    /// Coefficients `c[..=n]` of the interpolant of degree n of `values[j]`
    /// given at the Lobatto points `x_j` (j = 0..=n).
    pub(crate) fn coefficients(&self, values: &[f64], n: usize, c: &mut [f64]) {
        for (k, ck) in c[..=n].iter_mut().enumerate() {
            *ck = self.coefficient(values, n, k);
        }
    }
}

/// Estimate of the interpolant's largest error on the interval from its
/// last two coefficients `c_(n-1)`, `c_n`: their size (for a function
/// analytic around the interval the coefficients fall geometrically, and
/// the error is of the size of the first coefficient left out; Trefethen
/// 2013, ch. 8).
pub(crate) fn tail(last_two: [f64; 2]) -> f64 {
    last_two[0].abs() + last_two[1].abs()
}

/// `sum_k c_k T_k(x)` by Clenshaw's recurrence.
pub(crate) fn evaluate(c: &[f64], x: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    for &ck in c[1..].iter().rev() {
        (b1, b2) = (2.0 * x * b1 - b2 + ck, b1);
    }
    x * b1 - b2 + c[0]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolant_of_a_polynomial_of_lower_degree_is_the_polynomial() {
        let f = |x: f64| 3.0 - 2.0 * x + 0.5 * x.powi(5);
        let table = CoefficientMatrices::default();
        let values: Vec<f64> = (0..=8).map(|j| f(lobatto_point(j, 8))).collect();
        let mut c = [0.0; 9];
        table.coefficients(&values, 8, &mut c);
        assert!(tail([c[7], c[8]]) < 1e-14, "{c:?}");
        for x in [-1.0, -0.3, 0.123, 0.77, 1.0] {
            assert!((evaluate(&c, x) - f(x)).abs() < 1e-14, "{x}");
        }
    }

    #[test]
    fn tail_bounds_the_error_of_an_analytic_function() {
        // exp(x) sin(3x): the error of each degree below its tail estimate, and the degree 32 interpolant exact
        let f = |x: f64| x.exp() * (3.0 * x).sin();
        let table = CoefficientMatrices::default();
        for n in DEGREES {
            let values: Vec<f64> = (0..=n).map(|j| f(lobatto_point(j, n))).collect();
            let mut c = [0.0; MAX_DEGREE + 1];
            table.coefficients(&values, n, &mut c);
            let error = (0..=1000).map(|i| -1.0 + 2e-3 * i as f64).map(|x| (evaluate(&c[..=n], x) - f(x)).abs()).fold(0.0, f64::max);
            let tail = tail([c[n - 1], c[n]]);
            assert!(error <= tail.max(1e-14), "degree {n}: error {error}, tail {tail}");
            if n == 32 {
                assert!(error < 1e-13, "{n}: {error}");
            }
        }
    }
}
