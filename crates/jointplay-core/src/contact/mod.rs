//! Normal contact force of a journal in a bore: the elastic law (contact
//! stiffness) and the dissipative law (hysteresis damping).
//!
//! The normal force on penetration is
//! `F = F_el(δ) (1 + D(e) δ̇ / δ̇⁻)`, clamped to `F >= 0`, where
//! `F_el` comes from a [`ContactStiffness`] and `D(e)` from a
//! [`NormalForceLaw`]. Each law lives in its own file and has a theory page
//! in `docs/theory/`.

mod flores;
mod gonthier;
mod hertz;
mod hertz_cylinder;
mod hu_guo;
mod hunt_crossley;
mod johnson_line;
mod lankarani_nikravesh;
mod logarithmic;
mod material;
mod pereira_ramalho_ambrosio;
mod power_law;
mod rogers_andrews;

#[cfg(test)]
mod impact_test;
#[cfg(test)]
mod implicit_law_checks;

pub use hertz_cylinder::HertzCylinder;
pub use johnson_line::JohnsonLine;
pub use material::Material;
pub(crate) use material::effective_modulus;
pub use pereira_ramalho_ambrosio::PereiraRamalhoAmbrosio;
pub use power_law::{PowerLaw, PowerLawStiffness};
pub use rogers_andrews::RogersAndrews;

use crate::spec::{ranges, Range};

/// Dissipative normal force law: which hysteresis factor `D(e)` multiplies
/// the penetration rate.
///
/// All laws share `F = F_el(δ) (1 + D(e) δ̇ / δ̇⁻)`; they differ only in how
/// the coefficient of restitution `e` [-] maps to `D` [-].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NormalForceLaw {
    /// Hertz (1882): purely elastic, `D = 0`.
    Hertz,
    /// Hunt and Crossley (1975): `D = 3(1-e)/2`.
    HuntCrossley {
        /// Coefficient of restitution e, 0 <= e <= 1 [-].
        restitution: f64,
    },
    /// Lankarani and Nikravesh (1990): `D = 3(1-e²)/4`.
    LankaraniNikravesh {
        /// Coefficient of restitution e, 0 <= e <= 1 [-].
        restitution: f64,
    },
    /// Flores et al. (2011): `D = 8(1-e)/(5e)`.
    Flores {
        /// Coefficient of restitution e, 0 < e <= 1 [-].
        restitution: f64,
    },
    /// Gonthier et al. (2004): `D = (1-e²)/e`.
    Gonthier {
        /// Coefficient of restitution e, 0 < e <= 1 [-].
        restitution: f64,
    },
    /// Hu and Guo (2015): `D = 3(1-e)/(2e)`.
    HuGuo {
        /// Coefficient of restitution e, 0 < e <= 1 [-].
        restitution: f64,
    },
}

impl NormalForceLaw {
    /// The coefficient of restitution with its allowed range (defined in
    /// `python/jointplay/parameters.py`, [`crate::spec::ranges`]); none for Hertz.
    ///
    /// Hunt-Crossley and Lankarani-Nikravesh accept `0 <= e <= 1` (`D(0)` is
    /// finite); the laws that divide by `e` (Flores, Gonthier, Hu-Guo) need
    /// `0 < e <= 1`.
    pub fn restitution(&self) -> Option<(Range, f64)> {
        match *self {
            Self::Hertz => None,
            Self::HuntCrossley { restitution } => Some((ranges::CONTACT_HUNT_CROSSLEY_RESTITUTION, restitution)),
            Self::LankaraniNikravesh { restitution } => Some((ranges::CONTACT_LANKARANI_NIKRAVESH_RESTITUTION, restitution)),
            Self::Flores { restitution } => Some((ranges::CONTACT_FLORES_RESTITUTION, restitution)),
            Self::Gonthier { restitution } => Some((ranges::CONTACT_GONTHIER_RESTITUTION, restitution)),
            Self::HuGuo { restitution } => Some((ranges::CONTACT_HU_GUO_RESTITUTION, restitution)),
        }
    }

    /// Checks the coefficient of restitution against its range
    /// ([`Self::restitution`]) and returns the law unchanged.
    pub fn validated(self) -> Result<Self, String> {
        match self.restitution() {
            None => Ok(self),
            Some((range, restitution)) => range.check(restitution).map(|_| self).map_err(|message| format!("restitution {message}")),
        }
    }

    /// Hysteresis factor D(e) [-].
    pub fn hysteresis_factor(&self) -> f64 {
        match *self {
            Self::Hertz => hertz::hysteresis_factor(),
            Self::HuntCrossley { restitution } => hunt_crossley::hysteresis_factor(restitution),
            Self::LankaraniNikravesh { restitution } => {
                lankarani_nikravesh::hysteresis_factor(restitution)
            }
            Self::Flores { restitution } => flores::hysteresis_factor(restitution),
            Self::Gonthier { restitution } => gonthier::hysteresis_factor(restitution),
            Self::HuGuo { restitution } => hu_guo::hysteresis_factor(restitution),
        }
    }

