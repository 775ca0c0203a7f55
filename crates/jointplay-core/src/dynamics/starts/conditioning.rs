//! The conditioning of the constraint equations, for diagnostics only: whether
//! the joints' and drivers' equations are dependent (a locked mechanism, a
//! toggle position) or independent and only weighted badly by the bodies'
//! masses, measured by the singular values of their Jacobian with rows and
//! columns scaled to unit length (so that units and masses do not count).

use super::assembly_checks::{body_size, frames_at, mm, significant};
use crate::dynamics::formulations::absolute::equations::{jacobian_times, linearise_constraints, update_frames};
use crate::kinematics::planar::Frame;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::body::BodyKind;
use crate::error::SimulationError;
use nalgebra::DMatrix;

/// Smallest singular value of the equilibrated constraint Jacobian, relative
/// to its largest, below which its equations are dependent (locked, or at a
/// singular position) [-].
pub const DEPENDENT_EQUATIONS: f64 = 1e-8;

/// Ratio of the heaviest to the lightest body (inertias as masses at the bodies' sizes) from which a
/// failed velocity solve with independent equations is put down to the masses [-]: the constraint
/// solve treats eigenvalues below 1e-5 of the largest as a singular position, and the masses' ratio
/// enters those eigenvalues directly; parts of one mechanism rarely differ by 1e3.
pub const ILL_CONDITIONING_MASS_RATIO: f64 = 1e3;

/// Why the velocities of an assembled configuration `q` leave a `residual` (largest in `row`):
/// the joints and drivers are dependent (the mechanism is locked), or they are independent
/// and the bodies' masses and inertias make the mass-weighted equations too ill-conditioned
/// to solve, which is told as such, naming the heaviest body.
pub(crate) fn velocity_failure(model: &Model, t0: f64, q: &[f64], residual: f64, row: usize, ws: &mut Workspace) -> SimulationError {
    let all = model.constraints.len();
    let ratio = relative_smallest_singular_value(model, all, t0, q, None, ws);
    let frames = frames_at(model, q, ws);
    let (light, heavy) = mass_extremes(model, &frames);
    if ratio < DEPENDENT_EQUATIONS || !(heavy.2 > ILL_CONDITIONING_MASS_RATIO * light.2) {
        return SimulationError::SingularConfiguration {
            time: t0,
            element: model.elements[model.row_owner[row]].name.clone(),
            cause: format!(
                "the mechanism is locked: no velocities satisfy its joints and drivers together (residual {residual:.3e} m/s or rad/s remains); a driver fights a joint, or the joints leave no freedom to move"
            ),
        };
    }
    SimulationError::ImplausibleStart {
        time: t0,
        element: heavy.3.clone(),
        cause: format!(
            "its mass or inertia makes the start's velocities impossible to solve for, though the mechanism is not locked: its joints and drivers are independent (the smallest singular value of their equilibrated equations is {ratio:.2e} of the largest), but the bodies' masses and inertias differ so much ({}: {}; {}: {}; a ratio of {}) that the equations weighted by them are too ill-conditioned (residual {residual:.3e} m/s or rad/s remains); a unit slip in a mass or an inertia is the likely cause (see the plausibility warnings)",
            light.0,
            light.1,
            heavy.0,
            heavy.1,
            significant(heavy.2 / light.2)
        ),
    }
}

/// A body's mass or inertia: what, its text, as a mass [kg], the body's name.
type Extreme = (String, String, f64, String);

/// The lightest and the heaviest rigid body by mass or by inertia over the square
/// of its size (the largest distance from its centre of mass to one of its points):
/// (name and what, text, effective mass [kg], body name).
fn mass_extremes(model: &Model, frames: &[Frame]) -> (Extreme, Extreme) {
    let mut entries = Vec::new();
    for (k, body) in model.bodies.iter().enumerate() {
        if let BodyKind::PlanarRigid(rigid) = &body.kind {
            entries.push((format!("{}'s mass", body.name), format!("{} kg", significant(rigid.mass)), rigid.mass, body.name.clone()));
            let size = body_size(model, frames, k);
            if size > 0.0 {
                let text = format!("{} kg m^2, {} kg at its {}", significant(rigid.inertia), significant(rigid.inertia / size.powi(2)), mm(size));
                entries.push((format!("{}'s inertia", body.name), text, rigid.inertia / size.powi(2), body.name.clone()));
            }
        }
    }
    let by = |a: &&Extreme, b: &&Extreme| a.2.total_cmp(&b.2);
    let light = entries.iter().min_by(by).cloned().unwrap_or_default();
    let heavy = entries.iter().max_by(by).cloned().unwrap_or_default();
    (light, heavy)
}

/// Smallest singular value of the first-`n_constraints` constraints' Jacobian at `(t, q)`, rows
/// and columns scaled to unit length (so that units and masses do not count), relative to the
/// largest; `without` leaves out the rows of one element.
pub(crate) fn relative_smallest_singular_value(model: &Model, n_constraints: usize, t: f64, q: &[f64], without: Option<usize>, ws: &mut Workspace) -> f64 {
    let zero = vec![0.0; model.n_velocities()];
    update_frames(model, q, &zero, &mut ws.frames, &mut ws.spatial_frames);
    let rows = linearise_constraints(model, n_constraints, t, ws);
    let kept: Vec<usize> = (0..rows).filter(|&r| Some(model.row_owner[r]) != without).collect();
    let nv = model.n_velocities();
    if kept.len() > nv {
        return 0.0; // (more equations than coordinates: dependent)
    }
    let mut dense = DMatrix::<f64>::zeros(kept.len(), nv);
    let mut unit = vec![0.0; nv];
    let mut column = vec![0.0; rows];
    for c in 0..nv {
        unit[c] = 1.0;
        jacobian_times(model, rows, &ws.jacobian, &unit, &mut column);
        unit[c] = 0.0;
        for (i, &r) in kept.iter().enumerate() {
            dense[(i, c)] = column[r];
        }
    }
    equilibrate(&mut dense);
    let values = dense.singular_values();
    let largest = values.max();
    if kept.is_empty() || largest <= 0.0 {
        return 1.0;
    }
    values.min() / largest
}

/// Scales the rows, then the columns, of `a` to unit Euclidean length (zero ones left as they are).
fn equilibrate(a: &mut DMatrix<f64>) {
    for mut row in a.row_iter_mut() {
        let n = row.norm();
        if n > 0.0 {
            row /= n;
        }
    }
    for mut column in a.column_iter_mut() {
        let n = column.norm();
        if n > 0.0 {
            column /= n;
        }
    }
}
