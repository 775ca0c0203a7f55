//! The Jacobian of the right-hand side in absolute coordinates, formed from
//! the model's structure instead of one right-hand side per column
//! (`docs/theory/integrator-jacobian.md`).
//!
//! With `y = [q, v, z]` and `f = [v, a, z_dot]`:
//!
//! ```text
//! df/dy = [ 0         I         0        ]      q_dot = v (exact)
//!         [ A dQ/dq   A dQ/dv   A dQ/dz  ]      a = A(q) Q(t, q, v, z) + b(q, v, t)
//!         [ dz'/dq    dz'/dv    dz'/dz   ]
//! ```
//!
//! `Q` (the local forces: force elements, clearance joints, the beams'
//! internal forces) is a sum of contributions, each reading a few columns of
//! `y` and writing a few rows. Their derivatives are forward differences with
//! column grouping: the columns are coloured so that no contribution reads two
//! columns of one colour, all columns of a colour are perturbed together, and
//! each contribution's change is differenced on its own and put into the
//! column it read. `A` is the constrained-acceleration operator at the current
//! positions (mass solve, constraint solve with the factor of the evaluation).
//! The derivatives of `A(q)` and of `b` (the constraints' geometric stiffness,
//! velocity-product and stabilisation terms) are neglected.

use super::constraint_solution;
use super::equations::{jacobian_times, jacobian_transpose_times, update_frames};
use crate::kinematics::frames::Frames;
use crate::kinematics::planar::Frame;
use crate::kinematics::spatial::SpatialFrame;
use super::generalised_force::GeneralisedForces;
use crate::dynamics::model::mechanism::Model;
use crate::dynamics::formulations::workspace::Workspace;
use crate::body::{BodyKind, BodyModel};
use crate::error::SimulationError;
use crate::element::{ElementMemory, ElementModel, ElementWork};

/// One part of the local forces, evaluated on its own.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Contribution {
    /// Element `k` of `Model::elements` (one acting through forces): its generalised forces and its states' rates.
    Force(usize),
    /// Minus the internal forces of element `element` of the beam `body` (index
    /// into `Model::bodies`), whose coordinates are the body's `first..first + count`.
    BeamElement {
        /// The body.
        body: usize,
        /// The element.
        element: usize,
        /// Its first coordinate, counted from the body's first.
        first: usize,
        /// Its number of coordinates.
        count: usize,
    },
    /// The body forces of body `k`, a kind other than the beam, as a whole.
    Body(usize),
}

/// The contributions with what they read and write, the colouring of the
/// columns, and every buffer of the Jacobian (allocated once).
#[derive(Clone, Debug)]
pub(crate) struct StructuredJacobian {
    contributions: Vec<Contribution>,
    /// Columns of `y` read by contribution k: `reads[read_offsets[k]..read_offsets[k + 1]]`.
    reads: Vec<usize>,
    read_offsets: Vec<usize>,
    /// Rows written by contribution k, in the order it produces them: `r < nv`
    /// is row r of `Q`, `nv + i` the rate of `z_i`.
    writes: Vec<usize>,
    write_offsets: Vec<usize>,
    /// Colour of every column of `y` (`None`: read by no contribution, its column of dQ/dy is zero).
    colours: Vec<Option<usize>>,
    /// Columns of colour g: `colour_columns[colour_offsets[g]..colour_offsets[g + 1]]`.
    colour_columns: Vec<usize>,
    colour_offsets: Vec<usize>,
    /// (contribution, the one column of colour g it reads), over `hit_offsets[g]..hit_offsets[g + 1]`.
    hits: Vec<(usize, usize)>,
    /// Where each hit's derivatives (one per row the contribution writes) start in `local`.
    hit_entries: Vec<usize>,
    hit_offsets: Vec<usize>,
    /// Whether some contribution hit by colour g reads frames (a force element).
    needs_frames: Vec<bool>,
    /// `nv + nz`: the rows of `[Q, z_dot]`.
    n_rows: usize,
    /// Every contribution's rows at the unperturbed state, as `writes`.
    base: Vec<f64>,
    /// `d[Q, z_dot]/dy` contribution by contribution: contribution k's derivative of its
    /// i-th written row by its j-th read column at `entry_offsets[k] + j * writes + i`.
    local: Vec<f64>,
    entry_offsets: Vec<usize>,
    /// `d[Q, z_dot]/dy` summed, column-major (column c at `c * n_rows`): the dense Jacobian's.
    derivatives: Vec<f64>,
    /// Forward-difference increment of every column [unit of the column].
    steps: Vec<f64>,
    /// The perturbed state.
    state: Vec<f64>,
    /// What one contribution's evaluation needs and produces.
    scratch: Scratch,
    /// Velocity-length scratch of the constrained-acceleration operator.
    solved: Vec<f64>,
    response: Vec<f64>,
    /// Constraint-row scratch of that operator.
    multipliers: Vec<f64>,
    /// Columns of `y` whose mass is configuration dependent (a modal body's positions and
    /// velocities): the neglected `dA/dq Q` is not small there, so they are replaced by
    /// forward differences of the whole right-hand side ([`Self::difference_whole_columns`]).
    whole_columns: Vec<usize>,
    /// f at the Jacobian's state, f at a perturbed one and that state, for those columns.
    f_base: Vec<f64>,
    f_perturbed: Vec<f64>,
    y_perturbed: Vec<f64>,
}

