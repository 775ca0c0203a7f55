//! Equations of motion in absolute coordinates with Lagrange multipliers:
//!
//! ```text
//! M q_ddot + Phi_q^T lambda = Q(q, q_dot, t)
//!            Phi_q q_ddot   = gamma(q, q_dot, t)
//! ```
//!
//! `M` is constant and block diagonal, so the multipliers come from the
//! small system `(Phi_q M^-1 Phi_q^T) lambda = Phi_q M^-1 Q - gamma` and
//! then `q_ddot = M^-1 (Q - Phi_q^T lambda)`.

use crate::body::BodyModel;
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::Site;
use crate::kinematics::planar::Frame;
use crate::kinematics::spatial::SpatialFrame;
use super::generalised_force::GeneralisedForces;
use super::constraint_solution;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::error::SimulationError;
use crate::element::{ElementMemory, ElementModel};
use crate::joint::ConstraintRows;
use crate::linalg::RankDeficiency;

/// How constraint drift is controlled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stabilization {
    /// Project positions and velocities back onto the constraints after every accepted step (default).
    Projection,
    /// Baumgarte: `gamma - 2 alpha Phi_dot - beta^2 Phi` [1/s, 1/s].
    Baumgarte {
        /// Damping rate alpha [1/s].
        alpha: f64,
        /// Stiffness rate beta [1/s].
        beta: f64,
    },
    /// No drift control (for tests of the integrators).
    None,
}

/// Computes the frames of all bodies and then of all sections (markers on
/// flexible bodies) from the positions `q` and velocities `v` (reusing the
/// trigonometry of a frame whose orientation did not change), and their
/// spatial frames when `spatial` holds them (a model with spatial elements).
pub fn update_frames(model: &Model, q: &[f64], v: &[f64], frames: &mut [Frame], spatial: &mut [SpatialFrame]) {
    let (bodies, sections) = frames[1..].split_at_mut(model.bodies.len());
    for ((body, address), frame) in model.bodies.iter().zip(&model.layout.bodies).zip(bodies) {
        crate::body::planar_first!(&body.kind, update_frame(&q[address.q_range()], &v[address.v_range()], frame));
    }
    for (section, frame) in model.sections.iter().zip(sections) {
        *frame = model.section_frame(section, q, v, frame);
    }
    if !spatial.is_empty() {
        update_spatial_frames(model, q, v, frames, spatial);
    }
}

/// The spatial frames of the bodies and sections whose planar frames are `frames`.
fn update_spatial_frames(model: &Model, q: &[f64], v: &[f64], frames: &[Frame], spatial: &mut [SpatialFrame]) {
    let n = model.bodies.len();
    for (k, (body, address)) in model.bodies.iter().zip(&model.layout.bodies).enumerate() {
        spatial[k + 1] = body.kind.spatial_site_frame(&Site::Reference, &q[address.q_range()], &v[address.v_range()], &frames[k + 1]);
    }
    for (k, section) in model.sections.iter().enumerate() {
        let address = &model.layout.bodies[section.body.0 - 1];
        let kind = &model.bodies[section.body.0 - 1].kind;
        spatial[n + 1 + k] = kind.spatial_site_frame(&section.site, &q[address.q_range()], &v[address.v_range()], &frames[n + 1 + k]);
    }
}

/// Fills the Jacobian, `nu` and `gamma` of the first `n_constraints`
/// constraints from the current frames; returns the number of rows.
pub(crate) fn linearise_constraints(model: &Model, n_constraints: usize, t: f64, ws: &mut Workspace) -> usize {
    ws.factored_at = None;
    let rows = model.row_offsets[n_constraints];
    ws.jacobian.fill(0.0);
    for (k, c) in model.constraints[..n_constraints].iter().enumerate() {
        let target = ConstraintRows {
            jacobian: &mut ws.jacobian,
            pattern: &model.jacobian_pattern,
            bodies: &model.bodies,
            row: model.row_offsets[k],
            nu: &mut ws.nu,
            gamma: &mut ws.gamma,
        };
        c.kind.linearise(&Frames { planar: &ws.frames, spatial: &ws.spatial_frames }, t, target);
    }
    rows
}

