//! The geometrically exact planar beam element (Simo 1985; Simo and
//! Vu-Quoc 1986; Reissner 1972): nodal coordinates `(x, y, theta)` in the
//! inertial frame [m, m, rad], isoparametric with 2 or 3 nodes.
//!
//! At a point of the element, with `'` the derivative along the reference
//! arclength `S` and `Lambda(theta)` the rotation by `theta`:
//!
//! ```text
//! (Gamma_1, Gamma_2) = Lambda(theta)^T r' - Lambda(theta_0)^T r_0'   axial and shear strain [-]
//! kappa              = theta' - theta_0'                             curvature [1/m]
//! (N, Q, M)          = (EA Gamma_1, kGA Gamma_2, EI kappa)           stress resultants [N, N, N m]
//! ```
//!
//! (`_0`: the unstressed reference configuration). The virtual work of the
//! resultants gives the internal force of node `a` (shape function `N_a`):
//!
//! ```text
//! f_a = integral [ N_a' (N cos theta - Q sin theta),
//!                  N_a' (N sin theta + Q cos theta),
//!                  N_a (N m_2 - Q m_1) + N_a' M ] dS,      (m_1, m_2) = Lambda(theta)^T r'
//! ```
//!
//! (`m = (1 + Gamma_1, Gamma_2)` for a straight reference parametrised by arclength)
//!
//! integrated with one Gauss point (2 nodes) or two (3 nodes): uniform
//! reduced integration, which removes shear and membrane locking of these
//! elements (Simo and Vu-Quoc 1986, §4; Zienkiewicz and Taylor, *The Finite
//! Element Method for Solid and Structural Mechanics*, 6th ed., ch. 10).
//! The kinetic energy `1/2 integral (rhoA |r_dot|^2 + rhoI theta_dot^2) dS`
//! gives a constant consistent mass, integrated exactly (two and three
//! points). The tangent stiffness is the exact derivative of `f`.

use super::BeamSection;

/// Interpolation order of an element.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ElementOrder {
    /// Two nodes, linear interpolation.
    Linear,
    /// Three nodes (ends and middle, in order along the beam), quadratic interpolation.
    Quadratic,
}

impl ElementOrder {
    /// Number of nodes.
    pub const fn n_nodes(self) -> usize {
        match self {
            Self::Linear => 2,
            Self::Quadratic => 3,
        }
    }

    /// Shape functions and their derivatives by `xi` in [-1, 1] (unused entries zero).
    pub fn shape(self, xi: f64) -> ([f64; 3], [f64; 3]) {
        match self {
            Self::Linear => ([0.5 * (1.0 - xi), 0.5 * (1.0 + xi), 0.0], [-0.5, 0.5, 0.0]),
            Self::Quadratic => ([0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)], [xi - 0.5, -2.0 * xi, xi + 0.5]),
        }
    }

    /// Gauss points and weights of the reduced rule (stiffness).
    fn stiffness_rule(self) -> &'static [(f64, f64)] {
        const A: f64 = 0.577_350_269_189_625_8; // 1/sqrt(3)
        match self {
            Self::Linear => &[(0.0, 2.0)],
            Self::Quadratic => &[(-A, 1.0), (A, 1.0)],
        }
    }

    /// Gauss points and weights exact for the mass integrand.
    fn mass_rule(self) -> &'static [(f64, f64)] {
        const A: f64 = 0.577_350_269_189_625_8;
        const B: f64 = 0.774_596_669_241_483_4; // sqrt(3/5)
        match self {
            Self::Linear => &[(-A, 1.0), (A, 1.0)],
            Self::Quadratic => &[(-B, 5.0 / 9.0), (0.0, 8.0 / 9.0), (B, 5.0 / 9.0)],
        }
    }
}

/// Most coordinates of one element (3 nodes x 3).
pub const MAX_ELEMENT_COORDINATES: usize = 9;

/// Strains at a point of an element.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BeamStrains {
    /// Axial strain `Gamma_1` [-].
    pub axial: f64,
    /// Shear strain `Gamma_2` [-].
    pub shear: f64,
    /// Curvature `kappa` [1/m].
    pub curvature: f64,
}

