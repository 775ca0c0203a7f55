//! Progress of a running simulation: the simulated time reached and a
//! cancel flag, shared with another thread (a progress bar, a cancel
//! button) without locks, and optionally a watcher that the simulating
//! thread itself calls at a fixed interval of wall time (to report progress
//! or check for an interrupt without a second thread).

use std::sync::atomic::{AtomicBool, AtomicU32, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use crate::interrupt::Watch;
use std::time::{Duration, Instant};

/// Called with the simulated time [s]; returns false to cancel the run.
type WatchFn = Box<dyn FnMut(f64) -> bool + Send>;

/// Most reports between two readings of the clock: bounds the extra delay of
/// a watcher call when samples suddenly slow down.
const MAX_STRIDE: u32 = 64;

/// A watcher, when it is next due, and how often the clock is read.
struct Watcher {
    interval: Duration,
    due: Instant,
    callback: WatchFn,
    /// When the clock was last read.
    checked: Instant,
    /// Reports from one reading of the clock to the next.
    stride: u32,
}

/// Simulated time reached, a cancel flag and an optional watcher.
#[derive(Default)]
pub struct Progress {
    shared: Arc<Shared>,
}

/// What a [`Progress`] shares with the loops of its run ([`crate::interrupt`]).
#[derive(Default)]
struct Shared {
    time_bits: AtomicU64,
    cancel: AtomicBool,
    /// Locked only by the simulating thread (and never contended).
    watcher: Option<Mutex<Watcher>>,
    /// Reports left before the watcher next reads the clock.
    countdown: AtomicU32,
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
    /// While samples come fast, the clock is read only every few samples (at most
    /// [`MAX_STRIDE`]), about 16 times per interval.
    pub fn watched(interval: Duration, callback: impl FnMut(f64) -> bool + Send + 'static) -> Self {
        let now = Instant::now();
        let watcher = Watcher { interval, due: now + interval, callback: Box::new(callback), checked: now, stride: 1 };
        Self { shared: Arc::new(Shared { watcher: Some(Mutex::new(watcher)), ..Shared::default() }) }
    }

    /// Simulated time reached [s].
    pub fn time(&self) -> f64 {
        f64::from_bits(self.shared.time_bits.load(Ordering::Relaxed))
    }

    /// Asks the simulation to stop: at once inside a long loop that asks
    /// [`crate::interrupt::keep_going`] (a Reynolds solve, the evaluations of a step).
    pub fn cancel(&self) {
        self.shared.cancel();
    }

    /// Whether cancellation was requested.
    pub fn is_cancelled(&self) -> bool {
        self.shared.cancel.load(Ordering::Relaxed)
    }

    /// Records the simulated time reached [s] and calls the watcher when it is due.
    pub(crate) fn report(&self, time: f64) {
        self.shared.time_bits.store(time.to_bits(), Ordering::Relaxed);
        self.shared.watch(time);
    }

    /// Calls the watcher when it is due (with the time last reported); false once the run is cancelled.
    pub fn poll(&self) -> bool {
        self.shared.keep_going()
    }

    /// Runs `f` with this progress watching every long loop of the thread ([`crate::interrupt`]).
    pub fn scope<T>(&self, f: impl FnOnce() -> T) -> T {
        crate::interrupt::scoped(self.shared.clone(), f)
    }
}

impl Watch for Shared {
    fn keep_going(&self) -> bool {
        self.watch(f64::from_bits(self.time_bits.load(Ordering::Relaxed)));
        !self.cancel.load(Ordering::Relaxed)
    }
}

impl Shared {
    fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Calls the watcher with the simulated time [s] when it is due.
    fn watch(&self, time: f64) {
        let Some(watcher) = &self.watcher else { return };
        if self.countdown.fetch_sub(1, Ordering::Relaxed) > 1 {
            return;
        }
        let Ok(mut watcher) = watcher.try_lock() else { return };
        let now = Instant::now();
        // about 16 readings per interval: a longer stride while samples come fast
        watcher.stride = if now - watcher.checked < watcher.interval / 16 { (watcher.stride * 2).min(MAX_STRIDE) } else { (watcher.stride / 2).max(1) };
        watcher.checked = now;
        self.countdown.store(watcher.stride, Ordering::Relaxed);
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

    /// Reports t, t + 1, ... until the watcher is called; the number of reports it took.
    fn report_until_called(progress: &Progress, seen: &Mutex<Vec<f64>>, t: f64) -> usize {
        let before = seen.lock().unwrap().len();
        (1..=2 * MAX_STRIDE as usize)
            .find(|&k| {
                progress.report(t + k as f64);
                seen.lock().unwrap().len() > before
            })
            .expect("the watcher is called within a stride of its due time")
    }

    #[test]
    fn watcher_is_called_once_due_and_can_cancel() {
        let seen = Arc::new(Mutex::new(Vec::new()));
        let record = Arc::clone(&seen);
        let progress = Progress::watched(Duration::from_millis(100), move |t| {
            record.lock().unwrap().push(t);
            t < 100.0
        });
        // fast reports before it is due: no call, and the clock is read ever more rarely
        for k in 0..200 {
            progress.report(k as f64 * 1e-3);
        }
        assert!(seen.lock().unwrap().is_empty(), "not due before the interval has passed");
        assert!(progress.shared.watcher.as_ref().unwrap().lock().unwrap().stride > 1);
        std::thread::sleep(Duration::from_millis(110));
        let reports = report_until_called(&progress, &seen, 1.0);
        assert!(reports <= MAX_STRIDE as usize, "called {reports} reports after it was due");
        assert_eq!(seen.lock().unwrap().len(), 1, "called once");
        assert!(!progress.is_cancelled());
        std::thread::sleep(Duration::from_millis(110));
        report_until_called(&progress, &seen, 200.0);
        assert!(progress.is_cancelled(), "a watcher returning false cancels");
        assert_eq!(progress.time(), *seen.lock().unwrap().last().unwrap());
    }
}
