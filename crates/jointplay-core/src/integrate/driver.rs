//! The step loop shared by every method: step limits, output sampling,
//! event handling, `accept()` and restarts.

use super::events::{find_first_event, step_needs_scan, EventBuffers};
use super::{IntegratorOptions, OdeSystem, Statistics, Stepper};
use crate::error::SimulationError;

/// Fraction of a step the last step may stretch to land on t_end (Hairer's 1.01).
const LAST_STEP_STRETCH: f64 = 1.01;
/// A step is not cut to end on a sample closer than this fraction of it (an event
/// just before a sample time): that sample comes from the continuous extension.
const SAMPLE_CUT_FLOOR: f64 = 1e-3;
/// Grid samples closer than this fraction of the spacing to t_end merge into the t_end sample.
const OUTPUT_MERGE: f64 = 1e-6;

/// Integrates from t0 to t_end with `stepper`; y holds the final state.
pub(crate) fn run<S: OdeSystem, P: Stepper>(
    system: &mut S,
    stepper: &mut P,
    t0: f64,
    t_end: f64,
    y: &mut [f64],
    opts: &IntegratorOptions,
    stats: &mut Statistics,
) -> Result<(), SimulationError> {
    let mut events = EventBuffers::new(system.n_events(), y.len());
    let mut grid = OutputGrid::new(t0, t_end, opts.output_step);
    check_state(t0, y)?;
    system.record(t0, y)?;
    if t_end == t0 {
        return Ok(());
    }
    events.evaluate_at_step_start(system, t0, y);
    let mut h = stepper.start(system, stats, t0, y, opts.initial_step)?;
    let mut t = t0;
    while t < t_end {
        // limit the step, stretch or clip the last one onto t_end (and, for a method
        // whose samples are its step ends, the step onto the next output time)
        h = h.min(opts.max_step);
        let last = t + LAST_STEP_STRETCH * h >= t_end;
        let to_sample = !last && stepper.steps_end_on_samples() && t + LAST_STEP_STRETCH * h >= grid.next
            && grid.next - t > SAMPLE_CUT_FLOOR * h;
        let h_try = if last { t_end - t } else if to_sample { grid.next - t } else { h };
        if (!last && h_try < opts.min_step) || t + h_try == t {
            return Err(SimulationError::StepSizeUnderflow { time: t, step: h_try, element: None });
        }
        if stats.accepted_steps + stats.rejected_steps >= opts.max_steps {
            return Err(SimulationError::TooManySteps { time: t, max_steps: opts.max_steps });
        }
        let attempt = stepper.attempt(system, stats, t, y, h_try)?;
        h = attempt.h_next;
        if !attempt.accepted {
            stats.rejected_steps += 1;
            continue;
        }
        stats.count_accepted(h_try);
        let t_new = if last { t_end } else if to_sample { grid.next } else { t + h_try };
        let (t_stop, restart) = finish_step(system, stepper, stats, &mut events, &mut grid, t, t_new, y)?;
        t = t_stop;
        // restart after an event or a discontinuity reported by accept()
        if restart {
            stats.restarts += 1;
            h = stepper.start(system, stats, t, y, Some(h))?;
        } else {
            stepper.advance(system, stats, t, y)?;
        }
    }
    Ok(())
}

