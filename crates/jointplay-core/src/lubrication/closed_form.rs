//! Closed-form dynamic journal-bearing models (squeeze and wedge action,
//! infinitely short and infinitely long bearings), one enum for the kind.
//!
//! All models share two kernels, written in the line-of-centres frame of
//! [`LineOfCentres`] (`phi` from the thinnest film, wedge speed
//! `omega_j + omega_b - 2 gamma_dot`):
//!
//! - short bearing (`d/dx` term of Reynolds dropped):
//!   `p = 3 mu (L^2/4 - z^2) g(phi) / (c^2 D^3)`,
//!   `g = 2 eps_dot cos(phi) - eps wbar sin(phi)`, integrated over `[a, b]`:
//!   `F_n = -(mu R L^3 / 2c^2) int g cos / D^3`, `F_t = -(mu R L^3 / 2c^2) int g sin / D^3`;
//! - long bearing (`d/dz` term dropped): `dp/dphi = (6 mu R^2/c^2) N(phi) / D^3`,
//!   `N = -eps wbar cos(phi) - 2 eps_dot sin(phi) + K`, with `p = 0` at both
//!   ends of `[a, b]` (or periodic); integrating by parts,
//!   `F_n = (6 mu R^3 L/c^2) int N sin / D^3`, `F_t = -(6 mu R^3 L/c^2) int N cos / D^3`.
//!
//! `F_n < 0` pushes the journal back towards the bearing centre; `F_t` is
//! along `t = perp(n)`, positive for a positive wedge speed.
//! The friction torque is the Couette shear over the whole film plus the
//! pressure-gradient part, which integrates exactly to `-(e/2) F_t`:
//! `T = 2 pi mu R^3 L (omega_b - omega_j) / (c sqrt(1-eps^2)) - eps c F_t / 2`.
//! Theory: docs/theory/bearing-hamrock.md, bearing-frene.md, bearing-pinkus-sternlicht.md.

use crate::lubrication::film::{BearingGeometry, FilmForce, FilmKinematics};
use crate::lubrication::line_of_centres::{maximise, FilmMoments, LineOfCentres};
use crate::lubrication::{frene, hamrock, pinkus_sternlicht};
use std::f64::consts::PI;

/// Which closed-form dynamic bearing model to use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ClosedFormBearing {
    /// Infinitely short bearing, Gümbel film on the moving half where the Reynolds source is negative (Hamrock).
    HamrockShort,
    /// Infinitely long bearing, pi film on the same moving half with `p = 0` at both ends (Hamrock).
    HamrockLong,
    /// Infinitely short bearing, full 2 pi film without cavitation (Frêne et al.).
    FreneShort,
    /// Infinitely long bearing, full 2 pi film without cavitation (Frêne et al.).
    FreneLong,
    /// Infinitely long bearing, Sommerfeld pressure (ambient at the thickest film) kept where positive (Pinkus-Sternlicht).
    PinkusSternlichtLong,
}

impl ClosedFormBearing {
    /// Film force on the journal, peak pressure and friction torque for one state.
    pub fn film_force(&self, geometry: &BearingGeometry, kinematics: &FilmKinematics) -> FilmForce {
        self.film_force_with(geometry, kinematics, true)
    }

    /// As [`Self::film_force`]; without `with_peak` the short-bearing models skip the numerical
    /// search for the peak pressure and the long-bearing models its evaluation (reported as NaN).
    pub fn film_force_with(&self, geometry: &BearingGeometry, kinematics: &FilmKinematics, with_peak: bool) -> FilmForce {
        match self {
            ClosedFormBearing::HamrockShort => hamrock::short_film_force_with(geometry, kinematics, with_peak),
            ClosedFormBearing::HamrockLong => hamrock::long_film_force_with(geometry, kinematics, with_peak),
            ClosedFormBearing::FreneShort => frene::short_film_force_with(geometry, kinematics, with_peak),
            ClosedFormBearing::FreneLong => frene::long_film_force_with(geometry, kinematics, with_peak),
            ClosedFormBearing::PinkusSternlichtLong => pinkus_sternlicht::long_film_force_with(geometry, kinematics, with_peak),
        }
    }

    /// Whether the model is an infinitely short bearing (else infinitely long).
    pub fn is_short(&self) -> bool {
        matches!(self, ClosedFormBearing::HamrockShort | ClosedFormBearing::FreneShort)
    }
}

/// Limits `[phi0 - pi/2, phi0 + pi/2]` of the half film where the Reynolds
/// source `-g(phi)` is negative (squeeze and wedge both build pressure),
/// `phi0 = atan2(-eps wbar, 2 eps_dot)` [rad]; `None` when the source vanishes.
pub fn moving_half_film(state: &LineOfCentres) -> Option<(f64, f64)> {
    let (sq, wd) = (state.squeeze_rate, state.wedge_rate);
    if sq == 0.0 && wd == 0.0 {
        return None;
    }
    let centre = (-wd).atan2(2.0 * sq);
    Some((centre - 0.5 * PI, centre + 0.5 * PI))
}

/// Short-bearing film over `[a, b]` (line-of-centres angles) [N, Pa, rad, N m].
pub fn short_film_over(geometry: &BearingGeometry, kinematics: &FilmKinematics, state: &LineOfCentres, a: f64, b: f64) -> FilmForce {
    short_film_over_with(geometry, kinematics, state, a, b, true)
}

