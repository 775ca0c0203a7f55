//! Elements that act through forces, under one contract: springs and
//! dampers, prescribed loads, hydraulic cylinders and clearance joints.
//! Each adds its generalised force to `Q` through [`GeneralisedForces`]
//! (it never indexes coordinates) and declares its output channels. An
//! element may have continuous states (the cylinder's pressures: it reads
//! them and writes their rates), events located by the integrator with a
//! discrete memory changed only there and at accepted steps (the clearance
//! joint's contact onset and latched onset velocity), and scratch of its
//! own in the workspace (a Reynolds solver). Ideal joints are the other
//! kind of element: constraint rows ([`crate::joint::ConstraintKind`]).
//! Gravity is a body load (`crate::body`).

mod bushing;
mod hydraulic_cylinder;
mod point_force;
mod prescribed_load;
mod rotational_spring_damper;
mod spatial_spring_damper;
mod spring_damper;
mod torque;

pub use bushing::Bushing;
pub use hydraulic_cylinder::CylinderActuator;
pub use point_force::PointForce;
pub use prescribed_load::{LoadFrame, LoadKind, PrescribedLoad};
pub use rotational_spring_damper::RotationalSpringDamper;
pub use spatial_spring_damper::SpatialSpringDamper;
pub use spring_damper::SpringDamper;
pub use torque::AppliedTorque;

use crate::kinematics::marker::BodyIndex;
use crate::error::SimulationError;
use crate::joint::{ClearanceRevolute, ClearanceWork, ContactMemory};
use crate::kinematics::planar::Frame;
use crate::dynamics::GeneralisedForces;
use crate::kinematics::frames::Frames;

/// Most outputs a force element without its own evaluation record reports.
pub const MAX_OUTPUTS: usize = 7;

/// One output channel of an element: quantity, unit, description.
pub type OutputInfo = (&'static str, &'static str, &'static str);

/// Outputs of one force element at one evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ForceOutput {
    /// Values in the order of [`ForceElement::channels`] (the rest unused) [SI units].
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

/// Discrete memory of one element: changed only at its events and at accepted steps.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum ElementMemory {
    /// The element keeps none.
    #[default]
    None,
    /// A clearance joint's contact memory.
    Contact(ContactMemory),
}

