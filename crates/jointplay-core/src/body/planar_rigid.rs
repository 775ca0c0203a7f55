//! Planar rigid body with its frame at the centre of mass: coordinates
//! `q = (x, y, phi)` [m, m, rad], velocities `v = (vx, vy, omega)` [m/s, m/s, rad/s],
//! constant diagonal mass `diag(m, m, J)`.

use std::ops::Range;

use super::planar_embedding::embedded_in_the_plane;
use super::{channel, position_channels_of, velocity_channels_of, BodyModel, ChannelName, CoordinateChannels, MassBlock};
use crate::kinematics::marker::{Marker, MarkerFrames, Site, SpatialMarker};
use crate::kinematics::planar::{cross, perp, Frame, Vec2};
use crate::kinematics::spatial::{SpatialFrame, Vec3};
use crate::kinematics::wrench::Wrench;

/// Mass properties of a planar rigid body.
#[derive(Clone, Debug, PartialEq)]
pub struct PlanarRigidBody {
    /// Mass m [kg].
    pub mass: f64,
    /// Moment of inertia J about the centre of mass [kg m^2].
    pub inertia: f64,
    /// `(1/m, 1/m, 1/J)` [1/kg, 1/kg, 1/(kg m^2)].
    inverse_mass: [f64; 3],
}

impl PlanarRigidBody {
    /// Position coordinates `(x, y, phi)`.
    pub const NQ: usize = 3;
    /// Velocity coordinates `(vx, vy, omega)`.
    pub const NV: usize = 3;

    /// Channels of the coordinates, in coordinate order.
    pub const CHANNELS: [CoordinateChannels; 3] = [
        CoordinateChannels {
            position: channel("x", "m", "centre of mass x"),
            velocity: channel("vx", "m/s", "centre of mass velocity x"),
            acceleration: channel("ax", "m/s^2", "centre of mass acceleration x"),
        },
        CoordinateChannels {
            position: channel("y", "m", "centre of mass y"),
            velocity: channel("vy", "m/s", "centre of mass velocity y"),
            acceleration: channel("ay", "m/s^2", "centre of mass acceleration y"),
        },
        CoordinateChannels {
            position: channel("angle", "rad", "orientation"),
            velocity: channel("omega", "rad/s", "angular velocity"),
            acceleration: channel("alpha", "rad/s^2", "angular acceleration"),
        },
    ];

    /// Body of mass `mass` > 0 [kg] and inertia `inertia` > 0 [kg m^2].
    pub fn new(mass: f64, inertia: f64) -> Self {
        Self { mass, inertia, inverse_mass: [1.0 / mass, 1.0 / mass, 1.0 / inertia] }
    }

    /// The diagonal of `M^-1`.
    #[inline]
    pub fn inverse_mass(&self) -> &[f64] {
        &self.inverse_mass
    }
}

impl BodyModel for PlanarRigidBody {
    #[inline]
    fn nq(&self) -> usize {
        Self::NQ
    }

    #[inline]
    fn nv(&self) -> usize {
        Self::NV
    }

    /// Frame at the centre of mass from `(x, y, phi)` and `(vx, vy, omega)`.
    #[inline]
    fn frame(&self, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        Frame::from_coordinates_after(previous, q, v)
    }

    /// In place, by [`Frame::move_to`].
    #[inline]
    fn update_frame(&self, q: &[f64], v: &[f64], frame: &mut Frame) {
        frame.move_to(q, v);
    }

    /// Every site is the frame at the centre of mass.
    #[inline]
    fn site_frame(&self, _site: &Site, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        self.frame(q, v, previous)
    }

    /// `scale d(r_G + A s)/d(x, y, phi)` = `scale [[1, 0, -(A s)_y], [0, 1, (A s)_x]]`.
    #[inline]
    fn marker_jacobian(&self, _body: &Frame, frame: &Frame, marker: &Marker, scale: f64, jx: &mut [f64], jy: &mut [f64]) {
        let s = frame.rotate(marker.local) * scale;
        jx.copy_from_slice(&[scale, 0.0, -s.y]);
        jy.copy_from_slice(&[0.0, scale, s.x]);
    }

    /// All three coordinates.
    #[inline]
    fn marker_coordinates(&self, _marker: &Marker) -> Range<usize> {
        0..Self::NV
    }

    /// Adds `along . [[1, 0, -(A s)_y], [0, 1, (A s)_x]]` to `out`.
    #[inline]
    fn add_marker_jacobian(&self, _body: &Frame, frame: &Frame, marker: &Marker, along: Vec2, out: &mut [f64]) {
        let s = frame.rotate(marker.local);
        out[0] += along.x;
        out[1] += along.y;
        out[2] += along.dot(&perp(s));
    }

