//! Tests of the extrema tracker against closed forms.

use super::*;
use super::chebyshev::MAX_DEGREE;
use crate::dynamics::maximize;
use crate::dynamics::outputs::extrema_summary::JointToSummarize;

/// A probe whose single channel and single gap are known functions of time.
struct Known<F: Fn(f64) -> f64, G: Fn(f64) -> f64> {
    channel: F,
    gap: G,
    evaluations: usize,
}

impl<F: Fn(f64) -> f64, G: Fn(f64) -> f64> StepProbe for Known<F, G> {
    fn channels_at(&mut self, t: f64, values: &mut [f64]) -> Result<(), SimulationError> {
        self.evaluations += 1;
        values[0] = (self.channel)(t);
        Ok(())
    }
    fn gaps_at(&mut self, t: f64, gaps: &mut [f64]) {
        gaps[0] = (self.gap)(t);
    }
}

/// Runs the tracker over steps of `h` from 0 to `t_end`.
fn track<P: StepProbe>(probe: &mut P, h: f64, t_end: f64) -> ExtremaTracker {
    let mut tracker = ExtremaTracker::new(1, 1);
    tracker.begin(probe, 0.0).unwrap();
    let n = (t_end / h).round() as usize;
    for k in 0..n {
        tracker.observe(probe, k as f64 * h, (k + 1) as f64 * h).unwrap();
    }
    tracker
}

#[test]
fn test_brent_finds_the_maximum_of_a_parabola_inside_the_interval() {
    let mut f = |t: f64| Some(3.0 - (t - 0.3141).powi(2));
    let (t, v) = maximize(&mut f, 0.0, 1.0, 1e-9, 60).unwrap();
    assert!((t - 0.3141).abs() < 1e-8, "{t}");
    assert!((v - 3.0).abs() < 1e-15, "{v}");
}

#[test]
fn test_peak_strictly_inside_a_step_is_found_to_1e_8_relative() {
    // a Gaussian pulse of peak -5 (|value| 5) at t = 0.3737, steps of 0.1: the peak is inside [0.3, 0.4]
    let pulse = |t: f64| -5.0 * (-((t - 0.3737) / 0.08).powi(2)).exp();
    let mut probe = Known { channel: pulse, gap: |_| -1.0, evaluations: 0 };
    let tracker = track(&mut probe, 0.1, 1.0);
    let peak = tracker.channels.peaks[0];
    assert!((peak.score - 5.0).abs() < 5e-8, "{peak:?}");
    assert!((peak.value + 5.0).abs() < 5e-8, "{peak:?}");
    assert!((peak.time - 0.3737).abs() < 1e-4, "{peak:?}");
    // the step ends alone give far less
    let sampled = (0..=10).map(|k| pulse(0.1 * k as f64).abs()).fold(0.0, f64::max);
    assert!(sampled < 4.7, "{sampled}");
}

#[test]
fn test_peak_after_a_rising_step_end_is_searched_in_the_next_step() {
    // the pulse peaks at 0.305, just after the end of the step [0.2, 0.3]
    let pulse = |t: f64| 2.0 + (-((t - 0.305) / 0.05).powi(2)).exp();
    let mut probe = Known { channel: pulse, gap: |_| -1.0, evaluations: 0 };
    let tracker = track(&mut probe, 0.1, 1.0);
    let peak = tracker.channels.peaks[0];
    assert!((peak.score - 3.0).abs() < 3e-8, "{peak:?}");
    assert!((peak.time - 0.305).abs() < 1e-4, "{peak:?}");
}

#[test]
fn test_monotone_channel_costs_one_probe_per_improving_step() {
    let mut probe = Known { channel: |t: f64| t * t, gap: |_| -1.0, evaluations: 0 };
    let tracker = track(&mut probe, 0.1, 1.0);
    assert_eq!(tracker.channels.peaks[0].time, 1.0);
    assert!((tracker.channels.peaks[0].score - 1.0).abs() < 1e-15);
    // start, then per step: the end and one probe
    assert_eq!(probe.evaluations, 1 + 2 * 10);
}

