//! Compiling a [`ModelSpec`] into a [`Model`]: names resolved, laws built,
//! every problem reported with its location.

use std::collections::HashMap;

use crate::dynamics::model::channels::{Channel, ChannelInfo, ChannelRead, Source};
use crate::dynamics::model::constraint_jacobian::{JacobianPattern, MarkerColumns};
use crate::kinematics::marker::{BodyIndex, Marker, ModalNodeSite, Site, SpatialMarker};
use crate::kinematics::planar::{perp, Frame, Vec2};
use crate::kinematics::spatial::Vec3;
use crate::dynamics::model::mechanism::{Body, Model, SchurTerm, Section, StrainGauge, VelocityStart};
use crate::body::{BodyKind, BodyModel, MassBlock, PlanarRigidBody};
use crate::linalg::PatternLdl;
use crate::error::ModelErrors;
use crate::element::{Element, ElementKind, ElementModel};
use crate::force::{AppliedTorque, PointForce, RotationalSpringDamper, SpringDamper};
use crate::joint::{AxialProjection, ClearanceRevolute, Constraint, ConstraintKind, IdealElement, IdealKind, PointCoincidence, RelativeAngle, Target};
use crate::dynamics::model::joint_tree::JointTree;
use crate::spec::{ranges, Range, SpringDamperSpec, BeamSpec, ModalBodySpec, ClearanceJointSpec, DriverSpec, ForceSpec, JointSpec, ModelSpec, PointSpec, SensorSpec, GROUND};

#[path = "compile/beams.rs"]
mod beams;
#[path = "compile/hydraulic.rs"]
mod hydraulic;
#[path = "compile/laws.rs"]
mod laws;
#[path = "compile/lubrication.rs"]
mod lubrication;
#[path = "compile/modal.rs"]
mod modal;
#[path = "compile/spatial.rs"]
mod spatial;
#[path = "compile/spatial_clearance.rs"]
mod spatial_clearance;

use laws::{build_friction, build_function, build_normal_force_law, build_stiffness};
use beams::build_beam;
use hydraulic::build_cylinder;
use lubrication::build_lubrication;
use modal::build_modal_body;

/// Default bound on penetration as a fraction of the journal radius: far
/// beyond elastic contact of metals, so reaching it means a wrong input.
const MAX_PENETRATION_FRACTION_OF_RADIUS: f64 = 0.05;

/// A flexible body's initial rigid motion from its description: the velocity of
/// its reference point [m/s] and its angular velocity [rad/s] (a missing one
/// zero), and whether either was given (then it is held at assembly) or the
/// mechanism's rigid motion is to be found.
fn given_rigid_motion(velocity: Option<[f64; 2]>, angular_velocity: Option<f64>) -> (Vec2, f64, VelocityStart) {
    let start = if velocity.is_some() || angular_velocity.is_some() { VelocityStart::Given } else { VelocityStart::RigidMotion };
    let [vx, vy] = velocity.unwrap_or([0.0; 2]);
    (Vec2::new(vx, vy), angular_velocity.unwrap_or(0.0), start)
}

/// Whether a description has spatial bodies, joints or force elements.
fn is_spatial(spec: &ModelSpec) -> bool {
    let some = |n: Option<usize>| n.is_some_and(|n| n > 0);
    some(spec.spatial_bodies.as_ref().map(Vec::len)) || some(spec.spatial_joints.as_ref().map(Vec::len)) || some(spec.spatial_forces.as_ref().map(Vec::len))
        || some(spec.spatial_clearance_joints.as_ref().map(Vec::len))
}

/// Compiles a model description; returns every problem found.
pub fn compile(spec: &ModelSpec) -> Result<Model, ModelErrors> {
    let mut c = Compiler::new(spec);
    c.bodies();
    c.joints();
    c.spatial_joints();
    c.spatial_clearance_joints();
    c.drivers();
    c.forces();
    c.spatial_forces();
    c.sensors();
    c.locks();
    c.finish()
}

/// A spatial joint, for its drivers: its kind and its two marker frames.
#[derive(Clone, Copy)]
struct SpatialJointEntry {
    kind: crate::spec::SpatialJointKind,
    markers: [SpatialMarker; 2],
}

struct Compiler<'s> {
    spec: &'s ModelSpec,
    errors: ModelErrors,
    body_index: HashMap<&'s str, BodyIndex>,
    points: HashMap<String, Marker>,
    /// Every named point as a marker with a frame (planar points embedded).
    spatial_points: HashMap<String, SpatialMarker>,
    /// Spatial joint name -> kind and markers, for drivers.
    spatial_joint_index: HashMap<&'s str, SpatialJointEntry>,
    model: Model,
    /// joint name -> (kind, element index) for drivers
    joint_index: HashMap<&'s str, (IdealKind, usize)>,
    /// Clearance joints to lock at assembly: bearing, journal, initial eccentricity [m], name.
    assembly_locks: Vec<(Marker, Marker, Vec2, String)>,
    /// Spatial clearance joints held centred and aligned at assembly: bearing, journal, name.
    spatial_assembly_locks: Vec<(SpatialMarker, SpatialMarker, String)>,
    names: HashMap<String, String>,
}

