//! Tests of the closed-form bearing models against textbook closed forms
//! and against independent numerical integration of the analytic pressure
//! in the fixed global frame (no line-of-centres decomposition, no
//! Sommerfeld substitution).

use super::*;
use crate::lubrication::reference_closed_forms as reference;
use crate::lubrication::squeeze_film::{SqueezeFilm, SqueezeFilmTheory};
use nalgebra::{Rotation2, Vector2};

const ALL: [ClosedFormBearing; 5] = [
    ClosedFormBearing::HamrockShort,
    ClosedFormBearing::HamrockLong,
    ClosedFormBearing::FreneShort,
    ClosedFormBearing::FreneLong,
    ClosedFormBearing::PinkusSternlichtLong,
];

fn geometry() -> BearingGeometry {
    BearingGeometry { radius: 0.02, length: 0.015, clearance: 50e-6, viscosity: 0.04 }
}

/// Journal at eccentricity ratio `eps` along angle `gamma`, spin `omega`, fixed bearing, no whirl.
fn steady(eps: f64, gamma: f64, omega: f64) -> FilmKinematics {
    let c = geometry().clearance;
    FilmKinematics {
        eccentricity: Vector2::new(gamma.cos(), gamma.sin()) * (eps * c),
        eccentricity_rate: Vector2::zeros(),
        journal_spin: omega,
        bearing_spin: 0.0,
    }
}

/// Components along n and t of a global force.
fn components(k: &FilmKinematics, f: Vector2<f64>) -> (f64, f64) {
    let n = k.eccentricity.normalize();
    (f.dot(&n), f.dot(&Vector2::new(-n.y, n.x)))
}

fn close(a: f64, b: f64, tol: f64, scale: f64) -> bool {
    (a - b).abs() <= tol * scale
}

#[test]
fn test_steady_models_reduce_to_ocvirk_sommerfeld_and_gumbel() {
    let g = geometry();
    let (mu, r, l, c, w) = (g.viscosity, g.radius, g.length, g.clearance, 300.0);
    for &eps in &[0.05, 0.3, 0.6, 0.9, 0.99] {
        let k = steady(eps, 0.7, w);
        let oc = reference::ocvirk(mu, w, r, l, c, eps);
        let gu = reference::gumbel_long(mu, w, r, l, c, eps);
        let so = reference::sommerfeld_full(mu, w, r, l, c, eps);
        let cases = [
            (ClosedFormBearing::HamrockShort, oc.radial, oc.tangential),
            (ClosedFormBearing::FreneShort, 0.0, 2.0 * oc.tangential),
            (ClosedFormBearing::HamrockLong, gu.radial, gu.tangential),
            (ClosedFormBearing::PinkusSternlichtLong, gu.radial, gu.tangential),
            (ClosedFormBearing::FreneLong, so.radial, so.tangential),
        ];
        for (model, fr, ft) in cases {
            let (n, t) = components(&k, model.film_force(&g, &k).force_on_journal);
            let scale = fr.hypot(ft);
            assert!(close(n, fr, 1e-10, scale) && close(t, ft, 1e-10, scale), "{model:?} eps {eps}: ({n}, {t}) vs ({fr}, {ft})");
        }
    }
}

#[test]
fn test_wedge_speed_is_spin_sum_minus_twice_whirl() {
    // a journal whirling at gamma_dot with spins (w_j, w_b) equals a steady
    // journal spinning at w_j + w_b - 2 gamma_dot in a fixed bearing
    let g = geometry();
    let (eps, gamma, gamma_dot) = (0.4, 1.1, 35.0);
    let mut k = steady(eps, gamma, 120.0);
    k.bearing_spin = -20.0;
    k.eccentricity_rate = Vector2::new(-gamma.sin(), gamma.cos()) * (eps * g.clearance * gamma_dot);
    let reference = steady(eps, gamma, 120.0 - 20.0 - 2.0 * gamma_dot);
    for model in ALL {
        let (a, b) = (model.film_force(&g, &k).force_on_journal, model.film_force(&g, &reference).force_on_journal);
        assert!((a - b).norm() <= 1e-12 * b.norm(), "{model:?}");
    }
}

