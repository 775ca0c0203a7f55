//! Bodies: every kind behind one contract, the trait [`BodyModel`], one file
//! per kind, listed once in `bodies!` (which defines [`BodyKind`] and its dispatch).
//!
//! A body kind owns `nq` position and `nv` velocity coordinates (their
//! addresses in the state come from [`crate::dynamics::StateLayout`]; a kind
//! sees only its own slices) and provides:
//!
//! - the frame of a body marker (pose, velocity) from its coordinates; the
//!   velocity coordinates a marker moves with, the Jacobian of a marker point
//!   and of a marker's angle by them, and the velocity-dependent part of the
//!   marker's acceleration (what constraint rows are built from), planar and
//!   spatial;
//! - its mass block and the solve with it ([`MassBlock`]), at the body's
//!   positions (a modal body's mass depends on them);
//! - velocity-dependent inertial forces;
//! - the map from `v` to `q_dot`, positions displaced by a velocity-coordinate
//!   increment and the increment between two positions (MuJoCo's
//!   `mj_integratePos`, `mj_differentiatePos`);
//! - the generalised force of a point force, of a moment, of a wrench and of gravity;
//! - its kinetic energy and gravitational potential, for the energy channels;
//! - how its coordinates are scaled in the integrator's error control, and the
//!   names of its coordinates' channels.
//!
//! A marker's frame sits at a [`Site`] of its body: the body's reference
//! frame, (on a beam) a section interpolated from one element's nodes, or
//! (on a modal body) a node of its structure.
//!
//! Kinds: the planar rigid body (`planar_rigid.rs`), the geometrically
//! exact beam (`beam.rs`) and the modal body (`modal.rs`, floating frame plus
//! Craig-Bampton modes), all three embedded in space in the plane `z = 0`
//! (`planar_embedding.rs`). Theory: `docs/theory/planar-formulation.md`,
//! "Coordinates, bodies and markers", `docs/theory/beam.md` and
//! `docs/theory/modal-body.md`.

mod beam;
mod modal;
mod planar_embedding;
mod planar_rigid;
mod spatial_rigid;

pub use beam::{BeamBody, BeamMesh};
pub use modal::{ModalBody, Structure, MAX_MODES, MAX_STRUCTURE_NODES};
pub use planar_rigid::PlanarRigidBody;
pub use spatial_rigid::SpatialRigidBody;

use std::ops::Range;

use crate::kinematics::marker::{Marker, MarkerFrames, Site, SpatialMarker};
use crate::kinematics::planar::{Frame, Vec2};
use crate::kinematics::spatial::{SpatialFrame, Vec3};
use crate::kinematics::wrench::Wrench;
use crate::linalg::PatternLdl;

/// What every kind of body provides (see the module's documentation). A kind
/// sees only its own coordinates: `q` its `nq` positions, `v` and `a` its `nv`
/// velocities and accelerations, `out` its `nv` generalised forces, unless a
/// method names a marker's block ([`BodyModel::marker_coordinates`]).
///
/// Planar methods take planar [`Frame`]s and [`Marker`]s, spatial ones
/// [`MarkerFrames`] and [`SpatialMarker`]s; planar kinds answer the spatial ones
/// embedded in the plane `z = 0`, turning about `z` (`planar_embedding.rs`).
pub trait BodyModel {
    /// Number of position coordinates.
    fn nq(&self) -> usize;

    /// Number of velocity coordinates.
    fn nv(&self) -> usize;

    /// Frame of the body's reference marker from its position coordinates `q`
    /// and velocity coordinates `v`, reusing the trigonometry of `previous`
    /// where the orientation did not change.
    fn frame(&self, q: &[f64], v: &[f64], previous: &Frame) -> Frame;

    /// Moves `frame` to the body's frame at `q`, `v` in place (as [`Self::frame`] with it as the previous frame).
    #[inline]
    fn update_frame(&self, q: &[f64], v: &[f64], frame: &mut Frame) {
        *frame = self.frame(q, v, frame);
    }

    /// Frame of the marker site `site` (pose and velocity), as [`Self::frame`].
    fn site_frame(&self, site: &Site, q: &[f64], v: &[f64], previous: &Frame) -> Frame;

