//! Building the lubricant film of a clearance joint from its description.

use std::sync::{Arc, Mutex, OnceLock};

use crate::error::ModelErrors;
use crate::joint::{FilmModel, Lubrication};
use crate::lubrication::closed_form::ClosedFormBearing;
use crate::lubrication::reynolds::{Cavitation, ForceTable, ForceTableOptions, Groove, ReynoldsOptions, ReynoldsSolver};
use crate::lubrication::squeeze_film::{SqueezeFilm, SqueezeFilmTheory};
use crate::lubrication::transition::TransitionLaw;
use crate::lubrication::BearingGeometry;
use crate::spec::{ranges, Range, CavitationSpec, ClearanceJointSpec, FilmModelSpec, LubricationSpec, ReynoldsSpec, TransitionSpec};

pub(super) fn build_lubrication(
    c: &ClearanceJointSpec,
    spec: &LubricationSpec,
    journal_radius: f64,
    loc: &str,
    errors: &mut ModelErrors,
) -> Option<Lubrication> {
    build_film(spec, BearingSize { journal_radius, clearance: c.clearance, length: c.length }, loc, errors)
}

/// The size of a lubricated bearing: journal radius, radial clearance and length (if given) [m].
pub(super) struct BearingSize {
    pub journal_radius: f64,
    pub clearance: f64,
    pub length: Option<f64>,
}

/// The film `spec` of a bearing of `size`, its problems located under `loc.lubrication`.
pub(super) fn build_film(spec: &LubricationSpec, size: BearingSize, loc: &str, errors: &mut ModelErrors) -> Option<Lubrication> {
    let BearingSize { journal_radius, clearance, length } = size;
    let loc = format!("{loc}.lubrication");
    ranges::LUBRICATION_VISCOSITY.check_at(spec.viscosity, &loc, errors);
    let reynolds = [(ranges::LUBRICATION_AMBIENT_PRESSURE, Some(spec.reynolds.ambient_pressure)), (ranges::LUBRICATION_GROOVE_SUPPLY_PRESSURE, spec.reynolds.groove_supply_pressure)];
    if !Range::check_given(&reynolds, &format!("{loc}.reynolds"), errors) {
        return None;
    }
    let length = match length {
        Some(l) if l.is_finite() && l > 0.0 => l,
        _ => {
            errors.push(format!("{loc}"), "a lubricated joint needs the bearing length (joints.<name>.length)".to_string());
            return None;
        }
    };
    let geometry = BearingGeometry { radius: journal_radius, length, clearance, viscosity: spec.viscosity };
    let transition = build_transition(&spec.transition, &geometry, &loc, errors)?;
    let model = match spec.model {
        FilmModelSpec::SqueezeFilmShort => FilmModel::SqueezeFilm(SqueezeFilm::new(geometry, SqueezeFilmTheory::ShortBearing)),
        FilmModelSpec::SqueezeFilmLong => FilmModel::SqueezeFilm(SqueezeFilm::new(geometry, SqueezeFilmTheory::LongBearing)),
        FilmModelSpec::HamrockShort => FilmModel::ClosedForm(ClosedFormBearing::HamrockShort),
        FilmModelSpec::HamrockLong => FilmModel::ClosedForm(ClosedFormBearing::HamrockLong),
        FilmModelSpec::FreneShort => FilmModel::ClosedForm(ClosedFormBearing::FreneShort),
        FilmModelSpec::FreneLong => FilmModel::ClosedForm(ClosedFormBearing::FreneLong),
        FilmModelSpec::PinkusSternlichtLong => FilmModel::ClosedForm(ClosedFormBearing::PinkusSternlichtLong),
        FilmModelSpec::ReynoldsExact => {
            let options = reynolds_options(&spec.reynolds, &loc, errors)?;
            // build one solver now so that a bad set-up is a model error, not a run-time failure
            if let Err(message) = ReynoldsSolver::new(geometry, options) {
                errors.push(format!("{loc}.reynolds"), message);
                return None;
            }
            FilmModel::ReynoldsExact(options)
        }
        FilmModelSpec::ReynoldsTable => {
            let r = &spec.reynolds;
            if r.cavitation == CavitationSpec::ElrodAdams || r.groove_supply_pressure.is_some() || r.ambient_pressure != 0.0 {
                errors.push(
                    format!("{loc}.model"),
                    "force tables cover Gumbel and Swift-Stieber cavitation with ambient ends and no groove; use reynolds_exact".to_string(),
                );
                return None;
            }
            let options = reynolds_options(r, &loc, errors)?;
            match cached_table(length / (2.0 * journal_radius), options) {
                Ok(table) => FilmModel::ReynoldsTable(table),
                Err(message) => {
                    errors.push(format!("{loc}.reynolds"), message);
                    return None;
                }
            }
        }
    };
    errors.is_empty().then_some(Lubrication { geometry, model, transition })
}

