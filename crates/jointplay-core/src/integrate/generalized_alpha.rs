//! The generalized-alpha method (Chung & Hulbert 1993) in the form of
//! Arnold & Brüls (2007), with a fixed nominal step: second order,
//! unconditionally stable for linear systems, and with a chosen damping of
//! the vibrations the step does not resolve (spectral radius at infinity
//! rho_inf). The method of multibody codes for flexible bodies: its step
//! follows the motion of interest, not the undamped axial and shear
//! vibrations of a beam that an error-controlled method keeps resolving.
//!
//! The state is `y = [q, v, z]` with `dq/dt = v` for the first m components
//! ([`OdeSystem::second_order_positions`]; m = 0 for a system without that
//! split). The rates of `r = [v, z]` get an algorithmic counterpart w, and the step solves
//!
//! ```text
//! (1 - alpha_m) w_(n+1) + alpha_m w_n = (1 - alpha_f) f_r(y_(n+1)) + alpha_f f_r(y_n),
//! r_(n+1) = r_n + h (1 - gamma) w_n + h gamma w_(n+1),
//! q_(n+1) = q_n + h v_n + h^2 (1/2 - beta) a_n + h^2 beta a_(n+1)     (a: the v part of w),
//! alpha_m = (2 rho_inf - 1) / (rho_inf + 1),  alpha_f = rho_inf / (rho_inf + 1),
//! gamma = 1/2 + alpha_f - alpha_m,  beta = (gamma + 1/2)^2 / 4,
//! ```
//!
//! for w_(n+1) by Newton iterations on the Jacobian of f ([`IterationMatrix`],
//! the NDF's machinery), from the predictor `w_(n+1) = w_n`. The positions
//! move with the velocities as in Newmark's method, so that a body turning
//! fast keeps its lengths; rho_inf = 1 is Newmark's average acceleration
//! (trapezoidal) rule. There is no local error estimate: the accuracy is the
//! step's. A step whose Newton iterations fail with a fresh Jacobian is halved
//! (and counted as rejected); after [`GROW_AFTER`] converged steps it doubles
//! again, up to the nominal step. Dense output: the cubic Hermite interpolant
//! of y and dy/dt = f(y) at both ends of the step.
//! Sources: J. Chung, G. M. Hulbert, J. Appl. Mech. 60 (1993) 371-375;
//! M. Arnold, O. Brüls, Multibody Syst. Dyn. 18 (2007) 185-202
//! (`docs/theory/integrator-generalized-alpha.md`).

use super::control::{error_norm, eval, eval_start, Tolerances};
use super::newton_matrix::IterationMatrix;
use super::{Attempt, IntegratorOptions, OdeSystem, Statistics, Stepper};
use crate::error::SimulationError;

/// Newton iterations allowed before the step counts as not converged.
///
/// On a kept Jacobian the iterations stop early when they diverge or when their
/// contraction so far predicts that they will not converge in the iterations left
/// (Hairer's test): a fresh Jacobian is then formed. On a fresh one, whose failure
/// halves the step, that prediction is not made: it misjudges iterations whose
/// contraction varies from one iteration to the next (0.1, then 1e-4). There the
/// iterations stop when a correction grows (divergence: the step is halved) or when
/// one within the tolerances (weighted norm below 1) is not below
/// [`ROUND_OFF_CONTRACTION`] of the one before: Newton on a fresh Jacobian contracts
/// far faster near the solution, so the iterations have reached the round-off of the
/// right-hand side and the step is accepted at the iterate reached (a shorter step
/// would lower the round-off, not the error). Before, a damped beam under gravity at
/// rtol 1e-10, atol 1e-12 halved its step 49 times in its first 200 steps, though
/// Newton had converged; now never (docs/theory/integrator-generalized-alpha.md,
/// "Newton iterations").
const NEWTON_ITERATIONS: usize = 6;
/// Newton stops when its estimated remaining error, in the weighted RMS norm
/// of rtol and atol, is below this (the NDF's criterion).
const NEWTON_TOLERANCE: f64 = 0.03;
/// Factor by which the kept convergence-rate estimate may fall per iteration
/// (CVODE's CRDOWN; Hindmarsh et al., ACM TOMS 31 (2005) 363-396).
const RATE_DECAY: f64 = 0.3;
/// Contraction per iteration above which a correction within the tolerances is round-off
/// (on a fresh Jacobian; see [`NEWTON_ITERATIONS`]).
const ROUND_OFF_CONTRACTION: f64 = 0.5;
/// Step ratio after the Newton iterations failed with a fresh Jacobian.
const NEWTON_FAILURE_SHRINK: f64 = 0.5;
/// Converged steps after which a step cut by a Newton failure doubles again.
const GROW_AFTER: usize = 3;
/// Relative difference below which two steps share the Newton matrix's factors: a step cut to
/// end on an output time differs from the nominal one by rounding only.
const SAME_STEP: f64 = 1e-9;

