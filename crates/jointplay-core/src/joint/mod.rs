//! Joints. Ideal joints and drivers are constraint equations
//! `Phi(q, t) = 0` built from primitives: in the plane point coincidence,
//! relative angle and axial projection; in space point coincidence,
//! perpendicular axes, distance along an axis and rotation about an axis
//! (`docs/theory/spatial-joints.md`). The clearance revolute joint is not a
//! constraint but a force element between a bearing and a journal, with an
//! optional lubricant film, an event at contact onset and a discrete memory
//! (`clearance_element.rs`).

mod axial_projection;
mod axis_distance;
mod axis_rotation;
mod clearance_element;
mod clearance_revolute;
mod ideal;
mod lubricated_film;
mod perpendicular_axes;
mod point_coincidence;
mod relative_angle;
mod spatial_clearance_element;
mod spatial_clearance_geometry;
mod spatial_clearance_modes;
mod spatial_clearance_revolute;
mod spatial_point_coincidence;

pub use axial_projection::AxialProjection;
pub use axis_distance::AxisDistance;
pub use axis_rotation::AxisRotation;
pub use clearance_element::{ClearanceWork, ContactMemory, CHANNELS as CLEARANCE_CHANNELS};
pub use clearance_revolute::{ClearanceRevolute, ContactEvaluation};
pub use ideal::{IdealElement, IdealKind, SPATIAL_REACTION_CHANNELS};
pub use lubricated_film::{FilmEvaluation, FilmModel, Lubrication};
pub use perpendicular_axes::PerpendicularAxes;
pub use point_coincidence::PointCoincidence;
pub use relative_angle::RelativeAngle;
pub use spatial_clearance_geometry::{AxialContact, ContactPoint, JointDimensions, JointGeometry, JointMeasures, JointPose, RadialContact, RelativeMotion};
pub use spatial_clearance_element::{SpatialClearanceWork, CHANNELS as SPATIAL_CLEARANCE_CHANNELS};
pub use spatial_clearance_modes::{ModeTally, ModeThresholds, MotionMode, AXIAL_BIN, MODE_BINS, MODE_NAMES};
pub use spatial_clearance_revolute::{CandidateEvaluation, JointLoad, SpatialClearanceRevolute};
pub use spatial_point_coincidence::SpatialPointCoincidence;

use crate::body::BodyModel;
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::{BodyIndex, Marker, SpatialMarker};
use crate::kinematics::planar::{Frame, Vec2};
use crate::kinematics::spatial::Vec3;
use crate::kinematics::wrench::Wrench;
use crate::dynamics::{Body, JacobianPattern};
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
    /// Two points coincide in space (3 equations). (The spatial primitives are
    /// boxed: their markers carry frames, and an unboxed variant would make every
    /// planar constraint as large, which the planar hot loop pays for.)
    SpatialPointCoincidence(Box<SpatialPointCoincidence>),
    /// An axis of one marker stays perpendicular to an axis of another (1 equation).
    PerpendicularAxes(Box<PerpendicularAxes>),
    /// Distance along an axis of the first marker prescribed (1 equation).
    AxisDistance(Box<AxisDistance>),
    /// Rotation about the first marker's z axis prescribed (1 equation).
    AxisRotation(Box<AxisRotation>),
}

/// Where a constraint writes its equations for one evaluation, and the
/// marker kinematics it builds them from: each row's Jacobian is one block
/// per non-ground marker ([`JacobianPattern`]), filled through the marker's
/// body kind, so a primitive never knows how many coordinates a body has.
pub struct ConstraintRows<'a> {
    /// Values of the constraint Jacobian `Phi_q` (every row), zero before the constraint writes.
    pub jacobian: &'a mut [f64],
    /// Where each row's blocks sit.
    pub pattern: &'a JacobianPattern,
    /// The bodies (body `k` has [`BodyIndex`]`(k + 1)`).
    pub bodies: &'a [Body],
    /// First row of this constraint.
    pub row: usize,
    /// Right-hand side of the velocity equation `Phi_q qdot = nu` (`nu = -Phi_t`).
    pub nu: &'a mut [f64],
    /// Right-hand side of the acceleration equation `Phi_q qddot = gamma`.
    pub gamma: &'a mut [f64],
}

