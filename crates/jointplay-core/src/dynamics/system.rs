//! The mechanism as an ODE system for the integrators: the right-hand side,
//! contact-onset events, latching of the onset velocity, drift projection
//! after each accepted step, and recording of the channels.

use super::channels::{update_constraint_forces, value};
use super::extrema::{ExtremaTracker, StepProbe};
use super::trajectory::Trajectory;
use super::equations::{accelerations, update_frames, Stabilization};
use super::joint_coordinates::{self, joint_accelerations, JointTree};
use super::frame::{BodyIndex, Vec2};
use super::projection::{project_positions, project_velocities};
use super::simulate::{Diagnostics, SimulationOptions};
use super::state::ContactMemory;
use super::{Model, Progress, Workspace};
use crate::error::SimulationError;
use crate::integrate::OdeSystem;
use crate::joint::Lubrication;

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
    /// Summary quantities tracked at every accepted step.
    pub tracking: &'a mut Tracking,
    /// The tree whose joint coordinates are integrated, `y = [theta, theta_dot, z]`;
    /// `None`: absolute coordinates, `y = [q, v, z]`.
    pub tree: Option<&'a JointTree>,
}

/// The tracker of summary quantities with what it reads.
pub(crate) struct Tracking {
    /// Peaks, gaps and contact time.
    pub tracker: ExtremaTracker,
    /// Indices into `Model::channels` of the tracked channels.
    pub channels: Vec<usize>,
    /// Named body points whose acceleration magnitude is tracked after the channels: body and body-frame point [m].
    pub points: Vec<(BodyIndex, Vec2)>,
    /// State from the dense output at a time inside a step.
    pub state: Vec<f64>,
    /// State after the last accepted step (`[q, q_dot]`), at `MechanismSystem::last_accepted`.
    pub accepted_state: Vec<f64>,
}

/// The last evaluated and the last projected state, so that the sample at a
/// step end reuses the integrator's evaluation there instead of repeating
/// it, and `accept()` does not project a state projected already.
pub(crate) struct StepEndCache {
    /// Time [s] of the evaluation whose results the workspace holds, if it still does.
    evaluated_at: Option<f64>,
    /// State of that evaluation.
    evaluated_state: Vec<f64>,
    /// Whether that evaluation computed the outputs only samples need (`Workspace::detailed`).
    evaluated_detailed: bool,
    /// Time [s] of the last state `project()` returned.
    projected_at: Option<f64>,
    /// That state.
    projected_state: Vec<f64>,
}

impl StepEndCache {
    /// Empty cache for a state of `len` components.
    pub(crate) fn new(len: usize) -> Self {
        Self { evaluated_at: None, evaluated_state: vec![0.0; len], evaluated_detailed: false, projected_at: None, projected_state: vec![0.0; len] }
    }