/// Buffers of one contribution's evaluation.
#[derive(Clone, Debug)]
struct Scratch {
    /// Frames at the perturbed state.
    frames: Vec<Frame>,
    /// Their spatial frames (in a spatial model).
    spatial_frames: Vec<SpatialFrame>,
    /// The force elements' own scratch (the workspace keeps the last evaluation's).
    work: Vec<ElementWork>,
    /// Generalised forces over all velocity coordinates (zero outside an evaluation).
    forces: Vec<f64>,
    /// Rates of all element states.
    rates: Vec<f64>,
    /// The contribution's rows, as it writes them.
    local: Vec<f64>,
}

/// Appends `items` to `list` sorted and without repeats, and closes its offsets.
fn push_set(list: &mut Vec<usize>, offsets: &mut Vec<usize>, mut items: Vec<usize>) {
    items.sort_unstable();
    items.dedup();
    list.extend(items);
    offsets.push(list.len());
}

impl StructuredJacobian {
    /// The structure of `model` (absolute coordinates, `q_dot = v`) and all buffers.
    pub(crate) fn new(model: &Model) -> Self {
        let layout = &model.layout;
        let (nq, nv, nz) = (layout.nq, layout.nv, layout.nz);
        let mut contributions = Vec::new();
        let (mut reads, mut read_offsets, mut writes, mut write_offsets) = (Vec::new(), vec![0], Vec::new(), vec![0]);
        // force elements: the coordinates their markers move with, and their own states
        for &k in &model.acting {
            let (mut read, mut written) = (Vec::new(), Vec::new());
            for marker in model.elements[k].kind.markers() {
                let Some(address) = layout.body(marker.body) else { continue };
                for c in model.bodies[marker.body.0 - 1].kind.marker_coordinates(&marker) {
                    // (q_dot = v: position coordinate c sits where velocity coordinate c does)
                    read.extend([address.q + c, nq + address.v + c]);
                    written.push(address.v + c);
                }
            }
            for i in layout.element_states[k].clone() {
                read.push(nq + nv + i);
                written.push(nv + i);
            }
            contributions.push(Contribution::Force(k));
            push_set(&mut reads, &mut read_offsets, read);
            // (a force element's rows are read back from the whole Q in this order)
            push_set(&mut writes, &mut write_offsets, written);
        }
        // body forces: a beam element by element (its strain rates only when damped), another kind whole
        for (b, (body, address)) in model.bodies.iter().zip(&layout.bodies).enumerate() {
            match &body.kind {
                BodyKind::Beam(beam) => {
                    let mut first = 0;
                    for (e, element) in beam.elements.iter().enumerate() {
                        let count = element.n_coordinates();
                        let coordinates = first..first + count;
                        let mut read: Vec<usize> = coordinates.clone().map(|c| address.q + c).collect();
                        if beam.damping_time > 0.0 {
                            read.extend(coordinates.clone().map(|c| nq + address.v + c));
                        }
                        contributions.push(Contribution::BeamElement { body: b, element: e, first, count });
                        push_set(&mut reads, &mut read_offsets, read);
                        writes.extend(coordinates.map(|c| address.v + c));
                        write_offsets.push(writes.len());
                        // (consecutive elements share their end node, of n_coordinates / n_nodes coordinates)
                        first += count - count / element.order.n_nodes();
                    }
                }
                kind if kind.has_body_forces() => {
                    let read = address.q_range().chain(address.v_range().map(|c| nq + c)).collect();
                    contributions.push(Contribution::Body(b));
                    push_set(&mut reads, &mut read_offsets, read);
                    writes.extend(address.v_range());
                    write_offsets.push(writes.len());
                }
                _ => {}
            }
        }
        let n = layout.len();
        let whole_columns: Vec<usize> = model.bodies.iter().zip(&layout.bodies)
            .filter(|(body, _)| matches!(body.kind, BodyKind::Modal(_)))
            .flat_map(|(_, address)| address.q_range().chain(address.v_range().map(|c| nq + c)))
            .collect();
        let (colours, n_colours) = colour(n, &reads, &read_offsets);
        let mut structure = Self {
            contributions,
            reads,
            read_offsets,
            writes,
            write_offsets,
            colours,
            colour_columns: Vec::new(),
            colour_offsets: vec![0],
            hits: Vec::new(),
            hit_entries: Vec::new(),
            hit_offsets: vec![0],
            needs_frames: Vec::new(),
            n_rows: nv + nz,
            base: Vec::new(),
            local: Vec::new(),
            entry_offsets: Vec::new(),
            derivatives: vec![0.0; n * (nv + nz)],
            steps: vec![0.0; n],
            state: vec![0.0; n],
            scratch: Scratch {
                frames: vec![Frame::GROUND; model.n_frames()],
                spatial_frames: vec![SpatialFrame::GROUND; if model.spatial { model.n_frames() } else { 0 }],
                work: model.elements.iter().map(|e| e.kind.new_work()).collect(),
                forces: vec![0.0; nv],
                rates: vec![0.0; nz],
                local: Vec::new(),
            },
            solved: vec![0.0; nv],
            response: vec![0.0; nv],
            multipliers: vec![0.0; model.n_dynamic_equations()],
            f_base: vec![0.0; if whole_columns.is_empty() { 0 } else { n }],
            f_perturbed: vec![0.0; if whole_columns.is_empty() { 0 } else { n }],
            y_perturbed: vec![0.0; if whole_columns.is_empty() { 0 } else { n }],
            whole_columns,
        };
        structure.index_entries();
        structure.index_colours(n_colours);
        structure.base = vec![0.0; structure.writes.len()];
        let widest = structure.write_offsets.windows(2).map(|w| w[1] - w[0]).max().unwrap_or(0);
        structure.scratch.local = vec![0.0; widest];
        structure
    }

