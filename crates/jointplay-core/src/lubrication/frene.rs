//! Frêne et al.'s infinitely short and infinitely long bearings with a full
//! (2 pi, uncavitated) film, under squeeze and wedge action.
//!
//! With no cavitation the film limits do not move and the closed forms are
//! short in our conventions (`wbar = omega_j + omega_b - 2 gamma_dot`):
//!
//! - short: `F_n = -pi mu R L^3 (1 + 2 eps^2) eps_dot / (c^2 (1-eps^2)^(5/2))`,
//!   `F_t = pi mu R L^3 eps wbar / (2 c^2 (1-eps^2)^(3/2))`;
//! - long: `F_n = -12 pi mu R^3 L eps_dot / (c^2 (1-eps^2)^(3/2))`,
//!   `F_t = 12 pi mu R^3 L eps wbar / (c^2 (2+eps^2) sqrt(1-eps^2))`
//!   (Sommerfeld's load at 90 degrees attitude for steady running).
//!
//! They are evaluated through the same kernels as the cavitated models (over
//! `[-pi, pi]`; the long film with Sommerfeld's periodicity constant
//! `K = 3 eps (eps wbar) / (2 + eps^2)` and ambient pressure at the
//! thickest film, `phi = pi`), so the peak pressure comes with them.
//! Negative gauge pressures are kept: the model holds for a submerged or
//! pressurised bearing. See docs/theory/bearing-frene.md.

use crate::lubrication::closed_form::{long_film_with_moments, short_film_over_with};
use crate::lubrication::film::{BearingGeometry, FilmForce, FilmKinematics};
use crate::lubrication::line_of_centres::{FilmMoments, LineOfCentres};
use std::f64::consts::PI;

/// Short bearing, full film [N, Pa, rad, N m].
pub fn short_film_force(geometry: &BearingGeometry, kinematics: &FilmKinematics) -> FilmForce {
    short_film_force_with(geometry, kinematics, true)
}

/// As [`short_film_force`]; without `with_peak` the peak pressure is NaN.
pub fn short_film_force_with(geometry: &BearingGeometry, kinematics: &FilmKinematics, with_peak: bool) -> FilmForce {
    let state = LineOfCentres::new(geometry, kinematics);
    short_film_over_with(geometry, kinematics, &state, -PI, PI, with_peak)
}

/// Long bearing, full film, ambient pressure at the thickest film [N, Pa, rad, N m].
pub fn long_film_force(geometry: &BearingGeometry, kinematics: &FilmKinematics) -> FilmForce {
    long_film_force_with(geometry, kinematics, true)
}

/// As [`long_film_force`]; without `with_peak` the peak pressure is NaN.
pub fn long_film_force_with(geometry: &BearingGeometry, kinematics: &FilmKinematics, with_peak: bool) -> FilmForce {
    let state = LineOfCentres::new(geometry, kinematics);
    let m = FilmMoments::over(state.eccentricity_ratio, -PI, PI);
    long_film_with_moments(geometry, kinematics, &state, (-PI, PI), &m, sommerfeld_constant(&state), with_peak)
}

/// Sommerfeld's constant of the long-bearing numerator, from periodicity of
/// the pressure: `K = 3 eps (eps wbar) / (2 + eps^2)` [1/s].
pub fn sommerfeld_constant(state: &LineOfCentres) -> f64 {
    let eps = state.eccentricity_ratio;
    3.0 * eps * state.wedge_rate / (2.0 + eps * eps)
}
