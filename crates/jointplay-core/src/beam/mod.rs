//! Flexible links as geometrically exact planar beams: the section
//! (`section.rs`) and the element law (`element.rs`: strains, stress
//! resultants, internal forces, tangent stiffness, consistent mass) and the
//! natural modes of a mesh (`modes.rs`).

mod element;
mod modes;
mod section;

pub use element::{BeamElement, BeamStrains, ElementOrder, MAX_ELEMENT_COORDINATES};
pub use modes::{vibration_modes, VibrationModes};
pub use section::{BeamMaterial, BeamSection, SectionShape};

#[cfg(test)]
mod tests;
