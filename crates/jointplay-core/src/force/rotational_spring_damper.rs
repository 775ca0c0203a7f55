//! Linear torsional spring-damper on the relative angle of two markers' frames
//! (of two bodies' reference frames, as the model files name them):
//! torque on the second body `T = -k (theta - theta0) - c theta_dot`,
//! `theta = phi_j - phi_i`; the first body gets `-T`.

use crate::element::{ElementFault, ElementMemory, ElementModel, ElementWork, ForceOutput, OutputInfo};
use crate::kinematics::marker::Marker;
use crate::kinematics::planar::Frame;
use crate::dynamics::GeneralisedForces;
use crate::kinematics::frames::Frames;

/// Torsional spring and damper.
#[derive(Clone, Debug, PartialEq)]
pub struct RotationalSpringDamper {
    /// Frame on the first body.
    pub first: Marker,
    /// Frame on the second body.
    pub second: Marker,
    /// Stiffness k [N m/rad].
    pub stiffness: f64,
    /// Damping c [N m s/rad].
    pub damping: f64,
    /// Relaxed relative angle theta0 [rad].
    pub free_angle: f64,
}

impl RotationalSpringDamper {
    /// Outputs.
    pub const CHANNELS: [OutputInfo; 2] = [("torque", "N m", "torque on the second body"), ("angle", "rad", "relative angle")];

    /// Applies the torque pair; outputs torque on the second body [N m] and relative angle [rad].
    pub fn load(&self, frames: &[Frame], forces: &mut GeneralisedForces) -> ForceOutput {
        let (fi, fj) = (&frames[self.first.frame], &frames[self.second.frame]);
        let theta = fj.angle - fi.angle - self.free_angle;
        let theta_dot = fj.angular_velocity - fi.angular_velocity;
        let torque = -self.stiffness * theta - self.damping * theta_dot;
        forces.add_moment(&self.second, torque);
        forces.add_moment(&self.first, -torque);
        ForceOutput::new(&[torque, theta + self.free_angle], 0.5 * self.stiffness * theta * theta)
    }
}

impl ElementModel for RotationalSpringDamper {
    fn channels(&self) -> &'static [OutputInfo] {
        &Self::CHANNELS
    }

    fn markers(&self) -> Vec<Marker> {
        vec![self.first, self.second]
    }

    #[inline]
    fn apply(&self, frames: &Frames<'_>, _t: f64, _states: (&[f64], &mut [f64]), _memory: &[ElementMemory], work: &mut ElementWork, _detailed: bool, forces: &mut GeneralisedForces) -> Result<(), ElementFault> {
        *work.outputs_mut() = self.load(frames.planar, forces);
        Ok(())
    }
}
