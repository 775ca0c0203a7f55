//! Multibody dynamics in absolute coordinates: the compiled [`Model`]
//! (constant), the [`State`] (coordinates, velocities, contact memory), the
//! [`Workspace`] (scratch reused every evaluation), the equations of motion,
//! assembly of consistent initial conditions, drift projection, and the
//! simulation loop that produces a [`Trajectory`].

mod assembly;
mod assembly_checks;
mod equilibrium;
mod quasi_static_start;
mod rigid_motion_start;
mod brent;
mod channels;
mod compile;
mod conditioning;
mod constraint_jacobian;
mod constraint_solution;
mod equations;
mod extrema;
mod extrema_summary;
mod formulation_choice;
mod generalised_force;
mod jacobian;
pub mod joint_coordinates;
mod layout;
mod model;
mod newton_parts;
mod progress;
mod projection;
mod redundancy;
mod rigid_placement;
mod simulate;
mod singular_diagnosis;
mod spatial_reactions;
mod state;
mod system;
mod trajectory;
mod workspace;

pub use assembly::assemble;
pub use assembly_checks::{assembly_notes, AssemblyNote};
pub use equilibrium::{equilibrium, Equilibrium, EquilibriumOptions};
pub use channels::ChannelInfo;
pub use compile::compile;
pub use constraint_jacobian::{JacobianBlock, JacobianPattern, MarkerColumns};
pub use formulation_choice::{choose_formulation, FormulationChoice, MAX_JOINT_COORDINATES};
pub use generalised_force::GeneralisedForces;
pub use joint_coordinates::{Formulation, JointTree};
pub use layout::{BodyAddress, StateLayout};
pub use extrema_summary::{ChannelPeak, Extrema, JointExtrema, PEAK_UNITS};
pub use equations::{accelerations, update_frames, Stabilization};
pub use model::{Body, Model, SchurTerm, Section, StrainGauge, VelocityStart};
pub use progress::Progress;
pub use redundancy::{constraint_rank, ConstraintRank};
pub use simulate::{simulate, simulate_with_sink, Diagnostics, SimulationOptions, SimulationOutcome, PROJECTION_CEILING, PROJECTION_FLOOR, PROJECTION_SHARE};
pub use state::{ContactMemory, State};
pub use trajectory::{SampleSink, Trajectory, CHUNK_BYTES};
pub use workspace::Workspace;

#[cfg(test)]
pub(crate) use brent::maximize;
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
mod jacobian_tests;
#[cfg(test)]
mod newton_parts_tests;
#[cfg(test)]
mod spatial_tests;
#[cfg(test)]
mod spatial_clearance_tests;
