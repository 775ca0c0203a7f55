//! Cooperative interruption of long loops: a run installs what watches it
//! (its progress, which a front end's Ctrl-C cancels) for the thread that
//! computes it, and any loop deep inside the core that may take long (a
//! Reynolds solve's relaxation sweeps, the evaluations of a step) asks
//! [`keep_going`] at each pass, without the watcher being handed down to it.

use std::cell::RefCell;
use std::sync::Arc;

/// What a long loop asks whether it may go on.
pub trait Watch {
    /// False once the run was asked to stop; may call back into the front end when due.
    fn keep_going(&self) -> bool;
}

thread_local! {
    /// The watcher of the run this thread is computing, if any.
    static CURRENT: RefCell<Option<Arc<dyn Watch + Send + Sync>>> = const { RefCell::new(None) };
}

/// Runs `f` with `watch` as this thread's watcher (the one before is restored after, also on a panic).
pub fn scoped<T>(watch: Arc<dyn Watch + Send + Sync>, f: impl FnOnce() -> T) -> T {
    /// Puts the previous watcher back when dropped.
    struct Restore(Option<Arc<dyn Watch + Send + Sync>>);
    impl Drop for Restore {
        fn drop(&mut self) {
            let previous = self.0.take();
            CURRENT.with(|current| *current.borrow_mut() = previous);
        }
    }
    let _restore = Restore(CURRENT.with(|current| current.replace(Some(watch))));
    f()
}

/// Whether the loop that asks may go on: false once this thread's run was asked to
/// stop; true outside a watched run. Cheap enough for every pass of a loop.
pub fn keep_going() -> bool {
    // (the watcher is taken out of the cell before it is called: it may call back into the core)
    let watch = CURRENT.with(|current| current.borrow().clone());
    watch.is_none_or(|watch| watch.keep_going())
}

/// The message of an error that a loop returns when [`keep_going`] said no.
pub const INTERRUPTED: &str = "interrupted";

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// Goes on for `allowed` calls, then says stop.
    struct Countdown {
        calls: AtomicUsize,
        allowed: usize,
    }

    impl Watch for Countdown {
        fn keep_going(&self) -> bool {
            self.calls.fetch_add(1, Ordering::Relaxed) < self.allowed
        }
    }

    #[test]
    fn loops_see_the_watcher_of_their_scope_only() {
        assert!(keep_going(), "no run: go on");
        let watch = Arc::new(Countdown { calls: AtomicUsize::new(0), allowed: 2 });
        let passes = scoped(watch.clone(), || (0..10).take_while(|_| keep_going()).count());
        assert_eq!(passes, 2);
        assert!(keep_going(), "the scope ended: no watcher");
        assert_eq!(watch.calls.load(Ordering::Relaxed), 3);
    }
}
