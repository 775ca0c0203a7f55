//! Options of the Reynolds solver: grid, cavitation model, boundary pressures.

/// How the film ruptures where the Reynolds equation would give pressures
/// below the cavitation pressure (taken as 0 Pa gauge).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cavitation {
    /// Gümbel (half-Sommerfeld): solve the full film, then drop negative pressures.
    Gumbel,
    /// Swift (1932) - Stieber (1933), the "Reynolds" condition: `p >= 0` as a
    /// linear complementarity problem, solved by projected SOR.
    SwiftStieber,
    /// Elrod-Adams (1974) mass-conserving JFO model: pressure and fill
    /// fraction with `p (1 - fill) = 0`; needs a lubricant supply (a groove or
    /// an ambient pressure above 0).
    ElrodAdams,
}

/// A circumferential groove at mid-length, held at the supply pressure (paper 000).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Groove {
    /// Supply pressure p_s, gauge [Pa] (>= 0).
    pub supply_pressure: f64,
    /// Axial width of the groove [m]; 0 means a line groove at z = 0 only.
    pub width: f64,
}

/// Largest Reynolds grid the solver sets up, in nodes of the solved half
/// field, `n_circumferential x (n_axial / 2 + 1)` [-]. The solver keeps three
/// f64 fields over those nodes (24 MB at the bound) and a relaxation sweep
/// visits each node, while the sweeps to converge grow with the grid's side
/// (measured, eps 0.6, L/D 1: 1 080 nodes 1 ms, 15 840 nodes 0.16 s,
/// 62 400 nodes 1.8 s): at the bound one solve takes minutes, and the force
/// has converged with the grid long before (see the theory page). A bigger
/// grid is a slip, and setting it up could exhaust the memory and abort the
/// process.
pub const MAX_GRID_NODES: usize = 1_000_000;

/// Options of [`super::ReynoldsSolver`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReynoldsOptions {
    /// Number of nodes around the circumference (periodic) [-].
    pub n_circumferential: usize,
    /// Number of grid intervals over the full length L (even: the solver
    /// keeps one half, z in [0, L/2], by the mid-plane symmetry) [-].
    pub n_axial: usize,
    /// Cavitation model.
    pub cavitation: Cavitation,
    /// Pressure at both ends, gauge relative to the cavitation pressure [Pa] (>= 0).
    pub ambient_pressure: f64,
    /// Optional circumferential groove at mid-length.
    pub groove: Option<Groove>,
    /// Hold the axial line of largest film thickness (the grid column nearest
    /// to it) at the ambient pressure with a full film: an axial feed groove
    /// there, as Raimondi and Boyd (1958) assume for the full bearing.
    pub feed_at_thickest_film: bool,
    /// Convergence: largest change of a sweep relative to the pressure variation (max - min) over the film [-].
    pub tolerance: f64,
    /// Largest number of relaxation sweeps before giving up [-].
    pub max_iterations: usize,
}

impl Default for ReynoldsOptions {
    /// 120 x 16 grid (3 degree cells: about 1 ms per solve; force within
    /// about 0.3 % of the grid limit at L/D = 1, eps = 0.6, and turning the
    /// state against the grid changes it by under 0.3 % up to eps = 0.95; see
    /// the theory page), Swift-Stieber, ambient 0, no feed line, tolerance
    /// 1e-7 (well below the discretisation error), 20 000 sweeps.
    fn default() -> Self {
        Self {
            n_circumferential: 120,
            n_axial: 16,
            cavitation: Cavitation::SwiftStieber,
            ambient_pressure: 0.0,
            groove: None,
            feed_at_thickest_film: false,
            tolerance: 1e-7,
            max_iterations: 20_000,
        }
    }
}

impl ReynoldsOptions {
    /// Checks the grid alone (counts and [`MAX_GRID_NODES`]) before anything
    /// is allocated; the message names the offending value.
    pub fn validate_grid(&self) -> Result<(), String> {
        if self.n_circumferential < 8 {
            return Err(format!("n_circumferential must be at least 8, got {}", self.n_circumferential));
        }
        if self.n_axial < 2 || self.n_axial % 2 != 0 {
            return Err(format!("n_axial must be even and at least 2, got {}", self.n_axial));
        }
        let nodes = self.n_circumferential.saturating_mul(self.n_axial / 2 + 1);
        if nodes > MAX_GRID_NODES {
            return Err(format!(
                "grid {} x {} has {nodes} nodes on the half length, more than the limit of {MAX_GRID_NODES} \
                 (n_circumferential x (n_axial/2 + 1); solver memory and time grow with it)",
                self.n_circumferential, self.n_axial
            ));
        }
        Ok(())
    }

    /// Checks the options; the message names the offending field and value.
    pub fn validate(&self) -> Result<(), String> {
        self.validate_grid()?;
        if !(self.ambient_pressure.is_finite() && self.ambient_pressure >= 0.0) {
            return Err(format!("ambient_pressure must be finite and >= 0 Pa, got {}", self.ambient_pressure));
        }
        if !(self.tolerance.is_finite() && self.tolerance > 0.0) {
            return Err(format!("tolerance must be positive, got {}", self.tolerance));
        }
        if self.max_iterations == 0 {
            return Err("max_iterations must be at least 1, got 0".to_string());
        }
        if let Some(g) = self.groove {
            if !(g.supply_pressure.is_finite() && g.supply_pressure >= 0.0) {
                return Err(format!("groove supply_pressure must be finite and >= 0 Pa, got {}", g.supply_pressure));
            }
            if !(g.width.is_finite() && g.width >= 0.0) {
                return Err(format!("groove width must be finite and >= 0 m, got {}", g.width));
            }
        }
        if self.cavitation == Cavitation::ElrodAdams && self.groove.is_none() && self.ambient_pressure <= 0.0 && !self.feed_at_thickest_film {
            return Err("the Elrod-Adams model needs a lubricant supply: a groove, feed_at_thickest_film or ambient_pressure > 0 \
                        (with neither, the mass-conserving steady film starves)"
                .to_string());
        }
        Ok(())
    }
}
