//! The planar modal body (floating frame of reference): coordinates
//! `q = v = (x, y, phi, eta_1 .. eta_m)`, the frame's origin [m] and angle
//! [rad] in the inertial frame and the amplitudes of `m` modes [m or rad].
//!
//! A node `a` of the underlying structure is at `r_a = R + A(phi) (X_a + Phi_a eta)`,
//! its section at the angle `phi + Psi_a eta` (`Phi_a`, `Psi_a`: the
//! translation and rotation rows of the modes, `X_a` the reference position in
//! the body frame). The frame's origin is the first interface node; its axes
//! follow the chord to the second or the first node's section
//! ([`crate::modal::FrameReference`], [`crate::modal::craig_bampton_modes`]).
//!
//! - **Mass:** `M(q) = T(phi) Mbar(eta) T(phi)^T`, `T = diag(A, 1, I)`, with the
//!   body-frame mass `Mbar` given by the inertia invariants
//!   ([`crate::modal::InertiaInvariants`]); solved by its constant modal block,
//!   factored once, and the 3 x 3 Schur complement of the frame's coordinates
//!   ([`crate::modal::BodyMassSolve`]): quadratic in the modes per solve.
//! - **Body forces:** the quadratic velocity vector `dT/dq - M_dot q_dot`
//!   (centrifugal and Coriolis terms), minus the elastic force `K_ee eta` and
//!   modal damping `D eta_dot` (one damping ratio for every mode of the body
//!   held at its frame's reference conditions).
//! - **Markers** sit at nodes (interface nodes, for joints): frame, Jacobian over
//!   all `3 + m` coordinates, bias acceleration with the modal Coriolis terms.
//!
//! Linear modes, small elastic deformation, no geometric stiffening. Theory:
//! `docs/theory/modal-body.md`.

use std::borrow::Cow;
use std::ops::Range;

use nalgebra::DMatrix;

use super::planar_embedding::embedded_in_the_plane;
use super::{channel, position_channels_of, velocity_channels_of, BeamBody, BodyModel, ChannelName, CoordinateChannels, MassBlock};
use crate::beam::{vibration_modes, BeamStrains};
use crate::kinematics::marker::{Marker, MarkerFrames, SectionSite, Site, SpatialMarker};
use crate::kinematics::planar::{cross, perp, Frame, Vec2};
use crate::kinematics::spatial::{SpatialFrame, Vec3};
use crate::kinematics::wrench::Wrench;
use crate::modal::{check_free_structure, craig_bampton_modes, dot, BodyMassSolve, FrameReference, InertiaInvariants, NodalCoordinates};

/// Most modes of one body: the hot loop keeps its vectors on the stack (an
/// evaluation costs about `5 m^2` multiply-adds of the body's own terms and
/// `2.5 m^2` per mass solve).
pub const MAX_MODES: usize = 64;

/// Most nodes of a structure given by matrices: its reduction is dense
/// (factorisations and a symmetric eigenproblem of the interior, cubic in the
/// size), 2.5 s at 400 nodes on one core of the development machine, 90 s at 1000.
pub const MAX_STRUCTURE_NODES: usize = 400;

/// Most coordinates of one body.
const MAX_COORDINATES: usize = 3 + MAX_MODES;

/// A free planar finite-element structure in its own axes: mass and
/// stiffness (dense, symmetric, over the nodal `(u_x, u_y, theta)` node after
/// node), node positions [m] and section angles [rad] (zero for a structure
/// whose rotations are counted from its rest state).
#[derive(Clone, Copy, Debug)]
pub struct Structure<'a> {
    /// Mass matrix [kg, kg m, kg m^2], three coordinates `(u_x, u_y, theta)` per
    /// node (frame elements) or two `(u_x, u_y)` (plane solid elements).
    pub mass: &'a DMatrix<f64>,
    /// Stiffness matrix [N/m, N/rad, N m/rad], the coordinates of `mass`.
    pub stiffness: &'a DMatrix<f64>,
    /// Node positions [m].
    pub positions: &'a [[f64; 2]],
    /// Section angles of the nodes [rad] (ignored with two coordinates per node).
    pub angles: &'a [f64],
}

/// The beam a modal body was reduced from, with its frame's pose then
/// `(x, y, phi)` [m, m, rad]: strains are recovered on its elements.
#[derive(Clone, Debug, PartialEq)]
struct SourceBeam {
    beam: BeamBody,
    pose: [f64; 3],
}

/// A modal body: its invariants, modal stiffness and damping, and the nodes' mode rows.
#[derive(Clone, Debug, PartialEq)]
pub struct ModalBody {
    /// The inertia invariants.
    invariants: InertiaInvariants,
    /// The solve with the body-frame mass, its constant parts formed from the invariants.
    mass_solve: BodyMassSolve,
    /// Modal stiffness `K_ee = Phi^T K Phi` (m x m, row-major) [N/m per unit^2].
    stiffness: Vec<f64>,
    /// Modal damping `D` (m x m, row-major) [N s/m per unit^2].
    damping: Vec<f64>,
    /// Retardation time of the stiffness-proportional part of `D` [s].
    retardation_time: f64,
    /// Damping ratio of every mode of the body held at its frame's reference conditions [-].
    damping_ratio: f64,
    /// The frame's reference conditions.
    reference: FrameReference,
    /// Reference position of every node in the body frame [m].
    nodes: Vec<Vec2>,
    /// Mode rows of every node: `3 m` values, `Phi_a` x row, y row, then `Psi_a`.
    node_rows: Vec<f64>,
    /// Lines of the mesh between nodes, for drawing: node pairs the stiffness
    /// couples (a structure given by matrices) or neighbours along a beam.
    edges: Vec<[usize; 2]>,
    /// Interface nodes; the first carries the frame.
    interface: Vec<usize>,
    /// Number of constraint modes (the first modes).
    n_constraint: usize,
    /// Whether each mode's amplitude is a rotation (a constraint mode of a section angle).
    rotational: Vec<bool>,
    /// Angular frequencies of the fixed-interface normal modes [rad/s].
    fixed_interface_frequencies: Vec<f64>,
    /// Angular frequencies of the reduced body held at its frame's reference conditions [rad/s].
    held_frequencies: Vec<f64>,
    /// The beam reduced, when the body is one (not a structure given by matrices).
    source: Option<Box<SourceBeam>>,
}

