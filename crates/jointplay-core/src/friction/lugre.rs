//! LuGre friction: a bristle model with stiction, the Stribeck effect and
//! presliding, with bristle damping that fades with velocity.
//!
//! With the relative sliding velocity v [m/s] and the mean bristle
//! deflection z [m] (a continuous state of the element that owns the law):
//!
//! ```text
//! g(v)     = F_C + (F_S - F_C) exp(-(v/v_S)^2)          Stribeck curve [N]
//! dz/dt    = v - σ0 |v| z / g(v)                         [m/s]
//! σ1(v)    = σ1 exp(-(v/v_D)^2)                          [N s/m]
//! F        = σ0 z + σ1(v) dz/dt + σ2 v                   [N]
//! ```
//!
//! Sign: F is the *resisting* force in the sense of Canudas de Wit et al.
//! (1995): in steady sliding it has the sign of v, and the body moving at v
//! relative to the other receives -F. (The static laws of this module return
//! the force on the sliding body instead, negative for v > 0.)
//!
//! Sources: C. Canudas de Wit, H. Olsson, K. J. Åström, P. Lischinsky, "A new
//! model for control of systems with friction", IEEE Trans. Autom. Control
//! 40(3) (1995) 419-425 (the model, constant σ1); H. Olsson, K. J. Åström,
//! C. Canudas de Wit, M. Gäfvert, P. Lischinsky, "Friction models and
//! friction compensation", Eur. J. Control 4(3) (1998) 176-195 (damping that
//! decreases with velocity, over the damping velocity v_D). The
//! dissipativity bound checked by [`LugreFriction::new`] is derived on the
//! theory page: `docs/theory/friction-lugre.md`.

use crate::error::{non_negative, positive};
/// Default stick velocity [m/s]: 0.01 mm/s, the stiction tolerance of the
/// rod-seal friction of paper 002 (below it that law is in its sticking band).
pub const DEFAULT_STICK_VELOCITY: f64 = 1.0e-5;

/// Default damping velocity v_D [m/s]: 1 mm/s. The bristle damping then
/// adds at most (1 + F_S/F_C) σ1 v_D / sqrt(2e) to the friction in a
/// transient (9 N for paper 002's seal with σ1 = 1e4 N s/m, under 3 % of
/// its 340 N), yet still damps presliding vibrations up to mm/s (a fade at
/// v_S would leave the oil-spring vibrations of a cylinder undamped above
/// ~0.03 mm/s).
pub const DEFAULT_DAMPING_VELOCITY: f64 = 1.0e-3;

/// LuGre friction law with velocity-dependent bristle damping.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LugreFriction {
    static_force: f64,
    kinetic_force: f64,
    stribeck_velocity: f64,
    bristle_stiffness: f64,
    bristle_damping: f64,
    viscous_coefficient: f64,
    damping_velocity: f64,
    stick_velocity: f64,
}

/// Friction force and bristle rate at one (v, z).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LugreOutput {
    /// Resisting force F [N], the sign of v in steady sliding.
    pub force: f64,
    /// Bristle deflection rate dz/dt [m/s].
    pub bristle_rate: f64,
}

impl LugreFriction {
    /// Builds the law from the static force F_S [N] >= the kinetic (Coulomb)
    /// force F_C > 0 [N], the Stribeck velocity v_S > 0 [m/s], the bristle
    /// stiffness σ0 > 0 [N/m], the bristle damping σ1 >= 0 [N s/m] and the
    /// viscous coefficient σ2 >= 0 [N s/m]. Refuses σ1 > 4 sqrt(2e) F_C / v_D,
    /// beyond which the law could create energy. The damping velocity v_D is
    /// [`DEFAULT_DAMPING_VELOCITY`], the stick velocity [`DEFAULT_STICK_VELOCITY`].
    pub fn new(
        static_force: f64,
        kinetic_force: f64,
        stribeck_velocity: f64,
        bristle_stiffness: f64,
        bristle_damping: f64,
        viscous_coefficient: f64,
    ) -> Result<Self, String> {
        let kinetic_force = positive("kinetic force", "N", kinetic_force)?;
        if !(static_force.is_finite() && static_force >= kinetic_force) {
            return Err(format!(
                "static force must be finite and >= the kinetic force {kinetic_force} N, got {static_force}"
            ));
        }
        let law = Self {
            static_force,
            kinetic_force,
            stribeck_velocity: positive("Stribeck velocity", "m/s", stribeck_velocity)?,
            bristle_stiffness: positive("bristle stiffness", "N/m", bristle_stiffness)?,
            bristle_damping: non_negative("bristle damping", "N s/m", bristle_damping)?,
            viscous_coefficient: non_negative("viscous coefficient", "N s/m", viscous_coefficient)?,
            damping_velocity: DEFAULT_DAMPING_VELOCITY,
            stick_velocity: DEFAULT_STICK_VELOCITY,
        };
        law.check_dissipative()?;
        Ok(law)
    }

    /// The same law with another damping velocity v_D > 0 [m/s] (re-checks the dissipativity bound).
    pub fn with_damping_velocity(self, damping_velocity: f64) -> Result<Self, String> {
        let law = Self { damping_velocity: positive("damping velocity", "m/s", damping_velocity)?, ..self };
        law.check_dissipative()?;
        Ok(law)
    }