#[test]
fn test_pure_squeeze_matches_squeeze_closed_forms() {
    let g = geometry();
    let (mu, r, l, c) = (g.viscosity, g.radius, g.length, g.clearance);
    for &eps in &[0.0, 0.2, 0.5, 0.8, 0.95] {
        for &eps_dot in &[3.0, -3.0] {
            let mut k = steady(eps, -0.4, 0.0);
            let n = Vector2::new((-0.4f64).cos(), (-0.4f64).sin());
            k.eccentricity_rate = n * (eps_dot * c);
            let cases = [
                (ClosedFormBearing::HamrockShort, reference::short_squeeze(mu, r, l, c, eps, eps_dot, false)),
                (ClosedFormBearing::FreneShort, reference::short_squeeze(mu, r, l, c, eps, eps_dot, true)),
                (ClosedFormBearing::HamrockLong, reference::long_squeeze(mu, r, l, c, eps, eps_dot, false)),
                (ClosedFormBearing::FreneLong, reference::long_squeeze(mu, r, l, c, eps, eps_dot, true)),
                // Sommerfeld boundary: approach fills the whole film, recess empties it
                (ClosedFormBearing::PinkusSternlichtLong, if eps_dot > 0.0 { reference::long_squeeze(mu, r, l, c, eps, eps_dot, true) } else { 0.0 }),
            ];
            for (model, expected) in cases {
                // at e = 0 the frame follows e_dot, so a centred journal always approaches:
                // the Sommerfeld-boundary model jumps there between recess (0) and approach
                if eps == 0.0 && eps_dot < 0.0 && model == ClosedFormBearing::PinkusSternlichtLong {
                    continue;
                }
                let f = model.film_force(&g, &k).force_on_journal;
                assert!(close(f.dot(&n), expected, 1e-10, expected.abs().max(1e-300)), "{model:?} eps {eps} eps_dot {eps_dot}: {} vs {expected}", f.dot(&n));
                assert!(f.dot(&Vector2::new(-n.y, n.x)).abs() <= 1e-10 * expected.abs() + 1e-300, "{model:?}: tangential force under pure squeeze");
            }
            let sf = SqueezeFilm::new(g, SqueezeFilmTheory::ShortBearing);
            let expected = reference::short_squeeze(mu, r, l, c, eps, eps_dot, false);
            assert!(close(sf.film_force(&k).force_on_journal.dot(&n), expected, 1e-10, expected.abs()));
            let sf = SqueezeFilm::new(g, SqueezeFilmTheory::LongBearing);
            let expected = reference::long_squeeze(mu, r, l, c, eps, eps_dot, false);
            assert!(close(sf.film_force(&k).force_on_journal.dot(&n), expected, 1e-10, expected.abs()));
        }
    }
}

#[test]
fn test_long_kernel_on_fixed_half_reproduces_flores_fixed_limit_forms() {
    let g = geometry();
    for &(eps, eps_dot, wbar) in &[(0.3, 2.0, 100.0), (0.7, -5.0, 100.0), (0.85, 40.0, 10.0)] {
        let (c, gamma) = (g.clearance, 0.3f64);
        let n = Vector2::new(gamma.cos(), gamma.sin());
        let k = FilmKinematics { eccentricity: n * (eps * c), eccentricity_rate: n * (eps_dot * c), journal_spin: wbar, bearing_spin: 0.0 };
        let state = LineOfCentres::new(&g, &k);
        let kk = crate::lubrication::hamrock::pi_film_constant(&state, -PI, 0.0);
        let (n_f, t_f) = components(&k, long_film_over(&g, &k, &state, -PI, 0.0, kk).force_on_journal);
        let fl = reference::flores_fixed_long(g.viscosity, g.radius, g.length, c, eps, eps_dot, wbar);
        let scale = fl.radial.hypot(fl.tangential);
        assert!(close(n_f, fl.radial, 1e-10, scale) && close(t_f, fl.tangential, 1e-10, scale), "long {eps}");
        let (n_f, t_f) = components(&k, short_film_over(&g, &k, &state, -PI, 0.0).force_on_journal);
        let fs = reference::flores_fixed_short(g.viscosity, g.radius, g.length, c, eps, eps_dot, wbar);
        let scale = fs.radial.hypot(fs.tangential);
        assert!(close(n_f, fs.radial, 1e-10, scale) && close(t_f, fs.tangential, 1e-10, scale), "short {eps}");
    }
}

