//! Dormand-Prince 5(4): explicit Runge-Kutta of order 5 with an embedded
//! order-4 error estimate, first-same-as-last, and Shampine's order-4
//! continuous extension.
//!
//! Tableau: Dormand & Prince, J. Comput. Appl. Math. 6 (1980) 19-26;
//! error coefficients e_i = b_i - b̂_i and dense-output coefficients d_i as in
//! Hairer, Nørsett & Wanner, Solving ODEs I, 2nd ed., Table II.5.2 and
//! Section II.6 (Shampine 1986), checked against the published `dopri5` code.

use super::control::{error_norm, Tolerances, eval_start, eval_trial, starting_step, StartScratch, StepController};
use super::{Attempt, IntegratorOptions, OdeSystem, Statistics, Stepper};
use crate::error::SimulationError;

// nodes c_i
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
// coupling coefficients a_ij
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
// 5th-order weights b_i (= a_7i, FSAL)
const B1: f64 = 35.0 / 384.0;
const B3: f64 = 500.0 / 1113.0;
const B4: f64 = 125.0 / 192.0;
const B5: f64 = -2187.0 / 6784.0;
const B6: f64 = 11.0 / 84.0;
// error weights e_i = b_i - b̂_i
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// dense-output weights d_i (Shampine 1986)
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// PI weight beta of the step controller (Hairer's `dopri5` default 0.04).
const PI_BETA: f64 = 0.04;
/// Largest step growth per step (Hairer's `dopri5` default 10).
const GROW_LIMIT: f64 = 10.0;
/// Local error order of the embedded estimate: err = O(h^5).
const ERROR_ORDER: f64 = 5.0;

/// Dormand-Prince stepper with its stage and dense-output buffers.
pub(crate) struct DormandPrince {
    opts: IntegratorOptions,
    /// Relative and per-component absolute tolerances.
    tol: Tolerances,
    k: [Vec<f64>; 7],
    y_stage: Vec<f64>,
    y_new: Vec<f64>,
    /// Dense-output coefficients r1..r5 of the last accepted step (r1, its start
    /// state, kept at acceptance; r2..r5 formed by `prepare_dense` when first needed).
    r: [Vec<f64>; 5],
    /// Whether r2..r5 belong to the last accepted step.
    dense_ready: bool,
    /// Whether the stages of the last accepted step are still there to form r2..r5
    /// (until the next attempt or the first-same-as-last swap).
    dense_formable: bool,
    t_old: f64,
    h_old: f64,
    control: StepController,
    scratch: StartScratch,
}

impl DormandPrince {
    /// Allocates every buffer for a state of `n` components.
    pub(crate) fn new(n: usize, opts: &IntegratorOptions, tol: Tolerances) -> Self {
        let v = || vec![0.0; n];
        Self {
            opts: opts.clone(),
            tol,
            k: [v(), v(), v(), v(), v(), v(), v()],
            y_stage: v(),
            y_new: v(),
            r: [v(), v(), v(), v(), v()],
            dense_ready: false,
            dense_formable: false,
            t_old: 0.0,
            h_old: 0.0,
            control: StepController::new(PI_BETA, GROW_LIMIT),
            scratch: StartScratch::new(n),
        }
    }

    /// Stage s: y_stage = y + h sum_j a_j k_j, then k_s = f(t + c h, y_stage).
    #[allow(clippy::too_many_arguments)]
    fn stage<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
        h: f64,
        s: usize,
        a: &[f64],
    ) -> Result<Option<SimulationError>, SimulationError> {
        for i in 0..y.len() {
            let mut acc = 0.0;
            for (j, aj) in a.iter().enumerate() {
                acc += aj * self.k[j][i];
            }
            self.y_stage[i] = y[i] + h * acc;
        }
        let (_, rest) = self.k.split_at_mut(s);
        eval_trial(system, stats, t, &self.y_stage, &mut rest[0])
    }

    /// A step `h` rejected for a non-finite trial evaluation (`error` stands below `min_step`).
    fn rejected_non_finite(&mut self, h: f64, error: SimulationError) -> Result<Attempt, SimulationError> {
        Ok(Attempt { accepted: false, h_next: self.control.reject_non_finite(h, self.opts.min_step, error)? })
    }

    /// Keeps the start (t, y) and the step h of an accepted step for its dense output.
    fn keep_step_start(&mut self, y: &[f64], t: f64, h: f64) {
        self.r[0].copy_from_slice(y);
        self.t_old = t;
        self.h_old = h;
        self.dense_ready = false;
        self.dense_formable = true;
    }
}

