use super::*;
use crate::contact::{HertzCylinder, Material, PowerLawStiffness};
use crate::friction::StictionFriction;
use crate::joint::{JointDimensions, ModeThresholds};
use crate::kinematics::marker::{BodyIndex, Site};
use crate::kinematics::spatial::{Mat3, SpatialFrame};
use nalgebra::{Rotation3, Unit};

const STEEL: Material = Material { youngs_modulus: 207e9, poisson_ratio: 0.3 };

/// A 10 mm bore, 0.5 mm radial clearance, 20 mm long, 0.4 mm axial clearance.
fn dimensions() -> JointDimensions {
    JointDimensions { bore_radius: 0.010, journal_radius: 0.0095, bearing_length: 0.020, axial_clearance: 0.0004, flange_radius: 0.015, face_radius: 0.016 }
}

fn marker(body: usize) -> SpatialMarker {
    SpatialMarker { body: BodyIndex(body), frame: body, site: Site::Reference, local: Vec3::zeros(), axes: Mat3::identity() }
}

fn joint(friction: FrictionLaw, restitution: f64) -> SpatialClearanceRevolute {
    let d = dimensions();
    SpatialClearanceRevolute {
        bearing: marker(0),
        journal: marker(1),
        geometry: JointGeometry::new(d).unwrap(),
        radial_stiffness: ContactStiffness::HertzCylinder(HertzCylinder::new(d.bore_radius, d.journal_radius, STEEL, STEEL, 1.5).unwrap()),
        axial_stiffness: 2e9,
        normal_force_law: NormalForceLaw::LankaraniNikravesh { restitution },
        friction,
        onset_velocity_floor: 1e-4,
        max_penetration: 2.5e-4,
        modes: ModeThresholds { impact_speed: 1e-3, impact_duration: 1e-3, sliding_speed: 5e-5 },
        lubrication: None,
    }
}

fn stiction() -> FrictionLaw {
    FrictionLaw::Stiction(StictionFriction::new(0.15, 0.1, 1e-5, 5e-5).unwrap())
}

fn rotation(axis: Vec3, angle: f64) -> Mat3 {
    *Rotation3::from_axis_angle(&Unit::new_normalize(axis), angle).matrix()
}

/// The journal frame at `position` turned by `tilt` about x, moving at `velocity` and `angular_velocity`.
fn journal_frame(position: Vec3, tilt: f64, velocity: Vec3, angular_velocity: Vec3) -> SpatialFrame {
    SpatialFrame { position, rotation: rotation(Vec3::x(), tilt), velocity, angular_velocity }
}

/// Deterministic pseudo-random numbers in [-scale, scale) (Knuth's MMIX constants).
struct Lcg(u64);

impl Lcg {
    fn symmetric(&mut self, scale: f64) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        scale * (2.0 * ((self.0 >> 11) as f64 / (1u64 << 53) as f64) - 1.0)
    }
}

#[test]
fn every_candidate_gives_finite_forces_near_the_wall_whatever_the_tilt_and_motion() {
    let joint = joint(stiction(), 0.5);
    let mut random = Lcg(7);
    for k in 0..20_000 {
        let scale = [1e-13, 1e-6, 1e-4, 1e-3][k % 4];
        let position = Vec3::new(random.symmetric(scale), -4.9e-4 + random.symmetric([2e-5, 1e-3][k % 2]), random.symmetric([3e-4, 1e-3][k % 2]));
        let tilt = random.symmetric([3e-3, 0.2][k % 2]);
        let velocity = Vec3::new(random.symmetric(1e-3), random.symmetric(1e-2), random.symmetric(1e-3));
        let spin = Vec3::new(random.symmetric(1.0), random.symmetric(1e-3), random.symmetric(1e-3));
        let pose = JointPose::new(&SpatialFrame::GROUND, &journal_frame(position, tilt, velocity, spin));
        let mut load = JointLoad::default();
        for half in 0..2 {
            let c = joint.radial(&pose, half, [None, Some(1e-4)][k % 2], &mut load);
            assert!(c.normal_force.is_finite() && c.friction_force.is_finite(), "{k}: half {half} at {position:?}, tilt {tilt}: {c:?}");
            let f = joint.flange(&pose, half, [None, Some(1e-4)][k % 2], &mut load);
            assert!(f.normal_force.is_finite() && f.friction_force.is_finite(), "{k}: flange {half} at {position:?}, tilt {tilt}: {f:?}");
        }
        assert!(load.on_journal.force.iter().all(|f| f.is_finite()), "{k}: {load:?}");
    }
}

/// Elastic energy [J] and load of every candidate at `journal` (at rest, no dissipation, no friction).
fn elastic_state(joint: &SpatialClearanceRevolute, journal: &SpatialFrame) -> (f64, JointLoad) {
    let pose = JointPose::new(&SpatialFrame::GROUND, journal);
    let mut load = JointLoad::default();
    let mut energy = 0.0;
    for k in 0..2 {
        energy += joint.radial(&pose, k, Some(1.0), &mut load).elastic_energy;
        energy += joint.flange(&pose, k, Some(1.0), &mut load).elastic_energy;
    }
    (energy, load)
}

