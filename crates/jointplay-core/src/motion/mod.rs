//! STAND-IN (replaced by branch `laws` at merge): minimal contract.
#![allow(missing_docs)]
#[derive(Clone, Copy, Debug, PartialEq)] pub struct MotionSample { pub value: f64, pub rate: f64, pub acceleration: f64 }
#[derive(Clone, Copy, Debug, PartialEq)] pub struct ConstantRate { pub initial: f64, pub rate: f64 }
#[derive(Clone, Debug, PartialEq)] pub struct Polynomial { pub coefficients: Vec<f64> }
#[derive(Clone, Copy, Debug, PartialEq)] pub struct CubicStep { pub t_start: f64, pub t_end: f64, pub value_start: f64, pub value_end: f64 }
#[derive(Clone, Copy, Debug, PartialEq)] pub struct Sine { pub offset: f64, pub amplitude: f64, pub frequency: f64, pub phase: f64 }
#[derive(Clone, Debug, PartialEq)] pub struct SplineTable;
impl SplineTable { pub fn new(_t: Vec<f64>, _v: Vec<f64>) -> Result<Self, String> { Err("stand-in".into()) } }
#[derive(Clone, Debug, PartialEq)]
pub enum TimeFunction { Constant(f64), ConstantRate(ConstantRate), Polynomial(Polynomial), CubicStep(CubicStep), Sine(Sine), Table(SplineTable) }
impl TimeFunction {
    pub fn sample(&self, t: f64) -> MotionSample {
        match self {
            Self::Constant(v) => MotionSample { value: *v, rate: 0.0, acceleration: 0.0 },
            Self::ConstantRate(c) => MotionSample { value: c.initial + c.rate * t, rate: c.rate, acceleration: 0.0 },
            Self::Sine(s) => { let w = 2.0 * std::f64::consts::PI * s.frequency; let a = w * t + s.phase; MotionSample { value: s.offset + s.amplitude * a.sin(), rate: s.amplitude * w * a.cos(), acceleration: -s.amplitude * w * w * a.sin() } }
            _ => MotionSample { value: 0.0, rate: 0.0, acceleration: 0.0 },
        }
    }
}
