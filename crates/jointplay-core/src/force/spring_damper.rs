//! Linear translational spring-damper between two points:
//! tension `F = k (l - l0) + c l_dot`, pulling the points together.

use super::ForceOutput;
use crate::kinematics::marker::Marker;
use crate::kinematics::planar::Frame;
use crate::dynamics::GeneralisedForces;

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
    pub const CHANNELS: [super::OutputInfo; 2] = [("force", "N", "tension"), ("length", "m", "length")];

    /// Applies the tension to both points; outputs tension [N] and length [m].
    pub fn apply(&self, frames: &[Frame], forces: &mut GeneralisedForces) -> ForceOutput {
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
