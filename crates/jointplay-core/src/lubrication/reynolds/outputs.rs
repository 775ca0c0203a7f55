//! What a converged pressure field gives: force, torques, power, flows, peak.
//!
//! Quadrature: rectangle rule around the (periodic) circumference, trapezoid
//! rule along the half length, doubled for the other half. Friction follows
//! from the velocity profile of the thin film, shear on the journal
//! `tau_j = mu (U_b - U_j) / h - (h / 2) dp/dx`:
//! - Couette torque `T_C = mu R^3 (omega_b - omega_j) integral fill / h dtheta dz`
//!   (the full film shears the cavitated region too for Gümbel and
//!   Swift-Stieber, as Raimondi and Boyd 1958 assume; Elrod-Adams weighs it by the fill fraction);
//! - Poiseuille torque `T_P = -(R / 2) integral h dp/dtheta dtheta dz = -(e x F) / 2`
//!   (by parts, periodic), exact for the computed force;
//! - journal `T_j = T_C + T_P`, bearing `T_b = -T_C + T_P` (so `T_j + T_b + e x F = 0`).

use nalgebra::Vector2;
use std::f64::consts::PI;

use super::options::Cavitation;
use super::solver::Stencil;
use crate::lubrication::film::{BearingGeometry, FilmForce, FilmKinematics};

/// Results of one Reynolds solve (SI units, global frame of [`crate::lubrication::film`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FilmSolution {
    /// Force of the film on the journal [N].
    pub force_on_journal: Vector2<f64>,
    /// Largest pressure, gauge [Pa] (parabolic refinement around the circumference).
    pub peak_pressure: f64,
    /// Angle theta of the peak pressure [rad] in (-pi, pi].
    pub peak_pressure_angle: f64,
    /// Minimum film thickness c - |e| [m].
    pub min_film_thickness: f64,
    /// Eccentricity ratio |e| / c [-].
    pub eccentricity_ratio: f64,
    /// Attitude angle [rad]: the counter-clockwise angle from the load line
    /// (the load the film carries, `-force_on_journal`) to the line of
    /// centres `e`; positive for a journal spinning counter-clockwise in a
    /// fixed bearing; NaN when `e` or the force is zero.
    pub attitude_angle: f64,
    /// Shear torque on the journal about its centre, counter-clockwise positive [N m].
    pub friction_torque: f64,
    /// Shear torque on the bearing about its centre, counter-clockwise positive [N m].
    pub bearing_friction_torque: f64,
    /// Power lost in the film, `-(T_j omega_j + T_b omega_b)` [W].
    pub power_loss: f64,
    /// Net flow out through both ends [m^3/s].
    pub side_leakage: f64,
    /// Flow from the groove into the film (0 without a groove) [m^3/s].
    pub groove_inflow: f64,
    /// Circumferential flow across the axial line of largest film thickness,
    /// positive along +theta (Raimondi and Boyd's flow into the loaded film) [m^3/s].
    pub circumferential_flow: f64,
    /// Relaxation sweeps used [-].
    pub iterations: usize,
}

impl FilmSolution {
    /// The part every film model returns.
    pub fn film_force(&self) -> FilmForce {
        FilmForce {
            force_on_journal: self.force_on_journal,
            peak_pressure: self.peak_pressure,
            peak_pressure_angle: self.peak_pressure_angle,
            friction_torque: self.friction_torque,
        }
    }
}

/// What [`evaluate`] reads from the solver.
pub struct Parts<'a> {
    /// Bearing geometry.
    pub geometry: &'a BearingGeometry,
    /// Cavitation model used.
    pub cavitation: Cavitation,
    /// Coefficients of the solved state.
    pub stencil: &'a Stencil,
    /// Converged pressure [Pa].
    pub pressure: &'a [f64],
    /// Fill fraction [-].
    pub fill: &'a [f64],
}

/// Trapezoid weight of row `j` on the half length [m].
#[inline]
fn axial_weight(s: &Stencil, j: usize) -> f64 {
    if j == 0 || j + 1 == s.n_half { 0.5 * s.dz } else { s.dz }
}

