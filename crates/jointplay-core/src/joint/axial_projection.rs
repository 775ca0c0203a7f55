//! Axial projection `u . (P_j - P_i) - f(t) = 0` with `u = A_i u'` a unit
//! direction fixed in the first body: with `u'` normal to the sliding axis it
//! keeps the second point on the line of a translational joint; with `u'`
//! along the axis it is the displacement driver of that joint.

use super::{ConstraintRows, MarkerLoad, Target};
use crate::kinematics::marker::Marker;
use crate::kinematics::planar::{perp, Frame, Vec2};

/// Projection of the point-to-point vector on a body-fixed direction is prescribed.
#[derive(Clone, Debug, PartialEq)]
pub struct AxialProjection {
    /// Point on the first body (on the sliding line).
    pub first: Marker,
    /// Point on the second body.
    pub second: Marker,
    /// Unit direction `u'` in the first body's frame [-].
    pub direction: Vec2,
    /// Prescribed projection [m].
    pub target: Target,
}

impl AxialProjection {
    /// `Phi = u . d - f(t)` with `d = P_j - P_i` [m].
    pub fn residual(&self, frames: &[Frame], t: f64, out: &mut [f64]) {
        let fi = &frames[self.first.frame];
        let d = frames[self.second.frame].point(self.second.local) - fi.point(self.first.local);
        out[0] = fi.rotate(self.direction).dot(&d) - self.target.sample(t).value;
    }

    /// Jacobian: `u . (J_Pj - J_Pi) + (perp(u) . d) J_phi_i` (the markers'
    /// point Jacobians and the first body's angle Jacobian, `u` turning with it);
    /// `nu = f_dot`; `gamma = w_i^2 u.d - 2 w_i perp(u).d_dot - u.(a0_Pj - a0_Pi) + f_ddot`
    /// with `a0` the markers' velocity-dependent accelerations.
    pub fn linearise(&self, frames: &[Frame], t: f64, mut rows: ConstraintRows<'_>) {
        let (fi, fj) = (&frames[self.first.frame], &frames[self.second.frame]);
        let u = fi.rotate(self.direction);
        let d = fj.point(self.second.local) - fi.point(self.first.local);
        let d_dot = fj.point_velocity(self.second.local) - fi.point_velocity(self.first.local);
        rows.add_point_jacobian(frames, 0, 0, &self.first, -u);
        rows.add_point_jacobian(frames, 0, 1, &self.second, u);
        rows.add_angle_jacobian(0, 0, &self.first, perp(u).dot(&d));
        let wi = fi.angular_velocity;
        let bias = rows.bias_acceleration(frames, &self.second) - rows.bias_acceleration(frames, &self.first);
        let target = self.target.sample(t);
        rows.nu[rows.row] = target.rate;
        rows.gamma[rows.row] = wi * wi * u.dot(&d) - 2.0 * wi * perp(u).dot(&d_dot) - u.dot(&bias) + target.acceleration;
    }

    /// `-Phi_q^T lambda`: the force `+lambda u` at the first point with the
    /// moment `-lambda perp(u) . d` of the turning direction on the first body,
    /// the force `-lambda u` at the second point.
    pub fn loads(&self, frames: &[Frame], lambda: &[f64]) -> [MarkerLoad; 2] {
        let (fi, fj) = (&frames[self.first.frame], &frames[self.second.frame]);
        let u = fi.rotate(self.direction);
        let (pi, pj) = (fi.point(self.first.local), fj.point(self.second.local));
        let l = lambda[0];
        [MarkerLoad { force: u * l, point: pi, moment: -l * perp(u).dot(&(pj - pi)) }, MarkerLoad { force: -u * l, point: pj, moment: 0.0 }]
    }
}