impl<'s> Compiler<'s> {
    fn new(spec: &'s ModelSpec) -> Self {
        let model = Model {
            name: spec.name.clone(),
            bodies: Vec::new(),
            points: Vec::new(),
            sections: Vec::new(),
            gauges: Vec::new(),
            gravity: Vec3::from(spec.gravity),
            spatial: is_spatial(spec),
            layout: Default::default(),
            constraints: Vec::new(),
            n_dynamic_constraints: 0,
            row_offsets: vec![0],
            row_owner: Vec::new(),
            jacobian_pattern: JacobianPattern::default(),
            diagonal_inverse_mass: None,
            schur_terms: Vec::new(),
            schur_factor: PatternLdl::analyse(0, &[]),
            elements: Vec::new(),
            acting: Vec::new(),
            event_offsets: vec![0],
            memory_offsets: vec![0],
            event_bodies: Vec::new(),
            initial_coordinates: Vec::new(),
            initial_velocities: Vec::new(),
            initial_element_states: Vec::new(),
            channels: Vec::new(),
            channel_reads: Vec::new(),
            joint_tree: Err("not compiled".to_string()),
        };
        Self {
            spec,
            errors: ModelErrors::default(),
            body_index: HashMap::new(),
            points: HashMap::new(),
            spatial_points: HashMap::new(),
            spatial_joint_index: HashMap::new(),
            model,
            joint_index: HashMap::new(),
            assembly_locks: Vec::new(),
            spatial_assembly_locks: Vec::new(),
            names: HashMap::new(),
        }
    }

    /// Element names share one namespace (channels are `<name>.<quantity>`).
    fn claim_name(&mut self, name: &str, location: &str) {
        if name.is_empty() || name.contains('.') || name == GROUND {
            self.errors.push(location, format!("must be a non-empty name without '.', other than 'ground', got {name:?}"));
        } else if let Some(previous) = self.names.insert(name.to_string(), location.to_string()) {
            self.errors.push(location, format!("name {name:?} is already used by {previous}"));
        }
    }

    fn bodies(&mut self) {
        self.body_index.insert(GROUND, BodyIndex::GROUND);
        for (k, p) in self.spec.ground_points.iter().enumerate() {
            self.add_point(BodyIndex::GROUND, GROUND, p, format!("ground_points[{k}]"));
        }
        for (k, b) in self.spec.bodies.iter().enumerate() {
            let loc = format!("bodies[{k}]");
            self.claim_name(&b.name, &format!("{loc}.name"));
            Range::check_all(&[(ranges::BODIES_MASS, b.mass), (ranges::BODIES_INERTIA, b.inertia)], &loc, &mut self.errors);
            let index = BodyIndex(k + 1);
            self.body_index.insert(&b.name, index);
            let kind = BodyKind::PlanarRigid(PlanarRigidBody::new(b.mass, b.inertia));
            self.model.layout.push_body(&kind);
            self.model.initial_coordinates.extend([b.position[0], b.position[1], b.angle]);
            self.model.initial_velocities.extend([b.velocity[0], b.velocity[1], b.angular_velocity]);
            self.model.bodies.push(Body { name: b.name.clone(), kind, velocity_start: VelocityStart::Approximate });
            for (i, p) in b.points.iter().enumerate() {
                self.add_point(index, &b.name, p, format!("{loc}.points[{i}]"));
            }
            self.body_channels(k, &b.name);
        }
        for (k, b) in self.spec.beams.iter().enumerate() {
            self.beam(&format!("beams[{k}]"), b);
        }
        for (k, b) in self.spec.modal_bodies.iter().flatten().enumerate() {
            self.modal_body(&format!("modal_bodies[{k}]"), b);
        }
        self.spatial_bodies();
    }

