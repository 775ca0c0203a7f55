//! Solution of the constraint system `S x = b`, `S = Phi_q M^-1 Phi_q^T`,
//! at regular, singular and redundant configurations
//! (`docs/theory/planar-formulation.md`, "Constraint solution").
//!
//! - **Regular** (every pivot of `S` above [`crate::linalg::RELATIVE_PIVOT_TOLERANCE`] of its
//!   largest diagonal entry): `L D L^T` of `S` by the elimination program of its
//!   pattern, one solve.
//! - **Singular or redundant** (a pivot below that: dependent equations, a
//!   linkage at or near its flat or toggle position): the augmented Lagrangian
//!   iteration of Bayo, García de Jalón and Serna (1988) in its dual form,
//!   `x_{k+1} = x_k + (S + eps I)^-1 (b - S x_k)` from `x_0 = 0`, `eps = 1/alpha`
//!   the inverse penalty, taken [`AUGMENTED_LAGRANGIAN_ITERATIONS`] times. On the
//!   eigendecomposition `S = V diag(s) V^T` (cyclic Jacobi rotations: a
//!   rank-revealing factorisation, Golub and Van Loan, *Matrix Computations*,
//!   4th ed., §8.5) those iterations have the closed form
//!   `x = V diag((1 - (eps/(s_i + eps))^k) / s_i) V^T b`. Every iterate lies in the
//!   range of `S`: for redundant equations (`s_i = 0`) the reactions are the
//!   Lagrange multipliers of least Euclidean norm, the stated choice. Along a
//!   direction that is nearly dependent (`s_i` below `eps`, a linkage within about
//!   3e-3 rad of its flat position), the multiplier is bounded by `k b_i / eps`
//!   instead of `b_i / s_i`, which would amplify round-off and the small velocity
//!   error of the step without bound: the constraint there is kept by a stiff
//!   penalty and by the drift projection after the step, so the motion goes on
//!   along its branch.

use crate::dynamics::model::constraint_jacobian::{dot, JacobianBlock};
use crate::dynamics::model::mechanism::SchurTerm;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::body::BodyModel;
use crate::linalg::{cholesky_solve, RankDeficiency};

/// Inverse penalty `eps` relative to the largest eigenvalue of `S`. Chosen by
/// experiment on a parallelogram four-bar that passes its flat position ten
/// times (`tests/physics/test_singular_four_bar.py`): 1e-6 and below let the
/// amplified velocity error grow at tight tolerances, 1e-4 softens the linkage
/// so much that the step size collapses.
const INVERSE_PENALTY: f64 = 1e-5;

/// Augmented Lagrangian iterations `k`: directions with `s_i > 100 eps` are
/// then solved to `(1/100)^k`, exactly in double precision.
const AUGMENTED_LAGRANGIAN_ITERATIONS: i32 = 20;

/// An eigenvalue below this fraction of the largest is zero (a redundant equation, to round-off).
const ZERO_EIGENVALUE: f64 = 1e-13;

/// Jacobi sweeps allowed: each sweep squares the off-diagonal size once the
/// rotations have settled; ten are plenty for the small matrices of a mechanism.
const MAX_SWEEPS: usize = 30;

/// How the factor in `Workspace::schur` was made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FactorKind {
    /// `L D L^T` of the dynamic rows by [`Model::schur_factor`].
    Pattern,
    /// Dense Cholesky of `S` (other row counts: assembly with the clearance locks).
    Dense,
    /// Eigendecomposition of `S` (singular path): eigenvectors in `Workspace::schur`
    /// (column-major), eigenvalues in `Workspace::schur_eigenvalues`.
    Spectral,
}

/// Value of one precomputed term of `S`: row a's block times `M_c^-1` times row b's block.
#[inline]
fn term_value(term: &SchurTerm, blocks: &[JacobianBlock], values: &[f64], solved: &[f64]) -> f64 {
    let (a, b) = (&blocks[term.first as usize], &blocks[term.second as usize]);
    let start = b.solved + a.offset_in_body;
    dot(&values[a.values()], &solved[start..start + a.width])
}

/// The same with a diagonal `M^-1`: the sum over the blocks' common columns.
#[inline(always)]
fn diagonal_term_value(term: &SchurTerm, values: &[f64], inverse_mass: &[f64]) -> f64 {
    let (a, b, c, n) = (term.first_value as usize, term.second_value as usize, term.column_start as usize, term.common as usize);
    if n == 3 {
        // (the planar rigid body's blocks: unrolled)
        let (ja, jb, w) = (&values[a..a + 3], &values[b..b + 3], &inverse_mass[c..c + 3]);
        return ja[0] * w[0] * jb[0] + ja[1] * w[1] * jb[1] + ja[2] * w[2] * jb[2];
    }
    (0..n).map(|i| values[a + i] * inverse_mass[c + i] * values[b + i]).sum()
}

