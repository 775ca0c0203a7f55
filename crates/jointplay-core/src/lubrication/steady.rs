//! Steady journal bearing analysis in the variables of Raimondi and Boyd (1958).
//!
//! Full 360 degree bearing, both ends at ambient pressure (0 gauge), no
//! circumferential groove, fed at ambient pressure along the line of largest
//! film thickness, Swift-Stieber (Reynolds) cavitation, as Raimondi and Boyd used,
//! journal spinning at N rev/s in a fixed bearing, no squeeze. Everything is
//! computed on a canonical bearing (R = c = mu = N = 1, L = 2 L/D) and is
//! dimensionless; [`SteadyBearing::dimensional`] scales it for a real bearing:
//! load `W = mu N (R/c)^2 R L w(eps)`, so `S = (R/c)^2 mu N / P = 2 / w`
//! with `P = W / (L D)`.

use nalgebra::Vector2;
use std::f64::consts::PI;

use super::film::{BearingGeometry, FilmKinematics};
use super::reynolds::{Cavitation, ReynoldsOptions, ReynoldsSolver};

/// Smallest eccentricity ratio the load search accepts [-].
pub const MIN_ECCENTRICITY_RATIO: f64 = 1e-4;
/// Largest eccentricity ratio the load search accepts (the default grid resolves the film up to about here) [-].
pub const MAX_ECCENTRICITY_RATIO: f64 = 0.97;

/// Dimensionless steady operating point (Raimondi-Boyd variables).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadyBearing {
    /// Length over diameter L/D [-].
    pub length_over_diameter: f64,
    /// Eccentricity ratio eps = e / c [-].
    pub eccentricity_ratio: f64,
    /// Attitude angle: from the load line to the line of centres, in the direction of rotation [rad].
    pub attitude_angle: f64,
    /// Sommerfeld number S = (R/c)^2 mu N / P [-].
    pub sommerfeld_number: f64,
    /// Minimum film thickness over clearance h0 / c = 1 - eps [-].
    pub min_film_thickness_ratio: f64,
    /// Friction variable (R/c) f, f = (|journal torque| / R) / W [-].
    pub friction_variable: f64,
    /// Flow variable Q / (R c N L), Q the circumferential flow into the film at its thickest line [-].
    pub flow_variable: f64,
    /// Side-flow ratio Q_s / Q (side leakage over inflow) [-].
    pub side_flow_ratio: f64,
    /// Mean over peak pressure P / p_max [-].
    pub pressure_ratio: f64,
    /// Angle of the peak pressure ahead of the minimum film, against the rotation [rad].
    pub peak_pressure_angle: f64,
}

/// Dimensional outputs of a steady operating point (SI units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadyDimensional {
    /// Load W [N].
    pub load: f64,
    /// Mean pressure P = W / (L D) [Pa].
    pub mean_pressure: f64,
    /// Minimum film thickness h0 [m].
    pub min_film_thickness: f64,
    /// Peak pressure p_max [Pa].
    pub peak_pressure: f64,
    /// Friction torque on the journal (magnitude) [N m].
    pub friction_torque: f64,
    /// Friction coefficient f [-].
    pub friction_coefficient: f64,
    /// Power loss, torque times spin [W].
    pub power_loss: f64,
    /// Inflow Q [m^3/s].
    pub flow: f64,
    /// Side leakage Q_s [m^3/s].
    pub side_flow: f64,
}

impl SteadyBearing {
    /// Scales the point to a bearing of `geometry` spinning at `speed` [rev/s].
    pub fn dimensional(&self, geometry: &BearingGeometry, speed: f64) -> SteadyDimensional {
        let (r, l, c, mu) = (geometry.radius, geometry.length, geometry.clearance, geometry.viscosity);
        let mean_pressure = (r / c).powi(2) * mu * speed / self.sommerfeld_number;
        let load = mean_pressure * l * 2.0 * r;
        let friction_coefficient = self.friction_variable * c / r;
        let friction_torque = friction_coefficient * load * r;
        let flow = self.flow_variable * r * c * speed * l;
        SteadyDimensional {
            load,
            mean_pressure,
            min_film_thickness: c * self.min_film_thickness_ratio,
            peak_pressure: mean_pressure / self.pressure_ratio,
            friction_torque,
            friction_coefficient,
            power_loss: friction_torque * 2.0 * PI * speed,
            flow,
            side_flow: flow * self.side_flow_ratio,
        }
    }
}

