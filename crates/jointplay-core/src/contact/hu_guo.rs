//! Hu-Guo hysteresis damping.
//!
//! `D(e) = 3(1 - e)/(2e)`. Source: S. Hu, X. Guo, "A dissipative contact
//! force model for impact analysis in multibody dynamics", Multibody Syst.
//! Dyn. 35(2) (2015) 131-151, doi:10.1007/s11044-015-9453-z.
//! Theory page: `docs/theory/contact-hu-guo.md`.

/// Hysteresis factor D = 3(1-e)/(2e) [-] for restitution 0 < e <= 1 [-].
///
/// e is floored at 1e-6 so that an unvalidated e = 0 gives a large finite
/// factor instead of infinity.
pub(crate) fn hysteresis_factor(restitution: f64) -> f64 {
    let restitution = restitution.max(1e-6);
    1.5 * (1.0 - restitution) / restitution
}

#[cfg(test)]
mod tests {
    use super::super::impact_test::check_against_reference;
    use super::super::NormalForceLaw;

    #[test]
    fn test_hu_guo_factor_matches_closed_form() {
        for (restitution, expected) in [(0.25, 4.5), (0.5, 1.5), (0.75, 0.5), (1.0, 0.0)] {
            let law = NormalForceLaw::HuGuo { restitution };
            assert!((law.hysteresis_factor() - expected).abs() < 1e-14);
        }
    }

    #[test]
    fn test_hu_guo_restitution_within_3_percent_for_e_from_0_5_and_too_lossy_at_0_3() {
        // references: scipy solve_ivp (DOP853, rtol 1e-12) of the same impact
        for (restitution, reference) in
            [(0.3, 0.27066), (0.5, 0.48774), (0.7, 0.6973), (0.9, 0.8999), (0.95, 0.94999)]
        {
            let law = NormalForceLaw::HuGuo { restitution };
            let error = check_against_reference(law, restitution, reference);
            if restitution >= 0.5 {
                assert!(error.abs() < 0.03, "e = {restitution}: relative error {error}");
            } else {
                assert!(error < -0.05, "e = {restitution}: expected a low bias, got {error}");
            }
        }
        // from e = 0.7 up the law is within 0.5 %
        let error =
            check_against_reference(NormalForceLaw::HuGuo { restitution: 0.7 }, 0.7, 0.6973);
        assert!(error.abs() < 0.005);
    }
}
