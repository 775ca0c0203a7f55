//! Scratch buffers reused by every evaluation so that the right-hand side
//! never allocates.

use crate::kinematics::frames::Frames;
use crate::kinematics::spatial::SpatialFrame;
use crate::body::BodyModel;
use crate::kinematics::planar::Frame;
use crate::dynamics::formulations::absolute::jacobian::StructuredJacobian;
use super::joint_coordinates::JointWorkspace;
use crate::dynamics::model::mechanism::Model;
use crate::element::{ElementModel, ElementWork};

/// Buffers sized once for a model.
#[derive(Clone, Debug)]
pub struct Workspace {
    /// Frames of the ground (index 0) and every body.
    pub frames: Vec<Frame>,
    /// Frames the event functions work in (only `Model::event_bodies` are kept current).
    pub event_frames: Vec<Frame>,
    /// The spatial frames of the same (ground, bodies, sections), kept only in a
    /// model with spatial elements or bodies (empty otherwise).
    pub spatial_frames: Vec<SpatialFrame>,
    /// Spatial frames the event functions work in (a model with spatial elements; only `Model::event_bodies` and the sections are kept current).
    pub event_spatial_frames: Vec<SpatialFrame>,
    /// Generalised applied force `Q` over the velocity coordinates.
    pub generalised_force: Vec<f64>,
    /// The generalised force of gravity alone when it does not depend on the
    /// configuration (no modal body), formed once for the run.
    pub gravity_load: Option<Vec<f64>>,
    /// Values of the constraint Jacobian `Phi_q`, block by block (all rows including
    /// assembly locks; the pattern is `Model::jacobian_pattern`).
    pub jacobian: Vec<f64>,
    /// `M_c^-1 J_c^T` of every Jacobian block over its body's velocity coordinates.
    pub jacobian_solved: Vec<f64>,
    /// One body's velocity coordinates (the widest body).
    pub mass_scratch: Vec<f64>,
    /// A configuration-dependent mass block formed and factored in place (the largest body's).
    pub mass_matrix: Vec<f64>,
    /// Constraint residuals `Phi`.
    pub residual: Vec<f64>,
    /// Velocity right-hand side `nu`.
    pub nu: Vec<f64>,
    /// Acceleration right-hand side `gamma`.
    pub gamma: Vec<f64>,
    /// `Phi_q M^-1 Phi_q^T`, then its factor (`m (m + 1)` values for m rows, see `linalg::PatternLdl`).
    pub schur: Vec<f64>,
    /// `Phi_q M^-1 Phi_q^T` (`m x m`), diagonalised in place on the singular path.
    pub schur_matrix: Vec<f64>,
    /// Its eigenvalues on the singular path.
    pub schur_eigenvalues: Vec<f64>,
    /// How the factor in `schur` was made.
    pub(crate) factor_kind: super::constraint_solution::FactorKind,
    /// Scratch of the singular path's solve (`m`).
    pub solve_scratch: Vec<f64>,
    /// Factorisations that took the singular path (dependent equations) so far.
    pub singular_solves: usize,
    /// Time [s] and row count for which `schur` holds the factor at
    /// `factored_positions`; cleared whenever the Jacobian is linearised anew.
    pub factored_at: Option<(f64, usize)>,
    /// Coordinates `q` of that factor.
    pub factored_positions: Vec<f64>,
    /// Lagrange multipliers `lambda`.
    pub multipliers: Vec<f64>,
    /// Accelerations of the velocity coordinates `v_dot`.
    pub accelerations: Vec<f64>,
    /// Rates of the continuous element states `z_dot` [Pa/s, ...].
    pub element_state_rates: Vec<f64>,
    /// Scratch vector of velocity length.
    pub scratch: Vec<f64>,
    /// A projection's correction `M^-1 Phi_q^T lambda` in velocity coordinates.
    pub correction: Vec<f64>,
    /// Copy of the state for an output sample, projected before it is recorded.
    pub sample: Vec<f64>,
    /// Whether this evaluation is for a recorded sample (outputs that only samples need are computed).
    pub detailed: bool,
    /// Last evaluation and scratch of each force element (clearance joints included).
    pub element_work: Vec<ElementWork>,
    /// Constraint force `(fx [N], fy [N], moment about the centre of mass [N m])`
    /// of each element on its second body at the last recorded sample.
    pub constraint_forces: Vec<[f64; 3]>,
    /// Scratch of the joint-coordinate formulation (empty when the model is no tree).
    pub joint: JointWorkspace,
    /// The structure and buffers of the structured Jacobian, made at its first use.
    pub(crate) structured_jacobian: Option<Box<StructuredJacobian>>,
}

impl Workspace {
    /// The planar and spatial frames of the last evaluation.
    #[inline]
    pub fn frames(&self) -> Frames<'_> {
        Frames { planar: &self.frames, spatial: &self.spatial_frames }
    }

    /// Buffers for `model`.
    pub fn new(model: &Model) -> Self {
        let n = model.n_velocities();
        let m = model.n_assembly_equations();
        Self {
            frames: vec![Frame::GROUND; model.n_frames()],
            event_frames: vec![Frame::GROUND; model.n_frames()],
            spatial_frames: vec![SpatialFrame::GROUND; if model.spatial { model.n_frames() } else { 0 }],
            event_spatial_frames: vec![SpatialFrame::GROUND; if model.spatial { model.n_frames() } else { 0 }],
            generalised_force: vec![0.0; n],
            gravity_load: constant_gravity_load(model),
            jacobian: vec![0.0; model.jacobian_pattern.n_values()],
            jacobian_solved: vec![0.0; model.jacobian_pattern.n_solved()],
            mass_scratch: vec![0.0; model.layout.bodies.iter().map(|b| b.nv).max().unwrap_or(0)],
            mass_matrix: vec![0.0; model.bodies.iter().map(|b| b.kind.mass_scratch_len()).max().unwrap_or(0)],
            residual: vec![0.0; m],
            nu: vec![0.0; m],
            gamma: vec![0.0; m],
            schur: vec![0.0; m * (m + 1)],
            schur_matrix: vec![0.0; m * m],
            schur_eigenvalues: vec![0.0; m],
            factor_kind: super::constraint_solution::FactorKind::Dense,
            solve_scratch: vec![0.0; m],
            singular_solves: 0,
            factored_at: None,
            factored_positions: vec![0.0; model.layout.nq],
            multipliers: vec![0.0; m],
            accelerations: vec![0.0; n],
            scratch: vec![0.0; n],
            correction: vec![0.0; n],
            sample: vec![0.0; model.layout.len()],
            element_state_rates: vec![0.0; model.layout.nz],
            detailed: false,
            element_work: model.elements.iter().map(|e| e.kind.new_work()).collect(),
            constraint_forces: vec![[0.0; 3]; model.elements.len()],
            joint: match &model.joint_tree {
                Ok(tree) => JointWorkspace::new(tree, n, model.layout.len(), model.bodies.len()),
                Err(_) => JointWorkspace::default(),
            },
            structured_jacobian: None,
        }
    }
}

/// The generalised force of gravity when no body's depends on its configuration.
fn constant_gravity_load(model: &Model) -> Option<Vec<f64>> {
    if !model.bodies.iter().all(|b| b.kind.gravity_load_is_constant()) {
        return None;
    }
    let mut load = vec![0.0; model.n_velocities()];
    let q = vec![0.0; model.layout.nq];
    for (body, address) in model.bodies.iter().zip(&model.layout.bodies) {
        body.kind.add_gravity(model.gravity, &q[address.q_range()], &mut load[address.v_range()]);
    }
    Some(load)
}
