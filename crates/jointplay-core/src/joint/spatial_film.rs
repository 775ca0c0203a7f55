//! The lubricant film of the spatial clearance joint
//! (`docs/theory/spatial-clearance-revolute.md`, "Lubricated joint").
//!
//! In bearing coordinates (`z_B` the bore axis, the bore's centre at the
//! origin) the journal axis cuts the section at `z` at `e(z) = e0 + z tau`:
//! `e0` the mid-plane eccentricity, `tau` the misalignment [m/m]. With the
//! finite-difference Reynolds solver (`reynolds_exact`) the film is solved over
//! the whole length for that film ([`ReynoldsSolver::solve_misaligned`]:
//! force and moment, the half grid when aligned); every other film model (the
//! closed-form bearings, the squeeze film, the force tables) holds for aligned
//! axes and is evaluated with the mid-plane eccentricity, the tilt left out.
//! Pressure acts through the journal axis at each section, so the film's
//! moment about the bore's centre is `integral (e(z), z) x (f(z), 0) dz` plus
//! the shear torque; the bearing gets the opposite force and moment.

use super::spatial_clearance_geometry::JointPose;
use super::{FilmModel, Lubrication};
use crate::kinematics::planar::{cross, Vec2};
use crate::kinematics::spatial::Vec3;
use crate::lubrication::reynolds::misaligned::MisalignedFilmKinematics;
use crate::lubrication::reynolds::ReynoldsSolver;
use crate::lubrication::transition::LubricationRegime;
use crate::lubrication::FilmKinematics;

/// One evaluation of the film.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SpatialFilmEvaluation {
    /// Film force on the journal, after the transition weight (global) [N].
    pub force_on_journal: Vec3,
    /// Its moment on the journal about the bore's centre, shear torque included (global) [N m].
    pub moment_on_journal: Vec3,
    /// Smallest film thickness, `c - max |e(+-L/2)|`, 0 in contact [m].
    pub film_min: f64,
    /// Peak film pressure (gauge) after the transition weight [Pa].
    pub peak_pressure: f64,
    /// Share of the film force [-].
    pub weight: f64,
    /// 0 hydrodynamic, 1 transition, 2 contact.
    pub mode: u8,
}

/// The film's kinematics in bearing coordinates: the journal axis `e(z) = e0 + z tau`, their rates
/// relative to the bearing, and the two spins about the bore axis.
pub fn misaligned_kinematics(pose: &JointPose) -> MisalignedFilmKinematics {
    let (b, j) = (&pose.bearing, &pose.journal);
    // origin and axis of the journal, and their rates, in the bearing's (turning) coordinates
    let w_b = b.to_local(b.angular_velocity);
    let p = pose.journal_origin;
    let u = b.to_local(j.axis(2));
    let p_rate = b.to_local(j.velocity - b.velocity) - w_b.cross(&p);
    let u_rate = b.to_local(j.angular_velocity.cross(&j.axis(2))) - w_b.cross(&u);
    // the section z cuts the axis at p + u (z - p_z)/u_z
    let tau = u.xy() / u.z;
    let tau_rate = u_rate.xy() / u.z - u.xy() * (u_rate.z / (u.z * u.z));
    let e0 = p.xy() - tau * p.z;
    let e0_rate = p_rate.xy() - tau_rate * p.z - tau * p_rate.z;
    let z_b = b.axis(2);
    MisalignedFilmKinematics {
        eccentricity: e0,
        eccentricity_rate: e0_rate,
        misalignment: tau,
        misalignment_rate: tau_rate,
        journal_spin: j.angular_velocity.dot(&z_b),
        bearing_spin: b.angular_velocity.dot(&z_b),
    }
}

/// The film of `lubrication` at `pose` for a bearing of length `length` [m]; `solver` is the joint's
/// Reynolds solver (`reynolds_exact` only), `detailed` asks for the peak pressure of the closed forms.
pub fn evaluate(lubrication: &Lubrication, pose: &JointPose, length: f64, solver: Option<&mut ReynoldsSolver>, detailed: bool) -> Result<SpatialFilmEvaluation, String> {
    let k = misaligned_kinematics(pose);
    let mid_plane = FilmKinematics { eccentricity: k.eccentricity, eccentricity_rate: k.eccentricity_rate, journal_spin: k.journal_spin, bearing_spin: k.bearing_spin };
    let FilmModel::ReynoldsExact(_) = lubrication.model else {
        // an aligned-axes model at the mid-plane, through the journal's mid-plane centre
        let film = lubrication.evaluate(&mid_plane, None, detailed)?;
        let f = film.force_on_journal;
        return Ok(SpatialFilmEvaluation {
            force_on_journal: pose.bearing.rotate(Vec3::new(f.x, f.y, 0.0)),
            moment_on_journal: pose.bearing.rotate(Vec3::new(0.0, 0.0, cross(k.eccentricity, f) + film.journal_torque)),
            film_min: film.film_min,
            peak_pressure: film.peak_pressure,
            weight: film.weight,
            mode: film.mode,
        });
    };
    let Some(solver) = solver else { return Err("the Reynolds solver of this joint is missing from the workspace".to_string()) };
    // the transition sees the widest gap, at a rim
    let geometry = &lubrication.geometry;
    let half = 0.5 * length;
    let widest = (k.eccentricity - k.misalignment * half).norm().max((k.eccentricity + k.misalignment * half).norm());
    let eps = widest / geometry.clearance;
    let weight = lubrication.transition.weights(geometry, eps).hydrodynamic;
    let mode = match lubrication.transition.regime(geometry, eps) {
        LubricationRegime::Hydrodynamic => 0,
        LubricationRegime::Transition => 1,
        LubricationRegime::Contact => 2,
    };
    let mut out = SpatialFilmEvaluation { film_min: (geometry.clearance - widest).max(0.0), weight, mode, ..Default::default() };
    if weight <= 0.0 {
        return Ok(out);
    }
    let seen = lubrication.transition.film_kinematics(&mid_plane);
    let film = solver.solve_misaligned(&MisalignedFilmKinematics { eccentricity: seen.eccentricity, eccentricity_rate: seen.eccentricity_rate, journal_spin: seen.journal_spin, bearing_spin: seen.bearing_spin, ..k })?;
    let (f, m) = (film.force_on_journal, film.moment_on_journal);
    // integral z f dz = (m_y, -m_x): the axial moment of the pressure through the tilted axis
    let axial = cross(k.eccentricity, f) + cross(k.misalignment, Vec2::new(m.y, -m.x)) + film.friction_torque;
    out.force_on_journal = pose.bearing.rotate(Vec3::new(f.x, f.y, 0.0)) * weight;
    out.moment_on_journal = pose.bearing.rotate(Vec3::new(m.x, m.y, axial)) * weight;
    out.peak_pressure = film.peak_pressure * weight;
    Ok(out)
}

#[cfg(test)]
#[path = "spatial_film_tests.rs"]
mod tests;
