//! Time integrators with dense output and event location.
//!
//! [`integrate`] advances a first-order system [`OdeSystem`] from `t0` to
//! `t_end` with one of four [`Method`]s:
//!
//! - [`Method::DormandPrince45`]: explicit Runge-Kutta 5(4), FSAL, PI step
//!   control, 4th-order dense output (`docs/theory/integrator-dormand-prince.md`);
//! - [`Method::AdamsPredictorCorrector`]: variable-step Adams-Bashforth-Moulton
//!   PECE up to order 4 with Milne's error estimate, the method class of
//!   paper 001 (`docs/theory/integrator-adams.md`);
//! - [`Method::NumericalDifferentiation`]: implicit variable-order NDF/BDF
//!   with simplified Newton iterations, for stiff problems such as
//!   lubricated joints (`docs/theory/integrator-ndf.md`);
//! - [`Method::GeneralizedAlpha`]: implicit generalized-alpha for first-order
//!   systems with a fixed nominal step and numerical damping of unresolved
//!   vibrations, for flexible bodies (`docs/theory/integrator-generalized-alpha.md`).
//!
//! All share one driver: after each accepted step the event functions are
//! checked for a rise through zero, the earliest root is located on the
//! dense output, the step is cut there, outputs are recorded, the system
//! handles the event and the step (`on_event`, `accept`), and the method
//! restarts when the state jumped (`docs/theory/integrator-events.md`).

// component loops over several parallel buffers read best with an index
#![allow(clippy::needless_range_loop)]

mod adams;
mod bdf;
mod control;
mod dormand_prince;
mod driver;
mod events;
mod generalized_alpha;
mod newton_matrix;
mod options;
mod polynomial;
pub(crate) mod sparse_newton;
mod statistics;
#[cfg(test)]
mod tests;

pub use options::{IntegratorOptions, JacobianMethod, Method, MIN_RTOL};
pub use statistics::Statistics;
pub use sparse_newton::{NewtonParts, NewtonStructure};

use crate::error::SimulationError;

/// Whether a system can form the Jacobian of its right-hand side itself ([`OdeSystem::jacobian`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SystemJacobian {
    /// It cannot: the implicit method takes forward differences.
    Unavailable,
    /// It can, on request ([`JacobianMethod::Structured`]).
    Available,
    /// It can, and it pays: [`JacobianMethod::Auto`] takes it.
    Preferred,
}

/// What a Jacobian formed by the system cost, for the [`Statistics`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct JacobianCost {
    /// Full right-hand sides it evaluated itself (beyond the integrator's at the same state).
    pub rhs_evaluations: usize,
    /// Evaluations of the local forces (see [`Statistics::jacobian_force_evaluations`]).
    pub force_evaluations: usize,
}

/// A first-order system dy/dt = f(t, y) with discrete state the integrator does not see.
#[allow(clippy::len_without_is_empty)]
pub trait OdeSystem {
    /// Number of continuous states.
    fn len(&self) -> usize;

