//! Building a beam body from its description: section, mesh and damping.

use crate::beam::{BeamMaterial, BeamSection, ElementOrder, SectionShape};
use crate::body::{BeamBody, BeamMesh};
use crate::kinematics::planar::Vec2;
use crate::error::ModelErrors;
use crate::spec::{ranges, Range, BeamMaterialSpec, BeamSectionSpec, BeamSpec, ElementOrderSpec};

/// Most elements of one beam: far beyond any link's needs, and a bound on the
/// memory a mistyped element length could ask for.
pub(super) const MAX_BEAM_ELEMENTS: usize = 2000;

/// The beam described by `spec`; every problem goes to `errors` at `loc`.
pub(in crate::dynamics) fn build_beam(spec: &BeamSpec, loc: &str, errors: &mut ModelErrors) -> Option<BeamBody> {
    let section = build_section(&spec.section, &format!("{loc}.section"), errors);
    let (start, end) = (Vec2::new(spec.start[0], spec.start[1]), Vec2::new(spec.end[0], spec.end[1]));
    let length = (end - start).norm();
    if !(length.is_finite() && length > 0.0) {
        errors.push(format!("{loc}.end"), format!("must be a finite point other than the start {:?} m, got {:?} m", spec.start, spec.end));
        return None;
    }
    let mesh = build_mesh(spec, length, &format!("{loc}.mesh"), errors);
    if !ranges::BEAMS_DAMPING_TIME.check_at(spec.damping_time, loc, errors) {
        return None;
    }
    BeamBody::straight(start, end, section?, mesh?, spec.damping_time).map_err(|message| errors.push(loc, message)).ok()
}

/// The division into elements, from their count or their largest length.
fn build_mesh(spec: &BeamSpec, length: f64, loc: &str, errors: &mut ModelErrors) -> Option<BeamMesh> {
    let order = match spec.mesh.order {
        ElementOrderSpec::Linear => ElementOrder::Linear,
        ElementOrderSpec::Quadratic => ElementOrder::Quadratic,
    };
    let elements = match (spec.mesh.elements, spec.mesh.element_length) {
        (Some(n), None) => n,
        (None, Some(h)) if ranges::BEAMS_ELEMENT_LENGTH.check_at(h, loc, errors) => ((length / h) * (1.0 - 1e-12)).ceil().min(usize::MAX as f64) as usize,
        (None, Some(_)) => return None,
        _ => {
            errors.push(loc, "give exactly one of elements (a count) and element_length");
            return None;
        }
    };
    if !(1..=MAX_BEAM_ELEMENTS).contains(&elements) {
        errors.push(loc, format!("a beam has between 1 and {MAX_BEAM_ELEMENTS} elements, got {elements}"));
        return None;
    }
    Some(BeamMesh { order, elements })
}

/// The section from resultants, from properties and a material, or from a shape and a material.
fn build_section(spec: &BeamSectionSpec, loc: &str, errors: &mut ModelErrors) -> Option<BeamSection> {
    if !Range::check_all(&section_ranges(spec), loc, errors) {
        return None;
    }
    let built = match spec {
        BeamSectionSpec::Resultants { axial_stiffness, shear_stiffness, bending_stiffness, mass_per_length, rotary_inertia_per_length } => BeamSection {
            axial_stiffness: *axial_stiffness,
            shear_stiffness: *shear_stiffness,
            bending_stiffness: *bending_stiffness,
            mass_per_length: *mass_per_length,
            rotary_inertia_per_length: *rotary_inertia_per_length,
        }
        .validated(),
        BeamSectionSpec::Properties { area, second_moment, shear_factor, material } => {
            let m = build_material(material, &format!("{loc}.material"), errors)?;
            let g = m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio));
            BeamSection {
                axial_stiffness: m.youngs_modulus * area,
                shear_stiffness: shear_factor * g * area,
                bending_stiffness: m.youngs_modulus * second_moment,
                mass_per_length: m.density * area,
                rotary_inertia_per_length: m.density * second_moment,
            }
            .validated()
        }
        BeamSectionSpec::Rectangle { width, height, material } => {
            let m = build_material(material, &format!("{loc}.material"), errors)?;
            BeamSection::of(&SectionShape::Rectangle { width: *width, height: *height }, &m)
        }
        BeamSectionSpec::Circle { diameter, material } => {
            let m = build_material(material, &format!("{loc}.material"), errors)?;
            BeamSection::of(&SectionShape::Circle { diameter: *diameter }, &m)
        }
        BeamSectionSpec::Tube { outer_diameter, inner_diameter, material } => {
            let m = build_material(material, &format!("{loc}.material"), errors)?;
            BeamSection::of(&SectionShape::Tube { outer_diameter: *outer_diameter, inner_diameter: *inner_diameter }, &m)
        }
    };
    built.map_err(|message| errors.push(loc, message)).ok()
}

