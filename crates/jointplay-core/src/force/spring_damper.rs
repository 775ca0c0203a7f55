//! Linear translational spring-damper between two points:
//! tension `F = k (l - l0) + c l_dot`, pulling the points together.

use crate::element::{ElementFault, ElementMemory, ElementModel, ElementWork, ForceOutput, OutputInfo};
use crate::kinematics::marker::Marker;
use crate::kinematics::planar::Frame;
use crate::dynamics::GeneralisedForces;
use crate::kinematics::frames::Frames;

/// Point-to-point spring and damper.
#[derive(Clone, Debug, PartialEq)]
pub struct SpringDamper {
    /// Point on the first body.
    pub first: Marker,
    /// Point on the second body.
    pub second: Marker,
    /// Stiffness k [N/m].
    pub stiffness: f64,
    /// Damping coefficient c [N s/m].
    pub damping: f64,
    /// Free length l0 [m].
    pub free_length: f64,
}

impl SpringDamper {
    /// Outputs.
    pub const CHANNELS: [OutputInfo; 2] = [("force", "N", "tension"), ("length", "m", "length")];

    /// Applies the tension to both points; outputs tension [N] and length [m].
    pub fn load(&self, frames: &[Frame], forces: &mut GeneralisedForces) -> ForceOutput {
        let (fi, fj) = (&frames[self.first.frame], &frames[self.second.frame]);
        let (pi, pj) = (fi.point(self.first.local), fj.point(self.second.local));
        let d = pj - pi;
        let length = d.norm();
        let stretch = length - self.free_length;
        let potential_energy = 0.5 * self.stiffness * stretch * stretch;
        if length == 0.0 {
            return ForceOutput::new(&[0.0, 0.0], potential_energy);
        }
        let u = d / length;
        let length_rate = u.dot(&(fj.point_velocity(self.second.local) - fi.point_velocity(self.first.local)));
        let tension = self.stiffness * stretch + self.damping * length_rate;
        forces.add_point_force(&self.first, fi, pi, u * tension);
        forces.add_point_force(&self.second, fj, pj, -u * tension);
        ForceOutput::new(&[tension, length], potential_energy)
    }
}

impl ElementModel for SpringDamper {
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
