//! The sparse Newton matrix (`integrate/sparse_newton.rs` from `newton_parts.rs`) against
//! the dense one it replaces, formed independently: the dense structured Jacobian
//! (`A` applied column by column with the mass and constraint solves of an evaluation),
//! the reduced matrix of generalized-alpha and `I - c J` of the NDF written from it, and a
//! dense LU. In exact arithmetic both solve the same equations; the tolerances are
//! round-off levels (see [`check`]).

use crate::dynamics::beam_tests::spin_up_beam;
use super::jacobian::StructuredJacobian;
use super::{equations, newton_parts};
use super::jacobian_tests::{self, floors, mixed, mixed_state, structured};
use crate::dynamics::*;
use crate::integrate::sparse_newton::SparseNewton;
use crate::integrate::{NewtonParts, NewtonStructure};
use crate::linalg::{lu_factor, lu_solve};

/// The structure and the parts at (t, y), the workspace evaluated there as the system does.
fn parts_at(m: &Model, t: f64, y: &[f64], ws: &mut Workspace) -> (NewtonStructure, NewtonParts) {
    let memory = m.initial_memory();
    equations::accelerations(m, &memory, t, y, Stabilization::Projection, ws).unwrap();
    let mut s = StructuredJacobian::new(m);
    let structure = newton_parts::structure(m, &s).expect("a model without modal bodies has the structure");
    s.local_derivatives(m, &memory, t, y, &floors(y.len())).unwrap();
    let mut parts = NewtonParts { mass: vec![0.0; structure.mass.len()], constraint: vec![0.0; structure.constraint.len()], local: s.local_entries().to_vec() };
    newton_parts::fill_mass(m, &mut parts.mass);
    assert!(newton_parts::fill_constraint(m, ws, &mut parts.constraint), "regular constraint factor");
    (structure, parts)
}

/// A right-hand side of `n` entries of one size, signs varying.
fn load(n: usize) -> Vec<f64> {
    (0..n).map(|i| (0.37 * i as f64 + 0.2).sin() + 0.1).collect()
}

/// Dense solve of the row-major `size` square `matrix` for `b`.
fn dense_solve(mut matrix: Vec<f64>, size: usize, b: &[f64]) -> Vec<f64> {
    let mut pivots = vec![0; size];
    lu_factor(&mut matrix, size, &mut pivots).unwrap();
    let mut x = b.to_vec();
    lu_solve(&matrix, size, &pivots, &mut x);
    x
}

/// `max |N x - b| / (max row sum |N| max |x|)`: the backward error of x in the dense matrix N.
fn backward_error(matrix: &[f64], size: usize, x: &[f64], b: &[f64]) -> f64 {
    let norm = (0..size).map(|i| matrix[i * size..(i + 1) * size].iter().map(|a| a.abs()).sum::<f64>()).fold(0.0, f64::max);
    let scale = x.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    (0..size).map(|i| (matrix[i * size..(i + 1) * size].iter().zip(x).map(|(a, x)| a * x).sum::<f64>() - b[i]).abs()).fold(0.0, f64::max) / (norm * scale)
}

/// The sparse solution `x_s` against the dense one `x_d` of the dense matrix N:
/// its backward error in N at most 1e-11 (the dense J carries the rounding of the
/// mass and constraint solves that formed it, a few hundred eps relative to its
/// entries on these models; a missing or wrongly scaled term gives order 1), and
/// `max |x_s - x_d| / max |x_d|` at most 1e-8 (the backward error times the
/// condition numbers of N here, below 1e3).
fn check(name: &str, matrix: &[f64], size: usize, sparse: &[f64], b: &[f64]) {
    let dense = dense_solve(matrix.to_vec(), size, b);
    let backward = backward_error(matrix, size, sparse, b);
    let scale = dense.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let forward = sparse.iter().zip(&dense).map(|(s, d)| (s - d).abs()).fold(0.0, f64::max) / scale;
    assert!(backward <= 1e-11 && forward <= 1e-8, "{name}: backward error {backward:.2e}, forward {forward:.2e}");
}

