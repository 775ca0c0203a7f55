//! Double-acting single-rod hydraulic cylinder between two attachment points.
//!
//! Stroke s [m]: 0 fully retracted, S fully extended; ds/dt > 0 extends.
//! Chambers: cap side (piston area A1) and rod side (annulus A2 < A1):
//!
//! ```text
//! V_cap = V_cap,dead + A1 s              V_rod = V_rod,dead + A2 (S - s)
//! dp_cap/dt = β / V_cap (Q_cap - A1 ds/dt)
//! dp_rod/dt = β / V_rod (Q_rod + A2 ds/dt)
//! F = p_cap A1 - p_rod A2 - F_f           (pushes the attachments apart)
//! ```
//!
//! with gauge pressures [Pa], inflows Q into each chamber [m³/s], and the
//! seal friction F_f [N] resisting ds/dt (LuGre: positive for steady
//! extension). Paper 002, §2.2, models its cylinder this way (no leakage,
//! effective bulk modulus; its pressure equations were lost in extraction).
//! Theory page: `docs/theory/hydraulic-cylinder.md`.

use crate::error::positive;
use super::chamber::{compression_energy, pressure_rate};
use super::SealFriction;
use std::fmt;

/// Largest number of continuous states of a cylinder: p_cap, p_rod, bristle deflection.
pub const MAX_STATES: usize = 3;

/// Default lowest admissible gauge pressure [Pa]: -101 325 Pa, absolute
/// zero under a standard atmosphere. Below it the liquid would be in
/// tension; the constant-β law has lost validity well before (air release,
/// cavitation near a few kPa absolute), so the floor marks a failed run,
/// not the edge of validity.
pub const DEFAULT_PRESSURE_FLOOR: f64 = -101_325.0;

/// Geometry of the cylinder.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CylinderGeometry {
    piston_area: f64,
    rod_side_area: f64,
    stroke_length: f64,
    cap_dead_volume: f64,
    rod_dead_volume: f64,
}

impl CylinderGeometry {
    /// Builds the geometry from the piston area A1 > 0 [m²] (cap side), the
    /// annulus area 0 < A2 < A1 [m²] (rod side), the stroke length S > 0
    /// [m] and the dead volumes > 0 [m³] of the cap and rod chambers (ports
    /// and lines; they keep both volumes positive over the whole stroke).
    pub fn new(
        piston_area: f64,
        rod_side_area: f64,
        stroke_length: f64,
        cap_dead_volume: f64,
        rod_dead_volume: f64,
    ) -> Result<Self, String> {
        let piston_area = positive("piston area", "m^2", piston_area)?;
        let rod_side_area = positive("rod side area", "m^2", rod_side_area)?;
        if rod_side_area >= piston_area {
            return Err(format!(
                "rod side area must be < the piston area {piston_area} m^2 (it is the annulus), got {rod_side_area}"
            ));
        }
        Ok(Self {
            piston_area,
            rod_side_area,
            stroke_length: positive("stroke length", "m", stroke_length)?,
            cap_dead_volume: positive("cap dead volume", "m^3", cap_dead_volume)?,
            rod_dead_volume: positive("rod dead volume", "m^3", rod_dead_volume)?,
        })
    }

    /// Piston area A1 [m²].
    pub fn piston_area(&self) -> f64 {
        self.piston_area
    }

    /// Rod-side (annulus) area A2 [m²].
    pub fn rod_side_area(&self) -> f64 {
        self.rod_side_area
    }

    /// Stroke length S [m].
    pub fn stroke_length(&self) -> f64 {
        self.stroke_length
    }

    /// Dead volume of the cap chamber [m³].
    pub fn cap_dead_volume(&self) -> f64 {
        self.cap_dead_volume
    }

    /// Dead volume of the rod chamber [m³].
    pub fn rod_dead_volume(&self) -> f64 {
        self.rod_dead_volume
    }

    /// Chamber volumes (V_cap, V_rod) [m³] at the stroke s [m]:
    /// `V_cap,dead + A1 s`, `V_rod,dead + A2 (S - s)`.
    pub fn volumes(&self, stroke: f64) -> (f64, f64) {
        let cap = self.cap_dead_volume + self.piston_area * stroke;
        let rod = self.rod_dead_volume + self.rod_side_area * (self.stroke_length - stroke);
        (cap, rod)
    }

    /// Volume rates (dV_cap/dt, dV_rod/dt) = (A1, -A2) ds/dt [m³/s] for ds/dt [m/s].
    pub fn volume_rates(&self, stroke_rate: f64) -> (f64, f64) {
        (self.piston_area * stroke_rate, -self.rod_side_area * stroke_rate)
    }
}

