//! Consistent initial conditions from the approximate input: Newton on the
//! constraints (driver equations included, so driven coordinates are held
//! at their prescribed values) with every clearance joint locked at its
//! initial eccentricity, then the velocities of that locked (ideal)
//! mechanism, every flexible body in a rigid motion (`rigid_motion_start.rs`)
//! and in the strain that carries its loads there (`quasi_static_start.rs`).

use crate::dynamics::formulations::absolute::projection::{project_positions, project_velocities, velocity_residuals};
use super::quasi_static_start::strain_quasi_statically;
use super::rigid_motion_start::{needs_rigid_motion_start, start_in_rigid_motion};
use crate::dynamics::model::state::State;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::error::SimulationError;

/// Largest constraint residual accepted at assembly [m or rad].
pub const ASSEMBLY_TOLERANCE: f64 = 1e-12;

/// Velocity residual, relative to the initial one, that the projection onto
/// consistent joint equations always removes; more means contradictory equations.
const LOCKED_VELOCITY_RESIDUAL: f64 = 1e-8;

/// Newton iterations allowed at assembly: from a rough sketch of the
/// mechanism Newton needs a handful; fifty means the input is far off.
const ASSEMBLY_ITERATIONS: usize = 50;

/// Consistent initial state at time `t0` from the model's approximate input.
pub fn assemble(model: &Model, t0: f64, ws: &mut Workspace) -> Result<State, SimulationError> {
    let all = model.constraints.len();
    let mut q = model.initial_coordinates.clone();
    let mut qdot = model.initial_velocities.clone();
    project_positions(model, all, t0, &mut q, ASSEMBLY_TOLERANCE, ASSEMBLY_ITERATIONS, ws)?;
    super::assembly_checks::settle_start(model, t0, &mut q, ws)?;
    let (before, _) = velocity_residuals(model, all, t0, &q, &qdot, ws);
    if needs_rigid_motion_start(model) {
        start_in_rigid_motion(model, t0, &q, &mut qdot, ws)?;
    } else {
        project_velocities(model, all, t0, &q, &mut qdot, ASSEMBLY_TOLERANCE, ws)?;
    }
    // dependent equations that contradict each other (a driver against a weld) leave a residual
    // no velocity removes: the mechanism is locked
    let (after, row) = velocity_residuals(model, all, t0, &q, &qdot, ws);
    if after > LOCKED_VELOCITY_RESIDUAL * (1.0 + before) {
        return Err(super::conditioning::velocity_failure(model, t0, &q, after, row, ws));
    }
    if needs_rigid_motion_start(model) {
        strain_quasi_statically(model, t0, &mut q, &mut qdot, &model.initial_element_states, ws)?;
    }
    let mut y = Vec::with_capacity(model.layout.len());
    y.extend_from_slice(&q);
    y.extend_from_slice(&qdot);
    y.extend_from_slice(&model.initial_element_states);
    Ok(State::new(model, t0, y))
}
