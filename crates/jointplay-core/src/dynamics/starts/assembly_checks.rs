//! What assembly did to the description, checked and told: a flexible body
//! strained far beyond any elastic link to close a loop, or a journal started
//! deep inside its bearing, is refused, as a loop that a rigid link cannot close
//! is; a body moved far from its given place, a driver whose start value
//! contradicts the given positions and a flexible body strained noticeably are
//! noted (docs/model-files.md, "How a run starts"); a failed assembly says
//! whether the joints lock the mechanism or the masses make its equations too
//! ill-conditioned to solve ([`super::conditioning`]).

use super::assembly::ASSEMBLY_TOLERANCE;
use crate::dynamics::formulations::absolute::equations::{constraint_residuals, update_frames};
use crate::dynamics::formulations::absolute::projection::project_positions;
use super::rigid_placement::place_bodies_rigidly;
use crate::kinematics::marker::Marker;
use crate::kinematics::planar::Frame;
use crate::joint::IdealKind;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::body::BodyKind;
use crate::error::SimulationError;

/// Strain between two points of a flexible body above which assembly is refused
/// [-]: 1 %, beyond the elastic range of structural metals (steels yield near
/// 0.2 %, titanium alloys near 1 %); a link strained so much by assembly closes
/// a loop that a rigid link of its length could not close.
pub const REFUSED_STRAIN: f64 = 1e-2;

/// Strain between two points of a flexible body above which assembly notes it
/// [-]: 0.1 %, half the yield strain of a mild steel: a preload that the
/// description does not state.
pub const NOTED_STRAIN: f64 = 1e-3;

/// Change of the relative rotation between two points of a flexible body above
/// which assembly is refused [rad] (about 11 deg).
pub const REFUSED_ROTATION: f64 = 0.2;

/// Change of that relative rotation above which assembly notes it [rad] (about 1 deg).
pub const NOTED_ROTATION: f64 = 0.02;

/// Move of a body's frame from its given position that is noted, as a fraction
/// of the mechanism's size (the largest distance from a body's frame to one of its points) [-].
pub const MOVED_FRACTION: f64 = 0.2;

/// Turn of a body from its given angle that is noted [rad] (10 deg): more than a sketch's inaccuracy.
pub const MOVED_ANGLE: f64 = 10.0 * std::f64::consts::PI / 180.0;

/// Difference between a driver's start value and the joint coordinate of the
/// given positions that is noted: 5 deg for an angle [rad], 10 % of the
/// mechanism's size for a displacement [-].
pub const DRIVER_ANGLE: f64 = 5.0 * std::f64::consts::PI / 180.0;
/// See [`DRIVER_ANGLE`].
pub const DRIVER_FRACTION: f64 = 0.1;

/// A move never noted, whatever the mechanism's size (one without named points has none) [m]: round-off.
const NEGLIGIBLE_MOVE: f64 = 1e-9;

/// Something assembly did that the user should know, with what it is about.
#[derive(Clone, Debug, PartialEq)]
pub struct AssemblyNote {
    /// A body's name when `on_body`, else an element's (joint, driver).
    pub name: String,
    /// Whether `name` is a body.
    pub on_body: bool,
    /// What assembly did, with the numbers.
    pub message: String,
}

/// The largest change of a flexible body between two of its named points.
#[derive(Clone, Debug, PartialEq)]
struct Deformation {
    body: usize,
    strain: f64,
    chord: (String, String, f64, f64),
    rotation: f64,
    turned: (String, String),
}

/// Newton iterations of the second assembly, from the bodies placed as wholes (as the first's).
const SECOND_ASSEMBLY_ITERATIONS: usize = 50;

