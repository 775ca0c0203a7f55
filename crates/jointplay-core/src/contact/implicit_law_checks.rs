//! Property checks shared by the stiffness laws whose force is implicit in
//! the penetration (Johnson line contact, Rogers-Andrews): the inverse
//! F(delta(F)) round trip, monotonicity, and the energy integral.

/// What the checks need of an implicit stiffness law.
pub(super) trait ImplicitLaw {
    /// Elastic force at a penetration [N].
    fn force(&self, penetration: f64) -> f64;
    /// Penetration at a force, the explicit direction of the law [m].
    fn penetration_at(&self, force: f64) -> f64;
    /// Largest force for which the law itself holds [N].
    fn limit(&self) -> f64;
    /// Elastic energy at a penetration [J].
    fn energy(&self, penetration: f64) -> f64;
}

/// F(delta(F)) = F within 1e-10 from 1e-3 N to 1e6 N.
pub(super) fn assert_round_trip(law: &impl ImplicitLaw) {
    assert!(law.limit() > 1e6);
    for step in 0..=90 {
        let force = 10f64.powf(-3.0 + step as f64 / 10.0);
        let back = law.force(law.penetration_at(force));
        assert!((back / force - 1.0).abs() < 1e-10, "F = {force}: got {back}");
    }
}

/// The force rises strictly with the penetration, up to twice the limit's penetration.
pub(super) fn assert_monotone(law: &impl ImplicitLaw) {
    let top = 2.0 * law.penetration_at(law.limit());
    let mut previous = 0.0;
    for step in 1..=2000 {
        let force = law.force(top * step as f64 / 2000.0);
        assert!(force > previous, "not increasing at step {step}");
        previous = force;
    }
}

/// The closed-form energy equals a 200 000-interval trapezoid integral of the force within 1e-6.
pub(super) fn assert_energy_matches_trapezoid(law: &impl ImplicitLaw) {
    for penetration in [law.penetration_at(10.0), law.penetration_at(1e5), 1.5 * law.penetration_at(law.limit())] {
        let intervals = 200_000;
        let width = penetration / intervals as f64;
        let mut integral = 0.5 * law.force(penetration);
        for k in 1..intervals {
            integral += law.force(k as f64 * width);
        }
        integral *= width;
        let energy = law.energy(penetration);
        assert!((energy / integral - 1.0).abs() < 1e-6, "δ = {penetration}: {energy} vs {integral}");
    }
}

macro_rules! implicit_law {
    ($law:ty) => {
        impl ImplicitLaw for $law {
            fn force(&self, penetration: f64) -> f64 {
                self.elastic_force(penetration)
            }
            fn penetration_at(&self, force: f64) -> f64 {
                self.penetration(force)
            }
            fn limit(&self) -> f64 {
                self.limit_force()
            }
            fn energy(&self, penetration: f64) -> f64 {
                self.elastic_energy(penetration)
            }
        }
    };
}

implicit_law!(super::JohnsonLine);
implicit_law!(super::RogersAndrews);
