//! Lubricated revolute joints: the film between a journal and its bearing.
//!
//! [`film`] holds the shared conventions (geometry, kinematics, the force a
//! film model returns); each bearing model is one file; [`reynolds`] is the
//! finite-difference Reynolds solver and its force tables.

pub mod film;
pub mod reynolds;
pub mod steady;

pub use film::{BearingGeometry, FilmForce, FilmKinematics};
