//! Friction with stiction: static and kinetic coefficients joined by cubic
//! steps, as in ADAMS.
//!
//! With `STEP(x, x0, h0, x1, h1) = h0 + (h1 - h0) s²(3 - 2s)`,
//! `s = (x - x0)/(x1 - x0)` clamped to [0, 1], the coefficient is
//!
//! - `|v| <= v_s`: `STEP(v, -v_s, -μs, v_s, μs)` (0 at v = 0, ±μs at ±v_s),
//! - `v_s < |v| < v_t`: `sign(v) STEP(|v|, v_s, μs, v_t, μk)`,
//! - `|v| >= v_t`: `sign(v) μk`,
//!
//! and `F_t = -μ(v) F_n`. Paper 002 uses this shape for the rod-seal
//! friction (F_S = 385 N, F_C = 340 N, tolerances 0.01 and 0.05 mm/s),
//! written with forces rather than coefficients: pass F_S and F_C as the
//! coefficients with a unit normal force to reproduce it.
//! Theory page: `docs/theory/friction-stiction.md`.

use super::{checked_coefficient, checked_velocity};

/// Friction law with a static peak at the stiction velocity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StictionFriction {
    static_coefficient: f64,
    kinetic_coefficient: f64,
    stiction_velocity: f64,
    transition_velocity: f64,
}

impl StictionFriction {
    /// Builds the law from μs >= μk >= 0 [-] and 0 < v_s < v_t [m/s].
    pub fn new(
        static_coefficient: f64,
        kinetic_coefficient: f64,
        stiction_velocity: f64,
        transition_velocity: f64,
    ) -> Result<Self, String> {
        let kinetic_coefficient = checked_coefficient("kinetic coefficient", kinetic_coefficient)?;
        let static_coefficient = checked_coefficient("static coefficient", static_coefficient)?;
        if static_coefficient < kinetic_coefficient {
            return Err(format!(
                "static coefficient must be >= the kinetic coefficient {kinetic_coefficient}, got {static_coefficient}"
            ));
        }
        let stiction_velocity = checked_velocity("stiction velocity", stiction_velocity)?;
        if !(transition_velocity.is_finite() && transition_velocity > stiction_velocity) {
            return Err(format!(
                "transition velocity must be finite and > the stiction velocity {stiction_velocity} m/s, got {transition_velocity}"
            ));
        }
        Ok(Self { static_coefficient, kinetic_coefficient, stiction_velocity, transition_velocity })
    }

    /// Static coefficient μs [-], reached at the stiction velocity.
    pub fn static_coefficient(&self) -> f64 {
        self.static_coefficient
    }

    /// Kinetic coefficient μk [-], reached at the transition velocity.
    pub fn kinetic_coefficient(&self) -> f64 {
        self.kinetic_coefficient
    }

    /// Stiction velocity v_s [m/s].
    pub fn stiction_velocity(&self) -> f64 {
        self.stiction_velocity
    }

    /// Transition velocity v_t [m/s].
    pub fn transition_velocity(&self) -> f64 {
        self.transition_velocity
    }

    /// μ(v) [-]: the coefficient carrying the sign of v.
    pub(super) fn signed_coefficient(&self, sliding_velocity: f64) -> f64 {
        if sliding_velocity == 0.0 || sliding_velocity.is_nan() {
            return 0.0;
        }
        // evaluate at |v| and restore the sign, so the law is exactly odd
        let speed = sliding_velocity.abs();
        let (v_s, mu_s) = (self.stiction_velocity, self.static_coefficient);
        let magnitude = if speed <= v_s {
            cubic_step(speed, -v_s, -mu_s, v_s, mu_s)
        } else {
            cubic_step(speed, v_s, mu_s, self.transition_velocity, self.kinetic_coefficient)
        };
        magnitude.copysign(sliding_velocity)
    }
}

/// ADAMS STEP: h0 + (h1 - h0) s²(3 - 2s), s = (x - x0)/(x1 - x0) clamped to [0, 1].
fn cubic_step(x: f64, x0: f64, h0: f64, x1: f64, h1: f64) -> f64 {
    let s = ((x - x0) / (x1 - x0)).clamp(0.0, 1.0);
    h0 + (h1 - h0) * s * s * (3.0 - 2.0 * s)
}

#[cfg(test)]
mod tests {
    use super::super::FrictionLaw;
    use super::*;

    // paper 002 seal: tolerances 0.01 mm/s and 0.05 mm/s; forces as coefficients
    fn seal() -> FrictionLaw {
        FrictionLaw::Stiction(StictionFriction::new(385.0, 340.0, 1e-5, 5e-5).unwrap())
    }

    #[test]
    fn test_stiction_hits_static_and_kinetic_values_at_the_tolerances() {
        assert!((seal().friction_force(1.0, 1e-5) + 385.0).abs() < 1e-9);
        assert!((seal().friction_force(1.0, -1e-5) - 385.0).abs() < 1e-9);
        assert!((seal().friction_force(1.0, 5e-5) + 340.0).abs() < 1e-9);
        assert!((seal().friction_force(1.0, 1.0) + 340.0).abs() < 1e-9);
    }

    #[test]
    fn test_stiction_matches_cubic_step_inside_both_bands() {
        // |v| = v_s / 2: s = 3/4, μ = -385 + 770 * 0.84375 = 264.6875
        assert!((seal().friction_force(1.0, 5e-6) + 264.6875).abs() < 1e-9);
        // v = 3e-5: s = 1/2, μ = 385 - 45 * 0.5 = 362.5
        assert!((seal().friction_force(1.0, 3e-5) + 362.5).abs() < 1e-9);
    }

    #[test]
    fn test_stiction_is_continuous_with_zero_slope_at_the_tolerances() {
        for edge in [1e-5, 5e-5] {
            let below = seal().friction_force(1.0, edge * (1.0 - 1e-7));
            let above = seal().friction_force(1.0, edge * (1.0 + 1e-7));
            assert!((below - above).abs() < 1e-6, "edge {edge}: {below} vs {above}");
        }
    }

    #[test]
    fn test_stiction_constructor_messages() {
        assert_eq!(
            StictionFriction::new(0.1, 0.2, 1e-5, 5e-5).unwrap_err(),
            "static coefficient must be >= the kinetic coefficient 0.2, got 0.1"
        );
        assert_eq!(
            StictionFriction::new(0.2, 0.1, 5e-5, 5e-5).unwrap_err(),
            "transition velocity must be finite and > the stiction velocity 0.00005 m/s, got 0.00005"
        );
    }
}
