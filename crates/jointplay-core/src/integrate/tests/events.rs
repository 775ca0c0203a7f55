//! Event location and handling: falling and bouncing ball.

use super::*;

/// Gravity [m/s^2].
const G: f64 = 9.81;

/// Ball (height [m], velocity [m/s]) under gravity; event k fires when the
/// height falls below `levels[k]`; on the ground event (level 0) the
/// velocity is reversed and scaled by `restitution` when that is set.
pub(super) struct Ball {
    levels: Vec<f64>,
    restitution: Option<f64>,
    pub(super) events: Vec<(f64, usize)>,
    samples: Vec<(f64, Vec<f64>)>,
    calls: usize,
    /// Whether the ball reports the rates dg/dt of its event functions.
    rates: bool,
    /// Evaluations of the event functions.
    event_calls: usize,
    /// Downward acceleration [m/s^2] (negative: the ball is pushed up).
    gravity: f64,
}

impl Ball {
    pub(super) fn new(levels: Vec<f64>, restitution: Option<f64>) -> Self {
        Self { levels, restitution, events: Vec::new(), samples: Vec::new(), calls: 0, rates: false, event_calls: 0, gravity: G }
    }

    /// A ball that reports the rates of its event functions.
    fn with_rates(levels: Vec<f64>, restitution: Option<f64>) -> Self {
        Self { rates: true, ..Self::new(levels, restitution) }
    }
}

impl OdeSystem for Ball {
    fn len(&self) -> usize {
        2
    }
    fn second_order_positions(&self) -> usize {
        1
    }
    fn rhs(&mut self, _t: f64, y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError> {
        self.calls += 1;
        dydt[0] = y[1];
        dydt[1] = -self.gravity;
        Ok(())
    }
    fn n_events(&self) -> usize {
        self.levels.len()
    }
    fn event_functions(&mut self, _t: f64, y: &[f64], g: &mut [f64]) {
        self.event_calls += 1;
        for (gk, level) in g.iter_mut().zip(&self.levels) {
            *gk = -(y[0] - level);
        }
    }
    fn event_functions_and_rates(&mut self, t: f64, y: &[f64], g: &mut [f64], rates: &mut [f64]) -> bool {
        self.event_functions(t, y, g);
        rates.fill(-y[1]);
        self.rates
    }
    fn on_event(&mut self, t: f64, y: &mut [f64], event: usize) -> Result<(), SimulationError> {
        self.events.push((t, event));
        if let (Some(e), 0.0) = (self.restitution, self.levels[event]) {
            y[1] *= -e;
        }
        Ok(())
    }
    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        self.samples.push((t, y.to_vec()));
        Ok(())
    }
}

#[test]
fn falling_ball_impact_time_is_sqrt_2h_over_g() {
    let height = 1.0;
    let exact = (2.0 * height / G).sqrt();
    for method in METHODS {
        let mut ball = Ball::new(vec![0.0], None);
        let (stats, result, _) = run(&mut ball, 0.0, 1.0, &[height, 0.0], &options(method, 1e-10));
        result.unwrap();
        assert_eq!(ball.events.len(), 1, "{method:?}");
        let t_star = ball.events[0].0;
        assert!((t_star - exact).abs() < 1e-10 * exact, "{method:?}: t* = {t_star}, exact {exact}");
        // the located time is just after the numerical root: contact has begun
        let (_, y) = ball.samples.iter().find(|(t, _)| *t == t_star).expect("sample at t*");
        assert!(y[0] <= 0.0 && y[0] > -1e-12, "{method:?}: height at t* {}", y[0]);
        assert_eq!((stats.events, stats.restarts), (1, 1));
    }
}

/// Time of the n-th bounce (n >= 1) of a ball dropped from `height` with restitution `e`:
/// t_n = t_1 (1 + 2 (e - e^n) / (1 - e)), t_1 = sqrt(2 h / g).
pub(super) fn bounce_time(height: f64, e: f64, n: i32) -> f64 {
    let t1 = (2.0 * height / G).sqrt();
    t1 * (1.0 + 2.0 * (e - e.powi(n)) / (1.0 - e))
}