#[test]
fn the_contact_forces_are_the_gradient_of_the_elastic_energy() {
    // at rest (no damping) and without friction the joint's wrench on the journal is minus the gradient
    // of its stored energy in the journal's translations and small rotations (about its origin): checked
    // by central differences where a tilted journal bears near a rim, along its length and on a flange
    let mut joint = joint(FrictionLaw::None, 1.0);
    joint.normal_force_law = NormalForceLaw::Hertz;
    let still = Vec3::zeros();
    for (position, tilt) in [
        (Vec3::new(0.0, -5.02e-4, 0.0), 2e-3),  // rim contact, tilted
        (Vec3::new(1e-5, -5.05e-4, 0.0), 0.0),  // line contact, aligned
        (Vec3::new(0.0, -5.04e-4, 0.0), 2e-4),  // whole length, slightly tilted
        (Vec3::new(0.0, 0.0, -2.1e-4), 5e-3),   // flange contact, tilted
    ] {
        let at = |shift: Vec3, turn: Vec3| {
            let base = journal_frame(position, tilt, still, still);
            let rotation = if turn.norm() > 0.0 { rotation(turn, turn.norm()) } else { Mat3::identity() };
            SpatialFrame { position: base.position + shift, rotation: rotation * base.rotation, ..base }
        };
        let (energy, load) = elastic_state(&joint, &at(Vec3::zeros(), Vec3::zeros()));
        assert!(energy > 0.0, "the case at {position:?}, tilt {tilt} touches");
        let (h, g) = (1e-9, 1e-7);
        for axis in 0..3 {
            let e = Vec3::ith(axis, 1.0);
            let force = -(elastic_state(&joint, &at(e * h, Vec3::zeros())).0 - elastic_state(&joint, &at(-e * h, Vec3::zeros())).0) / (2.0 * h);
            let moment = -(elastic_state(&joint, &at(Vec3::zeros(), e * g)).0 - elastic_state(&joint, &at(Vec3::zeros(), -e * g)).0) / (2.0 * g);
            let scale = load.on_journal.force.norm();
            assert!((load.on_journal.force[axis] - force).abs() < 1e-3 * scale, "{position:?} tilt {tilt}: force {axis} {} against {force}", load.on_journal.force[axis]);
            // (a moment compared at the scale of the force times the 10 mm bore radius)
            assert!((load.on_journal.moment[axis] - moment).abs() < 1e-3 * scale * 0.01, "{position:?} tilt {tilt}: moment {axis} {} against {moment}", load.on_journal.moment[axis]);
        }
    }
}

/// The joint's static radial force [N] with the journal offset `depth` [m] beyond the clearance
/// along -y and tilted by `tilt` [rad] about x (at rest, elastic only).
fn static_force(joint: &SpatialClearanceRevolute, depth: f64, tilt: f64) -> f64 {
    let c = joint.geometry.radial_clearance();
    let pose = JointPose::new(&SpatialFrame::GROUND, &journal_frame(Vec3::new(0.0, -(c + depth), 0.0), tilt, Vec3::zeros(), Vec3::zeros()));
    let mut load = JointLoad::default();
    (0..2).map(|half| joint.radial(&pose, half, Some(1.0), &mut load).normal_force).sum()
}

/// The penetration [m] at which [`static_force`] carries `load` [N], by bisection.
fn static_penetration(joint: &SpatialClearanceRevolute, load: f64, tilt: f64) -> f64 {
    let (mut low, mut high) = (0.0, 1e-4);
    for _ in 0..200 {
        let mid = 0.5 * (low + high);
        if static_force(joint, mid, tilt) < load { low = mid } else { high = mid }
    }
    0.5 * (low + high)
}

#[test]
fn an_aligned_journal_under_a_load_sinks_by_johnsons_line_contact_penetration() {
    // Johnson's line contact (K. L. Johnson, Contact Mechanics, 1985, ch. 5; ESDU-78035) gives the
    // penetration of a cylinder of length L in a bore explicitly in the load W:
    // delta = W/(pi L E*) (ln(4 pi L E* dR / W) - 1). The aligned joint with the law applied per slice
    // (each slice W/L per unit length) sinks by that much under W; the Hertz-type point-contact law
    // (K delta^1.5 of the same radii) sinks further under the same load
    let mut joint = joint(FrictionLaw::None, 1.0);
    joint.normal_force_law = NormalForceLaw::Hertz;
    let d = dimensions();
    joint.radial_stiffness = ContactStiffness::JohnsonLine(crate::contact::JohnsonLine::new(d.bore_radius, d.journal_radius, d.bearing_length, STEEL, STEEL).unwrap());
    let modulus = 1.0 / (2.0 * (1.0 - 0.3 * 0.3) / 207e9);
    for load in [100.0, 1e3, 1e4] {
        let by_hand = load / (std::f64::consts::PI * d.bearing_length * modulus) * ((4.0 * std::f64::consts::PI * d.bearing_length * modulus * 5e-4 / load).ln() - 1.0);
        let sunk = static_penetration(&joint, load, 0.0);
        assert!((sunk / by_hand - 1.0).abs() < 1e-9, "{load} N: {sunk:e} m against Johnson's {by_hand:e} m");
        let point = (load / HertzCylinder::new(d.bore_radius, d.journal_radius, STEEL, STEEL, 1.5).unwrap().stiffness()).powf(1.0 / 1.5);
        assert!(point > sunk, "{load} N: the point law sinks {point:e} m, more than the line law's {sunk:e} m");
    }
}

