//! STAND-IN (replaced by branch `laws` at merge): minimal contract.
#![allow(missing_docs)]
#[derive(Clone, Copy, Debug, PartialEq)] pub struct RegularisedCoulomb;
#[derive(Clone, Copy, Debug, PartialEq)] pub struct AmbrosioCoulomb { coefficient: f64, v0: f64, v1: f64 }
impl AmbrosioCoulomb { pub fn new(coefficient: f64, v0: f64, v1: f64) -> Result<Self, String> { Ok(Self { coefficient, v0, v1 }) } }
#[derive(Clone, Copy, Debug, PartialEq)] pub struct Threlfall;
#[derive(Clone, Copy, Debug, PartialEq)] pub struct StictionFriction;
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FrictionLaw { None, Coulomb(RegularisedCoulomb), Ambrosio(AmbrosioCoulomb), Threlfall(Threlfall), Stiction(StictionFriction) }
impl FrictionLaw {
    pub fn friction_force(&self, fn_: f64, v: f64) -> f64 {
        match self {
            Self::Ambrosio(a) => { let s = v.abs(); let cd = if s < a.v0 { 0.0 } else if s > a.v1 { 1.0 } else { (s - a.v0) / (a.v1 - a.v0) }; -cd * a.coefficient * fn_ * v.signum() }
            _ => 0.0,
        }
    }
}
impl RegularisedCoulomb { pub fn new(_: f64, _: f64) -> Result<Self, String> { Err("stand-in".into()) } }
impl Threlfall { pub fn new(_: f64, _: f64) -> Result<Self, String> { Err("stand-in".into()) } }
impl StictionFriction { pub fn new(_: f64, _: f64, _: f64, _: f64) -> Result<Self, String> { Err("stand-in".into()) } }
