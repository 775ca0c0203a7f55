//! Transition from hydrodynamic lubrication to dry contact in a lubricated
//! clearance joint: which share of the film force and of the dry contact
//! force acts at a given eccentricity ratio.
//!
//! Three laws, all pure functions of `eps = |e|/c`:
//!
//! - [`TransitionLaw::Switch`]: paper 000 (Liu and Lin 1990): film force
//!   while `|e| < c`, impact force once the film is used up;
//! - [`TransitionLaw::Flores`]: after Flores et al. (2006, 2009): the film
//!   alone below `eps0`, dry contact alone once `delta = |e| - c > 0`, and
//!   in between the film force fades by the smoothstep
//!   `1 - s(x)`, `s = x^2 (3 - 2x)`, `x = (eps - eps0)/(1 - eps0)`, which has
//!   zero slope at both ends, so the total force is C1 at `eps0` and
//!   continuous at contact (the dry force is zero at `delta = 0`). Flores'
//!   hydrodynamic force is the pure squeeze film: use [`TransitionLaw::film_kinematics`];
//! - [`TransitionLaw::WangImproved`]: paper 001's improved model: the same
//!   blend, but with squeeze *and* wedge action in the film force and the
//!   threshold from the safe film thickness, `eps0 = 1 - h_safe/c`.
//!
//! The blending formulas of both papers are lost in our copies; this is
//! our reconstruction, documented in docs/theory/lubricated-contact-transition.md.

use crate::lubrication::film::{BearingGeometry, FilmKinematics};
use nalgebra::Vector2;

/// Safe minimum film thickness per unit bearing diameter (0.00015 mm/mm,
/// the design rule quoted by paper 001 after Frêne et al. and Pinkus-Sternlicht) [-].
pub const SAFE_FILM_THICKNESS_PER_DIAMETER: f64 = 0.00015;

/// Safe minimum film thickness for a bearing of this diameter [m].
pub fn safe_film_thickness(diameter: f64) -> f64 {
    SAFE_FILM_THICKNESS_PER_DIAMETER * diameter
}

/// Shares of the two forces [-].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TransitionWeights {
    /// Factor on the film force [-].
    pub hydrodynamic: f64,
    /// Factor on the dry contact force [-].
    pub contact: f64,
}

/// Regime of a lubricated joint (for the `mode` channel).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LubricationRegime {
    /// Film only.
    Hydrodynamic,
    /// Film fading, thinner than the threshold, no contact yet.
    Transition,
    /// Journal touches the bore.
    Contact,
}

/// How the film force hands over to the dry contact force.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TransitionLaw {
    /// Film force until contact, contact force after (paper 000).
    Switch,
    /// Pure squeeze film faded out by a smoothstep between `lubricated_limit` and contact.
    Flores {
        /// Eccentricity ratio `eps0` where the fading starts [-].
        lubricated_limit: f64,
    },
    /// Squeeze and wedge film faded out between `1 - h_safe/c` and contact (paper 001).
    WangImproved {
        /// Safe film thickness `h_safe` [m].
        safe_film_thickness: f64,
    },
}

impl TransitionLaw {
    /// Paper 001's law with the safe film thickness of this bearing (`0.00015 D`, `D` the bearing
    /// (bore) diameter `2 (R + c)`, `R` being the journal radius of the film geometry).
    pub fn wang_improved(geometry: &BearingGeometry) -> Self {
        TransitionLaw::WangImproved { safe_film_thickness: safe_film_thickness(2.0 * (geometry.radius + geometry.clearance)) }
    }

    /// Eccentricity ratio `eps0` below which only the film acts [-].
    pub fn lubricated_limit(&self, geometry: &BearingGeometry) -> f64 {
        match *self {
            TransitionLaw::Switch => 1.0,
            TransitionLaw::Flores { lubricated_limit } => lubricated_limit.clamp(0.0, 1.0),
            TransitionLaw::WangImproved { safe_film_thickness } => (1.0 - safe_film_thickness / geometry.clearance).clamp(0.0, 1.0),
        }
    }

    /// Shares of film and contact force at eccentricity ratio `eps` [-].
    pub fn weights(&self, geometry: &BearingGeometry, eps: f64) -> TransitionWeights {
        if eps >= 1.0 {
            return TransitionWeights { hydrodynamic: 0.0, contact: 1.0 };
        }
        let eps0 = self.lubricated_limit(geometry);
        if eps <= eps0 {
            return TransitionWeights { hydrodynamic: 1.0, contact: 0.0 };
        }
        let x = (eps - eps0) / (1.0 - eps0);
        let s = x * x * (3.0 - 2.0 * x);
        TransitionWeights { hydrodynamic: 1.0 - s, contact: s }
    }

