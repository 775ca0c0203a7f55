//! Summary quantities tracked at every accepted step, whatever the output
//! sampling: the peak |value| of every force, moment, acceleration and
//! pressure channel with its time, and per clearance joint the largest gap
//! `|e| - c` (maximum penetration, minimum film) with its time and the time
//! in contact.
//!
//! A peak inside a step is found, not sampled: when a step end improves a
//! channel's running peak, one probe just before the end tells whether the
//! channel still rises there. If it falls, the peak lies inside the step; if
//! it rises, the next step is searched unless its end improves again. A step
//! with peaks to search is evaluated once at the Chebyshev-Lobatto points of
//! its dense output, shared by all channels, and each channel's peak is
//! located on its interpolating polynomial; the degree doubles (reusing every
//! point) while some channel's interpolant has not converged, up to
//! [`chebyshev::MAX_DEGREE`], and only a channel whose interpolant still has
//! not (a kink inside the step) is searched by Brent's method on its own
//! (`docs/theory/summary-extrema.md`).

use super::brent::maximize_from;
#[path = "chebyshev.rs"]
mod chebyshev;
use crate::error::SimulationError;
use chebyshev::{CoefficientMatrices, DEGREES, MAX_DEGREE};
use std::sync::LazyLock;

/// The maps from values at the Lobatto points to Chebyshev coefficients,
/// computed once per process (a tracker is moved out of its system and back
/// at every step, so it holds no table of its own).
static MATRICES: LazyLock<CoefficientMatrices> = LazyLock::new(CoefficientMatrices::default);

/// Fraction of the step before its end where the probe looks [-]: small
/// enough to see the slope at the end, large enough to stay above the
/// round-off of the dense output.
const PROBE_FRACTION: f64 = 1e-3;
/// Interval tolerance of the peak search, as a fraction of the step [-]:
/// the peak value is then exact to about its square (1e-8) times the
/// channel's variation over the step, and the parabolic steps usually land
/// far closer. Tighter costs golden-section steps where a channel has a kink.
const SEARCH_TOLERANCE: f64 = 1e-4;
/// Interval tolerance locating a separation, as a fraction of the step [-]
/// (the gaps are cheap to evaluate).
const SEPARATION_TOLERANCE: f64 = 1e-9;
/// Most evaluations of one peak search (Brent needs about 10 on a smooth peak).
const SEARCH_EVALUATIONS: usize = 60;
/// Regula falsi iterations locating a separation inside a step.
const SEPARATION_ITERATIONS: usize = 30;
/// Evaluations of one step remembered so that the searches of several
/// quantities share them (beyond, a search starts from the whole step).
const STEP_POINTS: usize = 4 * SEARCH_EVALUATIONS;
/// An interpolant has converged when its error estimate is at most this
/// fraction of the channel's variation over the step [-] (its peak value is
/// then as exact as Brent's search to `SEARCH_TOLERANCE` makes it: about
/// 1e-8 of the variation).
const INTERPOLATION_TOLERANCE: f64 = 1e-9;
/// ... or at most this fraction of the channel's largest |value| in the step
/// [-]: the floor of what an evaluation resolves (the projection of a
/// dense-output state onto the constraints, and round-off).
const INTERPOLATION_FLOOR: f64 = 1e-8;
/// A channel whose interpolant's tail is at least this fraction of its
/// largest coefficient holds round-off alone [-] (an identically zero
/// quantity); a kink or a jump leaves a tail of at most a few hundredths
/// at the highest degree (coefficients falling as 1/k^2 or 1/k).
const ROUND_OFF_ONLY: f64 = 0.1;
/// Relative tolerance [-] of the maximum located on an interpolant (a
/// polynomial costs no model evaluation).
const POLYNOMIAL_TOLERANCE: f64 = 1e-12;

/// The largest score seen for one quantity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peak {
    /// The score that is maximised (|value| of a channel, the gap of a joint).
    pub score: f64,
    /// The signed value at that time (unit of the quantity).
    pub value: f64,
    /// When it occurred [s]; NaN before the first observation.
    pub time: f64,
}

impl Peak {
    const NONE: Peak = Peak { score: f64::NEG_INFINITY, value: f64::NAN, time: f64::NAN };
}

