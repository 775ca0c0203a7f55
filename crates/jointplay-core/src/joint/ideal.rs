//! Ideal joints, drivers and assembly locks as elements: each owns
//! constraint equations (compiled into the primitives of [`super::ConstraintKind`])
//! and reports its reaction (or, a driver, its effort) as channels, read from
//! the multipliers of its rows.

use crate::element::{ElementModel, OutputInfo};
use crate::kinematics::marker::{BodyIndex, SpatialMarker};
use crate::kinematics::planar::Vec2;
use crate::spec::SpatialJointKind;

/// What an element owning constraint equations is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IdealKind {
    /// Ideal revolute joint.
    RevoluteJoint,
    /// Ideal translational joint.
    TranslationalJoint,
    /// Ideal fixed joint.
    FixedJoint,
    /// Driver of a revolute joint's relative angle.
    AngleDriver,
    /// Driver of a translational joint's displacement.
    DisplacementDriver,
    /// A clearance joint held at its initial eccentricity while assembling.
    AssemblyLock,
    /// Ideal joint between two marker frames in space.
    SpatialJoint(SpatialJointKind),
    /// Driver of the rotation about a spatial joint's axis.
    SpatialAngleDriver,
    /// Driver of the displacement along a spatial joint's axis.
    SpatialDisplacementDriver,
}

/// Reaction channels of an ideal joint that leaves the relative rotation free.
const PIN_REACTION_CHANNELS: [OutputInfo; 3] = [
    ("fx", "N", "reaction on the second body from the first, x"),
    ("fy", "N", "reaction on the second body from the first, y"),
    ("f", "N", "reaction on the second body from the first, magnitude"),
];

/// Reaction channels of an ideal joint that also transmits a moment.
const REACTION_CHANNELS: [OutputInfo; 4] = [
    PIN_REACTION_CHANNELS[0],
    PIN_REACTION_CHANNELS[1],
    PIN_REACTION_CHANNELS[2],
    ("moment", "N m", "reaction on the second body from the first, moment about the joint point"),
];

/// Reaction channels of a spatial joint: the wrench on the second body from
/// the first at the second marker's point, global and in the joint's frame
/// (the first marker's axes).
pub const SPATIAL_REACTION_CHANNELS: [OutputInfo; 13] = [
    ("fx", "N", "reaction on the second body from the first, global x"),
    ("fy", "N", "reaction on the second body from the first, global y"),
    ("fz", "N", "reaction on the second body from the first, global z"),
    ("f", "N", "reaction on the second body from the first, magnitude"),
    ("mx", "N m", "reaction moment on the second body about its marker point, global x"),
    ("my", "N m", "reaction moment on the second body about its marker point, global y"),
    ("mz", "N m", "reaction moment on the second body about its marker point, global z"),
    ("joint_fx", "N", "reaction on the second body, along the joint frame's x"),
    ("joint_fy", "N", "reaction on the second body, along the joint frame's y"),
    ("joint_fz", "N", "reaction on the second body, along the joint frame's z (the axis)"),
    ("joint_mx", "N m", "reaction moment on the second body, about the joint frame's x"),
    ("joint_my", "N m", "reaction moment on the second body, about the joint frame's y"),
    ("joint_mz", "N m", "reaction moment on the second body, about the joint frame's z (the axis)"),
];

impl IdealKind {
    /// Output channels: quantity, unit, description (reactions `0 fx, 1 fy, 2 |f|, 3 moment`;
    /// a driver's one channel is its effort).
    pub fn channels(self) -> &'static [OutputInfo] {
        match self {
            Self::RevoluteJoint => &PIN_REACTION_CHANNELS,
            Self::TranslationalJoint | Self::FixedJoint => &REACTION_CHANNELS,
            Self::AngleDriver => &[("torque", "N m", "driver effort on the second body of the driven joint")],
            Self::DisplacementDriver => &[("force", "N", "driver effort along the axis on the second body of the driven joint")],
            Self::AssemblyLock => &[],
            Self::SpatialJoint(_) => &SPATIAL_REACTION_CHANNELS,
            Self::SpatialAngleDriver => &[("torque", "N m", "driver effort on the second body about the joint's axis")],
            Self::SpatialDisplacementDriver => &[("force", "N", "driver effort on the second body along the joint's axis")],
        }
    }
}

/// An element that owns constraint equations (joint, driver or assembly lock).
#[derive(Clone, Debug, PartialEq)]
pub struct IdealElement {
    /// Kind.
    pub kind: IdealKind,
    /// First body.
    pub first: BodyIndex,
    /// Second body.
    pub second: BodyIndex,
    /// Point of the second marker's frame at which the reaction moment is reported [m].
    pub second_point: Vec2,
    /// Frames of the first and the second marker (the bodies' own, or beam sections).
    pub frames: [usize; 2],
    /// Unit axis in the first body's frame (translational joints and their drivers) [-].
    pub axis: Vec2,
    /// Indices of its constraints in `Model::constraints`.
    pub constraints: std::ops::Range<usize>,
    /// The first and the second marker frame of a spatial joint or driver.
    pub spatial_markers: Option<Box<[SpatialMarker; 2]>>,
}

impl ElementModel for IdealElement {
    fn channels(&self) -> &'static [OutputInfo] {
        self.kind.channels()
    }

    fn constraints(&self) -> std::ops::Range<usize> {
        self.constraints.clone()
    }

    /// An ideal element acts only through its constraint equations.
    #[inline]
    fn acts_through_forces(&self) -> bool {
        false
    }
}

impl IdealKind {
    /// Whether it is a driver (one channel, its effort).
    pub fn is_driver(self) -> bool {
        matches!(self, Self::AngleDriver | Self::DisplacementDriver | Self::SpatialAngleDriver | Self::SpatialDisplacementDriver)
    }
}
