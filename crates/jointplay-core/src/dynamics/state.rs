//! The state of a simulation: coordinates, velocities and the discrete
//! memory of each contact.

/// Discrete memory of one clearance joint.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactMemory {
    /// Normal approach velocity latched at the accepted step where contact
    /// began [m/s]; `None` while the journal is free.
    pub onset_velocity: Option<f64>,
    /// Number of contact onsets so far.
    pub impacts: usize,
}

/// Everything that changes during a simulation.
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    /// Time [s].
    pub time: f64,
    /// `[q, q_dot]`: coordinates `(x, y, phi)` per body [m, rad] then their rates [m/s, rad/s].
    pub y: Vec<f64>,
    /// Memory of each clearance joint, in model order.
    pub contacts: Vec<ContactMemory>,
}

impl State {
    /// Coordinates `q`.
    pub fn coordinates(&self) -> &[f64] {
        &self.y[..self.y.len() / 2]
    }

    /// Velocities `q_dot`.
    pub fn velocities(&self) -> &[f64] {
        &self.y[self.y.len() / 2..]
    }
}