/// The method's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Parameters {
    pub alpha_m: f64,
    pub alpha_f: f64,
    pub gamma: f64,
    pub beta: f64,
}

impl Parameters {
    /// Chung & Hulbert (1993): second order, and the spectral radius of a vibration
    /// with omega h -> infinity equal to rho_inf.
    pub(crate) fn from_spectral_radius(rho_inf: f64) -> Self {
        let alpha_m = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0);
        let alpha_f = rho_inf / (rho_inf + 1.0);
        let gamma = 0.5 + alpha_f - alpha_m;
        Self { alpha_m, alpha_f, gamma, beta: 0.25 * (gamma + 0.5) * (gamma + 0.5) }
    }
}

/// Generalized-alpha stepper.
pub(crate) struct GeneralizedAlpha {
    tol: Tolerances,
    n: usize,
    /// Positions with `dq/dt = v`: components 0..m are q, m..2m are v.
    m: usize,
    parameters: Parameters,
    /// Nominal step [s].
    nominal: f64,
    /// The step asked for next [s]: the nominal one, or less after a Newton failure.
    ceiling: f64,
    /// Converged steps since the last Newton failure.
    converged_run: usize,
    /// Convergence rate of the Newton iterations, kept from step to step (1 after a fresh Jacobian).
    rate: f64,
    /// The Jacobian and the factors of the Newton matrix.
    pub(crate) matrix: IterationMatrix,
    /// f(y_n) and the algorithmic rates w_n (components m..n; 0..m unused).
    f_old: Vec<f64>,
    w: Vec<f64>,
    /// y_(n+1), f(y_(n+1)) and w_(n+1) of the last attempt.
    y_new: Vec<f64>,
    f_new: Vec<f64>,
    w_new: Vec<f64>,
    /// Newton correction of w (components m..n, shifted to 0..n-m) and of y.
    delta: Vec<f64>,
    dy: Vec<f64>,
    /// Start of the last accepted step: time [s], step [s], y_n and f(y_n).
    dense_t: f64,
    dense_h: f64,
    dense_y: Vec<f64>,
    dense_f: Vec<f64>,
}

impl GeneralizedAlpha {
    /// Allocates every buffer for a state of `n` components whose first `m` are positions
    /// with `dq/dt = v`; the nominal step and rho_inf come from `opts` (checked by
    /// [`IntegratorOptions::validate`]).
    pub(crate) fn new(n: usize, m: usize, opts: &IntegratorOptions, tol: Tolerances) -> Self {
        assert!(2 * m <= n, "{m} positions and their velocities in a state of {n}");
        let v = || vec![0.0; n];
        Self {
            matrix: IterationMatrix::new(n, &tol),
            tol,
            n,
            m,
            parameters: Parameters::from_spectral_radius(opts.spectral_radius),
            nominal: opts.step.unwrap_or(f64::INFINITY).min(opts.max_step),
            ceiling: f64::INFINITY,
            converged_run: 0,
            rate: 1.0,
            f_old: v(),
            w: v(),
            y_new: v(),
            f_new: v(),
            w_new: v(),
            delta: vec![0.0; n - m],
            dy: v(),
            dense_t: 0.0,
            dense_h: 0.0,
            dense_y: v(),
            dense_f: v(),
        }
    }

    /// y_(n+1) from y_n, w_n and w_(n+1).
    fn state_at_end(&mut self, y: &[f64], h: f64) {
        let Parameters { gamma, beta, .. } = self.parameters;
        let m = self.m;
        for i in 0..m {
            let (v, a_old, a_new) = (y[m + i], self.w[m + i], self.w_new[m + i]);
            self.y_new[i] = y[i] + h * v + h * h * ((0.5 - beta) * a_old + beta * a_new);
        }
        for i in m..self.n {
            self.y_new[i] = y[i] + h * ((1.0 - gamma) * self.w[i] + gamma * self.w_new[i]);
        }
    }