/// After the assembly's Newton: when it strained a flexible body beyond the refusal bounds,
/// assembles again from the bodies moved as wholes to satisfy the joints and drivers
/// ([`place_bodies_rigidly`]), and keeps that start if it strains no body so; then refuses
/// what is still implausible ([`refuse_implausible_start`]).
pub(crate) fn settle_start(model: &Model, t0: f64, q: &mut [f64], ws: &mut Workspace) -> Result<(), SimulationError> {
    if !model.is_rigid() && too_strained(model, q, ws) {
        let all = model.constraints.len();
        let given = frames_at(model, &model.initial_coordinates, ws);
        let mut again = place_bodies_rigidly(model, all, t0, mechanism_size(model, &given), ws);
        let assembled = project_positions(model, all, t0, &mut again, ASSEMBLY_TOLERANCE, SECOND_ASSEMBLY_ITERATIONS, ws);
        if assembled.is_ok() && !too_strained(model, &again, ws) {
            q.copy_from_slice(&again);
        }
    }
    refuse_implausible_start(model, t0, q, ws)
}

/// Whether a flexible body is strained beyond [`REFUSED_STRAIN`] or [`REFUSED_ROTATION`] at `q`.
fn too_strained(model: &Model, q: &[f64], ws: &mut Workspace) -> bool {
    deformations(model, q, ws).iter().any(|d| d.strain.abs() > REFUSED_STRAIN || d.rotation.abs() > REFUSED_ROTATION)
}

/// Refuses an assembled configuration `q` that bends or stretches a flexible body beyond
/// [`REFUSED_STRAIN`] or [`REFUSED_ROTATION`], or starts a journal deeper in its bearing
/// than its joint's penetration bound.
fn refuse_implausible_start(model: &Model, t0: f64, q: &[f64], ws: &mut Workspace) -> Result<(), SimulationError> {
    for d in deformations(model, q, ws) {
        if d.strain.abs() > REFUSED_STRAIN || d.rotation.abs() > REFUSED_ROTATION {
            return Err(SimulationError::ImplausibleStart { time: t0, element: model.bodies[d.body].name.clone(), cause: strain_text(&d, true) });
        }
    }
    let zero = vec![0.0; model.n_velocities()];
    update_frames(model, q, &zero, &mut ws.frames, &mut ws.spatial_frames);
    for (_, name, joint) in model.clearance_joints() {
        let penetration = joint.penetration(&ws.frames);
        if penetration > joint.max_penetration {
            let e = joint.eccentricity(&ws.frames).norm();
            return Err(SimulationError::ImplausibleStart {
                time: t0,
                element: name.to_string(),
                cause: format!(
                    "the start position puts the journal {} into its bearing (eccentricity {}, clearance {}), beyond the bound {} a run allows: the joint's initial_eccentricity or the bodies' given positions place it there, not the contact law or the step; start the journal within the clearance",
                    mm(penetration), mm(e), mm(joint.clearance), mm(joint.max_penetration)
                ),
            });
        }
    }
    Ok(())
}

/// Notes on the assembled configuration `q` at `t0`: bodies moved or turned far from
/// their given place, drivers whose start value contradicts the given positions,
/// flexible bodies strained beyond [`NOTED_STRAIN`] or [`NOTED_ROTATION`] by closing the loops.
pub fn assembly_notes(model: &Model, t0: f64, q: &[f64], ws: &mut Workspace) -> Vec<AssemblyNote> {
    let mut notes = driver_notes(model, t0, ws);
    notes.extend(moved_bodies(model, q, ws));
    if model.is_rigid() {
        return notes;
    }
    // the strain that closing the loops takes, before the quasi-static strain of the loads that the
    // assembly adds afterwards on purpose: the assembly's positions found again
    let mut closed = model.initial_coordinates.clone();
    let all = model.constraints.len();
    if project_positions(model, all, t0, &mut closed, ASSEMBLY_TOLERANCE, SECOND_ASSEMBLY_ITERATIONS, ws).is_err() || settle_start(model, t0, &mut closed, ws).is_err() {
        return notes;
    }
    for d in deformations(model, &closed, ws) {
        if d.strain.abs() > NOTED_STRAIN || d.rotation.abs() > NOTED_ROTATION {
            notes.push(AssemblyNote { name: model.bodies[d.body].name.clone(), on_body: true, message: strain_text(&d, false) });
        }
    }
    notes
}