/// As [`short_film_over`]; without `with_peak` the peak pressure is NaN.
pub fn short_film_over_with(geometry: &BearingGeometry, kinematics: &FilmKinematics, state: &LineOfCentres, a: f64, b: f64, with_peak: bool) -> FilmForce {
    let BearingGeometry { radius: r, length: l, clearance: c, viscosity: mu } = *geometry;
    let (eps, sq, wd) = (state.eccentricity_ratio, state.squeeze_rate, state.wedge_rate);
    let m = FilmMoments::over(eps, a, b);
    let scale = -mu * r * l.powi(3) / (2.0 * c * c);
    let f_n = scale * (2.0 * sq * m.cos_cos - wd * m.sin_cos);
    let f_t = scale * (2.0 * sq * m.sin_cos - wd * m.sin_sin);
    // peak at mid-length on the analytic pressure
    let p_scale = 0.75 * mu * l * l / (c * c);
    let pressure = |phi: f64| {
        let (s, co) = phi.sin_cos();
        p_scale * (2.0 * sq * co - wd * s) / (1.0 - eps * co).powi(3)
    };
    let (phi_peak, peak) = if with_peak { maximise(pressure, a, b) } else { (f64::NAN, f64::NAN) };
    finish(geometry, kinematics, state, f_n, f_t, phi_peak, peak)
}

/// Long-bearing film over `[a, b]` with numerator constant `k` (see the module doc) [N, Pa, rad, N m].
pub fn long_film_over(geometry: &BearingGeometry, kinematics: &FilmKinematics, state: &LineOfCentres, a: f64, b: f64, k: f64) -> FilmForce {
    let m = FilmMoments::over(state.eccentricity_ratio, a, b);
    long_film_with_moments(geometry, kinematics, state, (a, b), &m, k, true)
}

/// As [`long_film_over`] with the film moments over `[a, b]` already computed; without
/// `with_peak` the peak pressure is NaN (it costs two more moment evaluations).
pub fn long_film_with_moments(
    geometry: &BearingGeometry,
    kinematics: &FilmKinematics,
    state: &LineOfCentres,
    (a, b): (f64, f64),
    m: &FilmMoments,
    k: f64,
    with_peak: bool,
) -> FilmForce {
    let BearingGeometry { radius: r, length: l, clearance: c, viscosity: mu } = *geometry;
    let (sq, wd) = (state.squeeze_rate, state.wedge_rate);
    let scale = 6.0 * mu * r.powi(3) * l / (c * c);
    let f_n = scale * (-wd * m.sin_cos - 2.0 * sq * m.sin_sin + k * m.sin);
    let f_t = -scale * (-wd * m.cos_cos - 2.0 * sq * m.sin_cos + k * m.cos);
    let (phi_peak, peak) = if with_peak { long_peak(geometry, state, a, b, k) } else { (f64::NAN, f64::NAN) };
    finish(geometry, kinematics, state, f_n, f_t, phi_peak, peak)
}

/// Long-bearing pressure at `phi` with `p(a) = 0` [Pa].
pub fn long_pressure(geometry: &BearingGeometry, state: &LineOfCentres, a: f64, k: f64, phi: f64) -> f64 {
    let m = FilmMoments::over(state.eccentricity_ratio, a, phi);
    let scale = 6.0 * geometry.viscosity * geometry.radius * geometry.radius / (geometry.clearance * geometry.clearance);
    scale * (-state.wedge_rate * m.cos - 2.0 * state.squeeze_rate * m.sin + k * m.one)
}

/// Peak of the long-bearing pressure on `[a, b]`: at a root of `N(phi) = 0`,
/// i.e. `eps wbar cos(phi) + 2 eps_dot sin(phi) = K`, or at an end.
fn long_peak(geometry: &BearingGeometry, state: &LineOfCentres, a: f64, b: f64, k: f64) -> (f64, f64) {
    let (sq, wd) = (state.squeeze_rate, state.wedge_rate);
    let amplitude = wd.hypot(2.0 * sq);
    let (mut best_phi, mut best) = (a, 0.0);
    if amplitude > 0.0 {
        let centre = (2.0 * sq).atan2(wd);
        let half = (k / amplitude).clamp(-1.0, 1.0).acos();
        for candidate in [centre - half, centre + half] {
            // the representative of the candidate in [a, a + 2 pi)
            let phi = a + (candidate - a).rem_euclid(2.0 * PI);
            if phi <= b {
                let p = long_pressure(geometry, state, a, k, phi);
                if p > best {
                    best = p;
                    best_phi = phi;
                }
            }
        }
    }
    (best_phi, best)
}

/// Assemble the global force and the friction torque.
fn finish(geometry: &BearingGeometry, kinematics: &FilmKinematics, state: &LineOfCentres, f_n: f64, f_t: f64, phi_peak: f64, peak: f64) -> FilmForce {
    FilmForce {
        force_on_journal: state.to_global(f_n, f_t),
        peak_pressure: peak,
        peak_pressure_angle: state.global_angle(phi_peak),
        friction_torque: friction_torque(geometry, kinematics, state, f_t),
    }
}

/// Shear torque on the journal [N m]: Couette shear over the whole film
/// (also in the cavitated part, as in Petroff's law) plus `-e F_t / 2`.
pub fn friction_torque(geometry: &BearingGeometry, kinematics: &FilmKinematics, state: &LineOfCentres, f_t: f64) -> f64 {
    let BearingGeometry { radius: r, length: l, clearance: c, viscosity: mu } = *geometry;
    let eps = state.eccentricity_ratio;
    let couette = 2.0 * PI * mu * r.powi(3) * l * (kinematics.bearing_spin - kinematics.journal_spin) / (c * (1.0 - eps * eps).sqrt());
    couette - 0.5 * eps * c * f_t
}

#[cfg(test)]
#[path = "closed_form_tests.rs"]
mod tests;
