//! Which form of the equations of motion a run integrates, and why: the rule
//! of `Formulation::Auto`, written once here from measurements
//! (`docs/theory/planar-formulation.md`, "Choosing the formulation";
//! `benches/bench_scaling.py`).
//!
//! Joint coordinates remove the constraint equations of a tree of ideal joints,
//! but their mass matrix `R^T M R` is dense: forming it costs `nv n^2` and its
//! `L D L^T` `n^3 / 3` for `n` joint coordinates, where the absolute formulation's
//! sparse constraint solution grows linearly with the bodies. They pay only for a
//! small tree that has ideal joints to remove.

use super::joint_coordinates::{Formulation, JointTree};
use crate::dynamics::model::mechanism::Model;
use crate::body::BodyKind;

/// Most joint coordinates for which `auto` takes joint coordinates: the largest
/// tree where they were faster in every round of the long runs (0.71-0.80 at 8;
/// at 10 up to 1.02) and no slower in the short ones (medians 0.96-1.01 at 8 over
/// four runs). Measured (CPU medians of interleaved rounds,
/// `benches/bench_scaling.py --series rigid_chain --sizes ... --chain-time T`: a
/// chain of bars pinned end to end, falling, Dormand-Prince), joint over absolute
/// time over 1 s (9 rounds): 0.60 at 2 coordinates, 0.50 at 4, 0.71 at 6, 0.78 at
/// 8, 0.91 at 10, 1.03 at 12, 1.35 at 16; over 0.1 s (15 rounds), where the
/// per-run costs weigh more: 0.87 at 2, 0.76 at 4, 0.90 at 6, 0.96 at 8, 0.99 at
/// 10, 1.23 at 12, 1.65 at 16.
pub const MAX_JOINT_COORDINATES: usize = 8;

/// The formulation a run integrates and a one-line reason for it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FormulationChoice {
    /// `Absolute` or `JointCoordinates` (never `Auto`).
    pub formulation: Formulation,
    /// Why, in one line (shown by `jointplay check` and kept in the results).
    pub reason: String,
}

impl FormulationChoice {
    fn absolute(reason: String) -> Self {
        Self { formulation: Formulation::Absolute, reason }
    }
}

/// The formulation `requested` resolves to for `model`: `Auto` by the measured
/// rule (flexible bodies, loops of ideal joints, no ideal joint to remove, size),
/// the others as asked. `Err`: joint coordinates were asked for a model without a
/// tree of ideal joints (the reason).
pub fn choose_formulation(model: &Model, requested: Formulation) -> Result<FormulationChoice, String> {
    match requested {
        Formulation::Absolute => Ok(FormulationChoice::absolute("requested".to_string())),
        Formulation::JointCoordinates => match &model.joint_tree {
            Ok(tree) => Ok(FormulationChoice { formulation: Formulation::JointCoordinates, reason: format!("requested ({} joint coordinates)", tree.n_dofs) }),
            Err(why) => Err(why.clone()),
        },
        Formulation::Auto => Ok(automatic(model)),
    }
}

/// The rule of `Formulation::Auto`.
fn automatic(model: &Model) -> FormulationChoice {
    if model.spatial {
        // (the tree's reason: spatial models run in absolute coordinates)
        return FormulationChoice::absolute(model.joint_tree.as_ref().err().cloned().unwrap_or_default());
    }
    if let Some(body) = model.bodies.iter().find(|b| !matches!(b.kind, BodyKind::PlanarRigid(_))) {
        return FormulationChoice::absolute(format!("body {:?} is flexible (joint coordinates hold rigid bodies only)", body.name));
    }
    let tree = match &model.joint_tree {
        Ok(tree) => tree,
        Err(why) => return FormulationChoice::absolute(why.clone()),
    };
    if removes_no_constraint(tree) {
        return FormulationChoice::absolute(
            "no ideal joint to remove (every body is held by clearance joints or forces only), so joint coordinates would only add a dense mass matrix".to_string(),
        );
    }
    if tree.n_dofs > MAX_JOINT_COORDINATES {
        return FormulationChoice::absolute(format!(
            "the tree has {} joint coordinates, more than {MAX_JOINT_COORDINATES}, where its dense mass matrix costs more than the constraints it removes",
            tree.n_dofs
        ));
    }
    FormulationChoice {
        formulation: Formulation::JointCoordinates,
        reason: format!("the ideal joints form a tree of {} joint coordinates (at most {MAX_JOINT_COORDINATES}), so no constraint equation is solved", tree.n_dofs),
    }
}

/// Whether the tree holds no body by an ideal joint (every edge is a free body).
fn removes_no_constraint(tree: &JointTree) -> bool {
    tree.edges.iter().all(|edge| edge.joint_element.is_none())
}

#[cfg(test)]
#[path = "formulation_choice_tests.rs"]
mod tests;