impl ModalBody {
    /// The body of a structure of mass `mass` and stiffness `stiffness` (dense,
    /// symmetric, `d n_nodes` square, the nodal coordinates `coordinates` in the body
    /// frame's directions), nodes at `nodes` [m] (the frame's origin is moved to the
    /// first interface node; with a chord frame the second must lie on its x
    /// axis), Craig-Bampton modes for the interface nodes `interface` and the
    /// reference conditions `reference` with `n_normal` fixed-interface modes,
    /// and the damping ratio `damping_ratio` [-] of every mode.
    #[allow(clippy::too_many_arguments)]
    pub fn from_finite_elements(mass: &DMatrix<f64>, stiffness: &DMatrix<f64>, coordinates: NodalCoordinates, nodes: &[Vec2], interface: &[usize], reference: FrameReference, n_normal: usize, damping_ratio: f64) -> Result<Self, String> {
        if !(damping_ratio.is_finite() && damping_ratio >= 0.0) {
            return Err(format!("the damping ratio must be >= 0, got {damping_ratio}"));
        }
        let d = coordinates.per_node();
        let modes = craig_bampton_modes(mass, stiffness, coordinates, interface, reference, n_normal)?;
        let shapes = &modes.shapes;
        let m = shapes.ncols();
        if m > MAX_MODES {
            return Err(format!("a modal body has at most {MAX_MODES} modes, got {m}"));
        }
        if nodes.len() * d != mass.nrows() || nodes.iter().any(|p| !(p.x.is_finite() && p.y.is_finite())) {
            return Err(format!("give one finite position per node: {} positions for {} nodes", nodes.len(), mass.nrows() / d));
        }
        let origin = nodes[interface[0]];
        let nodes: Vec<Vec2> = nodes.iter().map(|p| p - origin).collect();
        if reference == FrameReference::Chord {
            let chord = nodes[interface[1]];
            if chord.y.abs() > 1e-9 * chord.norm() {
                return Err(format!("with a chord frame the second interface node must lie on the frame's x axis; it is at ({}, {}) m from the first", chord.x, chord.y));
            }
        }
        let invariants = InertiaInvariants::new(mass, coordinates, &nodes, shapes)?;
        let mass_solve = BodyMassSolve::new(&invariants)?;
        let modal_stiffness = shapes.transpose() * stiffness * shapes;
        let modal_mass = DMatrix::from_row_slice(m, m, &invariants.modal_mass);
        let (held_frequencies, damping) = held_modes(&modal_mass, &modal_stiffness, damping_ratio)?;
        // (three rows per node, x, y and the section's angle; a node without an angle turns with the frame: zeros)
        let mut node_rows = Vec::with_capacity(3 * m * nodes.len());
        for a in 0..nodes.len() {
            for i in 0..3 {
                if i < d {
                    node_rows.extend(shapes.row(d * a + i).iter());
                } else {
                    node_rows.extend(std::iter::repeat_n(0.0, m));
                }
            }
        }
        let rotational = (0..m).map(|j| j < modes.n_constraint && coordinates.is_rotation(modes.boundary[j])).collect();
        Ok(Self {
            invariants,
            mass_solve,
            stiffness: modal_stiffness.transpose().iter().copied().collect(),
            damping: damping.transpose().iter().copied().collect(),
            damping_ratio,
            retardation_time: 0.0,
            reference,
            nodes,
            node_rows,
            edges: coupled_nodes(stiffness, d),
            interface: interface.to_vec(),
            n_constraint: modes.n_constraint,
            rotational,
            fixed_interface_frequencies: modes.fixed_interface_frequencies,
            held_frequencies,
            source: None,
        })
    }

    /// The modal body of `beam` in its unstressed reference configuration (its
    /// consistent mass and linear stiffness there), with the interface nodes
    /// `interface` (node indices along the beam), the frame's reference
    /// conditions `frame`, `n_normal` fixed-interface modes and the damping
    /// ratio `damping_ratio`; also the frame's initial pose `(x, y, phi)` [m, m,
    /// rad]: the first interface node's position, the angle of the chord or of its section.
    pub fn from_beam(beam: &BeamBody, interface: &[usize], frame: FrameReference, n_normal: usize, damping_ratio: f64) -> Result<(Self, [f64; 3]), String> {
        let reference = beam.reference_coordinates();
        let positions: Vec<[f64; 2]> = reference.chunks_exact(3).map(|p| [p[0], p[1]]).collect();
        let angles: Vec<f64> = reference.chunks_exact(3).map(|p| p[2]).collect();
        let (mass, stiffness) = beam.dense_mass_and_stiffness(&reference);
        let structure = Structure { mass: &mass, stiffness: &stiffness, positions: &positions, angles: &angles };
        let (mut body, pose) = Self::from_structure(&structure, interface, frame, n_normal, damping_ratio)?;
        body.source = Some(Box::new(SourceBeam { beam: beam.clone(), pose }));
        body.edges = (1..body.nodes.len()).map(|a| [a - 1, a]).collect();
        Ok((body, pose))
    }

