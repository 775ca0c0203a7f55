//! Variable-step Adams-Bashforth-Moulton predictor-corrector in PECE mode.
//!
//! At order k the predictor integrates the polynomial through the last k
//! derivatives f_n, f_(n-1), ... at their actual (non-uniform) times; the
//! corrector integrates the polynomial through f(t_(n+1), y_P) and the last
//! k-1 derivatives. Both are order k. The weights are recomputed every step
//! from the Lagrange bases on the scaled nodes, so any step sequence is
//! exact for polynomials of degree k. The local error of the corrector is
//! estimated from the predictor-corrector difference (Milne's device) with
//! the variable-step constant C_C / (C_C - C_P), where C_P and C_C are the
//! integrals over [0, 1] of the nodal products of the two interpolants
//! (Hairer, Nørsett & Wanner, Solving ODEs I, Sections III.1 and III.5).
//! After a (re)start the order ramps from 1 up to [`MAX_ORDER`] as history
//! accumulates; two rejections in a row drop the history back to order 1.

use super::control::{error_norm, Tolerances, eval, eval_start, eval_trial, starting_step, StartScratch, StepController};
use super::polynomial::{integral, lagrange_basis, node_product_integral, Poly, MAX_NODES};
use super::{Attempt, IntegratorOptions, OdeSystem, Statistics, Stepper};
use crate::error::SimulationError;

/// Highest order used (the classic fourth-order Adams-Bashforth-Moulton pair).
pub(crate) const MAX_ORDER: usize = 4;
/// Largest step growth per step: keeps the non-uniform nodes well spread.
const GROW_LIMIT: f64 = 2.0;
/// Rejections in a row after which the order drops back to 1.
const REJECTIONS_BEFORE_ORDER_DROP: usize = 2;

/// Adams PECE stepper with its derivative history and dense-output data.
pub(crate) struct Adams {
    opts: IntegratorOptions,
    /// Relative and per-component absolute tolerances.
    tol: Tolerances,
    /// Past derivatives, index 0 the most recent (at the current time).
    history_f: Vec<Vec<f64>>,
    /// Times of the past derivatives [s].
    history_t: [f64; MAX_ORDER],
    /// Number of valid history entries.
    history_len: usize,
    y_pred: Vec<f64>,
    f_pred: Vec<f64>,
    y_new: Vec<f64>,
    /// State at the start of the last accepted step.
    y_old: Vec<f64>,
    /// Corrector Lagrange basis of the last attempt and of the last accepted step.
    trial_basis: [Poly; MAX_NODES],
    dense_basis: [Poly; MAX_NODES],
    dense_order: usize,
    t_old: f64,
    h_old: f64,
    control: StepController,
    rejections_in_a_row: usize,
    started: bool,
    scratch: StartScratch,
}

impl Adams {
    /// Allocates every buffer for a state of `n` components.
    pub(crate) fn new(n: usize, opts: &IntegratorOptions, tol: Tolerances) -> Self {
        let v = || vec![0.0; n];
        Self {
            opts: opts.clone(),
            tol,
            history_f: (0..MAX_ORDER).map(|_| v()).collect(),
            history_t: [0.0; MAX_ORDER],
            history_len: 0,
            y_pred: v(),
            f_pred: v(),
            y_new: v(),
            y_old: v(),
            trial_basis: [[0.0; MAX_NODES + 1]; MAX_NODES],
            dense_basis: [[0.0; MAX_NODES + 1]; MAX_NODES],
            dense_order: 1,
            t_old: 0.0,
            h_old: 0.0,
            control: StepController::new(0.0, GROW_LIMIT),
            rejections_in_a_row: 0,
            started: false,
            scratch: StartScratch::new(n),
        }
    }

    /// Predictor: y_pred = y + h sum_j w_j f_j over the last k derivatives; returns C_P.
    fn predict(&mut self, y: &[f64], h: f64, k: usize, nodes: &[f64; MAX_NODES]) -> f64 {
        let mut basis = [[0.0; MAX_NODES + 1]; MAX_NODES];
        lagrange_basis(&nodes[..k], &mut basis);
        let mut w = [0.0; MAX_NODES];
        for j in 0..k {
            w[j] = h * integral(&basis[j], 1.0);
        }
        for i in 0..y.len() {
            let mut acc = y[i];
            for j in 0..k {
                acc += w[j] * self.history_f[j][i];
            }
            self.y_pred[i] = acc;
        }
        node_product_integral(&nodes[..k], None)
    }

