//! Pinkus and Sternlicht's infinitely long bearing under squeeze and wedge
//! action, with the Gümbel condition on the Sommerfeld pressure.
//!
//! The full-film pressure with ambient pressure at the thickest film
//! (`phi = pi`) is, in our conventions (`wbar = omega_j + omega_b - 2 gamma_dot`),
//! `p = (6 mu R^2 / c^2) [P_w + P_s] / D^2` with the wedge part
//! `P_w = -eps wbar sin(phi) (2 - eps cos(phi)) / (2 + eps^2)` and the squeeze part
//! `P_s = eps_dot (1 + cos(phi)) (2 + eps - eps cos(phi)) / (1 + eps)^2`,
//! `= (12 mu R^2 / c^2) cos(phi/2) f(phi) / D^2`, with
//! `f = -eps wbar sin(phi/2) (2 - eps cos)/(2 + eps^2) + eps_dot cos(phi/2) (2 + eps - eps cos)/(1 + eps)^2`.
//! Only the positive part carries load. Besides `phi = pi`, the pressure
//! changes sign once, at the root `phi1` of `f`: the
//! film spans `(-pi, phi1)` when the wedge speed is positive and
//! `(phi1, pi)` when it is negative; with no wedge it is the whole film when
//! the journal approaches (`eps_dot > 0`) and empty when it recedes. The
//! two signs of `eps_dot` thus give the two cases of Pinkus and Sternlicht
//! (1961), and `phi1` is their film-end parameter. With `u = tan(phi/2)`,
//! `f = 0` is the cubic
//! `A (2 + eps) u^3 - 2 B (1 + eps) u^2 + A (2 - eps) u - 2 B = 0`,
//! `A = wedge_rate / (2 + eps^2)`, `B = squeeze_rate / (1 + eps)^2`, whose
//! single real root lies in `[t/2, t]`, `t = 2B/A`; [`film_end`] finds it by
//! a safeguarded Newton iteration. Steady running gives the
//! half-Sommerfeld (Gümbel) forces. At `e = 0` the thickest film has no
//! direction: the model then takes the frame along `e_dot` (an approach, so
//! the whole film), and its force is not continuous there for oblique
//! motion (unlike the Hamrock and Frêne models). See docs/theory/bearing-pinkus-sternlicht.md.

use crate::lubrication::closed_form::{friction_torque, long_film_with_moments};
use crate::lubrication::film::{BearingGeometry, FilmForce, FilmKinematics};
use crate::lubrication::frene::sommerfeld_constant;
use crate::lubrication::line_of_centres::{FilmMoments, LineOfCentres};
use std::f64::consts::PI;

/// Long bearing, positive part of the Sommerfeld pressure [N, Pa, rad, N m].
pub fn long_film_force(geometry: &BearingGeometry, kinematics: &FilmKinematics) -> FilmForce {
    long_film_force_with(geometry, kinematics, true)
}

/// As [`long_film_force`]; without `with_peak` the peak pressure is NaN.
pub fn long_film_force_with(geometry: &BearingGeometry, kinematics: &FilmKinematics, with_peak: bool) -> FilmForce {
    let state = LineOfCentres::new(geometry, kinematics);
    match positive_film(&state) {
        Some((a, b)) => {
            let m = FilmMoments::over(state.eccentricity_ratio, a, b);
            long_film_with_moments(geometry, kinematics, &state, (a, b), &m, sommerfeld_constant(&state), with_peak)
        }
        None => FilmForce { friction_torque: friction_torque(geometry, kinematics, &state, 0.0), ..FilmForce::default() },
    }
}

/// Line-of-centres limits `(a, b)` of the positive pressure, or `None` if
/// the pressure is nowhere positive [rad].
pub fn positive_film(state: &LineOfCentres) -> Option<(f64, f64)> {
    let wd = state.wedge_rate;
    if wd == 0.0 {
        return (state.squeeze_rate > 0.0).then_some((-PI, PI));
    }
    let phi1 = film_end(state);
    Some(if wd > 0.0 { (-PI, phi1) } else { (phi1, PI) })
}

/// Root `phi1` in `(-pi, pi)` of the bracket `f(phi)`: `2 atan(u)` with `u`
/// the real root of the cubic in `u = tan(phi/2)` (see the module docs) [rad].
/// Falls back to [`film_end_by_bisection`] where the cubic's bracket does not
/// hold (no wedge, or rates that are not finite).
pub fn film_end(state: &LineOfCentres) -> f64 {
    let eps = state.eccentricity_ratio;
    let a = state.wedge_rate / (2.0 + eps * eps);
    let b = state.squeeze_rate / ((1.0 + eps) * (1.0 + eps));
    match half_angle_tangent(eps, 2.0 * b / a) {
        Some(u) => 2.0 * u.atan(),
        None => film_end_by_bisection(state),
    }
}

