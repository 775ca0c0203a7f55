//! Spatial point coincidence `P_i - P_j = 0` (three equations, global x, y, z):
//! the spherical joint, and the point part of the revolute, universal and fixed joints.

use super::{ConstraintRows, MarkerWrench};
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::SpatialMarker;
use crate::kinematics::spatial::Vec3;
use crate::kinematics::wrench::Wrench;

/// Two marker points held together.
#[derive(Clone, Debug, PartialEq)]
pub struct SpatialPointCoincidence {
    /// Point on the first body.
    pub first: SpatialMarker,
    /// Point on the second body.
    pub second: SpatialMarker,
}

/// The global unit vectors, the directions of the three rows.
const AXES: [Vec3; 3] = [Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, 0.0, 1.0)];

impl SpatialPointCoincidence {
    /// `Phi = P_i - P_j` [m].
    pub fn residual(&self, frames: &Frames<'_>, out: &mut [f64]) {
        let r = frames.point(&self.first) - frames.point(&self.second);
        out[..3].copy_from_slice(r.as_slice());
    }

    /// Jacobian `+J_Pi - J_Pj` along each global axis; `nu = 0`;
    /// `gamma = -(a0_Pi - a0_Pj)`, `a0` the markers' velocity-dependent accelerations.
    #[inline(never)]
    pub fn linearise(&self, frames: &Frames<'_>, mut rows: ConstraintRows<'_>) {
        for (r, axis) in AXES.iter().enumerate() {
            rows.add_spatial_point_jacobian(frames, r, 0, &self.first, *axis);
            rows.add_spatial_point_jacobian(frames, r, 1, &self.second, -*axis);
        }
        let gamma = rows.spatial_bias(frames, &self.second).0 - rows.spatial_bias(frames, &self.first).0;
        let row = rows.row;
        rows.nu[row..row + 3].fill(0.0);
        rows.gamma[row..row + 3].copy_from_slice(gamma.as_slice());
    }

    /// `-Phi_q^T lambda`: the force `-lambda` at the first point, `+lambda` at the second.
    pub fn loads(&self, frames: &Frames<'_>, lambda: &[f64]) -> [MarkerWrench; 2] {
        let f = Vec3::new(lambda[0], lambda[1], lambda[2]);
        let at = |m: &SpatialMarker, force: Vec3| MarkerWrench { point: frames.point(m), wrench: Wrench { force, moment: Vec3::zeros() } };
        [at(&self.first, -f), at(&self.second, f)]
    }
}
