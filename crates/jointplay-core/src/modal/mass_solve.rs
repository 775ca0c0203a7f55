//! The solve with a modal body's body-frame mass `Mbar(eta)` without factoring
//! it at every evaluation: the modal block is constant and factored once, and
//! only the 3 x 3 Schur complement of the frame's coordinates changes with the
//! amplitudes `eta`, through matrices formed once from the inertia invariants.
//!
//! With the frame's coordinates `r = (x, y, phi)` and the modes `f` (theory:
//! `docs/theory/modal-body.md`, *Solving with the mass*):
//!
//! ```text
//! Mbar = [ M_rr(eta)  M_rf(eta) ]    M_rr = [ m I     b(eta) ]    M_rf = [ S_t      ]    M_ff = M_ee
//!        [ M_fr(eta)  M_ff      ]           [ b^T     J(eta) ]           [ h(eta)^T ]
//! ```
//!
//! `b = a_0 + A_1 eta`, `J = I_0 + 2 I_1 . eta + eta^T I_2 eta`, `h = h_0 + H_1^T eta`.
//! Block elimination of the modes (Golub and Van Loan, *Matrix Computations*,
//! 4th ed., 2013, §3.2.10, block LU): with `C = M_ff^-1 M_fr = [C_t, c(eta)]`,
//! `C_t = M_ee^-1 S_t^T` constant and `c = M_ee^-1 h = g_0 + G eta`
//! (`g_0 = M_ee^-1 h_0`, `G = M_ee^-1 H_1^T`), the Schur complement
//! `S = M_rr - M_rf C` is
//!
//! ```text
//! S = [ P             k(eta) ]    P = m I - S_t C_t                        (constant)
//!     [ k(eta)^T      s(eta) ]    k = (a_0 - S_t g_0) + (A_1 - S_t G) eta  (linear)
//!                                 s = j_0 + 2 j_1 . eta + eta^T Q eta      (quadratic)
//! ```
//!
//! with `j_0 = I_0 - h_0 . g_0`, `j_1 = I_1 - H_1 g_0`, `Q = I_2 - H_1 G`; all
//! exact (no expansion in `eta` is truncated). `Mbar x = g` is then
//! `x_r = S^-1 (g_r - [C_t^T g_f; c . g_f])` and
//! `x_f = M_ee^-1 g_f - C_t x_(x,y) - c x_phi`: per solve, `G eta` and
//! `eta^T Q eta` (`1.5 m^2` multiply-adds, `Q` symmetric), the constant
//! factor's two triangular solves (`m^2`), and O(m) for the rest.

use nalgebra::{DMatrix, DVector};

use crate::linalg::{cholesky_factor, RELATIVE_PIVOT_TOLERANCE};

use super::dense::{dot, solve_lower, solve_upper};
use super::InertiaInvariants;

/// The constant parts of the block solve with `Mbar(eta)`, matrices row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyMassSolve {
    /// Number of modes `m`.
    n_modes: usize,
    /// Cholesky factor `L` of the modal mass `M_ee = L L^T` (m x m, the layout
    /// of [`crate::linalg::cholesky_factor`]: lower triangle, inverse diagonal).
    modal_factor: Vec<f64>,
    /// Its transpose `L^T`, so that both triangular solves read rows.
    modal_factor_transposed: Vec<f64>,
    /// `C_t = M_ee^-1 S_t^T`, its x column then its y column (2 m) [m / unit].
    translation_coupling: Vec<f64>,
    /// `g_0 = M_ee^-1 h_0` (m) [unit].
    rotation_coupling: Vec<f64>,
    /// `G = M_ee^-1 H_1^T` (m x m) [-].
    rotation_coupling_modes: Vec<f64>,
    /// `P^-1 = (m I - S_t C_t)^-1` (2 x 2) [1/kg].
    translation_inverse: [f64; 4],
    /// `a_0 - S_t g_0` [kg m].
    frame_coupling: [f64; 2],
    /// `A_1 - S_t G` (2 x m) [kg m / unit].
    frame_coupling_modes: Vec<f64>,
    /// `j_0 = I_0 - h_0 . g_0` [kg m^2].
    inertia: f64,
    /// `j_1 = I_1 - H_1 g_0` (m) [kg m^2 / unit].
    inertia_linear: Vec<f64>,
    /// `Q = I_2 - H_1 G` (m x m, symmetric) [kg m^2 / unit^2].
    inertia_quadratic: Vec<f64>,
}

/// Row-major values of a matrix.
fn row_major(a: &DMatrix<f64>) -> Vec<f64> {
    a.transpose().iter().copied().collect()
}

