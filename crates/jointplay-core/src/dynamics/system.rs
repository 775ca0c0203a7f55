//! The mechanism as an ODE system for the integrators: the right-hand side,
//! contact-onset events, latching of the onset velocity, drift projection
//! after each accepted step, and recording of the channels.

use super::channels::Trajectory;
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
}

impl MechanismSystem<'_> {
    /// Latches or clears the onset velocity from the accepted state and checks the penetration bound.
    pub(crate) fn update_contact_memory(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        let n = self.model.n_coordinates();
        update_frames(self.model, &y[..n], &y[n..], &mut self.ws.frames);
        for (k, joint) in self.model.clearance_joints.iter().enumerate() {
            let penetration = joint.penetration(&self.ws.frames);
            let memory = &mut self.memory[k];
            if penetration <= 0.0 {
                memory.onset_velocity = None;
                continue;
            }
            if memory.onset_velocity.is_none() {
                // contact present without a located onset (start in contact, or re-contact inside one step)
                memory.onset_velocity = Some(joint.onset_velocity(&self.ws.frames));
                memory.impacts += 1;
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
        Ok(())
    }
}

impl MechanismSystem<'_> {
    /// Frames of the bodies of the clearance joints from the state y (the
    /// only frames the event functions read).
    fn update_clearance_frames(&mut self, y: &[f64]) {
        let n = self.model.n_coordinates();
        for joint in &self.model.clearance_joints {
            for body in [joint.bearing.body, joint.journal.body] {
                if let Some(c) = body.coordinate() {
                    self.ws.frames[body.0] = Frame::from_coordinates(&y[c..c + 3], &y[n + c..n + c + 3]);
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
        accelerations(self.model, self.memory, t, &y[..n], &y[n..], self.options.stabilization, self.ws)?;
        dydt[..n].copy_from_slice(&y[n..]);
        dydt[n..].copy_from_slice(&self.ws.accelerations);
        Ok(())
    }

    fn n_events(&self) -> usize {
        self.model.clearance_joints.len()
    }

    fn event_functions(&mut self, _t: f64, y: &[f64], g: &mut [f64]) {
        self.update_clearance_frames(y);
        for (k, joint) in self.model.clearance_joints.iter().enumerate() {
            g[k] = joint.penetration(&self.ws.frames);
        }
    }

    fn event_functions_and_rates(&mut self, _t: f64, y: &[f64], g: &mut [f64], rates: &mut [f64]) -> bool {
        self.update_clearance_frames(y);
        for (k, joint) in self.model.clearance_joints.iter().enumerate() {
            g[k] = joint.penetration(&self.ws.frames);
            rates[k] = joint.penetration_rate(&self.ws.frames);
        }
        true
    }

    fn on_event(&mut self, _t: f64, y: &mut [f64], event: usize) -> Result<(), SimulationError> {
        let n = self.model.n_coordinates();
        update_frames(self.model, &y[..n], &y[n..], &mut self.ws.frames);
        let joint = &self.model.clearance_joints[event];
        self.memory[event].onset_velocity = Some(joint.onset_velocity(&self.ws.frames));
        self.memory[event].impacts += 1;
        Ok(())
    }

    fn accept(&mut self, t: f64, y: &mut [f64]) -> Result<bool, SimulationError> {
        if self.options.stabilization == Stabilization::Projection {
            let n = self.model.n_coordinates();
            let m = self.model.n_dynamic_constraints;
            let (q, qdot) = y.split_at_mut(n);
            let iterations = project_positions(self.model, m, t, q, self.options.position_tolerance, PROJECTION_ITERATIONS, self.ws)?;
            self.diagnostics.max_projection_iterations = self.diagnostics.max_projection_iterations.max(iterations);
            project_velocities(self.model, m, t, q, qdot, self.options.position_tolerance, self.ws)?;
        }
        self.update_contact_memory(t, y)?;
        self.last_accepted = t;
        Ok(false)
    }

    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        let n = self.model.n_coordinates();
        // samples between steps come from dense output: project them like the steps
        // (a sample at the step just accepted was projected by accept())
        let mut sample = std::mem::take(&mut self.ws.sample);
        sample.copy_from_slice(y);
        if self.options.stabilization == Stabilization::Projection && t != self.last_accepted {
            let m = self.model.n_dynamic_constraints;
            let (q, qdot) = sample.split_at_mut(n);
            project_positions(self.model, m, t, q, self.options.position_tolerance, PROJECTION_ITERATIONS, self.ws)?;
            project_velocities(self.model, m, t, q, qdot, self.options.position_tolerance, self.ws)?;
        }
        self.ws.detailed = true;
        let evaluated = accelerations(self.model, self.memory, t, &sample[..n], &sample[n..], self.options.stabilization, self.ws);
        self.ws.detailed = false;
        if evaluated.is_ok() {
            self.trajectory.push(self.model, t, &sample, self.ws);
        }
        self.ws.sample = sample;
        evaluated?;
        if let Some(progress) = self.progress {
            progress.report(t);
            if progress.is_cancelled() {
                return Err(SimulationError::Interrupted { time: t });
            }
        }
        Ok(())
    }
}
