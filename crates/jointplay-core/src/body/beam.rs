//! The geometrically exact planar beam as a body kind: a chain of elements
//! ([`crate::beam::BeamElement`]) sharing their end nodes, coordinates
//! `q = v = (x_0, y_0, theta_0, x_1, ...)` node after node along the beam
//! [m, m, rad], in the inertial frame.
//!
//! - **Mass:** the consistent mass is constant in these coordinates (the
//!   kinetic energy is quadratic in the nodal rates with constant
//!   coefficients), so there are no velocity-dependent inertial forces; it is
//!   factored once, `L D L^T` on its sparsity pattern.
//! - **Internal forces:** the elements' elastic forces with strain-rate
//!   (Kelvin-Voigt) damping of retardation time `tau`, subtracted from the
//!   generalised forces.
//! - **Markers:** a marker sits at a section, the frame whose origin, angle and
//!   rates are the shape-function interpolation of one element's nodes:
//!   `(x, y, theta)(xi) = sum_a N_a(xi) (x_a, y_a, theta_a)`. It moves like a
//!   rigid frame whose coordinates are linear in the nodes', so a marker's
//!   Jacobian is the rigid one spread over the nodes with the weights `N_a(xi)`,
//!   and so are the generalised forces of a point force and of a moment.
//!   The body's reference frame is its first node's.
//!
//! Theory: `docs/theory/beam.md`.

use std::borrow::Cow;
use std::ops::Range;

use nalgebra::DMatrix;

use super::planar_embedding::embedded_in_the_plane;
use super::planar_rigid::point_acceleration;
use super::{position_channels_of, velocity_channels_of, BodyModel, ChannelName, CoordinateChannels, MassBlock};
use crate::beam::{vibration_modes, BeamElement, BeamSection, BeamStrains, ElementOrder, MAX_ELEMENT_COORDINATES};
use crate::kinematics::marker::{Marker, MarkerFrames, SectionSite, Site, SpatialMarker};
use crate::kinematics::planar::{cross, perp, Frame, Vec2};
use crate::kinematics::spatial::{SpatialFrame, Vec3};
use crate::kinematics::wrench::Wrench;
use crate::linalg::PatternLdl;

/// How a beam is divided into elements of equal length.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BeamMesh {
    /// Interpolation order of every element.
    pub order: ElementOrder,
    /// Number of elements (at least one).
    pub elements: usize,
}

/// A beam: its elements, damping and factored mass.
#[derive(Clone, Debug, PartialEq)]
pub struct BeamBody {
    /// Elements from the first end; element `e` has the nodes `e (n - 1) .. e (n - 1) + n`
    /// (`n` nodes per element), and its unstressed reference configuration.
    pub elements: Vec<BeamElement>,
    /// Length of the unstressed beam [m].
    pub length: f64,
    /// Retardation time `tau` of the strain-rate damping [s] (0: undamped).
    pub damping_time: f64,
    /// Number of nodes.
    n_nodes: usize,
    /// Lower entries `(i, j, M_ij)`, `i >= j`, of the consistent mass [kg, kg m^2].
    mass_entries: Vec<(u32, u32, f64)>,
    /// The factorisation program of the mass's pattern.
    mass_program: PatternLdl,
    /// The mass's `L D L^T` factor.
    mass_factor: Vec<f64>,
    /// `integral rho A N_a dS` of every node: its share of the weight [kg].
    node_masses: Vec<f64>,
}

impl BeamBody {
    /// The site of the first node, the body's reference frame.
    pub const FIRST_NODE: SectionSite = SectionSite { element: 0, first: 0, nodes: 1, xi: -1.0, weights: [1.0, 0.0, 0.0] };