    /// A modal body: its body, coordinates, interface nodes and points, and channels.
    fn modal_body(&mut self, loc: &str, b: &'s ModalBodySpec) {
        self.claim_name(&b.name, &format!("{loc}.name"));
        let Some(built) = build_modal_body(b, loc, &mut self.errors) else { return };
        let index = BodyIndex(self.model.bodies.len() + 1);
        self.body_index.insert(&b.name, index);
        let n_modes = built.body.n_modes();
        self.model.initial_coordinates.extend(built.pose.iter().copied().chain(std::iter::repeat_n(0.0, n_modes)));
        let (velocity, angular_velocity, velocity_start) = given_rigid_motion(b.velocity, b.angular_velocity);
        self.model.initial_velocities.extend([velocity.x, velocity.y, angular_velocity].into_iter().chain(std::iter::repeat_n(0.0, n_modes)));
        let kind = BodyKind::Modal(Box::new(built.body));
        self.model.layout.push_body(&kind);
        self.model.bodies.push(Body { name: b.name.clone(), kind, velocity_start });
        for (name, node, location) in built.interface.into_iter().chain(built.points) {
            let marker = self.section_marker(index, Site::ModalNode(ModalNodeSite { node: node as u32 }), Vec2::zeros());
            self.name_point(&b.name, &name, marker, location);
        }
        self.body_channels(index.0 - 1, &b.name);
    }

    /// A beam: its body, coordinates, points (`start`, `end` and the described ones) and channels.
    fn beam(&mut self, loc: &str, b: &'s BeamSpec) {
        self.claim_name(&b.name, &format!("{loc}.name"));
        let Some(beam) = build_beam(b, loc, &mut self.errors) else { return };
        let index = BodyIndex(self.model.bodies.len() + 1);
        self.body_index.insert(&b.name, index);
        self.model.initial_coordinates.extend(beam.reference_coordinates());
        let (velocity, angular_velocity, velocity_start) = given_rigid_motion(b.velocity, b.angular_velocity);
        self.model.initial_velocities.extend(beam.rigid_velocities(velocity, angular_velocity));
        let length = beam.length;
        let kind = BodyKind::Beam(beam);
        self.model.layout.push_body(&kind);
        self.model.bodies.push(Body { name: b.name.clone(), kind, velocity_start });
        let named = [("start", 0.0, format!("{loc}.start")), ("end", length, format!("{loc}.end"))];
        let described = b.points.iter().enumerate().map(|(i, p)| (p.name.as_str(), p.arclength, format!("{loc}.points[{i}]")));
        for (name, arclength, location) in named.into_iter().chain(described) {
            self.add_beam_point(index, &b.name, name, arclength, location);
        }
        self.body_channels(index.0 - 1, &b.name);
    }

    /// A named point on the axis of beam `body` at `arclength` [m] from its first end.
    fn add_beam_point(&mut self, body: BodyIndex, body_name: &str, name: &str, arclength: f64, location: String) {
        let BodyKind::Beam(beam) = &self.model.bodies[body.0 - 1].kind else { unreachable!("a beam point on a beam") };
        let site = match beam.site_at(arclength) {
            Ok(site) => site,
            Err(message) => {
                self.errors.push(format!("{location}.arclength"), message);
                return;
            }
        };
        let marker = self.section_marker(body, Site::Section(site), Vec2::zeros());
        self.name_point(body_name, name, marker, location);
    }

    /// A marker at a section of a flexible body (with its frame, shared by the markers at the same section).
    fn section_marker(&mut self, body: BodyIndex, site: Site, local: Vec2) -> Marker {
        let total_bodies = self.spec.bodies.len() + self.spec.beams.len() + self.spec.modal_bodies.as_ref().map_or(0, Vec::len) + self.spec.spatial_bodies.as_ref().map_or(0, Vec::len);
        let section = Section { body, site };
        let k = self.model.sections.iter().position(|s| *s == section).unwrap_or_else(|| {
            self.model.sections.push(section);
            self.model.sections.len() - 1
        });
        Marker { body, frame: 1 + total_bodies + k, site, local }
    }

    /// A named point of a planar body's (or the ground's) reference frame, with its frame for spatial joints.
    fn add_point(&mut self, body: BodyIndex, body_name: &str, point: &PointSpec, location: String) {
        let axes = spatial::marker_axes(point.axes, &location, &mut self.errors);
        self.add_spatial_point(body, body_name, &point.name, point.position, axes, location);
    }

    /// Names `marker` `"<body_name>.<name>"`.
    fn name_point(&mut self, body_name: &str, name: &str, marker: Marker, location: String) {
        let full = format!("{body_name}.{name}");
        if name.is_empty() || name.contains('.') {
            self.errors.push(format!("{location}.name"), format!("must be a non-empty name without '.', got {name:?}"));
        }
        let embedded = spatial::embedded_marker(marker, 0.0, nalgebra::Matrix3::identity());
        self.spatial_points.entry(full.clone()).or_insert(embedded);
        if self.points.insert(full.clone(), marker).is_some() {
            self.errors.push(format!("{location}.name"), format!("point {full:?} is defined twice"));
        }
        self.model.points.push((full, marker));
    }

