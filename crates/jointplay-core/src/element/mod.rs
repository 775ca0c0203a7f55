//! Elements: everything that connects bodies or loads them (ideal joints,
//! drivers, force elements, clearance joints), under one contract
//! ([`ElementModel`], `contract.rs`) and listed once (`registry.rs`, which
//! defines [`ElementKind`] and its dispatch). Each kind lives with its
//! physics: ideal joints and the clearance joint in [`crate::joint`], springs,
//! loads and cylinders in [`crate::force`].

mod contract;
mod registry;

pub use contract::{Acceptance, ElementFault, ElementMemory, ElementModel, ElementWork, ForceOutput, OutputInfo, MAX_OUTPUTS};
pub use registry::ElementKind;

/// An element of a model: its name and its kind (which holds its parameters and markers).
#[derive(Clone, Debug)]
pub struct Element {
    /// Name (as in the model description).
    pub name: String,
    /// Kind.
    pub kind: ElementKind,
}

impl Element {
    /// The ideal joint, driver or assembly lock it is, if it is one.
    #[inline]
    pub fn ideal(&self) -> Option<&crate::joint::IdealElement> {
        match &self.kind {
            ElementKind::Ideal(ideal) => Some(ideal),
            _ => None,
        }
    }
}