impl ElementMemory {
    /// Contact onsets counted so far (0 for an element without contact).
    pub fn impacts(&self) -> usize {
        match self {
            Self::Contact(memory) => memory.impacts,
            Self::None => 0,
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
}

/// What an element reports when a step is accepted.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Acceptance {
    /// Whether its discrete memory changed (the evaluations at this state no longer hold).
    pub memory_changed: bool,
    /// Penetration depth of a contact [m] (0 without one).
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

/// Every kind of element that acts through forces.
#[derive(Clone, Debug)]
pub enum ForceElement {
    /// Linear translational spring-damper between two points.
    SpringDamper(SpringDamper),
    /// Linear torsional spring-damper between two bodies.
    RotationalSpringDamper(RotationalSpringDamper),
    /// Prescribed force at a point.
    PointForce(PointForce),
    /// Prescribed torque on a body.
    Torque(AppliedTorque),
    /// Hydraulic cylinder between two markers, with its chamber pressures as states.
    HydraulicCylinder(CylinderActuator),
    /// Revolute joint with radial clearance (dry contact, optional film), with its contact onset as event.
    ClearanceRevolute(ClearanceRevolute),
    /// Linear spring-damper between two points in space (the spatial elements
    /// are boxed, so that planar ones stay small in the element list).
    SpatialSpringDamper(Box<SpatialSpringDamper>),
    /// Six-component spring-damper between two marker frames.
    Bushing(Box<Bushing>),
    /// Prescribed force or torque in space.
    PrescribedLoad(Box<PrescribedLoad>),
}

impl ForceElement {
    /// Output channels: quantity, unit, description, in the order [`Self::output`] reads them.
    pub fn channels(&self) -> &'static [OutputInfo] {
        match self {
            Self::SpringDamper(_) => &SpringDamper::CHANNELS,
            Self::RotationalSpringDamper(_) => &RotationalSpringDamper::CHANNELS,
            Self::PointForce(_) => &PointForce::CHANNELS,
            Self::Torque(_) => &AppliedTorque::CHANNELS,
            Self::HydraulicCylinder(_) => &CylinderActuator::CHANNELS,
            Self::ClearanceRevolute(e) => e.channels(),
            Self::SpatialSpringDamper(_) => &SpatialSpringDamper::CHANNELS,
            Self::Bushing(_) => &Bushing::CHANNELS,
            Self::PrescribedLoad(e) => e.channels(),
        }
    }

    /// Number of continuous states.
    pub fn n_states(&self) -> usize {
        match self {
            Self::HydraulicCylinder(e) => e.cylinder.n_states(),
            _ => 0,
        }
    }

    /// The continuous states at rest in the placement `frames`, from the states
    /// `reference` at the placement `reference_frames` (a static analysis): a
    /// cylinder's chambers closed, its pressures following their volumes.
    pub fn static_states(&self, reference_frames: &Frames<'_>, frames: &Frames<'_>, reference: &[f64], z: &mut [f64]) {
        match self {
            Self::HydraulicCylinder(e) => e.closed_states(reference_frames, frames, reference, z),
            _ => z.copy_from_slice(reference),
        }
    }

    /// Number of event functions (located by the integrator where they cross zero upwards).
    pub fn n_events(&self) -> usize {
        match self {
            Self::ClearanceRevolute(_) => 1,
            _ => 0,
        }
    }

    /// The bodies the event functions read (none without events).
    pub fn event_bodies(&self) -> Vec<BodyIndex> {
        match self {
            Self::ClearanceRevolute(e) => e.event_bodies().to_vec(),
            _ => Vec::new(),
        }
    }

    /// Discrete memory at the start of a run.
    pub fn new_memory(&self) -> ElementMemory {
        match self {
            Self::ClearanceRevolute(_) => ElementMemory::Contact(ContactMemory::default()),
            _ => ElementMemory::None,
        }
    }

    /// Scratch and last-evaluation record for the workspace.
    pub fn new_work(&self) -> ElementWork {
        match self {
            Self::ClearanceRevolute(e) => ElementWork::Clearance(Box::new(e.new_work())),
            _ => ElementWork::Outputs(ForceOutput::default()),
        }
    }

    /// Adds the element's generalised force to `forces` and writes the rates
    /// of its states `z` into `z_rate`, reading its `memory`; keeps what its
    /// channels read in `work`; `detailed` asks for outputs only recorded samples need.
    #[allow(clippy::too_many_arguments)]
    pub fn apply(
        &self,
        frames: &Frames<'_>,
        t: f64,
        (z, z_rate): (&[f64], &mut [f64]),
        memory: &ElementMemory,
        work: &mut ElementWork,
        detailed: bool,
        forces: &mut GeneralisedForces,
    ) -> Result<(), ElementFault> {
        let output = match (self, memory, work) {
            (Self::ClearanceRevolute(e), ElementMemory::Contact(memory), ElementWork::Clearance(work)) => {
                return e.apply_element(frames.planar, memory, work, detailed, forces);
            }
            (_, _, ElementWork::Outputs(output)) => output,
            _ => unreachable!("an element's memory and work are made by its own kind"),
        };
        *output = match self {
            Self::SpringDamper(e) => e.apply(frames.planar, forces),
            Self::RotationalSpringDamper(e) => e.apply(frames.planar, forces),
            Self::PointForce(e) => e.apply(frames.planar, t, forces),
            Self::Torque(e) => e.apply(t, forces),
            Self::HydraulicCylinder(e) => e.apply(frames, t, z, z_rate, forces),
            Self::SpatialSpringDamper(e) => e.apply(frames, forces),
            Self::Bushing(e) => e.apply(frames, forces),
            Self::PrescribedLoad(e) => e.apply(frames, t, forces),
            Self::ClearanceRevolute(_) => unreachable!("handled above"),
        };
        Ok(())
    }

    /// Completes the last evaluation with the outputs only recorded samples need.
    pub fn detail(&self, frames: &[Frame], work: &mut ElementWork) -> Result<(), ElementFault> {
        match (self, work) {
            (Self::ClearanceRevolute(e), ElementWork::Clearance(work)) => e.detail(frames, work),
            _ => Ok(()),
        }
    }

    /// Whether [`Self::detail`] adds anything.
    pub fn has_detailed_outputs(&self) -> bool {
        matches!(self, Self::ClearanceRevolute(e) if e.lubrication.is_some())
    }

    /// Outputs `which` (indices into [`ForceElement::channels`]) of the last evaluation into `out` (one each) [SI units].
    pub fn outputs(&self, which: std::ops::Range<usize>, frames: &[Frame], work: &ElementWork, out: &mut [f64]) {
        match (self, work) {
            (Self::ClearanceRevolute(e), ElementWork::Clearance(work)) => out.copy_from_slice(&e.outputs(frames, work)[which]),
            (_, ElementWork::Outputs(output)) => out.copy_from_slice(&output.values[which]),
            _ => out.fill(f64::NAN),
        }
    }

    /// Value of channel `which` from the last evaluation in `work` [SI units].
    pub fn output(&self, which: usize, frames: &[Frame], work: &ElementWork) -> f64 {
        match (self, work) {
            (Self::ClearanceRevolute(e), ElementWork::Clearance(work)) => e.output(which, frames, work),
            (_, ElementWork::Outputs(output)) => output.values[which],
            _ => f64::NAN,
        }
    }

    /// Potential energy stored at the last evaluation [J] (0 for non-conservative loads).
    pub fn potential_energy(&self, work: &ElementWork) -> f64 {
        match (self, work) {
            (Self::ClearanceRevolute(e), ElementWork::Clearance(work)) => e.potential_energy(work),
            (_, ElementWork::Outputs(output)) => output.potential_energy,
            _ => 0.0,
        }
    }

    /// Whether the last evaluation's outputs are finite.
    pub fn outputs_finite(work: &ElementWork) -> bool {
        match work {
            ElementWork::Clearance(work) => ClearanceRevolute::outputs_finite(work),
            ElementWork::Outputs(output) => output.values.iter().all(|v| v.is_finite()),
        }
    }

    /// Event functions `g` at `frames` (`rates`: their time derivatives, when asked).
    pub fn event_functions(&self, frames: &[Frame], g: &mut [f64], rates: Option<&mut [f64]>) {
        if let Self::ClearanceRevolute(e) = self {
            g[0] = e.penetration(frames);
            if let Some(rates) = rates {
                rates[0] = e.penetration_rate(frames);
            }
        }
    }

    /// Event `event` (of this element's) was located at `frames`: updates the memory.
    pub fn on_event(&self, frames: &[Frame], _event: usize, memory: &mut ElementMemory) {
        if let (Self::ClearanceRevolute(e), ElementMemory::Contact(memory)) = (self, memory) {
            e.on_event(frames, memory);
        }
    }

    /// A step ending at `frames` was accepted: updates the memory and checks the element's bounds.
    pub fn accept(&self, frames: &[Frame], memory: &mut ElementMemory) -> Result<Acceptance, ElementFault> {
        match (self, memory) {
            (Self::ClearanceRevolute(e), ElementMemory::Contact(memory)) => e.accept(frames, memory),
            _ => Ok(Acceptance::default()),
        }
    }

    /// Why the state is outside the range of the element's law, if it is.
    pub fn check(&self, frames: &Frames<'_>, z: &[f64]) -> Result<(), ElementFault> {
        match self {
            Self::HydraulicCylinder(e) => e.check(frames, z).map_err(|fault| ElementFault::OutOfRange(fault.to_string())),
            _ => Ok(()),
        }
    }

    /// Absolute-tolerance scales of the states (see `OdeSystem::absolute_tolerance_scales`).
    pub fn tolerance_scales(&self, scales: &mut [f64]) {
        if let Self::HydraulicCylinder(e) = self {
            e.tolerance_scales(scales);
        }
    }
}
