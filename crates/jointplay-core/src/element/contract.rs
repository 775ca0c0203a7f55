//! The element contract: what every element (ideal joint, driver, force
//! element, clearance joint) declares and does, as one trait with defaults,
//! so an element states only what it has.
//!
//! An element declares its output channels, the constraint equations it owns
//! (compiled into [`crate::joint::ConstraintKind`] primitives), its continuous
//! states `z`, its event functions and its discrete memory slots, a variable
//! number of each: a spatial clearance joint has several contact candidates,
//! each with its own event and onset memory. Its behaviour: the generalised
//! forces it applies ([`GeneralisedForces`]: it never indexes coordinates),
//! its states' rates, its event functions, what happens at an event and at an
//! accepted step (only there its memory changes), and the outputs of its last
//! evaluation.

use std::ops::Range;

use crate::dynamics::GeneralisedForces;
use crate::error::SimulationError;
use crate::joint::{ClearanceWork, ContactMemory, ModeTally, SpatialClearanceWork};
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::{BodyIndex, Marker};
use crate::kinematics::planar::Frame;

/// Most outputs an element without its own evaluation record reports.
pub const MAX_OUTPUTS: usize = 7;

/// One output channel of an element: quantity, unit, description.
pub type OutputInfo = (&'static str, &'static str, &'static str);

/// Outputs of one element at one evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ForceOutput {
    /// Values in the order of [`ElementModel::channels`] (the rest unused) [SI units].
    pub values: [f64; MAX_OUTPUTS],
    /// Potential energy stored [J] (0 for non-conservative loads).
    pub potential_energy: f64,
}

impl ForceOutput {
    /// Outputs `values` (the first of them, in channel order) and `potential_energy` [J].
    pub fn new(values: &[f64], potential_energy: f64) -> Self {
        let mut all = [0.0; MAX_OUTPUTS];
        all[..values.len()].copy_from_slice(values);
        Self { values: all, potential_energy }
    }
}

/// One slot of an element's discrete memory: changed only at its events and at accepted steps.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum ElementMemory {
    /// An empty slot.
    #[default]
    None,
    /// A contact's memory (its latched onset velocity and impact count).
    Contact(ContactMemory),
    /// The time a joint spent in each motion mode, and its radial contact under way.
    Modes(ModeTally),
}

impl ElementMemory {
    /// Contact onsets counted so far in this slot (0 without a contact).
    pub fn impacts(&self) -> usize {
        match self {
            Self::Contact(memory) => memory.impacts,
            Self::Modes(_) | Self::None => 0,
        }
    }
}

/// Last evaluation of one element (what its channels read) and the scratch it needs, in the workspace.
#[derive(Clone, Debug)]
pub enum ElementWork {
    /// Outputs computed at each evaluation.
    Outputs(ForceOutput),
    /// A clearance joint's contact and film evaluations and film solver.
    Clearance(Box<ClearanceWork>),
    /// A spatial clearance joint's candidates, load and measures.
    SpatialClearance(Box<SpatialClearanceWork>),
}

impl ElementWork {
    /// The outputs record of an element that keeps one.
    #[inline]
    pub fn outputs_mut(&mut self) -> &mut ForceOutput {
        match self {
            Self::Outputs(output) => output,
            Self::Clearance(_) | Self::SpatialClearance(_) => unreachable!("an element's work is made by its own kind"),
        }
    }

    /// Whether the last evaluation's outputs are finite.
    pub fn is_finite(&self) -> bool {
        match self {
            Self::Clearance(work) => work.forces_finite(),
            Self::SpatialClearance(work) => work.forces_finite(),
            Self::Outputs(output) => output.values.iter().all(|v| v.is_finite()),
        }
    }
}

/// What an element reports when a step is accepted.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Acceptance {
    /// Whether its discrete memory changed (the evaluations at this state no longer hold).
    pub memory_changed: bool,
    /// Deepest penetration of its contacts [m] (0 without one).
    pub penetration: f64,
    /// Whether that penetration is deep for the element (a hint that the contact is soft).
    pub deep_penetration: bool,
}

/// Why an element cannot go on.
#[derive(Clone, Debug, PartialEq)]
pub enum ElementFault {
    /// Its film model failed.
    Film(String),
    /// A contact penetrated beyond its bound [m].
    ExcessivePenetration {
        /// Penetration depth [m].
        penetration: f64,
        /// The bound [m].
        bound: f64,
    },
    /// Its state left the range where its law holds.
    OutOfRange(String),
}

impl ElementFault {
    /// The simulation error at time `time` [s] for the element named `element`.
    pub fn at(self, time: f64, element: &str) -> SimulationError {
        let element = element.to_string();
        match self {
            Self::Film(cause) => SimulationError::FilmModel { time, element, cause },
            Self::ExcessivePenetration { penetration, bound } => SimulationError::ExcessivePenetration { time, element, penetration, bound },
            Self::OutOfRange(cause) => SimulationError::ElementOutOfRange { time, element, cause },
        }
    }
}

