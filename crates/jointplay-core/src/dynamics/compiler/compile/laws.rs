//! Building laws and time functions from their plain-data choices.

use crate::contact::{ContactStiffness, HertzCylinder, JohnsonLine, Material, NormalForceLaw, RogersAndrews};
use crate::error::ModelErrors;
use crate::friction::{AmbrosioCoulomb, FrictionLaw, RegularisedCoulomb, StictionFriction, Threlfall};
use crate::motion::{ConstantRate, CubicStep, Polynomial, Sine, SpeedRamp, SplineTable, TimeFunction};
use crate::spec::{ranges, Range, ClearanceJointSpec, ContactSpec, FrictionSpec, FunctionSpec, MaterialSpec, StiffnessSpec};

fn material(m: &MaterialSpec) -> Material {
    Material { youngs_modulus: m.youngs_modulus, poisson_ratio: m.poisson_ratio }
}

/// Hertz exponent for metal contact.
const HERTZ_EXPONENT: f64 = 1.5;

pub(super) fn build_stiffness(c: &ClearanceJointSpec, journal_radius: f64, loc: &str, errors: &mut ModelErrors) -> Option<ContactStiffness> {
    check_materials(&c.bearing_material, &c.journal_material, loc, errors);
    if !(journal_radius > 0.0) {
        return None; // reported with the clearance
    }
    let needs_length = matches!(c.stiffness, StiffnessSpec::JohnsonLine | StiffnessSpec::RogersAndrews);
    let length = match c.length {
        Some(l) if ranges::JOINTS_CLEARANCE_REVOLUTE_LENGTH.check_at(l, loc, errors) => Some(l),
        Some(_) => None,
        None if needs_length => {
            errors.push(format!("{loc}.length"), "is required by the line-contact stiffness laws".to_string());
            None
        }
        None => None,
    };
    let bore = Bore { bore_radius: c.bearing_radius, journal_radius, length, bearing: &c.bearing_material, journal: &c.journal_material };
    build_bore_stiffness(&c.stiffness, &bore, loc, errors)
}

/// A journal in a bore, as its stiffness law needs it.
pub(super) struct Bore<'a> {
    /// Bore radius [m].
    pub bore_radius: f64,
    /// Journal radius [m].
    pub journal_radius: f64,
    /// Bearing length [m], when known (the line-contact laws need it).
    pub length: Option<f64>,
    /// Bearing material.
    pub bearing: &'a MaterialSpec,
    /// Journal material.
    pub journal: &'a MaterialSpec,
}

/// Checks the two materials of a contact, each key located at `loc.bearing_material` / `loc.journal_material`.
pub(super) fn check_materials(bearing: &MaterialSpec, journal: &MaterialSpec, loc: &str, errors: &mut ModelErrors) {
    for (m, what) in [(bearing, "bearing_material"), (journal, "journal_material")] {
        Range::check_all(&[(ranges::MATERIAL_YOUNGS_MODULUS, m.youngs_modulus), (ranges::MATERIAL_POISSON_RATIO, m.poisson_ratio)], &format!("{loc}.{what}"), errors);
    }
}

/// The stiffness law `stiffness` of the journal in `bore` (a line-contact law without a length gives `None`, reported by the caller).
pub(super) fn build_bore_stiffness(stiffness: &StiffnessSpec, bore: &Bore, loc: &str, errors: &mut ModelErrors) -> Option<ContactStiffness> {
    let (rb, rj, b, j) = (bore.bore_radius, bore.journal_radius, material(bore.bearing), material(bore.journal));
    let built = match *stiffness {
        StiffnessSpec::HertzCylinder => HertzCylinder::new(rb, rj, b, j, HERTZ_EXPONENT).map(ContactStiffness::HertzCylinder),
        StiffnessSpec::HertzCylinderExponent { exponent } if !ranges::STIFFNESS_HERTZ_CYLINDER_EXPONENT.check_at(exponent, &format!("{loc}.stiffness"), errors) => return None,
        StiffnessSpec::HertzCylinderExponent { exponent } => HertzCylinder::new(rb, rj, b, j, exponent).map(ContactStiffness::HertzCylinder),
        StiffnessSpec::JohnsonLine => JohnsonLine::new(rb, rj, bore.length?, b, j).map(ContactStiffness::JohnsonLine),
        StiffnessSpec::RogersAndrews => RogersAndrews::new(rb, rj, bore.length?, b, j).map(ContactStiffness::RogersAndrews),
    };
    built.map_err(|message| errors.push(format!("{loc}.stiffness"), message)).ok()
}

/// The effective modulus of two materials, `1/E* = (1-nu_b^2)/E_b + (1-nu_j^2)/E_j` [Pa].
pub(super) fn effective_modulus(bearing: &MaterialSpec, journal: &MaterialSpec) -> f64 {
    crate::contact::effective_modulus(&material(bearing), &material(journal))
}

pub(super) fn build_normal_force_law(c: &ContactSpec, loc: &str, errors: &mut ModelErrors) -> Option<NormalForceLaw> {
    let law = match *c {
        ContactSpec::Hertz => NormalForceLaw::Hertz,
        ContactSpec::HuntCrossley { restitution } => NormalForceLaw::HuntCrossley { restitution },
        ContactSpec::LankaraniNikravesh { restitution } => NormalForceLaw::LankaraniNikravesh { restitution },
        ContactSpec::Flores { restitution } => NormalForceLaw::Flores { restitution },
        ContactSpec::Gonthier { restitution } => NormalForceLaw::Gonthier { restitution },
        ContactSpec::HuGuo { restitution } => NormalForceLaw::HuGuo { restitution },
    };
    Range::check_all(law.restitution().as_slice(), loc, errors).then_some(law)
}