    fn point(&mut self, reference: &str, location: String) -> Option<Marker> {
        let found = self.points.get(reference).copied();
        if found.is_none() {
            let hint = match reference.split_once('.') {
                None => "a point is written \"body.point\"".to_string(),
                Some((body, _)) if !self.body_index.contains_key(body) => format!("no body named {body:?}"),
                Some((body, _)) => format!("body {body:?} has no such point"),
            };
            self.errors.push(location, format!("unknown point {reference:?} ({hint})"));
        }
        found
    }

    fn body(&mut self, name: &str, location: String) -> Option<BodyIndex> {
        let found = self.body_index.get(name).copied();
        if found.is_none() {
            self.errors.push(location, format!("unknown body {name:?}"));
        }
        found
    }

    /// The frame of a marker at the positions of the description.
    fn initial_frame(&self, marker: Marker) -> Frame {
        let Some(address) = self.model.layout.body(marker.body) else { return Frame::GROUND };
        let (q, v) = (&self.model.initial_coordinates[address.q_range()], &self.model.initial_velocities[address.v_range()]);
        self.model.bodies[marker.body.0 - 1].kind.site_frame(&marker.site, q, v, &Frame::GROUND)
    }

    /// Global position [m] of a marker at the positions of the description.
    fn initial_point(&self, marker: Marker) -> Vec2 {
        self.initial_frame(marker).point(marker.local)
    }

    /// Angle [rad] of a marker's frame at the positions of the description.
    fn initial_angle(&self, marker: Marker) -> f64 {
        self.initial_frame(marker).angle
    }

    /// The velocity coordinates a marker's constraint rows span (`None` on the ground).
    fn marker_columns(&self, marker: Marker) -> Option<MarkerColumns> {
        let address = self.model.layout.body(marker.body)?;
        let within = self.model.bodies[marker.body.0 - 1].kind.marker_coordinates(&marker);
        Some(MarkerColumns { body: marker.body.0 - 1, body_columns: address.v_range(), columns: address.v + within.start..address.v + within.end })
    }

    /// Adds an ideal element owning the constraints `kinds`, with its channels; returns its index.
    fn add_element(&mut self, name: &str, kind: IdealKind, first: Marker, second: Marker, axis: Vec2, kinds: Vec<ConstraintKind>) -> usize {
        let owner = self.model.elements.len();
        let start = self.model.constraints.len();
        for k in kinds {
            let rows = k.n_equations();
            let last = *self.model.row_offsets.last().unwrap();
            self.model.row_offsets.push(last + rows);
            self.model.row_owner.extend(std::iter::repeat_n(owner, rows));
            let markers = k.markers().map(|m| self.marker_columns(m));
            self.model.jacobian_pattern.push_rows(rows, markers);
            self.model.constraints.push(Constraint { kind: k, owner });
        }
        let ideal = IdealElement {
            kind,
            first: first.body,
            second: second.body,
            second_point: second.local,
            frames: [first.frame, second.frame],
            axis,
            constraints: start..self.model.constraints.len(),
            spatial_markers: None,
        };
        self.push_element(name, ElementKind::Ideal(ideal), Vec::new())
    }

    /// The ideal element `element`, to complete.
    fn ideal_mut(&mut self, element: usize) -> &mut IdealElement {
        match &mut self.model.elements[element].kind {
            ElementKind::Ideal(ideal) => ideal,
            _ => unreachable!("the element was added as an ideal one"),
        }
    }

    fn joints(&mut self) {
        for (k, joint) in self.spec.joints.iter().enumerate() {
            let loc = format!("joints[{k}]");
            match joint {
                JointSpec::Revolute { name, first, second } => self.ideal_joint(&loc, name, first, second, IdealKind::RevoluteJoint, None),
                JointSpec::Fixed { name, first, second } => self.ideal_joint(&loc, name, first, second, IdealKind::FixedJoint, None),
                JointSpec::Translational { name, first, second, axis } => {
                    self.ideal_joint(&loc, name, first, second, IdealKind::TranslationalJoint, Some(*axis))
                }
                JointSpec::ClearanceRevolute(c) => self.clearance_joint(&loc, c),
            }
        }
    }

    fn distinct_bodies(&mut self, loc: &str, a: Marker, b: Marker) -> bool {
        if a.body == b.body {
            self.errors.push(loc.to_string(), format!("connects body {:?} to itself", self.model.body_name(a.body)));
            return false;
        }
        true
    }

