use super::*;
use crate::kinematics::spatial::Mat3;
use nalgebra::{Rotation3, Unit};

/// A pin of 39 mm in a 40 mm bore of 40 mm length, 0.5 mm axial clearance.
fn dimensions() -> JointDimensions {
    JointDimensions {
        bore_radius: 0.020,
        journal_radius: 0.0195,
        bearing_length: 0.040,
        axial_clearance: 0.0005,
        flange_radius: 0.030,
        face_radius: 0.028,
    }
}

/// Round-off of a length computed from the markers' global positions: a few
/// units in the last place of their distance from the origin (0.4 m) [m].
const ROUND_OFF: f64 = 8.0 * f64::EPSILON * 0.4;

fn geometry() -> JointGeometry {
    JointGeometry::new(dimensions()).unwrap()
}

/// Deterministic pseudo-random numbers in [0, 1) (Knuth's MMIX constants).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn symmetric(&mut self, scale: f64) -> f64 {
        scale * (2.0 * self.next() - 1.0)
    }
}

fn rotation(axis: Vec3, angle: f64) -> Mat3 {
    *Rotation3::from_axis_angle(&Unit::new_normalize(axis), angle).matrix()
}

fn frame(position: Vec3, rotation: Mat3) -> SpatialFrame {
    SpatialFrame { position, rotation, ..SpatialFrame::GROUND }
}

/// A bearing marker in a general pose, and a journal marker placed relative to it
/// (offset and axes in bearing coordinates).
fn pose_in(bearing: &SpatialFrame, offset: Vec3, axes: Mat3) -> JointPose {
    let journal = bearing.compose(offset, &axes);
    JointPose::new(bearing, &journal)
}

fn general_bearing() -> SpatialFrame {
    frame(Vec3::new(0.3, -0.2, 0.1), rotation(Vec3::new(1.0, 2.0, -0.5), 0.7))
}

/// A random journal pose: tilt up to `max_tilt` about a random axis through O_J
/// perpendicular to z_B, a random spin, radial offset up to `max_offset`,
/// axial offset up to `max_axial`.
fn random_pose(rng: &mut Lcg, max_tilt: f64, max_offset: f64, max_axial: f64) -> JointPose {
    let tilt_axis_angle = rng.symmetric(std::f64::consts::PI);
    let tilt_axis = Vec3::new(tilt_axis_angle.cos(), tilt_axis_angle.sin(), 0.0);
    let axes = rotation(tilt_axis, max_tilt * rng.next()) * rotation(Vec3::z(), rng.symmetric(3.0));
    let (radius, direction) = (max_offset * rng.next().sqrt(), rng.symmetric(std::f64::consts::PI));
    let offset = Vec3::new(radius * direction.cos(), radius * direction.sin(), rng.symmetric(max_axial));
    pose_in(&general_bearing(), offset, axes)
}

/// The largest tilt of a centred journal: R_j / cos(g) + (L/2) tan(g) = R_b,
/// by bisection (derived for the rim circle in
/// `docs/theory/spatial-clearance-geometry.md`; the spatial joint's geometry after
/// Flores, Ambrósio, Claro, Lankarani, "Spatial revolute joints with clearances
/// for dynamic analysis of multibody systems", Proc. IMechE K 220, 2006).
fn largest_tilt(d: &JointDimensions) -> f64 {
    let excess = |g: f64| d.journal_radius / g.cos() + 0.5 * d.bearing_length * g.tan() - d.bore_radius;
    let (mut low, mut high) = (0.0, 0.5);
    for _ in 0..200 {
        let mid = 0.5 * (low + high);
        if excess(mid) > 0.0 { high = mid } else { low = mid }
    }
    0.5 * (low + high)
}

/// Distance from `x` to the journal axis [m], written out independently.
fn distance_to_axis(pose: &JointPose, x: Vec3) -> f64 {
    let (o, z) = (pose.journal.position, pose.journal.axis(2));
    (x - o).cross(&z).norm()
}