impl ConstraintRows<'_> {
    /// Adds `along . d(v_P)/d(v)` of `marker`'s point to row `row + r` in the
    /// block of the constraint's marker `slot` (0 first, 1 second; nothing on the ground).
    #[inline(always)]
    pub fn add_point_jacobian(&mut self, frames: &[Frame], r: usize, slot: usize, marker: &Marker, along: Vec2) {
        let values = self.pattern.slot_values(self.row + r, slot);
        if !values.is_empty() {
            let kind = &self.bodies[marker.body.0 - 1].kind;
            crate::body::planar_first!(kind, add_marker_jacobian(&frames[marker.body.0], &frames[marker.frame], marker, along, &mut self.jacobian[values]));
        }
    }

    /// Sets rows `row + r` and `row + r + 1` of the block of marker `slot` to `scale`
    /// times the Jacobian of the marker point's velocity, x and y (one call to the body kind).
    #[inline(always)]
    pub fn set_point_jacobian_rows(&mut self, frames: &[Frame], r: usize, slot: usize, marker: &Marker, scale: f64) {
        let (x, y) = (self.pattern.slot_values(self.row + r, slot), self.pattern.slot_values(self.row + r + 1, slot));
        if x.is_empty() {
            return;
        }
        // (a later row's blocks sit after an earlier row's)
        let (head, tail) = self.jacobian.split_at_mut(y.start);
        let (jx, jy) = (&mut head[x], &mut tail[..y.end - y.start]);
        crate::body::planar_first!(&self.bodies[marker.body.0 - 1].kind, marker_jacobian(&frames[marker.body.0], &frames[marker.frame], marker, scale, jx, jy));
    }

    /// Adds `scale d(omega)/d(v)` of `marker`'s frame to row `row + r`, block `slot`.
    #[inline(always)]
    pub fn add_angle_jacobian(&mut self, r: usize, slot: usize, marker: &Marker, scale: f64) {
        let values = self.pattern.slot_values(self.row + r, slot);
        if !values.is_empty() {
            crate::body::planar_first!(&self.bodies[marker.body.0 - 1].kind, add_marker_angle_jacobian(marker, scale, &mut self.jacobian[values]));
        }
    }

    /// The velocity-dependent part of `marker`'s point acceleration (zero on the ground) [m/s^2].
    #[inline(always)]
    pub fn bias_acceleration(&self, frames: &[Frame], marker: &Marker) -> Vec2 {
        if marker.body.is_ground() {
            return Vec2::zeros();
        }
        crate::body::planar_first!(&self.bodies[marker.body.0 - 1].kind, marker_bias_acceleration(&frames[marker.body.0], &frames[marker.frame], marker))
    }

    /// Adds `along . d(v_P)/d(v)` of the spatial `marker`'s point to row `row + r`, block `slot`.
    #[inline(always)]
    pub fn add_spatial_point_jacobian(&mut self, frames: &Frames<'_>, r: usize, slot: usize, marker: &SpatialMarker, along: Vec3) {
        let values = self.pattern.slot_values(self.row + r, slot);
        if !values.is_empty() {
            self.bodies[marker.body.0 - 1].kind.add_spatial_point_jacobian(frames.of(marker), marker, along, &mut self.jacobian[values]);
        }
    }

    /// Adds `along . d(omega)/d(v)` of the spatial `marker`'s frame to row `row + r`, block `slot`.
    #[inline(always)]
    pub fn add_spatial_angular_jacobian(&mut self, frames: &Frames<'_>, r: usize, slot: usize, marker: &SpatialMarker, along: Vec3) {
        let values = self.pattern.slot_values(self.row + r, slot);
        if !values.is_empty() {
            self.bodies[marker.body.0 - 1].kind.add_spatial_angular_jacobian(frames.of(marker), marker, along, &mut self.jacobian[values]);
        }
    }

    /// The velocity-dependent parts of the spatial `marker`'s point and angular
    /// accelerations (zero on the ground) [m/s^2, rad/s^2].
    #[inline(always)]
    pub fn spatial_bias(&self, frames: &Frames<'_>, marker: &SpatialMarker) -> (Vec3, Vec3) {
        if marker.body.is_ground() {
            return (Vec3::zeros(), Vec3::zeros());
        }
        self.bodies[marker.body.0 - 1].kind.spatial_bias_acceleration(frames.of(marker), marker)
    }

    /// The velocity-dependent part of `marker`'s angular acceleration (zero on the ground) [rad/s^2].
    #[inline(always)]
    pub fn bias_angular_acceleration(&self, frames: &[Frame], marker: &Marker) -> f64 {
        if marker.body.is_ground() {
            return 0.0;
        }
        crate::body::planar_first!(&self.bodies[marker.body.0 - 1].kind, marker_bias_angular_acceleration(&frames[marker.frame], marker))
    }
}

/// What a constraint's equations exert on one of its markers' bodies for
/// given multipliers: the generalised force `-Phi_q^T lambda` of its rows on that
/// body, as a force at a point and a pure moment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MarkerLoad {
    /// Force [N].
    pub force: Vec2,
    /// Global point where it acts [m].
    pub point: Vec2,
    /// Pure moment [N m] (counter-clockwise).
    pub moment: f64,
}

/// [`MarkerLoad`] in space: a force through a global point and a moment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MarkerWrench {
    /// Global point where the force acts [m].
    pub point: Vec3,
    /// Force and moment [N, N m] (global).
    pub wrench: Wrench,
}