/// What an observer can evaluate inside the step being observed.
pub(crate) trait StepProbe {
    /// Signed values of the tracked channels at t into `values`.
    fn channels_at(&mut self, t: f64, values: &mut [f64]) -> Result<(), SimulationError>;
    /// Gap `|e| - c` [m] of every clearance joint at t into `gaps` (positive in contact).
    fn gaps_at(&mut self, t: f64, gaps: &mut [f64]);
}

/// Which quantities of a group are evaluated.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
enum Quantities {
    #[default]
    /// Tracked channels (score |value|).
    Channels,
    /// Clearance-joint gaps (score the signed gap).
    Gaps,
}

impl Quantities {
    fn evaluate<P: StepProbe>(self, probe: &mut P, t: f64, out: &mut [f64]) -> Result<(), SimulationError> {
        match self {
            Quantities::Channels => probe.channels_at(t, out),
            Quantities::Gaps => {
                probe.gaps_at(t, out);
                Ok(())
            }
        }
    }

    fn score(self, value: f64) -> f64 {
        match self {
            Quantities::Channels => value.abs(),
            Quantities::Gaps => value,
        }
    }
}

/// Running peaks of a group of quantities evaluated together.
#[derive(Clone, Debug, Default)]
pub(crate) struct PeakGroup {
    kind: Quantities,
    /// Running peak of each quantity.
    pub peaks: Vec<Peak>,
    /// Values at the start of the current step (end of the previous one).
    pub start: Vec<f64>,
    /// Values at the end of the current step.
    pub end: Vec<f64>,
    /// Scratch values of one evaluation inside the step.
    scratch: Vec<f64>,
    /// Quantities still rising at the end of the previous step, at a new peak.
    pending: Vec<bool>,
    /// Quantities whose peak is searched inside the current step.
    search: Vec<bool>,
    /// Quantities whose running peak the current step end improved.
    improved: Vec<bool>,
    /// Evaluations made in the current step.
    points: StepPoints,
    /// Values at the Lobatto points of the highest degree of the current step,
    /// `width` per point, point 0 at the step end.
    nodes: Vec<f64>,
    /// Evaluations inside steps (probes and searches) over the run.
    pub inner_evaluations: usize,
    /// Peaks searched by Brent's method because their interpolant of the
    /// highest degree had not converged, over the run.
    pub fallback_searches: usize,
    /// Whether the peaks come from the step ends alone, with no probe or search
    /// inside a step (a method whose states inside a step are an interpolant that
    /// stiff forces would amplify: generalized-alpha).
    pub step_ends_only: bool,
}

/// The times and values of the evaluations made in one step.
#[derive(Clone, Debug, Default)]
struct StepPoints {
    /// Times [s].
    times: Vec<f64>,
    /// Values, `width` per time.
    values: Vec<f64>,
    /// Quantities per evaluation.
    width: usize,
    /// Evaluations held.
    len: usize,
}

impl StepPoints {
    fn new(width: usize) -> Self {
        Self { times: vec![0.0; STEP_POINTS], values: vec![0.0; STEP_POINTS * width], width, len: 0 }
    }

    /// Remembers an evaluation (silently dropped once the buffer is full).
    fn push(&mut self, t: f64, values: &[f64]) {
        if self.len < STEP_POINTS {
            self.times[self.len] = t;
            self.values[self.len * self.width..(self.len + 1) * self.width].copy_from_slice(values);
            self.len += 1;
        }
    }

    /// The evaluation where quantity i scores highest: its time and score,
    /// and the nearest evaluated times on either side within [a, b].
    fn bracket(&self, kind: Quantities, i: usize, a: f64, b: f64) -> (f64, f64, f64, f64) {
        let (mut x, mut best) = (a, f64::NEG_INFINITY);
        for k in 0..self.len {
            let score = kind.score(self.values[k * self.width + i]);
            if score > best {
                (x, best) = (self.times[k], score);
            }
        }
        let (mut low, mut high) = (a, b);
        for &t in &self.times[..self.len] {
            if t < x && t > low {
                low = t;
            }
            if t > x && t < high {
                high = t;
            }
        }
        (low, x, high, best)
    }
}

impl PeakGroup {
    fn new(kind: Quantities, n: usize) -> Self {
        Self {
            kind,
            peaks: vec![Peak::NONE; n],
            start: vec![0.0; n],
            end: vec![0.0; n],
            scratch: vec![0.0; n],
            pending: vec![false; n],
            search: vec![false; n],
            improved: vec![false; n],
            points: StepPoints::new(n),
            nodes: vec![0.0; (MAX_DEGREE + 1) * n],
            inner_evaluations: 0,
            fallback_searches: 0,
            step_ends_only: false,
        }
    }

