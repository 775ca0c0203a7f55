//! Bodies: every kind behind one contract, listed in [`BodyKind`].
//!
//! A body kind owns `nq` position and `nv` velocity coordinates (their
//! addresses in the state come from [`crate::dynamics::StateLayout`]; a kind
//! sees only its own slices) and provides:
//!
//! - the frame of a body marker (pose, velocity) from its coordinates; the
//!   velocity coordinates a marker moves with, the Jacobian of a marker point
//!   and of a marker's angle by them, and the velocity-dependent part of the
//!   marker's acceleration (what constraint rows are built from);
//! - its mass block and the solve with it ([`MassBlock`]);
//! - velocity-dependent inertial forces;
//! - the map from `v` to `q_dot`, and a position displaced by a velocity-coordinate increment;
//! - the generalised force of a point force and of a moment, and of gravity;
//! - its kinetic energy and gravitational potential, for the energy channels;
//! - how its coordinates are scaled in the integrator's error control.
//!
//! The planar rigid body (`planar_rigid.rs`) is the first kind. Theory:
//! `docs/theory/planar-formulation.md`, "Coordinates, bodies and markers".

mod planar_rigid;

pub use planar_rigid::PlanarRigidBody;

use std::ops::Range;

use crate::dynamics::frame::{Frame, Vec2};

/// The mass block of one body kind, as the equations of motion use it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MassBlock<'a> {
    /// Constant and diagonal: the entries of `M^-1` in velocity-coordinate order
    /// [1/kg, 1/(kg m^2)]. Factored once at compile time by inverting.
    ConstantDiagonal(&'a [f64]),
}

/// Every kind of body.
#[derive(Clone, Debug, PartialEq)]
pub enum BodyKind {
    /// Planar rigid body with its frame at the centre of mass, `(x, y, phi)`.
    PlanarRigid(PlanarRigidBody),
}

