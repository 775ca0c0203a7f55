//! STAND-IN (replaced by branch `integrate` at merge): contract + fixed-step RK4.
#![allow(missing_docs)]
use crate::error::SimulationError;
pub trait OdeSystem {
    fn len(&self) -> usize;
    fn rhs(&mut self, t: f64, y: &[f64], dydt: &mut [f64]) -> Result<(), SimulationError>;
    fn n_events(&self) -> usize { 0 }
    fn event_functions(&mut self, _t: f64, _y: &[f64], _g: &mut [f64]) {}
    fn on_event(&mut self, _t: f64, _y: &mut [f64], _event: usize) -> Result<(), SimulationError> { Ok(()) }
    fn accept(&mut self, t: f64, y: &mut [f64]) -> Result<bool, SimulationError>;
    fn record(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError>;
}
#[derive(Clone, Copy, Debug, PartialEq, Eq)] pub enum Method { DormandPrince45, AdamsPredictorCorrector }
#[derive(Clone, Debug, PartialEq)] pub struct IntegratorOptions { pub method: Method, pub rtol: f64, pub atol: f64, pub max_step: f64, pub initial_step: Option<f64>, pub min_step: f64, pub max_steps: usize, pub output_step: Option<f64> }
impl Default for IntegratorOptions { fn default() -> Self { Self { method: Method::DormandPrince45, rtol: 1e-6, atol: 1e-9, max_step: f64::INFINITY, initial_step: None, min_step: 1e-14, max_steps: 10_000_000, output_step: None } } }
impl IntegratorOptions { pub fn validate(&self) -> Result<(), String> { Ok(()) } }
#[derive(Clone, Debug, Default, PartialEq)] pub struct Statistics { pub accepted_steps: usize, pub rejected_steps: usize, pub rhs_evaluations: usize, pub events: usize, pub smallest_step: f64, pub largest_step: f64, pub restarts: usize }
pub fn integrate<S: OdeSystem>(s: &mut S, t0: f64, t_end: f64, y: &mut [f64], o: &IntegratorOptions) -> (Statistics, Result<(), SimulationError>) {
    let mut st = Statistics::default();
    let r = (|| {
        let n = y.len(); let h0 = o.max_step.min(1e-6); let mut t = t0;
        let (mut k1, mut k2, mut k3, mut k4, mut yt) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        s.record(t, y)?;
        while t < t_end {
            let h = h0.min(t_end - t);
            s.rhs(t, y, &mut k1)?; for i in 0..n { yt[i] = y[i] + 0.5 * h * k1[i]; }
            s.rhs(t + 0.5 * h, &yt, &mut k2)?; for i in 0..n { yt[i] = y[i] + 0.5 * h * k2[i]; }
            s.rhs(t + 0.5 * h, &yt, &mut k3)?; for i in 0..n { yt[i] = y[i] + h * k3[i]; }
            s.rhs(t + h, &yt, &mut k4)?; for i in 0..n { y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]); }
            t += h; st.accepted_steps += 1; st.rhs_evaluations += 4;
            s.accept(t, y)?; s.record(t, y)?;
        }
        Ok(())
    })();
    (st, r)
}