    /// Offers every value of `values` at t as a peak candidate.
    fn offer(peaks: &mut [Peak], kind: Quantities, values: &[f64], t: f64) {
        for (peak, &value) in peaks.iter_mut().zip(values) {
            Self::offer_one(peak, kind, value, t);
        }
    }

    /// Values at the start of the run.
    fn begin<P: StepProbe>(&mut self, probe: &mut P, t0: f64) -> Result<(), SimulationError> {
        self.kind.evaluate(probe, t0, &mut self.end)?;
        Self::offer(&mut self.peaks, self.kind, &self.end, t0);
        Ok(())
    }

    /// Observes the step [t_old, t_new]: its end, a probe before the end when
    /// the end is a new peak, and a search inside the step where one lies there.
    fn observe<P: StepProbe>(&mut self, probe: &mut P, t_old: f64, t_new: f64) -> Result<(), SimulationError> {
        std::mem::swap(&mut self.start, &mut self.end);
        self.kind.evaluate(probe, t_new, &mut self.end)?;
        self.points.len = 0;
        // offer the step end; a quantity that rose at the last step end and
        // did not climb further peaked in this step
        let (mut any_improved, mut any_search) = (false, false);
        let kind = self.kind;
        // (zipped, not indexed: one pass with no bounds checks, run at every step)
        let flags = self.improved.iter_mut().zip(self.search.iter_mut()).zip(self.pending.iter_mut());
        for ((&value, peak), ((improved, search), pending)) in self.end.iter().zip(self.peaks.iter_mut()).zip(flags) {
            let score = kind.score(value);
            *improved = score > peak.score;
            if *improved {
                *peak = Peak { score, value, time: t_new };
            }
            *search = *pending && !*improved;
            *pending = false;
            any_improved |= *improved;
            any_search |= *search;
        }
        if t_new <= t_old || self.step_ends_only {
            return Ok(());
        }
        if any_improved {
            any_search |= self.probe_slope(probe, t_old, t_new);
        }
        if any_search {
            self.points.push(t_old, &self.start);
            self.points.push(t_new, &self.end);
            if self.interpolate_peaks(probe, t_old, t_new) {
                for i in 0..self.peaks.len() {
                    if self.search[i] {
                        self.fallback_searches += 1;
                        self.search_peak(probe, i, t_old, t_new);
                    }
                }
            }
        }
        Ok(())
    }

    /// Locates the peaks of the quantities to search on their interpolants at
    /// the Lobatto points of the step [a, b], doubling the degree while some
    /// has not converged; clears the search of each one located. False when an
    /// evaluation failed (the step ends and the points evaluated stand).
    fn interpolate_peaks<P: StepProbe>(&mut self, probe: &mut P, a: f64, b: f64) -> bool {
        let width = self.peaks.len();
        self.nodes[..width].copy_from_slice(&self.end);
        self.nodes[MAX_DEGREE * width..].copy_from_slice(&self.start);
        for n in DEGREES {
            // the new points of degree n: all interior ones first (7), the odd ones after
            let stride = MAX_DEGREE / n;
            let first_new = if n == DEGREES[0] { 1 } else { 2 };
            for j in (1..n).step_by(first_new) {
                let t = 0.5 * (a + b) + 0.5 * (b - a) * chebyshev::lobatto_point(j, n);
                self.inner_evaluations += 1;
                if self.kind.evaluate(probe, t, &mut self.scratch).is_err() {
                    return false;
                }
                Self::offer(&mut self.peaks, self.kind, &self.scratch, t);
                self.points.push(t, &self.scratch);
                self.nodes[j * stride * width..(j * stride + 1) * width].copy_from_slice(&self.scratch);
            }
            let mut any_left = false;
            for i in 0..width {
                if self.search[i] {
                    self.search[i] = !self.locate_on_interpolant(i, n, a, b);
                    any_left |= self.search[i];
                }
            }
            if !any_left {
                break;
            }
        }
        true
    }

