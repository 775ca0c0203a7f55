//! Variable-order numerical differentiation formulas (NDF, orders 1 to 5)
//! with quasi-constant steps and simplified Newton iterations: the implicit
//! method for stiff problems such as squeeze films, whose damping limits an
//! explicit method's step by stability rather than accuracy.
//!
//! The state history is kept as backward differences `D_j = nabla^j y_n`
//! on an equally spaced grid of the current step h; a step change
//! re-interpolates them onto the new grid. At order k the step solves
//!
//! ```text
//! (1 - kappa_k) gamma_k (y_(n+1) - y_pred) + sum_(j=1..k) gamma_j D_j = h f(t_(n+1), y_(n+1)),
//! y_pred = sum_(j=0..k) D_j,   gamma_j = sum_(i=1..j) 1/i,
//! ```
//!
//! (kappa = 0 gives BDF; the NDF values of kappa buy stability-preserving
//! accuracy) by Newton iterations with the matrix `I - h / alpha_k J`, J a
//! finite-difference Jacobian or the system's own ([`OdeSystem::jacobian`],
//! `docs/theory/integrator-jacobian.md`), kept across steps and refreshed
//! only when the iterations fail to converge. The local error is
//! `(kappa_k gamma_k + 1/(k+1)) nabla^(k+1) y_(n+1)`; after k+1 steps of one
//! size the order moves to whichever of k-1, k, k+1 allows the largest step.
//! Source: Shampine & Reichelt, "The MATLAB ODE Suite", SIAM J. Sci. Comput.
//! 18 (1997) 1-22, Sections 2.1-2.3 (`docs/theory/integrator-ndf.md`).

use super::control::{error_norm, Tolerances, eval, eval_start, starting_step, StartScratch};
use super::newton_matrix::IterationMatrix;
use super::{Attempt, IntegratorOptions, OdeSystem, Statistics, Stepper};
use crate::error::SimulationError;

/// Highest order (the NDFs beyond order 5 are not zero-stable).
pub(crate) const MAX_ORDER: usize = 5;
/// Newton iterations allowed before the step counts as not converged.
const NEWTON_ITERATIONS: usize = 4;
/// Newton stops when its estimated remaining error, in the weighted RMS norm
/// of the error test (1 = the local error tolerance), is below this.
const NEWTON_TOLERANCE: f64 = 0.03;
/// Smallest and largest ratio of a new step to the old one.
const SHRINK_LIMIT: f64 = 0.2;
const GROW_LIMIT: f64 = 10.0;
/// Step ratio after the Newton iterations failed with a fresh Jacobian.
const NEWTON_FAILURE_SHRINK: f64 = 0.5;
/// The NDF coefficients kappa_k of Shampine & Reichelt (1997), Table 1
/// (index = order; order 5 is BDF).
const KAPPA: [f64; MAX_ORDER + 1] = [0.0, -0.1850, -1.0 / 9.0, -0.0823, -0.0415, 0.0];
/// Rows of the difference array: D_0 .. D_(k+2) at the highest order.
const DIFFERENCE_ROWS: usize = MAX_ORDER + 3;

/// Coefficients derived from kappa, by order.
struct Coefficients {
    /// gamma_k = sum_(i=1..k) 1/i.
    gamma: [f64; MAX_ORDER + 1],
    /// alpha_k = (1 - kappa_k) gamma_k.
    alpha: [f64; MAX_ORDER + 1],
    /// Local error constant kappa_k gamma_k + 1/(k+1).
    error_constant: [f64; MAX_ORDER + 1],
}

impl Coefficients {
    fn new() -> Self {
        let mut c = Self { gamma: [0.0; MAX_ORDER + 1], alpha: [0.0; MAX_ORDER + 1], error_constant: [0.0; MAX_ORDER + 1] };
        for k in 0..=MAX_ORDER {
            c.gamma[k] = (1..=k).map(|i| 1.0 / i as f64).sum();
            c.alpha[k] = (1.0 - KAPPA[k]) * c.gamma[k];
            c.error_constant[k] = KAPPA[k] * c.gamma[k] + 1.0 / (k + 1) as f64;
        }
        c
    }
}

/// What the Newton iterations of one step attempt came to.
enum Newton {
    /// Converged after this many iterations.
    Converged(usize),
    /// Diverged, too slow, or met a non-finite derivative.
    Failed,
}