    /// Replaces the columns of the coordinates whose mass depends on the configuration
    /// ([`Self::whole_columns`]) in `jacobian` (row-major, `y.len()` square) by forward
    /// differences of the whole right-hand side `rhs(y, f)` at the integrator's increments
    /// `sqrt(eps) max(|y_j|, floors[j])`; returns the right-hand sides evaluated at perturbed
    /// states (the one at `y` is the evaluation the integrator made there, which the system holds).
    pub(crate) fn difference_whole_columns(&mut self, y: &[f64], floors: &[f64], jacobian: &mut [f64],
                                           mut rhs: impl FnMut(&[f64], &mut [f64]) -> Result<(), SimulationError>) -> Result<usize, SimulationError> {
        if self.whole_columns.is_empty() {
            return Ok(0);
        }
        let n = y.len();
        rhs(y, &mut self.f_base)?;
        self.y_perturbed.copy_from_slice(y);
        for &j in &self.whole_columns {
            self.y_perturbed[j] = y[j] + f64::EPSILON.sqrt() * y[j].abs().max(floors[j]);
            let step = self.y_perturbed[j] - y[j];
            rhs(&self.y_perturbed, &mut self.f_perturbed)?;
            for i in 0..n {
                jacobian[i * n + j] = (self.f_perturbed[i] - self.f_base[i]) / step;
            }
            self.y_perturbed[j] = y[j];
        }
        Ok(self.whole_columns.len())
    }

    /// Where every contribution's derivatives start among the local entries.
    fn index_entries(&mut self) {
        let mut next = 0;
        for k in 0..self.contributions.len() {
            self.entry_offsets.push(next);
            next += self.reads(k).len() * (self.write_offsets[k + 1] - self.write_offsets[k]);
        }
        self.entry_offsets.push(next);
        self.local = vec![0.0; next];
    }