/// Mixed states: (eps, gamma, e_dot direction relative to n, |e_dot|/c, w_j, w_b).
const MIXED: [(f64, f64, f64, f64, f64, f64); 7] = [
    (0.5, 0.3, 0.0, 20.0, 100.0, 0.0),   // approach + wedge
    (0.5, 0.3, PI, 20.0, 100.0, 0.0),    // recess + wedge
    (0.7, 2.0, 0.8, 80.0, 60.0, -10.0),  // oblique, bearing turning
    (0.3, -1.0, -2.0, 50.0, -80.0, 0.0), // reverse rotation
    (0.8, 4.0, 0.2, 5.0, 400.0, 100.0),  // wedge-dominated
    (0.6, 1.0, 0.1, 400.0, 50.0, 0.0),   // squeeze-dominated
    (0.0, 0.0, 0.7, 30.0, 200.0, 0.0),   // centred journal
];

fn mixed(case: (f64, f64, f64, f64, f64, f64)) -> FilmKinematics {
    let (eps, gamma, dir, rate, wj, wb) = case;
    let c = geometry().clearance;
    FilmKinematics {
        eccentricity: Vector2::new(gamma.cos(), gamma.sin()) * (eps * c),
        eccentricity_rate: Vector2::new((gamma + dir).cos(), (gamma + dir).sin()) * (rate * c),
        journal_spin: wj,
        bearing_spin: wb,
    }
}

const N_THETA: usize = 40_000;

/// Film thickness, its theta-derivative and its time derivative at theta, fixed frame.
fn film(k: &FilmKinematics, theta: f64) -> (f64, f64, f64) {
    let (u, du) = (Vector2::new(theta.cos(), theta.sin()), Vector2::new(-theta.sin(), theta.cos()));
    let c = geometry().clearance;
    (c - k.eccentricity.dot(&u), -k.eccentricity.dot(&du), -k.eccentricity_rate.dot(&u))
}

/// Short bearing, Gümbel, midpoint rule in theta in the fixed frame.
fn numeric_short_gumbel(k: &FilmKinematics) -> Vector2<f64> {
    let g = geometry();
    let dtheta = 2.0 * PI / N_THETA as f64;
    let mut f = Vector2::zeros();
    for i in 0..N_THETA {
        let theta = (i as f64 + 0.5) * dtheta;
        let (h, dh_dtheta, dh_dt) = film(k, theta);
        let rhs = 6.0 * g.viscosity * (k.journal_spin + k.bearing_spin) * dh_dtheta + 12.0 * g.viscosity * dh_dt;
        let p_hat = (-rhs / (2.0 * h.powi(3))).max(0.0); // p = p_hat (L^2/4 - z^2)
        f -= Vector2::new(theta.cos(), theta.sin()) * (p_hat * g.radius * g.length.powi(3) / 6.0 * dtheta);
    }
    f
}

