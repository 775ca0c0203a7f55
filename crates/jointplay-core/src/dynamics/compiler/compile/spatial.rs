//! Compiling the spatial parts of a description: spatial rigid bodies, the
//! marker frames of every point, joints between marker frames built from the
//! spatial primitives, their drivers and the force elements in space.

use super::hydraulic::build_cylinder;
use super::laws::build_function;
use super::{Compiler, SpatialJointEntry};
use crate::body::{BodyKind, BodyModel, SpatialRigidBody};
use crate::dynamics::model::mechanism::{Body, VelocityStart};
use crate::element::ElementKind;
use crate::joint::IdealKind;
use crate::force::{Bushing, LoadFrame, LoadKind, PrescribedLoad, SpatialSpringDamper};
use crate::joint::{AxisDistance, AxisRotation, ConstraintKind, PerpendicularAxes, SpatialPointCoincidence, Target};
use crate::kinematics::marker::{BodyIndex, Marker, Site, SpatialMarker};
use crate::kinematics::euler::EulerSequence;
use crate::kinematics::quaternion;
use crate::kinematics::spatial::{Mat3, Vec3};
use crate::spec::{ranges, Range, SpringDamperSpec, LoadFrameSpec, SpatialBodySpec, SpatialForceSpec, SpatialJointKind, SpatialJointSpec};

/// Tolerance on a marker's axes being a rotation: `|A^T A - I|` and `|det A - 1|` [-].
const AXES_TOLERANCE: f64 = 1e-6;

/// The axes a point description gives, checked to be a rotation (identity when none).
pub(super) fn marker_axes(axes: Option<[[f64; 3]; 3]>, location: &str, errors: &mut crate::error::ModelErrors) -> Mat3 {
    let Some(rows) = axes else { return Mat3::identity() };
    let a = Mat3::from_fn(|i, j| rows[i][j]);
    let orthogonality = (a.transpose() * a - Mat3::identity()).amax();
    if !(orthogonality < AXES_TOLERANCE && (a.determinant() - 1.0).abs() < AXES_TOLERANCE) {
        errors.push(format!("{location}.axes"), format!("must be a rotation matrix (orthonormal, determinant +1), got {rows:?}"));
        return Mat3::identity();
    }
    a
}

impl<'s> Compiler<'s> {
    /// The spatial rigid bodies, after the planar, beam and modal ones.
    pub(super) fn spatial_bodies(&mut self) {
        for (k, b) in self.spec.spatial_bodies.iter().flatten().enumerate() {
            self.spatial_body(&format!("spatial_bodies[{k}]"), b);
        }
    }

    fn spatial_body(&mut self, loc: &str, b: &'s SpatialBodySpec) {
        self.claim_name(&b.name, &format!("{loc}.name"));
        ranges::SPATIAL_BODIES_MASS.check_at(b.mass, loc, &mut self.errors);
        let inertia = Mat3::from_fn(|i, j| b.inertia[i][j]);
        let mut body = match SpatialRigidBody::new(b.mass, inertia) {
            Ok(body) => body,
            Err(message) => {
                self.errors.push(format!("{loc}.inertia"), message);
                return;
            }
        };
        match EulerSequence::parse(&b.euler_sequence) {
            Some(sequence) => body.euler_sequence = sequence,
            None => self.errors.push(format!("{loc}.euler_sequence"), format!("must be three of the axes X, Y, Z, each different from the next (\"ZXZ\"), got {:?}", b.euler_sequence)),
        }
        let mut orientation = b.orientation;
        let norm = orientation.iter().map(|c| c * c).sum::<f64>().sqrt();
        if !(norm.is_finite() && norm > 0.0) {
            self.errors.push(format!("{loc}.orientation"), format!("must be a non-zero quaternion, got {orientation:?}"));
            return;
        }
        quaternion::normalise(&mut orientation);
        let index = BodyIndex(self.model.bodies.len() + 1);
        self.body_index.insert(&b.name, index);
        let kind = BodyKind::SpatialRigid(body);
        self.model.layout.push_body(&kind);
        self.model.initial_coordinates.extend(b.position.iter().chain(&orientation));
        // (the description's angular velocity is global; the coordinates' are in the body frame)
        let omega = quaternion::rotation_matrix(&orientation).transpose() * Vec3::from(b.angular_velocity);
        self.model.initial_velocities.extend(b.velocity.iter().chain(omega.as_slice()));
        self.model.bodies.push(Body { name: b.name.clone(), kind, velocity_start: VelocityStart::Approximate });
        for (i, p) in b.points.iter().enumerate() {
            let location = format!("{loc}.points[{i}]");
            let axes = marker_axes(p.axes, &location, &mut self.errors);
            self.add_spatial_point(index, &b.name, &p.name, p.position, axes, location);
        }
        self.body_channels(index.0 - 1, &b.name);
    }