/// One of the two chambers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Chamber {
    /// Cap (piston) side, area A1.
    Cap,
    /// Rod (annulus) side, area A2.
    Rod,
}

impl fmt::Display for Chamber {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Cap => "cap",
            Self::Rod => "rod",
        })
    }
}

/// Why a cylinder cannot be evaluated; the owning element turns it into a
/// `SimulationError` at an accepted step (at a trial stage of a step it may
/// reject the step instead).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CylinderFault {
    /// The stroke left [0, S]: the piston would pass an end cap (no end stop is modelled).
    StrokeOutOfRange {
        /// Stroke s [m].
        stroke: f64,
        /// Stroke length S [m].
        stroke_length: f64,
    },
    /// A chamber pressure fell below the floor (or is NaN).
    PressureBelowFloor {
        /// The chamber.
        chamber: Chamber,
        /// Its gauge pressure [Pa].
        pressure: f64,
        /// The floor [Pa].
        floor: f64,
    },
}

impl fmt::Display for CylinderFault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::StrokeOutOfRange { stroke, stroke_length } => write!(
                f,
                "stroke {stroke:.6e} m left [0, {stroke_length}] m: the piston would pass an end cap (no end stop is modelled)"
            ),
            Self::PressureBelowFloor { chamber, pressure, floor } => write!(
                f,
                "{chamber} chamber pressure {pressure:.6e} Pa fell below the floor {floor:.6e} Pa: the liquid would cavitate (the chamber is emptied faster than it is fed)"
            ),
        }
    }
}

/// Forces, state rates and stick flag of a cylinder at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CylinderEvaluation {
    /// Force pushing the two attachments apart [N]: pressure force - friction force.
    pub force: f64,
    /// Pressure force p_cap A1 - p_rod A2 [N], pushing apart when positive.
    pub pressure_force: f64,
    /// Seal friction F_f [N], resisting the stroke rate (positive in steady extension).
    pub friction_force: f64,
    /// Seal in its stick state (always false without friction).
    pub stick: bool,
    state_rates: [f64; MAX_STATES],
    n_states: usize,
}

impl CylinderEvaluation {
    /// Rates of the states, same layout: [dp_cap/dt [Pa/s], dp_rod/dt [Pa/s], (dz/dt [m/s])].
    pub fn state_rates(&self) -> &[f64] {
        &self.state_rates[..self.n_states]
    }
}

/// Hydraulic cylinder: geometry, liquid and seal friction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HydraulicCylinder {
    geometry: CylinderGeometry,
    bulk_modulus: f64,
    seal: SealFriction,
    pressure_floor: f64,
}

impl HydraulicCylinder {
    /// Builds the cylinder from its geometry, the effective bulk modulus
    /// β > 0 [Pa] and the seal friction; the pressure floor is
    /// [`DEFAULT_PRESSURE_FLOOR`].
    pub fn new(geometry: CylinderGeometry, bulk_modulus: f64, seal: SealFriction) -> Result<Self, String> {
        let bulk_modulus = positive("bulk modulus", "Pa", bulk_modulus)?;
        Ok(Self { geometry, bulk_modulus, seal, pressure_floor: DEFAULT_PRESSURE_FLOOR })
    }

    /// The same cylinder with another pressure floor [Pa] (finite; 0 when the
    /// pressures are absolute).
    pub fn with_pressure_floor(self, pressure_floor: f64) -> Result<Self, String> {
        if !pressure_floor.is_finite() {
            return Err(format!("pressure floor must be finite, got {pressure_floor}"));
        }
        Ok(Self { pressure_floor, ..self })
    }

    /// Geometry.
    pub fn geometry(&self) -> &CylinderGeometry {
        &self.geometry
    }

    /// Effective bulk modulus β [Pa].
    pub fn bulk_modulus(&self) -> f64 {
        self.bulk_modulus
    }

    /// Seal friction law.
    pub fn seal(&self) -> &SealFriction {
        &self.seal
    }

    /// Lowest admissible gauge pressure [Pa].
    pub fn pressure_floor(&self) -> f64 {
        self.pressure_floor
    }

    /// Number of continuous states: 2 (p_cap, p_rod) plus the seal's (0 or 1).
    pub fn n_states(&self) -> usize {
        2 + self.seal.n_states()
    }

