//! Event location on the dense output: the earliest rise of an event
//! function through zero inside an accepted step, found with the Illinois
//! variant of regula falsi (Dowell & Jarratt 1971), shared by every method.
//!
//! The event functions are sampled at the step end and at
//! [`EVENT_SUBDIVISIONS`] - 1 interior points of the dense output, so that an
//! excursion that starts and ends inside one long step (a short flight
//! between two impacts) is not missed; the first sub-interval with a rise
//! through zero holds the earliest event.
//!
//! When the system knows the rates dg/dt, a step whose ends lie, for every
//! event function, on the same side of zero and farther from it than the
//! function could plausibly move inside the step is not sampled inside
//! ([`EventBuffers::crossing_implausible`]).

use super::OdeSystem;

/// Iterations after which the Illinois step gives way to bisection.
const BISECT_AFTER: usize = 60;
/// Number of sub-intervals of an accepted step on which the event functions are sampled.
pub(crate) const EVENT_SUBDIVISIONS: usize = 8;
/// Hard cap on root-finding iterations (bisection from 1 s to 1e-15 s takes 50).
const MAX_ITERATIONS: usize = 200;
/// Largest excursion of a cubic Hermite interpolant beyond the range of its
/// end values, per unit of h (|g'_0| + |g'_1|): the maximum of s (1 - s)^2
/// on [0, 1], reached at s = 1/3.
const HERMITE_EXCURSION: f64 = 4.0 / 27.0;
/// Safety factor on [`HERMITE_EXCURSION`] before a step is left unsampled:
/// the reach h (|g'_0| + |g'_1|) covers event functions far less smooth
/// than a cubic over the step.
const SKIP_SAFETY: f64 = 27.0 / 4.0;

/// Time tolerance of the located root [s]: 4 eps |t| + 1e-15 s.
pub(crate) fn time_tolerance(t: f64) -> f64 {
    4.0 * f64::EPSILON * t.abs() + 1e-15
}

/// Event-function values and scratch, allocated once per run.
pub(crate) struct EventBuffers {
    /// g at the start of the current step.
    pub g_old: Vec<f64>,
    /// g at the start of the sub-interval being scanned.
    pub g_lo: Vec<f64>,
    /// g at the end of the sub-interval being scanned.
    pub g_hi: Vec<f64>,
    /// g at the end of the current step.
    pub g_new: Vec<f64>,
    /// g at a trial time.
    pub g_tmp: Vec<f64>,
    /// dg/dt at the start of the current step [unit of g per s].
    pub rate_old: Vec<f64>,
    /// dg/dt at the end of the current step [unit of g per s].
    pub rate_new: Vec<f64>,
    /// Whether the system gave `rate_old`.
    pub rates_known_old: bool,
    /// Whether `rate_new` holds dg/dt at the end of the step.
    pub rates_known_new: bool,
    /// State at a trial time.
    pub y_tmp: Vec<f64>,
}

impl EventBuffers {
    /// Buffers for `n_events` event functions and a state of `n` components.
    pub(crate) fn new(n_events: usize, n: usize) -> Self {
        let g = || vec![0.0; n_events];
        Self {
            g_old: g(),
            g_lo: g(),
            g_hi: g(),
            g_new: g(),
            g_tmp: g(),
            rate_old: g(),
            rate_new: g(),
            rates_known_old: false,
            rates_known_new: false,
            y_tmp: vec![0.0; n],
        }
    }

    /// Evaluates g (and dg/dt, when the system knows it) at the start of the next step.
    pub(crate) fn evaluate_at_step_start<S: OdeSystem>(&mut self, system: &mut S, t: f64, y: &[f64]) {
        self.rates_known_old = system.event_functions_and_rates(t, y, &mut self.g_old, &mut self.rate_old);
    }

    /// Takes g and dg/dt at the end of the step just scanned, where the next
    /// step starts when the state was not changed after the scan.
    pub(crate) fn carry_step_end_over(&mut self) {
        self.g_old.copy_from_slice(&self.g_new);
        self.rate_old.copy_from_slice(&self.rate_new);
        self.rates_known_old = self.rates_known_new;
    }

