//! Step-size control shared by the methods: the weighted error norm, the
//! starting-step heuristic and the PI step-size controller
//! (Hairer, Nørsett & Wanner, Solving ODEs I, 2nd ed., Sections II.4 and IV.2).

use super::{IntegratorOptions, OdeSystem, Statistics};
use crate::error::SimulationError;

/// Safety factor on the predicted optimal step.
const SAFETY: f64 = 0.9;
/// Smallest ratio new step / old step.
pub(crate) const SHRINK_LIMIT: f64 = 0.2;

/// Calls the right-hand side and counts the call.
pub(crate) fn eval<S: OdeSystem>(
    system: &mut S,
    stats: &mut Statistics,
    t: f64,
    y: &[f64],
    dydt: &mut [f64],
) -> Result<(), SimulationError> {
    stats.rhs_evaluations += 1;
    system.rhs(t, y, dydt)
}

/// Evaluates the derivative at a (re)start point, which must be finite: a restart cannot shrink a step.
pub(crate) fn eval_start<S: OdeSystem>(
    system: &mut S,
    stats: &mut Statistics,
    t: f64,
    y: &[f64],
    dydt: &mut [f64],
) -> Result<(), SimulationError> {
    eval(system, stats, t, y, dydt)?;
    if !dydt.iter().all(|v| v.is_finite()) {
        return Err(SimulationError::NonFinite { time: t, element: "state derivative".to_string() });
    }
    Ok(())
}

/// What a trial evaluation inside a step found: a finite derivative, or a
/// non-finite one (a step too long for a stiff force: the step is rejected
/// with the largest shrink, unless that falls below `min_step` [s], where the
/// error stands).
pub(crate) fn eval_trial<S: OdeSystem>(
    system: &mut S,
    stats: &mut Statistics,
    t: f64,
    y: &[f64],
    dydt: &mut [f64],
) -> Result<Option<SimulationError>, SimulationError> {
    match eval(system, stats, t, y, dydt) {
        Ok(()) if dydt.iter().all(|v| v.is_finite()) => Ok(None),
        Ok(()) => Ok(Some(SimulationError::NonFinite { time: t, element: "state derivative".to_string() })),
        Err(error @ SimulationError::NonFinite { .. }) => Ok(Some(error)),
        Err(error) => Err(error),
    }
}

impl StepController {
    /// The rejection of a step `h` [s] whose trial evaluation was not finite (`error`), with the
    /// largest shrink; the error itself when the smaller step would fall below `min_step` [s].
    pub(crate) fn reject_non_finite(&mut self, h: f64, min_step: f64, error: SimulationError) -> Result<f64, SimulationError> {
        let h_next = self.rejected(h, f64::NAN, 1.0);
        if h_next < min_step { Err(error) } else { Ok(h_next) }
    }
}

/// The tolerances of the error norm: one relative tolerance, an absolute
/// tolerance per component (the option's atol times the component's scale,
/// [`OdeSystem::absolute_tolerance_scales`]).
#[derive(Clone, Debug)]
pub(crate) struct Tolerances {
    /// Relative tolerance [-].
    pub rtol: f64,
    /// Absolute tolerance of each component [unit of the component].
    pub atol: Vec<f64>,
}

impl Tolerances {
    /// The tolerances of `opts` for `system`'s components.
    pub(crate) fn new<S: OdeSystem>(system: &S, opts: &IntegratorOptions) -> Self {
        let mut atol = vec![1.0; system.len()];
        system.absolute_tolerance_scales(&mut atol);
        for a in &mut atol {
            *a *= opts.atol;
        }
        Self { rtol: opts.rtol, atol }
    }
}

/// RMS of `scale * err_i / (atol_i + rtol * max(|y_old_i|, |y_new_i|))`; 0 for an empty state.
pub(crate) fn error_norm(scale: f64, err: &[f64], y_old: &[f64], y_new: &[f64], tol: &Tolerances) -> f64 {
    if err.is_empty() {
        return 0.0;
    }
    let mut sum = 0.0;
    for i in 0..err.len() {
        let sk = tol.atol[i] + tol.rtol * y_old[i].abs().max(y_new[i].abs());
        let r = scale * err[i] / sk;
        sum += r * r;
    }
    (sum / err.len() as f64).sqrt()
}

