//! Running a simulation: options, diagnostics, and the outcome that keeps
//! whatever was computed even when the run fails.

use crate::dynamics::model::channels::ChannelRead;
use crate::dynamics::outputs::trajectory::{SampleSink, Trajectory};
use crate::dynamics::formulations::absolute::equations::{update_frames, Stabilization};
use crate::dynamics::formulations::formulation_choice::{choose_formulation, FormulationChoice};
use crate::dynamics::formulations::joint_coordinates::{self, Formulation, JointTree};
use crate::dynamics::outputs::extrema::ExtremaTracker;
use crate::joint::SpatialClearanceRevolute;
use crate::kinematics::marker::Marker;
use crate::dynamics::outputs::extrema_summary::{is_peak_unit, Extrema, JointToSummarize};
use super::system::{MechanismSystem, StepEndCache, Tracking};
use crate::dynamics::model::mechanism::Model;
use super::progress::Progress;
use crate::dynamics::model::state::State;
use crate::dynamics::formulations::workspace::Workspace;
use crate::error::SimulationError;
use crate::element::{ElementMemory, ElementWork};
use crate::integrate::{integrate, IntegratorOptions, Method, Statistics};

/// Options of one simulation.
#[derive(Clone, Debug, PartialEq)]
pub struct SimulationOptions {
    /// Integrator, tolerances, step limits and output sampling.
    pub integrator: IntegratorOptions,
    /// Drift control.
    pub stabilization: Stabilization,
    /// Largest constraint residual left by the projection [m or rad], and of
    /// the velocity constraints [m/s or rad/s]; `None`: follow the integrator's
    /// tolerances ([`SimulationOptions::projection_tolerance`]).
    pub position_tolerance: Option<f64>,
    /// Form of the equations of motion (`Auto`: by the measured rule of [`choose_formulation`]).
    pub formulation: Formulation,
    /// Largest output allowed, samples x channels x 8 [bytes]; `None`: no limit.
    /// The run stops with [`SimulationError::OutputBudgetExceeded`] before exceeding it.
    pub max_output_bytes: Option<u64>,
}

/// Largest projection tolerance that follows the integrator's tolerances [m or rad]:
/// far below clearances of 1 um; a looser atol does not loosen it (a projection
/// costs one or two Newton iterations whatever its tolerance).
pub const PROJECTION_CEILING: f64 = 1e-10;

/// Projection tolerance as a share of atol: what a projection moves the state by
/// stays a tenth of what the step control allows. At the atol itself the moves
/// near a singular position reach the error estimate, and the steps collapse or the
/// linkage changes branch (measured on the parallelogram four-bar through its flat
/// position, `docs/theory/planar-formulation.md`, "Projection tolerance").
pub const PROJECTION_SHARE: f64 = 0.1;

/// Smallest projection tolerance [m or rad]: about 50 round-offs of coordinates
/// of order 1 m, below which Newton on the constraints stalls in rounding.
pub const PROJECTION_FLOOR: f64 = 1e-14;

impl SimulationOptions {
    /// The projection tolerance [m or rad] used: `position_tolerance` when given, else
    /// [`PROJECTION_SHARE`] times atol (times rtol x 1 m when atol is 0: coordinates of
    /// order 1 m), at most [`PROJECTION_CEILING`] and at least [`PROJECTION_FLOOR`].
    /// (The default atol 1e-9 gives 1e-10, the fixed value of the earlier engine.)
    pub fn projection_tolerance(&self) -> f64 {
        if let Some(tolerance) = self.position_tolerance {
            return tolerance;
        }
        let IntegratorOptions { atol, rtol, .. } = self.integrator;
        let reference = if atol > 0.0 { atol } else { rtol };
        (PROJECTION_SHARE * reference).min(PROJECTION_CEILING).max(PROJECTION_FLOOR)
    }
}

impl Default for SimulationOptions {
    /// Dormand-Prince at rtol 1e-6, atol 1e-9; the projection tolerance follows
    /// atol ([`SimulationOptions::projection_tolerance`]: 1e-10 here).
    fn default() -> Self {
        Self {
            integrator: IntegratorOptions::default(),
            stabilization: Stabilization::Projection,
            position_tolerance: None,
            formulation: Formulation::Auto,
            max_output_bytes: None,
        }
    }
}

/// Run-time observations that are not errors (MuJoCo-style warnings counted, not thrown).
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostics {
    /// Deepest penetration seen at an accepted step [m].
    pub max_penetration: f64,
    /// Accepted steps at which some penetration exceeded 10 % of its clearance.
    pub deep_penetration_steps: usize,
    /// Most Newton iterations one projection needed.
    pub max_projection_iterations: usize,
    /// Largest constraint residual a projection after a step left [m or rad]: at most the
    /// projection tolerance, except at a singular position, where Newton may stall above it.
    pub max_projection_residual: f64,
    /// Time of that projection [s] (NaN without one).
    pub max_projection_residual_time: f64,
    /// The projection tolerance of the run [m or rad] ([`SimulationOptions::projection_tolerance`]).
    pub projection_tolerance: f64,
    /// Contact onsets per clearance joint.
    pub impacts: Vec<usize>,
}