    /// Corrector: y_new = y + h (w_0 f_pred + sum_j w_j f_(j-1)); returns C_C.
    fn correct(&mut self, y: &[f64], h: f64, k: usize, nodes: &[f64; MAX_NODES]) -> f64 {
        let mut corr_nodes = [0.0; MAX_NODES];
        corr_nodes[0] = 1.0;
        corr_nodes[1..k].copy_from_slice(&nodes[..k - 1]);
        lagrange_basis(&corr_nodes[..k], &mut self.trial_basis);
        let mut w = [0.0; MAX_NODES];
        for j in 0..k {
            w[j] = h * integral(&self.trial_basis[j], 1.0);
        }
        for i in 0..y.len() {
            let mut acc = y[i] + w[0] * self.f_pred[i];
            for j in 1..k {
                acc += w[j] * self.history_f[j - 1][i];
            }
            self.y_new[i] = acc;
        }
        node_product_integral(&nodes[..k - 1], Some(1.0))
    }

    /// Keeps what the dense output of the accepted step needs.
    fn keep_dense(&mut self, t: f64, y: &[f64], h: f64, k: usize) {
        self.y_old.copy_from_slice(y);
        self.dense_basis = self.trial_basis;
        self.dense_order = k;
        self.t_old = t;
        self.h_old = h;
    }
}

impl Stepper for Adams {
    fn start<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
        h_hint: Option<f64>,
    ) -> Result<f64, SimulationError> {
        // history restarts from the single derivative at (t, y): order 1
        eval_start(system, stats, t, y, &mut self.history_f[0])?;
        self.history_t[0] = t;
        self.history_len = 1;
        self.rejections_in_a_row = 0;
        self.control.reset();
        let first = !self.started;
        self.started = true;
        if let (true, Some(h)) = (first, h_hint) {
            return Ok(h);
        }
        // order-1 starting step (local error O(h^2)), capped by the caller's proposal
        let (f0, _) = self.history_f.split_at(1);
        let h = starting_step(system, stats, t, y, &f0[0], 2.0, &self.opts, &self.tol, &mut self.scratch)?;
        Ok(h_hint.map_or(h, |hint| hint.min(h)))
    }

    fn attempt<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
        h: f64,
    ) -> Result<Attempt, SimulationError> {
        // nodes of the history in units of h, relative to t (node 0 is t itself)
        let k = self.history_len.min(MAX_ORDER);
        let mut nodes = [0.0; MAX_NODES];
        for j in 0..k {
            nodes[j] = (self.history_t[j] - t) / h;
        }
        // predict, evaluate, correct
        let cp = self.predict(y, h, k, &nodes);
        if let Some(error) = eval_trial(system, stats, t + h, &self.y_pred, &mut self.f_pred)? {
            self.rejections_in_a_row += 1;
            return Ok(Attempt { accepted: false, h_next: self.control.reject_non_finite(h, self.opts.min_step, error)? });
        }
        let cc = self.correct(y, h, k, &nodes);
        // Milne's device: corrector error = C_C / (C_C - C_P) (y_C - y_P)
        for i in 0..y.len() {
            self.y_pred[i] = self.y_new[i] - self.y_pred[i];
        }
        let milne = (cc / (cc - cp)).abs();
        let err = error_norm(milne, &self.y_pred, y, &self.y_new, &self.tol);
        let q = (k + 1) as f64;
        if err <= 1.0 {
            self.rejections_in_a_row = 0;
            self.keep_dense(t, y, h, k);
            return Ok(Attempt { accepted: true, h_next: self.control.accepted(h, err, q) });
        }
        // repeated failure: the old history is no guide, fall back to order 1
        self.rejections_in_a_row += 1;
        if self.rejections_in_a_row >= REJECTIONS_BEFORE_ORDER_DROP {
            self.history_len = 1;
        }
        Ok(Attempt { accepted: false, h_next: self.control.rejected(h, err, q) })
    }

    fn y_new(&self) -> &[f64] {
        &self.y_new
    }

    fn dense(&self, t: f64, out: &mut [f64]) {
        let theta = (t - self.t_old) / self.h_old;
        let k = self.dense_order;
        let mut w = [0.0; MAX_NODES];
        for j in 0..k {
            w[j] = self.h_old * integral(&self.dense_basis[j], theta);
        }
        for i in 0..out.len() {
            let mut acc = self.y_old[i] + w[0] * self.f_pred[i];
            for j in 1..k {
                acc += w[j] * self.history_f[j - 1][i];
            }
            out[i] = acc;
        }
    }

    fn advance<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
    ) -> Result<(), SimulationError> {
        // final evaluation of PECE at the accepted (possibly projected) state
        self.history_f.rotate_right(1);
        self.history_t.rotate_right(1);
        self.history_t[0] = t;
        self.history_len = (self.history_len + 1).min(MAX_ORDER);
        eval(system, stats, t, y, &mut self.history_f[0])
    }
}
