//! Constant-rate function `f = f0 + r t`, for example a crank driven at
//! constant angular speed.

use super::MotionSample;

/// `f(t) = initial + rate t`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstantRate {
    /// Value f0 at t = 0 [unit].
    pub initial: f64,
    /// Constant rate r [unit/s].
    pub rate: f64,
}

impl ConstantRate {
    /// Value, rate and (zero) acceleration at time t [s].
    pub fn sample(&self, t: f64) -> MotionSample {
        MotionSample { value: self.initial + self.rate * t, rate: self.rate, acceleration: 0.0 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn test_constant_rate_of_5000_rpm_crank() {
        // 5000 rpm = 5000 * 2π / 60 rad/s
        let speed = 5000.0 * std::f64::consts::TAU / 60.0;
        let crank = ConstantRate { initial: 0.0, rate: speed };
        let sample = crank.sample(0.012);
        // 0.012 s at 5000 rpm is one full turn: 2π rad
        assert!((sample.value - std::f64::consts::TAU).abs() < 1e-12);
        assert_eq!(sample.rate, speed);
        assert_eq!(sample.acceleration, 0.0);
    }
}
