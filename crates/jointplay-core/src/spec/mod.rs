//! The plain-data model description, in SI units, that the front ends
//! (Python builder, TOML model files) produce and [`crate::dynamics::compile`]
//! turns into a [`crate::dynamics::Model`].
//!
//! Names refer to bodies and points as strings; `ground` is the fixed frame.
//! A point is written `"body.point"` (for example `"crank.A"`), or
//! `"ground.O"` for a point of the ground.
//!
//! Every value is given explicitly: the defaults of the keys a user may leave
//! out are defined once, by the front end (`python/jointplay/parameters.py`),
//! which sends each of them. A key that is missing here is an error, except
//! an `Option` field, whose absence means "none" (no lubricant, no bearing
//! length, a limit or a film thickness that the core derives from the geometry).

mod beams;
mod laws;
mod lubrication;
mod modal;
mod keys;
mod range;
pub mod ranges;
mod spatial;

pub use beams::{BeamMaterialSpec, BeamMeshSpec, BeamPointSpec, BeamSectionSpec, BeamSpec, ElementOrderSpec, SensorSpec};
pub use laws::{ContactSpec, FrictionSpec, FunctionSpec, MaterialSpec, StiffnessSpec};
pub use lubrication::{CavitationSpec, FilmModelSpec, LubricationSpec, ReynoldsSpec, TransitionSpec};
pub use keys::{table_keys, TableKey, TableKeys};
pub use range::Range;
pub use spatial::{vector3, LoadFrameSpec, SpatialBodySpec, SpatialClearanceJointSpec, SpatialForceSpec, SpatialJointKind, SpatialJointSpec, SpatialPointSpec};
pub use modal::{ModalBodySpec, ModalPointSpec, ModalStructureSpec, SparseMatrixSpec, StructureMatricesSpec};
use serde::{Deserialize, Serialize};

/// Name of the fixed frame.
pub const GROUND: &str = "ground";

/// A whole mechanism.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelSpec {
    /// Name of the mechanism.
    pub name: String,
    /// Gravitational acceleration vector [m/s^2] (two numbers in planar descriptions: z is zero).
    #[serde(deserialize_with = "vector3")]
    pub gravity: [f64; 3],
    /// Points of the ground frame, by name: global coordinates [m].
    pub ground_points: Vec<PointSpec>,
    /// Rigid bodies.
    pub bodies: Vec<BodySpec>,
    /// Flexible links.
    pub beams: Vec<BeamSpec>,
    /// Flexible links reduced to modal bodies; none when left out or null (so
    /// that descriptions written before modal bodies existed stay valid).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub modal_bodies: Option<Vec<ModalBodySpec>>,
    /// Ideal and clearance joints.
    pub joints: Vec<JointSpec>,
    /// Drivers prescribing joint coordinates over time.
    pub drivers: Vec<DriverSpec>,
    /// Force elements.
    pub forces: Vec<ForceSpec>,
    /// Sensors.
    pub sensors: Vec<SensorSpec>,
    /// Spatial rigid bodies; none when left out or null (a planar model).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spatial_bodies: Option<Vec<SpatialBodySpec>>,
    /// Ideal joints between marker frames.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spatial_joints: Option<Vec<SpatialJointSpec>>,
    /// Force elements in space.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spatial_forces: Option<Vec<SpatialForceSpec>>,
    /// Revolute joints with radial and axial clearance between marker frames.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spatial_clearance_joints: Option<Vec<SpatialClearanceJointSpec>>,
}

/// A named point: coordinates in the frame of its body [m], and a frame there.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointSpec {
    /// Name, unique within its body.
    pub name: String,
    /// Coordinates in the body frame (global for ground points) [m]; two
    /// numbers in planar descriptions (z is zero).
    #[serde(deserialize_with = "vector3")]
    pub position: [f64; 3],
    /// The marker's axes in the body frame (columns x, y, z) [-], for spatial
    /// joints; `None`: the body's axes.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axes: Option<[[f64; 3]; 3]>,
}

