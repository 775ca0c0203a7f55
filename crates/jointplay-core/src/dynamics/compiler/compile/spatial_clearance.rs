//! Compiling a spatial revolute joint with radial and axial clearance: its
//! markers, dimensions, laws and motion-mode thresholds.

use super::laws::{build_bore_stiffness, build_friction, build_normal_force_law, check_materials, effective_modulus, Bore};
use super::Compiler;
use crate::element::ElementKind;
use crate::joint::{JointDimensions, JointGeometry, ModeThresholds, SpatialClearanceRevolute};
use crate::spec::{ranges, Range, SpatialClearanceJointSpec};

/// Largest penetration, as a fraction of the radial clearance, before a run stops, when none is given.
const MAX_PENETRATION_FRACTION_OF_CLEARANCE: f64 = 0.5;

impl<'s> Compiler<'s> {
    /// The spatial clearance joints.
    pub(super) fn spatial_clearance_joints(&mut self) {
        for (k, j) in self.spec.spatial_clearance_joints.iter().flatten().enumerate() {
            self.spatial_clearance_joint(&format!("spatial_clearance_joints[{k}]"), j);
        }
    }

    fn spatial_clearance_joint(&mut self, loc: &str, j: &'s SpatialClearanceJointSpec) {
        self.claim_name(&j.name, &format!("{loc}.name"));
        let bearing = self.spatial_point(&j.bearing, format!("{loc}.bearing"));
        let journal = self.spatial_point(&j.journal, format!("{loc}.journal"));
        let ranges_hold = Range::check_given(
            &[
                (ranges::SPATIAL_CLEARANCE_JOINTS_BORE_RADIUS, Some(j.bore_radius)),
                (ranges::SPATIAL_CLEARANCE_JOINTS_CLEARANCE, Some(j.clearance)),
                (ranges::SPATIAL_CLEARANCE_JOINTS_BEARING_LENGTH, Some(j.bearing_length)),
                (ranges::SPATIAL_CLEARANCE_JOINTS_AXIAL_CLEARANCE, Some(j.axial_clearance)),
                (ranges::SPATIAL_CLEARANCE_JOINTS_FLANGE_RADIUS, Some(j.flange_radius)),
                (ranges::SPATIAL_CLEARANCE_JOINTS_FACE_RADIUS, Some(j.face_radius)),
                (ranges::SPATIAL_CLEARANCE_JOINTS_AXIAL_STIFFNESS, j.axial_stiffness),
                (ranges::SPATIAL_CLEARANCE_JOINTS_ONSET_VELOCITY_FLOOR, Some(j.onset_velocity_floor)),
                (ranges::SPATIAL_CLEARANCE_JOINTS_MAX_PENETRATION, j.max_penetration),
                (ranges::SPATIAL_CLEARANCE_JOINTS_MODE_IMPACT_SPEED, Some(j.mode_impact_speed)),
                (ranges::SPATIAL_CLEARANCE_JOINTS_MODE_IMPACT_DURATION, Some(j.mode_impact_duration)),
                (ranges::SPATIAL_CLEARANCE_JOINTS_MODE_SLIDING_SPEED, Some(j.mode_sliding_speed)),
            ],
            loc,
            &mut self.errors,
        );
        check_materials(&j.bearing_material, &j.journal_material, loc, &mut self.errors);
        let law = build_normal_force_law(&j.contact, &format!("{loc}.contact"), &mut self.errors);
        let friction = build_friction(&j.friction, &format!("{loc}.friction"), &mut self.errors);
        let geometry = if ranges_hold { self.clearance_geometry(loc, j) } else { None };
        let stiffness = geometry.as_ref().and_then(|g| {
            let bore = Bore { bore_radius: j.bore_radius, journal_radius: g.dimensions().journal_radius, length: Some(j.bearing_length), bearing: &j.bearing_material, journal: &j.journal_material };
            build_bore_stiffness(&j.stiffness, &bore, loc, &mut self.errors)
        });
        let (Some(bearing), Some(journal), Some(geometry), Some(stiffness), Some(law), Some(friction)) = (bearing, journal, geometry, stiffness, law, friction) else {
            return;
        };
        if !self.distinct_bodies(loc, bearing.planar(), journal.planar()) {
            return;
        }
        if j.lock_at_assembly {
            self.spatial_assembly_locks.push((bearing, journal, j.name.clone()));
        }
        let axial_stiffness = j.axial_stiffness.unwrap_or_else(|| flat_punch_stiffness(&geometry, effective_modulus(&j.bearing_material, &j.journal_material)));
        let joint = SpatialClearanceRevolute {
            bearing,
            journal,
            radial_stiffness: stiffness,
            axial_stiffness,
            normal_force_law: law,
            friction,
            onset_velocity_floor: j.onset_velocity_floor,
            max_penetration: j.max_penetration.unwrap_or(MAX_PENETRATION_FRACTION_OF_CLEARANCE * geometry.radial_clearance()),
            modes: ModeThresholds { impact_speed: j.mode_impact_speed, impact_duration: j.mode_impact_duration, sliding_speed: j.mode_sliding_speed },
            geometry,
        };
        self.push_element(&j.name, ElementKind::SpatialClearanceRevolute(Box::new(joint)), Vec::new());
    }

    /// The joint's dimensions, each problem located at its key.
    fn clearance_geometry(&mut self, loc: &str, j: &SpatialClearanceJointSpec) -> Option<JointGeometry> {
        let dimensions = JointDimensions {
            bore_radius: j.bore_radius,
            journal_radius: j.bore_radius - j.clearance,
            bearing_length: j.bearing_length,
            axial_clearance: j.axial_clearance,
            flange_radius: j.flange_radius,
            face_radius: j.face_radius,
        };
        match JointGeometry::new(dimensions) {
            Ok(geometry) => Some(geometry),
            Err(problems) => {
                for problem in problems.0 {
                    // (the journal radius is the bore radius less the clearance given)
                    let key = if problem.location == "journal_radius" { "clearance" } else { problem.location.as_str() };
                    let message = if key == "clearance" { format!("must be smaller than bore_radius {} m, got {} m", j.bore_radius, j.clearance) } else { problem.message };
                    self.errors.push(format!("{loc}.{key}"), message);
                }
                None
            }
        }
    }
}

/// Stiffness of a rigid flat annular punch on an elastic half-space, taken as
/// the circular punch of equal area: `2 E* a` with `a = sqrt(A/pi)` [N/m]
/// (K. L. Johnson, Contact Mechanics, 1985, §3.8: the flat-ended cylindrical punch).
fn flat_punch_stiffness(geometry: &JointGeometry, effective_modulus: f64) -> f64 {
    let (inner, outer) = (geometry.dimensions().bore_radius, geometry.overlap_radius());
    2.0 * effective_modulus * (outer * outer - inner * inner).sqrt()
}
