//! [`ReynoldsSolver`]: grid and work arrays set up once, solved per state.
//!
//! Grid (node-centred, finite-volume form): `theta_i = i dtheta`,
//! `dtheta = 2 pi / n_circumferential`, periodic; `z_j = j dz`,
//! `dz = L / n_axial`, `j = 0 ..= n_axial / 2`, on the half `z in [0, L/2]`
//! (the film of an aligned journal is symmetric about the mid-plane, so
//! `dp/dz = 0` at `z = 0` unless a groove holds it at the supply pressure).
//! Row `j = n_axial / 2` is the end, held at the ambient pressure.
//! Field layout: `p[i * n_half + j]`, `n_half = n_axial / 2 + 1`.
//!
//! Scaled equation at node (i, j), multiplied by `c^3 / R^2`:
//! `[H+ (p_{i+1} - p_i) - H- (p_i - p_{i-1})] / dtheta^2 + kappa H_i^3 (p_{j+1} - 2 p_j + p_{j-1})
//!  = K [W (H_{i+1/2} - H_{i-1/2}) / dtheta + 2 Hdot_i]`
//! with `H = h / c`, `H+- = H^3` at the faces `i +- 1/2`, `kappa = (R / dz)^2`,
//! `K = 6 mu R^2 / c^2` [Pa s], `W = omega_j + omega_b` [rad/s],
//! `Hdot = (dh/dt) / c` [1/s].

use nalgebra::Vector2;

use super::full_length::FullLengthSolver;
use super::misaligned::{MisalignedFilmKinematics, MisalignedFilmSolution};
use super::options::{Cavitation, ReynoldsOptions};
use super::outputs::{self, FilmSolution};
use super::sweep;
use crate::lubrication::film::{BearingGeometry, FilmKinematics};

/// Coefficients of the discrete equation for one state (read by the sweeps).
#[derive(Clone, Debug)]
pub struct Stencil {
    /// Nodes around the circumference [-].
    pub n_theta: usize,
    /// Nodes along the half length, end row included [-].
    pub n_half: usize,
    /// First free row: rows below are groove nodes at the supply pressure [-].
    pub j_free: usize,
    /// Angular step [rad].
    pub dtheta: f64,
    /// Axial step [m].
    pub dz: f64,
    /// (R / dz)^2 [-].
    pub kappa: f64,
    /// H = h / c at the nodes [-].
    pub h_node: Vec<f64>,
    /// H at the faces i + 1/2 [-].
    pub h_face: Vec<f64>,
    /// H^3 at the nodes [-].
    pub h3_node: Vec<f64>,
    /// H^3 at the faces i + 1/2 [-].
    pub h3_face: Vec<f64>,
    /// (dh/dt) / c at the nodes [1/s].
    pub h_rate: Vec<f64>,
    /// Full-film right-hand side per column [Pa].
    pub rhs: Vec<f64>,
    /// K = 6 mu R^2 / c^2 [Pa s].
    pub k_scale: f64,
    /// W = omega_j + omega_b [rad/s].
    pub spin_sum: f64,
    /// Column held at ambient pressure as a feed line (`usize::MAX` for none) [-].
    pub feed_column: usize,
}

/// Finite-difference Reynolds solver for one bearing (see the module docs for the grid).
#[derive(Clone, Debug)]
pub struct ReynoldsSolver {
    geometry: BearingGeometry,
    options: ReynoldsOptions,
    stencil: Stencil,
    relaxation: f64,
    pressure: Vec<f64>,
    full_film: Vec<f64>,
    fill: Vec<f64>,
    kinematics: Option<FilmKinematics>,
    /// Full-length grid for tilted journals, set up at the first misaligned solve.
    full_length: Option<Box<FullLengthSolver>>,
}

impl ReynoldsSolver {
    /// Sets up the grid and work arrays; every allocation happens here.
    pub fn new(geometry: BearingGeometry, options: ReynoldsOptions) -> Result<Self, String> {
        check_geometry(&geometry)?;
        options.validate()?;
        let n_theta = options.n_circumferential;
        let n_half = options.n_axial / 2 + 1;
        let dtheta = 2.0 * std::f64::consts::PI / n_theta as f64;
        let dz = geometry.length / options.n_axial as f64;
        let kappa = (geometry.radius / dz).powi(2);
        // groove rows: the mid-plane, and every row within half the groove width
        let j_free = match options.groove {
            None => 0,
            Some(g) => 1 + ((0.5 * g.width / dz + 1e-9).floor() as usize).min(n_half - 2),
        };
        let zeros = vec![0.0; n_theta];
        let stencil = Stencil {
            n_theta, n_half, j_free, dtheta, dz, kappa,
            h_node: zeros.clone(), h_face: zeros.clone(), h3_node: zeros.clone(),
            h3_face: zeros.clone(), h_rate: zeros.clone(), rhs: zeros,
            k_scale: 6.0 * geometry.viscosity * (geometry.radius / geometry.clearance).powi(2),
            spin_sum: 0.0,
            feed_column: usize::MAX,
        };
        let relaxation = sor_factor(stencil.dtheta, stencil.kappa, stencil.n_half, stencil.j_free > 0);
        let n = n_theta * n_half;
        let mut solver = Self {
            geometry, options, stencil, relaxation,
            pressure: vec![0.0; n], full_film: vec![0.0; n], fill: vec![1.0; n], kinematics: None,
            full_length: None,
        };
        solver.set_boundary_values();
        Ok(solver)
    }

