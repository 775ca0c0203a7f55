//! Stage 4 of the pipeline: the simulation driver. The mechanism as the
//! integrators' ODE system, the run from a start to its end with samples,
//! events and step-end tracking, its progress and interruption, and the
//! diagnosis of a run that stops at a singular position. Imports every
//! lower stage.

pub(crate) mod progress;
pub(crate) mod simulate;
pub(crate) mod singular_diagnosis;
pub(crate) mod system;
