//! Hamrock's dynamically loaded short and long journal bearings with the
//! Gümbel (half-Sommerfeld) condition and moving film limits.
//!
//! Short bearing (Hamrock 2004, ch. "Dynamically loaded journal bearings";
//! Flores et al. 2009): the pressure numerator is
//! `g(phi) = 2 eps_dot cos(phi) - eps wbar sin(phi) = A cos(phi - phi0)`,
//! `phi0 = atan2(-eps wbar, 2 eps_dot)`, so the positive pressure fills
//! exactly `[phi0 - pi/2, phi0 + pi/2]` and moves with the ratio of squeeze
//! to wedge action. In closed form (`wbar = omega_j + omega_b - 2 gamma_dot`):
//! `F_n = -(mu R L^3 / 2c^2) [2 eps_dot I_cc - eps wbar I_sc]`,
//! `F_t = -(mu R L^3 / 2c^2) [2 eps_dot I_sc - eps wbar I_ss]`,
//! `I_xy = int x y / (1 - eps cos)^3` over that half. For pure wedge this is
//! Ocvirk's solution; for pure squeeze `F_n = -(mu R L^3 eps_dot / c^2)
//! [(1+2eps^2)(pi/2 + asin eps) + 3 eps sqrt(1-eps^2)] / (1-eps^2)^(5/2)`
//! (approach; `-asin`, `-3 eps` when separating).
//!
//! Long bearing: the same moving half, with the constant of the
//! long-bearing pressure gradient chosen so that `p = 0` at both of its ends
//! (two conditions: the integration constant and `K`). With `eps_dot = 0`
//! it is the half-Sommerfeld (Gümbel) solution; with the fixed half
//! `[-pi, 0]` it reproduces the fixed-limit forms of Flores et al. 2004
//! (`pi/2 - 8/(pi (2+eps^2))` squeeze term), which are exact only for pure
//! wedge. See docs/theory/bearing-hamrock.md.

use crate::lubrication::closed_form::{long_film_with_moments, moving_half_film, short_film_over_with};
use crate::lubrication::film::{BearingGeometry, FilmForce, FilmKinematics};
use crate::lubrication::line_of_centres::{FilmMoments, LineOfCentres};

/// Short bearing, Gümbel film on the moving half [N, Pa, rad, N m].
pub fn short_film_force(geometry: &BearingGeometry, kinematics: &FilmKinematics) -> FilmForce {
    short_film_force_with(geometry, kinematics, true)
}

/// As [`short_film_force`]; without `with_peak` the peak pressure is NaN.
pub fn short_film_force_with(geometry: &BearingGeometry, kinematics: &FilmKinematics, with_peak: bool) -> FilmForce {
    let state = LineOfCentres::new(geometry, kinematics);
    match moving_half_film(&state) {
        Some((a, b)) => short_film_over_with(geometry, kinematics, &state, a, b, with_peak),
        None => at_rest(geometry, kinematics, &state),
    }
}

/// Long bearing, pi film with `p = 0` at both ends of the moving half [N, Pa, rad, N m].
pub fn long_film_force(geometry: &BearingGeometry, kinematics: &FilmKinematics) -> FilmForce {
    long_film_force_with(geometry, kinematics, true)
}

/// As [`long_film_force`]; without `with_peak` the peak pressure is NaN.
pub fn long_film_force_with(geometry: &BearingGeometry, kinematics: &FilmKinematics, with_peak: bool) -> FilmForce {
    let state = LineOfCentres::new(geometry, kinematics);
    match moving_half_film(&state) {
        Some((a, b)) => {
            // one evaluation of the film moments serves the constant K and the force
            let m = FilmMoments::over(state.eccentricity_ratio, a, b);
            let k = pi_film_constant_from(&state, &m);
            long_film_with_moments(geometry, kinematics, &state, (a, b), &m, k, with_peak)
        }
        None => at_rest(geometry, kinematics, &state),
    }
}

/// Constant `K` of the long-bearing numerator that gives `p(a) = p(b) = 0`:
/// `int N / D^3 = 0` over `[a, b]` [1/s].
pub fn pi_film_constant(state: &LineOfCentres, a: f64, b: f64) -> f64 {
    pi_film_constant_from(state, &FilmMoments::over(state.eccentricity_ratio, a, b))
}

/// [`pi_film_constant`] from the film moments over the film.
fn pi_film_constant_from(state: &LineOfCentres, m: &FilmMoments) -> f64 {
    (state.wedge_rate * m.cos + 2.0 * state.squeeze_rate * m.sin) / m.one
}

/// No squeeze and no wedge: no pressure; only the Couette torque (zero here
/// too, since no wedge means `omega_j + omega_b = 2 gamma_dot`, but the spins
/// may still differ).
fn at_rest(geometry: &BearingGeometry, kinematics: &FilmKinematics, state: &LineOfCentres) -> FilmForce {
    FilmForce {
        friction_torque: crate::lubrication::closed_form::friction_torque(geometry, kinematics, state, 0.0),
        ..FilmForce::default()
    }
}
