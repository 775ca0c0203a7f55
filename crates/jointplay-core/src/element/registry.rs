//! The list of element kinds: `elements!` defines [`ElementKind`], one
//! variant per kind, and its [`ElementModel`], forwarding every method of
//! the contract to the kind's own. A new element is a file with its type and
//! its `impl ElementModel`, and one line here.

use std::ops::Range;

use super::contract::{Acceptance, ElementFault, ElementMemory, ElementModel, ElementWork, OutputInfo};
use crate::dynamics::GeneralisedForces;
use crate::force::{AppliedTorque, Bushing, CylinderActuator, PointForce, PrescribedLoad, RotationalSpringDamper, SpatialSpringDamper, SpringDamper};
use crate::joint::{ClearanceRevolute, IdealElement, SpatialClearanceRevolute};
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::{BodyIndex, Marker};
use crate::kinematics::planar::Frame;

/// The list of element kinds: defines [`ElementKind`] with one variant per
/// kind and its [`ElementModel`], forwarding every method to the kind's own.
macro_rules! elements {
    ($($(#[$doc:meta])* $kind:ident($element:ty)),+ $(,)?) => {
        /// Every kind of element.
        #[derive(Clone, Debug)]
        pub enum ElementKind {
            $($(#[$doc])* $kind($element),)+
        }

        impl ElementModel for ElementKind {
            crate::dispatch::forward! { [$($kind)+];
                fn channels(&self) -> &'static [OutputInfo];
                fn markers(&self) -> Vec<Marker>;
                fn constraints(&self) -> Range<usize>;
                #[inline] fn acts_through_forces(&self) -> bool;
                fn n_states(&self) -> usize;
                fn n_events(&self) -> usize;
                fn n_memory_slots(&self) -> usize;
                fn event_bodies(&self) -> Vec<BodyIndex>;
                fn start_memory(&self, memory: &mut [ElementMemory]);
                fn new_work(&self) -> ElementWork;
                #[inline] fn apply(&self, frames: &Frames<'_>, t: f64, states: (&[f64], &mut [f64]), memory: &[ElementMemory], work: &mut ElementWork, detailed: bool, forces: &mut GeneralisedForces) -> Result<(), ElementFault>;
                fn static_states(&self, reference_frames: &Frames<'_>, frames: &Frames<'_>, reference: &[f64], z: &mut [f64]);
                fn detail(&self, frames: &[Frame], work: &mut ElementWork) -> Result<(), ElementFault>;
                fn has_detailed_outputs(&self) -> bool;
                fn outputs(&self, which: Range<usize>, frames: &[Frame], work: &ElementWork, out: &mut [f64]);
                fn output(&self, which: usize, frames: &[Frame], work: &ElementWork) -> f64;
                fn potential_energy(&self, work: &ElementWork) -> f64;
                #[inline] fn event_functions(&self, frames: &Frames<'_>, g: &mut [f64], rates: Option<&mut [f64]>);
                fn on_event(&self, frames: &Frames<'_>, t: f64, event: usize, memory: &mut [ElementMemory]);
                #[inline] fn accept(&self, frames: &Frames<'_>, t: f64, memory: &mut [ElementMemory]) -> Result<Acceptance, ElementFault>;
                fn check(&self, frames: &Frames<'_>, z: &[f64]) -> Result<(), ElementFault>;
                fn tolerance_scales(&self, scales: &mut [f64]);
            }
        }
    };
}

elements! {
    /// Ideal joint, driver or assembly lock: constraint equations only.
    Ideal(IdealElement),
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
    /// Revolute joint with radial and axial clearance in space, with its four contact candidates' onsets as events.
    SpatialClearanceRevolute(Box<SpatialClearanceRevolute>),
}
