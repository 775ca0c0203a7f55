//! Inertia invariants of a planar floating-frame body: the constant matrices
//! from which its mass matrix, for any modal amplitudes `eta`, is formed
//! without going back to the finite elements (Shabana, *Dynamics of
//! Multibody Systems*, the floating frame of reference formulation;
//! Schwertassek and Wallrapp, *Dynamik flexibler Mehrkörpersysteme*, 1999).
//!
//! A node `a` of the structure sits at `X_a + Phi_a eta` in the body frame
//! (reference position `X_a` [m], translation rows `Phi_a` of the modes), its
//! section at `Psi_a eta` (rotation row). With body-frame velocities
//! `u = (A^T R_dot, omega, eta_dot)` the nodal velocities in the body frame are
//! `w_dot = B(eta) u`, `B = [T, J (x_0 + Phi eta) + e_theta, Phi]` (`T`: unit
//! translations of every node, `J` turning every nodal translation by +90
//! degrees, `e_theta`: unit rotation of every section), and the kinetic energy
//! is `u^T Mbar(eta) u / 2`, `Mbar = B^T M_fe B`, `M_fe` the structure's mass:
//!
//! ```text
//! Mbar = [ M_tt           a_0 + A_1 eta                    S_t   ]
//!        [ .      I_0 + 2 I_1 . eta + eta^T I_2 eta    (h_0 + H_1^T eta)^T ]
//!        [ .              .                                 M_ee  ]
//! ```
//!
//! with `c_0 = J x_0 + e_theta`, `C_1 = J Phi` and `M_tt = T^T M T` [kg],
//! `a_0 = T^T M c_0` [kg m], `A_1 = T^T M C_1`, `S_t = T^T M Phi`,
//! `I_0 = c_0^T M c_0` [kg m^2], `I_1 = C_1^T M c_0`, `I_2 = C_1^T M C_1`,
//! `h_0 = Phi^T M c_0`, `H_1 = C_1^T M Phi`, `M_ee = Phi^T M Phi` (units per
//! unit of modal amplitude), and the first moment `s_0 = T^T M x_0` [kg m].

use nalgebra::{DMatrix, DVector};

use super::NodalCoordinates;
use crate::kinematics::planar::Vec2;

/// The invariants of one body, matrices row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct InertiaInvariants {
    /// Number of modes `m`.
    pub n_modes: usize,
    /// Total mass `m` (`M_tt = m I`) [kg].
    pub mass: f64,
    /// First moment of the reference configuration about the frame origin, `s_0` [kg m].
    pub first_moment: Vec2,
    /// `S_t` (2 x m): the first moment's change per modal amplitude [kg m / unit].
    pub first_moment_modes: Vec<f64>,
    /// `a_0` (2): translation-rotation coupling at `eta = 0` [kg m].
    pub rotation_coupling: Vec2,
    /// `A_1` (2 x m): its change per modal amplitude [kg m / unit].
    pub rotation_coupling_modes: Vec<f64>,
    /// `I_0`: moment of inertia of the reference configuration about the frame origin [kg m^2].
    pub inertia: f64,
    /// `I_1` (m) [kg m^2 / unit].
    pub inertia_linear: Vec<f64>,
    /// `I_2` (m x m) [kg m^2 / unit^2].
    pub inertia_quadratic: Vec<f64>,
    /// `h_0` (m): rotation-deformation coupling at `eta = 0` [kg m^2 / unit].
    pub modal_rotation: Vec<f64>,
    /// `H_1` (m x m): its change per modal amplitude [kg m^2 / unit^2].
    pub modal_rotation_linear: Vec<f64>,
    /// `M_ee` (m x m): the modal mass [kg m^2 / unit^2].
    pub modal_mass: Vec<f64>,
}

/// Row-major values of a matrix.
fn row_major(a: &DMatrix<f64>) -> Vec<f64> {
    a.transpose().iter().copied().collect()
}

