//! The planar vocabulary: vectors of the plane and the pose and velocity of a
//! planar frame, the planar bodies' fast path (embedded in space by
//! [`super::spatial::SpatialFrame::from_planar`]).

use nalgebra::Vector2;

/// 2D vector [m, m/s, N, ...].
pub type Vec2 = Vector2<f64>;

/// `perp(v)`: `v` turned by +90 degrees, so that `d(A s)/dphi = perp(A s)`
/// and `omega x v = omega perp(v)`.
#[inline]
pub fn perp(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// z component of the planar cross product `a x b`.
#[inline]
pub fn cross(a: Vec2, b: Vec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Pose and velocity of one body frame (the ground is the identity at rest).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Position of the origin (centre of mass) [m].
    pub position: Vec2,
    /// Orientation [rad].
    pub angle: f64,
    /// cos(angle) [-].
    pub cos: f64,
    /// sin(angle) [-].
    pub sin: f64,
    /// Velocity of the origin [m/s].
    pub velocity: Vec2,
    /// Angular velocity [rad/s].
    pub angular_velocity: f64,
}

impl Frame {
    /// The ground frame.
    pub const GROUND: Frame = Frame {
        position: Vec2::new(0.0, 0.0),
        angle: 0.0,
        cos: 1.0,
        sin: 0.0,
        velocity: Vec2::new(0.0, 0.0),
        angular_velocity: 0.0,
    };

    /// Frame of a body from its coordinates `(x, y, phi)` and their rates.
    #[inline]
    pub fn from_coordinates(q: &[f64], qdot: &[f64]) -> Frame {
        Self::with_sin_cos(q, qdot, q[2].sin_cos())
    }

    /// [`Frame::from_coordinates`], taking cos and sin from `previous` when its
    /// angle is bit for bit the same: successive evaluations often share positions
    /// (a projection, then the evaluation of the projected state).
    #[inline]
    pub fn from_coordinates_after(previous: &Frame, q: &[f64], qdot: &[f64]) -> Frame {
        let sin_cos = if previous.angle.to_bits() == q[2].to_bits() { (previous.sin, previous.cos) } else { q[2].sin_cos() };
        Self::with_sin_cos(q, qdot, sin_cos)
    }

    /// Moves the frame to `(x, y, phi)` with rates `qdot` in place, as
    /// [`Frame::from_coordinates_after`] with itself as the previous frame (no
    /// temporary frame: assigning a returned one through the reference it was
    /// computed from makes the compiler build it on the stack and copy it).
    #[inline]
    pub fn move_to(&mut self, q: &[f64], qdot: &[f64]) {
        if self.angle.to_bits() != q[2].to_bits() {
            (self.sin, self.cos) = q[2].sin_cos();
            self.angle = q[2];
        }
        self.position = Vec2::new(q[0], q[1]);
        self.velocity = Vec2::new(qdot[0], qdot[1]);
        self.angular_velocity = qdot[2];
    }

    /// Frame from `(x, y, phi)`, their rates and `(sin phi, cos phi)`.
    #[inline]
    fn with_sin_cos(q: &[f64], qdot: &[f64], (sin, cos): (f64, f64)) -> Frame {
        Frame {
            position: Vec2::new(q[0], q[1]),
            angle: q[2],
            cos,
            sin,
            velocity: Vec2::new(qdot[0], qdot[1]),
            angular_velocity: qdot[2],
        }
    }

    /// `A s`: a body-frame vector expressed in the global frame.
    #[inline]
    pub fn rotate(&self, s: Vec2) -> Vec2 {
        Vec2::new(self.cos * s.x - self.sin * s.y, self.sin * s.x + self.cos * s.y)
    }

    /// Global position of a body point [m].
    #[inline]
    pub fn point(&self, s: Vec2) -> Vec2 {
        self.position + self.rotate(s)
    }

    /// Global velocity of a body point [m/s].
    #[inline]
    pub fn point_velocity(&self, s: Vec2) -> Vec2 {
        self.velocity + perp(self.rotate(s)) * self.angular_velocity
    }

    /// Velocity [m/s] of the material point of this body that is at the
    /// global position `p` [m] (not necessarily a named point).
    #[inline]
    pub fn material_velocity_at(&self, p: Vec2) -> Vec2 {
        self.velocity + perp(p - self.position) * self.angular_velocity
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_after_a_previous_one_equals_a_fresh_frame() {
        let (q, qdot) = ([0.1, -0.2, 0.7], [1.0, 2.0, -3.0]);
        let fresh = Frame::from_coordinates(&q, &qdot);
        // same angle: cos and sin taken over, and they are the ones sin_cos gives
        assert_eq!(Frame::from_coordinates_after(&fresh, &[0.5, 0.5, 0.7], &qdot).sin, fresh.sin);
        assert_eq!(Frame::from_coordinates_after(&fresh, &q, &qdot), fresh);
        // another angle (or a stale frame): computed anew
        let stale = Frame { sin: 9.0, ..fresh };
        assert_eq!(Frame::from_coordinates_after(&stale, &[0.1, -0.2, 0.8], &qdot), Frame::from_coordinates(&[0.1, -0.2, 0.8], &qdot));
        assert_eq!(Frame::from_coordinates_after(&Frame::GROUND, &q, &qdot), fresh);
        // in place, the same
        for (start, q) in [(fresh, [0.5, 0.5, 0.7]), (stale, [0.1, -0.2, 0.8]), (Frame::GROUND, q)] {
            let mut moved = start;
            moved.move_to(&q, &qdot);
            assert_eq!(moved, Frame::from_coordinates_after(&start, &q, &qdot));
        }
    }
}
