//! Building a modal body from its description: the structure it is reduced
//! from (a beam of jointplay's elements or matrices from another code), its
//! interface nodes and points, the Craig-Bampton modes.

use nalgebra::DMatrix;

use super::beams::build_beam;
use crate::body::{BeamBody, ModalBody, Structure, MAX_STRUCTURE_NODES};
use crate::error::ModelErrors;
use crate::modal::{FrameReference, NodalCoordinates};
use crate::spec::{ranges, Range, BeamMeshSpec, BeamSectionSpec, BeamSpec, ModalBodySpec, ModalPointSpec, ModalStructureSpec, SparseMatrixSpec, StructureMatricesSpec};

/// A built modal body: the body, its frame's initial pose `(x, y, phi)` [m, m, rad],
/// its interface nodes and its other named points (name, node, location of the description).
pub(super) struct BuiltModalBody {
    pub body: ModalBody,
    pub pose: [f64; 3],
    pub interface: Vec<(String, usize, String)>,
    pub points: Vec<(String, usize, String)>,
}

/// The reduction's settings common to every structure.
struct Reduction {
    frame: Option<FrameReference>,
    normal_modes: usize,
    damping_ratio: f64,
    damping_time: f64,
}

/// The modal body described by `spec`; every problem goes to `errors` at `loc`.
pub(super) fn build_modal_body(spec: &ModalBodySpec, loc: &str, errors: &mut ModelErrors) -> Option<BuiltModalBody> {
    let mut settled = true;
    if spec.interface.is_empty() {
        errors.push(format!("{loc}.interface"), "give at least one interface node (the first carries the body's frame)");
        settled = false;
    }
    settled &= Range::check_all(&[(ranges::MODAL_BODIES_DAMPING_RATIO, spec.damping_ratio), (ranges::MODAL_BODIES_DAMPING_TIME, spec.damping_time)], loc, errors);
    let reduction = Reduction { frame: spec.frame, normal_modes: spec.normal_modes, damping_ratio: spec.damping_ratio, damping_time: spec.damping_time };
    match &spec.structure {
        ModalStructureSpec::Beam { start, end, section, mesh } => {
            let beam = build_beam(&beam_spec(spec, *start, *end, section, mesh), loc, errors)?;
            let node_of = |point: &ModalPointSpec| node_at_arclength(&beam, point);
            let (interface, points) = named_nodes(spec, &node_of, loc, errors)?;
            settled.then_some(())?;
            let nodes: Vec<usize> = interface.iter().map(|(_, node, _)| *node).collect();
            let frame = chosen_frame(&reduction, &nodes);
            let built = ModalBody::from_beam(&beam, &nodes, frame, reduction.normal_modes, reduction.damping_ratio);
            finish(built, &reduction, (interface, points), loc, errors)
        }
        ModalStructureSpec::Matrices(matrices) => {
            let n_nodes = matrices.nodes.len();
            let node_of = |point: &ModalPointSpec| node_by_number(n_nodes, point);
            let named = named_nodes(spec, &node_of, loc, errors);
            let ((interface, points), (mass, stiffness)) = named.zip(structure_matrices(matrices, loc, errors))?;
            settled.then_some(())?;
            let nodes: Vec<usize> = interface.iter().map(|(_, node, _)| *node).collect();
            let frame = chosen_frame(&reduction, &nodes);
            let angles = vec![0.0; n_nodes];
            let structure = Structure { mass: &mass, stiffness: &stiffness, positions: &matrices.nodes, angles: &angles };
            let built = ModalBody::from_structure(&structure, &nodes, frame, reduction.normal_modes, reduction.damping_ratio)
                .map(|(body, pose)| (body, placed(pose, matrices.position, matrices.angle)));
            finish(built, &reduction, (interface, points), &format!("{loc}.matrices"), errors)
        }
    }
}

/// The beam a modal body is reduced from (undamped: the modal body has its own damping).
fn beam_spec(spec: &ModalBodySpec, start: [f64; 2], end: [f64; 2], section: &BeamSectionSpec, mesh: &BeamMeshSpec) -> BeamSpec {
    BeamSpec {
        name: spec.name.clone(),
        start,
        end,
        section: section.clone(),
        mesh: mesh.clone(),
        damping_time: 0.0,
        velocity: spec.velocity,
        angular_velocity: spec.angular_velocity,
        points: Vec::new(),
    }
}

/// The frame asked for, or the default: a chord frame with two or more interface nodes, clamped with one.
fn chosen_frame(reduction: &Reduction, interface: &[usize]) -> FrameReference {
    reduction.frame.unwrap_or(if interface.len() >= 2 { FrameReference::Chord } else { FrameReference::Clamped })
}

/// The built body with its stiffness-proportional damping, or its problem at `loc`.
fn finish(built: Result<(ModalBody, [f64; 3]), String>, reduction: &Reduction, named: NamedNodes, loc: &str, errors: &mut ModelErrors) -> Option<BuiltModalBody> {
    let built = built.and_then(|(mut body, pose)| {
        body.add_stiffness_proportional_damping(reduction.damping_time)?;
        Ok((body, pose))
    });
    match built {
        Ok((body, pose)) => Some(BuiltModalBody { body, pose, interface: named.0, points: named.1 }),
        Err(message) => {
            errors.push(loc, message);
            None
        }
    }
}