    /// Names a point of a body's reference frame at `position` [m] with `axes`.
    pub(super) fn add_spatial_point(&mut self, body: BodyIndex, body_name: &str, name: &str, position: [f64; 3], axes: Mat3, location: String) {
        if position.iter().any(|v| !v.is_finite()) {
            self.errors.push(format!("{location}.position"), format!("must be finite, got {position:?}"));
        }
        let local = Vec3::from(position);
        let marker = SpatialMarker { body, frame: body.0, site: Site::Reference, local, axes };
        self.spatial_points.insert(format!("{body_name}.{name}"), marker);
        self.name_point(body_name, name, marker.planar(), location);
    }

    /// The marker named `reference`, with a located error when there is none.
    pub(super) fn spatial_point(&mut self, reference: &str, location: String) -> Option<SpatialMarker> {
        let found = self.spatial_points.get(reference).copied();
        if found.is_none() {
            // (the planar lookup words the error)
            self.point(reference, location);
        }
        found
    }

    /// A body's reference marker.
    fn spatial_body_marker(&mut self, name: &str, location: String) -> Option<SpatialMarker> {
        let body = self.body(name, location)?;
        Some(SpatialMarker { body, frame: body.0, site: Site::Reference, local: Vec3::zeros(), axes: Mat3::identity() })
    }

    /// The joints between marker frames.
    pub(super) fn spatial_joints(&mut self) {
        for (k, j) in self.spec.spatial_joints.iter().flatten().enumerate() {
            self.spatial_joint(&format!("spatial_joints[{k}]"), j);
        }
    }

    fn spatial_joint(&mut self, loc: &str, j: &'s SpatialJointSpec) {
        self.claim_name(&j.name, &format!("{loc}.name"));
        let a = self.spatial_point(&j.first, format!("{loc}.first"));
        let b = self.spatial_point(&j.second, format!("{loc}.second"));
        let (Some(a), Some(b)) = (a, b) else { return };
        if !self.distinct_bodies(loc, a.planar(), b.planar()) {
            return;
        }
        let kinds = joint_equations(j.kind, a, b);
        let element = self.add_element(&j.name, IdealKind::SpatialJoint(j.kind), a.planar(), b.planar(), Default::default(), kinds);
        self.ideal_mut(element).spatial_markers = Some(Box::new([a, b]));
        self.spatial_joint_index.insert(&j.name, SpatialJointEntry { kind: j.kind, markers: [a, b] });
    }

    /// A driver of the spatial joint `entry`: the rotation about its axis
    /// (revolute, cylindrical) or the displacement along it (translational,
    /// cylindrical through `displacement`).
    pub(super) fn spatial_driver(&mut self, loc: &str, name: &str, joint: &str, entry: SpatialJointEntry, function: crate::motion::TimeFunction) {
        let [a, b] = entry.markers;
        let (kind, constraint) = match entry.kind {
            SpatialJointKind::Revolute | SpatialJointKind::Cylindrical => {
                (IdealKind::SpatialAngleDriver, ConstraintKind::AxisRotation(Box::new(AxisRotation { first: a, second: b, target: Target::Driven(function) })))
            }
            SpatialJointKind::Translational => (
                IdealKind::SpatialDisplacementDriver,
                ConstraintKind::AxisDistance(Box::new(AxisDistance { first: a, second: b, axis: 2, target: Target::Driven(function) })),
            ),
            other => {
                self.errors.push(format!("{loc}.joint"), format!("joint {joint:?} is a {} joint and cannot be driven (revolute, cylindrical and translational joints can)", other.name()));
                return;
            }
        };
        let element = self.add_element(name, kind, a.planar(), b.planar(), Default::default(), vec![constraint]);
        self.ideal_mut(element).spatial_markers = Some(Box::new([a, b]));
    }