impl Stepper for DormandPrince {
    fn start<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
        h_hint: Option<f64>,
    ) -> Result<f64, SimulationError> {
        // derivative at the (new) initial state
        self.dense_formable = false;
        eval_start(system, stats, t, y, &mut self.k[0])?;
        self.control.reset();
        match h_hint {
            Some(h) => Ok(h),
            None => {
                let (k0, _) = self.k.split_at(1);
                starting_step(system, stats, t, y, &k0[0], ERROR_ORDER, &self.opts, &self.tol, &mut self.scratch)
            }
        }
    }

    fn attempt<S: OdeSystem>(
        &mut self,
        system: &mut S,
        stats: &mut Statistics,
        t: f64,
        y: &[f64],
        h: f64,
    ) -> Result<Attempt, SimulationError> {
        self.dense_formable = false;
        // stages 2..6, then the 5th-order solution and its derivative (FSAL)
        let stages: [(f64, &[f64]); 5] =
            [(C2, &[A21]), (C3, &[A31, A32]), (C4, &[A41, A42, A43]), (C5, &[A51, A52, A53, A54]), (1.0, &[A61, A62, A63, A64, A65])];
        for (s, (c, a)) in stages.into_iter().enumerate() {
            if let Some(error) = self.stage(system, stats, t + c * h, y, h, s + 1, a)? {
                return self.rejected_non_finite(h, error);
            }
        }
        let k = &self.k;
        for i in 0..y.len() {
            self.y_new[i] = y[i] + h * (B1 * k[0][i] + B3 * k[2][i] + B4 * k[3][i] + B5 * k[4][i] + B6 * k[5][i]);
        }
        // project before the last stage: its derivative, at the state the step ends in, is
        // reused as the next first stage; a failed projection leaves y_new as it is
        let _ = system.project(t + h, &mut self.y_new);
        let (_, last) = self.k.split_at_mut(6);
        if let Some(error) = eval_trial(system, stats, t + h, &self.y_new, &mut last[0])? {
            return self.rejected_non_finite(h, error);
        }
        // embedded error estimate, kept in y_stage
        let k = &self.k;
        for i in 0..y.len() {
            self.y_stage[i] =
                E1 * k[0][i] + E3 * k[2][i] + E4 * k[3][i] + E5 * k[4][i] + E6 * k[5][i] + E7 * k[6][i];
        }
        let err = error_norm(h, &self.y_stage, y, &self.y_new, &self.tol);
        if err <= 1.0 {
            self.keep_step_start(y, t, h);
            Ok(Attempt { accepted: true, h_next: self.control.accepted(h, err, ERROR_ORDER) })
        } else {
            Ok(Attempt { accepted: false, h_next: self.control.rejected(h, err, ERROR_ORDER) })
        }
    }

    fn y_new(&self) -> &[f64] {
        &self.y_new
    }

    /// Fills r2..r5 so that y(t_old + θh) = r1 + θ(r2 + (1-θ)(r3 + θ(r4 + (1-θ) r5))).
    fn prepare_dense(&mut self) {
        if self.dense_ready {
            return;
        }
        debug_assert!(self.dense_formable, "dense output prepared after the stages of its step were replaced");
        let (k, h) = (&self.k, self.h_old);
        let [r0, r1, r2, r3, r4] = &mut self.r;
        for i in 0..r0.len() {
            let dy = self.y_new[i] - r0[i];
            let bspl = h * k[0][i] - dy;
            r1[i] = dy;
            r2[i] = bspl;
            r3[i] = dy - h * k[6][i] - bspl;
            r4[i] = h * (D1 * k[0][i] + D3 * k[2][i] + D4 * k[3][i] + D5 * k[4][i] + D6 * k[5][i] + D7 * k[6][i]);
        }
        self.dense_ready = true;
    }

    fn dense(&self, t: f64, out: &mut [f64]) {
        debug_assert!(self.dense_ready, "dense output used before prepare_dense");
        let theta = (t - self.t_old) / self.h_old;
        let theta1 = 1.0 - theta;
        let r = &self.r;
        for i in 0..out.len() {
            out[i] = r[0][i] + theta * (r[1][i] + theta1 * (r[2][i] + theta * (r[3][i] + theta1 * r[4][i])));
        }
    }

    fn advance<S: OdeSystem>(
        &mut self,
        _system: &mut S,
        _stats: &mut Statistics,
        _t: f64,
        _y: &[f64],
    ) -> Result<(), SimulationError> {
        // first same as last: f(t_new, y_new) becomes the first stage of the next step
        self.dense_formable = false;
        self.k.swap(0, 6);
        Ok(())
    }
}
