//! Coulomb friction regularised by a hyperbolic tangent.
//!
//! `F_t = -μ F_n tanh(v_t / v_tol)`. The tanh is chosen over a linear ramp
//! because it is smooth (C∞), odd, and within 0.1 % of full Coulomb friction
//! beyond 4 v_tol; the price is a small creep force below v_tol, so the law
//! cannot hold a body at rest against a load (true sticking needs a
//! stiction law). Theory page: `docs/theory/friction-coulomb.md`.

use super::{checked_coefficient, checked_velocity};

/// Coulomb friction with tanh regularisation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RegularisedCoulomb {
    coefficient: f64,
    velocity_tolerance: f64,
}

impl RegularisedCoulomb {
    /// Builds the law from the friction coefficient μ >= 0 [-] and the
    /// regularisation velocity v_tol > 0 [m/s].
    pub fn new(coefficient: f64, velocity_tolerance: f64) -> Result<Self, String> {
        Ok(Self {
            coefficient: checked_coefficient("friction coefficient", coefficient)?,
            velocity_tolerance: checked_velocity("velocity tolerance", velocity_tolerance)?,
        })
    }

    /// Friction coefficient μ [-].
    pub fn coefficient(&self) -> f64 {
        self.coefficient
    }

    /// Regularisation velocity v_tol [m/s].
    pub fn velocity_tolerance(&self) -> f64 {
        self.velocity_tolerance
    }

    /// μ tanh(v/v_tol) [-]: the coefficient carrying the sign of v.
    pub(super) fn signed_coefficient(&self, sliding_velocity: f64) -> f64 {
        self.coefficient * (sliding_velocity / self.velocity_tolerance).tanh()
    }
}

#[cfg(test)]
mod tests {
    use super::super::FrictionLaw;
    use super::*;

    #[test]
    fn test_coulomb_matches_tanh_closed_form() {
        let law = FrictionLaw::Coulomb(RegularisedCoulomb::new(0.2, 1e-3).unwrap());
        for velocity in [-3e-3, -1e-3, 2e-4, 1e-3, 5e-3] {
            let expected = -0.2 * 50.0 * (velocity / 1e-3_f64).tanh();
            assert!((law.friction_force(50.0, velocity) - expected).abs() < 1e-12);
        }
        // at v = v_tol the force is tanh(1) = 76.2 % of μ F_n
        assert!((law.friction_force(50.0, 1e-3) + 10.0 * 0.761_594_155_955_764_9).abs() < 1e-12);
    }

    #[test]
    fn test_coulomb_constructor_messages() {
        assert_eq!(
            RegularisedCoulomb::new(-0.1, 1e-3).unwrap_err(),
            "friction coefficient must be finite and >= 0, got -0.1"
        );
        assert_eq!(
            RegularisedCoulomb::new(0.1, 0.0).unwrap_err(),
            "velocity tolerance must be finite and > 0 m/s, got 0"
        );
    }
}
