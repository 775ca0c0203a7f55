//! Reference conditions of a floating frame: which three coordinates of the
//! structure the frame holds, so that the modes carry no rigid-body motion
//! (Shabana, *Dynamics of Multibody Systems*, Cambridge University Press, the
//! floating frame of reference and its reference conditions).
//!
//! The choice does not change the linear model's static or modal response
//! (the mode set spans the same motions), but it decides which loads couple
//! rigid motion and deformation at second order: a force along the line
//! through two pinned ends has no component across the chord frame's axis,
//! while in the tangent frame it has one proportional to the end's deflection,
//! a spurious geometric stiffness (`docs/theory/modal-body.md`).

use super::NodalCoordinates;
use serde::{Deserialize, Serialize};

/// Where a modal body's floating frame is attached.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FrameReference {
    /// Origin at the first interface node, x axis through the second: the
    /// first node's two translations and the second node's translation across
    /// the chord are held (the chord frame; the modes of a simply supported
    /// link). Right for a link pinned at two points, as a connecting rod.
    #[default]
    Chord,
    /// Origin and axes on the first interface node's position and section:
    /// its three coordinates are held (the tangent frame; cantilever modes).
    /// Right for a link clamped at one end, as a blade on a hub.
    Clamped,
}

impl FrameReference {
    /// The three held coordinates (nodal numbering of `coordinates`) for the
    /// interface nodes `interface` (the first carries the frame's origin).
    pub fn held_coordinates(self, interface: &[usize], coordinates: NodalCoordinates) -> Result<[usize; 3], String> {
        let first = *interface.first().ok_or("a modal body needs at least one interface node (the first carries its frame)")?;
        let d = coordinates.per_node();
        match self {
            Self::Clamped if coordinates == NodalCoordinates::Translations => Err(
                "a clamped frame holds the first interface node's section angle, which a structure with two coordinates per node \
                 (a plane solid) does not have: use the chord frame"
                    .to_string(),
            ),
            Self::Clamped => Ok([3 * first, 3 * first + 1, 3 * first + 2]),
            Self::Chord => match interface.get(1) {
                Some(&second) => Ok([d * first, d * first + 1, d * second + 1]),
                None => Err("a chord frame needs a second interface node (its x axis runs from the first to the second); \
                             give one, or clamp the frame at the first"
                    .to_string()),
            },
        }
    }

    /// The frame's angle in the structure's coordinates [rad], the structure's
    /// node positions `nodes` [m] and section angles `angles` [rad] given.
    pub fn frame_angle(self, interface: &[usize], nodes: &[[f64; 2]], angles: &[f64], coordinates: NodalCoordinates) -> Result<f64, String> {
        let first = interface[0];
        self.held_coordinates(interface, coordinates)?;
        match self {
            Self::Clamped => Ok(angles[first]),
            Self::Chord => {
                let (a, b) = (nodes[first], nodes[interface[1]]);
                let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                if dx.hypot(dy) == 0.0 {
                    return Err(format!("the first two interface nodes are at the same place ({}, {}) m: a chord frame needs them apart", a[0], a[1]));
                }
                Ok(dy.atan2(dx))
            }
        }
    }
}