/// A planar rigid body with its reference frame at the centre of mass.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// Name, unique in the model.
    pub name: String,
    /// Mass [kg].
    pub mass: f64,
    /// Moment of inertia about the centre of mass [kg m^2].
    pub inertia: f64,
    /// Approximate initial position of the centre of mass [m].
    pub position: [f64; 2],
    /// Approximate initial orientation [rad].
    pub angle: f64,
    /// Approximate initial velocity of the centre of mass [m/s].
    pub velocity: [f64; 2],
    /// Approximate initial angular velocity [rad/s].
    pub angular_velocity: f64,
    /// Named points in body coordinates.
    pub points: Vec<PointSpec>,
}

/// A joint between two bodies, each side given as a point `"body.point"`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum JointSpec {
    /// Ideal pin: the two points coincide.
    Revolute {
        /// Name of the joint.
        name: String,
        /// Point on the first body.
        first: String,
        /// Point on the second body.
        second: String,
    },
    /// Ideal slider: no relative rotation, the second point moves on the
    /// line through the first point along `axis`.
    Translational {
        /// Name of the joint.
        name: String,
        /// Point on the first body, on the sliding line.
        first: String,
        /// Point on the second body, on the sliding line.
        second: String,
        /// Sliding direction in the first body's frame [-] (normalised on compile).
        axis: [f64; 2],
    },
    /// Ideal weld: the points coincide and the relative angle is held.
    Fixed {
        /// Name of the joint.
        name: String,
        /// Point on the first body.
        first: String,
        /// Point on the second body.
        second: String,
    },
    /// Dry revolute joint with radial clearance: a bearing (bore) on the first
    /// body, a journal (pin) on the second, and contact forces between them.
    ClearanceRevolute(ClearanceJointSpec),
}

/// A dry revolute clearance joint.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClearanceJointSpec {
    /// Name of the joint.
    pub name: String,
    /// Bearing centre `"body.point"`.
    pub bearing: String,
    /// Journal centre `"body.point"`.
    pub journal: String,
    /// Bore radius R_b [m].
    pub bearing_radius: f64,
    /// Radial clearance c = R_b - R_j [m].
    pub clearance: f64,
    /// Axial length of the bearing [m] (line-contact stiffness laws).
    #[serde(default)]
    pub length: Option<f64>,
    /// Bearing material.
    pub bearing_material: MaterialSpec,
    /// Journal material.
    pub journal_material: MaterialSpec,
    /// Normal force law (dissipation).
    pub contact: ContactSpec,
    /// Contact stiffness law.
    pub stiffness: StiffnessSpec,
    /// Friction law.
    pub friction: FrictionSpec,
    /// Initial eccentricity vector of the journal centre from the bearing centre, global frame [m].
    pub initial_eccentricity: [f64; 2],
    /// Whether assembly holds the journal at `initial_eccentricity` for positions and velocities
    /// (the state of the ideal mechanism); `false` keeps the journal where the approximate input
    /// puts it, with its own velocity.
    pub lock_at_assembly: bool,
    /// Smallest contact-onset velocity used in the damping term [m/s]; guards grazing entries.
    pub onset_velocity_floor: f64,
    /// Penetration at which the simulation stops as unphysical [m]; none: 5 % of the journal radius.
    #[serde(default)]
    pub max_penetration: Option<f64>,
    /// Lubricant film; a dry joint when absent.
    #[serde(default)]
    pub lubrication: Option<LubricationSpec>,
}

/// A driver: a joint coordinate prescribed as a function of time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DriverSpec {
    /// Name of the driver.
    pub name: String,
    /// Revolute joint (relative angle, second minus first [rad]) or
    /// translational joint (displacement along the axis [m]) it drives.
    pub joint: String,
    /// The prescribed coordinate over time.
    pub function: FunctionSpec,
}