    /// Regime at eccentricity ratio `eps`.
    pub fn regime(&self, geometry: &BearingGeometry, eps: f64) -> LubricationRegime {
        if eps >= 1.0 {
            LubricationRegime::Contact
        } else if eps > self.lubricated_limit(geometry) {
            LubricationRegime::Transition
        } else {
            LubricationRegime::Hydrodynamic
        }
    }

    /// Kinematics the film model should see: Flores' law keeps only the
    /// squeeze motion along the line of centres (no spins, no whirl); the
    /// other laws pass the kinematics through.
    pub fn film_kinematics(&self, kinematics: &FilmKinematics) -> FilmKinematics {
        match self {
            TransitionLaw::Flores { .. } => {
                let e = kinematics.eccentricity;
                let distance = e.norm();
                let radial_rate = if distance > 0.0 { e * (kinematics.eccentricity_rate.dot(&e) / (distance * distance)) } else { kinematics.eccentricity_rate };
                FilmKinematics { eccentricity: e, eccentricity_rate: radial_rate, journal_spin: 0.0, bearing_spin: 0.0 }
            }
            _ => *kinematics,
        }
    }

    /// Total force on the journal from the film force and the dry contact
    /// force (both global, [N]) at eccentricity ratio `eps` [N].
    pub fn combine(&self, geometry: &BearingGeometry, film_force: Vector2<f64>, contact_force: Vector2<f64>, eps: f64) -> Vector2<f64> {
        let w = self.weights(geometry, eps);
        let mut total = contact_force * w.contact;
        // skip the film force where it has no weight (it may be huge or NaN there)
        if w.hydrodynamic > 0.0 {
            total += film_force * w.hydrodynamic;
        }
        total
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn geometry() -> BearingGeometry {
        BearingGeometry { radius: 0.0095, length: 0.02, clearance: 0.5e-3, viscosity: 0.4 }
    }

    #[test]
    fn test_safe_film_thickness_rule_gives_paper_001_threshold() {
        // journal radius 9.5 mm in a 10 mm bore, D = 20 mm: h_safe = 3 um, eps0 = 1 - 3e-6/5e-4 = 0.994
        let law = TransitionLaw::wang_improved(&geometry());
        assert!((safe_film_thickness(0.02) - 3.0e-6).abs() < 1e-18);
        assert!((law.lubricated_limit(&geometry()) - 0.994).abs() < 1e-12);
    }

    #[test]
    fn test_flores_weights_are_smooth_and_complete() {
        let (g, law) = (geometry(), TransitionLaw::Flores { lubricated_limit: 0.95 });
        assert_eq!(law.weights(&g, 0.5), TransitionWeights { hydrodynamic: 1.0, contact: 0.0 });
        assert_eq!(law.weights(&g, 1.0001), TransitionWeights { hydrodynamic: 0.0, contact: 1.0 });
        // midpoint of [0.95, 1]: smoothstep 1/2
        let mid = law.weights(&g, 0.975);
        assert!((mid.hydrodynamic - 0.5).abs() < 1e-12 && (mid.contact - 0.5).abs() < 1e-12);
        // zero slope at both ends: the weight changes by O(h^2)
        let h = 1e-6;
        let x = h / 0.05;
        assert!((1.0 - law.weights(&g, 0.95 + h).hydrodynamic) <= 3.0 * x * x);
        assert!(law.weights(&g, 1.0 - h).hydrodynamic <= 3.0 * x * x);
        for i in 0..=100 {
            let w = law.weights(&g, 0.9 + 0.0011 * i as f64);
            assert!((w.hydrodynamic + w.contact - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn test_combine_is_continuous_at_contact_and_ignores_unweighted_film() {
        let (g, law) = (geometry(), TransitionLaw::Flores { lubricated_limit: 0.95 });
        let film = Vector2::new(-1.0e4, 2.0e3);
        let below = law.combine(&g, film, Vector2::zeros(), 1.0 - 1e-7);
        assert!(below.norm() < 1e-6 * film.norm());
        let contact = Vector2::new(-5.0, 0.0);
        let above = law.combine(&g, Vector2::new(f64::NAN, f64::NAN), contact, 1.0);
        assert_eq!(above, contact);
        assert_eq!(TransitionLaw::Switch.combine(&g, film, contact, 0.999), film);
    }

    #[test]
    fn test_flores_film_kinematics_keep_only_radial_squeeze() {
        let k = FilmKinematics { eccentricity: Vector2::new(3e-4, 0.0), eccentricity_rate: Vector2::new(0.1, 0.2), journal_spin: 50.0, bearing_spin: 3.0 };
        let f = TransitionLaw::Flores { lubricated_limit: 0.95 }.film_kinematics(&k);
        assert_eq!(f.eccentricity_rate, Vector2::new(0.1, 0.0));
        assert_eq!((f.journal_spin, f.bearing_spin), (0.0, 0.0));
        assert_eq!(TransitionLaw::wang_improved(&geometry()).film_kinematics(&k), k);
    }
}
