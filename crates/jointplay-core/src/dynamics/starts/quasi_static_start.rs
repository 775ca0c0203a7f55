//! Initial strain of the flexible bodies: the deformation in which, moving
//! in the rigid motion of the start (`rigid_motion_start.rs`), their strain
//! does not accelerate — the quasi-static strain that carries the
//! mechanism's loads and inertial forces at `t0`. Without it a flexible link
//! starts unstrained while its rigid neighbours carry their loads at once,
//! and rings at the amplitude of that strain.
//!
//! Unknowns: the positions `q` (all bodies: a rod's strain moves the slider
//! it drives). Equations, Newton with a forward-difference Jacobian and the
//! equilibrated least-squares steps of the static analysis (`equilibrium.rs`):
//!
//! ```text
//! Phi(q, t0) = 0                                   every constraint, assembly locks included [m, rad]
//! a_b(q) - c_b(q) - T_b(q) w_b = 0                 each flexible body b [m/s^2, rad/s^2]
//! ```
//!
//! `a` the accelerations of the equations of motion at `(q, v(q))`, `v(q)`
//! the rigid-motion start at `q`; `T_b w_b + c_b` the best (least-squares) fit
//! of a rigid motion's accelerations to the body's (`T_b` its rigid motions,
//! [`BodyKind::rigid_motion_velocities`], `c_b` their centripetal part,
//! [`BodyKind::rigid_motion_bias_accelerations`]): what is left is the
//! acceleration of the body's strain.

use nalgebra::{DMatrix, DVector};

use crate::dynamics::formulations::absolute::equations::{accelerations, constraint_residuals, update_frames, Stabilization};
use super::equilibrium::Linearisation;
use crate::kinematics::planar::Vec2;
use crate::dynamics::model::mechanism::VelocityStart;
use super::rigid_motion_start::{follow_rigid_motion, free_rigid_motions};
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::body::{BodyKind, BodyModel};
use crate::error::SimulationError;
use crate::element::ElementMemory;

/// Newton iterations allowed; a quasi-static strain is small, Newton needs two or three.
const ITERATIONS: usize = 12;

/// Strain acceleration accepted, relative to the largest acceleration at the start [-].
const TOLERANCE: f64 = 1e-9;

/// Relative forward-difference step in a position coordinate [-] (of at least 1e-3 m or rad).
const DIFFERENCE_STEP: f64 = 1.5e-8;

/// Moves `q` (assembled) to the quasi-static strain and `qdot` to the rigid
/// motion there, when the model has a flexible body. Leaves both as they
/// were when Newton does not find it (the start is then unstrained, as
/// before this step existed) and says so in the returned flag.
pub(crate) fn strain_quasi_statically(model: &Model, t: f64, q: &mut [f64], qdot: &mut [f64], z: &[f64], ws: &mut Workspace) -> Result<bool, SimulationError> {
    let flexible: Vec<usize> = (0..model.bodies.len()).filter(|&b| model.bodies[b].velocity_start != VelocityStart::Approximate).collect();
    if flexible.is_empty() {
        return Ok(true);
    }
    let free = free_rigid_motions(model, t, q, ws);
    let mut problem = Start { model, t, z, memory: model.initial_memory(), flexible, scale: 1.0, unstrained: qdot.to_vec(), assembled: q.to_vec(), free };
    let mut x = DVector::from_column_slice(q);
    let Ok(mut r) = problem.residual(&x, ws) else { return Ok(false) };
    problem.scale = problem.largest_acceleration(&x, ws).unwrap_or(1.0).max(1.0);
    let rows = model.row_offsets[model.constraints.len()];
    for _ in 0..ITERATIONS {
        if !crate::interrupt::keep_going() {
            return Err(SimulationError::Interrupted { time: t });
        }
        if r.rows(0, rows).amax() <= 1e-12 && r.rows(rows, r.len() - rows).amax() <= TOLERANCE * problem.scale {
            q.copy_from_slice(x.as_slice());
            problem.velocities(q, qdot, ws)?;
            return Ok(true);
        }
        let Ok(jacobian) = problem.jacobian(&x, &r, ws) else { return Ok(false) };
        let step = Linearisation::of(&jacobian).solve(&r);
        x += step;
        let Ok(next) = problem.residual(&x, ws) else { return Ok(false) };
        r = next;
    }
    Ok(false)
}

/// The equations' evaluation.
struct Start<'m> {
    model: &'m Model,
    t: f64,
    z: &'m [f64],
    memory: Vec<ElementMemory>,
    flexible: Vec<usize>,
    /// Largest acceleration at the unstrained start [m/s^2 or rad/s^2].
    scale: f64,
    /// The velocities of the unstrained start (consistent, given ones checked) [m/s, rad/s].
    unstrained: Vec<f64>,
    /// The assembled positions [m, rad].
    assembled: Vec<f64>,
    /// The free motions of the rigid mechanism there: the strain must not move the mechanism along them.
    free: Vec<Vec<f64>>,
}

