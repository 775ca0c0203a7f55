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
    /// `[q, v, z]` laid out as [`super::StateLayout`] says: position coordinates
    /// (`(x, y, phi)` per planar body [m, rad]), velocity coordinates [m/s, rad/s],
    /// continuous element states (chamber pressures [Pa], ...).
    pub y: Vec<f64>,
    /// Memory of each clearance joint, in model order.
    pub contacts: Vec<ContactMemory>,
    /// Lengths of `q` and `v` in `y`.
    split: (usize, usize),
}

impl State {
    /// State of `model` at time `t` [s] with `y` laid out as its [`super::StateLayout`]
    /// and every clearance joint free of contact memory.
    pub fn new(model: &super::Model, time: f64, y: Vec<f64>) -> Self {
        debug_assert_eq!(y.len(), model.layout.len());
        let contacts = vec![ContactMemory::default(); model.clearance_joints.len()];
        Self { time, y, contacts, split: (model.layout.nq, model.layout.nv) }
    }

    /// Position coordinates `q`.
    pub fn coordinates(&self) -> &[f64] {
        &self.y[..self.split.0]
    }

    /// Velocity coordinates `v`.
    pub fn velocities(&self) -> &[f64] {
        &self.y[self.split.0..self.split.0 + self.split.1]
    }

    /// Continuous element states `z`.
    pub fn element_states(&self) -> &[f64] {
        &self.y[self.split.0 + self.split.1..]
    }
}
