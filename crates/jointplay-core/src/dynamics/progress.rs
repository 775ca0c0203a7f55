//! Progress of a running simulation: the simulated time reached and a
//! cancel flag, shared with another thread (a progress bar, a cancel
//! button) without locks, and optionally a watcher that the simulating
//! thread itself calls at a fixed interval of wall time (to report progress
//! or check for an interrupt without a second thread).

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Called with the simulated time [s]; returns false to cancel the run.
type WatchFn = Box<dyn FnMut(f64) -> bool + Send>;

/// A watcher and when it is next due.
struct Watcher {
    interval: Duration,
    due: Instant,
    callback: WatchFn,
}

/// Simulated time reached, a cancel flag and an optional watcher.
#[derive(Default)]
pub struct Progress {
    time_bits: AtomicU64,
    cancel: AtomicBool,
    /// Locked only by the simulating thread (and never contended).
    watcher: Option<Mutex<Watcher>>,
}

impl std::fmt::Debug for Progress {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Progress").field("time", &self.time()).field("cancelled", &self.is_cancelled()).finish_non_exhaustive()
    }
}

impl Progress {
    /// Fresh progress at t = 0.
    pub fn new() -> Self {
        Self::default()
    }

    /// Progress whose `callback` the simulating thread calls with the simulated
    /// time [s] at an output sample once at least `interval` of wall time has
    /// passed since the start or the previous call; the run is cancelled when it returns false.
    pub fn watched(interval: Duration, callback: impl FnMut(f64) -> bool + Send + 'static) -> Self {
        let watcher = Watcher { interval, due: Instant::now() + interval, callback: Box::new(callback) };
        Self { watcher: Some(Mutex::new(watcher)), ..Self::default() }
    }

    /// Simulated time reached [s].
    pub fn time(&self) -> f64 {
        f64::from_bits(self.time_bits.load(Ordering::Relaxed))
    }

    /// Asks the simulation to stop at its next output sample.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Whether cancellation was requested.
    pub fn is_cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }

    /// Records the simulated time reached [s] and calls the watcher when it is due.
    pub(crate) fn report(&self, time: f64) {
        self.time_bits.store(time.to_bits(), Ordering::Relaxed);
        let Some(watcher) = &self.watcher else { return };
        let Ok(mut watcher) = watcher.try_lock() else { return };
        let now = Instant::now();
        if now < watcher.due {
            return;
        }
        watcher.due = now + watcher.interval;
        if !(watcher.callback)(time) {
            self.cancel();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;

    #[test]
    fn watcher_is_called_once_due_and_can_cancel() {
        let seen = Arc::new(Mutex::new(Vec::new()));
        let record = Arc::clone(&seen);
        let progress = Progress::watched(Duration::from_millis(100), move |t| {
            record.lock().unwrap().push(t);
            t < 2.0
        });
        progress.report(0.5);
        assert!(seen.lock().unwrap().is_empty(), "not due before the interval has passed");
        std::thread::sleep(Duration::from_millis(110));
        progress.report(1.0);
        progress.report(1.5);
        assert_eq!(*seen.lock().unwrap(), vec![1.0], "called once when due, then not until the next interval");
        assert!(!progress.is_cancelled());
        std::thread::sleep(Duration::from_millis(110));
        progress.report(2.5);
        assert_eq!(*seen.lock().unwrap(), vec![1.0, 2.5]);
        assert!(progress.is_cancelled(), "a watcher returning false cancels");
        assert_eq!(progress.time(), 2.5);
    }
}
