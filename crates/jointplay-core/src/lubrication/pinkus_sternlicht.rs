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
//! changes sign once, at the root `phi1` of `f` (found by bisection): the
//! film spans `(-pi, phi1)` when the wedge speed is positive and
//! `(phi1, pi)` when it is negative; with no wedge it is the whole film when
//! the journal approaches (`eps_dot > 0`) and empty when it recedes. The
//! two signs of `eps_dot` thus give the two cases of Pinkus and Sternlicht
//! (1961), and `phi1` is their film-end parameter. Steady running gives the
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

/// Root `phi1` in `(-pi, pi)` of the bracket `f(phi)` (bisection to machine precision) [rad].
pub fn film_end(state: &LineOfCentres) -> f64 {
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