    /// The modal body of a free structure `structure` with the interface nodes
    /// `interface`, the frame's reference conditions `frame`, `n_normal`
    /// fixed-interface modes and the damping ratio `damping_ratio`; also the
    /// frame's pose `(x, y, phi)` [m, m, rad] in the structure's axes.
    pub fn from_structure(structure: &Structure, interface: &[usize], frame: FrameReference, n_normal: usize, damping_ratio: f64) -> Result<(Self, [f64; 3]), String> {
        let Structure { mass, stiffness, positions, angles } = *structure;
        let coordinates = NodalCoordinates::of_size(mass.nrows(), positions.len()).filter(|_| positions.len() == angles.len())
            .ok_or_else(|| format!("{} node positions and {} section angles for matrices of size {} (3 or 2 coordinates per node)", positions.len(), angles.len(), mass.nrows()))?;
        let d = coordinates.per_node();
        if let Some(&node) = interface.iter().find(|&&node| node >= positions.len()) {
            return Err(format!("interface node {node} is not a node of the structure (it has {} nodes, from 0)", positions.len()));
        }
        check_free_structure(stiffness, positions, coordinates)?;
        let first = *interface.first().ok_or("a modal body needs at least one interface node (the first carries its frame)")?;
        let pose = [positions[first][0], positions[first][1], frame.frame_angle(interface, positions, angles, coordinates)?];
        // (the structure expressed in the frame: every node's translations turned by -phi)
        let (sin, cos) = pose[2].sin_cos();
        let n = mass.nrows();
        let rotation = DMatrix::from_fn(n, n, |i, j| match (i / d == j / d, i % d, j % d) {
            (true, 0, 0) | (true, 1, 1) => cos,
            (true, 0, 1) => -sin,
            (true, 1, 0) => sin,
            (true, 2, 2) => 1.0,
            _ => 0.0,
        });
        let local = |a: &DMatrix<f64>| rotation.transpose() * a * &rotation;
        let nodes: Vec<Vec2> = positions.iter().map(|p| Vec2::new(cos * (p[0] - pose[0]) + sin * (p[1] - pose[1]), -sin * (p[0] - pose[0]) + cos * (p[1] - pose[1]))).collect();
        let body = Self::from_finite_elements(&local(mass), &local(stiffness), coordinates, &nodes, interface, frame, n_normal, damping_ratio)?;
        Ok((body, pose))
    }

    /// Number of modes `m`.
    pub fn n_modes(&self) -> usize {
        self.invariants.n_modes
    }

    /// Number of coordinates `3 + m`.
    pub fn n_coordinates(&self) -> usize {
        3 + self.n_modes()
    }

    /// Number of nodes of the structure.
    pub fn n_nodes(&self) -> usize {
        self.nodes.len()
    }

    /// Total mass [kg].
    pub fn mass(&self) -> f64 {
        self.invariants.mass
    }

    /// The inertia invariants.
    pub fn invariants(&self) -> &InertiaInvariants {
        &self.invariants
    }

    /// Damping ratio of every mode of the body held at its frame's reference conditions [-].
    pub fn damping_ratio(&self) -> f64 {
        self.damping_ratio
    }

    /// Adds stiffness-proportional damping `D += tau K_ee` with the retardation
    /// time `tau` [s]: the linear form of a beam's strain-rate (Kelvin-Voigt)
    /// damping of the same `tau`, so each mode gets the ratio `tau w / 2`.
    pub fn add_stiffness_proportional_damping(&mut self, tau: f64) -> Result<(), String> {
        if !(tau.is_finite() && tau >= 0.0) {
            return Err(format!("the retardation time must be >= 0, got {tau}"));
        }
        self.retardation_time += tau;
        for (d, k) in self.damping.iter_mut().zip(&self.stiffness) {
            *d += tau * k;
        }
        Ok(())
    }

    /// Retardation time of the stiffness-proportional damping [s].
    pub fn retardation_time(&self) -> f64 {
        self.retardation_time
    }

    /// The frame's reference conditions.
    pub fn frame_reference(&self) -> FrameReference {
        self.reference
    }

    /// The interface nodes (the first carries the frame).
    pub fn interface(&self) -> &[usize] {
        &self.interface
    }

    /// Angular frequencies of the fixed-interface normal modes kept [rad/s].
    pub fn fixed_interface_frequencies(&self) -> &[f64] {
        &self.fixed_interface_frequencies
    }

    /// Angular frequencies of the reduced body held at its frame's reference
    /// conditions (clamped at the first interface node, or simply supported
    /// at the first two), lowest first [rad/s].
    pub fn held_frequencies(&self) -> &[f64] {
        &self.held_frequencies
    }

    /// The modal stiffness `K_ee` (m x m, row-major) [N/m per unit^2].
    pub fn modal_stiffness(&self) -> &[f64] {
        &self.stiffness
    }

    /// Reference position of node `a` in the body frame [m].
    pub fn node_position(&self, a: usize) -> Vec2 {
        self.nodes[a]
    }

    /// Translation of node `a` per unit amplitude of each mode, in the body
    /// frame: `(Phi_a x row, Phi_a y row)`, `m` values each [m per unit].
    pub fn node_mode_translations(&self, a: usize) -> (&[f64], &[f64]) {
        let m = self.n_modes();
        let rows = &self.node_rows[3 * m * a..3 * m * (a + 1)];
        (&rows[..m], &rows[m..2 * m])
    }

