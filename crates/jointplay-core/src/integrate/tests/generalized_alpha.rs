//! Generalized-alpha against closed forms: order two, the trapezoidal rule's
//! energy conservation at rho_inf = 1, the damping of unresolved vibrations
//! (the spectral radius at infinity of Chung & Hulbert 1993), events, and the
//! step halved where Newton fails.

use super::events::{bounce_time, Ball};
use super::*;

/// Options of generalized-alpha with nominal step `step` [s] and spectral radius `rho` (tight Newton tolerance).
fn alpha(step: f64, rho: f64) -> IntegratorOptions {
    IntegratorOptions { method: Method::GeneralizedAlpha, step: Some(step), spectral_radius: rho, rtol: 1e-12, atol: 1e-14, ..IntegratorOptions::default() }
}

/// x'' = -w^2 x - c x^3 (the cubic term until `hard_until` [s]) as (x, v), with dx/dt = v
/// declared: the method's second-order form.
struct Oscillator {
    w: f64,
    cubic: f64,
    hard_until: f64,
    samples: Vec<(f64, Vec<f64>)>,
}

impl Oscillator {
    fn linear(w: f64) -> Self {
        Self { w, cubic: 0.0, hard_until: 0.0, samples: Vec::new() }
    }
    /// Amplitude of a linear vibration [m]: sqrt(x^2 + (v / w)^2).
    fn amplitude(&self, y: &[f64]) -> f64 {
        y[0].hypot(y[1] / self.w)
    }
    /// Energy per unit mass [m^2/s^2] of a sample.
    fn energy(&self, y: &[f64]) -> f64 {
        0.5 * y[1] * y[1] + 0.5 * self.w * self.w * y[0] * y[0] + 0.25 * self.cubic * y[0].powi(4)
    }
}

impl OdeSystem for Oscillator {
    fn len(&self) -> usize {
        2
    }
    fn second_order_positions(&self) -> usize {
        1
    }
    fn rhs(&mut self, t: f64, y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError> {
        let cubic = if t < self.hard_until { self.cubic } else { 0.0 };
        dydt[0] = y[1];
        dydt[1] = -self.w * self.w * y[0] - cubic * y[0].powi(3);
        Ok(())
    }
    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        self.samples.push((t, y.to_vec()));
        Ok(())
    }
}

/// Largest error of x over 0..2 s of the 1 Hz oscillator from x = 1, v = 0, step h.
fn oscillator_error(h: f64, rho: f64) -> f64 {
    let w = 2.0 * std::f64::consts::PI;
    let mut system = Oscillator::linear(w);
    let (_, result, _) = run(&mut system, 0.0, 2.0, &[1.0, 0.0], &alpha(h, rho));
    result.unwrap();
    system.samples.iter().map(|(t, y)| (y[0] - (w * t).cos()).abs()).fold(0.0, f64::max)
}

#[test]
fn second_order_on_an_oscillator_for_every_spectral_radius() {
    for rho in [0.0, 0.5, 0.9, 1.0] {
        let (coarse, fine) = (oscillator_error(1.0 / 100.0, rho), oscillator_error(1.0 / 200.0, rho));
        let order = (coarse / fine).log2();
        assert!((order - 2.0).abs() < 0.05, "rho_inf {rho}: errors {coarse:e}, {fine:e}, order {order}");
    }
}

#[test]
fn second_order_on_a_first_order_system() {
    // y' = -y with no position-velocity split: the rates' update alone
    let error = |h: f64| {
        let mut system = Smooth::new(1, decay);
        let (_, result, y) = run(&mut system, 0.0, 1.0, &[1.0], &alpha(h, 0.8));
        result.unwrap();
        (y[0] - (-1.0f64).exp()).abs()
    };
    let order = (error(0.02) / error(0.01)).log2();
    assert!((order - 2.0).abs() < 0.05, "order {order}");
}

