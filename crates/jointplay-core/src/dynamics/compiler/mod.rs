//! Stage 1 of the pipeline: compiling a checked [`crate::spec::ModelSpec`]
//! into the constant [`crate::dynamics::model::mechanism::Model`]. Imports
//! only `model/`.

pub(crate) mod compile;
