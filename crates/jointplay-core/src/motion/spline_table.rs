//! Natural cubic spline through tabulated points.
//!
//! Between knots the spline is the cubic with continuous value, slope and
//! curvature whose second derivative M_i solves the tridiagonal system
//! `h_{i-1} M_{i-1} + 2(h_{i-1} + h_i) M_i + h_i M_{i+1}
//!  = 6((y_{i+1} - y_i)/h_i - (y_i - y_{i-1})/h_{i-1})` with the natural ends
//! `M_0 = M_{n-1} = 0`. Outside the table the function continues linearly
//! with the end slope (zero acceleration), which keeps value, rate and
//! acceleration continuous at the ends because the natural spline has zero
//! curvature there.

use super::MotionSample;

/// Natural cubic spline table, built once and evaluated by binary search.
#[derive(Clone, Debug, PartialEq)]
pub struct SplineTable {
    times: Vec<f64>,
    values: Vec<f64>,
    second_derivatives: Vec<f64>,
}

impl SplineTable {
    /// Builds the spline from at least two points with strictly increasing
    /// finite times [s] and finite values [unit].
    pub fn new(times: Vec<f64>, values: Vec<f64>) -> Result<Self, String> {
        check_table(&times, &values)?;
        let second_derivatives = natural_second_derivatives(&times, &values);
        Ok(Self { times, values, second_derivatives })
    }

    /// Knot times [s].
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// Knot values [unit].
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// Value, rate and acceleration at time t [s]. Does not allocate.
    pub fn sample(&self, t: f64) -> MotionSample {
        let last = self.times.len() - 1;
        if t < self.times[0] {
            return self.extend_linearly(0, 0, t);
        }
        if t > self.times[last] {
            return self.extend_linearly(last, last - 1, t);
        }
        // interval [t_i, t_i+1] holding t
        let index = self.times.partition_point(|&knot| knot <= t).clamp(1, last) - 1;
        self.sample_interval(index, t)
    }

    fn extend_linearly(&self, knot: usize, interval: usize, t: f64) -> MotionSample {
        let end = self.sample_interval(interval, self.times[knot]);
        MotionSample {
            value: end.value + end.rate * (t - self.times[knot]),
            rate: end.rate,
            acceleration: 0.0,
        }
    }

    fn sample_interval(&self, index: usize, t: f64) -> MotionSample {
        let (t0, t1) = (self.times[index], self.times[index + 1]);
        let (y0, y1) = (self.values[index], self.values[index + 1]);
        let (m0, m1) = (self.second_derivatives[index], self.second_derivatives[index + 1]);
        let width = t1 - t0;
        let (a, b) = ((t1 - t) / width, (t - t0) / width);
        MotionSample {
            value: a * y0
                + b * y1
                + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * width * width / 6.0,
            rate: (y1 - y0) / width
                + ((3.0 * b * b - 1.0) * m1 - (3.0 * a * a - 1.0) * m0) * width / 6.0,
            acceleration: a * m0 + b * m1,
        }
    }
}

fn check_table(times: &[f64], values: &[f64]) -> Result<(), String> {
    if times.len() != values.len() {
        return Err(format!(
            "table needs as many values as times, got {} times and {} values",
            times.len(),
            values.len()
        ));
    }
    if times.len() < 2 {
        return Err(format!("table needs at least 2 points, got {}", times.len()));
    }
    if let Some(index) = values.iter().position(|value| !value.is_finite()) {
        return Err(format!("table value {index} must be finite, got {}", values[index]));
    }
    if let Some(index) = times.iter().position(|time| !time.is_finite()) {
        return Err(format!("table time {index} must be finite, got {}", times[index]));
    }
    if let Some(index) = times.windows(2).position(|pair| pair[1] <= pair[0]) {
        return Err(format!(
            "table times must be strictly increasing, got {} after {} at index {}",
            times[index + 1],
            times[index],
            index + 1
        ));
    }
    Ok(())
}

