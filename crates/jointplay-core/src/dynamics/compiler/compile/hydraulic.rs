//! Building a hydraulic cylinder element from its description.

use super::laws::build_function;
use crate::kinematics::marker::Marker;
use crate::error::ModelErrors;
use crate::force::CylinderActuator;
use crate::friction::LugreFriction;
use crate::hydraulic::{CylinderGeometry, HydraulicCylinder, SealFriction};
use crate::spec::{ranges, HydraulicCylinderSpec, Range, SealFrictionSpec};

/// The cylinder between `first` and `second`, whose attachments are
/// `initial_length` [m] apart at the positions of the description, with its
/// initial states; every problem goes to `errors` at `loc`.
pub(super) fn build_cylinder(
    spec: &HydraulicCylinderSpec,
    (first, second): (Marker, Marker),
    initial_length: f64,
    loc: &str,
    errors: &mut ModelErrors,
) -> Option<(CylinderActuator, Vec<f64>)> {
    if !Range::check_all(&cylinder_ranges(spec), loc, errors) {
        return None;
    }
    let cap_inflow = spec.cap_inflow.as_ref().map(|f| build_function(f, &format!("{loc}.cap_inflow"), errors));
    let rod_inflow = spec.rod_inflow.as_ref().map(|f| build_function(f, &format!("{loc}.rod_inflow"), errors));
    let seal = match &spec.seal_friction {
        None => Some(SealFriction::None),
        Some(s) => build_seal(s, &format!("{loc}.seal_friction"), errors),
    };
    let geometry = CylinderGeometry::new(spec.piston_area, spec.rod_side_area, spec.stroke_length, spec.cap_dead_volume, spec.rod_dead_volume)
        .map_err(|message| errors.push(loc, message))
        .ok();
    let cylinder = match (geometry, seal) {
        (Some(geometry), Some(seal)) => HydraulicCylinder::new(geometry, spec.bulk_modulus, seal).map_err(|message| errors.push(format!("{loc}.bulk_modulus"), message)).ok(),
        _ => None,
    };
    if !(spec.initial_stroke.is_finite() && (0.0..=spec.stroke_length).contains(&spec.initial_stroke)) {
        errors.push(format!("{loc}.initial_stroke"), format!("must lie within [0, stroke_length = {} m], got {} m", spec.stroke_length, spec.initial_stroke));
    }
    let retracted_length = initial_length - spec.initial_stroke;
    if !(retracted_length > 0.0) {
        errors.push(
            format!("{loc}.initial_stroke"),
            format!("the attachments are {initial_length} m apart at the start, so an initial stroke of {} m leaves no retracted length", spec.initial_stroke),
        );
    }
    let cylinder = cylinder?;
    for (name, pressure) in [("cap_pressure", spec.cap_pressure), ("rod_pressure", spec.rod_pressure)] {
        if !(pressure.is_finite() && pressure >= cylinder.pressure_floor()) {
            errors.push(format!("{loc}.{name}"), format!("must be >= {} Pa (absolute zero), got {pressure} Pa", cylinder.pressure_floor()));
        }
    }
    let states = cylinder.initial_states(spec.cap_pressure, spec.rod_pressure)[..cylinder.n_states()].to_vec();
    let element = CylinderActuator {
        first,
        second,
        cylinder,
        retracted_length,
        initial_stroke: spec.initial_stroke,
        cap_inflow: cap_inflow.flatten(),
        rod_inflow: rod_inflow.flatten(),
        spatial_attachments: None,
    };
    Some((element, states))
}

/// The ranges of a cylinder's own keys.
fn cylinder_ranges(spec: &HydraulicCylinderSpec) -> [(Range, f64); 9] {
    use ranges::*;
    [
        (FORCES_HYDRAULIC_CYLINDER_PISTON_AREA, spec.piston_area),
        (FORCES_HYDRAULIC_CYLINDER_ROD_SIDE_AREA, spec.rod_side_area),
        (FORCES_HYDRAULIC_CYLINDER_STROKE_LENGTH, spec.stroke_length),
        (FORCES_HYDRAULIC_CYLINDER_CAP_DEAD_VOLUME, spec.cap_dead_volume),
        (FORCES_HYDRAULIC_CYLINDER_ROD_DEAD_VOLUME, spec.rod_dead_volume),
        (FORCES_HYDRAULIC_CYLINDER_INITIAL_STROKE, spec.initial_stroke),
        (FORCES_HYDRAULIC_CYLINDER_CAP_PRESSURE, spec.cap_pressure),
        (FORCES_HYDRAULIC_CYLINDER_ROD_PRESSURE, spec.rod_pressure),
        (FORCES_HYDRAULIC_CYLINDER_BULK_MODULUS, spec.bulk_modulus),
    ]
}

/// The ranges of the keys of a seal's LuGre law.
fn seal_ranges(s: &SealFrictionSpec) -> [(Range, f64); 8] {
    use ranges::*;
    [
        (SEAL_FRICTION_LUGRE_SEAL_STATIC_FORCE, s.static_force),
        (SEAL_FRICTION_LUGRE_SEAL_KINETIC_FORCE, s.kinetic_force),
        (SEAL_FRICTION_LUGRE_SEAL_STRIBECK_VELOCITY, s.stribeck_velocity),
        (SEAL_FRICTION_LUGRE_SEAL_BRISTLE_STIFFNESS, s.bristle_stiffness),
        (SEAL_FRICTION_LUGRE_SEAL_BRISTLE_DAMPING, s.bristle_damping),
        (SEAL_FRICTION_LUGRE_SEAL_VISCOUS_COEFFICIENT, s.viscous_coefficient),
        (SEAL_FRICTION_LUGRE_SEAL_DAMPING_VELOCITY, s.damping_velocity),
        (SEAL_FRICTION_LUGRE_SEAL_STICK_VELOCITY, s.stick_velocity),
    ]
}

/// The words each message of [`LugreFriction`] starts with, and the key they locate.
const SEAL_KEYS: [(&str, &str); 8] = [
    ("static force", "static_force"),
    ("kinetic force", "kinetic_force"),
    ("Stribeck velocity", "stribeck_velocity"),
    ("bristle stiffness", "bristle_stiffness"),
    ("bristle damping", "bristle_damping"),
    ("viscous coefficient", "viscous_coefficient"),
    ("damping velocity", "damping_velocity"),
    ("stick velocity", "stick_velocity"),
];

fn build_seal(s: &SealFrictionSpec, loc: &str, errors: &mut ModelErrors) -> Option<SealFriction> {
    if !Range::check_all(&seal_ranges(s), loc, errors) {
        return None;
    }
    LugreFriction::new(s.static_force, s.kinetic_force, s.stribeck_velocity, s.bristle_stiffness, s.bristle_damping, s.viscous_coefficient)
        .and_then(|law| law.with_damping_velocity(s.damping_velocity))
        .and_then(|law| law.with_stick_velocity(s.stick_velocity))
        .map(SealFriction::Lugre)
        .map_err(|message| {
            let key = SEAL_KEYS.iter().find(|(words, _)| message.starts_with(words)).map(|(_, key)| *key);
            errors.push(key.map_or(loc.to_string(), |key| format!("{loc}.{key}")), message)
        })
        .ok()
}
