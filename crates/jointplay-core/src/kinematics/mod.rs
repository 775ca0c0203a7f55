//! The kinematic vocabulary every body and element speaks: poses with an
//! orientation, their velocities (twists), the loads they carry (wrenches),
//! markers and the rotation conventions.
//!
//! The vocabulary is spatial. Planar bodies keep a planar [`planar::Frame`]
//! (their fast path) and are embedded in it as Drake embeds its planar joint in a
//! 3D plant: they move in the plane `z = 0` and turn about `z`
//! ([`spatial::SpatialFrame::from_planar`]), so a spatial element works on any body.
//!
//! Conventions (`docs/theory/spatial-rigid-body.md`): a rotation matrix maps body
//! coordinates to global ones; a unit quaternion is scalar first `[w, x, y, z]`
//! (Hamilton product, active rotation, body to global).

pub mod euler;
pub mod frames;
pub mod marker;
pub mod planar;
pub mod quaternion;
pub mod spatial;
pub mod wrench;
