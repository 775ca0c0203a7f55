//! A prescribed force at a body point, global components as functions of time.

use crate::element::{ElementFault, ElementMemory, ElementModel, ElementWork, ForceOutput, OutputInfo};
use crate::kinematics::marker::Marker;
use crate::kinematics::planar::{Frame, Vec2};
use crate::dynamics::GeneralisedForces;
use crate::kinematics::frames::Frames;
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
    pub const CHANNELS: [OutputInfo; 2] = [("fx", "N", "applied force x"), ("fy", "N", "applied force y")];

    /// Applies the force; outputs its components [N].
    pub fn load(&self, frames: &[Frame], t: f64, forces: &mut GeneralisedForces) -> ForceOutput {
        let frame = &frames[self.point.frame];
        let f = Vec2::new(self.fx.sample(t).value, self.fy.sample(t).value);
        forces.add_point_force(&self.point, frame, frame.point(self.point.local), f);
        ForceOutput::new(&[f.x, f.y], 0.0)
    }
}

impl ElementModel for PointForce {
    fn channels(&self) -> &'static [OutputInfo] {
        &Self::CHANNELS
    }

    fn markers(&self) -> Vec<Marker> {
        vec![self.point]
    }

    #[inline]
    fn apply(&self, frames: &Frames<'_>, t: f64, _states: (&[f64], &mut [f64]), _memory: &[ElementMemory], work: &mut ElementWork, _detailed: bool, forces: &mut GeneralisedForces) -> Result<(), ElementFault> {
        *work.outputs_mut() = self.load(frames.planar, t, forces);
        Ok(())
    }
}