    /// The force elements in space.
    pub(super) fn spatial_forces(&mut self) {
        for (k, f) in self.spec.spatial_forces.iter().flatten().enumerate() {
            let loc = format!("spatial_forces[{k}]");
            if let Some((name, element, states)) = self.spatial_force(&loc, f) {
                self.push_element(name, element, states);
            }
        }
    }

    fn spatial_force(&mut self, loc: &str, f: &'s SpatialForceSpec) -> Option<(&'s str, ElementKind, Vec<f64>)> {
        match f {
            SpatialForceSpec::SpringDamper(SpringDamperSpec { name, first, second, stiffness, damping, free_length }) => {
                self.claim_name(name, &format!("{loc}.name"));
                let (a, b) = (self.spatial_point(first, format!("{loc}.first")), self.spatial_point(second, format!("{loc}.second")));
                let checks = [
                    (ranges::SPATIAL_FORCES_SPRING_DAMPER_STIFFNESS, *stiffness),
                    (ranges::SPATIAL_FORCES_SPRING_DAMPER_DAMPING, *damping),
                    (ranges::SPATIAL_FORCES_SPRING_DAMPER_FREE_LENGTH, *free_length),
                ];
                Range::check_all(&checks, loc, &mut self.errors);
                let element = SpatialSpringDamper { first: a?, second: b?, stiffness: *stiffness, damping: *damping, free_length: *free_length };
                Some((name, ElementKind::SpatialSpringDamper(Box::new(element)), Vec::new()))
            }
            SpatialForceSpec::Bushing { name, first, second, stiffness, damping, rotational_stiffness, rotational_damping } => {
                self.claim_name(name, &format!("{loc}.name"));
                let (a, b) = (self.spatial_point(first, format!("{loc}.first")), self.spatial_point(second, format!("{loc}.second")));
                let ranges = [
                    (ranges::SPATIAL_FORCES_BUSHING_STIFFNESS, stiffness),
                    (ranges::SPATIAL_FORCES_BUSHING_DAMPING, damping),
                    (ranges::SPATIAL_FORCES_BUSHING_ROTATIONAL_STIFFNESS, rotational_stiffness),
                    (ranges::SPATIAL_FORCES_BUSHING_ROTATIONAL_DAMPING, rotational_damping),
                ];
                for (range, values) in ranges {
                    // (each component within the key's range)
                    values.iter().all(|v| range.check_at(*v, loc, &mut self.errors));
                }
                let element = Bushing {
                    first: a?,
                    second: b?,
                    stiffness: Vec3::from(*stiffness),
                    damping: Vec3::from(*damping),
                    rotational_stiffness: Vec3::from(*rotational_stiffness),
                    rotational_damping: Vec3::from(*rotational_damping),
                };
                Some((name, ElementKind::Bushing(Box::new(element)), Vec::new()))
            }
            SpatialForceSpec::PointForce { name, point, force, frame } => {
                self.claim_name(name, &format!("{loc}.name"));
                let marker = self.spatial_point(point, format!("{loc}.point"));
                let components = self.functions(force, &format!("{loc}.force"));
                Some((name, ElementKind::PrescribedLoad(Box::new(PrescribedLoad { marker: marker?, kind: LoadKind::Force, frame: load_frame(*frame), components: components? })), Vec::new()))
            }
            SpatialForceSpec::Torque { name, body, torque, frame } => {
                self.claim_name(name, &format!("{loc}.name"));
                let marker = self.spatial_body_marker(body, format!("{loc}.body"));
                let components = self.functions(torque, &format!("{loc}.torque"));
                Some((name, ElementKind::PrescribedLoad(Box::new(PrescribedLoad { marker: marker?, kind: LoadKind::Torque, frame: load_frame(*frame), components: components? })), Vec::new()))
            }
            SpatialForceSpec::HydraulicCylinder(c) => {
                self.claim_name(&c.name, &format!("{loc}.name"));
                let (a, b) = (self.spatial_point(&c.first, format!("{loc}.first")), self.spatial_point(&c.second, format!("{loc}.second")));
                let (a, b) = (a?, b?);
                let length = (self.initial_spatial_point(b) - self.initial_spatial_point(a)).norm();
                let (mut element, states) = build_cylinder(c, (a.planar(), b.planar()), length, loc, &mut self.errors)?;
                element.spatial_attachments = Some(Box::new([a, b]));
                Some((&c.name, ElementKind::HydraulicCylinder(element), states))
            }
        }
    }