// Thomas algorithm on the interior knots; M_0 = M_{n-1} = 0
fn natural_second_derivatives(times: &[f64], values: &[f64]) -> Vec<f64> {
    let count = times.len();
    let mut second = vec![0.0; count];
    let mut upper = vec![0.0; count];
    for i in 1..count - 1 {
        let (left, right) = (times[i] - times[i - 1], times[i + 1] - times[i]);
        let rhs = 6.0 * ((values[i + 1] - values[i]) / right - (values[i] - values[i - 1]) / left);
        // forward elimination
        let pivot = 2.0 * (left + right) - left * upper[i - 1];
        upper[i] = right / pivot;
        second[i] = (rhs - left * second[i - 1]) / pivot;
    }
    // back substitution
    for i in (1..count - 1).rev() {
        second[i] -= upper[i] * second[i + 1];
    }
    second
}

#[cfg(test)]
mod tests {
    use super::super::{assert_derivatives_match_finite_differences, TimeFunction};
    use super::*;

    fn example() -> SplineTable {
        SplineTable::new(vec![0.0, 1.0, 2.5, 4.0], vec![0.0, 2.0, 1.0, 3.0]).unwrap()
    }

    #[test]
    fn test_spline_matches_scipy_natural_cubic_spline() {
        // reference: scipy 1.17.1 CubicSpline(x, y, bc_type='natural') evaluated now and pasted
        let reference = [
            (0.5, 1.2567567567567568, 2.171171171171171, -2.0540540540540544),
            (1.7, 1.7068828828828828, -1.07963963963964, -0.7783783783783793),
            (3.0, 1.2462462462462462, 1.081081081081081, 2.018018018018018),
            (3.9, 2.791327327327327, 2.079999999999999, 0.20180180180180196),
        ];
        for (t, value, rate, acceleration) in reference {
            let sample = example().sample(t);
            assert!((sample.value - value).abs() < 1e-12, "value at {t}");
            assert!((sample.rate - rate).abs() < 1e-12, "rate at {t}");
            assert!((sample.acceleration - acceleration).abs() < 1e-12, "acceleration at {t}");
        }
    }

    #[test]
    fn test_spline_passes_through_knots_and_reproduces_linear_data() {
        let spline = example();
        for (&t, &value) in spline.times().iter().zip(spline.values()) {
            assert!((spline.sample(t).value - value).abs() < 1e-14);
        }
        let line = SplineTable::new(vec![0.0, 0.3, 1.0, 1.1], vec![1.0, 1.6, 3.0, 3.2]).unwrap();
        for t in [-1.0, 0.1, 0.5, 1.05, 2.0] {
            let sample = line.sample(t);
            assert!((sample.value - (1.0 + 2.0 * t)).abs() < 1e-13, "value at {t}");
            assert!((sample.rate - 2.0).abs() < 1e-12 && sample.acceleration.abs() < 1e-12);
        }
    }

    #[test]
    fn test_spline_extends_linearly_with_end_slope() {
        // end slopes from scipy: 2.684684684684685 at t = 0, 2.0900900900900896 at t = 4
        let spline = example();
        let before = spline.sample(-0.5);
        assert!((before.value + 0.5 * 2.684684684684685).abs() < 1e-12);
        assert!((before.rate - 2.684684684684685).abs() < 1e-12 && before.acceleration == 0.0);
        let after = spline.sample(5.0);
        assert!((after.value - (3.0 + 2.0900900900900896)).abs() < 1e-12);
        assert!((after.rate - 2.0900900900900896).abs() < 1e-12 && after.acceleration == 0.0);
    }

    #[test]
    fn test_spline_derivatives_match_finite_differences() {
        let function = TimeFunction::Table(example());
        for t in [0.2, 0.99, 1.01, 2.0, 3.7] {
            assert_derivatives_match_finite_differences(&function, t, 1e-6);
        }
    }

    #[test]
    fn test_spline_constructor_messages() {
        assert_eq!(
            SplineTable::new(vec![0.0], vec![1.0]).unwrap_err(),
            "table needs at least 2 points, got 1"
        );
        assert_eq!(
            SplineTable::new(vec![0.0, 1.0, 1.0], vec![1.0, 2.0, 3.0]).unwrap_err(),
            "table times must be strictly increasing, got 1 after 1 at index 2"
        );
        assert_eq!(
            SplineTable::new(vec![0.0, f64::NAN], vec![1.0, 2.0]).unwrap_err(),
            "table time 1 must be finite, got NaN"
        );
        assert_eq!(
            SplineTable::new(vec![0.0, 1.0], vec![1.0]).unwrap_err(),
            "table needs as many values as times, got 2 times and 1 values"
        );
    }
}
