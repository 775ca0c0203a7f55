//! Cross-section of a beam: the stiffnesses and inertias per unit length the
//! element law reads, given directly or from a material and a shape.
//!
//! Shear factors `k` (the shear stiffness is `k G A`) after Cowper, "The
//! shear coefficient in Timoshenko's beam theory", J. Appl. Mech. 33 (1966)
//! 335-340, Table 1: solid rectangle `10 (1 + nu) / (12 + 11 nu)`, solid
//! circle `6 (1 + nu) / (7 + 6 nu)`, hollow circle (inner over outer radius
//! `m`) `6 (1 + nu) (1 + m^2)^2 / ((7 + 6 nu)(1 + m^2)^2 + (20 + 12 nu) m^2)`.

use crate::error::{non_negative, positive};

/// Stiffnesses and inertias of a section, per unit length of the beam.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BeamSection {
    /// Axial stiffness `E A` [N].
    pub axial_stiffness: f64,
    /// Shear stiffness `k G A` [N].
    pub shear_stiffness: f64,
    /// Bending stiffness `E I` [N m^2].
    pub bending_stiffness: f64,
    /// Mass per length `rho A` [kg/m].
    pub mass_per_length: f64,
    /// Rotary inertia per length `rho I` [kg m].
    pub rotary_inertia_per_length: f64,
}

/// A shape of section [m].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SectionShape {
    /// Solid rectangle: `width` along the bending axis, `height` in the plane of bending [m].
    Rectangle {
        /// Width (out of the plane) [m].
        width: f64,
        /// Height (in the plane of bending) [m].
        height: f64,
    },
    /// Solid circle of diameter [m].
    Circle {
        /// Diameter [m].
        diameter: f64,
    },
    /// Tube of outer and inner diameter [m].
    Tube {
        /// Outer diameter [m].
        outer_diameter: f64,
        /// Inner diameter [m] (smaller than the outer).
        inner_diameter: f64,
    },
}

/// An isotropic elastic material.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BeamMaterial {
    /// Young's modulus `E` [Pa].
    pub youngs_modulus: f64,
    /// Poisson's ratio `nu` [-] (the shear modulus is `E / (2 (1 + nu))`).
    pub poisson_ratio: f64,
    /// Density `rho` [kg/m^3].
    pub density: f64,
}

impl SectionShape {
    /// Area [m^2], second moment about the bending axis [m^4] and Cowper's shear factor [-].
    pub fn properties(&self, poisson_ratio: f64) -> Result<(f64, f64, f64), String> {
        let nu = poisson_ratio;
        match *self {
            Self::Rectangle { width, height } => {
                let (b, h) = (positive("width", "m", width)?, positive("height", "m", height)?);
                Ok((b * h, b * h.powi(3) / 12.0, 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu)))
            }
            Self::Circle { diameter } => {
                let r = 0.5 * positive("diameter", "m", diameter)?;
                let pi = std::f64::consts::PI;
                Ok((pi * r * r, pi * r.powi(4) / 4.0, 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu)))
            }
            Self::Tube { outer_diameter, inner_diameter } => {
                let outer = 0.5 * positive("outer diameter", "m", outer_diameter)?;
                let inner = 0.5 * non_negative("inner diameter", "m", inner_diameter)?;
                if inner >= outer {
                    return Err(format!("inner diameter must be smaller than the outer diameter {outer_diameter} m, got {inner_diameter} m"));
                }
                let pi = std::f64::consts::PI;
                let m2 = (inner / outer).powi(2);
                let k = 6.0 * (1.0 + nu) * (1.0 + m2).powi(2) / ((7.0 + 6.0 * nu) * (1.0 + m2).powi(2) + (20.0 + 12.0 * nu) * m2);
                Ok((pi * (outer * outer - inner * inner), pi * (outer.powi(4) - inner.powi(4)) / 4.0, k))
            }
        }
    }
}

impl BeamSection {
    /// The section of `shape` made of `material`.
    pub fn of(shape: &SectionShape, material: &BeamMaterial) -> Result<Self, String> {
        let e = positive("Young's modulus", "Pa", material.youngs_modulus)?;
        let rho = positive("density", "kg/m^3", material.density)?;
        let nu = material.poisson_ratio;
        if !(nu.is_finite() && (-1.0..0.5).contains(&nu)) {
            return Err(format!("Poisson's ratio must be in [-1, 0.5), got {nu}"));
        }
        let (area, second_moment, shear_factor) = shape.properties(nu)?;
        let g = e / (2.0 * (1.0 + nu));
        Ok(Self {
            axial_stiffness: e * area,
            shear_stiffness: shear_factor * g * area,
            bending_stiffness: e * second_moment,
            mass_per_length: rho * area,
            rotary_inertia_per_length: rho * second_moment,
        })
    }

    /// Checks that every stiffness and inertia is finite and positive.
    pub fn validated(self) -> Result<Self, String> {
        positive("axial stiffness EA", "N", self.axial_stiffness)?;
        positive("shear stiffness kGA", "N", self.shear_stiffness)?;
        positive("bending stiffness EI", "N m^2", self.bending_stiffness)?;
        positive("mass per length rho A", "kg/m", self.mass_per_length)?;
        positive("rotary inertia per length rho I", "kg m", self.rotary_inertia_per_length)?;
        Ok(self)
    }
}