/// The least value of `f` over the circle: 1e5 angles, then golden-section
/// search about the best sample.
fn sampled_minimum(f: impl Fn(f64) -> f64) -> f64 {
    let n = 100_000;
    let step = std::f64::consts::TAU / n as f64;
    let best = (0..n).map(|k| k as f64 * step).min_by(|a, b| f(*a).total_cmp(&f(*b))).unwrap();
    let (mut a, mut b) = (best - step, best + step);
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..200 {
        let (x1, x2) = (b - ratio * (b - a), a + ratio * (b - a));
        if f(x1) < f(x2) { b = x2 } else { a = x1 }
    }
    f(0.5 * (a + b)).min(f(best))
}

/// Brute force: the least distance from the section circle at `s` to the journal axis.
fn brute_force_distance(pose: &JointPose, radius: f64, s: f64) -> f64 {
    sampled_minimum(|phi| distance_to_axis(pose, pose.bearing.point(Vec3::new(radius * phi.cos(), radius * phi.sin(), s))))
}

#[test]
fn constructor_names_each_bad_value() {
    let bad = JointDimensions { journal_radius: 0.021, axial_clearance: -1e-4, face_radius: f64::NAN, ..dimensions() };
    let errors = JointGeometry::new(bad).unwrap_err();
    let located: Vec<&str> = errors.0.iter().map(|e| e.location.as_str()).collect();
    assert_eq!(located, ["journal_radius", "axial_clearance", "face_radius"]);
    assert_eq!(errors.0[0].message, "must be finite and > 0 and < bore_radius, got 0.021 m");
    let geometry = geometry();
    assert!((geometry.radial_clearance() - 0.0005).abs() < 1e-18);
    assert!((geometry.flange_offset() - 0.02025).abs() < 1e-18);
    assert_eq!(geometry.overlap_radius(), 0.028);
}

#[test]
fn largest_tilt_of_a_centred_journal_matches_the_closed_form() {
    let geometry = geometry();
    let g = largest_tilt(geometry.dimensions());
    let tilt_axis = Vec3::new(0.6, -0.8, 0.0);
    let rims_at = |tilt: f64| geometry.rim_contacts(&pose_in(&general_bearing(), Vec3::zeros(), rotation(tilt_axis, tilt)));
    for rim in rims_at(g) {
        assert!(rim.contact.penetration.abs() < ROUND_OFF, "{}", rim.contact.penetration);
    }
    // beyond the largest tilt both rims cut into the journal, below they are free
    let step = 1e-9;
    assert!(rims_at(g + step).iter().all(|r| r.contact.penetration > 1e-13));
    assert!(rims_at(g - step).iter().all(|r| r.contact.penetration < -1e-13));
    // the two rims touch on opposite sides
    let [low, high] = rims_at(g);
    assert!((low.contact.normal + high.contact.normal).norm() < 1e-12);
}

#[test]
fn aligned_axes_give_the_planar_penetration_and_the_flange_gaps() {
    let (geometry, mut rng) = (geometry(), Lcg(7));
    let c = geometry.radial_clearance();
    for _ in 0..200 {
        let (e, direction, axial) = (1.5 * c * rng.next(), rng.symmetric(3.2), rng.symmetric(0.0004));
        let offset = Vec3::new(e * direction.cos(), e * direction.sin(), axial);
        let pose = pose_in(&general_bearing(), offset, rotation(Vec3::z(), rng.symmetric(3.0)));
        let eccentricity = pose.bearing.rotate(Vec3::new(direction.cos(), direction.sin(), 0.0));
        for rim in geometry.rim_contacts(&pose) {
            assert!((rim.contact.penetration - (e - c)).abs() < ROUND_OFF, "{} {}", rim.contact.penetration, e - c);
            assert!((rim.contact.normal - eccentricity).norm() < 1e-12);
        }
        for s in [-0.02, -0.013, 0.0, 0.007, 0.02] {
            assert!((geometry.section_penetration(&pose, s) - (e - c)).abs() < ROUND_OFF);
        }
        let half_gap = 0.5 * geometry.dimensions().axial_clearance;
        let measures = geometry.measures(&pose);
        assert!((measures.axial_gaps[0] - (half_gap - axial)).abs() < ROUND_OFF);
        assert!((measures.axial_gaps[1] - (half_gap + axial)).abs() < ROUND_OFF);
        assert!((measures.axial_position - axial).abs() < ROUND_OFF);
        assert!(measures.tilt < 4.0 * f64::EPSILON);
        for centre in measures.eccentricities {
            assert!((centre - offset.xy()).norm() < ROUND_OFF);
        }
        for flange in geometry.flange_contacts(&pose) {
            assert_eq!(flange.full_ring, flange.contact.penetration > 0.0);
            assert!((flange.mean_penetration - flange.contact.penetration).abs() < ROUND_OFF);
        }
    }
}

