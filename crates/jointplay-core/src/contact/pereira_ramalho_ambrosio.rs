//! Pereira-Ramalho-Ambrósio fitted law of a journal pressed into its bore
//! (internal contact of cylinders of length L).
//!
//! In the units of the fit (F [N]; ΔR, L, δ [mm]; E* [MPa = N/mm²]):
//!
//! `F = ((a ΔR + b) / ΔR) L E* δ^n`, `n = Y ΔR^(-0.005)`,
//! `a = 0.965`, `b = 0.0965 mm`,
//! `Y = 1.51 (ln(1000 ΔR))^(-0.151)` for `0.005 mm <= ΔR <= 0.34954 mm`,
//! `Y = 0.0151 ΔR + 1.151` for `0.34954 mm < ΔR <= 10 mm`,
//! with `ΔR = R_b - R_j` and `1/E* = Σ (1-ν²)/E`. The law is a power law in
//! δ, so in SI units it is `F = K δ^n` with `K [N/m^n]` converted once here.
//!
//! Source: C. M. Pereira, A. L. Ramalho, J. A. Ambrósio, "A critical overview
//! of internal and external cylinder contact force models", Nonlinear Dyn. 63
//! (2011) 681-697, a fit to finite-element results. The paper's text was not
//! at hand: the form and constants are as restated by the implementation that
//! accompanies L. Skrinjar, J. Slavič, M. Boltežar, "A review of continuous
//! contact-force models in multibody dynamics", Int. J. Mech. Sci. 145 (2018)
//! 171-187 (repository ladisk/DyS, `MBD_system/contact_model/contact_model_cylinder.py`,
//! commit d2f0c46, "Validation of cylindrical contact models"), including its
//! range of ΔR. The two pieces of Y meet at ΔR = 0.34954 mm only with ΔR in mm
//! in both (the test checks it), which fixes the units.
//! Theory page: `docs/theory/stiffness-pereira-ramalho-ambrosio.md`.

use super::power_law::{PowerLaw, PowerLawStiffness};
use super::material::{checked_length, effective_modulus, radial_clearance, Material};

/// Millimetres per metre: the fit's length unit.
const MM_PER_M: f64 = 1e3;
/// Megapascals per pascal: the fit's modulus unit.
const MPA_PER_PA: f64 = 1e-6;
/// Slope a of the fit's stiffness factor (a ΔR + b)/ΔR [-].
const SLOPE: f64 = 0.965;
/// Offset b of the fit's stiffness factor (a ΔR + b)/ΔR [mm].
const OFFSET_MM: f64 = 0.0965;
/// Exponent of ΔR [mm] in n = Y ΔR^(-0.005) [-].
const CLEARANCE_EXPONENT: f64 = -0.005;
/// Radial clearance [mm] where Y switches from its logarithmic to its linear piece.
const BREAK_MM: f64 = 0.34954;
/// Smallest radial clearance of the fit [mm].
pub const MIN_CLEARANCE_MM: f64 = 0.005;
/// Largest radial clearance of the fit [mm].
pub const MAX_CLEARANCE_MM: f64 = 10.0;

/// The fit's coefficient Y [-] of the exponent, for a radial clearance ΔR [mm] in the fit's range.
fn exponent_coefficient(clearance_mm: f64) -> f64 {
    if clearance_mm <= BREAK_MM {
        1.51 * (MM_PER_M * clearance_mm).ln().powf(-0.151)
    } else {
        0.0151 * clearance_mm + 1.151
    }
}

/// The exponent n = Y ΔR^(-0.005) [-] for a radial clearance ΔR [mm].
fn exponent(clearance_mm: f64) -> f64 {
    exponent_coefficient(clearance_mm) * clearance_mm.powf(CLEARANCE_EXPONENT)
}

/// Pereira-Ramalho-Ambrósio (2011) internal cylinder contact: `F = K δ^n`,
/// the exponent n between 1.15 and 1.45 over the fit's range.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PereiraRamalhoAmbrosio {
    law: PowerLaw,
}

