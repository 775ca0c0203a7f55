//! Small polynomial helpers for the variable-step Adams coefficients:
//! Lagrange bases on non-uniform nodes in monomial form and their integrals.

/// Largest number of interpolation nodes (Adams order up to 5).
pub(crate) const MAX_NODES: usize = 5;

/// Monomial coefficients: `c[p]` multiplies τ^p.
pub(crate) type Poly = [f64; MAX_NODES + 1];

/// Multiplies `poly` (degree `degree`) by (τ - root) in place.
fn times_linear(poly: &mut Poly, degree: usize, root: f64) {
    for p in (0..=degree + 1).rev() {
        let shifted = if p > 0 { poly[p - 1] } else { 0.0 };
        poly[p] = shifted - root * poly[p];
    }
}

/// Lagrange basis polynomials on `nodes` (distinct): `basis[j]` is 1 at node j, 0 at the others.
pub(crate) fn lagrange_basis(nodes: &[f64], basis: &mut [Poly; MAX_NODES]) {
    for (j, tj) in nodes.iter().enumerate() {
        let mut poly: Poly = [0.0; MAX_NODES + 1];
        poly[0] = 1.0;
        let mut denominator = 1.0;
        let mut degree = 0;
        for (m, tm) in nodes.iter().enumerate() {
            if m != j {
                times_linear(&mut poly, degree, *tm);
                degree += 1;
                denominator *= tj - tm;
            }
        }
        for c in poly.iter_mut() {
            *c /= denominator;
        }
        basis[j] = poly;
    }
}

/// Integral over [0, θ] of the polynomial with coefficients `poly`.
pub(crate) fn integral(poly: &Poly, theta: f64) -> f64 {
    let mut acc = 0.0;
    for p in (0..poly.len()).rev() {
        acc = acc * theta + poly[p] / (p + 1) as f64;
    }
    acc * theta
}

/// Integral over [0, 1] of the product of (τ - r) over `roots`, times (τ - extra) when given.
pub(crate) fn node_product_integral(roots: &[f64], extra: Option<f64>) -> f64 {
    let mut poly: Poly = [0.0; MAX_NODES + 1];
    poly[0] = 1.0;
    for (degree, r) in roots.iter().chain(extra.iter()).enumerate() {
        times_linear(&mut poly, degree, *r);
    }
    integral(&poly, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_nodes_give_adams_bashforth_4_weights() {
        // AB4 weights 55/24, -59/24, 37/24, -9/24 on nodes 0, -1, -2, -3
        let nodes = [0.0, -1.0, -2.0, -3.0];
        let mut basis = [[0.0; MAX_NODES + 1]; MAX_NODES];
        lagrange_basis(&nodes, &mut basis);
        let expected = [55.0 / 24.0, -59.0 / 24.0, 37.0 / 24.0, -9.0 / 24.0];
        for j in 0..4 {
            assert!((integral(&basis[j], 1.0) - expected[j]).abs() < 1e-13);
        }
    }

    #[test]
    fn uniform_nodes_give_milne_factor_19_over_270() {
        // constant-step AB4/AM4 pair: error of the corrector = 19/270 (y_C - y_P)
        let cp = node_product_integral(&[0.0, -1.0, -2.0, -3.0], None);
        let cc = node_product_integral(&[0.0, -1.0, -2.0], Some(1.0));
        assert!((cp - 251.0 / 30.0).abs() < 1e-13);
        assert!((cc + 19.0 / 30.0).abs() < 1e-13);
        assert!((cc / (cc - cp) - 19.0 / 270.0).abs() < 1e-15);
    }
}
