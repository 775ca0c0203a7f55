//! Flores et al. hysteresis damping.
//!
//! `D(e) = 8(1 - e)/(5e)`. Source: P. Flores, M. Machado, M. T. Silva,
//! J. M. Martins, "On the continuous contact force models for soft
//! materials in multibody dynamics", Multibody Syst. Dyn. 25(3) (2011)
//! 357-375. Theory page: `docs/theory/contact-flores.md`.

/// Hysteresis factor D = 8(1-e)/(5e) [-] for restitution 0 < e <= 1 [-].
///
/// e is floored at 1e-6 so that an unvalidated e = 0 gives a large finite
/// factor instead of infinity.
pub(crate) fn hysteresis_factor(restitution: f64) -> f64 {
    let restitution = restitution.max(1e-6);
    1.6 * (1.0 - restitution) / restitution
}

#[cfg(test)]
mod tests {
    use super::super::impact_test::check_against_reference;
    use super::super::NormalForceLaw;

    #[test]
    fn test_flores_factor_matches_closed_form() {
        for (restitution, expected) in [(0.25, 4.8), (0.5, 1.6), (0.8, 0.4), (1.0, 0.0)] {
            let law = NormalForceLaw::Flores { restitution };
            assert!((law.hysteresis_factor() - expected).abs() < 1e-14);
        }
        assert!(NormalForceLaw::Flores { restitution: 0.0 }.hysteresis_factor().is_finite());
    }

    #[test]
    fn test_flores_restitution_within_3_percent_for_e_from_0_7_and_too_lossy_below() {
        // references: scipy solve_ivp (DOP853, rtol 1e-12) of the same impact
        for (restitution, reference) in
            [(0.3, 0.25621), (0.5, 0.47044), (0.7, 0.68318), (0.9, 0.89392), (0.95, 0.94683)]
        {
            let law = NormalForceLaw::Flores { restitution };
            let error = check_against_reference(law, restitution, reference);
            if restitution >= 0.7 {
                assert!(error.abs() < 0.03, "e = {restitution}: relative error {error}");
            } else {
                // known limitation: too much dissipation at low e (-6 % at 0.5, -15 % at 0.3)
                assert!(error < -0.04, "e = {restitution}: expected a low bias, got {error}");
            }
        }
    }
}
