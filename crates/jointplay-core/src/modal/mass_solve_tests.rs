//! The mass solve that factors only the constant modal block
//! ([`crate::modal::BodyMassSolve`]) checked against nalgebra's dense Cholesky
//! of the whole mass `M(q) = T(phi) Mbar(eta) T(phi)^T`, formed in the test,
//! over random configurations, frames and mode counts; `Mbar` itself against
//! the mass of the kinetic energy (which `modal/tests.rs` checks against the
//! beam mesh's).

use nalgebra::{DMatrix, DVector};

use crate::beam::{BeamSection, ElementOrder};
use crate::body::{BeamBody, BeamMesh, BodyKind, BodyModel, ModalBody};
use crate::kinematics::planar::Vec2;
use crate::modal::{BodyMassSolve, FrameReference, InertiaInvariants, NodalCoordinates};

/// A 1 m beam (EI = 100 N m^2, rho A = 2 kg/m) of `elements` quadratic elements along (0.6, 0.8).
fn beam(elements: usize) -> BeamBody {
    let section = BeamSection { axial_stiffness: 2.0e6, shear_stiffness: 8.0e5, bending_stiffness: 100.0, mass_per_length: 2.0, rotary_inertia_per_length: 1.0e-4 };
    BeamBody::straight(Vec2::new(0.3, -0.2), Vec2::new(0.9, 0.6), section, BeamMesh { order: ElementOrder::Quadratic, elements }, 0.0).unwrap()
}

/// Uniform numbers in [-1, 1) from a xorshift generator (Marsaglia, "Xorshift RNGs", J. Stat. Softw. 8(14), 2003).
struct Uniform(u64);

