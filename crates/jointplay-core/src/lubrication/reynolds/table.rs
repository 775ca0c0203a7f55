//! Fast mode: dimensionless force tables precomputed by the Reynolds solver.
//!
//! In the frame of the line of centres (`n = e / |e|`, `t` = `n` turned by
//! +90 degrees, `theta' = theta - gamma`) the right-hand side of the
//! Reynolds equation is
//! `6 mu c eps (omega_j + omega_b - 2 gamma_dot) sin theta' - 12 mu c eps_dot cos theta'
//!  = 12 mu c (V_w sin theta' - V_s cos theta')`
//! with the wedge rate `V_w = eps (omega_j + omega_b - 2 gamma_dot) / 2 = eps (omega_j + omega_b) / 2 - (e_dot . t) / c`
//! and the squeeze rate `V_s = eps_dot = (e_dot . n) / c` [1/s]. With
//! ambient pressure 0 and no groove, Gümbel and Swift-Stieber cavitation
//! keep the pressure positively homogeneous of degree one in `(V_w, V_s)`, so
//! `F = mu R L (R / c)^2 |V| [f_n(eps, psi) n + f_t(eps, psi) t]`,
//! `psi = atan2(V_s, V_w)`, and likewise the peak pressure
//! `mu (R / c)^2 |V| g(eps, psi)`. The table holds `f_n, f_t` and
//! `g (cos, sin)` of the peak angle (relative to `n`), each times `(1 - eps^2)^2`,
//! on a grid uniform in `s = -ln(1 - eps)` (points cluster towards eps = 1)
//! and in `psi` (periodic); lookups are tensor-product Catmull-Rom cubics.
//! Beyond the largest tabulated eps the scaled values are held constant.
//! Friction torque: full-film Couette `-mu R^3 (omega_j - omega_b) 2 pi L / (c sqrt(1 - eps^2))`
//! plus `-(e x F) / 2` (see [`super::outputs`]).

use nalgebra::Vector2;
use std::f64::consts::PI;

use super::options::{Cavitation, ReynoldsOptions};
use super::solver::ReynoldsSolver;
use crate::lubrication::film::{BearingGeometry, FilmForce, FilmKinematics};

/// How to build a [`ForceTable`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForceTableOptions {
    /// Solver options (Gümbel or Swift-Stieber, ambient 0, no groove).
    pub solver: ReynoldsOptions,
    /// Eccentricity-ratio nodes, uniform in `-ln(1 - eps)` from 0 to the largest [-].
    pub n_eccentricity: usize,
    /// Nodes of the velocity angle psi over a full turn [-].
    pub n_angle: usize,
    /// Largest tabulated eccentricity ratio [-].
    pub max_eccentricity_ratio: f64,
}

impl Default for ForceTableOptions {
    /// Default solver grid, 40 x 64 table up to eps = 0.98 (interpolation
    /// error measured well below 1 % of the exact solver; see the theory page).
    fn default() -> Self {
        Self { solver: ReynoldsOptions::default(), n_eccentricity: 40, n_angle: 64, max_eccentricity_ratio: 0.98 }
    }
}

/// Largest force table, in nodes `n_eccentricity x n_angle` [-]. Every node is
/// one Reynolds solve (about 1 ms on the default grid): the default 40 x 64
/// table (2 560 nodes) builds in seconds, one at the bound in about a minute
/// on the default grid, and its interpolation error is far below the film
/// model's long before.
pub const MAX_TABLE_NODES: usize = 65_536;

/// Number of tabulated quantities per node: f_n, f_t, g cos, g sin.
const N_VALUES: usize = 4;

/// Dimensionless film forces of one L/D, interpolated in (eps, psi).
#[derive(Clone, Debug)]
pub struct ForceTable {
    length_over_diameter: f64,
    s_max: f64,
    n_s: usize,
    n_psi: usize,
    /// Rows of s padded with one ghost row at each end: `(n_s + 2) x n_psi`.
    values: Vec<[f64; N_VALUES]>,
}