/// Long bearing on [t0, t0 + span] of global theta, trapezoid rule, fixed frame;
/// `periodic` closes the film with Sommerfeld's condition and ambient pressure
/// at theta_ref, otherwise p = 0 at both ends; `gumbel` drops negative pressure.
fn numeric_long(k: &FilmKinematics, t0: f64, span: f64, periodic: bool, theta_ref: f64, gumbel: bool) -> Vector2<f64> {
    let g = geometry();
    let (mu, r) = (g.viscosity, g.radius);
    let dtheta = span / N_THETA as f64;
    // h^3 dp/dtheta = R^2 [6 mu (w_j + w_b) h + 12 mu H] + K, H = int dh/dt dtheta
    let q = |theta: f64| {
        let (h, _, _) = film(k, theta);
        let big_h = -k.eccentricity_rate.x * theta.sin() + k.eccentricity_rate.y * theta.cos();
        (r * r * (6.0 * mu * (k.journal_spin + k.bearing_spin) * h + 12.0 * mu * big_h) / h.powi(3), 1.0 / h.powi(3))
    };
    let (mut int_q, mut int_w) = (0.0, 0.0);
    for i in 0..N_THETA {
        let (qa, wa) = q(t0 + i as f64 * dtheta);
        let (qb, wb) = q(t0 + (i + 1) as f64 * dtheta);
        int_q += 0.5 * (qa + qb) * dtheta;
        int_w += 0.5 * (wa + wb) * dtheta;
    }
    let kk = -int_q / int_w;
    let mut p = vec![0.0; N_THETA + 1];
    for i in 0..N_THETA {
        let (qa, wa) = q(t0 + i as f64 * dtheta);
        let (qb, wb) = q(t0 + (i + 1) as f64 * dtheta);
        p[i + 1] = p[i] + 0.5 * (qa + kk * wa + qb + kk * wb) * dtheta;
    }
    if periodic {
        let i_ref = (((theta_ref - t0).rem_euclid(2.0 * PI)) / dtheta).round() as usize;
        let offset = p[i_ref.min(N_THETA)];
        p.iter_mut().for_each(|x| *x -= offset);
    }
    let mut f = Vector2::zeros();
    for (i, &pi) in p.iter().enumerate() {
        let theta = t0 + i as f64 * dtheta;
        let weight = if i == 0 || i == N_THETA { 0.5 } else { 1.0 };
        let pi = if gumbel { pi.max(0.0) } else { pi };
        f -= Vector2::new(theta.cos(), theta.sin()) * (weight * pi * r * g.length * dtheta);
    }
    f
}

#[test]
fn test_moving_gumbel_limits_match_numerical_integration() {
    let g = geometry();
    for case in MIXED {
        let k = mixed(case);
        let state = LineOfCentres::new(&g, &k);
        let thick = state.angle + PI;
        // short bearing, positive part of the analytic pressure
        let expected = numeric_short_gumbel(&k);
        let got = ClosedFormBearing::HamrockShort.film_force(&g, &k).force_on_journal;
        assert!((got - expected).norm() <= 1e-6 * expected.norm(), "short {case:?}: {got} vs {expected}");
        // long bearing, Sommerfeld pressure (ambient at the thickest film), full and Gümbel
        let expected = numeric_long(&k, thick, 2.0 * PI, true, thick, false);
        let got = ClosedFormBearing::FreneLong.film_force(&g, &k).force_on_journal;
        assert!((got - expected).norm() <= 1e-6 * expected.norm(), "Frêne long {case:?}: {got} vs {expected}");
        let expected = numeric_long(&k, thick, 2.0 * PI, true, thick, true);
        let got = ClosedFormBearing::PinkusSternlichtLong.film_force(&g, &k).force_on_journal;
        assert!((got - expected).norm() <= 1e-5 * expected.norm(), "P-S long {case:?}: {got} vs {expected}");
        // long pi film on the moving half, p = 0 at both ends
        let (a, _) = moving_half_film(&state).unwrap();
        let expected = numeric_long(&k, state.angle + a, PI, false, 0.0, false);
        let got = ClosedFormBearing::HamrockLong.film_force(&g, &k).force_on_journal;
        assert!((got - expected).norm() <= 1e-6 * expected.norm(), "Hamrock long {case:?}: {got} vs {expected}");
    }
}

#[test]
fn test_rotating_the_state_rotates_the_force() {
    let g = geometry();
    let rot = Rotation2::new(2.3);
    for case in MIXED {
        let k = mixed(case);
        let kr = FilmKinematics { eccentricity: rot * k.eccentricity, eccentricity_rate: rot * k.eccentricity_rate, ..k };
        for model in ALL {
            let (f, fr) = (model.film_force(&g, &k), model.film_force(&g, &kr));
            assert!((rot * f.force_on_journal - fr.force_on_journal).norm() <= 1e-10 * f.force_on_journal.norm(), "{model:?} {case:?}");
            assert!(close(f.peak_pressure, fr.peak_pressure, 1e-9, f.peak_pressure), "{model:?} {case:?} peak");
        }
    }
}

