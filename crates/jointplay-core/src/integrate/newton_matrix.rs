//! The Newton iteration matrix `I - c J` shared by the implicit methods
//! (NDF and generalized-alpha): the Jacobian `J = df/dy`, formed by the
//! system ([`OdeSystem::jacobian`]) or by forward differences, kept across
//! steps until the iterations fail, and its LU factors, kept until `c`
//! changes by more than [`REFACTOR_CHANGE`] (`docs/theory/integrator-jacobian.md`).
//!
//! A system that describes the structure of its Jacobian ([`OdeSystem::newton_structure`])
//! gets a sparse augmented Newton matrix instead of the dense one
//! ([`SparseNewton`]): same equations, cost growing with the coupling. Should that
//! matrix be singular (dependent constraints), the run goes on with the dense one.

use super::control::{eval, Tolerances};
use super::sparse_newton::SparseNewton;
use super::{OdeSystem, Statistics};
use crate::error::SimulationError;
use crate::linalg::{lu_factor, lu_solve};

/// Relative change of `c` beyond which `I - c J` is factored again (the
/// threshold of CVODE's linear-solver setup, 0.3).
const REFACTOR_CHANGE: f64 = 0.3;

/// The Jacobian, the factors of `I - c J` and the scratch to form them.
pub(crate) struct IterationMatrix {
    n: usize,
    /// df/dy, row-major, and whether it exists.
    jacobian: Vec<f64>,
    valid: bool,
    /// Whether the system forms the Jacobian ([`OdeSystem::jacobian`]) instead of forward differences.
    pub(crate) use_system_jacobian: bool,
    /// `atol_j / rtol` (at least the smallest positive number): below this
    /// magnitude a finite-difference increment of component j stops shrinking with |y_j|.
    floors: Vec<f64>,
    /// LU factors of `I - c J` (or of another matrix formed from J), their pivots,
    /// the c (or key) and the size they were built for.
    factors: Vec<f64>,
    pivots: Vec<usize>,
    factored_c: Option<f64>,
    factored_size: usize,
    /// f at the Jacobian's state, and at a perturbed state.
    f_base: Vec<f64>,
    f_perturbed: Vec<f64>,
    /// The perturbed state.
    y_perturbed: Vec<f64>,
    /// The sparse Newton matrix, when the system describes its structure.
    sparse: Option<SparseNewton>,
    /// Whether the system was asked for that structure.
    probed: bool,
    /// Whether the kept Jacobian is in the sparse form, and the factors sparse.
    sparse_kept: bool,
    /// Whether the sparse factors are of `I - c J` (the NDF), else of the reduced matrix.
    sparse_full: bool,
    /// Whether a sparse matrix was found singular: the dense one is used from then on.
    sparse_disabled: bool,
    /// Whether the last factorisation failed on the sparse matrix (see [`Self::retry_dense`]).
    sparse_failed: bool,
}

impl IterationMatrix {
    /// Buffers for a state of `n` components and the difference floors of `tol`.
    pub(crate) fn new(n: usize, tol: &Tolerances) -> Self {
        let floors = tol.atol.iter().map(|atol| (atol / tol.rtol).max(f64::MIN_POSITIVE)).collect();
        Self {
            n,
            jacobian: vec![0.0; n * n],
            valid: false,
            use_system_jacobian: false,
            floors,
            factors: vec![0.0; n * n],
            pivots: vec![0; n],
            factored_c: None,
            factored_size: n,
            f_base: vec![0.0; n],
            f_perturbed: vec![0.0; n],
            y_perturbed: vec![0.0; n],
            sparse: None,
            probed: false,
            sparse_kept: false,
            sparse_full: false,
            sparse_disabled: false,
            sparse_failed: false,
        }
    }

    /// After a failed factorisation: whether it was the sparse matrix's (singular), the
    /// sparse form is now off and the caller should form the Jacobian again (dense) rather
    /// than count the attempt as failed.
    pub(crate) fn retry_dense(&mut self) -> bool {
        std::mem::take(&mut self.sparse_failed)
    }

    /// The system's sparse parts at (t, y), when it offers them; the cost, or None for dense.
    fn update_sparse<S: OdeSystem>(&mut self, system: &mut S, t: f64, y: &[f64]) -> Result<Option<super::JacobianCost>, SimulationError> {
        if !self.probed {
            self.probed = true;
            self.sparse = system.newton_structure().and_then(|structure| SparseNewton::new(structure).ok());
        }
        match (&mut self.sparse, self.sparse_disabled) {
            (Some(sparse), false) => system.jacobian_parts(t, y, &self.floors, &mut sparse.parts),
            _ => Ok(None),
        }
    }

    /// Whether a Jacobian is kept.
    pub(crate) fn is_valid(&self) -> bool {
        self.valid
    }

    /// Drops the kept Jacobian: the next [`Self::update`] forms a fresh one.
    pub(crate) fn invalidate(&mut self) {
        self.valid = false;
    }

