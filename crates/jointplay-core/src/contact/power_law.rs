//! The power law `F = K delta^n` of the Hertz-type and the
//! Pereira-Ramalho-Ambrósio stiffness laws: force and stored energy.

/// A stiffness law `F = K delta^n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PowerLaw {
    /// Generalised stiffness K [N/m^n].
    pub stiffness: f64,
    /// Exponent n [-].
    pub exponent: f64,
}

impl PowerLaw {
    /// Elastic force K δ^n [N] for penetration δ [m] (0 for δ <= 0).
    #[inline]
    pub fn elastic_force(&self, penetration: f64) -> f64 {
        if penetration > 0.0 {
            // the metal-contact exponent 1.5 is by far the most common: sqrt is cheaper than powf
            let power = if self.exponent == 1.5 { penetration * penetration.sqrt() } else { penetration.powf(self.exponent) };
            self.stiffness * power
        } else {
            0.0
        }
    }

    /// Stored energy K δ^(n+1)/(n+1) [J] for penetration δ [m] (0 for δ <= 0).
    #[inline]
    pub fn elastic_energy(&self, penetration: f64) -> f64 {
        if penetration > 0.0 {
            self.elastic_force(penetration) * penetration / (self.exponent + 1.0)
        } else {
            0.0
        }
    }
}

/// A stiffness law that is the power law `F = K delta^n` once its constants
/// are found from the joint's geometry and materials: its force, energy and
/// constants are the power law's.
pub trait PowerLawStiffness {
    /// The law with its constants.
    fn power_law(&self) -> &PowerLaw;

    /// Generalised stiffness K [N/m^n].
    fn stiffness(&self) -> f64 {
        self.power_law().stiffness
    }

    /// Exponent n [-].
    fn exponent(&self) -> f64 {
        self.power_law().exponent
    }

    /// Elastic force K δ^n [N] for penetration δ [m] (0 for δ <= 0).
    #[inline]
    fn elastic_force(&self, penetration: f64) -> f64 {
        self.power_law().elastic_force(penetration)
    }

    /// Stored energy K δ^(n+1)/(n+1) [J] for penetration δ [m] (0 for δ <= 0).
    #[inline]
    fn elastic_energy(&self, penetration: f64) -> f64 {
        self.power_law().elastic_energy(penetration)
    }
}