fn reynolds_options(spec: &ReynoldsSpec, loc: &str, errors: &mut ModelErrors) -> Option<ReynoldsOptions> {
    let defaults = ReynoldsOptions::default();
    let options = ReynoldsOptions {
        n_circumferential: spec.n_circumferential.unwrap_or(defaults.n_circumferential),
        n_axial: spec.n_axial.unwrap_or(defaults.n_axial),
        cavitation: match spec.cavitation {
            CavitationSpec::Gumbel => Cavitation::Gumbel,
            CavitationSpec::SwiftStieber => Cavitation::SwiftStieber,
            CavitationSpec::ElrodAdams => Cavitation::ElrodAdams,
        },
        ambient_pressure: spec.ambient_pressure,
        // paper 000: the supply pressure holds on the mid-plane z = 0 (a line groove)
        groove: spec.groove_supply_pressure.map(|p| Groove { supply_pressure: p, width: 0.0 }),
        ..defaults
    };
    if options.cavitation == Cavitation::ElrodAdams && options.groove.is_none() && options.ambient_pressure <= 0.0 {
        errors.push(
            format!("{loc}.cavitation"),
            "elrod_adams (mass-conserving) needs a lubricant supply: set groove_supply_pressure or an ambient_pressure > 0".to_string(),
        );
        return None;
    }
    // the grid first, at its key in the model file, before a solver allocates it
    if let Err(message) = options.validate_grid() {
        errors.push(format!("{loc}.grid"), message);
        return None;
    }
    match options.validate() {
        Ok(()) => Some(options),
        Err(message) => {
            errors.push(format!("{loc}.reynolds"), message);
            None
        }
    }
}

/// Force tables already built in this process, by L/D and solver options: a
/// parameter study compiles the same bearing many times and a table takes seconds.
fn cached_table(length_over_diameter: f64, solver: ReynoldsOptions) -> Result<Arc<ForceTable>, String> {
    static TABLES: OnceLock<Mutex<Vec<(f64, ReynoldsOptions, Arc<ForceTable>)>>> = OnceLock::new();
    let tables = TABLES.get_or_init(|| Mutex::new(Vec::new()));
    let mut tables = tables.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    if let Some((_, _, table)) = tables.iter().find(|(ratio, options, _)| *ratio == length_over_diameter && *options == solver) {
        return Ok(Arc::clone(table));
    }
    let table = Arc::new(ForceTable::build(length_over_diameter, &ForceTableOptions { solver, ..Default::default() })?);
    tables.push((length_over_diameter, solver, Arc::clone(&table)));
    Ok(table)
}

fn build_transition(t: &TransitionSpec, geometry: &BearingGeometry, loc: &str, errors: &mut ModelErrors) -> Option<TransitionLaw> {
    match *t {
        TransitionSpec::Switch => Some(TransitionLaw::Switch),
        TransitionSpec::Flores { lubricated_limit } => {
            if !ranges::TRANSITION_FLORES_LUBRICATED_LIMIT.check_at(lubricated_limit, &format!("{loc}.transition"), errors) {
                return None;
            }
            Some(TransitionLaw::Flores { lubricated_limit })
        }
        TransitionSpec::WangImproved { safe_film_thickness: None } => Some(TransitionLaw::wang_improved(geometry)),
        TransitionSpec::WangImproved { safe_film_thickness: Some(h) } => {
            if !ranges::TRANSITION_WANG_IMPROVED_SAFE_FILM_THICKNESS.check_at(h, &format!("{loc}.transition"), errors) {
                return None;
            }
            if h >= geometry.clearance {
                errors.push(
                    format!("{loc}.transition.safe_film_thickness"),
                    format!("must be smaller than the clearance {} m, got {h} m", geometry.clearance),
                );
                return None;
            }
            Some(TransitionLaw::WangImproved { safe_film_thickness: h })
        }
    }
}