    /// The mesh's lines, as pairs of node indices (for drawing the body).
    pub fn edges(&self) -> &[[usize; 2]] {
        &self.edges
    }

    /// The lowest bending frequency [Hz] of the body held at its frame's
    /// reference conditions: spun faster than this about its frame's origin, a
    /// linear modal body (no geometric stiffening) diverges.
    pub fn first_bending_frequency(&self) -> Option<f64> {
        self.held_frequencies.first().map(|w| w / (2.0 * std::f64::consts::PI))
    }

    /// Free-free natural frequencies [Hz] of the reduced body at rest (its three rigid modes left out).
    pub fn free_frequencies(&self) -> Result<Vec<f64>, String> {
        let n = self.n_coordinates();
        let mut mass = vec![0.0; n * n];
        self.body_frame_mass(&vec![0.0; self.n_modes()], &mut mass);
        let mass = DMatrix::from_row_slice(n, n, &mass);
        let mut stiffness = DMatrix::zeros(n, n);
        let m = self.n_modes();
        stiffness.view_mut((3, 3), (m, m)).copy_from(&DMatrix::from_row_slice(m, m, &self.stiffness));
        let modes = vibration_modes(&mass, &stiffness, &[])?;
        Ok(modes.angular_frequencies.iter().skip(3).map(|w| w / (2.0 * std::f64::consts::PI)).collect())
    }

    /// The section of the reduced beam at node `a`, for strain recovery; `None`
    /// for a body given by matrices (no elements to recover strains on).
    pub fn node_section(&self, a: usize) -> Option<SectionSite> {
        let beam = &self.source.as_ref()?.beam;
        beam.site_at(beam.length * a as f64 / (beam.n_nodes() - 1) as f64).ok()
    }

    /// The strains' rows over the modes at `site`: axial [-], shear [-] and
    /// curvature [1/m] per unit of each amplitude, `3 x m` row-major. They are
    /// the reduced beam's linear strain-displacement relation at its unstressed
    /// state (central differences of its element's strain recovery from the
    /// reduced-rule points) times the element's mode rows: linear, as the
    /// modes are. `None` for a body given by matrices (no elements).
    pub fn strain_modes(&self, site: &SectionSite) -> Option<Vec<f64>> {
        let source = self.source.as_ref()?;
        let element = &source.beam.elements[site.element as usize];
        let n = 3 * site.nodes as usize;
        let m = self.n_modes();
        let (sin, cos) = source.pose[2].sin_cos();
        let length_step = 1e-6 * source.beam.length / source.beam.elements.len() as f64;
        let mut rows = vec![0.0; 3 * m];
        for c in 0..n {
            let step = if c % 3 == 2 { 1e-6 } else { length_step };
            let strains_at = |offset: f64| {
                let mut q = [0.0; 9];
                q[..n].copy_from_slice(&element.reference[..n]);
                q[c] += offset;
                let (s, _) = element.recovered_strains(&q[..n], None, site.xi);
                [s.axial, s.shear, s.curvature]
            };
            let (plus, minus) = (strains_at(step), strains_at(-step));
            // the element's coordinate c (inertial directions) per unit of each mode
            let (rx, ry, rt) = self.rows(site.first as usize / 3 + c / 3);
            for j in 0..m {
                let per_mode = match c % 3 {
                    0 => cos * rx[j] - sin * ry[j],
                    1 => sin * rx[j] + cos * ry[j],
                    _ => rt[j],
                };
                for k in 0..3 {
                    rows[k * m + j] += (plus[k] - minus[k]) / (2.0 * step) * per_mode;
                }
            }
        }
        Some(rows)
    }

    /// Strains and elastic stress resultants `(N, Q, M)` [N, N, N m] at `site`
    /// from its `strain_modes` ([`Self::strain_modes`]) and the amplitudes in
    /// `q`. Modal damping is not a section stress and is left out. `None` for a
    /// body given by matrices.
    pub fn section_state(&self, site: &SectionSite, strain_modes: &[f64], q: &[f64]) -> Option<(BeamStrains, [f64; 3])> {
        let section = &self.source.as_ref()?.beam.elements[site.element as usize].section;
        let (m, eta) = (self.n_modes(), &q[3..]);
        let strains = BeamStrains { axial: dot(&strain_modes[..m], eta), shear: dot(&strain_modes[m..2 * m], eta), curvature: dot(&strain_modes[2 * m..], eta) };
        Some((strains, [section.axial_stiffness * strains.axial, section.shear_stiffness * strains.shear, section.bending_stiffness * strains.curvature]))
    }

    /// The interface node of a marker (its reference site: the frame's node).
    #[inline]
    fn node(&self, marker: &Marker) -> usize {
        match marker.site {
            Site::ModalNode(site) => site.node as usize,
            _ => self.interface[0],
        }
    }

    /// The x row, y row and rotation row of node `a`'s modes.
    #[inline]
    fn rows(&self, a: usize) -> (&[f64], &[f64], &[f64]) {
        let m = self.n_modes();
        let rows = &self.node_rows[3 * m * a..3 * m * (a + 1)];
        (&rows[..m], &rows[m..2 * m], &rows[2 * m..])
    }

