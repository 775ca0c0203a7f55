//! Tests of the film end of the Pinkus-Sternlicht model: the cubic in
//! `u = tan(phi/2)` against the bisection on the original bracket `f(phi)`.

use super::*;
use nalgebra::Vector2;

/// A line-of-centres state with the given ratio and rates (frame along x).
fn state(eps: f64, squeeze_rate: f64, wedge_rate: f64) -> LineOfCentres {
    LineOfCentres {
        eccentricity_ratio: eps,
        normal: Vector2::new(1.0, 0.0),
        tangent: Vector2::new(0.0, 1.0),
        angle: 0.0,
        squeeze_rate,
        wedge_rate,
    }
}

/// The bracket of the module docs, `f(phi)`, in its trigonometric form.
fn bracket(s: &LineOfCentres, phi: f64) -> f64 {
    let eps = s.eccentricity_ratio;
    let (sh, ch) = (0.5 * phi).sin_cos();
    -s.wedge_rate * sh * (2.0 - eps * phi.cos()) / (2.0 + eps * eps)
        + s.squeeze_rate * ch * (2.0 + eps - eps * phi.cos()) / ((1.0 + eps) * (1.0 + eps))
}

const EPS: [f64; 9] = [0.0, 1e-12, 1e-6, 0.1, 0.5, 0.9, 0.97, 0.999, 1.0 - 1e-12];
const SQUEEZE: [f64; 13] = [-1e6, -1e3, -10.0, -1.0, -1e-3, -1e-9, 0.0, 1e-9, 1e-3, 1.0, 10.0, 1e3, 1e6];
const WEDGE: [f64; 12] = [-1e6, -1e3, -1.0, -1e-3, -1e-9, -1e-30, 1e-30, 1e-9, 1e-3, 1.0, 1e3, 1e6];

#[test]
fn film_end_by_cubic_matches_bisection_over_signs_and_scales() {
    let mut worst = 0.0_f64;
    for eps in EPS {
        for sq in SQUEEZE {
            for wd in WEDGE {
                let s = state(eps, sq, wd);
                let (cubic, bisection) = (film_end(&s), film_end_by_bisection(&s));
                assert!(cubic > -PI - 1e-15 && cubic < PI + 1e-15, "eps {eps}, squeeze {sq}, wedge {wd}: {cubic}");
                let d = (cubic - bisection).abs();
                assert!(d < 1e-12, "eps {eps}, squeeze {sq}, wedge {wd}: cubic {cubic}, bisection {bisection}");
                worst = worst.max(d);
            }
        }
    }
    // the bisection stops at 2 pi / 2^61; the two agree to about that
    assert!(worst < 1e-14, "worst difference {worst:e} rad");
}

#[test]
fn film_end_is_a_root_of_the_trigonometric_bracket() {
    // independent of the bisection: the sign of f changes across phi1
    for eps in [0.0, 0.3, 0.8, 0.99] {
        for (sq, wd) in [(1.0, 1.0), (-2.0, 0.5), (3.0, -1.0), (-0.1, -4.0), (50.0, 1.0), (-1.0, 100.0)] {
            let s = state(eps, sq, wd);
            let phi1 = film_end(&s);
            let h = 1e-9;
            let (left, right) = (bracket(&s, phi1 - h), bracket(&s, phi1 + h));
            assert!(left * wd > 0.0 && right * wd < 0.0, "eps {eps}, squeeze {sq}, wedge {wd}: f({phi1} -+ h) = {left}, {right}");
        }
    }
}

#[test]
fn zero_squeeze_puts_the_film_end_at_the_thinnest_film() {
    for eps in EPS {
        for wd in [-3.0, 1e-30, 2.0] {
            assert_eq!(film_end(&state(eps, 0.0, wd)), 0.0, "eps {eps}, wedge {wd}");
        }
    }
}

#[test]
fn cubic_root_recovers_a_known_tangent() {
    // t = u k(u) built from a chosen u; the solver must give u back
    for eps in [0.0, 0.25, 0.75, 0.999] {
        for u in [-1e40, -3e5, -2.0, -1e-3, 1e-12, 0.7, 1.0, 42.0, 1e8, 1e40] {
            let k = ((2.0 + eps) * u * u + 2.0 - eps) / ((1.0 + eps) * u * u + 1.0);
            let got = half_angle_tangent(eps, u * k).expect("bracket holds for eps in [0, 1)");
            assert!(((got - u) / u).abs() < 1e-14, "eps {eps}, u {u}: got {got}");
        }
    }
}

#[test]
fn cubic_declines_what_it_cannot_bracket_and_the_fallback_answers() {
    assert_eq!(half_angle_tangent(0.5, f64::INFINITY), None);
    assert_eq!(half_angle_tangent(0.5, f64::NAN), None);
    assert_eq!(half_angle_tangent(1.5, 1.0), None);
    // no wedge: t = 2B/0; the bisection gives an end of the film
    let s = state(0.4, 1.0, 0.0);
    assert_eq!(film_end(&s), film_end_by_bisection(&s));
    // rates that are not finite still return (no hang, no panic)
    assert!(film_end(&state(0.4, f64::NAN, 1.0)).is_finite() || film_end(&state(0.4, f64::NAN, 1.0)).is_nan());
    let far = film_end(&state(0.4, 1e300, 1e-300));
    assert!((far - PI).abs() < 1e-12, "huge squeeze over wedge: {far}");
}

#[test]
fn newton_converges_in_a_few_iterations_over_25_decades() {
    // the point of the cubic: a handful of polynomial evaluations, not 60 trigonometric ones
    let mut worst = 0;
    for eps in EPS {
        for decade in -12..=12 {
            for mantissa in [1.0, 2.0, 5.0] {
                let x = mantissa * 10f64.powi(decade);
                let (u, iterations) = root_in_bracket(eps, x).expect("bracket holds");
                assert!(u >= 0.5 * x && u <= x, "eps {eps}, t {x}: u {u}");
                worst = worst.max(iterations);
            }
        }
    }
    assert!(worst <= 8, "worst case {worst} Newton iterations");
}