#[test]
fn test_contact_time_and_deepest_gap_of_a_sine_match_the_closed_form() {
    // gap sin(2 pi t) - 0.5 on [0, 1]: positive on (1/12, 5/12), peak 0.5 at t = 1/4
    let gap = |t: f64| (2.0 * std::f64::consts::PI * t).sin() - 0.5;
    let mut probe = Known { channel: |_| 0.0, gap, evaluations: 0 };
    let tracker = track(&mut probe, 0.07, 1.05);
    let expected = 5.0 / 12.0 - 1.0 / 12.0;
    assert!((tracker.contact_time[0] - expected).abs() < 1e-7, "{}", tracker.contact_time[0]);
    let deepest = tracker.gaps.peaks[0];
    assert!((deepest.score - 0.5).abs() < 1e-10, "{deepest:?}");
    assert!((deepest.time - 0.25).abs() < 1e-4, "{deepest:?}");
    let summary = tracker.summary(&[("a.f".to_string(), "N")], 1, &[JointToSummarize { name: "B".to_string(), events: 0..1, impacts: 3, lubricated: true, clearance: 2.0, modes: None }]);
    let joint = &summary.clearance_joints[0];
    assert_eq!(joint.impacts, 3);
    assert!((joint.contact_fraction - expected / 1.05).abs() < 1e-7);
    assert_eq!(joint.min_film, Some(0.0));
    assert!((joint.max_penetration - 0.5).abs() < 1e-10);
    assert!((joint.max_eccentricity_ratio - 1.25).abs() < 1e-10);
}

#[test]
fn test_minimum_film_of_a_joint_never_in_contact_is_the_smallest_clearance_left() {
    // gap -1e-5 + 4e-6 cos(t - 0.42): thinnest film 6e-6 at t = 0.42, inside the step [0.4, 0.5]
    let gap = |t: f64| -1e-5 + 4e-6 * (t - 0.42).cos();
    let mut probe = Known { channel: |_| 0.0, gap, evaluations: 0 };
    let tracker = track(&mut probe, 0.1, 1.0);
    let summary = tracker.summary(&[("a.f".to_string(), "N")], 1, &[JointToSummarize { name: "B".to_string(), events: 0..1, impacts: 0, lubricated: true, clearance: 2e-5, modes: None }]);
    let joint = &summary.clearance_joints[0];
    assert!((joint.min_film.unwrap() - 6e-6).abs() < 6e-6 * 1e-8, "{joint:?}");
    assert!((joint.min_film_time.unwrap() - 0.42).abs() < 1e-3, "{joint:?}");
    assert_eq!((joint.max_penetration, joint.contact_time), (0.0, 0.0));
    assert!((joint.max_eccentricity_ratio - 0.7).abs() < 1e-8);
    assert!(joint.max_penetration_time.is_nan());
}

/// Two channels: a pulse and a multiple of it, which peak together.
struct Pair {
    scale: f64,
    evaluations: usize,
}

impl StepProbe for Pair {
    fn channels_at(&mut self, t: f64, values: &mut [f64]) -> Result<(), SimulationError> {
        self.evaluations += 1;
        let pulse = (-((t - 0.3737) / 0.08).powi(2)).exp();
        values[0] = pulse;
        values[1] = self.scale * pulse;
        Ok(())
    }
    fn gaps_at(&mut self, _t: f64, gaps: &mut [f64]) {
        gaps[0] = -1.0;
    }
}

#[test]
fn channels_that_peak_together_share_one_search() {
    let mut single = Known { channel: |t: f64| (-((t - 0.3737) / 0.08).powi(2)).exp(), gap: |_| -1.0, evaluations: 0 };
    track(&mut single, 0.1, 1.0);
    let mut pair = Pair { scale: -3.0, evaluations: 0 };
    let mut tracker = ExtremaTracker::new(2, 1);
    tracker.begin(&mut pair, 0.0).unwrap();
    for k in 0..10 {
        tracker.observe(&mut pair, k as f64 * 0.1, (k + 1) as f64 * 0.1).unwrap();
    }
    assert_eq!(pair.evaluations, single.evaluations, "the second channel's search cost evaluations");
    let [first, second] = [tracker.channels.peaks[0], tracker.channels.peaks[1]];
    assert!((first.score - 1.0).abs() < 1e-8 && (second.score - 3.0).abs() < 3e-8, "{first:?} {second:?}");
    assert_eq!(second.value.signum(), -1.0);
}