    /// A straight, unstressed beam from `start` to `end` [m] of section
    /// `section`, meshed by `mesh`, with strain-rate damping of retardation time `damping_time` [s].
    pub fn straight(start: Vec2, end: Vec2, section: BeamSection, mesh: BeamMesh, damping_time: f64) -> Result<Self, String> {
        let length = (end - start).norm();
        if !(length.is_finite() && length > 0.0) {
            return Err(format!("the beam's ends must be distinct finite points, got a length of {length} m"));
        }
        if mesh.elements == 0 {
            return Err("a beam needs at least one element".to_string());
        }
        if !(damping_time.is_finite() && damping_time >= 0.0) {
            return Err(format!("the damping time must be >= 0 s, got {damping_time}"));
        }
        let section = section.validated()?;
        let per_element = mesh.order.n_nodes() - 1;
        let n_nodes = mesh.elements * per_element + 1;
        let angle = (end.y - start.y).atan2(end.x - start.x);
        let node = |k: usize| {
            let p = start + (end - start) * (k as f64 / (n_nodes - 1) as f64);
            [p.x, p.y, angle]
        };
        let elements: Vec<BeamElement> = (0..mesh.elements)
            .map(|e| {
                let nodes: Vec<[f64; 3]> = (0..=per_element).map(|a| node(e * per_element + a)).collect();
                BeamElement::new(mesh.order, section, &nodes)
            })
            .collect();
        let mut body = Self {
            elements,
            length,
            damping_time,
            n_nodes,
            mass_entries: Vec::new(),
            mass_program: PatternLdl::analyse(0, &[]),
            mass_factor: Vec::new(),
            node_masses: vec![0.0; n_nodes],
        };
        body.assemble_mass()?;
        Ok(body)
    }

    /// Assembles the consistent mass and the nodes' weights, and factors the mass.
    fn assemble_mass(&mut self) -> Result<(), String> {
        let n = self.n_coordinates();
        let mut entries: std::collections::BTreeMap<(u32, u32), f64> = Default::default();
        for (e, element) in self.elements.iter().enumerate() {
            let nc = element.n_coordinates();
            let mut m = [0.0; MAX_ELEMENT_COORDINATES * MAX_ELEMENT_COORDINATES];
            element.add_mass_matrix(&mut m[..nc * nc]);
            let first = self.element_first(e);
            for i in 0..nc {
                for j in 0..=i {
                    if m[i * nc + j] != 0.0 {
                        *entries.entry(((first + i) as u32, (first + j) as u32)).or_default() += m[i * nc + j];
                    }
                }
                // (the x rows of the element mass: rho A integral N_a N_b, summed over b)
                if i % 3 == 0 {
                    self.node_masses[(first + i) / 3] += (0..nc).step_by(3).map(|j| m[i * nc + j]).sum::<f64>();
                }
            }
        }
        self.mass_entries = entries.into_iter().map(|((i, j), v)| (i, j, v)).collect();
        let lower: Vec<(usize, usize)> = self.mass_entries.iter().map(|&(i, j, _)| (i as usize, j as usize)).collect();
        self.mass_program = PatternLdl::analyse(n, &lower);
        self.mass_factor = vec![0.0; n * (n + 1)];
        for &(i, j, v) in &self.mass_entries {
            self.mass_factor[self.mass_program.storage_index(i as usize, j as usize)] = v;
        }
        self.mass_program.factor(&mut self.mass_factor).map_err(|d| format!("its mass matrix is not positive definite (row {})", d.row))
    }

    /// Number of coordinates (`3 x nodes`).
    pub fn n_coordinates(&self) -> usize {
        3 * self.n_nodes
    }

    /// Total mass `integral rho A dS` [kg].
    pub fn mass(&self) -> f64 {
        self.node_masses.iter().sum()
    }

    /// Number of nodes.
    pub fn n_nodes(&self) -> usize {
        self.n_nodes
    }

    /// First coordinate of element `e`.
    fn element_first(&self, e: usize) -> usize {
        3 * e * (self.elements[0].order.n_nodes() - 1)
    }

    /// The coordinates of element `e` within the body's.
    fn element_coordinates(&self, e: usize) -> Range<usize> {
        let first = self.element_first(e);
        first..first + self.elements[e].n_coordinates()
    }

