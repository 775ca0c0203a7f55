//! Failures: step-size underflow, step limit, errors from rhs and record, bad options.

use super::*;

/// y' = y^2 from y(0) = 1: y = 1 / (1 - t) blows up at t = 1.
fn blow_up(_t: f64, y: &[f64], dydt: &mut [f64]) {
    dydt[0] = y[0] * y[0];
}

#[test]
fn blow_up_returns_step_size_underflow_near_singularity() {
    for method in METHODS {
        let mut sys = Smooth::new(1, blow_up);
        let (stats, result, _) = run(&mut sys, 0.0, 2.0, &[1.0], &options(method, 1e-8));
        match result {
            Err(SimulationError::StepSizeUnderflow { time, step, element: None }) => {
                // the numerical blow-up time matches the exact one to about the tolerance
                assert!((time - 1.0).abs() < 1e-3, "{method:?}: stopped at {time}");
                assert!(step < 1e-14, "{method:?}: step {step:e}");
            }
            other => panic!("{method:?}: expected StepSizeUnderflow, got {other:?}"),
        }
        assert!(stats.accepted_steps > 10);
        assert!(sys.samples.last().unwrap().0 < 1.001);
    }
}

#[test]
fn too_many_steps_reports_limit_and_time_reached() {
    for method in METHODS {
        let mut sys = Smooth::new(2, oscillator);
        let mut opts = options(method, 1e-8);
        opts.max_steps = 10;
        let (stats, result, _) = run(&mut sys, 0.0, 10.0, &[1.0, 0.0], &opts);
        let last_time = sys.samples.last().unwrap().0;
        assert_eq!(result, Err(SimulationError::TooManySteps { time: last_time, max_steps: 10 }), "{method:?}");
        assert_eq!(stats.accepted_steps + stats.rejected_steps, 10);
    }
}

#[test]
fn too_many_steps_message_names_the_option_to_raise() {
    let error = SimulationError::TooManySteps { time: 0.25, max_steps: 10_000_000 };
    assert_eq!(
        error.to_string(),
        "the run exceeded max_steps = 10000000 attempted steps at t = 2.500000e-1 s; raise simulation.max_steps (or look for why the steps are so small)"
    );
}

/// y' = -y whose rhs fails after t = 0.5 s.
struct FailsLate {
    samples: usize,
}

impl OdeSystem for FailsLate {
    fn len(&self) -> usize {
        1
    }
    fn rhs(&mut self, t: f64, y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError> {
        if t > 0.5 {
            return Err(SimulationError::ExcessivePenetration {
                time: t,
                element: "B".to_string(),
                penetration: 1e-3,
                bound: 1e-4,
            });
        }
        dydt[0] = -y[0];
        Ok(())
    }
    fn record(&mut self, t: f64, _y: &[f64]) -> Result<(), SimulationError> {
        self.samples += 1;
        if self.samples > 5 {
            return Err(SimulationError::Interrupted { time: t });
        }
        Ok(())
    }
}

#[test]
fn rhs_error_is_propagated_with_statistics() {
    for method in METHODS {
        let mut sys = FailsLate { samples: 0 };
        let mut opts = options(method, 1e-6);
        opts.output_step = Some(1.0); // records only t0 before the failure
        let (stats, result) = integrate(&mut sys, 0.0, 1.0, &mut [1.0], &opts);
        match result {
            Err(SimulationError::ExcessivePenetration { time, element, .. }) => {
                assert!(time > 0.5 && time <= 1.0, "{method:?}: {time}");
                assert_eq!(element, "B");
            }
            other => panic!("{method:?}: expected the rhs error, got {other:?}"),
        }
        assert!(stats.accepted_steps > 0 && stats.rhs_evaluations > 0, "{method:?}: {stats:?}");
    }
}

#[test]
fn error_from_record_aborts_the_run() {
    for method in METHODS {
        let mut sys = FailsLate { samples: 0 };
        let mut opts = options(method, 1e-6);
        opts.output_step = Some(0.01);
        let (stats, result) = integrate(&mut sys, 0.0, 0.4, &mut [1.0], &opts);
        // the sixth sample (t = 0.05) interrupts
        assert_eq!(result, Err(SimulationError::Interrupted { time: 0.05 }), "{method:?}");
        assert!(stats.accepted_steps > 0);
    }
}

/// y' = -sqrt(y), defined only for y >= 0: the rhs returns NaN below.
fn square_root_decay(_t: f64, y: &[f64], dydt: &mut [f64]) {
    dydt[0] = -y[0].sqrt();
}

#[test]
fn non_finite_stage_rejects_the_step_and_shrinks_it() {
    // a 5 s first step sends stages below y = 0; y = (1 - t/2)^2 until t = 2
    for method in METHODS {
        let mut sys = Smooth::new(1, square_root_decay);
        let mut opts = options(method, 1e-8);
        opts.initial_step = Some(5.0);
        let (stats, result, y) = run(&mut sys, 0.0, 1.5, &[1.0], &opts);
        result.unwrap();
        assert!(stats.rejected_steps >= 1, "{method:?}: {stats:?}");
        assert!((y[0] - 0.0625).abs() < tolerance_bound(method, 1e-8, &stats), "{method:?}: {}", y[0]);
    }
}

#[test]
fn invalid_options_are_listed_one_per_field() {
    let opts = IntegratorOptions { rtol: 0.0, atol: -1.0, output_step: Some(0.0), ..IntegratorOptions::default() };
    assert_eq!(
        opts.validate(),
        Err("rtol: must be >= 2.2e-14 and finite, got 0e0; atol: must be >= 0 and finite, got -1e0; \
             output_step: must be > 0 s and finite, got 0e0"
            .to_string())
    );
    assert_eq!(IntegratorOptions::default().validate(), Ok(()));
}

#[test]
fn integrate_refuses_invalid_input_before_stepping() {
    let mut sys = Smooth::new(1, decay);
    let opts = IntegratorOptions { max_step: 0.0, ..IntegratorOptions::default() };
    let (stats, result) = integrate(&mut sys, 0.0, 1.0, &mut [1.0], &opts);
    assert_eq!(
        result,
        Err(SimulationError::InvalidInput {
            time: 0.0,
            message: "max_step: must be > 0 s, got 0e0; min_step: must be < max_step, got 1e-14".to_string()
        })
    );
    assert_eq!((stats, sys.samples.len()), (Statistics::default(), 0));
    let (_, result) = integrate(&mut sys, 0.0, 1.0, &mut [1.0, 2.0], &IntegratorOptions::default());
    assert!(matches!(result, Err(SimulationError::InvalidInput { .. })));
}
