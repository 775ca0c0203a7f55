//! Hydraulic actuators: the laws of a double-acting, single-rod cylinder.
//!
//! - [`chamber`]: the pressure of one chamber with a constant effective bulk
//!   modulus, and the energy stored in its liquid;
//! - [`HydraulicCylinder`] (`cylinder.rs`): two chambers, the piston and rod
//!   areas, and seal friction, evaluated as a force between the two
//!   attachment points with its continuous states (the two pressures and,
//!   for the LuGre seal, the bristle deflection).
//!
//! The laws know nothing of `Model`: an element that owns a cylinder supplies
//! the stroke s [m] (0 fully retracted, growing as the rod extends), its rate
//! ds/dt [m/s], the element states and the inflows, and applies the returned
//! force along the line of the two attachments. Pressures are gauge
//! (relative to the ambient pressure acting on the rod) [Pa].
//! Theory pages: `docs/theory/hydraulic-cylinder.md`, `docs/theory/friction-lugre.md`.

pub mod chamber;
mod cylinder;

pub use cylinder::{
    Chamber, CylinderEvaluation, CylinderFault, CylinderGeometry, HydraulicCylinder, DEFAULT_PRESSURE_FLOOR, MAX_STATES,
};

use crate::friction::LugreFriction;

/// Friction of the piston and rod seals, acting against the stroke rate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SealFriction {
    /// Frictionless seals.
    None,
    /// LuGre bristle law with stiction; adds the bristle deflection z [m] as a state.
    Lugre(LugreFriction),
}

impl SealFriction {
    /// Number of continuous states the seal adds to the cylinder: 0 or 1.
    pub fn n_states(&self) -> usize {
        match self {
            Self::None => 0,
            Self::Lugre(_) => 1,
        }
    }
}