impl MarkerWrench {
    /// Its projection on the plane: the in-plane force and the moment about z.
    fn planar(&self) -> MarkerLoad {
        MarkerLoad { force: self.wrench.force.xy(), point: self.point.xy(), moment: self.wrench.moment.z }
    }
}

impl MarkerLoad {
    /// The planar load in space.
    fn embedded(&self) -> MarkerWrench {
        let (f, p) = (self.force, self.point);
        MarkerWrench { point: Vec3::new(p.x, p.y, 0.0), wrench: Wrench { force: Vec3::new(f.x, f.y, 0.0), moment: Vec3::new(0.0, 0.0, self.moment) } }
    }
}

impl ConstraintKind {
    /// Number of scalar equations.
    pub fn n_equations(&self) -> usize {
        match self {
            Self::SpatialPointCoincidence(_) => 3,
            Self::PointCoincidence(_) => 2,
            Self::RelativeAngle(_) | Self::AxialProjection(_) | Self::PerpendicularAxes(_) | Self::AxisDistance(_) | Self::AxisRotation(_) => 1,
        }
    }

    /// The first and the second marker (slots 0 and 1 of every row's blocks).
    pub fn markers(&self) -> [Marker; 2] {
        match self {
            Self::PointCoincidence(c) => [c.first, c.second],
            Self::RelativeAngle(c) => [c.first, c.second],
            Self::AxialProjection(c) => [c.first, c.second],
            Self::SpatialPointCoincidence(c) => [c.first.planar(), c.second.planar()],
            Self::PerpendicularAxes(c) => [c.first.planar(), c.second.planar()],
            Self::AxisDistance(c) => [c.first.planar(), c.second.planar()],
            Self::AxisRotation(c) => [c.first.planar(), c.second.planar()],
        }
    }

    /// The first and the second body.
    pub fn bodies(&self) -> [BodyIndex; 2] {
        self.markers().map(|m| m.body)
    }

    /// Residuals `Phi(q, t)` into `out` (length `n_equations`) [m or rad].
    #[inline(always)]
    pub fn residual(&self, frames: &Frames<'_>, t: f64, out: &mut [f64]) {
        match self {
            Self::PointCoincidence(c) => c.residual(frames.planar, out),
            Self::RelativeAngle(c) => c.residual(frames.planar, t, out),
            Self::AxialProjection(c) => c.residual(frames.planar, t, out),
            Self::SpatialPointCoincidence(c) => c.residual(frames, out),
            Self::PerpendicularAxes(c) => c.residual(frames, out),
            Self::AxisDistance(c) => c.residual(frames, t, out),
            Self::AxisRotation(c) => c.residual(frames, t, out),
        }
    }

    /// Jacobian rows, `nu` and `gamma` at the current frames (positions and velocities).
    #[inline(always)]
    pub fn linearise(&self, frames: &Frames<'_>, t: f64, rows: ConstraintRows<'_>) {
        match self {
            Self::PointCoincidence(c) => c.linearise(frames.planar, rows),
            Self::RelativeAngle(c) => c.linearise(frames.planar, t, rows),
            Self::AxialProjection(c) => c.linearise(frames.planar, t, rows),
            Self::SpatialPointCoincidence(c) => c.linearise(frames, rows),
            Self::PerpendicularAxes(c) => c.linearise(frames, rows),
            Self::AxisDistance(c) => c.linearise(frames, t, rows),
            Self::AxisRotation(c) => c.linearise(frames, t, rows),
        }
    }

    /// What the equations exert on the first and on the second marker's body
    /// for the multipliers `lambda` of its rows: the generalised force
    /// `-Phi_q^T lambda` as a force at a point plus a pure moment.
    /// A spatial primitive's loads are projected on the plane (a planar
    /// element's reactions; spatial ones read [`Self::wrenches`]).
    pub fn loads(&self, frames: &Frames<'_>, lambda: &[f64]) -> [MarkerLoad; 2] {
        match self {
            Self::PointCoincidence(c) => c.loads(frames.planar, lambda),
            Self::RelativeAngle(c) => c.loads(frames.planar, lambda),
            Self::AxialProjection(c) => c.loads(frames.planar, lambda),
            _ => self.wrenches(frames, lambda).map(|w| w.planar()),
        }
    }

    /// [`Self::loads`] in space: a force through a point and a moment on each
    /// marker's body (a planar primitive's, embedded).
    pub fn wrenches(&self, frames: &Frames<'_>, lambda: &[f64]) -> [MarkerWrench; 2] {
        match self {
            Self::SpatialPointCoincidence(c) => c.loads(frames, lambda),
            Self::PerpendicularAxes(c) => c.loads(frames, lambda),
            Self::AxisDistance(c) => c.loads(frames, lambda),
            Self::AxisRotation(c) => c.loads(frames, lambda),
            _ => self.loads(frames, lambda).map(|l| l.embedded()),
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
