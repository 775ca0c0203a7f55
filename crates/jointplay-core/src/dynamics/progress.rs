//! Progress of a running simulation, shared with another thread (a progress
//! bar, a cancel button) without locks.

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Simulated time reached and a cancel flag.
#[derive(Debug, Default)]
pub struct Progress {
    time_bits: AtomicU64,
    cancel: AtomicBool,
}

impl Progress {
    /// Fresh progress at t = 0.
    pub fn new() -> Self {
        Self::default()
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

    pub(crate) fn report(&self, time: f64) {
        self.time_bits.store(time.to_bits(), Ordering::Relaxed);
    }
}
