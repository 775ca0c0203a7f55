//! The constraint Jacobian `Phi_q` as sparse rows of body blocks.
//!
//! A row of a constraint between two markers depends only on the velocity
//! coordinates of the markers' bodies, and of those only on the coordinates a
//! marker moves with (all three of a planar rigid body; the nodes of one element
//! of a beam). Each row therefore stores one block per non-ground marker: a run of
//! consecutive velocity coordinates of one body, as wide as the body kind says
//! ([`crate::body::BodyKind::marker_coordinates`]). The pattern is fixed at
//! compile time; the values are written at every linearisation.
//!
//! `Phi_q M^-1 Phi_q^T` is formed from the blocks and the blocks solved with
//! their body's mass block, `M_b^-1 J_b^T` over all of the body's velocity
//! coordinates, so a body kind with a full or configuration-dependent mass
//! block needs nothing here but its own solve.

use std::ops::Range;

/// One block of a constraint row: the derivatives by `width` consecutive
/// velocity coordinates of one body.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct JacobianBlock {
    /// The body (index into `Model::bodies`).
    pub body: usize,
    /// First velocity coordinate of the block (address in `v`).
    pub start: usize,
    /// Number of velocity coordinates it spans.
    pub width: usize,
    /// Its first velocity coordinate counted from the body's first.
    pub offset_in_body: usize,
    /// Where its values start among the Jacobian's values.
    pub value: usize,
    /// Where `M_b^-1` times the block (the body's `nv` values) starts among the solved values.
    pub solved: usize,
}

impl JacobianBlock {
    /// The velocity coordinates of the block.
    #[inline]
    pub fn columns(&self) -> Range<usize> {
        self.start..self.start + self.width
    }

    /// Its values within the Jacobian's values.
    #[inline]
    pub fn values(&self) -> Range<usize> {
        self.value..self.value + self.width
    }
}

/// Where a marker's block sits: its body, the body's velocity coordinates, and
/// the ones the marker moves with.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MarkerColumns {
    /// The body (index into `Model::bodies`).
    pub body: usize,
    /// All velocity coordinates of the body.
    pub body_columns: Range<usize>,
    /// The velocity coordinates of the marker's block (within `body_columns`).
    pub columns: Range<usize>,
}

/// The blocks of every row, fixed at compile time.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct JacobianPattern {
    blocks: Vec<JacobianBlock>,
    /// The blocks of row `r` are `blocks[row_blocks[r]..row_blocks[r + 1]]`.
    row_blocks: Vec<usize>,
    /// The values of each row's block for the first and second marker (empty on the ground),
    /// what a constraint writes at every linearisation.
    slot_values: Vec<[Range<usize>; 2]>,
    /// The row of every block.
    block_rows: Vec<usize>,
    n_values: usize,
    n_solved: usize,
    /// Whether some block is not three wide (a marker on a beam or a modal body).
    mixed_widths: bool,
}

impl JacobianPattern {
    /// Appends `rows` rows, each with a block for the first and the second
    /// marker (`None` for a marker on the ground).
    pub fn push_rows(&mut self, rows: usize, markers: [Option<MarkerColumns>; 2]) {
        if self.row_blocks.is_empty() {
            self.row_blocks.push(0);
        }
        for _ in 0..rows {
            let mut values = [0..0, 0..0];
            for (slot, marker) in markers.iter().enumerate() {
                let Some(m) = marker else { continue };
                let width = m.columns.len();
                values[slot] = self.n_values..self.n_values + width;
                self.blocks.push(JacobianBlock {
                    body: m.body,
                    start: m.columns.start,
                    width,
                    offset_in_body: m.columns.start - m.body_columns.start,
                    value: self.n_values,
                    solved: self.n_solved,
                });
                self.block_rows.push(self.slot_values.len());
                self.n_values += width;
                self.mixed_widths |= width != 3;
                self.n_solved += m.body_columns.len();
            }
            self.slot_values.push(values);
            self.row_blocks.push(self.blocks.len());
        }
    }

    /// Number of rows.
    pub fn n_rows(&self) -> usize {
        self.slot_values.len()
    }

    /// Number of Jacobian values (the length of the values array).
    pub fn n_values(&self) -> usize {
        self.n_values
    }

