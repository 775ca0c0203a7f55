//! Shared machinery of the two logarithmic line-contact laws (Johnson,
//! Rogers-Andrews), whose penetration is explicit in the force:
//!
//! `δ(F) = c F (ln(A/F) + b)`
//!
//! with compliance c [m/N], force scale A [N] and offset b [-]. The law is
//! increasing and concave for `ln(A/F) > 1 - b`; it is used up to the force
//! `F_lim` where `ln(A/F_lim) = 2 - b` (there `dδ/dF = c`), and continued
//! beyond by the tangent line `F = F_lim + (δ - δ_lim)/c`. The limit lies
//! at a penetration of a sizeable fraction of the clearance, far past the
//! range where either law is meant to be used.

/// Logarithmic force-penetration law with its validity limit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct LogarithmicLaw {
    compliance: f64,
    force_scale: f64,
    offset: f64,
    limit_force: f64,
    limit_penetration: f64,
    limit_energy: f64,
}

impl LogarithmicLaw {
    /// Builds the law from c [m/N] > 0, A [N] > 0 and b [-].
    pub(crate) fn new(compliance: f64, force_scale: f64, offset: f64) -> Self {
        let limit_force = force_scale * (offset - 2.0).exp();
        let mut law = Self {
            compliance,
            force_scale,
            offset,
            limit_force,
            limit_penetration: 0.0,
            limit_energy: 0.0,
        };
        law.limit_penetration = law.log_penetration(limit_force);
        law.limit_energy = law.log_energy(limit_force);
        law
    }

    /// Force [N] at the end of the logarithmic range.
    pub(crate) fn limit_force(&self) -> f64 {
        self.limit_force
    }

    /// Penetration [m] for a force F >= 0 [N]: the explicit law, or its tangent continuation.
    pub(crate) fn penetration(&self, force: f64) -> f64 {
        if force.is_nan() || force <= 0.0 {
            0.0
        } else if force <= self.limit_force {
            self.log_penetration(force)
        } else {
            self.limit_penetration + self.compliance * (force - self.limit_force)
        }
    }

    /// Force [N] for a penetration δ [m], inverting the law by safeguarded Newton.
    pub(crate) fn force(&self, penetration: f64) -> f64 {
        if penetration.is_nan() || penetration <= 0.0 {
            0.0
        } else if penetration >= self.limit_penetration {
            let excess = penetration - self.limit_penetration;
            (self.limit_force + excess / self.compliance).min(f64::MAX)
        } else {
            self.invert(penetration)
        }
    }

    /// Stored energy ∫0^δ F dδ [J], in closed form via ∫F dδ = F δ - ∫δ dF.
    pub(crate) fn energy(&self, penetration: f64) -> f64 {
        if penetration.is_nan() || penetration <= 0.0 {
            0.0
        } else if penetration >= self.limit_penetration {
            let excess = penetration - self.limit_penetration;
            let energy = self.limit_energy
                + self.limit_force * excess
                + 0.5 * excess * excess / self.compliance;
            energy.min(f64::MAX)
        } else {
            self.log_energy(self.invert(penetration))
        }
    }

    fn log_penetration(&self, force: f64) -> f64 {
        self.compliance * force * ((self.force_scale / force).ln() + self.offset)
    }

    fn log_slope(&self, force: f64) -> f64 {
        self.compliance * ((self.force_scale / force).ln() + self.offset - 1.0)
    }

    // energy at the force F: F δ(F) - c F²/2 (ln(A/F) + b + 1/2)
    fn log_energy(&self, force: f64) -> f64 {
        let log_term = (self.force_scale / force).ln() + self.offset;
        force * self.log_penetration(force)
            - 0.5 * self.compliance * force * force * (log_term + 0.5)
    }

    // Newton on g(F) = δ(F) - δ, for 0 < δ < δ_lim. Because δ(F) >= 2cF on
    // (0, F_lim], the root lies below δ/(2c); starting there the iterates
    // of a concave increasing g approach the root from the left, monotonically.
    fn invert(&self, penetration: f64) -> f64 {
        let mut upper = (0.5 * penetration / self.compliance).min(self.limit_force);
        let mut lower = 0.0;
        let mut force = upper;
        for _ in 0..100 {
            if force.is_nan() || force <= 0.0 {
                return 0.0;
            }
            let residual = self.log_penetration(force) - penetration;
            if residual > 0.0 {
                upper = force;
            } else {
                lower = force;
            }
            let next = force - residual / self.log_slope(force);
            if residual == 0.0 || (next - force).abs() <= 1e-15 * force {
                return next.max(0.0);
            }
            // safeguard: bisect when Newton leaves the bracket
            force = if next > lower && next < upper { next } else { 0.5 * (lower + upper) };
        }
        force
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn example() -> LogarithmicLaw {
        LogarithmicLaw::new(1e-10, 5e7, -1.0)
    }

    #[test]
    fn test_round_trip_over_twelve_decades_of_force() {
        let law = example();
        for exponent in -6..=7 {
            let force = 10f64.powi(exponent);
            let back = law.force(law.penetration(force));
            assert!((back / force - 1.0).abs() < 1e-12, "F = {force}: got {back}");
        }
    }

    #[test]
    fn test_continuation_is_continuous_at_the_limit() {
        let law = example();
        let limit = law.limit_penetration;
        let below = law.force(limit * (1.0 - 1e-9));
        let above = law.force(limit * (1.0 + 1e-9));
        assert!((above - below).abs() < 1e-6 * law.limit_force());
        assert!(above > below);
    }

    #[test]
    fn test_force_is_finite_for_extreme_penetrations() {
        let law = example();
        for penetration in [0.0, 1e-300, 1e-20, 1.0, 1e6, f64::MAX] {
            assert!(law.force(penetration).is_finite());
            assert!(law.energy(penetration).is_finite());
            assert!(law.force(penetration) >= 0.0);
        }
        assert_eq!(law.force(-1.0), 0.0);
        assert_eq!(law.force(f64::NAN), 0.0);
    }
}
