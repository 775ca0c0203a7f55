//! STAND-IN (replaced by branch `laws` at merge): minimal contract.
#![allow(missing_docs)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material { pub youngs_modulus: f64, pub poisson_ratio: f64 }
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NormalForceLaw { Hertz, HuntCrossley { restitution: f64 }, LankaraniNikravesh { restitution: f64 }, Flores { restitution: f64 }, Gonthier { restitution: f64 }, HuGuo { restitution: f64 } }
impl NormalForceLaw {
    pub fn hysteresis_factor(&self) -> f64 {
        match *self { Self::LankaraniNikravesh { restitution: e } => 0.75 * (1.0 - e * e), Self::Hertz => 0.0, _ => 0.0 }
    }
    pub fn normal_force(&self, elastic_force: f64, penetration_rate: f64, onset_velocity: f64) -> f64 {
        (elastic_force * (1.0 + self.hysteresis_factor() * penetration_rate / onset_velocity)).max(0.0)
    }
}
#[derive(Clone, Debug, PartialEq)]
pub struct HertzCylinder { k: f64, n: f64 }
impl HertzCylinder {
    pub fn new(rb: f64, rj: f64, b: Material, j: Material, exponent: f64) -> Result<Self, String> {
        let es = 1.0 / ((1.0 - b.poisson_ratio.powi(2)) / b.youngs_modulus + (1.0 - j.poisson_ratio.powi(2)) / j.youngs_modulus);
        let r = rb * rj / (rb - rj);
        Ok(Self { k: 4.0 / 3.0 * es * r.sqrt(), n: exponent })
    }
    pub fn stiffness(&self) -> f64 { self.k }
    pub fn exponent(&self) -> f64 { self.n }
}
#[derive(Clone, Debug, PartialEq)] pub struct JohnsonLine;
#[derive(Clone, Debug, PartialEq)] pub struct RogersAndrews;
#[derive(Clone, Debug, PartialEq)]
pub enum ContactStiffness { HertzCylinder(HertzCylinder), JohnsonLine(JohnsonLine), RogersAndrews(RogersAndrews) }
impl ContactStiffness {
    pub fn elastic_force(&self, d: f64) -> f64 { match self { Self::HertzCylinder(h) => if d > 0.0 { h.k * d.powf(h.n) } else { 0.0 }, _ => 0.0 } }
    pub fn elastic_energy(&self, d: f64) -> f64 { match self { Self::HertzCylinder(h) => if d > 0.0 { h.k * d.powf(h.n + 1.0) / (h.n + 1.0) } else { 0.0 }, _ => 0.0 } }
}
impl JohnsonLine { pub fn new(_: f64, _: f64, _: f64, _: Material, _: Material) -> Result<Self, String> { Err("stand-in".into()) } }
impl RogersAndrews { pub fn new(_: f64, _: f64, _: f64, _: Material, _: Material) -> Result<Self, String> { Err("stand-in".into()) } }