    /// The columns and the hits of every colour.
    fn index_colours(&mut self, n_colours: usize) {
        for g in 0..n_colours {
            self.colour_columns.extend((0..self.colours.len()).filter(|&c| self.colours[c] == Some(g)));
            self.colour_offsets.push(self.colour_columns.len());
            let mut frames = false;
            for (k, contribution) in self.contributions.iter().enumerate() {
                if let Some(j) = self.reads(k).iter().position(|&c| self.colours[c] == Some(g)) {
                    let c = self.reads(k)[j];
                    self.hits.push((k, c));
                    self.hit_entries.push(self.entry_offsets[k] + j * (self.write_offsets[k + 1] - self.write_offsets[k]));
                    frames |= matches!(contribution, Contribution::Force(_));
                }
            }
            self.hit_offsets.push(self.hits.len());
            self.needs_frames.push(frames);
        }
    }

    /// Number of colours: the passes over the local forces of one Jacobian, besides the unperturbed one.
    pub(crate) fn n_colours(&self) -> usize {
        self.needs_frames.len()
    }

    /// The contributions.
    #[cfg(test)]
    pub(crate) fn contributions(&self) -> &[Contribution] {
        &self.contributions
    }

    /// Columns of `y` contribution k reads.
    pub(crate) fn reads(&self, k: usize) -> &[usize] {
        &self.reads[self.read_offsets[k]..self.read_offsets[k + 1]]
    }

    /// Colour of column c of `y` (`None`: no contribution reads it).
    #[cfg(test)]
    pub(crate) fn colour_of(&self, c: usize) -> Option<usize> {
        self.colours[c]
    }

    /// `d[Q, z_dot]_r / dy_c` of the last [`Self::fill`] (`r < nv`: row r of `Q`; `nv + i`: the rate of `z_i`).
    #[cfg(test)]
    pub(crate) fn local_derivative(&self, r: usize, c: usize) -> f64 {
        self.derivatives[c * self.n_rows + r]
    }

    /// `sum |contribution|` of every row of `[Q, z_dot]` at the state of the last
    /// [`Self::fill`]: the scale of the rounding in its differences.
    #[cfg(test)]
    pub(crate) fn row_magnitudes(&self) -> Vec<f64> {
        let mut sums = vec![0.0; self.n_rows];
        for (&r, value) in self.writes.iter().zip(&self.base) {
            sums[r] += value.abs();
        }
        sums
    }

