//! Spatial revolute joint with radial and axial clearance: a journal with two
//! flanges in a bore of finite length, touching the bore along any part of its
//! length and striking the bearing's end faces with its flanges
//! (`docs/theory/spatial-clearance-revolute.md`; geometry in
//! [`super::spatial_clearance_geometry`]).
//!
//! **Radial contact, by slices.** The bore is cut into sections along its
//! axis; the section at `s` penetrates the journal's cylinder by `delta(s)`
//! and carries the load per unit length `f(delta) = F(delta) / L`, where `F` is
//! the joint's stiffness law for the whole bearing length `L` (the slicing
//! technique of roller-bearing analysis, ISO/TS 16281). With aligned axes every
//! section penetrates alike and the joint's force is `F(delta)`, the planar
//! joint's law; a tilted journal bears on a part of the length next to a rim,
//! which shrinks to the rim's point as the tilt grows, so point and line
//! contact join continuously. Each half of the bore (`s` in `[-L/2, 0]`, rim
//! A, and `[0, L/2]`, rim B) is one contact candidate with its own onset
//! memory; its penetrated part is integrated by Gauss-Legendre after the
//! substitution `s = s0 + (s1 - s0) u^2` from the end where the penetration
//! vanishes, which makes `delta^n` smooth there.
//!
//! **Axial contact, by area.** A flange's inner face and the bearing's end
//! face overlap on the annulus `R_b <= r <= r_o`; each point of it penetrates
//! by `delta` (linear over the annulus when the axes are tilted) and carries
//! the pressure `k_a delta / A`, `A` the annulus' area and `k_a` the axial
//! stiffness: with aligned axes the flange's force is `k_a delta` through the
//! axis, with a tilt the load moves to the deep side.
//!
//! Every slice and area point carries its normal force from the joint's
//! normal force law (its own penetration rate, the candidate's latched onset
//! velocity) and a friction force against its own sliding velocity (spin
//! included).

use super::spatial_clearance_geometry::{ContactPoint, JointGeometry, JointPose};
use super::spatial_clearance_modes::ModeThresholds;
use crate::contact::{ContactStiffness, NormalForceLaw};
use crate::friction::FrictionLaw;
use crate::kinematics::marker::SpatialMarker;
use crate::kinematics::spatial::Vec3;
use crate::kinematics::wrench::Wrench;

/// Gauss-Legendre nodes on [0, 1] (4 points) [-].
const GAUSS_NODES: [f64; 4] = [0.069_431_844_202_973_71, 0.330_009_478_207_571_87, 0.669_990_521_792_428_1, 0.930_568_155_797_026_3];
/// Gauss-Legendre weights on [0, 1] (4 points) [-].
const GAUSS_WEIGHTS: [f64; 4] = [0.173_927_422_568_726_93, 0.326_072_577_431_273_07, 0.326_072_577_431_273_07, 0.173_927_422_568_726_93];
/// Angular samples of a flange's annulus (the trapezoidal rule, exact for the
/// uniform and the linear parts of an aligned or fully touching ring).
const RING_ANGLES: usize = 24;
/// Largest number of regula falsi steps locating where a half's penetration vanishes.
const ROOT_ITERATIONS: usize = 40;
/// Tolerance of that location, as a fraction of the bearing length [-].
const ROOT_TOLERANCE: f64 = 1e-12;

/// Index of each contact candidate: the bore's halves at rims A (`s < 0`) and
/// B (`s > 0`), then the flanges at `-z` (A) and `+z` (B).
pub const CANDIDATES: usize = 4;

/// A spatial revolute joint with radial and axial clearance.
#[derive(Clone, Debug)]
pub struct SpatialClearanceRevolute {
    /// Bearing marker: origin at the bore's centre, z along the bore axis.
    pub bearing: SpatialMarker,
    /// Journal marker: origin midway between the flanges, z along the journal axis.
    pub journal: SpatialMarker,
    /// Dimensions.
    pub geometry: JointGeometry,
    /// Radial stiffness law of the whole bearing length (applied per unit length).
    pub radial_stiffness: ContactStiffness,
    /// Axial stiffness of a whole flange ring [N/m] (applied per unit area).
    pub axial_stiffness: f64,
    /// Dissipation of the normal forces.
    pub normal_force_law: NormalForceLaw,
    /// Friction of every candidate.
    pub friction: FrictionLaw,
    /// Smallest onset velocity used in the damping term [m/s].
    pub onset_velocity_floor: f64,
    /// Penetration at which the simulation stops [m].
    pub max_penetration: f64,
    /// Where the motion modes part.
    pub modes: ModeThresholds,
}

