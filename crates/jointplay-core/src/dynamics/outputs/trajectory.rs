//! The recorded channels over time: kept in memory, or handed in chunks of
//! bounded size to a [`SampleSink`] (a results file) while the run goes on,
//! within an optional budget of output bytes.

use super::channel_values::append_sample;
use crate::dynamics::model::channels::ChannelInfo;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::error::SimulationError;

/// Size of the buffer handed to a sink at once [bytes]: about 4 MiB of samples.
pub const CHUNK_BYTES: usize = 4 << 20;

/// Fewest and most samples in one chunk (few channels, or very many).
const CHUNK_ROWS: (usize, usize) = (16, 65_536);

/// Bytes one value takes in the output (a 64-bit float) [bytes].
const VALUE_BYTES: u64 = 8;

/// Receives the recorded samples chunk by chunk, in order, while the run goes on.
pub trait SampleSink: Send {
    /// Takes `times.len()` samples: their times [s] and, row after row, the
    /// values of all channels of each sample. An `Err` stops the run.
    fn write_chunk(&mut self, times: &[f64], rows: &[f64]) -> Result<(), String>;
}

/// Recorded channels over time. With a sink the trajectory holds only the
/// samples not yet handed over (at most one chunk); without one, all of them.
#[derive(Default)]
pub struct Trajectory {
    /// Sample times not yet handed to the sink (all of them without a sink) [s].
    pub time: Vec<f64>,
    /// Channel descriptions.
    pub channels: Vec<ChannelInfo>,
    /// Sample after sample, each the values of all channels in the order of
    /// `channels` (one contiguous append per sample).
    samples: Vec<f64>,
    /// Where full chunks go, if anywhere.
    sink: Option<Box<dyn SampleSink>>,
    /// Samples per chunk handed to the sink.
    chunk_rows: usize,
    /// Samples handed to the sink so far.
    flushed: usize,
    /// Time of the last sample recorded [s].
    last_time: Option<f64>,
    /// Largest output allowed, samples x channels x 8 [bytes].
    max_bytes: Option<u64>,
}

impl std::fmt::Debug for Trajectory {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Trajectory")
            .field("samples", &self.total_len())
            .field("buffered", &self.len())
            .field("channels", &self.channels.len())
            .field("sink", &self.sink.is_some())
            .finish_non_exhaustive()
    }
}

impl Clone for Trajectory {
    /// A copy of the recorded data; the copy has no sink.
    fn clone(&self) -> Self {
        Self {
            time: self.time.clone(),
            channels: self.channels.clone(),
            samples: self.samples.clone(),
            sink: None,
            chunk_rows: self.chunk_rows,
            flushed: self.flushed,
            last_time: self.last_time,
            max_bytes: self.max_bytes,
        }
    }
}

impl PartialEq for Trajectory {
    /// Same channels and the same samples held (sinks are not compared).
    fn eq(&self, other: &Self) -> bool {
        self.time == other.time && self.channels == other.channels && self.samples == other.samples && self.flushed == other.flushed
    }
}

impl Trajectory {
    /// Empty trajectory with the model's channels, keeping every sample in memory.
    pub fn new(model: &Model) -> Self {
        Self::with_channels(model.channel_infos())
    }

    /// Empty trajectory with these channels, keeping every sample in memory.
    pub fn with_channels(channels: Vec<ChannelInfo>) -> Self {
        let chunk_rows = (CHUNK_BYTES / (VALUE_BYTES as usize * channels.len().max(1))).clamp(CHUNK_ROWS.0, CHUNK_ROWS.1);
        Self { channels, chunk_rows, ..Self::default() }
    }

    /// Hands the samples to `sink` in chunks of about [`CHUNK_BYTES`] instead of keeping them.
    pub fn set_sink(&mut self, sink: Box<dyn SampleSink>) {
        self.sink = Some(sink);
        // one chunk, allocated once and reused
        self.time.reserve(self.chunk_rows);
        self.samples.reserve(self.chunk_rows * self.channels.len());
    }

    /// Stops the run with [`SimulationError::OutputBudgetExceeded`] before the output
    /// (samples x channels x 8 bytes) would exceed `max_bytes` [bytes].
    pub fn set_max_bytes(&mut self, max_bytes: Option<u64>) {
        self.max_bytes = max_bytes;
    }

    /// Samples per chunk handed to a sink.
    pub fn chunk_rows(&self) -> usize {
        self.chunk_rows
    }

