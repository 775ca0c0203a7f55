//! Force elements: springs and dampers, bushings, prescribed loads and
//! hydraulic cylinders, one per file, each under the element contract
//! ([`crate::element::ElementModel`]): it adds its generalised force through
//! [`crate::dynamics::GeneralisedForces`] (it never indexes coordinates) and
//! declares its output channels; the cylinder also has continuous states (its
//! chamber pressures). Gravity is a body load (`crate::body`).

mod bushing;
mod hydraulic_cylinder;
mod point_force;
mod prescribed_load;
mod rotational_spring_damper;
mod spatial_spring_damper;
mod spring_damper;
mod torque;

pub use bushing::Bushing;
pub use hydraulic_cylinder::CylinderActuator;
pub use point_force::PointForce;
pub use prescribed_load::{LoadFrame, LoadKind, PrescribedLoad};
pub use rotational_spring_damper::RotationalSpringDamper;
pub use spatial_spring_damper::SpatialSpringDamper;
pub use spring_damper::SpringDamper;
pub use torque::AppliedTorque;