    /// The workspace holds the evaluation at (t, y), `detailed` or not.
    fn remember_evaluation(&mut self, t: f64, y: &[f64], detailed: bool) {
        self.evaluated_state.copy_from_slice(y);
        self.evaluated_at = Some(t);
        self.evaluated_detailed = detailed;
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
        if !self.step_end.holds_evaluation(t, y) {
            // (the frames of the evaluation at this very state are already there)
            self.place_frames(t, y);
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

    /// Checks that every element's accepted state is within the range of its law
    /// (the frames are those of `y`: [`Self::update_contact_memory`] made them).
    fn check_elements(&self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        let z = self.element_states(y);
        for (k, element) in self.model.forces.iter().enumerate() {
            if let Err(cause) = element.check(&self.ws.frames, &z[self.model.layout.force_states[k].clone()]) {
                return Err(SimulationError::ElementOutOfRange { time: t, element: self.model.force_names[k].clone(), cause });
            }
        }
        Ok(())
    }

    /// Projects positions and velocities of y onto the constraints at t (the
    /// workspace no longer holds the last evaluation afterwards).
    fn project_state(&mut self, t: f64, y: &mut [f64]) -> Result<(), SimulationError> {
        if self.tree.is_some() {
            return Ok(()); // joint coordinates satisfy the joints by construction
        }
        self.step_end.evaluated_at = None;
        let m = self.model.n_dynamic_constraints;
        let (q, qdot, _) = self.model.layout.split_mut(y);
        let iterations = project_positions(self.model, m, t, q, self.options.position_tolerance, PROJECTION_ITERATIONS, self.ws)?;
        self.diagnostics.max_projection_iterations = self.diagnostics.max_projection_iterations.max(iterations);
        project_velocities(self.model, m, t, q, qdot, self.options.position_tolerance, self.ws)
    }
}

impl MechanismSystem<'_> {
    /// Frames of all bodies at `(t, y)` into the workspace (in joint coordinates
    /// also the body-space state); the workspace no longer holds an evaluation.
    fn place_frames(&mut self, t: f64, y: &[f64]) {
        self.step_end.evaluated_at = None;
        match self.tree {
            Some(tree) => joint_coordinates::place(self.model, tree, t, y, self.ws),
            None => {
                let (q, v, _) = self.model.layout.split(y);
                update_frames(self.model, q, v, &mut self.ws.frames);
            }
        }
    }

    /// The continuous element states `z` of `y`.
    fn element_states<'y>(&self, y: &'y [f64]) -> &'y [f64] {
        match self.tree {
            Some(tree) => &y[2 * tree.n_dofs..],
            None => self.model.layout.split(y).2,
        }
    }

    /// Evaluates the accelerations at `(t, y)` in the formulation being integrated.
    fn evaluate(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        match self.tree {
            Some(tree) => joint_accelerations(self.model, tree, self.memory, t, y, self.ws),
            None => accelerations(self.model, self.memory, t, y, self.options.stabilization, self.ws),
        }
    }

    /// Records the sample at `(t, y)` from the evaluation the workspace holds there
    /// (in joint coordinates, with the body-space state of that evaluation).
    fn push_sample(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        if self.tree.is_none() {
            return self.trajectory.push(self.model, t, y, self.ws);
        }
        let body = std::mem::take(&mut self.ws.joint.body_state);
        let pushed = self.trajectory.push(self.model, t, &body, self.ws);
        self.ws.joint.body_state = body;
        pushed
    }

    /// Frames of the bodies of the clearance joints from the state y (the
    /// only frames the event functions read), in their own buffer so that
    /// the workspace keeps the last evaluation.
    fn update_clearance_frames(&mut self, t: f64, y: &[f64]) {
        if let Some(tree) = self.tree {
            let n = tree.n_dofs;
            tree.place(t, &y[..n], &y[n..2 * n], &mut self.ws.event_frames);
            return;
        }
        let (q, v, _) = self.model.layout.split(y);
        for joint in &self.model.clearance_joints {
            for body in [joint.bearing.body, joint.journal.body] {
                if let Some(address) = self.model.layout.body(body) {
                    // (at a step end the evaluation there has the same angle)
                    let kind = &self.model.bodies[body.0 - 1].kind;
                    self.ws.event_frames[body.0] = kind.frame(&q[address.q_range()], &v[address.v_range()], &self.ws.frames[body.0]);
                }
            }
        }
    }
}

