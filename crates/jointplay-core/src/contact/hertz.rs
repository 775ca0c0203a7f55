//! Hertz normal force law: purely elastic, no dissipation.
//!
//! `F = F_el(δ)`, i.e. `D = 0`. Source: H. Hertz, "Über die Berührung
//! fester elastischer Körper", J. reine angew. Math. 92 (1882) 156-171.
//! Theory page: `docs/theory/contact-hertz.md`.

/// Hysteresis factor of the Hertz law, D = 0 [-].
pub(crate) fn hysteresis_factor() -> f64 {
    0.0
}

#[cfg(test)]
mod tests {
    use super::super::impact_test::effective_restitution;
    use super::super::NormalForceLaw;

    #[test]
    fn test_hertz_factor_is_zero() {
        assert_eq!(NormalForceLaw::Hertz.hysteresis_factor(), 0.0);
    }

    #[test]
    fn test_hertz_impact_is_perfectly_elastic() {
        let restitution = effective_restitution(NormalForceLaw::Hertz);
        assert!((restitution - 1.0).abs() < 1e-4, "effective restitution {restitution}");
    }
}
