//! Building a modal body from its description: the beam it is reduced from,
//! its interface nodes, the Craig-Bampton modes.

use super::beams::build_beam;
use crate::body::{BeamBody, ModalBody};
use crate::error::ModelErrors;
use crate::modal::FrameReference;
use crate::spec::{BeamPointSpec, BeamSpec, ModalBodySpec};

/// A built modal body: the body, its frame's initial pose `(x, y, phi)` [m, m, rad],
/// its interface nodes and its other named points (name, node, location of the description).
pub(super) struct BuiltModalBody {
    pub body: ModalBody,
    pub pose: [f64; 3],
    pub interface: Vec<(String, usize, String)>,
    pub points: Vec<(String, usize, String)>,
}

/// The modal body described by `spec`; every problem goes to `errors` at `loc`.
pub(super) fn build_modal_body(spec: &ModalBodySpec, loc: &str, errors: &mut ModelErrors) -> Option<BuiltModalBody> {
    let beam_spec = BeamSpec {
        name: spec.name.clone(),
        start: spec.start,
        end: spec.end,
        section: spec.section.clone(),
        mesh: spec.mesh.clone(),
        damping_time: 0.0,
        velocity: spec.velocity,
        angular_velocity: spec.angular_velocity,
        points: Vec::new(),
    };
    let beam = build_beam(&beam_spec, loc, errors)?;
    if spec.interface.is_empty() {
        errors.push(format!("{loc}.interface"), "give at least one interface node (the first carries the body's frame)");
        return None;
    }
    let interface = named_nodes(&beam, &spec.interface, &format!("{loc}.interface"), errors);
    let points = named_nodes(&beam, &spec.points, &format!("{loc}.points"), errors);
    if interface.len() < spec.interface.len() || points.len() < spec.points.len() {
        return None;
    }
    if !(spec.damping_ratio.is_finite() && spec.damping_ratio >= 0.0) {
        errors.push(format!("{loc}.damping_ratio"), format!("must be >= 0, got {}", spec.damping_ratio));
        return None;
    }
    let nodes: Vec<usize> = interface.iter().map(|(_, node, _)| *node).collect();
    let frame = spec.frame.unwrap_or(if nodes.len() >= 2 { FrameReference::Chord } else { FrameReference::Clamped });
    if !(spec.damping_time.is_finite() && spec.damping_time >= 0.0) {
        errors.push(format!("{loc}.damping_time"), format!("must be >= 0, got {}", spec.damping_time));
        return None;
    }
    let built = ModalBody::from_beam(&beam, &nodes, frame, spec.normal_modes, spec.damping_ratio).and_then(|(mut body, pose)| {
        body.add_stiffness_proportional_damping(spec.damping_time)?;
        Ok((body, pose))
    });
    match built {
        Ok((body, pose)) => Some(BuiltModalBody { body, pose, interface, points }),
        Err(message) => {
            errors.push(loc, message);
            None
        }
    }
}

/// The nodes of the named points `given` (name, node, location `at[k]`); each miss goes to `errors`.
fn named_nodes(beam: &BeamBody, given: &[BeamPointSpec], at: &str, errors: &mut ModelErrors) -> Vec<(String, usize, String)> {
    let mut nodes = Vec::new();
    for (k, point) in given.iter().enumerate() {
        let location = format!("{at}[{k}]");
        match node_at(beam, point.arclength) {
            Ok(node) => nodes.push((point.name.clone(), node, location)),
            Err(message) => errors.push(format!("{location}.arclength"), message),
        }
    }
    nodes
}

/// The node of the (straight, evenly meshed) beam at `arclength` [m], or why there is none.
fn node_at(beam: &BeamBody, arclength: f64) -> Result<usize, String> {
    let spacing = beam.length / (beam.n_nodes() - 1) as f64;
    let node = (arclength / spacing).round();
    if !(arclength.is_finite() && (0.0..=(beam.n_nodes() - 1) as f64).contains(&node)) || (arclength - node * spacing).abs() > 1e-9 * beam.length {
        return Err(format!(
            "a point of a modal body must sit at a node of the mesh, every {spacing} m from 0 to {} m; got {arclength} m",
            beam.length
        ));
    }
    Ok(node as usize)
}
