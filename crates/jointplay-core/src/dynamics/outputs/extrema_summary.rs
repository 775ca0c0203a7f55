//! The summary a run returns: peaks of the force, moment, acceleration and
//! pressure channels with their times, and the contact statistics of each
//! clearance joint, as tracked at every accepted step by
//! [`super::extrema::ExtremaTracker`].

use super::extrema::ExtremaTracker;
use crate::joint::{ModeTally, AXIAL_BIN, MODE_BINS};

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
    /// Fractions of the time in free flight, impact, sliding and sustained contact (summing to 1), and in
    /// axial contact apart [-]; joints that tally their motion modes only.
    pub mode_fractions: Option<[f64; MODE_BINS]>,
}

/// Summary quantities of a run, from every accepted step and refined inside
/// the steps on the dense output, whatever the output sampling.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Extrema {
    /// Accepted steps observed.
    pub steps: usize,
    /// Evaluations of the mechanism the tracker made inside steps (a probe
    /// before a step end that set a new peak, and the searches of peaks inside
    /// steps), on top of the integrator's; the cost of finding peaks between steps.
    pub inner_evaluations: usize,
    /// Peaks searched by Brent's method on their own, because the interpolant
    /// on the step's shared points had not converged (a kink inside the step);
    /// their evaluations are part of `inner_evaluations`.
    pub fallback_searches: usize,
    /// Start of the run [s].
    pub t_start: f64,
    /// End of the last accepted step [s].
    pub t_end: f64,
    /// Peaks of the channels with a unit in [`PEAK_UNITS`], in channel order.
    pub channels: Vec<ChannelPeak>,
    /// Peak acceleration magnitude of each named body point `"<body>.<point>"` [m/s^2]
    /// (`value` is the magnitude too).
    pub point_accelerations: Vec<ChannelPeak>,
    /// Statistics of each clearance joint, in model order.
    pub clearance_joints: Vec<JointExtrema>,
}

/// A clearance joint as the summary needs it.
pub(crate) struct JointToSummarize {
    /// Name.
    pub name: String,
    /// Indices of its radial event functions (each a gap, `|e| - c` or a bore half's deepest penetration)
    /// among the tracked ones.
    pub events: std::ops::Range<usize>,
    /// Contact onsets counted.
    pub impacts: usize,
    /// Whether it carries a film.
    pub lubricated: bool,
    /// Radial clearance [m].
    pub clearance: f64,
    /// Its motion modes' tally, for a joint that keeps one (its contact time is then the tally's).
    pub modes: Option<ModeTally>,
}

impl ExtremaTracker {
    /// The summary: `names` and `units` of the tracked quantities (the first
    /// `n_channels` channels, then point accelerations), then the clearance joints.
    pub(crate) fn summary(&self, names: &[(String, &'static str)], n_channels: usize, joints: &[JointToSummarize]) -> Extrema {
        let duration = self.t_last - self.t_start;
        let peaks = |range: std::ops::Range<usize>| -> Vec<ChannelPeak> {
            names[range.clone()]
                .iter()
                .zip(&self.channels.peaks[range])
                .filter(|(_, p)| !p.time.is_nan())
                .map(|((name, unit), p)| ChannelPeak { name: name.clone(), unit, peak: p.score, value: p.value, time: p.time })
                .collect()
        };
        let channels = peaks(0..n_channels);
        let point_accelerations = peaks(n_channels..names.len());
        let clearance_joints = joints
            .iter()
            .map(|JointToSummarize { name, events, impacts, lubricated, clearance, modes }| {
                let (impacts, lubricated, clearance) = (*impacts, *lubricated, *clearance);
                let deepest = events.clone().max_by(|&a, &b| self.gaps.peaks[a].score.total_cmp(&self.gaps.peaks[b].score)).expect("a joint has a radial event");
                let gap = &self.gaps.peaks[deepest];
                let contact_time = match modes {
                    Some(tally) => tally.times[1..AXIAL_BIN].iter().sum(),
                    None => self.contact_time[events.start],
                };
                let mode_fractions = modes.map(|tally| tally.fractions());
                // (a joint observed at no step at all has no extrema: NaN)
                let observed = !gap.time.is_nan();
                let touched = gap.score > 0.0;
                JointExtrema {
                    name: name.clone(),
                    impacts,
                    contact_time,
                    contact_fraction: match mode_fractions {
                        Some(fractions) => fractions[1..AXIAL_BIN].iter().sum(),
                        None if duration > 0.0 => contact_time / duration,
                        None => 0.0,
                    },
                    max_penetration: if touched { gap.score } else { 0.0 },
                    max_penetration_time: if touched { gap.time } else { f64::NAN },
                    max_eccentricity_ratio: if observed { 1.0 + gap.score / clearance } else { f64::NAN },
                    min_film: lubricated.then_some(if observed { (-gap.score).max(0.0) } else { f64::NAN }),
                    min_film_time: lubricated.then_some(gap.time),
                    peak_film_pressure: None,
                    mode_fractions,
                }
            })
            .collect();
        Extrema {
            steps: self.steps,
            inner_evaluations: self.channels.inner_evaluations,
            fallback_searches: self.channels.fallback_searches,
            t_start: self.t_start,
            t_end: self.t_last,
            channels,
            point_accelerations,
            clearance_joints,
        }
    }
}
