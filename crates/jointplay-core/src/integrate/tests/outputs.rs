//! Output sampling, step limits and exact statistics.

use super::*;

#[test]
fn output_times_lie_exactly_on_grid_with_t0_and_t_end() {
    let (t0, t_end, dt) = (0.3, 1.3, 0.1);
    for method in METHODS {
        let mut sys = Smooth::new(1, decay);
        let mut opts = options(method, 1e-9);
        opts.output_step = Some(dt);
        let (stats, result, _) = run(&mut sys, t0, t_end, &[1.0], &opts);
        result.unwrap();
        // t0, then t0 + i dt for i = 1..9, then t_end
        let mut expected = vec![t0];
        expected.extend((1..10).map(|i| t0 + i as f64 * dt));
        expected.push(t_end);
        let times: Vec<f64> = sys.samples.iter().map(|(t, _)| *t).collect();
        assert_eq!(times, expected, "{method:?}");
        // dense-output samples are as accurate as step ends
        let err = max_sample_error(&sys.samples, |t| vec![(t0 - t).exp()]);
        let bound = tolerance_bound(method, 1e-9, &stats);
        assert!(err < bound, "{method:?}: dense output error {err:e} > {bound:e}");
    }
}

#[test]
fn every_accepted_step_is_recorded_without_output_step() {
    for method in METHODS {
        let mut sys = Smooth::new(2, oscillator);
        let (stats, result, _) = run(&mut sys, 0.0, 2.0, &[1.0, 0.0], &options(method, 1e-7));
        result.unwrap();
        assert_eq!(sys.samples.len(), stats.accepted_steps + 1, "{method:?}");
        assert_eq!(sys.samples.first().unwrap().0, 0.0);
        assert_eq!(sys.samples.last().unwrap().0, 2.0);
        assert!(sys.samples.windows(2).all(|w| w[1].0 > w[0].0), "{method:?}: times not increasing");
    }
}

#[test]
fn max_step_is_honoured() {
    for method in METHODS {
        let mut sys = Smooth::new(1, decay);
        let mut opts = options(method, 1e-4);
        opts.max_step = 1e-2;
        let (stats, result, _) = run(&mut sys, 0.0, 1.0, &[1.0], &opts);
        result.unwrap();
        assert!(stats.largest_step <= 1e-2, "{method:?}: {stats:?}");
        assert!(stats.accepted_steps >= 100, "{method:?}: {stats:?}");
        let widest = sys.samples.windows(2).map(|w| w[1].0 - w[0].0).fold(0.0, f64::max);
        assert!(widest <= 1e-2 * (1.0 + 1e-12), "{method:?}: gap {widest}");
    }
}

#[test]
fn zero_length_interval_records_t0_once() {
    let mut sys = Smooth::new(1, decay);
    let (stats, result, y) = run(&mut sys, 1.0, 1.0, &[2.0], &IntegratorOptions::default());
    result.unwrap();
    assert_eq!(sys.samples, vec![(1.0, vec![2.0])]);
    assert_eq!((stats.accepted_steps, stats.rhs_evaluations, y[0]), (0, 0, 2.0));
}

#[test]
fn rhs_evaluations_are_counted_exactly_with_rejections() {
    // a first step of 1 s on y' = -y at 1e-9 is rejected several times
    for method in EXPLICIT_METHODS {
        for initial_step in [Some(1.0), None] {
            let mut sys = Smooth::new(1, decay);
            let mut opts = options(method, 1e-9);
            opts.initial_step = initial_step;
            let (stats, result, _) = run(&mut sys, 0.0, 3.0, &[1.0], &opts);
            result.unwrap();
            let probe = usize::from(initial_step.is_none());
            let attempted = stats.accepted_steps + stats.rejected_steps;
            let expected = match method {
                Method::DormandPrince45 => 6 * attempted + 1 + probe,
                Method::AdamsPredictorCorrector => 2 * stats.accepted_steps + stats.rejected_steps + 1 + probe,
                Method::NumericalDifferentiation | Method::GeneralizedAlpha => unreachable!("implicit: counted in tests/stiff.rs and tests/generalized_alpha.rs"),
            };
            assert_eq!(stats.rhs_evaluations, expected, "{method:?} {initial_step:?}: {stats:?}");
            assert_eq!(stats.rhs_evaluations, sys.calls);
            if initial_step.is_some() {
                assert!(stats.rejected_steps > 0, "{method:?}: no rejection to count");
            }
            assert!(stats.smallest_step > 0.0 && stats.smallest_step <= stats.largest_step);
        }
    }
}
