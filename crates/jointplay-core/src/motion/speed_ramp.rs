//! Speed ramp: a coordinate at rest until t = 0 whose rate rises smoothly to
//! `final_rate` over `ramp_time` and stays there (the spin-up manoeuvre of
//! Simo and Vu-Quoc, "On the dynamics of flexible beams under large overall
//! motions - the plane case: Part II", J. Appl. Mech. 53 (1986) 855-863, §5).
//!
//! With `T` the ramp time and `w` the final rate:
//!
//! ```text
//! f(t) = (w/T) [t^2/2 + (T/2 pi)^2 (cos(2 pi t/T) - 1)]    0 <= t <= T
//! f(t) = w t - w T/2                                      t > T
//! ```
//!
//! so the acceleration `(w/T)(1 - cos(2 pi t/T))` is zero at both ends of the ramp.

use super::MotionSample;
use std::f64::consts::PI;

/// Rate rising from zero to `final_rate` over `ramp_time`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeedRamp {
    /// Duration of the ramp T > 0 [s].
    pub ramp_time: f64,
    /// Rate after the ramp w [unit/s].
    pub final_rate: f64,
}

impl SpeedRamp {
    /// Value, rate and acceleration at time t [s] (at rest, zero, before t = 0).
    pub fn sample(&self, t: f64) -> MotionSample {
        let (ramp, rate) = (self.ramp_time, self.final_rate);
        if t <= 0.0 {
            return MotionSample::at_rest(0.0);
        }
        if t >= ramp {
            return MotionSample { value: rate * (t - 0.5 * ramp), rate, acceleration: 0.0 };
        }
        let omega = 2.0 * PI / ramp;
        let (sin, cos) = (omega * t).sin_cos();
        let k = rate / ramp;
        MotionSample { value: k * (0.5 * t * t + (cos - 1.0) / (omega * omega)), rate: k * (t - sin / omega), acceleration: k * (1.0 - cos) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::motion::{assert_derivatives_match_finite_differences, TimeFunction};

    #[test]
    fn the_spin_up_of_simo_and_vu_quoc() {
        // theta(t) = (6/15)[t^2/2 + (15/2 pi)^2 (cos(2 pi t/15) - 1)] for t <= 15 s, 6 t - 45 after
        let ramp = SpeedRamp { ramp_time: 15.0, final_rate: 6.0 };
        for t in [0.5, 3.0, 7.5, 14.0] {
            let expected = 0.4 * (0.5 * t * t + (15.0 / (2.0 * PI)).powi(2) * ((2.0 * PI * t / 15.0).cos() - 1.0));
            assert!((ramp.sample(t).value - expected).abs() < 1e-12, "t = {t}");
        }
        assert_eq!(ramp.sample(20.0).value, 6.0 * 20.0 - 45.0);
        // continuous in value, rate and acceleration at the end of the ramp, at rest before the start
        let (before, after) = (ramp.sample(15.0 - 1e-9), ramp.sample(15.0 + 1e-9));
        // (2e-9 s apart at a rate of 6 per second)
        assert!((before.value - after.value).abs() < 2e-8 && (before.rate - after.rate).abs() < 1e-8 && before.acceleration.abs() < 1e-8);
        assert_eq!(ramp.sample(-1.0), MotionSample::at_rest(0.0));
        for t in [0.7, 5.0, 11.0, 18.0] {
            assert_derivatives_match_finite_differences(&TimeFunction::SpeedRamp(ramp), t, 1e-4);
        }
    }
}