    /// The nodal coordinates of the unstressed reference configuration [m, m, rad].
    pub fn reference_coordinates(&self) -> Vec<f64> {
        let mut q = vec![0.0; self.n_coordinates()];
        for (e, element) in self.elements.iter().enumerate() {
            let range = self.element_coordinates(e);
            q[range.clone()].copy_from_slice(&element.reference[..range.len()]);
        }
        q
    }

    /// Nodal velocities of a rigid motion of the reference configuration: the
    /// first node moving at `velocity` [m/s], the beam turning at `angular_velocity` [rad/s].
    pub fn rigid_velocities(&self, velocity: Vec2, angular_velocity: f64) -> Vec<f64> {
        let q = self.reference_coordinates();
        let mut v = vec![0.0; q.len()];
        self.rigid_motion_velocities(&q, velocity, angular_velocity, &mut v);
        v
    }

    /// The section at `arclength` [m] along the unstressed beam from its first end.
    pub fn site_at(&self, arclength: f64) -> Result<SectionSite, String> {
        // (a rounding margin at the ends)
        let margin = 1e-12 * self.length;
        if !(arclength.is_finite() && (-margin..=self.length + margin).contains(&arclength)) {
            return Err(format!("arclength must be within the beam's length [0, {}] m, got {arclength}", self.length));
        }
        let element_length = self.length / self.elements.len() as f64;
        let e = ((arclength / element_length).floor().max(0.0) as usize).min(self.elements.len() - 1);
        let xi = (2.0 * (arclength - e as f64 * element_length) / element_length - 1.0).clamp(-1.0, 1.0);
        let order = self.elements[e].order;
        Ok(SectionSite { element: e as u32, first: self.element_first(e) as u32, nodes: order.n_nodes() as u8, xi, weights: order.shape(xi).0 })
    }

    /// The section of a marker (its reference frame: the first node).
    #[inline]
    fn section(marker: &Marker) -> &SectionSite {
        match &marker.site {
            Site::Section(s) => s,
            Site::Reference | Site::ModalNode(_) => &Self::FIRST_NODE,
        }
    }

    /// Frame of a section from the body's coordinates `q` and rates `v`.
    #[inline]
    pub fn section_frame(site: &SectionSite, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        let first = site.first as usize;
        let (mut position, mut rates) = ([0.0; 3], [0.0; 3]);
        for (a, w) in site.weights[..site.nodes as usize].iter().enumerate() {
            for i in 0..3 {
                position[i] += w * q[first + 3 * a + i];
                rates[i] += w * v[first + 3 * a + i];
            }
        }
        Frame::from_coordinates_after(previous, &position, &rates)
    }

    /// Adds `weight_a g` to the three coordinates of every node `a` of the section, `out` starting at its first.
    #[inline]
    fn spread(site: &SectionSite, g: [f64; 3], out: &mut [f64]) {
        for (a, w) in site.weights[..site.nodes as usize].iter().enumerate() {
            for i in 0..3 {
                out[3 * a + i] += w * g[i];
            }
        }
    }

    /// Lower entries `(i, j, M_ij)`, `i >= j`, of the consistent mass [kg, kg m, kg m^2],
    /// in the body's velocity coordinates.
    pub fn mass_entries(&self) -> &[(u32, u32, f64)] {
        &self.mass_entries
    }

    /// The consistent mass and the tangent stiffness of the whole beam at `q`,
    /// dense (for natural modes and reductions, once before a run).
    pub fn dense_mass_and_stiffness(&self, q: &[f64]) -> (DMatrix<f64>, DMatrix<f64>) {
        let n = self.n_coordinates();
        let (mut mass, mut stiffness) = (DMatrix::zeros(n, n), DMatrix::zeros(n, n));
        for &(i, j, m) in &self.mass_entries {
            let (i, j) = (i as usize, j as usize);
            mass[(i, j)] = m;
            mass[(j, i)] = m;
        }
        for (e, element) in self.elements.iter().enumerate() {
            let range = self.element_coordinates(e);
            let nc = range.len();
            let mut k = [0.0; MAX_ELEMENT_COORDINATES * MAX_ELEMENT_COORDINATES];
            element.add_tangent_stiffness(&q[range.clone()], &mut k[..nc * nc]);
            for (a, i) in range.clone().enumerate() {
                for (b, j) in range.clone().enumerate() {
                    stiffness[(i, j)] += k[a * nc + b];
                }
            }
        }
        (mass, stiffness)
    }

