//! Reduced models of flexible bodies for the floating frame of reference:
//! the Craig-Bampton mode set of a finite-element structure
//! (`craig_bampton.rs`) for the frame's reference conditions
//! (`reference.rs`), the check that a structure given by matrices is free
//! (`free_structure.rs`) and the inertia invariants of a body moving with its
//! frame (`invariants.rs`), for nodes with a section angle or without one
//! (`nodal.rs`), and the solve with its mass that factors only what is
//! constant (`mass_solve.rs`), with the products it evaluates (`dense.rs`). The body kind is `body/modal.rs`; theory:
//! `docs/theory/modal-body.md`.

mod craig_bampton;
mod dense;
mod free_structure;
mod invariants;
mod mass_solve;
mod nodal;
mod reference;

pub use craig_bampton::{craig_bampton_modes, CraigBamptonModes};
pub(crate) use dense::dot;
pub use free_structure::{check_free_structure, rigid_motions, RIGID_MOTION_TOLERANCE};
pub use invariants::InertiaInvariants;
pub use mass_solve::BodyMassSolve;
pub use nodal::NodalCoordinates;
pub use reference::FrameReference;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod mass_solve_tests;
