//! Maximum of a function of one variable on an interval by Brent's method,
//! used to find a peak inside an integration step on the dense output.

/// Maximum of f on [a, b] by Brent's method (golden section with parabolic
/// steps; Brent 1973, ch. 5), to an interval of `tolerance` [unit of t] or
/// after `max_evaluations`; returns the best (t, f(t)) found, `None` when an
/// evaluation failed first.
#[cfg(test)]
pub(crate) fn maximize(f: &mut dyn FnMut(f64) -> Option<f64>, a: f64, b: f64, tolerance: f64, max_evaluations: usize) -> Option<(f64, f64)> {
    maximize_from(f, a, b, None, tolerance, max_evaluations)
}

/// As [`maximize`], from a known interior point `(x, f(x))` when given
/// (else from the golden-section point of [a, b]).
pub(crate) fn maximize_from(
    f: &mut dyn FnMut(f64) -> Option<f64>,
    a: f64,
    b: f64,
    start: Option<(f64, f64)>,
    tolerance: f64,
    max_evaluations: usize,
) -> Option<(f64, f64)> {
    let golden = 0.5 * (3.0 - 5f64.sqrt());
    let (mut a, mut b) = (a, b);
    // minimise -f
    let (mut x, mut fx) = match start {
        Some((x, fx)) => (x, -fx),
        None => {
            let x = a + golden * (b - a);
            (x, -f(x)?)
        }
    };
    let (mut w, mut v) = (x, x);
    let (mut fw, mut fv) = (fx, fx);
    let (mut d, mut e) = (0.0f64, 0.0f64);
    let tol1 = (tolerance / 3.0).max(f64::EPSILON * b.abs().max(a.abs()));
    for _ in 1..max_evaluations {
        let xm = 0.5 * (a + b);
        let tol2 = 2.0 * tol1;
        if (x - xm).abs() <= tol2 - 0.5 * (b - a) {
            break;
        }
        let mut take_golden = true;
        if e.abs() > tol1 {
            // parabola through x, w, v
            let r = (x - w) * (fx - fv);
            let q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            let mut q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            }
            q = q.abs();
            let e_old = e;
            e = d;
            if p.abs() < (0.5 * q * e_old).abs() && p > q * (a - x) && p < q * (b - x) {
                d = p / q;
                let u = x + d;
                if u - a < tol2 || b - u < tol2 {
                    d = tol1.copysign(xm - x);
                }
                take_golden = false;
            }
        }
        if take_golden {
            e = if x >= xm { a - x } else { b - x };
            d = golden * e;
        }
        let u = x + if d.abs() >= tol1 { d } else { tol1.copysign(d) };
        let fu = -f(u)?;
        if fu <= fx {
            if u >= x { a = x } else { b = x }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x { a = u } else { b = u }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    Some((x, -fx))
}
