//! Test support: a 1-DOF impact of a mass on a Hertz spring `K δ^1.5`
//! with a given damping law, integrated by fixed-step RK4, to measure the
//! effective coefficient of restitution `v_out / v_in`.
//!
//! The ratio depends on the law only through D(e) (the problem scales out
//! m, K and v_in), so one realistic set of numbers serves every law: the
//! Flores journal-bearing stiffness, a 0.5 kg body, 0.5 m/s approach.

use super::NormalForceLaw;

/// Mass of the impacting body [kg].
const MASS: f64 = 0.5;
/// Hertz stiffness of the Flores example, R* = 0.19 m, steel on steel [N/m^1.5].
const STIFFNESS: f64 = 6.610198397896845e10;
/// Approach velocity [m/s].
const APPROACH_VELOCITY: f64 = 0.5;

/// Effective restitution v_out/v_in [-] of the law, from an RK4 integration.
pub(super) fn effective_restitution(law: NormalForceLaw) -> f64 {
    // step from the undamped maximum penetration: ½ m v² = K δ^2.5 / 2.5
    let max_penetration =
        (1.25 * MASS * APPROACH_VELOCITY * APPROACH_VELOCITY / STIFFNESS).powf(0.4);
    let step = max_penetration / APPROACH_VELOCITY / 4000.0;
    let acceleration = |penetration: f64, rate: f64| -> f64 {
        if penetration <= 0.0 {
            return 0.0;
        }
        let elastic = STIFFNESS * penetration.powf(1.5);
        -law.normal_force(elastic, rate, APPROACH_VELOCITY) / MASS
    };
    let mut state = (0.0_f64, APPROACH_VELOCITY);
    for _ in 0..10_000_000 {
        let next = rk4_step(state, step, &acceleration);
        // leave contact: interpolate the rate at δ = 0
        if state.0 > 0.0 && next.0 <= 0.0 {
            let fraction = state.0 / (state.0 - next.0);
            let exit_rate = state.1 + fraction * (next.1 - state.1);
            return -exit_rate / APPROACH_VELOCITY;
        }
        state = next;
    }
    f64::NAN
}

fn rk4_step(state: (f64, f64), step: f64, acceleration: &impl Fn(f64, f64) -> f64) -> (f64, f64) {
    let (x, v) = state;
    let (k1x, k1v) = (v, acceleration(x, v));
    let (k2x, k2v) =
        (v + 0.5 * step * k1v, acceleration(x + 0.5 * step * k1x, v + 0.5 * step * k1v));
    let (k3x, k3v) =
        (v + 0.5 * step * k2v, acceleration(x + 0.5 * step * k2x, v + 0.5 * step * k2v));
    let (k4x, k4v) = (v + step * k3v, acceleration(x + step * k3x, v + step * k3v));
    (
        x + step / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x),
        v + step / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v),
    )
}

/// Checks the RK4 result against a reference value computed independently
/// and returns the relative error of the effective restitution against e.
pub(super) fn check_against_reference(
    law: NormalForceLaw,
    restitution: f64,
    reference: f64,
) -> f64 {
    let effective = effective_restitution(law);
    assert!(
        (effective - reference).abs() < 1e-3,
        "{law:?}: RK4 gives {effective}, independent reference {reference}"
    );
    (effective - restitution) / restitution
}