    /// Frame of node `a`: position `R + A (X_a + Phi_a eta)`, angle `phi + Psi_a eta` and their rates.
    pub fn node_frame(&self, a: usize, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        let body = Frame::from_coordinates(q, v);
        let (rx, ry, rt) = self.rows(a);
        let (eta, rates) = (&q[3..], &v[3..]);
        let local = self.nodes[a] + Vec2::new(dot(rx, eta), dot(ry, eta));
        let local_rate = Vec2::new(dot(rx, rates), dot(ry, rates));
        let offset = body.rotate(local);
        let position = body.position + offset;
        let velocity = body.velocity + perp(offset) * body.angular_velocity + body.rotate(local_rate);
        let angle = q[2] + dot(rt, eta);
        Frame::from_coordinates_after(previous, &[position.x, position.y, angle], &[velocity.x, velocity.y, v[2] + dot(rt, rates)])
    }

    /// Column `3 + i` of a marker point's Jacobian: `A Phi_a,i + perp(s) Psi_a,i` (`s` the point from the node) [m/unit].
    #[inline]
    fn modal_column(body: &Frame, rows: (&[f64], &[f64], &[f64]), s: Vec2, i: usize) -> Vec2 {
        body.rotate(Vec2::new(rows.0[i], rows.1[i])) + perp(s) * rows.2[i]
    }

    /// `Mbar(eta)`, row-major `(3 + m)^2`, into `out`.
    pub fn body_frame_mass(&self, eta: &[f64], out: &mut [f64]) {
        let (inv, m) = (&self.invariants, self.n_modes());
        let n = 3 + m;
        let out = &mut out[..n * n];
        out.fill(0.0);
        let b = self.rotation_coupling(eta);
        let mut h = [0.0; MAX_MODES];
        self.modal_rotations(eta, &mut h[..m]);
        out[0] = inv.mass;
        out[n + 1] = inv.mass;
        out[2] = b.x;
        out[n + 2] = b.y;
        out[2 * n + 2] = self.rotational_inertia(eta);
        for j in 0..m {
            let (sx, sy, h) = (inv.first_moment_modes[j], inv.first_moment_modes[m + j], h[j]);
            out[3 + j] = sx;
            out[n + 3 + j] = sy;
            out[2 * n + 3 + j] = h;
            for i in 0..m {
                out[(3 + i) * n + 3 + j] = inv.modal_mass[i * m + j];
            }
        }
        for i in 0..n {
            for j in 0..i {
                out[i * n + j] = out[j * n + i];
            }
        }
    }

    /// `a_0 + A_1 eta` [kg m].
    #[inline]
    fn rotation_coupling(&self, eta: &[f64]) -> Vec2 {
        let (inv, m) = (&self.invariants, self.n_modes());
        inv.rotation_coupling + Vec2::new(dot(&inv.rotation_coupling_modes[..m], eta), dot(&inv.rotation_coupling_modes[m..], eta))
    }

    /// `I_0 + 2 I_1 . eta + eta^T I_2 eta` [kg m^2].
    #[inline]
    fn rotational_inertia(&self, eta: &[f64]) -> f64 {
        let (inv, m) = (&self.invariants, self.n_modes());
        let quadratic: f64 = (0..m).map(|i| eta[i] * dot(&inv.inertia_quadratic[i * m..(i + 1) * m], eta)).sum();
        inv.inertia + 2.0 * dot(&inv.inertia_linear, eta) + quadratic
    }

    /// `p = Mbar(eta) u` over the `3 + m` body-frame velocities `u`.
    fn times_body_mass(&self, eta: &[f64], u: &[f64], p: &mut [f64]) {
        let (inv, m) = (&self.invariants, self.n_modes());
        let (b, omega, rates) = (self.rotation_coupling(eta), u[2], &u[3..]);
        let st = &inv.first_moment_modes;
        let mut h = [0.0; MAX_MODES];
        self.modal_rotations(eta, &mut h[..m]);
        p[0] = inv.mass * u[0] + b.x * omega + dot(&st[..m], rates);
        p[1] = inv.mass * u[1] + b.y * omega + dot(&st[m..], rates);
        p[2] = b.x * u[0] + b.y * u[1] + self.rotational_inertia(eta) * omega + dot(&h[..m], rates);
        for i in 0..m {
            p[3 + i] = st[i] * u[0] + st[m + i] * u[1] + h[i] * omega + dot(&inv.modal_mass[i * m..(i + 1) * m], rates);
        }
    }

    /// `h_0 + H_1^T eta` into `out` (m) [kg m^2 / unit], by rows of `H_1`.
    fn modal_rotations(&self, eta: &[f64], out: &mut [f64]) {
        let (inv, m) = (&self.invariants, self.n_modes());
        out.copy_from_slice(&inv.modal_rotation);
        for (k, e) in eta.iter().enumerate() {
            for (o, h) in out.iter_mut().zip(&inv.modal_rotation_linear[k * m..(k + 1) * m]) {
                *o += h * e;
            }
        }
    }

    /// The body-frame velocities `u = (A^T R_dot, omega, eta_dot)` from `v`.
    #[inline]
    fn body_velocities(q: &[f64], v: &[f64], u: &mut [f64]) {
        let (sin, cos) = q[2].sin_cos();
        u[..v.len()].copy_from_slice(v);
        u[0] = cos * v[0] + sin * v[1];
        u[1] = -sin * v[0] + cos * v[1];
    }