    fn ideal_joint(&mut self, loc: &str, name: &'s str, first: &str, second: &str, kind: IdealKind, axis: Option<[f64; 2]>) {
        self.claim_name(name, &format!("{loc}.name"));
        let a = self.point(first, format!("{loc}.first"));
        let b = self.point(second, format!("{loc}.second"));
        let (Some(a), Some(b)) = (a, b) else { return };
        if !self.distinct_bodies(loc, a, b) {
            return;
        }
        let relative_angle = self.initial_angle(b) - self.initial_angle(a);
        let lock_rotation = ConstraintKind::RelativeAngle(RelativeAngle { first: a, second: b, target: Target::Fixed(relative_angle) });
        let coincide = ConstraintKind::PointCoincidence(PointCoincidence { first: a, second: b, offset: Vec2::zeros() });
        let mut unit_axis = Vec2::zeros();
        let kinds = match kind {
            IdealKind::RevoluteJoint => vec![coincide],
            IdealKind::FixedJoint => vec![coincide, lock_rotation],
            _ => {
                let axis = axis.unwrap_or([0.0, 0.0]);
                let v = Vec2::new(axis[0], axis[1]);
                if !(v.norm() > 0.0 && v.norm().is_finite()) {
                    self.errors.push(format!("{loc}.axis"), format!("must be a non-zero direction, got {axis:?}"));
                    return;
                }
                unit_axis = v / v.norm();
                let normal = AxialProjection { first: a, second: b, direction: perp(unit_axis), target: Target::Fixed(0.0) };
                vec![lock_rotation, ConstraintKind::AxialProjection(normal)]
            }
        };
        let element = self.add_element(name, kind, a, b, unit_axis, kinds);
        self.joint_index.insert(name, (kind, element));
    }

    fn clearance_joint(&mut self, loc: &str, c: &'s ClearanceJointSpec) {
        self.claim_name(&c.name, &format!("{loc}.name"));
        let a = self.point(&c.bearing, format!("{loc}.bearing"));
        let b = self.point(&c.journal, format!("{loc}.journal"));
        let given = [
            (ranges::JOINTS_CLEARANCE_REVOLUTE_BEARING_RADIUS, Some(c.bearing_radius)),
            (ranges::JOINTS_CLEARANCE_REVOLUTE_CLEARANCE, Some(c.clearance)),
            (ranges::JOINTS_CLEARANCE_REVOLUTE_ONSET_VELOCITY_FLOOR, Some(c.onset_velocity_floor)),
            (ranges::JOINTS_CLEARANCE_REVOLUTE_MAX_PENETRATION, c.max_penetration),
        ];
        Range::check_given(&given, loc, &mut self.errors);
        if c.clearance.is_finite() && c.bearing_radius.is_finite() && c.clearance >= c.bearing_radius && c.clearance > 0.0 {
            self.errors.push(
                format!("{loc}.clearance"),
                format!("must be smaller than the bearing radius {} m (the journal radius would be <= 0), got {} m", c.bearing_radius, c.clearance),
            );
        }
        let journal_radius = c.bearing_radius - c.clearance;
        let stiffness = build_stiffness(c, journal_radius, loc, &mut self.errors);
        let law = build_normal_force_law(&c.contact, &format!("{loc}.contact"), &mut self.errors);
        let friction = build_friction(&c.friction, &format!("{loc}.friction"), &mut self.errors);
        let lubrication = match &c.lubrication {
            Some(l) if journal_radius > 0.0 => build_lubrication(c, l, journal_radius, loc, &mut self.errors).map(Some),
            Some(_) => None,
            None => Some(None),
        };
        let (Some(a), Some(b), Some(stiffness), Some(law), Some(friction), Some(lubrication)) = (a, b, stiffness, law, friction, lubrication) else {
            return;
        };
        if !self.distinct_bodies(loc, a, b) {
            return;
        }
        let e0 = Vec2::new(c.initial_eccentricity[0], c.initial_eccentricity[1]);
        if !(e0.norm() <= c.clearance) {
            self.errors.push(format!("{loc}.initial_eccentricity"), format!("must lie within the clearance {} m, got {:?} m", c.clearance, c.initial_eccentricity));
        }
        let max_penetration = c.max_penetration.unwrap_or(MAX_PENETRATION_FRACTION_OF_RADIUS * journal_radius);
        if c.lock_at_assembly {
            self.assembly_locks.push((a, b, e0, c.name.clone()));
        }
        let joint = ClearanceRevolute {
            bearing: a,
            journal: b,
            bearing_radius: c.bearing_radius,
            journal_radius,
            clearance: c.clearance,
            stiffness,
            normal_force_law: law,
            friction,
            onset_velocity_floor: c.onset_velocity_floor,
            max_penetration,
            initial_eccentricity: e0,
            lubrication,
        };
        self.push_element(&c.name, ElementKind::ClearanceRevolute(joint), Vec::new());
    }

    fn drivers(&mut self) {
        for (k, d) in self.spec.drivers.iter().enumerate() {
            self.driver(&format!("drivers[{k}]"), d);
        }
    }