#[test]
fn bouncing_ball_bounce_times_follow_geometric_series() {
    let (height, e) = (1.0, 0.8);
    // 7 bounces happen before 3.2 s (t_7 = 3.12 s, t_8 = 3.31 s); steps of at most 20 ms
    for method in METHODS {
        let mut ball = Ball::new(vec![0.0], Some(e));
        let mut opts = options(method, 1e-10);
        opts.max_step = 0.02;
        let (stats, result, _) = run(&mut ball, 0.0, 3.2, &[height, 0.0], &opts);
        result.unwrap();
        assert_eq!(ball.events.len(), 7, "{method:?}: {:?}", ball.events);
        for (n, (t, _)) in ball.events.iter().enumerate() {
            let exact = bounce_time(height, e, n as i32 + 1);
            let rel = (t - exact).abs() / exact;
            // the NDF restarts at order 1 after every bounce: its error builds up faster
            let bound = if method == Method::NumericalDifferentiation { 1e-8 } else { 1e-9 };
            assert!(rel < bound, "{method:?}: bounce {} at {t}, exact {exact} (rel {rel:e})", n + 1);
        }
        assert_eq!((stats.events, stats.restarts), (7, 7), "{method:?}");
    }
}

#[test]
fn short_flight_inside_one_long_step_is_not_missed() {
    // restitution 0.3: the flight after the first bounce (0.45 s to 0.72 s) fits in the last step;
    // with rates the end values of that step are small against step x rate, so it is still sampled inside
    for ball in [Ball::new(vec![0.0], Some(0.3)), Ball::with_rates(vec![0.0], Some(0.3))] {
        let mut ball = ball;
        let opts = options(Method::DormandPrince45, 1e-10);
        let (stats, result, _) = run(&mut ball, 0.0, 0.78, &[1.0, 0.0], &opts);
        result.unwrap();
        let flight = bounce_time(1.0, 0.3, 2) - bounce_time(1.0, 0.3, 1);
        assert!(stats.largest_step > flight, "no step spans the flight: {stats:?}");
        assert_eq!(ball.events.len(), 2, "{:?}", ball.events);
        assert!((ball.events[1].0 - bounce_time(1.0, 0.3, 2)).abs() < 1e-12);
    }
}

/// Runs a ball reporting rates from height 0 with velocity `v0` [m/s], one
/// step of 0.6 s asked for; returns the event times and the largest step.
fn excursion_run(level: f64, v0: f64, gravity: f64) -> (Vec<f64>, f64) {
    let mut ball = Ball::with_rates(vec![level], None);
    ball.gravity = gravity;
    let mut opts = options(Method::DormandPrince45, 1e-6);
    opts.initial_step = Some(0.6);
    let (stats, result, _) = run(&mut ball, 0.0, 0.6, &[0.0, v0], &opts);
    result.unwrap();
    (ball.events.iter().map(|(t, _)| *t).collect(), stats.largest_step)
}

#[test]
fn short_rise_between_small_negative_end_values_is_found_with_rates() {
    // pushed up (gravity -G) after a downward throw at 3 m/s: below -0.45 m
    // (g > 0) for 0.083 s around 0.306 s; one step spans the dip and g < 0 at both of its ends
    let (events, largest_step) = excursion_run(-0.45, -3.0, -G);
    assert!(largest_step > 0.4, "no step spans the dip: {largest_step}");
    let exact = (3.0 - (9.0 - 2.0 * G * 0.45_f64).sqrt()) / G;
    assert_eq!(events.len(), 1, "{events:?}");
    assert!((events[0] - exact).abs() < 1e-9, "{} vs {exact}", events[0]);
}

#[test]
fn short_dip_between_small_positive_end_values_is_found_with_rates() {
    // thrown up at 3 m/s: above 0.45 m (g < 0) for 0.083 s around the apex;
    // one step spans the flight, g > 0 at both of its ends; the level is
    // crossed downwards on the way back
    let (events, largest_step) = excursion_run(0.45, 3.0, G);
    assert!(largest_step > 0.4, "no step spans the flight: {largest_step}");
    let exact = (3.0 + (9.0 - 2.0 * G * 0.45_f64).sqrt()) / G;
    assert_eq!(events.len(), 1, "{events:?}");
    assert!((events[0] - exact).abs() < 1e-9, "{} vs {exact}", events[0]);
}