    /// The same law with another stick velocity v_stick > 0 [m/s] (see [`Self::is_sticking`]).
    pub fn with_stick_velocity(self, stick_velocity: f64) -> Result<Self, String> {
        Ok(Self { stick_velocity: positive("stick velocity", "m/s", stick_velocity)?, ..self })
    }

    fn check_dissipative(&self) -> Result<(), String> {
        // σ1(v)|v| peaks at σ1 v_D / sqrt(2e); 4 g(v) >= 4 F_C (theory page)
        let bound = 4.0 * (2.0 * std::f64::consts::E).sqrt() * self.kinetic_force / self.damping_velocity;
        if self.bristle_damping > bound {
            return Err(format!(
                "bristle damping must be <= 4 sqrt(2e) F_C / v_D = {bound:.6e} N s/m for the law to dissipate energy, got {} N s/m",
                self.bristle_damping
            ));
        }
        Ok(())
    }

    /// Static (break-away) force F_S [N].
    pub fn static_force(&self) -> f64 {
        self.static_force
    }

    /// Kinetic (Coulomb) force F_C [N].
    pub fn kinetic_force(&self) -> f64 {
        self.kinetic_force
    }

    /// Stribeck velocity v_S [m/s].
    pub fn stribeck_velocity(&self) -> f64 {
        self.stribeck_velocity
    }

    /// Bristle stiffness σ0 [N/m].
    pub fn bristle_stiffness(&self) -> f64 {
        self.bristle_stiffness
    }

    /// Bristle damping at rest σ1 [N s/m].
    pub fn bristle_damping(&self) -> f64 {
        self.bristle_damping
    }

    /// Viscous coefficient σ2 [N s/m].
    pub fn viscous_coefficient(&self) -> f64 {
        self.viscous_coefficient
    }

    /// Damping velocity v_D [m/s]: σ1(v) = σ1 exp(-(v/v_D)²).
    pub fn damping_velocity(&self) -> f64 {
        self.damping_velocity
    }

    /// Stick velocity v_stick [m/s].
    pub fn stick_velocity(&self) -> f64 {
        self.stick_velocity
    }

    /// Largest bristle deflection F_S/σ0 [m]: |z| never leaves [0, F_S/σ0] once inside.
    pub fn deflection_limit(&self) -> f64 {
        self.static_force / self.bristle_stiffness
    }

    /// Stribeck curve g(v) = F_C + (F_S - F_C) exp(-(v/v_S)²) [N] for v [m/s].
    pub fn stribeck_force(&self, velocity: f64) -> f64 {
        let drop = self.static_force - self.kinetic_force;
        self.kinetic_force + drop * self.stribeck_factor(velocity)
    }

    /// Bristle damping σ1(v) = σ1 exp(-(v/v_D)²) [N s/m] for v [m/s].
    pub fn damping_at(&self, velocity: f64) -> f64 {
        self.bristle_damping * gaussian(velocity / self.damping_velocity)
    }

    /// exp(-(v/v_S)²) [-].
    fn stribeck_factor(&self, velocity: f64) -> f64 {
        gaussian(velocity / self.stribeck_velocity)
    }

    /// Resisting force F [N] and bristle rate dz/dt [m/s] at sliding
    /// velocity v [m/s] and bristle deflection z [m]. Does not allocate.
    pub fn evaluate(&self, velocity: f64, deflection: f64) -> LugreOutput {
        let g = self.stribeck_force(velocity);
        let bristle_rate = velocity - self.bristle_stiffness * velocity.abs() * deflection / g;
        let force = self.bristle_stiffness * deflection
            + self.damping_at(velocity) * bristle_rate
            + self.viscous_coefficient * velocity;
        LugreOutput { force, bristle_rate }
    }

    /// Steady-sliding bristle deflection z_ss = g(v) sign(v) / σ0 [m] at constant v [m/s].
    pub fn steady_deflection(&self, velocity: f64) -> f64 {
        if velocity == 0.0 {
            return 0.0;
        }
        (self.stribeck_force(velocity) / self.bristle_stiffness).copysign(velocity)
    }

    /// Steady-sliding force g(v) sign(v) + σ2 v [N] at constant v [m/s].
    pub fn steady_force(&self, velocity: f64) -> f64 {
        self.bristle_stiffness * self.steady_deflection(velocity) + self.viscous_coefficient * velocity
    }

    /// Elastic energy of the bristles σ0 z²/2 [J] at deflection z [m].
    pub fn bristle_energy(&self, deflection: f64) -> f64 {
        0.5 * self.bristle_stiffness * deflection * deflection
    }

    /// Power dissipated F v - d/dt(σ0 z²/2) [W] at v [m/s], z [m]; >= 0
    /// whenever the constructor's bound holds (theory page).
    pub fn dissipation_rate(&self, velocity: f64, deflection: f64) -> f64 {
        let out = self.evaluate(velocity, deflection);
        out.force * velocity - self.bristle_stiffness * deflection * out.bristle_rate
    }

    /// Stick state: |v| < v_stick [m/s], the relative velocity inside the
    /// stick band (default: paper 002's stiction tolerance, 0.01 mm/s).
    pub fn is_sticking(&self, velocity: f64) -> bool {
        velocity.abs() < self.stick_velocity
    }
}

/// exp(-r²) [-].
fn gaussian(ratio: f64) -> f64 {
    (-ratio * ratio).exp()
}

#[cfg(test)]
#[path = "lugre_tests.rs"]
mod tests;
