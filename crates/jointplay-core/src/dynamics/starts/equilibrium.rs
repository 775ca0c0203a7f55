//! Static equilibrium: the positions at which the mechanism, at rest, stays
//! at rest under its loads, with its drivers held at their values at `t0`.
//!
//! Unknowns: the position coordinates `q` and the multipliers `lambda` of the
//! joints and drivers. Equations (`docs/theory/static-equilibrium.md`):
//!
//! ```text
//! f(q, lambda) = Q(q, v = 0, z(q)) - Phi_q(q)^T lambda = 0     (balance of forces) [N, N m]
//! Phi(q, t0) = 0                                              (joints, drivers held) [m, rad]
//! ```
//!
//! `Q` holds gravity, the force elements (springs, loads, clearance contacts
//! at rest, cylinders) and a flexible body's internal forces; friction and
//! damping vanish at rest. A cylinder's chambers are closed: its pressures
//! follow their volumes from the assembled state ([`crate::element::ElementModel::static_states`]).
//! Newton with a Jacobian by forward differences in `q` (exact in `lambda`),
//! each step the least-squares, minimum-norm solution (singular value
//! decomposition: redundant joints and unloaded directions take no step),
//! the loads applied in increments where Newton does not converge at once.
//! A clearance joint's journal is first held, then placed against its bore
//! along its load, then released ([`equilibrium`]). A load with a part that no
//! stiffness or joint can carry (a free body under gravity) leaves a
//! least-squares residual: there is no equilibrium, and the error names the body.

use crate::kinematics::frames::Frames;
use nalgebra::{DMatrix, DVector};

use super::assembly::assemble;
use crate::dynamics::formulations::absolute::equations::{applied_forces, constraint_residuals, jacobian_transpose_times, linearise_constraints, update_frames};
use crate::body::BodyModel;
use crate::kinematics::planar::{Frame, Vec2};
use crate::dynamics::model::state::State;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::error::SimulationError;
use crate::element::{ElementMemory, ElementModel};
use crate::joint::{ClearanceRevolute, ConstraintKind};

/// Options of the static analysis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EquilibriumOptions {
    /// Largest force residual accepted, relative to the largest applied load
    /// at the start (1e-10: six orders above rounding in a stiff beam's forces) [-].
    pub force_tolerance: f64,
    /// Largest constraint residual accepted [m or rad].
    pub constraint_tolerance: f64,
    /// Newton iterations allowed.
    pub max_iterations: usize,
}

impl Default for EquilibriumOptions {
    fn default() -> Self {
        Self { force_tolerance: 1e-10, constraint_tolerance: 1e-10, max_iterations: 100 }
    }
}

/// A static equilibrium found.
#[derive(Clone, Debug)]
pub struct Equilibrium {
    /// The state at rest: positions, zero velocities, element states (closed chambers' pressures).
    pub state: State,
    /// Largest force residual left [N or N m].
    pub force_residual: f64,
    /// Largest constraint residual left [m or rad].
    pub constraint_residual: f64,
    /// Newton iterations taken.
    pub iterations: usize,
    /// Multipliers of the joints' and drivers' equations, in row order (the
    /// reactions' generalised components) [N, N m].
    pub multipliers: Vec<f64>,
}

/// Singular values of the scaled Jacobian below this fraction of the largest
/// are dropped (redundant joints, directions no load or stiffness reaches).
const RANK_TOLERANCE: f64 = 1e-11;

/// Relative forward-difference step in a position coordinate (about the square
/// root of the machine precision) [-], of at least this many metres or radians.
const DIFFERENCE_STEP: f64 = 1.5e-8;

/// Fraction of the residual a least-squares step may leave before the loads
/// are declared unbalanced: well above what the forward-difference Jacobian's
/// error leaves in a consistent solve (up to 4e-7 seen in a beam of EA / EI =
/// 1e7 / m^2), well below the whole residual that an uncarried load leaves.
const UNBALANCED: f64 = 1e-3;

