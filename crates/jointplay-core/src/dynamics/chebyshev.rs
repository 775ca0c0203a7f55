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

/// Cosines `cos(pi m / MAX_DEGREE)`, m = 0..2 MAX_DEGREE, computed once.
#[derive(Clone, Debug)]
pub(crate) struct CosineTable([f64; 2 * MAX_DEGREE]);

impl Default for CosineTable {
    fn default() -> Self {
        Self(std::array::from_fn(|m| (std::f64::consts::PI * m as f64 / MAX_DEGREE as f64).cos()))
    }
}

impl CosineTable {
    /// `cos(pi j k / n)` for a degree n dividing [`MAX_DEGREE`].
    fn cos(&self, j: usize, k: usize, n: usize) -> f64 {
        self.0[(j * k * (MAX_DEGREE / n)) % (2 * MAX_DEGREE)]
    }

    /// Coefficients `c[..=n]` of the interpolant of degree n of `values[j]`
    /// given at the Lobatto points `x_j` (j = 0..=n).
    pub(crate) fn coefficients(&self, values: &[f64], n: usize, c: &mut [f64]) {
        for (k, ck) in c[..=n].iter_mut().enumerate() {
            let mut sum = 0.5 * (values[0] + values[n] * self.cos(n, k, n));
            for (j, &v) in values.iter().enumerate().take(n).skip(1) {
                sum += v * self.cos(j, k, n);
            }
            let halve = if k == 0 || k == n { 0.5 } else { 1.0 };
            *ck = halve * 2.0 / n as f64 * sum;
        }
    }
}

/// Estimate of the interpolant's largest error on the interval: the size of
/// its last two coefficients (for a function analytic around the interval
/// the coefficients fall geometrically, and the error is of the size of the
/// first coefficient left out; Trefethen 2013, ch. 8).
pub(crate) fn tail(c: &[f64], n: usize) -> f64 {
    c[n - 1].abs() + c[n].abs()
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
        let table = CosineTable::default();
        let values: Vec<f64> = (0..=8).map(|j| f(lobatto_point(j, 8))).collect();
        let mut c = [0.0; 9];
        table.coefficients(&values, 8, &mut c);
        assert!(tail(&c, 8) < 1e-14, "{c:?}");
        for x in [-1.0, -0.3, 0.123, 0.77, 1.0] {
            assert!((evaluate(&c, x) - f(x)).abs() < 1e-14, "{x}");
        }
    }

    #[test]
    fn tail_bounds_the_error_of_an_analytic_function() {
        // exp(x) sin(3x): the error of each degree below its tail estimate, and the degree 32 interpolant exact
        let f = |x: f64| x.exp() * (3.0 * x).sin();
        let table = CosineTable::default();
        for n in [8, 16, 32] {
            let values: Vec<f64> = (0..=n).map(|j| f(lobatto_point(j, n))).collect();
            let mut c = [0.0; MAX_DEGREE + 1];
            table.coefficients(&values, n, &mut c);
            let error = (0..=1000).map(|i| -1.0 + 2e-3 * i as f64).map(|x| (evaluate(&c[..=n], x) - f(x)).abs()).fold(0.0, f64::max);
            assert!(error <= tail(&c, n).max(1e-14), "degree {n}: error {error}, tail {}", tail(&c, n));
            if n == 32 {
                assert!(error < 1e-13, "{n}: {error}");
            }
        }
    }
}
