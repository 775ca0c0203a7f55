//! Summary quantities tracked at every accepted step, whatever the output
//! sampling: the peak |value| of every force, moment, acceleration and
//! pressure channel with its time, and per clearance joint the largest gap
//! `|e| - c` (maximum penetration, minimum film) with its time and the time
//! in contact.
//!
//! A peak inside a step is found, not sampled: when a step end improves a
//! channel's running peak, one probe just before the end tells whether the
//! channel still rises there. If it falls, the peak lies inside the step and
//! Brent's method searches it on the step's dense output; if it rises, the
//! next step is searched unless its end improves again. Every evaluation
//! serves all channels of its group (`docs/theory/summary-extrema.md`).

use crate::error::SimulationError;

/// Fraction of the step before its end where the probe looks [-]: small
/// enough to see the slope at the end, large enough to stay above the
/// round-off of the dense output.
const PROBE_FRACTION: f64 = 1e-3;
/// Interval tolerance of the peak search, as a fraction of the step [-]:
/// the peak value is then exact to about its square (1e-12 relative).
const SEARCH_TOLERANCE: f64 = 1e-6;
/// Most evaluations of one peak search (Brent needs about 10 on a smooth peak).
const SEARCH_EVALUATIONS: usize = 60;
/// Regula falsi iterations locating a separation inside a step.
const SEPARATION_ITERATIONS: usize = 30;

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
        }
    }

    /// Offers every value of `values` at t as a peak candidate.
    fn offer(peaks: &mut [Peak], kind: Quantities, values: &[f64], t: f64, improved: Option<&mut [bool]>) {
        let mut flags = improved;
        for (i, (peak, &v)) in peaks.iter_mut().zip(values).enumerate() {
            let score = kind.score(v);
            let better = score > peak.score;
            if better {
                *peak = Peak { score, value: v, time: t };
            }
            if let Some(flags) = flags.as_deref_mut() {
                flags[i] = better;
            }
        }
    }

    /// Values at the start of the run.
    fn begin<P: StepProbe>(&mut self, probe: &mut P, t0: f64) -> Result<(), SimulationError> {
        self.kind.evaluate(probe, t0, &mut self.end)?;
        Self::offer(&mut self.peaks, self.kind, &self.end, t0, None);
        Ok(())
    }

    /// Observes the step [t_old, t_new]: its end, a probe before the end when
    /// the end is a new peak, and a search inside the step where one lies there.
    fn observe<P: StepProbe>(&mut self, probe: &mut P, t_old: f64, t_new: f64) -> Result<(), SimulationError> {
        std::mem::swap(&mut self.start, &mut self.end);
        self.kind.evaluate(probe, t_new, &mut self.end)?;
        Self::offer(&mut self.peaks, self.kind, &self.end, t_new, Some(&mut self.improved));
        // a quantity that rose at the last step end and did not climb further peaked in this step
        for i in 0..self.peaks.len() {
            self.search[i] = self.pending[i] && !self.improved[i];
            self.pending[i] = false;
        }
        if self.improved.iter().any(|&b| b) && t_new > t_old {
            // probe the slope at the end: falling means a peak inside the step
            let t_probe = t_new - PROBE_FRACTION * (t_new - t_old);
            if self.kind.evaluate(probe, t_probe, &mut self.scratch).is_ok() {
                for i in 0..self.peaks.len() {
                    if self.improved[i] {
                        let falling = self.kind.score(self.scratch[i]) > self.kind.score(self.end[i]);
                        self.search[i] |= falling;
                        self.pending[i] = !falling;
                    }
                }
                Self::offer(&mut self.peaks, self.kind, &self.scratch, t_probe, None);
            }
        }
        for i in 0..self.peaks.len() {
            if self.search[i] && t_new > t_old {
                self.search_peak(probe, i, t_old, t_new);
            }
        }
        Ok(())
    }

    /// Searches the peak of quantity i inside [a, b]; every evaluation is offered to all quantities.
    /// An evaluation that fails inside the step ends the search (the step ends stand).
    fn search_peak<P: StepProbe>(&mut self, probe: &mut P, i: usize, a: f64, b: f64) {
        let (kind, peaks, scratch) = (self.kind, &mut self.peaks, &mut self.scratch);
        let mut score = |t: f64| -> Option<f64> {
            kind.evaluate(probe, t, scratch).ok()?;
            Self::offer(peaks, kind, scratch, t, None);
            Some(kind.score(scratch[i]))
        };
        maximize(&mut score, a, b, SEARCH_TOLERANCE * (b - a), SEARCH_EVALUATIONS);
    }
}

