//! The beam element against what it must equal independently of its code:
//! finite differences of its own forces and energy, rigid motion, the
//! Euler-Bernoulli and Timoshenko frequencies, the closed-form roll-up of a
//! cantilever under a tip moment, and the elastica under a tip load solved
//! here by shooting.

use super::*;
use nalgebra::{DMatrix, DVector, SymmetricEigen};
use std::f64::consts::PI;

/// Steel, for the frequency checks.
const STEEL: BeamMaterial = BeamMaterial { youngs_modulus: 210e9, poisson_ratio: 0.3, density: 7850.0 };

/// A straight beam of length `length` [m] along x from the origin, in `n` elements.
struct Mesh {
    elements: Vec<BeamElement>,
    /// Nodes per element minus one.
    step: usize,
    n_nodes: usize,
}

impl Mesh {
    fn straight(order: ElementOrder, section: BeamSection, length: f64, n: usize) -> Self {
        let step = order.n_nodes() - 1;
        let n_nodes = n * step + 1;
        let node = |k: usize| [length * k as f64 / (n_nodes - 1) as f64, 0.0, 0.0];
        let elements = (0..n)
            .map(|e| {
                let nodes: Vec<[f64; 3]> = (0..=step).map(|a| node(e * step + a)).collect();
                BeamElement::new(order, section, &nodes)
            })
            .collect();
        Self { elements, step, n_nodes }
    }

    fn n_coordinates(&self) -> usize {
        3 * self.n_nodes
    }

    /// The reference coordinates of all nodes.
    fn reference(&self) -> DVector<f64> {
        let mut q = DVector::zeros(self.n_coordinates());
        for (e, element) in self.elements.iter().enumerate() {
            let first = 3 * e * self.step;
            q.rows_mut(first, element.n_coordinates()).copy_from_slice(&element.reference[..element.n_coordinates()]);
        }
        q
    }

    /// Internal forces, tangent stiffness and mass of the whole beam at `q`.
    fn assemble(&self, q: &DVector<f64>) -> (DVector<f64>, DMatrix<f64>, DMatrix<f64>) {
        let n = self.n_coordinates();
        let (mut f, mut k, mut m) = (DVector::zeros(n), DMatrix::zeros(n, n), DMatrix::zeros(n, n));
        for (e, element) in self.elements.iter().enumerate() {
            let (first, nc) = (3 * e * self.step, element.n_coordinates());
            let qe: Vec<f64> = q.rows(first, nc).iter().copied().collect();
            let mut fe = vec![0.0; nc];
            let (mut ke, mut me) = (vec![0.0; nc * nc], vec![0.0; nc * nc]);
            element.add_internal_forces(&qe, &mut fe);
            element.add_tangent_stiffness(&qe, &mut ke);
            element.add_mass_matrix(&mut me);
            for i in 0..nc {
                f[first + i] += fe[i];
                for j in 0..nc {
                    k[(first + i, first + j)] += ke[i * nc + j];
                    m[(first + i, first + j)] += me[i * nc + j];
                }
            }
        }
        (f, k, m)
    }

    /// Static equilibrium `f(q) = load` with the coordinates `fixed` held at the
    /// reference, by Newton's method over `steps` equal load increments.
    fn solve_static(&self, load: &DVector<f64>, fixed: &[usize], steps: usize) -> DVector<f64> {
        let mut q = self.reference();
        let free: Vec<usize> = (0..self.n_coordinates()).filter(|i| !fixed.contains(i)).collect();
        for step in 1..=steps {
            let target = load * (step as f64 / steps as f64);
            // (converged when the correction reaches round-off of coordinates of order 1 m)
            for iteration in 0.. {
                let (f, k, _) = self.assemble(&q);
                let residual = DVector::from_iterator(free.len(), free.iter().map(|&i| target[i] - f[i]));
                let kf = DMatrix::from_fn(free.len(), free.len(), |r, c| k[(free[r], free[c])]);
                let dq = kf.lu().solve(&residual).expect("a regular tangent");
                for (r, &i) in free.iter().enumerate() {
                    q[i] += dq[r];
                }
                if dq.amax() < 1e-13 {
                    break;
                }
                assert!(iteration < 30, "Newton did not converge at load step {step}: correction {}", dq.amax());
            }
        }
        q
    }

