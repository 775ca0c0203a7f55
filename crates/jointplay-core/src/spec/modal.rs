//! Modal bodies (floating frame plus Craig-Bampton modes) as the front ends describe them.

use serde::{Deserialize, Serialize};

use super::{BeamMeshSpec, BeamPointSpec, BeamSectionSpec};
use crate::modal::FrameReference;

/// A modal body reduced from a straight beam of jointplay's own elements:
/// the beam's consistent mass and linear stiffness in its unstressed state,
/// Craig-Bampton modes for the interface nodes, modal damping.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModalBodySpec {
    /// Name, unique in the model (bodies, beams and modal bodies share names).
    pub name: String,
    /// Initial position of the beam's first end [m].
    pub start: [f64; 2],
    /// Initial position of the beam's second end [m].
    pub end: [f64; 2],
    /// Cross-section.
    pub section: BeamSectionSpec,
    /// Division of the beam into elements (before the reduction).
    pub mesh: BeamMeshSpec,
    /// Interface nodes, named points by arclength from the first end (each at a
    /// node of the mesh); the first carries the body's frame. Joints attach here.
    pub interface: Vec<BeamPointSpec>,
    /// Other named points, each at a node of the mesh (by arclength from the
    /// first end): markers for forces and sensors, and where strain gauges read.
    pub points: Vec<BeamPointSpec>,
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
    /// Initial velocity of the frame's origin (the first interface node) [m/s].
    pub velocity: [f64; 2],
    /// Initial angular velocity of the frame [rad/s].
    pub angular_velocity: f64,
}