    /// `scale` on `phi`.
    #[inline]
    fn add_marker_angle_jacobian(&self, _marker: &Marker, scale: f64, out: &mut [f64]) {
        out[2] += scale;
    }

    /// `-omega^2 A s` [m/s^2].
    #[inline]
    fn marker_bias_acceleration(&self, _body: &Frame, frame: &Frame, marker: &Marker) -> Vec2 {
        point_acceleration(frame, &[0.0; 3], marker.local)
    }

    /// None: the angle is a coordinate.
    #[inline]
    fn marker_bias_angular_acceleration(&self, _frame: &Frame, _marker: &Marker) -> f64 {
        0.0
    }

    /// `a_G + alpha perp(A s) - omega^2 A s` [m/s^2].
    #[inline]
    fn marker_acceleration(&self, _body: &Frame, frame: &Frame, a: &[f64], marker: &Marker) -> Vec2 {
        point_acceleration(frame, a, marker.local)
    }

    /// `alpha` [rad/s^2].
    #[inline]
    fn marker_angular_acceleration(&self, _frame: &Frame, a: &[f64], _marker: &Marker) -> f64 {
        a[2]
    }

    /// Constant and diagonal.
    #[inline]
    fn mass_block(&self) -> MassBlock<'_> {
        MassBlock::ConstantDiagonal(&self.inverse_mass)
    }

    /// `out = diag(1/m, 1/m, 1/J) f`.
    #[inline]
    fn solve_mass(&self, _q: &[f64], f: &[f64], out: &mut [f64], _scratch: &mut [f64]) {
        for ((o, w), f) in out.iter_mut().zip(&self.inverse_mass).zip(f) {
            *o = w * f;
        }
    }

    /// None: the frame is at the centre of mass and the mass is constant.
    #[inline]
    fn has_body_forces(&self) -> bool {
        false
    }

    /// (frame at the centre of mass, planar: M is constant, no such terms)
    #[inline]
    fn add_body_forces(&self, _q: &[f64], _v: &[f64], _out: &mut [f64]) {}

    /// `(vx, vy, omega)` as given.
    fn rigid_motion_velocities(&self, _q: &[f64], velocity: Vec2, angular_velocity: f64, v: &mut [f64]) {
        v.copy_from_slice(&[velocity.x, velocity.y, angular_velocity]);
    }

    /// Force on `(x, y)`, its moment about the centre of mass on `phi`.
    #[inline]
    fn add_point_force(&self, _body: &Frame, frame: &Frame, _marker: &Marker, p: Vec2, f: Vec2, out: &mut [f64]) {
        out[0] += f.x;
        out[1] += f.y;
        out[2] += cross(p - frame.position, f);
    }

    /// The moment on `phi`.
    #[inline]
    fn add_moment(&self, _marker: &Marker, m: f64, out: &mut [f64]) {
        out[2] += m;
    }

    fn gravity_load_is_constant(&self) -> bool {
        true
    }

    /// `m g` on `(x, y)`.
    #[inline]
    fn add_gravity(&self, g: Vec3, _q: &[f64], out: &mut [f64]) {
        out[0] += self.mass * g.x;
        out[1] += self.mass * g.y;
    }

    /// `-m g . r_G` [J].
    fn potential_energy(&self, g: Vec3, q: &[f64]) -> f64 {
        -self.mass * (g.x * q[0] + g.y * q[1])
    }

    /// `(m |v_G|^2 + J omega^2) / 2` [J].
    fn kinetic_energy(&self, _q: &[f64], v: &[f64]) -> f64 {
        0.5 * (self.mass * (v[0] * v[0] + v[1] * v[1]) + self.inertia * v[2] * v[2])
    }

    fn position_channels(&self) -> Vec<ChannelName> {
        position_channels_of(Self::CHANNELS)
    }

    fn velocity_channels(&self) -> Vec<(ChannelName, ChannelName)> {
        velocity_channels_of(Self::CHANNELS)
    }

    embedded_in_the_plane!();
}

/// `a_G + alpha perp(A s) - omega^2 A s` [m/s^2]: the acceleration of the point
/// `local` [m] of the rigid frame `frame` whose coordinates accelerate at `a`
/// (a rigid body's, and a beam section's, interpolated).
#[inline]
pub(super) fn point_acceleration(frame: &Frame, a: &[f64], local: Vec2) -> Vec2 {
    let s = frame.rotate(local);
    let omega = frame.angular_velocity;
    Vec2::new(a[0], a[1]) + perp(s) * a[2] - s * (omega * omega)
}