/// NDF stepper: difference array, Jacobian, iteration matrix and dense-output data.
pub(crate) struct Ndf {
    opts: IntegratorOptions,
    /// Relative and per-component absolute tolerances.
    tol: Tolerances,
    n: usize,
    coefficients: Coefficients,
    /// Backward differences D_0..D_(k+2), row j at `j * n`.
    differences: Vec<f64>,
    /// Current order k.
    order: usize,
    /// Step the differences are spaced by [s].
    h: f64,
    /// Steps taken with the current h and order.
    equal_steps: usize,
    /// The Jacobian and the factors of `I - c J`, c = h / alpha_k.
    pub(crate) matrix: IterationMatrix,
    y_predict: Vec<f64>,
    psi: Vec<f64>,
    y_new: Vec<f64>,
    /// Sum of the Newton corrections: nabla^(k+1) y_(n+1).
    correction: Vec<f64>,
    f: Vec<f64>,
    delta: Vec<f64>,
    /// Scratch for re-interpolating the differences.
    rescaled: Vec<f64>,
    /// Differences, order, end time and step of the last accepted step, for dense output.
    dense_differences: Vec<f64>,
    dense_order: usize,
    dense_t: f64,
    dense_h: f64,
    scratch: StartScratch,
}

impl Ndf {
    /// Allocates every buffer for a state of `n` components.
    pub(crate) fn new(n: usize, opts: &IntegratorOptions, tol: Tolerances) -> Self {
        let v = || vec![0.0; n];
        Self {
            opts: opts.clone(),
            matrix: IterationMatrix::new(n, &tol),
            tol,
            n,
            coefficients: Coefficients::new(),
            differences: vec![0.0; DIFFERENCE_ROWS * n],
            order: 1,
            h: 0.0,
            equal_steps: 0,
            y_predict: v(),
            psi: v(),
            y_new: v(),
            correction: v(),
            f: v(),
            delta: v(),
            rescaled: vec![0.0; (MAX_ORDER + 1) * n],
            dense_differences: vec![0.0; (MAX_ORDER + 1) * n],
            dense_order: 1,
            dense_t: 0.0,
            dense_h: 0.0,
            scratch: StartScratch::new(n),
        }
    }

    /// Row j of the difference array.
    fn row(&self, j: usize) -> &[f64] {
        &self.differences[j * self.n..(j + 1) * self.n]
    }

    /// Re-interpolates D_0..D_k onto a grid of step `factor * h` (same
    /// polynomial, new spacing): D <- (R U)^T D with R and U of [`step_change_matrix`].
    fn change_step(&mut self, factor: f64) {
        let (k, n) = (self.order, self.n);
        let r = step_change_matrix(k, factor);
        let u = step_change_matrix(k, 1.0);
        self.rescaled[..(k + 1) * n].fill(0.0);
        for j in 0..=k {
            for i in 0..=k {
                let ru: f64 = (0..=k).map(|l| r[i][l] * u[l][j]).sum();
                if ru != 0.0 {
                    let (source, target) = (&self.differences[i * n..(i + 1) * n], &mut self.rescaled[j * n..(j + 1) * n]);
                    for (t, s) in target.iter_mut().zip(source) {
                        *t += ru * s;
                    }
                }
            }
        }
        self.differences[..(k + 1) * n].copy_from_slice(&self.rescaled[..(k + 1) * n]);
        self.h *= factor;
        self.equal_steps = 0;
    }

    /// Predicted state and the known part psi of the order-k formula.
    fn predict(&mut self) {
        let k = self.order;
        let alpha = self.coefficients.alpha[k];
        self.y_predict.fill(0.0);
        self.psi.fill(0.0);
        for j in 0..=k {
            let gamma = self.coefficients.gamma[j] / alpha;
            let (row, y_predict, psi) = (&self.differences[j * self.n..(j + 1) * self.n], &mut self.y_predict, &mut self.psi);
            for i in 0..row.len() {
                y_predict[i] += row[i];
                psi[i] += gamma * row[i];
            }
        }
    }

