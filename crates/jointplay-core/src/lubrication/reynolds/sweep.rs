//! Relaxation sweeps over the grid of [`super::solver::Stencil`].
//!
//! - [`sor`]: Gauss-Seidel with over-relaxation on the full-film equation
//!   (Gümbel), optionally projected onto `p >= 0` after each node update
//!   (projected SOR for the Swift-Stieber complementarity problem,
//!   Cryer 1971);
//! - [`elrod_adams`]: the mass-conserving p-theta switch scheme (Elrod and
//!   Adams 1974, in the two-variable form of Fesanghary and Khonsari 2011):
//!   the Couette flux carries the fill fraction of the upwind node, each node
//!   is full film (`p >= 0`, fill 1) or cavitated (`p = 0`, fill < 1).
//!
//! Each sweep returns the largest change it made (pressure [Pa]; for
//! Elrod-Adams the fill change counts as `scale` times the change).

use super::options::{Cavitation, ReynoldsOptions};
use super::solver::Stencil;

/// The fields a relaxation updates: the pressure [Pa], the unprojected
/// full-film pressure of Gümbel's model [Pa] and the fill fraction [-].
pub(super) struct Fields<'a> {
    pub pressure: &'a mut [f64],
    pub full_film: &'a mut [f64],
    pub fill: &'a mut [f64],
}

/// A pressure scale [Pa] for the convergence test at eccentricity ratio `eps`:
/// the hydrodynamic scale `K (|W| eps + 2 max|Hdot|) / (1 - eps)^2` from the
/// stencil's `k_scale`, spin sum `spin_sum` and squeeze rates `h_rate`, or the
/// ambient or supply pressure when larger.
pub(super) fn pressure_scale(options: &ReynoldsOptions, k_scale: f64, spin_sum: f64, h_rate: &[f64], eps: f64) -> f64 {
    let rate = h_rate.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let hydro = k_scale * (spin_sum.abs() * eps + 2.0 * rate) / (1.0 - eps).powi(2);
    let supply = options.groove.map_or(0.0, |g| g.supply_pressure);
    hydro.max(options.ambient_pressure).max(supply)
}

/// Sweeps of the chosen cavitation model (`sweep` makes one and returns its
/// largest change) until the change is within `options.tolerance` of the
/// field's pressure variation (an ambient level does not count; `scale` [Pa]
/// floors it); Gümbel's field is then clamped at zero. Returns the number of
/// sweeps; an error when they do not converge within `options.max_iterations`
/// or the run is cancelled (Ctrl-C stops inside a long solve, not after it),
/// the fields then left for the caller to reset.
pub(super) fn relax(options: &ReynoldsOptions, scale: f64, fields: Fields<'_>, mut sweep: impl FnMut(&mut Fields<'_>) -> f64) -> Result<usize, String> {
    let mut fields = fields;
    let mut iterations = 0;
    loop {
        iterations += 1;
        let change = sweep(&mut fields);
        let field: &[f64] = if options.cavitation == Cavitation::Gumbel { fields.full_film } else { fields.pressure };
        let (low, high) = field.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(*v), h.max(*v)));
        let peak = high - low;
        if change <= options.tolerance * peak.max(1e-9 * scale) {
            break;
        }
        if !crate::interrupt::keep_going() {
            return Err(crate::interrupt::INTERRUPTED.to_string());
        }
        if iterations >= options.max_iterations || !change.is_finite() {
            return Err(format!("Reynolds solver did not converge in {iterations} sweeps (relative change {:.3e})", change / peak.max(1e-300)));
        }
    }
    if options.cavitation == Cavitation::Gumbel {
        for (p, f) in fields.pressure.iter_mut().zip(fields.full_film.iter()) {
            *p = f.max(0.0);
        }
    }
    Ok(iterations)
}

/// Neighbours of column `i` on the periodic grid.
#[inline]
pub(super) fn neighbours(i: usize, n: usize) -> (usize, usize) {
    (if i == 0 { n - 1 } else { i - 1 }, if i + 1 == n { 0 } else { i + 1 })
}

/// One SOR sweep (projected onto `p >= 0` when `project`); returns the largest change [Pa].
pub fn sor(s: &Stencil, p: &mut [f64], omega: f64, project: bool) -> f64 {
    let (nt, nz) = (s.n_theta, s.n_half);
    let inv_dt2 = 1.0 / (s.dtheta * s.dtheta);
    let mut change: f64 = 0.0;
    for i in 0..nt {
        if i == s.feed_column {
            continue;
        }
        let (im, ip) = neighbours(i, nt);
        let ap = s.h3_face[i] * inv_dt2;
        let am = s.h3_face[im] * inv_dt2;
        let az = s.kappa * s.h3_node[i];
        let inv_diag = 1.0 / (ap + am + 2.0 * az);
        let r = s.rhs[i];
        let (row, rp, rm) = (i * nz, ip * nz, im * nz);
        for j in s.j_free..nz - 1 {
            // mirror node below the mid-plane: p_{-1} = p_1
            let below = if j == 0 { p[row + 1] } else { p[row + j - 1] };
            let gs = (ap * p[rp + j] + am * p[rm + j] + az * (below + p[row + j + 1]) - r) * inv_diag;
            let old = p[row + j];
            let mut new = old + omega * (gs - old);
            if project && new < 0.0 {
                new = 0.0;
            }
            p[row + j] = new;
            change = change.max((new - old).abs());
        }
    }
    change
}