#[test]
fn trapezoidal_rule_keeps_the_energy_of_a_linear_oscillator() {
    // rho_inf = 1 is Newmark's average acceleration rule, which conserves the energy of linear systems
    let mut system = Oscillator::linear(2.0 * std::f64::consts::PI);
    let (_, result, _) = run(&mut system, 0.0, 20.0, &[1.0, 0.0], &alpha(0.05, 1.0));
    result.unwrap();
    let e0 = system.energy(&system.samples[0].1);
    let drift = system.samples.iter().map(|(_, y)| (system.energy(y) / e0 - 1.0).abs()).fold(0.0, f64::max);
    assert!(drift < 1e-10, "energy drift {drift:e} over 400 steps");
}

#[test]
fn unresolved_vibration_decays_by_the_spectral_radius_per_step() {
    // omega h = 1e4: each step multiplies the vibration's amplitude by about rho_inf (Chung & Hulbert
    // 1993, the spectral radius at infinity; at this omega h it is 1.0068, 1.0034 and 1.0021 times
    // rho_inf = 0.2, 0.5, 0.8); measured between steps 50 and 250. atol 1e-200: the amplitude falls
    // to 1e-175; rtol 1e-6: the Newton residual's rounding is eps (omega h)^2 = 2e-8 of the state
    for rho in [0.2, 0.5, 0.8] {
        let mut system = Oscillator::linear(1e4);
        let (_, result, _) = run(&mut system, 0.0, 250.0, &[1.0, 0.0], &IntegratorOptions { rtol: 1e-6, atol: 1e-200, ..alpha(1.0, rho) });
        result.unwrap();
        let amplitude = |k: usize| system.amplitude(&system.samples[k].1);
        let per_step = (amplitude(250) / amplitude(50)).powf(1.0 / 200.0);
        assert!((per_step / rho - 1.0).abs() < 0.01, "rho_inf {rho}: amplitude x {per_step} per step");
    }
    // rho_inf = 0 removes it: 0.0022 per step at this omega h, after a start transient. The
    // amplitudes after each step are those of the method's linear recursion, written out below
    // (2500, 0.5, 1e-4, 2.5e-5, 5e-9): every step is taken whole (Newton converges in two
    // iterations on a fresh Jacobian; a prediction of slow convergence once halved the first step)
    let mut system = Oscillator::linear(1e4);
    let (stats, result, _) = run(&mut system, 0.0, 5.0, &[1.0, 0.0], &IntegratorOptions { rtol: 1e-6, atol: 1e-200, ..alpha(1.0, 0.0) });
    result.unwrap();
    assert_eq!((stats.accepted_steps, stats.rejected_steps), (5, 0));
    let expected = linear_recursion(1e4, 1.0, 0.0, 5);
    for (k, (t, y)) in system.samples.iter().enumerate().skip(1) {
        let (amplitude, exact) = (system.amplitude(y), expected[k - 1]);
        assert!((amplitude / exact - 1.0).abs() < 1e-6, "t = {t}: amplitude {amplitude:e}, recursion {exact:e}");
    }
    let last = system.amplitude(&system.samples.last().unwrap().1);
    assert!(last < 1e-8, "left {last:e}");
}

/// Amplitudes after each of `steps` steps h of generalized-alpha (rho_inf) on `x'' = -w^2 x` from
/// x = 1, v = 0 (the algorithmic acceleration starting at -w^2): the method's formulas solved for
/// the new acceleration in closed form, as the linear problem allows.
fn linear_recursion(w: f64, h: f64, rho: f64, steps: usize) -> Vec<f64> {
    let (am, af) = ((2.0 * rho - 1.0) / (rho + 1.0), rho / (rho + 1.0));
    let g = 0.5 + af - am;
    let b = 0.25 * (g + 0.5) * (g + 0.5);
    let (mut x, mut v, mut a) = (1.0, 0.0, -w * w);
    (0..steps)
        .map(|_| {
            let a1 = (-am * a - (1.0 - af) * w * w * (x + h * v + h * h * (0.5 - b) * a) - af * w * w * x) / ((1.0 - am) + (1.0 - af) * w * w * b * h * h);
            (x, v) = (x + h * v + h * h * ((0.5 - b) * a + b * a1), v + h * ((1.0 - g) * a + g * a1));
            a = a1;
            x.hypot(v / w)
        })
        .collect()
}