impl BodyKind {
    /// Number of position coordinates.
    pub fn nq(&self) -> usize {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::NQ,
        }
    }

    /// Number of velocity coordinates.
    pub fn nv(&self) -> usize {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::NV,
        }
    }

    /// Frame of the body's reference marker from its position coordinates `q`
    /// and velocity coordinates `v`, reusing the trigonometry of `previous`
    /// where the orientation did not change.
    #[inline]
    pub fn frame(&self, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::frame(q, v, previous),
        }
    }

    /// Jacobian of the global velocity of the marker point `local` [m] (body
    /// frame) by the velocity coordinates the marker moves with
    /// ([`Self::marker_coordinates`]): row x into `jx`, row y into `jy` [m/m, m/rad].
    #[inline]
    pub fn marker_jacobian(&self, frame: &Frame, local: Vec2, jx: &mut [f64], jy: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::marker_jacobian(frame, local, jx, jy),
        }
    }

    /// The velocity coordinates (counted from the body's first) that a marker
    /// at `local` [m] moves with: the width of its constraint-Jacobian block.
    /// Fixed for a marker, so the Jacobian's pattern is known at compile time.
    pub fn marker_coordinates(&self, _local: Vec2) -> Range<usize> {
        match self {
            Self::PlanarRigid(_) => 0..PlanarRigidBody::NV,
        }
    }

    /// Adds `along . d(v_P)/d(v)`, the Jacobian of the marker point's velocity
    /// projected on `along`, to the marker's block `out` (see
    /// [`Self::marker_coordinates`]) [m/m, m/rad times the unit of `along`].
    #[inline]
    pub fn add_marker_jacobian(&self, frame: &Frame, local: Vec2, along: Vec2, out: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::add_marker_jacobian(frame, local, along, out),
        }
    }

    /// Adds `scale d(omega_P)/d(v)`, the Jacobian of the marker's angular
    /// velocity, to the marker's block `out` [rad/rad times `scale`].
    #[inline]
    pub fn add_marker_angle_jacobian(&self, _local: Vec2, scale: f64, out: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => out[2] += scale,
        }
    }

    /// The marker point's acceleration at zero coordinate accelerations (the
    /// velocity-dependent part, `-omega^2 A s` for a rigid body) [m/s^2].
    #[inline]
    pub fn marker_bias_acceleration(&self, frame: &Frame, local: Vec2) -> Vec2 {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::marker_acceleration(frame, &[0.0; 3], local),
        }
    }

    /// The marker's angular acceleration at zero coordinate accelerations
    /// (zero for a rigid body) [rad/s^2].
    #[inline]
    pub fn marker_bias_angular_acceleration(&self, _frame: &Frame, _local: Vec2) -> f64 {
        match self {
            Self::PlanarRigid(_) => 0.0,
        }
    }

    /// Global acceleration [m/s^2] of the marker point `local` [m] from the
    /// body's frame and its velocity-coordinate accelerations `a`.
    #[inline]
    pub fn marker_acceleration(&self, frame: &Frame, a: &[f64], local: Vec2) -> Vec2 {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::marker_acceleration(frame, a, local),
        }
    }

    /// The mass block.
    #[inline]
    pub fn mass_block(&self) -> MassBlock<'_> {
        match self {
            Self::PlanarRigid(b) => MassBlock::ConstantDiagonal(b.inverse_mass()),
        }
    }

    /// `out = M^-1 f` over the body's velocity coordinates.
    #[inline]
    pub fn solve_mass(&self, f: &[f64], out: &mut [f64]) {
        match self.mass_block() {
            MassBlock::ConstantDiagonal(w) => {
                for ((o, w), f) in out.iter_mut().zip(w).zip(f) {
                    *o = w * f;
                }
            }
        }
    }

    /// Whether [`Self::position_rates`] is the identity `q_dot = v` (the engine then copies `v`).
    pub fn has_identity_position_rates(&self) -> bool {
        match self {
            Self::PlanarRigid(_) => true,
        }
    }

    /// Whether [`Self::add_inertial_forces`] adds anything (the engine skips it otherwise).
    pub fn has_inertial_forces(&self) -> bool {
        match self {
            Self::PlanarRigid(_) => false,
        }
    }

    /// Adds the velocity-dependent inertial forces (gyroscopic, centrifugal
    /// terms of a moving frame) to the body's generalised forces `out` [N, N m].
    #[inline]
    pub fn add_inertial_forces(&self, _q: &[f64], _v: &[f64], _out: &mut [f64]) {
        match self {
            // (frame at the centre of mass, planar: M is constant, no such terms)
            Self::PlanarRigid(_) => {}
        }
    }

    /// `q_dot` from `v` (the identity while `nq == nv`).
    #[inline]
    pub fn position_rates(&self, _q: &[f64], v: &[f64], qdot: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => qdot.copy_from_slice(v),
        }
    }

    /// Moves the positions `q` by the velocity-coordinate increment `dv` (a
    /// position correction `q + dv` where `nq == nv`).
    #[inline]
    pub fn displace(&self, q: &mut [f64], dv: &[f64]) {
        match self {
            Self::PlanarRigid(_) => {
                for (q, d) in q.iter_mut().zip(dv) {
                    *q += d;
                }
            }
        }
    }

    /// Adds the generalised force of the force `f` [N] at the global point `p` [m]
    /// to the body's generalised forces `out`.
    #[inline]
    pub fn add_point_force(&self, frame: &Frame, p: Vec2, f: Vec2, out: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::add_point_force(frame, p, f, out),
        }
    }

    /// Adds the generalised force of a moment `m` [N m] (counter-clockwise) to `out`.
    #[inline]
    pub fn add_moment(&self, m: f64, out: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::add_moment(m, out),
        }
    }

    /// Adds the generalised force of uniform gravity `g` [m/s^2] to `out`.
    #[inline]
    pub fn add_gravity(&self, g: Vec2, out: &mut [f64]) {
        match self {
            Self::PlanarRigid(b) => b.add_gravity(g, out),
        }
    }

    /// Gravitational potential energy `-m g . r_G` [J] from `q`.
    pub fn gravity_potential_energy(&self, g: Vec2, q: &[f64]) -> f64 {
        match self {
            Self::PlanarRigid(b) => b.gravity_potential_energy(g, q),
        }
    }

    /// Kinetic energy [J] from `v`.
    pub fn kinetic_energy(&self, v: &[f64]) -> f64 {
        match self {
            Self::PlanarRigid(b) => b.kinetic_energy(v),
        }
    }

    /// Scales of the position and velocity coordinates in the integrator's
    /// absolute tolerance (1 for metres, radians and their rates).
    pub fn tolerance_scales(&self, q: &mut [f64], v: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => {
                q.fill(1.0);
                v.fill(1.0);
            }
        }
    }

    /// Names, units and descriptions of the coordinates, as channel
    /// quantities: position, velocity and acceleration channels.
    pub fn coordinate_channels(&self) -> &'static [CoordinateChannels] {
        match self {
            Self::PlanarRigid(_) => &PlanarRigidBody::CHANNELS,
        }
    }
}

/// The channels of one velocity coordinate (and of the position coordinate
/// at the same place while `nq == nv`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoordinateChannels {
    /// Position: quantity, unit, description.
    pub position: (&'static str, &'static str, &'static str),
    /// Velocity: quantity, unit, description.
    pub velocity: (&'static str, &'static str, &'static str),
    /// Acceleration: quantity, unit, description.
    pub acceleration: (&'static str, &'static str, &'static str),
}

#[cfg(test)]
mod tests;
