//! Modal bodies (floating frame plus Craig-Bampton modes) as the front ends describe them.

use serde::{Deserialize, Serialize};

use super::{BeamMeshSpec, BeamSectionSpec};
use crate::modal::FrameReference;

/// A modal body: the structure it is reduced from (a straight beam of
/// jointplay's own elements, or matrices from another finite-element code),
/// Craig-Bampton modes for its interface nodes, modal damping.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModalBodySpec {
    /// Name, unique in the model (bodies, beams and modal bodies share names).
    pub name: String,
    /// The structure reduced, in its unstressed state.
    pub structure: ModalStructureSpec,
    /// Interface nodes, named; the first carries the body's frame. Joints attach here.
    pub interface: Vec<ModalPointSpec>,
    /// Other named nodes: markers for forces and sensors, and where strain gauges read.
    pub points: Vec<ModalPointSpec>,
    /// The frame's reference conditions; `None`: a chord frame with two or
    /// more interface nodes, the frame clamped at the only one otherwise.
    #[serde(default)]
    pub frame: Option<FrameReference>,
    /// Number of fixed-interface normal modes kept.
    pub normal_modes: usize,
    /// Damping ratio of every mode of the body held at its frame's reference conditions [-].
    pub damping_ratio: f64,
    /// Retardation time of stiffness-proportional damping, added to the modal
    /// damping (a beam's strain-rate damping of the same time, linearised) [s].
    pub damping_time: f64,
    /// Initial velocity of the frame's origin (the first interface node) [m/s];
    /// with `angular_velocity`, the rigid motion the body starts in (modal
    /// rates zero), held and checked against the joints. Neither given: the
    /// rigid motion the assembled mechanism gives the body.
    #[serde(default)]
    pub velocity: Option<[f64; 2]>,
    /// Initial angular velocity of the frame [rad/s] (see `velocity`).
    #[serde(default)]
    pub angular_velocity: Option<f64>,
}

/// The structure a modal body is reduced from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "from", rename_all = "snake_case", deny_unknown_fields)]
pub enum ModalStructureSpec {
    /// A straight beam of jointplay's elements: its consistent mass and linear
    /// stiffness in the unstressed state. Its points are given by arclength.
    Beam {
        /// Initial position of the beam's first end [m].
        start: [f64; 2],
        /// Initial position of the beam's second end [m].
        end: [f64; 2],
        /// Cross-section.
        section: BeamSectionSpec,
        /// Division of the beam into elements (before the reduction).
        mesh: BeamMeshSpec,
    },
    /// Mass and stiffness matrices of a planar structure from another
    /// finite-element code, with its nodes. Its points are given by node.
    Matrices(StructureMatricesSpec),
}

/// A planar finite-element structure given by its matrices: coordinates
/// `(u_x, u_y, theta)` of node 0, then node 1, ..., in the structure's own axes,
/// which the model places by `position` and `angle`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StructureMatricesSpec {
    /// Mass matrix [kg, kg m, kg m^2].
    pub mass: SparseMatrixSpec,
    /// Stiffness matrix of the free (unsupported) structure [N/m, N/rad, N m/rad].
    pub stiffness: SparseMatrixSpec,
    /// Position of every node in the structure's axes [m].
    pub nodes: Vec<[f64; 2]>,
    /// Where the origin of the structure's axes is in the model at the start [m].
    pub position: [f64; 2],
    /// Angle of the structure's axes in the model at the start [rad].
    pub angle: f64,
}

/// A square matrix by its entries (coordinate format; repeated entries add up,
/// as in finite-element assembly). Both triangles of a symmetric matrix are given.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SparseMatrixSpec {
    /// Number of rows and of columns.
    pub size: usize,
    /// Row of each entry (from 0).
    pub rows: Vec<usize>,
    /// Column of each entry (from 0).
    pub columns: Vec<usize>,
    /// Value of each entry.
    pub values: Vec<f64>,
}

/// A named point of a modal body, at a node of its structure: by arclength
/// from the first end for a beam, by node number for a structure given by matrices.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModalPointSpec {
    /// Name, unique within the body.
    pub name: String,
    /// Arclength from the first end along the unstressed beam [m] (beam structures).
    #[serde(default)]
    pub arclength: Option<f64>,
    /// Node number, from 0 in the order of the structure's nodes (structures given by matrices).
    #[serde(default)]
    pub node: Option<usize>,
}
