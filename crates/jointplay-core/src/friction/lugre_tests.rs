//! Tests of the LuGre law against closed forms: the steady-sliding force,
//! the exponential bristle transient at constant velocity, a mass held by
//! stiction below F_S and sliding above it, and the dissipation bound.
//! Seal numbers: F_S = 385 N, F_C = 340 N from paper 002; v_S, σ0, σ1 chosen
//! (docs/theory/friction-lugre.md); v_D and v_stick at their defaults.

use super::*;

/// Paper-002 seal with the chosen v_S = 0.03 mm/s, σ0 = 1e7 N/m, σ1 = 1e4 N s/m, no viscous term
/// (v_D = 1 mm/s, v_stick = 0.01 mm/s).
fn seal() -> LugreFriction {
    LugreFriction::new(385.0, 340.0, 3.0e-5, 1.0e7, 1.0e4, 0.0).unwrap()
}

/// The same seal with a viscous term σ2 = 50 N s/m.
fn viscous_seal() -> LugreFriction {
    LugreFriction::new(385.0, 340.0, 3.0e-5, 1.0e7, 1.0e4, 50.0).unwrap()
}

/// Mass m [kg] on the law under an applied force f(t) [N]: state (x, v, z).
fn mass_rates(law: &LugreFriction, mass: f64, force: f64, y: [f64; 3]) -> [f64; 3] {
    let out = law.evaluate(y[1], y[2]);
    [y[1], (force - out.force) / mass, out.bristle_rate]
}