impl InertiaInvariants {
    /// The invariants of the structure of mass `mass` (`d n_nodes` square, the
    /// nodal coordinates `coordinates`), nodes at `nodes` in the body frame [m], modes
    /// `shapes` (columns over the nodal coordinates). The translational mass must
    /// be isotropic (`T^T M T = m I`), as a consistent or lumped mass whose `x`
    /// and `y` share their interpolation is.
    pub fn new(mass: &DMatrix<f64>, coordinates: NodalCoordinates, nodes: &[Vec2], shapes: &DMatrix<f64>) -> Result<Self, String> {
        let n = mass.nrows();
        let d = coordinates.per_node();
        if nodes.len() * d != n || shapes.nrows() != n {
            return Err(format!("{} node positions and {} mode rows for a mass matrix of size {n}", nodes.len(), shapes.nrows()));
        }
        let (x0, theta, tx, ty) = reference_vectors(nodes, d);
        let c0: DVector<f64> = turn(&DMatrix::from_column_slice(n, 1, x0.as_slice()), d).column(0).into_owned() + &theta;
        let c1 = turn(shapes, d);
        let translations = DMatrix::from_columns(&[tx, ty]);
        let mt = translations.transpose() * mass;
        let m_tt = &mt * &translations;
        let total = m_tt[(0, 0)];
        let isotropic = (m_tt[(1, 1)] - total).abs() <= 1e-9 * total && m_tt[(0, 1)].abs() <= 1e-9 * total;
        if !(total > 0.0 && isotropic) {
            return Err(format!("the translational mass must be m I with m > 0, got [[{}, {}], [{}, {}]] kg", m_tt[(0, 0)], m_tt[(0, 1)], m_tt[(1, 0)], m_tt[(1, 1)]));
        }
        let s0 = &mt * &x0;
        let a0 = &mt * &c0;
        let mc1 = c1.transpose() * mass;
        let mphi = shapes.transpose() * mass;
        Ok(Self {
            n_modes: shapes.ncols(),
            mass: total,
            first_moment: Vec2::new(s0[0], s0[1]),
            first_moment_modes: row_major(&(&mt * shapes)),
            rotation_coupling: Vec2::new(a0[0], a0[1]),
            rotation_coupling_modes: row_major(&(&mt * &c1)),
            inertia: c0.dot(&(mass * &c0)),
            inertia_linear: (&mc1 * &c0).iter().copied().collect(),
            inertia_quadratic: row_major(&(&mc1 * &c1)),
            modal_rotation: (&mphi * &c0).iter().copied().collect(),
            modal_rotation_linear: row_major(&(&mc1 * shapes)),
            modal_mass: row_major(&(&mphi * shapes)),
        })
    }
}

/// `x_0` (the nodes' reference positions), `e_theta` (zero without section angles), and the
/// unit translations in x and y, for `d` coordinates per node.
fn reference_vectors(nodes: &[Vec2], d: usize) -> (DVector<f64>, DVector<f64>, DVector<f64>, DVector<f64>) {
    let n = d * nodes.len();
    let (mut x0, mut theta, mut tx, mut ty) = (DVector::zeros(n), DVector::zeros(n), DVector::zeros(n), DVector::zeros(n));
    for (a, p) in nodes.iter().enumerate() {
        x0[d * a] = p.x;
        x0[d * a + 1] = p.y;
        if d == 3 {
            theta[d * a + 2] = 1.0;
        }
        tx[d * a] = 1.0;
        ty[d * a + 1] = 1.0;
    }
    (x0, theta, tx, ty)
}

/// `J a`: every nodal translation of every column turned by +90 degrees, rotations zero (`d` coordinates per node).
fn turn(a: &DMatrix<f64>, d: usize) -> DMatrix<f64> {
    let mut out = DMatrix::zeros(a.nrows(), a.ncols());
    for c in 0..a.ncols() {
        for node in 0..a.nrows() / d {
            out[(d * node, c)] = -a[(d * node + 1, c)];
            out[(d * node + 1, c)] = a[(d * node, c)];
        }
    }
    out
}
