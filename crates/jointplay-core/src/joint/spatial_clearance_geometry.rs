//! Geometry and kinematics of a spatial revolute joint with radial and axial
//! clearance: a journal with two flanges in a bore of finite length
//! (`docs/theory/spatial-clearance-geometry.md`).
//!
//! Everything here is a pure function of two marker frames: the bearing marker B
//! (origin at the bore's centre, `z_B` the bore axis) and the journal marker J
//! (origin midway between the flanges, `z_J` the journal axis). Contact
//! candidates: the bore's two rim circles (or any bore section) against the
//! journal's cylinder, and each flange's inner face against the bearing's end
//! face. Nothing allocates.

use crate::error::ModelErrors;
use crate::kinematics::planar::Vec2;
use crate::kinematics::spatial::{SpatialFrame, Vec3};

/// Largest number of safeguarded Newton steps in the rim-angle search (it
/// converges in a handful; the bound only guards against a pathological input).
const MAX_NEWTON_STEPS: usize = 64;

/// Samples of the section circle in the general (strongly tilted, nearly
/// centred) case, where two local minima of the distance may exist.
const GENERAL_CASE_SAMPLES: usize = 32;

/// The dimensions of the joint as given [m].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointDimensions {
    /// Bore radius R_b [m].
    pub bore_radius: f64,
    /// Journal radius R_j < R_b [m].
    pub journal_radius: f64,
    /// Bearing length L: the bore spans `s` in `[-L/2, L/2]` along `z_B` [m].
    pub bearing_length: f64,
    /// Axial clearance c_a: flange spacing minus bearing length [m].
    pub axial_clearance: f64,
    /// Outer radius of the journal's flanges R_f > R_b [m].
    pub flange_radius: f64,
    /// Outer radius of the bearing's end faces R_face > R_b [m].
    pub face_radius: f64,
}

/// The validated dimensions of a journal in a bore with flanges.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointGeometry {
    dimensions: JointDimensions,
}

/// Where a candidate touches: the same quantities for radial and axial candidates.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactPoint {
    /// Penetration delta, positive in contact [m].
    pub penetration: f64,
    /// The bearing's point Q (global) [m].
    pub bearing_point: Vec3,
    /// The journal's point P = Q + delta n (global) [m].
    pub journal_point: Vec3,
    /// Unit normal n (global): the journal moving along n penetrates further; it is pushed back along -n [-].
    pub normal: Vec3,
}

/// A bore section against the journal's cylinder.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RadialContact {
    /// Penetration, points and normal.
    pub contact: ContactPoint,
    /// Axial coordinate of the section along `z_B` from the bore's centre [m].
    pub section: f64,
}

/// A flange's inner face against the bearing's end face.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct AxialContact {
    /// The deepest point of the overlap's outer edge circle.
    pub contact: ContactPoint,
    /// Penetration at the edge circle's centre: the mean over the ring [m].
    pub mean_penetration: f64,
    /// Whether the whole edge circle penetrates, `0 < 2 r_o sin(tilt) <= delta`
    /// (with aligned axes: whenever `delta > 0`), so that an area law applies:
    /// the tilt is below `asin(delta / (2 r_o))`.
    pub full_ring: bool,
}

/// Relative motion at a candidate's contact location.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RelativeMotion {
    /// Velocity of the journal's material point at P minus the bearing's at Q (global) [m/s].
    pub velocity: Vec3,
    /// Normal component `velocity . n`: the penetration rate d(delta)/dt, positive when penetrating further [m/s].
    pub approach_rate: f64,
    /// Tangential part `velocity - (velocity . n) n` (global) [m/s].
    pub tangential_velocity: Vec3,
}

