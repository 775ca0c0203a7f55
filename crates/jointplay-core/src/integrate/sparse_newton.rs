//! The Newton matrix of the implicit methods as a sparse augmented system, for
//! a system `y = [q, v, z]`, `q_dot = v`, whose accelerations are
//! `a = A Q(t, q, v, z) + b` with `A` the constrained-acceleration operator
//! (`M x + Phi_q^T mu = g`, `Phi_q x = 0` gives `x = A g`) and whose Jacobian
//! neglects the derivatives of `A` and `b` (`docs/theory/integrator-jacobian.md`,
//! "Sparse Newton matrix").
//!
//! The reduced Newton equation `(alpha I - c_v J_rr - c_q J_rq) [dv, dz] = [b_v, b_z]`
//! on `r = [v, z]` is then the same as
//!
//! ```text
//! [ alpha M - c_v Q_v - c_q Q_q   Phi_q^T   -c_v Q_z          ] [dv]   [ M b_v     ]
//! [ alpha Phi_q                   0         0                 ] [mu] = [ Phi_q b_v ]
//! [ -c_v Z_v - c_q Z_q            0         alpha I - c_v Z_z ] [dz]   [ b_z       ]
//! ```
//!
//! (`Q_x = dQ/dx`, `Z_x = dz_dot/dx`), whose pattern is the model's: the cost
//! of a factorisation grows with the coupling, not with the square of the
//! coordinates. The NDF's `(I - c J) [dq, dv, dz] = [b_q, b_v, b_z]` is this with
//! `alpha = 1`, `c_v = c`, `c_q = c^2`, the right-hand side augmented by
//! `c Q_q b_q` and `c Z_q b_q`, and `dq = b_q + c dv`.

use crate::linalg::{SingularSparse, SparseLu};

/// Where the values of the parts sit: the entries of `M`, of `Phi_q` and of `d[Q, z_dot]/dy`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NewtonStructure {
    /// Velocity coordinates (and positions: `q_dot = v`).
    pub nv: usize,
    /// Constraint rows of `Phi_q`.
    pub n_constraints: usize,
    /// Force states.
    pub nz: usize,
    /// Entries `(i, j)` of the mass matrix over the velocity coordinates (both triangles).
    pub mass: Vec<(usize, usize)>,
    /// Entries `(row, velocity coordinate)` of `Phi_q`.
    pub constraint: Vec<(usize, usize)>,
    /// Entries `(row of [Q, z_dot], column of y)` of the local derivatives (repeats add).
    pub local: Vec<(usize, usize)>,
}

/// The values of the parts, entry by entry of a [`NewtonStructure`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NewtonParts {
    /// Mass entries [kg, kg m, kg m^2].
    pub mass: Vec<f64>,
    /// `Phi_q` entries.
    pub constraint: Vec<f64>,
    /// `d[Q, z_dot]/dy` entries.
    pub local: Vec<f64>,
}

/// Which coefficient multiplies a local derivative in the augmented matrix.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LocalColumn {
    /// A position column: `-c_q`.
    Position,
    /// A velocity or force-state column: `-c_v`.
    Rate,
}

/// The augmented matrix's pattern, its sparse LU and the parts its values come from.
pub(crate) struct SparseNewton {
    structure: NewtonStructure,
    /// The parts at the kept Jacobian's state (the system writes them).
    pub(crate) parts: NewtonParts,
    lu: SparseLu,
    /// Slot of every mass entry; of every `Phi_q` entry in its row and in its transposed column.
    mass_slots: Vec<usize>,
    constraint_row_slots: Vec<usize>,
    constraint_column_slots: Vec<usize>,
    /// Slot, augmented row and column kind of every local derivative.
    local_slots: Vec<usize>,
    local_rows: Vec<usize>,
    local_columns: Vec<LocalColumn>,
    /// Slots of the force states' diagonal.
    state_diagonal_slots: Vec<usize>,
    /// Right-hand side and solution of the augmented system.
    augmented: Vec<f64>,
}

