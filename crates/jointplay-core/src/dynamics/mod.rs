//! Multibody dynamics: from a checked model description to a recorded run,
//! one folder per stage of the pipeline, each importing only from the stages
//! before it (`layout_rules_tests.rs` checks it):
//!
//! 0. `model/`: the compiled [`Model`] (constant), its [`StateLayout`], the
//!    channels' definitions, the tree of ideal joints and the [`State`]
//!    (coordinates, velocities, element states and memory);
//! 1. `compiler/`: [`compile`], from a [`crate::spec::ModelSpec`] to a [`Model`];
//!    `formulations/`: the equations of motion in absolute coordinates with
//!    constraint equations or in joint coordinates, which of the two a run
//!    takes, and the [`Workspace`] (scratch reused every evaluation). The two
//!    folders of stage 1 do not import each other;
//! 2. `starts/`: consistent initial conditions ([`assemble`]) and static
//!    [`equilibrium`];
//! 3. `outputs/`: channel values, the [`Trajectory`] and the extrema;
//! 4. `simulation/`: the run ([`simulate`]), the integrators' ODE system and
//!    the [`Progress`] of a run.
//!
//! A file imports from its own folder (`super::`) or from a lower stage
//! (`crate::dynamics::<folder>::...`); the names below are the crate's
//! public interface, not a way between folders.

mod compiler;
mod formulations;
mod model;
mod outputs;
mod simulation;
mod starts;

pub use compiler::compile::compile;
pub use formulations::absolute::equations::{accelerations, update_frames, Stabilization};
pub use formulations::absolute::generalised_force::GeneralisedForces;
pub use formulations::absolute::redundancy::{constraint_rank, ConstraintRank};
pub use formulations::formulation_choice::{choose_formulation, FormulationChoice, MAX_JOINT_COORDINATES};
pub use formulations::joint_coordinates;
pub use formulations::joint_coordinates::{Formulation, JointTree};
pub use formulations::workspace::Workspace;
pub use model::channels::ChannelInfo;
pub use model::constraint_jacobian::{JacobianBlock, JacobianPattern, MarkerColumns};
pub use model::layout::{BodyAddress, StateLayout};
pub use model::mechanism::{Body, Model, SchurTerm, Section, StrainGauge, VelocityStart};
pub use model::state::{ContactMemory, State};
pub use outputs::extrema_summary::{ChannelPeak, Extrema, JointExtrema, PEAK_UNITS};
pub use outputs::trajectory::{SampleSink, Trajectory, CHUNK_BYTES};
pub use simulation::progress::Progress;
pub use simulation::simulate::{simulate, simulate_with_sink, Diagnostics, SimulationOptions, SimulationOutcome, PROJECTION_CEILING, PROJECTION_FLOOR, PROJECTION_SHARE};
pub use starts::assembly::assemble;
pub use starts::assembly_checks::{assembly_notes, AssemblyNote};
pub use starts::equilibrium::{equilibrium, Equilibrium, EquilibriumOptions};

#[cfg(test)]
pub(crate) use outputs::brent::maximize;
#[cfg(test)]
mod layout_rules_tests;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod element_tests;
#[cfg(test)]
mod beam_tests;
#[cfg(test)]
mod modal_tests;
#[cfg(test)]
mod modal_matrices_tests;
#[cfg(test)]
mod spatial_tests;
#[cfg(test)]
mod spatial_clearance_tests;
#[cfg(test)]
mod spatial_clearance_joint_tests;
