//! Forward kinematics over the tree: body frames from the joint state, the
//! velocity transformation `R` and the bias accelerations `b`, edge by edge
//! from the ground out; and the joint state of given body frames.
//!
//! For an edge from parent `p` to child `c` with `d = r_c - r_p` and joint
//! rate `s_dot` along the joint's motion `h` (a revolute joint turns the child
//! about the joint point `P`: `h = sigma (perp(r_c - P), 1)`; a translational
//! joint slides it along the axis `u`: `h = (+-u, 0)`):
//!
//! ```text
//! v_c     = v_p + omega_p perp(d) + h s_dot,            omega_c = omega_p + h_omega s_dot
//! a_c     = a_p + alpha_p perp(d) + omega_p perp(d_dot) + h_dot s_dot + h s_ddot
//! ```
//!
//! with `h_dot = sigma perp(v_c - v_P)` for the revolute joint and
//! `+-omega perp(u)` for the translational one. `s` is the joint's relative
//! coordinate; a free revolute joint's state coordinate is the child's
//! absolute angle, so its `s_dot` is `sigma (theta_dot_k - omega_p)`.

use crate::dynamics::model::joint_tree::{EdgeCoordinate, EdgeJoint, JointTree, TreeEdge, ANY_DOFS};
use crate::kinematics::planar::{perp, Frame, Vec2};

/// The joint's relative coordinate `s` (revolute: `phi_second - phi_first`),
/// its rate and, when driven, its acceleration at `t`. The coordinate of a
/// free revolute joint is the child's absolute angle (so that its size, which
/// the relative error control sees, does not grow with the turns of the parent);
/// its relative value comes from the parent's frame.
#[inline(always)]
fn coordinate(edge: &TreeEdge, parent: &Frame, t: f64, theta: &[f64], theta_dot: &[f64]) -> (f64, f64, f64) {
    match &edge.coordinate {
        EdgeCoordinate::Dofs(k) => match edge.joint {
            EdgeJoint::Revolute { sign, .. } => (sign * (theta[*k] - parent.angle), sign * (theta_dot[*k] - parent.angular_velocity), 0.0),
            _ => (theta[*k], theta_dot[*k], 0.0),
        },
        EdgeCoordinate::Driven(f) => {
            let s = f.sample(t);
            (s.value, s.rate, s.acceleration)
        }
        EdgeCoordinate::Locked => (0.0, 0.0, 0.0),
    }
}

/// Frame at `angle` with zero position and velocities, taking sine and cosine
/// from `previous` when its angle is bit for bit the same (a body whose angle
/// is locked, or unchanged between evaluations).
#[inline(always)]
fn turned(previous: &Frame, angle: f64, angular_velocity: f64) -> Frame {
    let (sin, cos) = if previous.angle.to_bits() == angle.to_bits() { (previous.sin, previous.cos) } else { angle.sin_cos() };
    Frame { position: Vec2::zeros(), angle, cos, sin, velocity: Vec2::zeros(), angular_velocity }
}

/// The motion `h = (h_lin, h_omega)` of a one-coordinate joint and its rate `h_dot`
/// (linear part only; `h_omega` is constant), at the placed child frame.
#[inline(always)]
fn joint_motion(edge: &TreeEdge, parent: &Frame, child: &Frame) -> (Vec2, f64, Vec2) {
    match &edge.joint {
        EdgeJoint::Revolute { parent_point, sign, .. } => {
            let p = parent.point(*parent_point);
            let v_p = parent.point_velocity(*parent_point);
            (perp(child.position - p) * *sign, *sign, perp(child.velocity - v_p) * *sign)
        }
        EdgeJoint::Translational { axis, parent_is_first, .. } => {
            let (first, sign) = if *parent_is_first { (parent, 1.0) } else { (child, -1.0) };
            let u = first.rotate(*axis);
            (u * sign, 0.0, perp(u) * (sign * first.angular_velocity))
        }
        EdgeJoint::Fixed { .. } | EdgeJoint::Free => (Vec2::zeros(), 0.0, Vec2::zeros()),
    }
}