    /// dy/dt at (t, y). Called many times per step, at trial stages; must not allocate. May fail.
    fn rhs(&mut self, t: f64, y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError>;

    /// Scale of each component's absolute tolerance, into `scales` (filled with 1
    /// beforehand): component i is held to `atol * scales[i] + rtol |y_i|`. A
    /// system whose components have different units (metres and pascals) scales
    /// each by its kind, so that one atol means the same for all (default: all 1).
    fn absolute_tolerance_scales(&self, _scales: &mut [f64]) {}

    /// Number m of leading components that are positions whose rates are the
    /// next m components exactly (`y = [q, v, ...]`, `dq/dt = v`): generalized-alpha
    /// then updates q from v as a second-order method does. 0 (the default): no such split.
    fn second_order_positions(&self) -> usize {
        0
    }

    /// Whether [`Self::jacobian`] forms the Jacobian, and whether it pays
    /// (default: [`SystemJacobian::Unavailable`]).
    fn system_jacobian(&self) -> SystemJacobian {
        SystemJacobian::Unavailable
    }

    /// The Jacobian `df/dy` at (t, y) into `jacobian` (row-major, `len()` square),
    /// called by the implicit method right after `rhs` at the same (t, y).
    /// Where the system takes forward differences of its own, the increment of
    /// component j is `sqrt(eps) max(|y_j|, floors[j])` (`floors[j]`: the
    /// magnitude below which the absolute tolerance governs y_j, as the
    /// integrator's own differences use). Returns what it cost, or `None` when
    /// the system forms no Jacobian (the default): the integrator then takes
    /// forward differences of `rhs`. Must not allocate after its first call.
    fn jacobian(&mut self, _t: f64, _y: &[f64], _floors: &[f64], _jacobian: &mut [f64]) -> Result<Option<JacobianCost>, SimulationError> {
        Ok(None)
    }

    /// The structure of the Jacobian as the parts of a sparse Newton matrix
    /// ([`sparse_newton`]: `y = [q, v, z]`, `q_dot = v`, accelerations `A Q + b` with `A`
    /// the constrained-acceleration operator of a mass matrix and constraint rows), or
    /// `None` (the default): the Newton matrix is then dense. Asked once per run.
    fn newton_structure(&self) -> Option<NewtonStructure> {
        None
    }

    /// The values of the parts of [`Self::newton_structure`] at (t, y), called where
    /// [`Self::jacobian`] would be; returns what it cost, or `None` when the parts do not
    /// describe the Jacobian at this state (the dense Jacobian is then formed).
    fn jacobian_parts(&mut self, _t: f64, _y: &[f64], _floors: &[f64], _parts: &mut NewtonParts) -> Result<Option<JacobianCost>, SimulationError> {
        Ok(None)
    }

    /// Number of event functions (default 0).
    fn n_events(&self) -> usize {
        0
    }

    /// Event functions g_k(t, y); event k fires when g_k rises through zero:
    /// g_k(t_prev) <= 0 < g_k(t_new).
    fn event_functions(&mut self, _t: f64, _y: &[f64], _g: &mut [f64]) {}

    /// Event functions g_k(t, y) into `g` and their time derivatives dg_k/dt
    /// into `rates` [unit of g per s]; returns whether the rates are known.
    ///
    /// With rates at both ends of a step the driver skips the interior
    /// sampling of a step in which no event function can plausibly cross
    /// zero (`docs/theory/integrator-events.md`). The default fills `g` only
    /// and returns false: rates unknown, every step is sampled inside.
    fn event_functions_and_rates(&mut self, t: f64, y: &[f64], g: &mut [f64], _rates: &mut [f64]) -> bool {
        self.event_functions(t, y, g);
        false
    }

    /// Called with the state at the located time t* of the earliest event
    /// (y from dense output at t*), before `accept()`; may update discrete state and y.
    fn on_event(&mut self, _t: f64, _y: &mut [f64], _event: usize) -> Result<(), SimulationError> {
        Ok(())
    }

    /// Projects a trial step end onto the system's invariants before the
    /// method evaluates f there (Dormand-Prince's last stage, whose
    /// derivative becomes the next step's first); the default does nothing.
    ///
    /// On success y is the projected state; on failure y must be left as it
    /// was. The method then evaluates the unprojected state, and `accept()`
    /// projects it again and reports the failure should the step be accepted.
    fn project(&mut self, _t: f64, _y: &mut [f64]) -> Result<(), SimulationError> {
        Ok(())
    }

    /// Called at the end of every accepted step (after event handling) with
    /// the new state; may project y onto constraints and update discrete state.
    ///
    /// Returns true when the change to y or to the discrete state is a
    /// discontinuity that requires the integrator to restart (re-evaluate f,
    /// drop history); false when y changed at most by a correction at
    /// tolerance level (the integrator may keep its FSAL derivative / history).
    /// By default the state is kept as it is (a system without constraints or discrete state).
    fn accept(&mut self, _t: f64, _y: &mut [f64]) -> Result<bool, SimulationError> {
        Ok(false)
    }

    /// Records an output sample at time t (state from dense output or step end).
    /// Err aborts the run (e.g. Interrupted).
    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError>;

    /// Called once per accepted step, after `accept()` and the samples of the
    /// step, with the step's interval [t_old, t_new] [s], the accepted state y at
    /// t_new and the step's continuous extension: `dense(t, out)` writes the
    /// state at any t in [t_old, t_new] into `out` (length `len()`).
    ///
    /// Lets the system track quantities at every step whatever the output
    /// sampling (peaks, time in contact). The default does nothing.
    fn observe_step(&mut self, _t_old: f64, _t_new: f64, _y: &[f64], _dense: &mut dyn FnMut(f64, &mut [f64])) -> Result<(), SimulationError> {
        Ok(())
    }
}

/// One method's step, as the shared driver sees it.
pub(crate) trait Stepper {
    /// (Re)starts at (t, y): evaluates f there, drops history and returns the step to try,
    /// `h_hint` [s] being the caller's proposal (`None` at the very start).
    fn start<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
        h_hint: Option<f64>,
    ) -> Result<f64, SimulationError>;

