//! Textbook closed forms of journal-bearing forces, written independently
//! of the dynamic models so that tests (here and for the Reynolds solver)
//! can check against them. Components are along the line of centres: `radial`
//! along `n` (negative: towards the bearing centre), `tangential` along
//! `t = perp(n)`; `omega` is the journal spin with the bearing fixed.

use std::f64::consts::PI;

/// Force components along `n` and `t` [N].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineOfCentresForce {
    /// Component along `n` [N].
    pub radial: f64,
    /// Component along `t` [N].
    pub tangential: f64,
}

/// Ocvirk's steady short bearing, pi film: `F_r = -mu w R L^3 eps^2 / (c^2 (1-eps^2)^2)`,
/// `F_t = pi mu w R L^3 eps / (4 c^2 (1-eps^2)^(3/2))` [N]; `mu` [Pa s], `omega` [rad/s], lengths [m].
pub fn ocvirk(mu: f64, omega: f64, r: f64, l: f64, c: f64, eps: f64) -> LineOfCentresForce {
    let k = 1.0 - eps * eps;
    LineOfCentresForce {
        radial: -mu * omega * r * l.powi(3) * eps * eps / (c * c * k * k),
        tangential: PI * mu * omega * r * l.powi(3) * eps / (4.0 * c * c * k.powf(1.5)),
    }
}

/// Sommerfeld's steady long bearing, full film: purely tangential load
/// `W = 12 pi mu w R^3 L eps / (c^2 (2+eps^2) sqrt(1-eps^2))` [N].
pub fn sommerfeld_full(mu: f64, omega: f64, r: f64, l: f64, c: f64, eps: f64) -> LineOfCentresForce {
    LineOfCentresForce {
        radial: 0.0,
        tangential: 12.0 * PI * mu * omega * r.powi(3) * l * eps / (c * c * (2.0 + eps * eps) * (1.0 - eps * eps).sqrt()),
    }
}

/// Gümbel's (half-Sommerfeld) steady long bearing:
/// `F_r = -12 mu w R^3 L eps^2 / (c^2 (2+eps^2)(1-eps^2))`,
/// `F_t = 6 pi mu w R^3 L eps / (c^2 (2+eps^2) sqrt(1-eps^2))` [N].
pub fn gumbel_long(mu: f64, omega: f64, r: f64, l: f64, c: f64, eps: f64) -> LineOfCentresForce {
    let s = 2.0 + eps * eps;
    LineOfCentresForce {
        radial: -12.0 * mu * omega * r.powi(3) * l * eps * eps / (c * c * s * (1.0 - eps * eps)),
        tangential: 6.0 * PI * mu * omega * r.powi(3) * l * eps / (c * c * s * (1.0 - eps * eps).sqrt()),
    }
}

/// Pure squeeze of a short bearing, radial force [N]: full film
/// `-pi mu R L^3 (1+2eps^2) eps_dot / (c^2 (1-eps^2)^(5/2))`; half film
/// (Gümbel, the half being squeezed) `-(mu R L^3 eps_dot / c^2) [(1+2eps^2)(pi/2 + s asin eps)
/// + 3 s eps sqrt(1-eps^2)] / (1-eps^2)^(5/2)`, `s = sign(eps_dot)`; `eps_dot` [1/s].
pub fn short_squeeze(mu: f64, r: f64, l: f64, c: f64, eps: f64, eps_dot: f64, full_film: bool) -> f64 {
    let k = 1.0 - eps * eps;
    let scale = mu * r * l.powi(3) * eps_dot / (c * c * k.powf(2.5));
    if full_film {
        return -PI * (1.0 + 2.0 * eps * eps) * scale;
    }
    let s = eps_dot.signum();
    -scale * ((1.0 + 2.0 * eps * eps) * (0.5 * PI + s * eps.asin()) + 3.0 * s * eps * k.sqrt())
}

/// Pure squeeze of a long bearing, radial force [N]: full film
/// `-12 pi mu R^3 L eps_dot / (c^2 (1-eps^2)^(3/2))`; half film (the half
/// being squeezed, `p = 0` at its ends)
/// `-(12 mu R^3 L eps_dot / c^2) [pi/2 + s asin eps + s eps sqrt(1-eps^2)] / (1-eps^2)^(3/2)`.
pub fn long_squeeze(mu: f64, r: f64, l: f64, c: f64, eps: f64, eps_dot: f64, full_film: bool) -> f64 {
    let k = 1.0 - eps * eps;
    let scale = 12.0 * mu * r.powi(3) * l * eps_dot / (c * c * k.powf(1.5));
    if full_film {
        return -PI * scale;
    }
    let s = eps_dot.signum();
    -scale * (0.5 * PI + s * eps.asin() + s * eps * k.sqrt())
}

/// Fixed-limit dynamic forms of Flores et al. (2004, after Pinkus and
/// Sternlicht) for a long bearing, film on the wedge half `[-pi, 0]` of our
/// frame with `p = 0` at both ends; `wbar` is the wedge speed [rad/s]:
/// `F_r = -(12 mu R^3 L / c^2) [wbar eps^2/((2+eps^2)(1-eps^2)) + eps_dot (pi/2 - 8/(pi (2+eps^2)))/(1-eps^2)^(3/2)]`,
/// `F_t = (12 mu R^3 L / c^2) [pi wbar eps / (2 (2+eps^2) sqrt(1-eps^2)) + 2 eps eps_dot / ((2+eps^2)(1-eps^2))]` [N].
pub fn flores_fixed_long(mu: f64, r: f64, l: f64, c: f64, eps: f64, eps_dot: f64, wbar: f64) -> LineOfCentresForce {
    let (k, s) = (1.0 - eps * eps, 2.0 + eps * eps);
    let scale = 12.0 * mu * r.powi(3) * l / (c * c);
    LineOfCentresForce {
        radial: -scale * (wbar * eps * eps / (s * k) + eps_dot * (0.5 * PI - 8.0 / (PI * s)) / k.powf(1.5)),
        tangential: scale * (PI * wbar * eps / (2.0 * s * k.sqrt()) + 2.0 * eps * eps_dot / (s * k)),
    }
}

/// Fixed-limit dynamic forms of Flores et al. for a short bearing, film on
/// `[-pi, 0]` (negative pressures in it kept, positive ones outside dropped):
/// `F_r = -(mu R L^3 / 2c^2) [2 wbar eps^2/(1-eps^2)^2 + pi (1+2eps^2) eps_dot/(1-eps^2)^(5/2)]`,
/// `F_t = (mu R L^3 / 2c^2) [pi wbar eps/(2 (1-eps^2)^(3/2)) + 4 eps eps_dot/(1-eps^2)^2]` [N].
pub fn flores_fixed_short(mu: f64, r: f64, l: f64, c: f64, eps: f64, eps_dot: f64, wbar: f64) -> LineOfCentresForce {
    let k = 1.0 - eps * eps;
    let scale = mu * r * l.powi(3) / (2.0 * c * c);
    LineOfCentresForce {
        radial: -scale * (2.0 * wbar * eps * eps / (k * k) + PI * (1.0 + 2.0 * eps * eps) * eps_dot / k.powf(2.5)),
        tangential: scale * (PI * wbar * eps / (2.0 * k.powf(1.5)) + 4.0 * eps * eps_dot / (k * k)),
    }
}