    fn driver(&mut self, loc: &str, d: &'s DriverSpec) {
        self.claim_name(&d.name, &format!("{loc}.name"));
        let function = build_function(&d.function, &format!("{loc}.function"), &mut self.errors);
        if let Some(&entry) = self.spatial_joint_index.get(d.joint.as_str()) {
            if let Some(function) = function {
                self.spatial_driver(loc, &d.name, &d.joint, entry, function);
            }
            return;
        }
        let Some(&(kind, joint)) = self.joint_index.get(d.joint.as_str()) else {
            self.errors.push(format!("{loc}.joint"), format!("unknown revolute or translational joint {:?}", d.joint));
            return;
        };
        let Some(function) = function else { return };
        let element = self.model.ideal(joint).clone();
        let [first_point, second] = self.joint_points(joint);
        let (driver_kind, constraint) = match kind {
            IdealKind::RevoluteJoint => (
                IdealKind::AngleDriver,
                ConstraintKind::RelativeAngle(RelativeAngle { first: first_point, second, target: Target::Driven(function) }),
            ),
            IdealKind::TranslationalJoint => (
                IdealKind::DisplacementDriver,
                ConstraintKind::AxialProjection(AxialProjection { first: first_point, second, direction: element.axis, target: Target::Driven(function) }),
            ),
            _ => {
                self.errors.push(format!("{loc}.joint"), format!("joint {:?} is a fixed joint and cannot be driven", d.joint));
                return;
            }
        };
        self.add_element(&d.name, driver_kind, first_point, second, element.axis, vec![constraint]);
    }

    /// The first and the second point of an ideal joint (its constraints' markers).
    fn joint_points(&self, element: usize) -> [Marker; 2] {
        self.model.constraints[self.model.ideal(element).constraints.start].kind.markers()
    }

    fn forces(&mut self) {
        for (k, f) in self.spec.forces.iter().enumerate() {
            let loc = format!("forces[{k}]");
            if let Some((name, element, states)) = self.force(&loc, f) {
                self.push_element(name, element, states);
            }
        }
    }

    /// Adds an element with its channels, initial states, events and memory
    /// slots, as its kind declares them; returns its index.
    fn push_element(&mut self, name: &str, kind: ElementKind, initial_states: Vec<f64>) -> usize {
        let index = self.model.elements.len();
        let acting = kind.acts_through_forces();
        for (q, (quantity, unit, description)) in kind.channels().iter().enumerate() {
            let source = if acting { Source::Force(index, q as u8) } else { Source::Ideal(index, q as u8) };
            self.channel(name, quantity, unit, description.to_string(), source);
        }
        self.model.layout.push_element_states(kind.n_states());
        self.model.initial_element_states.extend(initial_states);
        self.model.event_offsets.push(self.model.n_events() + kind.n_events());
        self.model.memory_offsets.push(self.model.memory_offsets[index] + kind.n_memory_slots());
        for body in kind.event_bodies() {
            if !body.is_ground() && !self.model.event_bodies.contains(&body) {
                self.model.event_bodies.push(body);
            }
        }
        if acting {
            self.model.acting.push(index);
        }
        self.model.elements.push(Element { name: name.to_string(), kind });
        index
    }

    /// The element described by `f`, with its name and initial states.
    fn force(&mut self, loc: &str, f: &'s ForceSpec) -> Option<(&'s str, ElementKind, Vec<f64>)> {
        match f {
            ForceSpec::SpringDamper(SpringDamperSpec { name, first, second, stiffness, damping, free_length }) => {
                self.claim_name(name, &format!("{loc}.name"));
                let a = self.point(first, format!("{loc}.first"));
                let b = self.point(second, format!("{loc}.second"));
                let checks = [(ranges::FORCES_SPRING_DAMPER_STIFFNESS, *stiffness), (ranges::FORCES_SPRING_DAMPER_DAMPING, *damping), (ranges::FORCES_SPRING_DAMPER_FREE_LENGTH, *free_length)];
                Range::check_all(&checks, loc, &mut self.errors);
                let element = SpringDamper { first: a?, second: b?, stiffness: *stiffness, damping: *damping, free_length: *free_length };
                Some((name, ElementKind::SpringDamper(element), Vec::new()))
            }
            ForceSpec::RotationalSpringDamper { name, first, second, stiffness, damping, free_angle } => {
                self.claim_name(name, &format!("{loc}.name"));
                let a = self.body(first, format!("{loc}.first"));
                let b = self.body(second, format!("{loc}.second"));
                Range::check_all(&[(ranges::FORCES_ROTATIONAL_SPRING_DAMPER_STIFFNESS, *stiffness), (ranges::FORCES_ROTATIONAL_SPRING_DAMPER_DAMPING, *damping)], loc, &mut self.errors);
                let element = RotationalSpringDamper { first: Marker::reference(a?), second: Marker::reference(b?), stiffness: *stiffness, damping: *damping, free_angle: *free_angle };
                Some((name, ElementKind::RotationalSpringDamper(element), Vec::new()))
            }
            ForceSpec::PointForce { name, point, fx, fy } => {
                self.claim_name(name, &format!("{loc}.name"));
                let p = self.point(point, format!("{loc}.point"));
                let fx = build_function(fx, &format!("{loc}.fx"), &mut self.errors);
                let fy = build_function(fy, &format!("{loc}.fy"), &mut self.errors);
                let element = PointForce { point: p?, fx: fx?, fy: fy? };
                Some((name, ElementKind::PointForce(element), Vec::new()))
            }
            ForceSpec::Torque { name, body, torque } => {
                self.claim_name(name, &format!("{loc}.name"));
                let b = self.body(body, format!("{loc}.body"));
                let torque = build_function(torque, &format!("{loc}.torque"), &mut self.errors);
                Some((name, ElementKind::Torque(AppliedTorque { body: Marker::reference(b?), torque: torque? }), Vec::new()))
            }
            ForceSpec::HydraulicCylinder(c) => {
                self.claim_name(&c.name, &format!("{loc}.name"));
                let a = self.point(&c.first, format!("{loc}.first"));
                let b = self.point(&c.second, format!("{loc}.second"));
                let (a, b) = (a?, b?);
                let length = (self.initial_point(b) - self.initial_point(a)).norm();
                let (element, states) = build_cylinder(c, (a, b), length, loc, &mut self.errors)?;
                Some((&c.name, ElementKind::HydraulicCylinder(element), states))
            }
        }
    }