/// The static equilibrium of `model` at `t0` from its assembled configuration.
///
/// The loads are applied in increments where Newton does not converge at once
/// (a continuation in the factor `mu` on the loads and force elements, from
/// the assembled configuration, an equilibrium at `mu = 0`, to `mu = 1`): the
/// first Newton step of a stiff beam under its whole load is the linear
/// solution, which stretches the beam as it bends it.
pub fn equilibrium(model: &Model, t0: f64, options: &EquilibriumOptions, ws: &mut Workspace) -> Result<Equilibrium, SimulationError> {
    if !model.layout.identity_position_rates {
        // (the Newton iteration below moves the positions as a vector of the velocities' size)
        return Err(SimulationError::InvalidInput {
            time: t0,
            message: "the static equilibrium of a model whose positions are not its velocities' integrals (a spatial body's quaternion) is not available; simulate from the assembled start instead (with damping, to rest)".to_string(),
        });
    }
    let start = assemble(model, t0, ws)?;
    let all = model.constraints.len();
    if all == model.n_dynamic_constraints {
        return solve(model, model.n_dynamic_constraints, t0, &start, options, ws);
    }
    // clearance joints: held at their assembled eccentricity first, which gives the load on each journal;
    // then held where that load presses it into its bore, at the contact law's static penetration; then free
    let locked = solve(model, all, t0, &start, options, ws)?;
    let placed = resting_journals(model, t0, &locked, ws);
    let resting = solve(&placed, all, t0, &locked.state, options, ws)?;
    let mut free = solve(model, model.n_dynamic_constraints, t0, &resting.state, options, ws)?;
    free.iterations += locked.iterations + resting.iterations;
    Ok(free)
}

/// The equilibrium with the first `n_constraints` constraints from the positions and element states of
/// `from` (an equilibrium at no load, or near the one sought), by load increments as [`equilibrium`] says.
fn solve(model: &Model, n_constraints: usize, t0: f64, from: &State, options: &EquilibriumOptions, ws: &mut Workspace) -> Result<Equilibrium, SimulationError> {
    let mut problem = Statics::new(model, n_constraints, t0, from, ws);
    let (n, rows) = (model.layout.nv, model.row_offsets[n_constraints]);
    let mut x = DVector::zeros(n + rows);
    x.rows_mut(0, n).copy_from(&DVector::from_column_slice(from.coordinates()));
    let (mut reached, mut increment, mut iterations) = (0.0_f64, 1.0_f64, 0);
    loop {
        problem.load_factor = (reached + increment).min(1.0);
        let allowed = INCREMENT_ITERATIONS.min(options.max_iterations.saturating_sub(iterations));
        match newton(&mut problem, x.clone(), options, allowed, ws)? {
            Newton::Converged { x: found, iterations: taken } => {
                iterations += taken;
                x = found;
                reached = problem.load_factor;
                if reached >= 1.0 {
                    let f = problem.residual(&x, ws)?;
                    let (force, constraint) = (f.rows(0, n).amax(), f.rows(n, rows).amax());
                    return Ok(problem.finish(&x, from.clone(), force, constraint, iterations));
                }
                if taken <= EASY_INCREMENT {
                    increment *= 2.0;
                }
            }
            Newton::Unbalanced(left) => return Err(unbalanced(model, t0, &left, n)),
            Newton::Stalled { force, iterations: taken } => {
                iterations += taken;
                increment *= 0.5;
                if increment < SMALLEST_INCREMENT || iterations >= options.max_iterations {
                    return Err(not_converged(t0, reached, force, iterations));
                }
            }
        }
    }
}

/// A copy of `model` whose assembly lock of each loaded clearance joint holds
/// the journal where its load presses it: against the bore, along the load,
/// at the penetration where the contact law's elastic force carries it (at
/// rest the damping and friction terms vanish). The load is read from the
/// lock's reaction in the `locked` equilibrium; an unloaded journal stays.
fn resting_journals(model: &Model, t: f64, locked: &Equilibrium, ws: &mut Workspace) -> Model {
    let mut placed = model.clone();
    let q = locked.state.coordinates();
    for k in model.n_dynamic_constraints..model.constraints.len() {
        let ConstraintKind::PointCoincidence(lock) = &model.constraints[k].kind else { continue };
        let Some((_, _, joint)) = model.clearance_joints().find(|(_, _, j)| j.bearing == lock.first && j.journal == lock.second) else {
            continue;
        };
        let force = lock_force_on_journal(model, k, t, q, &locked.multipliers, ws);
        let magnitude = force.norm();
        if !(magnitude > 0.0 && magnitude.is_finite()) {
            continue;
        }
        let penetration = static_penetration(joint, magnitude);
        if let ConstraintKind::PointCoincidence(moved) = &mut placed.constraints[k].kind {
            // the journal moves along its load, -force
            moved.offset = -force / magnitude * (joint.clearance + penetration);
        }
    }
    placed
}