    /// Number of solved values (`M_b^-1 J_b^T` of every block).
    pub fn n_solved(&self) -> usize {
        self.n_solved
    }

    /// Every block, rows in order.
    pub fn blocks(&self) -> &[JacobianBlock] {
        &self.blocks
    }

    /// The blocks of the first `rows` rows.
    pub fn blocks_of_rows(&self, rows: usize) -> &[JacobianBlock] {
        &self.blocks[..self.row_blocks.get(rows).copied().unwrap_or(0)]
    }

    /// The blocks of row `r`.
    #[inline]
    pub fn row(&self, r: usize) -> &[JacobianBlock] {
        &self.blocks[self.row_blocks[r]..self.row_blocks[r + 1]]
    }

    /// Index (into [`Self::blocks`]) of the blocks of row `r`.
    pub fn row_block_indices(&self, r: usize) -> Range<usize> {
        self.row_blocks[r]..self.row_blocks[r + 1]
    }

    /// The values of the block of row `r` for the constraint's marker `slot`
    /// (0 first, 1 second); empty for a marker on the ground.
    #[inline(always)]
    pub fn slot_values(&self, r: usize, slot: usize) -> Range<usize> {
        self.slot_values[r][slot].clone()
    }

    /// `out[r] = (Phi_q v)_r` for the first `rows` rows.
    pub fn times(&self, rows: usize, values: &[f64], v: &[f64], out: &mut [f64]) {
        let out = &mut out[..rows];
        out.fill(0.0);
        let blocks = self.blocks_of_rows(rows).iter().zip(&self.block_rows);
        if !self.mixed_widths {
            // (every block three wide, the values of one after the other's)
            for ((b, &r), a) in blocks.zip(values.chunks_exact(3)) {
                out[r] += block_dot(a, &v[b.start..b.start + 3]);
            }
            return;
        }
        for (b, &r) in blocks {
            out[r] += block_dot(&values[b.values()], &v[b.columns()]);
        }
    }

    /// `out = Phi_q^T w` over the first `rows` rows.
    pub fn transpose_times(&self, rows: usize, values: &[f64], w: &[f64], out: &mut [f64]) {
        out.fill(0.0);
        let blocks = self.blocks_of_rows(rows).iter().zip(&self.block_rows);
        if !self.mixed_widths {
            for ((b, &r), a) in blocks.zip(values.chunks_exact(3)) {
                block_add_scaled(&mut out[b.start..b.start + 3], a, w[r]);
            }
            return;
        }
        for (b, &r) in blocks {
            block_add_scaled(&mut out[b.columns()], &values[b.values()], w[r]);
        }
    }

    /// Entry `(r, k)` of `Phi_q` (velocity coordinate `k`).
    pub fn entry(&self, values: &[f64], r: usize, k: usize) -> f64 {
        self.row(r).iter().filter(|b| b.columns().contains(&k)).map(|b| values[b.value + k - b.start]).sum()
    }
}

/// `a . b`.
#[inline]
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// `a . b` for a block and its columns, unrolled for the planar rigid body's three.
#[inline(always)]
fn block_dot(a: &[f64], b: &[f64]) -> f64 {
    if let (Ok(a), Ok(b)) = (<&[f64; 3]>::try_from(a), <&[f64; 3]>::try_from(b)) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
    dot(a, b)
}

