//! Force elements: springs and dampers, prescribed loads. Each adds its
//! generalised force to `Q` through [`GeneralisedForces`] (it never indexes
//! coordinates) and reports a few outputs. Gravity is a body load (`crate::body`).

mod point_force;
mod rotational_spring_damper;
mod spring_damper;
mod torque;

pub use point_force::PointForce;
pub use rotational_spring_damper::RotationalSpringDamper;
pub use spring_damper::SpringDamper;
pub use torque::AppliedTorque;

use crate::dynamics::frame::Frame;
use crate::dynamics::GeneralisedForces;

/// Outputs of one force element at one evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ForceOutput {
    /// Main force or torque of the element (spring tension [N], torque [N m], load x [N]).
    pub primary: f64,
    /// Second output (length [m], relative angle [rad], load y [N]).
    pub secondary: f64,
    /// Potential energy stored [J] (0 for non-conservative loads).
    pub potential_energy: f64,
}

/// Every kind of force element.
#[derive(Clone, Debug, PartialEq)]
pub enum ForceElement {
    /// Linear translational spring-damper between two points.
    SpringDamper(SpringDamper),
    /// Linear torsional spring-damper between two bodies.
    RotationalSpringDamper(RotationalSpringDamper),
    /// Prescribed force at a point.
    PointForce(PointForce),
    /// Prescribed torque on a body.
    Torque(AppliedTorque),
}

impl ForceElement {
    /// Adds the element's generalised force to `forces` and returns its outputs.
    pub fn apply(&self, frames: &[Frame], t: f64, forces: &mut GeneralisedForces) -> ForceOutput {
        match self {
            Self::SpringDamper(e) => e.apply(frames, forces),
            Self::RotationalSpringDamper(e) => e.apply(frames, forces),
            Self::PointForce(e) => e.apply(frames, t, forces),
            Self::Torque(e) => e.apply(t, forces),
        }
    }
}