    fn sensors(&mut self) {
        for (k, sensor) in self.spec.sensors.iter().enumerate() {
            let loc = format!("sensors[{k}]");
            match sensor {
                SensorSpec::StrainGauge { name, point, fibre } => self.strain_gauge(&loc, name, point, *fibre),
            }
        }
    }

    /// A strain gauge at a point of a beam or modal body, with its channels.
    fn strain_gauge(&mut self, loc: &str, name: &str, point: &str, fibre: f64) {
        self.claim_name(name, &format!("{loc}.name"));
        let Some(marker) = self.point(point, format!("{loc}.point")) else { return };
        if !fibre.is_finite() {
            self.errors.push(format!("{loc}.fibre"), format!("must be finite, got {fibre}"));
        }
        let (site, strain_modes) = match (marker.site, &self.model.bodies[marker.body.0 - 1].kind) {
            (Site::Section(site), _) => (site, Vec::new()),
            (Site::ModalNode(node), BodyKind::Modal(modal)) => match modal.node_section(node.node as usize).and_then(|site| Some((site, modal.strain_modes(&site)?))) {
                Some(found) => found,
                None => {
                    self.errors.push(format!("{loc}.point"), format!("the modal body {:?} was given by matrices, without elements to recover strains on", self.model.body_name(marker.body)));
                    return;
                }
            },
            _ => {
                self.errors.push(format!("{loc}.point"), format!("must be a point of a beam or of a modal body, got {point:?} on the rigid body {:?}", self.model.body_name(marker.body)));
                return;
            }
        };
        let index = self.model.gauges.len();
        self.model.gauges.push(StrainGauge { name: name.to_string(), body: marker.body, site, fibre, strain_modes });
        for (q, (quantity, unit, description)) in StrainGauge::CHANNELS.iter().enumerate() {
            self.channel(name, quantity, unit, description.to_string(), Source::Gauge(index, q as u8));
        }
    }

    /// Clearance joints locked at their initial eccentricity, used only at assembly.
    fn locks(&mut self) {
        self.model.n_dynamic_constraints = self.model.constraints.len();
        for (bearing, journal, eccentricity, name) in std::mem::take(&mut self.assembly_locks) {
            let kind = ConstraintKind::PointCoincidence(PointCoincidence { first: bearing, second: journal, offset: eccentricity });
            self.add_element(&format!("{name} (assembly lock)"), IdealKind::AssemblyLock, bearing, journal, Vec2::zeros(), vec![kind]);
        }
        for (bearing, journal, name) in std::mem::take(&mut self.spatial_assembly_locks) {
            // the journal centred and aligned in its bore: an ideal revolute joint's equations
            let kinds = spatial::joint_equations(crate::spec::SpatialJointKind::Revolute, bearing, journal);
            let element = self.add_element(&format!("{name} (assembly lock)"), IdealKind::AssemblyLock, bearing.planar(), journal.planar(), Vec2::zeros(), kinds);
            self.ideal_mut(element).spatial_markers = Some(Box::new([bearing, journal]));
        }
    }