    /// Angular frequencies [rad/s] of small vibrations about the reference with `fixed` held,
    /// and whether each mode moves mostly transversely (y) rather than axially (x).
    fn frequencies(&self, fixed: &[usize]) -> Vec<(f64, bool)> {
        let (_, k, m) = self.assemble(&self.reference());
        let free: Vec<usize> = (0..self.n_coordinates()).filter(|i| !fixed.contains(i)).collect();
        let pick = |a: &DMatrix<f64>| DMatrix::from_fn(free.len(), free.len(), |r, c| a[(free[r], free[c])]);
        let (k, m) = (pick(&k), pick(&m));
        // K x = w^2 M x with M = L L^T: (L^-1 K L^-T) y = w^2 y
        let l = m.cholesky().expect("a positive definite mass").l();
        let l_inv = l.clone().try_inverse().unwrap();
        let c = &l_inv * k * l_inv.transpose();
        let c = (&c + c.transpose()) * 0.5;
        let eigen = SymmetricEigen::new(c);
        let modes = l_inv.transpose() * eigen.eigenvectors;
        let mut out: Vec<(f64, bool)> = eigen
            .eigenvalues
            .iter()
            .enumerate()
            .map(|(j, &w2)| {
                let mode = modes.column(j);
                let along = |dof: usize| free.iter().enumerate().filter(|(_, &i)| i % 3 == dof).map(|(r, _)| mode[r] * mode[r]).sum::<f64>();
                (w2.max(0.0).sqrt(), along(1) > along(0))
            })
            .collect();
        out.sort_by(|a, b| a.0.total_cmp(&b.0));
        out
    }
}

/// A deformed, turned and stretched state of one element for the derivative checks.
fn deformed(element: &BeamElement) -> Vec<f64> {
    let nc = element.n_coordinates();
    (0..nc)
        .map(|i| {
            let wiggle = [0.013, -0.021, 0.37][i % 3] * (1.0 + 0.7 * (i / 3) as f64);
            element.reference[i] * 1.02 + wiggle
        })
        .collect()
}

/// Central difference of `f` by coordinate `j` of `q`, with step 1e-6.
fn central_difference(q: &[f64], j: usize, f: impl Fn(&[f64]) -> Vec<f64>) -> Vec<f64> {
    let h = 1e-6;
    let (mut plus, mut minus) = (q.to_vec(), q.to_vec());
    plus[j] += h;
    minus[j] -= h;
    f(&plus).iter().zip(f(&minus)).map(|(p, m)| (p - m) / (2.0 * h)).collect()
}

fn section() -> BeamSection {
    BeamSection { axial_stiffness: 3.0e6, shear_stiffness: 1.1e6, bending_stiffness: 2.0e3, mass_per_length: 1.2, rotary_inertia_per_length: 6e-4 }
}

#[test]
fn tangent_stiffness_is_the_derivative_of_the_internal_forces() {
    for order in [ElementOrder::Linear, ElementOrder::Quadratic] {
        let nodes: Vec<[f64; 3]> = (0..order.n_nodes()).map(|a| [0.3 * a as f64, 0.1 * a as f64, (0.1f64).atan2(0.3)]).collect();
        let element = BeamElement::new(order, section(), &nodes);
        let q = deformed(&element);
        let nc = element.n_coordinates();
        let mut k = vec![0.0; nc * nc];
        element.add_tangent_stiffness(&q, &mut k);
        let scale = k.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for j in 0..nc {
            let forces = |q: &[f64]| {
                let mut f = vec![0.0; nc];
                element.add_internal_forces(q, &mut f);
                f
            };
            let column = central_difference(&q, j, forces);
            for (i, &difference) in column.iter().enumerate() {
                assert!((k[i * nc + j] - difference).abs() < 1e-7 * scale, "{order:?} K[{i}][{j}] = {} against {difference}", k[i * nc + j]);
            }
        }
        // symmetric: the forces derive from the strain energy
        for i in 0..nc {
            for j in 0..i {
                assert!((k[i * nc + j] - k[j * nc + i]).abs() < 1e-12 * scale);
            }
        }
    }
}

#[test]
fn internal_forces_are_the_gradient_of_the_strain_energy() {
    for order in [ElementOrder::Linear, ElementOrder::Quadratic] {
        let nodes: Vec<[f64; 3]> = (0..order.n_nodes()).map(|a| [0.25 * a as f64, 0.0, 0.0]).collect();
        let element = BeamElement::new(order, section(), &nodes);
        let q = deformed(&element);
        let nc = element.n_coordinates();
        let mut f = vec![0.0; nc];
        element.add_internal_forces(&q, &mut f);
        let scale = f.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for j in 0..nc {
            let gradient = central_difference(&q, j, |q| vec![element.strain_energy(q)])[0];
            assert!((f[j] - gradient).abs() < 1e-7 * scale, "{order:?} f[{j}] = {} against dU/dq {gradient}", f[j]);
        }
    }
}