    /// Initial states [p_cap [Pa], p_rod [Pa], z = 0 [m]]; the first
    /// [`Self::n_states`] entries are the layout of `evaluate`.
    pub fn initial_states(&self, cap_pressure: f64, rod_pressure: f64) -> [f64; MAX_STATES] {
        [cap_pressure, rod_pressure, 0.0]
    }

    /// Stiffness of the closed chambers -dF/ds = β (A1²/V_cap + A2²/V_rod)
    /// [N/m] at the stroke s [m]; it does not depend on the pressures.
    pub fn hydraulic_stiffness(&self, stroke: f64) -> f64 {
        let (cap, rod) = self.geometry.volumes(stroke);
        let (a1, a2) = (self.geometry.piston_area, self.geometry.rod_side_area);
        self.bulk_modulus * (a1 * a1 / cap + a2 * a2 / rod)
    }

    /// Evaluates the cylinder at the stroke s [m] and stroke rate ds/dt
    /// [m/s], with `states` = [p_cap [Pa], p_rod [Pa], (z [m])] (at least
    /// [`Self::n_states`] entries; panics if fewer) and inflows (Q_cap,
    /// Q_rod) [m³/s] into the chambers. Fails when s leaves [0, S] or a
    /// pressure is below the floor. Does not allocate.
    pub fn evaluate(
        &self,
        stroke: f64,
        stroke_rate: f64,
        states: &[f64],
        inflows: (f64, f64),
    ) -> Result<CylinderEvaluation, CylinderFault> {
        self.check(stroke, states)?;
        Ok(self.evaluate_unchecked(stroke, stroke_rate, states, inflows))
    }

    /// [`Self::evaluate`] without [`Self::check`]: for the trial stages of a
    /// step, which may pass outside the valid range where an accepted step
    /// would not (the owning element checks every accepted step).
    pub fn evaluate_unchecked(&self, stroke: f64, stroke_rate: f64, states: &[f64], inflows: (f64, f64)) -> CylinderEvaluation {
        let g = &self.geometry;
        let (cap, rod) = g.volumes(stroke);
        let (cap_rate, rod_rate) = g.volume_rates(stroke_rate);
        let mut state_rates = [0.0; MAX_STATES];
        state_rates[0] = pressure_rate(self.bulk_modulus, cap, inflows.0, cap_rate);
        state_rates[1] = pressure_rate(self.bulk_modulus, rod, inflows.1, rod_rate);
        let pressure_force = states[0] * g.piston_area - states[1] * g.rod_side_area;
        let (friction_force, stick) = match &self.seal {
            SealFriction::None => (0.0, false),
            SealFriction::Lugre(law) => {
                let out = law.evaluate(stroke_rate, states[2]);
                state_rates[2] = out.bristle_rate;
                (out.force, law.is_sticking(stroke_rate))
            }
        };
        CylinderEvaluation {
            force: pressure_force - friction_force,
            pressure_force,
            friction_force,
            stick,
            state_rates,
            n_states: self.n_states(),
        }
    }

    /// Stroke inside [0, S] and both pressures at or above the floor.
    pub fn check(&self, stroke: f64, states: &[f64]) -> Result<(), CylinderFault> {
        let stroke_length = self.geometry.stroke_length;
        if !(0.0..=stroke_length).contains(&stroke) {
            return Err(CylinderFault::StrokeOutOfRange { stroke, stroke_length });
        }
        for (chamber, pressure) in [(Chamber::Cap, states[0]), (Chamber::Rod, states[1])] {
            // NaN fails too
            if pressure.is_nan() || pressure < self.pressure_floor {
                return Err(CylinderFault::PressureBelowFloor { chamber, pressure, floor: self.pressure_floor });
            }
        }
        Ok(())
    }

    /// Stored energy [J] at the stroke s [m] and `states`: the compression
    /// energy of both liquids relative to gauge pressure 0, plus the bristle
    /// energy σ0 z²/2 of a LuGre seal. With no inflow, its rate is
    /// `-F ds/dt - D` (D >= 0: the seal's dissipation), so with friction off
    /// it plus the kinetic energy of the attached bodies is conserved.
    pub fn stored_energy(&self, stroke: f64, states: &[f64]) -> f64 {
        let (cap, rod) = self.geometry.volumes(stroke);
        let beta = self.bulk_modulus;
        let liquid = compression_energy(states[0], cap, 0.0, beta) + compression_energy(states[1], rod, 0.0, beta);
        match &self.seal {
            SealFriction::None => liquid,
            SealFriction::Lugre(law) => liquid + law.bristle_energy(states[2]),
        }
    }
}

#[cfg(test)]
#[path = "cylinder_tests.rs"]
mod tests;