/// Handles an accepted step from t_old to t_new: events, outputs, `on_event`,
/// `accept()`. Leaves the state in y; returns the time reached and whether to restart.
#[allow(clippy::too_many_arguments)]
fn finish_step<S: OdeSystem, P: Stepper>(
    system: &mut S,
    stepper: &mut P,
    stats: &mut Statistics,
    events: &mut EventBuffers,
    grid: &mut OutputGrid,
    t_old: f64,
    t_new: f64,
    y: &mut [f64],
) -> Result<(f64, bool), SimulationError> {
    // earliest event in the step, if any
    let mut event_time = None;
    if !events.g_old.is_empty() && step_needs_scan(system, stepper.y_new(), t_old, t_new, events) {
        stepper.prepare_dense();
        let dense = |t: f64, out: &mut [f64]| stepper.dense(t, out);
        event_time = find_first_event(system, dense, t_old, t_new, events);
    }
    let t_stop = event_time.unwrap_or(t_new);
    // samples strictly inside the step, from the dense output
    grid.record_inside(system, stepper, t_stop, &mut events.y_tmp)?;
    // state at the stop time, event handling, accept
    let mut restart = false;
    match event_time {
        Some(t_star) => {
            stepper.dense(t_star, y);
            restart = fire_events(system, stats, events, t_star, y)?;
        }
        None => y.copy_from_slice(stepper.y_new()),
    }
    restart |= system.accept(t_stop, y)?;
    check_state(t_stop, y)?;
    grid.record_at_stop(system, t_stop, y)?;
    // the step as a whole, for quantities tracked at every step
    let mut dense = |t: f64, out: &mut [f64]| {
        stepper.prepare_dense();
        stepper.dense(t, out);
    };
    system.observe_step(t_old, t_stop, y, &mut dense)?;
    if event_time.is_none() && !events.g_old.is_empty() && y == stepper.y_new() {
        // the scan ended at this very state: its values start the next step
        events.carry_step_end_over();
    } else {
        events.evaluate_at_step_start(system, t_stop, y);
    }
    Ok((t_stop, restart))
}

/// Calls `on_event` for every event that has fired by t* (state in y); true when one did.
fn fire_events<S: OdeSystem>(
    system: &mut S,
    stats: &mut Statistics,
    events: &mut EventBuffers,
    t_star: f64,
    y: &mut [f64],
) -> Result<bool, SimulationError> {
    system.event_functions(t_star, y, &mut events.g_tmp);
    let mut fired = false;
    for k in 0..events.g_old.len() {
        if events.fires_at_tmp(k) {
            system.on_event(t_star, y, k)?;
            stats.events += 1;
            fired = true;
        }
    }
    Ok(fired)
}

/// NonFinite when the state holds NaN or infinity.
fn check_state(t: f64, y: &[f64]) -> Result<(), SimulationError> {
    if y.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(SimulationError::NonFinite { time: t, element: "state".to_string() })
    }
}

/// Output times t0 + i * dt in (t0, t_end), then t_end; or every step end.
struct OutputGrid {
    /// Start time [s].
    t0: f64,
    /// End time [s].
    t_end: f64,
    /// Sample spacing [s], `None` for a sample per accepted step.
    spacing: Option<f64>,
    /// Index of the next grid sample.
    index: u64,
    /// Time of the next grid sample [s]; infinity when the grid is exhausted.
    next: f64,
}

impl OutputGrid {
    /// Grid starting after t0.
    fn new(t0: f64, t_end: f64, spacing: Option<f64>) -> Self {
        let mut grid = Self { t0, t_end, spacing, index: 0, next: f64::INFINITY };
        grid.advance();
        grid
    }

    /// Moves to the next grid time (exactly t0 + i dt), or to infinity past the end.
    fn advance(&mut self) {
        self.next = f64::INFINITY;
        if let Some(dt) = self.spacing {
            self.index += 1;
            let t = self.t0 + self.index as f64 * dt;
            if t < self.t_end - OUTPUT_MERGE * dt {
                self.next = t;
            }
        }
    }

    /// Records grid samples strictly before t_stop from the dense output.
    fn record_inside<S: OdeSystem, P: Stepper>(
        &mut self,
        system: &mut S,
        stepper: &mut P,
        t_stop: f64,
        buffer: &mut [f64],
    ) -> Result<(), SimulationError> {
        while self.next < t_stop {
            stepper.prepare_dense();
            stepper.dense(self.next, buffer);
            system.record(self.next, buffer)?;
            self.advance();
        }
        Ok(())
    }

    /// Records the state at the end of a step when it is a grid time, t_end, or every step.
    fn record_at_stop<S: OdeSystem>(&mut self, system: &mut S, t_stop: f64, y: &[f64]) -> Result<(), SimulationError> {
        let on_grid = self.next == t_stop;
        if on_grid {
            self.advance();
        }
        if on_grid || self.spacing.is_none() || t_stop == self.t_end {
            system.record(t_stop, y)?;
        }
        Ok(())
    }
}