    /// Simplified Newton on `y - y_pred = c f(t, y) - psi` from y_pred; the
    /// result in `y_new`, the sum of corrections in `correction`.
    fn solve_step<S: OdeSystem>(&mut self, system: &mut S, stats: &mut Statistics, t: f64, c: f64) -> Result<Newton, SimulationError> {
        let n = self.n;
        self.y_new.copy_from_slice(&self.y_predict);
        self.correction.fill(0.0);
        let mut last_norm: Option<f64> = None;
        for iteration in 0..NEWTON_ITERATIONS {
            eval(system, stats, t, &self.y_new, &mut self.f)?;
            if !self.f.iter().all(|v| v.is_finite()) {
                return Ok(Newton::Failed);
            }
            for i in 0..n {
                self.delta[i] = c * self.f[i] - self.psi[i] - self.correction[i];
            }
            self.matrix.solve(&mut self.delta);
            let norm = error_norm(1.0, &self.delta, &self.y_predict, &self.y_predict, &self.tol);
            if !norm.is_finite() {
                return Ok(Newton::Failed);
            }
            let rate = last_norm.map(|old| norm / old);
            if let Some(rate) = rate {
                // diverging, or too slow to converge in the iterations left
                let remaining = (NEWTON_ITERATIONS - iteration) as i32;
                if rate >= 1.0 || rate.powi(remaining) / (1.0 - rate) * norm > NEWTON_TOLERANCE {
                    return Ok(Newton::Failed);
                }
            }
            for i in 0..n {
                self.y_new[i] += self.delta[i];
                self.correction[i] += self.delta[i];
            }
            if norm == 0.0 || rate.is_some_and(|rate| rate / (1.0 - rate) * norm < NEWTON_TOLERANCE) {
                return Ok(Newton::Converged(iteration + 1));
            }
            last_norm = Some(norm);
        }
        Ok(Newton::Failed)
    }

    /// Newton with the kept Jacobian, then once more with a fresh one if that failed.
    fn converge<S: OdeSystem>(&mut self, system: &mut S, stats: &mut Statistics, t_new: f64, c: f64) -> Result<Newton, SimulationError> {
        let mut fresh = false;
        loop {
            if !self.matrix.is_valid() {
                self.matrix.update(system, stats, t_new, &self.y_predict)?;
                fresh = true;
            }
            if self.matrix.factor(stats, c) {
                if let Newton::Converged(iterations) = self.solve_step(system, stats, t_new, c)? {
                    return Ok(Newton::Converged(iterations));
                }
            }
            if fresh && !self.matrix.retry_dense() {
                return Ok(Newton::Failed);
            }
            self.matrix.invalidate();
        }
    }

    /// Folds the accepted correction into the differences and keeps the dense-output data.
    fn update_differences(&mut self, t_new: f64) {
        let (k, n) = (self.order, self.n);
        // D_(k+2) = d - D_(k+1); D_(k+1) = d; D_j += D_(j+1) for j = k..0
        for i in 0..n {
            let d = self.correction[i];
            self.differences[(k + 2) * n + i] = d - self.differences[(k + 1) * n + i];
            self.differences[(k + 1) * n + i] = d;
        }
        for j in (0..=k).rev() {
            let (lower, upper) = self.differences.split_at_mut((j + 1) * n);
            for (a, b) in lower[j * n..].iter_mut().zip(&upper[..n]) {
                *a += b;
            }
        }
        self.dense_differences[..(k + 1) * n].copy_from_slice(&self.differences[..(k + 1) * n]);
        self.dense_order = k;
        self.dense_t = t_new;
        self.dense_h = self.h;
    }

    /// After k+1 steps of one size: the order among k-1, k, k+1 that allows
    /// the largest next step, and that step's ratio to h.
    fn choose_order_and_step(&mut self, error: f64, safety: f64) -> f64 {
        let k = self.order;
        let weighted = |this: &Self, j: usize, constant: f64| error_norm(constant, this.row(j), &this.y_new, &this.y_new, &this.tol);
        let lower = if k > 1 { weighted(self, k, self.coefficients.error_constant[k - 1]) } else { f64::INFINITY };
        let higher = if k < self.opts.max_order.min(MAX_ORDER) { weighted(self, k + 2, self.coefficients.error_constant[k + 1]) } else { f64::INFINITY };
        let candidates = [(k - 1, lower.powf(-1.0 / k as f64)), (k, error.powf(-1.0 / (k + 1) as f64)), (k + 1, higher.powf(-1.0 / (k + 2) as f64))];
        let (order, best) = candidates.iter().copied().fold((k, 0.0), |acc, c| if c.1 > acc.1 { c } else { acc });
        self.order = order.clamp(1, self.opts.max_order.min(MAX_ORDER));
        (safety * best).min(GROW_LIMIT)
    }
}

