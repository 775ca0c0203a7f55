//! A prescribed torque on a marker's frame (a body's reference frame, as the
//! model files name it) as a function of time.

use super::ForceOutput;
use crate::kinematics::marker::Marker;
use crate::dynamics::GeneralisedForces;
use crate::motion::TimeFunction;

/// Torque `T(t)` [N m], counter-clockwise positive.
#[derive(Clone, Debug, PartialEq)]
pub struct AppliedTorque {
    /// The frame it acts on.
    pub body: Marker,
    /// Torque [N m].
    pub torque: TimeFunction,
}

impl AppliedTorque {
    /// Outputs.
    pub const CHANNELS: [super::OutputInfo; 1] = [("torque", "N m", "applied torque")];

    /// Applies the torque; outputs it [N m].
    pub fn apply(&self, t: f64, forces: &mut GeneralisedForces) -> ForceOutput {
        let torque = self.torque.sample(t).value;
        forces.add_moment(&self.body, torque);
        ForceOutput::new(&[torque], 0.0)
    }
}