/// Drivers whose value at `t0` differs from the joint coordinate of the given positions.
fn driver_notes(model: &Model, t0: f64, ws: &mut Workspace) -> Vec<AssemblyNote> {
    let frames = frames_at(model, &model.initial_coordinates, ws);
    let size = mechanism_size(model, &frames);
    constraint_residuals(model, model.n_dynamic_constraints, t0, ws);
    let mut notes = Vec::new();
    for (k, element) in model.ideal_elements() {
        let angle = match element.kind {
            IdealKind::AngleDriver => true,
            IdealKind::DisplacementDriver => false,
            _ => continue,
        };
        let row = model.row_offsets[element.constraints.start];
        let r = ws.residual[row];
        let (off, text) = if angle {
            let wrapped = wrap(r);
            (wrapped.abs() > DRIVER_ANGLE, format!("{} deg", significant(wrapped.abs().to_degrees())))
        } else {
            (r.abs() > (DRIVER_FRACTION * size).max(NEGLIGIBLE_MOVE), mm(r.abs()))
        };
        if off {
            let what = if angle { "relative angle" } else { "displacement" };
            notes.push(AssemblyNote {
                name: model.elements[k].name.clone(),
                on_body: false,
                message: format!(
                    "its value at the start (t = {t0:.6} s) differs by {text} from the {what} its joint has between the bodies as given; assembly moved the linkage to the driver's value (see the notes on the bodies moved): give the bodies at the driver's start value, or the driver's `initial` that matches them"
                ),
            });
        }
    }
    notes
}

/// Bodies whose frame assembly moved by more than [`MOVED_FRACTION`] of the mechanism's size or turned by more than [`MOVED_ANGLE`].
fn moved_bodies(model: &Model, q: &[f64], ws: &mut Workspace) -> Vec<AssemblyNote> {
    let given = frames_at(model, &model.initial_coordinates, ws);
    let size = mechanism_size(model, &given);
    let assembled = frames_at(model, q, ws);
    let mut notes = Vec::new();
    for (k, body) in model.bodies.iter().enumerate() {
        let (a, b) = (&given[k + 1], &assembled[k + 1]);
        let moved = (b.position - a.position).norm();
        let turned = wrap(b.angle - a.angle);
        if moved > (MOVED_FRACTION * size).max(NEGLIGIBLE_MOVE) || turned.abs() > MOVED_ANGLE {
            notes.push(AssemblyNote {
                name: body.name.clone(),
                on_body: true,
                message: format!(
                    "assembly moved it {} and turned it {} deg from its given position and angle (to ({}, {}) and {} deg) to satisfy the joints and drivers: check that the given positions describe the configuration you mean",
                    mm(moved),
                    significant(turned.to_degrees()),
                    mm(b.position.x),
                    mm(b.position.y),
                    significant(b.angle.to_degrees())
                ),
            });
        }
    }
    notes
}

/// For every flexible body, the largest change of distance (as a strain) and of
/// relative rotation between two of its named points, from the given to `q`.
fn deformations(model: &Model, q: &[f64], ws: &mut Workspace) -> Vec<Deformation> {
    let given = frames_at(model, &model.initial_coordinates, ws);
    let assembled = frames_at(model, q, ws);
    let mut out = Vec::new();
    for (k, body) in model.bodies.iter().enumerate() {
        if matches!(body.kind, BodyKind::PlanarRigid(_)) {
            continue;
        }
        let points: Vec<_> = model.points.iter().filter(|(_, m)| m.body.0 == k + 1).collect();
        let mut d = Deformation { body: k, strain: 0.0, chord: Default::default(), rotation: 0.0, turned: Default::default() };
        for (i, (name_a, a)) in points.iter().enumerate() {
            for (name_b, b) in &points[i + 1..] {
                let at = |frames: &[Frame], m: &Marker| frames[m.frame].point(m.local);
                let before = (at(&given, b) - at(&given, a)).norm();
                let after = (at(&assembled, b) - at(&assembled, a)).norm();
                if before > 0.0 && ((after - before) / before).abs() > d.strain.abs() {
                    d.strain = (after - before) / before;
                    d.chord = (name_a.clone(), name_b.clone(), before, after);
                }
                let turn = wrap((assembled[b.frame].angle - assembled[a.frame].angle) - (given[b.frame].angle - given[a.frame].angle));
                if turn.abs() > d.rotation.abs() {
                    d.rotation = turn;
                    d.turned = (name_a.clone(), name_b.clone());
                }
            }
        }
        out.push(d);
    }
    out
}