impl SparseNewton {
    /// The augmented pattern of `structure`, analysed once.
    pub(crate) fn new(structure: NewtonStructure) -> Result<Self, SingularSparse> {
        let (nv, nc, nz) = (structure.nv, structure.n_constraints, structure.nz);
        let size = nv + nc + nz;
        let state_row = |i: usize| nv + nc + i;
        let mut entries: Vec<(usize, usize)> = structure.mass.clone();
        entries.extend(structure.constraint.iter().map(|&(r, c)| (nv + r, c)));
        entries.extend(structure.constraint.iter().map(|&(r, c)| (c, nv + r)));
        let mut local_rows = Vec::with_capacity(structure.local.len());
        let mut local_columns = Vec::with_capacity(structure.local.len());
        for &(row, column) in &structure.local {
            let row = if row < nv { row } else { state_row(row - nv) };
            let (column, kind) = if column < nv {
                (column, LocalColumn::Position)
            } else if column < 2 * nv {
                (column - nv, LocalColumn::Rate)
            } else {
                (state_row(column - 2 * nv), LocalColumn::Rate)
            };
            entries.push((row, column));
            local_rows.push(row);
            local_columns.push(kind);
        }
        entries.extend((0..nz).map(|i| (state_row(i), state_row(i))));
        let (lu, slots) = SparseLu::analyse(size, &entries)?;
        let (nm, nk, nl) = (structure.mass.len(), structure.constraint.len(), structure.local.len());
        let mut slots = slots.into_iter();
        let mut take = |count: usize| slots.by_ref().take(count).collect::<Vec<_>>();
        let (mass_slots, constraint_row_slots, constraint_column_slots, local_slots, state_diagonal_slots) = (take(nm), take(nk), take(nk), take(nl), take(nz));
        let parts = NewtonParts { mass: vec![0.0; nm], constraint: vec![0.0; nk], local: vec![0.0; nl] };
        Ok(Self {
            structure,
            parts,
            lu,
            mass_slots,
            constraint_row_slots,
            constraint_column_slots,
            local_slots,
            local_rows,
            local_columns,
            state_diagonal_slots,
            augmented: vec![0.0; size],
        })
    }

    /// Size of the augmented matrix.
    #[cfg(test)]
    pub(crate) fn size(&self) -> usize {
        self.lu.size()
    }

    /// Forms and factors the augmented matrix of `alpha I - c_v J_rr - c_q J_rq` from the parts.
    pub(crate) fn factor(&mut self, alpha: f64, c_v: f64, c_q: f64) -> Result<(), SingularSparse> {
        let parts = &self.parts;
        let values = self.lu.values_mut();
        values.fill(0.0);
        for (&s, m) in self.mass_slots.iter().zip(&parts.mass) {
            values[s] += alpha * m;
        }
        for ((&row, &column), phi) in self.constraint_row_slots.iter().zip(&self.constraint_column_slots).zip(&parts.constraint) {
            values[row] += alpha * phi;
            values[column] += phi;
        }
        for ((&s, kind), d) in self.local_slots.iter().zip(&self.local_columns).zip(&parts.local) {
            values[s] -= match kind {
                LocalColumn::Position => c_q * d,
                LocalColumn::Rate => c_v * d,
            } ;
        }
        for &s in &self.state_diagonal_slots {
            values[s] += alpha;
        }
        self.lu.factor()
    }

    /// `[M b_v, Phi_q b_v, b_z]` into the augmented vector.
    fn load(&mut self, b_v: &[f64], b_z: &[f64]) {
        let NewtonStructure { nv, n_constraints: nc, .. } = self.structure;
        self.augmented.fill(0.0);
        for (&(i, j), m) in self.structure.mass.iter().zip(&self.parts.mass) {
            self.augmented[i] += m * b_v[j];
        }
        for (&(r, c), phi) in self.structure.constraint.iter().zip(&self.parts.constraint) {
            self.augmented[nv + r] += phi * b_v[c];
        }
        self.augmented[nv + nc..].copy_from_slice(b_z);
    }

    /// Solves the reduced equation for `b = [b_v, b_z]` in place (the factors of [`Self::factor`]).
    pub(crate) fn solve_reduced(&mut self, b: &mut [f64]) {
        let NewtonStructure { nv, n_constraints: nc, .. } = self.structure;
        let (b_v, b_z) = b.split_at_mut(nv);
        self.load(b_v, b_z);
        self.lu.solve(&mut self.augmented);
        b_v.copy_from_slice(&self.augmented[..nv]);
        b_z.copy_from_slice(&self.augmented[nv + nc..]);
    }

    /// Solves `(I - c J) x = b` in place for `b = [b_q, b_v, b_z]`, the factors made
    /// by [`Self::factor`] with `alpha = 1`, `c_v = c`, `c_q = c^2`.
    pub(crate) fn solve_full(&mut self, c: f64, b: &mut [f64]) {
        let NewtonStructure { nv, n_constraints: nc, .. } = self.structure;
        let (b_q, rest) = b.split_at_mut(nv);
        let (b_v, b_z) = rest.split_at_mut(nv);
        self.load(b_v, b_z);
        // (dq = b_q + c dv carries b_q into the rows of Q and z_dot through their position derivatives)
        for ((&(_, column), &row), d) in self.structure.local.iter().zip(&self.local_rows).zip(&self.parts.local) {
            if column < nv {
                self.augmented[row] += c * d * b_q[column];
            }
        }
        self.lu.solve(&mut self.augmented);
        for ((q, v), dv) in b_q.iter_mut().zip(b_v.iter_mut()).zip(&self.augmented[..nv]) {
            *q += c * dv;
            *v = *dv;
        }
        b_z.copy_from_slice(&self.augmented[nv + nc..]);
    }
}