/// The frame's pose in the model, `pose` [m, m, rad] given in the axes of a
/// structure whose origin is at `position` [m] and whose axes are at `angle` [rad].
fn placed(pose: [f64; 3], position: [f64; 2], angle: f64) -> [f64; 3] {
    let (sin, cos) = angle.sin_cos();
    [position[0] + cos * pose[0] - sin * pose[1], position[1] + sin * pose[0] + cos * pose[1], angle + pose[2]]
}

/// Named nodes (name, node, location of the description).
type NamedNodes = (Vec<(String, usize, String)>, Vec<(String, usize, String)>);

/// The nodes of the interface and of the other points of `spec`, each found by
/// `node_of`; `None` after a problem (each goes to `errors`).
fn named_nodes(spec: &ModalBodySpec, node_of: &dyn Fn(&ModalPointSpec) -> Result<usize, (&'static str, String)>, loc: &str, errors: &mut ModelErrors) -> Option<NamedNodes> {
    let mut found = |given: &[ModalPointSpec], key: &str| {
        let mut nodes = Vec::new();
        for (k, point) in given.iter().enumerate() {
            let location = format!("{loc}.{key}[{k}]");
            match node_of(point) {
                Ok(node) => nodes.push((point.name.clone(), node, location)),
                Err((field, message)) => errors.push(format!("{location}.{field}"), message),
            }
        }
        nodes
    };
    let interface = found(&spec.interface, "interface");
    let points = found(&spec.points, "points");
    (interface.len() == spec.interface.len() && points.len() == spec.points.len()).then_some((interface, points))
}

/// The node of a point of a beam structure, given by its arclength, or which field is wrong and why.
fn node_at_arclength(beam: &BeamBody, point: &ModalPointSpec) -> Result<usize, (&'static str, String)> {
    match (point.arclength, point.node) {
        (Some(arclength), None) => node_at(beam, arclength).map_err(|message| ("arclength", message)),
        _ => Err(("arclength", "a point of a modal body reduced from a beam is given by its arclength alone".to_string())),
    }
}

/// The node of a point of a structure of `n_nodes` nodes given by matrices, or which field is wrong and why.
fn node_by_number(n_nodes: usize, point: &ModalPointSpec) -> Result<usize, (&'static str, String)> {
    match (point.node, point.arclength) {
        (Some(node), None) if node < n_nodes => Ok(node),
        (Some(node), None) => Err(("node", format!("must be a node of the structure, from 0 to {}, got {node}", n_nodes.saturating_sub(1)))),
        _ => Err(("node", "a point of a modal body given by matrices is given by its node number alone".to_string())),
    }
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

/// The dense mass and stiffness of a structure given by matrices, after
/// checking their sizes against its nodes; `None` after a problem (each goes to `errors`).
fn structure_matrices(matrices: &StructureMatricesSpec, loc: &str, errors: &mut ModelErrors) -> Option<(DMatrix<f64>, DMatrix<f64>)> {
    let n_nodes = matrices.nodes.len();
    let at = |key: &str| format!("{loc}.matrices.{key}");
    if n_nodes == 0 || n_nodes > MAX_STRUCTURE_NODES {
        errors.push(at("nodes"), format!("a structure given by matrices has 1 to {MAX_STRUCTURE_NODES} nodes, got {n_nodes}; reduce a larger model in its own code first"));
        return None;
    }
    if let Some((k, node)) = matrices.nodes.iter().enumerate().find(|(_, p)| !(p[0].is_finite() && p[1].is_finite())) {
        errors.push(at("nodes"), format!("node {k} is not at a finite position: ({}, {}) m", node[0], node[1]));
        return None;
    }
    // (the mass matrix's size says how many coordinates each node has: 3 for frame elements, 2 for plane solids)
    let coordinates = NodalCoordinates::of_size(matrices.mass.size, n_nodes).unwrap_or(NodalCoordinates::TranslationsAndRotation);
    let mass = dense(&matrices.mass, coordinates, n_nodes).map_err(|message| errors.push(at("mass"), message));
    let stiffness = dense(&matrices.stiffness, coordinates, n_nodes).map_err(|message| errors.push(at("stiffness"), message));
    Some((mass.ok()?, stiffness.ok()?))
}

/// The dense matrix of `matrix`, which must have the `coordinates` of each of `n_nodes` nodes, or why it cannot be.
fn dense(matrix: &SparseMatrixSpec, coordinates: NodalCoordinates, n_nodes: usize) -> Result<DMatrix<f64>, String> {
    let SparseMatrixSpec { size: given, rows, columns, values } = matrix;
    let size = coordinates.per_node() * n_nodes;
    if *given != size {
        return Err(format!(
            "must be {0} x {0} (three coordinates u_x, u_y, theta for each of the {n_nodes} nodes of a frame) or {1} x {1} (two, u_x and u_y, \
             for each node of a plane solid), got {given} x {given}",
            3 * n_nodes,
            2 * n_nodes
        ));
    }
    if rows.len() != values.len() || columns.len() != values.len() {
        return Err(format!("{} rows, {} columns and {} values: one of each per entry", rows.len(), columns.len(), values.len()));
    }
    let mut out = DMatrix::zeros(size, size);
    for ((&i, &j), &value) in rows.iter().zip(columns).zip(values) {
        if i >= size || j >= size {
            return Err(format!("entry ({i}, {j}) is outside a {size} x {size} matrix"));
        }
        if !value.is_finite() {
            return Err(format!("entry ({i}, {j}) is {value}"));
        }
        out[(i, j)] += value;
    }
    Ok(out)
}
