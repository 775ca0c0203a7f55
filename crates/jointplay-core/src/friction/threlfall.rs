//! Threlfall's regularised Coulomb friction.
//!
//! `F_t = -μ F_n (1 - exp(-3|v_t|/v0)) sign(v_t)`: the friction reaches
//! 1 - e⁻³ = 95 % of μ F_n at the speed v0. Source: D. C. Threlfall, "The
//! inclusion of Coulomb friction in mechanisms programs with particular
//! reference to DRAM", Mech. Mach. Theory 13(4) (1978) 475-483; as reviewed
//! by E. Pennestrì et al., "Review and comparison of dry friction force
//! models", Nonlinear Dyn. 83 (2016) 1785-1801.
//! Theory page: `docs/theory/friction-threlfall.md`.

use super::{checked_coefficient, checked_velocity};

/// Threlfall's exponential friction law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Threlfall {
    coefficient: f64,
    v0: f64,
}

impl Threlfall {
    /// Builds the law from μ >= 0 [-] and the 95 %-friction speed v0 > 0 [m/s].
    pub fn new(coefficient: f64, v0: f64) -> Result<Self, String> {
        Ok(Self {
            coefficient: checked_coefficient("friction coefficient", coefficient)?,
            v0: checked_velocity("velocity v0", v0)?,
        })
    }

    /// Friction coefficient μ [-].
    pub fn coefficient(&self) -> f64 {
        self.coefficient
    }

    /// Speed v0 [m/s] at which 95 % of full friction acts.
    pub fn v0(&self) -> f64 {
        self.v0
    }

    /// μ (1 - exp(-3|v|/v0)) sign(v) [-]: the coefficient carrying the sign of v.
    pub(super) fn signed_coefficient(&self, sliding_velocity: f64) -> f64 {
        // -expm1(-x) = 1 - exp(-x), exact to rounding for small x; odd in v
        let fraction = -(-3.0 * sliding_velocity.abs() / self.v0).exp_m1();
        (self.coefficient * fraction).copysign(sliding_velocity)
    }
}

#[cfg(test)]
mod tests {
    use super::super::FrictionLaw;
    use super::*;

    #[test]
    fn test_threlfall_matches_closed_form() {
        let law = FrictionLaw::Threlfall(Threlfall::new(0.3, 2e-3).unwrap());
        for velocity in [1e-6, 5e-4, 2e-3, 1e-2] {
            let expected = -0.3 * 10.0 * (1.0 - (-3.0 * velocity / 2e-3_f64).exp());
            assert!(
                (law.friction_force(10.0, velocity) - expected).abs() < 1e-13,
                "v = {velocity}"
            );
        }
        // 95.0213 % of μ F_n at v = v0
        assert!((law.friction_force(10.0, 2e-3) / -3.0 - 0.950_212_931_632_136).abs() < 1e-12);
    }

    #[test]
    fn test_threlfall_is_continuous_through_zero() {
        let law = FrictionLaw::Threlfall(Threlfall::new(0.3, 2e-3).unwrap());
        // slope at zero: -3 μ F_n / v0
        let slope = (law.friction_force(10.0, 1e-9) - law.friction_force(10.0, -1e-9)) / 2e-9;
        assert!((slope / (-3.0 * 3.0 / 2e-3) - 1.0).abs() < 1e-5);
    }

    #[test]
    fn test_threlfall_constructor_messages() {
        assert_eq!(
            Threlfall::new(0.3, -1.0).unwrap_err(),
            "velocity v0 must be finite and > 0 m/s, got -1"
        );
    }
}