/// Places the child of `edge`: its frame from the parent frame and the joint's
/// coordinate `s` and rate `s_dot` (`previous`: the child's last frame).
#[inline(always)]
fn place_child(edge: &TreeEdge, parent: &Frame, previous: &Frame, theta: &[f64], theta_dot: &[f64], (s, s_dot): (f64, f64)) -> Frame {
    match &edge.joint {
        EdgeJoint::Free => {
            let EdgeCoordinate::Dofs(k) = edge.coordinate else { unreachable!("a free body has three coordinates") };
            let mut child = turned(previous, theta[k + 2], theta_dot[k + 2]);
            child.position = Vec2::new(theta[k], theta[k + 1]);
            child.velocity = Vec2::new(theta_dot[k], theta_dot[k + 1]);
            child
        }
        EdgeJoint::Revolute { parent_point, child_point, sign } => {
            let p = parent.point(*parent_point);
            let omega = parent.angular_velocity + sign * s_dot;
            let mut child = turned(previous, parent.angle + sign * s, omega);
            child.position = p - child.rotate(*child_point);
            let d = child.position - parent.position;
            child.velocity = parent.velocity + perp(d) * parent.angular_velocity + perp(child.position - p) * (sign * s_dot);
            child
        }
        EdgeJoint::Translational { parent_point, child_point, axis, parent_is_first, relative_angle } => {
            let sign = if *parent_is_first { 1.0 } else { -1.0 };
            let mut child = turned(previous, parent.angle + sign * relative_angle, parent.angular_velocity);
            let u = if *parent_is_first { parent.rotate(*axis) } else { child.rotate(*axis) };
            child.position = parent.point(*parent_point) + u * (sign * s) - child.rotate(*child_point);
            let d = child.position - parent.position;
            child.velocity = parent.velocity + perp(d) * parent.angular_velocity + u * (sign * s_dot);
            child
        }
        EdgeJoint::Fixed { parent_point, child_point, relative_angle } => {
            let mut child = turned(previous, parent.angle + relative_angle, parent.angular_velocity);
            child.position = parent.point(*parent_point) - child.rotate(*child_point);
            child.velocity = parent.velocity + perp(child.position - parent.position) * parent.angular_velocity;
            child
        }
    }
}

impl JointTree {
    /// Frames of all bodies (index 0, the ground, untouched) from the joint state at `t`.
    pub fn place(&self, t: f64, theta: &[f64], theta_dot: &[f64], frames: &mut [Frame]) {
        for edge in &self.edges {
            let parent = frames[edge.parent.0];
            let (s, s_dot, _) = coordinate(edge, &parent, t, theta, theta_dot);
            frames[edge.child.0] = place_child(edge, &parent, &frames[edge.child.0], theta, theta_dot, (s, s_dot));
        }
    }

    /// [`JointTree::place`], and the velocity transformation `R` (`velocity_map`,
    /// row-major `nv x n_dofs`) and the bias accelerations `b` (`nv`) of the bodies'
    /// velocity coordinates `(vx, vy, omega)` (three per body, in body order).
    pub fn place_and_linearise(&self, t: f64, theta: &[f64], theta_dot: &[f64], frames: &mut [Frame], velocity_map: &mut [f64], bias: &mut [f64]) {
        match self.n_dofs {
            1 => self.place_and_linearise_sized::<1>(t, theta, theta_dot, frames, velocity_map, bias),
            2 => self.place_and_linearise_sized::<2>(t, theta, theta_dot, frames, velocity_map, bias),
            3 => self.place_and_linearise_sized::<3>(t, theta, theta_dot, frames, velocity_map, bias),
            4 => self.place_and_linearise_sized::<4>(t, theta, theta_dot, frames, velocity_map, bias),
            _ => self.place_and_linearise_sized::<ANY_DOFS>(t, theta, theta_dot, frames, velocity_map, bias),
        }
    }