    /// Offers the maximum of quantity i's interpolant of degree n on [a, b]
    /// when it has converged; false when it has not.
    fn locate_on_interpolant(&mut self, i: usize, n: usize, a: f64, b: f64) -> bool {
        let (width, stride, kind) = (self.peaks.len(), MAX_DEGREE / n, self.kind);
        let mut values = [0.0; MAX_DEGREE + 1];
        for (j, v) in values[..=n].iter_mut().enumerate() {
            *v = self.nodes[j * stride * width + i];
        }
        let (low, high) = values[..=n].iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| (l.min(v), h.max(v)));
        let magnitude = low.abs().max(high.abs());
        let values = &values[..=n];
        let tail = chebyshev::tail([MATRICES.coefficient(values, n, n - 1), MATRICES.coefficient(values, n, n)]);
        let mut c = [0.0; MAX_DEGREE + 1];
        if tail > INTERPOLATION_TOLERANCE * (high - low) + INTERPOLATION_FLOOR * magnitude {
            if n < MAX_DEGREE {
                return false;
            }
            // a channel of round-off alone (no coefficient stands above its tail) keeps its evaluated points
            MATRICES.coefficients(values, n, &mut c);
            let signal = c[..=n].iter().fold(0.0f64, |m, ck| m.max(ck.abs()));
            return tail >= ROUND_OFF_ONLY * signal;
        }
        MATRICES.coefficients(values, n, &mut c);
        // the best point and its neighbours bracket the interpolant's maximum
        let best = (0..=n).max_by(|&p, &q| kind.score(values[p]).total_cmp(&kind.score(values[q]))).unwrap_or(0);
        let (x_high, x_low) = (chebyshev::lobatto_point(best.saturating_sub(1), n), chebyshev::lobatto_point((best + 1).min(n), n));
        let polynomial = &c[..=n];
        let mut score = |x: f64| Some(kind.score(chebyshev::evaluate(polynomial, x)));
        let start = Some((chebyshev::lobatto_point(best, n), kind.score(values[best]))).filter(|&(x, _)| x > x_low && x < x_high);
        if let Some((x, _)) = maximize_from(&mut score, x_low, x_high, start, POLYNOMIAL_TOLERANCE, 200) {
            let t = 0.5 * (a + b) + 0.5 * (b - a) * x;
            Self::offer_one(&mut self.peaks[i], kind, chebyshev::evaluate(polynomial, x), t);
        }
        true
    }

    /// Offers a value of one quantity at t as a peak candidate.
    fn offer_one(peak: &mut Peak, kind: Quantities, value: f64, t: f64) {
        let score = kind.score(value);
        if score > peak.score {
            *peak = Peak { score, value, time: t };
        }
    }

    /// Probes the slope at the end of the step for the quantities the end
    /// improved: falling means a peak inside the step (searched now), rising
    /// one in the next step (pending). True when some search is due.
    fn probe_slope<P: StepProbe>(&mut self, probe: &mut P, t_old: f64, t_new: f64) -> bool {
        let t_probe = t_new - PROBE_FRACTION * (t_new - t_old);
        self.inner_evaluations += 1;
        if self.kind.evaluate(probe, t_probe, &mut self.scratch).is_err() {
            return false;
        }
        let mut any_search = false;
        for i in 0..self.peaks.len() {
            if self.improved[i] {
                let falling = self.kind.score(self.scratch[i]) > self.kind.score(self.end[i]);
                self.search[i] |= falling;
                self.pending[i] = !falling;
                any_search |= falling;
            }
        }
        Self::offer(&mut self.peaks, self.kind, &self.scratch, t_probe);
        self.points.push(t_probe, &self.scratch);
        any_search
    }

    /// Searches the peak of quantity i inside the step [a, b], starting from the
    /// best evaluation of the step so far and its neighbours (the searches of
    /// quantities that peak together then share their evaluations); every
    /// evaluation is offered to all quantities. An evaluation that fails
    /// inside the step ends the search (the step ends stand).
    fn search_peak<P: StepProbe>(&mut self, probe: &mut P, i: usize, a: f64, b: f64) {
        let tolerance = SEARCH_TOLERANCE * (b - a);
        let (low, x, high, best) = self.points.bracket(self.kind, i, a, b);
        if high - low <= 2.0 * tolerance {
            return;
        }
        let (kind, peaks, scratch, points) = (self.kind, &mut self.peaks, &mut self.scratch, &mut self.points);
        let evaluations = &mut self.inner_evaluations;
        let mut score = |t: f64| -> Option<f64> {
            *evaluations += 1;
            kind.evaluate(probe, t, scratch).ok()?;
            Self::offer(peaks, kind, scratch, t);
            points.push(t, scratch);
            Some(kind.score(scratch[i]))
        };
        let start = (x > low && x < high).then_some((x, best));
        maximize_from(&mut score, low, high, start, tolerance, SEARCH_EVALUATIONS);
    }
}