/// `out += a s` for a block and its columns, unrolled for the planar rigid body's three.
#[inline(always)]
fn block_add_scaled(out: &mut [f64], a: &[f64], s: f64) {
    if let (Ok(out), Ok(a)) = (<&mut [f64; 3]>::try_from(&mut *out), <&[f64; 3]>::try_from(a)) {
        out[0] += a[0] * s;
        out[1] += a[1] * s;
        out[2] += a[2] * s;
        return;
    }
    for (o, j) in out.iter_mut().zip(a) {
        *o += j * s;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rows over blocks of unequal width, one inside a wider body: the products and
    /// entries against the same Jacobian written densely.
    #[test]
    fn products_and_entries_of_blocks_of_any_width_match_the_dense_jacobian() {
        // body 0: coordinates 0..3; body 1: 3..10, its markers moving with 4..7 (width 3) or 3..10 (all 7)
        let rigid = MarkerColumns { body: 0, body_columns: 0..3, columns: 0..3 };
        let inner = MarkerColumns { body: 1, body_columns: 3..10, columns: 4..7 };
        let whole = MarkerColumns { body: 1, body_columns: 3..10, columns: 3..10 };
        let mut pattern = JacobianPattern::default();
        pattern.push_rows(2, [Some(rigid.clone()), Some(inner)]);
        pattern.push_rows(1, [None, Some(whole)]);
        pattern.push_rows(1, [Some(rigid), None]);
        assert_eq!(pattern.n_rows(), 4);
        assert_eq!(pattern.n_values(), 2 * (3 + 3) + 7 + 3);
        assert_eq!(pattern.n_solved(), 2 * (3 + 7) + 7 + 3);
        assert!(pattern.mixed_widths, "the products take their loop for blocks of any width");
        // each row's blocks, first marker before second, their values one after the other (none on the ground)
        assert_eq!([pattern.slot_values(0, 0), pattern.slot_values(0, 1)], [0..3, 3..6]);
        assert_eq!([pattern.slot_values(1, 0), pattern.slot_values(1, 1)], [6..9, 9..12]);
        assert_eq!([pattern.slot_values(2, 0), pattern.slot_values(2, 1)], [0..0, 12..19]);
        assert_eq!([pattern.slot_values(3, 0), pattern.slot_values(3, 1)], [19..22, 0..0]);
        let wide = pattern.row(2)[0];
        assert_eq!((wide.start, wide.width, wide.offset_in_body, wide.values()), (3, 7, 0, 12..19));
        let inner = pattern.row(0)[1];
        assert_eq!((inner.start, inner.width, inner.offset_in_body, inner.values()), (4, 3, 1, 3..6));
        let dense = products_match_dense(&pattern, 10);
        assert_eq!(dense[0][3], 0.0, "the inner marker's block leaves the body's first coordinate out");
    }

    /// Rows over three-wide blocks only (planar rigid bodies, the products' own loop):
    /// the products against the dense Jacobian.
    #[test]
    fn products_of_three_wide_blocks_match_the_dense_jacobian() {
        let body = |k: usize| Some(MarkerColumns { body: k, body_columns: 3 * k..3 * k + 3, columns: 3 * k..3 * k + 3 });
        let mut pattern = JacobianPattern::default();
        pattern.push_rows(2, [body(0), body(2)]);
        pattern.push_rows(1, [None, body(1)]);
        pattern.push_rows(2, [body(2), body(1)]);
        assert!(!pattern.mixed_widths);
        products_match_dense(&pattern, 9);
    }

    /// Checks `Phi_q v`, `Phi_q^T w` and the entries of `pattern` (over `columns`
    /// velocity coordinates) against its dense Jacobian, written from the blocks'
    /// definitions for made-up values; returns that Jacobian.
    fn products_match_dense(pattern: &JacobianPattern, columns: usize) -> Vec<Vec<f64>> {
        let rows = pattern.n_rows();
        let values: Vec<f64> = (0..pattern.n_values()).map(|k| 0.5 + (k as f64 * 0.37).sin()).collect();
        let mut dense = vec![vec![0.0; columns]; rows];
        for (r, dense_row) in dense.iter_mut().enumerate() {
            for block in pattern.row(r) {
                for (i, c) in block.columns().enumerate() {
                    dense_row[c] += values[block.value + i];
                }
            }
        }
        let v: Vec<f64> = (0..columns).map(|k| 1.0 - 0.3 * k as f64).collect();
        let w: Vec<f64> = (0..rows).map(|r| 0.7 - 0.45 * r as f64).collect();
        let mut jv = vec![0.0; rows];
        pattern.times(rows, &values, &v, &mut jv);
        let mut jtw = vec![0.0; columns];
        pattern.transpose_times(rows, &values, &w, &mut jtw);
        for r in 0..rows {
            let expected: f64 = (0..columns).map(|c| dense[r][c] * v[c]).sum();
            assert!((jv[r] - expected).abs() < 1e-14, "row {r}");
            for c in 0..columns {
                assert_eq!(pattern.entry(&values, r, c), dense[r][c]);
            }
        }
        for c in 0..columns {
            let expected: f64 = (0..rows).map(|r| dense[r][c] * w[r]).sum();
            assert!((jtw[c] - expected).abs() < 1e-14, "column {c}");
        }
        dense
    }
}
