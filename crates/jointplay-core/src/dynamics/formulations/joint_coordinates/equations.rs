//! Equations of motion in joint coordinates: `R^T M R theta_ddot = R^T (Q - M b)`.

use crate::dynamics::model::joint_tree::{JointTree, ANY_DOFS, FIXED_DOFS_MAX};
use crate::dynamics::formulations::absolute::equations::{applied_forces, check_finite};
use crate::kinematics::planar::Frame;
use crate::element::ElementMemory;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::error::SimulationError;
use crate::linalg::ldl_solve_scaled;

impl JointTree {
    /// Writes the body-space state `[q, v, z]` (the model's `StateLayout`) of the
    /// placed `frames` and element states `z` into `out`.
    pub fn body_state(&self, model: &Model, frames: &[Frame], z: &[f64], out: &mut [f64]) {
        let (q, rest) = out.split_at_mut(model.layout.nq);
        let (v, zb) = rest.split_at_mut(model.layout.nv);
        for (k, address) in model.layout.bodies.iter().enumerate() {
            let f = &frames[k + 1];
            q[address.q_range()].copy_from_slice(&[f.position.x, f.position.y, f.angle]);
            v[address.v_range()].copy_from_slice(&[f.velocity.x, f.velocity.y, f.angular_velocity]);
        }
        zb.copy_from_slice(z);
    }
}

/// Places the bodies from the joint state `y = [theta, theta_dot, z]` at `t`:
/// the frames into `ws.frames`, the body-space state into `ws.joint.body_state`.
pub(crate) fn place(model: &Model, tree: &JointTree, t: f64, y: &[f64], ws: &mut Workspace) {
    let n = tree.n_dofs;
    tree.place(t, &y[..n], &y[n..2 * n], &mut ws.frames);
    tree.body_state(model, &ws.frames, &y[2 * n..], &mut ws.joint.body_state);
}

/// Evaluates the joint accelerations `ws.joint.accelerations` at `(t, y)`,
/// `y = [theta, theta_dot, z]`, with the bodies' frames in `ws.frames`, their
/// accelerations in `ws.accelerations`, their applied forces in
/// `ws.generalised_force` and the element state rates in
/// `ws.element_state_rates` (the body-space state `ws.joint.body_state` only
/// when the forces need it: [`JointTree::body_state`] makes it from the frames).
/// Never allocates.
pub fn joint_accelerations(model: &Model, tree: &JointTree, memory: &[ElementMemory], t: f64, y: &[f64], ws: &mut Workspace) -> Result<(), SimulationError> {
    match tree.n_dofs {
        1 => joint_accelerations_sized::<1>(model, tree, memory, t, y, ws),
        2 => joint_accelerations_sized::<2>(model, tree, memory, t, y, ws),
        3 => joint_accelerations_sized::<3>(model, tree, memory, t, y, ws),
        4 => joint_accelerations_sized::<4>(model, tree, memory, t, y, ws),
        _ => joint_accelerations_sized::<ANY_DOFS>(model, tree, memory, t, y, ws),
    }
}

/// [`joint_accelerations`] for `N` joint coordinates ([`ANY_DOFS`]: any number).
fn joint_accelerations_sized<const N: usize>(model: &Model, tree: &JointTree, memory: &[ElementMemory], t: f64, y: &[f64], ws: &mut Workspace) -> Result<(), SimulationError> {
    let n = tree.dofs::<N>();
    let (theta, rest) = y.split_at(n);
    let (theta_dot, z) = rest.split_at(n);
    tree.place_and_linearise(t, theta, theta_dot, &mut ws.frames, &mut ws.joint.velocity_map, &mut ws.joint.bias);
    // the forces read the frames; the bodies' coordinates only body forces and a
    // configuration-dependent gravity load read (samples make them when they need them)
    if model.layout.has_body_forces || ws.gravity_load.is_none() {
        let mut body = std::mem::take(&mut ws.joint.body_state);
        tree.body_state(model, &ws.frames, z, &mut body);
        let applied = applied_forces(model, memory, t, model.layout.split(&body), ws);
        ws.joint.body_state = body;
        applied?;
    } else {
        applied_forces(model, memory, t, (&[], &[], z), ws)?;
    }
    let j = &mut ws.joint;
    if N == ANY_DOFS {
        solve_reduced::<N>(tree, &j.velocity_map, &ws.generalised_force, &j.bias, &mut j.mass[..n * n], &mut j.accelerations[..n], t)?;
    } else {
        // (a local system of fixed size, which the compiler keeps in registers)
        const { assert!(N <= FIXED_DOFS_MAX, "a kernel of fixed size beyond the local system's") };
        let (mut mass, mut theta_ddot) = ([0.0; FIXED_DOFS_MAX * FIXED_DOFS_MAX], [0.0; FIXED_DOFS_MAX]);
        solve_reduced::<N>(tree, &j.velocity_map, &ws.generalised_force, &j.bias, &mut mass[..n * n], &mut theta_ddot[..n], t)?;
        j.accelerations[..n].copy_from_slice(&theta_ddot[..n]);
    }
    let (r, theta_ddot) = (&j.velocity_map, &j.accelerations[..n]);
    // the bodies' accelerations v_dot = R theta_ddot + b, checked finite as they are made
    let mut finite = true;
    if n == 0 {
        ws.accelerations.copy_from_slice(&j.bias);
        finite = ws.accelerations.iter().all(|a| a.is_finite());
    }
    for (a, (r_row, &b)) in ws.accelerations.iter_mut().zip(r.chunks_exact(n.max(1)).zip(&j.bias)) {
        *a = b + r_row.iter().zip(theta_ddot.iter()).map(|(x, y)| x * y).sum::<f64>();
        finite &= a.is_finite();
    }
    if finite {
        return Ok(());
    }
    check_finite(model, t, ws)
}

/// Forms `R^T M R` (lower triangle, into `mass`, `n x n`) and `R^T (Q - M b)`
/// (into `theta_ddot`) row by row of `R` (slices of constant length when `N`
/// is: the loops unroll), and solves for the joint accelerations `theta_ddot`.
#[inline(always)]
fn solve_reduced<const N: usize>(tree: &JointTree, r: &[f64], q: &[f64], bias: &[f64], mass: &mut [f64], theta_ddot: &mut [f64], t: f64) -> Result<(), SimulationError> {
    let n = tree.dofs::<N>();
    mass.fill(0.0);
    theta_ddot.fill(0.0);
    for (r_row, ((&m, &q), &b)) in r.chunks_exact(n.max(1)).zip(tree.mass.iter().zip(q).zip(bias)) {
        let effective = q - m * b;
        for k in 0..n {
            let mk = m * r_row[k];
            // (a large tree's R is sparse)
            if N == ANY_DOFS && mk == 0.0 {
                continue;
            }
            theta_ddot[k] += r_row[k] * effective;
            for l in 0..=k {
                mass[k * n + l] += mk * r_row[l];
            }
        }
    }
    if n == 0 {
        return Ok(());
    }
    // (scaled to a unit diagonal for the rank test: joint coordinates mix lengths and angles)
    ldl_solve_scaled(mass, n, theta_ddot).map_err(|d| SimulationError::SingularConfiguration {
        time: t,
        element: "joint coordinates".to_string(),
        cause: format!("the mass matrix of the joint coordinates is singular at coordinate {} (relative pivot {:.2e})", d.row, d.relative_pivot),
    })
}
