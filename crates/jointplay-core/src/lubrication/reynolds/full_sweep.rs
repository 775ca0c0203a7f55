//! Relaxation sweeps over the full-length grid of
//! [`super::full_length::FullStencil`]: the same schemes as [`super::sweep`]
//! (SOR, projected SOR for Swift-Stieber, the Elrod-Adams p-theta switch)
//! with the film thickness varying from row to row and the axial
//! coefficients taken at the faces `j +- 1/2`.
//!
//! Each sweep returns the largest change it made (pressure [Pa]; for
//! Elrod-Adams the fill change counts as `scale` times the change).

use super::full_length::FullStencil;
use super::sweep::neighbours;

/// Off-diagonal coefficients of node (i, j) and the inverse of its diagonal.
struct Coefficients {
    /// Towards i + 1, i - 1, j + 1, j - 1 [-].
    plus: f64,
    minus: f64,
    up: f64,
    down: f64,
    inv_diag: f64,
}

#[inline]
fn coefficients(s: &FullStencil, n: usize, m: usize, inv_dt2: f64) -> Coefficients {
    let plus = s.h3_face[n] * inv_dt2;
    let minus = s.h3_face[m] * inv_dt2;
    let up = s.kappa * s.h3_axial[n];
    let down = s.kappa * s.h3_axial[n - 1];
    Coefficients { plus, minus, up, down, inv_diag: 1.0 / (plus + minus + up + down) }
}

/// Weighted sum of the four neighbours of node `n` (column `i`, its neighbours' rows `rp`, `rm`, row `j`).
#[inline]
fn neighbour_sum(a: &Coefficients, p: &[f64], n: usize, rp: usize, rm: usize) -> f64 {
    a.plus * p[rp] + a.minus * p[rm] + a.up * p[n + 1] + a.down * p[n - 1]
}

/// One SOR sweep (projected onto `p >= 0` when `project`); returns the largest change [Pa].
pub fn sor(s: &FullStencil, p: &mut [f64], omega: f64, project: bool) -> f64 {
    let (nt, nz) = (s.n_theta, s.n_rows);
    let inv_dt2 = 1.0 / (s.dtheta * s.dtheta);
    let mut change: f64 = 0.0;
    for i in (0..nt).filter(|i| *i != s.feed_column) {
        let (im, ip) = neighbours(i, nt);
        for j in (1..nz - 1).filter(|j| !s.row_fixed[*j]) {
            let n = i * nz + j;
            let a = coefficients(s, n, im * nz + j, inv_dt2);
            let gs = (neighbour_sum(&a, p, n, ip * nz + j, im * nz + j) - s.rhs[n]) * a.inv_diag;
            let old = p[n];
            let mut new = old + omega * (gs - old);
            if project && new < 0.0 {
                new = 0.0;
            }
            p[n] = new;
            change = change.max((new - old).abs());
        }
    }
    change
}

/// One Elrod-Adams sweep in the direction of the mean surface motion; returns the largest change [Pa].
pub fn elrod_adams(s: &FullStencil, p: &mut [f64], fill: &mut [f64], omega: f64, scale: f64) -> f64 {
    let mut change: f64 = 0.0;
    if s.spin_sum >= 0.0 {
        for i in 0..s.n_theta {
            change = change.max(elrod_column(s, p, fill, omega, scale, i));
        }
    } else {
        for i in (0..s.n_theta).rev() {
            change = change.max(elrod_column(s, p, fill, omega, scale, i));
        }
    }
    change
}

/// Elrod-Adams update of column `i` (the scheme of [`super::sweep::elrod_adams`], node by node).
fn elrod_column(s: &FullStencil, p: &mut [f64], fill: &mut [f64], omega: f64, scale: f64, i: usize) -> f64 {
    if i == s.feed_column {
        return 0.0;
    }
    let (nt, nz) = (s.n_theta, s.n_rows);
    let (im, ip) = neighbours(i, nt);
    let inv_dt2 = 1.0 / (s.dtheta * s.dtheta);
    let (k, w) = (s.k_scale, s.spin_sum);
    let mut change: f64 = 0.0;
    for j in (1..nz - 1).filter(|j| !s.row_fixed[*j]) {
        let (n, m, q) = (i * nz + j, im * nz + j, ip * nz + j);
        let c = coefficients(s, n, m, inv_dt2);
        // coefficient of the own fill fraction, and the upwind face's Couette flux per unit fill
        let squeeze = 2.0 * k * s.h_rate[n];
        let (a, b_unit, up) = if w >= 0.0 {
            (k * w * s.h_face[n] / s.dtheta + squeeze, -k * w * s.h_face[m] / s.dtheta, m)
        } else {
            (-k * w * s.h_face[m] / s.dtheta + squeeze, k * w * s.h_face[n] / s.dtheta, q)
        };
        let sum = neighbour_sum(&c, p, n, q, m);
        let b = b_unit * fill[up];
        let full = (sum - a - b) * c.inv_diag;
        let (old_p, old_f) = (p[n], fill[n]);
        if full > 0.0 {
            // full film: relax the pressure
            p[n] = (old_p + omega * (full - old_p)).max(0.0);
            fill[n] = 1.0;
        } else {
            // cavitated: zero pressure, fill fraction from the mass balance
            p[n] = 0.0;
            fill[n] = if a > 0.0 { ((sum - b) / a).clamp(0.0, 1.0) } else { 1.0 };
        }
        change = change.max((p[n] - old_p).abs()).max(scale * (fill[n] - old_f).abs());
    }
    change
}