/// The ranges of a section's own keys (its material is checked with it).
fn section_ranges(spec: &BeamSectionSpec) -> Vec<(Range, f64)> {
    use ranges::*;
    match *spec {
        BeamSectionSpec::Resultants { axial_stiffness, shear_stiffness, bending_stiffness, mass_per_length, rotary_inertia_per_length } => vec![
            (SECTION_RESULTANTS_AXIAL_STIFFNESS, axial_stiffness),
            (SECTION_RESULTANTS_SHEAR_STIFFNESS, shear_stiffness),
            (SECTION_RESULTANTS_BENDING_STIFFNESS, bending_stiffness),
            (SECTION_RESULTANTS_MASS_PER_LENGTH, mass_per_length),
            (SECTION_RESULTANTS_ROTARY_INERTIA_PER_LENGTH, rotary_inertia_per_length),
        ],
        BeamSectionSpec::Properties { area, second_moment, shear_factor, .. } => {
            vec![(SECTION_PROPERTIES_AREA, area), (SECTION_PROPERTIES_SECOND_MOMENT, second_moment), (SECTION_PROPERTIES_SHEAR_FACTOR, shear_factor)]
        }
        BeamSectionSpec::Rectangle { width, height, .. } => vec![(SECTION_RECTANGLE_WIDTH, width), (SECTION_RECTANGLE_HEIGHT, height)],
        BeamSectionSpec::Circle { diameter, .. } => vec![(SECTION_CIRCLE_DIAMETER, diameter)],
        BeamSectionSpec::Tube { outer_diameter, inner_diameter, .. } => vec![(SECTION_TUBE_OUTER_DIAMETER, outer_diameter), (SECTION_TUBE_INNER_DIAMETER, inner_diameter)],
    }
}

/// The material, with Poisson's ratio from the shear modulus where that is given.
fn build_material(spec: &BeamMaterialSpec, loc: &str, errors: &mut ModelErrors) -> Option<BeamMaterial> {
    let e = spec.youngs_modulus;
    let given = [(ranges::BEAM_MATERIAL_YOUNGS_MODULUS, Some(e)), (ranges::BEAM_MATERIAL_DENSITY, Some(spec.density)),
        (ranges::BEAM_MATERIAL_POISSON_RATIO, spec.poisson_ratio), (ranges::BEAM_MATERIAL_SHEAR_MODULUS, spec.shear_modulus)];
    if !Range::check_given(&given, loc, errors) {
        return None;
    }
    let poisson_ratio = match (spec.poisson_ratio, spec.shear_modulus) {
        (Some(nu), None) => nu,
        (None, Some(g)) => e / (2.0 * g) - 1.0,
        _ => {
            errors.push(loc, "give exactly one of poisson_ratio and shear_modulus");
            return None;
        }
    };
    if !ranges::BEAM_MATERIAL_POISSON_RATIO.contains(poisson_ratio) {
        let range = ranges::BEAM_MATERIAL_POISSON_RATIO.rule;
        errors.push(format!("{loc}.shear_modulus"), format!("gives Poisson's ratio E / (2 G) - 1 = {poisson_ratio}, which must {range} (E = {e} Pa)"));
        return None;
    }
    Some(BeamMaterial { youngs_modulus: e, poisson_ratio, density: spec.density })
}
