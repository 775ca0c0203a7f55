//! Lubricated revolute joints: the film between a journal and its bearing.
//!
//! [`film`] holds the shared conventions (geometry, kinematics, the force a
//! film model returns); each bearing model is one file; [`reynolds`] is the
//! finite-difference Reynolds solver and its force tables.

pub mod closed_form;
pub mod film;
pub mod frene;
pub mod hamrock;
pub mod line_of_centres;
pub mod pinkus_sternlicht;
pub mod reference_closed_forms;
pub mod reynolds;
pub mod squeeze_film;
pub mod steady;
pub mod transition;

pub use film::{BearingGeometry, FilmForce, FilmKinematics};

#[cfg(test)]
mod cross_check_tests;