/// Maximum of f on [a, b] by Brent's method (golden section with parabolic
/// steps; Brent 1973, ch. 5), to an interval of `tolerance` [unit of t] or
/// after `max_evaluations`; returns the best (t, f(t)) found, `None` when an
/// evaluation failed first.
pub(crate) fn maximize(f: &mut dyn FnMut(f64) -> Option<f64>, a: f64, b: f64, tolerance: f64, max_evaluations: usize) -> Option<(f64, f64)> {
    let golden = 0.5 * (3.0 - 5f64.sqrt());
    let (mut a, mut b) = (a, b);
    let mut x = a + golden * (b - a);
    let (mut w, mut v) = (x, x);
    // minimise -f
    let mut fx = -f(x)?;
    let (mut fw, mut fv) = (fx, fx);
    let (mut d, mut e) = (0.0f64, 0.0f64);
    let tol1 = (tolerance / 3.0).max(f64::EPSILON * b.abs().max(a.abs()));
    for _ in 1..max_evaluations {
        let xm = 0.5 * (a + b);
        let tol2 = 2.0 * tol1;
        if (x - xm).abs() <= tol2 - 0.5 * (b - a) {
            break;
        }
        let mut take_golden = true;
        if e.abs() > tol1 {
            // parabola through x, w, v
            let r = (x - w) * (fx - fv);
            let q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            let mut q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            }
            q = q.abs();
            let e_old = e;
            e = d;
            if p.abs() < (0.5 * q * e_old).abs() && p > q * (a - x) && p < q * (b - x) {
                d = p / q;
                let u = x + d;
                if u - a < tol2 || b - u < tol2 {
                    d = tol1.copysign(xm - x);
                }
                take_golden = false;
            }
        }
        if take_golden {
            e = if x >= xm { a - x } else { b - x };
            d = golden * e;
        }
        let u = x + if d.abs() >= tol1 { d } else { tol1.copysign(d) };
        let fu = -f(u)?;
        if fu <= fx {
            if u >= x { a = x } else { b = x }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x { a = u } else { b = u }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    Some((x, -fx))
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
        let tolerance = SEARCH_TOLERANCE * (b - a);
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

/// Units of the channels whose peak is tracked: forces, moments and
/// torques, linear and angular accelerations, pressures.
pub const PEAK_UNITS: [&str; 5] = ["N", "N m", "m/s^2", "rad/s^2", "Pa"];

/// Whether a channel of this unit has its peak tracked.
pub(crate) fn is_peak_unit(unit: &str) -> bool {
    PEAK_UNITS.contains(&unit)
}

/// Peak |value| of one channel over a run.
#[derive(Clone, Debug, PartialEq)]
pub struct ChannelPeak {
    /// Channel name `"<element>.<quantity>"`.
    pub name: String,
    /// SI unit of the channel.
    pub unit: &'static str,
    /// Largest |value| [unit].
    pub peak: f64,
    /// The signed value there [unit].
    pub value: f64,
    /// When it occurred [s].
    pub time: f64,
}

/// Contact statistics of one clearance joint over a run.
#[derive(Clone, Debug, PartialEq)]
pub struct JointExtrema {
    /// Name of the clearance joint.
    pub name: String,
    /// Contact onsets.
    pub impacts: usize,
    /// Time in contact (penetration > 0) [s].
    pub contact_time: f64,
    /// Time in contact over the time simulated [-].
    pub contact_fraction: f64,
    /// Deepest penetration [m] (0 when never in contact).
    pub max_penetration: f64,
    /// When it occurred [s] (NaN when never in contact).
    pub max_penetration_time: f64,
    /// Largest eccentricity ratio |e| / c [-], at the time of the largest gap.
    pub max_eccentricity_ratio: f64,
    /// Thinnest film c - |e| [m] (0 in contact); lubricated joints only.
    pub min_film: Option<f64>,
    /// When it occurred [s]; lubricated joints only.
    pub min_film_time: Option<f64>,
    /// Largest film pressure (gauge) [Pa] and when it occurred [s]; lubricated joints only.
    pub peak_film_pressure: Option<(f64, f64)>,
}

/// Summary quantities of a run, from every accepted step and refined inside
/// the steps on the dense output, whatever the output sampling.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Extrema {
    /// Accepted steps observed.
    pub steps: usize,
    /// Start of the run [s].
    pub t_start: f64,
    /// End of the last accepted step [s].
    pub t_end: f64,
    /// Peaks of the channels with a unit in [`PEAK_UNITS`], in channel order.
    pub channels: Vec<ChannelPeak>,
    /// Statistics of each clearance joint, in model order.
    pub clearance_joints: Vec<JointExtrema>,
}

impl ExtremaTracker {
    /// The summary: `names` and `units` of the tracked channels, then for each
    /// clearance joint its name, impacts, whether it is lubricated and its clearance [m].
    pub(crate) fn summary(&self, names: &[(String, &'static str)], joints: &[(String, usize, bool, f64)]) -> Extrema {
        let duration = self.t_last - self.t_start;
        let channels = names
            .iter()
            .zip(&self.channels.peaks)
            .filter(|(_, p)| !p.time.is_nan())
            .map(|((name, unit), p)| ChannelPeak { name: name.clone(), unit, peak: p.score, value: p.value, time: p.time })
            .collect();
        let clearance_joints = joints
            .iter()
            .zip(self.gaps.peaks.iter().zip(&self.contact_time))
            .map(|((name, impacts, lubricated, clearance), (gap, &contact_time))| {
                let touched = gap.score > 0.0;
                JointExtrema {
                    name: name.clone(),
                    impacts: *impacts,
                    contact_time,
                    contact_fraction: if duration > 0.0 { contact_time / duration } else { 0.0 },
                    max_penetration: if touched { gap.score } else { 0.0 },
                    max_penetration_time: if touched { gap.time } else { f64::NAN },
                    max_eccentricity_ratio: 1.0 + gap.score / clearance,
                    min_film: lubricated.then_some((-gap.score).max(0.0)),
                    min_film_time: lubricated.then_some(gap.time),
                    peak_film_pressure: None,
                }
            })
            .collect();
        Extrema { steps: self.steps, t_start: self.t_start, t_end: self.t_last, channels, clearance_joints }
    }
}

#[cfg(test)]
#[path = "extrema_tests.rs"]
mod tests;
