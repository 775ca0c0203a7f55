//! Relative angle `phi_j - phi_i - theta(t) = 0`: the rotation lock of
//! translational and fixed joints, and the angle driver of a revolute joint.

use super::{ConstraintRows, Target};
use crate::dynamics::frame::{BodyIndex, Frame};

/// The angle of the second body relative to the first is prescribed.
#[derive(Clone, Debug, PartialEq)]
pub struct RelativeAngle {
    /// First body.
    pub first: BodyIndex,
    /// Second body.
    pub second: BodyIndex,
    /// Prescribed `phi_j - phi_i` [rad].
    pub target: Target,
}

impl RelativeAngle {
    /// `Phi = phi_j - phi_i - theta(t)` [rad].
    pub fn residual(&self, frames: &[Frame], t: f64, out: &mut [f64]) {
        out[0] = frames[self.second.0].angle - frames[self.first.0].angle - self.target.sample(t).value;
    }

    /// Jacobian `[-1 on phi_i, +1 on phi_j]`, `nu = theta_dot`, `gamma = theta_ddot`.
    pub fn linearise(&self, t: f64, rows: ConstraintRows<'_>) {
        let r = rows.row;
        rows.jacobian[r] = [[0.0, 0.0, -1.0], [0.0, 0.0, 1.0]];
        let target = self.target.sample(t);
        rows.nu[r] = target.rate;
        rows.gamma[r] = target.acceleration;
    }
}