    /// Natural frequencies [Hz] of the unstressed beam, lowest first, `count` of
    /// each: free-free (its three rigid modes left out) and clamped at its
    /// first end.
    pub fn natural_frequencies(&self, count: usize) -> Result<(Vec<f64>, Vec<f64>), String> {
        let (mass, stiffness) = self.dense_mass_and_stiffness(&self.reference_coordinates());
        let hertz = |w: &f64| w / (2.0 * std::f64::consts::PI);
        let free = vibration_modes(&mass, &stiffness, &[])?;
        let clamped = vibration_modes(&mass, &stiffness, &[0, 1, 2])?;
        Ok((
            free.angular_frequencies.iter().skip(3).take(count).map(hertz).collect(),
            clamped.angular_frequencies.iter().take(count).map(hertz).collect(),
        ))
    }

    /// Subtracts every element's internal forces, with strain-rate damping, from `out`.
    pub fn subtract_internal_forces(&self, q: &[f64], v: &[f64], out: &mut [f64]) {
        for (e, element) in self.elements.iter().enumerate() {
            let range = self.element_coordinates(e);
            let mut f = [0.0; MAX_ELEMENT_COORDINATES];
            let rate = (self.damping_time > 0.0).then(|| (&v[range.clone()], self.damping_time));
            element.add_viscoelastic_forces(&q[range.clone()], rate, &mut f);
            for (o, f) in out[range].iter_mut().zip(&f) {
                *o -= f;
            }
        }
    }

    /// `-integral g . r dm` [J].
    pub fn gravity_potential_energy(&self, g: Vec3, q: &[f64]) -> f64 {
        q.chunks_exact(3).zip(&self.node_masses).map(|(node, m)| -m * (g.x * node[0] + g.y * node[1])).sum()
    }

    /// The strain energy of every element [J].
    pub fn strain_energy(&self, q: &[f64]) -> f64 {
        self.elements.iter().enumerate().map(|(e, element)| element.strain_energy(&q[self.element_coordinates(e)])).sum()
    }

    /// Strains and stress resultants `(N [N], Q [N], M [N m])` at a section, with the
    /// viscous part of the damping (the section's true internal forces), recovered
    /// from the element's reduced-rule points (`BeamElement::recovered_strains`).
    pub fn section_state(&self, site: &SectionSite, q: &[f64], v: &[f64]) -> (BeamStrains, [f64; 3]) {
        let e = site.element as usize;
        let range = self.element_coordinates(e);
        let element = &self.elements[e];
        let damped = self.damping_time > 0.0;
        let (strains, rates) = element.recovered_strains(&q[range.clone()], damped.then(|| &v[range]), site.xi);
        let total = |value: f64, rate: f64| value + self.damping_time * rate;
        let s = &element.section;
        let resultants = [
            s.axial_stiffness * total(strains.axial, rates.axial),
            s.shear_stiffness * total(strains.shear, rates.shear),
            s.bending_stiffness * total(strains.curvature, rates.curvature),
        ];
        (strains, resultants)
    }

}

impl BeamBody {

    /// Channels of every node's coordinates: `node<k>_x`, `node<k>_y`, `node<k>_angle` and their rates.
    fn coordinate_channels(&self) -> Vec<CoordinateChannels> {
        let named = |k: usize, quantity: &str, unit: &'static str, what: &str| (Cow::Owned(format!("node{k}_{quantity}")), unit, Cow::Owned(format!("node {k} {what}")));
        (0..self.n_nodes)
            .flat_map(|k| {
                [
                    CoordinateChannels { position: named(k, "x", "m", "x"), velocity: named(k, "vx", "m/s", "velocity x"), acceleration: named(k, "ax", "m/s^2", "acceleration x") },
                    CoordinateChannels { position: named(k, "y", "m", "y"), velocity: named(k, "vy", "m/s", "velocity y"), acceleration: named(k, "ay", "m/s^2", "acceleration y") },
                    CoordinateChannels {
                        position: named(k, "angle", "rad", "section angle"),
                        velocity: named(k, "omega", "rad/s", "section angular velocity"),
                        acceleration: named(k, "alpha", "rad/s^2", "section angular acceleration"),
                    },
                ]
            })
            .collect()
    }