    /// Jacobian of the global velocity of `marker`'s point (its frame is `frame`,
    /// the body's reference frame `body`) by the velocity coordinates the marker
    /// moves with ([`Self::marker_coordinates`]), times `scale` [-]: row x into `jx`, row y into `jy` [m/m, m/rad].
    fn marker_jacobian(&self, body: &Frame, frame: &Frame, marker: &Marker, scale: f64, jx: &mut [f64], jy: &mut [f64]);

    /// The velocity coordinates (counted from the body's first) that `marker`
    /// moves with: the width of its constraint-Jacobian block. Fixed for a
    /// marker, so the Jacobian's pattern is known at compile time.
    fn marker_coordinates(&self, marker: &Marker) -> Range<usize>;

    /// Adds `along . d(v_P)/d(v)`, the Jacobian of `marker`'s point velocity
    /// projected on `along`, to the marker's block `out` (see
    /// [`Self::marker_coordinates`]) [m/m, m/rad times the unit of `along`];
    /// `body` is the body's reference frame.
    fn add_marker_jacobian(&self, body: &Frame, frame: &Frame, marker: &Marker, along: Vec2, out: &mut [f64]);

    /// Adds `scale d(omega_P)/d(v)`, the Jacobian of `marker`'s angular
    /// velocity, to the marker's block `out` [rad/rad times `scale`].
    fn add_marker_angle_jacobian(&self, marker: &Marker, scale: f64, out: &mut [f64]);

    /// `marker`'s point acceleration at zero coordinate accelerations (the
    /// velocity-dependent part, `-omega^2 A s` for a rigid body and for a beam's
    /// section frame, whose coordinates are linear in the nodes'); `body` is the
    /// body's reference frame [m/s^2].
    fn marker_bias_acceleration(&self, body: &Frame, frame: &Frame, marker: &Marker) -> Vec2;

    /// `marker`'s angular acceleration at zero coordinate accelerations [rad/s^2].
    fn marker_bias_angular_acceleration(&self, frame: &Frame, marker: &Marker) -> f64;

    /// Global acceleration [m/s^2] of `marker`'s point from its frame, the body's
    /// reference frame `body` and the body's velocity-coordinate accelerations `a`.
    fn marker_acceleration(&self, body: &Frame, frame: &Frame, a: &[f64], marker: &Marker) -> Vec2;

    /// Angular acceleration [rad/s^2] of `marker`'s frame from the body's
    /// velocity-coordinate accelerations `a` (its frame is `frame`).
    fn marker_angular_acceleration(&self, frame: &Frame, a: &[f64], marker: &Marker) -> f64;

    /// The mass block.
    fn mass_block(&self) -> MassBlock<'_>;

    /// Values of scratch [`Self::solve_mass`] needs (a configuration-dependent mass block's matrix).
    #[inline]
    fn mass_scratch_len(&self) -> usize {
        0
    }

    /// `out = M(q)^-1 f` over the body's velocity coordinates, at the body's
    /// positions `q`, with `scratch` of at least [`Self::mass_scratch_len`] values.
    fn solve_mass(&self, q: &[f64], f: &[f64], out: &mut [f64], scratch: &mut [f64]);

    /// Whether [`Self::position_rates`] is the identity `q_dot = v` (the engine then copies `v`).
    #[inline]
    fn has_identity_position_rates(&self) -> bool {
        true
    }

    /// Whether [`Self::add_body_forces`] adds anything (the engine skips it otherwise).
    fn has_body_forces(&self) -> bool;

    /// Adds the forces a body exerts on its own coordinates to its generalised
    /// forces `out` [N, N m]: velocity-dependent inertial forces (gyroscopic,
    /// centrifugal terms of a moving frame) and, for a deformable body, minus its
    /// internal elastic and damping forces.
    fn add_body_forces(&self, q: &[f64], v: &[f64], out: &mut [f64]);

    /// `q_dot = N(q) v` (here the identity, `nq == nv`).
    #[inline]
    fn position_rates(&self, _q: &[f64], v: &[f64], qdot: &mut [f64]) {
        qdot.copy_from_slice(v);
    }