/// The ranges of a friction law's keys.
fn friction_ranges(f: &FrictionSpec) -> Vec<(Range, f64)> {
    use ranges::*;
    match *f {
        FrictionSpec::None => Vec::new(),
        FrictionSpec::Coulomb { coefficient, velocity_tolerance } => vec![(FRICTION_COULOMB_COEFFICIENT, coefficient), (FRICTION_COULOMB_VELOCITY_TOLERANCE, velocity_tolerance)],
        FrictionSpec::Ambrosio { coefficient, v0, v1 } => vec![(FRICTION_AMBROSIO_COEFFICIENT, coefficient), (FRICTION_AMBROSIO_V0, v0), (FRICTION_AMBROSIO_V1, v1)],
        FrictionSpec::Threlfall { coefficient, v0 } => vec![(FRICTION_THRELFALL_COEFFICIENT, coefficient), (FRICTION_THRELFALL_V0, v0)],
        FrictionSpec::Stiction { static_coefficient, kinetic_coefficient, stiction_velocity, transition_velocity } => vec![
            (FRICTION_STICTION_STATIC_COEFFICIENT, static_coefficient),
            (FRICTION_STICTION_KINETIC_COEFFICIENT, kinetic_coefficient),
            (FRICTION_STICTION_STICTION_VELOCITY, stiction_velocity),
            (FRICTION_STICTION_TRANSITION_VELOCITY, transition_velocity),
        ],
    }
}

pub(super) fn build_friction(f: &FrictionSpec, loc: &str, errors: &mut ModelErrors) -> Option<FrictionLaw> {
    if !Range::check_all(&friction_ranges(f), loc, errors) {
        return None;
    }
    let built = match *f {
        FrictionSpec::None => Ok(FrictionLaw::None),
        FrictionSpec::Coulomb { coefficient, velocity_tolerance } => RegularisedCoulomb::new(coefficient, velocity_tolerance).map(FrictionLaw::Coulomb),
        FrictionSpec::Ambrosio { coefficient, v0, v1 } => AmbrosioCoulomb::new(coefficient, v0, v1).map(FrictionLaw::Ambrosio),
        FrictionSpec::Threlfall { coefficient, v0 } => Threlfall::new(coefficient, v0).map(FrictionLaw::Threlfall),
        FrictionSpec::Stiction { static_coefficient, kinetic_coefficient, stiction_velocity, transition_velocity } => {
            StictionFriction::new(static_coefficient, kinetic_coefficient, stiction_velocity, transition_velocity).map(FrictionLaw::Stiction)
        }
    };
    built.map_err(|message| errors.push(loc, message)).ok()
}

pub(super) fn build_function(f: &FunctionSpec, loc: &str, errors: &mut ModelErrors) -> Option<TimeFunction> {
    let finite = |values: &[f64], errors: &mut ModelErrors| {
        let ok = values.iter().all(|v| v.is_finite());
        if !ok {
            errors.push(loc, format!("values must be finite, got {values:?}"));
        }
        ok
    };
    match f {
        FunctionSpec::Constant { value } => finite(&[*value], errors).then_some(TimeFunction::Constant(*value)),
        FunctionSpec::ConstantRate { initial, rate } => {
            finite(&[*initial, *rate], errors).then_some(TimeFunction::ConstantRate(ConstantRate { initial: *initial, rate: *rate }))
        }
        FunctionSpec::Polynomial { coefficients } => {
            finite(coefficients, errors).then(|| TimeFunction::Polynomial(Polynomial { coefficients: coefficients.clone() }))
        }
        FunctionSpec::CubicStep { t_start, t_end, value_start, value_end } => {
            if !(t_end > t_start) {
                errors.push(format!("{loc}.t_end"), format!("must be greater than t_start = {t_start} s, got {t_end} s"));
                return None;
            }
            finite(&[*t_start, *t_end, *value_start, *value_end], errors)
                .then_some(TimeFunction::CubicStep(CubicStep { t_start: *t_start, t_end: *t_end, value_start: *value_start, value_end: *value_end }))
        }
        FunctionSpec::Sine { offset, amplitude, frequency, phase } => finite(&[*offset, *amplitude, *frequency, *phase], errors)
            .then_some(TimeFunction::Sine(Sine { offset: *offset, amplitude: *amplitude, frequency: *frequency, phase: *phase })),
        FunctionSpec::SpeedRamp { ramp_time, final_rate } => {
            if !ranges::FUNCTION_SPEED_RAMP_RAMP_TIME.check_at(*ramp_time, loc, errors) {
                return None;
            }
            finite(&[*final_rate], errors).then_some(TimeFunction::SpeedRamp(SpeedRamp { ramp_time: *ramp_time, final_rate: *final_rate }))
        }
        FunctionSpec::Table { times, values } => SplineTable::new(times.clone(), values.clone())
            .map(TimeFunction::Table)
            .map_err(|message| errors.push(loc, message))
            .ok(),
    }
}
