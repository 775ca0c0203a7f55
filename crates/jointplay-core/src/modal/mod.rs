//! Reduced models of flexible bodies for the floating frame of reference:
//! the Craig-Bampton mode set of a finite-element structure
//! (`craig_bampton.rs`) and the inertia invariants of a body moving with its
//! frame (`invariants.rs`). The body kind is `body/modal.rs`; theory:
//! `docs/theory/modal-body.md`.

mod craig_bampton;
mod invariants;

pub use craig_bampton::{craig_bampton_modes, CraigBamptonModes};
pub use invariants::InertiaInvariants;

#[cfg(test)]
mod tests;