/// Adds the terms of the first `rows` rows of `S` into `out` at the index `at(term)`.
fn add_terms(model: &Model, rows: usize, q: &[f64], ws: &mut Workspace, out: &mut [f64], at: impl Fn(&SchurTerm) -> usize) {
    let terms = model.schur_terms.iter().take_while(|term| (term.row as usize) < rows);
    match &model.diagonal_inverse_mass {
        Some(w) => terms.for_each(|term| out[at(term)] += diagonal_term_value(term, &ws.jacobian, w)),
        None => {
            solve_blocks_with_mass(model, rows, q, ws);
            let blocks = model.jacobian_pattern.blocks();
            terms.for_each(|term| out[at(term)] += term_value(term, blocks, &ws.jacobian, &ws.jacobian_solved));
        }
    }
}

/// `M_c^-1 J_c^T` of every block of the first `rows` rows into `ws.jacobian_solved`, each over
/// all velocity coordinates of its body `c` (the block widened by zeros), with the body kind's solve
/// at the positions `q`.
fn solve_blocks_with_mass(model: &Model, rows: usize, q: &[f64], ws: &mut Workspace) {
    for block in model.jacobian_pattern.blocks_of_rows(rows) {
        let kind = &model.bodies[block.body].kind;
        let address = &model.layout.bodies[block.body];
        let nv = address.nv;
        let widened = &mut ws.mass_scratch[..nv];
        widened.fill(0.0);
        widened[block.offset_in_body..block.offset_in_body + block.width].copy_from_slice(&ws.jacobian[block.values()]);
        kind.solve_mass(&q[address.q_range()], widened, &mut ws.jacobian_solved[block.solved..block.solved + nv], &mut ws.mass_matrix);
    }
}

/// Forms the lower triangle of `S` for the first `rows` rows, row-major `rows x rows`, into `out`.
fn form_dense(model: &Model, rows: usize, q: &[f64], ws: &mut Workspace, out: &mut [f64]) {
    let out = &mut out[..rows * rows];
    out.fill(0.0);
    add_terms(model, rows, q, ws, out, |term| term.row as usize * rows + term.column as usize);
}

/// Factors `S` for the first `rows` rows: the regular path when it is well
/// conditioned, else the regularised factor of the singular path. Fails only
/// when `S` is not finite or the regularised factor has a non-positive pivot.
pub(crate) fn factor(model: &Model, rows: usize, q: &[f64], ws: &mut Workspace) -> Result<FactorKind, RankDeficiency> {
    let kind = match factor_regular(model, rows, q, ws) {
        Ok(kind) => kind,
        Err(_) => {
            factor_spectral(model, rows, q, ws)?;
            ws.singular_solves += 1;
            FactorKind::Spectral
        }
    };
    ws.factor_kind = kind;
    Ok(kind)
}

/// The regular path: patterned `L D L^T` of the dynamic rows or dense Cholesky.
fn factor_regular(model: &Model, rows: usize, q: &[f64], ws: &mut Workspace) -> Result<FactorKind, RankDeficiency> {
    if rows == model.schur_factor.size() {
        // only the factor's stored values: clearing costs what factoring does, not rows^2
        let stored = model.schur_factor.storage_len();
        let mut schur = std::mem::take(&mut ws.schur);
        schur[..stored].fill(0.0);
        add_terms(model, rows, q, ws, &mut schur, |term| term.entry as usize);
        let factored = model.schur_factor.factor(&mut schur[..stored]);
        ws.schur = schur;
        factored?;
        Ok(FactorKind::Pattern)
    } else {
        let mut schur = std::mem::take(&mut ws.schur);
        form_dense(model, rows, q, ws, &mut schur);
        let factored = crate::linalg::cholesky_factor(&mut schur, rows);
        ws.schur = schur;
        factored?;
        Ok(FactorKind::Dense)
    }
}

