//! Conventions shared by every film model.
//!
//! Frame: global, non-rotating, translating with the bearing centre. The
//! eccentricity `e = P_j - P_b` is the journal centre relative to the
//! bearing centre [m]; the angle `theta` is measured from the global x axis
//! counter-clockwise, and `u(theta) = (cos theta, sin theta)`.
//!
//! Film thickness `h(theta) = c - e . u(theta)`: thinnest in the direction
//! of `e` (`h_min = c - |e|`), thickest opposite. Its rate is
//! `dh/dt = -e_dot . u(theta)`.
//!
//! Surface speeds: the journal surface moves at `R omega_j` and the bore at
//! `R omega_b` in the direction of increasing `theta`, with `omega_j`,
//! `omega_b` the absolute spin rates of the two bodies [rad/s] (the
//! film is thin, so one radius `R` serves both surfaces).
//!
//! Reynolds equation (incompressible, isoviscous) on `x = R theta`, `z`
//! along the axis in `[-L/2, L/2]`:
//! `d/dx(h^3 dp/dx) + d/dz(h^3 dp/dz) = 6 mu R (omega_j + omega_b) dh/dx + 12 mu dh/dt`.
//!
//! Force on the journal: `F = -integral p u(theta) R dtheta dz` (pressure
//! pushes the journal away from the thin film); the bearing gets `-F`.
//! Friction torque: the torque of the film's shear stress on the journal
//! about its centre [N m], counter-clockwise positive (negative when the
//! journal spins faster than the bore, `omega_j > omega_b`).

use nalgebra::Vector2;

/// Geometry of a journal bearing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingGeometry {
    /// Journal radius R [m] (the film is thin: used for both surfaces).
    pub radius: f64,
    /// Axial length L [m].
    pub length: f64,
    /// Radial clearance c [m].
    pub clearance: f64,
    /// Dynamic viscosity mu [Pa s].
    pub viscosity: f64,
}

/// Relative motion of journal and bearing at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilmKinematics {
    /// Eccentricity e = P_j - P_b [m].
    pub eccentricity: Vector2<f64>,
    /// Its time derivative [m/s].
    pub eccentricity_rate: Vector2<f64>,
    /// Absolute spin of the journal [rad/s].
    pub journal_spin: f64,
    /// Absolute spin of the bearing [rad/s].
    pub bearing_spin: f64,
}

impl FilmKinematics {
    /// Eccentricity ratio eps = |e| / c [-].
    pub fn eccentricity_ratio(&self, geometry: &BearingGeometry) -> f64 {
        self.eccentricity.norm() / geometry.clearance
    }
}

/// What a film model returns.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FilmForce {
    /// Force of the film on the journal, global frame [N].
    pub force_on_journal: Vector2<f64>,
    /// Largest film pressure (gauge) [Pa].
    pub peak_pressure: f64,
    /// Angle theta of the peak pressure [rad].
    pub peak_pressure_angle: f64,
    /// Shear torque of the film on the journal about its centre, counter-clockwise positive [N m] (NaN if the model does not give it).
    pub friction_torque: f64,
}