/// Peaks, gaps and contact time over the accepted steps of a run (the
/// default tracks nothing and holds no buffer).
#[derive(Clone, Debug, Default)]
pub(crate) struct ExtremaTracker {
    /// Tracked channels.
    pub channels: PeakGroup,
    /// Gaps `|e| - c` of the clearance joints [m].
    pub gaps: PeakGroup,
    /// Time in contact of each clearance joint [s].
    pub contact_time: Vec<f64>,
    /// Accepted steps observed.
    pub steps: usize,
    /// Start of the run [s]; NaN before [`ExtremaTracker::begin`].
    pub t_start: f64,
    /// End of the last observed step [s].
    pub t_last: f64,
}

impl ExtremaTracker {
    /// Tracker of `n_channels` channels and `n_joints` clearance joints.
    pub(crate) fn new(n_channels: usize, n_joints: usize) -> Self {
        Self {
            channels: PeakGroup::new(Quantities::Channels, n_channels),
            gaps: PeakGroup::new(Quantities::Gaps, n_joints),
            contact_time: vec![0.0; n_joints],
            steps: 0,
            t_start: f64::NAN,
            t_last: f64::NAN,
        }
    }

    /// Offers the initial state at t0 [s].
    pub(crate) fn begin<P: StepProbe>(&mut self, probe: &mut P, t0: f64) -> Result<(), SimulationError> {
        self.t_start = t0;
        self.t_last = t0;
        self.channels.begin(probe, t0)?;
        self.gaps.begin(probe, t0)
    }

    /// Observes the accepted step [t_old, t_new].
    pub(crate) fn observe<P: StepProbe>(&mut self, probe: &mut P, t_old: f64, t_new: f64) -> Result<(), SimulationError> {
        self.gaps.observe(probe, t_old, t_new)?;
        self.add_contact_time(probe, t_old, t_new);
        self.channels.observe(probe, t_old, t_new)?;
        self.steps += 1;
        self.t_last = t_new;
        Ok(())
    }

    /// Adds the part of [t_old, t_new] each joint spent in contact (gap > 0),
    /// a sign change located on the dense output by regula falsi (Illinois).
    fn add_contact_time<P: StepProbe>(&mut self, probe: &mut P, t_old: f64, t_new: f64) {
        for k in 0..self.contact_time.len() {
            let (g0, g1) = (self.gaps.start[k], self.gaps.end[k]);
            self.contact_time[k] += match (g0 > 0.0, g1 > 0.0) {
                (true, true) => t_new - t_old,
                (false, false) => 0.0,
                (in_at_start, _) => {
                    let root = self.locate_sign_change(probe, k, t_old, t_new);
                    if in_at_start { root - t_old } else { t_new - root }
                }
            };
        }
    }

    /// Time in [a, b] where the gap of joint k changes sign (the ends have opposite signs).
    fn locate_sign_change<P: StepProbe>(&mut self, probe: &mut P, k: usize, a: f64, b: f64) -> f64 {
        let tolerance = SEPARATION_TOLERANCE * (b - a);
        let (mut a, mut b) = (a, b);
        let (mut ga, mut gb) = (self.gaps.start[k], self.gaps.end[k]);
        let mut side = 0i8;
        for _ in 0..SEPARATION_ITERATIONS {
            let t = if gb != ga { (a * gb - b * ga) / (gb - ga) } else { 0.5 * (a + b) };
            let t = t.clamp(a, b);
            probe.gaps_at(t, &mut self.gaps.scratch);
            let g = self.gaps.scratch[k];
            if (g > 0.0) == (ga > 0.0) {
                (a, ga) = (t, g);
                if side == -1 { gb *= 0.5 }
                side = -1;
            } else {
                (b, gb) = (t, g);
                if side == 1 { ga *= 0.5 }
                side = 1;
            }
            if b - a <= tolerance || g == 0.0 {
                break;
            }
        }
        0.5 * (a + b)
    }
}

#[cfg(test)]
#[path = "extrema_tests.rs"]
mod tests;
