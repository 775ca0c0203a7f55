//! The lubricant film of a clearance joint: a film model gives the force
//! on the journal from the relative motion, and a transition law hands it
//! over to the dry contact force as the film runs out (DESIGN.md §4).
//!
//! The film force acts through the journal centre (pressure is normal to
//! the surfaces), the bearing gets the opposite force through its centre,
//! and the shear torque `T_j` acts on the journal; the massless film's
//! moment balance gives the bearing `-(T_j + e x F)`.

use crate::kinematics::planar::{cross, Frame, Vec2};
use crate::lubrication::squeeze_film::SqueezeFilm;
use crate::lubrication::transition::{LubricationRegime, TransitionLaw};
use std::sync::Arc;

use crate::lubrication::closed_form::ClosedFormBearing;
use crate::lubrication::reynolds::{ForceTable, ReynoldsOptions, ReynoldsSolver};
use crate::lubrication::{BearingGeometry, FilmForce, FilmKinematics};

/// Every film model a joint can use.
#[derive(Clone, Debug)]
pub enum FilmModel {
    /// Closed-form short or long bearing (Hamrock, Frêne et al., Pinkus-Sternlicht).
    ClosedForm(ClosedFormBearing),
    /// Squeeze film only (paper 000, after Phelan).
    SqueezeFilm(SqueezeFilm),
    /// Finite-difference Reynolds solution at every evaluation (the solver lives in the workspace).
    ReynoldsExact(ReynoldsOptions),
    /// Interpolation in dimensionless force tables precomputed by the Reynolds solver.
    ReynoldsTable(Arc<ForceTable>),
}

/// Lubricant, film model and transition law of one joint.
#[derive(Clone, Debug)]
pub struct Lubrication {
    /// Journal radius, length, clearance and viscosity.
    pub geometry: BearingGeometry,
    /// How the film force is computed.
    pub model: FilmModel,
    /// How the film force hands over to the dry contact force.
    pub transition: TransitionLaw,
}

/// One evaluation of a film.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FilmEvaluation {
    /// Film force on the journal after the transition weight, global [N].
    pub force_on_journal: Vec2,
    /// Shear torque on the journal after the transition weight [N m] (0 if the model has none).
    pub journal_torque: f64,
    /// Peak film pressure [Pa] (0 where the film carries no weight).
    pub peak_pressure: f64,
    /// Minimum film thickness `c - |e|`, 0 in contact [m].
    pub film_min: f64,
    /// Share of the film force [-].
    pub weight: f64,
    /// 0 hydrodynamic, 1 transition, 2 contact.
    pub mode: u8,
}

impl Lubrication {
    /// Film kinematics of a bearing on body frame `fi` at point `pi` and a journal on `fj` at `pj`.
    pub fn kinematics(fi: &Frame, fj: &Frame, pi: Vec2, pj: Vec2) -> FilmKinematics {
        FilmKinematics {
            eccentricity: pj - pi,
            eccentricity_rate: fj.material_velocity_at(pj) - fi.material_velocity_at(pi),
            journal_spin: fj.angular_velocity,
            bearing_spin: fi.angular_velocity,
        }
    }

    /// Film force with its transition weight. `solver` is this joint's
    /// Reynolds solver for the exact mode (from the workspace); `detailed`
    /// asks for the outputs only recorded samples need (the peak pressure).
    pub fn evaluate(&self, kinematics: &FilmKinematics, solver: Option<&mut ReynoldsSolver>, detailed: bool) -> Result<FilmEvaluation, String> {
        let eps = kinematics.eccentricity_ratio(&self.geometry);
        let weights = self.transition.weights(&self.geometry, eps);
        let mode = match self.transition.regime(&self.geometry, eps) {
            LubricationRegime::Hydrodynamic => 0,
            LubricationRegime::Transition => 1,
            LubricationRegime::Contact => 2,
        };
        let film_min = (self.geometry.clearance - kinematics.eccentricity.norm()).max(0.0);
        let mut out = FilmEvaluation { film_min, weight: weights.hydrodynamic, mode, ..Default::default() };
        if weights.hydrodynamic <= 0.0 {
            return Ok(out);
        }
        let seen = self.transition.film_kinematics(kinematics);
        let film = self.film_force(&seen, solver, detailed)?;
        let w = weights.hydrodynamic;
        out.force_on_journal = film.force_on_journal * w;
        out.journal_torque = if film.friction_torque.is_finite() { film.friction_torque * w } else { 0.0 };
        out.peak_pressure = film.peak_pressure * w;
        Ok(out)
    }

    fn film_force(&self, kinematics: &FilmKinematics, solver: Option<&mut ReynoldsSolver>, detailed: bool) -> Result<FilmForce, String> {
        match &self.model {
            FilmModel::ClosedForm(model) => Ok(model.film_force_with(&self.geometry, kinematics, detailed)),
            FilmModel::SqueezeFilm(model) => Ok(model.film_force(kinematics)),
            FilmModel::ReynoldsTable(table) => Ok(table.film_force(&self.geometry, kinematics)),
            FilmModel::ReynoldsExact(_) => match solver {
                Some(solver) => solver.solve(kinematics).map(|s| s.film_force()),
                None => Err("the Reynolds solver of this joint is missing from the workspace".to_string()),
            },
        }
    }

    /// A Reynolds solver for this joint's exact mode (None for the other models).
    pub fn new_solver(&self) -> Option<ReynoldsSolver> {
        match &self.model {
            FilmModel::ReynoldsExact(options) => ReynoldsSolver::new(self.geometry, *options).ok(),
            _ => None,
        }
    }

    /// Generalised forces of the film on the bearing and the journal, each given
    /// as its marker's frame, the marker, and the centre [m].
    pub fn apply(
        evaluation: &FilmEvaluation,
        forces: &mut crate::dynamics::GeneralisedForces,
        bearing: (&Frame, &crate::kinematics::marker::Marker, Vec2),
        journal: (&Frame, &crate::kinematics::marker::Marker, Vec2),
    ) {
        let f = evaluation.force_on_journal;
        let e = journal.2 - bearing.2;
        forces.add_point_force(journal.1, journal.0, journal.2, f);
        forces.add_point_force(bearing.1, bearing.0, bearing.2, -f);
        forces.add_moment(journal.1, evaluation.journal_torque);
        forces.add_moment(bearing.1, -(evaluation.journal_torque + cross(e, f)));
    }
}
