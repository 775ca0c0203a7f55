//! [`FullLengthSolver`]: the Reynolds solver on the full bearing length, for
//! films that vary along the axis (a tilted journal, see [`super::misaligned`]).
//!
//! Grid: `theta_i = i dtheta` as in [`super::solver`] (periodic),
//! `z_j = (j - n_axial / 2) dz`, `dz = L / n_axial`, `j = 0 ..= n_axial`:
//! both ends (`j = 0`, `j = n_axial`) held at the ambient pressure, the
//! groove (if any) over the rows within half its width of the mid-plane.
//! Field layout: `p[i * n_rows + j]`, `n_rows = n_axial + 1`.
//!
//! Scaled equation at node (i, j), multiplied by `c^3 / R^2`:
//!
//! ```text
//! [H+ (p_{i+1} - p_i) - H- (p_i - p_{i-1})] / dtheta^2
//!   + kappa [Hu (p_{j+1} - p_j) - Hd (p_j - p_{j-1})]
//!   = K [W (H_{i+1/2,j} - H_{i-1/2,j}) / dtheta + 2 Hdot_{ij}]
//! ```
//!
//! with `H+-` the cube of `H = h / c` at the faces `i +- 1/2` of row j and
//! `Hu`, `Hd` its cube at the faces `j +- 1/2` of column i (conservative in
//! both directions, since `h` varies along z); `kappa`, `K`, `W` as in
//! [`super::solver`]. With `h` independent of z this is the half grid's
//! equation mirrored about the mid-plane.

use std::f64::consts::PI;

use super::full_outputs;
use super::full_sweep;
use super::misaligned::{MisalignedFilmKinematics, MisalignedFilmSolution};
use super::options::{Cavitation, ReynoldsOptions, MAX_GRID_NODES};
use super::solver::{check_geometry, sor_factor};
use crate::lubrication::film::BearingGeometry;

/// Coefficients of the full-length discrete equation for one state (read by the sweeps).
#[derive(Clone, Debug)]
pub struct FullStencil {
    /// Nodes around the circumference [-].
    pub n_theta: usize,
    /// Nodes along the full length, both end rows included [-].
    pub n_rows: usize,
    /// Whether row j is held at a boundary value (an end or a groove row) [-].
    pub row_fixed: Vec<bool>,
    /// Angular step [rad].
    pub dtheta: f64,
    /// Axial step [m].
    pub dz: f64,
    /// (R / dz)^2 [-].
    pub kappa: f64,
    /// H = h / c at the nodes [-].
    pub h_node: Vec<f64>,
    /// H at the faces (i + 1/2, j) [-].
    pub h_face: Vec<f64>,
    /// H^3 at the faces (i + 1/2, j) [-].
    pub h3_face: Vec<f64>,
    /// H^3 at the faces (i, j + 1/2) (the last row's entry is unused) [-].
    pub h3_axial: Vec<f64>,
    /// (dh/dt) / c at the nodes [1/s].
    pub h_rate: Vec<f64>,
    /// Full-film right-hand side at the nodes [Pa].
    pub rhs: Vec<f64>,
    /// K = 6 mu R^2 / c^2 [Pa s].
    pub k_scale: f64,
    /// W = omega_j + omega_b [rad/s].
    pub spin_sum: f64,
    /// Column held at ambient pressure as a feed line (`usize::MAX` for none) [-].
    pub feed_column: usize,
}

impl FullStencil {
    /// Axial position of row `j` [m] (0 at the mid-plane).
    pub fn z(&self, j: usize) -> f64 {
        (j as f64 - 0.5 * (self.n_rows - 1) as f64) * self.dz
    }
}

/// Finite-difference Reynolds solver over the full length of one bearing.
#[derive(Clone, Debug)]
pub struct FullLengthSolver {
    geometry: BearingGeometry,
    options: ReynoldsOptions,
    stencil: FullStencil,
    relaxation: f64,
    pressure: Vec<f64>,
    full_film: Vec<f64>,
    fill: Vec<f64>,
}