    /// The terms of `Phi_q M^-1 Phi_q^T` (one per pair of row blocks on a common body, rows in
    /// ascending order) and the factorisation of its dynamic rows.
    fn analyse_constraint_matrix(&mut self) {
        let model = &mut self.model;
        let pattern = &model.jacobian_pattern;
        // (a, b, block of a, block of b)
        let mut terms = Vec::new();
        for a in 0..pattern.n_rows() {
            for b in 0..=a {
                for first in pattern.row_block_indices(a) {
                    let body = pattern.blocks()[first].body;
                    for second in pattern.row_block_indices(b).filter(|&k| pattern.blocks()[k].body == body) {
                        terms.push((a, b, first, second));
                    }
                }
            }
        }
        let m = model.row_offsets[model.n_dynamic_constraints];
        let lower: Vec<(usize, usize)> = terms.iter().filter(|t| t.0 < m).map(|t| (t.0, t.1)).collect();
        model.schur_factor = PatternLdl::analyse(m, &lower);
        let narrow = |i: usize| u32::try_from(i).expect("a model has fewer than 2^32 constraint rows");
        let blocks = pattern.blocks();
        model.schur_terms = terms
            .into_iter()
            .map(|(a, b, first, second)| {
                let entry = if a < m { model.schur_factor.storage_index(a, b) } else { 0 };
                let (ba, bb) = (&blocks[first], &blocks[second]);
                // (blocks on one body without common columns, in two elements of a beam, have none)
                let common = ba.start.max(bb.start)..(ba.start + ba.width).min(bb.start + bb.width);
                let (start, common) = if common.is_empty() { (ba.start, 0) } else { (common.start, common.len()) };
                let (first_value, second_value) = if common == 0 { (ba.value, bb.value) } else { (ba.value + start - ba.start, bb.value + start - bb.start) };
                SchurTerm {
                    row: narrow(a),
                    column: narrow(b),
                    entry: narrow(entry),
                    first: narrow(first),
                    second: narrow(second),
                    first_value: narrow(first_value),
                    second_value: narrow(second_value),
                    column_start: narrow(start),
                    common: narrow(common),
                }
            })
            .collect();
    }

    /// The diagonal of `M^-1` when every body's mass block is constant and diagonal.
    fn diagonal_inverse_mass(&mut self) {
        let mut diagonal = Vec::with_capacity(self.model.layout.nv);
        for body in &self.model.bodies {
            match body.kind.mass_block() {
                MassBlock::ConstantDiagonal(w) => diagonal.extend_from_slice(w),
                MassBlock::ConstantFactored { .. } | MassBlock::ConfigurationDependent => return,
            }
        }
        self.model.diagonal_inverse_mass = Some(diagonal);
    }

    fn finish(mut self) -> Result<Model, ModelErrors> {
        // (more equations than coordinates is no error by itself: dependent equations are
        // handled, and a mechanism that cannot move as driven is reported at assembly)
        self.analyse_constraint_matrix();
        self.diagonal_inverse_mass();
        self.model.joint_tree = JointTree::of(&self.model);
        for (q, (quantity, description)) in [("kinetic_energy", "kinetic energy"), ("potential_energy", "potential energy (gravity, strain, springs, contact)"), ("energy", "total mechanical energy")].iter().enumerate() {
            self.channel("system", quantity, "J", description.to_string(), Source::Energy(q as u8));
        }
        self.model.channel_reads = ChannelRead::plan(&self.model, self.model.channels.iter().map(|c| c.source));
        self.errors.into_result(self.model)
    }

    fn channel(&mut self, element: &str, quantity: &str, unit: &'static str, description: String, source: Source) {
        let info = ChannelInfo { name: format!("{element}.{quantity}"), unit, description };
        self.model.channels.push(Channel { info, source });
    }

    /// The position, velocity and acceleration channels the kind of body `k` declares.
    fn body_channels(&mut self, k: usize, name: &str) {
        let address = self.model.layout.bodies[k];
        let kind = &self.model.bodies[k].kind;
        let (positions, rates) = (kind.position_channels(), kind.velocity_channels());
        for (i, (quantity, unit, description)) in positions.iter().enumerate() {
            self.channel(name, quantity, unit, description.to_string(), Source::Coordinate(address.q + i));
        }
        for (i, ((quantity, unit, description), _)) in rates.iter().enumerate() {
            self.channel(name, quantity, unit, description.to_string(), Source::Velocity(address.v + i));
        }
        for (i, (_, (quantity, unit, description))) in rates.iter().enumerate() {
            self.channel(name, quantity, unit, description.to_string(), Source::Acceleration(address.v + i));
        }
        for (i, (quantity, unit, description)) in self.model.bodies[k].kind.derived_channels().iter().enumerate() {
            self.channel(name, quantity, unit, description.to_string(), Source::Derived(k, i as u8));
        }
    }
}
