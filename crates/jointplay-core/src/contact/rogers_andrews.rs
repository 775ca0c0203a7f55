//! Logarithmic law of Rogers and Andrews for a journal in a bore.
//!
//! Paper 000, eq. (10) (garbled in extraction, rebuilt):
//!
//! `δ = C1 F (C2 - ln F)`, `C1 = (k_b + k_j)/L`,
//! `C2 = ln(L³ e ΔR / (R_b R_j (k_b + k_j)))`, `k_i = (1 - ν_i²)/(π E_i)`,
//!
//! that is `δ = C1 F (ln(L³ ΔR / (R_b R_j (k_b + k_j) F)) + 1)`, the
//! cylinder-in-bore result of S. Dubowsky, F. Freudenstein, "Dynamic
//! analysis of mechanical systems with clearances, Part 1", J. Eng. Ind.
//! 93(1) (1971) 305-309, used by R. J. Rogers, G. C. Andrews, J. Eng. Ind.
//! 99(1) (1977) 131-137. The force follows by a safeguarded Newton
//! inversion; past the force `L³ ΔR / (e R_b R_j (k_b + k_j))` the law is
//! continued by its tangent (see `logarithmic.rs`).
//! Theory page: `docs/theory/stiffness-rogers-andrews.md`.

use std::f64::consts::PI;

use super::logarithmic::LogarithmicLaw;
use super::material::{checked_length, effective_modulus, radial_clearance, Material};

/// Rogers-Andrews (Dubowsky-Freudenstein) logarithmic contact law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RogersAndrews {
    law: LogarithmicLaw,
}

impl RogersAndrews {
    /// Builds the law from the bore radius R_b [m], the journal radius
    /// R_j < R_b [m], the bearing length L [m] and the two materials.
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
        // k_b + k_j = 1 / (π E*)
        let compliance_sum = 1.0 / (PI * modulus);
        let force_scale =
            length.powi(3) * clearance / (bearing_radius * journal_radius * compliance_sum);
        Ok(Self { law: LogarithmicLaw::new(compliance_sum / length, force_scale, 1.0) })
    }

    /// Elastic force F [N] for penetration δ [m] (0 for δ <= 0); finite for any δ.
    pub fn elastic_force(&self, penetration: f64) -> f64 {
        self.law.force(penetration)
    }

    /// Stored energy ∫0^δ F dδ [J], closed form.
    pub fn elastic_energy(&self, penetration: f64) -> f64 {
        self.law.energy(penetration)
    }

    /// Penetration δ [m] under the force F [N]: the explicit logarithmic formula.
    pub fn penetration(&self, force: f64) -> f64 {
        self.law.penetration(force)
    }

    /// Force [N] above which the law is continued linearly, L³ ΔR / (e R_b R_j (k_b + k_j)).
    pub fn limit_force(&self) -> f64 {
        self.law.limit_force()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const STEEL: Material = Material { youngs_modulus: 207e9, poisson_ratio: 0.3 };

    fn example() -> RogersAndrews {
        RogersAndrews::new(0.020, 0.019, 0.040, STEEL, STEEL).unwrap()
    }

    #[test]
    fn test_penetration_matches_paper_000_form_by_hand() {
        // k = 0.91 / (π 207e9) per body; C1 = 2k / L; C2 = ln(L³ e ΔR / (R_b R_j 2k))
        let k = 0.91 / (PI * 207e9);
        let c1 = 2.0 * k / 0.04;
        let c2 = (0.04_f64.powi(3) * std::f64::consts::E * 1e-3 / (0.02 * 0.019 * 2.0 * k)).ln();
        let force = 1e4;
        let expected = c1 * force * (c2 - force.ln());
        assert!((example().penetration(force) / expected - 1.0).abs() < 1e-12);
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
    fn test_stiffer_than_johnson_is_not_assumed_but_both_agree_in_order_of_magnitude() {
        // same compliance scale 1/(π E* L); the logarithms differ by a few units
        let johnson = super::super::JohnsonLine::new(0.020, 0.019, 0.040, STEEL, STEEL).unwrap();
        let ratio = example().penetration(1e4) / johnson.penetration(1e4);
        assert!(ratio > 0.5 && ratio < 2.0, "ratio {ratio}");
    }
}