#[test]
fn rim_point_is_the_closest_point_of_the_rim_by_brute_force() {
    let (geometry, mut rng) = (geometry(), Lcg(11));
    let d = *geometry.dimensions();
    let g = largest_tilt(&d);
    for _ in 0..20 {
        let pose = random_pose(&mut rng, g, geometry.radial_clearance(), 0.0003);
        for rim in geometry.rim_contacts(&pose) {
            let brute = brute_force_distance(&pose, d.bore_radius, rim.section);
            let ours = d.journal_radius - rim.contact.penetration;
            assert!((ours - brute).abs() <= 1e-12 * brute, "{ours} {brute}");
            assert!((distance_to_axis(&pose, rim.contact.bearing_point) - ours).abs() < 1e-15);
            assert!((distance_to_axis(&pose, rim.contact.journal_point) - d.journal_radius).abs() < 1e-15);
        }
    }
}

#[test]
fn general_case_of_a_strongly_tilted_centred_journal_finds_the_global_minimum() {
    // a short, wide bore with a thin journal: tilts of 30 degrees and offsets
    // comparable to R tilt^2, where the distance has two local minima
    let wide = JointDimensions { bore_radius: 1.0, journal_radius: 0.2, bearing_length: 0.3, axial_clearance: 0.1, flange_radius: 1.5, face_radius: 1.4 };
    let (geometry, mut rng) = (JointGeometry::new(wide).unwrap(), Lcg(3));
    for _ in 0..40 {
        let pose = random_pose(&mut rng, 0.6, 0.15, 0.1);
        for s in [-0.15, 0.05, 0.15] {
            let section = geometry.section_contact(&pose, s);
            let brute = brute_force_distance(&pose, 1.0, s);
            let ours = 0.2 - section.contact.penetration;
            assert!((ours - brute).abs() <= 1e-12 * brute, "{ours} {brute}");
        }
    }
}

#[test]
fn flange_deepest_point_by_brute_force_over_the_edge_circle() {
    let mut rng = Lcg(5);
    let face_larger = dimensions();
    let flange_larger = JointDimensions { face_radius: 0.032, ..dimensions() };
    for d in [face_larger, flange_larger] {
        let geometry = JointGeometry::new(d).unwrap();
        for _ in 0..20 {
            let pose = random_pose(&mut rng, largest_tilt(&d), geometry.radial_clearance(), 0.0004);
            for (flange, side) in geometry.flange_contacts(&pose).iter().zip([-1.0, 1.0]) {
                let brute = brute_force_edge(&pose, &d, side);
                assert!((flange.contact.penetration - brute).abs() < 1e-12 * d.bearing_length, "{} {brute}", flange.contact.penetration);
                let planes = (flange.contact.journal_point - flange.contact.bearing_point).cross(&pose.bearing.axis(2));
                assert!(planes.norm() < 1e-12 || d.face_radius < d.flange_radius);
            }
        }
    }
}

/// The deepest penetration of the overlap's outer edge circle into the other
/// body's face, by sampling the edge (written from the
/// definitions: the flange's inner face at `side (L + c_a)/2` along z_J, the
/// bearing's face at `side L/2` along z_B).
fn brute_force_edge(pose: &JointPose, d: &JointDimensions, side: f64) -> f64 {
    let (b, j) = (&pose.bearing, &pose.journal);
    let flange_at = 0.5 * (d.bearing_length + d.axial_clearance);
    let depth = |phi: f64| {
        if d.flange_radius <= d.face_radius {
            let x = j.point(Vec3::new(d.flange_radius * phi.cos(), d.flange_radius * phi.sin(), side * flange_at));
            0.5 * d.bearing_length - side * b.to_local(x - b.position).z
        } else {
            let y = b.point(Vec3::new(d.face_radius * phi.cos(), d.face_radius * phi.sin(), side * 0.5 * d.bearing_length));
            side * j.to_local(y - j.position).z - flange_at
        }
    };
    -sampled_minimum(|phi| -depth(phi))
}