    /// True when no event function can plausibly cross zero inside a step of
    /// length `h` [s]: for every k, g_k at both ends has the same sign and a
    /// magnitude above `SKIP_SAFETY * HERMITE_EXCURSION * h (|g'_k(t_old)| + |g'_k(t_new)|)`.
    /// Needs the rates at both ends; false whenever a value is not finite.
    fn crossing_implausible(&self, h: f64) -> bool {
        (0..self.g_old.len()).all(|k| {
            let (g0, g1) = (self.g_old[k], self.g_new[k]);
            let reach = SKIP_SAFETY * HERMITE_EXCURSION * h * (self.rate_old[k].abs() + self.rate_new[k].abs());
            let same_side = (g0 < 0.0 && g1 < 0.0) || (g0 > 0.0 && g1 > 0.0);
            // written so that NaN anywhere means "plausible"
            same_side && g0.abs() > reach && g1.abs() > reach
        })
    }

    /// True when some event function rose through zero over the scanned sub-interval.
    fn any_crossed(&self) -> bool {
        self.g_lo.iter().zip(&self.g_hi).any(|(lo, hi)| *lo <= 0.0 && *hi > 0.0)
    }

    /// True when event k fires at a time whose values are in `g_tmp`.
    pub(crate) fn fires_at_tmp(&self, k: usize) -> bool {
        self.g_lo[k] <= 0.0 && self.g_tmp[k] > 0.0
    }
}

/// Evaluates g (and its rates) at the end `(t_new, y_new)` of an accepted step;
/// false when no event function can plausibly have crossed zero in the step
/// (see [`EventBuffers::crossing_implausible`]), so that it needs no scan.
pub(crate) fn step_needs_scan<S: OdeSystem>(system: &mut S, y_new: &[f64], t_old: f64, t_new: f64, buffers: &mut EventBuffers) -> bool {
    buffers.rates_known_new = system.event_functions_and_rates(t_new, y_new, &mut buffers.g_new, &mut buffers.rate_new);
    !(buffers.rates_known_old && buffers.rates_known_new && buffers.crossing_implausible(t_new - t_old))
}

/// Earliest event time in (t_old, t_new], scanning the step in sub-intervals;
/// `None` when no event function rose through zero. `g_old` must hold g at
/// t_old and `g_new` at t_new ([`step_needs_scan`]); on return `g_lo` holds g
/// at the start of the sub-interval of the event.
pub(crate) fn find_first_event<S, D>(system: &mut S, dense: D, t_old: f64, t_new: f64, buffers: &mut EventBuffers) -> Option<f64>
where
    S: OdeSystem,
    D: Fn(f64, &mut [f64]),
{
    buffers.g_lo.copy_from_slice(&buffers.g_old);
    let mut t_a = t_old;
    for i in 1..=EVENT_SUBDIVISIONS {
        // g at the end of the sub-interval: step end exactly, else dense output
        let t_b = if i == EVENT_SUBDIVISIONS {
            buffers.g_hi.copy_from_slice(&buffers.g_new);
            t_new
        } else {
            let t_b = t_old + (t_new - t_old) * (i as f64 / EVENT_SUBDIVISIONS as f64);
            dense(t_b, &mut buffers.y_tmp);
            system.event_functions(t_b, &buffers.y_tmp, &mut buffers.g_hi);
            t_b
        };
        if buffers.any_crossed() {
            return locate_earliest(system, &dense, t_a, t_b, buffers);
        }
        buffers.g_lo.copy_from_slice(&buffers.g_hi);
        t_a = t_b;
    }
    None
}

/// Earliest time t* in (t_a, t_b] at which some event function has risen
/// through zero, with g_k(t*) > 0 for that k; `None` when no event crossed.
/// `g_lo` and `g_hi` hold g at t_a and t_b; `dense` gives the state inside the step.
fn locate_earliest<S, D>(
    system: &mut S,
    dense: D,
    t_a: f64,
    t_b: f64,
    buffers: &mut EventBuffers,
) -> Option<f64>
where
    S: OdeSystem,
    D: Fn(f64, &mut [f64]),
{
    let EventBuffers { g_lo, g_hi, g_tmp, y_tmp, .. } = buffers;
    let mut best: Option<f64> = None;
    for k in 0..g_lo.len() {
        if !(g_lo[k] <= 0.0 && g_hi[k] > 0.0) {
            continue;
        }
        let mut g_at = |t: f64| {
            dense(t, y_tmp);
            system.event_functions(t, y_tmp, g_tmp);
            g_tmp[k]
        };
        // the root of g_k beats the current best only if g_k is already positive there
        let (b, gb) = match best {
            None => (t_b, g_hi[k]),
            Some(tb) => (tb, g_at(tb)),
        };
        if gb > 0.0 {
            best = Some(illinois(&mut g_at, t_a, g_lo[k], b, gb));
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