    /// The velocity coordinates `v` of the body at positions `q` moving as a
    /// rigid body: its reference point (a rigid body's centre of mass, a beam's
    /// first node, a modal body's frame origin) at `velocity` [m/s], turning at
    /// `angular_velocity` [rad/s], undeformed in rate (a modal body's modal rates zero).
    fn rigid_motion_velocities(&self, q: &[f64], velocity: Vec2, angular_velocity: f64, v: &mut [f64]);

    /// The velocity-dependent part of the accelerations of the velocity
    /// coordinates `a` in a rigid motion at angular velocity `angular_velocity`
    /// [rad/s] at positions `q`, the part [`Self::rigid_motion_velocities`] of
    /// the accelerations does not span [m/s^2] (here none: the body's reference
    /// coordinates take the rigid motion whole).
    fn rigid_motion_bias_accelerations(&self, _q: &[f64], _angular_velocity: f64, a: &mut [f64]) {
        a.fill(0.0);
    }

    /// Moves the positions `q` by the velocity-coordinate increment `dv`
    /// (MuJoCo's `mj_integratePos`; here `q + dv`, `nq == nv`).
    #[inline]
    fn displace(&self, q: &mut [f64], dv: &[f64]) {
        for (q, d) in q.iter_mut().zip(dv) {
            *q += d;
        }
    }

    /// `q` moved so that it is again a valid position (unit quaternions); nothing here.
    #[inline]
    fn normalise_positions(&self, _q: &mut [f64]) {}

    /// The velocity-coordinate increment `dv` that [`Self::displace`] turns
    /// `from` into `to` (MuJoCo's `mj_differentiatePos`; here `to - from`).
    #[inline]
    fn difference(&self, from: &[f64], to: &[f64], dv: &mut [f64]) {
        for ((d, a), b) in dv.iter_mut().zip(from).zip(to) {
            *d = b - a;
        }
    }

    /// Adds the generalised force of the force `f` [N] at the global point `p` [m]
    /// (a point moving with `marker`, whose frame is `frame`; the body's reference
    /// frame is `body`) to the body's generalised forces `out`.
    fn add_point_force(&self, body: &Frame, frame: &Frame, marker: &Marker, p: Vec2, f: Vec2, out: &mut [f64]);

    /// Adds the generalised force of a moment `m` [N m] (counter-clockwise) on `marker`'s frame to `out`.
    fn add_moment(&self, marker: &Marker, m: f64, out: &mut [f64]);

    /// Whether [`Self::add_gravity`] adds the same load in every configuration.
    fn gravity_load_is_constant(&self) -> bool;

    /// Adds the generalised force of uniform gravity `g` [m/s^2] at the body's
    /// positions `q` to `out` (planar kinds: its in-plane part `g.xy`).
    fn add_gravity(&self, g: Vec3, q: &[f64], out: &mut [f64]);

    /// Potential energy [J] from `q`: of gravity `g` [m/s^2], `-integral g . r dm`,
    /// and the strain energy of a deformable body.
    fn potential_energy(&self, g: Vec3, q: &[f64]) -> f64;

    /// Kinetic energy [J] from the positions `q` and velocities `v`.
    fn kinetic_energy(&self, q: &[f64], v: &[f64]) -> f64;

    /// Scales of the position and velocity coordinates in the integrator's
    /// absolute tolerance (here 1: metres, radians and their rates).
    fn tolerance_scales(&self, q: &mut [f64], v: &mut [f64]) {
        q.fill(1.0);
        v.fill(1.0);
    }

    /// Names, units and descriptions of the position channels, in coordinate order (`nq`).
    fn position_channels(&self) -> Vec<ChannelName>;

    /// Names, units and descriptions of the velocity and acceleration channels,
    /// in velocity-coordinate order (`nv`).
    fn velocity_channels(&self) -> Vec<(ChannelName, ChannelName)>;

    /// Channels the body derives from its coordinates (a spatial body's global
    /// angular velocity and Euler angles); none here.
    fn derived_channels(&self) -> Vec<ChannelName> {
        Vec::new()
    }

