//! Running a simulation: options, diagnostics, and the outcome that keeps
//! whatever was computed even when the run fails.

use super::trajectory::{SampleSink, Trajectory};
use super::equations::Stabilization;
use super::system::{MechanismSystem, StepEndCache};
use super::{Model, Progress, State, Workspace};
use crate::error::SimulationError;
use crate::integrate::{integrate, IntegratorOptions, Statistics};

/// Options of one simulation.
#[derive(Clone, Debug, PartialEq)]
pub struct SimulationOptions {
    /// Integrator, tolerances, step limits and output sampling.
    pub integrator: IntegratorOptions,
    /// Drift control.
    pub stabilization: Stabilization,
    /// Largest constraint residual left by the projection [m or rad], and of
    /// the velocity constraints [m/s or rad/s].
    pub position_tolerance: f64,
    /// Largest output allowed, samples x channels x 8 [bytes]; `None`: no limit.
    /// The run stops with [`SimulationError::OutputBudgetExceeded`] before exceeding it.
    pub max_output_bytes: Option<u64>,
}

impl Default for SimulationOptions {
    /// Dormand-Prince at rtol 1e-6, atol 1e-9; projection to 1e-10, far
    /// below clearances of 1 um and above the round-off of coordinates of order 1 m.
    fn default() -> Self {
        Self {
            integrator: IntegratorOptions::default(),
            stabilization: Stabilization::Projection,
            position_tolerance: 1e-10,
            max_output_bytes: None,
        }
    }
}

/// Run-time observations that are not errors (MuJoCo-style warnings counted, not thrown).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Diagnostics {
    /// Deepest penetration seen at an accepted step [m].
    pub max_penetration: f64,
    /// Accepted steps at which some penetration exceeded 10 % of its clearance.
    pub deep_penetration_steps: usize,
    /// Most Newton iterations one projection needed.
    pub max_projection_iterations: usize,
    /// Contact onsets per clearance joint.
    pub impacts: Vec<usize>,
}

/// What a simulation returns, successful or not.
#[derive(Clone, Debug)]
pub struct SimulationOutcome {
    /// Recorded channels up to where the run stopped.
    pub trajectory: Trajectory,
    /// Integrator statistics.
    pub statistics: Statistics,
    /// Diagnostics.
    pub diagnostics: Diagnostics,
    /// Why the run stopped early, if it did.
    pub error: Option<SimulationError>,
}

/// Integrates `model` from `state` to `t_end` [s]; `state` is advanced in place.
/// Every sample is kept in the returned trajectory.
pub fn simulate(
    model: &Model,
    state: &mut State,
    t_end: f64,
    options: &SimulationOptions,
    progress: Option<&Progress>,
) -> SimulationOutcome {
    simulate_with_sink(model, state, t_end, options, progress, None)
}

/// As [`simulate`], handing the samples to `sink` (when given) in chunks of
/// about [`super::CHUNK_BYTES`] while the run goes on, and at its end (also
/// when it fails); the returned trajectory then holds no samples. A sink
/// error stops the run with [`SimulationError::OutputSink`].
pub fn simulate_with_sink(
    model: &Model,
    state: &mut State,
    t_end: f64,
    options: &SimulationOptions,
    progress: Option<&Progress>,
    sink: Option<Box<dyn SampleSink>>,
) -> SimulationOutcome {
    let mut ws = Workspace::new(model);
    let mut trajectory = Trajectory::new(model);
    trajectory.set_max_bytes(options.max_output_bytes);
    if let Some(sink) = sink {
        trajectory.set_sink(sink);
    }
    let mut diagnostics = Diagnostics::default();
    let t0 = state.time;
    let mut y = state.y.clone();
    let (statistics, result) = {
        let mut system = MechanismSystem {
            model,
            memory: &mut state.contacts,
            ws: &mut ws,
            trajectory: &mut trajectory,
            diagnostics: &mut diagnostics,
            options,
            progress,
            last_accepted: f64::NAN,
            step_end: StepEndCache::new(y.len()),
        };
        match system.update_contact_memory(t0, &y) {
            Ok(_) => integrate(&mut system, t0, t_end, &mut y, &options.integrator),
            Err(e) => (Statistics::default(), Err(e)),
        }
    };
    // what was computed goes to the sink, also after a failure
    let finished = trajectory.finish();
    let result = result.and(finished);
    state.y = y;
    state.time = trajectory.last_time().unwrap_or(t0);
    diagnostics.impacts = state.contacts.iter().map(|c| c.impacts).collect();
    let error = result.err().map(|e| name_likely_cause(model, e, &ws));
    SimulationOutcome { trajectory, statistics, diagnostics, error }
}

/// A step-size underflow names the clearance joint with the deepest relative penetration, if any is in contact.
fn name_likely_cause(model: &Model, error: SimulationError, ws: &Workspace) -> SimulationError {
    match error {
        SimulationError::StepSizeUnderflow { time, step, element: None } => {
            let element = ws
                .contacts
                .iter()
                .enumerate()
                .filter(|(_, c)| c.in_contact)
                .max_by(|a, b| a.1.penetration.total_cmp(&b.1.penetration))
                .map(|(k, _)| format!("contact in {}", model.clearance_names[k]));
            SimulationError::StepSizeUnderflow { time, step, element }
        }
        other => other,
    }
}