/// Beyond this `|t|` the root `u` of the cubic is at least `5e99`, and
/// `2 atan(u)` is `+-pi` to the last bit: `u = t` is returned as it is [-].
const HUGE_RATIO: f64 = 1e100;

/// Newton iterations at most; each either converges quadratically or
/// halves a bracket of ratio 2, so 80 reach the last bit from any start
/// (the grid of the tests needs at most 6) [-].
const MAX_ITERATIONS: usize = 80;

/// Real root `u` of `(2 + eps) u^3 - t (1 + eps) u^2 + (2 - eps) u - t = 0`
/// (the film-end cubic divided by `A`, `t = 2B/A`) [-].
///
/// `u k(u) = t` with `k(u) = ((2 + eps) u^2 + 2 - eps) / ((1 + eps) u^2 + 1)`,
/// which lies in `(1, 2]` for `0 <= eps < 1`: the map is odd and increasing,
/// the root is unique and `|u|` lies in `[|t|/2, |t|]`. Newton's step is
/// kept inside that bracket (bisection otherwise). `None` when `t` is not
/// finite or the bracket does not change sign (eps outside `[0, 1)`).
pub fn half_angle_tangent(eps: f64, t: f64) -> Option<f64> {
    if !t.is_finite() || !(0.0..1.0).contains(&eps) {
        return None;
    }
    if t == 0.0 || t.abs() > HUGE_RATIO {
        return Some(t);
    }
    Some(root_in_bracket(eps, t.abs())?.0.copysign(t))
}

/// Root `u > 0` of the cubic for `x = |t| > 0`, with the number of Newton
/// iterations taken; `None` if `[x/2, x]` does not bracket it.
fn root_in_bracket(eps: f64, x: f64) -> Option<(f64, usize)> {
    let cubic = |u: f64| ((((2.0 + eps) * u - x * (1.0 + eps)) * u + (2.0 - eps)) * u) - x;
    let slope = |u: f64| (3.0 * (2.0 + eps) * u - 2.0 * x * (1.0 + eps)) * u + (2.0 - eps);
    let (mut lo, mut hi) = (0.5 * x, x);
    if cubic(lo) > 0.0 || cubic(hi) < 0.0 {
        return None;
    }
    // start from the small-|t| or large-|t| asymptote, whichever is inside
    let mut u = if x < 1.0 { x / (2.0 - eps) } else { x * (1.0 + eps) / (2.0 + eps) };
    for iteration in 1..=MAX_ITERATIONS {
        let r = cubic(u);
        if r == 0.0 {
            return Some((u, iteration));
        }
        if r < 0.0 {
            lo = u;
        } else {
            hi = u;
        }
        let step = r / slope(u);
        // converged: a Newton step of a few ulps, or a bracket that narrow
        if step.abs() <= 4.0 * f64::EPSILON * u {
            return Some(((u - step).clamp(lo, hi), iteration));
        }
        if hi - lo <= 4.0 * f64::EPSILON * lo {
            return Some((0.5 * (lo + hi), iteration));
        }
        let newton = u - step;
        u = if newton > lo && newton < hi { newton } else { 0.5 * (lo + hi) };
    }
    Some((u, MAX_ITERATIONS))
}

/// Root `phi1` of `f(phi)` by bisection on `(-pi, pi)` to machine precision
/// (60 halvings) [rad]: the reference of [`film_end`] and its fallback.
pub fn film_end_by_bisection(state: &LineOfCentres) -> f64 {
    let eps = state.eccentricity_ratio;
    let (sq, wd) = (state.squeeze_rate, state.wedge_rate);
    let f = |phi: f64| {
        let (s, c) = (0.5 * phi).sin_cos();
        let cos_phi = phi.cos();
        -wd * s * (2.0 - eps * cos_phi) / (2.0 + eps * eps) + sq * c * (2.0 + eps - eps * cos_phi) / ((1.0 + eps) * (1.0 + eps))
    };
    // f(-pi) has the sign of the wedge rate, f(pi) the opposite one
    let (mut lo, mut hi) = (-PI, PI);
    let sign_lo = wd.signum();
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if f(mid) * sign_lo > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
#[path = "pinkus_sternlicht_tests.rs"]
mod tests;
