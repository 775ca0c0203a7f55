//! Smooth cubic step, the ideal drive function of paper 003, eq. (5).
//!
//! `s = (t - t0)/(t1 - t0)`, `f = v0 + (v1 - v0) s²(3 - 2s)` for
//! t0 <= t <= t1, `v0` before and `v1` after; the rate vanishes at both ends.
//! Paper 003 drives the upper link with v0 = 0, v1 = -19 over t1 = 0.03 s.

use super::MotionSample;

/// Cubic step from `value_start` at `t_start` to `value_end` at `t_end`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CubicStep {
    /// Start of the step t0 [s].
    pub t_start: f64,
    /// End of the step t1 > t0 [s].
    pub t_end: f64,
    /// Value before the step v0 [unit].
    pub value_start: f64,
    /// Value after the step v1 [unit].
    pub value_end: f64,
}

impl CubicStep {
    /// Builds the step, checking finite inputs and t_end > t_start.
    pub fn new(t_start: f64, t_end: f64, value_start: f64, value_end: f64) -> Result<Self, String> {
        if !(t_start.is_finite() && value_start.is_finite() && value_end.is_finite()) {
            return Err(format!(
                "cubic step needs finite start time and values, got t_start = {t_start}, values {value_start} -> {value_end}"
            ));
        }
        if !(t_end.is_finite() && t_end > t_start) {
            return Err(format!(
                "cubic step end time must be finite and > t_start = {t_start} s, got {t_end}"
            ));
        }
        Ok(Self { t_start, t_end, value_start, value_end })
    }

    /// Value, rate and acceleration at time t [s]. An (unvalidated) empty
    /// interval t_end <= t_start acts as a jump at t_start.
    pub fn sample(&self, t: f64) -> MotionSample {
        if t <= self.t_start {
            return MotionSample::at_rest(self.value_start);
        }
        if t >= self.t_end {
            return MotionSample::at_rest(self.value_end);
        }
        let duration = self.t_end - self.t_start;
        let s = (t - self.t_start) / duration;
        let rise = self.value_end - self.value_start;
        MotionSample {
            value: self.value_start + rise * s * s * (3.0 - 2.0 * s),
            rate: rise * 6.0 * s * (1.0 - s) / duration,
            acceleration: rise * 6.0 * (1.0 - 2.0 * s) / (duration * duration),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn paper_003_drive() -> CubicStep {
        CubicStep::new(0.0, 0.03, 0.0, -19.0).unwrap()
    }

    #[test]
    fn test_cubic_step_end_values_and_zero_end_rates() {
        let step = paper_003_drive();
        assert_eq!(step.sample(0.0), MotionSample::at_rest(0.0));
        assert_eq!(step.sample(0.03), MotionSample::at_rest(-19.0));
        assert_eq!(step.sample(-1.0), MotionSample::at_rest(0.0));
        assert_eq!(step.sample(1.0), MotionSample::at_rest(-19.0));
        // rates just inside the ends tend to zero (peak rate is 950 /s)
        assert!(step.sample(1e-9).rate.abs() < 1e-3);
        assert!(step.sample(0.03 - 1e-9).rate.abs() < 1e-3);
    }

    #[test]
    fn test_cubic_step_mid_point_matches_paper_003_equation_5() {
        // x = -19 (t/0.03)² (3 - 2t/0.03): at t = 0.015, x = -9.5, rate = -19 * 1.5 / 0.03 = -950
        let sample = paper_003_drive().sample(0.015);
        assert!((sample.value + 9.5).abs() < 1e-12);
        assert!((sample.rate + 950.0).abs() < 1e-9);
        assert!(sample.acceleration.abs() < 1e-6);
        // t = 0.01: s = 1/3, x = -19 * (1/9) * (7/3)
        let sample = paper_003_drive().sample(0.01);
        assert!((sample.value + 19.0 * 7.0 / 27.0).abs() < 1e-12);
    }

    #[test]
    fn test_cubic_step_constructor_messages() {
        assert_eq!(
            CubicStep::new(0.03, 0.03, 0.0, 1.0).unwrap_err(),
            "cubic step end time must be finite and > t_start = 0.03 s, got 0.03"
        );
    }

    #[test]
    fn test_cubic_step_with_empty_interval_is_a_jump() {
        let step = CubicStep { t_start: 1.0, t_end: 1.0, value_start: 0.0, value_end: 2.0 };
        assert_eq!(step.sample(0.5), MotionSample::at_rest(0.0));
        assert_eq!(step.sample(1.5), MotionSample::at_rest(2.0));
    }
}