/// Both markers moving rigidly: constant velocities and angular velocities
/// (global), rotations `exp(omega t) R0`, the journal spinning about its axis too.
struct Motion {
    bearing: (SpatialFrame, Vec3, Vec3),
    journal: (SpatialFrame, Vec3, Vec3),
}

impl Motion {
    fn frame_at(start: &(SpatialFrame, Vec3, Vec3), t: f64) -> SpatialFrame {
        let (f, v, w) = start;
        let turn = if w.norm() > 0.0 { rotation(*w, w.norm() * t) } else { Mat3::identity() };
        SpatialFrame { position: f.position + v * t, rotation: turn * f.rotation, velocity: *v, angular_velocity: *w }
    }

    fn pose_at(&self, t: f64) -> JointPose {
        JointPose::new(&Self::frame_at(&self.bearing, t), &Self::frame_at(&self.journal, t))
    }
}

fn tilted_motion(spin: f64) -> Motion {
    let bearing = general_bearing();
    let journal = bearing.compose(Vec3::new(0.0003, -0.0002, 0.0001), &rotation(Vec3::new(1.0, 0.3, 0.0), 0.01));
    Motion {
        bearing: (bearing, Vec3::new(0.1, -0.2, 0.05), Vec3::new(0.5, -1.0, 2.0)),
        journal: (journal, Vec3::new(0.12, -0.21, 0.04), Vec3::new(0.52, -1.03, 2.0) + journal.axis(2) * spin),
    }
}

#[test]
fn penetration_rates_match_central_differences_along_a_motion() {
    let (geometry, motion, h) = (geometry(), tilted_motion(30.0), 1e-6);
    let candidates = |pose: &JointPose| {
        let ([r0, r1], [f0, f1]) = (geometry.rim_contacts(pose), geometry.flange_contacts(pose));
        [r0.contact, r1.contact, f0.contact, f1.contact, geometry.section_contact(pose, 0.006).contact]
    };
    let pose = motion.pose_at(0.0);
    let (before, after) = (candidates(&motion.pose_at(-h)), candidates(&motion.pose_at(h)));
    for (k, contact) in candidates(&pose).iter().enumerate() {
        let numeric = (after[k].penetration - before[k].penetration) / (2.0 * h);
        let rate = pose.relative_motion(contact).approach_rate;
        assert!((rate - numeric).abs() < 1e-7 * (1.0 + numeric.abs()), "candidate {k}: {rate} {numeric}");
        assert!(rate.abs() > 1e-3, "candidate {k} moves");
    }
}

#[test]
fn relative_velocity_is_the_rate_of_the_material_points() {
    let (geometry, motion, h) = (geometry(), tilted_motion(30.0), 1e-6);
    let pose = motion.pose_at(0.0);
    let ([r0, r1], [f0, f1]) = (geometry.rim_contacts(&pose), geometry.flange_contacts(&pose));
    for contact in [r0.contact, r1.contact, f0.contact, f1.contact] {
        // the material points, fixed in each marker's coordinates at t = 0
        let on_journal = pose.journal.to_local(contact.journal_point - pose.journal.position);
        let on_bearing = pose.bearing.to_local(contact.bearing_point - pose.bearing.position);
        let separation = |t: f64| {
            let p = motion.pose_at(t);
            p.journal.point(on_journal) - p.bearing.point(on_bearing)
        };
        let numeric = (separation(h) - separation(-h)) / (2.0 * h);
        let relative = pose.relative_motion(&contact);
        assert!((relative.velocity - numeric).norm() < 1e-8, "{} {}", relative.velocity, numeric);
        assert!(relative.tangential_velocity.dot(&contact.normal).abs() < 1e-14);
    }
}