#[test]
fn a_rigid_motion_strains_nothing() {
    for order in [ElementOrder::Linear, ElementOrder::Quadratic] {
        let nodes: Vec<[f64; 3]> = (0..order.n_nodes()).map(|a| [0.2 * a as f64, 0.0, 0.0]).collect();
        let element = BeamElement::new(order, section(), &nodes);
        let (turn, shift) = (2.3f64, [0.7, -1.9]);
        let (s, c) = turn.sin_cos();
        let q: Vec<f64> = nodes.iter().flat_map(|n| [c * n[0] - s * n[1] + shift[0], s * n[0] + c * n[1] + shift[1], n[2] + turn]).collect();
        let mut f = vec![0.0; element.n_coordinates()];
        element.add_internal_forces(&q, &mut f);
        assert!(f.iter().all(|v| v.abs() < 1e-9 * section().axial_stiffness), "{f:?}");
        assert!(element.strain_energy(&q).abs() < 1e-20 * section().axial_stiffness);
        let strains = element.strains(&q, 0.3);
        assert!(strains.axial.abs() < 1e-14 && strains.shear.abs() < 1e-14 && strains.curvature.abs() < 1e-14);
    }
}

#[test]
fn mass_matrix_carries_the_mass_and_rotary_inertia_of_the_beam() {
    for order in [ElementOrder::Linear, ElementOrder::Quadratic] {
        let length = 0.8;
        let nodes: Vec<[f64; 3]> = (0..order.n_nodes()).map(|a| [length * a as f64 / (order.n_nodes() - 1) as f64, 0.0, 0.0]).collect();
        let element = BeamElement::new(order, section(), &nodes);
        let nc = element.n_coordinates();
        let mut m = vec![0.0; nc * nc];
        element.add_mass_matrix(&mut m);
        // a uniform velocity (1, 0, 0) at every node: kinetic energy rhoA L / 2; a uniform spin, rhoI L / 2
        let energy = |v: [f64; 3]| -> f64 {
            let u: Vec<f64> = (0..nc).map(|i| v[i % 3]).collect();
            (0..nc).map(|i| (0..nc).map(|j| u[i] * m[i * nc + j] * u[j]).sum::<f64>()).sum::<f64>() / 2.0
        };
        assert!((energy([1.0, 0.0, 0.0]) - section().mass_per_length * length / 2.0).abs() < 1e-14);
        assert!((energy([0.0, 0.0, 1.0]) - section().rotary_inertia_per_length * length / 2.0).abs() < 1e-16);
        // a linear velocity field v_y = x: integral of rhoA x^2 / 2 = rhoA L^3 / 6 (exact for both orders)
        let u: Vec<f64> = (0..nc).map(|i| if i % 3 == 1 { nodes[i / 3][0] } else { 0.0 }).collect();
        let e: f64 = (0..nc).map(|i| (0..nc).map(|j| u[i] * m[i * nc + j] * u[j]).sum::<f64>()).sum::<f64>() / 2.0;
        assert!((e - section().mass_per_length * length.powi(3) / 6.0).abs() < 1e-14);
    }
}

/// `beta L` of the first three bending modes, clamped-free and free-free (Euler-Bernoulli;
/// Blevins, *Formulas for Natural Frequency and Mode Shape*, 1979, Table 8-1).
const CLAMPED_FREE: [f64; 3] = [1.875_104_07, 4.694_091_13, 7.854_757_44];
const FREE_FREE: [f64; 3] = [4.730_040_74, 7.853_204_62, 10.995_607_84];

