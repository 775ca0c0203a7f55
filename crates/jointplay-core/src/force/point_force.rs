//! A prescribed force at a body point, global components as functions of time.

use super::ForceOutput;
use crate::kinematics::marker::Marker;
use crate::kinematics::planar::{Frame, Vec2};
use crate::dynamics::GeneralisedForces;
use crate::motion::TimeFunction;

/// Force `(f_x(t), f_y(t))` [N] applied at a point.
#[derive(Clone, Debug, PartialEq)]
pub struct PointForce {
    /// Point of application.
    pub point: Marker,
    /// x component [N].
    pub fx: TimeFunction,
    /// y component [N].
    pub fy: TimeFunction,
}

impl PointForce {
    /// Outputs.
    pub const CHANNELS: [super::OutputInfo; 2] = [("fx", "N", "applied force x"), ("fy", "N", "applied force y")];

    /// Applies the force; outputs its components [N].
    pub fn apply(&self, frames: &[Frame], t: f64, forces: &mut GeneralisedForces) -> ForceOutput {
        let frame = &frames[self.point.frame];
        let f = Vec2::new(self.fx.sample(t).value, self.fy.sample(t).value);
        forces.add_point_force(&self.point, frame, frame.point(self.point.local), f);
        ForceOutput::new(&[f.x, f.y], 0.0)
    }
}
