//! Johnson line-contact law of a cylinder of length L in a bore.
//!
//! The penetration is explicit in the force F [N] (load per unit length
//! P = F/L):
//!
//! `δ = (P / (π E*)) (ln(4 π E* ΔR / P) - 1)`, `1/E* = Σ (1-ν²)/E`,
//! `ΔR = R_b - R_j`.
//!
//! Sources: K. L. Johnson, Contact Mechanics, Cambridge University Press
//! (1985), ch. 5 (two-dimensional contact of cylinders); ESDU-78035,
//! "Contact phenomena I" (1978); in the form compared by C. M. Pereira,
//! A. L. Ramalho, J. A. Ambrósio, Nonlinear Dyn. 63 (2011) 681-697, and
//! solved by Newton iteration in paper 002. The force follows by a
//! safeguarded Newton inversion; past the force `4π E* ΔR L / e³` the law
//! is continued by its tangent (see `logarithmic.rs`).
//! Theory page: `docs/theory/stiffness-johnson-line.md`.

use std::f64::consts::PI;

use super::logarithmic::LogarithmicLaw;
use super::material::{checked_length, effective_modulus, radial_clearance, Material};

/// Johnson (1985) line contact of a journal of length L in a bore.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JohnsonLine {
    law: LogarithmicLaw,
}

impl JohnsonLine {
    /// Builds the law from the bore radius R_b [m], the journal radius
    /// R_j < R_b [m], the contact length L [m] and the two materials.
    pub fn new(
        bearing_radius: f64,
        journal_radius: f64,
        length: f64,
        bearing: Material,
        journal: Material,
    ) -> Result<Self, String> {
        let clearance = radial_clearance(bearing_radius, journal_radius)?;
        let length = checked_length(length)?;
        let modulus =
            effective_modulus(&bearing.validated("bearing")?, &journal.validated("journal")?);
        let compliance = 1.0 / (PI * modulus * length);
        let force_scale = 4.0 * PI * modulus * clearance * length;
        Ok(Self { law: LogarithmicLaw::new(compliance, force_scale, -1.0) })
    }

    /// Elastic force F [N] for penetration δ [m] (0 for δ <= 0); finite for any δ.
    pub fn elastic_force(&self, penetration: f64) -> f64 {
        self.law.force(penetration)
    }

    /// Stored energy ∫0^δ F dδ [J], closed form.
    pub fn elastic_energy(&self, penetration: f64) -> f64 {
        self.law.energy(penetration)
    }

    /// Penetration δ [m] under the force F [N]: the explicit Johnson formula.
    pub fn penetration(&self, force: f64) -> f64 {
        self.law.penetration(force)
    }

    /// Force [N] above which the law is continued linearly, 4π E* ΔR L / e³.
    pub fn limit_force(&self) -> f64 {
        self.law.limit_force()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const STEEL: Material = Material { youngs_modulus: 207e9, poisson_ratio: 0.3 };

    fn example() -> JohnsonLine {
        JohnsonLine::new(0.020, 0.019, 0.040, STEEL, STEEL).unwrap()
    }

    #[test]
    fn test_penetration_matches_johnson_formula_by_hand() {
        // E* = 113.736 GPa, P = 1e4 N / 0.04 m = 2.5e5 N/m
        // δ = P/(π E*) (ln(4 π E* 1e-3 / P) - 1) = 6.99667e-7 m * (ln(5717.01) - 1) = 5.35329e-6 m
        let modulus = 207e9 / 1.82;
        let load = 2.5e5;
        let expected = load / (PI * modulus) * ((4.0 * PI * modulus * 1e-3 / load).ln() - 1.0);
        assert!((example().penetration(1e4) / expected - 1.0).abs() < 1e-13);
        assert!((expected / 5.35329e-6 - 1.0).abs() < 1e-5, "hand value {expected}");
    }

    #[test]
    fn test_round_trip_monotonicity_and_energy() {
        use super::super::implicit_law_checks::{assert_energy_matches_trapezoid, assert_monotone, assert_round_trip};
        let law = example();
        assert_round_trip(&law);
        assert_monotone(&law);
        assert_energy_matches_trapezoid(&law);
    }

    #[test]
    fn test_constructor_rejects_bad_length() {
        assert_eq!(
            JohnsonLine::new(0.02, 0.019, -0.04, STEEL, STEEL).unwrap_err(),
            "contact length must be finite and > 0 m, got -0.04"
        );
    }
}
