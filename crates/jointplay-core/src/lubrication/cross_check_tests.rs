//! Closed-form dynamic bearing models against the finite-difference Reynolds
//! solver in their limits. The two were written separately: the closed forms
//! integrate analytic pressures in the line-of-centres frame with the wedge
//! speed `omega_j + omega_b - 2 gamma_dot`; the solver discretises the
//! Reynolds equation in the fixed frame from `h(theta)` and `dh/dt` and
//! knows nothing of whirl or of a line of centres.
//!
//! Limits and the matching film condition of each model (docs/theory/bearing-*.md):
//!
//! | model | limit | solver film condition |
//! |---|---|---|
//! | `HamrockShort`, `SqueezeFilm` short | L/D -> 0 | Gümbel (drop negative full-film pressures) |
//! | `FreneShort` | L/D -> 0 | full film (ambient pressure far above the film pressures) |
//! | `FreneLong` | L/D -> inf | full film, mid-plane force per length |
//! | `PinkusSternlichtLong` | L/D -> inf | Gümbel with the thickest line held at ambient (`feed_at_thickest_film`), mid-plane |
//! | `HamrockLong`, `SqueezeFilm` long | L/D -> inf | Gümbel, mid-plane (pure wedge only: see below) |
//!
//! Short limit: the solver is run at L/D = 1/8 and 1/16 and the force per
//! `L^3` extrapolated to L/D = 0 by Richardson (the short-bearing expansion
//! is in powers of (L/D)^2). Long limit: the force per unit length at the
//! mid-plane of an L/D = 8 bearing (end effects decay like exp(-z/R), 8 radii
//! away: below 1e-3), times L.

use super::closed_form::ClosedFormBearing;
use super::film::{BearingGeometry, FilmKinematics};
use super::reynolds::{Cavitation, ReynoldsOptions, ReynoldsSolver};
use super::squeeze_film::{SqueezeFilm, SqueezeFilmTheory};
use nalgebra::Vector2;
use std::f64::consts::PI;

const RADIUS: f64 = 0.01;
const CLEARANCE: f64 = 1e-5;
const VISCOSITY: f64 = 0.04;
/// Ambient pressure far above every film pressure here (< 3e8 Pa): the film stays full [Pa].
const FULL_FILM_AMBIENT: f64 = 1e10;

fn geometry(l_over_d: f64) -> BearingGeometry {
    BearingGeometry { radius: RADIUS, length: 2.0 * RADIUS * l_over_d, clearance: CLEARANCE, viscosity: VISCOSITY }
}

/// A state of the film: eccentricity ratio along +x, squeeze rate eps_dot [1/s],
/// whirl gamma_dot [rad/s], journal and bearing spins [rad/s].
#[derive(Clone, Copy, Debug)]
struct Motion {
    name: &'static str,
    eps: f64,
    eps_dot: f64,
    whirl: f64,
    journal_spin: f64,
    bearing_spin: f64,
}

impl Motion {
    fn kinematics(&self) -> FilmKinematics {
        FilmKinematics {
            eccentricity: Vector2::new(self.eps * CLEARANCE, 0.0),
            eccentricity_rate: Vector2::new(self.eps_dot, self.eps * self.whirl) * CLEARANCE,
            journal_spin: self.journal_spin,
            bearing_spin: self.bearing_spin,
        }
    }
}

/// Wedge with squeeze `eps_dot = ratio * eps * wbar / 2` (ratio = squeeze over wedge term in the Reynolds source).
const fn mixed(name: &'static str, ratio: f64) -> Motion {
    Motion { name, eps: 0.6, eps_dot: ratio * 0.6 * 100.0 / 2.0, whirl: 0.0, journal_spin: 100.0, bearing_spin: 0.0 }
}

const MOTIONS: [Motion; 8] = [
    Motion { name: "pure wedge", eps: 0.6, eps_dot: 0.0, whirl: 0.0, journal_spin: 100.0, bearing_spin: 0.0 },
    Motion { name: "pure squeeze, approach", eps: 0.5, eps_dot: 30.0, whirl: 0.0, journal_spin: 0.0, bearing_spin: 0.0 },
    Motion { name: "pure squeeze, recess", eps: 0.5, eps_dot: -30.0, whirl: 0.0, journal_spin: 0.0, bearing_spin: 0.0 },
    mixed("squeeze/wedge +0.5", 0.5),
    mixed("squeeze/wedge -0.5", -0.5),
    mixed("squeeze/wedge +2", 2.0),
    mixed("squeeze/wedge -2", -2.0),
    // wbar = 120 - 30 - 2 * 25 = 40 rad/s
    Motion { name: "whirl, turning bearing", eps: 0.4, eps_dot: 8.0, whirl: 25.0, journal_spin: 120.0, bearing_spin: -30.0 },
];

fn options(grid: (usize, usize), cavitation: Cavitation) -> ReynoldsOptions {
    ReynoldsOptions { n_circumferential: grid.0, n_axial: grid.1, cavitation, tolerance: 1e-9, ..Default::default() }
}