/// Generalized-alpha's reduced matrix on `r = [v, z]` and the NDF's `I - c J`, sparse
/// against dense, at the steps given.
fn compare(name: &str, m: &Model, t: f64, y: &[f64], steps: &[f64]) {
    let n = y.len();
    let nv = m.layout.nv;
    let p = n - nv;
    let mut ws = Workspace::new(m);
    let (structure, parts) = parts_at(m, t, y, &mut ws);
    let mut dense_ws = Workspace::new(m);
    let (_, jacobian) = structured(m, &m.initial_memory(), t, y, Stabilization::Projection, &mut dense_ws);
    let mut sparse = SparseNewton::new(structure).unwrap();
    sparse.parts = parts;
    assert_eq!(sparse.size(), nv + m.n_dynamic_equations() + m.layout.nz);
    // rho_inf 0.9, as the spin-up example
    let (alpha_m, alpha_f) = ((2.0 * 0.9 - 1.0) / 1.9, 0.9 / 1.9);
    let gamma = 0.5 + alpha_f - alpha_m;
    let beta = 0.25 * (gamma + 0.5) * (gamma + 0.5);
    for &h in steps {
        let (alpha, c_v, c_q) = (1.0 - alpha_m, (1.0 - alpha_f) * h * gamma, (1.0 - alpha_f) * h * h * beta);
        let mut reduced = vec![0.0; p * p];
        for i in 0..p {
            for j in 0..p {
                let mut d = -c_v * jacobian[(nv + i) * n + nv + j];
                if j < nv {
                    d -= c_q * jacobian[(nv + i) * n + j];
                }
                reduced[i * p + j] = d + if i == j { alpha } else { 0.0 };
            }
        }
        sparse.factor(alpha, c_v, c_q).unwrap();
        let b = load(p);
        let mut x = b.clone();
        sparse.solve_reduced(&mut x);
        check(&format!("{name}, generalized-alpha, h = {h}"), &reduced, p, &x, &b);
        // the NDF at c = h / alpha_2 of its order 2
        let c = h / 1.5;
        let mut full = vec![0.0; n * n];
        for (i, row) in full.chunks_exact_mut(n).enumerate() {
            for (j, a) in row.iter_mut().enumerate() {
                *a = -c * jacobian[i * n + j] + if i == j { 1.0 } else { 0.0 };
            }
        }
        sparse.factor(1.0, c, c * c).unwrap();
        let b = load(n);
        let mut x = b.clone();
        sparse.solve_full(c, &mut x);
        check(&format!("{name}, NDF, c = {c}"), &full, n, &x, &b);
    }
}

#[test]
fn on_a_spinning_beam_the_sparse_newton_solve_is_the_dense_one() {
    let m = spin_up_beam(6.0, 6, 0.0);
    let mut y: Vec<f64> = m.initial_coordinates.iter().chain(&m.initial_velocities).chain(&m.initial_element_states).copied().collect();
    let nq = m.layout.nq;
    let beam = m.layout.bodies[1];
    for (k, node) in y[beam.q_range()].chunks_exact_mut(3).enumerate() {
        node[1] += 0.05 * (0.9 * k as f64).sin();
        node[2] += 0.02 * (0.6 * k as f64).cos();
    }
    for rate in y[nq + beam.v..nq + beam.v + beam.nv].chunks_exact_mut(3) {
        rate[1] += 0.3;
    }
    compare("spin-up beam", &m, 2.0, &y, &[1e-3, 1e-2]);
}

#[test]
fn on_a_beam_mechanism_with_a_clearance_joint_and_a_hydraulic_cylinder_the_sparse_newton_solve_is_the_dense_one() {
    let m = mixed();
    assert_eq!(m.layout.nz, 2, "the cylinder's two pressures");
    let y = mixed_state(&m);
    compare("mixed", &m, 0.3, &y, &[1e-4, 1e-3]);
}


/// The statistics of the spin-up beam (quadratic elements) run over 0.5 s with `integrator`.
fn spin_up_run(integrator: crate::integrate::IntegratorOptions) -> crate::integrate::Statistics {
    let m = spin_up_beam(6.0, 4, 0.0);
    jacobian_tests::run(&m, 0.5, integrator, Stabilization::Projection, &[]).1
}

#[test]
fn the_implicit_methods_factor_the_sparse_matrix_on_a_beam() {
    use crate::integrate::{IntegratorOptions, JacobianMethod, Method};
    for method in [Method::GeneralizedAlpha, Method::NumericalDifferentiation] {
        let integrator = IntegratorOptions { method, step: Some(1e-3), jacobian: JacobianMethod::Structured, ..IntegratorOptions::default() };
        let s = spin_up_run(integrator);
        assert!(s.factorizations > 0 && s.sparse_factorizations == s.factorizations, "{method:?}: {s:?}");
    }
}