/// All outputs of a converged field.
pub fn evaluate(parts: Parts<'_>, k: &FilmKinematics, iterations: usize) -> FilmSolution {
    let (g, s, p) = (parts.geometry, parts.stencil, parts.pressure);
    let (r, c, mu) = (g.radius, g.clearance, g.viscosity);
    let elrod = parts.cavitation == Cavitation::ElrodAdams;
    let nz = s.n_half;
    // force and the Couette integral of fill / H
    let (mut fx, mut fy, mut couette) = (0.0, 0.0, 0.0);
    for i in 0..s.n_theta {
        let (sn, cs) = (i as f64 * s.dtheta).sin_cos();
        let (mut col, mut film) = (0.0, 0.0);
        for j in 0..nz {
            let w = axial_weight(s, j);
            col += w * p[i * nz + j];
            film += w * if elrod { parts.fill[i * nz + j] } else { 1.0 };
        }
        fx += col * cs;
        fy += col * sn;
        couette += film / s.h_node[i];
    }
    let area = 2.0 * s.dtheta;
    let force = Vector2::new(-fx, -fy) * (area * r);
    let e = k.eccentricity;
    let e_cross_f = e.x * force.y - e.y * force.x;
    let t_couette = mu * r.powi(3) * (k.bearing_spin - k.journal_spin) * couette * area / c;
    let t_poiseuille = -0.5 * e_cross_f;
    let (t_j, t_b) = (t_couette + t_poiseuille, -t_couette + t_poiseuille);
    let (peak, peak_angle) = peak(s, p);
    FilmSolution {
        force_on_journal: force,
        peak_pressure: peak,
        peak_pressure_angle: peak_angle,
        min_film_thickness: c - e.norm(),
        eccentricity_ratio: e.norm() / c,
        attitude_angle: attitude(&e, &force),
        friction_torque: t_j,
        bearing_friction_torque: t_b,
        power_loss: -(t_j * k.journal_spin + t_b * k.bearing_spin),
        side_leakage: side_leakage(&parts),
        groove_inflow: groove_inflow(&parts),
        circumferential_flow: circumferential_flow(&parts, &e),
        iterations,
    }
}

/// Counter-clockwise angle from the load `-F` to `e` [rad]; NaN if either is zero.
fn attitude(e: &Vector2<f64>, force: &Vector2<f64>) -> f64 {
    if e.norm() == 0.0 || force.norm() == 0.0 {
        return f64::NAN;
    }
    let load = -force;
    (load.x * e.y - load.y * e.x).atan2(load.dot(e))
}

/// Largest pressure and its angle, refined by a parabola through the three nodes around it.
fn peak(s: &Stencil, p: &[f64]) -> (f64, f64) {
    let (value, angle, _) = peak_on_grid(p, s.n_theta, s.n_half, s.dtheta);
    (value, angle)
}

/// Largest pressure of a field `p[i * n_rows + j]` over `n_theta` columns `dtheta`
/// apart [rad], its angle in (-pi, pi] refined by the parabola through the three
/// nodes around it, and its row `j`.
pub(super) fn peak_on_grid(p: &[f64], n_theta: usize, n_rows: usize, dtheta: f64) -> (f64, f64, usize) {
    let (mut best, mut at) = (f64::NEG_INFINITY, 0);
    for (n, v) in p.iter().enumerate() {
        if *v > best {
            best = *v;
            at = n;
        }
    }
    let (i, j) = (at / n_rows, at % n_rows);
    let im = if i == 0 { n_theta - 1 } else { i - 1 };
    let ip = if i + 1 == n_theta { 0 } else { i + 1 };
    let (pm, p0, pp) = (p[im * n_rows + j], best, p[ip * n_rows + j]);
    let curvature = pm - 2.0 * p0 + pp;
    let (shift, value) = if curvature < 0.0 {
        let d = 0.5 * (pm - pp) / curvature;
        (d, p0 - 0.25 * (pm - pp) * d)
    } else {
        (0.0, p0)
    };
    let mut angle = (i as f64 + shift) * dtheta;
    if angle > PI {
        angle -= 2.0 * PI;
    }
    (value, angle, j)
}