/// The eigendecomposition of `S` into `ws.schur` (eigenvectors) and `ws.schur_eigenvalues`.
fn factor_spectral(model: &Model, rows: usize, q: &[f64], ws: &mut Workspace) -> Result<(), RankDeficiency> {
    let mut matrix = std::mem::take(&mut ws.schur_matrix);
    form_dense(model, rows, q, ws, &mut matrix);
    ws.schur_matrix = matrix;
    let a = &mut ws.schur_matrix[..rows * rows];
    for i in 0..rows {
        for j in 0..i {
            a[j * rows + i] = a[i * rows + j];
        }
    }
    if !a.iter().all(|v| v.is_finite()) {
        return Err(RankDeficiency { row: 0, relative_pivot: f64::NAN });
    }
    symmetric_eigen(a, rows, &mut ws.schur[..rows * rows]);
    for i in 0..rows {
        ws.schur_eigenvalues[i] = a[i * rows + i];
    }
    Ok(())
}

/// Cyclic Jacobi: diagonalises the symmetric `n x n` matrix `a` (row-major, both
/// triangles) in place, its eigenvectors into the columns of `v` (row-major).
fn symmetric_eigen(a: &mut [f64], n: usize, v: &mut [f64]) {
    v.fill(0.0);
    for i in 0..n {
        v[i * n + i] = 1.0;
    }
    let norm: f64 = a.iter().map(|x| x * x).sum::<f64>().sqrt();
    for _ in 0..MAX_SWEEPS {
        let off: f64 = (0..n).flat_map(|i| (0..n).filter(move |&j| j != i).map(move |j| (i, j))).map(|(i, j)| a[i * n + j] * a[i * n + j]).sum::<f64>().sqrt();
        if off <= f64::EPSILON * norm {
            return;
        }
        for p in 0..n {
            for q in (p + 1)..n {
                rotate(a, v, n, p, q);
            }
        }
    }
}

/// One Jacobi rotation zeroing `a[p][q]` (Golub and Van Loan, Algorithm 8.5.1).
fn rotate(a: &mut [f64], v: &mut [f64], n: usize, p: usize, q: usize) {
    let apq = a[p * n + q];
    if apq == 0.0 {
        return;
    }
    let tau = (a[q * n + q] - a[p * n + p]) / (2.0 * apq);
    let t = tau.signum() / (tau.abs() + (1.0 + tau * tau).sqrt());
    let t = if tau == 0.0 { 1.0 } else { t };
    let c = 1.0 / (1.0 + t * t).sqrt();
    let s = t * c;
    for k in 0..n {
        // columns p and q of A J
        let (akp, akq) = (a[k * n + p], a[k * n + q]);
        a[k * n + p] = c * akp - s * akq;
        a[k * n + q] = s * akp + c * akq;
    }
    for k in 0..n {
        // rows p and q of J^T (A J)
        let (apk, aqk) = (a[p * n + k], a[q * n + k]);
        a[p * n + k] = c * apk - s * aqk;
        a[q * n + k] = s * apk + c * aqk;
    }
    for k in 0..n {
        let (vkp, vkq) = (v[k * n + p], v[k * n + q]);
        v[k * n + p] = c * vkp - s * vkq;
        v[k * n + q] = s * vkp + c * vkq;
    }
}

/// Solves `S x = b` in place for the first `rows` rows with the factor in
/// `ws.schur` (made by [`factor`]); on the singular path `x` is the augmented
/// Lagrangian solution (minimum norm for redundant equations).
pub(crate) fn solve(model: &Model, rows: usize, ws: &mut Workspace, b: &mut [f64]) {
    match ws.factor_kind {
        FactorKind::Pattern => model.schur_factor.solve(&ws.schur, &mut b[..rows]),
        FactorKind::Dense => cholesky_solve(&ws.schur[..rows * rows], rows, &mut b[..rows]),
        FactorKind::Spectral => solve_spectral(rows, ws, b),
    }
}

/// `x = V diag((1 - (eps/(s_i + eps))^k) / s_i) V^T b`, 0 along zero eigenvalues.
fn solve_spectral(rows: usize, ws: &mut Workspace, b: &mut [f64]) {
    let (v, values) = (&ws.schur[..rows * rows], &ws.schur_eigenvalues[..rows]);
    let largest = values.iter().fold(0.0_f64, |m, s| m.max(s.abs()));
    let eps = INVERSE_PENALTY * largest;
    let coefficients = &mut ws.solve_scratch[..rows];
    for (i, c) in coefficients.iter_mut().enumerate() {
        let s = values[i];
        let projection: f64 = (0..rows).map(|k| v[k * rows + i] * b[k]).sum();
        *c = if s > ZERO_EIGENVALUE * largest { (1.0 - (eps / (s + eps)).powi(AUGMENTED_LAGRANGIAN_ITERATIONS)) * projection / s } else { 0.0 };
    }
    for k in 0..rows {
        b[k] = (0..rows).map(|i| v[k * rows + i] * coefficients[i]).sum();
    }
}