impl ForceTable {
    /// Builds the table for length-over-diameter `length_over_diameter` [-] by solving the Reynolds equation at every node.
    pub fn build(length_over_diameter: f64, options: &ForceTableOptions) -> Result<Self, String> {
        check_options(length_over_diameter, options)?;
        let geometry = BearingGeometry { radius: 1.0, length: 2.0 * length_over_diameter, clearance: 1.0, viscosity: 1.0 };
        let mut solver = ReynoldsSolver::new(geometry, options.solver)?;
        let (n_s, n_psi) = (options.n_eccentricity, options.n_angle);
        let s_max = -(1.0 - options.max_eccentricity_ratio).ln();
        let mut values = vec![[0.0; N_VALUES]; (n_s + 2) * n_psi];
        for a in 0..n_s {
            let eps = (1.0 - (-(s_max * a as f64 / (n_s - 1) as f64)).exp()).max(1e-6);
            for b in 0..n_psi {
                let psi = 2.0 * PI * b as f64 / n_psi as f64;
                values[(a + 1) * n_psi + b] = node_values(&mut solver, eps, psi, geometry.length)?;
            }
        }
        // ghost rows by cubic extrapolation
        for b in 0..n_psi {
            for q in 0..N_VALUES {
                let v = |a: usize| values[a * n_psi + b][q];
                let (low, high) = (3.0 * v(1) - 3.0 * v(2) + v(3), 3.0 * v(n_s) - 3.0 * v(n_s - 1) + v(n_s - 2));
                values[b][q] = low;
                values[(n_s + 1) * n_psi + b][q] = high;
            }
        }
        Ok(Self { length_over_diameter, s_max, n_s, n_psi, values })
    }

    /// Length over diameter the table was built for [-].
    pub fn length_over_diameter(&self) -> f64 {
        self.length_over_diameter
    }

    /// Film force by interpolation (no allocation). `geometry.length / (2 radius)`
    /// should equal the table's L/D; the caller checks it once. `|e| >= c` gives
    /// the values at the largest tabulated eccentricity ratio scaled by `(1 - eps^2)^-2` with eps capped just below 1.
    pub fn film_force(&self, geometry: &BearingGeometry, k: &FilmKinematics) -> FilmForce {
        let (r, l, c, mu) = (geometry.radius, geometry.length, geometry.clearance, geometry.viscosity);
        let e = k.eccentricity;
        let eps = (e.norm() / c).min(1.0 - 1e-9);
        let n = if e.norm() > 0.0 { e / e.norm() } else { Vector2::new(1.0, 0.0) };
        let t = Vector2::new(-n.y, n.x);
        let spin = k.journal_spin + k.bearing_spin;
        let v_w = 0.5 * eps * spin - k.eccentricity_rate.dot(&t) / c;
        let v_s = k.eccentricity_rate.dot(&n) / c;
        let speed = v_w.hypot(v_s);
        let couette = -mu * r.powi(3) * (k.journal_spin - k.bearing_spin) * 2.0 * PI * l / (c * (1.0 - eps * eps).sqrt());
        if speed == 0.0 {
            return FilmForce { force_on_journal: Vector2::zeros(), peak_pressure: 0.0, peak_pressure_angle: 0.0, friction_torque: couette };
        }
        let q = self.lookup(eps, v_s.atan2(v_w));
        let unscale = 1.0 / (1.0 - eps * eps).powi(2);
        let force = (n * q[0] + t * q[1]) * (mu * r * l * (r / c).powi(2) * speed * unscale);
        let peak = mu * (r / c).powi(2) * speed * unscale * q[2].hypot(q[3]);
        let mut angle = n.y.atan2(n.x) + q[3].atan2(q[2]);
        angle = (angle + PI).rem_euclid(2.0 * PI) - PI;
        let e_cross_f = e.x * force.y - e.y * force.x;
        FilmForce { force_on_journal: force, peak_pressure: peak, peak_pressure_angle: angle, friction_torque: couette - 0.5 * e_cross_f }
    }

