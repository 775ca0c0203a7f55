//! Modal bodies (floating frame plus Craig-Bampton modes) as the front ends describe them.

use serde::{Deserialize, Serialize};

use super::{BeamMeshSpec, BeamPointSpec, BeamSectionSpec};

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
    /// Number of fixed-interface normal modes kept.
    pub normal_modes: usize,
    /// Damping ratio of every mode of the body clamped at its frame node [-].
    pub damping_ratio: f64,
    /// Initial velocity of the frame's origin (the first interface node) [m/s].
    pub velocity: [f64; 2],
    /// Initial angular velocity of the frame [rad/s].
    pub angular_velocity: f64,
}