    /// The accelerations of a section's frame, interpolated from its nodes' in `a` [m/s^2, rad/s^2].
    #[inline]
    fn section_accelerations(site: &SectionSite, a: &[f64]) -> [f64; 3] {
        let first = site.first as usize;
        let mut section = [0.0; 3];
        for (k, w) in site.weights[..site.nodes as usize].iter().enumerate() {
            for i in 0..3 {
                section[i] += w * a[first + 3 * k + i];
            }
        }
        section
    }
}

impl BodyModel for BeamBody {
    fn nq(&self) -> usize {
        self.n_coordinates()
    }

    fn nv(&self) -> usize {
        self.n_coordinates()
    }

    /// The first node's frame.
    #[inline]
    fn frame(&self, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        Self::section_frame(&Self::FIRST_NODE, q, v, previous)
    }

    /// A section's frame, or the first node's.
    #[inline]
    fn site_frame(&self, site: &Site, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        match site {
            Site::Section(section) => Self::section_frame(section, q, v, previous),
            Site::Reference | Site::ModalNode(_) => self.frame(q, v, previous),
        }
    }

    /// The rigid frame's rows `scale [1, 0, -(A s)_y]`, `scale [0, 1, (A s)_x]` spread over the nodes.
    fn marker_jacobian(&self, _body: &Frame, frame: &Frame, marker: &Marker, scale: f64, jx: &mut [f64], jy: &mut [f64]) {
        let s = frame.rotate(marker.local) * scale;
        jx.fill(0.0);
        jy.fill(0.0);
        let site = Self::section(marker);
        Self::spread(site, [scale, 0.0, -s.y], jx);
        Self::spread(site, [0.0, scale, s.x], jy);
    }

    /// The element's nodes' coordinates: the marker's block.
    fn marker_coordinates(&self, marker: &Marker) -> Range<usize> {
        let s = Self::section(marker);
        s.first as usize..s.first as usize + 3 * s.nodes as usize
    }

    /// `along . [[1, 0, -(A s)_y], [0, 1, (A s)_x]]` spread over the nodes.
    fn add_marker_jacobian(&self, _body: &Frame, frame: &Frame, marker: &Marker, along: Vec2, out: &mut [f64]) {
        let s = frame.rotate(marker.local);
        Self::spread(Self::section(marker), [along.x, along.y, along.dot(&perp(s))], out);
    }

    /// `scale` on every node's angle, with its weight.
    fn add_marker_angle_jacobian(&self, marker: &Marker, scale: f64, out: &mut [f64]) {
        Self::spread(Self::section(marker), [0.0, 0.0, scale], out);
    }

    /// `-omega^2 A s` of the section's frame, whose coordinates are linear in the nodes' [m/s^2].
    fn marker_bias_acceleration(&self, _body: &Frame, frame: &Frame, marker: &Marker) -> Vec2 {
        point_acceleration(frame, &[0.0; 3], marker.local)
    }

    /// None: the section's angle is linear in the nodes'.
    #[inline]
    fn marker_bias_angular_acceleration(&self, _frame: &Frame, _marker: &Marker) -> f64 {
        0.0
    }

    /// The section's interpolated accelerations, then the rigid formula.
    fn marker_acceleration(&self, _body: &Frame, frame: &Frame, a: &[f64], marker: &Marker) -> Vec2 {
        point_acceleration(frame, &Self::section_accelerations(Self::section(marker), a), marker.local)
    }

    /// The section's interpolated angular acceleration [rad/s^2].
    fn marker_angular_acceleration(&self, _frame: &Frame, a: &[f64], marker: &Marker) -> f64 {
        Self::section_accelerations(Self::section(marker), a)[2]
    }

