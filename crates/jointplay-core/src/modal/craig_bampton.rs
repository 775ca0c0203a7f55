//! Craig-Bampton modes of a finite-element structure for a floating frame
//! attached at its interface nodes (Craig and Bampton, "Coupling of
//! substructures for dynamic analyses", AIAA J. 6(7), 1968, 1313-1319).
//!
//! Coordinates are the structure's nodal `(u_x, u_y, theta)`, node after node,
//! in the body frame. The interface nodes' coordinates are the boundary set,
//! less the three the frame's reference conditions hold
//! ([`FrameReference`]): the rigid-body motion is carried by the frame and the
//! modes hold none. The mode set is
//!
//! - **constraint modes** (static): a unit value of one boundary coordinate,
//!   the other boundary coordinates and the frame's three held,
//!   the interior in static equilibrium, `u_I = -K_II^-1 K_IB`;
//! - **fixed-interface normal modes**: `K_II x = w^2 M_II x` with every
//!   interface coordinate held, the lowest `n_normal`.
//!
//! With only the first node as interface (clamped frame) the set is the
//! structure's cantilever modes about that node. Constraint modes have unit amplitude
//! (their coordinate is the interface displacement [m] or rotation [rad]);
//! normal modes are scaled to a largest nodal displacement of 1, so their
//! amplitudes are in metres too.

use nalgebra::DMatrix;

use super::{FrameReference, NodalCoordinates};
use crate::beam::vibration_modes;

/// A Craig-Bampton mode set.
#[derive(Clone, Debug, PartialEq)]
pub struct CraigBamptonModes {
    /// Mode shapes as columns over all nodal coordinates (constraint modes
    /// first, then normal modes) [m/unit, rad/unit].
    pub shapes: DMatrix<f64>,
    /// Number of constraint modes (3 per interface node, less the frame's 3).
    pub n_constraint: usize,
    /// The boundary coordinate of each constraint mode (nodal numbering).
    pub boundary: Vec<usize>,
    /// Angular frequencies of the fixed-interface normal modes kept [rad/s].
    pub fixed_interface_frequencies: Vec<f64>,
}

/// The Craig-Bampton modes of the structure of mass `mass` and stiffness
/// `stiffness` (dense, symmetric, `d n_nodes` square with the `d` coordinates
/// `coordinates` per node, in the body frame) with the interface nodes
/// `interface` (the first one carries the floating frame's origin), the
/// frame's reference conditions `reference` and `n_normal` fixed-interface normal modes.
pub fn craig_bampton_modes(mass: &DMatrix<f64>, stiffness: &DMatrix<f64>, coordinates: NodalCoordinates, interface: &[usize], reference: FrameReference, n_normal: usize) -> Result<CraigBamptonModes, String> {
    let n = mass.nrows();
    let d = coordinates.per_node();
    check_sizes(mass, stiffness, d, interface)?;
    let frame = reference.held_coordinates(interface, coordinates)?;
    let held: Vec<usize> = interface.iter().flat_map(|&k| d * k..d * k + d).collect();
    let boundary: Vec<usize> = held.iter().copied().filter(|i| !frame.contains(i)).collect();
    let interior: Vec<usize> = (0..n).filter(|i| !held.contains(i)).collect();
    if n_normal > interior.len() {
        return Err(format!("asked for {n_normal} normal modes, but the structure has only {} interior coordinates", interior.len()));
    }
    let constraint = constraint_modes(stiffness, &boundary, &interior)?;
    let mut shapes = DMatrix::zeros(n, boundary.len() + n_normal);
    shapes.columns_mut(0, boundary.len()).copy_from(&constraint);
    if n_normal == 0 {
        return Ok(CraigBamptonModes { shapes, n_constraint: boundary.len(), boundary, fixed_interface_frequencies: Vec::new() });
    }
    let normal = vibration_modes(mass, stiffness, &held)?;
    for j in 0..n_normal {
        let column = normal.shapes.column(j);
        let largest = (0..n).filter(|&i| !coordinates.is_rotation(i)).map(|i| column[i].abs()).fold(0.0, f64::max);
        let scale = if largest > 0.0 { 1.0 / largest } else { 1.0 };
        shapes.column_mut(boundary.len() + j).copy_from(&(column * scale));
    }
    let n_constraint = boundary.len();
    Ok(CraigBamptonModes { shapes, n_constraint, boundary, fixed_interface_frequencies: normal.angular_frequencies[..n_normal].to_vec() })
}

/// Square matrices of `d n_nodes`, distinct interface nodes within the structure.
fn check_sizes(mass: &DMatrix<f64>, stiffness: &DMatrix<f64>, d: usize, interface: &[usize]) -> Result<(), String> {
    let n = mass.nrows();
    if n == 0 || !n.is_multiple_of(d) || mass.ncols() != n || stiffness.shape() != (n, n) {
        return Err(format!("the mass and stiffness matrices must be square, of the same size, {d} coordinates per node; got {:?} and {:?}", mass.shape(), stiffness.shape()));
    }
    if mass.iter().chain(stiffness.iter()).any(|v| !v.is_finite()) {
        return Err("the mass and stiffness matrices must be finite".to_string());
    }
    for (a, what) in [(mass, "mass"), (stiffness, "stiffness")] {
        let largest = a.amax();
        if (a - a.transpose()).amax() > 1e-9 * largest {
            return Err(format!("the {what} matrix must be symmetric"));
        }
    }
    if interface.is_empty() {
        return Err("a modal body needs at least one interface node (the first carries its frame)".to_string());
    }
    for (k, &node) in interface.iter().enumerate() {
        if node >= n / d {
            return Err(format!("interface node {node} is not a node of the structure (it has {} nodes)", n / d));
        }
        if interface[..k].contains(&node) {
            return Err(format!("interface node {node} is listed twice"));
        }
    }
    Ok(())
}

/// The static constraint modes of the boundary coordinates `boundary` (the
/// frame's held coordinates and the other boundary coordinates held): columns over all coordinates.
fn constraint_modes(stiffness: &DMatrix<f64>, boundary: &[usize], interior: &[usize]) -> Result<DMatrix<f64>, String> {
    let n = stiffness.nrows();
    let mut modes = DMatrix::zeros(n, boundary.len());
    if boundary.is_empty() {
        return Ok(modes);
    }
    let k_ii = DMatrix::from_fn(interior.len(), interior.len(), |r, c| stiffness[(interior[r], interior[c])]);
    let k_ib = DMatrix::from_fn(interior.len(), boundary.len(), |r, c| stiffness[(interior[r], boundary[c])]);
    let interior_response = if interior.is_empty() {
        DMatrix::zeros(0, boundary.len())
    } else {
        let factor = k_ii.cholesky().ok_or("the stiffness held at the interface nodes is not positive definite (is the structure connected?)")?;
        -factor.solve(&k_ib)
    };
    for (j, &b) in boundary.iter().enumerate() {
        modes[(b, j)] = 1.0;
        for (r, &i) in interior.iter().enumerate() {
            modes[(i, j)] = interior_response[(r, j)];
        }
    }
    Ok(modes)
}
