//! The compiled, immutable description of a mechanism.

use super::channels::{Channel, ChannelRead};
use crate::kinematics::marker::{BodyIndex, Marker, SectionSite, Site, SpatialMarker};
use crate::spec::SpatialJointKind;
use crate::kinematics::planar::{Frame, Vec2};
use crate::kinematics::spatial::Vec3;
use super::joint_tree::JointTree;
use super::constraint_jacobian::JacobianPattern;
use super::layout::StateLayout;
use crate::body::{BodyKind, BodyModel};
use crate::force::{ElementMemory, ForceElement, OutputInfo};
use crate::joint::{ClearanceRevolute, Constraint};
use crate::linalg::PatternLdl;

/// A body: its name and its kind (which holds its mass properties).
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// Name.
    pub name: String,
    /// Kind and mass properties.
    pub kind: BodyKind,
    /// How its initial velocities are found at assembly.
    pub velocity_start: VelocityStart,
}

/// How assembly finds a body's initial velocities
/// (`docs/theory/planar-formulation.md`, "Initial conditions").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VelocityStart {
    /// The description's velocities are approximate: corrected onto the joints
    /// by the smallest change in the mass metric (a rigid body, whose every
    /// velocity is a rigid motion).
    Approximate,
    /// A flexible body with no velocities given: it starts in the rigid motion
    /// the assembled mechanism gives it, found as a rigid link's velocities are.
    RigidMotion,
    /// A flexible body whose rigid motion was given: held as given, and the
    /// assembly fails, naming the body, if the joints contradict it.
    Given,
}

/// What an element owning constraint equations is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ElementKind {
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

impl ElementKind {
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
    /// Name (as in the model description).
    pub name: String,
    /// Kind.
    pub kind: ElementKind,
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

/// The compiled mechanism. Built by `compile` (`compiler/compile.rs`); never changes.
#[derive(Clone, Debug)]
pub struct Model {
    /// Name of the mechanism.
    pub name: String,
    /// Rigid bodies; body `k` has [`BodyIndex`]`(k + 1)`.
    pub bodies: Vec<Body>,
    /// Names of the named points of every body (`"crank.A"`) and their markers.
    pub points: Vec<(String, Marker)>,
    /// The section frames of markers on flexible bodies: section `k` is frame
    /// `1 + bodies.len() + k` of an evaluation, after the bodies' own.
    pub sections: Vec<Section>,
    /// Strain gauges on beams: their sections and what they record.
    pub gauges: Vec<StrainGauge>,
    /// Where every body's coordinates and every element's states sit in `y = [q, v, z]`.
    pub layout: StateLayout,
    /// Gravitational acceleration [m/s^2] (planar bodies feel its in-plane part).
    pub gravity: Vec3,
    /// Whether the model has spatial bodies or elements: evaluations then keep
    /// spatial frames of every body and section (planar bodies embedded).
    pub spatial: bool,
    /// The diagonal of `M^-1` over all velocity coordinates when every body's
    /// mass block is constant and diagonal (a fast path of [`Self::solve_mass`]
    /// and of the constraint matrix); `None` otherwise [1/kg, 1/(kg m^2)].
    pub diagonal_inverse_mass: Option<Vec<f64>>,
    /// Constraints: the dynamic ones first, then the assembly locks of the clearance joints.
    pub constraints: Vec<Constraint>,
    /// How many of `constraints` act during the simulation.
    pub n_dynamic_constraints: usize,
    /// First equation row of every constraint, plus the total at the end.
    pub row_offsets: Vec<usize>,
    /// Owner (index into `elements`) of every equation row.
    pub row_owner: Vec<usize>,
    /// The blocks of every equation row of `Phi_q` (one per non-ground marker, as wide as its body kind says).
    pub jacobian_pattern: JacobianPattern,
    /// The terms of `Phi_q M^-1 Phi_q^T` over all rows, rows in ascending order (see [`SchurTerm`]).
    pub schur_terms: Vec<SchurTerm>,
    /// Factorisation of `Phi_q M^-1 Phi_q^T` for the dynamic rows, chosen from its pattern.
    pub schur_factor: PatternLdl,
    /// Joints, drivers and assembly locks that own constraints.
    pub elements: Vec<IdealElement>,
    /// Elements acting through forces (clearance joints included), in the
    /// order of the description: clearance joints with the joints, then the forces.
    pub forces: Vec<ForceElement>,
    /// Names of the force elements.
    pub force_names: Vec<String>,
    /// First event function of every force element, plus the total at the end.
    pub event_offsets: Vec<usize>,
    /// The bodies some event function reads (each once, ground excluded).
    pub event_bodies: Vec<BodyIndex>,
    /// Approximate initial coordinates from the description.
    pub initial_coordinates: Vec<f64>,
    /// Approximate initial velocities from the description.
    pub initial_velocities: Vec<f64>,
    /// Initial continuous element states `z` (chamber pressures [Pa], ...).
    pub initial_element_states: Vec<f64>,
    /// Output channels, in recording order.
    pub(crate) channels: Vec<Channel>,
    /// How a sample reads them (runs that one copy or one evaluation serves).
    pub(crate) channel_reads: Vec<ChannelRead>,
    /// The tree of the ideal joints, for the joint-coordinate formulation, or
    /// why the model needs absolute coordinates (a joint closing a loop, ...).
    pub joint_tree: Result<JointTree, String>,
}

/// A section frame of a flexible body (where markers on it sit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Section {
    /// The body.
    pub body: BodyIndex,
    /// Where on it (a beam's section, a modal body's node).
    pub site: Site,
}

