//! The mechanism as an ODE system for the integrators: the right-hand side,
//! the elements' events and their discrete memory at accepted steps (a
//! clearance joint's contact onset and latched onset velocity), drift
//! projection after each accepted step, and recording of the channels.

use crate::dynamics::outputs::channel_values::read_channels;
use crate::dynamics::model::channels::ChannelRead;
use crate::dynamics::outputs::extrema::{ExtremaTracker, StepProbe};
use crate::dynamics::outputs::trajectory::Trajectory;
use crate::dynamics::formulations::absolute::equations::{accelerations, update_frames, Stabilization};
use crate::dynamics::formulations::joint_coordinates::{self, joint_accelerations, JointTree};
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::{Marker, Site};
use crate::dynamics::formulations::absolute::jacobian::StructuredJacobian;
use crate::dynamics::formulations::absolute::newton_parts;
use crate::dynamics::formulations::absolute::projection::{project_positions, project_velocities};
use super::simulate::{Diagnostics, SimulationOptions};
use crate::dynamics::model::mechanism::Model;
use super::progress::Progress;
use crate::dynamics::formulations::workspace::Workspace;
use crate::error::SimulationError;
use crate::element::{ElementFault, ElementMemory, ElementModel};
use crate::body::{BodyKind, BodyModel};
use crate::integrate::{JacobianCost, NewtonParts, NewtonStructure, OdeSystem, SystemJacobian};

/// Newton iterations allowed when projecting after a step: the drift of one
/// step is at the level of the integration tolerance, so one or two suffice.
const PROJECTION_ITERATIONS: usize = 8;

pub(crate) struct MechanismSystem<'a> {
    pub model: &'a Model,
    /// Discrete memory of every force element.
    pub memory: &'a mut [ElementMemory],
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
    /// How an evaluation reads them.
    pub reads: Vec<ChannelRead>,
    /// Named body points whose acceleration magnitude is tracked after the channels.
    pub points: Vec<Marker>,
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

/// Every body's positions moved back to valid ones (unit quaternions).
fn normalise_positions(model: &Model, q: &mut [f64]) {
    for (body, address) in model.bodies.iter().zip(&model.layout.bodies) {
        body.kind.normalise_positions(&mut q[address.q_range()]);
    }
}

