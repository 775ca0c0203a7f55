//! Force elements: springs and dampers, prescribed loads, hydraulic
//! cylinders. Each adds its generalised force to `Q` through
//! [`GeneralisedForces`] (it never indexes coordinates), declares its output
//! channels and reports their values; an element with continuous states
//! (the cylinder's pressures) reads them and writes their rates. Gravity is a
//! body load (`crate::body`).

mod hydraulic_cylinder;
mod point_force;
mod rotational_spring_damper;
mod spring_damper;
mod torque;

pub use hydraulic_cylinder::CylinderActuator;
pub use point_force::PointForce;
pub use rotational_spring_damper::RotationalSpringDamper;
pub use spring_damper::SpringDamper;
pub use torque::AppliedTorque;

use crate::dynamics::frame::Frame;
use crate::dynamics::GeneralisedForces;

/// Most outputs a force element reports.
pub const MAX_OUTPUTS: usize = 7;

/// One output channel of an element: quantity, unit, description.
pub type OutputInfo = (&'static str, &'static str, &'static str);

/// Outputs of one force element at one evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ForceOutput {
    /// Values in the order of [`ForceElement::channels`] (the rest unused) [SI units].
    pub values: [f64; MAX_OUTPUTS],
    /// Potential energy stored [J] (0 for non-conservative loads).
    pub potential_energy: f64,
}

impl ForceOutput {
    /// Outputs `values` (the first of them, in channel order) and `potential_energy` [J].
    pub fn new(values: &[f64], potential_energy: f64) -> Self {
        let mut all = [0.0; MAX_OUTPUTS];
        all[..values.len()].copy_from_slice(values);
        Self { values: all, potential_energy }
    }
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
    /// Hydraulic cylinder between two markers, with its chamber pressures as states.
    HydraulicCylinder(CylinderActuator),
}

impl ForceElement {
    /// Output channels: quantity, unit, description, in the order of [`ForceOutput::values`].
    pub fn channels(&self) -> &'static [OutputInfo] {
        match self {
            Self::SpringDamper(_) => &SpringDamper::CHANNELS,
            Self::RotationalSpringDamper(_) => &RotationalSpringDamper::CHANNELS,
            Self::PointForce(_) => &PointForce::CHANNELS,
            Self::Torque(_) => &AppliedTorque::CHANNELS,
            Self::HydraulicCylinder(_) => &CylinderActuator::CHANNELS,
        }
    }

    /// Number of continuous states.
    pub fn n_states(&self) -> usize {
        match self {
            Self::HydraulicCylinder(e) => e.cylinder.n_states(),
            _ => 0,
        }
    }

    /// Adds the element's generalised force to `forces`, writes the rates of its
    /// states `z` into `z_rate`, and returns its outputs.
    pub fn apply(&self, frames: &[Frame], t: f64, z: &[f64], z_rate: &mut [f64], forces: &mut GeneralisedForces) -> ForceOutput {
        match self {
            Self::SpringDamper(e) => e.apply(frames, forces),
            Self::RotationalSpringDamper(e) => e.apply(frames, forces),
            Self::PointForce(e) => e.apply(frames, t, forces),
            Self::Torque(e) => e.apply(t, forces),
            Self::HydraulicCylinder(e) => e.apply(frames, t, z, z_rate, forces),
        }
    }

    /// Why the accepted state is outside the range of the element's law, if it is.
    pub fn check(&self, frames: &[Frame], z: &[f64]) -> Result<(), String> {
        match self {
            Self::HydraulicCylinder(e) => e.check(frames, z).map_err(|fault| fault.to_string()),
            _ => Ok(()),
        }
    }

    /// Absolute-tolerance scales of the states (see `OdeSystem::absolute_tolerance_scales`).
    pub fn tolerance_scales(&self, scales: &mut [f64]) {
        if let Self::HydraulicCylinder(e) = self {
            e.tolerance_scales(scales);
        }
    }
}
