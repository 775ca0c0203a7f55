//! The mechanism as an ODE system for the integrators: the right-hand side,
//! contact-onset events, latching of the onset velocity, drift projection
//! after each accepted step, and recording of the channels.

use super::trajectory::Trajectory;
use super::equations::{accelerations, update_frames, Stabilization};
use super::frame::Frame;
use super::projection::{project_positions, project_velocities};
use super::simulate::{Diagnostics, SimulationOptions};
use super::state::ContactMemory;
use super::{Model, Progress, Workspace};
use crate::error::SimulationError;
use crate::integrate::OdeSystem;

/// Newton iterations allowed when projecting after a step: the drift of one
/// step is at the level of the integration tolerance, so one or two suffice.
const PROJECTION_ITERATIONS: usize = 8;

/// A penetration deeper than this fraction of the clearance is counted in
/// the diagnostics (a hint that the contact is soft for the clearance).
const DEEP_PENETRATION_FRACTION: f64 = 0.1;

pub(crate) struct MechanismSystem<'a> {
    pub model: &'a Model,
    pub memory: &'a mut [ContactMemory],
    pub ws: &'a mut Workspace,
    pub trajectory: &'a mut Trajectory,
    pub diagnostics: &'a mut Diagnostics,
    pub options: &'a SimulationOptions,
    pub progress: Option<&'a Progress>,
    /// Time of the last accepted (and projected) step end [s].
    pub last_accepted: f64,
    /// What the workspace holds: the state of the last successful `rhs()`
    /// and of the last `project()`; a step-end sample reuses them.
    pub step_end: StepEndCache,
}

/// The last evaluated and the last projected state, so that the sample at a
/// step end reuses the integrator's evaluation there instead of repeating
/// it, and `accept()` does not project a state projected already.
pub(crate) struct StepEndCache {
    /// Time [s] of the evaluation whose results the workspace holds, if it still does.
    evaluated_at: Option<f64>,
    /// State of that evaluation.
    evaluated_state: Vec<f64>,
    /// Time [s] of the last state `project()` returned.
    projected_at: Option<f64>,
    /// That state.
    projected_state: Vec<f64>,
}

impl StepEndCache {
    /// Empty cache for a state of `len` components.
    pub(crate) fn new(len: usize) -> Self {
        Self { evaluated_at: None, evaluated_state: vec![0.0; len], projected_at: None, projected_state: vec![0.0; len] }
    }

    /// The workspace holds the evaluation at (t, y).
    fn remember_evaluation(&mut self, t: f64, y: &[f64]) {
        self.evaluated_state.copy_from_slice(y);
        self.evaluated_at = Some(t);
    }

    /// Whether the workspace holds the evaluation at exactly (t, y).
    fn holds_evaluation(&self, t: f64, y: &[f64]) -> bool {
        self.evaluated_at == Some(t) && self.evaluated_state == y
    }

    /// Whether (t, y) is exactly the last projected state.
    fn holds_projection(&self, t: f64, y: &[f64]) -> bool {
        self.projected_at == Some(t) && self.projected_state == y
    }
}

impl MechanismSystem<'_> {
    /// Latches or clears the onset velocity from the accepted state and checks
    /// the penetration bound; true when some onset velocity was latched or cleared.
    pub(crate) fn update_contact_memory(&mut self, t: f64, y: &[f64]) -> Result<bool, SimulationError> {
        let n = self.model.n_coordinates();
        if !self.step_end.holds_evaluation(t, y) {
            // (the frames of the evaluation at this very state are already there)
            update_frames(self.model, &y[..n], &y[n..], &mut self.ws.frames);
        }
        let mut changed = false;
        for (k, joint) in self.model.clearance_joints.iter().enumerate() {
            let penetration = joint.penetration(&self.ws.frames);
            let memory = &mut self.memory[k];
            if penetration <= 0.0 {
                changed |= memory.onset_velocity.take().is_some();
                continue;
            }
            if memory.onset_velocity.is_none() {
                // contact present without a located onset (start in contact, or re-contact inside one step)
                memory.onset_velocity = Some(joint.onset_velocity(&self.ws.frames));
                memory.impacts += 1;
                changed = true;
            }
            self.diagnostics.max_penetration = self.diagnostics.max_penetration.max(penetration);
            if penetration > DEEP_PENETRATION_FRACTION * joint.clearance {
                self.diagnostics.deep_penetration_steps += 1;
            }
            if penetration > joint.max_penetration {
                return Err(SimulationError::ExcessivePenetration {
                    time: t,
                    element: self.model.clearance_names[k].clone(),
                    penetration,
                    bound: joint.max_penetration,
                });
            }
        }
        Ok(changed)
    }

    /// Projects positions and velocities of y onto the constraints at t (the
    /// workspace no longer holds the last evaluation afterwards).
    fn project_state(&mut self, t: f64, y: &mut [f64]) -> Result<(), SimulationError> {
        self.step_end.evaluated_at = None;
        let n = self.model.n_coordinates();
        let m = self.model.n_dynamic_constraints;
        let (q, qdot) = y.split_at_mut(n);
        let iterations = project_positions(self.model, m, t, q, self.options.position_tolerance, PROJECTION_ITERATIONS, self.ws)?;
        self.diagnostics.max_projection_iterations = self.diagnostics.max_projection_iterations.max(iterations);
        project_velocities(self.model, m, t, q, qdot, self.options.position_tolerance, self.ws)
    }
}

