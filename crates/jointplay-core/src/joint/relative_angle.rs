//! Relative angle `phi_j - phi_i - theta(t) = 0` of two markers' frames: the
//! rotation lock of translational and fixed joints, and the angle driver of a
//! revolute joint.

use super::{ConstraintRows, MarkerLoad, Target};
use crate::kinematics::marker::Marker;
use crate::kinematics::planar::{Frame, Vec2};

/// The angle of the second frame relative to the first is prescribed.
#[derive(Clone, Debug, PartialEq)]
pub struct RelativeAngle {
    /// Frame on the first body.
    pub first: Marker,
    /// Frame on the second body.
    pub second: Marker,
    /// Prescribed `phi_j - phi_i` [rad].
    pub target: Target,
}

impl RelativeAngle {
    /// `Phi = phi_j - phi_i - theta(t)` [rad].
    pub fn residual(&self, frames: &[Frame], t: f64, out: &mut [f64]) {
        out[0] = frames[self.second.frame].angle - frames[self.first.frame].angle - self.target.sample(t).value;
    }

    /// Jacobian `[-1 on phi_i, +1 on phi_j]` (the bodies' angle Jacobians),
    /// `nu = theta_dot`, `gamma = theta_ddot - (a0_j - a0_i)` with `a0` the
    /// velocity-dependent angular accelerations (zero on a rigid body).
    pub fn linearise(&self, frames: &[Frame], t: f64, mut rows: ConstraintRows<'_>) {
        rows.add_angle_jacobian(0, 0, &self.first, -1.0);
        rows.add_angle_jacobian(0, 1, &self.second, 1.0);
        let target = self.target.sample(t);
        let bias = rows.bias_angular_acceleration(frames, &self.second) - rows.bias_angular_acceleration(frames, &self.first);
        rows.nu[rows.row] = target.rate;
        rows.gamma[rows.row] = target.acceleration - bias;
    }

    /// `-Phi_q^T lambda`: the moment `+lambda` on the first body, `-lambda` on the second.
    pub fn loads(&self, frames: &[Frame], lambda: &[f64]) -> [MarkerLoad; 2] {
        let on = |marker: &Marker, moment: f64| MarkerLoad { force: Vec2::zeros(), point: frames[marker.frame].position, moment };
        [on(&self.first, lambda[0]), on(&self.second, -lambda[0])]
    }
}
