//! Stage 1 of the pipeline: the equations of motion of a compiled model, in
//! absolute coordinates with constraint equations (`absolute/`) or in the
//! joint coordinates of a tree of ideal joints (`joint_coordinates/`), which
//! of the two a run takes, and the [`workspace::Workspace`] every evaluation
//! writes its intermediate results to. Imports only `model/`.

pub(crate) mod absolute;
pub(crate) mod formulation_choice;
pub mod joint_coordinates;
pub(crate) mod workspace;

// the constraint solution as workspace.rs names it, one level up, in this module
use absolute::constraint_solution;