/// One Elrod-Adams sweep in the direction of the mean surface motion; returns the largest change [Pa].
pub fn elrod_adams(s: &Stencil, p: &mut [f64], fill: &mut [f64], omega: f64, scale: f64) -> f64 {
    let nt = s.n_theta;
    let mut change: f64 = 0.0;
    if s.spin_sum >= 0.0 {
        for i in 0..nt {
            change = change.max(elrod_column(s, p, fill, omega, scale, i));
        }
    } else {
        for i in (0..nt).rev() {
            change = change.max(elrod_column(s, p, fill, omega, scale, i));
        }
    }
    change
}

/// Elrod-Adams update of column `i`.
fn elrod_column(s: &Stencil, p: &mut [f64], fill: &mut [f64], omega: f64, scale: f64, i: usize) -> f64 {
    if i == s.feed_column {
        return 0.0;
    }
    let (nt, nz) = (s.n_theta, s.n_half);
    let (im, ip) = neighbours(i, nt);
    let inv_dt2 = 1.0 / (s.dtheta * s.dtheta);
    let ap = s.h3_face[i] * inv_dt2;
    let am = s.h3_face[im] * inv_dt2;
    let az = s.kappa * s.h3_node[i];
    let inv_diag = 1.0 / (ap + am + 2.0 * az);
    let (k, w) = (s.k_scale, s.spin_sum);
    // coefficient of the own fill fraction, and the upwind face (its H and column)
    let squeeze = 2.0 * k * s.h_rate[i];
    let (a, up_face, up_col, up_sign) = if w >= 0.0 {
        (k * w * s.h_face[i] / s.dtheta + squeeze, s.h_face[im], im, -1.0)
    } else {
        (-k * w * s.h_face[im] / s.dtheta + squeeze, s.h_face[i], ip, 1.0)
    };
    let b_unit = up_sign * k * w * up_face / s.dtheta;
    let (row, rp, rm, ru) = (i * nz, ip * nz, im * nz, up_col * nz);
    let mut change: f64 = 0.0;
    for j in s.j_free..nz - 1 {
        let below = if j == 0 { p[row + 1] } else { p[row + j - 1] };
        let n = ap * p[rp + j] + am * p[rm + j] + az * (below + p[row + j + 1]);
        let b = b_unit * fill[ru + j];
        let full = (n - a - b) * inv_diag;
        let (old_p, old_f) = (p[row + j], fill[row + j]);
        if full > 0.0 {
            // full film: relax the pressure
            p[row + j] = (old_p + omega * (full - old_p)).max(0.0);
            fill[row + j] = 1.0;
        } else {
            // cavitated: zero pressure, fill fraction from the mass balance
            p[row + j] = 0.0;
            fill[row + j] = if a > 0.0 { ((n - b) / a).clamp(0.0, 1.0) } else { 1.0 };
        }
        change = change.max((p[row + j] - old_p).abs()).max(scale * (fill[row + j] - old_f).abs());
    }
    change
}

/// Largest `|min(p, s)|` over the free nodes relative to the peak pressure [-],
/// with `s = (rhs - L(p)) / diag` the complementary slack as a pressure.
pub fn complementarity(s: &Stencil, p: &[f64]) -> f64 {
    let (nt, nz) = (s.n_theta, s.n_half);
    let inv_dt2 = 1.0 / (s.dtheta * s.dtheta);
    let peak = p.iter().fold(0.0_f64, |m, v| m.max(*v)).max(1e-300);
    let mut worst: f64 = 0.0;
    for i in (0..nt).filter(|i| *i != s.feed_column) {
        let (im, ip) = neighbours(i, nt);
        let ap = s.h3_face[i] * inv_dt2;
        let am = s.h3_face[im] * inv_dt2;
        let az = s.kappa * s.h3_node[i];
        let diag = ap + am + 2.0 * az;
        for j in s.j_free..nz - 1 {
            let below = if j == 0 { p[i * nz + 1] } else { p[i * nz + j - 1] };
            let lp = ap * p[ip * nz + j] + am * p[im * nz + j] + az * (below + p[i * nz + j + 1]) - diag * p[i * nz + j];
            let slack = (s.rhs[i] - lp) / diag;
            worst = worst.max(p[i * nz + j].min(slack).abs()).max((-p[i * nz + j]).max(0.0));
        }
    }
    worst / peak
}