/// Film condition of the solver.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Film {
    Gumbel,
    SwiftStieber,
    Full,
    GumbelFedAtThickest,
}

fn solver(l_over_d: f64, grid: (usize, usize), film: Film) -> ReynoldsSolver {
    let mut o = options(grid, Cavitation::Gumbel);
    match film {
        Film::Gumbel => {}
        Film::SwiftStieber => o.cavitation = Cavitation::SwiftStieber,
        Film::Full => o.ambient_pressure = FULL_FILM_AMBIENT,
        Film::GumbelFedAtThickest => o.feed_at_thickest_film = true,
    }
    ReynoldsSolver::new(geometry(l_over_d), o).unwrap()
}

/// Total force of the solver divided by L^3, extrapolated to L/D = 0 from L/D = 1/8 and 1/16.
fn short_limit_per_cube(k: &FilmKinematics, film: Film) -> (Vector2<f64>, Vector2<f64>) {
    let per_cube = |lod: f64| {
        let mut s = solver(lod, (144, 32), film);
        s.solve(k).unwrap().force_on_journal / geometry(lod).length.powi(3)
    };
    let (coarse, fine) = (per_cube(1.0 / 8.0), per_cube(1.0 / 16.0));
    ((4.0 * fine - coarse) / 3.0, coarse)
}

/// Force per unit length at the mid-plane (row j = 0) of an L/D = 8 bearing.
fn long_limit_per_length(k: &FilmKinematics, film: Film) -> Vector2<f64> {
    let mut s = solver(8.0, (144, 64), film);
    s.solve(k).unwrap();
    let ambient = if film == Film::Full { FULL_FILM_AMBIENT } else { 0.0 };
    let (n_theta, n_half) = s.field_shape();
    let dtheta = 2.0 * PI / n_theta as f64;
    let p = s.pressure();
    let mut f = Vector2::zeros();
    for i in 0..n_theta {
        let (sn, cs) = (i as f64 * dtheta).sin_cos();
        f -= Vector2::new(cs, sn) * ((p[i * n_half] - ambient) * RADIUS * dtheta);
    }
    f
}

/// Relative magnitude error and angle between two forces [-, rad].
fn disagreement(closed: Vector2<f64>, solver: Vector2<f64>) -> (f64, f64) {
    let angle = (closed.x * solver.y - closed.y * solver.x).atan2(closed.dot(&solver));
    (solver.norm() / closed.norm() - 1.0, angle)
}

/// Asserts agreement of magnitude (relative) and direction, printing the numbers.
fn assert_agrees(what: &str, closed: Vector2<f64>, solver: Vector2<f64>, magnitude_tol: f64, angle_tol_deg: f64) {
    let (magnitude, angle) = disagreement(closed, solver);
    println!("{what:<60} magnitude {:+.3} %  direction {:+.3} deg", 100.0 * magnitude, angle.to_degrees());
    assert!(magnitude.abs() < magnitude_tol, "{what}: magnitude off by {:.3} %", 100.0 * magnitude);
    assert!(angle.to_degrees().abs() < angle_tol_deg, "{what}: direction off by {:.3} deg", angle.to_degrees());
}

fn is_pure_squeeze(m: &Motion) -> bool {
    m.journal_spin == 0.0 && m.bearing_spin == 0.0 && m.whirl == 0.0
}

/// Short models against the solver extrapolated to L/D = 0, every motion.
///
/// Tolerance 0.4 % in magnitude and 0.2 degree in direction. The error
/// budget of the extrapolated solver force on the 144x32 grid: the trapezoid
/// rule over the 16 half-length intervals integrates the parabolic axial
/// profile `L^2/4 - z^2` low by `1/(4 * 16^2)` = 0.098 % (observed -0.09 to
/// -0.18 %); the circumferential error is O(dtheta^2), about 0.05 % at 2.5
/// degree cells (the helper tests show ~1 % at 120x16 for L/D = 1, where the
/// axial error dominates); the Richardson step leaves O((L/D)^4) of the
/// 1.2-2.9 % finite-length correction seen at L/D = 1/8, i.e. below 0.1 %.
/// Observed: magnitude within 0.19 %, direction within 0.04 degree.
#[test]
fn short_models_match_the_solver_as_l_over_d_goes_to_zero() {
    let g = geometry(1.0);
    let cube = g.length.powi(3);
    for m in MOTIONS {
        let k = m.kinematics();
        let hamrock = ClosedFormBearing::HamrockShort.film_force(&g, &k).force_on_journal / cube;
        let (gumbel, _) = short_limit_per_cube(&k, Film::Gumbel);
        assert_agrees(&format!("HamrockShort / Gümbel, {}", m.name), hamrock, gumbel, 0.004, 0.2);
        // in the short limit each axial line is its own problem: Swift-Stieber gives the same film
        let (swift_stieber, _) = short_limit_per_cube(&k, Film::SwiftStieber);
        assert_agrees(&format!("HamrockShort / Swift-Stieber, {}", m.name), hamrock, swift_stieber, 0.004, 0.2);
        let frene = ClosedFormBearing::FreneShort.film_force(&g, &k).force_on_journal / cube;
        let (full, _) = short_limit_per_cube(&k, Film::Full);
        assert_agrees(&format!("FreneShort / full film, {}", m.name), frene, full, 0.004, 0.2);
        if is_pure_squeeze(&m) {
            let squeeze = SqueezeFilm::new(g, SqueezeFilmTheory::ShortBearing).film_force(&k).force_on_journal / cube;
            assert_agrees(&format!("SqueezeFilm short / Gümbel, {}", m.name), squeeze, gumbel, 0.004, 0.2);
        }
    }
}