    /// Number of samples held (not yet handed to a sink).
    pub fn len(&self) -> usize {
        self.time.len()
    }

    /// True when no sample is held.
    pub fn is_empty(&self) -> bool {
        self.time.is_empty()
    }

    /// Number of samples recorded, including those handed to a sink.
    pub fn total_len(&self) -> usize {
        self.flushed + self.len()
    }

    /// Time of the last sample recorded [s], held or handed over.
    pub fn last_time(&self) -> Option<f64> {
        self.last_time
    }

    /// Output size of `samples` samples of all channels [bytes].
    pub fn output_bytes(&self, samples: usize) -> u64 {
        samples as u64 * self.channels.len() as u64 * VALUE_BYTES
    }

    /// Channel `c` at held sample `k`.
    pub fn value(&self, c: usize, k: usize) -> f64 {
        self.samples[k * self.channels.len() + c]
    }

    /// Values of channel `c` over the held samples.
    pub fn column(&self, c: usize) -> Vec<f64> {
        (0..self.len()).map(|k| self.value(c, k)).collect()
    }

    /// Values of the channel named `name` over the held samples, if present.
    pub fn channel(&self, name: &str) -> Option<Vec<f64>> {
        self.channels.iter().position(|c| c.name == name).map(|c| self.column(c))
    }

    /// The values of the last sample (one per channel) when it was taken at `t` [s]
    /// and is still held (not yet handed to a sink).
    pub(crate) fn last_sample_at(&self, t: f64) -> Option<&[f64]> {
        if self.time.last() != Some(&t) {
            return None;
        }
        let width = self.channels.len();
        Some(&self.samples[self.samples.len() - width..])
    }

    /// The held values sample after sample (`len()` rows of `channels.len()` values), row-major.
    pub fn samples(&self) -> &[f64] {
        &self.samples
    }

    /// Takes the held times and [`Trajectory::samples`] out, leaving none held.
    pub fn take(&mut self) -> (Vec<f64>, Vec<f64>) {
        (std::mem::take(&mut self.time), std::mem::take(&mut self.samples))
    }

    /// Appends one sample from an evaluated workspace (whose `constraint_forces`
    /// it fills first); hands a full chunk to the sink.
    pub(crate) fn push(&mut self, model: &Model, t: f64, y: &[f64], ws: &mut Workspace) -> Result<(), SimulationError> {
        self.check_budget(t)?;
        append_sample(model, y, ws, &mut self.samples);
        self.appended(t)
    }

    /// Appends one sample of given values (one per channel) at `t` [s], as [`Trajectory::push`] does.
    pub fn push_values(&mut self, t: f64, values: &[f64]) -> Result<(), SimulationError> {
        assert_eq!(values.len(), self.channels.len(), "one value per channel");
        self.check_budget(t)?;
        self.samples.extend_from_slice(values);
        self.appended(t)
    }

    /// Records the time of the sample whose values were just appended; hands a full chunk to the sink.
    fn appended(&mut self, t: f64) -> Result<(), SimulationError> {
        self.time.push(t);
        self.last_time = Some(t);
        if self.sink.is_some() && self.len() >= self.chunk_rows {
            self.flush()?;
        }
        Ok(())
    }

    /// Hands the held samples to the sink (if any) and clears the buffer, keeping its allocation.
    pub fn flush(&mut self) -> Result<(), SimulationError> {
        let Some(sink) = self.sink.as_mut() else { return Ok(()) };
        if self.time.is_empty() {
            return Ok(());
        }
        let written = sink.write_chunk(&self.time, &self.samples);
        self.flushed += self.time.len();
        self.time.clear();
        self.samples.clear();
        written.map_err(|message| SimulationError::OutputSink { time: self.last_time.unwrap_or(f64::NAN), message })
    }

    /// Hands over what is held and drops the sink.
    pub fn finish(&mut self) -> Result<(), SimulationError> {
        let flushed = self.flush();
        self.sink = None;
        flushed
    }

