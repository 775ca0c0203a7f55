//! Hunt-Crossley hysteresis damping.
//!
//! `D(e) = 3(1 - e)/2`. Source: K. H. Hunt, F. R. E. Crossley,
//! "Coefficient of restitution interpreted as damping in vibroimpact",
//! J. Appl. Mech. 42(2) (1975) 440-445. Derived for small losses: accurate
//! for e near 1, too little damping (effective restitution above e) for
//! lower e. Theory page: `docs/theory/contact-hunt-crossley.md`.

/// Hysteresis factor D = 3(1-e)/2 [-] for restitution e [-].
pub(crate) fn hysteresis_factor(restitution: f64) -> f64 {
    1.5 * (1.0 - restitution)
}

#[cfg(test)]
mod tests {
    use super::super::impact_test::check_against_reference;
    use super::super::NormalForceLaw;

    #[test]
    fn test_hunt_crossley_factor_matches_closed_form() {
        for (restitution, expected) in [(0.0, 1.5), (0.5, 0.75), (0.9, 0.15), (1.0, 0.0)] {
            let law = NormalForceLaw::HuntCrossley { restitution };
            assert!((law.hysteresis_factor() - expected).abs() < 1e-15);
        }
    }

    #[test]
    fn test_hunt_crossley_restitution_within_2_percent_for_high_e_and_too_elastic_below() {
        // references: scipy solve_ivp (DOP853, rtol 1e-12) of the same impact
        for (restitution, reference) in
            [(0.3, 0.58129), (0.5, 0.66296), (0.7, 0.768), (0.9, 0.90902), (0.95, 0.95237)]
        {
            let law = NormalForceLaw::HuntCrossley { restitution };
            let error = check_against_reference(law, restitution, reference);
            if restitution >= 0.9 {
                assert!(error.abs() < 0.02, "e = {restitution}: relative error {error}");
            } else {
                // known limitation: too little dissipation at low e
                assert!(error > 0.05, "e = {restitution}: expected a high bias, got {error}");
            }
        }
    }
}