    /// `dT/dq - M_dot q_dot` in body-frame components (`u` the body-frame
    /// velocities): centrifugal, Coriolis and gyroscopic terms [N, N m, N per unit].
    /// Three passes over `m x m` invariants: `H_1` (times the rates, and its
    /// transpose times them) and `I_2` (times `eta`).
    fn quadratic_velocity_vector(&self, eta: &[f64], u: &[f64], out: &mut [f64]) {
        let (inv, m, n) = (&self.invariants, self.n_modes(), self.n_coordinates());
        let (omega, rates) = (u[2], &u[3..n]);
        let st = &inv.first_moment_modes;
        let b = self.rotation_coupling(eta);
        // the linear momentum (Mbar u)_(x,y)
        let p = Vec2::new(inv.mass * u[0] + b.x * omega + dot(&st[..m], rates), inv.mass * u[1] + b.y * omega + dot(&st[m..], rates));
        // Mbar w with w = (J^T u_R, 0, 0): the rate of the frame's turn seen in the body frame
        let w = Vec2::new(u[1], -u[0]);
        // M_dot u (the rates of the eta-dependent entries): H_1 eta_dot, H_1^T eta_dot, I_2 eta
        let (mut h1_rates, mut h_rate, mut i2_eta) = ([0.0; MAX_MODES], [0.0; MAX_MODES], [0.0; MAX_MODES]);
        for k in 0..m {
            let row = &inv.modal_rotation_linear[k * m..(k + 1) * m];
            h1_rates[k] = dot(row, rates);
            for (h, r) in h_rate[..m].iter_mut().zip(row) {
                *h += r * rates[k];
            }
            i2_eta[k] = dot(&inv.inertia_quadratic[k * m..(k + 1) * m], eta);
        }
        let b_rate = Vec2::new(dot(&inv.rotation_coupling_modes[..m], rates), dot(&inv.rotation_coupling_modes[m..], rates));
        let inertia_rate = 2.0 * (dot(&inv.inertia_linear, rates) + dot(rates, &i2_eta[..m]));
        let h_rate_dot = dot(&h_rate[..m], rates);
        out[0] = omega * p.y - b_rate.x * omega - omega * inv.mass * w.x;
        out[1] = -omega * p.x - b_rate.y * omega - omega * inv.mass * w.y;
        out[2] = w.dot(&p) - (b_rate.dot(&Vec2::new(u[0], u[1])) + inertia_rate * omega + h_rate_dot) - omega * b.dot(&w);
        for i in 0..m {
            let st = Vec2::new(st[i], st[m + i]);
            let a1 = Vec2::new(inv.rotation_coupling_modes[i], inv.rotation_coupling_modes[m + i]);
            let kinetic_gradient = omega * a1.dot(&Vec2::new(u[0], u[1])) + omega * omega * (inv.inertia_linear[i] + i2_eta[i]) + omega * h1_rates[i];
            out[3 + i] = kinetic_gradient - h_rate[i] * omega - omega * st.dot(&w);
        }
    }

    /// `s(eta) = s_0 + S_t eta` in the body frame [kg m].
    fn first_moment(&self, eta: &[f64]) -> Vec2 {
        let (inv, m) = (&self.invariants, self.n_modes());
        inv.first_moment + Vec2::new(dot(&inv.first_moment_modes[..m], eta), dot(&inv.first_moment_modes[m..], eta))
    }

}

impl ModalBody {
    /// Channels: the frame's `x`, `y`, `angle` (as a rigid body's) and `eta1`, `eta2`, ... with their rates.
    fn coordinate_channels(&self) -> Vec<CoordinateChannels> {
        let frame = [
            CoordinateChannels { position: channel("x", "m", "frame origin x"), velocity: channel("vx", "m/s", "frame origin velocity x"), acceleration: channel("ax", "m/s^2", "frame origin acceleration x") },
            CoordinateChannels { position: channel("y", "m", "frame origin y"), velocity: channel("vy", "m/s", "frame origin velocity y"), acceleration: channel("ay", "m/s^2", "frame origin acceleration y") },
            CoordinateChannels { position: channel("angle", "rad", "frame angle"), velocity: channel("omega", "rad/s", "frame angular velocity"), acceleration: channel("alpha", "rad/s^2", "frame angular acceleration") },
        ];
        let modes = (0..self.n_modes()).map(|j| {
            let kind = if j < self.n_constraint { "constraint" } else { "fixed-interface normal" };
            let (unit, rate, acceleration) = if self.rotational[j] { ("rad", "rad/s", "rad/s^2") } else { ("m", "m/s", "m/s^2") };
            let named = |prefix: &str, unit: &'static str, what: &str| (Cow::Owned(format!("{prefix}{}", j + 1)), unit, Cow::Owned(format!("{what} of mode {} ({kind})", j + 1)));
            CoordinateChannels { position: named("eta", unit, "amplitude"), velocity: named("eta_rate", rate, "amplitude rate"), acceleration: named("eta_acceleration", acceleration, "amplitude acceleration") }
        });
        frame.into_iter().chain(modes).collect()
    }
}

impl BodyModel for ModalBody {
    fn nq(&self) -> usize {
        self.n_coordinates()
    }

    fn nv(&self) -> usize {
        self.n_coordinates()
    }

    /// The body frame's pose and velocity from `(x, y, phi)` and their rates.
    #[inline]
    fn frame(&self, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        Frame::from_coordinates_after(previous, q, v)
    }

    /// A node's frame, or the body frame.
    #[inline]
    fn site_frame(&self, site: &Site, q: &[f64], v: &[f64], previous: &Frame) -> Frame {
        match site {
            Site::ModalNode(node) => self.node_frame(node.node as usize, q, v, previous),
            Site::Reference | Site::Section(_) => self.frame(q, v, previous),
        }
    }