#[test]
fn slender_beam_frequencies_match_euler_bernoulli() {
    // L / h = 100: shear and rotary inertia lower the third clamped-free frequency by about 1e-3
    let length = 1.0;
    let section = BeamSection::of(&SectionShape::Rectangle { width: 0.02, height: 0.01 }, &STEEL).unwrap();
    let unit = (section.bending_stiffness / section.mass_per_length).sqrt() / (length * length);
    for order in [ElementOrder::Linear, ElementOrder::Quadratic] {
        let n = if order == ElementOrder::Linear { 60 } else { 16 };
        let mesh = Mesh::straight(order, section, length, n);
        let bending = |fixed: &[usize]| -> Vec<f64> { mesh.frequencies(fixed).into_iter().filter(|&(w, transverse)| transverse && w > 1e-3 * unit).map(|(w, _)| w).collect() };
        let clamped = bending(&[0, 1, 2]);
        let free = bending(&[]);
        // reduced integration leaves no spurious zero-energy mode: only the three rigid ones
        let zero = mesh.frequencies(&[]).iter().filter(|m| m.0 < 1e-3 * unit).count();
        assert_eq!(zero, 3, "{order:?}: {zero} modes without stiffness");
        for (k, beta) in CLAMPED_FREE.iter().enumerate() {
            let expected = beta * beta * unit;
            assert!((clamped[k] / expected - 1.0).abs() < 2e-3, "{order:?} clamped-free mode {}: {} against {expected}", k + 1, clamped[k]);
        }
        for (k, beta) in FREE_FREE.iter().enumerate() {
            let expected = beta * beta * unit;
            assert!((free[k] / expected - 1.0).abs() < 2e-3, "{order:?} free-free mode {}: {} against {expected}", k + 1, free[k]);
        }
    }
}

#[test]
fn thick_simply_supported_beam_frequencies_match_timoshenko() {
    // L / h = 5, where Euler-Bernoulli overestimates the first frequency by several per cent.
    // Timoshenko's equations with w = W sin(k x), psi = Psi cos(k x), k = n pi / L give
    // (kGA k^2 - rhoA w^2)(EI k^2 + kGA - rhoI w^2) = (kGA k)^2, whose lower root in w^2 is
    // the bending frequency (Timoshenko 1921; Han, Benaroya and Wei, J. Sound Vib. 225 (1999) 935-988, §7).
    let length = 1.0;
    let s = BeamSection::of(&SectionShape::Rectangle { width: 0.1, height: 0.2 }, &STEEL).unwrap();
    let timoshenko = |n: f64| {
        let k = n * PI / length;
        let (ga, ei, ra, ri) = (s.shear_stiffness, s.bending_stiffness, s.mass_per_length, s.rotary_inertia_per_length);
        let a = ra * ri;
        let b = -(ra * (ei * k * k + ga) + ri * ga * k * k);
        let c = ga * ei * k.powi(4);
        ((-b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a)).sqrt()
    };
    let euler_bernoulli = (PI / length).powi(2) * (s.bending_stiffness / s.mass_per_length).sqrt();
    assert!(timoshenko(1.0) < 0.97 * euler_bernoulli, "the case is thick enough to tell the theories apart");
    let mesh = Mesh::straight(ElementOrder::Quadratic, s, length, 20);
    let last = 3 * (mesh.n_nodes - 1);
    let bending: Vec<f64> = mesh.frequencies(&[0, 1, last + 1]).into_iter().filter(|m| m.1).map(|m| m.0).collect();
    for n in [1.0, 2.0] {
        let expected = timoshenko(n);
        let found = bending[n as usize - 1];
        assert!((found / expected - 1.0).abs() < 1e-3, "mode {n}: {found} against Timoshenko {expected} rad/s");
    }
}

/// Largest distance [m] of the nodes of a cantilever rolled by a tip moment from the
/// circle of radius L / (2 pi) through the root, and the tip angle [rad].
fn rolled_cantilever(order: ElementOrder, n: usize) -> (f64, f64, f64) {
    let length = 1.0;
    let section = BeamSection { axial_stiffness: 1e4, shear_stiffness: 1e4, bending_stiffness: 1.0, mass_per_length: 1.0, rotary_inertia_per_length: 1e-4 };
    let mesh = Mesh::straight(order, section, length, n);
    let mut load = DVector::zeros(mesh.n_coordinates());
    let tip = mesh.n_coordinates() - 1;
    load[tip] = 2.0 * PI * section.bending_stiffness / length;
    let q = mesh.solve_static(&load, &[0, 1, 2], 8);
    let radius = length / (2.0 * PI);
    let off_circle = (0..mesh.n_nodes).map(|a| ((q[3 * a].powi(2) + (q[3 * a + 1] - radius).powi(2)).sqrt() - radius).abs()).fold(0.0, f64::max);
    let tip_gap = (q[tip - 2].powi(2) + q[tip - 1].powi(2)).sqrt();
    (off_circle, tip_gap, q[tip])
}