impl FullLengthSolver {
    /// Sets up the full grid and work arrays; every allocation happens here.
    pub fn new(geometry: BearingGeometry, options: ReynoldsOptions) -> Result<Self, String> {
        check_geometry(&geometry)?;
        options.validate()?;
        let (n_theta, n_rows) = (options.n_circumferential, options.n_axial + 1);
        let nodes = n_theta.saturating_mul(n_rows);
        if nodes > MAX_GRID_NODES {
            return Err(format!(
                "grid {} x {} has {nodes} nodes on the full length, more than the limit of {MAX_GRID_NODES} \
                 (n_circumferential x (n_axial + 1) for a misaligned journal)",
                options.n_circumferential, options.n_axial
            ));
        }
        let n_half = options.n_axial / 2 + 1;
        let dtheta = 2.0 * PI / n_theta as f64;
        let dz = geometry.length / options.n_axial as f64;
        let kappa = (geometry.radius / dz).powi(2);
        let j_free = match options.groove {
            None => 0,
            Some(g) => 1 + ((0.5 * g.width / dz + 1e-9).floor() as usize).min(n_half - 2),
        };
        let relaxation = sor_factor(dtheta, kappa, n_half, j_free > 0);
        let stencil = FullStencil {
            n_theta, n_rows, row_fixed: fixed_rows(n_rows, j_free), dtheta, dz, kappa,
            h_node: vec![0.0; nodes], h_face: vec![0.0; nodes], h3_face: vec![0.0; nodes],
            h3_axial: vec![0.0; nodes], h_rate: vec![0.0; nodes], rhs: vec![0.0; nodes],
            k_scale: 6.0 * geometry.viscosity * (geometry.radius / geometry.clearance).powi(2),
            spin_sum: 0.0,
            feed_column: usize::MAX,
        };
        let mut solver = Self {
            geometry, options, stencil, relaxation,
            pressure: vec![0.0; nodes], full_film: vec![0.0; nodes], fill: vec![1.0; nodes],
        };
        solver.set_boundary_values();
        Ok(solver)
    }

    /// Solves for the film of a tilted journal, warm-started from the previous solution.
    ///
    /// Errors: non-finite input, `|e(z)| >= c` at an end ("film thickness <= 0"),
    /// no convergence within `max_iterations` sweeps, or a cancelled run.
    pub fn solve(&mut self, k: &MisalignedFilmKinematics) -> Result<MisalignedFilmSolution, String> {
        k.check_finite()?;
        let half = 0.5 * self.geometry.length;
        let eps = k.eccentricity_at(-half).norm().max(k.eccentricity_at(half).norm()) / self.geometry.clearance;
        if eps >= 1.0 {
            return Err(format!("film thickness <= 0: eccentricity ratio {eps} >= 1 at an end of the bearing"));
        }
        self.fill_stencil(k);
        let scale = self.pressure_scale(eps);
        let iterations = if scale > 0.0 { self.relax(scale)? } else { self.zero_field() };
        Ok(full_outputs::evaluate(self.parts(), k, iterations))
    }

    /// Pressure field [Pa gauge] of the last solve, `p[i * n_rows + j]` at
    /// `theta_i = i 2 pi / n_circumferential` and `z_j` = [`Self::axial_position`]`(j)`.
    pub fn pressure(&self) -> &[f64] {
        &self.pressure
    }

    /// Fill fraction of the last solve (Elrod-Adams; 1 everywhere for the other models) [-], same layout.
    pub fn fill_fraction(&self) -> &[f64] {
        &self.fill
    }

    /// Node counts `(n_theta, n_rows)` of the field layout [-].
    pub fn field_shape(&self) -> (usize, usize) {
        (self.stencil.n_theta, self.stencil.n_rows)
    }

    /// Axial coordinate of row `j` [m] (0 at the mid-plane, `-L/2` at row 0).
    pub fn axial_position(&self, j: usize) -> f64 {
        self.stencil.z(j)
    }

    /// Bearing geometry.
    pub fn geometry(&self) -> &BearingGeometry {
        &self.geometry
    }

    /// Forgets the warm start (next solve starts from the boundary pressures).
    pub fn reset(&mut self) {
        self.pressure.iter_mut().for_each(|p| *p = 0.0);
        self.full_film.iter_mut().for_each(|p| *p = 0.0);
        self.fill.iter_mut().for_each(|f| *f = 1.0);
        self.set_boundary_values();
    }