impl OdeSystem for MechanismSystem<'_> {
    fn len(&self) -> usize {
        match self.tree {
            Some(tree) => 2 * tree.n_dofs + self.model.layout.nz,
            None => self.model.layout.len(),
        }
    }

    fn rhs(&mut self, t: f64, y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError> {
        // the state of the evaluation the workspace still holds (a sample just recorded
        // there, or a restart at the state just evaluated): reuse it
        if !self.step_end.holds_evaluation(t, y) {
            self.step_end.evaluated_at = None;
            self.evaluate(t, y)?;
        }
        if let Some(tree) = self.tree {
            let n = tree.n_dofs;
            dydt[..n].copy_from_slice(&y[n..2 * n]);
            dydt[n..2 * n].copy_from_slice(&self.ws.joint.accelerations);
            dydt[2 * n..].copy_from_slice(&self.ws.element_state_rates);
            if self.step_end.evaluated_at.is_none() {
                self.step_end.remember_evaluation(t, y, false);
            }
            return Ok(());
        }
        let layout = &self.model.layout;
        let (q, v, _) = layout.split(y);
        let (qdot, vdot, zdot) = layout.split_mut(dydt);
        if layout.identity_position_rates {
            qdot.copy_from_slice(v);
        } else {
            for (body, address) in self.model.bodies.iter().zip(&layout.bodies) {
                body.kind.position_rates(&q[address.q_range()], &v[address.v_range()], &mut qdot[address.q_range()]);
            }
        }
        vdot.copy_from_slice(&self.ws.accelerations);
        zdot.copy_from_slice(&self.ws.element_state_rates);
        if self.step_end.evaluated_at.is_none() {
            self.step_end.remember_evaluation(t, y, false);
        }
        Ok(())
    }

    fn absolute_tolerance_scales(&self, scales: &mut [f64]) {
        let layout = &self.model.layout;
        if let Some(tree) = self.tree {
            // joint angles [rad] and displacements [m] as the bodies' coordinates
            let (joint, z) = scales.split_at_mut(2 * tree.n_dofs);
            joint.fill(1.0);
            for (element, states) in self.model.forces.iter().zip(&layout.force_states) {
                element.tolerance_scales(&mut z[states.clone()]);
            }
            return;
        }
        let (q, v, _) = layout.split_mut(scales);
        for (body, address) in self.model.bodies.iter().zip(&layout.bodies) {
            body.kind.tolerance_scales(&mut q[address.q_range()], &mut v[address.v_range()]);
        }
        let (_, _, z) = layout.split_mut(scales);
        for (element, states) in self.model.forces.iter().zip(&layout.force_states) {
            element.tolerance_scales(&mut z[states.clone()]);
        }
    }

    fn n_events(&self) -> usize {
        self.model.clearance_joints.len()
    }

    fn event_functions(&mut self, t: f64, y: &[f64], g: &mut [f64]) {
        self.update_clearance_frames(t, y);
        for (k, joint) in self.model.clearance_joints.iter().enumerate() {
            g[k] = joint.penetration(&self.ws.event_frames);
        }
    }

    fn event_functions_and_rates(&mut self, t: f64, y: &[f64], g: &mut [f64], rates: &mut [f64]) -> bool {
        self.update_clearance_frames(t, y);
        for (k, joint) in self.model.clearance_joints.iter().enumerate() {
            g[k] = joint.penetration(&self.ws.event_frames);
            rates[k] = joint.penetration_rate(&self.ws.event_frames);
        }
        true
    }

    fn on_event(&mut self, t: f64, y: &mut [f64], event: usize) -> Result<(), SimulationError> {
        self.place_frames(t, y);
        let joint = &self.model.clearance_joints[event];
        self.memory[event].onset_velocity = Some(joint.onset_velocity(&self.ws.frames));
        self.memory[event].impacts += 1;
        Ok(())
    }

    fn project(&mut self, t: f64, y: &mut [f64]) -> Result<(), SimulationError> {
        if self.options.stabilization != Stabilization::Projection || self.tree.is_some() {
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
        self.check_elements(t, y)?;
        self.last_accepted = t;
        self.tracking.accepted_state.copy_from_slice(y);
        Ok(false)
    }

    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        if self.step_end.holds_evaluation(t, y) && !self.model.has_lubricated_joints() {
            // the step end the integrator just evaluated (and projected): record its evaluation
            self.check_elements(t, y)?;
            self.push_sample(t, y)?;
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

    fn observe_step(&mut self, t_old: f64, t_new: f64, y: &[f64], dense: &mut dyn FnMut(f64, &mut [f64])) -> Result<(), SimulationError> {
        self.track_step(t_old, t_new, y, dense)
    }
}

impl MechanismSystem<'_> {
    /// Evaluates the sample at (t, y) with the outputs only samples need and records it.
    fn evaluate_and_push(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        self.evaluate_sample(t, y)?;
        let sample = std::mem::take(&mut self.ws.sample);
        // a sample inside the step where an element left its range is not recorded: the error stops there
        let pushed = self.check_elements(t, &sample).and_then(|()| self.push_sample(t, &sample));
        self.ws.sample = sample;
        pushed
    }

    /// Evaluates (t, y) with the outputs only samples need; the workspace then
    /// holds the evaluation and `ws.sample` the state it was made at.
    fn evaluate_sample(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        self.step_end.evaluated_at = None;
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
            evaluated = self.evaluate(t, &sample);
            self.ws.detailed = false;
        }
        if evaluated.is_ok() {
            self.step_end.remember_evaluation(t, &sample, true);
        }
        self.ws.sample = sample;
        evaluated
    }

    /// Completes the evaluation the workspace holds with the film outputs only
    /// samples need (the peak pressure), re-evaluating just the films.
    fn detail_films(&mut self, t: f64) -> Result<(), SimulationError> {
        let ws = &mut *self.ws;
        for (k, joint) in self.model.clearance_joints.iter().enumerate() {
            let Some(lubrication) = &joint.lubrication else { continue };
            let (fi, fj) = (&ws.frames[joint.bearing.body.0], &ws.frames[joint.journal.body.0]);
            let kinematics = Lubrication::kinematics(fi, fj, fi.point(joint.bearing.local), fj.point(joint.journal.local));
            let film = lubrication.evaluate(&kinematics, ws.film_solvers[k].as_mut(), true);
            ws.films[k] = film.map_err(|cause| SimulationError::FilmModel { time: t, element: self.model.clearance_names[k].clone(), cause })?;
        }
        self.step_end.evaluated_detailed = true;
        Ok(())
    }

    /// Tracked channel values, then point acceleration magnitudes [m/s^2], from
    /// the evaluation the workspace holds at `state`.
    fn tracked_values(&mut self, state: &[f64], values: &mut [f64]) {
        update_constraint_forces(self.model, self.ws);
        let ws = &*self.ws;
        // (in joint coordinates the evaluation's body-space state)
        let state = if self.tree.is_some() { &ws.joint.body_state[..] } else { state };
        let (channels, points) = values.split_at_mut(self.tracking.channels.len());
        for (v, &c) in channels.iter_mut().zip(&self.tracking.channels) {
            // (tracked channels read forces and accelerations, never the energy)
            *v = value(self.model, self.model.channels[c].source, state, ws, [f64::NAN; 2]);
        }
        for (v, &(body, local)) in points.iter_mut().zip(&self.tracking.points) {
            *v = point_acceleration(self.model, ws, body, local);
        }
    }
}

