//! The implicit NDF method on stiff problems: accuracy against a closed form
//! and against Dormand-Prince at tight tolerance, the step counts that make
//! it worth having, and exact counting of its evaluations.

use super::*;

/// Stiffness of the linear test problem [1/s].
const LAMBDA: f64 = 1e4;

/// y' = -lambda (y - cos t) - sin t: y = cos t + (y0 - 1) e^(-lambda t).
fn stiff_linear(t: f64, y: &[f64], dydt: &mut [f64]) {
    dydt[0] = -LAMBDA * (y[0] - t.cos()) - t.sin();
}

/// Van der Pol oscillator with mu = 100 as (x, x'): x'' = mu (1 - x^2) x' - x.
fn van_der_pol(_t: f64, y: &[f64], dydt: &mut [f64]) {
    dydt[0] = y[1];
    dydt[1] = 100.0 * (1.0 - y[0] * y[0]) * y[1] - y[0];
}

#[test]
fn stiff_linear_problem_follows_the_closed_form_in_few_steps() {
    for tol in [1e-6, 1e-8] {
        let mut sys = Smooth::new(1, stiff_linear);
        let opts = options(Method::NumericalDifferentiation, tol);
        let (stats, result, _) = run(&mut sys, 0.0, 10.0, &[2.0], &opts);
        result.unwrap();
        let err = max_sample_error(&sys.samples, |t| vec![t.cos() + (-LAMBDA * t).exp()]);
        let bound = tolerance_bound(Method::NumericalDifferentiation, tol, &stats);
        println!("stiff linear tol {tol:e}: error {err:e} (bound {bound:e}), {stats:?}");
        assert!(err < bound, "tol {tol:e}: error {err:e} > {bound:e}");
        // an explicit method needs h < ~3.3 / lambda: at least 30 000 steps over 10 s
        assert!(stats.accepted_steps < 2_000, "tol {tol:e}: {} steps", stats.accepted_steps);
    }
}

#[test]
fn explicit_methods_need_far_more_steps_on_the_stiff_problem() {
    let mut implicit = Smooth::new(1, stiff_linear);
    let (ndf, result, _) = run(&mut implicit, 0.0, 10.0, &[2.0], &options(Method::NumericalDifferentiation, 1e-6));
    result.unwrap();
    let mut explicit = Smooth::new(1, stiff_linear);
    let (dopri, result, _) = run(&mut explicit, 0.0, 10.0, &[2.0], &options(Method::DormandPrince45, 1e-6));
    result.unwrap();
    println!("steps: NDF {}, Dormand-Prince {}", ndf.accepted_steps, dopri.accepted_steps);
    assert!(dopri.accepted_steps > 20 * ndf.accepted_steps);
    assert!(dopri.rhs_evaluations > 20 * ndf.rhs_evaluations);
}

#[test]
fn van_der_pol_agrees_with_dormand_prince_at_tight_tolerance() {
    // reference: the explicit method at 1e-12 (independent of the implicit code)
    let y0 = [2.0, 0.0];
    let mut reference = Smooth::new(2, van_der_pol);
    let (_, result, exact) = run(&mut reference, 0.0, 50.0, &y0, &options(Method::DormandPrince45, 1e-12));
    result.unwrap();
    for tol in [1e-6, 1e-8] {
        let mut sys = Smooth::new(2, van_der_pol);
        let (stats, result, y) = run(&mut sys, 0.0, 50.0, &y0, &options(Method::NumericalDifferentiation, tol));
        result.unwrap();
        // on the slow branch x' is about -x / (mu (x^2 - 1)): compare x, the state the error test sees at scale 1
        let err = (y[0] - exact[0]).abs();
        println!("van der Pol tol {tol:e}: x error {err:e}, {stats:?}");
        assert!(err < 100.0 * tol, "tol {tol:e}: x error {err:e}");
        assert!(err > 1e-4 * tol, "error {err:e} suspiciously small");
    }
}

#[test]
fn evaluations_are_counted_exactly_including_jacobians() {
    let mut sys = Smooth::new(2, van_der_pol);
    let (stats, result, _) = run(&mut sys, 0.0, 50.0, &[2.0, 0.0], &options(Method::NumericalDifferentiation, 1e-6));
    result.unwrap();
    assert_eq!(stats.rhs_evaluations, sys.calls);
    assert!(stats.jacobian_evaluations >= 1 && stats.factorizations >= stats.jacobian_evaluations, "{stats:?}");
    // each attempt evaluates at least once (Newton), each Jacobian n + 1 times, plus the start and its probe
    let attempts = stats.accepted_steps + stats.rejected_steps;
    let jacobians = 3 * stats.jacobian_evaluations;
    assert!(stats.rhs_evaluations >= attempts + jacobians + 2, "{stats:?}");
    assert!(stats.rhs_evaluations <= 4 * 2 * attempts + jacobians + 2, "{stats:?}");
}

#[test]
fn dense_output_samples_follow_the_closed_form() {
    let mut sys = Smooth::new(1, stiff_linear);
    let mut opts = options(Method::NumericalDifferentiation, 1e-8);
    opts.output_step = Some(0.01);
    let (stats, result, _) = run(&mut sys, 0.0, 10.0, &[1.0], &opts);
    result.unwrap();
    assert_eq!(sys.samples.len(), 1001);
    // more samples than steps: most come from the interpolant between steps
    assert!(stats.accepted_steps < 500, "{stats:?}");
    let err = max_sample_error(&sys.samples, |t| vec![t.cos()]);
    assert!(err < tolerance_bound(Method::NumericalDifferentiation, 1e-8, &stats), "error {err:e}");
}



#[test]
fn max_order_is_checked() {
    assert!(IntegratorOptions { max_order: 6, ..IntegratorOptions::default() }.validate().unwrap_err().contains("max_order: must be 1 to 5"));
    assert!(IntegratorOptions { max_order: 0, ..IntegratorOptions::default() }.validate().is_err());
    assert!(IntegratorOptions { max_order: 2, ..IntegratorOptions::default() }.validate().is_ok());
}