#[test]
fn inner_evaluations_count_the_probe_and_the_search() {
    // a peak strictly inside the second step: the first step end sets a record
    // (one probe), the second one is searched; every evaluation inside a step is counted
    let pulse = |t: f64| (-((t - 0.35) / 0.2).powi(2)).exp();
    let mut probe = Known { channel: pulse, gap: |_| -1.0, evaluations: 0 };
    let mut tracker = ExtremaTracker::new(1, 1);
    tracker.begin(&mut probe, 0.0).unwrap();
    let at_steps = 1 + 2; // the start and the two step ends
    tracker.observe(&mut probe, 0.0, 0.3).unwrap();
    tracker.observe(&mut probe, 0.3, 0.6).unwrap();
    assert!(tracker.channels.inner_evaluations > 1, "a probe and a search");
    assert_eq!(tracker.channels.inner_evaluations, probe.evaluations - at_steps);
}

/// A chain of `n` bars pinned end to end from a ground pin, in absolute coordinates: 6
/// tracked channels per bar and 2 per pin, plus the points' accelerations.
fn hanging_chain(n: usize) -> crate::dynamics::Model {
    crate::dynamics::beam_tests::model(crate::dynamics::tests::bar_chain_spec(n, 0))
}

/// Runs a chain for 0.1 s in absolute coordinates, sampled every `output_step` when given.
fn run_chain(n: usize, output_step: Option<f64>) -> crate::dynamics::SimulationOutcome {
    use crate::dynamics::{assemble, simulate, Formulation, SimulationOptions, Workspace};
    let model = hanging_chain(n);
    let mut state = assemble(&model, 0.0, &mut Workspace::new(&model)).unwrap();
    let mut options = SimulationOptions { formulation: Formulation::Absolute, ..Default::default() };
    options.integrator.output_step = output_step;
    simulate(&model, &mut state, 0.1, &options, None)
}

#[test]
fn peak_search_evaluations_per_step_do_not_grow_with_the_number_of_channels() {
    // from 4 to 64 bars the channels grow 16-fold; the evaluations per step stay
    // below the bound of one probe and the 31 points of the highest degree, and
    // no peak needs a search of its own (the chain has no kink inside a step)
    let mut per_step = Vec::new();
    for n in [4, 16, 64] {
        let outcome = run_chain(n, None);
        assert!(outcome.error.is_none(), "{:?}", outcome.error);
        let extrema = &outcome.extrema;
        assert_eq!(extrema.fallback_searches, 0, "{n} bars");
        per_step.push(extrema.inner_evaluations as f64 / extrema.steps as f64);
    }
    assert!(per_step.iter().all(|&e| e <= (1 + MAX_DEGREE - 1) as f64), "{per_step:?}");
    assert!(per_step[2] <= 2.0 * per_step[0], "evaluations per step grow with the channels: {per_step:?}");
}

#[test]
fn chain_peaks_equal_a_fine_sampling_of_the_dense_output() {
    // the reference: samples every 1 us (from the same dense output), refined by the
    // parabola through the largest sample and its neighbours
    let tracked = run_chain(16, None);
    let sampled = run_chain(16, Some(1e-6));
    assert!(tracked.extrema.channels.len() >= 6 * 16);
    for peak in &tracked.extrema.channels {
        let samples = sampled.trajectory.channel(&peak.name).unwrap();
        let i = (0..samples.len()).max_by(|&p, &q| samples[p].abs().total_cmp(&samples[q].abs())).unwrap();
        let mut reference = samples[i].abs();
        if i > 0 && i + 1 < samples.len() {
            let (a, b, c) = (samples[i - 1].abs(), reference, samples[i + 1].abs());
            let curvature = a - 2.0 * b + c;
            if curvature < 0.0 {
                reference = b - (a - c).powi(2) / (8.0 * curvature);
            }
        }
        // stated accuracy: 1e-8 of the peak (measured: 1e-10 at most)
        assert!((peak.peak - reference).abs() <= 1e-8 * reference, "{}: tracked {}, reference {reference}", peak.name, peak.peak);
    }
}