/// The force [N] the assembly lock `k` exerts on its journal at `(t, q)`
/// with the multipliers `multipliers`: the virtual work of `-Phi_q^T lambda`
/// of the lock's rows in a translation of the journal's body.
fn lock_force_on_journal(model: &Model, k: usize, t: f64, q: &[f64], multipliers: &[f64], ws: &mut Workspace) -> Vec2 {
    let ConstraintKind::PointCoincidence(lock) = &model.constraints[k].kind else { return Vec2::zeros() };
    let Some(address) = model.layout.body(lock.second.body) else { return Vec2::zeros() };
    let rows = model.row_offsets[model.constraints.len()];
    update_frames(model, q, &vec![0.0; model.layout.nv], &mut ws.frames, &mut ws.spatial_frames);
    linearise_constraints(model, model.constraints.len(), t, ws);
    let mut lambda = vec![0.0; rows];
    let own = model.row_offsets[k]..model.row_offsets[k + 1];
    lambda[own.clone()].copy_from_slice(&multipliers[own]);
    jacobian_transpose_times(model, rows, &ws.jacobian, &lambda, &mut ws.scratch);
    let body = &model.bodies[lock.second.body.0 - 1].kind;
    let component = |velocity: Vec2| {
        let mut rates = vec![0.0; address.nv];
        body.rigid_motion_velocities(&q[address.q_range()], velocity, 0.0, &mut rates);
        -rates.iter().zip(&ws.scratch[address.v_range()]).map(|(r, g)| r * g).sum::<f64>()
    };
    Vec2::new(component(Vec2::new(1.0, 0.0)), component(Vec2::new(0.0, 1.0)))
}

/// The penetration [m] at which the contact law's elastic force is `force` [N]
/// (bisection: the force grows with the penetration), at most the clearance.
fn static_penetration(joint: &ClearanceRevolute, force: f64) -> f64 {
    let (mut low, mut high) = (0.0, joint.clearance.max(joint.max_penetration.min(joint.bearing_radius)));
    if joint.stiffness.elastic_force(high) < force {
        return high;
    }
    for _ in 0..200 {
        let middle = 0.5 * (low + high);
        if joint.stiffness.elastic_force(middle) < force { low = middle } else { high = middle }
    }
    0.5 * (low + high)
}

/// Newton iterations allowed for one load increment before it is halved.
const INCREMENT_ITERATIONS: usize = 25;

/// An increment that converged within this many iterations is doubled for the next.
const EASY_INCREMENT: usize = 6;

/// Smallest load increment tried before giving up [-].
const SMALLEST_INCREMENT: f64 = 1.0 / 1024.0;

/// How Newton at one load factor ended.
enum Newton {
    Converged { x: DVector<f64>, iterations: usize },
    /// A load that no stiffness or joint carries: the residual left by the least-squares step.
    Unbalanced(DVector<f64>),
    Stalled { force: f64, iterations: usize },
}

/// Newton on `problem` at its load factor from `x`, at most `allowed` iterations.
fn newton(problem: &mut Statics<'_>, mut x: DVector<f64>, options: &EquilibriumOptions, allowed: usize, ws: &mut Workspace) -> Result<Newton, SimulationError> {
    let model = problem.model;
    let (n, rows) = (model.layout.nv, model.row_offsets[problem.n_constraints]);
    let load = problem.load_scale;
    let mut f = problem.residual(&x, ws)?;
    for iteration in 0..=allowed {
        if !crate::interrupt::keep_going() {
            return Err(SimulationError::Interrupted { time: problem.t });
        }
        let (force, constraint) = (f.rows(0, n).amax(), f.rows(n, rows).amax());
        if force <= options.force_tolerance * load && constraint <= options.constraint_tolerance {
            return Ok(Newton::Converged { x, iterations: iteration });
        }
        if iteration == allowed {
            return Ok(Newton::Stalled { force, iterations: iteration });
        }
        let jacobian = problem.jacobian(&x, &f, ws)?;
        let linear = Linearisation::of(&jacobian);
        let step = linear.solve(&f);
        let left = &f + &jacobian * &step;
        if scaled_norm(&left, n, load) > UNBALANCED * scaled_norm(&f, n, load) {
            return Ok(Newton::Unbalanced(left));
        }
        // a step at the round-off of the positions: the residual is as small as the forces can tell
        let settled = linear.norm(&step) <= ROUND_OFF_STEP * linear.norm(&x).max(1.0);
        (x, f) = damped_step(problem, &x, &step, ws)?;
        if settled && f.rows(n, rows).amax() <= options.constraint_tolerance && f.rows(0, n).amax() <= options.force_tolerance.sqrt() * load {
            return Ok(Newton::Converged { x, iterations: iteration + 1 });
        }
    }
    unreachable!("the loop returns at iteration == allowed")
}

