//! The per-step hook `observe_step`: called once per accepted step with
//! contiguous intervals and a dense output that matches the solution.

use super::*;

/// y' = cos t from y(0) = 0 (y = sin t), checking every observed step.
struct Observed {
    /// Intervals seen [s].
    steps: Vec<(f64, f64)>,
    /// Largest error of the dense output at step midpoints and of y at step ends.
    worst: f64,
    /// Largest y found by searching each step's dense output.
    peak: (f64, f64),
}

impl OdeSystem for Observed {
    fn len(&self) -> usize {
        1
    }
    fn rhs(&mut self, t: f64, _y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError> {
        dydt[0] = t.cos();
        Ok(())
    }
    fn record(&mut self, _t: f64, _y: &[f64]) -> Result<(), SimulationError> {
        Ok(())
    }
    fn observe_step(&mut self, t_old: f64, t_new: f64, y: &[f64], dense: &mut dyn FnMut(f64, &mut [f64])) -> Result<(), SimulationError> {
        self.steps.push((t_old, t_new));
        let mut out = [0.0];
        dense(0.5 * (t_old + t_new), &mut out);
        self.worst = self.worst.max((out[0] - (0.5 * (t_old + t_new)).sin()).abs()).max((y[0] - t_new.sin()).abs());
        let mut f = |t: f64| {
            dense(t, &mut out);
            Some(out[0])
        };
        if let Some((t, v)) = crate::dynamics::maximize(&mut f, t_old, t_new, 1e-9 * (t_new - t_old), 60) {
            if v > self.peak.1 {
                self.peak = (t, v);
            }
        }
        Ok(())
    }
}

#[test]
fn observe_step_sees_every_accepted_step_with_its_dense_output() {
    for method in METHODS {
        let mut sys = Observed { steps: Vec::new(), worst: 0.0, peak: (0.0, f64::NEG_INFINITY) };
        let mut opts = options(method, 1e-10);
        opts.output_step = Some(0.5);
        let mut y = [0.0];
        let (stats, result) = integrate(&mut sys, 0.0, 3.0, &mut y, &opts);
        result.unwrap();
        assert_eq!(sys.steps.len(), stats.accepted_steps, "{method:?}");
        assert_eq!(sys.steps[0].0, 0.0);
        assert_eq!(sys.steps.last().unwrap().1, 3.0);
        assert!(sys.steps.windows(2).all(|w| w[0].1 == w[1].0), "{method:?}: steps not contiguous");
        assert!(sys.worst < 1e-7, "{method:?}: dense output error {:e}", sys.worst);
        // the maximum of sin t at pi/2, found inside a step whatever the output grid
        assert!((sys.peak.0 - std::f64::consts::FRAC_PI_2).abs() < 1e-3, "{method:?}: {:?}", sys.peak);
        assert!((sys.peak.1 - 1.0).abs() < 1e-7, "{method:?}: {:?}", sys.peak);
    }
}