impl BodyMassSolve {
    /// The solve for the body of the invariants `inv`; an error when its modal
    /// mass or the translational mass left to the frame is not positive
    /// definite (modes that depend on each other or carry a rigid translation).
    pub fn new(inv: &InertiaInvariants) -> Result<Self, String> {
        let m = inv.n_modes;
        let modal_mass = DMatrix::from_row_slice(m, m, &inv.modal_mass);
        let mut modal_factor = inv.modal_mass.clone();
        if let Err(e) = cholesky_factor(&mut modal_factor, m) {
            return Err(format!("the modes' mass matrix is singular: mode {} depends on the modes before it (relative pivot {:.1e})", e.row + 1, e.relative_pivot));
        }
        let cholesky = modal_mass.cholesky().ok_or("the modes' mass matrix is not positive definite")?;
        let first_moment = DMatrix::from_row_slice(2, m, &inv.first_moment_modes);
        let rotation_linear = DMatrix::from_row_slice(m, m, &inv.modal_rotation_linear);
        let translation_coupling = cholesky.solve(&first_moment.transpose());
        let rotation_coupling = cholesky.solve(&DVector::from_column_slice(&inv.modal_rotation));
        let rotation_coupling_modes = cholesky.solve(&rotation_linear.transpose());
        let p = DMatrix::identity(2, 2) * inv.mass - &first_moment * &translation_coupling;
        // (its two pivots: the translational mass the modes leave to the frame, in x and then in y)
        let off = 0.5 * (p[(0, 1)] + p[(1, 0)]);
        let determinant = p[(0, 0)] * p[(1, 1)] - off * off;
        let smallest = p[(0, 0)].min(determinant / p[(0, 0)]);
        if !(smallest > RELATIVE_PIVOT_TOLERANCE * inv.mass) {
            return Err(format!("the modes carry a rigid translation of the body: {smallest:.3e} kg of its {} kg is left to its frame", inv.mass));
        }
        let frame_coupling = DVector::from_column_slice(&[inv.rotation_coupling.x, inv.rotation_coupling.y]) - &first_moment * &rotation_coupling;
        let frame_coupling_modes = DMatrix::from_row_slice(2, m, &inv.rotation_coupling_modes) - &first_moment * &rotation_coupling_modes;
        let inertia_quadratic = DMatrix::from_row_slice(m, m, &inv.inertia_quadratic) - &rotation_linear * &rotation_coupling_modes;
        let modal_factor_transposed = (0..m * m).map(|k| if k / m <= k % m { modal_factor[(k % m) * m + k / m] } else { 0.0 }).collect();
        Ok(Self {
            n_modes: m,
            modal_factor,
            modal_factor_transposed,
            translation_coupling: translation_coupling.iter().copied().collect(),
            rotation_coupling: rotation_coupling.iter().copied().collect(),
            rotation_coupling_modes: row_major(&rotation_coupling_modes),
            translation_inverse: [p[(1, 1)] / determinant, -off / determinant, -off / determinant, p[(0, 0)] / determinant],
            frame_coupling: [frame_coupling[0], frame_coupling[1]],
            frame_coupling_modes: row_major(&frame_coupling_modes),
            inertia: inv.inertia - DVector::from_column_slice(&inv.modal_rotation).dot(&rotation_coupling),
            inertia_linear: (DVector::from_column_slice(&inv.inertia_linear) - &rotation_linear * &rotation_coupling).iter().copied().collect(),
            inertia_quadratic: row_major(&(0.5 * (&inertia_quadratic + inertia_quadratic.transpose()))),
        })
    }

    /// Values of `work` [`Self::solve`] needs: `m`.
    pub fn work_len(&self) -> usize {
        self.n_modes
    }

    /// `g <- Mbar(eta)^-1 g` over the `3 + m` body-frame coordinates, with
    /// `work` of at least [`Self::work_len`] values. `false` (and `g` left
    /// unsolved) when the frame's rotational pivot is not positive: a
    /// non-finite `eta`, or one so large that the mass is no longer definite.
    pub fn solve(&self, eta: &[f64], g: &mut [f64], work: &mut [f64]) -> bool {
        let m = self.n_modes;
        let (rigid, modal) = g[..3 + m].split_at_mut(3);
        let coupling = &mut work[..m];
        // c = g_0 + G eta, and eta^T Q eta from Q's upper triangle, in one pass over the rows
        let mut quadratic = 0.0;
        for (i, c) in coupling.iter_mut().enumerate() {
            *c = self.rotation_coupling[i] + dot(&self.rotation_coupling_modes[i * m..(i + 1) * m], eta);
            let upper = dot(&self.inertia_quadratic[i * m + i + 1..(i + 1) * m], &eta[i + 1..m]);
            quadratic += eta[i] * (self.inertia_quadratic[i * m + i] * eta[i] + 2.0 * upper);
        }
        let s = self.inertia + 2.0 * dot(&self.inertia_linear, eta) + quadratic;
        let k = [self.frame_coupling[0] + dot(&self.frame_coupling_modes[..m], eta), self.frame_coupling[1] + dot(&self.frame_coupling_modes[m..], eta)];
        // the frame's right-hand side less what the modes take: g_r - M_rf M_ee^-1 g_f
        let (tx, ty) = self.translation_coupling.split_at(m);
        let r = [rigid[0] - dot(tx, modal), rigid[1] - dot(ty, modal), rigid[2] - dot(coupling, modal)];
        // S x_r = r by the constant 2 x 2 block: w = P^-1 k, pivot s - k . w
        let p = &self.translation_inverse;
        let times_p = |a: [f64; 2]| [p[0] * a[0] + p[1] * a[1], p[2] * a[0] + p[3] * a[1]];
        let w = times_p(k);
        let pivot = s - k[0] * w[0] - k[1] * w[1];
        if !(pivot > RELATIVE_PIVOT_TOLERANCE * s) {
            return false;
        }
        let angle = (r[2] - w[0] * r[0] - w[1] * r[1]) / pivot;
        let pr = times_p([r[0], r[1]]);
        let frame = [pr[0] - w[0] * angle, pr[1] - w[1] * angle, angle];
        // x_f = M_ee^-1 g_f - C_t x_(x,y) - c x_phi
        solve_lower(&self.modal_factor, m, modal);
        solve_upper(&self.modal_factor_transposed, m, modal);
        for (i, x) in modal.iter_mut().enumerate() {
            *x -= tx[i] * frame[0] + ty[i] * frame[1] + coupling[i] * frame[2];
        }
        rigid.copy_from_slice(&frame);
        true
    }
}
