//! The compiled, immutable description of a mechanism.

use super::channels::{Channel, ChannelRead};
use crate::kinematics::marker::{BodyIndex, Marker, SectionSite, Site};
use crate::kinematics::planar::Frame;
use crate::kinematics::spatial::Vec3;
use super::joint_tree::JointTree;
use super::constraint_jacobian::JacobianPattern;
use super::layout::StateLayout;
use crate::body::{BodyKind, BodyModel};
use crate::element::{Element, ElementKind, ElementMemory, ElementModel, OutputInfo};
use crate::joint::{ClearanceRevolute, Constraint, IdealElement, SpatialClearanceRevolute};
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
    /// Every element (joints, drivers, clearance joints, force elements, then
    /// the assembly locks), in the order of the description.
    pub elements: Vec<Element>,
    /// The elements acting through forces (indices into `elements`), in order.
    pub acting: Vec<usize>,
    /// First event function of every element, plus the total at the end.
    pub event_offsets: Vec<usize>,
    /// First discrete memory slot of every element, plus the total at the end.
    pub memory_offsets: Vec<usize>,
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
        self.elements.iter().any(|e| e.kind.has_detailed_outputs())
    }

    /// Number of event functions of all elements.
    pub fn n_events(&self) -> usize {
        *self.event_offsets.last().unwrap_or(&0)
    }

    /// The event functions of element `k`.
    #[inline]
    pub fn events_of(&self, k: usize) -> std::ops::Range<usize> {
        self.event_offsets[k]..self.event_offsets[k + 1]
    }

    /// The element owning event function `event`, and the event's index among that element's.
    #[inline]
    pub fn event_owner(&self, event: usize) -> (usize, usize) {
        // the last element whose first event is at or before it (one with no
        // events starts where the next one does, after its owner)
        let k = self.event_offsets.partition_point(|&first| first <= event) - 1;
        (k, event - self.event_offsets[k])
    }

    /// The discrete memory slots of element `k`.
    #[inline]
    pub fn memory_of(&self, k: usize) -> std::ops::Range<usize> {
        self.memory_offsets[k]..self.memory_offsets[k + 1]
    }

    /// The discrete memory of every element at the start of a run (all slots, element by element).
    pub fn initial_memory(&self) -> Vec<ElementMemory> {
        let mut memory = vec![ElementMemory::None; *self.memory_offsets.last().unwrap_or(&0)];
        for (k, element) in self.elements.iter().enumerate() {
            element.kind.start_memory(&mut memory[self.memory_of(k)]);
        }
        memory
    }

    /// Contact onsets counted in element `k`'s memory slots.
    pub fn impacts(&self, k: usize, memory: &[ElementMemory]) -> usize {
        memory[self.memory_of(k)].iter().map(ElementMemory::impacts).sum()
    }

    /// The ideal joint, driver or assembly lock `e` (an index into [`Self::elements`] of one).
    #[inline]
    pub fn ideal(&self, e: usize) -> &IdealElement {
        self.elements[e].ideal().expect("the element owns constraint equations: it is ideal")
    }

    /// The ideal joints, drivers and assembly locks: index in [`Self::elements`] and element.
    pub fn ideal_elements(&self) -> impl Iterator<Item = (usize, &IdealElement)> + Clone {
        self.elements.iter().enumerate().filter_map(|(k, element)| element.ideal().map(|ideal| (k, ideal)))
    }

    /// The spatial clearance joints: index in [`Self::elements`], name and joint.
    pub fn spatial_clearance_joints(&self) -> impl Iterator<Item = (usize, &str, &SpatialClearanceRevolute)> + Clone {
        self.elements.iter().enumerate().filter_map(|(k, element)| match &element.kind {
            ElementKind::SpatialClearanceRevolute(joint) => Some((k, element.name.as_str(), &**joint)),
            _ => None,
        })
    }

    /// The clearance joints: index in [`Self::elements`], name and joint.
    pub fn clearance_joints(&self) -> impl Iterator<Item = (usize, &str, &ClearanceRevolute)> + Clone {
        self.elements.iter().enumerate().filter_map(|(k, element)| match &element.kind {
            ElementKind::ClearanceRevolute(joint) => Some((k, element.name.as_str(), joint)),
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