/// A Newton step this small relative to the unknowns (equilibrated) is round-off [-].
const ROUND_OFF_STEP: f64 = 1e-13;

/// The error for a continuation that did not reach the whole load.
fn not_converged(t: f64, reached: f64, force: f64, iterations: usize) -> SimulationError {
    SimulationError::NoEquilibrium {
        time: t,
        element: "the mechanism".to_string(),
        cause: format!(
            "no equilibrium found beyond {:.1} % of the loads: a force residual of {force:.4e} N (or N m) after {iterations} Newton iterations in all (a load beyond a buckling or snap-through limit, or an equilibrium far from the assembled configuration)",
            100.0 * reached
        ),
    }
}

/// The Jacobian's singular value decomposition, rows and columns equilibrated
/// first (each scaled by its largest entry: a beam's axial and bending
/// stiffnesses differ by 1e7 and more, which would otherwise drop its bending
/// directions as if they were singular).
pub(super) struct Linearisation {
    svd: nalgebra::SVD<f64, nalgebra::Dyn, nalgebra::Dyn>,
    row_scales: Vec<f64>,
    column_scales: Vec<f64>,
}

impl Linearisation {
    pub(super) fn of(jacobian: &DMatrix<f64>) -> Self {
        let mut scaled = jacobian.clone();
        let row_scales: Vec<f64> = scaled.row_iter().map(|r| if r.amax() > 0.0 { r.amax() } else { 1.0 }).collect();
        for (i, s) in row_scales.iter().enumerate() {
            scaled.row_mut(i).scale_mut(1.0 / s);
        }
        let column_scales: Vec<f64> = scaled.column_iter().map(|c| if c.amax() > 0.0 { c.amax() } else { 1.0 }).collect();
        for (j, s) in column_scales.iter().enumerate() {
            scaled.column_mut(j).scale_mut(1.0 / s);
        }
        Self { svd: scaled.svd(true, true), row_scales, column_scales }
    }

    /// The least-squares `dx` of `J dx = -f` of smallest norm in the equilibrated unknowns.
    pub(super) fn solve(&self, f: &DVector<f64>) -> DVector<f64> {
        let rhs = DVector::from_iterator(f.len(), f.iter().zip(&self.row_scales).map(|(v, s)| -v / s));
        let largest = self.svd.singular_values.max();
        let mut step = self.svd.solve(&rhs, RANK_TOLERANCE * largest.max(f64::MIN_POSITIVE)).unwrap_or_else(|_| DVector::zeros(f.len()));
        for (v, s) in step.iter_mut().zip(&self.column_scales) {
            *v /= s;
        }
        step
    }

    /// The norm of `dx` in the equilibrated unknowns.
    fn norm(&self, dx: &DVector<f64>) -> f64 {
        dx.iter().zip(&self.column_scales).map(|(v, s)| (v * s).powi(2)).sum::<f64>().sqrt()
    }
}