/// One candidate's evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CandidateEvaluation {
    /// Deepest penetration (negative: the gap) [m].
    pub penetration: f64,
    /// Total normal force [N].
    pub normal_force: f64,
    /// Magnitude of the total friction force [N].
    pub friction_force: f64,
    /// Sliding speed at the deepest point [m/s].
    pub sliding_speed: f64,
    /// Elastic energy stored [J].
    pub elastic_energy: f64,
}

/// A load accumulated on the journal and the bearing.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct JointLoad {
    /// Force [N] and moment about the journal marker's origin [N m] on the journal (global).
    pub on_journal: Wrench,
    /// Moment of the opposite forces about the bearing marker's origin [N m] (global).
    pub bearing_moment: Vec3,
}

/// The relative motion and the laws a contact point is evaluated with.
struct PointLoad<'a> {
    joint: &'a SpatialClearanceRevolute,
    pose: &'a JointPose,
    onset_velocity: f64,
}

impl JointLoad {
    /// Adds the force `force` [N] on the journal at `journal_point`, its opposite on the bearing at `bearing_point`.
    fn add(&mut self, pose: &JointPose, force: Vec3, contact: &ContactPoint) {
        self.on_journal.force += force;
        self.on_journal.moment += (contact.journal_point - pose.journal.position).cross(&force);
        self.bearing_moment -= (contact.bearing_point - pose.bearing.position).cross(&force);
    }
}

impl PointLoad<'_> {
    /// Adds the normal and friction forces of `contact` carrying the elastic force
    /// `elastic` [N] to `load`; returns (normal, friction vector on the journal).
    fn apply(&self, contact: &ContactPoint, elastic: f64, load: &mut JointLoad) -> (f64, Vec3) {
        let motion = self.pose.relative_motion(contact);
        let normal = self.joint.normal_force_law.normal_force(elastic, motion.approach_rate, self.onset_velocity);
        let speed = motion.tangential_velocity.norm();
        let friction = if speed > 0.0 { motion.tangential_velocity * (self.joint.friction.friction_force(normal, speed) / speed) } else { Vec3::zeros() };
        load.add(self.pose, friction - contact.normal * normal, contact);
        (normal, friction)
    }
}

impl SpatialClearanceRevolute {
    /// The axial coordinates `(rim, inner)` of radial candidate `half` (0: A, 1: B) [m].
    #[inline]
    fn half_ends(&self, half: usize) -> (f64, f64) {
        let rim = 0.5 * self.geometry.dimensions().bearing_length;
        (if half == 0 { -rim } else { rim }, 0.0)
    }

    /// The deepest contact of radial candidate `half`: at its rim or at the bore's middle (the
    /// penetration of a section is convex in `s`).
    pub fn radial_deepest(&self, pose: &JointPose, half: usize) -> ContactPoint {
        let (rim, inner) = self.half_ends(half);
        let (at_rim, at_inner) = (self.geometry.section_contact(pose, rim).contact, self.geometry.section_contact(pose, inner).contact);
        if at_rim.penetration >= at_inner.penetration { at_rim } else { at_inner }
    }

    /// The deepest contact of flange candidate `side` (0: A at `-z`, 1: B at `+z`).
    #[inline]
    pub fn flange_deepest(&self, pose: &JointPose, side: usize) -> ContactPoint {
        self.geometry.flange_contact(pose, side_sign(side)).contact
    }

    /// The deepest contact of candidate `k` ([`CANDIDATES`]).
    #[inline]
    pub fn deepest(&self, pose: &JointPose, k: usize) -> ContactPoint {
        if k < 2 { self.radial_deepest(pose, k) } else { self.flange_deepest(pose, k - 2) }
    }

    /// Velocity to latch at the onset of candidate `k`: its approach rate at the deepest point, floored [m/s].
    pub fn onset_velocity(&self, pose: &JointPose, k: usize) -> f64 {
        pose.relative_motion(&self.deepest(pose, k)).approach_rate.max(self.onset_velocity_floor)
    }