#[test]
fn test_swapping_spins_and_scaling_velocities() {
    let g = geometry();
    for case in MIXED {
        let k = mixed(case);
        let swapped = FilmKinematics { journal_spin: k.bearing_spin, bearing_spin: k.journal_spin, ..k };
        let lambda = 2.5;
        let scaled = FilmKinematics { eccentricity_rate: k.eccentricity_rate * lambda, journal_spin: k.journal_spin * lambda, bearing_spin: k.bearing_spin * lambda, ..k };
        for model in ALL {
            let f = model.film_force(&g, &k);
            let norm = f.force_on_journal.norm();
            assert!((model.film_force(&g, &swapped).force_on_journal - f.force_on_journal).norm() <= 1e-13 * norm, "{model:?} swap");
            let fs = model.film_force(&g, &scaled);
            assert!((fs.force_on_journal - f.force_on_journal * lambda).norm() <= 1e-12 * norm * lambda, "{model:?} scale");
            assert!(close(fs.peak_pressure, lambda * f.peak_pressure, 1e-9, lambda * f.peak_pressure), "{model:?} peak scale");
        }
    }
}

#[test]
fn test_limits_of_eccentricity_and_motion() {
    let g = geometry();
    for model in ALL {
        // zero everything: zero force and torque, no NaN
        let f = model.film_force(&g, &steady(0.0, 0.0, 0.0));
        assert_eq!((f.force_on_journal, f.peak_pressure, f.friction_torque), (Vector2::zeros(), 0.0, 0.0), "{model:?}");
        // pure spin at the centre: no force, continuous from a tiny eccentricity
        let f0 = model.film_force(&g, &steady(0.0, 0.0, 300.0)).force_on_journal;
        let f1 = model.film_force(&g, &steady(1e-9, 0.5, 300.0)).force_on_journal;
        let f_ref = model.film_force(&g, &steady(0.1, 0.5, 300.0)).force_on_journal;
        // the wedge force is linear in eps near the centre
        assert!(f0.norm() == 0.0 && f1.norm() <= 1.02e-8 * f_ref.norm(), "{model:?}: {f0} {f1}");
        // centred journal moving: the limit of a tiny eccentricity along any direction
        let mut k0 = mixed(MIXED[6]);
        let mut k1 = k0;
        k1.eccentricity = Vector2::new(0.3f64.cos(), 0.3f64.sin()) * (1e-10 * g.clearance);
        let (a, b) = (model.film_force(&g, &k0).force_on_journal, model.film_force(&g, &k1).force_on_journal);
        // (except Pinkus-Sternlicht: its ambient point, the thickest film, has no
        // direction at e = 0, so its force depends on the direction of approach there)
        if model != ClosedFormBearing::PinkusSternlichtLong {
            assert!(a.norm() > 0.0 && (a - b).norm() <= 1e-8 * a.norm(), "{model:?} centre: {a} vs {b}");
        }
        // near and beyond contact: finite
        for eps in [1.0 - 1e-6, 1.0, 1.3] {
            k0.eccentricity = Vector2::new(1.0, 0.0) * (eps * g.clearance);
            let f = model.film_force(&g, &k0);
            assert!(f.force_on_journal.iter().all(|x| x.is_finite()) && f.peak_pressure.is_finite() && f.friction_torque.is_finite(), "{model:?} eps {eps}");
        }
    }
}

#[test]
fn test_reverse_rotation_mirrors_the_steady_force() {
    let g = geometry();
    for model in ALL {
        let (n1, t1) = components(&steady(0.6, 0.2, 250.0), model.film_force(&g, &steady(0.6, 0.2, 250.0)).force_on_journal);
        let (n2, t2) = components(&steady(0.6, 0.2, -250.0), model.film_force(&g, &steady(0.6, 0.2, -250.0)).force_on_journal);
        assert!(close(n1, n2, 1e-12, n1.hypot(t1)) && close(t1, -t2, 1e-12, n1.hypot(t1)), "{model:?}");
    }
}