    /// An error when one more sample would exceed the budget.
    fn check_budget(&self, t: f64) -> Result<(), SimulationError> {
        let Some(budget) = self.max_bytes else { return Ok(()) };
        let bytes = self.output_bytes(self.total_len() + 1);
        if bytes <= budget {
            return Ok(());
        }
        Err(SimulationError::OutputBudgetExceeded { time: t, samples: self.total_len(), channels: self.channels.len(), budget })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::{Arc, Mutex};

    /// One chunk as a sink received it: (times, rows).
    type Chunk = (Vec<f64>, Vec<f64>);

    /// Records every chunk it receives.
    #[derive(Clone, Default)]
    struct Recorder(Arc<Mutex<Vec<Chunk>>>);

    impl SampleSink for Recorder {
        fn write_chunk(&mut self, times: &[f64], rows: &[f64]) -> Result<(), String> {
            self.0.lock().unwrap().push((times.to_vec(), rows.to_vec()));
            Ok(())
        }
    }

    /// Fails on its second chunk.
    struct FailsSecond(usize);

    impl SampleSink for FailsSecond {
        fn write_chunk(&mut self, _times: &[f64], _rows: &[f64]) -> Result<(), String> {
            self.0 += 1;
            if self.0 == 2 { Err("disk full".to_string()) } else { Ok(()) }
        }
    }

    fn channels(n: usize) -> Vec<ChannelInfo> {
        (0..n).map(|k| ChannelInfo { name: format!("c.{k}"), unit: "m", description: String::new() }).collect()
    }

    /// Sample k of channel c has the value 1000 k + c.
    fn row(k: usize, n: usize) -> Vec<f64> {
        (0..n).map(|c| (1000 * k + c) as f64).collect()
    }

    #[test]
    fn chunk_size_is_about_four_mebibytes_within_bounds() {
        assert_eq!(Trajectory::with_channels(channels(53)).chunk_rows(), CHUNK_BYTES / (8 * 53));
        assert_eq!(Trajectory::with_channels(channels(1)).chunk_rows(), 65_536);
        assert_eq!(Trajectory::with_channels(channels(100_000)).chunk_rows(), 16);
    }

    #[test]
    fn sink_receives_every_sample_once_in_order_in_full_chunks() {
        let n = 100_000; // 16 rows per chunk
        let recorder = Recorder::default();
        let mut trajectory = Trajectory::with_channels(channels(n));
        trajectory.set_sink(Box::new(recorder.clone()));
        let (capacity_times, capacity_rows) = (trajectory.time.capacity(), trajectory.samples.capacity());
        for k in 0..40 {
            trajectory.push_values(k as f64 * 1e-3, &row(k, n)).unwrap();
            assert!(trajectory.len() < 16, "never more than one chunk held");
        }
        assert_eq!((trajectory.time.capacity(), trajectory.samples.capacity()), (capacity_times, capacity_rows), "buffer reused");
        assert_eq!(trajectory.len(), 8);
        trajectory.finish().unwrap();
        let chunks = recorder.0.lock().unwrap();
        assert_eq!(chunks.iter().map(|c| c.0.len()).collect::<Vec<_>>(), vec![16, 16, 8]);
        let times: Vec<f64> = chunks.iter().flat_map(|c| c.0.clone()).collect();
        assert_eq!(times, (0..40).map(|k| k as f64 * 1e-3).collect::<Vec<_>>());
        let rows: Vec<f64> = chunks.iter().flat_map(|c| c.1.clone()).collect();
        assert_eq!(rows, (0..40).flat_map(|k| row(k, n)).collect::<Vec<_>>());
        assert_eq!((trajectory.total_len(), trajectory.last_time()), (40, Some(39e-3)));
    }

    #[test]
    fn without_a_sink_every_sample_stays_in_memory() {
        let mut trajectory = Trajectory::with_channels(channels(3));
        for k in 0..100_000 {
            trajectory.push_values(k as f64, &row(k, 3)).unwrap();
        }
        trajectory.finish().unwrap();
        assert_eq!((trajectory.len(), trajectory.total_len()), (100_000, 100_000));
        assert_eq!(trajectory.value(2, 99_999), 99_999_002.0);
    }

    #[test]
    fn a_failing_sink_stops_with_its_message() {
        let mut trajectory = Trajectory::with_channels(channels(100_000));
        trajectory.set_sink(Box::new(FailsSecond(0)));
        let error = (0..40).find_map(|k| trajectory.push_values(k as f64, &row(k, 100_000)).err()).expect("an error");
        assert_eq!(error, SimulationError::OutputSink { time: 31.0, message: "disk full".to_string() });
        assert_eq!(error.to_string(), "writing the results failed at t = 3.100000e1 s: disk full");
    }

    #[test]
    fn budget_stops_before_the_sample_that_would_exceed_it() {
        // 3 channels x 8 bytes = 24 bytes per sample: 10 samples fit in 250 bytes
        let mut trajectory = Trajectory::with_channels(channels(3));
        trajectory.set_max_bytes(Some(250));
        let error = (0..20).find_map(|k| trajectory.push_values(k as f64, &row(k, 3)).err()).expect("an error");
        assert_eq!(trajectory.total_len(), 10, "what fits is kept");
        assert_eq!(error, SimulationError::OutputBudgetExceeded { time: 10.0, samples: 10, channels: 3, budget: 250 });
        assert_eq!(
            error.to_string(),
            "output budget max_output_bytes = 250 bytes reached at t = 1.000000e1 s (10 samples x 3 channels x 8 bytes); \
             raise max_output_bytes, set a coarser output_step or a shorter t_end"
        );
    }

    /// A pendulum of 1 + 3 x 12 channels (bodies) sampled every 0.1 ms for 0.2 s.
    fn pendulum_run(sink: Option<Box<dyn SampleSink>>, max_output_bytes: Option<u64>) -> crate::dynamics::SimulationOutcome {
        use crate::dynamics::{assemble, compile, simulate_with_sink, SimulationOptions, Workspace};
        let spec = r#"{"name": "pendulum", "gravity": [0, -9.81], "ground_points": [{"name": "O", "position": [0, 0]}],
            "bodies": [{"name": "bar", "mass": 1, "inertia": 0.02, "position": [0.25, 0], "angle": 0, "velocity": [0, 0],
                        "angular_velocity": 0, "points": [{"name": "O", "position": [-0.25, 0]}]}],
            "joints": [{"type": "revolute", "name": "pin", "first": "ground.O", "second": "bar.O"}],
            "drivers": [], "beams": [], "sensors": [], "forces": []}"#;
        let model = compile(&serde_json::from_str(spec).unwrap()).unwrap();
        let mut state = assemble(&model, 0.0, &mut Workspace::new(&model)).unwrap();
        let mut options = SimulationOptions { max_output_bytes, ..Default::default() };
        options.integrator.output_step = Some(1e-4);
        let outcome = simulate_with_sink(&model, &mut state, 0.2, &options, None, sink);
        // the state is that of the last accepted step: the end of a complete run; after a failure
        // inside a step, samples taken from that step's dense output may lie beyond it
        let last_sample = outcome.trajectory.last_time().unwrap_or(0.0);
        match outcome.error {
            None => assert_eq!(state.time, last_sample, "a complete run ends at its last sample"),
            Some(_) => assert!(state.time <= last_sample, "state at {} after the last sample {last_sample}", state.time),
        }
        outcome
    }