/// Kinematics at one point of an element.
struct PointKinematics {
    /// Shape functions.
    n: [f64; 3],
    /// Their derivatives along the reference arclength [1/m].
    dn: [f64; 3],
    /// `theta` [rad].
    theta: f64,
    /// `Lambda(theta)^T r'` [-] (the strains plus the reference's).
    material: [f64; 2],
    /// Strains.
    strains: BeamStrains,
}

/// One element: its order, section and unstressed reference configuration.
#[derive(Clone, Debug, PartialEq)]
pub struct BeamElement {
    /// Interpolation order.
    pub order: ElementOrder,
    /// Section.
    pub section: BeamSection,
    /// Nodal coordinates `(x, y, theta)` of the unstressed configuration, node after
    /// node (unused entries zero) [m, m, rad].
    pub reference: [f64; MAX_ELEMENT_COORDINATES],
}

impl BeamElement {
    /// An element with nodal reference coordinates `reference` (as many as `order` has nodes).
    pub fn new(order: ElementOrder, section: BeamSection, reference: &[[f64; 3]]) -> Self {
        assert_eq!(reference.len(), order.n_nodes(), "an element of this order has {} nodes", order.n_nodes());
        let mut flat = [0.0; MAX_ELEMENT_COORDINATES];
        for (a, node) in reference.iter().enumerate() {
            flat[3 * a..3 * a + 3].copy_from_slice(node);
        }
        Self { order, section, reference: flat }
    }

    /// Number of coordinates `3 x nodes`.
    pub fn n_coordinates(&self) -> usize {
        3 * self.order.n_nodes()
    }

    /// `dS/dxi` at `xi` from the reference positions [m].
    fn jacobian(&self, dn_dxi: &[f64; 3]) -> f64 {
        let (mut dx, mut dy) = (0.0, 0.0);
        for a in 0..self.order.n_nodes() {
            dx += dn_dxi[a] * self.reference[3 * a];
            dy += dn_dxi[a] * self.reference[3 * a + 1];
        }
        (dx * dx + dy * dy).sqrt()
    }

    /// `Lambda(theta)^T r'` and `theta'` of nodal coordinates `q` at a point.
    fn deformation(&self, q: &[f64], n: &[f64; 3], dn: &[f64; 3]) -> (f64, [f64; 2], f64) {
        let (mut theta, mut dtheta, mut dr) = (0.0, 0.0, [0.0; 2]);
        for a in 0..self.order.n_nodes() {
            theta += n[a] * q[3 * a + 2];
            dtheta += dn[a] * q[3 * a + 2];
            dr[0] += dn[a] * q[3 * a];
            dr[1] += dn[a] * q[3 * a + 1];
        }
        let (s, c) = theta.sin_cos();
        (theta, [c * dr[0] + s * dr[1], -s * dr[0] + c * dr[1]], dtheta)
    }

    /// Kinematics of `q` at `xi`, with the point's `dS/dxi` [m].
    fn kinematics(&self, q: &[f64], xi: f64) -> (PointKinematics, f64) {
        let (n, dn_dxi) = self.order.shape(xi);
        let j = self.jacobian(&dn_dxi);
        let dn = dn_dxi.map(|d| d / j);
        let (_, material_reference, curvature_reference) = self.deformation(&self.reference, &n, &dn);
        let (theta, material, curvature) = self.deformation(q, &n, &dn);
        let strains = BeamStrains {
            axial: material[0] - material_reference[0],
            shear: material[1] - material_reference[1],
            curvature: curvature - curvature_reference,
        };
        (PointKinematics { n, dn, theta, material, strains }, j)
    }

    /// Strains at `xi` in [-1, 1] for nodal coordinates `q`.
    pub fn strains(&self, q: &[f64], xi: f64) -> BeamStrains {
        self.kinematics(q, xi).0.strains
    }

    /// Stress resultants `(N [N], Q [N], M [N m])` at `xi` for nodal coordinates `q`.
    pub fn stress_resultants(&self, q: &[f64], xi: f64) -> (f64, f64, f64) {
        self.resultants(&self.strains(q, xi))
    }

    /// Axial strain [-] of the fibre at distance `fibre` [m] from the axis along the
    /// section direction `t_2` (rotated by +90 degrees from the axis), at `xi`, from
    /// the recovered strains: `Gamma_1 - fibre kappa`.
    pub fn fibre_axial_strain(&self, q: &[f64], xi: f64, fibre: f64) -> f64 {
        let (strains, _) = self.recovered_strains(q, None, xi);
        strains.axial - fibre * strains.curvature
    }

