//! A prescribed torque on a marker's frame (a body's reference frame, as the
//! model files name it) as a function of time.

use crate::element::{ElementFault, ElementMemory, ElementModel, ElementWork, ForceOutput, OutputInfo};
use crate::kinematics::marker::Marker;
use crate::dynamics::GeneralisedForces;
use crate::kinematics::frames::Frames;
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
    pub const CHANNELS: [OutputInfo; 1] = [("torque", "N m", "applied torque")];

    /// Applies the torque; outputs it [N m].
    pub fn load(&self, t: f64, forces: &mut GeneralisedForces) -> ForceOutput {
        let torque = self.torque.sample(t).value;
        forces.add_moment(&self.body, torque);
        ForceOutput::new(&[torque], 0.0)
    }
}

impl ElementModel for AppliedTorque {
    fn channels(&self) -> &'static [OutputInfo] {
        &Self::CHANNELS
    }

    fn markers(&self) -> Vec<Marker> {
        vec![self.body]
    }

    #[inline]
    fn apply(&self, _frames: &Frames<'_>, t: f64, _states: (&[f64], &mut [f64]), _memory: &[ElementMemory], work: &mut ElementWork, _detailed: bool, forces: &mut GeneralisedForces) -> Result<(), ElementFault> {
        *work.outputs_mut() = self.load(t, forces);
        Ok(())
    }
}
