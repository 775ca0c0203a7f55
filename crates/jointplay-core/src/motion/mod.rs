//! Prescribed functions of time for drivers and loads.
//!
//! A [`TimeFunction`] is sampled at a time t [s] and returns the value, its
//! rate and its acceleration together ([`MotionSample`]), so a driver
//! constraint gets its right-hand sides at position, velocity and
//! acceleration level from one call. The unit of the value is that of the
//! driven quantity (m, rad, N, ...). Sampling never allocates.
//! Theory page: `docs/theory/motion-functions.md`.

mod constant_rate;
mod cubic_step;
mod polynomial;
mod sine;
mod speed_ramp;
mod spline_table;

pub use constant_rate::ConstantRate;
pub use cubic_step::CubicStep;
pub use polynomial::Polynomial;
pub use sine::Sine;
pub use speed_ramp::SpeedRamp;
pub use spline_table::SplineTable;

/// Value of a time function and its first two time derivatives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MotionSample {
    /// f(t) [unit of the driven quantity].
    pub value: f64,
    /// df/dt [unit/s].
    pub rate: f64,
    /// d²f/dt² [unit/s²].
    pub acceleration: f64,
}

impl MotionSample {
    /// A constant value with zero rate and acceleration.
    pub fn at_rest(value: f64) -> Self {
        Self { value, rate: 0.0, acceleration: 0.0 }
    }
}

/// A prescribed function of time.
#[derive(Clone, Debug, PartialEq)]
pub enum TimeFunction {
    /// Constant value.
    Constant(f64),
    /// Constant rate (for example a crank at constant speed).
    ConstantRate(ConstantRate),
    /// Polynomial in t.
    Polynomial(Polynomial),
    /// Smooth cubic step between two values (paper 003, eq. 5).
    CubicStep(CubicStep),
    /// Sine wave.
    Sine(Sine),
    /// Natural cubic spline through tabulated points.
    Table(SplineTable),
    /// Rate rising smoothly from zero to a final rate (a spin-up).
    SpeedRamp(SpeedRamp),
}

impl TimeFunction {
    /// Value, rate and acceleration at time t [s]. Does not allocate.
    pub fn sample(&self, t: f64) -> MotionSample {
        match self {
            Self::Constant(value) => MotionSample::at_rest(*value),
            Self::ConstantRate(function) => function.sample(t),
            Self::Polynomial(function) => function.sample(t),
            Self::CubicStep(function) => function.sample(t),
            Self::Sine(function) => function.sample(t),
            Self::Table(function) => function.sample(t),
            Self::SpeedRamp(function) => function.sample(t),
        }
    }
}

/// Test support: checks rate and acceleration against central differences.
#[cfg(test)]
pub(crate) fn assert_derivatives_match_finite_differences(
    function: &TimeFunction,
    t: f64,
    step: f64,
) {
    let sample = function.sample(t);
    let (before, after) = (function.sample(t - step), function.sample(t + step));
    let rate = (after.value - before.value) / (2.0 * step);
    let acceleration = (after.rate - before.rate) / (2.0 * step);
    let scale = 1.0 + sample.rate.abs() + sample.acceleration.abs();
    assert!((rate - sample.rate).abs() < 1e-6 * scale, "rate at {t}: {} vs {rate}", sample.rate);
    assert!(
        (acceleration - sample.acceleration).abs() < 1e-6 * scale,
        "acceleration at {t}: {} vs {acceleration}",
        sample.acceleration
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn test_constant_has_zero_rates() {
        let sample = TimeFunction::Constant(2.5).sample(7.0);
        assert_eq!(sample, MotionSample { value: 2.5, rate: 0.0, acceleration: 0.0 });
    }

    #[test]
    fn test_every_kind_has_consistent_derivatives() {
        let functions = [
            TimeFunction::ConstantRate(ConstantRate { initial: 0.3, rate: 523.6 }),
            TimeFunction::Polynomial(Polynomial { coefficients: vec![1.0, -2.0, 0.5, 3.0] }),
            TimeFunction::CubicStep(CubicStep::new(0.0, 0.03, 0.0, -19.0).unwrap()),
            TimeFunction::Sine(Sine::new(1.0, 2.0, 10.0, 0.3).unwrap()),
            TimeFunction::Table(
                SplineTable::new(vec![0.0, 0.01, 0.025, 0.04], vec![0.0, 2.0, 1.0, 3.0]).unwrap(),
            ),
        ];
        for function in &functions {
            for t in [0.004, 0.013, 0.021, 0.033] {
                assert_derivatives_match_finite_differences(function, t, 1e-6);
            }
        }
    }
}
