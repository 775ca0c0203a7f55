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

/// A tiny deterministic generator for test states in [0, 1).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn random_state(rng: &mut Lcg, c: f64) -> FilmKinematics {
    let (eps, angle) = (0.95 * rng.next(), 2.0 * PI * rng.next());
    let rate = 200.0 * c * (rng.next() - 0.5);
    let rate_angle = 2.0 * PI * rng.next();
    FilmKinematics {
        eccentricity: Vector2::new(angle.cos(), angle.sin()) * eps * c,
        eccentricity_rate: Vector2::new(rate_angle.cos(), rate_angle.sin()) * rate,
        journal_spin: 200.0 * (rng.next() - 0.3),
        bearing_spin: 50.0 * (rng.next() - 0.5),
    }
}

/// Scaling every velocity by k scales the force by k; turning the whole state
/// turns the force (to the grid's rotation error); spin and whirl enter only
/// through V_w = eps (omega_j + omega_b - 2 gamma_dot) / 2.
#[test]
fn force_is_homogeneous_and_rotates_with_the_state() {
    let g = geometry(0.5);
    let o = ReynoldsOptions { tolerance: 1e-10, ..Default::default() };
    let mut s = ReynoldsSolver::new(g, o).unwrap();
    let k = FilmKinematics {
        eccentricity: Vector2::new(6e-6, 2e-6),
        eccentricity_rate: Vector2::new(-4e-4, 9e-4),
        journal_spin: 80.0,
        bearing_spin: -20.0,
    };
    let f = s.solve(&k).unwrap().force_on_journal;
    let scaled = FilmKinematics { eccentricity_rate: k.eccentricity_rate * 3.0, journal_spin: 240.0, bearing_spin: -60.0, ..k };
    assert!((s.solve(&scaled).unwrap().force_on_journal - f * 3.0).norm() < 1e-6 * f.norm());
    let rot = nalgebra::Rotation2::new(0.7);
    let turned = FilmKinematics { eccentricity: rot * k.eccentricity, eccentricity_rate: rot * k.eccentricity_rate, ..k };
    let f_turned = s.solve(&turned).unwrap().force_on_journal;
    println!("rotation: {f_turned} vs {}", rot * f);
    assert!((f_turned - rot * f).norm() < 5e-3 * f.norm());
    // extra whirl gamma_dot with 2 gamma_dot added to the spin: same V_w, same force
    let e = k.eccentricity;
    let t = Vector2::new(-e.y, e.x) / e.norm();
    let whirl = 10.0;
    let shifted = FilmKinematics { eccentricity_rate: k.eccentricity_rate + t * (whirl * e.norm()), journal_spin: 80.0 + 2.0 * whirl, ..k };
    let f_shifted = s.solve(&shifted).unwrap().force_on_journal;
    // equal up to the O(dtheta^2) difference between the central difference of H (wedge) and the exact dh/dt (squeeze)
    assert!((f_shifted - f).norm() < 1e-3 * f.norm(), "{f_shifted} vs {f}");
}

/// Fast mode against the exact solver (same grid) on random states up to eps = 0.95.
#[test]
fn force_table_matches_the_exact_solver() {
    let lod = 0.5;
    let t0 = std::time::Instant::now();
    let table = ForceTable::build(lod, &ForceTableOptions::default()).unwrap();
    let build = t0.elapsed();
    let g = geometry(lod);
    let mut s = ReynoldsSolver::new(g, ReynoldsOptions::default()).unwrap();
    let mut rng = Lcg(7);
    let (mut worst, mut sum, n) = (0.0_f64, 0.0, 300);
    let (mut exact_time, mut fast_time) = (std::time::Duration::ZERO, std::time::Duration::ZERO);
    for _ in 0..n {
        let k = random_state(&mut rng, g.clearance);
        let t1 = std::time::Instant::now();
        let exact = s.solve(&k).unwrap().film_force();
        exact_time += t1.elapsed();
        let t2 = std::time::Instant::now();
        let fast = table.film_force(&g, &k);
        fast_time += t2.elapsed();
        let err = (fast.force_on_journal - exact.force_on_journal).norm() / exact.force_on_journal.norm();
        let torque_err = (fast.friction_torque - exact.friction_torque).abs() / exact.friction_torque.abs();
        assert!(torque_err < 0.01, "torque error {torque_err}");
        worst = worst.max(err);
        sum += err;
    }
    println!(
        "table build {build:?}; force error mean {:.2e} max {worst:.2e}; exact {:?}, fast {:?} per state",
        sum / n as f64, exact_time / n as u32, fast_time / n as u32
    );
    assert!(worst < 0.005, "largest relative force error {worst}");
}


