//! What a converged full-length field gives: force, moment, friction torques, peak.
//!
//! Quadrature: rectangle rule around the (periodic) circumference, trapezoid
//! rule along the full length. Per row, the force per unit length
//! `f(z) = -R integral p u(theta) dtheta` [N/m]; then
//! - force `F = integral f dz`;
//! - moment about the bearing's centre `M = integral (z e_z) x f dz = (-integral z f_y dz, integral z f_x dz)`;
//! - friction torques as in [`super::outputs`], with the Poiseuille part
//!   `T_P = -(1/2) integral e(z) x f(z) dz` (the by-parts identity row by row).

use nalgebra::Vector2;

use super::full_length::FullStencil;
use super::misaligned::{MisalignedFilmKinematics, MisalignedFilmSolution};
use super::options::Cavitation;
use crate::lubrication::film::BearingGeometry;

/// What [`evaluate`] reads from the solver.
pub struct Parts<'a> {
    /// Bearing geometry.
    pub geometry: &'a BearingGeometry,
    /// Cavitation model used.
    pub cavitation: Cavitation,
    /// Coefficients of the solved state.
    pub stencil: &'a FullStencil,
    /// Converged pressure [Pa].
    pub pressure: &'a [f64],
    /// Fill fraction [-].
    pub fill: &'a [f64],
}

/// Trapezoid weight of row `j` on the full length [m].
#[inline]
fn axial_weight(s: &FullStencil, j: usize) -> f64 {
    if j == 0 || j + 1 == s.n_rows { 0.5 * s.dz } else { s.dz }
}

/// Force per unit length of row `j` on the journal [N/m] and its Couette integral of fill / H [-].
fn row_integrals(parts: &Parts<'_>, j: usize) -> (Vector2<f64>, f64) {
    let (s, p) = (parts.stencil, parts.pressure);
    let elrod = parts.cavitation == Cavitation::ElrodAdams;
    let (mut fx, mut fy, mut couette) = (0.0, 0.0, 0.0);
    for i in 0..s.n_theta {
        let n = i * s.n_rows + j;
        let (sn, cs) = (i as f64 * s.dtheta).sin_cos();
        fx += p[n] * cs;
        fy += p[n] * sn;
        couette += if elrod { parts.fill[n] } else { 1.0 } / s.h_node[n];
    }
    (Vector2::new(-fx, -fy) * (parts.geometry.radius * s.dtheta), couette * s.dtheta)
}

/// All outputs of a converged field.
pub fn evaluate(parts: Parts<'_>, k: &MisalignedFilmKinematics, iterations: usize) -> MisalignedFilmSolution {
    let (g, s) = (parts.geometry, parts.stencil);
    let (r, c, mu) = (g.radius, g.clearance, g.viscosity);
    let (mut force, mut moment) = (Vector2::zeros(), Vector2::zeros());
    let (mut couette, mut e_cross_f) = (0.0, 0.0);
    for j in 0..s.n_rows {
        let (w, z) = (axial_weight(s, j), s.z(j));
        let (f, film) = row_integrals(&parts, j);
        let e = k.eccentricity_at(z);
        force += f * w;
        moment += Vector2::new(-z * f.y, z * f.x) * w;
        couette += film * w;
        e_cross_f += (e.x * f.y - e.y * f.x) * w;
    }
    let t_couette = mu * r.powi(3) * (k.bearing_spin - k.journal_spin) * couette / c;
    let t_poiseuille = -0.5 * e_cross_f;
    let (t_j, t_b) = (t_couette + t_poiseuille, -t_couette + t_poiseuille);
    let (peak, angle, position) = peak(s, parts.pressure);
    let half = 0.5 * g.length;
    let largest = k.eccentricity_at(-half).norm().max(k.eccentricity_at(half).norm());
    MisalignedFilmSolution {
        force_on_journal: force,
        moment_on_journal: moment,
        peak_pressure: peak,
        peak_pressure_angle: angle,
        peak_pressure_position: position,
        min_film_thickness: c - largest,
        friction_torque: t_j,
        bearing_friction_torque: t_b,
        power_loss: -(t_j * k.journal_spin + t_b * k.bearing_spin),
        iterations,
    }
}

/// Largest pressure, its angle (parabola through the three nodes around it) and its axial position.
fn peak(s: &FullStencil, p: &[f64]) -> (f64, f64, f64) {
    let (value, angle, j) = super::outputs::peak_on_grid(p, s.n_theta, s.n_rows, s.dtheta);
    (value, angle, s.z(j))
}
