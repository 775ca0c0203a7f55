//! Reactions of the ideal joints of a tree by Newton-Euler recursion from
//! the leaves: the wrench an edge passes to its child is what the child's
//! motion needs beyond its applied forces and the wrenches of its own
//! children,
//!
//! ```text
//! W_c = M_c a_c - Q_c + sum over children k of (f_k, n_k + (r_k - r_c) x f_k)
//! ```
//!
//! (generalised at the centre of mass: force, moment about it). It is then
//! split between the joint and its driver as the absolute formulation's
//! multipliers split it: a driver takes the pure moment (revolute) or the
//! force along the axis (translational), the joint the rest, all reported
//! on the element's second body at its joint point.

use crate::dynamics::model::joint_tree::{EdgeJoint, JointTree, TreeEdge};
use crate::kinematics::planar::{cross, Frame, Vec2};
use crate::joint::IdealElement;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;

/// A wrench `(force [N], moment [N m])` acting at a point.
#[derive(Clone, Copy)]
struct Wrench {
    force: Vec2,
    moment: f64,
}

impl JointTree {
    /// Fills `ws.constraint_forces` of every ideal element of the tree from
    /// the evaluation the workspace holds (body accelerations, applied forces, frames).
    pub(crate) fn reactions(&self, model: &Model, ws: &mut Workspace) {
        let wrenches = &mut ws.joint.edge_wrenches;
        for (k, address) in model.layout.bodies.iter().enumerate() {
            let v = address.v_range();
            let (m, a, q) = (&self.mass[v.clone()], &ws.accelerations[v.clone()], &ws.generalised_force[v]);
            wrenches[k + 1] = [m[0] * a[0] - q[0], m[1] * a[1] - q[1], m[2] * a[2] - q[2]];
        }
        for edge in self.edges.iter().rev() {
            let (c, p) = (edge.child.0, edge.parent.0);
            if p != 0 {
                let w = wrenches[c];
                let d = ws.frames[c].position - ws.frames[p].position;
                wrenches[p][0] += w[0];
                wrenches[p][1] += w[1];
                wrenches[p][2] += w[2] + cross(d, Vec2::new(w[0], w[1]));
            }
        }
        for edge in &self.edges {
            let Some(joint) = edge.joint_element else { continue };
            let w = wrenches[edge.child.0];
            let (joint_force, driver_force) = split(edge, model.ideal(joint), &ws.frames, w);
            ws.constraint_forces[joint] = joint_force;
            if let Some(driver) = edge.driver_element {
                ws.constraint_forces[driver] = driver_force;
            }
        }
    }
}

/// The generalised forces `(fx, fy, moment about the centre of mass)` of the
/// joint and of its driver on the joint's second body (on the first, negated,
/// when the second is the ground: the convention of the absolute formulation),
/// from the wrench `w` the edge passes to its child.
fn split(edge: &TreeEdge, joint: &IdealElement, frames: &[Frame], w: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let child = &frames[edge.child.0];
    // the joint point: the second body's marker
    let second_is_child = joint.second == edge.child;
    let point = match &edge.joint {
        EdgeJoint::Revolute { parent_point, child_point, .. }
        | EdgeJoint::Translational { parent_point, child_point, .. }
        | EdgeJoint::Fixed { parent_point, child_point, .. } => {
            if second_is_child { child.point(*child_point) } else { frames[edge.parent.0].point(*parent_point) }
        }
        EdgeJoint::Free => return ([0.0; 3], [0.0; 3]),
    };
    let force = Vec2::new(w[0], w[1]);
    // the same wrench about the joint point, on the child
    let on_child = Wrench { force, moment: w[2] + cross(child.position - point, force) };
    let (reference, sign) = if joint.second.is_ground() { (joint.first, -1.0) } else { (joint.second, if second_is_child { 1.0 } else { -1.0 }) };
    let arm = point - frames[reference.0].position;
    let generalised = |f: Vec2, moment: f64| [sign * f.x, sign * f.y, sign * (moment + cross(arm, f))];
    match &edge.joint {
        EdgeJoint::Revolute { .. } => (generalised(on_child.force, 0.0), generalised(Vec2::zeros(), on_child.moment)),
        EdgeJoint::Translational { axis, .. } => {
            let u = frames[joint.first.0].rotate(*axis);
            let along = u * u.dot(&on_child.force);
            (generalised(on_child.force - along, on_child.moment), generalised(along, 0.0))
        }
        _ => (generalised(on_child.force, on_child.moment), [0.0; 3]),
    }
}