    /// [`JointTree::place_and_linearise`] for `N` joint coordinates ([`ANY_DOFS`]: any number).
    fn place_and_linearise_sized<const N: usize>(&self, t: f64, theta: &[f64], theta_dot: &[f64], frames: &mut [Frame], velocity_map: &mut [f64], bias: &mut [f64]) {
        let n = self.dofs::<N>();
        for edge in &self.edges {
            let parent = frames[edge.parent.0];
            let (s, s_dot, mut s_ddot) = coordinate(edge, &parent, t, theta, theta_dot);
            let child = place_child(edge, &parent, &frames[edge.child.0], theta, theta_dot, (s, s_dot));
            frames[edge.child.0] = child;
            let d = child.position - parent.position;
            // rows of the child: the parent's rows carried rigidly, then the joint's own column
            let (parent_rows, rows) = rows_of(velocity_map, edge, n);
            let (row_x, rest) = rows.split_at_mut(n);
            let (row_y, row_omega) = rest.split_at_mut(n);
            let (bias_parent, bias_child) = bias_of(bias, edge);
            let mut alpha = 0.0;
            match (parent_rows, bias_parent) {
                (Some(parent_rows), Some(bias_parent)) => {
                    let (parent_x, rest) = parent_rows.split_at(n);
                    let (parent_y, parent_omega) = rest.split_at(n);
                    for k in 0..n {
                        let omega = parent_omega[k];
                        row_x[k] = parent_x[k] - d.y * omega;
                        row_y[k] = parent_y[k] + d.x * omega;
                        row_omega[k] = omega;
                    }
                    let w = parent.angular_velocity;
                    alpha = bias_parent[2];
                    let carried = Vec2::new(bias_parent[0], bias_parent[1]) + perp(d) * alpha + perp(child.velocity - parent.velocity) * w;
                    bias_child.copy_from_slice(&[carried.x, carried.y, alpha]);
                }
                _ => {
                    row_x.fill(0.0);
                    row_y.fill(0.0);
                    row_omega.fill(0.0);
                    bias_child.fill(0.0);
                }
            }
            let (h, h_omega, h_dot) = joint_motion(edge, &parent, &child);
            match &edge.coordinate {
                EdgeCoordinate::Dofs(k) if edge.joint == EdgeJoint::Free => {
                    row_x[*k] = 1.0;
                    row_y[k + 1] = 1.0;
                    row_omega[k + 2] = 1.0;
                }
                EdgeCoordinate::Dofs(k) if matches!(edge.joint, EdgeJoint::Revolute { .. }) => {
                    // s_dot = sigma (theta_dot_k - omega_p): h sigma times (e_k - the parent's omega row);
                    // the child's omega row holds the parent's (zero on the ground)
                    let sigma = h_omega;
                    for l in 0..n {
                        let rate = sigma * (f64::from(u8::from(l == *k)) - row_omega[l]);
                        row_x[l] += h.x * rate;
                        row_y[l] += h.y * rate;
                        row_omega[l] += h_omega * rate;
                    }
                    // and s_ddot = -sigma alpha_p at zero joint accelerations
                    if !edge.parent.is_ground() {
                        s_ddot = -sigma * alpha;
                    }
                }
                EdgeCoordinate::Dofs(k) => {
                    row_x[*k] += h.x;
                    row_y[*k] += h.y;
                    row_omega[*k] += h_omega;
                }
                EdgeCoordinate::Driven(_) | EdgeCoordinate::Locked => {}
            }
            let extra = h_dot * s_dot + h * s_ddot;
            bias_child[0] += extra.x;
            bias_child[1] += extra.y;
            bias_child[2] += h_omega * s_ddot;
        }
    }

    /// The joint state `(theta, theta_dot)` of body frames that satisfy the joints
    /// (an assembled state), the inverse of [`JointTree::place`].
    pub fn joint_state(&self, frames: &[Frame], theta: &mut [f64], theta_dot: &mut [f64]) {
        for edge in &self.edges {
            let EdgeCoordinate::Dofs(k) = edge.coordinate else { continue };
            let (parent, child) = (&frames[edge.parent.0], &frames[edge.child.0]);
            match &edge.joint {
                EdgeJoint::Free => {
                    theta[k..k + 3].copy_from_slice(&[child.position.x, child.position.y, child.angle]);
                    theta_dot[k..k + 3].copy_from_slice(&[child.velocity.x, child.velocity.y, child.angular_velocity]);
                }
                EdgeJoint::Revolute { .. } => {
                    theta[k] = child.angle;
                    theta_dot[k] = child.angular_velocity;
                }
                EdgeJoint::Translational { parent_point, child_point, axis, parent_is_first, .. } => {
                    let (first, second, first_point, second_point) =
                        if *parent_is_first { (parent, child, parent_point, child_point) } else { (child, parent, child_point, parent_point) };
                    let u = first.rotate(*axis);
                    let d = second.point(*second_point) - first.point(*first_point);
                    let d_dot = second.point_velocity(*second_point) - first.point_velocity(*first_point);
                    theta[k] = u.dot(&d);
                    theta_dot[k] = u.dot(&d_dot) + perp(u).dot(&d) * first.angular_velocity;
                }
                EdgeJoint::Fixed { .. } => {}
            }
        }
    }
}

/// The three rows (`x`, `y`, `omega`, each of `n` columns) of the velocity map
/// of the parent of `edge` (none for the ground) and of its child.
#[inline(always)]
fn rows_of<'m>(map: &'m mut [f64], edge: &TreeEdge, n: usize) -> (Option<&'m [f64]>, &'m mut [f64]) {
    let c = JointTree::body_offset(edge.child) * n;
    if edge.parent.is_ground() {
        return (None, &mut map[c..c + 3 * n]);
    }
    let p = JointTree::body_offset(edge.parent) * n;
    if p < c {
        let (before, after) = map.split_at_mut(c);
        (Some(&before[p..p + 3 * n]), &mut after[..3 * n])
    } else {
        let (before, after) = map.split_at_mut(p);
        (Some(&after[..3 * n]), &mut before[c..c + 3 * n])
    }
}

/// The bias accelerations of the parent of `edge` (none for the ground) and of its child.
#[inline(always)]
fn bias_of<'b>(bias: &'b mut [f64], edge: &TreeEdge) -> (Option<&'b [f64]>, &'b mut [f64]) {
    rows_of(bias, edge, 1)
}