/// Fills `ws.residual` for the first `n_constraints` constraints; returns the largest |residual| and its row.
pub(crate) fn constraint_residuals(model: &Model, n_constraints: usize, t: f64, ws: &mut Workspace) -> (f64, usize) {
    for (k, c) in model.constraints[..n_constraints].iter().enumerate() {
        let (a, b) = (model.row_offsets[k], model.row_offsets[k + 1]);
        c.kind.residual(&Frames { planar: &ws.frames, spatial: &ws.spatial_frames }, t, &mut ws.residual[a..b]);
    }
    let rows = model.row_offsets[n_constraints];
    ws.residual[..rows].iter().enumerate().fold((0.0, 0), |(m, i), (r, v)| if v.abs() > m { (v.abs(), r) } else { (m, i) })
}

/// `out[r] = (Phi_q v)_r` for the first `rows` rows, summing only over each row's blocks.
pub(crate) fn jacobian_times(model: &Model, rows: usize, jacobian: &[f64], v: &[f64], out: &mut [f64]) {
    model.jacobian_pattern.times(rows, jacobian, v, out);
}

/// `out = Phi_q^T w` over the first `rows` rows, touching only each row's blocks.
pub(crate) fn jacobian_transpose_times(model: &Model, rows: usize, jacobian: &[f64], w: &[f64], out: &mut [f64]) {
    model.jacobian_pattern.transpose_times(rows, jacobian, w, out);
}

/// Factors `S = Phi_q M^-1 Phi_q^T` for the first `rows` rows at `(t, q)`
/// ([`constraint_solution::factor`]), remembered so that an evaluation at the
/// same time and positions (after a velocity projection) reuses the factor.
pub(crate) fn factor_constraint_matrix_at(model: &Model, rows: usize, t: f64, q: &[f64], ws: &mut Workspace) -> Result<(), SimulationError> {
    constraint_solution::factor(model, rows, q, ws).map_err(|d| non_finite_constraints(model, t, d))?;
    ws.factored_positions.copy_from_slice(q);
    ws.factored_at = Some((t, rows));
    Ok(())
}

/// Whether `ws.schur` holds the factor for `rows` rows at `(t, q)`.
fn holds_factor(ws: &Workspace, rows: usize, t: f64, q: &[f64]) -> bool {
    ws.factored_at == Some((t, rows)) && ws.factored_positions == q
}

/// Solves `S x = b` with `b` in `ws.multipliers` (see [`constraint_solution::solve`]).
pub(crate) fn solve_in_multipliers(model: &Model, rows: usize, ws: &mut Workspace) {
    let mut b = std::mem::take(&mut ws.multipliers);
    constraint_solution::solve(model, rows, ws, &mut b);
    ws.multipliers = b;
}

/// Error for a constraint matrix that could not be factored even regularised (not finite).
fn non_finite_constraints(model: &Model, t: f64, deficiency: RankDeficiency) -> SimulationError {
    let owner = &model.elements[model.row_owner[deficiency.row]];
    SimulationError::SingularConfiguration {
        time: t,
        element: owner.name.clone(),
        cause: format!("its constraint equations could not be factored (relative pivot {:.2e}); the state is not finite", deficiency.relative_pivot),
    }
}

/// Applied generalised forces: the bodies' own (inertial, internal), gravity
/// and the force elements (clearance joints included), whose evaluations are
/// kept in the workspace.
pub(crate) fn applied_forces(model: &Model, memory: &[ElementMemory], t: f64, (q, v, z): (&[f64], &[f64], &[f64]), ws: &mut Workspace) -> Result<(), SimulationError> {
    match &ws.gravity_load {
        Some(load) => ws.generalised_force.copy_from_slice(load),
        None => ws.generalised_force.fill(0.0),
    }
    if model.layout.has_body_forces {
        for (body, address) in model.bodies.iter().zip(&model.layout.bodies) {
            body.kind.add_body_forces(&q[address.q_range()], &v[address.v_range()], &mut ws.generalised_force[address.v_range()]);
        }
    }
    let frames = Frames { planar: &ws.frames, spatial: &ws.spatial_frames };
    let mut forces = GeneralisedForces::new(&mut ws.generalised_force, &model.bodies, &model.layout, frames);
    if ws.gravity_load.is_none() {
        forces.add_gravity(model.gravity, q);
    }
    for &k in &model.acting {
        let (element, states) = (&model.elements[k], model.layout.element_states[k].clone());
        let own = (&z[states.clone()], &mut ws.element_state_rates[states]);
        element
            .kind
            .apply(&frames, t, own, &memory[model.memory_of(k)], &mut ws.element_work[k], ws.detailed, &mut forces)
            .map_err(|fault| fault.at(t, &element.name))?;
    }
    Ok(())
}