impl Start<'_> {
    /// The rigid-motion velocities at `q`: the unstrained start's, adjusted to `q`.
    fn velocities(&self, q: &[f64], qdot: &mut [f64], ws: &mut Workspace) -> Result<(), SimulationError> {
        qdot.copy_from_slice(&self.unstrained);
        follow_rigid_motion(self.model, self.t, q, qdot, ws);
        Ok(())
    }

    /// The accelerations at `q` with the rigid-motion velocities there, in `ws.accelerations`; returns the state.
    fn accelerate(&self, x: &DVector<f64>, ws: &mut Workspace) -> Result<Vec<f64>, SimulationError> {
        let layout = &self.model.layout;
        let mut y = vec![0.0; layout.len()];
        y[..layout.nq].copy_from_slice(x.as_slice());
        let (q, rest) = y.split_at_mut(layout.nq);
        self.velocities(q, &mut rest[..layout.nv], ws)?;
        rest[layout.nv..].copy_from_slice(self.z);
        accelerations(self.model, &self.memory, self.t, &y, Stabilization::None, ws)?;
        Ok(y)
    }

    fn largest_acceleration(&self, x: &DVector<f64>, ws: &mut Workspace) -> Result<f64, SimulationError> {
        self.accelerate(x, ws)?;
        Ok(ws.accelerations.iter().fold(0.0_f64, |m, a| m.max(a.abs())))
    }

    /// `[Phi; strain accelerations of each flexible body]` at positions `x`.
    fn residual(&self, x: &DVector<f64>, ws: &mut Workspace) -> Result<DVector<f64>, SimulationError> {
        let model = self.model;
        let y = self.accelerate(x, ws)?;
        let (q, v) = (&y[..model.layout.nq], &y[model.layout.nq..model.layout.nq + model.layout.nv]);
        let mut out = Vec::new();
        for &b in &self.flexible {
            let address = &model.layout.bodies[b];
            out.extend(strain_acceleration(&model.bodies[b].kind, &q[address.q_range()], v[address.v_range()][2], &ws.accelerations[address.v_range()]));
        }
        // the mechanism stays where it was put along its free motions: (free motion, q - q0) = 0 in the mass metric
        for motion in &self.free {
            out.push(self.mass_product(q, motion));
        }
        update_frames(model, q, &vec![0.0; model.layout.nv], &mut ws.frames, &mut ws.spatial_frames);
        constraint_residuals(model, model.constraints.len(), self.t, ws);
        let rows = model.row_offsets[model.constraints.len()];
        Ok(DVector::from_iterator(rows + out.len(), ws.residual[..rows].iter().copied().chain(out)))
    }

    /// `motion^T M (q - q0)` [kg m^2/s or the like], body by body from the kinetic energy
    /// (`a^T M b = T(a + b) - T(a) - T(b)`).
    fn mass_product(&self, q: &[f64], motion: &[f64]) -> f64 {
        let model = self.model;
        let mut sum = 0.0;
        for (body, address) in model.bodies.iter().zip(&model.layout.bodies) {
            let (qb, m) = (&q[address.q_range()], &motion[address.v_range()]);
            let d: Vec<f64> = qb.iter().zip(&self.assembled[address.q_range()]).map(|(a, b)| a - b).collect();
            let both: Vec<f64> = m.iter().zip(&d).map(|(a, b)| a + b).collect();
            sum += body.kind.kinetic_energy(qb, &both) - body.kind.kinetic_energy(qb, m) - body.kind.kinetic_energy(qb, &d);
        }
        sum
    }

    fn jacobian(&self, x: &DVector<f64>, r: &DVector<f64>, ws: &mut Workspace) -> Result<DMatrix<f64>, SimulationError> {
        let mut jacobian = DMatrix::zeros(r.len(), x.len());
        let mut shifted = x.clone();
        for j in 0..x.len() {
            let h = DIFFERENCE_STEP * x[j].abs().max(1e-3);
            shifted[j] = x[j] + h;
            let g = self.residual(&shifted, ws)?;
            jacobian.column_mut(j).copy_from(&((g - r) / h));
            shifted[j] = x[j];
        }
        Ok(jacobian)
    }
}

/// The accelerations `a` of a body at positions `q` turning at `angular_velocity`
/// less the rigid motion's accelerations that fit them best (least squares).
fn strain_acceleration(kind: &BodyKind, q: &[f64], angular_velocity: f64, a: &[f64]) -> Vec<f64> {
    let n = a.len();
    let mut bias = vec![0.0; n];
    kind.rigid_motion_bias_accelerations(q, angular_velocity, &mut bias);
    let mut basis = DMatrix::zeros(n, 3);
    for (k, unit) in [(Vec2::new(1.0, 0.0), 0.0), (Vec2::new(0.0, 1.0), 0.0), (Vec2::zeros(), 1.0)].into_iter().enumerate() {
        let mut column = vec![0.0; n];
        kind.rigid_motion_velocities(q, unit.0, unit.1, &mut column);
        basis.column_mut(k).copy_from_slice(&column);
    }
    let target = DVector::from_iterator(n, a.iter().zip(&bias).map(|(a, c)| a - c));
    let fit = basis.clone().svd(true, true).solve(&target, 1e-12).unwrap_or_else(|_| DVector::zeros(3));
    (target - basis * fit).iter().copied().collect()
}