/// The system seen by the extrema tracker during one accepted step.
struct SystemProbe<'s, 'a, 'd> {
    system: &'s mut MechanismSystem<'a>,
    /// End of the step [s].
    t_new: f64,
    /// Accepted state at its end.
    y_new: &'s [f64],
    /// The step's dense output.
    dense: &'d mut dyn FnMut(f64, &mut [f64]),
}

impl StepProbe for SystemProbe<'_, '_, '_> {
    fn channels_at(&mut self, t: f64, values: &mut [f64]) -> Result<(), SimulationError> {
        let system = &mut *self.system;
        if t == self.t_new {
            // the step end: reuse its evaluation when the workspace holds it with the needed outputs
            if !system.step_end.holds_evaluation(t, self.y_new) {
                system.evaluate_sample(t, self.y_new)?;
            } else if system.model.has_lubricated_joints() && !system.step_end.evaluated_detailed {
                system.detail_films(t)?;
            }
            system.tracked_values(self.y_new, values);
        } else {
            let mut state = std::mem::take(&mut system.tracking.state);
            (self.dense)(t, &mut state);
            let evaluated = system.evaluate_sample(t, &state);
            system.tracking.state = state;
            evaluated?;
            let sample = std::mem::take(&mut system.ws.sample);
            system.tracked_values(&sample, values);
            system.ws.sample = sample;
        }
        Ok(())
    }

    fn gaps_at(&mut self, t: f64, gaps: &mut [f64]) {
        let system = &mut *self.system;
        if t == self.t_new {
            system.event_functions(t, self.y_new, gaps);
        } else {
            let mut state = std::mem::take(&mut system.tracking.state);
            (self.dense)(t, &mut state);
            system.event_functions(t, &state, gaps);
            system.tracking.state = state;
        }
    }
}

impl MechanismSystem<'_> {
    /// Observes an accepted step for the summary (see [`OdeSystem::observe_step`]).
    fn track_step(&mut self, t_old: f64, t_new: f64, y: &[f64], dense: &mut dyn FnMut(f64, &mut [f64])) -> Result<(), SimulationError> {
        let mut tracker = std::mem::take(&mut self.tracking.tracker);
        let mut probe = SystemProbe { system: self, t_new, y_new: y, dense };
        let mut observed = Ok(());
        if tracker.t_start.is_nan() {
            observed = tracker.begin(&mut probe, t_old);
        }
        if observed.is_ok() {
            observed = tracker.observe(&mut probe, t_old, t_new);
        }
        self.tracking.tracker = tracker;
        observed
    }
}

/// Acceleration magnitude [m/s^2] of the marker point `local` [m] (body frame)
/// of a moving body from an evaluated workspace.
fn point_acceleration(model: &Model, ws: &Workspace, body: BodyIndex, local: Vec2) -> f64 {
    let Some(address) = model.layout.body(body) else { return 0.0 };
    let kind = &model.bodies[body.0 - 1].kind;
    kind.marker_acceleration(&ws.frames[body.0], &ws.accelerations[address.v_range()], local).norm()
}
