//! Accuracy against closed forms and observed order of convergence.

use super::*;

/// Exact oscillator state with x(0) = 1, v(0) = 0.
fn oscillator_exact(t: f64) -> Vec<f64> {
    let w = 2.0 * std::f64::consts::PI;
    vec![(w * t).cos(), -w * (w * t).sin()]
}

/// Global error of the oscillator over 5 periods at tolerance `tol` (velocity scaled by 1/w), with the statistics.
fn oscillator_error(method: Method, tol: f64) -> (f64, Statistics) {
    let mut sys = Smooth::new(2, oscillator);
    let (stats, result, y) = run(&mut sys, 0.0, 5.0, &[1.0, 0.0], &options(method, tol));
    result.unwrap();
    let exact = oscillator_exact(5.0);
    let w = 2.0 * std::f64::consts::PI;
    ((y[0] - exact[0]).abs().max((y[1] - exact[1]).abs() / w), stats)
}

#[test]
fn decay_matches_exponential_within_tolerance_for_both_methods() {
    for method in METHODS {
        for tol in [1e-6, 1e-8, 1e-10] {
            let mut sys = Smooth::new(1, decay);
            let (stats, result, _) = run(&mut sys, 0.0, 5.0, &[1.0], &options(method, tol));
            result.unwrap();
            let err = max_sample_error(&sys.samples, |t| vec![(-t).exp()]);
            let bound = tolerance_bound(method, tol, &stats);
            println!("decay {method:?} tol {tol:e}: max error {err:e}, bound {bound:e}");
            assert!(err < bound, "{method:?} tol {tol:e}: error {err:e} > {bound:e}");
            assert!(err > 1e-4 * tol, "{method:?}: error {err:e} suspiciously small, test is vacuous");
        }
    }
}

#[test]
fn harmonic_oscillator_error_is_proportional_to_tolerance() {
    // over 5 periods the global error should stay within a modest multiple of the tolerance
    for method in METHODS {
        for tol in [1e-6, 1e-8, 1e-10] {
            let (err, stats) = oscillator_error(method, tol);
            let bound = tolerance_bound(method, tol, &stats);
            println!("oscillator {method:?} tol {tol:e}: error {err:e}, bound {bound:e}");
            assert!(err < bound, "{method:?} tol {tol:e}: error {err:e} > {bound:e}");
        }
    }
}

#[test]
fn pendulum_energy_drift_is_proportional_to_tolerance() {
    // large swing (2.5 rad) for 10 s: energy is conserved by the exact flow
    for method in METHODS {
        for tol in [1e-6, 1e-8, 1e-10] {
            let mut sys = Smooth::new(2, pendulum);
            let (stats, result, _) = run(&mut sys, 0.0, 10.0, &[2.5, 0.0], &options(method, tol));
            result.unwrap();
            let e0 = pendulum_energy(&[2.5, 0.0]);
            let drift = sys.samples.iter().map(|(_, y)| (pendulum_energy(y) - e0).abs()).fold(0.0, f64::max);
            let bound = tolerance_bound(method, tol, &stats) * e0.abs();
            println!("pendulum {method:?} tol {tol:e}: energy drift {drift:e}, bound {bound:e}");
            assert!(drift < bound, "{method:?} tol {tol:e}: drift {drift:e} > {bound:e}");
        }
    }
}

#[test]
fn dormand_prince_fixed_steps_converge_at_order_five() {
    // huge tolerances accept every step; initial_step = max_step fixes h
    let error_with = |h: f64| {
        let opts = IntegratorOptions {
            rtol: 1e6,
            atol: 1e6,
            initial_step: Some(h),
            max_step: h,
            ..IntegratorOptions::default()
        };
        let mut sys = Smooth::new(2, oscillator);
        let (stats, result, y) = run(&mut sys, 0.0, 1.0, &[1.0, 0.0], &opts);
        result.unwrap();
        assert_eq!(stats.accepted_steps, (1.0 / h).round() as usize);
        (y[0] - 1.0).abs().max(y[1].abs() / 6.3)
    };
    let (e1, e2) = (error_with(1.0 / 40.0), error_with(1.0 / 80.0));
    let order = (e1 / e2).log2();
    println!("DOPRI fixed-step order {order}");
    assert!((order - 5.0).abs() < 0.3, "observed order {order}");
}

/// Slope of log(error) against log(steps) over a tolerance sweep 1e-6 to 1e-10.
fn observed_order(method: Method) -> f64 {
    let (e1, s1) = oscillator_error(method, 1e-6);
    let (e2, s2) = oscillator_error(method, 1e-10);
    -(e2 / e1).ln() / (s2.accepted_steps as f64 / s1.accepted_steps as f64).ln()
}

#[test]
fn error_scales_with_tolerance_as_the_control_strategy_predicts() {
    // extrapolated DOPRI: error ~ tol; per-step-controlled Adams of order 4: error ~ tol^(4/5)
    for (method, exponent) in [(Method::DormandPrince45, 1.0), (Method::AdamsPredictorCorrector, 0.8)] {
        let (e1, _) = oscillator_error(method, 1e-6);
        let (e2, _) = oscillator_error(method, 1e-10);
        let observed = (e2 / e1).log10() / -4.0;
        println!("{method:?}: error ~ tol^{observed}");
        assert!((observed - exponent).abs() < 0.1, "{method:?}: exponent {observed}");
    }
}

#[test]
fn dormand_prince_error_falls_as_fifth_power_of_step_count() {
    let order = observed_order(Method::DormandPrince45);
    println!("DOPRI observed order {order}");
    assert!((order - 5.0).abs() < 0.6, "observed order {order}");
}

#[test]
fn adams_error_falls_as_fourth_power_of_step_count() {
    let order = observed_order(Method::AdamsPredictorCorrector);
    println!("Adams observed order {order}");
    assert!((order - 4.0).abs() < 0.5, "observed order {order}");
}

/// `y' = cos t` in one component whose unit is `scale` times smaller (pascals next to metres).
struct ScaledSine {
    scale: f64,
    last: f64,
}

impl OdeSystem for ScaledSine {
    fn len(&self) -> usize {
        1
    }
    fn rhs(&mut self, t: f64, _y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError> {
        dydt[0] = self.scale * t.cos();
        Ok(())
    }
    fn absolute_tolerance_scales(&self, scales: &mut [f64]) {
        scales[0] = self.scale;
    }
    fn record(&mut self, _t: f64, y: &[f64]) -> Result<(), SimulationError> {
        self.last = y[0];
        Ok(())
    }
}

#[test]
fn a_component_in_smaller_units_with_its_tolerance_scaled_takes_the_same_steps() {
    // the same motion in metres and in micrometres: with atol scaled by the unit the
    // error control sees the same problem, so the steps and the relative error agree
    for method in METHODS {
        let opts = IntegratorOptions { rtol: 1e-13, atol: 1e-8, ..options(method, 1e-8) };
        let run = |scale: f64| {
            let mut system = ScaledSine { scale, last: 0.0 };
            let mut y = [0.0];
            let (stats, result) = integrate(&mut system, 0.0, 3.0, &mut y, &opts);
            result.unwrap();
            (stats.accepted_steps, (system.last / scale - 3.0_f64.sin()).abs())
        };
        let (metres, micrometres) = (run(1.0), run(1e6));
        assert_eq!(metres.0, micrometres.0, "{method:?}: steps");
        assert!(micrometres.1 < 1e-6 && metres.1 < 1e-6, "{method:?}: errors {metres:?} {micrometres:?}");
    }
}
