//! Squeeze-film joint of Liu and Lin (1990, paper 000) after Phelan (1970):
//! the film force depends only on the eccentricity ratio and its rate
//! (wedge action ignored), and the joint switches to impact when the film
//! is used up.
//!
//! Phelan's semi-empirical formula (paper 000, eq. 15) is illegible in our
//! copy beyond its structure: a power of `C_r / f` (clearance over film
//! thickness) times the approach rate `f_dot`, scaled by viscosity and the
//! bearing dimensions. We therefore use the analytic pure-squeeze result it
//! approximates, the Gümbel half film on the side being squeezed
//! (Booker 1965; Hamrock 2004), in our conventions
//! (`eps_dot = e_dot . n / c`, force along `n`):
//!
//! - short bearing: `F = -(mu R L^3 eps_dot / c^2) [(1+2eps^2)(pi/2 + s asin eps) + 3 s eps sqrt(1-eps^2)] / (1-eps^2)^(5/2)`;
//! - long bearing: `F = -(12 mu R^3 L eps_dot / c^2) [pi/2 + s asin eps + s eps sqrt(1-eps^2)] / (1-eps^2)^(3/2)`;
//!
//! `s = sign(eps_dot)`. Near contact the long form is `d f_dot / f^(3/2)` with
//! `d = (12 pi / 2^(3/2)) mu R^3 L / c^(3/2)`, Phelan's structure.
//! See docs/theory/squeeze-film-phelan.md.

use crate::lubrication::film::{BearingGeometry, FilmForce, FilmKinematics};
use crate::lubrication::hamrock;
use crate::lubrication::line_of_centres::LineOfCentres;
use std::f64::consts::PI;

/// Which analytic squeeze film stands in for Phelan's formula.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SqueezeFilmTheory {
    /// Infinitely short bearing (`L/D` below about 0.5).
    ShortBearing,
    /// Infinitely long bearing (`L/D` above about 2).
    LongBearing,
}

/// A squeeze-film lubricated clearance joint.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SqueezeFilm {
    /// Bearing geometry and lubricant.
    pub geometry: BearingGeometry,
    /// Short- or long-bearing squeeze film.
    pub theory: SqueezeFilmTheory,
    /// Eccentricity ratio at which the film counts as used up and the joint
    /// switches to impact [-]. Default 1: paper 000 switches when the
    /// relative displacement of the centres reaches the clearance.
    pub exhaustion_ratio: f64,
}

impl SqueezeFilm {
    /// A squeeze film that is used up at contact (`exhaustion_ratio = 1`, paper 000).
    pub fn new(geometry: BearingGeometry, theory: SqueezeFilmTheory) -> Self {
        SqueezeFilm { geometry, theory, exhaustion_ratio: 1.0 }
    }

    /// Whether the film is used up at this eccentricity ratio, so that the
    /// joint must be treated as an impact (dry contact) joint.
    pub fn film_exhausted(&self, eccentricity_ratio: f64) -> bool {
        eccentricity_ratio >= self.exhaustion_ratio
    }

    /// Film force along `n` (negative: towards the centre) for `eps` [-] and `eps_dot` [1/s] [N].
    pub fn radial_force(&self, eps: f64, eps_dot: f64) -> f64 {
        let BearingGeometry { radius: r, length: l, clearance: c, viscosity: mu } = self.geometry;
        let eps = eps.min(crate::lubrication::line_of_centres::MAX_ECCENTRICITY_RATIO);
        let (k, s) = (1.0 - eps * eps, eps_dot.signum());
        let arc = 0.5 * PI + s * eps.asin();
        match self.theory {
            SqueezeFilmTheory::ShortBearing => {
                -mu * r * l.powi(3) * eps_dot / (c * c) * ((1.0 + 2.0 * eps * eps) * arc + 3.0 * s * eps * k.sqrt()) / k.powf(2.5)
            }
            SqueezeFilmTheory::LongBearing => {
                -12.0 * mu * r.powi(3) * l * eps_dot / (c * c) * (arc + s * eps * k.sqrt()) / k.powf(1.5)
            }
        }
    }

    /// Film force on the journal (global), peak pressure and its angle; the
    /// friction torque is NaN (the model has no shear) [N, Pa, rad].
    pub fn film_force(&self, kinematics: &FilmKinematics) -> FilmForce {
        let state = LineOfCentres::new(&self.geometry, kinematics);
        let force = self.radial_force(state.eccentricity_ratio, state.squeeze_rate);
        // the pressure field of the same half film, wedge and spins removed
        let pure_squeeze = FilmKinematics {
            eccentricity: kinematics.eccentricity,
            eccentricity_rate: state.normal * (state.squeeze_rate * self.geometry.clearance),
            journal_spin: 0.0,
            bearing_spin: 0.0,
        };
        let field = match self.theory {
            SqueezeFilmTheory::ShortBearing => hamrock::short_film_force(&self.geometry, &pure_squeeze),
            SqueezeFilmTheory::LongBearing => hamrock::long_film_force(&self.geometry, &pure_squeeze),
        };
        FilmForce {
            force_on_journal: state.normal * force,
            peak_pressure: field.peak_pressure,
            peak_pressure_angle: field.peak_pressure_angle,
            friction_torque: f64::NAN,
        }
    }
}