    /// Solves for the film at one state, warm-started from the previous solution.
    ///
    /// Errors: non-finite input, `|e| >= c` ("film thickness <= 0"), no
    /// convergence within `max_iterations` sweeps, or a run cancelled during the
    /// sweeps ([`crate::interrupt::INTERRUPTED`]).
    pub fn solve(&mut self, kinematics: &FilmKinematics) -> Result<FilmSolution, String> {
        check_kinematics(kinematics)?;
        let c = self.geometry.clearance;
        let eps = kinematics.eccentricity.norm() / c;
        if eps >= 1.0 {
            return Err(format!("film thickness <= 0: eccentricity ratio {eps} >= 1"));
        }
        self.fill_stencil(kinematics);
        let scale = self.pressure_scale(eps);
        let iterations = if scale > 0.0 { self.relax(scale)? } else { self.zero_field() };
        self.kinematics = Some(*kinematics);
        Ok(outputs::evaluate(self.parts(), kinematics, iterations))
    }

    /// Solves for the film of a possibly tilted journal: force and moment.
    ///
    /// An aligned state ([`MisalignedFilmKinematics::is_aligned`]) takes
    /// [`Self::solve`] on the half grid (same result, moment zero); a tilted
    /// one the [`FullLengthSolver`] over the whole length, set up once at the
    /// first such call (its only allocation) and warm-started afterwards.
    pub fn solve_misaligned(&mut self, kinematics: &MisalignedFilmKinematics) -> Result<MisalignedFilmSolution, String> {
        if kinematics.is_aligned() {
            return self.solve(&kinematics.mid_plane()).map(|s| MisalignedFilmSolution::from_aligned(&s));
        }
        if self.full_length.is_none() {
            self.full_length = Some(Box::new(FullLengthSolver::new(self.geometry, self.options)?));
        }
        match self.full_length.as_deref_mut() {
            Some(full) => full.solve(kinematics),
            None => Err("full-length Reynolds grid was not set up".to_string()),
        }
    }

    /// Pressure field [Pa gauge] of the last solve, `p[i * n_half + j]` at
    /// `theta_i = i 2 pi / n_circumferential`, `z_j = j L / n_axial` (half length, see module docs).
    pub fn pressure(&self) -> &[f64] {
        &self.pressure
    }

    /// Fill fraction of the last solve (Elrod-Adams; 1 everywhere for the other models) [-], same layout.
    pub fn fill_fraction(&self) -> &[f64] {
        &self.fill
    }

    /// Node counts `(n_theta, n_half)` of the field layout [-].
    pub fn field_shape(&self) -> (usize, usize) {
        (self.stencil.n_theta, self.stencil.n_half)
    }

    /// Axial coordinate of row `j` [m] (0 at the mid-plane).
    pub fn axial_position(&self, j: usize) -> f64 {
        j as f64 * self.stencil.dz
    }

    /// Bearing geometry.
    pub fn geometry(&self) -> &BearingGeometry {
        &self.geometry
    }

    /// Options.
    pub fn options(&self) -> &ReynoldsOptions {
        &self.options
    }

    /// Complementarity residual of the last Swift-Stieber solve, relative to the peak pressure [-]:
    /// `max_i |min(p_i, s_i)| / p_max` with `s = rhs - L(p)` scaled as a pressure.
    pub fn complementarity_residual(&self) -> f64 {
        sweep::complementarity(&self.stencil, &self.pressure)
    }

    /// Forgets the warm start (next solve starts from the boundary pressures).
    pub fn reset(&mut self) {
        self.pressure.iter_mut().for_each(|p| *p = 0.0);
        self.full_film.iter_mut().for_each(|p| *p = 0.0);
        self.fill.iter_mut().for_each(|f| *f = 1.0);
        self.set_boundary_values();
    }