    /// Value of derived channel `which` at the positions `q` and velocities `v` [SI units].
    fn derived_value(&self, _q: &[f64], _v: &[f64], _which: usize) -> f64 {
        f64::NAN
    }

    /// The spatial frame of the site whose planar frame is `planar`.
    fn spatial_site_frame(&self, site: &Site, q: &[f64], v: &[f64], planar: &Frame) -> SpatialFrame;

    /// Adds `along . d(v_P)/d(v)` of the marker point (3D) to the marker's block `out`
    /// [m/m, m/rad times the unit of `along`].
    fn add_spatial_point_jacobian(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, along: Vec3, out: &mut [f64]);

    /// Adds `along . d(omega)/d(v)` of the marker frame's global angular velocity
    /// to the marker's block `out` [rad/rad times the unit of `along`].
    fn add_spatial_angular_jacobian(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, along: Vec3, out: &mut [f64]);

    /// Point and angular acceleration of the marker at zero coordinate
    /// accelerations [m/s^2, rad/s^2] (global).
    fn spatial_bias_acceleration(&self, at: MarkerFrames<'_>, marker: &SpatialMarker) -> (Vec3, Vec3);

    /// Point and angular acceleration of the marker for the body's
    /// velocity-coordinate accelerations `a` [m/s^2, rad/s^2] (global).
    fn spatial_marker_acceleration(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, a: &[f64]) -> (Vec3, Vec3);

    /// Adds the generalised force of the force `wrench.force` [N] at the global
    /// point `point` [m] (moving with `marker`) and of the moment
    /// `wrench.moment` [N m] (global) to the body's generalised forces `out`.
    fn add_wrench(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, point: Vec3, wrench: &Wrench, out: &mut [f64]);
}

/// Calls `method` of a body kind with the planar rigid body, the kind of every
/// body of a planar rigid model, peeled off first: its code is then inlined at
/// the call, the other kinds dispatched as usual.
macro_rules! planar_first {
    ($kind:expr, $method:ident($($arg:expr),*)) => {
        match $kind {
            $crate::body::BodyKind::PlanarRigid(body) => body.$method($($arg),*),
            kind => kind.$method($($arg),*),
        }
    };
}

pub(crate) use planar_first;

/// The list of body kinds: defines [`BodyKind`] with one variant per kind and
/// its [`BodyModel`], forwarding every method to the kind's own.
macro_rules! bodies {
    ($($(#[$doc:meta])* $kind:ident($body:ty)),+ $(,)?) => {
        /// Every kind of body.
        #[derive(Clone, Debug, PartialEq)]
        pub enum BodyKind {
            $($(#[$doc])* $kind($body),)+
        }

        impl BodyModel for BodyKind {
            crate::dispatch::forward! { [$($kind)+];
                fn nq(&self) -> usize;
                fn nv(&self) -> usize;
                #[inline] fn frame(&self, q: &[f64], v: &[f64], previous: &Frame) -> Frame;
                #[inline] fn update_frame(&self, q: &[f64], v: &[f64], frame: &mut Frame);
                #[inline] fn site_frame(&self, site: &Site, q: &[f64], v: &[f64], previous: &Frame) -> Frame;
                #[inline(always)] fn marker_jacobian(&self, body: &Frame, frame: &Frame, marker: &Marker, scale: f64, jx: &mut [f64], jy: &mut [f64]);
                fn marker_coordinates(&self, marker: &Marker) -> Range<usize>;
                #[inline(always)] fn add_marker_jacobian(&self, body: &Frame, frame: &Frame, marker: &Marker, along: Vec2, out: &mut [f64]);
                #[inline(always)] fn add_marker_angle_jacobian(&self, marker: &Marker, scale: f64, out: &mut [f64]);
                #[inline(always)] fn marker_bias_acceleration(&self, body: &Frame, frame: &Frame, marker: &Marker) -> Vec2;
                #[inline] fn marker_bias_angular_acceleration(&self, frame: &Frame, marker: &Marker) -> f64;
                #[inline] fn marker_acceleration(&self, body: &Frame, frame: &Frame, a: &[f64], marker: &Marker) -> Vec2;
                #[inline] fn marker_angular_acceleration(&self, frame: &Frame, a: &[f64], marker: &Marker) -> f64;
                #[inline] fn mass_block(&self) -> MassBlock<'_>;
                fn mass_scratch_len(&self) -> usize;
                #[inline] fn solve_mass(&self, q: &[f64], f: &[f64], out: &mut [f64], scratch: &mut [f64]);
                fn has_identity_position_rates(&self) -> bool;
                fn has_body_forces(&self) -> bool;
                #[inline] fn add_body_forces(&self, q: &[f64], v: &[f64], out: &mut [f64]);
                #[inline] fn position_rates(&self, q: &[f64], v: &[f64], qdot: &mut [f64]);
                fn rigid_motion_velocities(&self, q: &[f64], velocity: Vec2, angular_velocity: f64, v: &mut [f64]);
                fn rigid_motion_bias_accelerations(&self, q: &[f64], angular_velocity: f64, a: &mut [f64]);
                #[inline] fn displace(&self, q: &mut [f64], dv: &[f64]);
                #[inline] fn normalise_positions(&self, q: &mut [f64]);
                #[inline] fn difference(&self, from: &[f64], to: &[f64], dv: &mut [f64]);
                #[inline] fn add_point_force(&self, body: &Frame, frame: &Frame, marker: &Marker, p: Vec2, f: Vec2, out: &mut [f64]);
                #[inline] fn add_moment(&self, marker: &Marker, m: f64, out: &mut [f64]);
                fn gravity_load_is_constant(&self) -> bool;
                #[inline] fn add_gravity(&self, g: Vec3, q: &[f64], out: &mut [f64]);
                fn potential_energy(&self, g: Vec3, q: &[f64]) -> f64;
                fn kinetic_energy(&self, q: &[f64], v: &[f64]) -> f64;
                fn tolerance_scales(&self, q: &mut [f64], v: &mut [f64]);
                fn position_channels(&self) -> Vec<ChannelName>;
                fn velocity_channels(&self) -> Vec<(ChannelName, ChannelName)>;
                fn derived_channels(&self) -> Vec<ChannelName>;
                fn derived_value(&self, q: &[f64], v: &[f64], which: usize) -> f64;
                #[inline] fn spatial_site_frame(&self, site: &Site, q: &[f64], v: &[f64], planar: &Frame) -> SpatialFrame;
                #[inline] fn add_spatial_point_jacobian(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, along: Vec3, out: &mut [f64]);
                #[inline] fn add_spatial_angular_jacobian(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, along: Vec3, out: &mut [f64]);
                #[inline] fn spatial_bias_acceleration(&self, at: MarkerFrames<'_>, marker: &SpatialMarker) -> (Vec3, Vec3);
                #[inline] fn spatial_marker_acceleration(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, a: &[f64]) -> (Vec3, Vec3);
                #[inline] fn add_wrench(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, point: Vec3, wrench: &Wrench, out: &mut [f64]);
            }
        }
    };
}

bodies! {
    /// Planar rigid body with its frame at the centre of mass, `(x, y, phi)`.
    PlanarRigid(PlanarRigidBody),
    /// Geometrically exact planar beam, nodes `(x, y, theta)` along it.
    Beam(BeamBody),
    /// Modal body: floating frame `(x, y, phi)` plus modal amplitudes.
    Modal(Box<ModalBody>),
    /// Spatial rigid body: centre of mass and unit quaternion, `(x, y, z, w, qx, qy, qz)`.
    SpatialRigid(SpatialRigidBody),
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
    /// factored at every solve, in a scratch of [`BodyModel::mass_scratch_len`] values.
    ConfigurationDependent,
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

/// The position channels of kinds whose coordinates share their channels' names.
fn position_channels_of(coordinates: impl IntoIterator<Item = CoordinateChannels>) -> Vec<ChannelName> {
    coordinates.into_iter().map(|c| c.position).collect()
}

/// The velocity and acceleration channels of kinds whose coordinates share their channels' names.
fn velocity_channels_of(coordinates: impl IntoIterator<Item = CoordinateChannels>) -> Vec<(ChannelName, ChannelName)> {
    coordinates.into_iter().map(|c| (c.velocity, c.acceleration)).collect()
}

#[cfg(test)]
mod tests;