    /// `scale d(v_P)/d(v)`: `scale [I, perp(P - R), A Phi_a + perp(s) Psi_a]`, rows x and y.
    fn marker_jacobian(&self, body: &Frame, frame: &Frame, marker: &Marker, scale: f64, jx: &mut [f64], jy: &mut [f64]) {
        let s = frame.rotate(marker.local);
        let d = (frame.position + s - body.position) * scale;
        jx[..3].copy_from_slice(&[scale, 0.0, -d.y]);
        jy[..3].copy_from_slice(&[0.0, scale, d.x]);
        let rows = self.rows(self.node(marker));
        for i in 0..self.n_modes() {
            let c = Self::modal_column(body, rows, s, i) * scale;
            jx[3 + i] = c.x;
            jy[3 + i] = c.y;
        }
    }

    /// All `3 + m` coordinates.
    fn marker_coordinates(&self, _marker: &Marker) -> Range<usize> {
        0..self.n_coordinates()
    }

    /// Adds `along . d(v_P)/d(v)` to `out`.
    fn add_marker_jacobian(&self, body: &Frame, frame: &Frame, marker: &Marker, along: Vec2, out: &mut [f64]) {
        let s = frame.rotate(marker.local);
        let d = frame.position + s - body.position;
        out[0] += along.x;
        out[1] += along.y;
        out[2] += along.dot(&perp(d));
        let rows = self.rows(self.node(marker));
        for i in 0..self.n_modes() {
            out[3 + i] += along.dot(&Self::modal_column(body, rows, s, i));
        }
    }

    /// Adds `scale d(omega_P)/d(v)` = `scale [0, 0, 1, Psi_a]` to `out`.
    fn add_marker_angle_jacobian(&self, marker: &Marker, scale: f64, out: &mut [f64]) {
        out[2] += scale;
        let (_, _, rt) = self.rows(self.node(marker));
        for (o, r) in out[3..].iter_mut().zip(rt) {
            *o += scale * r;
        }
    }

    /// `omega^2 d + 2 omega perp(v_a - R_dot) - omega_a^2 s` [m/s^2]: the point's
    /// acceleration at zero coordinate accelerations (`d` the node from the frame
    /// origin, `v_a` its velocity, `omega_a` its section's rate, `s` the point from the node).
    fn marker_bias_acceleration(&self, body: &Frame, frame: &Frame, marker: &Marker) -> Vec2 {
        let s = frame.rotate(marker.local);
        let d = frame.position - body.position;
        let omega = body.angular_velocity;
        d * (omega * omega) + perp(frame.velocity - body.velocity) * (2.0 * omega) - s * (frame.angular_velocity * frame.angular_velocity)
    }

    /// None: the node's section angle `phi + Psi_a eta` is linear in the coordinates.
    #[inline]
    fn marker_bias_angular_acceleration(&self, _frame: &Frame, _marker: &Marker) -> f64 {
        0.0
    }

    /// The bias acceleration plus the Jacobian times the accelerations `a` [m/s^2].
    fn marker_acceleration(&self, body: &Frame, frame: &Frame, a: &[f64], marker: &Marker) -> Vec2 {
        let s = frame.rotate(marker.local);
        let d = frame.position + s - body.position;
        let rows = self.rows(self.node(marker));
        let modal: Vec2 = (0..self.n_modes()).map(|i| Self::modal_column(body, rows, s, i) * a[3 + i]).sum();
        self.marker_bias_acceleration(body, frame, marker) + Vec2::new(a[0], a[1]) + perp(d) * a[2] + modal
    }

    /// `alpha + Psi_a eta_ddot` [rad/s^2].
    fn marker_angular_acceleration(&self, _frame: &Frame, a: &[f64], marker: &Marker) -> f64 {
        let (_, _, rt) = self.rows(self.node(marker));
        a[2] + dot(rt, &a[3..])
    }