/// A strain gauge: the stress resultants of a beam's section and the axial
/// strain of one fibre there.
#[derive(Clone, Debug, PartialEq)]
pub struct StrainGauge {
    /// Name (its channels are `<name>.<quantity>`).
    pub name: String,
    /// The beam or modal body.
    pub body: BodyIndex,
    /// The section (of the beam a modal body was reduced from).
    pub site: SectionSite,
    /// Distance of the fibre from the axis along the section's direction `t_2` [m].
    pub fibre: f64,
    /// On a modal body, the strains' rows over its modes
    /// ([`crate::body::ModalBody::strain_modes`]); empty on a beam.
    pub strain_modes: Vec<f64>,
}

impl StrainGauge {
    /// Channels: quantity, unit, description.
    pub const CHANNELS: [OutputInfo; 6] = [
        ("axial_force", "N", "axial force N of the section (tension positive)"),
        ("shear_force", "N", "shear force Q of the section"),
        ("bending_moment", "N m", "bending moment M of the section"),
        ("axial_strain", "1", "axial strain of the fibre (elongation positive)"),
        ("axis_strain", "1", "axial strain of the beam's axis"),
        ("curvature", "1/m", "curvature of the axis"),
    ];
}

/// One body's contribution `J_a,c M_c^-1 J_b,c^T` to entry `(a, b)`, `a >= b`, of
/// `Phi_q M^-1 Phi_q^T`, by indices of the two rows' Jacobian blocks on that
/// body (32-bit: the terms are read at every evaluation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SchurTerm {
    /// Row a.
    pub row: u32,
    /// Row b (at most a).
    pub column: u32,
    /// Where entry (a, b) is stored for [`Model::schur_factor`] (dynamic rows only).
    pub entry: u32,
    /// Row a's block on the body (index into [`JacobianPattern::blocks`]).
    pub first: u32,
    /// Row b's block on the body.
    pub second: u32,
    /// Where the two blocks' common columns start among row a's values.
    pub first_value: u32,
    /// Where they start among row b's values.
    pub second_value: u32,
    /// The first common column (velocity coordinate).
    pub column_start: u32,
    /// Number of common columns (the term is zero without any when the body's mass is diagonal).
    pub common: u32,
}

impl Model {
    /// Number of velocity coordinates (the size of `M`, of `Q` and of `q_ddot`).
    pub fn n_velocities(&self) -> usize {
        self.layout.nv
    }