impl PereiraRamalhoAmbrosio {
    /// Builds the law from the bore radius R_b [m], the journal radius
    /// R_j < R_b [m], the contact length L [m] and the two materials.
    /// Refuses a radial clearance outside the fit's range, 0.005 mm to 10 mm.
    pub fn new(
        bearing_radius: f64,
        journal_radius: f64,
        length: f64,
        bearing: Material,
        journal: Material,
    ) -> Result<Self, String> {
        let clearance_mm = radial_clearance(bearing_radius, journal_radius)? * MM_PER_M;
        let length_mm = checked_length(length)? * MM_PER_M;
        let modulus_mpa = effective_modulus(&bearing.validated("bearing")?, &journal.validated("journal")?) * MPA_PER_PA;
        if !(MIN_CLEARANCE_MM..=MAX_CLEARANCE_MM).contains(&clearance_mm) {
            // shown to the picometre: R_b - R_j carries the round-off of R_j = R_b - c
            let shown = (clearance_mm * 1e9).round() / 1e9;
            return Err(format!(
                "radial clearance must lie in [{MIN_CLEARANCE_MM}, {MAX_CLEARANCE_MM}] mm, the range of the \
                 Pereira-Ramalho-Ambrosio fit, got {shown} mm"
            ));
        }
        let exponent = exponent(clearance_mm);
        // N/mm^n from the fit, then N/m^n: δ_mm^n = (1000 δ_m)^n
        let stiffness_mm = (SLOPE * clearance_mm + OFFSET_MM) / clearance_mm * length_mm * modulus_mpa;
        Ok(Self { law: PowerLaw { stiffness: stiffness_mm * MM_PER_M.powf(exponent), exponent } })
    }
}