    /// The Jacobian at `(t, y)` into `jacobian` (row-major, `n x n`); the workspace
    /// must hold the evaluation at `(t, y)` (its constraint linearisation and
    /// factor). Increments `sqrt(eps) max(|y_c|, floors[c])`. Returns the number of
    /// passes over the local forces.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn fill(
        &mut self,
        model: &Model,
        memory: &[ElementMemory],
        t: f64,
        y: &[f64],
        floors: &[f64],
        ws: &mut Workspace,
        jacobian: &mut [f64],
    ) -> Result<usize, SimulationError> {
        let passes = self.local_derivatives(model, memory, t, y, floors)?;
        self.assemble(model, model.layout.split(y).0, ws, jacobian);
        Ok(passes)
    }

    /// `d[Q, z_dot]/dy` by coloured forward differences, into the local entries; returns the passes made.
    pub(crate) fn local_derivatives(&mut self, model: &Model, memory: &[ElementMemory], t: f64, y: &[f64], floors: &[f64]) -> Result<usize, SimulationError> {
        let layout = &model.layout;
        self.state.copy_from_slice(y);
        // the unperturbed pass
        {
            let (q, v, _) = layout.split(&self.state);
            update_frames(model, q, v, &mut self.scratch.frames, &mut self.scratch.spatial_frames);
        }
        for k in 0..self.contributions.len() {
            let rows = self.write_offsets[k]..self.write_offsets[k + 1];
            evaluate(model, memory, t, self.contributions[k], &self.writes[rows.clone()], &self.state, &mut self.scratch)?;
            self.base[rows.clone()].copy_from_slice(&self.scratch.local[..rows.len()]);
        }
        for (c, colour) in self.colours.iter().enumerate() {
            if colour.is_some() {
                let step = f64::EPSILON.sqrt() * y[c].abs().max(floors[c]);
                self.steps[c] = (y[c] + step) - y[c];
            }
        }
        // one pass per colour: its columns perturbed together, each contribution differenced on its own
        for g in 0..self.n_colours() {
            let columns = self.colour_offsets[g]..self.colour_offsets[g + 1];
            for &c in &self.colour_columns[columns.clone()] {
                self.state[c] = y[c] + self.steps[c];
            }
            if self.needs_frames[g] {
                let (q, v, _) = layout.split(&self.state);
                update_frames(model, q, v, &mut self.scratch.frames, &mut self.scratch.spatial_frames);
            }
            for (&(k, c), &entry) in self.hits[self.hit_offsets[g]..self.hit_offsets[g + 1]].iter().zip(&self.hit_entries[self.hit_offsets[g]..]) {
                let rows = self.write_offsets[k]..self.write_offsets[k + 1];
                evaluate(model, memory, t, self.contributions[k], &self.writes[rows.clone()], &self.state, &mut self.scratch)?;
                let entries = &mut self.local[entry..entry + rows.len()];
                for ((d, value), base) in entries.iter_mut().zip(&self.scratch.local).zip(&self.base[rows]) {
                    *d = (value - base) / self.steps[c];
                }
            }
            for &c in &self.colour_columns[columns] {
                self.state[c] = y[c];
            }
        }
        Ok(1 + self.n_colours())
    }

    /// The Jacobian from the local derivatives: `q_dot = v`, `A` applied to the
    /// columns of `dQ/dy`, `dz_dot/dy` as differenced (the mass at the positions `q`).
    fn assemble(&mut self, model: &Model, q: &[f64], ws: &mut Workspace, jacobian: &mut [f64]) {
        let (nq, nv) = (model.layout.nq, model.layout.nv);
        self.sum_local_derivatives();
        let n = model.layout.len();
        let rows = model.n_dynamic_equations();
        jacobian.fill(0.0);
        // (q_dot = v with q and v laid out alike)
        for i in 0..nq {
            jacobian[i * n + nq + i] = 1.0;
        }
        for c in 0..n {
            if self.colours[c].is_none() {
                continue;
            }
            let column = &self.derivatives[c * self.n_rows..(c + 1) * self.n_rows];
            let (forces, rates) = column.split_at(nv);
            if forces.iter().any(|&d| d != 0.0) {
                constrained_response(model, rows, q, ws, forces, (&mut self.solved, &mut self.multipliers), &mut self.response);
                for (i, a) in self.response.iter().enumerate() {
                    jacobian[(nq + i) * n + c] = *a;
                }
            }
            for (i, d) in rates.iter().enumerate() {
                jacobian[(nq + nv + i) * n + c] = *d;
            }
        }
    }
}

impl StructuredJacobian {
    /// The local entries summed into the dense `derivatives`, contribution by contribution.
    fn sum_local_derivatives(&mut self) {
        self.derivatives.fill(0.0);
        for k in 0..self.contributions.len() {
            let rows = &self.writes[self.write_offsets[k]..self.write_offsets[k + 1]];
            let reads = &self.reads[self.read_offsets[k]..self.read_offsets[k + 1]];
            let entries = &self.local[self.entry_offsets[k]..self.entry_offsets[k + 1]];
            for (&c, derivatives) in reads.iter().zip(entries.chunks_exact(rows.len().max(1))) {
                let column = &mut self.derivatives[c * self.n_rows..(c + 1) * self.n_rows];
                for (&r, d) in rows.iter().zip(derivatives) {
                    column[r] += d;
                }
            }
        }
    }

    /// Entries `(row of [Q, z_dot], column of y)` of the local derivatives, in the order
    /// [`Self::local_entries`] gives their values.
    pub(crate) fn local_pattern(&self) -> Vec<(usize, usize)> {
        let mut pattern = Vec::with_capacity(self.local.len());
        for k in 0..self.contributions.len() {
            let rows = &self.writes[self.write_offsets[k]..self.write_offsets[k + 1]];
            for &c in self.reads(k) {
                pattern.extend(rows.iter().map(|&r| (r, c)));
            }
        }
        pattern
    }

    /// The local derivatives of the last [`Self::local_derivatives`], as [`Self::local_pattern`].
    pub(crate) fn local_entries(&self) -> &[f64] {
        &self.local
    }

    /// Whether some columns are differenced whole (a configuration-dependent mass).
    pub(crate) fn has_whole_columns(&self) -> bool {
        !self.whole_columns.is_empty()
    }
}

