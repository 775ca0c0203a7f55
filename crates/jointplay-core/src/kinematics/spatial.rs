//! Spatial frames: the pose of a body or marker frame and its velocity.

use nalgebra::{Matrix3, Vector3};

use super::planar::Frame;

/// 3D vector [m, m/s, N, ...].
pub type Vec3 = Vector3<f64>;

/// 3x3 matrix (rotation [-], inertia tensor [kg m^2], ...).
pub type Mat3 = Matrix3<f64>;

/// `[a]x`: the matrix of the cross product, `skew(a) b = a x b`.
#[inline]
pub fn skew(a: Vec3) -> Mat3 {
    Mat3::new(0.0, -a.z, a.y, a.z, 0.0, -a.x, -a.y, a.x, 0.0)
}

/// Pose and velocity of one frame in space (the ground is the identity at rest).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpatialFrame {
    /// Position of the origin [m].
    pub position: Vec3,
    /// Rotation matrix from frame to global coordinates [-].
    pub rotation: Mat3,
    /// Velocity of the origin [m/s].
    pub velocity: Vec3,
    /// Angular velocity in global coordinates [rad/s].
    pub angular_velocity: Vec3,
}

impl Default for SpatialFrame {
    fn default() -> Self {
        Self::GROUND
    }
}

impl SpatialFrame {
    /// The ground frame.
    pub const GROUND: SpatialFrame = SpatialFrame {
        position: Vec3::new(0.0, 0.0, 0.0),
        rotation: Mat3::new(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0),
        velocity: Vec3::new(0.0, 0.0, 0.0),
        angular_velocity: Vec3::new(0.0, 0.0, 0.0),
    };

    /// A planar frame embedded in space: in the plane `z = 0`, turned about `z`.
    #[inline]
    pub fn from_planar(frame: &Frame) -> SpatialFrame {
        let (c, s) = (frame.cos, frame.sin);
        SpatialFrame {
            position: Vec3::new(frame.position.x, frame.position.y, 0.0),
            rotation: Mat3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0),
            velocity: Vec3::new(frame.velocity.x, frame.velocity.y, 0.0),
            angular_velocity: Vec3::new(0.0, 0.0, frame.angular_velocity),
        }
    }

    /// `R s`: a frame vector in global coordinates.
    #[inline]
    pub fn rotate(&self, s: Vec3) -> Vec3 {
        self.rotation * s
    }

    /// `R^T a`: a global vector in frame coordinates.
    #[inline]
    pub fn to_local(&self, a: Vec3) -> Vec3 {
        self.rotation.transpose() * a
    }

    /// Global position of the frame point `s` [m].
    #[inline]
    pub fn point(&self, s: Vec3) -> Vec3 {
        self.position + self.rotation * s
    }

    /// Global velocity of the frame point `s` [m/s].
    #[inline]
    pub fn point_velocity(&self, s: Vec3) -> Vec3 {
        self.velocity + self.angular_velocity.cross(&(self.rotation * s))
    }

    /// Velocity [m/s] of the material point of this frame's body at the global position `p` [m].
    #[inline]
    pub fn material_velocity_at(&self, p: Vec3) -> Vec3 {
        self.velocity + self.angular_velocity.cross(&(p - self.position))
    }

    /// Acceleration [m/s^2] of the frame point `s` at zero acceleration of the
    /// frame's coordinates: `omega x (omega x R s)`.
    #[inline]
    pub fn point_centripetal_acceleration(&self, s: Vec3) -> Vec3 {
        let w = self.angular_velocity;
        w.cross(&w.cross(&(self.rotation * s)))
    }

    /// Axis `k` (0 x, 1 y, 2 z) of the frame in global coordinates [-].
    #[inline]
    pub fn axis(&self, k: usize) -> Vec3 {
        self.rotation.column(k).into_owned()
    }

    /// The frame of a marker fixed to this one at `local` [m] with axes `axes`
    /// (columns: the marker's axes in this frame's coordinates).
    #[inline]
    pub fn compose(&self, local: Vec3, axes: &Mat3) -> SpatialFrame {
        SpatialFrame {
            position: self.point(local),
            rotation: self.rotation * axes,
            velocity: self.point_velocity(local),
            angular_velocity: self.angular_velocity,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_planar_frame_moves_points_as_the_planar_frame() {
        let planar = Frame::from_coordinates(&[0.3, -0.1, 0.7], &[1.5, -2.0, 3.0]);
        let spatial = SpatialFrame::from_planar(&planar);
        let s = crate::kinematics::planar::Vec2::new(0.2, -0.4);
        let (p, v) = (planar.point(s), planar.point_velocity(s));
        let (p3, v3) = (spatial.point(Vec3::new(s.x, s.y, 0.05)), spatial.point_velocity(Vec3::new(s.x, s.y, 0.05)));
        assert!((p3 - Vec3::new(p.x, p.y, 0.05)).norm() < 1e-15);
        assert!((v3 - Vec3::new(v.x, v.y, 0.0)).norm() < 1e-15);
        assert!((spatial.rotation.determinant() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn point_velocity_is_the_derivative_of_the_point() {
        // a frame turning about a fixed axis: finite difference of the point against point_velocity
        let axis = Vec3::new(1.0, 2.0, 2.0) / 3.0;
        let (rate, s) = (1.3, Vec3::new(0.1, 0.2, -0.3));
        let at = |t: f64| SpatialFrame {
            position: Vec3::new(t, 2.0 * t, 0.0),
            rotation: *nalgebra::Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(axis), rate * t).matrix(),
            velocity: Vec3::new(1.0, 2.0, 0.0),
            angular_velocity: axis * rate,
        };
        let h = 1e-6;
        let numeric = (at(0.4 + h).point(s) - at(0.4 - h).point(s)) / (2.0 * h);
        assert!((numeric - at(0.4).point_velocity(s)).norm() < 1e-9);
        let numeric_velocity = (at(0.4 + h).point_velocity(s) - at(0.4 - h).point_velocity(s)) / (2.0 * h);
        assert!((numeric_velocity - at(0.4).point_centripetal_acceleration(s)).norm() < 1e-8);
        assert_eq!(skew(axis) * s, axis.cross(&s));
    }
}