/// A force element.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum ForceSpec {
    /// Linear spring and damper between two points, tension positive.
    SpringDamper(SpringDamperSpec),
    /// Torsional spring and damper on the relative angle of two bodies.
    RotationalSpringDamper {
        /// Name.
        name: String,
        /// First body (`ground` allowed).
        first: String,
        /// Second body.
        second: String,
        /// Stiffness [N m/rad].
        stiffness: f64,
        /// Damping coefficient [N m s/rad].
        damping: f64,
        /// Relative angle (second minus first) at which the spring is relaxed [rad].
        free_angle: f64,
    },
    /// A force at a point, given in the global frame as functions of time.
    PointForce {
        /// Name.
        name: String,
        /// Point of application `"body.point"`.
        point: String,
        /// x component [N].
        fx: FunctionSpec,
        /// y component [N].
        fy: FunctionSpec,
    },
    /// A torque on a body as a function of time.
    Torque {
        /// Name.
        name: String,
        /// Body it acts on.
        body: String,
        /// Torque, counter-clockwise positive [N m].
        torque: FunctionSpec,
    },
    /// Double-acting hydraulic cylinder between two points, along their line;
    /// its chamber pressures are states of the simulation.
    HydraulicCylinder(HydraulicCylinderSpec),
}

/// A linear spring and damper between two points, tension positive (in the
/// plane and in space alike).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpringDamperSpec {
    /// Name.
    pub name: String,
    /// Point on the first body.
    pub first: String,
    /// Point on the second body.
    pub second: String,
    /// Stiffness [N/m].
    pub stiffness: f64,
    /// Damping coefficient [N s/m].
    pub damping: f64,
    /// Free length [m].
    pub free_length: f64,
}

/// A hydraulic cylinder: barrel attached at `first`, rod eye at `second`.
/// Pressures are gauge. Every value is given (the front end supplies defaults).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HydraulicCylinderSpec {
    /// Name.
    pub name: String,
    /// Barrel attachment `"body.point"`.
    pub first: String,
    /// Rod-eye attachment `"body.point"`.
    pub second: String,
    /// Piston (cap-side) area A1 [m^2].
    pub piston_area: f64,
    /// Rod-side (annulus) area A2 < A1 [m^2].
    pub rod_side_area: f64,
    /// Stroke length S [m].
    pub stroke_length: f64,
    /// Dead volume of the cap chamber [m^3].
    pub cap_dead_volume: f64,
    /// Dead volume of the rod chamber [m^3].
    pub rod_dead_volume: f64,
    /// Stroke at the start, at the positions given in the model [m].
    pub initial_stroke: f64,
    /// Cap-chamber pressure at the start [Pa].
    pub cap_pressure: f64,
    /// Rod-chamber pressure at the start [Pa].
    pub rod_pressure: f64,
    /// Effective bulk modulus of the liquid [Pa].
    pub bulk_modulus: f64,
    /// Seal friction; `None`: frictionless seals.
    pub seal_friction: Option<SealFrictionSpec>,
    /// Flow into the cap chamber [m^3/s]; `None`: closed.
    pub cap_inflow: Option<FunctionSpec>,
    /// Flow into the rod chamber [m^3/s]; `None`: closed.
    pub rod_inflow: Option<FunctionSpec>,
}

/// LuGre seal friction of a cylinder.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SealFrictionSpec {
    /// Static (breakaway) force F_S [N].
    pub static_force: f64,
    /// Kinetic (Coulomb) force F_C [N].
    pub kinetic_force: f64,
    /// Stribeck velocity v_S [m/s].
    pub stribeck_velocity: f64,
    /// Bristle stiffness sigma0 [N/m].
    pub bristle_stiffness: f64,
    /// Bristle damping sigma1 [N s/m].
    pub bristle_damping: f64,
    /// Viscous coefficient sigma2 [N s/m].
    pub viscous_coefficient: f64,
    /// Velocity over which the bristle damping fades, v_D [m/s].
    pub damping_velocity: f64,
    /// Stroke rate below which the seal is reported sticking [m/s].
    pub stick_velocity: f64,
}

#[cfg(test)]
mod tests;