    /// `out = M(q)^-1 f` over all velocity coordinates at the positions `q`, body
    /// by body with each body kind's mass block (`scratch`: the workspace's
    /// `mass_matrix`, for configuration-dependent blocks).
    pub fn solve_mass(&self, q: &[f64], f: &[f64], out: &mut [f64], scratch: &mut [f64]) {
        if let Some(w) = &self.diagonal_inverse_mass {
            for ((o, w), f) in out.iter_mut().zip(w).zip(f) {
                *o = w * f;
            }
            return;
        }
        for (body, address) in self.bodies.iter().zip(&self.layout.bodies) {
            body.kind.solve_mass(&q[address.q_range()], &f[address.v_range()], &mut out[address.v_range()], scratch);
        }
    }

    /// Frame of a section from all positions `q` and velocities `v`.
    #[inline]
    pub fn section_frame(&self, section: &Section, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        let address = &self.layout.bodies[section.body.0 - 1];
        let kind = &self.bodies[section.body.0 - 1].kind;
        kind.site_frame(&section.site, &q[address.q_range()], &v[address.v_range()], previous)
    }

    /// Number of frames of an evaluation: the ground, the bodies, the sections.
    pub fn n_frames(&self) -> usize {
        1 + self.bodies.len() + self.sections.len()
    }

    /// The first bending frequency [Hz] of every modal body (its lowest mode
    /// clamped at its frame node), with the body's name: a linear modal body
    /// (no geometric stiffening) spinning faster than `2 pi` times this diverges,
    /// which the front end warns of.
    pub fn modal_bending_frequencies(&self) -> Vec<(&str, f64)> {
        self.bodies
            .iter()
            .filter_map(|b| match &b.kind {
                BodyKind::Modal(modal) => modal.first_bending_frequency().map(|f| (b.name.as_str(), f)),
                _ => None,
            })
            .collect()
    }

    /// Whether every body is rigid (no body force, no section frame).
    pub fn is_rigid(&self) -> bool {
        self.bodies.iter().all(|b| matches!(b.kind, BodyKind::PlanarRigid(_)))
    }

    /// Number of constraint equations active during the simulation.
    pub fn n_dynamic_equations(&self) -> usize {
        self.row_offsets[self.n_dynamic_constraints]
    }

    /// Number of constraint equations including the assembly locks.
    pub fn n_assembly_equations(&self) -> usize {
        *self.row_offsets.last().unwrap_or(&0)
    }

    /// Degrees of freedom (velocity coordinates minus simulation equations; the
    /// two relative freedoms of each clearance joint are counted).
    pub fn degrees_of_freedom(&self) -> i64 {
        self.n_velocities() as i64 - self.n_dynamic_equations() as i64
    }

    /// Whether some element has outputs only recorded samples need (a film's peak pressure).
    pub fn has_detailed_outputs(&self) -> bool {
        self.forces.iter().any(ForceElement::has_detailed_outputs)
    }

    /// Number of event functions of all elements.
    pub fn n_events(&self) -> usize {
        *self.event_offsets.last().unwrap_or(&0)
    }

    /// The discrete memory of every force element at the start of a run.
    pub fn initial_memory(&self) -> Vec<ElementMemory> {
        self.forces.iter().map(ForceElement::new_memory).collect()
    }

    /// The clearance joints: index in [`Self::forces`], name and joint.
    pub fn clearance_joints(&self) -> impl Iterator<Item = (usize, &str, &ClearanceRevolute)> + Clone {
        self.forces.iter().enumerate().filter_map(|(k, element)| match element {
            ForceElement::ClearanceRevolute(joint) => Some((k, self.force_names[k].as_str(), joint)),
            _ => None,
        })
    }

    /// Name of a body index (`ground` for 0).
    pub fn body_name(&self, body: BodyIndex) -> &str {
        if body.is_ground() { crate::spec::GROUND } else { &self.bodies[body.0 - 1].name }
    }

    /// Names, units and descriptions of the output channels.
    pub fn channel_infos(&self) -> Vec<super::ChannelInfo> {
        self.channels.iter().map(|c| c.info.clone()).collect()
    }
}