/// The words of a deformation, for a refusal (`refused`) or a note.
fn strain_text(d: &Deformation, refused: bool) -> String {
    let mut changes = Vec::new();
    if d.strain != 0.0 {
        let (a, b, before, after) = &d.chord;
        let stretch = if d.strain > 0.0 { "stretches" } else { "compresses" };
        let (before, after) = lengths_apart(*before, *after);
        changes.push(format!("{stretch} it from {before} to {after} between {a} and {b}, a strain of {} %", significant(100.0 * d.strain.abs())));
    }
    if d.rotation.abs() > 1e-9 {
        let (a, b) = &d.turned;
        changes.push(format!("bends it by {} deg between {a} and {b}", significant(d.rotation.abs().to_degrees())));
    }
    let mut text = format!("closing the loops {}", changes.join(" and "));
    if refused {
        text.push_str(&format!(
            "; beyond what an elastic link takes ({} % strain, {} deg), so refused, as a rigid link of its given shape, which could not close the loop, is: check the lengths of the links and the positions of their points (and the length unit of a modal body's matrices)",
            significant(100.0 * REFUSED_STRAIN),
            significant(REFUSED_ROTATION.to_degrees())
        ));
    } else {
        text.push_str(": assembly preloads it, which the description does not say; check the lengths of the links and the positions of their points");
    }
    text
}

/// Two lengths in millimetres with as many decimals as their difference needs (up to six).
fn lengths_apart(before: f64, after: f64) -> (String, String) {
    let difference = (after - before).abs() * 1e3;
    let decimals = if difference > 0.0 { (-difference.log10().floor()).clamp(0.0, 6.0) as usize } else { 0 };
    (format!("{:.decimals$} mm", before * 1e3), format!("{:.decimals$} mm", after * 1e3))
}

/// The frames (ground, bodies, sections) at positions `q`, at rest.
pub(super) fn frames_at(model: &Model, q: &[f64], ws: &mut Workspace) -> Vec<Frame> {
    let zero = vec![0.0; model.n_velocities()];
    update_frames(model, q, &zero, &mut ws.frames, &mut ws.spatial_frames);
    ws.frames.clone()
}

/// Size L of the mechanism [m]: the largest distance from a body's frame to one of its named points.
fn mechanism_size(model: &Model, frames: &[Frame]) -> f64 {
    (0..model.bodies.len()).map(|k| body_size(model, frames, k)).fold(0.0, f64::max)
}

/// The largest distance from body `k`'s frame to one of its named points [m].
pub(super) fn body_size(model: &Model, frames: &[Frame], k: usize) -> f64 {
    let origin = frames[k + 1].position;
    model
        .points
        .iter()
        .filter(|(_, m)| m.body.0 == k + 1)
        .map(|(_, m)| (frames[m.frame].point(m.local) - origin).norm())
        .fold(0.0, f64::max)
}

/// An angle wrapped to (-pi, pi] [rad].
fn wrap(angle: f64) -> f64 {
    let two_pi = 2.0 * std::f64::consts::PI;
    let wrapped = angle.rem_euclid(two_pi);
    if wrapped > std::f64::consts::PI { wrapped - two_pi } else { wrapped }
}

/// A length in millimetres, to three significant digits.
pub(crate) fn mm(value: f64) -> String {
    // (below a picometre: round-off of a zero)
    format!("{} mm", significant(if value.abs() < 1e-12 { 0.0 } else { value * 1e3 }))
}

/// `x` to three significant digits, without an exponent from 1e-3 to 1e4.
pub(crate) fn significant(x: f64) -> String {
    let size = x.abs();
    if size == 0.0 || !size.is_finite() {
        return format!("{}", if size == 0.0 { 0.0 } else { x });
    }
    if !(1e-3..1e4).contains(&size) {
        return format!("{x:.2e}");
    }
    let decimals = (2 - size.log10().floor() as i32).max(0) as usize;
    format!("{x:.decimals$}")
}

#[cfg(test)]
#[path = "assembly_checks_tests.rs"]
mod tests;
