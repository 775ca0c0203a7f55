//! Gonthier et al. hysteresis damping.
//!
//! `D(e) = (1 - e²)/e`. Source: Y. Gonthier, J. McPhee, C. Lange,
//! J.-C. Piedbœuf, "A regularized contact model with asymmetric damping
//! and dwell-time dependent friction", Multibody Syst. Dyn. 11(3) (2004)
//! 209-233 (their approximation d ≈ (1-e²)/(e v⁻) of the exact
//! restitution relation). Theory page: `docs/theory/contact-gonthier.md`.

/// Hysteresis factor D = (1-e²)/e [-] for restitution 0 < e <= 1 [-].
///
/// e is floored at 1e-6 so that an unvalidated e = 0 gives a large finite
/// factor instead of infinity.
pub(crate) fn hysteresis_factor(restitution: f64) -> f64 {
    let restitution = restitution.max(1e-6);
    (1.0 - restitution * restitution) / restitution
}

#[cfg(test)]
mod tests {
    use super::super::impact_test::check_against_reference;
    use super::super::NormalForceLaw;

    #[test]
    fn test_gonthier_factor_matches_closed_form() {
        for (restitution, expected) in [(0.25, 3.75), (0.5, 1.5), (0.8, 0.45), (1.0, 0.0)] {
            let law = NormalForceLaw::Gonthier { restitution };
            assert!((law.hysteresis_factor() - expected).abs() < 1e-14);
        }
    }

    #[test]
    fn test_gonthier_restitution_within_5_percent_over_0_3_to_0_95() {
        // references: scipy solve_ivp (DOP853, rtol 1e-12) of the same impact
        for (restitution, reference) in
            [(0.3, 0.30422), (0.5, 0.48774), (0.7, 0.66958), (0.9, 0.87644), (0.95, 0.93593)]
        {
            let law = NormalForceLaw::Gonthier { restitution };
            let error = check_against_reference(law, restitution, reference);
            assert!(error.abs() < 0.05, "e = {restitution}: relative error {error}");
            // the approximation dissipates slightly too much from e = 0.5 up
            if restitution >= 0.5 {
                assert!(error < -0.01, "e = {restitution}: expected a low bias, got {error}");
            }
        }
    }
}