/// Steady point at eccentricity ratio `eccentricity_ratio` [-] for `length_over_diameter` [-].
/// `options` give the grid and tolerance; cavitation, ambient pressure, groove and feed line are overridden.
pub fn steady_at_eccentricity(length_over_diameter: f64, eccentricity_ratio: f64, options: &ReynoldsOptions) -> Result<SteadyBearing, String> {
    let mut solver = canonical_solver(length_over_diameter, options)?;
    point(&mut solver, length_over_diameter, eccentricity_ratio)
}

/// Steady point carrying `load` [N] in `geometry` at `speed` [rev/s]: bisection on eps
/// (the Sommerfeld number falls monotonically with eps) to 1e-9 in `-ln(1 - eps)`.
pub fn steady_for_load(load: f64, geometry: &BearingGeometry, speed: f64, options: &ReynoldsOptions) -> Result<SteadyBearing, String> {
    for (name, v) in [("load", load), ("speed", speed)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(format!("{name} must be positive and finite, got {v}"));
        }
    }
    let lod = geometry.length / (2.0 * geometry.radius);
    let target = (geometry.radius / geometry.clearance).powi(2) * geometry.viscosity * speed * geometry.length * 2.0 * geometry.radius / load;
    let mut solver = canonical_solver(lod, options)?;
    let mut eval = |s: f64| point(&mut solver, lod, 1.0 - (-s).exp());
    let (mut lo, mut hi) = (-(1.0 - MIN_ECCENTRICITY_RATIO).ln(), -(1.0 - MAX_ECCENTRICITY_RATIO).ln());
    let (low_end, high_end) = (eval(lo)?, eval(hi)?);
    if target > low_end.sommerfeld_number {
        return Err(format!("load {load} N is too light: Sommerfeld number {target:.4e} above {:.4e} (eccentricity ratio < {MIN_ECCENTRICITY_RATIO})", low_end.sommerfeld_number));
    }
    if target < high_end.sommerfeld_number {
        return Err(format!("load {load} N is too heavy: Sommerfeld number {target:.4e} below {:.4e} (eccentricity ratio > {MAX_ECCENTRICITY_RATIO})", high_end.sommerfeld_number));
    }
    while hi - lo > 1e-9 {
        let mid = 0.5 * (lo + hi);
        if eval(mid)?.sommerfeld_number > target { lo = mid } else { hi = mid }
    }
    eval(0.5 * (lo + hi))
}

/// Solver on the canonical bearing R = c = mu = 1, L = 2 L/D, Swift-Stieber, ambient 0.
fn canonical_solver(length_over_diameter: f64, options: &ReynoldsOptions) -> Result<ReynoldsSolver, String> {
    if !(length_over_diameter.is_finite() && length_over_diameter > 0.0) {
        return Err(format!("length_over_diameter must be positive and finite, got {length_over_diameter}"));
    }
    let geometry = BearingGeometry { radius: 1.0, length: 2.0 * length_over_diameter, clearance: 1.0, viscosity: 1.0 };
    let options = ReynoldsOptions { cavitation: Cavitation::SwiftStieber, ambient_pressure: 0.0, groove: None, feed_at_thickest_film: true, ..*options };
    ReynoldsSolver::new(geometry, options)
}

/// One canonical solve at eps (e along +x, journal at 1 rev/s counter-clockwise).
fn point(solver: &mut ReynoldsSolver, lod: f64, eps: f64) -> Result<SteadyBearing, String> {
    if !(eps.is_finite() && eps > 0.0 && eps < 1.0) {
        return Err(format!("eccentricity_ratio must be in (0, 1), got {eps}"));
    }
    let kin = FilmKinematics { eccentricity: Vector2::new(eps, 0.0), eccentricity_rate: Vector2::zeros(), journal_spin: 2.0 * PI, bearing_spin: 0.0 };
    let sol = solver.solve(&kin)?;
    let length = 2.0 * lod;
    let load = sol.force_on_journal.norm();
    let mean_pressure = load / (2.0 * length);
    let mut peak_angle = -sol.peak_pressure_angle;
    if peak_angle < -PI {
        peak_angle += 2.0 * PI;
    }
    Ok(SteadyBearing {
        length_over_diameter: lod,
        eccentricity_ratio: eps,
        attitude_angle: sol.attitude_angle,
        sommerfeld_number: 1.0 / mean_pressure,
        min_film_thickness_ratio: 1.0 - eps,
        friction_variable: sol.friction_torque.abs() / load,
        flow_variable: sol.circumferential_flow / length,
        side_flow_ratio: sol.side_leakage / sol.circumferential_flow,
        pressure_ratio: mean_pressure / sol.peak_pressure,
        peak_pressure_angle: peak_angle,
    })
}