/// The contract of every element. Declarations first (sizes are fixed at
/// compile time), then the behaviour; every method but [`Self::channels`]
/// has the default of an element without that part.
pub trait ElementModel {
    /// Output channels: quantity, unit, description, in the order [`Self::outputs`] reads them.
    fn channels(&self) -> &'static [OutputInfo];

    /// The markers it acts at, as planar markers (a spatial marker's body and
    /// frame; the ground's included): the coordinates its forces read and write.
    fn markers(&self) -> Vec<Marker> {
        Vec::new()
    }

    /// The constraint equations it owns (indices into `Model::constraints`; none for a force element).
    fn constraints(&self) -> Range<usize> {
        0..0
    }

    /// Whether it acts through generalised forces (an ideal joint acts only through its constraints).
    fn acts_through_forces(&self) -> bool {
        true
    }

    /// Number of continuous states (in `z`).
    fn n_states(&self) -> usize {
        0
    }

    /// Number of event functions (located by the integrator where they cross zero upwards).
    fn n_events(&self) -> usize {
        0
    }

    /// Number of discrete memory slots.
    fn n_memory_slots(&self) -> usize {
        0
    }

    /// The bodies the event functions read (none without events).
    fn event_bodies(&self) -> Vec<BodyIndex> {
        Vec::new()
    }

    /// Fills its memory slots (`n_memory_slots` of them) for the start of a run.
    fn start_memory(&self, _memory: &mut [ElementMemory]) {}

    /// Scratch and last-evaluation record for the workspace.
    fn new_work(&self) -> ElementWork {
        ElementWork::Outputs(ForceOutput::default())
    }

    /// Adds its generalised force to `forces` and writes the rates of its
    /// states `z` into `z_rate`, reading its `memory` slots; keeps what its
    /// channels read in `work`; `detailed` asks for outputs only recorded samples need.
    #[allow(clippy::too_many_arguments)]
    fn apply(
        &self,
        _frames: &Frames<'_>,
        _t: f64,
        _states: (&[f64], &mut [f64]),
        _memory: &[ElementMemory],
        _work: &mut ElementWork,
        _detailed: bool,
        _forces: &mut GeneralisedForces,
    ) -> Result<(), ElementFault> {
        Ok(())
    }

    /// The continuous states at rest in the placement `frames`, from the states
    /// `reference` at the placement `reference_frames` (a static analysis).
    fn static_states(&self, _reference_frames: &Frames<'_>, _frames: &Frames<'_>, reference: &[f64], z: &mut [f64]) {
        z.copy_from_slice(reference);
    }

    /// Completes the last evaluation with the outputs only recorded samples need.
    fn detail(&self, _frames: &[Frame], _work: &mut ElementWork) -> Result<(), ElementFault> {
        Ok(())
    }

    /// Whether [`Self::detail`] adds anything.
    fn has_detailed_outputs(&self) -> bool {
        false
    }

    /// Outputs `which` (indices into [`Self::channels`]) of the last evaluation into `out` (one each) [SI units].
    fn outputs(&self, which: Range<usize>, _frames: &[Frame], work: &ElementWork, out: &mut [f64]) {
        match work {
            ElementWork::Outputs(output) => out.copy_from_slice(&output.values[which]),
            ElementWork::Clearance(_) | ElementWork::SpatialClearance(_) => out.fill(f64::NAN),
        }
    }

    /// Value of channel `which` from the last evaluation in `work` [SI units].
    fn output(&self, which: usize, _frames: &[Frame], work: &ElementWork) -> f64 {
        match work {
            ElementWork::Outputs(output) => output.values[which],
            ElementWork::Clearance(_) | ElementWork::SpatialClearance(_) => f64::NAN,
        }
    }

    /// Potential energy stored at the last evaluation [J] (0 for non-conservative loads).
    fn potential_energy(&self, work: &ElementWork) -> f64 {
        match work {
            ElementWork::Outputs(output) => output.potential_energy,
            ElementWork::Clearance(_) | ElementWork::SpatialClearance(_) => 0.0,
        }
    }

    /// Event functions `g` at `frames` (`rates`: their time derivatives, when asked).
    fn event_functions(&self, _frames: &Frames<'_>, _g: &mut [f64], _rates: Option<&mut [f64]>) {}

    /// Event `event` (of this element's) was located at `frames`, time `t` [s]: updates its memory slots.
    fn on_event(&self, _frames: &Frames<'_>, _t: f64, _event: usize, _memory: &mut [ElementMemory]) {}

    /// A step ending at `frames`, time `t` [s], was accepted: updates its memory slots and checks its bounds.
    fn accept(&self, _frames: &Frames<'_>, _t: f64, _memory: &mut [ElementMemory]) -> Result<Acceptance, ElementFault> {
        Ok(Acceptance::default())
    }

    /// Why the state is outside the range of its law, if it is.
    fn check(&self, _frames: &Frames<'_>, _z: &[f64]) -> Result<(), ElementFault> {
        Ok(())
    }

    /// Absolute-tolerance scales of its states (see `OdeSystem::absolute_tolerance_scales`).
    fn tolerance_scales(&self, _scales: &mut [f64]) {}
}
