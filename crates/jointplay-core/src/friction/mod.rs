//! Tangential friction force at a contact point.
//!
//! Every law returns the friction force [N] along the tangent, opposing the
//! sliding velocity v_t [m/s], for a normal force F_n >= 0 [N]. Each law
//! lives in its own file and has a theory page in `docs/theory/`.

mod ambrosio;
mod coulomb;
mod lugre;
mod stiction;
mod threlfall;

pub use ambrosio::AmbrosioCoulomb;
pub use coulomb::RegularisedCoulomb;
pub use lugre::{LugreFriction, LugreOutput, DEFAULT_DAMPING_VELOCITY, DEFAULT_STICK_VELOCITY};
pub use stiction::StictionFriction;
pub use threlfall::Threlfall;

/// Friction law of a contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FrictionLaw {
    /// Frictionless contact.
    None,
    /// Coulomb friction regularised by tanh.
    Coulomb(RegularisedCoulomb),
    /// Modified Coulomb law of Ambrósio (dead band, linear ramp, full friction).
    Ambrosio(AmbrosioCoulomb),
    /// Threlfall's exponential regularisation of Coulomb friction.
    Threlfall(Threlfall),
    /// Static and kinetic coefficients joined by cubic steps (ADAMS-style stiction).
    Stiction(StictionFriction),
}

impl FrictionLaw {
    /// Friction force [N] along the tangent, opposing the sliding velocity
    /// v_t [m/s], for a normal force F_n >= 0 [N]. Negative for v_t > 0.
    /// A negative normal force is treated as zero. Does not allocate.
    pub fn friction_force(&self, normal_force: f64, sliding_velocity: f64) -> f64 {
        let normal_force = normal_force.max(0.0);
        let coefficient = match self {
            Self::None => return 0.0,
            Self::Coulomb(law) => law.signed_coefficient(sliding_velocity),
            Self::Ambrosio(law) => law.signed_coefficient(sliding_velocity),
            Self::Threlfall(law) => law.signed_coefficient(sliding_velocity),
            Self::Stiction(law) => law.signed_coefficient(sliding_velocity),
        };
        -coefficient * normal_force
    }
}

/// Checks that a friction coefficient is finite and >= 0.
fn checked_coefficient(name: &str, value: f64) -> Result<f64, String> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(format!("{name} must be finite and >= 0, got {value}"))
    }
}

/// Checks that a velocity is finite and > 0 [m/s].
fn checked_velocity(name: &str, value: f64) -> Result<f64, String> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(format!("{name} must be finite and > 0 m/s, got {value}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all_laws() -> [FrictionLaw; 5] {
        [
            FrictionLaw::None,
            FrictionLaw::Coulomb(RegularisedCoulomb::new(0.1, 1e-3).unwrap()),
            FrictionLaw::Ambrosio(AmbrosioCoulomb::new(0.1, 1e-4, 1e-3).unwrap()),
            FrictionLaw::Threlfall(Threlfall::new(0.1, 1e-3).unwrap()),
            FrictionLaw::Stiction(StictionFriction::new(0.15, 0.1, 1e-4, 5e-4).unwrap()),
        ]
    }

    #[test]
    fn test_every_law_opposes_sliding_and_is_odd() {
        for law in all_laws() {
            for velocity in [1e-5, 3e-4, 2e-3, 1.0] {
                let forward = law.friction_force(100.0, velocity);
                let backward = law.friction_force(100.0, -velocity);
                assert!(forward <= 0.0, "{law:?} at {velocity}");
                assert_eq!(forward, -backward, "{law:?} at {velocity}");
            }
        }
    }

    #[test]
    fn test_every_law_is_zero_at_zero_velocity_and_zero_load() {
        for law in all_laws() {
            assert_eq!(law.friction_force(100.0, 0.0), 0.0, "{law:?}");
            assert_eq!(law.friction_force(0.0, 1.0), 0.0, "{law:?}");
            assert_eq!(law.friction_force(-5.0, 1.0), 0.0, "{law:?}");
        }
    }

    #[test]
    fn test_every_law_reaches_kinetic_friction_at_high_speed() {
        for law in all_laws().into_iter().skip(1) {
            let force = law.friction_force(100.0, 10.0);
            assert!((force + 10.0).abs() < 1e-9, "{law:?}: {force}");
        }
    }
}