/// Moves `x` by the Newton `step`, halved only where the equations cannot be
/// evaluated there (a non-finite force, a chamber volume below zero). No
/// residual-norm line search: a stiff beam's axial forces grow with the square
/// of the rotation its bending step makes, so a norm rises on the way to the
/// solution (a test by the simplified Newton correction, Deuflhard 2004, §3.3,
/// rejected every full step of a bending cantilever as well, where full
/// steps converge in 6 to 10 iterations); a Newton that does not converge is
/// handled by the load increments instead.
fn damped_step(
    problem: &mut Statics<'_>,
    x: &DVector<f64>,
    step: &DVector<f64>,
    ws: &mut Workspace,
) -> Result<(DVector<f64>, DVector<f64>), SimulationError> {
    let mut fraction = 1.0;
    for _ in 0..MAX_HALVINGS {
        let trial = x + step * fraction;
        if let Ok(g) = problem.residual(&trial, ws) {
            if g.iter().all(|v| v.is_finite()) {
                return Ok((trial, g));
            }
        }
        fraction *= 0.5;
    }
    let trial = x + step * fraction;
    let g = problem.residual(&trial, ws)?;
    Ok((trial, g))
}

/// Halvings of a Newton step before the smallest is taken as it is.
const MAX_HALVINGS: usize = 30;

/// The equations' evaluation with what stays fixed: time, the assembled
/// placement and element states, the elements' memory.
struct Statics<'m> {
    model: &'m Model,
    /// The constraints held: the joints and drivers, and the assembly locks in a first stage.
    n_constraints: usize,
    t: f64,
    memory: Vec<ElementMemory>,
    reference_frames: Vec<Frame>,
    /// Their spatial frames (in a spatial model).
    reference_spatial_frames: Vec<crate::kinematics::spatial::SpatialFrame>,
    reference_states: Vec<f64>,
    states: Vec<f64>,
    zeros: Vec<f64>,
    /// Largest generalised load at the assembled placement (floored at 1 N) [N or N m].
    load_scale: f64,
    /// The continuation's factor on the loads and force elements (not on the bodies' internal forces) [-].
    load_factor: f64,
    /// The bodies' internal forces (scratch) [N, N m].
    internal: Vec<f64>,
}

impl<'m> Statics<'m> {
    fn new(model: &'m Model, n_constraints: usize, t: f64, start: &State, ws: &mut Workspace) -> Self {
        let zeros = vec![0.0; model.layout.nv];
        update_frames(model, start.coordinates(), &zeros, &mut ws.frames, &mut ws.spatial_frames);
        let reference_states = model.layout.split(&start.y).2.to_vec();
        let mut statics = Self {
            model,
            n_constraints,
            t,
            memory: start.memory.clone(),
            reference_frames: ws.frames.clone(),
            reference_spatial_frames: ws.spatial_frames.clone(),
            states: reference_states.clone(),
            reference_states,
            internal: zeros.clone(),
            zeros,
            load_scale: 1.0,
            load_factor: 1.0,
        };
        if applied_forces(model, &statics.memory, t, (start.coordinates(), &statics.zeros, &statics.states), ws).is_ok() {
            statics.load_scale = ws.generalised_force.iter().fold(1.0_f64, |m, f| m.max(f.abs()));
        }
        statics
    }

    /// `[f; Phi]` at `x = [q; lambda]`.
    fn residual(&mut self, x: &DVector<f64>, ws: &mut Workspace) -> Result<DVector<f64>, SimulationError> {
        let model = self.model;
        let (n, rows) = (model.layout.nv, model.row_offsets[self.n_constraints]);
        let q = x.as_slice()[..n].to_vec();
        update_frames(model, &q, &self.zeros, &mut ws.frames, &mut ws.spatial_frames);
        for (element, range) in model.elements.iter().zip(&model.layout.element_states) {
            let reference = Frames { planar: &self.reference_frames, spatial: &self.reference_spatial_frames };
            element.kind.static_states(&reference, &ws.frames(), &self.reference_states[range.clone()], &mut self.states[range.clone()]);
        }
        applied_forces(model, &self.memory, self.t, (&q, &self.zeros, &self.states), ws)?;
        if self.load_factor != 1.0 {
            // mu Q + (1 - mu) Q_internal: the loads and force elements scaled, the bodies' own forces not
            self.internal.fill(0.0);
            for (body, address) in model.bodies.iter().zip(&model.layout.bodies) {
                body.kind.add_body_forces(&q[address.q_range()], &self.zeros[address.v_range()], &mut self.internal[address.v_range()]);
            }
            for (g, internal) in ws.generalised_force.iter_mut().zip(&self.internal) {
                *g = self.load_factor * *g + (1.0 - self.load_factor) * internal;
            }
        }
        linearise_constraints(model, self.n_constraints, self.t, ws);
        constraint_residuals(model, self.n_constraints, self.t, ws);
        let mut out = DVector::zeros(n + rows);
        jacobian_transpose_times(model, rows, &ws.jacobian, &x.as_slice()[n..], &mut ws.scratch);
        for i in 0..n {
            out[i] = ws.generalised_force[i] - ws.scratch[i];
        }
        out.rows_mut(n, rows).copy_from_slice(&ws.residual[..rows]);
        Ok(out)
    }