/// RMS of `v_i / (atol_i + rtol |y_i|)`.
fn weighted_rms(v: &[f64], y: &[f64], tol: &Tolerances) -> f64 {
    error_norm(1.0, v, y, y, tol)
}

/// Scratch buffers of the starting-step heuristic, allocated once.
pub(crate) struct StartScratch {
    y1: Vec<f64>,
    f1: Vec<f64>,
}

impl StartScratch {
    /// Buffers for a state of `n` components.
    pub(crate) fn new(n: usize) -> Self {
        Self { y1: vec![0.0; n], f1: vec![0.0; n] }
    }
}

/// Hairer's starting step for a method whose local error is O(h^q): one
/// explicit Euler probe estimates the second derivative (ODE I, II.4).
#[allow(clippy::too_many_arguments)]
pub(crate) fn starting_step<S: OdeSystem>(
    system: &mut S,
    stats: &mut Statistics,
    t: f64,
    y: &[f64],
    f0: &[f64],
    q: f64,
    opts: &IntegratorOptions,
    tol: &Tolerances,
    scratch: &mut StartScratch,
) -> Result<f64, SimulationError> {
    // first guess from the size of y and of f
    let d0 = weighted_rms(y, y, tol);
    let d1 = weighted_rms(f0, y, tol);
    let mut h0 = if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 };
    h0 = h0.min(opts.max_step);
    // explicit Euler probe for the second derivative
    for i in 0..y.len() {
        scratch.y1[i] = y[i] + h0 * f0[i];
    }
    eval(system, stats, t + h0, &scratch.y1, &mut scratch.f1)?;
    for i in 0..y.len() {
        scratch.f1[i] = (scratch.f1[i] - f0[i]) / h0;
    }
    let d2 = weighted_rms(&scratch.f1, y, tol);
    // step whose local error would be about 1 % of the tolerance
    let dmax = d1.max(d2);
    let h1 = if !dmax.is_finite() {
        h0
    } else if dmax <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / dmax).powf(1.0 / q)
    };
    Ok((100.0 * h0).min(h1).min(opts.max_step))
}

/// PI step-size controller with Lund stabilisation (ODE I, IV.2, eq. 2.43).
pub(crate) struct StepController {
    /// Weight of the previous error (0 gives the standard controller).
    beta: f64,
    /// Largest ratio new step / old step.
    grow_limit: f64,
    /// Error norm of the previous accepted step (floored at 1e-4).
    err_old: f64,
    /// Whether the previous attempt was rejected.
    rejected_last: bool,
}

impl StepController {
    /// Controller with PI weight `beta` and growth limit `grow_limit`.
    pub(crate) fn new(beta: f64, grow_limit: f64) -> Self {
        Self { beta, grow_limit, err_old: 1e-4, rejected_last: false }
    }

    /// Forgets the previous error (after a restart).
    pub(crate) fn reset(&mut self) {
        self.err_old = 1e-4;
        self.rejected_last = false;
    }

    /// Next step after accepting a step `h` with error norm `err` <= 1, for local error O(h^q).
    pub(crate) fn accepted(&mut self, h: f64, err: f64, q: f64) -> f64 {
        let alpha = 1.0 / q - 0.75 * self.beta;
        let err = err.max(1e-10);
        let mut factor = SAFETY * err.powf(-alpha) * self.err_old.powf(self.beta);
        factor = factor.clamp(SHRINK_LIMIT, self.grow_limit);
        // no growth right after a rejection
        if self.rejected_last {
            factor = factor.min(1.0);
        }
        self.err_old = err.max(1e-4);
        self.rejected_last = false;
        h * factor
    }

    /// Smaller step after rejecting a step `h` with error norm `err` (> 1 or not finite).
    pub(crate) fn rejected(&mut self, h: f64, err: f64, q: f64) -> f64 {
        self.rejected_last = true;
        if !err.is_finite() {
            return h * SHRINK_LIMIT;
        }
        let factor = SAFETY * err.powf(-1.0 / q);
        h * factor.clamp(SHRINK_LIMIT, 1.0)
    }
}
