//! Uniform gravity: `Q = m g` on every body, potential `-m g . r`.

use crate::dynamics::frame::Vec2;

/// Adds `m g` [N] to the translational coordinates of every rigid body.
/// `masses[k]` is the mass of body `k + 1` [kg]; `g` in [m/s^2].
pub fn gravity_generalised_force(masses: &[f64], g: Vec2, generalised: &mut [f64]) {
    for (k, m) in masses.iter().enumerate() {
        generalised[3 * k] += m * g.x;
        generalised[3 * k + 1] += m * g.y;
    }
}

/// Gravitational potential energy `-sum m g . r` [J] from the coordinates `q`.
pub fn gravity_potential_energy(masses: &[f64], g: Vec2, q: &[f64]) -> f64 {
    masses.iter().enumerate().map(|(k, m)| -m * (g.x * q[3 * k] + g.y * q[3 * k + 1])).sum()
}
