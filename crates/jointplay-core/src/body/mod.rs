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
//! - its mass block and the solve with it ([`MassBlock`]), at the body's
//!   positions (a modal body's mass depends on them);
//! - velocity-dependent inertial forces;
//! - the map from `v` to `q_dot`, and a position displaced by a velocity-coordinate increment;
//! - the generalised force of a point force and of a moment, and of gravity;
//! - its kinetic energy and gravitational potential, for the energy channels;
//! - how its coordinates are scaled in the integrator's error control.
//!
//! A marker's frame sits at a [`Site`] of its body: the body's reference
//! frame, (on a beam) a section interpolated from one element's nodes, or
//! (on a modal body) a node of its structure.
//!
//! Kinds: the planar rigid body (`planar_rigid.rs`), the geometrically
//! exact beam (`beam.rs`) and the modal body (`modal.rs`, floating frame plus
//! Craig-Bampton modes). Theory: `docs/theory/planar-formulation.md`,
//! "Coordinates, bodies and markers", `docs/theory/beam.md` and
//! `docs/theory/modal-body.md`.

mod beam;
mod modal;
mod planar_rigid;
mod spatial_rigid;

pub use beam::{BeamBody, BeamMesh};
pub use modal::{ModalBody, ModalNodeSite, Structure, MAX_MODES, MAX_STRUCTURE_NODES};
pub use planar_rigid::PlanarRigidBody;
pub use spatial_rigid::SpatialRigidBody;

use std::ops::Range;

use crate::dynamics::frame::{Frame, Marker, Vec2};
use crate::linalg::PatternLdl;

/// Where on its body a marker's frame is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Site {
    /// The body's reference frame (a rigid body's frame at its centre of mass;
    /// a beam's first node).
    Reference,
    /// A section of a beam, interpolated from the nodes of one element.
    Section(SectionSite),
    /// A node of a modal body's structure.
    ModalNode(ModalNodeSite),
}

/// A section of a beam: an element and a point in it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SectionSite {
    /// The element (counted from the beam's first end).
    pub element: u32,
    /// The element's first velocity coordinate, counted from the body's first.
    pub first: u32,
    /// Number of nodes of the element.
    pub nodes: u8,
    /// Natural coordinate `xi` in [-1, 1] along the element.
    pub xi: f64,
    /// The shape functions' values at `xi` (unused entries zero) [-].
    pub weights: [f64; 3],
}

/// The mass block of one body kind, as the equations of motion use it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MassBlock<'a> {
    /// Constant and diagonal: the entries of `M^-1` in velocity-coordinate order
    /// [1/kg, 1/(kg m^2)]. Factored once at compile time by inverting.
    ConstantDiagonal(&'a [f64]),
    /// Constant and sparse (a beam's consistent mass): its `L D L^T` factor,
    /// made once at compile time, and the elimination program of its pattern.
    ConstantFactored {
        /// The factorisation's program.
        program: &'a PatternLdl,
        /// The factor's values.
        factor: &'a [f64],
    },
    /// Dense and dependent on the body's positions (a modal body's): formed and
    /// factored at every solve, in a scratch of [`BodyKind::mass_scratch_len`] values.
    ConfigurationDependent,
}

/// Every kind of body.
#[derive(Clone, Debug, PartialEq)]
pub enum BodyKind {
    /// Planar rigid body with its frame at the centre of mass, `(x, y, phi)`.
    PlanarRigid(PlanarRigidBody),
    /// Geometrically exact planar beam, nodes `(x, y, theta)` along it.
    Beam(BeamBody),
    /// Modal body: floating frame `(x, y, phi)` plus modal amplitudes.
    Modal(Box<ModalBody>),
}

