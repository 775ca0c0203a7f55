//! Stage 2 of the pipeline: consistent initial conditions. Assembly of
//! positions and velocities that satisfy the constraints, the checks and
//! diagnostics of a start that fails (the conditioning of the constraint
//! equations), a rigid placement of the bodies, starts in rigid-body motion
//! and quasi-statically strained, and static equilibrium. Imports `model/`
//! and `formulations/`.

pub(crate) mod assembly;
pub(crate) mod assembly_checks;
pub(crate) mod conditioning;
pub(crate) mod equilibrium;
pub(crate) mod quasi_static_start;
pub(crate) mod rigid_motion_start;
pub(crate) mod rigid_placement;