/// The matrix R(k, factor) with `R_0j = 1` and `R_ij = prod_(l=1..i) (l - 1 - factor j) / l`:
/// the map between backward differences on grids of step h and `factor` h
/// (Shampine & Reichelt 1997, Section 2.3).
fn step_change_matrix(k: usize, factor: f64) -> [[f64; MAX_ORDER + 1]; MAX_ORDER + 1] {
    let mut r = [[0.0; MAX_ORDER + 1]; MAX_ORDER + 1];
    for j in 0..=k {
        r[0][j] = 1.0;
    }
    for i in 1..=k {
        for j in 1..=k {
            r[i][j] = r[i - 1][j] * (i as f64 - 1.0 - factor * j as f64) / i as f64;
        }
    }
    r
}

impl Stepper for Ndf {
    fn start<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
        h_hint: Option<f64>,
    ) -> Result<f64, SimulationError> {
        // order 1 from the derivative at the (new) initial state; the Jacobian is kept
        let mut f = std::mem::take(&mut self.f);
        let started = eval_start(system, stats, t, y, &mut f);
        self.f = f;
        started?;
        let h = match h_hint {
            Some(h) => h,
            None => starting_step(system, stats, t, y, &self.f, 2.0, &self.opts, &self.tol, &mut self.scratch)?,
        };
        let n = self.n;
        self.differences.fill(0.0);
        self.differences[..n].copy_from_slice(y);
        for i in 0..n {
            self.differences[n + i] = h * self.f[i];
        }
        self.order = 1;
        self.h = h;
        self.equal_steps = 0;
        Ok(h)
    }

    fn attempt<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
        h: f64,
    ) -> Result<Attempt, SimulationError> {
        if h != self.h {
            self.change_step(h / self.h);
        }
        self.predict();
        let c = h / self.coefficients.alpha[self.order];
        let t_new = t + h;
        let iterations = match self.converge(system, stats, t_new, c)? {
            Newton::Converged(iterations) => iterations,
            Newton::Failed => return Ok(Attempt { accepted: false, h_next: h * NEWTON_FAILURE_SHRINK }),
        };
        // fewer Newton iterations, larger step (Shampine & Reichelt's safety factor)
        let safety = 0.9 * (2 * NEWTON_ITERATIONS + 1) as f64 / (2 * NEWTON_ITERATIONS + iterations) as f64;
        let k = self.order;
        for i in 0..self.n {
            self.delta[i] = self.coefficients.error_constant[k] * self.correction[i];
        }
        let error = error_norm(1.0, &self.delta, y, &self.y_new, &self.tol);
        if !(error <= 1.0) {
            let factor = if error.is_finite() { (safety * error.powf(-1.0 / (k + 1) as f64)).max(SHRINK_LIMIT) } else { SHRINK_LIMIT };
            return Ok(Attempt { accepted: false, h_next: h * factor.min(1.0) });
        }
        self.update_differences(t_new);
        self.equal_steps += 1;
        if self.equal_steps > k {
            let factor = self.choose_order_and_step(error, safety);
            self.change_step(factor);
        }
        Ok(Attempt { accepted: true, h_next: self.h })
    }

    fn y_new(&self) -> &[f64] {
        &self.y_new
    }

    fn dense(&self, t: f64, out: &mut [f64]) {
        // Newton form of the interpolant through the last k+1 grid points
        let (n, h, k) = (self.n, self.dense_h, self.dense_order);
        out.copy_from_slice(&self.dense_differences[..n]);
        let mut product = 1.0;
        for j in 0..k {
            product *= (t - (self.dense_t - h * j as f64)) / (h * (j + 1) as f64);
            let row = &self.dense_differences[(j + 1) * n..(j + 2) * n];
            for i in 0..n {
                out[i] += product * row[i];
            }
        }
    }

    fn advance<S: OdeSystem>(
        &mut self,
        _system: &mut S,
        _stats: &mut Statistics,
        _t: f64,
        y: &[f64],
    ) -> Result<(), SimulationError> {
        // a projection moved y_n: move the whole interpolant with it (D_0 only), as if
        // the history had been projected too; shifting y_n alone would put a kink of
        // the size of the projection tolerance into the differences and the predictor
        let n = self.n;
        self.differences[..n].copy_from_slice(y);
        Ok(())
    }
}