    /// Total normal force [N] from the elastic force [N], the penetration
    /// rate δ̇ [m/s] (positive while approaching) and the approach velocity
    /// latched at contact onset δ̇⁻ [m/s].
    ///
    /// `F = F_el (1 + D δ̇/δ̇⁻)`, clamped to `F >= 0`: the contact pushes,
    /// never pulls. Without the clamp the damping term makes the force
    /// negative (adhesive) late in the restitution phase of a lossy impact;
    /// the clamp is what lets the bodies separate there. The caller floors
    /// δ̇⁻ at a small positive velocity; a non-positive or non-finite δ̇⁻ is
    /// treated as "no damping" rather than divided by.
    pub fn normal_force(
        &self,
        elastic_force: f64,
        penetration_rate: f64,
        onset_velocity: f64,
    ) -> f64 {
        let damping = if onset_velocity > 0.0 && onset_velocity.is_finite() {
            self.hysteresis_factor() * penetration_rate / onset_velocity
        } else {
            0.0
        };
        (elastic_force * (1.0 + damping)).max(0.0)
    }
}

/// Elastic law of a journal pressed into its bore: normal force and stored
/// energy as functions of the penetration depth δ [m].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ContactStiffness {
    /// Hertz-type power law `F = K δ^n` with the Flores stiffness.
    HertzCylinder(HertzCylinder),
    /// Johnson (1985) line contact of a cylinder of length L in a bore.
    JohnsonLine(JohnsonLine),
    /// Logarithmic law of Rogers and Andrews (1977), after Dubowsky and Freudenstein.
    RogersAndrews(RogersAndrews),
    /// Power law fitted by Pereira, Ramalho and Ambrósio (2011) to internal cylinder contact of length L.
    PereiraRamalhoAmbrosio(PereiraRamalhoAmbrosio),
}

impl ContactStiffness {
    /// Elastic normal force [N] for a penetration δ >= 0 [m] (0 for δ <= 0). Does not allocate.
    pub fn elastic_force(&self, penetration: f64) -> f64 {
        match self {
            Self::HertzCylinder(law) => law.elastic_force(penetration),
            Self::JohnsonLine(law) => law.elastic_force(penetration),
            Self::RogersAndrews(law) => law.elastic_force(penetration),
            Self::PereiraRamalhoAmbrosio(law) => law.elastic_force(penetration),
        }
    }

    /// Elastic potential energy stored at penetration δ [J], `∫0^δ F_el dδ`
    /// (closed form for every law). Does not allocate.
    pub fn elastic_energy(&self, penetration: f64) -> f64 {
        match self {
            Self::HertzCylinder(law) => law.elastic_energy(penetration),
            Self::JohnsonLine(law) => law.elastic_energy(penetration),
            Self::RogersAndrews(law) => law.elastic_energy(penetration),
            Self::PereiraRamalhoAmbrosio(law) => law.elastic_energy(penetration),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn test_normal_force_is_elastic_force_at_zero_rate() {
        let law = NormalForceLaw::LankaraniNikravesh { restitution: 0.5 };
        assert_eq!(law.normal_force(120.0, 0.0, 0.3), 120.0);
    }

    #[test]
    fn test_normal_force_adds_damping_proportional_to_rate() {
        // d = 3(1 - 0.25)/4 = 0.5625; rate/onset = 0.5
        let law = NormalForceLaw::LankaraniNikravesh { restitution: 0.5 };
        let force = law.normal_force(100.0, 0.15, 0.3);
        assert!((force - 100.0 * (1.0 + 0.5625 * 0.5)).abs() < 1e-12);
    }

    #[test]
    fn test_normal_force_never_pulls() {
        let law = NormalForceLaw::Flores { restitution: 0.3 };
        assert_eq!(law.normal_force(100.0, -10.0, 0.1), 0.0);
    }

    #[test]
    fn test_normal_force_ignores_damping_for_non_positive_onset_velocity() {
        let law = NormalForceLaw::HuntCrossley { restitution: 0.5 };
        assert_eq!(law.normal_force(50.0, 1.0, 0.0), 50.0);
        assert_eq!(law.normal_force(50.0, 1.0, -1.0), 50.0);
    }

    #[test]
    fn test_validated_rejects_restitution_out_of_range() {
        let error = NormalForceLaw::Flores { restitution: 0.0 }.validated().unwrap_err();
        assert_eq!(error, "restitution must lie in (0, 1], got 0");
        let error = NormalForceLaw::HuntCrossley { restitution: 1.5 }.validated().unwrap_err();
        assert_eq!(error, "restitution must lie in [0, 1], got 1.5");
        // D(0) = 3/2 is finite for Hunt-Crossley: a perfectly plastic impact is a valid input there
        assert!(NormalForceLaw::HuntCrossley { restitution: 0.0 }.validated().is_ok());
        assert!(NormalForceLaw::HuntCrossley { restitution: 0.0 }.validated().is_ok());
        assert!(NormalForceLaw::Gonthier { restitution: f64::NAN }.validated().is_err());
    }

    #[test]
    fn test_contact_stiffness_dispatches_to_the_law() {
        let steel = Material { youngs_modulus: 207e9, poisson_ratio: 0.3 };
        let hertz = HertzCylinder::new(0.01, 0.0095, steel, steel, 1.5).unwrap();
        let stiffness = ContactStiffness::HertzCylinder(hertz);
        assert_eq!(stiffness.elastic_force(1e-5), hertz.elastic_force(1e-5));
        assert_eq!(stiffness.elastic_energy(1e-5), hertz.elastic_energy(1e-5));
        assert_eq!(stiffness.elastic_force(-1e-5), 0.0);
    }
}
