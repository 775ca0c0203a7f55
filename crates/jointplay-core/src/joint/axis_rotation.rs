//! Rotation about an axis `theta - f(t) = 0` (one equation): the angle from
//! the first marker's x axis to the second marker's x axis about the first
//! marker's z axis, `theta = atan2(x_j . y_i, x_j . x_i)`; the driver of a
//! revolute or cylindrical joint, whose other equations keep the z axes aligned.

use super::{ConstraintRows, MarkerWrench, Target};
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::SpatialMarker;
use crate::kinematics::spatial::Vec3;
use crate::kinematics::wrench::Wrench;
use std::f64::consts::PI;

/// The rotation of the second marker about the first marker's z axis is prescribed.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisRotation {
    /// Marker on the first body.
    pub first: SpatialMarker,
    /// Marker on the second body.
    pub second: SpatialMarker,
    /// Prescribed angle [rad].
    pub target: Target,
}

impl AxisRotation {
    /// `theta` [rad] in `(-pi, pi]`.
    fn angle(&self, frames: &Frames<'_>) -> f64 {
        let xj = frames.axis(&self.second, 0);
        xj.dot(&frames.axis(&self.first, 1)).atan2(xj.dot(&frames.axis(&self.first, 0)))
    }

    /// `Phi = theta - f(t)`, wrapped to `(-pi, pi]` [rad] (the driven angle
    /// may grow without bound; the measured one turns round).
    pub fn residual(&self, frames: &Frames<'_>, t: f64, out: &mut [f64]) {
        out[0] = wrap(self.angle(frames) - self.target.sample(t).value);
    }

    /// `Phi_dot = z_i . (w_j - w_i)` (exact while the z axes are aligned, as the
    /// joint keeps them): angular Jacobians along `-+z_i`; `nu = f_dot`;
    /// `gamma = f_ddot - (w_i x z_i) . (w_j - w_i) - z_i . (alpha0_j - alpha0_i)`.
    #[inline(never)]
    pub fn linearise(&self, frames: &Frames<'_>, t: f64, mut rows: ConstraintRows<'_>) {
        let z = frames.axis(&self.first, 2);
        rows.add_spatial_angular_jacobian(frames, 0, 0, &self.first, -z);
        rows.add_spatial_angular_jacobian(frames, 0, 1, &self.second, z);
        let (wi, wj) = (frames.angular_velocity(&self.first), frames.angular_velocity(&self.second));
        let bias = rows.spatial_bias(frames, &self.second).1 - rows.spatial_bias(frames, &self.first).1;
        let target = self.target.sample(t);
        let row = rows.row;
        rows.nu[row] = target.rate;
        rows.gamma[row] = target.acceleration - wi.cross(&z).dot(&(wj - wi)) - z.dot(&bias);
    }

    /// `-Phi_q^T lambda`: the moment `+lambda z_i` on the first body, `-lambda z_i` on the second.
    pub fn loads(&self, frames: &Frames<'_>, lambda: &[f64]) -> [MarkerWrench; 2] {
        let m = frames.axis(&self.first, 2) * lambda[0];
        let at = |marker: &SpatialMarker, moment: Vec3| MarkerWrench { point: frames.point(marker), wrench: Wrench { force: Vec3::zeros(), moment } };
        [at(&self.first, m), at(&self.second, -m)]
    }
}

/// `x` moved by whole turns into `(-pi, pi]` [rad].
fn wrap(x: f64) -> f64 {
    let y = x - 2.0 * PI * (x / (2.0 * PI)).round();
    if y <= -PI { y + 2.0 * PI } else { y }
}
