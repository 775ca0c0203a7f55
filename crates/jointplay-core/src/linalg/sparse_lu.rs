//! LU factorisation with partial pivoting of a square sparse matrix whose
//! pattern is known before its values, by faer's sparse LU
//! (<https://docs.rs/faer/0.24>, `faer::sparse::linalg::lu`): the
//! fill-reducing column ordering (COLAMD) and the symbolic factorisation are
//! made once for the pattern ([`SparseLu::analyse`]); every numeric
//! factorisation and solve then reuses them and the scratch allocated with
//! them. The matrix is stored column-major (compressed sparse columns) and
//! its values are written in place through the slots [`SparseLu::analyse`]
//! returns for the entries it was given.
//!
//! Partial pivoting does not report a matrix that is singular to round-off
//! (a pivot of 1e-17 is still a pivot), so every factorisation is checked by
//! solving for a known vector ([`SparseLu::factor`]): an error above
//! [`ACCEPTED_ERROR`] reports the matrix as singular.

use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::sparse::linalg::lu::{factorize_symbolic_lu, LuRef, LuSymbolicParams, NumericLu, SymbolicLu};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par};

/// Largest relative error (max norm) of the check solve for which a factorisation is used:
/// a regular matrix of condition number kappa solves to about `kappa eps`, so this accepts
/// condition numbers up to about 1e10 and rejects a matrix singular to round-off.
pub const ACCEPTED_ERROR: f64 = 1e-6;

/// A pattern, its values, its symbolic LU and the numeric LU of its last values.
pub struct SparseLu {
    n: usize,
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    values: Vec<f64>,
    symbolic: SymbolicLu<usize>,
    numeric: NumericLu<usize, f64>,
    /// Scratch of the numeric factorisation and of a solve.
    memory: MemBuffer,
    /// The check's known solution, `A` times it, and the check solve's result.
    known: Vec<f64>,
    check: Vec<f64>,
    factored: bool,
}

/// The matrix could not be factored, or its factors fail the check solve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SingularSparse;

impl SparseLu {
    /// The `n x n` pattern of `entries` `(row, column)` (repeats allowed: they share a value),
    /// analysed once; returns the factorisation and the index into [`Self::values_mut`] of every entry.
    pub fn analyse(n: usize, entries: &[(usize, usize)]) -> Result<(Self, Vec<usize>), SingularSparse> {
        // sorted by column, then row; the diagonal always present (a pivot may land there)
        let mut keys: Vec<(usize, usize)> = entries.iter().map(|&(r, c)| (c, r)).chain((0..n).map(|i| (i, i))).collect();
        keys.sort_unstable();
        keys.dedup();
        let mut col_ptr = vec![0usize; n + 1];
        for &(c, _) in &keys {
            col_ptr[c + 1] += 1;
        }
        for c in 0..n {
            col_ptr[c + 1] += col_ptr[c];
        }
        let row_idx: Vec<usize> = keys.iter().map(|&(_, r)| r).collect();
        let slots = entries.iter().map(|&(r, c)| keys.binary_search(&(c, r)).unwrap_or(0)).collect();
        let pattern = SymbolicSparseColMatRef::new_checked(n, n, &col_ptr, None, &row_idx);
        let symbolic = factorize_symbolic_lu(pattern, LuSymbolicParams::default()).map_err(|_| SingularSparse)?;
        let memory = MemBuffer::try_new(StackReq::any_of(&[
            symbolic.factorize_numeric_lu_scratch::<f64>(Par::Seq, Default::default()),
            symbolic.solve_in_place_scratch::<f64>(1, Par::Seq),
        ]))
        .map_err(|_| SingularSparse)?;
        let values = vec![0.0; row_idx.len()];
        // the check's solution: entries of one size and varying sign, none zero
        let known = (0..n).map(|i| 1.0 + 0.5 * ((i * 7919) % 13) as f64 / 13.0 * if i % 2 == 0 { 1.0 } else { -1.0 }).collect();
        let lu = Self { n, col_ptr, row_idx, values, symbolic, numeric: NumericLu::new(), memory, known, check: vec![0.0; n], factored: false };
        Ok((lu, slots))
    }

    /// Size n.
    pub fn size(&self) -> usize {
        self.n
    }

    /// The values, in the slots [`Self::analyse`] returned (the caller zeroes and fills them).
    pub fn values_mut(&mut self) -> &mut [f64] {
        &mut self.values
    }