/// Long models with a well-defined long-bearing film against the mid-plane
/// of an L/D = 8 bearing, every motion: Frêne et al. (full film) and
/// Pinkus-Sternlicht (Sommerfeld pressure, ambient at the thickest film,
/// negative part dropped = Gümbel with the thickest line held at ambient).
///
/// Tolerance 0.5 % in magnitude and 0.1 degree in direction: on the
/// 144x64 grid the circumferential O(dtheta^2) error is about 0.05 %, the
/// clipped (Gümbel) film edges between nodes add a similar amount, and the
/// end effect at the mid-plane is of order exp(-8) = 3e-4.
/// Observed: magnitude within 0.12 %, direction within 0.03 degree. The
/// receding pure squeeze of Pinkus-Sternlicht gives no force on either side.
#[test]
fn long_full_film_and_pinkus_sternlicht_match_the_solver_at_the_midplane() {
    let g = geometry(1.0);
    for m in MOTIONS {
        let k = m.kinematics();
        let frene = ClosedFormBearing::FreneLong.film_force(&g, &k).force_on_journal / g.length;
        assert_agrees(&format!("FreneLong / full film, {}", m.name), frene, long_limit_per_length(&k, Film::Full), 0.005, 0.1);
        let pinkus = ClosedFormBearing::PinkusSternlichtLong.film_force(&g, &k).force_on_journal / g.length;
        let fed = long_limit_per_length(&k, Film::GumbelFedAtThickest);
        if pinkus.norm() == 0.0 {
            println!("{:<60} both zero (solver {:.1e} N/m)", format!("PinkusSternlichtLong / Gümbel fed, {}", m.name), fed.norm());
            assert!(fed.norm() < 1e-9 * frene.norm(), "{}: solver {fed}", m.name);
        } else {
            assert_agrees(&format!("PinkusSternlichtLong / Gümbel fed at thickest, {}", m.name), pinkus, fed, 0.005, 0.1);
        }
    }
}

/// Hamrock's long bearing (and the long squeeze film, its pure-squeeze case)
/// puts the pi film on the half where the Reynolds source is negative, with
/// `p = 0` at both ends. That is where the short-bearing Gümbel pressure is
/// positive, but not the long one: under pure squeeze the full-film long
/// pressure is `(6 mu R^2/c^2)(eps_dot/eps)(1/D^2 - C)`, with
/// `C = 1/(1 + 3 eps^2/2)` for a bearing with ambient ends (the `h^3`-weighted
/// mean of the mid-plane pressure vanishes), so it changes sign elsewhere than
/// at the ends of the half. Its positive part, integrated analytically, is
/// +13.77 % (approach) and -56.65 % (recess) off the model at eps = 0.5, as
/// the solver finds (+13.78 %, -56.66 %).
/// The model is the Gümbel long bearing for pure wedge only (tolerance as
/// above; observed -0.02 %); with squeeze it is off by 10 to 57 %. Pinned
/// here so that a change of either side is noticed; see
/// docs/theory/lubrication-validation.md.
#[test]
fn hamrock_long_is_the_gumbel_long_bearing_for_pure_wedge_only() {
    let g = geometry(1.0);
    for m in MOTIONS {
        let k = m.kinematics();
        let hamrock = ClosedFormBearing::HamrockLong.film_force(&g, &k).force_on_journal / g.length;
        let gumbel = long_limit_per_length(&k, Film::Gumbel);
        if m.eps_dot == 0.0 {
            assert_agrees(&format!("HamrockLong / Gümbel, {}", m.name), hamrock, gumbel, 0.005, 0.1);
            continue;
        }
        let (magnitude, angle) = disagreement(hamrock, gumbel);
        println!("{:<60} magnitude {:+.3} %  direction {:+.3} deg (known)", format!("HamrockLong / Gümbel, {}", m.name), 100.0 * magnitude, angle.to_degrees());
        assert!(magnitude.abs() > 0.05, "{}: HamrockLong now agrees with the Gümbel long bearing ({:.3} %): update the docs", m.name, 100.0 * magnitude);
        if is_pure_squeeze(&m) {
            let squeeze = SqueezeFilm::new(g, SqueezeFilmTheory::LongBearing).film_force(&k).force_on_journal / g.length;
            assert!((squeeze - hamrock).norm() < 1e-10 * hamrock.norm(), "{}: long squeeze film is HamrockLong's pure squeeze", m.name);
        }
    }
}