    /// The Newton matrix `d residual / d w_(n+1)` for the step h from the kept Jacobian,
    /// factored unless it was for this h (to [`SAME_STEP`]); false when singular.
    fn factor(&mut self, stats: &mut Statistics, h: f64) -> bool {
        let Parameters { alpha_m, alpha_f, gamma, beta } = self.parameters;
        let (n, m) = (self.n, self.m);
        let p = n - m;
        let coefficients = (1.0 - alpha_m, (1.0 - alpha_f) * h * gamma, (1.0 - alpha_f) * h * h * beta);
        self.matrix.factor_reduced(stats, h, SAME_STEP, p, coefficients, |jacobian, matrix| {
            for i in 0..p {
                let row = &jacobian[(m + i) * n..(m + i + 1) * n];
                for j in 0..p {
                    // w_j moves r_j by h gamma, and for a velocity (j < m) its position by h^2 beta
                    let mut d = h * gamma * row[m + j];
                    if j < m {
                        d += h * h * beta * row[j];
                    }
                    matrix[i * p + j] = -(1.0 - alpha_f) * d + if i == j { 1.0 - alpha_m } else { 0.0 };
                }
            }
        })
    }

    /// Simplified Newton iterations for w_(n+1) from the predictor `w_(n+1) = w_n`;
    /// y_(n+1) in `y_new`, on a `fresh` Jacobian or a kept one. False when they diverge, are too
    /// slow (kept Jacobian only), have not converged after [`NEWTON_ITERATIONS`] or meet a
    /// non-finite derivative.
    #[allow(clippy::too_many_arguments)]
    fn solve_step<S: OdeSystem>(&mut self, system: &mut S, stats: &mut Statistics, t_new: f64, y: &[f64], h: f64, fresh: bool) -> Result<bool, SimulationError> {
        let Parameters { alpha_m, alpha_f, gamma, beta } = self.parameters;
        let (n, m) = (self.n, self.m);
        self.w_new[m..].copy_from_slice(&self.w[m..]);
        self.state_at_end(y, h);
        let mut last_norm: Option<f64> = None;
        for iteration in 0..NEWTON_ITERATIONS {
            eval(system, stats, t_new, &self.y_new, &mut self.f_new)?;
            if !self.f_new[m..].iter().all(|v| v.is_finite()) {
                return Ok(false);
            }
            for i in m..n {
                let residual = (1.0 - alpha_m) * self.w_new[i] + alpha_m * self.w[i] - (1.0 - alpha_f) * self.f_new[i] - alpha_f * self.f_old[i];
                self.delta[i - m] = -residual;
            }
            self.matrix.solve(&mut self.delta);
            for i in 0..m {
                self.dy[i] = h * h * beta * self.delta[i];
            }
            for i in m..n {
                self.dy[i] = h * gamma * self.delta[i - m];
            }
            let norm = error_norm(1.0, &self.dy, y, &self.y_new, &self.tol);
            if !norm.is_finite() {
                return Ok(false);
            }
            // the estimated rate: this iteration's, or the kept one on the first (CVODE's test)
            if let Some(old) = last_norm {
                self.rate = (RATE_DECAY * self.rate).max(norm / old);
            }
            let converged = norm * self.rate.min(1.0) < NEWTON_TOLERANCE;
            if let (false, Some(old)) = (converged, last_norm) {
                if fresh {
                    // on a fresh Jacobian (see NEWTON_ITERATIONS): stalled within the tolerances is
                    // round-off, the iterate reached is the solution; growing corrections diverge
                    if norm < 1.0 && norm > ROUND_OFF_CONTRACTION * old {
                        return Ok(true);
                    }
                    if norm >= old {
                        return Ok(false);
                    }
                } else {
                    // on a kept Jacobian, diverging or too slow to converge in the iterations left: form a fresh one
                    let remaining = (NEWTON_ITERATIONS - iteration) as i32;
                    if self.rate >= 1.0 || self.rate.powi(remaining) / (1.0 - self.rate) * norm > NEWTON_TOLERANCE {
                        return Ok(false);
                    }
                }
            }
            for i in m..n {
                self.w_new[i] += self.delta[i - m];
            }
            for (y, d) in self.y_new.iter_mut().zip(&self.dy) {
                *y += d;
            }
            if converged {
                return Ok(true);
            }
            last_norm = Some(norm);
        }
        Ok(false)
    }

