//! The tree of ideal joints: each body's parent, the joint between them and
//! the coordinate that joint contributes, found from the compiled elements.

use crate::body::BodyKind;
use crate::kinematics::marker::{BodyIndex, Marker};
use crate::kinematics::planar::Vec2;
use super::mechanism::Model;
use crate::joint::IdealKind;
use crate::joint::{ConstraintKind, Target};
use crate::motion::TimeFunction;

/// How a body moves relative to its parent.
#[derive(Clone, Debug, PartialEq)]
pub enum EdgeJoint {
    /// No ideal joint: the body's own `(x, y, phi)` are three joint coordinates (the parent is the ground).
    Free,
    /// Revolute joint; its coordinate is the child's absolute angle [rad] (a
    /// driver prescribes `phi_second - phi_first`).
    Revolute {
        /// Joint point on the parent (body frame) [m].
        parent_point: Vec2,
        /// Joint point on the child (body frame) [m].
        child_point: Vec2,
        /// +1 when the child is the joint's second body, -1 when it is the first.
        sign: f64,
    },
    /// Translational joint; its coordinate is `u . (P_second - P_first)` [m], `u` the axis fixed in the first body.
    Translational {
        /// Joint point on the parent (body frame) [m].
        parent_point: Vec2,
        /// Joint point on the child (body frame) [m].
        child_point: Vec2,
        /// Unit axis in the first body's frame [-].
        axis: Vec2,
        /// Whether the parent is the joint's first body.
        parent_is_first: bool,
        /// The locked `phi_second - phi_first` [rad].
        relative_angle: f64,
    },
    /// Fixed joint: no coordinate.
    Fixed {
        /// Joint point on the parent (body frame) [m].
        parent_point: Vec2,
        /// Joint point on the child (body frame) [m].
        child_point: Vec2,
        /// The locked `phi_child - phi_parent` [rad].
        relative_angle: f64,
    },
}

/// Where the value of an edge's coordinate comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum EdgeCoordinate {
    /// The joint's coordinates start at this index of `theta` (three for a free body, else one).
    Dofs(usize),
    /// A driver prescribes it as a function of time [rad or m].
    Driven(TimeFunction),
    /// The joint has no coordinate (fixed joint).
    Locked,
}

/// The size parameter of the kernels compiled for any number of joint coordinates.
pub(crate) const ANY_DOFS: usize = 0;

/// The largest number of joint coordinates with kernels compiled for their own
/// size (the others run the kernel for [`ANY_DOFS`]).
pub(crate) const FIXED_DOFS_MAX: usize = 4;

/// One edge of the tree: a body and how it hangs on its parent.
#[derive(Clone, Debug, PartialEq)]
pub struct TreeEdge {
    /// The body placed by this edge.
    pub child: BodyIndex,
    /// Its parent (the ground or a body placed by an earlier edge).
    pub parent: BodyIndex,
    /// The joint between them.
    pub joint: EdgeJoint,
    /// Its coordinate.
    pub coordinate: EdgeCoordinate,
    /// The ideal joint element (index into `Model::elements`), if any.
    pub joint_element: Option<usize>,
    /// The driver element of that joint, if any.
    pub driver_element: Option<usize>,
}

/// The spanning tree of a mechanism whose ideal joints close no loop.
#[derive(Clone, Debug, PartialEq)]
pub struct JointTree {
    /// One edge per body, parents before children.
    pub edges: Vec<TreeEdge>,
    /// Number of joint coordinates.
    pub n_dofs: usize,
    /// Diagonal of the mass matrix over the bodies' velocity coordinates [kg, kg m^2].
    pub(crate) mass: Vec<f64>,
}