    /// Forms the Jacobian at (t, y): the system's own when it forms one and
    /// was chosen to, else forward differences (n + 1 evaluations).
    pub(crate) fn update<S: OdeSystem>(&mut self, system: &mut S, stats: &mut Statistics, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        let n = self.n;
        eval(system, stats, t, y, &mut self.f_base)?;
        stats.jacobian_rhs_evaluations += 1;
        self.factored_c = None;
        self.sparse_kept = false;
        if self.use_system_jacobian {
            if let Some(cost) = self.update_sparse(system, t, y)? {
                stats.rhs_evaluations += cost.rhs_evaluations;
                stats.jacobian_rhs_evaluations += cost.rhs_evaluations;
                stats.jacobian_force_evaluations += cost.force_evaluations;
                stats.jacobian_evaluations += 1;
                self.sparse_kept = true;
                self.valid = true;
                return Ok(());
            }
            if let Some(cost) = system.jacobian(t, y, &self.floors, &mut self.jacobian)? {
                stats.rhs_evaluations += cost.rhs_evaluations;
                stats.jacobian_rhs_evaluations += cost.rhs_evaluations;
                stats.jacobian_force_evaluations += cost.force_evaluations;
                stats.jacobian_evaluations += 1;
                self.valid = true;
                return Ok(());
            }
        }
        // increments of sqrt(eps) relative to |y_j|, floored at the scale where atol takes over from rtol
        self.y_perturbed.copy_from_slice(y);
        for j in 0..n {
            let step = f64::EPSILON.sqrt() * y[j].abs().max(self.floors[j]);
            self.y_perturbed[j] = y[j] + step;
            let step = self.y_perturbed[j] - y[j];
            eval(system, stats, t, &self.y_perturbed, &mut self.f_perturbed)?;
            stats.jacobian_rhs_evaluations += 1;
            for i in 0..n {
                self.jacobian[i * n + j] = (self.f_perturbed[i] - self.f_base[i]) / step;
            }
            self.y_perturbed[j] = y[j];
        }
        stats.jacobian_evaluations += 1;
        self.valid = true;
        Ok(())
    }

    /// Factors `I - c J` unless the present factors were built for a c within
    /// [`REFACTOR_CHANGE`]; false when the matrix is singular.
    pub(crate) fn factor(&mut self, stats: &mut Statistics, c: f64) -> bool {
        let n = self.n;
        if self.sparse_kept {
            return self.factor_sparse(stats, c, REFACTOR_CHANGE, true, (1.0, c, c * c));
        }
        self.factor_with(stats, c, REFACTOR_CHANGE, n, |jacobian, matrix| {
            for (a, j) in matrix.iter_mut().zip(jacobian) {
                *a = -c * j;
            }
            for i in 0..n {
                matrix[i * n + i] += 1.0;
            }
        })
    }

    /// Factors the reduced Newton matrix `alpha I - c_v J_rr - c_q J_rq` on `r = [v, z]`
    /// (`J_rq`: their derivatives by the positions), of `size` rows, unless the present factors were built for a `key`
    /// within the relative `tolerance`: sparse from the coefficients, or dense from the
    /// matrix `fill(J, matrix)` writes (row-major); false when the matrix is singular.
    pub(crate) fn factor_reduced(&mut self, stats: &mut Statistics, key: f64, tolerance: f64, size: usize, coefficients: (f64, f64, f64), fill: impl FnOnce(&[f64], &mut [f64])) -> bool {
        if self.sparse_kept {
            return self.factor_sparse(stats, key, tolerance, false, coefficients);
        }
        self.factor_with(stats, key, tolerance, size, fill)
    }

    /// The sparse factorisation for `(alpha, c_v, c_q)` unless the present one was for a
    /// `key` within `tolerance`; on a singular matrix the sparse form is turned off.
    fn factor_sparse(&mut self, stats: &mut Statistics, key: f64, tolerance: f64, full: bool, (alpha, c_v, c_q): (f64, f64, f64)) -> bool {
        if let Some(built) = self.factored_c {
            if (key / built - 1.0).abs() <= tolerance && full == self.sparse_full {
                return true;
            }
        }
        let Some(sparse) = &mut self.sparse else { return false };
        stats.factorizations += 1;
        stats.sparse_factorizations += 1;
        let ok = sparse.factor(alpha, c_v, c_q).is_ok();
        self.factored_c = ok.then_some(key);
        self.sparse_full = full;
        if !ok {
            self.sparse_disabled = true;
            self.sparse_failed = true;
            self.valid = false;
        }
        ok
    }

    /// Factors the `size x size` matrix that `fill(J, matrix)` writes (row-major) from the
    /// Jacobian, unless the present factors were built for a `key` within the relative
    /// `tolerance` of this one; false when the matrix is singular.
    pub(crate) fn factor_with(&mut self, stats: &mut Statistics, key: f64, tolerance: f64, size: usize, fill: impl FnOnce(&[f64], &mut [f64])) -> bool {
        if let Some(built) = self.factored_c {
            if (key / built - 1.0).abs() <= tolerance && size == self.factored_size {
                return true;
            }
        }
        fill(&self.jacobian, &mut self.factors[..size * size]);
        stats.factorizations += 1;
        let ok = lu_factor(&mut self.factors[..size * size], size, &mut self.pivots[..size]).is_ok();
        self.factored_c = ok.then_some(key);
        self.factored_size = size;
        ok
    }

    /// Solves `A x = b` in place with the present factors (A: `I - c J` or the last matrix of [`Self::factor_with`]).
    pub(crate) fn solve(&mut self, b: &mut [f64]) {
        if let (true, Some(sparse)) = (self.sparse_kept, &mut self.sparse) {
            match (self.sparse_full, self.factored_c) {
                (true, Some(c)) => sparse.solve_full(c, b),
                _ => sparse.solve_reduced(b),
            }
            return;
        }
        let size = self.factored_size;
        lu_solve(&self.factors[..size * size], size, &self.pivots[..size], b);
    }
}