/// Kinematic measures of the joint for its channels.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct JointMeasures {
    /// Journal-axis offsets from the bore axis in the bearing frame's (x, y) at
    /// `s = -L/2, 0, +L/2`: the journal-axis point nearest each section's centre [m].
    pub eccentricities: [Vec2; 3],
    /// Angle between `z_J` and `z_B` [rad].
    pub tilt: f64,
    /// Axial position `(O_J - O_B) . z_B` [m].
    pub axial_position: f64,
    /// Axial gaps of the flanges k = -1, +1 (negative when penetrating) [m].
    pub axial_gaps: [f64; 2],
}

/// The two marker frames of one evaluation and the journal axis seen from the bearing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointPose {
    /// Bearing marker frame.
    pub bearing: SpatialFrame,
    /// Journal marker frame.
    pub journal: SpatialFrame,
    /// `O_J - O_B` in bearing coordinates [m].
    pub(crate) journal_origin: Vec3,
    /// `z_J` in bearing coordinates [-].
    journal_axis: Vec3,
}

impl JointPose {
    /// The pose of the journal marker relative to the bearing marker.
    #[inline]
    pub fn new(bearing: &SpatialFrame, journal: &SpatialFrame) -> JointPose {
        JointPose {
            bearing: *bearing,
            journal: *journal,
            journal_origin: bearing.to_local(journal.position - bearing.position),
            journal_axis: bearing.to_local(journal.axis(2)),
        }
    }

    /// Angle between the journal axis and the bore axis [rad].
    #[inline]
    pub fn tilt(&self) -> f64 {
        let u = self.journal_axis;
        u.xy().norm().atan2(u.z)
    }

    /// The journal-axis point nearest the bore-axis point at `s`, in bearing coordinates [m].
    #[inline]
    pub(crate) fn axis_foot(&self, s: f64) -> Vec3 {
        let (p, u) = (self.journal_origin, self.journal_axis);
        p + u * (Vec3::new(0.0, 0.0, s) - p).dot(&u)
    }

    /// Relative motion of the journal's material point at P and the bearing's at Q.
    #[inline]
    pub fn relative_motion(&self, contact: &ContactPoint) -> RelativeMotion {
        let velocity = self.journal.material_velocity_at(contact.journal_point) - self.bearing.material_velocity_at(contact.bearing_point);
        let approach_rate = velocity.dot(&contact.normal);
        RelativeMotion { velocity, approach_rate, tangential_velocity: velocity - contact.normal * approach_rate }
    }
}

impl JointGeometry {
    /// Checks the dimensions: every one finite, radii and length > 0,
    /// `R_j < R_b`, `c_a >= 0`, `R_f > R_b`, `R_face > R_b`. Each bad value is
    /// one error located at its field's name.
    pub fn new(dimensions: JointDimensions) -> Result<JointGeometry, ModelErrors> {
        let d = dimensions;
        let mut errors = ModelErrors::default();
        let mut check = |name: &str, ok: bool, rule: &str, value: f64| {
            if !(ok && value.is_finite()) {
                errors.push(name, format!("must be finite and {rule}, got {value} m"));
            }
        };
        check("bore_radius", d.bore_radius > 0.0, "> 0", d.bore_radius);
        check("journal_radius", d.journal_radius > 0.0 && d.journal_radius < d.bore_radius, "> 0 and < bore_radius", d.journal_radius);
        check("bearing_length", d.bearing_length > 0.0, "> 0", d.bearing_length);
        check("axial_clearance", d.axial_clearance >= 0.0, ">= 0", d.axial_clearance);
        check("flange_radius", d.flange_radius > d.bore_radius, "> bore_radius", d.flange_radius);
        check("face_radius", d.face_radius > d.bore_radius, "> bore_radius", d.face_radius);
        errors.into_result(JointGeometry { dimensions })
    }

    /// The dimensions.
    #[inline]
    pub fn dimensions(&self) -> &JointDimensions {
        &self.dimensions
    }

    /// Radial clearance c = R_b - R_j [m].
    #[inline]
    pub fn radial_clearance(&self) -> f64 {
        self.dimensions.bore_radius - self.dimensions.journal_radius
    }

