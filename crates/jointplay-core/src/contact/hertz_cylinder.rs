//! Hertz-type power-law stiffness of a journal in a bore, as used by Flores.
//!
//! `F = K δ^n`, `K = (4/3) E* sqrt(R*)`, `1/E* = Σ (1-ν²)/E`,
//! `R* = R_b R_j / (R_b - R_j)`. This is the sphere (point-contact) Hertz
//! formula applied with the conformal radius of the cylinder pair; it is
//! what the Flores papers use, not a line-contact result.
//! Theory page: `docs/theory/stiffness-hertz-cylinder.md`.

use super::power_law::{PowerLaw, PowerLawStiffness};
use super::material::{effective_modulus, radial_clearance, Material};

/// Power-law contact stiffness `F = K δ^n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HertzCylinder {
    law: PowerLaw,
}

impl HertzCylinder {
    /// Builds the law from the bore radius R_b [m], the journal radius
    /// R_j < R_b [m], the two materials and the exponent n > 0 [-]
    /// (1.5 for metals).
    pub fn new(
        bearing_radius: f64,
        journal_radius: f64,
        bearing: Material,
        journal: Material,
        exponent: f64,
    ) -> Result<Self, String> {
        let clearance = radial_clearance(bearing_radius, journal_radius)?;
        let bearing = bearing.validated("bearing")?;
        let journal = journal.validated("journal")?;
        if !(exponent.is_finite() && exponent > 0.0) {
            return Err(format!("exponent must be finite and > 0, got {exponent}"));
        }
        let radius = bearing_radius * journal_radius / clearance;
        let stiffness = 4.0 / 3.0 * effective_modulus(&bearing, &journal) * radius.sqrt();
        Ok(Self { law: PowerLaw { stiffness, exponent } })
    }
}

impl PowerLawStiffness for HertzCylinder {
    fn power_law(&self) -> &PowerLaw {
        &self.law
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const STEEL: Material = Material { youngs_modulus: 207e9, poisson_ratio: 0.3 };

    #[test]
    fn test_stiffness_matches_hand_value_for_flores_example() {
        // R* = 0.01 * 0.0095 / 0.0005 = 0.19 m; E* = 207e9 / (2 * 0.91) = 113.736 GPa
        // K = 4/3 * 113.736e9 * sqrt(0.19) = 6.6102e10 N/m^1.5 (by hand, 5 digits)
        let law = HertzCylinder::new(0.01, 0.0095, STEEL, STEEL, 1.5).unwrap();
        assert!((law.stiffness() / 6.6102e10 - 1.0).abs() < 1e-4, "K = {}", law.stiffness());
        assert_eq!(law.exponent(), 1.5);
    }

    #[test]
    fn test_force_and_energy_closed_forms() {
        let law = HertzCylinder::new(0.01, 0.0095, STEEL, STEEL, 1.5).unwrap();
        let penetration = 1e-5;
        let force = law.stiffness() * 1e-5_f64.powf(1.5);
        assert!((law.elastic_force(penetration) / force - 1.0).abs() < 1e-14);
        assert!(
            (law.elastic_energy(penetration) / (force * penetration / 2.5) - 1.0).abs() < 1e-14
        );
        assert_eq!(law.elastic_force(0.0), 0.0);
        assert_eq!(law.elastic_energy(-1e-5), 0.0);
    }

    #[test]
    fn test_constructor_rejects_bad_input() {
        assert_eq!(
            HertzCylinder::new(0.01, 0.0095, STEEL, STEEL, 0.0).unwrap_err(),
            "exponent must be finite and > 0, got 0"
        );
        assert!(HertzCylinder::new(0.0095, 0.01, STEEL, STEEL, 1.5).is_err());
        let soft = Material { youngs_modulus: 0.0, poisson_ratio: 0.3 };
        assert!(HertzCylinder::new(0.01, 0.0095, soft, STEEL, 1.5).is_err());
    }
}