    /// Evaluates radial candidate `half` with the onset velocity `onset` [m/s]
    /// (`None`: the current approach rate), adding its forces to `load`.
    pub fn radial(&self, pose: &JointPose, half: usize, onset: Option<f64>, load: &mut JointLoad) -> CandidateEvaluation {
        let deepest = self.radial_deepest(pose, half);
        let mut out = CandidateEvaluation { penetration: deepest.penetration, ..Default::default() };
        if deepest.penetration <= 0.0 {
            return out;
        }
        let motion = pose.relative_motion(&deepest);
        out.sliding_speed = motion.tangential_velocity.norm();
        let onset_velocity = onset.unwrap_or(motion.approach_rate).max(self.onset_velocity_floor);
        let point = PointLoad { joint: self, pose, onset_velocity };
        let Some((anchor, far)) = self.penetrated_part(pose, half) else { return out };
        let length = self.geometry.dimensions().bearing_length;
        let mut friction = Vec3::zeros();
        for (u, w) in GAUSS_NODES.iter().zip(GAUSS_WEIGHTS) {
            let s = anchor + (far - anchor) * u * u;
            let weight = 2.0 * (far - anchor).abs() * u * w;
            let contact = self.geometry.section_contact(pose, s).contact;
            if contact.penetration <= 0.0 {
                continue;
            }
            let per_length = weight / length;
            let (normal, slice_friction) = point.apply(&contact, self.radial_stiffness.elastic_force(contact.penetration) * per_length, load);
            out.normal_force += normal;
            out.elastic_energy += self.radial_stiffness.elastic_energy(contact.penetration) * per_length;
            friction += slice_friction;
        }
        out.friction_force = friction.norm();
        out
    }

    /// The penetrated part of radial candidate `half` as `(anchor, far)`: from the
    /// end where the penetration vanishes (or the inner end when the whole half
    /// touches) to the other [m]; `None` when no part touches.
    fn penetrated_part(&self, pose: &JointPose, half: usize) -> Option<(f64, f64)> {
        let (rim, inner) = self.half_ends(half);
        let depth = |s: f64| self.geometry.section_penetration(pose, s);
        let (at_rim, at_inner) = (depth(rim), depth(inner));
        match (at_rim > 0.0, at_inner > 0.0) {
            (true, true) => Some((inner, rim)),
            (false, false) => None,
            (true, false) => Some((self.where_vanishing(&depth, (inner, at_inner), (rim, at_rim)), rim)),
            (false, true) => Some((self.where_vanishing(&depth, (rim, at_rim), (inner, at_inner)), inner)),
        }
    }

    /// Where `depth` crosses zero between `(a, depth(a))` (not touching) and
    /// `(b, depth(b))` (touching), by regula falsi (Illinois) to
    /// [`ROOT_TOLERANCE`] of the bearing length [m].
    fn where_vanishing(&self, depth: &impl Fn(f64) -> f64, (mut a, mut fa): (f64, f64), (mut b, mut fb): (f64, f64)) -> f64 {
        let tolerance = ROOT_TOLERANCE * self.geometry.dimensions().bearing_length;
        let mut side = 0i8;
        let mut s = b;
        for _ in 0..ROOT_ITERATIONS {
            s = (a * fb - b * fa) / (fb - fa);
            let f = depth(s);
            if f == 0.0 {
                return s;
            }
            if f > 0.0 {
                (b, fb) = (s, f);
                if side == 1 {
                    fa *= 0.5;
                }
                side = 1;
            } else {
                (a, fa) = (s, f);
                if side == -1 {
                    fb *= 0.5;
                }
                side = -1;
            }
            if (b - a).abs() <= tolerance {
                break;
            }
        }
        s
    }

