//! Point coincidence `P_i + offset - P_j = 0`: the revolute joint, half of
//! the fixed joint, and the temporary lock of a clearance joint at assembly.

use super::ConstraintRows;
use crate::dynamics::frame::{Marker, Frame, Vec2};

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
        let pi = frames[self.first.body.0].point(self.first.local);
        let pj = frames[self.second.body.0].point(self.second.local);
        let r = pi + self.offset - pj;
        out[0] = r.x;
        out[1] = r.y;
    }

    /// Jacobian `[I, perp(A_i s_i); -I, -perp(A_j s_j)]`, `nu = 0`,
    /// `gamma = A_i s_i w_i^2 - A_j s_j w_j^2`.
    pub fn linearise(&self, frames: &[Frame], rows: ConstraintRows<'_>) {
        let (fi, fj) = (&frames[self.first.body.0], &frames[self.second.body.0]);
        let si = fi.rotate(self.first.local);
        let sj = fj.rotate(self.second.local);
        let r = rows.row;
        rows.jacobian[r] = [[1.0, 0.0, -si.y], [-1.0, 0.0, sj.y]];
        rows.jacobian[r + 1] = [[0.0, 1.0, si.x], [0.0, -1.0, -sj.x]];
        let g = si * fi.angular_velocity.powi(2) - sj * fj.angular_velocity.powi(2);
        rows.nu[r] = 0.0;
        rows.nu[r + 1] = 0.0;
        rows.gamma[r] = g.x;
        rows.gamma[r + 1] = g.y;
    }
}