#[test]
fn a_tip_moment_of_two_pi_ei_over_l_rolls_a_cantilever_into_a_circle() {
    // closed form: constant curvature M / EI = 2 pi / L, the tip back at the root turned by
    // 2 pi, every point on the circle of radius L / (2 pi) through the root. (With reduced
    // integration the resultants vanish at the Gauss points, so the elements keep their length
    // and the tip closes to round-off; the nodes sit on a slightly larger circle.)
    for (order, n, tolerance) in [(ElementOrder::Linear, 32, 1e-3), (ElementOrder::Quadratic, 16, 1e-5)] {
        let (off_circle, tip_gap, tip_angle) = rolled_cantilever(order, n);
        assert!((tip_angle - 2.0 * PI).abs() < 1e-9, "{order:?} tip angle {tip_angle}");
        assert!(tip_gap < 1e-9, "{order:?}: tip {tip_gap} m from the root");
        assert!(off_circle < tolerance, "{order:?}: nodes up to {off_circle} m off the circle");
    }
    // the distance from the circle falls as h^2 (linear; measured 2.02) and h^4 (quadratic; 3.99)
    for (order, at_least) in [(ElementOrder::Linear, 1.9), (ElementOrder::Quadratic, 3.8)] {
        let (coarse, fine) = (rolled_cantilever(order, 8).0, rolled_cantilever(order, 16).0);
        let rate = (coarse / fine).log2();
        assert!(rate > at_least, "{order:?} convergence order {rate} (off the circle by {coarse}, {fine} m)");
    }
}

