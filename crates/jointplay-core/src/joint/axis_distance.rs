//! Distance along an axis `a_i . (P_j - P_i) - f(t) = 0` (one equation), with
//! `a_i` an axis of the first marker's frame: held at zero across the axis it
//! keeps a cylindrical or translational joint's second point on the first's
//! line; along the axis and driven, it is the displacement driver.

use super::{ConstraintRows, MarkerWrench, Target};
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::SpatialMarker;
use crate::kinematics::spatial::Vec3;
use crate::kinematics::wrench::Wrench;

/// The projection of `P_j - P_i` on axis `axis` of the first marker is prescribed.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisDistance {
    /// Marker on the first body (its axis turns with it).
    pub first: SpatialMarker,
    /// Point on the second body.
    pub second: SpatialMarker,
    /// Axis of the first marker's frame (0 x, 1 y, 2 z).
    pub axis: usize,
    /// Prescribed distance [m].
    pub target: Target,
}

impl AxisDistance {
    /// The axis `a_i` and the vector `d = P_j - P_i`.
    fn geometry(&self, frames: &Frames<'_>) -> (Vec3, Vec3) {
        (frames.axis(&self.first, self.axis), frames.point(&self.second) - frames.point(&self.first))
    }

    /// `Phi = a_i . d - f(t)` [m].
    pub fn residual(&self, frames: &Frames<'_>, t: f64, out: &mut [f64]) {
        let (a, d) = self.geometry(frames);
        out[0] = a.dot(&d) - self.target.sample(t).value;
    }

    /// `Phi_dot = a_i . (v_Pj - v_Pi) + (a_i x d) . w_i`: point Jacobians along
    /// `+-a_i` and the first marker's angular Jacobian along `a_i x d`;
    /// `nu = f_dot`; `gamma = f_ddot` minus the velocity-dependent part of `Phi_ddot`.
    #[inline(never)]
    pub fn linearise(&self, frames: &Frames<'_>, t: f64, mut rows: ConstraintRows<'_>) {
        let (a, d) = self.geometry(frames);
        rows.add_spatial_point_jacobian(frames, 0, 0, &self.first, -a);
        rows.add_spatial_point_jacobian(frames, 0, 1, &self.second, a);
        rows.add_spatial_angular_jacobian(frames, 0, 0, &self.first, a.cross(&d));
        let w = frames.angular_velocity(&self.first);
        let a_dot = w.cross(&a);
        let d_dot = frames.point_velocity(&self.second) - frames.point_velocity(&self.first);
        let (bias_i, bias_j) = (rows.spatial_bias(frames, &self.first), rows.spatial_bias(frames, &self.second));
        // d/dt (a . d) = a_dot . d + a . d_dot; at zero coordinate accelerations:
        // w x (w x a) . d + 2 a_dot . d_dot + a . (a0_Pj - a0_Pi) + (alpha0_i x a) . d
        let bias = w.cross(&a_dot).dot(&d) + 2.0 * a_dot.dot(&d_dot) + a.dot(&(bias_j.0 - bias_i.0)) + bias_i.1.cross(&a).dot(&d);
        let target = self.target.sample(t);
        let row = rows.row;
        rows.nu[row] = target.rate;
        rows.gamma[row] = target.acceleration - bias;
    }

    /// `-Phi_q^T lambda`: the force `+lambda a_i` at the first point with the
    /// moment `-lambda a_i x d` of the turning axis, the force `-lambda a_i` at the second point.
    pub fn loads(&self, frames: &Frames<'_>, lambda: &[f64]) -> [MarkerWrench; 2] {
        let (a, d) = self.geometry(frames);
        let l = lambda[0];
        [
            MarkerWrench { point: frames.point(&self.first), wrench: Wrench { force: a * l, moment: -a.cross(&d) * l } },
            MarkerWrench { point: frames.point(&self.second), wrench: Wrench { force: -a * l, moment: Vec3::zeros() } },
        ]
    }
}