/// One classical RK4 step of the mass on the law, force held at its mid-step value.
fn rk4_step(law: &LugreFriction, mass: f64, force: f64, y: [f64; 3], h: f64) -> [f64; 3] {
    let add = |a: [f64; 3], k: [f64; 3], s: f64| [a[0] + s * k[0], a[1] + s * k[1], a[2] + s * k[2]];
    let k1 = mass_rates(law, mass, force, y);
    let k2 = mass_rates(law, mass, force, add(y, k1, 0.5 * h));
    let k3 = mass_rates(law, mass, force, add(y, k2, 0.5 * h));
    let k4 = mass_rates(law, mass, force, add(y, k3, h));
    let mut next = y;
    for i in 0..3 {
        next[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    next
}

/// Integrates from y over [t0, t1] with step h under force(t); returns the final state
/// and the largest |v| seen.
fn run(
    law: &LugreFriction,
    mass: f64,
    force: impl Fn(f64) -> f64,
    mut y: [f64; 3],
    (t0, t1, h): (f64, f64, f64),
) -> ([f64; 3], f64) {
    let steps = ((t1 - t0) / h).round() as usize;
    let mut peak_speed: f64 = 0.0;
    for k in 0..steps {
        y = rk4_step(law, mass, force(t0 + (k as f64 + 0.5) * h), y, h);
        peak_speed = peak_speed.max(y[1].abs());
    }
    (y, peak_speed)
}

#[test]
fn test_lugre_stribeck_curve_runs_from_static_to_kinetic_force() {
    let law = seal();
    assert_eq!(law.stribeck_force(0.0), 385.0);
    // g(v_S) = F_C + (F_S - F_C)/e
    assert!((law.stribeck_force(3.0e-5) - (340.0 + 45.0 / std::f64::consts::E)).abs() < 1e-12);
    assert!((law.stribeck_force(-3.0e-5) - law.stribeck_force(3.0e-5)).abs() < 1e-12);
    assert_eq!(law.stribeck_force(1.0), 340.0);
    // damping fades over v_D = 1 mm/s: σ1/e there
    assert!((law.damping_at(-1.0e-3) - 1.0e4 / std::f64::consts::E).abs() < 1e-9);
    assert_eq!(law.damping_at(0.0), 1.0e4);
    assert!((law.deflection_limit() - 38.5e-6).abs() < 1e-18);
}

#[test]
fn test_lugre_steady_sliding_force_is_stribeck_curve_plus_viscous() {
    let law = viscous_seal();
    for v in [1e-6, 1e-5, 3e-5, 1e-4, 1e-2, 0.3] {
        for velocity in [v, -v] {
            let z = law.steady_deflection(velocity);
            let out = law.evaluate(velocity, z);
            // steady state: no bristle motion, F = g(v) sign(v) + σ2 v
            assert!(out.bristle_rate.abs() < 1e-12 * v, "v = {velocity}: rate {}", out.bristle_rate);
            let expected = law.stribeck_force(velocity).copysign(velocity) + 50.0 * velocity;
            assert!((out.force - expected).abs() < 1e-9, "v = {velocity}: {} vs {expected}", out.force);
            assert!((law.steady_force(velocity) - expected).abs() < 1e-9);
        }
    }
}

#[test]
fn test_lugre_bristle_relaxes_exponentially_at_constant_velocity() {
    // at constant v, dz/dt = v - (σ0 |v|/g) z is linear: z = z_ss (1 - exp(-σ0 |v| t / g))
    let law = seal();
    for velocity in [2e-5, -1e-3] {
        let (z_ss, rate) = (law.steady_deflection(velocity), 1.0e7 * velocity.abs() / law.stribeck_force(velocity));
        let (h, steps) = (0.02 / rate, 200);
        let mut z = 0.0;
        for k in 1..=steps {
            let f = |z: f64| law.evaluate(velocity, z).bristle_rate;
            let (k1, k2) = (f(z), f(z + 0.5 * h * f(z)));
            let (k3, k4) = (f(z + 0.5 * h * k2), 0.0);
            let k4 = k4 + f(z + h * k3);
            z += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
            let exact = z_ss * (1.0 - (-rate * h * k as f64).exp());
            // RK4 error at h·rate = 0.02 is ~1e-10 of z_ss
            assert!((z - exact).abs() < 1e-9 * z_ss.abs(), "v = {velocity}, step {k}: {z} vs {exact}");
        }
    }
}

#[test]
fn test_lugre_holds_a_mass_below_the_kinetic_force_and_keeps_it() {
    // 20 kg under a step of 300 N < F_C: comes to rest with σ0 z = 300 N
    let law = seal();
    let (y, _) = run(&law, 20.0, |_| 300.0, [0.0; 3], (0.0, 2.0, 1e-5));
    assert!(y[1].abs() < 1e-9, "still moving: {}", y[1]);
    assert!((y[2] - 300.0 / 1.0e7).abs() < 1e-6 * 300.0 / 1.0e7, "bristle {}", y[2]);
    assert!(law.is_sticking(y[1]));
    // and stays: one more second moves it by less than a nanometre
    let (later, peak) = run(&law, 20.0, |_| 300.0, y, (2.0, 3.0, 1e-5));
    assert!((later[0] - y[0]).abs() < 1e-9, "drift {}", later[0] - y[0]);
    assert!(peak < 1e-8);
}

#[test]
fn test_lugre_holds_a_slowly_loaded_mass_between_kinetic_and_static_force() {
    // ramp to 370 N (F_C < 370 < F_S) slowly enough that v stays well below v_S
    let law = seal();
    let ramp = |t: f64| 370.0 * (t / 200.0).min(1.0);
    let (y, peak) = run(&law, 20.0, ramp, [0.0; 3], (0.0, 210.0, 1e-4));
    // quasi-static presliding speed at 370 N is about 5e-6 m/s: sticking throughout
    assert!(peak < law.stick_velocity(), "peak speed {peak}");
    assert!(y[1].abs() < 1e-9 && (y[2] - 370.0 / 1.0e7).abs() < 1e-6 * 370.0 / 1.0e7, "{y:?}");
    // presliding displacement of slow loading, with g ~ F_S: dx = dz / (1 - σ0 z/F_S),
    // x = -(F_S/σ0) ln(1 - F/F_S) = 124.9 µm; g(v) is ~0.3 % below F_S at the
    // presliding speed, hence 2 %
    let expected = -law.deflection_limit() * (1.0 - 370.0 / 385.0_f64).ln();
    assert!((y[0] - expected).abs() < 0.02 * expected, "displacement {} vs {expected}", y[0]);
}

#[test]
fn test_lugre_break_away_force_under_a_slow_ramp_matches_the_quasi_static_prediction() {
    // quasi-static presliding (inertia and damping negligible): σ0 z = F, so
    // dz/dt = F'/σ0 = v (1 - F/g(v)) and the largest force the seal holds at
    // the load rate F' is max_v g(v) (1 - F'/(σ0 v)), which tends to F_S as F' -> 0
    let (law, rate) = (seal(), 1.0);
    let predicted = (1..20_000)
        .map(|i| i as f64 * 1e-9)
        .map(|v| law.stribeck_force(v) * (1.0 - rate / (1.0e7 * v)))
        .fold(f64::NEG_INFINITY, f64::max);
    assert!(predicted < 385.0 && predicted > 0.97 * 385.0, "predicted {predicted}");
    // ramp the load at 1 N/s until the mass slides (|v| > 10 v_S)
    let (mut y, h, mut t): ([f64; 3], f64, f64) = ([0.0; 3], 1e-4, 0.0);
    while y[1].abs() < 3.0e-4 && t < 500.0 {
        y = rk4_step(&law, 20.0, rate * (t + 0.5 * h), y, h);
        t += h;
    }
    assert!((rate * t - predicted).abs() < 0.002 * predicted, "broke away at {} N, predicted {predicted}", rate * t);
}

#[test]
fn test_lugre_mass_slides_above_the_static_force_with_coulomb_deceleration() {
    // 20 kg under 420 N > F_S: slides; once v >> v_S, F -> F_C, so a = (420 - 340)/20 = 4 m/s²
    let law = seal();
    let (y1, _) = run(&law, 20.0, |_| 420.0, [0.0; 3], (0.0, 0.1, 1e-5));
    let (y2, _) = run(&law, 20.0, |_| 420.0, y1, (0.1, 0.6, 1e-5));
    assert!(y1[0] > 100.0 * law.deflection_limit(), "displacement {}", y1[0]);
    assert!(!law.is_sticking(y1[1]));
    let acceleration = (y2[1] - y1[1]) / 0.5;
    assert!((acceleration - 4.0).abs() < 1e-3 * 4.0, "acceleration {acceleration}");
    assert!((y2[2] - 340.0 / 1.0e7).abs() < 1e-6 * 340.0 / 1.0e7);
}

#[test]
fn test_lugre_bristle_stays_below_the_deflection_limit() {
    // Canudas de Wit et al. (1995), property 1: |z(0)| <= F_S/σ0 implies |z(t)| <= F_S/σ0
    let law = seal();
    let limit = law.deflection_limit();
    let (mut z, h) = (0.9 * limit, 1e-6);
    for k in 0..200_000 {
        let t = k as f64 * h;
        let v = 2e-3 * (2.0 * std::f64::consts::PI * 7.0 * t).sin() + 5e-5 * (900.0 * t).cos();
        z += h * law.evaluate(v, z).bristle_rate;
        assert!(z.abs() <= limit * (1.0 + 1e-12), "t = {t}: z = {z}");
    }
}

#[test]
fn test_lugre_dissipates_energy_within_the_bound_and_not_beyond() {
    let at_bound = {
        let bound = 4.0 * (2.0 * std::f64::consts::E).sqrt() * 340.0 / DEFAULT_DAMPING_VELOCITY;
        LugreFriction::new(385.0, 340.0, 3.0e-5, 1.0e7, bound, 0.0).unwrap()
    };
    // the bound makes F v - d/dt(σ0 z²/2) >= 0 for every z, reachable or not:
    // scan to ten times the deflection limit F_S/σ0
    let limit = 10.0 * at_bound.deflection_limit();
    let grid = |law: &LugreFriction| {
        let mut lowest = f64::INFINITY;
        for i in -300..=300 {
            let v = 3.0e-5 * (i as f64 / 60.0).powi(3);
            for j in -50..=50 {
                let z = limit * j as f64 / 50.0;
                // scale by the largest term so round-off does not count
                let scale = (law.evaluate(v, z).force * v).abs().max(1e-30);
                lowest = lowest.min(law.dissipation_rate(v, z) / scale);
            }
        }
        lowest
    };
    assert!(grid(&seal()) > -1e-12);
    assert!(grid(&at_bound) > -1e-12);
    // three times the bound: some (v, z) would feed energy in (the bound is within a factor 3 of sharp)
    let beyond = LugreFriction { bristle_damping: 3.0 * at_bound.bristle_damping, ..at_bound };
    assert!(grid(&beyond) < -1e-3);
}

#[test]
fn test_lugre_stick_flag_uses_the_stick_velocity() {
    let law = seal();
    assert!(law.is_sticking(0.0) && law.is_sticking(-0.99e-5));
    assert!(!law.is_sticking(1.0e-5) && !law.is_sticking(-2.0e-5));
    let wide = law.with_stick_velocity(1e-3).unwrap();
    assert!(wide.is_sticking(5e-4));
}

#[test]
fn test_lugre_constructor_messages() {
    let err = |r: Result<LugreFriction, String>| r.unwrap_err();
    assert_eq!(
        err(LugreFriction::new(300.0, 340.0, 3e-5, 1e7, 1e4, 0.0)),
        "static force must be finite and >= the kinetic force 340 N, got 300"
    );
    assert_eq!(
        err(LugreFriction::new(385.0, 0.0, 3e-5, 1e7, 1e4, 0.0)),
        "kinetic force must be finite and > 0 N, got 0"
    );
    assert_eq!(
        err(LugreFriction::new(385.0, 340.0, 3e-5, -1.0, 1e4, 0.0)),
        "bristle stiffness must be finite and > 0 N/m, got -1"
    );
    assert_eq!(
        err(LugreFriction::new(385.0, 340.0, 3e-5, 1e7, 1e4, f64::NAN)),
        "viscous coefficient must be finite and >= 0 N s/m, got NaN"
    );
    assert_eq!(
        err(LugreFriction::new(385.0, 340.0, 3e-5, 1e7, 1e9, 0.0)),
        "bristle damping must be <= 4 sqrt(2e) F_C / v_D = 3.171036e6 N s/m for the law to dissipate energy, got 1000000000 N s/m"
    );
    assert_eq!(err(seal().with_stick_velocity(0.0)), "stick velocity must be finite and > 0 m/s, got 0");
    assert_eq!(err(seal().with_damping_velocity(-1.0)), "damping velocity must be finite and > 0 m/s, got -1");
    // a larger v_D lowers the bound: σ1 = 1e4 N s/m fails beyond v_D = 0.317 m/s
    assert!(seal().with_damping_velocity(0.3).is_ok() && seal().with_damping_velocity(0.33).is_err());
}