#[test]
fn the_load_moves_continuously_from_line_to_rim_contact_as_the_journal_tilts() {
    // at a fixed deepest (rim) penetration, the force falls continuously and monotonically as the tilt
    // grows from 0 (the whole length bears) to where only a short zone at the rim bears: no switch
    // between a line and a point law, no jump
    let mut joint = joint(FrictionLaw::None, 1.0);
    joint.normal_force_law = NormalForceLaw::Hertz;
    let (rim_depth, half_length) = (5e-6, 0.5 * dimensions().bearing_length);
    let mut previous = f64::INFINITY;
    let mut largest_step = 0.0_f64;
    for k in 0..=2000 {
        let tilt = 2e-3 * k as f64 / 2000.0;
        // the journal offset so that rim B penetrates by rim_depth
        let force = static_force(&joint, rim_depth - half_length * tilt.tan(), tilt);
        assert!(force <= previous * (1.0 + 1e-12), "tilt {tilt}: {force} N after {previous} N");
        if k > 0 {
            largest_step = largest_step.max((previous - force) / previous);
        }
        previous = force;
    }
    assert!(largest_step < 0.01, "the largest drop between neighbouring tilts (1e-6 rad apart) is {largest_step}");
    // at 2 mrad a zone of l = delta_rim / tan(tilt) = 2.5 mm bears, its penetration falling linearly to
    // zero: F = K delta_rim^1.5 l / (2.5 L), the aligned force times l / (2.5 L)
    let zone = rim_depth / 2e-3_f64.tan();
    let expected = static_force(&joint, rim_depth, 0.0) * zone / (2.5 * 2.0 * half_length);
    assert!((previous / expected - 1.0).abs() < 0.02, "at 2 mrad: {previous} N against {expected} N");
}

#[test]
fn a_tilted_flange_touching_on_an_arc_carries_the_pressure_of_that_arc() {
    // flange B (the flange's edge, R_f = 15 mm, against the face's plane) with the journal tilted so that
    // only an arc near the edge touches: the force and moment equal a brute-force sum of the linear
    // pressure k_a delta / A over the touching part of the annulus (2000 x 8000 midpoints), from the
    // edge barely touching (a few micrometres) to a third of the ring
    let mut joint = joint(FrictionLaw::None, 1.0);
    joint.normal_force_law = NormalForceLaw::Hertz;
    let (d, still) = (dimensions(), Vec3::zeros());
    let flange_offset = 0.5 * (d.bearing_length + d.axial_clearance);
    for (tilt, shift) in [(0.0128, -1e-5), (0.0128, -3e-5), (5e-3, -2.5e-4)] {
        let frame = journal_frame(Vec3::new(0.0, 0.0, shift), tilt, still, still);
        let pose = JointPose::new(&SpatialFrame::GROUND, &frame);
        let mut load = JointLoad::default();
        let flange = joint.flange(&pose, 1, Some(1.0), &mut load);
        // brute force over the flange's annulus, in the journal's frame
        let (inner, outer) = (d.bore_radius, d.flange_radius);
        let pressure = joint.axial_stiffness / (std::f64::consts::PI * (outer * outer - inner * inner));
        let (nr, nphi) = (2000, 8000);
        let (mut force, mut moment) = (0.0, Vec3::zeros());
        for i in 0..nr {
            let r = inner + (outer - inner) * (i as f64 + 0.5) / nr as f64;
            for k in 0..nphi {
                let phi = std::f64::consts::TAU * (k as f64 + 0.5) / nphi as f64;
                let x = frame.position + frame.rotate(Vec3::new(r * phi.cos(), r * phi.sin(), flange_offset));
                let depth = 0.5 * d.bearing_length - x.z;
                if depth > 0.0 {
                    let f = pressure * depth * r * (outer - inner) / nr as f64 * std::f64::consts::TAU / nphi as f64;
                    force += f;
                    moment += (x - frame.position).cross(&Vec3::new(0.0, 0.0, f)); // the face pushes flange B out, along +z
                }
            }
        }
        assert!(force > 0.0);
        assert!((flange.normal_force / force - 1.0).abs() < 2e-3, "tilt {tilt}, shift {shift}: {} N against {force} N", flange.normal_force);
        let m = load.on_journal.moment;
        assert!((m - moment).norm() < 3e-3 * moment.norm(), "tilt {tilt}, shift {shift}: moment {m:?} against {moment:?}");
    }
}
