//! Modified Coulomb friction of Ambrósio.
//!
//! `F_t = -c_d μ F_n sign(v_t)` with the dynamic correction
//! `c_d = 0` for `|v| < v0`, `(|v| - v0)/(v1 - v0)` for `v0 <= |v| <= v1`,
//! `1` for `|v| > v1`. The dead band below v0 avoids the sign switch of
//! Coulomb friction near zero sliding speed. Source: J. A. C. Ambrósio,
//! "Impact of rigid and flexible multibody systems: deformation description
//! and contact models", in Virtual Nonlinear Multibody Systems, NATO
//! Science Series II vol. 103, Kluwer (2003) 57-81; used by paper 001.
//! Theory page: `docs/theory/friction-ambrosio.md`.

use super::checked_coefficient;

/// Modified Coulomb friction with a dead band and a linear ramp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AmbrosioCoulomb {
    coefficient: f64,
    v0: f64,
    v1: f64,
}

impl AmbrosioCoulomb {
    /// Builds the law from μ >= 0 [-], the dead-band limit v0 >= 0 [m/s] and
    /// the full-friction speed v1 > v0 [m/s].
    pub fn new(coefficient: f64, v0: f64, v1: f64) -> Result<Self, String> {
        let coefficient = checked_coefficient("friction coefficient", coefficient)?;
        if !(v0.is_finite() && v0 >= 0.0) {
            return Err(format!("dead-band velocity v0 must be finite and >= 0 m/s, got {v0}"));
        }
        if !(v1.is_finite() && v1 > v0) {
            return Err(format!(
                "full-friction velocity v1 must be finite and > v0 = {v0} m/s, got {v1}"
            ));
        }
        Ok(Self { coefficient, v0, v1 })
    }

    /// Friction coefficient μ [-].
    pub fn coefficient(&self) -> f64 {
        self.coefficient
    }

    /// Dead-band limit v0 [m/s].
    pub fn v0(&self) -> f64 {
        self.v0
    }

    /// Speed v1 [m/s] from which full friction acts.
    pub fn v1(&self) -> f64 {
        self.v1
    }

    /// Dynamic correction c_d [-] at the sliding speed |v| [m/s].
    pub fn dynamic_correction(&self, speed: f64) -> f64 {
        ((speed - self.v0) / (self.v1 - self.v0)).clamp(0.0, 1.0)
    }

    /// c_d μ sign(v) [-]: the coefficient carrying the sign of v.
    pub(super) fn signed_coefficient(&self, sliding_velocity: f64) -> f64 {
        if sliding_velocity == 0.0 || sliding_velocity.is_nan() {
            return 0.0;
        }
        let magnitude = self.coefficient * self.dynamic_correction(sliding_velocity.abs());
        magnitude.copysign(sliding_velocity)
    }
}

#[cfg(test)]
mod tests {
    use super::super::FrictionLaw;
    use super::*;

    fn law() -> FrictionLaw {
        FrictionLaw::Ambrosio(AmbrosioCoulomb::new(0.1, 1e-4, 1e-3).unwrap())
    }

    #[test]
    fn test_ambrosio_matches_piecewise_closed_form() {
        // (velocity, c_d): dead band, band edges, mid-ramp, full friction
        let points = [(5e-5, 0.0), (1e-4, 0.0), (5.5e-4, 0.5), (1e-3, 1.0), (2e-3, 1.0)];
        for (velocity, correction) in points {
            let expected = -correction * 0.1 * 200.0;
            assert!(
                (law().friction_force(200.0, velocity) - expected).abs() < 1e-12,
                "v = {velocity}"
            );
            assert!(
                (law().friction_force(200.0, -velocity) + expected).abs() < 1e-12,
                "v = -{velocity}"
            );
        }
    }

    #[test]
    fn test_ambrosio_is_continuous_at_band_edges() {
        for edge in [1e-4, 1e-3] {
            let below = law().friction_force(200.0, edge * (1.0 - 1e-9));
            let above = law().friction_force(200.0, edge * (1.0 + 1e-9));
            assert!((below - above).abs() < 1e-6, "edge {edge}");
        }
    }

    #[test]
    fn test_ambrosio_constructor_messages() {
        assert_eq!(
            AmbrosioCoulomb::new(0.1, 1e-3, 1e-3).unwrap_err(),
            "full-friction velocity v1 must be finite and > v0 = 0.001 m/s, got 0.001"
        );
        assert_eq!(
            AmbrosioCoulomb::new(0.1, -1e-3, 1e-3).unwrap_err(),
            "dead-band velocity v0 must be finite and >= 0 m/s, got -0.001"
        );
    }
}
