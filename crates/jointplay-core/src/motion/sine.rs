//! Sine wave `f = f_offset + A sin(2π f t + φ)`, for example the input force
//! of paper 002 (1-4 kN at 5-20 Hz).

use std::f64::consts::TAU;

use super::MotionSample;

/// `f(t) = offset + amplitude sin(2π frequency t + phase)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sine {
    /// Mean value [unit].
    pub offset: f64,
    /// Amplitude A [unit].
    pub amplitude: f64,
    /// Frequency [Hz].
    pub frequency: f64,
    /// Phase φ [rad].
    pub phase: f64,
}

impl Sine {
    /// Builds the wave, checking finite inputs and frequency >= 0.
    pub fn new(offset: f64, amplitude: f64, frequency: f64, phase: f64) -> Result<Self, String> {
        if !(offset.is_finite() && amplitude.is_finite() && phase.is_finite()) {
            return Err(format!(
                "sine needs finite offset, amplitude and phase, got {offset}, {amplitude}, {phase}"
            ));
        }
        if !(frequency.is_finite() && frequency >= 0.0) {
            return Err(format!("sine frequency must be finite and >= 0 Hz, got {frequency}"));
        }
        Ok(Self { offset, amplitude, frequency, phase })
    }

    /// Value, rate and acceleration at time t [s].
    pub fn sample(&self, t: f64) -> MotionSample {
        let angular = TAU * self.frequency;
        let (sin, cos) = (angular * t + self.phase).sin_cos();
        MotionSample {
            value: self.offset + self.amplitude * sin,
            rate: self.amplitude * angular * cos,
            acceleration: -self.amplitude * angular * angular * sin,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn test_sine_quarter_period_values() {
        // 3 kN at 10 Hz: peak at t = 25 ms, zero crossing rate A ω at t = 0
        let force = Sine::new(0.0, 3000.0, 10.0, 0.0).unwrap();
        let peak = force.sample(0.025);
        assert!((peak.value - 3000.0).abs() < 1e-9);
        assert!(peak.rate.abs() < 1e-9);
        assert!((peak.acceleration + 3000.0 * (20.0 * std::f64::consts::PI).powi(2)).abs() < 1e-6);
        assert!((force.sample(0.0).rate - 3000.0 * 20.0 * std::f64::consts::PI).abs() < 1e-9);
    }

    #[test]
    fn test_sine_constructor_messages() {
        assert_eq!(
            Sine::new(0.0, 1.0, -5.0, 0.0).unwrap_err(),
            "sine frequency must be finite and >= 0 Hz, got -5"
        );
    }
}