#[test]
fn steps_far_from_every_event_are_not_sampled_inside() {
    // falling 1 m with the event level 100 m below: with rates, g is
    // evaluated once per step (at its end, which also starts the next step);
    // without, 8 times (7 interior samples and the end)
    for method in METHODS {
        let run_with = |mut ball: Ball| {
            let mut opts = options(method, 1e-8);
            opts.max_step = 0.01;
            let (stats, result, _) = run(&mut ball, 0.0, 0.4, &[1.0, 0.0], &opts);
            result.unwrap();
            assert!(ball.events.is_empty(), "{method:?}");
            (stats.accepted_steps, ball.event_calls)
        };
        let (steps, calls) = run_with(Ball::with_rates(vec![-100.0], None));
        assert!(steps >= 40, "{method:?}: {steps} steps");
        assert_eq!(calls, steps + 1, "{method:?}: skipping");
        let (steps, calls) = run_with(Ball::new(vec![-100.0], None));
        assert_eq!(calls, 8 * steps + 1, "{method:?}: sampling");
    }
}

#[test]
fn sample_at_event_time_shows_state_after_on_event() {
    let mut ball = Ball::new(vec![0.0], Some(0.5));
    let (_, result, _) = run(&mut ball, 0.0, 0.5, &[1.0, 0.0], &options(Method::DormandPrince45, 1e-8));
    result.unwrap();
    let t_star = ball.events[0].0;
    let (_, y) = ball.samples.iter().find(|(t, _)| *t == t_star).expect("sample at t*");
    let v_impact = G * t_star;
    assert!((y[1] - 0.5 * v_impact).abs() < 1e-9, "velocity after bounce {}", y[1]);
    assert!(y[0] <= 0.0 && y[0] > -1e-12, "height at t* {}", y[0]);
}

#[test]
fn earliest_of_two_events_in_one_step_fires_first() {
    // levels 0.5 m and 0 m are crossed at sqrt(1/g) and sqrt(2/g); a large first step spans both
    for method in METHODS {
        let mut ball = Ball::new(vec![0.0, 0.5], None);
        let mut opts = options(method, 1e-10);
        opts.initial_step = Some(0.6);
        let (stats, result, _) = run(&mut ball, 0.0, 0.6, &[1.0, 0.0], &opts);
        result.unwrap();
        let order: Vec<usize> = ball.events.iter().map(|(_, k)| *k).collect();
        assert_eq!(order, vec![1, 0], "{method:?}");
        assert!((ball.events[0].0 - (1.0 / G).sqrt()).abs() < 1e-9);
        assert!((ball.events[1].0 - (2.0 / G).sqrt()).abs() < 1e-9);
        assert_eq!(stats.events, 2);
    }
}

#[test]
fn rhs_evaluations_with_events_follow_the_restart_rule() {
    // DOPRI: 6 per attempted step + 1 initial + 1 starting-step probe + 1 per restart;
    // Adams: 2 per accepted + 1 per rejected step + 1 initial + 1 probe + 1 probe per restart
    for method in EXPLICIT_METHODS {
        let mut ball = Ball::new(vec![0.0], Some(0.8));
        let (stats, result, _) = run(&mut ball, 0.0, 3.0, &[1.0, 0.0], &options(method, 1e-8));
        result.unwrap();
        let expected = match method {
            Method::DormandPrince45 => 6 * (stats.accepted_steps + stats.rejected_steps) + 2 + stats.restarts,
            Method::AdamsPredictorCorrector => 2 * stats.accepted_steps + stats.rejected_steps + 2 + stats.restarts,
            Method::NumericalDifferentiation | Method::GeneralizedAlpha => unreachable!("implicit: counted in tests/stiff.rs and tests/generalized_alpha.rs"),
        };
        assert_eq!(stats.rhs_evaluations, expected, "{method:?}: {stats:?}");
        assert_eq!(stats.rhs_evaluations, ball.calls, "{method:?}");
    }
}