impl BodyKind {
    /// Number of position coordinates.
    pub fn nq(&self) -> usize {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::NQ,
            Self::Beam(b) => b.n_coordinates(),
            Self::Modal(b) => b.n_coordinates(),
        }
    }

    /// Number of velocity coordinates.
    pub fn nv(&self) -> usize {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::NV,
            Self::Beam(b) => b.n_coordinates(),
            Self::Modal(b) => b.n_coordinates(),
        }
    }

    /// Frame of the body's reference marker from its position coordinates `q`
    /// and velocity coordinates `v`, reusing the trigonometry of `previous`
    /// where the orientation did not change.
    #[inline]
    pub fn frame(&self, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::frame(q, v, previous),
            Self::Beam(_) => BeamBody::section_frame(&BeamBody::FIRST_NODE, q, v, previous),
            Self::Modal(_) => ModalBody::frame(q, v, previous),
        }
    }

    /// Moves `frame` to the body's frame at `q`, `v` in place (as [`Self::frame`] with it as the previous frame).
    #[inline]
    pub fn update_frame(&self, q: &[f64], v: &[f64], frame: &mut Frame) {
        match self {
            Self::PlanarRigid(_) => frame.move_to(q, v),
            _ => *frame = self.frame(q, v, frame),
        }
    }

    /// Frame of the marker site `site` (pose and velocity), as [`Self::frame`].
    #[inline]
    pub fn site_frame(&self, site: &Site, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        match (self, site) {
            (Self::Beam(_), Site::Section(section)) => BeamBody::section_frame(section, q, v, previous),
            (Self::Modal(b), Site::ModalNode(node)) => b.node_frame(node.node as usize, q, v, previous),
            _ => self.frame(q, v, previous),
        }
    }

    /// Jacobian of the global velocity of `marker`'s point (its frame is `frame`,
    /// the body's reference frame `body`) by the velocity coordinates the marker
    /// moves with ([`Self::marker_coordinates`]), times `scale` [-]: row x into `jx`, row y into `jy` [m/m, m/rad].
    #[inline(always)]
    pub fn marker_jacobian(&self, body: &Frame, frame: &Frame, marker: &Marker, scale: f64, jx: &mut [f64], jy: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::marker_jacobian(frame, marker.local, scale, jx, jy),
            Self::Beam(_) => BeamBody::marker_jacobian(frame, marker, scale, jx, jy),
            Self::Modal(b) => b.marker_jacobian(body, frame, marker, scale, jx, jy),
        }
    }

    /// The velocity coordinates (counted from the body's first) that `marker`
    /// moves with: the width of its constraint-Jacobian block. Fixed for a
    /// marker, so the Jacobian's pattern is known at compile time.
    pub fn marker_coordinates(&self, marker: &Marker) -> Range<usize> {
        match self {
            Self::PlanarRigid(_) => 0..PlanarRigidBody::NV,
            Self::Beam(_) => BeamBody::marker_coordinates(marker),
            Self::Modal(b) => 0..b.n_coordinates(),
        }
    }

    /// Adds `along . d(v_P)/d(v)`, the Jacobian of `marker`'s point velocity
    /// projected on `along`, to the marker's block `out` (see
    /// [`Self::marker_coordinates`]) [m/m, m/rad times the unit of `along`];
    /// `body` is the body's reference frame.
    #[inline(always)]
    pub fn add_marker_jacobian(&self, body: &Frame, frame: &Frame, marker: &Marker, along: Vec2, out: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::add_marker_jacobian(frame, marker.local, along, out),
            Self::Beam(_) => BeamBody::add_marker_jacobian(frame, marker, along, out),
            Self::Modal(b) => b.add_marker_jacobian(body, frame, marker, along, out),
        }
    }

    /// Adds `scale d(omega_P)/d(v)`, the Jacobian of `marker`'s angular
    /// velocity, to the marker's block `out` [rad/rad times `scale`].
    #[inline(always)]
    pub fn add_marker_angle_jacobian(&self, marker: &Marker, scale: f64, out: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => out[2] += scale,
            Self::Beam(_) => BeamBody::add_marker_angle_jacobian(marker, scale, out),
            Self::Modal(b) => b.add_marker_angle_jacobian(marker, scale, out),
        }
    }

    /// `marker`'s point acceleration at zero coordinate accelerations (the
    /// velocity-dependent part, `-omega^2 A s` for a rigid body and for a beam's
    /// section frame, whose coordinates are linear in the nodes'); `body` is the
    /// body's reference frame [m/s^2].
    #[inline]
    pub fn marker_bias_acceleration(&self, body: &Frame, frame: &Frame, marker: &Marker) -> Vec2 {
        match self {
            Self::PlanarRigid(_) | Self::Beam(_) => PlanarRigidBody::marker_acceleration(frame, &[0.0; 3], marker.local),
            Self::Modal(_) => ModalBody::marker_bias_acceleration(body, frame, marker),
        }
    }

    /// `marker`'s angular acceleration at zero coordinate accelerations (zero
    /// for a rigid body, a beam's section and a modal body's node, whose angles
    /// are linear in the coordinates) [rad/s^2].
    #[inline]
    pub fn marker_bias_angular_acceleration(&self, _frame: &Frame, _marker: &Marker) -> f64 {
        match self {
            Self::PlanarRigid(_) | Self::Beam(_) | Self::Modal(_) => 0.0,
        }
    }

    /// Global acceleration [m/s^2] of `marker`'s point from its frame, the body's
    /// reference frame `body` and the body's velocity-coordinate accelerations `a`.
    #[inline]
    pub fn marker_acceleration(&self, body: &Frame, frame: &Frame, a: &[f64], marker: &Marker) -> Vec2 {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::marker_acceleration(frame, a, marker.local),
            Self::Beam(_) => BeamBody::marker_acceleration(frame, a, marker),
            Self::Modal(b) => b.marker_acceleration(body, frame, a, marker),
        }
    }

    /// The mass block.
    #[inline]
    pub fn mass_block(&self) -> MassBlock<'_> {
        match self {
            Self::PlanarRigid(b) => MassBlock::ConstantDiagonal(b.inverse_mass()),
            Self::Beam(b) => b.mass_block(),
            Self::Modal(_) => MassBlock::ConfigurationDependent,
        }
    }

    /// Values of scratch [`Self::solve_mass`] needs (a configuration-dependent mass block's matrix).
    pub fn mass_scratch_len(&self) -> usize {
        match self {
            Self::PlanarRigid(_) | Self::Beam(_) => 0,
            Self::Modal(b) => b.mass_scratch_len(),
        }
    }

    /// `out = M(q)^-1 f` over the body's velocity coordinates, at the body's
    /// positions `q`, with `scratch` of at least [`Self::mass_scratch_len`] values.
    #[inline]
    pub fn solve_mass(&self, q: &[f64], f: &[f64], out: &mut [f64], scratch: &mut [f64]) {
        match self.mass_block() {
            MassBlock::ConstantDiagonal(w) => {
                for ((o, w), f) in out.iter_mut().zip(w).zip(f) {
                    *o = w * f;
                }
            }
            MassBlock::ConstantFactored { program, factor } => {
                out.copy_from_slice(f);
                program.solve(factor, out);
            }
            MassBlock::ConfigurationDependent => self.solve_configuration_dependent_mass(q, f, out, scratch),
        }
    }

    /// The solve of a [`MassBlock::ConfigurationDependent`] block.
    #[inline]
    fn solve_configuration_dependent_mass(&self, q: &[f64], f: &[f64], out: &mut [f64], scratch: &mut [f64]) {
        match self {
            Self::Modal(b) => b.solve_mass(q, f, out, scratch),
            // (their blocks are constant)
            Self::PlanarRigid(_) | Self::Beam(_) => out.copy_from_slice(f),
        }
    }

    /// Whether [`Self::position_rates`] is the identity `q_dot = v` (the engine then copies `v`).
    pub fn has_identity_position_rates(&self) -> bool {
        match self {
            Self::PlanarRigid(_) | Self::Beam(_) | Self::Modal(_) => true,
        }
    }

    /// Whether [`Self::add_body_forces`] adds anything (the engine skips it otherwise).
    pub fn has_body_forces(&self) -> bool {
        match self {
            Self::PlanarRigid(_) => false,
            Self::Beam(_) | Self::Modal(_) => true,
        }
    }

    /// Adds the forces a body exerts on its own coordinates to its generalised
    /// forces `out` [N, N m]: velocity-dependent inertial forces (gyroscopic,
    /// centrifugal terms of a moving frame) and, for a deformable body, minus its
    /// internal elastic and damping forces.
    #[inline]
    pub fn add_body_forces(&self, q: &[f64], v: &[f64], out: &mut [f64]) {
        match self {
            // (frame at the centre of mass, planar: M is constant, no such terms)
            Self::PlanarRigid(_) => {}
            // (nodal coordinates in the inertial frame: M is constant, no inertial terms)
            Self::Beam(b) => b.subtract_internal_forces(q, v, out),
            // (a moving frame: quadratic velocity terms, elastic and damping forces)
            Self::Modal(b) => b.add_body_forces(q, v, out),
        }
    }

    /// `q_dot` from `v` (the identity while `nq == nv`).
    #[inline]
    pub fn position_rates(&self, _q: &[f64], v: &[f64], qdot: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) | Self::Beam(_) | Self::Modal(_) => qdot.copy_from_slice(v),
        }
    }

    /// The velocity coordinates `v` of the body at positions `q` moving as a
    /// rigid body: its reference point (a rigid body's centre of mass, a beam's
    /// first node, a modal body's frame origin) at `velocity` [m/s], turning at
    /// `angular_velocity` [rad/s], undeformed in rate (a modal body's modal rates zero).
    pub fn rigid_motion_velocities(&self, q: &[f64], velocity: Vec2, angular_velocity: f64, v: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => v.copy_from_slice(&[velocity.x, velocity.y, angular_velocity]),
            Self::Beam(_) => BeamBody::rigid_motion_velocities(q, velocity, angular_velocity, v),
            Self::Modal(_) => {
                v.fill(0.0);
                v[..3].copy_from_slice(&[velocity.x, velocity.y, angular_velocity]);
            }
        }
    }

    /// The velocity-dependent part of the accelerations of the velocity
    /// coordinates `a` in a rigid motion at angular velocity `angular_velocity`
    /// [rad/s] at positions `q`, the part [`Self::rigid_motion_velocities`] of
    /// the accelerations does not span: a beam's nodes' centripetal
    /// accelerations `-omega^2 (r_k - r_0)`; none for a rigid body and for a
    /// modal body, whose frame coordinates take the rigid motion whole [m/s^2].
    pub fn rigid_motion_bias_accelerations(&self, q: &[f64], angular_velocity: f64, a: &mut [f64]) {
        a.fill(0.0);
        if let Self::Beam(_) = self {
            let (x0, y0) = (q[0], q[1]);
            for (node, out) in q.chunks_exact(3).zip(a.chunks_exact_mut(3)) {
                out[0] = -angular_velocity * angular_velocity * (node[0] - x0);
                out[1] = -angular_velocity * angular_velocity * (node[1] - y0);
            }
        }
    }

    /// Moves the positions `q` by the velocity-coordinate increment `dv` (a
    /// position correction `q + dv` where `nq == nv`).
    #[inline]
    pub fn displace(&self, q: &mut [f64], dv: &[f64]) {
        match self {
            Self::PlanarRigid(_) | Self::Beam(_) | Self::Modal(_) => {
                for (q, d) in q.iter_mut().zip(dv) {
                    *q += d;
                }
            }
        }
    }

    /// Adds the generalised force of the force `f` [N] at the global point `p` [m]
    /// (a point moving with `marker`, whose frame is `frame`; the body's reference
    /// frame is `body`) to the body's generalised forces `out`.
    #[inline]
    pub fn add_point_force(&self, body: &Frame, frame: &Frame, marker: &Marker, p: Vec2, f: Vec2, out: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::add_point_force(frame, p, f, out),
            Self::Beam(_) => BeamBody::add_point_force(frame, marker, p, f, out),
            Self::Modal(b) => b.add_point_force(body, frame, marker, p, f, out),
        }
    }

    /// Adds the generalised force of a moment `m` [N m] (counter-clockwise) on `marker`'s frame to `out`.
    #[inline]
    pub fn add_moment(&self, marker: &Marker, m: f64, out: &mut [f64]) {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::add_moment(m, out),
            Self::Beam(_) => BeamBody::add_moment(marker, m, out),
            Self::Modal(b) => b.add_moment(marker, m, out),
        }
    }

    /// Whether [`BodyKind::add_gravity`] adds the same load in every configuration.
    pub fn gravity_load_is_constant(&self) -> bool {
        match self {
            Self::PlanarRigid(_) | Self::Beam(_) => true,
            Self::Modal(_) => false,
        }
    }

    /// Adds the generalised force of uniform gravity `g` [m/s^2] at the body's positions `q` to `out`.
    #[inline]
    pub fn add_gravity(&self, g: Vec2, q: &[f64], out: &mut [f64]) {
        match self {
            Self::PlanarRigid(b) => b.add_gravity(g, out),
            Self::Beam(b) => b.add_gravity(g, out),
            Self::Modal(b) => b.add_gravity(g, q, out),
        }
    }

    /// Potential energy [J] from `q`: of gravity, `-integral g . r dm`, and the strain energy of a deformable body.
    pub fn potential_energy(&self, g: Vec2, q: &[f64]) -> f64 {
        match self {
            Self::PlanarRigid(b) => b.gravity_potential_energy(g, q),
            Self::Beam(b) => b.gravity_potential_energy(g, q) + b.strain_energy(q),
            Self::Modal(b) => b.potential_energy(g, q),
        }
    }

    /// Kinetic energy [J] from the positions `q` and velocities `v`.
    pub fn kinetic_energy(&self, q: &[f64], v: &[f64]) -> f64 {
        match self {
            Self::PlanarRigid(b) => b.kinetic_energy(v),
            Self::Beam(b) => b.kinetic_energy(v),
            Self::Modal(b) => b.kinetic_energy(q, v),
        }
    }

    /// Scales of the position and velocity coordinates in the integrator's
    /// absolute tolerance (1 for metres, radians and their rates).
    pub fn tolerance_scales(&self, q: &mut [f64], v: &mut [f64]) {
        match self {
            // (modal amplitudes are interface displacements [m, rad] or normal modes scaled to 1 m at most)
            Self::PlanarRigid(_) | Self::Beam(_) | Self::Modal(_) => {
                q.fill(1.0);
                v.fill(1.0);
            }
        }
    }

    /// Names, units and descriptions of the coordinates, as channel
    /// quantities: position, velocity and acceleration channels, in coordinate order.
    pub fn coordinate_channels(&self) -> Vec<CoordinateChannels> {
        match self {
            Self::PlanarRigid(_) => PlanarRigidBody::CHANNELS.to_vec(),
            Self::Beam(b) => b.coordinate_channels(),
            Self::Modal(b) => b.coordinate_channels(),
        }
    }
}

/// Quantity, unit and description of one channel.
pub type ChannelName = (std::borrow::Cow<'static, str>, &'static str, std::borrow::Cow<'static, str>);

/// A channel's name from static text.
pub const fn channel(quantity: &'static str, unit: &'static str, description: &'static str) -> ChannelName {
    (std::borrow::Cow::Borrowed(quantity), unit, std::borrow::Cow::Borrowed(description))
}

/// The channels of one velocity coordinate (and of the position coordinate
/// at the same place while `nq == nv`).
#[derive(Clone, Debug, PartialEq)]
pub struct CoordinateChannels {
    /// Position: quantity, unit, description.
    pub position: ChannelName,
    /// Velocity: quantity, unit, description.
    pub velocity: ChannelName,
    /// Acceleration: quantity, unit, description.
    pub acceleration: ChannelName,
}

#[cfg(test)]
mod tests;