#[test]
fn journal_spin_in_contact_slides_at_journal_radius_times_spin() {
    let geometry = geometry();
    let c = geometry.radial_clearance();
    let bearing = general_bearing();
    let journal = bearing.compose(Vec3::new(c, 0.0, 0.0), &Mat3::identity());
    let spin = 40.0;
    let journal = SpatialFrame { angular_velocity: journal.axis(2) * spin, ..journal };
    let pose = JointPose::new(&bearing, &journal);
    for rim in geometry.rim_contacts(&pose) {
        let relative = pose.relative_motion(&rim.contact);
        assert!(rim.contact.penetration.abs() < ROUND_OFF);
        assert!(relative.approach_rate.abs() < 1e-14);
        let expected = pose.bearing.axis(1) * (geometry.dimensions().journal_radius * spin);
        assert!((relative.tangential_velocity - expected).norm() < 1e-13, "{}", relative.tangential_velocity);
    }
}

#[test]
fn moving_both_markers_by_one_rigid_motion_changes_no_penetration() {
    let (geometry, mut rng) = (geometry(), Lcg(13));
    let d = *geometry.dimensions();
    for _ in 0..20 {
        let pose = random_pose(&mut rng, largest_tilt(&d), 1.2 * geometry.radial_clearance(), 0.0004);
        let (turn, shift) = (rotation(Vec3::new(rng.next(), rng.next(), rng.next()), rng.symmetric(3.0)), Vec3::new(rng.next(), rng.next(), rng.next()));
        let moved = |f: &SpatialFrame| frame(turn * f.position + shift, turn * f.rotation);
        let other = JointPose::new(&moved(&pose.bearing), &moved(&pose.journal));
        let penetrations = |p: &JointPose| {
            let ([r0, r1], [f0, f1]) = (geometry.rim_contacts(p), geometry.flange_contacts(p));
            [r0.contact.penetration, r1.contact.penetration, f0.contact.penetration, f1.contact.penetration, geometry.section_penetration(p, 0.003)]
        };
        for (a, b) in penetrations(&pose).iter().zip(penetrations(&other)) {
            assert!((a - b).abs() < 1e-15, "{a} {b}");
        }
        assert!((geometry.measures(&pose).tilt - geometry.measures(&other).tilt).abs() < 1e-14);
    }
}

#[test]
fn section_profile_is_continuous_and_ends_at_the_rims() {
    let (geometry, mut rng) = (geometry(), Lcg(17));
    let d = *geometry.dimensions();
    let pose = random_pose(&mut rng, largest_tilt(&d), geometry.radial_clearance(), 0.0);
    let sections: Vec<f64> = (0..=400).map(|k| -0.02 + 0.04 * k as f64 / 400.0).collect();
    let mut profile = vec![0.0; sections.len()];
    geometry.section_penetrations(&pose, &sections, &mut profile);
    let [low, high] = geometry.rim_contacts(&pose);
    assert_eq!(profile[0], low.contact.penetration);
    assert_eq!(profile[400], high.contact.penetration);
    // the profile of a straight axis in a straight bore has a bounded slope: at most tan(tilt) + the curvature term
    let slope_bound = geometry.measures(&pose).tilt.tan() * 1.01;
    for pair in profile.windows(2) {
        assert!((pair[1] - pair[0]).abs() <= slope_bound * 1e-4, "{pair:?}");
    }
}

#[test]
fn tilted_flange_is_no_full_ring_until_the_whole_edge_penetrates() {
    let geometry = geometry();
    let d = *geometry.dimensions();
    let tilt: f64 = 1e-3;
    let spread = 2.0 * geometry.overlap_radius() * tilt.sin();
    // axial shift that makes the flange +1 face penetrate by `depth` at its deepest point
    let at_depth = |depth: f64| {
        // (the face's edge against the flange's plane: mean = (L/2 - shift) cos(tilt) - (L + c_a)/2)
        let shift = 0.5 * d.bearing_length - (geometry.flange_offset() + depth - 0.5 * spread) / tilt.cos();
        let pose = pose_in(&general_bearing(), Vec3::new(0.0, 0.0, shift), rotation(Vec3::x(), tilt));
        geometry.flange_contacts(&pose)[1]
    };
    let shallow = at_depth(0.5 * spread);
    assert!((shallow.contact.penetration - 0.5 * spread).abs() < 1e-15, "{} {}", shallow.contact.penetration, 0.5 * spread);
    assert!((shallow.mean_penetration - 0.0).abs() < 1e-15);
    assert!(!shallow.full_ring);
    assert!(at_depth(1.001 * spread).full_ring);
}