impl Uniform {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// `M(q) = T(phi) Mbar(eta) T(phi)^T` from the body-frame mass.
fn inertial_mass(body: &ModalBody, q: &[f64]) -> DMatrix<f64> {
    let n = body.n_coordinates();
    let mut values = vec![0.0; n * n];
    body.body_frame_mass(&q[3..], &mut values);
    let (sin, cos) = q[2].sin_cos();
    let mut turn = DMatrix::identity(n, n);
    turn[(0, 0)] = cos;
    turn[(0, 1)] = -sin;
    turn[(1, 0)] = sin;
    turn[(1, 1)] = cos;
    &turn * DMatrix::from_row_slice(n, n, &values) * turn.transpose()
}

/// Condition number of a symmetric positive definite matrix in the 2-norm.
fn condition(a: &DMatrix<f64>) -> f64 {
    let eigenvalues = a.clone().symmetric_eigenvalues();
    eigenvalues.max() / eigenvalues.min()
}

/// The mode sets checked: (elements, interface nodes as fractions of the beam, frame, normal modes).
const MODE_SETS: [(usize, &[f64], FrameReference, usize); 7] = [
    (4, &[0.0, 1.0], FrameReference::Chord, 1),
    (8, &[0.0, 1.0], FrameReference::Clamped, 5),
    (8, &[0.0], FrameReference::Clamped, 8),
    (16, &[0.0, 0.5, 1.0], FrameReference::Chord, 10),
    (16, &[0.0, 1.0], FrameReference::Chord, 29),
    (32, &[0.0, 1.0], FrameReference::Clamped, 40),
    (32, &[0.0, 1.0], FrameReference::Chord, 61),
];

fn body(elements: usize, interface: &[f64], frame: FrameReference, normal: usize) -> ModalBody {
    let b = beam(elements);
    let nodes: Vec<usize> = interface.iter().map(|s| (s * (b.n_nodes() - 1) as f64).round() as usize).collect();
    ModalBody::from_beam(&b, &nodes, frame, normal, 0.0).unwrap().0
}

#[test]
fn the_body_frame_mass_is_the_mass_of_the_kinetic_energy() {
    // polarisation of T = u^T Mbar u / 2 at a deformed configuration, the frame at angle 0 (u = v)
    let body = body(8, &[0.0, 1.0], FrameReference::Chord, 4);
    let n = body.n_coordinates();
    let q: Vec<f64> = (0..n).map(|k| if k < 3 { 0.0 } else { 0.03 * (1.7 * k as f64).sin() }).collect();
    let kind = BodyKind::Modal(Box::new(body.clone()));
    let unit = |i: usize, j: usize| (0..n).map(|k| if k == i || k == j { 1.0 } else { 0.0 }).collect::<Vec<f64>>();
    let t = |v: &[f64]| kind.kinetic_energy(&q, v);
    let energy_mass = DMatrix::from_fn(n, n, |i, j| if i == j { 2.0 * t(&unit(i, i)) } else { t(&unit(i, j)) - t(&unit(i, i)) - t(&unit(j, j)) });
    let formed = inertial_mass(&body, &q);
    assert!((&formed - &energy_mass).amax() < 1e-13 * formed.amax(), "{:.2e}", (&formed - &energy_mass).amax());
}

#[test]
fn the_block_solve_is_the_dense_cholesky_of_the_whole_mass() {
    // over random angles, amplitudes up to 0.1 m or rad (a tenth of the link) and right-hand sides: the
    // difference to the dense solve is bounded by rounding of the one and the other, about
    // n eps cond(M) |x| (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., 2002, chapters 10 and
    // 7: the backward error of Cholesky and the perturbation bound); the residual of the block solve
    // is at rounding of |M| |x| whatever the conditioning
    let mut random = Uniform(0x9e37_79b9_7f4a_7c15);
    let mut worst = (0.0_f64, 0.0_f64);
    for &(elements, interface, frame, normal) in &MODE_SETS {
        let body = body(elements, interface, frame, normal);
        let (n, m) = (body.n_coordinates(), body.n_modes());
        let kind = BodyKind::Modal(Box::new(body.clone()));
        let mut scratch = vec![0.0; kind.mass_scratch_len()];
        for sample in 0..20 {
            let amplitude = if sample < 10 { 0.01 } else { 0.1 };
            let q: Vec<f64> = (0..n).map(|k| match k {
                0 | 1 => random.next(),
                2 => std::f64::consts::PI * random.next(),
                _ => amplitude * random.next(),
            }).collect();
            let f: Vec<f64> = (0..n).map(|_| random.next()).collect();
            let mass = inertial_mass(&body, &q);
            let reference = mass.clone().cholesky().expect("the mass is positive definite").solve(&DVector::from_column_slice(&f));
            let mut solved = vec![0.0; n];
            kind.solve_mass(&q, &f, &mut solved, &mut scratch);
            let solved = DVector::from_vec(solved);
            let error = (&solved - &reference).norm() / reference.norm();
            let bound = n as f64 * f64::EPSILON * condition(&mass);
            let residual = (&mass * &solved - DVector::from_column_slice(&f)).norm() / (mass.norm() * solved.norm());
            assert!(error < bound, "{m} modes, sample {sample}: error {error:.2e}, bound {bound:.2e}");
            assert!(residual < n as f64 * f64::EPSILON, "{m} modes, sample {sample}: residual {residual:.2e}");
            worst = (worst.0.max(error / bound), worst.1.max(residual / f64::EPSILON));
        }
    }
    // (seen: errors up to a fraction of the bound, residuals of a few eps)
    eprintln!("worst error / bound {:.2e}, worst residual / eps {:.2e}", worst.0, worst.1);
}

#[test]
fn the_modal_mass_of_craig_bampton_modes_couples_them() {
    // the fixed-interface normal modes are orthogonal in the mass among themselves, not to the
    // constraint modes: the modal block is not diagonal, so it is factored (once), not inverted entry by entry
    let body = body(16, &[0.0, 1.0], FrameReference::Chord, 6);
    let (m, mass) = (body.n_modes(), &body.invariants().modal_mass);
    let coupling = |i: usize, j: usize| mass[i * m + j].abs() / (mass[i * m + i] * mass[j * m + j]).sqrt();
    let constraint_normal = (0..3).flat_map(|i| (3..m).map(move |j| (i, j))).map(|(i, j)| coupling(i, j)).fold(0.0, f64::max);
    let normal_normal = (3..m).flat_map(|i| (3..i).map(move |j| (i, j))).map(|(i, j)| coupling(i, j)).fold(0.0, f64::max);
    assert!(constraint_normal > 0.1, "{constraint_normal:.2e}");
    assert!(normal_normal < 1e-10, "{normal_normal:.2e}");
}

#[test]
fn a_state_that_is_not_finite_solves_to_nan() {
    let body = body(4, &[0.0, 1.0], FrameReference::Chord, 2);
    let n = body.n_coordinates();
    let mut q = vec![0.0; n];
    q[4] = f64::NAN;
    let mut solved = vec![0.0; n];
    body.solve_mass(&q, &vec![1.0; n], &mut solved, &mut vec![0.0; body.mass_scratch_len()]);
    assert!(solved.iter().all(|x| x.is_nan()));
}

#[test]
fn modes_that_depend_on_each_other_or_carry_a_translation_are_refused() {
    let mesh = beam(2);
    let (mass, _) = mesh.dense_mass_and_stiffness(&mesh.reference_coordinates());
    let n = mass.nrows();
    let nodes: Vec<Vec2> = (0..n / 3).map(|a| Vec2::new(0.25 * a as f64, 0.0)).collect();
    let bending = DVector::from_fn(n, |i, _| if i % 3 == 1 { (i as f64 / n as f64).powi(2) } else { 0.0 });
    let solve = |shapes: DMatrix<f64>| BodyMassSolve::new(&InertiaInvariants::new(&mass, NodalCoordinates::TranslationsAndRotation, &nodes, &shapes).unwrap());
    // the same shape twice
    let twice = DMatrix::from_columns(&[bending.clone(), 2.0 * &bending]);
    assert!(solve(twice).unwrap_err().contains("mode 2 depends on the modes before it"), "twice");
    // a rigid translation across the body among the modes: the frame is left no mass in y
    let across = DVector::from_fn(n, |i, _| if i % 3 == 1 { 1.0 } else { 0.0 });
    assert!(solve(DMatrix::from_columns(&[bending, across])).unwrap_err().contains("carry a rigid translation"));
}