impl MechanismSystem<'_> {
    /// Frames of the bodies of the clearance joints from the state y (the
    /// only frames the event functions read), in their own buffer so that
    /// the workspace keeps the last evaluation.
    fn update_clearance_frames(&mut self, y: &[f64]) {
        let n = self.model.n_coordinates();
        for joint in &self.model.clearance_joints {
            for body in [joint.bearing.body, joint.journal.body] {
                if let Some(c) = body.coordinate() {
                    // (at a step end the evaluation there has the same angle)
                    self.ws.event_frames[body.0] = Frame::from_coordinates_after(&self.ws.frames[body.0], &y[c..c + 3], &y[n + c..n + c + 3]);
                }
            }
        }
    }
}

impl OdeSystem for MechanismSystem<'_> {
    fn len(&self) -> usize {
        2 * self.model.n_coordinates()
    }

    fn rhs(&mut self, t: f64, y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError> {
        let n = self.model.n_coordinates();
        // the state of the evaluation the workspace still holds (a sample just recorded
        // there, or a restart at the state just evaluated): reuse it
        if !self.step_end.holds_evaluation(t, y) {
            self.step_end.evaluated_at = None;
            accelerations(self.model, self.memory, t, &y[..n], &y[n..], self.options.stabilization, self.ws)?;
        }
        dydt[..n].copy_from_slice(&y[n..]);
        dydt[n..].copy_from_slice(&self.ws.accelerations);
        self.step_end.remember_evaluation(t, y);
        Ok(())
    }

    fn n_events(&self) -> usize {
        self.model.clearance_joints.len()
    }

    fn event_functions(&mut self, _t: f64, y: &[f64], g: &mut [f64]) {
        self.update_clearance_frames(y);
        for (k, joint) in self.model.clearance_joints.iter().enumerate() {
            g[k] = joint.penetration(&self.ws.event_frames);
        }
    }

    fn event_functions_and_rates(&mut self, _t: f64, y: &[f64], g: &mut [f64], rates: &mut [f64]) -> bool {
        self.update_clearance_frames(y);
        for (k, joint) in self.model.clearance_joints.iter().enumerate() {
            g[k] = joint.penetration(&self.ws.event_frames);
            rates[k] = joint.penetration_rate(&self.ws.event_frames);
        }
        true
    }

    fn on_event(&mut self, _t: f64, y: &mut [f64], event: usize) -> Result<(), SimulationError> {
        self.step_end.evaluated_at = None;
        let n = self.model.n_coordinates();
        update_frames(self.model, &y[..n], &y[n..], &mut self.ws.frames);
        let joint = &self.model.clearance_joints[event];
        self.memory[event].onset_velocity = Some(joint.onset_velocity(&self.ws.frames));
        self.memory[event].impacts += 1;
        Ok(())
    }

    fn project(&mut self, t: f64, y: &mut [f64]) -> Result<(), SimulationError> {
        if self.options.stabilization != Stabilization::Projection {
            return Ok(());
        }
        // project a copy: y stays as it was should the projection fail
        let mut state = std::mem::take(&mut self.step_end.projected_state);
        state.copy_from_slice(y);
        self.step_end.projected_at = None;
        let projected = self.project_state(t, &mut state);
        if projected.is_ok() {
            y.copy_from_slice(&state);
            self.step_end.projected_at = Some(t);
        }
        self.step_end.projected_state = state;
        projected
    }

    fn accept(&mut self, t: f64, y: &mut [f64]) -> Result<bool, SimulationError> {
        if self.options.stabilization == Stabilization::Projection && !self.step_end.holds_projection(t, y) {
            self.project_state(t, y)?;
        }
        if self.update_contact_memory(t, y)? {
            // the contact law reads the latched onset velocity: the evaluation no longer holds
            self.step_end.evaluated_at = None;
        }
        self.last_accepted = t;
        Ok(false)
    }

    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        if self.step_end.holds_evaluation(t, y) && !self.model.has_lubricated_joints() {
            // the step end the integrator just evaluated (and projected): record its evaluation
            self.trajectory.push(self.model, t, y, self.ws)?;
        } else {
            self.evaluate_and_push(t, y)?;
        }
        if let Some(progress) = self.progress {
            progress.report(t);
            if progress.is_cancelled() {
                return Err(SimulationError::Interrupted { time: t });
            }
        }
        Ok(())
    }
}

impl MechanismSystem<'_> {
    /// Evaluates the sample at (t, y) with the outputs only samples need and records it.
    fn evaluate_and_push(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        let n = self.model.n_coordinates();
        // samples between steps come from dense output: project them like the steps
        // (a sample at the step just accepted was projected by accept())
        let mut sample = std::mem::take(&mut self.ws.sample);
        sample.copy_from_slice(y);
        let mut evaluated = Ok(());
        if self.options.stabilization == Stabilization::Projection && t != self.last_accepted {
            evaluated = self.project_state(t, &mut sample);
        }
        if evaluated.is_ok() {
            self.ws.detailed = true;
            evaluated = accelerations(self.model, self.memory, t, &sample[..n], &sample[n..], self.options.stabilization, self.ws);
            self.ws.detailed = false;
        }
        if evaluated.is_ok() {
            evaluated = self.trajectory.push(self.model, t, &sample, self.ws);
            self.step_end.remember_evaluation(t, &sample);
        }
        self.ws.sample = sample;
        evaluated
    }
}