    /// Three functions of time, each located.
    fn functions(&mut self, specs: &[crate::spec::FunctionSpec; 3], loc: &str) -> Option<[crate::motion::TimeFunction; 3]> {
        let [x, y, z] = [0, 1, 2].map(|k| build_function(&specs[k], &format!("{loc}[{k}]"), &mut self.errors));
        Some([x?, y?, z?])
    }

    /// Global position [m] of a marker at the positions of the description.
    fn initial_spatial_point(&self, marker: SpatialMarker) -> Vec3 {
        let Some(address) = self.model.layout.body(marker.body) else { return marker.local };
        let (q, v) = (&self.model.initial_coordinates[address.q_range()], &self.model.initial_velocities[address.v_range()]);
        let kind = &self.model.bodies[marker.body.0 - 1].kind;
        let planar = kind.site_frame(&marker.site, q, v, &crate::kinematics::planar::Frame::GROUND);
        kind.spatial_site_frame(&marker.site, q, v, &planar).point(marker.local)
    }
}

/// The primitives of a joint between the marker frames `a` and `b`.
pub(super) fn joint_equations(kind: SpatialJointKind, a: SpatialMarker, b: SpatialMarker) -> Vec<ConstraintKind> {
    let point = || ConstraintKind::SpatialPointCoincidence(Box::new(SpatialPointCoincidence { first: a, second: b }));
    let perpendicular = |first_axis, second_axis| ConstraintKind::PerpendicularAxes(Box::new(PerpendicularAxes { first: a, second: b, first_axis, second_axis }));
    let on_axis = |axis| ConstraintKind::AxisDistance(Box::new(AxisDistance { first: a, second: b, axis, target: Target::Fixed(0.0) }));
    // (z_a stays normal to x_b and y_b: the z axes stay aligned; x_a normal to y_b: no turning about them)
    match kind {
        SpatialJointKind::Spherical => vec![point()],
        SpatialJointKind::Revolute => vec![point(), perpendicular(2, 0), perpendicular(2, 1)],
        SpatialJointKind::Universal => vec![point(), perpendicular(0, 1)],
        SpatialJointKind::Cylindrical => vec![perpendicular(2, 0), perpendicular(2, 1), on_axis(0), on_axis(1)],
        SpatialJointKind::Translational => vec![perpendicular(2, 0), perpendicular(2, 1), perpendicular(0, 1), on_axis(0), on_axis(1)],
        SpatialJointKind::Fixed => vec![point(), perpendicular(2, 0), perpendicular(2, 1), perpendicular(0, 1)],
    }
}

/// The load frame a description names.
fn load_frame(frame: LoadFrameSpec) -> LoadFrame {
    match frame {
        LoadFrameSpec::Global => LoadFrame::Global,
        LoadFrameSpec::Body => LoadFrame::Body,
    }
}

impl SpatialJointKind {
    /// The kind's name in descriptions.
    pub fn name(self) -> &'static str {
        match self {
            Self::Revolute => "revolute",
            Self::Spherical => "spherical",
            Self::Cylindrical => "cylindrical",
            Self::Translational => "translational",
            Self::Universal => "universal",
            Self::Fixed => "fixed",
        }
    }
}

/// Marker of a planar point: its planar marker with height `z` and axes.
pub(super) fn embedded_marker(marker: Marker, z: f64, axes: Mat3) -> SpatialMarker {
    SpatialMarker { body: marker.body, frame: marker.frame, site: marker.site, local: Vec3::new(marker.local.x, marker.local.y, z), axes }
}