    fn resultants(&self, s: &BeamStrains) -> (f64, f64, f64) {
        let section = &self.section;
        (section.axial_stiffness * s.axial, section.shear_stiffness * s.shear, section.bending_stiffness * s.curvature)
    }

    /// Adds the internal forces `f(q)` [N, N, N m] of the element (`M q_ddot + f = f_ext`) to `out`.
    pub fn add_internal_forces(&self, q: &[f64], out: &mut [f64]) {
        self.add_viscoelastic_forces(q, None, out);
    }

    /// Adds the internal forces with strain-rate (Kelvin-Voigt) damping to `out`:
    /// the resultants of the strains `e + tau e_dot` [N, N, N m], where `e_dot`
    /// is the strain rate of the nodal velocities `v` and `tau` the retardation
    /// time [s]; `None` for none. A rigid motion has no strain rate, so it is not damped.
    pub fn add_viscoelastic_forces(&self, q: &[f64], rate: Option<(&[f64], f64)>, out: &mut [f64]) {
        for &(xi, w) in self.order.stiffness_rule() {
            let (p, j) = self.kinematics(q, xi);
            let mut strains = p.strains;
            if let Some((v, tau)) = rate {
                let e_dot = self.strain_rates(&p, v);
                strains.axial += tau * e_dot.axial;
                strains.shear += tau * e_dot.shear;
                strains.curvature += tau * e_dot.curvature;
            }
            let (normal, shear, moment) = self.resultants(&strains);
            let (s, c) = p.theta.sin_cos();
            let (fx, fy) = (normal * c - shear * s, normal * s + shear * c);
            let spin = normal * p.material[1] - shear * p.material[0];
            for a in 0..self.order.n_nodes() {
                out[3 * a] += w * j * p.dn[a] * fx;
                out[3 * a + 1] += w * j * p.dn[a] * fy;
                out[3 * a + 2] += w * j * (p.n[a] * spin + p.dn[a] * moment);
            }
        }
    }

    /// Strain rates at a point for nodal velocities `v`: `B(q) v` [1/s, 1/s, 1/(m s)].
    fn strain_rates(&self, p: &PointKinematics, v: &[f64]) -> BeamStrains {
        let (s, c) = p.theta.sin_cos();
        let [m1, m2] = p.material;
        let mut rate = BeamStrains::default();
        for a in 0..self.order.n_nodes() {
            let (vx, vy, omega) = (v[3 * a], v[3 * a + 1], v[3 * a + 2]);
            rate.axial += p.dn[a] * (c * vx + s * vy) + p.n[a] * m2 * omega;
            rate.shear += p.dn[a] * (-s * vx + c * vy) - p.n[a] * m1 * omega;
            rate.curvature += p.dn[a] * omega;
        }
        rate
    }

    /// Strain rates `B(q) v` at `xi` for nodal coordinates `q` and velocities `v`.
    pub fn strain_rates_at(&self, q: &[f64], v: &[f64], xi: f64) -> BeamStrains {
        let (p, _) = self.kinematics(q, xi);
        self.strain_rates(&p, v)
    }

    /// Strains at `xi` recovered from the points of the reduced rule, and their
    /// rates for velocities `v` (zero without): the values at those points
    /// interpolated by the Lagrange polynomial through them (constant over a
    /// linear element, linear over a quadratic one). Those are the points where
    /// a reduced-integrated element's strains are accurate (Barlow, "Optimal
    /// stress locations in finite element models", IJNME 10 (1976) 243-251);
    /// between them the interpolated displacements carry parasitic shear and
    /// membrane strains, large in bending, that the reduced rule does not see.
    pub fn recovered_strains(&self, q: &[f64], v: Option<&[f64]>, xi: f64) -> (BeamStrains, BeamStrains) {
        let rule = self.order.stiffness_rule();
        let (mut strains, mut rates) = (BeamStrains::default(), BeamStrains::default());
        for (g, &(point, _)) in rule.iter().enumerate() {
            let weight: f64 = rule.iter().enumerate().filter(|&(h, _)| h != g).map(|(_, &(other, _))| (xi - other) / (point - other)).product();
            let (p, _) = self.kinematics(q, point);
            let rate = v.map(|v| self.strain_rates(&p, v)).unwrap_or_default();
            for (sum, value) in [(&mut strains, &p.strains), (&mut rates, &rate)] {
                sum.axial += weight * value.axial;
                sum.shear += weight * value.shear;
                sum.curvature += weight * value.curvature;
            }
        }
        (strains, rates)
    }