impl MechanismSystem<'_> {
    /// Lets every element update its discrete memory at the accepted state (a clearance
    /// joint latches or clears its onset velocity) and check its bounds; true when some memory changed.
    pub(crate) fn accept_elements(&mut self, t: f64, y: &[f64]) -> Result<bool, SimulationError> {
        if !self.step_end.holds_evaluation(t, y) {
            // (the frames of the evaluation at this very state are already there)
            self.place_frames(t, y);
        }
        let mut changed = false;
        for &k in &self.model.acting {
            let element = &self.model.elements[k];
            let frames = Frames { planar: &self.ws.frames, spatial: &self.ws.spatial_frames };
            let acceptance = match element.kind.accept(&frames, t, &mut self.memory[self.model.memory_of(k)]) {
                Ok(acceptance) => acceptance,
                Err(fault) => {
                    if let ElementFault::ExcessivePenetration { penetration, .. } = fault {
                        self.diagnostics.max_penetration = self.diagnostics.max_penetration.max(penetration);
                    }
                    return Err(fault.at(t, &element.name));
                }
            };
            changed |= acceptance.memory_changed;
            self.diagnostics.max_penetration = self.diagnostics.max_penetration.max(acceptance.penetration);
            self.diagnostics.deep_penetration_steps += usize::from(acceptance.deep_penetration);
        }
        Ok(changed)
    }

    /// Checks that every element's accepted state is within the range of its law
    /// (the frames are those of `y`: [`Self::accept_elements`] made them).
    fn check_elements(&self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        let z = self.element_states(y);
        for &k in &self.model.acting {
            let element = &self.model.elements[k];
            element.kind.check(&self.ws.frames(), &z[self.model.layout.element_states[k].clone()]).map_err(|fault| fault.at(t, &element.name))?;
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
        let tolerance = self.diagnostics.projection_tolerance;
        let (iterations, residual) = project_positions(self.model, m, t, q, tolerance, PROJECTION_ITERATIONS, self.ws)?;
        let diagnostics = &mut *self.diagnostics;
        diagnostics.max_projection_iterations = diagnostics.max_projection_iterations.max(iterations);
        if residual > diagnostics.max_projection_residual {
            diagnostics.max_projection_residual = residual;
            diagnostics.max_projection_residual_time = t;
        }
        project_velocities(self.model, m, t, q, qdot, tolerance, self.ws)
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
                update_frames(self.model, q, v, &mut self.ws.frames, &mut self.ws.spatial_frames);
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
    /// The constraint linearisation and factor at (t, y) that a Jacobian is formed at: the
    /// integrator's evaluation there, normally, else one made now; the evaluations made (0 or 1).
    fn evaluation_at(&mut self, t: f64, y: &[f64]) -> Result<usize, SimulationError> {
        if self.step_end.holds_evaluation(t, y) {
            return Ok(0);
        }
        self.step_end.evaluated_at = None;
        self.evaluate(t, y)?;
        self.step_end.remember_evaluation(t, y, false);
        Ok(1)
    }

    fn push_sample(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        let Some(tree) = self.tree else {
            return self.trajectory.push(self.model, t, y, self.ws);
        };
        let mut body = std::mem::take(&mut self.ws.joint.body_state);
        tree.body_state(self.model, &self.ws.frames, &y[2 * tree.n_dofs..], &mut body);
        let pushed = self.trajectory.push(self.model, t, &body, self.ws);
        self.ws.joint.body_state = body;
        pushed
    }

    /// Frames of the bodies the event functions read from the state y, in
    /// their own buffer so that the workspace keeps the last evaluation.
    fn update_event_frames(&mut self, t: f64, y: &[f64]) {
        if self.step_end.holds_evaluation(t, y) {
            // (the evaluation at this very state, a step end, placed them all)
            self.ws.event_frames.copy_from_slice(&self.ws.frames);
            self.ws.event_spatial_frames.copy_from_slice(&self.ws.spatial_frames);
            return;
        }
        if let Some(tree) = self.tree {
            let n = tree.n_dofs;
            tree.place(t, &y[..n], &y[n..2 * n], &mut self.ws.event_frames);
            return;
        }
        let (q, v, _) = self.model.layout.split(y);
        for &body in &self.model.event_bodies {
            if let Some(address) = self.model.layout.body(body) {
                // (at a step end the evaluation there has the same angle)
                let kind = &self.model.bodies[body.0 - 1].kind;
                self.ws.event_frames[body.0] = kind.frame(&q[address.q_range()], &v[address.v_range()], &self.ws.frames[body.0]);
            }
        }
        // (the sections of flexible bodies: few, each from its own coordinates)
        let first = 1 + self.model.bodies.len();
        for (k, section) in self.model.sections.iter().enumerate() {
            self.ws.event_frames[first + k] = self.model.section_frame(section, q, v, &self.ws.frames[first + k]);
        }
        if self.model.spatial {
            self.update_spatial_event_frames(q, v);
        }
    }

    /// The spatial frames of the bodies the event functions read and of the
    /// sections, from their planar event frames (a model with spatial elements).
    fn update_spatial_event_frames(&mut self, q: &[f64], v: &[f64]) {
        let ws = &mut *self.ws;
        for &body in &self.model.event_bodies {
            if let Some(address) = self.model.layout.body(body) {
                let kind = &self.model.bodies[body.0 - 1].kind;
                ws.event_spatial_frames[body.0] = kind.spatial_site_frame(&Site::Reference, &q[address.q_range()], &v[address.v_range()], &ws.event_frames[body.0]);
            }
        }
        let first = 1 + self.model.bodies.len();
        for (k, section) in self.model.sections.iter().enumerate() {
            let address = &self.model.layout.bodies[section.body.0 - 1];
            let kind = &self.model.bodies[section.body.0 - 1].kind;
            ws.event_spatial_frames[first + k] = kind.spatial_site_frame(&section.site, &q[address.q_range()], &v[address.v_range()], &ws.event_frames[first + k]);
        }
    }

    /// Event functions (and their rates, when asked) of every element at the event frames.
    fn element_event_functions(&self, g: &mut [f64], mut rates: Option<&mut [f64]>) {
        let frames = Frames { planar: &self.ws.event_frames, spatial: &self.ws.event_spatial_frames };
        for &k in &self.model.acting {
            let events = self.model.events_of(k);
            if !events.is_empty() {
                self.model.elements[k].kind.event_functions(&frames, &mut g[events.clone()], rates.as_deref_mut().map(|r| &mut r[events]));
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
            // a cancel is answered at the next evaluation, not at the next sample, which
            // may be many steps away
            if self.progress.is_some_and(|progress| !progress.poll()) {
                return Err(SimulationError::Interrupted { time: self.last_accepted });
            }
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

    fn second_order_positions(&self) -> usize {
        match self.tree {
            Some(tree) => tree.n_dofs,
            None if self.model.layout.identity_position_rates => self.model.layout.nq,
            None => 0,
        }
    }

    fn system_jacobian(&self) -> SystemJacobian {
        // (the joint-coordinate formulation keeps forward differences)
        if self.tree.is_some() || !self.model.layout.identity_position_rates {
            SystemJacobian::Unavailable
        } else if self.model.bodies.iter().any(|b| matches!(b.kind, BodyKind::Beam(_))) {
            // (a beam's many coordinates make it pay; without one the model is small, and
            // forward differences keep the constraints' geometric stiffness the structured
            // Jacobian neglects, which the Newton iterations of a modal mechanism need)
            SystemJacobian::Preferred
        } else {
            SystemJacobian::Available
        }
    }

    fn jacobian(&mut self, t: f64, y: &[f64], floors: &[f64], jacobian: &mut [f64]) -> Result<Option<JacobianCost>, SimulationError> {
        if self.system_jacobian() == SystemJacobian::Unavailable {
            return Ok(None);
        }
        let mut cost = JacobianCost::default();
        cost.rhs_evaluations += self.evaluation_at(t, y)?;
        let mut structured = self.ws.structured_jacobian.take().unwrap_or_else(|| Box::new(StructuredJacobian::new(self.model)));
        let filled = structured.fill(self.model, self.memory, t, y, floors, self.ws, jacobian).and_then(|passes| {
            cost.force_evaluations = passes;
            structured.difference_whole_columns(y, floors, jacobian, |y, f| self.rhs(t, y, f))
        });
        self.ws.structured_jacobian = Some(structured);
        cost.rhs_evaluations += filled?;
        Ok(Some(cost))
    }

    fn newton_structure(&self) -> Option<NewtonStructure> {
        if self.system_jacobian() == SystemJacobian::Unavailable {
            return None;
        }
        newton_parts::structure(self.model, &StructuredJacobian::new(self.model))
    }

    fn jacobian_parts(&mut self, t: f64, y: &[f64], floors: &[f64], parts: &mut NewtonParts) -> Result<Option<JacobianCost>, SimulationError> {
        let mut cost = JacobianCost::default();
        cost.rhs_evaluations += self.evaluation_at(t, y)?;
        if !newton_parts::fill_constraint(self.model, self.ws, &mut parts.constraint) {
            return Ok(None);
        }
        newton_parts::fill_mass(self.model, &mut parts.mass);
        let mut structured = self.ws.structured_jacobian.take().unwrap_or_else(|| Box::new(StructuredJacobian::new(self.model)));
        let passes = structured.local_derivatives(self.model, self.memory, t, y, floors);
        parts.local.copy_from_slice(structured.local_entries());
        self.ws.structured_jacobian = Some(structured);
        cost.force_evaluations = passes?;
        Ok(Some(cost))
    }

    fn absolute_tolerance_scales(&self, scales: &mut [f64]) {
        let layout = &self.model.layout;
        if let Some(tree) = self.tree {
            // joint angles [rad] and displacements [m] as the bodies' coordinates
            let (joint, z) = scales.split_at_mut(2 * tree.n_dofs);
            joint.fill(1.0);
            for (element, states) in self.model.elements.iter().zip(&layout.element_states) {
                element.kind.tolerance_scales(&mut z[states.clone()]);
            }
            return;
        }
        let (q, v, _) = layout.split_mut(scales);
        for (body, address) in self.model.bodies.iter().zip(&layout.bodies) {
            body.kind.tolerance_scales(&mut q[address.q_range()], &mut v[address.v_range()]);
        }
        let (_, _, z) = layout.split_mut(scales);
        for (element, states) in self.model.elements.iter().zip(&layout.element_states) {
            element.kind.tolerance_scales(&mut z[states.clone()]);
        }
    }

    fn n_events(&self) -> usize {
        self.model.n_events()
    }

    fn event_functions(&mut self, t: f64, y: &[f64], g: &mut [f64]) {
        self.update_event_frames(t, y);
        self.element_event_functions(g, None);
    }

    fn event_functions_and_rates(&mut self, t: f64, y: &[f64], g: &mut [f64], rates: &mut [f64]) -> bool {
        self.update_event_frames(t, y);
        self.element_event_functions(g, Some(rates));
        true
    }

    fn on_event(&mut self, t: f64, y: &mut [f64], event: usize) -> Result<(), SimulationError> {
        self.place_frames(t, y);
        let (k, own) = self.model.event_owner(event);
        let frames = Frames { planar: &self.ws.frames, spatial: &self.ws.spatial_frames };
        self.model.elements[k].kind.on_event(&frames, t, own, &mut self.memory[self.model.memory_of(k)]);
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
        if !self.model.layout.identity_position_rates && self.tree.is_none() {
            // positions back onto their manifold (unit quaternions), whatever the drift control
            normalise_positions(self.model, self.model.layout.split_mut(y).0);
        }
        if self.options.stabilization == Stabilization::Projection && !self.step_end.holds_projection(t, y) {
            self.project_state(t, y)?;
        }
        if self.accept_elements(t, y)? {
            // the elements' laws read their memory (a latched onset velocity): the evaluation no longer holds
            self.step_end.evaluated_at = None;
        }
        self.check_elements(t, y)?;
        self.last_accepted = t;
        self.tracking.accepted_state.copy_from_slice(y);
        Ok(false)
    }

    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        if self.step_end.holds_evaluation(t, y) && !self.model.has_detailed_outputs() {
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

    /// Completes the evaluation the workspace holds with the element outputs only
    /// samples need (a film's peak pressure), re-evaluating just those.
    fn detail_elements(&mut self, t: f64) -> Result<(), SimulationError> {
        let ws = &mut *self.ws;
        for &k in &self.model.acting {
            let element = &self.model.elements[k];
            element.kind.detail(&ws.frames, &mut ws.element_work[k]).map_err(|fault| fault.at(t, &element.name))?;
        }
        self.step_end.evaluated_detailed = true;
        Ok(())
    }

    /// Tracked channel values, then point acceleration magnitudes [m/s^2], at the
    /// step end `(t, y)` from the sample recorded there, when there is one and the
    /// workspace still holds its evaluation (for the points); false otherwise.
    /// (The driver records a step end before the tracker observes the step, from
    /// the same state.)
    fn tracked_values_from_sample(&self, t: f64, y: &[f64], values: &mut [f64]) -> bool {
        let Some(sample) = self.trajectory.last_sample_at(t) else { return false };
        if !self.step_end.holds_evaluation(t, y) {
            return false;
        }
        let (channels, points) = values.split_at_mut(self.tracking.channels.len());
        for (v, &c) in channels.iter_mut().zip(&self.tracking.channels) {
            *v = sample[c];
        }
        for (v, marker) in points.iter_mut().zip(&self.tracking.points) {
            *v = point_acceleration(self.model, self.ws, marker);
        }
        true
    }

    /// Tracked channel values, then point acceleration magnitudes [m/s^2], from
    /// the evaluation the workspace holds at `state`.
    fn tracked_values(&mut self, state: &[f64], values: &mut [f64]) {
        // (in joint coordinates the evaluation's body-space state)
        let mut body = std::mem::take(&mut self.ws.joint.body_state);
        if let Some(tree) = self.tree {
            tree.body_state(self.model, &self.ws.frames, &state[2 * tree.n_dofs..], &mut body);
        }
        let state = if self.tree.is_some() { &body[..] } else { state };
        let (channels, points) = values.split_at_mut(self.tracking.channels.len());
        read_channels(self.model, &self.tracking.reads, state, self.ws, channels);
        self.ws.joint.body_state = body;
        for (v, marker) in points.iter_mut().zip(&self.tracking.points) {
            *v = point_acceleration(self.model, self.ws, marker);
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
            // the step end: the sample just recorded there holds the channels' values
            if system.tracked_values_from_sample(t, self.y_new, values) {
                return Ok(());
            }
            // else reuse its evaluation when the workspace holds it with the needed outputs
            if !system.step_end.holds_evaluation(t, self.y_new) {
                system.evaluate_sample(t, self.y_new)?;
            } else if system.model.has_detailed_outputs() && !system.step_end.evaluated_detailed {
                system.detail_elements(t)?;
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

/// Acceleration magnitude [m/s^2] of a marker's point from an evaluated workspace.
fn point_acceleration(model: &Model, ws: &Workspace, marker: &Marker) -> f64 {
    let Some(address) = model.layout.body(marker.body) else { return 0.0 };
    let kind = &model.bodies[marker.body.0 - 1].kind;
    kind.marker_acceleration(&ws.frames[marker.body.0], &ws.frames[marker.frame], &ws.accelerations[address.v_range()], marker).norm()
}