    /// Attempts a step of size h from (t, y); the new state is kept in the stepper.
    fn attempt<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
        h: f64,
    ) -> Result<Attempt, SimulationError>;

    /// State at the end of the last accepted attempt.
    fn y_new(&self) -> &[f64];

    /// Whether the driver cuts the steps to end on the output times, so that no sample
    /// comes from the continuous extension (default: no, samples are interpolated).
    fn steps_end_on_samples(&self) -> bool {
        false
    }

    /// Makes the continuous extension of the last accepted step ready for [`Stepper::dense`];
    /// the driver calls it before the first `dense` of a step (a method may form its
    /// extension only then, since most steps never use it).
    fn prepare_dense(&mut self) {}

    /// State at time t inside the last accepted step, from the continuous extension
    /// (after [`Stepper::prepare_dense`]).
    fn dense(&self, t: f64, out: &mut [f64]);

    /// Continues after an accepted step without restart; y is the state after `accept()`.
    fn advance<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
    ) -> Result<(), SimulationError>;
}

/// Outcome of one step attempt.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Attempt {
    /// Whether the error estimate passed.
    pub accepted: bool,
    /// Step to try next [s].
    pub h_next: f64,
}

/// Integrates from t0 to t_end (y0 updated in place to the final state).
///
/// `record()` is called at t0, at every output time in (t0, t_end) and at
/// t_end exactly. On error, returns the error and the statistics so far;
/// whatever `record()` stored stays with the system. Options that fail
/// [`IntegratorOptions::validate`], `t_end < t0`, non-finite times or a
/// state whose length differs from `system.len()` are reported as
/// `InvalidInput` naming the problem.
pub fn integrate<S: OdeSystem>(
    system: &mut S,
    t0: f64,
    t_end: f64,
    y: &mut [f64],
    options: &IntegratorOptions,
) -> (Statistics, Result<(), SimulationError>) {
    let mut stats = Statistics::default();
    if let Err(problem) = check_input(system, t0, t_end, y, options) {
        return (stats, Err(SimulationError::InvalidInput { time: t0, message: problem }));
    }
    let n = y.len();
    let result = match options.method {
        Method::DormandPrince45 => {
            let mut stepper = dormand_prince::DormandPrince::new(n, options, control::Tolerances::new(system, options));
            driver::run(system, &mut stepper, t0, t_end, y, options, &mut stats)
        }
        Method::AdamsPredictorCorrector => {
            let mut stepper = adams::Adams::new(n, options, control::Tolerances::new(system, options));
            driver::run(system, &mut stepper, t0, t_end, y, options, &mut stats)
        }
        Method::NumericalDifferentiation => {
            let mut stepper = bdf::Ndf::new(n, options, control::Tolerances::new(system, options));
            stepper.matrix.use_system_jacobian = use_system_jacobian(options, system);
            driver::run(system, &mut stepper, t0, t_end, y, options, &mut stats)
        }
        Method::GeneralizedAlpha => {
            let mut stepper = generalized_alpha::GeneralizedAlpha::new(n, system.second_order_positions(), options, control::Tolerances::new(system, options));
            stepper.matrix.use_system_jacobian = use_system_jacobian(options, system);
            driver::run(system, &mut stepper, t0, t_end, y, options, &mut stats)
        }
    };
    (stats, result)
}

/// Whether an implicit method takes the system's own Jacobian (else forward differences).
fn use_system_jacobian<S: OdeSystem>(options: &IntegratorOptions, system: &S) -> bool {
    match (options.jacobian, system.system_jacobian()) {
        (JacobianMethod::FiniteDifference, _) | (_, SystemJacobian::Unavailable) => false,
        (JacobianMethod::Structured, _) | (JacobianMethod::Auto, SystemJacobian::Preferred) => true,
        (JacobianMethod::Auto, SystemJacobian::Available) => false,
    }
}

/// Problems with the arguments of [`integrate`], if any.
fn check_input<S: OdeSystem>(
    system: &S,
    t0: f64,
    t_end: f64,
    y: &[f64],
    options: &IntegratorOptions,
) -> Result<(), String> {
    options.validate()?;
    if !(t0.is_finite() && t_end.is_finite()) {
        return Err(format!("t0 and t_end must be finite, got {t0:e} and {t_end:e}"));
    }
    if t_end < t0 {
        return Err(format!("t_end must be >= t0, got {t_end:e} < {t0:e}"));
    }
    if y.len() != system.len() {
        return Err(format!("state has {} components, system.len() is {}", y.len(), system.len()));
    }
    Ok(())
}