    /// Factors the present values and checks the factors by a solve for a known vector.
    pub fn factor(&mut self) -> Result<(), SingularSparse> {
        self.factored = false;
        let pattern = SymbolicSparseColMatRef::new_checked(self.n, self.n, &self.col_ptr, None, &self.row_idx);
        let matrix = SparseColMatRef::new(pattern, &self.values);
        let stack = MemStack::new(&mut self.memory);
        self.symbolic
            .factorize_numeric_lu(&mut self.numeric, matrix, Par::Seq, stack, Default::default())
            .map_err(|_| SingularSparse)?;
        // check = A known, solved back, compared with known
        self.check.fill(0.0);
        for c in 0..self.n {
            for k in self.col_ptr[c]..self.col_ptr[c + 1] {
                self.check[self.row_idx[k]] += self.values[k] * self.known[c];
            }
        }
        self.factored = true;
        let mut check = std::mem::take(&mut self.check);
        self.solve(&mut check);
        // (f64::max would drop a NaN: a zero pivot's)
        let accepted = check.iter().zip(&self.known).all(|(x, k)| (x - k).abs() <= ACCEPTED_ERROR * k.abs());
        self.check = check;
        if !accepted {
            self.factored = false;
            return Err(SingularSparse);
        }
        Ok(())
    }

    /// Solves `A x = b` in place with the factors of the last successful [`Self::factor`].
    pub fn solve(&mut self, b: &mut [f64]) {
        debug_assert!(self.factored, "solve before a successful factorisation");
        let lu = LuRef::new_unchecked(&self.symbolic, &self.numeric);
        let rhs = MatMut::from_column_major_slice_mut(b, self.n, 1);
        let stack = MemStack::new(&mut self.memory);
        lu.solve_in_place_with_conj(Conj::No, rhs, Par::Seq, stack);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linalg::{lu_factor, lu_solve};

    /// A tridiagonal matrix bordered by a constraint row and column (zero diagonal block):
    /// the saddle-point shape of a constrained Newton matrix.
    fn bordered(n: usize) -> Vec<(usize, usize, f64)> {
        let mut e = Vec::new();
        for i in 0..n - 1 {
            e.push((i, i, 4.0 + i as f64 * 0.1));
            if i + 1 < n - 1 {
                e.push((i, i + 1, -1.0 + 0.05 * i as f64));
                e.push((i + 1, i, -1.2));
            }
        }
        // last row/column: a constraint on coordinates 0 and 2
        e.extend([(n - 1, 0, 1.0), (n - 1, 2, -0.5), (0, n - 1, 1.0), (2, n - 1, -0.5)]);
        e
    }

    #[test]
    fn solves_as_the_dense_lu_does() {
        let n = 9;
        let entries = bordered(n);
        let pattern: Vec<(usize, usize)> = entries.iter().map(|&(r, c, _)| (r, c)).collect();
        let (mut lu, slots) = SparseLu::analyse(n, &pattern).unwrap();
        let mut dense = vec![0.0; n * n];
        for (&(r, c, v), &s) in entries.iter().zip(&slots) {
            lu.values_mut()[s] += v;
            dense[r * n + c] += v;
        }
        lu.factor().unwrap();
        let b: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
        let mut x = b.clone();
        lu.solve(&mut x);
        let mut pivots = vec![0; n];
        lu_factor(&mut dense, n, &mut pivots).unwrap();
        let mut reference = b.clone();
        lu_solve(&dense, n, &pivots, &mut reference);
        for (a, r) in x.iter().zip(&reference) {
            assert!((a - r).abs() <= 1e-14 * r.abs().max(1.0), "{a} vs {r}");
        }
    }

    #[test]
    fn a_dependent_constraint_is_reported_singular() {
        // two equal constraint rows: the bordered matrix is singular, in exact arithmetic
        let n = 6;
        let mut entries: Vec<(usize, usize, f64)> = (0..4).map(|i| (i, i, 2.0)).collect();
        for row in [4, 5] {
            entries.extend([(row, 1, 1.0), (row, 3, 1.0), (1, row, 1.0), (3, row, 1.0)]);
        }
        let pattern: Vec<(usize, usize)> = entries.iter().map(|&(r, c, _)| (r, c)).collect();
        let (mut lu, slots) = SparseLu::analyse(n, &pattern).unwrap();
        for (&(_, _, v), &s) in entries.iter().zip(&slots) {
            lu.values_mut()[s] += v;
        }
        assert_eq!(lu.factor(), Err(SingularSparse));
    }
}