/// Couette divergence plus squeeze rate at full film in column `i`, as a velocity [m/s]:
/// `d/dx (U h / 2) + dh/dt` (the in-plane source of a half cell next to a fixed row).
fn full_film_source(s: &Stencil, c: f64, i: usize) -> f64 {
    let im = if i == 0 { s.n_theta - 1 } else { i - 1 };
    c * (0.5 * s.spin_sum * (s.h_face[i] - s.h_face[im]) / s.dtheta + s.h_rate[i])
}

/// Net flow out through both ends [m^3/s]: face flux next to the end row
/// plus the half cell's mass balance (second order, conservative). For
/// Gümbel and Swift-Stieber the balance holds only where the film carries
/// pressure, so the half-cell term is dropped in ruptured columns.
fn side_leakage(parts: &Parts<'_>) -> f64 {
    let (g, s, p) = (parts.geometry, parts.stencil, parts.pressure);
    let (c, mu, nz) = (g.clearance, g.viscosity, s.n_half);
    let mass_conserving = parts.cavitation == Cavitation::ElrodAdams;
    let mut total = 0.0;
    for i in 0..s.n_theta {
        let h3 = c.powi(3) * s.h3_node[i];
        let inner = p[i * nz + nz - 2];
        let face = -h3 / (12.0 * mu) * (p[i * nz + nz - 1] - inner) / s.dz;
        let film = mass_conserving || inner > p[i * nz + nz - 1];
        total += face - if film { 0.5 * s.dz * full_film_source(s, c, i) } else { 0.0 };
    }
    2.0 * total * g.radius * s.dtheta
}

/// Flow from the groove into the film on both sides [m^3/s] (0 without a groove).
fn groove_inflow(parts: &Parts<'_>) -> f64 {
    let (g, s, p) = (parts.geometry, parts.stencil, parts.pressure);
    if s.j_free == 0 {
        return 0.0;
    }
    let (c, mu, nz, jg) = (g.clearance, g.viscosity, s.n_half, s.j_free - 1);
    let mut total = 0.0;
    for i in 0..s.n_theta {
        let h3 = c.powi(3) * s.h3_node[i];
        let face = -h3 / (12.0 * mu) * (p[i * nz + jg + 1] - p[i * nz + jg]) / s.dz;
        total += face + 0.5 * s.dz * full_film_source(s, c, i);
    }
    2.0 * total * g.radius * s.dtheta
}

/// Flow along +theta across the face nearest the largest film thickness [m^3/s].
fn circumferential_flow(parts: &Parts<'_>, e: &Vector2<f64>) -> f64 {
    let (g, s, p) = (parts.geometry, parts.stencil, parts.pressure);
    let (r, c, mu, nz) = (g.radius, g.clearance, g.viscosity, s.n_half);
    let thickest = (-e.y).atan2(-e.x).rem_euclid(2.0 * PI);
    let f = ((thickest / s.dtheta - 0.5).round() as isize).rem_euclid(s.n_theta as isize) as usize;
    let fp = if f + 1 == s.n_theta { 0 } else { f + 1 };
    let upwind = if s.spin_sum >= 0.0 { f } else { fp };
    let h = c * s.h_face[f];
    let mut total = 0.0;
    for j in 0..nz {
        let fill = if parts.cavitation == Cavitation::ElrodAdams { parts.fill[upwind * nz + j] } else { 1.0 };
        let couette = 0.5 * r * s.spin_sum * h * fill;
        let poiseuille = -h.powi(3) / (12.0 * mu * r) * (p[fp * nz + j] - p[f * nz + j]) / s.dtheta;
        total += axial_weight(s, j) * (couette + poiseuille);
    }
    2.0 * total
}