/// A grid past [`MAX_GRID_NODES`] is refused with its size before anything is
/// allocated (100 000 x 100 000 would need 120 GB and abort the process).
#[test]
fn oversized_grid_is_refused_before_allocating() {
    let o = ReynoldsOptions { n_circumferential: 100_000, n_axial: 100_000, ..Default::default() };
    let message = ReynoldsSolver::new(geometry(1.0), o).unwrap_err();
    assert_eq!(
        message,
        "grid 100000 x 100000 has 5000100000 nodes on the half length, more than the limit of 1000000 \
         (n_circumferential x (n_axial/2 + 1); solver memory and time grow with it)"
    );
    // the product saturates instead of overflowing
    let huge = ReynoldsOptions { n_circumferential: usize::MAX, n_axial: usize::MAX - 1, ..Default::default() };
    assert!(huge.validate_grid().unwrap_err().contains(&format!("{} nodes", usize::MAX)));
    // the bound itself is accepted: 2000 x (998/2 + 1) = 1 000 000 nodes
    let at_bound = ReynoldsOptions { n_circumferential: 2000, n_axial: 998, ..Default::default() };
    assert_eq!(at_bound.validate_grid(), Ok(()));
    let past = ReynoldsOptions { n_axial: 1000, ..at_bound };
    assert!(past.validate_grid().is_err());
}

#[test]
fn oversized_force_table_is_refused_before_solving() {
    let o = ForceTableOptions { n_eccentricity: 1000, n_angle: 1000, ..Default::default() };
    let message = ForceTable::build(1.0, &o).unwrap_err();
    assert_eq!(message, "force table 1000 x 1000 has 1000000 nodes, more than the limit of 65536 (one Reynolds solve each)");
    let grid = ForceTableOptions { solver: ReynoldsOptions { n_circumferential: 1 << 20, ..Default::default() }, ..Default::default() };
    assert!(ForceTable::build(1.0, &grid).unwrap_err().starts_with("grid 1048576 x 16 has"));
}

/// A run cancelled while its Reynolds solve relaxes stops the solve at the next sweep: the
/// solve asks [`crate::interrupt::keep_going`] once per sweep (here a watcher due at every call,
/// cancelling at its third), and the warm start is forgotten.
#[test]
fn a_cancelled_run_stops_the_solve_at_the_next_sweep() {
    use crate::dynamics::Progress;
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Arc;
    use std::time::Duration;

    let calls = Arc::new(AtomicUsize::new(0));
    let counted = Arc::clone(&calls);
    let progress = Progress::watched(Duration::ZERO, move |_| counted.fetch_add(1, Ordering::Relaxed) < 2);
    let o = ReynoldsOptions { n_circumferential: 240, n_axial: 32, tolerance: 1e-12, ..Default::default() };
    let mut solver = ReynoldsSolver::new(geometry(1.0), o).unwrap();
    let solved = progress.scope(|| solver.solve(&spinning(0.6, 100.0)));
    assert_eq!(solved.unwrap_err(), crate::interrupt::INTERRUPTED);
    assert_eq!(calls.load(Ordering::Relaxed), 3, "three sweeps, one call each");
    assert!(progress.is_cancelled());
    assert!(solver.pressure().iter().all(|p| *p == 0.0));
    // outside the run the same solve converges (it needs hundreds of sweeps)
    let converged = solver.solve(&spinning(0.6, 100.0)).unwrap();
    assert!(converged.iterations > 100, "{} sweeps", converged.iterations);
}