    /// Newton with the kept Jacobian, then once more with a fresh one (at the predictor) if that failed.
    fn converge<S: OdeSystem>(&mut self, system: &mut S, stats: &mut Statistics, t: f64, y: &[f64], h: f64) -> Result<bool, SimulationError> {
        let mut fresh = false;
        loop {
            if !self.matrix.is_valid() {
                let m = self.m;
                self.w_new[m..].copy_from_slice(&self.w[m..]);
                self.state_at_end(y, h);
                self.matrix.update(system, stats, t + h, &self.y_new)?;
                self.rate = 1.0;
                fresh = true;
            }
            if self.factor(stats, h) && self.solve_step(system, stats, t + h, y, h, fresh)? {
                return Ok(true);
            }
            if fresh && !self.matrix.retry_dense() {
                return Ok(false);
            }
            self.matrix.invalidate();
        }
    }
}

impl Stepper for GeneralizedAlpha {
    fn start<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
        h_hint: Option<f64>,
    ) -> Result<f64, SimulationError> {
        // the algorithmic rates restart from the derivative at the (new) initial state; the Jacobian is kept
        eval_start(system, stats, t, y, &mut self.f_old)?;
        self.w.copy_from_slice(&self.f_old);
        self.converged_run = 0;
        self.ceiling = h_hint.map_or(self.nominal, |h| h.min(self.nominal));
        Ok(self.ceiling)
    }

    fn attempt<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
        h: f64,
    ) -> Result<Attempt, SimulationError> {
        if !self.converge(system, stats, t, y, h)? {
            self.converged_run = 0;
            self.ceiling = h * NEWTON_FAILURE_SHRINK;
            return Ok(Attempt { accepted: false, h_next: self.ceiling });
        }
        // the derivative at the converged end, which the next step's equation and the dense output use
        eval(system, stats, t + h, &self.y_new, &mut self.f_new)?;
        self.dense_t = t;
        self.dense_h = h;
        self.dense_y.copy_from_slice(y);
        self.dense_f.copy_from_slice(&self.f_old);
        // back towards the nominal step after a Newton failure cut it (a step the
        // driver shortened to land on a sample or on t_end leaves the ceiling as it was)
        self.converged_run += 1;
        if self.ceiling < self.nominal && self.converged_run >= GROW_AFTER {
            self.converged_run = 0;
            self.ceiling = (2.0 * self.ceiling).min(self.nominal);
        }
        Ok(Attempt { accepted: true, h_next: self.ceiling })
    }

    fn y_new(&self) -> &[f64] {
        &self.y_new
    }

    fn steps_end_on_samples(&self) -> bool {
        // inside a step the state is the Hermite interpolant of its ends: the forces of a stiff
        // element at it amplify the interpolation error by its stiffness (docs/theory/integrator-generalized-alpha.md)
        true
    }

    fn dense(&self, t: f64, out: &mut [f64]) {
        // cubic Hermite through (y_n, f(y_n)) and (y_(n+1), f(y_(n+1)))
        let h = self.dense_h;
        let s = (t - self.dense_t) / h;
        let (s2, s3) = (s * s, s * s * s);
        let (h00, h10, h01, h11) = (2.0 * s3 - 3.0 * s2 + 1.0, s3 - 2.0 * s2 + s, 3.0 * s2 - 2.0 * s3, s3 - s2);
        for i in 0..self.n {
            out[i] = h00 * self.dense_y[i] + h10 * h * self.dense_f[i] + h01 * self.y_new[i] + h11 * h * self.f_new[i];
        }
    }

    fn advance<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
    ) -> Result<(), SimulationError> {
        // y is the next step's start; accept() may have moved it (a projection)
        if y == self.y_new.as_slice() {
            self.f_old.copy_from_slice(&self.f_new);
        } else {
            eval(system, stats, t, y, &mut self.f_old)?;
        }
        let m = self.m;
        self.w[m..].copy_from_slice(&self.w_new[m..]);
        Ok(())
    }
}
