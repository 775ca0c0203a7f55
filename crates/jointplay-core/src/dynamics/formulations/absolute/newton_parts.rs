//! The parts of the sparse Newton matrix of the implicit methods
//! ([`crate::integrate::NewtonStructure`]) for a model in absolute coordinates:
//! the mass matrix body by body, the dynamic rows of the constraint Jacobian
//! `Phi_q` block by block, and the local derivatives `d[Q, z_dot]/dy` of the
//! structured Jacobian contribution by contribution
//! (`docs/theory/integrator-jacobian.md`, "Sparse Newton matrix").

use super::constraint_solution::FactorKind;
use super::jacobian::StructuredJacobian;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::body::BodyKind;
use crate::integrate::NewtonStructure;

/// The structure, or `None` when a body's mass depends on its configuration (a modal
/// body: its columns of the Jacobian are differences of the whole right-hand side).
pub(crate) fn structure(model: &Model, jacobian: &StructuredJacobian) -> Option<NewtonStructure> {
    if jacobian.has_whole_columns() {
        return None;
    }
    let mut mass = Vec::new();
    for (body, address) in model.bodies.iter().zip(&model.layout.bodies) {
        let v = address.v;
        match &body.kind {
            BodyKind::PlanarRigid(rigid) => mass.extend((0..rigid.inverse_mass().len()).map(|i| (v + i, v + i))),
            BodyKind::Beam(beam) => {
                for &(i, j, _) in beam.mass_entries() {
                    let (i, j) = (v + i as usize, v + j as usize);
                    mass.push((i, j));
                    if i != j {
                        mass.push((j, i));
                    }
                }
            }
            // (configuration-dependent mass, or positions with q_dot != v: the whole right-hand side)
            BodyKind::Modal(_) | BodyKind::SpatialRigid(_) => return None,
        }
    }
    let rows = model.n_dynamic_equations();
    let constraint = (0..rows).flat_map(|r| model.jacobian_pattern.row(r).iter().flat_map(move |b| b.columns().map(move |c| (r, c)))).collect();
    let layout = &model.layout;
    Some(NewtonStructure { nv: layout.nv, n_constraints: rows, nz: layout.nz, mass, constraint, local: jacobian.local_pattern() })
}

/// The mass entries, as [`structure`] lists them.
pub(crate) fn fill_mass(model: &Model, out: &mut [f64]) {
    let mut out = out.iter_mut();
    for body in &model.bodies {
        match &body.kind {
            BodyKind::PlanarRigid(rigid) => {
                // (the shorter iterator first: zip draws from its first before it sees the second end)
                for (w, o) in rigid.inverse_mass().iter().zip(out.by_ref()) {
                    *o = 1.0 / w;
                }
            }
            BodyKind::Beam(beam) => {
                for &(i, j, m) in beam.mass_entries() {
                    let copies = if i != j { 2 } else { 1 };
                    for o in out.by_ref().take(copies) {
                        *o = m;
                    }
                }
            }
            BodyKind::Modal(_) | BodyKind::SpatialRigid(_) => {}
        }
    }
}

/// The `Phi_q` entries of the dynamic rows linearised in the workspace, as [`structure`]
/// lists them; false when the workspace's constraint factor is not the regular one
/// (dependent or nearly dependent rows: the dense Jacobian's spectral solve is not `A`'s
/// augmented form).
pub(crate) fn fill_constraint(model: &Model, ws: &Workspace, out: &mut [f64]) -> bool {
    let rows = model.n_dynamic_equations();
    if rows > 0 && ws.factor_kind != FactorKind::Pattern {
        return false;
    }
    let mut out = out.iter_mut();
    for r in 0..rows {
        for b in model.jacobian_pattern.row(r) {
            for (value, o) in ws.jacobian[b.values()].iter().zip(out.by_ref()) {
                *o = *value;
            }
        }
    }
    true
}
