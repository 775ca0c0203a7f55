//! Tests of the integrators against closed forms: accuracy and order,
//! output sampling and statistics, events, projection in `accept()`, errors.

mod accuracy;
mod errors;
mod events;
mod generalized_alpha;
mod observe;
mod outputs;
mod projection;
mod stiff;

use super::{integrate, IntegratorOptions, Method, OdeSystem, Statistics};
use crate::error::SimulationError;

/// Every method, for tests that must hold for each.
pub(super) const METHODS: [Method; 3] = [Method::DormandPrince45, Method::AdamsPredictorCorrector, Method::NumericalDifferentiation];
/// The explicit methods, whose evaluation count follows a formula of the step counts.
pub(super) const EXPLICIT_METHODS: [Method; 2] = [Method::DormandPrince45, Method::AdamsPredictorCorrector];

/// Options with the given method and tolerance (atol = rtol).
pub(super) fn options(method: Method, tol: f64) -> IntegratorOptions {
    IntegratorOptions { method, rtol: tol, atol: tol, ..IntegratorOptions::default() }
}

/// A smooth system given by a right-hand-side function, recording every sample.
pub(super) struct Smooth {
    /// Number of states.
    pub n: usize,
    /// dy/dt = f(t, y).
    pub f: fn(f64, &[f64], &mut [f64]),
    /// Calls of rhs seen by the system (independent of the integrator's count).
    pub calls: usize,
    /// Recorded (t, y).
    pub samples: Vec<(f64, Vec<f64>)>,
}

impl Smooth {
    /// System with `n` states and right-hand side `f`.
    pub fn new(n: usize, f: fn(f64, &[f64], &mut [f64])) -> Self {
        Self { n, f, calls: 0, samples: Vec::new() }
    }
}

impl OdeSystem for Smooth {
    fn len(&self) -> usize {
        self.n
    }
    fn rhs(&mut self, t: f64, y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError> {
        self.calls += 1;
        (self.f)(t, y, dydt);
        Ok(())
    }
    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        self.samples.push((t, y.to_vec()));
        Ok(())
    }
}

/// y' = -y.
pub(super) fn decay(_t: f64, y: &[f64], dydt: &mut [f64]) {
    dydt[0] = -y[0];
}

/// Harmonic oscillator x'' = -(2 pi)^2 x as (x, v): period 1 s.
pub(super) fn oscillator(_t: f64, y: &[f64], dydt: &mut [f64]) {
    let w = 2.0 * std::f64::consts::PI;
    dydt[0] = y[1];
    dydt[1] = -w * w * y[0];
}

/// Pendulum theta'' = -(g/L) sin theta as (theta, omega), g/L = 9.81 1/s^2.
pub(super) fn pendulum(_t: f64, y: &[f64], dydt: &mut [f64]) {
    dydt[0] = y[1];
    dydt[1] = -9.81 * y[0].sin();
}

/// Pendulum energy per unit m L^2: omega^2/2 - (g/L) cos theta [1/s^2].
pub(super) fn pendulum_energy(y: &[f64]) -> f64 {
    0.5 * y[1] * y[1] - 9.81 * y[0].cos()
}

/// Bound on the global error of a run at tolerance `tol` (scaled to the solution size 1).
///
/// Dormand-Prince propagates the 5th-order solution while controlling the
/// 4th-order estimate (local extrapolation), so its global error stays within
/// a small multiple of the tolerance. The Adams corrector's own error is
/// controlled per step without extrapolation, so its global error is bounded
/// by the sum of the local errors: twice the tolerance times the step count;
/// the same holds for the NDF.
pub(super) fn tolerance_bound(method: Method, tol: f64, stats: &Statistics) -> f64 {
    match method {
        Method::DormandPrince45 => 20.0 * tol,
        Method::AdamsPredictorCorrector | Method::NumericalDifferentiation => 2.0 * tol * stats.accepted_steps as f64,
        Method::GeneralizedAlpha => unreachable!("no error control: its accuracy is its step's"),
    }
}

/// Runs `integrate` and returns statistics, result and final state.
pub(super) fn run<S: OdeSystem>(
    system: &mut S,
    t0: f64,
    t_end: f64,
    y0: &[f64],
    opts: &IntegratorOptions,
) -> (Statistics, Result<(), SimulationError>, Vec<f64>) {
    let mut y = y0.to_vec();
    let (stats, result) = integrate(system, t0, t_end, &mut y, opts);
    (stats, result, y)
}

/// Largest |a - b| over recorded samples against a closed form of t.
pub(super) fn max_sample_error(samples: &[(f64, Vec<f64>)], exact: impl Fn(f64) -> Vec<f64>) -> f64 {
    let mut worst: f64 = 0.0;
    for (t, y) in samples {
        for (a, b) in y.iter().zip(exact(*t)) {
            worst = worst.max((a - b).abs());
        }
    }
    worst
}
