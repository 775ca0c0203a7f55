//! Solver checks that need no reference beyond a closed form; the full
//! validation suite is tests/physics/test_reynolds.py.

use super::*;
use crate::lubrication::film::{BearingGeometry, FilmKinematics};
use nalgebra::Vector2;
use std::f64::consts::PI;

fn geometry(l_over_d: f64) -> BearingGeometry {
    BearingGeometry { radius: 0.01, length: 0.02 * l_over_d, clearance: 1e-5, viscosity: 0.04 }
}

fn spinning(eps: f64, omega: f64) -> FilmKinematics {
    FilmKinematics {
        eccentricity: Vector2::new(eps * 1e-5, 0.0),
        eccentricity_rate: Vector2::zeros(),
        journal_spin: omega,
        bearing_spin: 0.0,
    }
}

fn solve(lod: f64, cav: Cavitation, grid: (usize, usize), k: &FilmKinematics) -> FilmSolution {
    let o = ReynoldsOptions { n_circumferential: grid.0, n_axial: grid.1, cavitation: cav, tolerance: 1e-10, ..Default::default() };
    ReynoldsSolver::new(geometry(lod), o).unwrap().solve(k).unwrap()
}

/// Force converges at second order: Richardson's observed order from three
/// grids (ratio 2) lies near 2 and the finest grid is within 0.5 % of the extrapolation.
#[test]
fn force_converges_at_second_order_with_the_grid() {
    for cav in [Cavitation::Gumbel, Cavitation::SwiftStieber] {
        let f: Vec<f64> = [(36, 8), (72, 16), (144, 32)]
            .iter()
            .map(|g| solve(1.0, cav, *g, &spinning(0.6, 100.0)).force_on_journal.norm())
            .collect();
        let order = ((f[0] - f[1]) / (f[1] - f[2])).abs().log2();
        let extrapolated = f[2] + (f[2] - f[1]) / (2f64.powf(order) - 1.0);
        println!("{cav:?}: {f:?} order {order:.2} extrapolated {extrapolated:.4}");
        assert!(order > 1.6 && order < 2.6, "{cav:?} observed order {order}");
        assert!(((f[2] - extrapolated) / extrapolated).abs() < 0.005);
    }
}

/// Ocvirk short bearing (DESIGN.md 4; Hamrock, Fundamentals of Fluid Film
/// Lubrication, ch. 10): with omega_j = omega, omega_b = 0 the formulas hold
/// with omega itself (no factor 2), the journal pushed back along -e and sideways along +90 degrees.
#[test]
fn gumbel_matches_ocvirk_at_small_l_over_d() {
    let (eps, w) = (0.6, 100.0);
    let g = geometry(1.0 / 16.0);
    let sol = solve(1.0 / 16.0, Cavitation::Gumbel, (144, 32), &spinning(eps, w));
    let (mu, r, l, c) = (g.viscosity, g.radius, g.length, g.clearance);
    let fr = mu * w * r * l.powi(3) * eps * eps / (c * c * (1.0 - eps * eps).powi(2));
    let ft = PI * mu * w * r * l.powi(3) * eps / (4.0 * c * c * (1.0 - eps * eps).powf(1.5));
    let (fx, fy) = (sol.force_on_journal.x, sol.force_on_journal.y);
    println!("Ocvirk L/D 1/16: ({fx}, {fy}) vs (-{fr}, {ft}) attitude {}", sol.attitude_angle.to_degrees());
    assert!((-fx / fr - 1.0).abs() < 0.015);
    assert!((fy / ft - 1.0).abs() < 0.01);
    assert!((sol.attitude_angle - (ft / fr).atan()).abs() < 0.01);
}

#[test]
fn eccentricity_at_the_clearance_is_an_error() {
    let mut s = ReynoldsSolver::new(geometry(1.0), ReynoldsOptions::default()).unwrap();
    let err = s.solve(&spinning(1.0, 10.0)).unwrap_err();
    assert_eq!(err, "film thickness <= 0: eccentricity ratio 1 >= 1");
    let mut k = spinning(0.5, 10.0);
    k.journal_spin = f64::NAN;
    assert!(s.solve(&k).unwrap_err().starts_with("film kinematics must be finite"));
    // the solver still works afterwards, and a still journal gives no force
    assert!(s.solve(&spinning(0.5, 0.0)).unwrap().force_on_journal.norm() == 0.0);
}

#[test]
fn elrod_adams_without_supply_is_refused() {
    let o = ReynoldsOptions { cavitation: Cavitation::ElrodAdams, ..Default::default() };
    let err = ReynoldsSolver::new(geometry(1.0), o).unwrap_err();
    assert!(err.starts_with("the Elrod-Adams model needs a lubricant supply"));
}

/// Swift-Stieber: p >= 0 and complementarity with the discrete equation.
#[test]
fn swift_stieber_satisfies_the_complementarity_conditions() {
    let o = ReynoldsOptions { tolerance: 1e-10, ..Default::default() };
    let mut s = ReynoldsSolver::new(geometry(1.0), o).unwrap();
    let mut k = spinning(0.7, 50.0);
    k.eccentricity_rate = Vector2::new(3e-4, -2e-4);
    s.solve(&k).unwrap();
    assert!(s.pressure().iter().all(|p| *p >= 0.0));
    assert!(s.complementarity_residual() < 1e-6, "{}", s.complementarity_residual());
}
