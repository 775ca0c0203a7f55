//! Reduced models of flexible bodies for the floating frame of reference:
//! the Craig-Bampton mode set of a finite-element structure
//! (`craig_bampton.rs`) for the frame's reference conditions
//! (`reference.rs`) and the inertia invariants of a body moving with its
//! frame (`invariants.rs`). The body kind is `body/modal.rs`; theory:
//! `docs/theory/modal-body.md`.

mod craig_bampton;
mod invariants;
mod reference;

pub use craig_bampton::{craig_bampton_modes, CraigBamptonModes};
pub use invariants::InertiaInvariants;
pub use reference::FrameReference;

#[cfg(test)]
mod tests;
