//! The state of a simulation: coordinates, velocities and the discrete
//! memory of each element.

pub use crate::joint::ContactMemory;
use crate::element::ElementMemory;

/// Everything that changes during a simulation.
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    /// Time [s].
    pub time: f64,
    /// `[q, v, z]` laid out as [`super::layout::StateLayout`] says: position coordinates
    /// (`(x, y, phi)` per planar body [m, rad]), velocity coordinates [m/s, rad/s],
    /// continuous element states (chamber pressures [Pa], ...).
    pub y: Vec<f64>,
    /// Discrete memory of each force element (`Model::forces` order).
    pub memory: Vec<ElementMemory>,
    /// Lengths of `q` and `v` in `y`.
    split: (usize, usize),
}

impl State {
    /// State of `model` at time `t` [s] with `y` laid out as its [`super::layout::StateLayout`]
    /// and every element's memory as at the start of a run.
    pub fn new(model: &super::Model, time: f64, y: Vec<f64>) -> Self {
        debug_assert_eq!(y.len(), model.layout.len());
        Self { time, y, memory: model.initial_memory(), split: (model.layout.nq, model.layout.nv) }
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