/// Evaluates the accelerations `ws.accelerations` (of the velocity
/// coordinates) and multipliers `ws.multipliers` at `(t, y)`, `y = [q, v, z]`.
/// Never allocates.
pub fn accelerations(
    model: &Model,
    memory: &[ElementMemory],
    t: f64,
    y: &[f64],
    stabilization: Stabilization,
    ws: &mut Workspace,
) -> Result<(), SimulationError> {
    let (q, qdot, z) = model.layout.split(y);
    // the factor depends on the positions only: kept from a projection at the same (t, q)
    let factored = holds_factor(ws, model.row_offsets[model.n_dynamic_constraints], t, q);
    update_frames(model, q, qdot, &mut ws.frames, &mut ws.spatial_frames);
    applied_forces(model, memory, t, (q, qdot, z), ws)?;
    constrained_accelerations(model, t, (q, qdot), stabilization, factored, ws)?;
    check_finite(model, t, ws)
}

/// The accelerations `ws.accelerations` and multipliers `ws.multipliers` from
/// the generalised forces `ws.generalised_force` at `(t, q, qdot)`, the frames
/// placed there already: the constraints are linearised, and their matrix is
/// factored unless `factored` says the workspace holds its factor at `(t, q)`.
/// The map from `Q` to the accelerations is affine: `q_ddot = A(q) Q + b(q, qdot, t)`.
pub(crate) fn constrained_accelerations(
    model: &Model,
    t: f64,
    (q, qdot): (&[f64], &[f64]),
    stabilization: Stabilization,
    factored: bool,
    ws: &mut Workspace,
) -> Result<(), SimulationError> {
    let rows = linearise_constraints(model, model.n_dynamic_constraints, t, ws);
    if let Stabilization::Baumgarte { alpha, beta } = stabilization {
        constraint_residuals(model, model.n_dynamic_constraints, t, ws);
        // (the multipliers' buffer holds Phi_dot for a moment)
        let phi_dot = &mut ws.multipliers;
        jacobian_times(model, rows, &ws.jacobian, qdot, phi_dot);
        for r in 0..rows {
            ws.gamma[r] -= 2.0 * alpha * (phi_dot[r] - ws.nu[r]) + beta * beta * ws.residual[r];
        }
    }
    // lambda from (J M^-1 J^T) lambda = J M^-1 Q - gamma
    if rows > 0 {
        if factored {
            ws.factored_at = Some((t, rows));
        } else {
            factor_constraint_matrix_at(model, rows, t, q, ws)?;
        }
        // the right-hand side J M^-1 Q - gamma, solved in place into lambda
        model.solve_mass(q, &ws.generalised_force, &mut ws.accelerations, &mut ws.mass_matrix);
        let lambda = &mut ws.multipliers;
        jacobian_times(model, rows, &ws.jacobian, &ws.accelerations, lambda);
        for (l, g) in lambda[..rows].iter_mut().zip(&ws.gamma) {
            *l -= g;
        }
        solve_in_multipliers(model, rows, ws);
        jacobian_transpose_times(model, rows, &ws.jacobian, &ws.multipliers, &mut ws.scratch);
        // q_ddot = M^-1 (Q - J^T lambda)
        for (c, f) in ws.scratch.iter_mut().zip(&ws.generalised_force) {
            *c = f - *c;
        }
        model.solve_mass(q, &ws.scratch, &mut ws.accelerations, &mut ws.mass_matrix);
    } else {
        model.solve_mass(q, &ws.generalised_force, &mut ws.accelerations, &mut ws.mass_matrix);
    }
    Ok(())
}

/// Names the first element whose output is not finite when some acceleration is not.
pub(crate) fn check_finite(model: &Model, t: f64, ws: &Workspace) -> Result<(), SimulationError> {
    if ws.accelerations.iter().all(|a| a.is_finite()) {
        return Ok(());
    }
    let element = ws
        .element_work
        .iter()
        .position(|work| !work.is_finite())
        .map(|k| model.elements[k].name.clone())
        .unwrap_or_else(|| "state".to_string());
    Err(SimulationError::NonFinite { time: t, element })
}