    /// Constant, factored.
    #[inline]
    fn mass_block(&self) -> MassBlock<'_> {
        MassBlock::ConstantFactored { program: &self.mass_program, factor: &self.mass_factor }
    }

    /// By the factor made at compile time.
    #[inline]
    fn solve_mass(&self, _q: &[f64], f: &[f64], out: &mut [f64], _scratch: &mut [f64]) {
        out.copy_from_slice(f);
        self.mass_program.solve(&self.mass_factor, out);
    }

    /// The internal forces.
    fn has_body_forces(&self) -> bool {
        true
    }

    /// Minus the internal forces (nodal coordinates in the inertial frame: M is constant, no inertial terms).
    fn add_body_forces(&self, q: &[f64], v: &[f64], out: &mut [f64]) {
        self.subtract_internal_forces(q, v, out);
    }

    /// Node `k`: `velocity + omega x (r_k - r_0)`, `omega`, the first node at
    /// `velocity` [m/s], every section turning at `angular_velocity` [rad/s].
    fn rigid_motion_velocities(&self, q: &[f64], velocity: Vec2, angular_velocity: f64, v: &mut [f64]) {
        let origin = Vec2::new(q[0], q[1]);
        for (node, rates) in q.chunks_exact(3).zip(v.chunks_exact_mut(3)) {
            let u = velocity + perp(Vec2::new(node[0], node[1]) - origin) * angular_velocity;
            rates.copy_from_slice(&[u.x, u.y, angular_velocity]);
        }
    }

    /// The nodes' centripetal accelerations `-omega^2 (r_k - r_0)` [m/s^2].
    fn rigid_motion_bias_accelerations(&self, q: &[f64], angular_velocity: f64, a: &mut [f64]) {
        a.fill(0.0);
        let (x0, y0) = (q[0], q[1]);
        for (node, out) in q.chunks_exact(3).zip(a.chunks_exact_mut(3)) {
            out[0] = -angular_velocity * angular_velocity * (node[0] - x0);
            out[1] = -angular_velocity * angular_velocity * (node[1] - y0);
        }
    }

    /// The force and its moment about the section's origin, spread over the nodes.
    fn add_point_force(&self, _body: &Frame, frame: &Frame, marker: &Marker, p: Vec2, f: Vec2, out: &mut [f64]) {
        let site = Self::section(marker);
        Self::spread(site, [f.x, f.y, cross(p - frame.position, f)], &mut out[site.first as usize..]);
    }

    /// The moment on the nodes' angles, spread with the weights.
    fn add_moment(&self, marker: &Marker, m: f64, out: &mut [f64]) {
        let site = Self::section(marker);
        Self::spread(site, [0.0, 0.0, m], &mut out[site.first as usize..]);
    }

    fn gravity_load_is_constant(&self) -> bool {
        true
    }

    /// The weight on the nodes' positions.
    fn add_gravity(&self, g: Vec3, _q: &[f64], out: &mut [f64]) {
        for (node, m) in out.chunks_exact_mut(3).zip(&self.node_masses) {
            node[0] += m * g.x;
            node[1] += m * g.y;
        }
    }

    /// Of gravity and the strain energy [J].
    fn potential_energy(&self, g: Vec3, q: &[f64]) -> f64 {
        self.gravity_potential_energy(g, q) + self.strain_energy(q)
    }

    /// `v^T M v / 2` [J].
    fn kinetic_energy(&self, _q: &[f64], v: &[f64]) -> f64 {
        self.mass_entries
            .iter()
            .map(|&(i, j, m)| {
                let (i, j) = (i as usize, j as usize);
                if i == j { 0.5 * m * v[i] * v[i] } else { m * v[i] * v[j] }
            })
            .sum()
    }

    fn position_channels(&self) -> Vec<ChannelName> {
        position_channels_of(self.coordinate_channels())
    }

    fn velocity_channels(&self) -> Vec<(ChannelName, ChannelName)> {
        velocity_channels_of(self.coordinate_channels())
    }

    embedded_in_the_plane!();
}
