//! Axial projection `u . (P_j - P_i) - f(t) = 0` with `u = A_i u'` a unit
//! direction fixed in the first body: with `u'` normal to the sliding axis it
//! keeps the second point on the line of a translational joint; with `u'`
//! along the axis it is the displacement driver of that joint.

use super::{ConstraintRows, Target};
use crate::dynamics::frame::{perp, Marker, Frame, Vec2};

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
        let fi = &frames[self.first.body.0];
        let d = frames[self.second.body.0].point(self.second.local) - fi.point(self.first.local);
        out[0] = fi.rotate(self.direction).dot(&d) - self.target.sample(t).value;
    }

    /// Jacobian: `r_i: -u`, `phi_i: perp(u).d - u.perp(A_i s_i)`, `r_j: u`,
    /// `phi_j: u.perp(A_j s_j)`; `nu = f_dot`;
    /// `gamma = w_i^2 u.d - 2 w_i perp(u).d_dot + u.(w_j^2 A_j s_j - w_i^2 A_i s_i) + f_ddot`.
    pub fn linearise(&self, frames: &[Frame], t: f64, rows: ConstraintRows<'_>) {
        let (fi, fj) = (&frames[self.first.body.0], &frames[self.second.body.0]);
        let (si, sj) = (fi.rotate(self.first.local), fj.rotate(self.second.local));
        let u = fi.rotate(self.direction);
        let d = fj.position + sj - fi.position - si;
        let d_dot = fj.point_velocity(self.second.local) - fi.point_velocity(self.first.local);
        rows.jacobian[rows.row] = [[-u.x, -u.y, perp(u).dot(&d) - u.dot(&perp(si))], [u.x, u.y, u.dot(&perp(sj))]];
        let (wi, wj) = (fi.angular_velocity, fj.angular_velocity);
        let target = self.target.sample(t);
        rows.nu[rows.row] = target.rate;
        rows.gamma[rows.row] = wi * wi * u.dot(&d) - 2.0 * wi * perp(u).dot(&d_dot)
            + u.dot(&(sj * (wj * wj) - si * (wi * wi)))
            + target.acceleration;
    }
}
