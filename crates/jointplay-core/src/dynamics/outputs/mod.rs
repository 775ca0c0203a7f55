//! Stage 3 of the pipeline: what a run reports. The values of the channels
//! at a sample (spatial reaction wrenches among them), the recorded
//! [`trajectory::Trajectory`], and the extrema of the channels between
//! samples (Chebyshev fits of the dense output, Brent's method for the
//! peak). Imports `model/` and `formulations/`.

pub(crate) mod brent;
pub(crate) mod channel_values;
pub(crate) mod extrema;
pub(crate) mod extrema_summary;
pub(crate) mod spatial_reactions;
pub(crate) mod trajectory;