/// Greedy colouring of the `n` columns: a column takes the lowest colour that
/// no column read by one of the same contributions has. Returns the colours
/// (`None` for columns no contribution reads) and their number.
fn colour(n: usize, reads: &[usize], offsets: &[usize]) -> (Vec<Option<usize>>, usize) {
    // the contributions reading each column
    let mut readers: Vec<Vec<usize>> = vec![Vec::new(); n];
    for k in 0..offsets.len() - 1 {
        for &c in &reads[offsets[k]..offsets[k + 1]] {
            readers[c].push(k);
        }
    }
    let mut colours: Vec<Option<usize>> = vec![None; n];
    // forbidden[g] == c + 1: colour g is taken by a neighbour of column c
    let mut forbidden: Vec<usize> = Vec::new();
    let mut n_colours = 0;
    for c in 0..n {
        if readers[c].is_empty() {
            continue;
        }
        for &k in &readers[c] {
            for &other in &reads[offsets[k]..offsets[k + 1]] {
                if let Some(g) = colours[other] {
                    forbidden[g] = c + 1;
                }
            }
        }
        let g = (0..n_colours).find(|&g| forbidden[g] != c + 1).unwrap_or(n_colours);
        if g == n_colours {
            n_colours += 1;
            forbidden.push(0);
        }
        colours[c] = Some(g);
    }
    (colours, n_colours)
}

/// Evaluates one contribution at the state `y` (frames in `scratch.frames` placed
/// there when it reads frames) into `scratch.local`, row by row of `rows`.
fn evaluate(model: &Model, memory: &[ElementMemory], t: f64, contribution: Contribution, rows: &[usize], y: &[f64], scratch: &mut Scratch) -> Result<(), SimulationError> {
    let layout = &model.layout;
    let (q, v, z) = layout.split(y);
    let nv = layout.nv;
    match contribution {
        Contribution::Force(k) => {
            scratch.forces.fill(0.0);
            let states = layout.element_states[k].clone();
            let frames = Frames { planar: &scratch.frames, spatial: &scratch.spatial_frames };
            let mut forces = GeneralisedForces::new(&mut scratch.forces, &model.bodies, layout, frames);
            let element = &model.elements[k];
            element
                .kind
                .apply(&frames, t, (&z[states.clone()], &mut scratch.rates[states]), &memory[model.memory_of(k)], &mut scratch.work[k], false, &mut forces)
                .map_err(|fault| fault.at(t, &element.name))?;
            for (out, &r) in scratch.local.iter_mut().zip(rows) {
                *out = if r < nv { scratch.forces[r] } else { scratch.rates[r - nv] };
            }
        }
        Contribution::BeamElement { body, element, first, count } => {
            let BodyKind::Beam(beam) = &model.bodies[body].kind else { return Ok(()) };
            let address = &layout.bodies[body];
            let (start, local) = (address.q + first, &mut scratch.local[..count]);
            local.fill(0.0);
            let rate = (beam.damping_time > 0.0).then(|| (&v[address.v + first..address.v + first + count], beam.damping_time));
            beam.elements[element].add_viscoelastic_forces(&q[start..start + count], rate, local);
            for f in local.iter_mut() {
                *f = -*f;
            }
        }
        Contribution::Body(body) => {
            let address = &layout.bodies[body];
            let local = &mut scratch.local[..address.nv];
            local.fill(0.0);
            model.bodies[body].kind.add_body_forces(&q[address.q_range()], &v[address.v_range()], local);
        }
    }
    Ok(())
}

/// `out = A g`: the accelerations that the generalised forces `g` cause under
/// the constraints linearised in the workspace (`rows` rows, factored there):
/// `A g = M^-1 (g - Phi_q^T S^-1 Phi_q M^-1 g)`, `S = Phi_q M^-1 Phi_q^T`, `M` at the positions `q`.
pub(crate) fn constrained_response(model: &Model, rows: usize, q: &[f64], ws: &mut Workspace, g: &[f64], (solved, multipliers): (&mut [f64], &mut [f64]), out: &mut [f64]) {
    if rows == 0 {
        model.solve_mass(q, g, out, &mut ws.mass_matrix);
        return;
    }
    model.solve_mass(q, g, solved, &mut ws.mass_matrix);
    jacobian_times(model, rows, &ws.jacobian, solved, multipliers);
    constraint_solution::solve(model, rows, ws, multipliers);
    jacobian_transpose_times(model, rows, &ws.jacobian, multipliers, solved);
    for (s, g) in solved.iter_mut().zip(g) {
        *s = g - *s;
    }
    model.solve_mass(q, solved, out, &mut ws.mass_matrix);
}
