//! Event location on the dense output: the earliest rise of an event
//! function through zero inside an accepted step, found with the Illinois
//! variant of regula falsi (Dowell & Jarratt 1971), shared by both methods.

use super::OdeSystem;

/// Iterations after which the Illinois step gives way to bisection.
const BISECT_AFTER: usize = 60;
/// Hard cap on root-finding iterations (bisection from 1 s to 1e-15 s takes 50).
const MAX_ITERATIONS: usize = 200;

/// Time tolerance of the located root [s]: 4 eps |t| + 1e-15 s.
pub(crate) fn time_tolerance(t: f64) -> f64 {
    4.0 * f64::EPSILON * t.abs() + 1e-15
}

/// Event-function values and scratch, allocated once per run.
pub(crate) struct EventBuffers {
    /// g at the start of the current step.
    pub g_old: Vec<f64>,
    /// g at the end of the current step.
    pub g_new: Vec<f64>,
    /// g at a trial time.
    pub g_tmp: Vec<f64>,
    /// State at a trial time.
    pub y_tmp: Vec<f64>,
}

impl EventBuffers {
    /// Buffers for `n_events` event functions and a state of `n` components.
    pub(crate) fn new(n_events: usize, n: usize) -> Self {
        Self { g_old: vec![0.0; n_events], g_new: vec![0.0; n_events], g_tmp: vec![0.0; n_events], y_tmp: vec![0.0; n] }
    }

    /// True when event k rose through zero over the step.
    pub(crate) fn crossed(&self, k: usize) -> bool {
        self.g_old[k] <= 0.0 && self.g_new[k] > 0.0
    }

    /// True when event k fires at a time whose values are in `g_tmp`.
    pub(crate) fn fires_at_tmp(&self, k: usize) -> bool {
        self.g_old[k] <= 0.0 && self.g_tmp[k] > 0.0
    }
}

/// Earliest time t* in (t_old, t_new] at which some event function has risen
/// through zero, with g_k(t*) > 0 for that k; `None` when no event crossed.
/// `g_new` must hold g at t_new; `dense` gives the state inside the step.
pub(crate) fn locate_earliest<S, D>(
    system: &mut S,
    dense: D,
    t_old: f64,
    t_new: f64,
    buffers: &mut EventBuffers,
) -> Option<f64>
where
    S: OdeSystem,
    D: Fn(f64, &mut [f64]),
{
    let EventBuffers { g_old, g_new, g_tmp, y_tmp } = buffers;
    let mut best: Option<f64> = None;
    for k in 0..g_old.len() {
        if !(g_old[k] <= 0.0 && g_new[k] > 0.0) {
            continue;
        }
        let mut g_at = |t: f64| {
            dense(t, y_tmp);
            system.event_functions(t, y_tmp, g_tmp);
            g_tmp[k]
        };
        // the root of g_k beats the current best only if g_k is already positive there
        let (b, gb) = match best {
            None => (t_new, g_new[k]),
            Some(tb) => (tb, g_at(tb)),
        };
        if gb > 0.0 {
            best = Some(illinois(&mut g_at, t_old, g_old[k], b, gb));
        }
    }
    best
}

/// Root of g in (a, b] with g(a) <= 0 < g(b), returned as the right end of
/// the final bracket, so that g(t*) > 0 holds at the returned time.
fn illinois<G: FnMut(f64) -> f64>(g: &mut G, mut a: f64, mut ga: f64, mut b: f64, mut gb: f64) -> f64 {
    // side: +1 when a moved last, -1 when b moved last
    let mut side = 0i8;
    for iteration in 0..MAX_ITERATIONS {
        let tol = time_tolerance(b);
        if b - a <= tol {
            break;
        }
        // regula falsi point, kept half a tolerance inside the bracket
        let secant = b - gb * (b - a) / (gb - ga);
        let mut c = if iteration < BISECT_AFTER && secant.is_finite() { secant } else { 0.5 * (a + b) };
        c = c.clamp(a + 0.5 * tol, b - 0.5 * tol);
        let gc = g(c);
        // shrink the bracket; halve the stale end's value when one end sticks (Illinois)
        if gc > 0.0 {
            b = c;
            gb = gc;
            if side == -1 {
                ga *= 0.5;
            }
            side = -1;
        } else {
            a = c;
            ga = gc;
            if side == 1 {
                gb *= 0.5;
            }
            side = 1;
        }
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn illinois_finds_cubic_root_to_time_tolerance() {
        // g(t) = t^3 - 2 has its root at 2^(1/3)
        let mut calls = 0;
        let mut g = |t: f64| {
            calls += 1;
            t * t * t - 2.0
        };
        let root = illinois(&mut g, 0.0, -2.0, 2.0, 6.0);
        let exact = 2f64.cbrt();
        assert!(root >= exact - 1e-15 && root - exact <= time_tolerance(exact) + 1e-15, "{root} vs {exact}");
        assert!(root * root * root - 2.0 > 0.0);
        assert!(calls < 30, "Illinois should converge superlinearly, took {calls} calls");
    }

    #[test]
    fn illinois_handles_zero_at_left_end() {
        let mut g = |t: f64| t;
        let root = illinois(&mut g, 0.0, 0.0, 1.0, 1.0);
        assert!(root > 0.0 && root <= 2.0 * time_tolerance(0.0));
    }
}
