//! Projection in `accept()` and restarts requested by it.

use super::*;

/// Rotation x' = -y, y' = x; `accept` projects onto the unit circle when
/// `project` is set and asks for a restart every `restart_every` steps.
struct Circle {
    project: bool,
    restart_every: usize,
    accepts: usize,
    calls: usize,
    samples: Vec<(f64, Vec<f64>)>,
}

impl Circle {
    fn new(project: bool, restart_every: usize) -> Self {
        Self { project, restart_every, accepts: 0, calls: 0, samples: Vec::new() }
    }
}

impl OdeSystem for Circle {
    fn len(&self) -> usize {
        2
    }
    fn rhs(&mut self, _t: f64, y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError> {
        self.calls += 1;
        dydt[0] = -y[1];
        dydt[1] = y[0];
        Ok(())
    }
    fn accept(&mut self, _t: f64, y: &mut [f64]) -> Result<bool, SimulationError> {
        self.accepts += 1;
        if self.project {
            let r = y[0].hypot(y[1]);
            y[0] /= r;
            y[1] /= r;
        }
        Ok(self.restart_every > 0 && self.accepts.is_multiple_of(self.restart_every))
    }
    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        self.samples.push((t, y.to_vec()));
        Ok(())
    }
}

/// Largest |r - 1| over the samples.
fn radius_drift(samples: &[(f64, Vec<f64>)]) -> f64 {
    samples.iter().map(|(_, y)| (y[0].hypot(y[1]) - 1.0).abs()).fold(0.0, f64::max)
}

#[test]
fn projection_in_accept_keeps_state_on_unit_circle() {
    for method in METHODS {
        // without projection the radius drifts at tolerance level over 50 turns
        let mut free = Circle::new(false, 0);
        let t_end = 100.0 * std::f64::consts::PI;
        let (_, result, y_free) = run(&mut free, 0.0, t_end, &[1.0, 0.0], &options(method, 1e-6));
        result.unwrap();
        let free_drift = radius_drift(&free.samples);
        let free_phase_error = y_free[1].atan2(y_free[0]).abs();
        assert!(free_drift > 1e-7, "{method:?}: drift {free_drift:e} too small for the test to mean anything");
        // with projection every recorded state is on the circle to rounding
        let mut projected = Circle::new(true, 0);
        let (stats, result, y) = run(&mut projected, 0.0, t_end, &[1.0, 0.0], &options(method, 1e-6));
        result.unwrap();
        assert!(radius_drift(&projected.samples) < 4.0 * f64::EPSILON, "{method:?}");
        assert_eq!(stats.restarts, 0);
        // projection removes the radial error without spoiling the phase (back at (1, 0) after 50 turns)
        let phase_error = y[1].atan2(y[0]).abs();
        println!("{method:?}: free drift {free_drift:e}, phase error {phase_error:e} (free {free_phase_error:e})");
        assert!(phase_error < 1.5 * free_phase_error + 1e-9, "{method:?}: phase error {phase_error:e}");
    }
}

#[test]
fn restart_requested_by_accept_is_counted_and_keeps_accuracy() {
    for method in EXPLICIT_METHODS {
        let mut sys = Circle::new(false, 10);
        let (stats, result, y) = run(&mut sys, 0.0, 10.0, &[1.0, 0.0], &options(method, 1e-8));
        result.unwrap();
        assert_eq!(stats.restarts, stats.accepted_steps / 10, "{method:?}: {stats:?}");
        let expected = match method {
            Method::DormandPrince45 => 6 * (stats.accepted_steps + stats.rejected_steps) + 2 + stats.restarts,
            Method::AdamsPredictorCorrector => 2 * stats.accepted_steps + stats.rejected_steps + 2 + stats.restarts,
            Method::NumericalDifferentiation | Method::GeneralizedAlpha => unreachable!("implicit: counted in tests/stiff.rs and tests/generalized_alpha.rs"),
        };
        assert_eq!(stats.rhs_evaluations, expected, "{method:?}: {stats:?}");
        assert_eq!(stats.rhs_evaluations, sys.calls);
        let err = (y[0] - 10f64.cos()).abs().max((y[1] - 10f64.sin()).abs());
        assert!(err < tolerance_bound(method, 1e-8, &stats), "{method:?}: error {err:e}");
    }
}

/// Rotation as in [`Circle`], projected in `project()` (before the last
/// stage) and checked in `rhs()`: every evaluation at a step end sees the
/// projected state.
struct TrialProjection {
    projections: usize,
    evaluated_off_circle: usize,
    last_attempt_end: f64,
    samples: Vec<(f64, Vec<f64>)>,
}

impl OdeSystem for TrialProjection {
    fn len(&self) -> usize {
        2
    }
    fn rhs(&mut self, t: f64, y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError> {
        if t == self.last_attempt_end && (y[0].hypot(y[1]) - 1.0).abs() > 1e-15 {
            self.evaluated_off_circle += 1;
        }
        dydt[0] = -y[1];
        dydt[1] = y[0];
        Ok(())
    }
    fn project(&mut self, t: f64, y: &mut [f64]) -> Result<(), SimulationError> {
        self.projections += 1;
        self.last_attempt_end = t;
        let r = y[0].hypot(y[1]);
        y[0] /= r;
        y[1] /= r;
        Ok(())
    }
    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        self.samples.push((t, y.to_vec()));
        Ok(())
    }
}

#[test]
fn dormand_prince_projects_each_trial_step_end_before_its_last_stage() {
    let mut sys = TrialProjection { projections: 0, evaluated_off_circle: 0, last_attempt_end: f64::NAN, samples: Vec::new() };
    let t_end = 20.0 * std::f64::consts::PI;
    let (stats, result, y) = run(&mut sys, 0.0, t_end, &[1.0, 0.0], &options(Method::DormandPrince45, 1e-8));
    result.unwrap();
    assert_eq!(sys.projections, stats.accepted_steps + stats.rejected_steps);
    assert_eq!(sys.evaluated_off_circle, 0);
    // on the circle at every recorded step end, and back at (1, 0) after 10 turns
    assert!(radius_drift(&sys.samples) < 1e-15, "drift {:e}", radius_drift(&sys.samples));
    assert!(y[1].atan2(y[0]).abs() < 1e-6, "phase {:e}", y[1].atan2(y[0]));
}