impl JointTree {
    /// The tree of `model`'s ideal joints, or why its equations need the absolute form
    /// (a joint that closes a loop, a joint driven twice, a body kind without joint coordinates).
    pub fn of(model: &Model) -> Result<JointTree, String> {
        if model.spatial {
            return Err(SPATIAL_MODELS.to_string());
        }
        let mut mass = Vec::with_capacity(model.layout.nv);
        for body in &model.bodies {
            match &body.kind {
                BodyKind::PlanarRigid(b) => mass.extend(b.inverse_mass().iter().map(|w| 1.0 / w)),
                BodyKind::Beam(_) => return Err(format!("body {:?} is a beam (flexible bodies run in absolute coordinates)", body.name)),
                BodyKind::Modal(_) => return Err(format!("body {:?} is a modal body (flexible bodies run in absolute coordinates)", body.name)),
                BodyKind::SpatialRigid(_) => return Err(SPATIAL_MODELS.to_string()),
            }
        }
        let joints = joint_elements(model)?;
        let drivers = drivers_of(model, &joints)?;
        let mut placed = vec![false; model.bodies.len() + 1];
        let mut used = vec![false; joints.len()];
        let mut edges = Vec::with_capacity(model.bodies.len());
        let mut n_dofs = 0;
        // breadth first from the ground, then from every body no ideal joint holds
        let mut roots = std::iter::once(BodyIndex::GROUND).chain((1..=model.bodies.len()).map(BodyIndex));
        let mut queue = std::collections::VecDeque::new();
        loop {
            let Some(parent) = queue.pop_front().or_else(|| next_root(&mut roots, &mut placed, &mut edges, &mut n_dofs)) else { break };
            for (j, &element) in joints.iter().enumerate() {
                let e = model.ideal(element);
                if used[j] || (e.first != parent && e.second != parent) {
                    continue;
                }
                used[j] = true;
                let child = if e.first == parent { e.second } else { e.first };
                if placed[child.0] {
                    return Err(format!("joint {:?} closes a loop of ideal joints", model.elements[element].name));
                }
                placed[child.0] = true;
                let (joint, has_coordinate) = edge_joint(model, element, parent);
                let coordinate = match (&drivers[j], has_coordinate) {
                    (Some((_, f)), _) => EdgeCoordinate::Driven(f.clone()),
                    (None, true) => {
                        n_dofs += 1;
                        EdgeCoordinate::Dofs(n_dofs - 1)
                    }
                    (None, false) => EdgeCoordinate::Locked,
                };
                let driver_element = drivers[j].as_ref().map(|d| d.0);
                edges.push(TreeEdge { child, parent, joint, coordinate, joint_element: Some(element), driver_element });
                queue.push_back(child);
            }
        }
        Ok(JointTree { edges, n_dofs, mass })
    }

    /// The number of joint coordinates, `N` itself unless it is [`ANY_DOFS`]: the
    /// kernels are compiled for small fixed sizes, whose loops the compiler unrolls.
    #[inline(always)]
    pub(crate) fn dofs<const N: usize>(&self) -> usize {
        debug_assert!(N == ANY_DOFS || N == self.n_dofs);
        if N == ANY_DOFS { self.n_dofs } else { N }
    }

    /// Velocity coordinates of body `body` in the body-space layout (three per planar body).
    #[inline]
    pub(crate) fn body_offset(body: BodyIndex) -> usize {
        3 * (body.0 - 1)
    }
}

/// Why a spatial model runs in absolute coordinates (`docs/theory/spatial-formulation.md`).
const SPATIAL_MODELS: &str = "the model is spatial: the joint-coordinate formulation holds planar trees, spatial models run in absolute coordinates";

/// The next body not yet placed, as a free root of the tree (placed here).
fn next_root(
    roots: &mut impl Iterator<Item = BodyIndex>,
    placed: &mut [bool],
    edges: &mut Vec<TreeEdge>,
    n_dofs: &mut usize,
) -> Option<BodyIndex> {
    let body = roots.find(|b| !placed[b.0])?;
    placed[body.0] = true;
    if !body.is_ground() {
        edges.push(TreeEdge {
            child: body,
            parent: BodyIndex::GROUND,
            joint: EdgeJoint::Free,
            coordinate: EdgeCoordinate::Dofs(*n_dofs),
            joint_element: None,
            driver_element: None,
        });
        *n_dofs += 3;
    }
    Some(body)
}

