//! The check that a structure given by matrices is free: its stiffness
//! resists no rigid motion. A supported structure, nodes that do not match
//! the matrices (another length unit, another order of the coordinates) or a
//! stiffness matrix of another structure all fail it, and a floating frame
//! would otherwise carry a wrong rigid-body motion.

use super::NodalCoordinates;
use nalgebra::{DMatrix, DVector};

/// Largest relative force of a rigid motion, `max_i |(K r)_i|` against the
/// largest sum of the terms' sizes, `max_i sum_j |K_ij r_j|`: matrices
/// written with 8 significant digits stay below 1e-7.
pub const RIGID_MOTION_TOLERANCE: f64 = 1e-6;

/// The three rigid motions of a planar structure with nodes at `nodes` [m]
/// (coordinates `coordinates` node after node): translations along x and
/// y [m per m], and a rotation about the origin [m or rad per rad].
pub fn rigid_motions(nodes: &[[f64; 2]], coordinates: NodalCoordinates) -> [(&'static str, DVector<f64>); 3] {
    let d = coordinates.per_node();
    let n = d * nodes.len();
    let along = |axis: usize| DVector::from_fn(n, |i, _| if i % d == axis { 1.0 } else { 0.0 });
    let rotation = DVector::from_fn(n, |i, _| match i % d {
        0 => -nodes[i / d][1],
        1 => nodes[i / d][0],
        _ => 1.0,
    });
    [("a translation along x", along(0)), ("a translation along y", along(1)), ("a rotation about the origin", rotation)]
}

/// Ok when `stiffness` resists none of the rigid motions of the nodes `nodes`
/// [m] within [`RIGID_MOTION_TOLERANCE`]; otherwise which motion, how much and what may be wrong.
pub fn check_free_structure(stiffness: &DMatrix<f64>, nodes: &[[f64; 2]], coordinates: NodalCoordinates) -> Result<(), String> {
    let d = coordinates.per_node();
    if stiffness.nrows() != d * nodes.len() {
        return Err(format!("{} nodes need matrices of size {}, got {}", nodes.len(), d * nodes.len(), stiffness.nrows()));
    }
    let order = if d == 3 { "(u_x, u_y, theta)" } else { "(u_x, u_y)" };
    for (motion, r) in rigid_motions(nodes, coordinates) {
        let force = stiffness * &r;
        let scale = stiffness.abs() * r.abs();
        let relative = if scale.max() > 0.0 { force.amax() / scale.max() } else { 0.0 };
        if relative > RIGID_MOTION_TOLERANCE {
            return Err(format!(
                "the stiffness matrix resists {motion} of the nodes (relative force {relative:.1e}, more than {RIGID_MOTION_TOLERANCE:e}): \
                 give the stiffness of the free, unsupported structure, with the coordinates {order} of each node in turn, \
                 and the nodes' positions in the matrices' length unit"
            ));
        }
    }
    Ok(())
}