    /// Evaluates flange candidate `side` with the onset velocity `onset` [m/s]
    /// (`None`: the current approach rate), adding its forces to `load`.
    pub fn flange(&self, pose: &JointPose, side: usize, onset: Option<f64>, load: &mut JointLoad) -> CandidateEvaluation {
        let deepest = self.flange_deepest(pose, side);
        let mut out = CandidateEvaluation { penetration: deepest.penetration, ..Default::default() };
        if deepest.penetration <= 0.0 {
            return out;
        }
        let motion = pose.relative_motion(&deepest);
        out.sliding_speed = motion.tangential_velocity.norm();
        let onset_velocity = onset.unwrap_or(motion.approach_rate).max(self.onset_velocity_floor);
        let point = PointLoad { joint: self, pose, onset_velocity };
        let ring = FlangeRing::new(self, pose, side_sign(side));
        let pressure_per_depth = self.axial_stiffness / ring.area();
        let mut friction = Vec3::zeros();
        for (r, radial_weight) in ring.radii() {
            for j in 0..RING_ANGLES {
                let contact = ring.contact(r, std::f64::consts::TAU * j as f64 / RING_ANGLES as f64);
                if contact.penetration <= 0.0 {
                    continue;
                }
                let area = radial_weight * r * std::f64::consts::TAU / RING_ANGLES as f64;
                let (normal, point_friction) = point.apply(&contact, pressure_per_depth * contact.penetration * area, load);
                out.normal_force += normal;
                out.elastic_energy += 0.5 * pressure_per_depth * contact.penetration * contact.penetration * area;
                friction += point_friction;
            }
        }
        out.friction_force = friction.norm();
        out
    }
}

/// `-1` for candidate side 0 (A), `+1` for side 1 (B).
#[inline]
fn side_sign(side: usize) -> f64 {
    if side == 0 { -1.0 } else { 1.0 }
}

/// The overlap annulus of a flange and its bearing face, on the body whose
/// edge is the outer one (as [`JointGeometry::flange_contact`] takes it).
struct FlangeRing<'a> {
    pose: &'a JointPose,
    /// Centre of the annulus (global) [m].
    centre: Vec3,
    /// In-plane axes of the annulus' body (global) [-].
    axes: (Vec3, Vec3),
    /// Radii of the annulus [m].
    inner: f64,
    outer: f64,
    /// Whether the annulus lies on the journal's flange (else on the bearing's face).
    on_flange: bool,
    /// Flange side, -1 or +1.
    side: f64,
    /// Distance of the flange's inner face from the journal origin, and of the face from the bearing origin [m].
    flange_offset: f64,
    face_offset: f64,
}

impl<'a> FlangeRing<'a> {
    fn new(joint: &SpatialClearanceRevolute, pose: &'a JointPose, side: f64) -> Self {
        let d = joint.geometry.dimensions();
        let on_flange = d.flange_radius <= d.face_radius;
        let (flange_offset, face_offset) = (joint.geometry.flange_offset(), 0.5 * d.bearing_length);
        let (frame, offset) = if on_flange { (&pose.journal, flange_offset) } else { (&pose.bearing, face_offset) };
        FlangeRing {
            pose,
            centre: frame.position + frame.axis(2) * (side * offset),
            axes: (frame.axis(0), frame.axis(1)),
            inner: d.bore_radius,
            outer: joint.geometry.overlap_radius(),
            on_flange,
            side,
            flange_offset,
            face_offset,
        }
    }

    /// Area of the annulus [m^2].
    fn area(&self) -> f64 {
        std::f64::consts::PI * (self.outer * self.outer - self.inner * self.inner)
    }

    /// Gauss-Legendre radii over the annulus and their weights [m].
    fn radii(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        let width = self.outer - self.inner;
        GAUSS_NODES.iter().zip(GAUSS_WEIGHTS).map(move |(u, w)| (self.inner + width * u, width * w))
    }

    /// The contact at the annulus point of radius `r` [m] and angle `angle` [rad].
    fn contact(&self, r: f64, angle: f64) -> ContactPoint {
        let x = self.centre + (self.axes.0 * angle.cos() + self.axes.1 * angle.sin()) * r;
        let (b, j, side) = (&self.pose.bearing, &self.pose.journal, self.side);
        if self.on_flange {
            // the flange's point against the face plane
            let normal = -side * b.axis(2);
            let penetration = self.face_offset - side * (x - b.position).dot(&b.axis(2));
            ContactPoint { penetration, bearing_point: x - normal * penetration, journal_point: x, normal }
        } else {
            // the face's point against the flange plane
            let normal = -side * j.axis(2);
            let penetration = side * (x - j.position).dot(&j.axis(2)) - self.flange_offset;
            ContactPoint { penetration, bearing_point: x, journal_point: x + normal * penetration, normal }
        }
    }
}

#[cfg(test)]
#[path = "spatial_clearance_revolute_tests.rs"]
mod tests;
