//! Polynomial function of time `f = Σ c_k t^k`.

use super::MotionSample;

/// `f(t) = Σ c_k t^k`, coefficients in ascending order of power.
#[derive(Clone, Debug, PartialEq)]
pub struct Polynomial {
    /// Coefficients c_0, c_1, ... [unit/s^k]; empty means f = 0.
    pub coefficients: Vec<f64>,
}

impl Polynomial {
    /// Value, rate and acceleration at time t [s], by Horner's scheme for
    /// f, f' and f'' together.
    pub fn sample(&self, t: f64) -> MotionSample {
        let (mut value, mut first, mut half_second) = (0.0, 0.0, 0.0);
        for &coefficient in self.coefficients.iter().rev() {
            half_second = half_second * t + first;
            first = first * t + value;
            value = value * t + coefficient;
        }
        MotionSample { value, rate: first, acceleration: 2.0 * half_second }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn test_polynomial_matches_hand_derivatives() {
        // f = 1 - 2t + 0.5t² + 3t³; f' = -2 + t + 9t²; f'' = 1 + 18t
        let polynomial = Polynomial { coefficients: vec![1.0, -2.0, 0.5, 3.0] };
        let sample = polynomial.sample(2.0);
        assert_eq!(sample, MotionSample { value: 23.0, rate: 36.0, acceleration: 37.0 });
    }

    #[test]
    fn test_empty_and_constant_polynomials() {
        assert_eq!(Polynomial { coefficients: vec![] }.sample(3.0), MotionSample::at_rest(0.0));
        assert_eq!(Polynomial { coefficients: vec![4.0] }.sample(3.0), MotionSample::at_rest(4.0));
    }
}