#[test]
fn test_peak_pressure_and_friction_torque_match_classical_values() {
    let g = geometry();
    let (mu, r, l, c, w) = (g.viscosity, g.radius, g.length, g.clearance, 300.0);
    for &eps in &[0.2, 0.6, 0.9] {
        let k = steady(eps, 0.0, w);
        // Sommerfeld: peak where cos(theta_m) = -3 eps/(2+eps^2), theta from the thickest film
        let tm = (-3.0 * eps / (2.0 + eps * eps)).acos();
        let p_max = 6.0 * mu * w * r * r / (c * c) * eps * tm.sin() * (2.0 + eps * tm.cos()) / ((2.0 + eps * eps) * (1.0 + eps * tm.cos()).powi(2));
        let f = ClosedFormBearing::FreneLong.film_force(&g, &k);
        assert!(close(f.peak_pressure, p_max, 1e-10, p_max), "eps {eps}: {} vs {p_max}", f.peak_pressure);
        assert!((f.peak_pressure_angle - (tm - PI)).abs() < 1e-9);
        // Gümbel keeps the positive Sommerfeld half: same peak
        let f = ClosedFormBearing::PinkusSternlichtLong.film_force(&g, &k);
        assert!(close(f.peak_pressure, p_max, 1e-10, p_max));
        // Ocvirk mid-plane peak by a dense scan of its pressure formula
        let (mut best, n_scan) = (0.0f64, 200_000);
        for i in 0..n_scan {
            let th = PI * (i as f64 + 0.5) / n_scan as f64;
            best = best.max(3.0 * mu * w * l * l / (4.0 * c * c) * eps * th.sin() / (1.0 + eps * th.cos()).powi(3));
        }
        let f = ClosedFormBearing::HamrockShort.film_force(&g, &k);
        assert!(close(f.peak_pressure, best, 1e-9, best), "Ocvirk peak {} vs {best}", f.peak_pressure);
        // Sommerfeld's journal friction torque 4 pi (1+2eps^2)/((2+eps^2) sqrt(1-eps^2)) mu R^3 L w / c
        let t_ref = -4.0 * PI * (1.0 + 2.0 * eps * eps) / ((2.0 + eps * eps) * (1.0 - eps * eps).sqrt()) * mu * r.powi(3) * l * w / c;
        let t = ClosedFormBearing::FreneLong.film_force(&g, &k).friction_torque;
        assert!(close(t, t_ref, 1e-12, t_ref.abs()), "torque {t} vs {t_ref}");
    }
    // Petroff at the centre
    let t = ClosedFormBearing::HamrockShort.film_force(&g, &steady(0.0, 0.0, w)).friction_torque;
    let petroff = -2.0 * PI * mu * r.powi(3) * l * w / c;
    assert!(close(t, petroff, 1e-14, petroff.abs()));
}

#[test]
fn test_squeeze_film_switches_to_impact_at_contact() {
    let g = geometry();
    let sf = SqueezeFilm::new(g, SqueezeFilmTheory::LongBearing);
    assert!(!sf.film_exhausted(0.999) && sf.film_exhausted(1.0));
    // near contact the long-bearing squeeze film follows Phelan's d f_dot / f^(3/2)
    let (eps, eps_dot) = (1.0 - 1e-6, 2.0);
    let f_min = (1.0 - eps) * g.clearance;
    let d = 12.0 * PI / 2f64.powf(1.5) * g.viscosity * g.radius.powi(3) * g.length / g.clearance.powf(1.5);
    let phelan = -d * (eps_dot * g.clearance) / f_min.powf(1.5);
    assert!(close(sf.radial_force(eps, eps_dot), phelan, 1e-5, phelan.abs()));
    // squeeze force only: spin and whirl change nothing
    let mut k = mixed(MIXED[2]);
    let f = sf.film_force(&k).force_on_journal;
    k.journal_spin = 1e4;
    k.eccentricity_rate += Vector2::new(-k.eccentricity.y, k.eccentricity.x) * 50.0;
    assert_eq!(sf.film_force(&k).force_on_journal, f);
    assert!(sf.film_force(&k).friction_torque.is_nan());
}
