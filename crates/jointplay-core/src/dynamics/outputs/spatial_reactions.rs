//! Reactions of spatial joints and efforts of their drivers, from the
//! multipliers of their rows (`docs/theory/spatial-joints.md`, "Reactions").

use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::kinematics::spatial::Vec3;
use crate::kinematics::wrench::Wrench;

/// The wrench on the second body of spatial element `e` from the first, about
/// the second marker's point (global) [N, N m]: the loads `-Phi_q^T lambda` of
/// its rows on the second marker's body (on the first's, negated, when the
/// second is the ground).
pub(crate) fn reaction_wrench(model: &Model, e: usize, ws: &Workspace) -> Wrench {
    let element = model.ideal(e);
    let Some([_, second]) = element.spatial_markers.as_deref() else { return Wrench::default() };
    let frames = ws.frames();
    let (slot, sign) = if element.second.is_ground() { (0, -1.0) } else { (1, 1.0) };
    let about = frames.point(&second);
    let mut total = Wrench::default();
    for k in element.constraints.clone() {
        let rows = model.row_offsets[k]..model.row_offsets[k + 1];
        let load = model.constraints[k].kind.wrenches(&frames, &ws.multipliers[rows])[slot];
        let shifted = load.wrench.shifted(load.point, about);
        total.force += shifted.force * sign;
        total.moment += shifted.moment * sign;
    }
    total
}

/// The reaction channels of spatial joint `e` (see [`crate::joint::SPATIAL_REACTION_CHANNELS`]).
pub(crate) fn spatial_reactions(model: &Model, e: usize, ws: &Workspace) -> [f64; 13] {
    let w = reaction_wrench(model, e, ws);
    let local = match model.ideal(e).spatial_markers.as_deref() {
        Some([first, _]) => w.rotated(&ws.frames().marker_frame(first).rotation.transpose()),
        None => Wrench::default(),
    };
    let (f, m, lf, lm) = (w.force, w.moment, local.force, local.moment);
    [f.x, f.y, f.z, f.norm(), m.x, m.y, m.z, lf.x, lf.y, lf.z, lm.x, lm.y, lm.z]
}

/// The effort of spatial driver `e`: the reaction's moment about (angle
/// driver) or force along (displacement driver) the first marker's z axis [N m or N].
pub(crate) fn spatial_driver_effort(model: &Model, e: usize, ws: &Workspace, along_axis_moment: bool) -> f64 {
    let Some([first, _]) = model.ideal(e).spatial_markers.as_deref() else { return f64::NAN };
    let axis: Vec3 = ws.frames().axis(first, 2);
    let w = reaction_wrench(model, e, ws);
    if along_axis_moment { w.moment.dot(&axis) } else { w.force.dot(&axis) }
}