impl Default for Diagnostics {
    fn default() -> Self {
        Self {
            max_penetration: 0.0,
            deep_penetration_steps: 0,
            max_projection_iterations: 0,
            max_projection_residual: 0.0,
            max_projection_residual_time: f64::NAN,
            projection_tolerance: 0.0,
            impacts: Vec::new(),
        }
    }
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
    /// Peaks, contact statistics and film extrema from every accepted step
    /// (up to the failure when the run failed).
    pub extrema: Extrema,
    /// Why the run stopped early, if it did.
    pub error: Option<SimulationError>,
    /// The form of the equations that was integrated (`Absolute` or `JointCoordinates`).
    pub formulation: Formulation,
    /// Why that form, in one line ([`FormulationChoice::reason`]).
    pub formulation_reason: String,
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
/// about [`crate::dynamics::outputs::trajectory::CHUNK_BYTES`] while the run goes on, and at its end (also
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
    // every long loop of the run (a Reynolds solve included) answers the progress's cancel
    match progress {
        Some(progress) => progress.scope(|| run(model, state, t_end, options, Some(progress), sink)),
        None => run(model, state, t_end, options, None, sink),
    }
}

/// [`simulate_with_sink`] inside the progress's scope.
fn run(
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
    let mut diagnostics = Diagnostics { projection_tolerance: options.projection_tolerance(), ..Diagnostics::default() };
    let t0 = state.time;
    let (tree, choice) = match joint_tree(model, options.formulation, t0) {
        Ok(chosen) => chosen,
        Err(error) => {
            let tracking = new_tracking(model, 0);
            let extrema = summarize(model, &tracking.tracker, &tracking.channels, &model.initial_memory());
            let formulation_reason = error.to_string();
            return SimulationOutcome { trajectory, statistics: Statistics::default(), diagnostics, extrema, error: Some(error), formulation: options.formulation, formulation_reason };
        }
    };
    ws.joint.active = tree.is_some();
    let mut y = match tree {
        Some(tree) => joint_state(model, tree, &state.y, &mut ws),
        None => state.y.clone(),
    };
    ws.sample.resize(y.len(), 0.0);
    let mut tracking = new_tracking(model, y.len());
    // generalized-alpha's states inside a step interpolate its step ends: the forces of a stiff
    // element there amplify the interpolation error, so its peaks come from the step ends
    tracking.tracker.channels.step_ends_only = options.integrator.method == Method::GeneralizedAlpha;
    let (statistics, result, last_accepted) = {
        let mut system = MechanismSystem {
            model,
            memory: &mut state.memory,
            ws: &mut ws,
            trajectory: &mut trajectory,
            diagnostics: &mut diagnostics,
            options,
            progress,
            last_accepted: f64::NAN,
            step_end: StepEndCache::new(y.len()),
            tracking: &mut tracking,
            tree,
        };
        let (statistics, result) = match system.accept_elements(t0, &y) {
            Ok(_) => integrate(&mut system, t0, t_end, &mut y, &options.integrator),
            Err(e) => (Statistics::default(), Err(e)),
        };
        (statistics, result, system.last_accepted)
    };
    // what was computed goes to the sink, also after a failure
    let result = result.and(trajectory.finish());
    // the state of the last accepted step: time and coordinates of one instant, also after a failure
    if !last_accepted.is_nan() {
        state.time = last_accepted;
        match tree {
            Some(tree) => {
                joint_coordinates::place(model, tree, last_accepted, &tracking.accepted_state, &mut ws);
                state.y.copy_from_slice(&ws.joint.body_state);
            }
            None => state.y = tracking.accepted_state,
        }
    }
    diagnostics.impacts = model.clearance_joints().map(|(k, _, _)| model.impacts(k, &state.memory)).collect();
    let extrema = summarize(model, &tracking.tracker, &tracking.channels, &state.memory);
    // a cancelled run stops wherever a loop saw it (a Reynolds solve says "interrupted"): say why it stopped
    let cancelled = progress.is_some_and(Progress::is_cancelled);
    let error = result.err().map(|e| match cancelled {
        true => SimulationError::Interrupted { time: if last_accepted.is_nan() { t0 } else { last_accepted } },
        false => name_likely_cause(model, e, &ws),
    });
    let error = error.map(|e| super::singular_diagnosis::diagnose_toggle(model, e, t0, state.time, state.coordinates(), &mut ws));
    SimulationOutcome { trajectory, statistics, diagnostics, extrema, error, formulation: choice.formulation, formulation_reason: choice.reason }
}