    /// Distance of each flange's inner face from O_J along z_J, (L + c_a)/2 [m].
    #[inline]
    pub fn flange_offset(&self) -> f64 {
        0.5 * (self.dimensions.bearing_length + self.dimensions.axial_clearance)
    }

    /// Radius of the overlap's outer edge, r_o = min(R_f, R_face) [m].
    #[inline]
    pub fn overlap_radius(&self) -> f64 {
        self.dimensions.flange_radius.min(self.dimensions.face_radius)
    }

    /// The bore's rims at `s = -L/2` (index 0) and `s = +L/2` (index 1).
    #[inline]
    pub fn rim_contacts(&self, pose: &JointPose) -> [RadialContact; 2] {
        let half = 0.5 * self.dimensions.bearing_length;
        [self.section_contact(pose, -half), self.section_contact(pose, half)]
    }

    /// Penetration of the bore section at `s` (in `[-L/2, L/2]`) into the journal's cylinder [m].
    #[inline]
    pub fn section_penetration(&self, pose: &JointPose, s: f64) -> f64 {
        self.section_contact(pose, s).contact.penetration
    }

    /// [`Self::section_penetration`] at each of `sections` into `penetrations` (same length) [m].
    pub fn section_penetrations(&self, pose: &JointPose, sections: &[f64], penetrations: &mut [f64]) {
        for (s, delta) in sections.iter().zip(penetrations.iter_mut()) {
            *delta = self.section_penetration(pose, *s);
        }
    }

    /// The bore section at `s` against the journal's cylinder: Q is the point
    /// of the section circle closest to the journal axis, `delta = R_j - dist(Q, axis)`.
    pub fn section_contact(&self, pose: &JointPose, s: f64) -> RadialContact {
        let radius = self.dimensions.bore_radius;
        let distance = SectionDistance::new(pose, radius, s);
        let angle = distance.closest_angle();
        let local = Vec3::new(radius * angle.cos(), radius * angle.sin(), s);
        let q = pose.bearing.point(local);
        let (o, z) = (pose.journal.position, pose.journal.axis(2));
        let foot = o + z * (q - o).dot(&z);
        let radial = q - foot;
        let dist = radial.norm();
        let normal = if dist > 0.0 { radial / dist } else { pose.bearing.rotate(Vec3::new(angle.cos(), angle.sin(), 0.0)) };
        let penetration = self.dimensions.journal_radius - dist;
        let contact = ContactPoint { penetration, bearing_point: q, journal_point: q + normal * penetration, normal };
        RadialContact { contact, section: s }
    }

    /// Flange k = -1 (index 0) and k = +1 (index 1) against the bearing's end face k.
    #[inline]
    pub fn flange_contacts(&self, pose: &JointPose) -> [AxialContact; 2] {
        [self.flange_contact(pose, -1.0), self.flange_contact(pose, 1.0)]
    }

    /// Flange `side` (-1 or +1) against the bearing's end face on that side.
    /// The deepest point lies on the outer edge circle of the overlap: the
    /// flange's edge against the face's plane when `R_f <= R_face`, else the
    /// face's edge against the flange's plane; the maximum of a linear function
    /// over a circle, `centre + r_o sin(tilt)`.
    pub fn flange_contact(&self, pose: &JointPose, side: f64) -> AxialContact {
        let d = &self.dimensions;
        let (b, j) = (&pose.bearing, &pose.journal);
        let (flange, face) = (self.flange_offset(), 0.5 * d.bearing_length);
        if d.flange_radius <= d.face_radius {
            // the flange's edge (journal material) against the face plane (normal side z_B)
            let centre = j.position + j.axis(2) * (side * flange);
            let normal = -side * b.axis(2);
            let depth = |x: Vec3| face - side * (x - b.position).dot(&b.axis(2));
            let edge = edge_circle_deepest(j, centre, d.flange_radius, normal);
            let penetration = depth(edge);
            let contact = ContactPoint { penetration, bearing_point: edge - normal * penetration, journal_point: edge, normal };
            self.ring(contact, depth(centre), pose)
        } else {
            // the face's edge (bearing material) against the flange plane (normal -side z_J)
            let centre = b.position + b.axis(2) * (side * face);
            let normal = -side * j.axis(2);
            let depth = |y: Vec3| side * (y - j.position).dot(&j.axis(2)) - flange;
            let edge = edge_circle_deepest(b, centre, d.face_radius, -normal);
            let penetration = depth(edge);
            let contact = ContactPoint { penetration, bearing_point: edge, journal_point: edge + normal * penetration, normal };
            self.ring(contact, depth(centre), pose)
        }
    }