    /// Dependent on the modal amplitudes.
    fn mass_block(&self) -> MassBlock<'_> {
        MassBlock::ConfigurationDependent
    }

    /// Values of scratch the mass solve needs: `m` ([`BodyMassSolve::work_len`]).
    fn mass_scratch_len(&self) -> usize {
        self.mass_solve.work_len()
    }

    /// `out = M(q)^-1 f`: `f` turned into the body frame, solved with `Mbar(eta)`
    /// by its modal block factored once and the Schur complement of the frame's
    /// coordinates ([`BodyMassSolve`], `scratch` of [`Self::mass_scratch_len`]
    /// values), turned back. A mass that is not definite (a non-finite state)
    /// gives NaN, which the engine reports.
    fn solve_mass(&self, q: &[f64], f: &[f64], out: &mut [f64], scratch: &mut [f64]) {
        let (sin, cos) = q[2].sin_cos();
        out.copy_from_slice(f);
        out[0] = cos * f[0] + sin * f[1];
        out[1] = -sin * f[0] + cos * f[1];
        if !self.mass_solve.solve(&q[3..], out, scratch) {
            out.fill(f64::NAN);
            return;
        }
        let (x, y) = (out[0], out[1]);
        out[0] = cos * x - sin * y;
        out[1] = sin * x + cos * y;
    }

    /// The quadratic velocity vector, elastic and damping forces.
    fn has_body_forces(&self) -> bool {
        true
    }

    /// Adds the quadratic velocity vector, minus the elastic and damping forces, to `out`.
    fn add_body_forces(&self, q: &[f64], v: &[f64], out: &mut [f64]) {
        let (n, m) = (self.n_coordinates(), self.n_modes());
        let (mut qv, mut u) = ([0.0; MAX_COORDINATES], [0.0; MAX_COORDINATES]);
        Self::body_velocities(q, v, &mut u[..n]);
        self.quadratic_velocity_vector(&q[3..], &u[..n], &mut qv[..n]);
        let (sin, cos) = q[2].sin_cos();
        out[0] += cos * qv[0] - sin * qv[1];
        out[1] += sin * qv[0] + cos * qv[1];
        out[2] += qv[2];
        let (eta, rates) = (&q[3..], &v[3..]);
        for i in 0..m {
            let row = i * m..(i + 1) * m;
            out[3 + i] += qv[3 + i] - dot(&self.stiffness[row.clone()], eta) - dot(&self.damping[row], rates);
        }
    }

    /// The frame's coordinates take the rigid motion; modal rates zero.
    fn rigid_motion_velocities(&self, _q: &[f64], velocity: Vec2, angular_velocity: f64, v: &mut [f64]) {
        v.fill(0.0);
        v[..3].copy_from_slice(&[velocity.x, velocity.y, angular_velocity]);
    }

    /// Adds the generalised force of `f` [N] at `p` [m] (moving with `marker`): the transpose of its Jacobian times `f`.
    fn add_point_force(&self, body: &Frame, frame: &Frame, marker: &Marker, p: Vec2, f: Vec2, out: &mut [f64]) {
        let s = p - frame.position;
        out[0] += f.x;
        out[1] += f.y;
        out[2] += cross(p - body.position, f);
        let rows = self.rows(self.node(marker));
        for i in 0..self.n_modes() {
            out[3 + i] += f.dot(&Self::modal_column(body, rows, s, i));
        }
    }

    /// Adds the generalised force of the moment `m` [N m] on the node's section: `m [0, 0, 1, Psi_a]`.
    fn add_moment(&self, marker: &Marker, m: f64, out: &mut [f64]) {
        self.add_marker_angle_jacobian(marker, m, out);
    }

    /// The weight's moment and modal loads turn with the frame.
    fn gravity_load_is_constant(&self) -> bool {
        false
    }

    /// Generalised gravity `-dV/dq`, `V = -g . (m R + A s(eta))`, `s = s_0 + S_t eta`.
    fn add_gravity(&self, g: Vec3, q: &[f64], out: &mut [f64]) {
        let (inv, m) = (&self.invariants, self.n_modes());
        let (sin, cos) = q[2].sin_cos();
        let g_body = Vec2::new(cos * g.x + sin * g.y, -sin * g.x + cos * g.y);
        out[0] += inv.mass * g.x;
        out[1] += inv.mass * g.y;
        out[2] += cross(self.first_moment(&q[3..]), g_body);
        for i in 0..m {
            out[3 + i] += inv.first_moment_modes[i] * g_body.x + inv.first_moment_modes[m + i] * g_body.y;
        }
    }

    /// Gravity's potential `-g . (m R + A s(eta))` plus the strain energy `eta^T K_ee eta / 2` [J].
    fn potential_energy(&self, g: Vec3, q: &[f64]) -> f64 {
        let m = self.n_modes();
        let eta = &q[3..];
        let (sin, cos) = q[2].sin_cos();
        let s = self.first_moment(eta);
        let centre = Vec2::new(q[0], q[1]) * self.invariants.mass + Vec2::new(cos * s.x - sin * s.y, sin * s.x + cos * s.y);
        let strain: f64 = (0..m).map(|i| eta[i] * dot(&self.stiffness[i * m..(i + 1) * m], eta)).sum();
        -Vec2::new(g.x, g.y).dot(&centre) + 0.5 * strain
    }

    /// `u^T Mbar(eta) u / 2` [J].
    fn kinetic_energy(&self, q: &[f64], v: &[f64]) -> f64 {
        let n = self.n_coordinates();
        let (mut u, mut p) = ([0.0; MAX_COORDINATES], [0.0; MAX_COORDINATES]);
        Self::body_velocities(q, v, &mut u[..n]);
        self.times_body_mass(&q[3..], &u[..n], &mut p[..n]);
        0.5 * dot(&u[..n], &p[..n])
    }

    fn position_channels(&self) -> Vec<ChannelName> {
        position_channels_of(self.coordinate_channels())
    }

    fn velocity_channels(&self) -> Vec<(ChannelName, ChannelName)> {
        velocity_channels_of(self.coordinate_channels())
    }

    embedded_in_the_plane!();
}

/// The modes of the reduced body held at its frame's reference conditions:
/// angular frequencies [rad/s], and the modal damping `D = M V diag(2 zeta w) V^T M`
/// that gives each of them the damping ratio `zeta` (`V` mass-normalised).
fn held_modes(mass: &DMatrix<f64>, stiffness: &DMatrix<f64>, zeta: f64) -> Result<(Vec<f64>, DMatrix<f64>), String> {
    let m = mass.nrows();
    if m == 0 {
        return Ok((Vec::new(), DMatrix::zeros(0, 0)));
    }
    let modes = vibration_modes(mass, stiffness, &[])?;
    let rates = DMatrix::from_diagonal(&nalgebra::DVector::from_iterator(m, modes.angular_frequencies.iter().map(|w| 2.0 * zeta * w)));
    let mv = mass * &modes.shapes;
    Ok((modes.angular_frequencies, &mv * rates * mv.transpose()))
}

/// The node pairs `(a, b)`, `a < b`, whose coupling block in `stiffness` (`d`
/// coordinates per node) is not zero: the lines of a finite-element mesh.
fn coupled_nodes(stiffness: &DMatrix<f64>, d: usize) -> Vec<[usize; 2]> {
    let n = stiffness.nrows() / d;
    let scale = stiffness.amax();
    let coupled = |a: usize, b: usize| (0..d).any(|i| (0..d).any(|j| stiffness[(d * a + i, d * b + j)].abs() > 1e-12 * scale));
    (0..n).flat_map(|a| (a + 1..n).map(move |b| [a, b])).filter(|&[a, b]| coupled(a, b)).collect()
}
