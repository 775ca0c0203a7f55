//! Joints. Ideal joints and drivers are constraint equations
//! `Phi(q, t) = 0` built from three primitives (point coincidence, relative
//! angle, axial projection); the clearance revolute joint is not a
//! constraint but a force element between a bearing and a journal, with an
//! optional lubricant film.

mod axial_projection;
mod clearance_revolute;
mod lubricated_film;
mod point_coincidence;
mod relative_angle;

pub use axial_projection::AxialProjection;
pub use clearance_revolute::{ClearanceRevolute, ContactEvaluation};
pub use lubricated_film::{FilmEvaluation, FilmModel, Lubrication};
pub use point_coincidence::PointCoincidence;
pub use relative_angle::RelativeAngle;

use crate::dynamics::frame::{BodyIndex, Frame};
use crate::motion::{MotionSample, TimeFunction};

/// What a constraint prescribes: a constant or a function of time.
#[derive(Clone, Debug, PartialEq)]
pub enum Target {
    /// A fixed value [m or rad].
    Fixed(f64),
    /// A driver function of time [m or rad].
    Driven(TimeFunction),
}

impl Target {
    /// Value, first and second time derivative at `t`.
    #[inline]
    pub fn sample(&self, t: f64) -> MotionSample {
        match self {
            Target::Fixed(v) => MotionSample { value: *v, rate: 0.0, acceleration: 0.0 },
            Target::Driven(f) => f.sample(t),
        }
    }
}

/// One kind of constraint equation set; every kind is listed here.
#[derive(Clone, Debug, PartialEq)]
pub enum ConstraintKind {
    /// Two points coincide (2 equations).
    PointCoincidence(PointCoincidence),
    /// Relative angle of two bodies prescribed (1 equation).
    RelativeAngle(RelativeAngle),
    /// Displacement along a body-fixed direction prescribed (1 equation).
    AxialProjection(AxialProjection),
}

/// One equation row of the constraint Jacobian `Phi_q`: the derivatives by
/// `(x, y, phi)` of the row's first and of its second body (see
/// [`ConstraintKind::bodies`]); no row involves more than two bodies, and the
/// block of a ground body is written but never read.
pub type RowJacobian = [[f64; 3]; 2];

/// Where a constraint writes its equations for one evaluation.
pub struct ConstraintRows<'a> {
    /// Constraint Jacobian `Phi_q` by rows (rows of this constraint start at `row`).
    pub jacobian: &'a mut [RowJacobian],
    /// First row of this constraint.
    pub row: usize,
    /// Right-hand side of the velocity equation `Phi_q qdot = nu` (`nu = -Phi_t`).
    pub nu: &'a mut [f64],
    /// Right-hand side of the acceleration equation `Phi_q qddot = gamma`.
    pub gamma: &'a mut [f64],
}

impl ConstraintKind {
    /// Number of scalar equations.
    pub fn n_equations(&self) -> usize {
        match self {
            Self::PointCoincidence(_) => 2,
            Self::RelativeAngle(_) | Self::AxialProjection(_) => 1,
        }
    }

    /// The first and the second body of every row, in the order of the blocks of [`RowJacobian`].
    pub fn bodies(&self) -> [BodyIndex; 2] {
        match self {
            Self::PointCoincidence(c) => [c.first.body, c.second.body],
            Self::RelativeAngle(c) => [c.first, c.second],
            Self::AxialProjection(c) => [c.first.body, c.second.body],
        }
    }

    /// Residuals `Phi(q, t)` into `out` (length `n_equations`) [m or rad].
    pub fn residual(&self, frames: &[Frame], t: f64, out: &mut [f64]) {
        match self {
            Self::PointCoincidence(c) => c.residual(frames, out),
            Self::RelativeAngle(c) => c.residual(frames, t, out),
            Self::AxialProjection(c) => c.residual(frames, t, out),
        }
    }

    /// Jacobian rows, `nu` and `gamma` at the current frames (positions and velocities).
    pub fn linearise(&self, frames: &[Frame], t: f64, rows: ConstraintRows<'_>) {
        match self {
            Self::PointCoincidence(c) => c.linearise(frames, rows),
            Self::RelativeAngle(c) => c.linearise(t, rows),
            Self::AxialProjection(c) => c.linearise(frames, t, rows),
        }
    }
}

/// A constraint and the model element (joint or driver) it belongs to.
#[derive(Clone, Debug, PartialEq)]
pub struct Constraint {
    /// The equations.
    pub kind: ConstraintKind,
    /// Index of the owning element in `Model::element_names`.
    pub owner: usize,
}

#[cfg(test)]
mod tests;