/// The formulation `formulation` resolves to ([`choose_formulation`]) with the joint tree to
/// integrate in when it is joint coordinates.
fn joint_tree(model: &Model, formulation: Formulation, t0: f64) -> Result<(Option<&JointTree>, FormulationChoice), SimulationError> {
    let choice = choose_formulation(model, formulation).map_err(|why| SimulationError::InvalidInput {
        time: t0,
        message: format!("the joint-coordinate formulation needs a tree of ideal joints, but {why}; use the absolute formulation"),
    })?;
    let tree = match (choice.formulation, &model.joint_tree) {
        (Formulation::JointCoordinates, Ok(tree)) => Some(tree),
        _ => None,
    };
    Ok((tree, choice))
}

/// The joint state `[theta, theta_dot, z]` of the (assembled) body-space state `y`.
fn joint_state(model: &Model, tree: &JointTree, y: &[f64], ws: &mut Workspace) -> Vec<f64> {
    let (q, v, z) = model.layout.split(y);
    update_frames(model, q, v, &mut ws.frames, &mut ws.spatial_frames);
    let n = tree.n_dofs;
    let mut joint = vec![0.0; 2 * n + z.len()];
    let (theta, rest) = joint.split_at_mut(n);
    let (theta_dot, zj) = rest.split_at_mut(n);
    tree.joint_state(&ws.frames, theta, theta_dot);
    zj.copy_from_slice(z);
    joint
}

/// The tracker of the channels with a unit in [`crate::dynamics::outputs::extrema_summary::PEAK_UNITS`], of the
/// acceleration of every named point of a moving body and of every event function
/// (a clearance joint's gap).
fn new_tracking(model: &Model, len: usize) -> Tracking {
    let channels: Vec<usize> = (0..model.channels.len()).filter(|&c| is_peak_unit(model.channels[c].info.unit)).collect();
    let points: Vec<Marker> = model.points.iter().filter(|p| !p.1.body.is_ground()).map(|p| p.1).collect();
    Tracking {
        tracker: ExtremaTracker::new(channels.len() + points.len(), model.n_events()),
        reads: ChannelRead::plan(model, channels.iter().map(|&c| model.channels[c].source)),
        channels,
        points,
        state: vec![0.0; len],
        accepted_state: vec![0.0; len],
    }
}

/// The tracked summary with the names of its channels and joints (`memory`: every element's at the end).
fn summarize(model: &Model, tracker: &ExtremaTracker, channels: &[usize], memory: &[ElementMemory]) -> Extrema {
    let points = model.points.iter().filter(|p| !p.1.body.is_ground()).map(|p| (p.0.clone(), "m/s^2"));
    let names: Vec<(String, &'static str)> =
        channels.iter().map(|&c| (model.channels[c].info.name.clone(), model.channels[c].info.unit)).chain(points).collect();
    // (a clearance joint's one event function is its gap; a spatial one's first two are its bore halves')
    let planar = model.clearance_joints().map(|(k, name, joint)| JointToSummarize {
        name: name.to_string(),
        events: model.event_offsets[k]..model.event_offsets[k] + 1,
        impacts: model.impacts(k, memory),
        lubricated: joint.lubrication.is_some(),
        clearance: joint.clearance,
        modes: None,
    });
    let spatial = model.spatial_clearance_joints().map(|(k, name, joint)| JointToSummarize {
        name: name.to_string(),
        events: model.event_offsets[k]..model.event_offsets[k] + 2,
        impacts: model.impacts(k, memory),
        lubricated: false,
        clearance: joint.geometry.radial_clearance(),
        modes: SpatialClearanceRevolute::mode_times(&memory[model.memory_of(k)]),
    });
    let joints: Vec<JointToSummarize> = planar.chain(spatial).collect();
    let mut extrema = tracker.summary(&names, channels.len(), &joints);
    for joint in extrema.clearance_joints.iter_mut().filter(|j| j.min_film.is_some()) {
        let pressure = format!("{}.peak_pressure", joint.name);
        joint.peak_film_pressure = extrema.channels.iter().find(|c| c.name == pressure).map(|c| (c.peak, c.time));
    }
    extrema
}

/// A step-size underflow names the clearance joint with the deepest relative penetration, if any is in contact.
fn name_likely_cause(model: &Model, error: SimulationError, ws: &Workspace) -> SimulationError {
    match error {
        SimulationError::StepSizeUnderflow { time, step, element: None } => {
            let element = model
                .clearance_joints()
                .filter_map(|(k, name, _)| match &ws.element_work[k] {
                    ElementWork::Clearance(work) if work.contact.in_contact => Some((name, work.contact.penetration)),
                    _ => None,
                })
                .max_by(|a, b| a.1.total_cmp(&b.1))
                .map(|(name, _)| format!("contact in {name}"));
            SimulationError::StepSizeUnderflow { time, step, element }
        }
        other => other,
    }
}

#[cfg(test)]
#[path = "simulate_tests.rs"]
mod tests;
