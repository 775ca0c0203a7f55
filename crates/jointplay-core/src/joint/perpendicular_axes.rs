//! Perpendicular axes `a_i . a_j = 0` (one equation) between an axis of the
//! first marker's frame and an axis of the second's: two of them keep a
//! revolute joint's axes aligned, one is the cross of a universal joint.

use super::{ConstraintRows, MarkerWrench};
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::SpatialMarker;
use crate::kinematics::spatial::Vec3;
use crate::kinematics::wrench::Wrench;

/// Axis `first_axis` of the first marker stays perpendicular to axis `second_axis` of the second.
#[derive(Clone, Debug, PartialEq)]
pub struct PerpendicularAxes {
    /// Marker on the first body.
    pub first: SpatialMarker,
    /// Marker on the second body.
    pub second: SpatialMarker,
    /// Axis of the first marker's frame (0 x, 1 y, 2 z).
    pub first_axis: usize,
    /// Axis of the second marker's frame.
    pub second_axis: usize,
}

impl PerpendicularAxes {
    /// The two axes in global coordinates.
    fn axes(&self, frames: &Frames<'_>) -> (Vec3, Vec3) {
        (frames.axis(&self.first, self.first_axis), frames.axis(&self.second, self.second_axis))
    }

    /// `Phi = a_i . a_j` [-].
    pub fn residual(&self, frames: &Frames<'_>, out: &mut [f64]) {
        let (ai, aj) = self.axes(frames);
        out[0] = ai.dot(&aj);
    }

    /// `Phi_dot = (a_i x a_j) . (w_i - w_j)`: the angular Jacobians along
    /// `+-(a_i x a_j)`; `nu = 0`; `gamma` minus the velocity-dependent part of
    /// `Phi_ddot`, `d/dt(a_i x a_j) . (w_i - w_j)` plus the markers' angular biases.
    #[inline(never)]
    pub fn linearise(&self, frames: &Frames<'_>, mut rows: ConstraintRows<'_>) {
        let (ai, aj) = self.axes(frames);
        let n = ai.cross(&aj);
        rows.add_spatial_angular_jacobian(frames, 0, 0, &self.first, n);
        rows.add_spatial_angular_jacobian(frames, 0, 1, &self.second, -n);
        let (wi, wj) = (frames.angular_velocity(&self.first), frames.angular_velocity(&self.second));
        let n_dot = wi.cross(&ai).cross(&aj) + ai.cross(&wj.cross(&aj));
        let bias = rows.spatial_bias(frames, &self.first).1 - rows.spatial_bias(frames, &self.second).1;
        let row = rows.row;
        rows.nu[row] = 0.0;
        rows.gamma[row] = -(n_dot.dot(&(wi - wj)) + n.dot(&bias));
    }

    /// `-Phi_q^T lambda`: the moment `-lambda a_i x a_j` on the first body, `+lambda a_i x a_j` on the second.
    pub fn loads(&self, frames: &Frames<'_>, lambda: &[f64]) -> [MarkerWrench; 2] {
        let (ai, aj) = self.axes(frames);
        let m = ai.cross(&aj) * lambda[0];
        let at = |marker: &SpatialMarker, moment: Vec3| MarkerWrench { point: frames.point(marker), wrench: Wrench { force: Vec3::zeros(), moment } };
        [at(&self.first, -m), at(&self.second, m)]
    }
}
