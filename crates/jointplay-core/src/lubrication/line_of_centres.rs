//! The line-of-centres frame of a journal bearing and the film integrals
//! every closed-form model is built from.
//!
//! With `phi = theta - gamma` measured from the line of centres (the
//! direction of `e`, where the film is thinnest), the film of `film.rs` is
//! `h = c D(phi)`, `D = 1 - eps cos(phi)`, and the right-hand side of the
//! Reynolds equation becomes, exactly,
//! `6 mu c [eps wbar sin(phi) - 2 eps_dot cos(phi)]` per unit `R^2` in `phi`,
//! with the wedge speed `wbar = omega_j + omega_b - 2 gamma_dot`. The factor
//! 2 in front of `gamma_dot` comes from `dh/dt = -e_dot . u`, whose
//! tangential part `-|e| gamma_dot sin(phi)` is twice the rate at which the
//! mean surface speed `R (omega_j + omega_b)/2` sweeps the wedge.
//! Every model therefore depends on the state only through `eps`,
//! `eps_dot` and the product `eps wbar` ([`LineOfCentres`]), which stays
//! defined when `e = 0` although `gamma_dot` does not.
//!
//! The integrals `int f(phi) / D^3 dphi` over any interval are evaluated in
//! closed form with the Sommerfeld substitution
//! `cos(psi) = (cos(phi) - eps) / D`, `sin(psi) = sqrt(1-eps^2) sin(phi) / D`,
//! which turns every integrand into a trigonometric polynomial in `psi`
//! (no cancellation as `eps -> 0`).

use crate::lubrication::film::{BearingGeometry, FilmKinematics};
use nalgebra::Vector2;
use std::f64::consts::PI;

/// Largest eccentricity ratio the closed forms evaluate [-]: beyond it the
/// ratio is clamped, so forces stay finite (of order `(2e-9)^(-5/2)` times
/// their scale); the caller switches to contact well before.
pub const MAX_ECCENTRICITY_RATIO: f64 = 1.0 - 1e-9;

/// State of the film in the line-of-centres frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineOfCentres {
    /// Eccentricity ratio `eps = |e|/c`, clamped to [`MAX_ECCENTRICITY_RATIO`] [-].
    pub eccentricity_ratio: f64,
    /// Unit vector `n` along the line of centres (towards the thinnest film) [-].
    pub normal: Vector2<f64>,
    /// `t = perp(n)`, `n` turned by +90 degrees [-].
    pub tangent: Vector2<f64>,
    /// Angle `gamma` of `n` from the global x axis [rad].
    pub angle: f64,
    /// Squeeze rate `eps_dot = e_dot . n / c` [1/s].
    pub squeeze_rate: f64,
    /// Wedge rate `eps (omega_j + omega_b - 2 gamma_dot) = eps (omega_j + omega_b) - 2 e_dot . t / c` [1/s].
    pub wedge_rate: f64,
}

impl LineOfCentres {
    /// Decompose the kinematics. At `e = 0` the frame follows `e_dot`
    /// (or the x axis if the journal is also at rest): the film problem is
    /// then rotation-invariant, so the force is the limit `e -> 0`.
    pub fn new(geometry: &BearingGeometry, kinematics: &FilmKinematics) -> Self {
        let c = geometry.clearance;
        let e = kinematics.eccentricity;
        let e_dot = kinematics.eccentricity_rate;
        let distance = e.norm();
        let normal = if distance > 0.0 {
            e / distance
        } else if e_dot.norm() > 0.0 {
            e_dot / e_dot.norm()
        } else {
            Vector2::new(1.0, 0.0)
        };
        let tangent = Vector2::new(-normal.y, normal.x);
        let eps = (distance / c).min(MAX_ECCENTRICITY_RATIO);
        let spin_sum = kinematics.journal_spin + kinematics.bearing_spin;
        LineOfCentres {
            eccentricity_ratio: eps,
            normal,
            tangent,
            angle: normal.y.atan2(normal.x),
            squeeze_rate: e_dot.dot(&normal) / c,
            wedge_rate: eps * spin_sum - 2.0 * e_dot.dot(&tangent) / c,
        }
    }

    /// Global force from its components along `n` and `t` [N].
    #[inline]
    pub fn to_global(&self, along_normal: f64, along_tangent: f64) -> Vector2<f64> {
        self.normal * along_normal + self.tangent * along_tangent
    }