    /// Film thickness, its rate and the full-film right-hand side per column.
    fn fill_stencil(&mut self, k: &FilmKinematics) {
        let s = &mut self.stencil;
        let c = self.geometry.clearance;
        let (ex, ey) = (k.eccentricity.x / c, k.eccentricity.y / c);
        let (vx, vy) = (k.eccentricity_rate.x / c, k.eccentricity_rate.y / c);
        for i in 0..s.n_theta {
            let (sn, cs) = (i as f64 * s.dtheta).sin_cos();
            let (sf, cf) = ((i as f64 + 0.5) * s.dtheta).sin_cos();
            s.h_node[i] = 1.0 - ex * cs - ey * sn;
            s.h_face[i] = 1.0 - ex * cf - ey * sf;
            s.h3_node[i] = s.h_node[i].powi(3);
            s.h3_face[i] = s.h_face[i].powi(3);
            s.h_rate[i] = -(vx * cs + vy * sn);
        }
        s.spin_sum = k.journal_spin + k.bearing_spin;
        if self.options.feed_at_thickest_film {
            let thickest = (-ey).atan2(-ex).rem_euclid(2.0 * std::f64::consts::PI);
            s.feed_column = ((thickest / s.dtheta).round() as usize) % s.n_theta;
            let row = s.feed_column * s.n_half;
            for j in s.j_free..s.n_half - 1 {
                self.pressure[row + j] = self.options.ambient_pressure;
                self.full_film[row + j] = self.options.ambient_pressure;
                self.fill[row + j] = 1.0;
            }
        }
        for i in 0..s.n_theta {
            let im = if i == 0 { s.n_theta - 1 } else { i - 1 };
            let wedge = s.spin_sum * (s.h_face[i] - s.h_face[im]) / s.dtheta;
            s.rhs[i] = s.k_scale * (wedge + 2.0 * s.h_rate[i]);
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
            Cavitation::Gumbel => sweep::sor(stencil, f.full_film, w, false),
            Cavitation::SwiftStieber => sweep::sor(stencil, f.pressure, w, true),
            Cavitation::ElrodAdams => sweep::elrod_adams(stencil, f.pressure, f.fill, w, scale),
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

    /// Ambient pressure on the end row, supply pressure on the groove rows, full film there.
    fn set_boundary_values(&mut self) {
        let s = &self.stencil;
        let supply = self.options.groove.map_or(0.0, |g| g.supply_pressure);
        for i in 0..s.n_theta {
            let row = i * s.n_half;
            for j in 0..s.j_free {
                self.pressure[row + j] = supply;
                self.full_film[row + j] = supply;
            }
            self.pressure[row + s.n_half - 1] = self.options.ambient_pressure;
            self.full_film[row + s.n_half - 1] = self.options.ambient_pressure;
        }
    }

    /// What [`outputs::evaluate`] reads.
    fn parts(&self) -> outputs::Parts<'_> {
        outputs::Parts {
            geometry: &self.geometry,
            cavitation: self.options.cavitation,
            stencil: &self.stencil,
            pressure: &self.pressure,
            fill: &self.fill,
        }
    }
}

/// SOR factor from the constant-coefficient model problem: the slowest mode
/// is constant around the circumference and lowest along the axis (the same
/// on the half grid and on the full grid it mirrors: `n_half` nodes from the
/// mid-plane to an end, with or without a groove holding the mid-plane).
pub(super) fn sor_factor(dtheta: f64, kappa: f64, n_half: usize, groove: bool) -> f64 {
    let a_theta = 2.0 / (dtheta * dtheta);
    let a_z = 2.0 * kappa;
    let m = (n_half - 1) as f64;
    let lowest = if groove { std::f64::consts::PI / m } else { std::f64::consts::PI / (2.0 * m) };
    let rho = (a_theta + a_z * lowest.cos()) / (a_theta + a_z);
    (2.0 / (1.0 + (1.0 - rho * rho).sqrt())).min(1.95)
}

pub(super) fn check_geometry(g: &BearingGeometry) -> Result<(), String> {
    for (name, v) in [("radius", g.radius), ("length", g.length), ("clearance", g.clearance), ("viscosity", g.viscosity)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(format!("bearing {name} must be positive and finite, got {v}"));
        }
    }
    Ok(())
}

fn check_kinematics(k: &FilmKinematics) -> Result<(), String> {
    let finite = |v: &Vector2<f64>| v.x.is_finite() && v.y.is_finite();
    if !(finite(&k.eccentricity) && finite(&k.eccentricity_rate) && k.journal_spin.is_finite() && k.bearing_spin.is_finite()) {
        return Err(format!("film kinematics must be finite, got {k:?}"));
    }
    Ok(())
}