    /// Interpolated scaled values at (eps, psi).
    fn lookup(&self, eps: f64, psi: f64) -> [f64; N_VALUES] {
        let s = (-(1.0 - eps).ln()).min(self.s_max);
        let u = s / self.s_max * (self.n_s - 1) as f64;
        let a0 = (u.floor() as usize).min(self.n_s - 2);
        let ws = catmull_rom(u - a0 as f64);
        let v = psi.rem_euclid(2.0 * PI) / (2.0 * PI) * self.n_psi as f64;
        let b0 = (v.floor() as usize).min(self.n_psi - 1);
        let wp = catmull_rom(v - b0 as f64);
        let mut out = [0.0; N_VALUES];
        for (da, wa) in ws.iter().enumerate() {
            // padded row index of s-node a0 - 1 + da is a0 + da
            let row = (a0 + da) * self.n_psi;
            for (db, wb) in wp.iter().enumerate() {
                let b = (b0 + self.n_psi + db - 1) % self.n_psi;
                let node = &self.values[row + b];
                for q in 0..N_VALUES {
                    out[q] += wa * wb * node[q];
                }
            }
        }
        out
    }
}

/// Catmull-Rom weights of the nodes -1, 0, 1, 2 at fraction `x` in [0, 1].
fn catmull_rom(x: f64) -> [f64; 4] {
    let (x2, x3) = (x * x, x * x * x);
    [
        0.5 * (-x3 + 2.0 * x2 - x),
        0.5 * (3.0 * x3 - 5.0 * x2 + 2.0),
        0.5 * (-3.0 * x3 + 4.0 * x2 + x),
        0.5 * (x3 - x2),
    ]
}

/// Solves the canonical state (e along +x, |V| = 1) and returns the scaled values.
fn node_values(solver: &mut ReynoldsSolver, eps: f64, psi: f64, length: f64) -> Result<[f64; N_VALUES], String> {
    let (v_s, v_w) = psi.sin_cos();
    let kin = FilmKinematics {
        eccentricity: Vector2::new(eps, 0.0),
        eccentricity_rate: Vector2::new(v_s, 0.0),
        journal_spin: 2.0 * v_w / eps,
        bearing_spin: 0.0,
    };
    let sol = solver.solve(&kin)?;
    let scale = (1.0 - eps * eps).powi(2);
    let (sn, cs) = sol.peak_pressure_angle.sin_cos();
    Ok([
        sol.force_on_journal.x / length * scale,
        sol.force_on_journal.y / length * scale,
        sol.peak_pressure * cs * scale,
        sol.peak_pressure * sn * scale,
    ])
}

fn check_options(length_over_diameter: f64, o: &ForceTableOptions) -> Result<(), String> {
    if !(length_over_diameter.is_finite() && length_over_diameter > 0.0) {
        return Err(format!("length_over_diameter must be positive, got {length_over_diameter}"));
    }
    if o.solver.cavitation == Cavitation::ElrodAdams {
        return Err("force tables need Gümbel or Swift-Stieber cavitation (Elrod-Adams is not homogeneous in the velocities)".into());
    }
    if o.solver.groove.is_some() || o.solver.ambient_pressure != 0.0 {
        return Err("force tables need ambient pressure 0 and no groove (otherwise the force is not homogeneous)".into());
    }
    if o.n_eccentricity < 4 || o.n_angle < 8 {
        return Err(format!("force table needs n_eccentricity >= 4 and n_angle >= 8, got {} and {}", o.n_eccentricity, o.n_angle));
    }
    let nodes = o.n_eccentricity.saturating_mul(o.n_angle);
    if nodes > MAX_TABLE_NODES {
        return Err(format!(
            "force table {} x {} has {nodes} nodes, more than the limit of {MAX_TABLE_NODES} (one Reynolds solve each)",
            o.n_eccentricity, o.n_angle
        ));
    }
    o.solver.validate_grid()?;
    if !(o.max_eccentricity_ratio > 0.0 && o.max_eccentricity_ratio < 1.0) {
        return Err(format!("max_eccentricity_ratio must be in (0, 1), got {}", o.max_eccentricity_ratio));
    }
    Ok(())
}
