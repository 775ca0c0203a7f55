//! Elastic material of one contacting body.

/// Elastic material of one body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Young's modulus E [Pa].
    pub youngs_modulus: f64,
    /// Poisson's ratio ν [-].
    pub poisson_ratio: f64,
}

impl Material {
    /// Checks that E > 0 is finite and -1 < ν <= 0.5 (the range allowed for an isotropic solid).
    pub fn validated(self, which: &str) -> Result<Self, String> {
        if !(self.youngs_modulus.is_finite() && self.youngs_modulus > 0.0) {
            return Err(format!(
                "{which} Young's modulus must be finite and > 0 Pa, got {}",
                self.youngs_modulus
            ));
        }
        if !(self.poisson_ratio > -1.0 && self.poisson_ratio <= 0.5) {
            return Err(format!(
                "{which} Poisson's ratio must be in (-1, 0.5], got {}",
                self.poisson_ratio
            ));
        }
        Ok(self)
    }

    /// Plane-strain compliance (1 - ν²)/E [1/Pa].
    pub fn plane_strain_compliance(&self) -> f64 {
        (1.0 - self.poisson_ratio * self.poisson_ratio) / self.youngs_modulus
    }
}

/// Effective modulus of a pair, `1/E* = (1-ν_b²)/E_b + (1-ν_j²)/E_j` [Pa].
pub(crate) fn effective_modulus(bearing: &Material, journal: &Material) -> f64 {
    1.0 / (bearing.plane_strain_compliance() + journal.plane_strain_compliance())
}

/// Checks a bore and journal radius pair and returns the radial clearance `R_b - R_j` [m].
pub(crate) fn radial_clearance(bearing_radius: f64, journal_radius: f64) -> Result<f64, String> {
    if !(journal_radius.is_finite() && journal_radius > 0.0) {
        return Err(format!("journal radius must be finite and > 0 m, got {journal_radius}"));
    }
    if !(bearing_radius.is_finite() && bearing_radius > journal_radius) {
        return Err(format!(
            "bearing radius must be finite and larger than the journal radius {journal_radius} m, got {bearing_radius}"
        ));
    }
    Ok(bearing_radius - journal_radius)
}

/// Checks a contact length [m].
pub(crate) fn checked_length(length: f64) -> Result<f64, String> {
    if length.is_finite() && length > 0.0 {
        Ok(length)
    } else {
        Err(format!("contact length must be finite and > 0 m, got {length}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const STEEL: Material = Material { youngs_modulus: 207e9, poisson_ratio: 0.3 };

    #[test]
    fn test_effective_modulus_of_steel_pair() {
        // 1/E* = 2 (1 - 0.09) / 207e9
        let expected = 207e9 / (2.0 * 0.91);
        assert!((effective_modulus(&STEEL, &STEEL) / expected - 1.0).abs() < 1e-14);
    }

    #[test]
    fn test_material_validation_messages() {
        let bad = Material { youngs_modulus: -1.0, poisson_ratio: 0.3 };
        assert_eq!(
            bad.validated("bearing").unwrap_err(),
            "bearing Young's modulus must be finite and > 0 Pa, got -1"
        );
        let bad = Material { youngs_modulus: 1e9, poisson_ratio: 0.6 };
        assert_eq!(
            bad.validated("journal").unwrap_err(),
            "journal Poisson's ratio must be in (-1, 0.5], got 0.6"
        );
    }

    #[test]
    fn test_radial_clearance_needs_bore_larger_than_journal() {
        assert!((radial_clearance(0.01, 0.0095).unwrap() - 0.0005).abs() < 1e-15);
        assert_eq!(
            radial_clearance(0.009, 0.0095).unwrap_err(),
            "bearing radius must be finite and larger than the journal radius 0.0095 m, got 0.009"
        );
    }
}
