//! The equations of motion in absolute coordinates: every body's own
//! coordinates, the constraint equations of the ideal joints and drivers
//! with their multipliers, the applied forces as generalised forces, the
//! structured Jacobian and the Newton matrix of the implicit integrators,
//! the projection onto the constraints, and the rank of the constraints.

pub(crate) mod constraint_solution;
pub(crate) mod equations;
pub(crate) mod generalised_force;
pub(crate) mod jacobian;
pub(crate) mod newton_parts;
pub(crate) mod projection;
pub(crate) mod redundancy;

#[cfg(test)]
mod jacobian_tests;
#[cfg(test)]
mod newton_parts_tests;