#[test]
fn bounces_are_located_on_the_dense_output() {
    // the ball's motion is quadratic in t between bounces: Newmark's update and the cubic
    // Hermite output are exact for it, so the bounce times come out to rounding
    let (height, e) = (1.0, 0.8);
    let mut ball = Ball::new(vec![0.0], Some(e));
    let (stats, result, _) = run(&mut ball, 0.0, 3.2, &[height, 0.0], &alpha(0.02, 0.9));
    result.unwrap();
    assert_eq!(ball.events.len(), 7, "{:?}", ball.events);
    for (n, (t, _)) in ball.events.iter().enumerate() {
        let exact = bounce_time(height, e, n as i32 + 1);
        assert!((t - exact).abs() < 1e-11, "bounce {} at {t}, exact {exact}", n + 1);
    }
    assert_eq!((stats.events, stats.restarts), (7, 7));
}

#[test]
fn a_step_too_long_for_newton_is_halved_and_grows_back() {
    // a hard spring far from its rest until t = 1 s: Newton from the constant-acceleration
    // predictor cannot follow a step of 0.2 s there and converges on shorter ones; once the
    // spring is linear the step comes back to 0.2 s, and the samples keep the nominal spacing
    let mut system = Oscillator { w: 1.0, cubic: 1e4, hard_until: 1.0, samples: Vec::new() };
    let (stats, result, _) = run(&mut system, 0.0, 4.0, &[1.0, 0.0], &IntegratorOptions { rtol: 1e-6, atol: 1e-9, ..alpha(0.2, 0.8) });
    result.unwrap();
    assert!(stats.rejected_steps > 0 && stats.smallest_step < 0.05, "{stats:?}");
    // (the last step is cut to end at 4 s)
    let last = &system.samples[system.samples.len() - 6..system.samples.len() - 1];
    for pair in last.windows(2) {
        assert!((pair[1].0 - pair[0].0 - 0.2).abs() < 1e-12, "steps at the end: {:?}", last.iter().map(|s| s.0).collect::<Vec<_>>());
    }
}

#[test]
fn generalized_alpha_needs_a_step_and_a_spectral_radius_from_0_to_1() {
    let mut system = Oscillator::linear(1.0);
    let no_step = IntegratorOptions { step: None, ..alpha(0.1, 0.9) };
    let (_, result, _) = run(&mut system, 0.0, 1.0, &[1.0, 0.0], &no_step);
    assert!(matches!(&result, Err(SimulationError::InvalidInput { message, .. }) if message.contains("step")), "{result:?}");
    let (_, result, _) = run(&mut system, 0.0, 1.0, &[1.0, 0.0], &alpha(0.1, 1.5));
    assert!(matches!(&result, Err(SimulationError::InvalidInput { message, .. }) if message.contains("spectral_radius")), "{result:?}");
}

#[test]
fn steps_are_cut_to_end_on_the_output_times() {
    // samples every 15 ms with 10 ms steps: each sample is a step end (a step of 10 ms, then one of
    // 5 ms), never the continuous extension, whose forces a stiff element would spoil
    let mut system = Oscillator::linear(2.0 * std::f64::consts::PI);
    let opts = IntegratorOptions { output_step: Some(0.015), ..alpha(0.01, 0.9) };
    let (stats, result, _) = run(&mut system, 0.0, 0.3, &[1.0, 0.0], &opts);
    result.unwrap();
    assert_eq!(system.samples.len(), 21);
    assert_eq!(stats.accepted_steps, 40, "{stats:?}");
    assert!((stats.smallest_step - 0.005).abs() < 1e-12 && (stats.largest_step - 0.01).abs() < 1e-12, "{stats:?}");
    // the next step after a cut one is the nominal step again
    let mut system = Oscillator::linear(2.0 * std::f64::consts::PI);
    let opts = IntegratorOptions { output_step: Some(0.025), ..alpha(0.01, 0.9) };
    let (stats, result, _) = run(&mut system, 0.0, 0.1, &[1.0, 0.0], &opts);
    result.unwrap();
    assert_eq!(stats.accepted_steps, 12, "{stats:?}"); // 10 + 10 + 5 ms per 25 ms
}