    /// The axial candidate with its ring quantities.
    #[inline]
    fn ring(&self, contact: ContactPoint, mean_penetration: f64, pose: &JointPose) -> AxialContact {
        let spread = 2.0 * self.overlap_radius() * pose.tilt().sin();
        AxialContact { contact, mean_penetration, full_ring: contact.penetration > 0.0 && spread <= contact.penetration }
    }

    /// Eccentricities at both ends and the middle, tilt, axial position and gaps.
    pub fn measures(&self, pose: &JointPose) -> JointMeasures {
        let half = 0.5 * self.dimensions.bearing_length;
        let eccentricities = [-half, 0.0, half].map(|s| pose.axis_foot(s).xy());
        let axial_position = pose.journal_origin.z;
        let [minus, plus] = self.flange_contacts(pose);
        JointMeasures { eccentricities, tilt: pose.tilt(), axial_position, axial_gaps: [-minus.contact.penetration, -plus.contact.penetration] }
    }
}

/// The point of a circle (centre `centre`, radius `radius` [m], in the plane
/// spanned by `frame`'s x and y axes) farthest along `direction`: the maximum
/// of a linear function over a circle, `centre + radius * (direction projected
/// on the plane, normalised)`; the frame's x axis when the projection vanishes.
/// (The projection is taken in the frame's coordinates, so the point stays in
/// the plane to round-off even when `direction` is nearly normal to it.)
#[inline]
fn edge_circle_deepest(frame: &SpatialFrame, centre: Vec3, radius: f64, direction: Vec3) -> Vec3 {
    let in_plane = frame.to_local(direction).xy();
    let length = in_plane.norm();
    let unit = if length > 0.0 { in_plane / length } else { Vec2::new(1.0, 0.0) };
    centre + frame.rotate(Vec3::new(unit.x, unit.y, 0.0)) * radius
}

/// The squared distance from the point at angle `phi` on a bore section
/// circle (radius R, at `s` along `z_B`) to the journal axis, a trigonometric
/// polynomial of degree 2 (bearing coordinates, `p` = O_J, `u` = z_J,
/// `m = (-p_x, -p_y, s - p_z)`, `mu = m . u`):
/// `d^2(phi) = c0 + c1 cos(phi) + s1 sin(phi) + c2 cos(2 phi) + s2 sin(2 phi)`,
/// `c1 = 2R (m_x - mu u_x)`, `s1 = 2R (m_y - mu u_y)`,
/// `c2 = -R^2 (u_x^2 - u_y^2)/2`, `s2 = -R^2 u_x u_y` (c0 plays no part in the minimum).
struct SectionDistance {
    c1: f64,
    s1: f64,
    c2: f64,
    s2: f64,
}

impl SectionDistance {
    fn new(pose: &JointPose, radius: f64, s: f64) -> SectionDistance {
        let (p, u) = (pose.journal_origin, pose.journal_axis);
        let m = Vec3::new(-p.x, -p.y, s - p.z);
        let mu = m.dot(&u);
        SectionDistance {
            c1: 2.0 * radius * (m.x - mu * u.x),
            s1: 2.0 * radius * (m.y - mu * u.y),
            c2: -0.5 * radius * radius * (u.x * u.x - u.y * u.y),
            s2: -radius * radius * u.x * u.y,
        }
    }