    /// Adds the tangent stiffness `df/dq` (row-major, `n_coordinates` square) to `out`.
    pub fn add_tangent_stiffness(&self, q: &[f64], out: &mut [f64]) {
        let nc = self.n_coordinates();
        let section = &self.section;
        let d = [section.axial_stiffness, section.shear_stiffness, section.bending_stiffness];
        for &(xi, w) in self.order.stiffness_rule() {
            let (p, j) = self.kinematics(q, xi);
            let (normal, shear, _) = self.resultants(&p.strains);
            let (s, c) = p.theta.sin_cos();
            let [m1, m2] = p.material;
            // B: rows (dGamma_1, dGamma_2, dkappa) by the coordinates of each node
            let b = |a: usize| [[p.dn[a] * c, p.dn[a] * s, p.n[a] * m2], [-p.dn[a] * s, p.dn[a] * c, -p.n[a] * m1], [0.0, 0.0, p.dn[a]]];
            // the derivative of (N cos - Q sin, N sin + Q cos) by theta at fixed resultants
            let (turn_x, turn_y) = (-normal * s - shear * c, normal * c - shear * s);
            for a in 0..self.order.n_nodes() {
                let ba = b(a);
                for bn in 0..self.order.n_nodes() {
                    let bb = b(bn);
                    for i in 0..3 {
                        for k in 0..3 {
                            let material: f64 = (0..3).map(|r| ba[r][i] * d[r] * bb[r][k]).sum();
                            out[(3 * a + i) * nc + 3 * bn + k] += w * j * material;
                        }
                    }
                    // geometric part: the B matrices' own dependence on theta and r'
                    let geometric = [
                        (0, 2, p.dn[a] * turn_x * p.n[bn]),
                        (1, 2, p.dn[a] * turn_y * p.n[bn]),
                        (2, 0, p.n[a] * turn_x * p.dn[bn]),
                        (2, 1, p.n[a] * turn_y * p.dn[bn]),
                        (2, 2, p.n[a] * (-normal * m1 - shear * m2) * p.n[bn]),
                    ];
                    for (i, k, value) in geometric {
                        out[(3 * a + i) * nc + 3 * bn + k] += w * j * value;
                    }
                }
            }
        }
    }

    /// Adds the consistent mass matrix (row-major, `n_coordinates` square) [kg, kg m^2] to `out`.
    pub fn add_mass_matrix(&self, out: &mut [f64]) {
        let nc = self.n_coordinates();
        let inertia = [self.section.mass_per_length, self.section.mass_per_length, self.section.rotary_inertia_per_length];
        for &(xi, w) in self.order.mass_rule() {
            let (n, dn_dxi) = self.order.shape(xi);
            let j = self.jacobian(&dn_dxi);
            for a in 0..self.order.n_nodes() {
                for b in 0..self.order.n_nodes() {
                    for (i, rho) in inertia.iter().enumerate() {
                        out[(3 * a + i) * nc + 3 * b + i] += w * j * rho * n[a] * n[b];
                    }
                }
            }
        }
    }

    /// Strain energy [J] of nodal coordinates `q` (same quadrature as the forces).
    pub fn strain_energy(&self, q: &[f64]) -> f64 {
        let section = &self.section;
        self.order
            .stiffness_rule()
            .iter()
            .map(|&(xi, w)| {
                let (p, j) = self.kinematics(q, xi);
                let s = p.strains;
                0.5 * w * j * (section.axial_stiffness * s.axial * s.axial + section.shear_stiffness * s.shear * s.shear + section.bending_stiffness * s.curvature * s.curvature)
            })
            .sum()
    }

    /// Position [m] and angle [rad] of the axis at `xi` for nodal coordinates `q`.
    pub fn axis_point(&self, q: &[f64], xi: f64) -> ([f64; 2], f64) {
        let (n, _) = self.order.shape(xi);
        let mut point = ([0.0; 2], 0.0);
        for a in 0..self.order.n_nodes() {
            point.0[0] += n[a] * q[3 * a];
            point.0[1] += n[a] * q[3 * a + 1];
            point.1 += n[a] * q[3 * a + 2];
        }
        point
    }
}