    /// Global angle `theta = gamma + phi`, wrapped to (-pi, pi] [rad].
    #[inline]
    pub fn global_angle(&self, phi: f64) -> f64 {
        wrap_angle(self.angle + phi)
    }
}

/// Wrap an angle to (-pi, pi] [rad].
#[inline]
pub fn wrap_angle(angle: f64) -> f64 {
    let wrapped = (angle + PI).rem_euclid(2.0 * PI) - PI;
    if wrapped <= -PI {
        wrapped + 2.0 * PI
    } else {
        wrapped
    }
}

/// Integrals over `[a, b]` of `{1, cos, sin, cos^2, sin^2, sin cos}(phi) / D^3`,
/// `D = 1 - eps cos(phi)` [-].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FilmMoments {
    /// `int 1/D^3`.
    pub one: f64,
    /// `int cos/D^3`.
    pub cos: f64,
    /// `int sin/D^3`.
    pub sin: f64,
    /// `int cos^2/D^3`.
    pub cos_cos: f64,
    /// `int sin^2/D^3`.
    pub sin_sin: f64,
    /// `int sin cos/D^3`.
    pub sin_cos: f64,
}

/// Sommerfeld angle `psi(phi)`, continuous with `phi` (`|psi - phi| < pi`) [rad].
#[inline]
pub fn sommerfeld_angle(eps: f64, phi: f64) -> f64 {
    let (s, c) = phi.sin_cos();
    let raw = ((1.0 - eps * eps).sqrt() * s).atan2(c - eps);
    phi + wrap_angle(raw - phi)
}

impl FilmMoments {
    /// Closed-form moments over `[a, b]` for `0 <= eps < 1`.
    pub fn over(eps: f64, a: f64, b: f64) -> Self {
        let (pa, pb) = (sommerfeld_angle(eps, a), sommerfeld_angle(eps, b));
        let (sa, ca) = pa.sin_cos();
        let (sb, cb) = pb.sin_cos();
        // differences of the psi antiderivatives
        let dpsi = pb - pa;
        let dsin = sb - sa;
        let dcos = cb - ca;
        let dsin2 = 2.0 * (sb * cb - sa * ca);
        let dsinsq = sb * sb - sa * sa;
        let cos_sq = 0.5 * dpsi + 0.25 * dsin2;
        let sin_sq = 0.5 * dpsi - 0.25 * dsin2;
        // powers of 1 - eps^2
        let k = 1.0 - eps * eps;
        let k32 = k * k.sqrt();
        let k2 = k * k;
        let k52 = k2 * k.sqrt();
        FilmMoments {
            one: (dpsi + 2.0 * eps * dsin + eps * eps * cos_sq) / k52,
            cos: (eps * dpsi + (1.0 + eps * eps) * dsin + eps * cos_sq) / k52,
            sin: (-dcos + 0.5 * eps * dsinsq) / k2,
            cos_cos: (cos_sq + 2.0 * eps * dsin + eps * eps * dpsi) / k52,
            sin_sin: sin_sq / k32,
            sin_cos: (0.5 * dsinsq - eps * dcos) / k2,
        }
    }
}

/// Maximise `f` on `[a, b]`: a 64-point scan refined by golden-section
/// search around the best sample. Returns `(argmax, max)`.
pub fn maximise<F: Fn(f64) -> f64>(f: F, a: f64, b: f64) -> (f64, f64) {
    const N_SCAN: usize = 64;
    let step = (b - a) / N_SCAN as f64;
    let (mut best_x, mut best_f) = (a, f(a));
    for i in 1..=N_SCAN {
        let x = a + step * i as f64;
        let fx = f(x);
        if fx > best_f {
            best_x = x;
            best_f = fx;
        }
    }
    // golden section in the cell pair around the best sample
    let (mut lo, mut hi) = ((best_x - step).max(a), (best_x + step).min(b));
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..40 {
        let x1 = hi - ratio * (hi - lo);
        let x2 = lo + ratio * (hi - lo);
        if f(x1) >= f(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    let x = 0.5 * (lo + hi);
    let fx = f(x);
    if fx > best_f {
        (x, fx)
    } else {
        (best_x, best_f)
    }
}