    /// `d^2(phi) - c0` [m^2].
    #[inline]
    fn value(&self, phi: f64) -> f64 {
        let (s, c) = phi.sin_cos();
        let (s2, c2) = (2.0 * phi).sin_cos();
        self.c1 * c + self.s1 * s + self.c2 * c2 + self.s2 * s2
    }

    /// First and second derivative of `d^2` in `phi` [m^2/rad, m^2/rad^2].
    #[inline]
    fn slope_and_curvature(&self, phi: f64) -> (f64, f64) {
        let (s, c) = phi.sin_cos();
        let (s2, c2) = (2.0 * phi).sin_cos();
        let slope = -self.c1 * s + self.s1 * c - 2.0 * self.c2 * s2 + 2.0 * self.s2 * c2;
        let curvature = -self.c1 * c - self.s1 * s - 4.0 * self.c2 * c2 - 4.0 * self.s2 * s2;
        (slope, curvature)
    }

    /// The angle of the global minimum of `d^2` over the circle [rad].
    ///
    /// With first-harmonic amplitude `a1` and second `a2`: when `a1 >= 5 a2`
    /// the minimum is unique and lies within `asin(2 a2 / a1)` of the first
    /// harmonic's minimum, where `d^2` is strictly convex (the page derives
    /// it); otherwise every discrete minimum of a sampling is refined and the
    /// lowest kept.
    fn closest_angle(&self) -> f64 {
        let a1 = self.c1.hypot(self.s1);
        let a2 = self.c2.hypot(self.s2);
        if a1 == 0.0 && a2 == 0.0 {
            return 0.0;
        }
        if a1 >= 5.0 * a2 {
            let centre = (-self.s1).atan2(-self.c1);
            let half_width = (2.0 * a2 / a1).asin();
            return self.refine(centre - half_width, centre + half_width, centre);
        }
        self.general_minimum()
    }

    /// Every discrete minimum of an even sampling refined; the lowest [rad].
    fn general_minimum(&self) -> f64 {
        let step = std::f64::consts::TAU / GENERAL_CASE_SAMPLES as f64;
        let at = |k: usize| self.value(k as f64 * step);
        let (mut best, mut best_value) = (0.0, f64::INFINITY);
        for k in 0..GENERAL_CASE_SAMPLES {
            let (before, here, after) = (at(k + GENERAL_CASE_SAMPLES - 1), at(k), at(k + 1));
            if here <= before && here <= after {
                let centre = k as f64 * step;
                let refined = self.refine(centre - step, centre + step, centre);
                let (phi, value) = if self.value(refined) <= here { (refined, self.value(refined)) } else { (centre, here) };
                if value < best_value {
                    (best, best_value) = (phi, value);
                }
            }
        }
        best
    }

    /// Newton on `d(d^2)/dphi = 0` from `start`, safeguarded by bisection of
    /// the bracket `[low, high]` (slope <= 0 at `low`, >= 0 at `high`), to round-off [rad]
    /// (Press et al., Numerical Recipes, 2nd ed., §9.4, `rtsafe`).
    fn refine(&self, mut low: f64, mut high: f64, start: f64) -> f64 {
        let mut phi = start;
        for _ in 0..MAX_NEWTON_STEPS {
            let (slope, curvature) = self.slope_and_curvature(phi);
            if slope == 0.0 {
                return phi;
            }
            if slope < 0.0 { low = phi } else { high = phi }
            let newton = phi - slope / curvature;
            let next = if curvature > 0.0 && newton > low && newton < high { newton } else { 0.5 * (low + high) };
            if (next - phi).abs() <= 4.0 * f64::EPSILON * (1.0 + phi.abs()) {
                return next;
            }
            phi = next;
        }
        phi
    }
}

#[cfg(test)]
#[path = "spatial_clearance_geometry_tests.rs"]
mod tests;