impl PowerLawStiffness for PereiraRamalhoAmbrosio {
    fn power_law(&self) -> &PowerLaw {
        &self.law
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::JohnsonLine;

    const STEEL: Material = Material { youngs_modulus: 207e9, poisson_ratio: 0.3 };

    /// The Flores slider-crank's joint: R_b = 10 mm, ΔR = 0.5 mm, L = 40 mm, steel on steel.
    fn flores_joint() -> PereiraRamalhoAmbrosio {
        PereiraRamalhoAmbrosio::new(0.010, 0.0095, 0.040, STEEL, STEEL).unwrap()
    }

    #[test]
    fn test_force_matches_the_fit_evaluated_in_its_own_units() {
        // ΔR = 0.5 mm: Y = 0.0151*0.5 + 1.151 = 1.15855, n = 1.15855 * 0.5^-0.005 = 1.162572;
        // E* = 207000 MPa / 1.82 = 113736.26 MPa; (0.965*0.5 + 0.0965)/0.5 = 1.158;
        // δ = 0.01 mm: F = 1.158 * 40 mm * 113736.26 MPa * 0.01^1.162572 = 24 919 N (by hand, 5 digits)
        let modulus_mpa = 207e3 / 1.82;
        let n = 1.15855 * 0.5_f64.powf(-0.005);
        let by_units_of_the_fit = 1.158 * 40.0 * modulus_mpa * 0.01_f64.powf(n);
        let law = flores_joint();
        assert!((law.exponent() / n - 1.0).abs() < 1e-14, "n = {}", law.exponent());
        assert!((law.elastic_force(1e-5) / by_units_of_the_fit - 1.0).abs() < 1e-12);
        assert!((by_units_of_the_fit / 24_919.0 - 1.0).abs() < 1e-4, "hand value {by_units_of_the_fit}");
    }

    #[test]
    fn test_the_two_pieces_of_y_meet_at_the_published_break_with_clearance_in_mm() {
        // 1.51 ln(349.54)^-0.151 = 1.156241 and 0.0151*0.34954 + 1.151 = 1.156278: the constants as
        // restated meet to 3e-5; read with ΔR in m the linear piece would be 1.151005, 0.5 % off.
        let logarithmic = 1.51 * (MM_PER_M * BREAK_MM).ln().powf(-0.151);
        let linear = 0.0151 * BREAK_MM + 1.151;
        assert!((logarithmic / linear - 1.0).abs() < 1e-4, "{logarithmic} vs {linear}");
        assert!((exponent_coefficient(BREAK_MM) / exponent_coefficient(BREAK_MM * (1.0 + 1e-12)) - 1.0).abs() < 1e-4);
    }

    #[test]
    fn test_exponent_spans_the_range_documented_over_the_fit() {
        // n falls from 1.443 at 0.005 mm to its minimum near the break and rises to 1.287 at 10 mm
        for (clearance_mm, expected) in [(0.005, 1.4430), (BREAK_MM, 1.1624), (10.0, 1.2871)] {
            assert!((exponent(clearance_mm) - expected).abs() < 1e-4, "ΔR = {clearance_mm} mm: n = {}", exponent(clearance_mm));
        }
    }

    #[test]
    fn test_energy_is_the_integral_of_the_force() {
        let law = flores_joint();
        for penetration in [1e-7, 1e-5, 2e-4] {
            let intervals = 200_000;
            let width = penetration / intervals as f64;
            let mut integral = 0.5 * law.elastic_force(penetration);
            for k in 1..intervals {
                integral += law.elastic_force(k as f64 * width);
            }
            integral *= width;
            let energy = law.elastic_energy(penetration);
            assert!((energy / integral - 1.0).abs() < 1e-6, "δ = {penetration}: {energy} vs {integral}");
        }
        assert_eq!(law.elastic_energy(-1e-6), 0.0);
    }

    #[test]
    fn test_force_rises_strictly_with_penetration_and_vanishes_without_it() {
        let law = flores_joint();
        let mut previous = 0.0;
        for step in 1..=2000 {
            let force = law.elastic_force(0.5e-3 * step as f64 / 2000.0);
            assert!(force > previous, "not increasing at step {step}");
            previous = force;
        }
        assert_eq!(law.elastic_force(0.0), 0.0);
        assert_eq!(law.elastic_force(-1e-6), 0.0);
    }

    #[test]
    fn test_agrees_with_johnson_line_contact_within_twenty_percent() {
        // Both laws describe the same elastic line contact; the fit follows finite-element results that
        // Johnson's closed form also approximates. Over 1e-3 <= δ/ΔR <= 0.1 and ΔR from 0.1 mm to 5 mm
        // the two closed forms differ by -17 % to +17 %. A units slip (m for mm: factor 1000^(n-1) ≈ 3),
        // a π in E* or a and b swapped (factor 1.75 at ΔR = 0.5 mm) would leave this band.
        for clearance in [1e-4, 5e-4, 1e-3, 5e-3] {
            let bearing_radius = 0.010 + clearance;
            let law = PereiraRamalhoAmbrosio::new(bearing_radius, 0.010, 0.040, STEEL, STEEL).unwrap();
            let johnson = JohnsonLine::new(bearing_radius, 0.010, 0.040, STEEL, STEEL).unwrap();
            for step in 0..=20 {
                let penetration = clearance * 10f64.powf(-3.0 + 2.0 * step as f64 / 20.0);
                let ratio = law.elastic_force(penetration) / johnson.elastic_force(penetration);
                assert!((0.8..1.2).contains(&ratio), "ΔR = {clearance} m, δ = {penetration} m: ratio {ratio}");
            }
        }
    }

    #[test]
    fn test_constructor_refuses_clearances_outside_the_fit() {
        assert_eq!(
            PereiraRamalhoAmbrosio::new(0.010, 0.009_999, 0.040, STEEL, STEEL).unwrap_err(),
            "radial clearance must lie in [0.005, 10] mm, the range of the Pereira-Ramalho-Ambrosio fit, got 0.001 mm"
        );
        assert!(PereiraRamalhoAmbrosio::new(0.030, 0.019, 0.040, STEEL, STEEL).is_err());
        assert!(PereiraRamalhoAmbrosio::new(0.010, 0.009_994, 0.040, STEEL, STEEL).is_ok());
        assert!(PereiraRamalhoAmbrosio::new(0.0289, 0.019, 0.040, STEEL, STEEL).is_ok());
    }

    #[test]
    fn test_constructor_refuses_bad_length_and_material() {
        assert_eq!(
            PereiraRamalhoAmbrosio::new(0.01, 0.0095, 0.0, STEEL, STEEL).unwrap_err(),
            "contact length must be finite and > 0 m, got 0"
        );
        let soft = Material { youngs_modulus: -1.0, poisson_ratio: 0.3 };
        assert!(PereiraRamalhoAmbrosio::new(0.01, 0.0095, 0.04, soft, STEEL).is_err());
        assert!(PereiraRamalhoAmbrosio::new(0.0095, 0.01, 0.04, STEEL, STEEL).is_err());
    }
}