    /// Film thickness, its rate and the full-film right-hand side at every node.
    fn fill_stencil(&mut self, k: &MisalignedFilmKinematics) {
        let c = self.geometry.clearance;
        let s = &mut self.stencil;
        for i in 0..s.n_theta {
            let (sn, cs) = (i as f64 * s.dtheta).sin_cos();
            let (sf, cf) = ((i as f64 + 0.5) * s.dtheta).sin_cos();
            for j in 0..s.n_rows {
                let z = s.z(j);
                let (e, v) = (k.eccentricity_at(z) / c, k.eccentricity_rate_at(z) / c);
                let e_up = k.eccentricity_at(z + 0.5 * s.dz) / c;
                let n = i * s.n_rows + j;
                s.h_node[n] = 1.0 - e.x * cs - e.y * sn;
                s.h_face[n] = 1.0 - e.x * cf - e.y * sf;
                s.h3_face[n] = s.h_face[n].powi(3);
                s.h3_axial[n] = (1.0 - e_up.x * cs - e_up.y * sn).powi(3);
                s.h_rate[n] = -(v.x * cs + v.y * sn);
            }
        }
        s.spin_sum = k.journal_spin + k.bearing_spin;
        for i in 0..s.n_theta {
            let im = if i == 0 { s.n_theta - 1 } else { i - 1 };
            for j in 0..s.n_rows {
                let (n, m) = (i * s.n_rows + j, im * s.n_rows + j);
                let wedge = s.spin_sum * (s.h_face[n] - s.h_face[m]) / s.dtheta;
                s.rhs[n] = s.k_scale * (wedge + 2.0 * s.h_rate[n]);
            }
        }
        if self.options.feed_at_thickest_film {
            self.hold_feed_column(k);
        }
    }

    /// Holds the column nearest the thickest film at the mid-plane at the ambient pressure.
    fn hold_feed_column(&mut self, k: &MisalignedFilmKinematics) {
        let s = &mut self.stencil;
        let (ex, ey) = (k.eccentricity.x, k.eccentricity.y);
        let thickest = (-ey).atan2(-ex).rem_euclid(2.0 * PI);
        s.feed_column = ((thickest / s.dtheta).round() as usize) % s.n_theta;
        let column = s.feed_column * s.n_rows;
        for j in (0..s.n_rows).filter(|j| !s.row_fixed[*j]) {
            self.pressure[column + j] = self.options.ambient_pressure;
            self.full_film[column + j] = self.options.ambient_pressure;
            self.fill[column + j] = 1.0;
        }
    }

    /// A pressure scale [Pa] for the convergence test: hydrodynamic, ambient and supply.
    fn pressure_scale(&self, eps: f64) -> f64 {
        let s = &self.stencil;
        super::sweep::pressure_scale(&self.options, s.k_scale, s.spin_sum, &s.h_rate, eps)
    }

    /// Relaxation sweeps of the chosen cavitation model until converged ([`super::sweep::relax`]).
    fn relax(&mut self, scale: f64) -> Result<usize, String> {
        let (options, stencil, w) = (&self.options, &self.stencil, self.relaxation);
        let fields = super::sweep::Fields { pressure: &mut self.pressure, full_film: &mut self.full_film, fill: &mut self.fill };
        let relaxed = super::sweep::relax(options, scale, fields, |f| match options.cavitation {
            Cavitation::Gumbel => full_sweep::sor(stencil, f.full_film, w, false),
            Cavitation::SwiftStieber => full_sweep::sor(stencil, f.pressure, w, true),
            Cavitation::ElrodAdams => full_sweep::elrod_adams(stencil, f.pressure, f.fill, w, scale),
        });
        if relaxed.is_err() {
            self.reset();
        }
        relaxed
    }

    /// No motion, no boundary pressure: the field is zero.
    fn zero_field(&mut self) -> usize {
        self.reset();
        0
    }

    /// Ambient pressure on both end rows, supply pressure on the groove rows.
    fn set_boundary_values(&mut self) {
        let s = &self.stencil;
        let supply = self.options.groove.map_or(0.0, |g| g.supply_pressure);
        for i in 0..s.n_theta {
            for j in (0..s.n_rows).filter(|j| s.row_fixed[*j]) {
                let end = j == 0 || j + 1 == s.n_rows;
                let value = if end { self.options.ambient_pressure } else { supply };
                self.pressure[i * s.n_rows + j] = value;
                self.full_film[i * s.n_rows + j] = value;
            }
        }
    }

    /// What [`full_outputs::evaluate`] reads.
    fn parts(&self) -> full_outputs::Parts<'_> {
        full_outputs::Parts {
            geometry: &self.geometry,
            cavitation: self.options.cavitation,
            stencil: &self.stencil,
            pressure: &self.pressure,
            fill: &self.fill,
        }
    }
}

/// Rows held at a boundary value: both ends, and the `j_free` rows of the
/// half grid's groove mirrored about the mid-plane.
fn fixed_rows(n_rows: usize, j_free: usize) -> Vec<bool> {
    let mid = (n_rows - 1) / 2;
    (0..n_rows).map(|j| j == 0 || j + 1 == n_rows || (j_free > 0 && j.abs_diff(mid) < j_free)).collect()
}
