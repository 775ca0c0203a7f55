//! Linear translational spring-damper between two points in space:
//! tension `F = k (l - l0) + c l_dot`, pulling the points together.

use crate::element::{ElementFault, ElementMemory, ElementModel, ElementWork, ForceOutput, OutputInfo};
use crate::dynamics::GeneralisedForces;
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::{Marker, SpatialMarker};
use crate::kinematics::wrench::Wrench;
use crate::kinematics::spatial::Vec3;

/// Point-to-point spring and damper between two markers.
#[derive(Clone, Debug, PartialEq)]
pub struct SpatialSpringDamper {
    /// Point on the first body.
    pub first: SpatialMarker,
    /// Point on the second body.
    pub second: SpatialMarker,
    /// Stiffness k [N/m].
    pub stiffness: f64,
    /// Damping coefficient c [N s/m].
    pub damping: f64,
    /// Free length l0 [m].
    pub free_length: f64,
}

impl SpatialSpringDamper {
    /// Outputs.
    pub const CHANNELS: [OutputInfo; 3] = [("force", "N", "tension"), ("length", "m", "length"), ("rate", "m/s", "rate of the length")];

    /// Applies the tension to both points; outputs tension [N], length [m] and its rate [m/s].
    pub fn load(&self, frames: &Frames<'_>, forces: &mut GeneralisedForces) -> ForceOutput {
        let (pi, pj) = (frames.point(&self.first), frames.point(&self.second));
        let d = pj - pi;
        let length = d.norm();
        let stretch = length - self.free_length;
        let potential_energy = 0.5 * self.stiffness * stretch * stretch;
        if length == 0.0 {
            return ForceOutput::new(&[0.0, 0.0, 0.0], potential_energy);
        }
        let u = d / length;
        let rate = u.dot(&(frames.point_velocity(&self.second) - frames.point_velocity(&self.first)));
        let tension = self.stiffness * stretch + self.damping * rate;
        let pull = |force: Vec3| Wrench { force, moment: Vec3::zeros() };
        forces.add_wrench(&self.first, pi, &pull(u * tension));
        forces.add_wrench(&self.second, pj, &pull(-u * tension));
        ForceOutput::new(&[tension, length, rate], potential_energy)
    }
}

impl ElementModel for SpatialSpringDamper {
    fn channels(&self) -> &'static [OutputInfo] {
        &Self::CHANNELS
    }

    fn markers(&self) -> Vec<Marker> {
        vec![self.first.planar(), self.second.planar()]
    }

    #[inline]
    fn apply(&self, frames: &Frames<'_>, _t: f64, _states: (&[f64], &mut [f64]), _memory: &[ElementMemory], work: &mut ElementWork, _detailed: bool, forces: &mut GeneralisedForces) -> Result<(), ElementFault> {
        *work.outputs_mut() = self.load(frames, forces);
        Ok(())
    }
}
