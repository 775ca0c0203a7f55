//! Joint coordinates for mechanisms whose ideal joints form a tree.
//!
//! Every clearance joint is a force element, so it cuts the loop it closes:
//! many mechanisms with clearance joints (the slider-crank with play in one
//! joint, a pendulum chain) are trees of ideal joints. Their motion is then
//! described by the joint coordinates alone (a revolute joint's relative
//! angle, a translational joint's displacement, the pose of a body free of
//! ideal joints), with no constraint equations to solve: the velocity
//! transformation `v = R(theta, t) theta_dot + v_t` maps joint rates to the
//! bodies' velocity coordinates, and the equations of motion are
//!
//! ```text
//! R^T M R theta_ddot = R^T (Q - M b),   b = R_dot theta_dot + v_t_dot
//! ```
//!
//! (the velocity-transformation form, García de Jalón and Bayo, "Kinematic
//! and Dynamic Simulation of Multibody Systems", Springer 1994, ch. 5).
//! Bodies, forces, clearance joints, channels and events keep working on the
//! bodies' frames, which forward kinematics computes from the joint state;
//! the reactions of the ideal joints come from Newton-Euler recursion from
//! the leaves. Theory: `docs/theory/planar-formulation.md`, "Joint coordinates".

mod equations;
mod kinematics;
mod reactions;

pub use equations::joint_accelerations;
pub(crate) use equations::place;
pub use crate::dynamics::model::joint_tree::{EdgeCoordinate, EdgeJoint, JointTree, TreeEdge};

/// Which form of the equations of motion a simulation integrates.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Formulation {
    /// By the measured rule of [`super::formulation_choice::choose_formulation`]: joint coordinates for a small
    /// tree of ideal joints, else absolute coordinates.
    #[default]
    Auto,
    /// Absolute coordinates of every body with constraint equations and multipliers.
    Absolute,
    /// Joint coordinates (only for a model whose ideal joints form a tree).
    JointCoordinates,
}

impl Formulation {
    /// The name used in options and results (`"auto"`, `"absolute"`, `"joint_coordinates"`).
    pub fn name(self) -> &'static str {
        match self {
            Self::Auto => "auto",
            Self::Absolute => "absolute",
            Self::JointCoordinates => "joint_coordinates",
        }
    }
}

/// Scratch of the joint-coordinate evaluation, sized once for a tree.
#[derive(Clone, Debug, Default)]
pub struct JointWorkspace {
    /// Whether the simulation integrates joint coordinates (then the reactions come from the tree).
    pub active: bool,
    /// `R`: body velocity coordinates by joint rates, row-major (`nv x n_dofs`).
    pub velocity_map: Vec<f64>,
    /// `b`: body accelerations at zero joint accelerations (`nv`) [m/s^2, rad/s^2].
    pub bias: Vec<f64>,
    /// `R^T M R`, then its `L D L^T` factor (`n_dofs x n_dofs`).
    pub mass: Vec<f64>,
    /// Joint accelerations `theta_ddot` (`n_dofs`).
    pub accelerations: Vec<f64>,
    /// Body-space state `[q, v, z]` of the last placement, laid out as the model's `StateLayout`.
    pub body_state: Vec<f64>,
    /// Wrench each body receives from its parent edge, `(fx, fy, moment about the centre of mass)`, by body index.
    pub edge_wrenches: Vec<[f64; 3]>,
}

impl JointWorkspace {
    /// Buffers for `tree` in a model with `nv` body velocity coordinates, `len` body-space
    /// state components and `n_bodies` bodies besides the ground.
    pub fn new(tree: &JointTree, nv: usize, len: usize, n_bodies: usize) -> Self {
        let n = tree.n_dofs;
        Self {
            active: false,
            velocity_map: vec![0.0; nv * n],
            bias: vec![0.0; nv],
            mass: vec![0.0; n * n],
            accelerations: vec![0.0; n],
            body_state: vec![0.0; len],
            edge_wrenches: vec![[0.0; 3]; n_bodies + 1],
        }
    }
}

#[cfg(test)]
mod tests;