/// Tip position `(x, y)` / L of the inextensible, unshearable elastica of a cantilever along x
/// under a dead tip load `-alpha EI / L^2` along y: `theta'' = alpha cos(theta)` (L = EI = 1),
/// `theta(0) = 0`, `theta'(1) = 0`, by shooting on `theta'(0)` with classical Runge-Kutta.
fn elastica_tip(alpha: f64) -> (f64, f64) {
    let shoot = |kappa0: f64| -> (f64, f64, f64) {
        let steps = 20_000;
        let h = 1.0 / steps as f64;
        let rate = |s: [f64; 4]| [s[1], alpha * s[0].cos(), s[0].cos(), s[0].sin()];
        let mut s = [0.0, kappa0, 0.0, 0.0];
        for _ in 0..steps {
            let k1 = rate(s);
            let k2 = rate(std::array::from_fn(|i| s[i] + 0.5 * h * k1[i]));
            let k3 = rate(std::array::from_fn(|i| s[i] + 0.5 * h * k2[i]));
            let k4 = rate(std::array::from_fn(|i| s[i] + h * k3[i]));
            s = std::array::from_fn(|i| s[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        }
        (s[1], s[2], s[3])
    };
    // the root curvature lies in [-alpha, 0]: bisection on the tip curvature
    let (mut low, mut high) = (-alpha, 0.0);
    for _ in 0..60 {
        let mid = 0.5 * (low + high);
        if shoot(mid).0 > 0.0 { high = mid } else { low = mid }
    }
    let (_, x, y) = shoot(0.5 * (low + high));
    (x, y)
}

#[test]
fn a_tip_load_bends_a_cantilever_as_the_elastica() {
    // stiff in tension and shear (EA, kGA = 1e7 EI / L^2) so that the inextensible elastica applies
    let section = BeamSection { axial_stiffness: 1e7, shear_stiffness: 1e7, bending_stiffness: 1.0, mass_per_length: 1.0, rotary_inertia_per_length: 1e-4 };
    // Bisshopp and Drucker (Q. Appl. Math. 3 (1945) 272-275) solved this elastica by elliptic
    // integrals; for alpha = 1 their tip deflection is 0.3017 L, which the shooting reproduces
    let (_, y1) = elastica_tip(1.0);
    assert!((-y1 - 0.3017).abs() < 5e-5, "shooting: {}", -y1);
    for alpha in [1.0, 3.0, 10.0] {
        let (x, y) = elastica_tip(alpha);
        let mesh = Mesh::straight(ElementOrder::Quadratic, section, 1.0, 16);
        let mut load = DVector::zeros(mesh.n_coordinates());
        let tip = 3 * (mesh.n_nodes - 1);
        load[tip + 1] = -alpha;
        let q = mesh.solve_static(&load, &[0, 1, 2], 10);
        assert!((q[tip] - x).abs() < 2e-5 && (q[tip + 1] - y).abs() < 2e-5, "alpha {alpha}: tip ({}, {}) against the elastica ({x}, {y})", q[tip], q[tip + 1]);
    }
}

#[test]
fn sections_from_shapes_have_their_closed_form_properties() {
    let steel = STEEL;
    let g = steel.youngs_modulus / (2.0 * 1.3);
    let rectangle = BeamSection::of(&SectionShape::Rectangle { width: 0.02, height: 0.01 }, &steel).unwrap();
    assert!((rectangle.bending_stiffness - steel.youngs_modulus * 0.02 * 1e-6 / 12.0).abs() < 1e-9 * rectangle.bending_stiffness);
    assert!((rectangle.shear_stiffness - 10.0 * 1.3 / (12.0 + 3.3) * g * 2e-4).abs() < 1e-9 * rectangle.shear_stiffness);
    // a tube whose bore tends to zero is the solid circle
    let circle = BeamSection::of(&SectionShape::Circle { diameter: 0.02 }, &steel).unwrap();
    let tube = BeamSection::of(&SectionShape::Tube { outer_diameter: 0.02, inner_diameter: 1e-9 }, &steel).unwrap();
    for (a, b) in [(circle.axial_stiffness, tube.axial_stiffness), (circle.shear_stiffness, tube.shear_stiffness), (circle.bending_stiffness, tube.bending_stiffness)] {
        assert!((a / b - 1.0).abs() < 1e-9, "{a} against {b}");
    }
    assert!((circle.rotary_inertia_per_length - 7850.0 * PI * 1e-8 / 4.0).abs() < 1e-15);
    let bad = BeamSection::of(&SectionShape::Tube { outer_diameter: 0.02, inner_diameter: 0.03 }, &steel).unwrap_err();
    assert!(bad.contains("inner diameter") && bad.contains("0.03"), "{bad}");
    assert!(BeamSection { bending_stiffness: -1.0, ..rectangle }.validated().unwrap_err().contains("-1"));
}

#[test]
fn recovered_resultants_of_a_loaded_cantilever_balance_the_load_at_every_section() {
    // a cantilever under a tip force (P, -F) is, by statics, under N = P, Q = -F, M = -F (L - s)
    // in the small-deflection limit (here deflection / L = 4e-6, so the rotation of the
    // section changes N and Q by less than 1e-5 of F); the displacement field of a coarse
    // reduced-integrated mesh has large parasitic shear between the Gauss points, so the
    // strains read directly at an element's end are wrong while the recovered ones are not
    let (length, n) = (1.0, 4);
    let section = section();
    let f = 1e-6 * section.bending_stiffness / (length * length);
    let p = 0.5 * f;
    for order in [ElementOrder::Linear, ElementOrder::Quadratic] {
        let mesh = Mesh::straight(order, section, length, n);
        let mut load = DVector::zeros(mesh.n_coordinates());
        load[mesh.n_coordinates() - 3] = p;
        load[mesh.n_coordinates() - 2] = -f;
        let q = mesh.solve_static(&load, &[0, 1, 2], 1);
        for (e, element) in mesh.elements.iter().enumerate() {
            let qe: Vec<f64> = q.rows(3 * e * mesh.step, element.n_coordinates()).iter().copied().collect();
            for xi in [-1.0, -0.3, 0.6, 1.0] {
                let s = length * (e as f64 + 0.5 * (xi + 1.0)) / n as f64;
                let (strains, _) = element.recovered_strains(&qe, None, xi);
                let (normal, shear, moment) = (section.axial_stiffness * strains.axial, section.shear_stiffness * strains.shear, section.bending_stiffness * strains.curvature);
                assert!((normal - p).abs() < 1e-4 * f, "{order:?} element {e} xi {xi}: N {normal} vs {p}");
                assert!((shear + f).abs() < 1e-4 * f, "{order:?} element {e} xi {xi}: Q {shear} vs {}", -f);
                // the moment is linear in s: exact at the points of a quadratic element's rule,
                // constant (the element's mid value) over a linear one
                let mid = length * (e as f64 + 0.5) / n as f64;
                let expected = if order == ElementOrder::Linear { -f * (length - mid) } else { -f * (length - s) };
                assert!((moment - expected).abs() < 1e-4 * f * length, "{order:?} element {e} xi {xi}: M {moment} vs {expected}");
            }
        }
    }
}