    #[test]
    fn streamed_run_hands_over_exactly_the_samples_kept_in_memory() {
        let kept = pendulum_run(None, None);
        assert!(kept.error.is_none(), "{:?}", kept.error);
        assert_eq!(kept.trajectory.len(), 2001);
        let recorder = Recorder::default();
        let streamed = pendulum_run(Some(Box::new(recorder.clone())), None);
        assert!(streamed.error.is_none(), "{:?}", streamed.error);
        assert_eq!((streamed.trajectory.len(), streamed.trajectory.total_len()), (0, 2001), "nothing held at the end");
        let chunks = recorder.0.lock().unwrap();
        let times: Vec<f64> = chunks.iter().flat_map(|c| c.0.clone()).collect();
        let rows: Vec<f64> = chunks.iter().flat_map(|c| c.1.clone()).collect();
        assert_eq!(times, kept.trajectory.time);
        assert_eq!(rows, kept.trajectory.samples());
    }

    #[test]
    fn budget_stops_a_run_keeping_the_samples_within_it() {
        let channels = pendulum_run(None, Some(0)).trajectory.channels.len();
        let budget = 100 * 8 * channels as u64 + 7;
        let outcome = pendulum_run(None, Some(budget));
        assert_eq!(outcome.trajectory.len(), 100);
        match outcome.error {
            Some(SimulationError::OutputBudgetExceeded { time, samples: 100, budget: b, .. }) => {
                assert!((time - 100e-4).abs() < 1e-12, "stopped at the 101st sample, t = {time}");
                assert_eq!(b, budget);
            }
            other => panic!("expected the budget error, got {other:?}"),
        }
    }
}
