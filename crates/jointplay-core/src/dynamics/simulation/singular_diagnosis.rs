//! Why a run stopped, when the cause is the linkage's position rather than a
//! contact law or a step size: a driver that pushes the linkage through a
//! toggle (singular) position, where the driven coordinate no longer moves it,
//! makes a clearance joint take the driver's effort, and its penetration or
//! the step size runs away there.

use crate::dynamics::starts::assembly_checks::significant;
use crate::dynamics::starts::conditioning::relative_smallest_singular_value;
use crate::joint::IdealKind;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::error::SimulationError;

/// Smallest singular value of the equilibrated constraint Jacobian (clearance
/// joints locked where they are), relative to the largest, below which the
/// linkage is at a toggle position [-]: about 4 deg from the dead centre of a
/// slider-crank (the value falls linearly with the angle; the test's slider-crank
/// has 6e-3 at 1.2 deg and 0.28 with its crank at 90 deg). It is looked at only
/// once a run has stopped.
pub const TOGGLE_RATIO: f64 = 2e-2;

/// How much larger that value must be without a driver's equation for the driver
/// to be the one pushing the linkage through the position [-].
const DRIVER_GAIN: f64 = 10.0;

/// `error` restated when, at the last accepted positions `q` (time `t`), a driver holds the
/// linkage at a toggle position: a penetration beyond its bound, a step size underflow or
/// equations that could not be kept there follow from the position, not from a soft
/// contact, a large step or a tolerance.
pub(crate) fn diagnose_toggle(model: &Model, error: SimulationError, t0: f64, t: f64, q: &[f64], ws: &mut Workspace) -> SimulationError {
    let stopped = match &error {
        SimulationError::ExcessivePenetration { .. } | SimulationError::StepSizeUnderflow { .. } | SimulationError::ConstraintViolation { .. } => error.time() > t0,
        _ => false,
    };
    if !stopped {
        return error;
    }
    let consequence = if model.clearance_joints().next().is_some() { "the clearance joints take the driver's effort" } else { "the joints cannot follow the driver" };
    let all = model.constraints.len();
    let with = relative_smallest_singular_value(model, all, t, q, None, ws);
    if with >= TOGGLE_RATIO {
        return error;
    }
    let drivers = model.ideal_elements().filter(|(_, e)| matches!(e.kind, IdealKind::AngleDriver | IdealKind::DisplacementDriver));
    for (k, _) in drivers {
        let without = relative_smallest_singular_value(model, all, t, q, Some(k), ws);
        if without > DRIVER_GAIN * with {
            return SimulationError::SingularConfiguration {
                time: error.time(),
                element: model.elements[k].name.clone(),
                cause: format!(
                    "the driver pushes the linkage through a toggle (singular) position at t = {} s: there the driven coordinate no longer moves the linkage (the smallest singular value of the joints' and drivers' equations, with the clearance joints held where they are, is {:.2e} of the largest, {:.2e} without this driver), so {}: {}; check the driver's range of motion (a crank-rocker driven at its rocker, a slider driven beyond its dead centre) or drive another joint",
                    significant(t),
                    with,
                    without,
                    consequence,
                    what_stopped(&error)
                ),
            };
        }
    }
    error
}

/// What stopped the run, without the generic advice of its message.
fn what_stopped(error: &SimulationError) -> String {
    match error {
        SimulationError::ExcessivePenetration { element, penetration, bound, .. } => {
            format!("the penetration in {element} reached {} mm, beyond its bound {} mm", significant(penetration * 1e3), significant(bound * 1e3))
        }
        SimulationError::StepSizeUnderflow { step, .. } => format!("the step size fell to {step:.3e} s"),
        SimulationError::ConstraintViolation { element, residual, .. } => format!("the joints' equations could not be kept (residual {residual:.3e} in {element})"),
        other => other.to_string(),
    }
}

#[cfg(test)]
#[path = "singular_diagnosis_tests.rs"]
mod tests;
