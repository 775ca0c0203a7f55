//! Building the lubricant film of a clearance joint from its description.

use crate::error::ModelErrors;
use crate::joint::{FilmModel, Lubrication};
use crate::lubrication::closed_form::ClosedFormBearing;
use crate::lubrication::squeeze_film::{SqueezeFilm, SqueezeFilmTheory};
use crate::lubrication::transition::TransitionLaw;
use crate::lubrication::BearingGeometry;
use crate::spec::{ClearanceJointSpec, FilmModelSpec, LubricationSpec, TransitionSpec};

pub(super) fn build_lubrication(
    c: &ClearanceJointSpec,
    spec: &LubricationSpec,
    journal_radius: f64,
    loc: &str,
    errors: &mut ModelErrors,
) -> Option<Lubrication> {
    let loc = format!("{loc}.lubrication");
    if !(spec.viscosity.is_finite() && spec.viscosity > 0.0) {
        errors.push(format!("{loc}.viscosity"), format!("must be > 0, got {} Pa s", spec.viscosity));
    }
    let length = match c.length {
        Some(l) if l.is_finite() && l > 0.0 => l,
        _ => {
            errors.push(format!("{loc}"), "a lubricated joint needs the bearing length (joints.<name>.length)".to_string());
            return None;
        }
    };
    let geometry = BearingGeometry { radius: journal_radius, length, clearance: c.clearance, viscosity: spec.viscosity };
    let transition = build_transition(&spec.transition, &geometry, &loc, errors)?;
    let model = match spec.model {
        FilmModelSpec::SqueezeFilmShort => FilmModel::SqueezeFilm(SqueezeFilm::new(geometry, SqueezeFilmTheory::ShortBearing)),
        FilmModelSpec::SqueezeFilmLong => FilmModel::SqueezeFilm(SqueezeFilm::new(geometry, SqueezeFilmTheory::LongBearing)),
        FilmModelSpec::HamrockShort => FilmModel::ClosedForm(ClosedFormBearing::HamrockShort),
        FilmModelSpec::HamrockLong => FilmModel::ClosedForm(ClosedFormBearing::HamrockLong),
        FilmModelSpec::FreneShort => FilmModel::ClosedForm(ClosedFormBearing::FreneShort),
        FilmModelSpec::FreneLong => FilmModel::ClosedForm(ClosedFormBearing::FreneLong),
        FilmModelSpec::PinkusSternlichtLong => FilmModel::ClosedForm(ClosedFormBearing::PinkusSternlichtLong),
        FilmModelSpec::ReynoldsExact | FilmModelSpec::ReynoldsTable => {
            errors.push(format!("{loc}.model"), "the Reynolds film models are not available yet".to_string());
            return None;
        }
    };
    errors.is_empty().then_some(Lubrication { geometry, model, transition })
}

fn build_transition(t: &TransitionSpec, geometry: &BearingGeometry, loc: &str, errors: &mut ModelErrors) -> Option<TransitionLaw> {
    match *t {
        TransitionSpec::Switch => Some(TransitionLaw::Switch),
        TransitionSpec::Flores { lubricated_limit } => {
            if !(lubricated_limit > 0.0 && lubricated_limit < 1.0) {
                errors.push(format!("{loc}.transition.lubricated_limit"), format!("must lie in (0, 1), got {lubricated_limit}"));
                return None;
            }
            Some(TransitionLaw::Flores { lubricated_limit })
        }
        TransitionSpec::WangImproved { safe_film_thickness: None } => Some(TransitionLaw::wang_improved(geometry)),
        TransitionSpec::WangImproved { safe_film_thickness: Some(h) } => {
            if !(h > 0.0 && h < geometry.clearance) {
                errors.push(
                    format!("{loc}.transition.safe_film_thickness"),
                    format!("must lie between 0 and the clearance {} m, got {h} m", geometry.clearance),
                );
                return None;
            }
            Some(TransitionLaw::WangImproved { safe_film_thickness: h })
        }
    }
}
