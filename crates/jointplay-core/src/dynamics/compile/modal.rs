//! Building a modal body from its description: the beam it is reduced from,
//! its interface nodes, the Craig-Bampton modes.

use super::beams::build_beam;
use crate::body::{BeamBody, ModalBody};
use crate::error::ModelErrors;
use crate::spec::{BeamSpec, ModalBodySpec};

/// A built modal body: the body, its frame's initial pose `(x, y, phi)` [m, m, rad]
/// and its interface nodes (name, node, location of the description).
pub(super) struct BuiltModalBody {
    pub body: ModalBody,
    pub pose: [f64; 3],
    pub interface: Vec<(String, usize, String)>,
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
    let mut interface = Vec::new();
    for (k, point) in spec.interface.iter().enumerate() {
        let location = format!("{loc}.interface[{k}]");
        match node_at(&beam, point.arclength) {
            Ok(node) => interface.push((point.name.clone(), node, location)),
            Err(message) => errors.push(format!("{location}.arclength"), message),
        }
    }
    if interface.len() < spec.interface.len() {
        return None;
    }
    if !(spec.damping_ratio.is_finite() && spec.damping_ratio >= 0.0) {
        errors.push(format!("{loc}.damping_ratio"), format!("must be >= 0, got {}", spec.damping_ratio));
        return None;
    }
    let nodes: Vec<usize> = interface.iter().map(|(_, node, _)| *node).collect();
    match ModalBody::from_beam(&beam, &nodes, spec.normal_modes, spec.damping_ratio) {
        Ok((body, pose)) => Some(BuiltModalBody { body, pose, interface }),
        Err(message) => {
            errors.push(loc, message);
            None
        }
    }
}

/// The node of the (straight, evenly meshed) beam at `arclength` [m], or why there is none.
fn node_at(beam: &BeamBody, arclength: f64) -> Result<usize, String> {
    let spacing = beam.length / (beam.n_nodes() - 1) as f64;
    let node = (arclength / spacing).round();
    if !(arclength.is_finite() && (0.0..=(beam.n_nodes() - 1) as f64).contains(&node)) || (arclength - node * spacing).abs() > 1e-9 * beam.length {
        return Err(format!(
            "an interface node must sit at a node of the mesh, every {spacing} m from 0 to {} m; got {arclength} m",
            beam.length
        ));
    }
    Ok(node as usize)
}
