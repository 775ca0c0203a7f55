//! The spatial parts of a model description: rigid bodies with an inertia
//! tensor and an orientation, joints between marker frames, force elements
//! in space. A model is spatial when it has any of them; its planar bodies
//! are embedded in the plane `z = 0`.

use serde::{Deserialize, Deserializer, Serialize};

use super::{ContactSpec, FrictionSpec, FunctionSpec, HydraulicCylinderSpec, MaterialSpec, SpringDamperSpec, StiffnessSpec};

/// A 3-vector given as 3 numbers, or as 2 (the third zero: planar descriptions).
pub fn vector3<'de, D: Deserializer<'de>>(deserializer: D) -> Result<[f64; 3], D::Error> {
    let values = Vec::<f64>::deserialize(deserializer)?;
    match values.as_slice() {
        [x, y] => Ok([*x, *y, 0.0]),
        [x, y, z] => Ok([*x, *y, *z]),
        _ => Err(serde::de::Error::custom(format!("expected 2 or 3 numbers, got {}", values.len()))),
    }
}

/// A named point with a frame on a spatial body.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpatialPointSpec {
    /// Name, unique within its body.
    pub name: String,
    /// Coordinates in the body frame [m].
    pub position: [f64; 3],
    /// The marker's axes in the body frame: a rotation matrix whose columns are
    /// the marker's x, y, z axes [-]; `None`: the body's axes.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axes: Option<[[f64; 3]; 3]>,
}

/// A spatial rigid body with its reference frame at the centre of mass.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpatialBodySpec {
    /// Name, unique in the model.
    pub name: String,
    /// Mass [kg].
    pub mass: f64,
    /// Inertia tensor about the centre of mass in the body frame, by rows [kg m^2].
    pub inertia: [[f64; 3]; 3],
    /// Approximate initial position of the centre of mass [m].
    pub position: [f64; 3],
    /// Approximate initial orientation, a unit quaternion `[w, x, y, z]` (body to global) [-].
    pub orientation: [f64; 4],
    /// Approximate initial velocity of the centre of mass [m/s].
    pub velocity: [f64; 3],
    /// Approximate initial angular velocity in the global frame [rad/s].
    pub angular_velocity: [f64; 3],
    /// Named points with frames in body coordinates.
    pub points: Vec<SpatialPointSpec>,
    /// Intrinsic Euler sequence of its orientation channels (`"ZYX"`, `"ZXZ"`, ...).
    pub euler_sequence: String,
}

/// An ideal joint between two marker frames (`"body.point"`), whose common
/// z axis is the joint's axis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpatialJointSpec {
    /// What the joint leaves free.
    #[serde(rename = "type")]
    pub kind: SpatialJointKind,
    /// Name of the joint.
    pub name: String,
    /// Marker on the first body.
    pub first: String,
    /// Marker on the second body.
    pub second: String,
}

/// The kinds of spatial ideal joints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SpatialJointKind {
    /// Rotation about the common z axis (5 equations).
    Revolute,
    /// Rotation about the common point (3 equations).
    Spherical,
    /// Translation along and rotation about the common z axis (4 equations).
    Cylindrical,
    /// Translation along the common z axis (5 equations).
    Translational,
    /// Rotations about the first marker's x axis and the second marker's y axis (4 equations).
    Universal,
    /// No relative motion (6 equations).
    Fixed,
}

/// Which frame a prescribed load's components are given in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LoadFrameSpec {
    /// The global frame.
    Global,
    /// The frame of the marker (turning with its body).
    Body,
}

/// A force element in space.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum SpatialForceSpec {
    /// Linear spring and damper between two points, tension positive.
    SpringDamper(SpringDamperSpec),
    /// Six linear springs and dampers between two marker frames, in the first's axes.
    Bushing {
        /// Name.
        name: String,
        /// Marker on the first body.
        first: String,
        /// Marker on the second body.
        second: String,
        /// Translational stiffnesses [N/m].
        stiffness: [f64; 3],
        /// Translational damping [N s/m].
        damping: [f64; 3],
        /// Rotational stiffnesses [N m/rad].
        rotational_stiffness: [f64; 3],
        /// Rotational damping [N m s/rad].
        rotational_damping: [f64; 3],
    },
    /// A force at a point, components as functions of time.
    PointForce {
        /// Name.
        name: String,
        /// Point of application `"body.point"`.
        point: String,
        /// Components x, y, z [N].
        force: [FunctionSpec; 3],
        /// Frame of the components.
        frame: LoadFrameSpec,
    },
    /// A torque on a body, components as functions of time.
    Torque {
        /// Name.
        name: String,
        /// Body it acts on.
        body: String,
        /// Components x, y, z [N m].
        torque: [FunctionSpec; 3],
        /// Frame of the components (the body's axes for `body`).
        frame: LoadFrameSpec,
    },
    /// Double-acting hydraulic cylinder between two points, along their line.
    HydraulicCylinder(HydraulicCylinderSpec),
}

/// A revolute joint with radial and axial clearance between two marker
/// frames: a bore of finite length on the bearing's body, a journal with two
/// flanges on the journal's body (`docs/theory/spatial-clearance-revolute.md`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpatialClearanceJointSpec {
    /// Its kind (the one there is), as a model file names it.
    #[serde(rename = "type")]
    pub kind: SpatialClearanceKind,
    /// Name of the joint.
    pub name: String,
    /// Bearing marker `"body.point"`: origin at the bore's centre, z along the bore axis.
    pub bearing: String,
    /// Journal marker `"body.point"`: origin midway between the flanges, z along the journal axis.
    pub journal: String,
    /// Bore radius R_b [m].
    pub bore_radius: f64,
    /// Radial clearance c = R_b - R_j [m].
    pub clearance: f64,
    /// Bearing length L [m].
    pub bearing_length: f64,
    /// Axial clearance: flange spacing minus bearing length [m].
    pub axial_clearance: f64,
    /// Outer radius of the journal's flanges [m].
    pub flange_radius: f64,
    /// Outer radius of the bearing's end faces [m].
    pub face_radius: f64,
    /// Bearing material.
    pub bearing_material: MaterialSpec,
    /// Journal material.
    pub journal_material: MaterialSpec,
    /// Normal force law (dissipation) of every contact.
    pub contact: ContactSpec,
    /// Radial stiffness law of the whole bearing length.
    pub stiffness: StiffnessSpec,
    /// Stiffness of a whole flange ring against its face [N/m]; none: the flat annular punch's.
    #[serde(default)]
    pub axial_stiffness: Option<f64>,
    /// Friction law of every contact.
    pub friction: FrictionSpec,
    /// Whether assembly holds the journal centred and aligned in its bore (the state of the ideal
    /// mechanism); `false` keeps it where the bodies' approximate positions put it, with their own velocities.
    pub lock_at_assembly: bool,
    /// Smallest contact-onset velocity used in the damping term [m/s].
    pub onset_velocity_floor: f64,
    /// Penetration at which the simulation stops as unphysical [m]; none: half the radial clearance.
    #[serde(default)]
    pub max_penetration: Option<f64>,
    /// Smallest onset approach speed of a radial contact that begins with an impact [m/s].
    pub mode_impact_speed: f64,
    /// How long after such an onset the contact counts as impact and rebound [s].
    pub mode_impact_duration: f64,
    /// Sliding speed above which a radial contact is sliding, at or below it sustained [m/s].
    pub mode_sliding_speed: f64,
}

/// The kinds of joint with clearance between marker frames.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SpatialClearanceKind {
    /// A revolute joint with radial and axial clearance.
    SpatialClearanceRevolute,
}