/// The ideal joints acting during the simulation (element indices); an error for an element the tree cannot hold.
fn joint_elements(model: &Model) -> Result<Vec<usize>, String> {
    let mut joints = Vec::new();
    for (e, element) in model.ideal_elements() {
        if element.constraints.start >= model.n_dynamic_constraints {
            continue; // assembly locks
        }
        match element.kind {
            IdealKind::RevoluteJoint | IdealKind::TranslationalJoint | IdealKind::FixedJoint => joints.push(e),
            IdealKind::AngleDriver | IdealKind::DisplacementDriver => {}
            IdealKind::AssemblyLock => return Err(format!("the assembly lock {:?} acts during the simulation", model.elements[e].name)),
            IdealKind::SpatialJoint(_) | IdealKind::SpatialAngleDriver | IdealKind::SpatialDisplacementDriver => return Err(SPATIAL_MODELS.to_string()),
        }
    }
    Ok(joints)
}

/// For each joint of `joints`, its driver element and function, if driven.
fn drivers_of(model: &Model, joints: &[usize]) -> Result<Vec<Option<(usize, TimeFunction)>>, String> {
    let mut drivers: Vec<Option<(usize, TimeFunction)>> = vec![None; joints.len()];
    for (d, element) in model.ideal_elements() {
        let wanted = match element.kind {
            IdealKind::AngleDriver => IdealKind::RevoluteJoint,
            IdealKind::DisplacementDriver => IdealKind::TranslationalJoint,
            _ => continue,
        };
        let name = &model.elements[d].name;
        let Some(j) = joints.iter().position(|&e| {
            let joint = model.ideal(e);
            joint.kind == wanted && joint.first == element.first && joint.second == element.second
        }) else {
            return Err(format!("the driver {name:?} drives no joint of the tree"));
        };
        if drivers[j].is_some() {
            return Err(format!("joint {:?} is driven twice", model.elements[joints[j]].name));
        }
        let function = match &model.constraints[element.constraints.start].kind {
            ConstraintKind::RelativeAngle(c) => &c.target,
            ConstraintKind::AxialProjection(c) => &c.target,
            _ => return Err(format!("the driver {name:?} has no driven planar coordinate")),
        };
        let Target::Driven(function) = function else { return Err(format!("the driver {name:?} prescribes no function")) };
        drivers[j] = Some((d, function.clone()));
    }
    Ok(drivers)
}

/// The joint of element `e` seen from `parent`, and whether it has a coordinate.
fn edge_joint(model: &Model, e: usize, parent: BodyIndex) -> (EdgeJoint, bool) {
    let element = model.ideal(e);
    let mut points: Option<(Marker, Marker)> = None;
    let mut relative_angle = 0.0;
    for c in element.constraints.clone() {
        match &model.constraints[c].kind {
            ConstraintKind::PointCoincidence(p) => points = Some((p.first, p.second)),
            ConstraintKind::AxialProjection(p) => points = Some((p.first, p.second)),
            ConstraintKind::RelativeAngle(r) => {
                if let Target::Fixed(angle) = r.target {
                    relative_angle = angle;
                }
            }
            // (spatial models never reach the tree: [`JointTree::of`] refuses them first)
            _ => {}
        }
    }
    let (first, second) = points.expect("a revolute, translational or fixed joint has two joint points");
    let parent_is_first = element.first == parent;
    let (parent_point, child_point) = if parent_is_first { (first.local, second.local) } else { (second.local, first.local) };
    let sign = if parent_is_first { 1.0 } else { -1.0 };
    match element.kind {
        IdealKind::RevoluteJoint => (EdgeJoint::Revolute { parent_point, child_point, sign }, true),
        IdealKind::TranslationalJoint => {
            (EdgeJoint::Translational { parent_point, child_point, axis: element.axis, parent_is_first, relative_angle }, true)
        }
        _ => (EdgeJoint::Fixed { parent_point, child_point, relative_angle: sign * relative_angle }, false),
    }
}
