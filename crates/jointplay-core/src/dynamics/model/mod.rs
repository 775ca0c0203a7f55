//! Stage 0 of the pipeline: what a compiled mechanism is and the state it
//! evolves. The [`mechanism::Model`] (bodies, elements, markers, channels;
//! constant once compiled), where each body's coordinates sit in the state
//! vector ([`layout::StateLayout`]), the sparsity pattern of the constraint
//! Jacobian, the channels' definitions and the plan by which a sample reads
//! them, the tree of ideal joints, and the [`state::State`]. Imports nothing
//! else of `dynamics/`.

pub(crate) mod channels;
pub(crate) mod constraint_jacobian;
pub(crate) mod joint_tree;
pub(crate) mod layout;
pub(crate) mod mechanism;
pub(crate) mod state;

// names that mechanism.rs and state.rs reach one level up, in this module
use channels::ChannelInfo;
use mechanism::Model;
