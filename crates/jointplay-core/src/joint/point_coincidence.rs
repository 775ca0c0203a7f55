//! Point coincidence `P_i + offset - P_j = 0`: the revolute joint, half of
//! the fixed joint, and the temporary lock of a clearance joint at assembly.

use super::{ConstraintRows, MarkerLoad};
use crate::kinematics::marker::Marker;
use crate::kinematics::planar::{Frame, Vec2};

/// Two body points held at a constant global offset (zero for a revolute joint).
#[derive(Clone, Debug, PartialEq)]
pub struct PointCoincidence {
    /// Point on the first body.
    pub first: Marker,
    /// Point on the second body.
    pub second: Marker,
    /// Required `P_j - P_i` in the global frame [m].
    pub offset: Vec2,
}

impl PointCoincidence {
    /// `Phi = P_i + offset - P_j` [m].
    pub fn residual(&self, frames: &[Frame], out: &mut [f64]) {
        let pi = frames[self.first.frame].point(self.first.local);
        let pj = frames[self.second.frame].point(self.second.local);
        let r = pi + self.offset - pj;
        out[0] = r.x;
        out[1] = r.y;
    }

    /// Jacobian: the marker Jacobians, `+J_Pi - J_Pj`, row x along `e_x` and
    /// row y along `e_y`; `nu = 0`; `gamma = -(a0_Pi - a0_Pj)` with `a0` the
    /// markers' velocity-dependent accelerations (`-omega^2 A s` on a rigid body).
    pub fn linearise(&self, frames: &[Frame], mut rows: ConstraintRows<'_>) {
        rows.set_point_jacobian_rows(frames, 0, 0, &self.first, 1.0);
        rows.set_point_jacobian_rows(frames, 0, 1, &self.second, -1.0);
        let g = rows.bias_acceleration(frames, &self.second) - rows.bias_acceleration(frames, &self.first);
        let r = rows.row;
        rows.nu[r] = 0.0;
        rows.nu[r + 1] = 0.0;
        rows.gamma[r] = g.x;
        rows.gamma[r + 1] = g.y;
    }

    /// `-Phi_q^T lambda`: the force `-lambda` at the first point, `+lambda` at the second.
    pub fn loads(&self, frames: &[Frame], lambda: &[f64]) -> [MarkerLoad; 2] {
        let f = Vec2::new(lambda[0], lambda[1]);
        let at = |m: &Marker, force: Vec2| MarkerLoad { force, point: frames[m.frame].point(m.local), moment: 0.0 };
        [at(&self.first, -f), at(&self.second, f)]
    }
}
