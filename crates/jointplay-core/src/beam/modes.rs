//! Small vibrations of a structure about a configuration: the generalised
//! symmetric eigenproblem `K x = w^2 M x` with some coordinates held at zero.
//!
//! `M` (symmetric positive definite on the free coordinates) is factored
//! `M = L L^T` and the standard problem `(L^-1 K L^-T) y = w^2 y`, `x = L^-T y`,
//! solved by nalgebra's symmetric eigensolver (Golub and Van Loan, Matrix
//! Computations, 4th ed., §8.7.2). Dense: meant for one body's mesh at a time
//! (a few thousand coordinates at most), once before a run.

use nalgebra::{DMatrix, SymmetricEigen};

/// Natural modes, lowest frequency first.
#[derive(Clone, Debug)]
pub struct VibrationModes {
    /// Angular frequencies `w` [rad/s] (rigid modes give about 0).
    pub angular_frequencies: Vec<f64>,
    /// Mode shapes as columns over all coordinates (held ones zero), scaled to
    /// unit modal mass `x^T M x = 1`.
    pub shapes: DMatrix<f64>,
}

/// The modes of `K x = w^2 M x` with the coordinates `held` fixed; an error
/// when `M` is not positive definite on the free coordinates.
pub fn vibration_modes(mass: &DMatrix<f64>, stiffness: &DMatrix<f64>, held: &[usize]) -> Result<VibrationModes, String> {
    let n = mass.nrows();
    let free: Vec<usize> = (0..n).filter(|i| !held.contains(i)).collect();
    let pick = |a: &DMatrix<f64>| DMatrix::from_fn(free.len(), free.len(), |r, c| a[(free[r], free[c])]);
    let (k, m) = (pick(stiffness), pick(mass));
    let l = m.cholesky().ok_or("the mass matrix is not positive definite on the free coordinates")?.l();
    let l_inv = l.try_inverse().ok_or("the mass matrix is singular")?;
    let c = &l_inv * k * l_inv.transpose();
    let eigen = SymmetricEigen::new((&c + c.transpose()) * 0.5);
    let free_shapes = l_inv.transpose() * eigen.eigenvectors;
    let mut order: Vec<usize> = (0..free.len()).collect();
    order.sort_by(|&a, &b| eigen.eigenvalues[a].total_cmp(&eigen.eigenvalues[b]));
    let mut shapes = DMatrix::zeros(n, free.len());
    for (column, &j) in order.iter().enumerate() {
        for (r, &i) in free.iter().enumerate() {
            shapes[(i, column)] = free_shapes[(r, j)];
        }
    }
    let angular_frequencies = order.iter().map(|&j| eigen.eigenvalues[j].max(0.0).sqrt()).collect();
    Ok(VibrationModes { angular_frequencies, shapes })
}
