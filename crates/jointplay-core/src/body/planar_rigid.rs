//! Planar rigid body with its frame at the centre of mass: coordinates
//! `q = (x, y, phi)` [m, m, rad], velocities `v = (vx, vy, omega)` [m/s, m/s, rad/s],
//! constant diagonal mass `diag(m, m, J)`.

use super::{channel, CoordinateChannels};
use crate::dynamics::frame::{cross, perp, Frame, Vec2};

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

    /// Frame at the centre of mass from `(x, y, phi)` and `(vx, vy, omega)`.
    #[inline]
    pub fn frame(q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        Frame::from_coordinates_after(previous, q, v)
    }

    /// `scale d(r_G + A s)/d(x, y, phi)` = `scale [[1, 0, -(A s)_y], [0, 1, (A s)_x]]`.
    #[inline]
    pub fn marker_jacobian(frame: &Frame, local: Vec2, scale: f64, jx: &mut [f64], jy: &mut [f64]) {
        let s = frame.rotate(local) * scale;
        jx.copy_from_slice(&[scale, 0.0, -s.y]);
        jy.copy_from_slice(&[0.0, scale, s.x]);
    }

    /// Adds `along . [[1, 0, -(A s)_y], [0, 1, (A s)_x]]` to `out`.
    #[inline]
    pub fn add_marker_jacobian(frame: &Frame, local: Vec2, along: Vec2, out: &mut [f64]) {
        let s = frame.rotate(local);
        out[0] += along.x;
        out[1] += along.y;
        out[2] += along.dot(&perp(s));
    }

    /// `a_G + alpha perp(A s) - omega^2 A s` [m/s^2].
    #[inline]
    pub fn marker_acceleration(frame: &Frame, a: &[f64], local: Vec2) -> Vec2 {
        let s = frame.rotate(local);
        let omega = frame.angular_velocity;
        Vec2::new(a[0], a[1]) + perp(s) * a[2] - s * (omega * omega)
    }

    /// Force on `(x, y)`, its moment about the centre of mass on `phi`.
    #[inline]
    pub fn add_point_force(frame: &Frame, p: Vec2, f: Vec2, out: &mut [f64]) {
        out[0] += f.x;
        out[1] += f.y;
        out[2] += cross(p - frame.position, f);
    }

    /// The moment on `phi`.
    #[inline]
    pub fn add_moment(m: f64, out: &mut [f64]) {
        out[2] += m;
    }

    /// `m g` on `(x, y)`.
    #[inline]
    pub fn add_gravity(&self, g: Vec2, out: &mut [f64]) {
        out[0] += self.mass * g.x;
        out[1] += self.mass * g.y;
    }

    /// `-m g . r_G` [J].
    pub fn gravity_potential_energy(&self, g: Vec2, q: &[f64]) -> f64 {
        -self.mass * (g.x * q[0] + g.y * q[1])
    }

    /// `(m |v_G|^2 + J omega^2) / 2` [J].
    pub fn kinetic_energy(&self, v: &[f64]) -> f64 {
        0.5 * (self.mass * (v[0] * v[0] + v[1] * v[1]) + self.inertia * v[2] * v[2])
    }
}