    /// The Jacobian of [`Self::residual`] at `x` (where it is `f`).
    fn jacobian(&mut self, x: &DVector<f64>, f: &DVector<f64>, ws: &mut Workspace) -> Result<DMatrix<f64>, SimulationError> {
        let n = self.model.layout.nv;
        let size = x.len();
        let mut jacobian = DMatrix::zeros(size, size);
        let mut shifted = x.clone();
        for j in 0..n {
            let h = DIFFERENCE_STEP * x[j].abs().max(1e-3);
            shifted[j] = x[j] + h;
            let g = self.residual(&shifted, ws)?;
            jacobian.column_mut(j).copy_from(&((g - f) / h));
            shifted[j] = x[j];
        }
        // d f / d lambda = -Phi_q^T, exact: the columns of the Jacobian at q
        self.residual(x, ws)?;
        let rows = size - n;
        let mut unit = vec![0.0; rows];
        for r in 0..rows {
            unit[r] = 1.0;
            jacobian_transpose_times(self.model, rows, &ws.jacobian, &unit, &mut ws.scratch);
            for i in 0..n {
                jacobian[(i, n + r)] = -ws.scratch[i];
            }
            unit[r] = 0.0;
        }
        Ok(jacobian)
    }

    fn finish(&mut self, x: &DVector<f64>, start: State, force: f64, constraint: f64, iterations: usize) -> Equilibrium {
        let layout = &self.model.layout;
        let mut state = start;
        let (q, v, z) = layout.split_mut(&mut state.y);
        q.copy_from_slice(&x.as_slice()[..layout.nq]);
        v.fill(0.0);
        z.copy_from_slice(&self.states);
        let multipliers = x.as_slice()[layout.nv..].to_vec();
        Equilibrium { state, force_residual: force, constraint_residual: constraint, iterations, multipliers }
    }
}

/// Force rows scaled by the load, constraint rows as they are.
fn scaled_norm(f: &DVector<f64>, n: usize, load: f64) -> f64 {
    let force = f.rows(0, n).norm() / load;
    let constraint = f.rows(n, f.len() - n).norm();
    force.hypot(constraint)
}

/// The error for loads that no joint or stiffness carries: the body whose
/// coordinate keeps the largest unbalanced force after the least-squares step.
fn unbalanced(model: &Model, t: f64, left: &DVector<f64>, n: usize) -> SimulationError {
    let (coordinate, force) = left.rows(0, n).iter().enumerate().fold((0, 0.0), |(k, m), (i, v)| if v.abs() > m { (i, v.abs()) } else { (k, m) });
    let body = model.layout.bodies.iter().position(|a| a.v_range().contains(&coordinate)).map_or("?", |b| model.bodies[b].name.as_str());
    SimulationError::NoEquilibrium {
        time: t,
        element: body.to_string(),
        cause: format!(
            "an unbalanced load of {force:.4e} N (or N m) on it that no joint, driver or stiffness carries: a body free to move under gravity or a load, or a mechanism whose degree of freedom no spring or driver holds"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interrupt::{scoped, Watch};
    use std::sync::Arc;

    /// Says stop at once.
    struct Stop;

    impl Watch for Stop {
        fn keep_going(&self) -> bool {
            false
        }
    }

    #[test]
    fn a_cancelled_search_stops_as_interrupted() {
        // the clearance slider-crank: held, then resting, then free (each stage asks at every iteration)
        let model = crate::dynamics::tests::clearance_slider_crank();
        let mut ws = Workspace::new(&model);
        let found = scoped(Arc::new(Stop), || equilibrium(&model, 0.0, &EquilibriumOptions::default(), &mut ws));
        assert!(matches!(found, Err(SimulationError::Interrupted { time }) if time == 0.0), "{found:?}");
    }
}
