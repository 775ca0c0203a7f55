//! Where every body's coordinates and every element's states sit in the
//! state vector `y = [q, v, z]`: position coordinates `q`, velocity
//! coordinates `v`, continuous element states `z` (as MuJoCo's `nq`/`nv`/`na`
//! and Drake's `q`/`v`/`z`). Addresses are assigned once at compile time;
//! nothing else computes an index from a body number.

use std::ops::Range;

use crate::kinematics::marker::BodyIndex;
use crate::body::{BodyKind, BodyModel};

/// Addresses of one body's coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BodyAddress {
    /// First position coordinate, in `q`.
    pub q: usize,
    /// Number of position coordinates.
    pub nq: usize,
    /// First velocity coordinate, in `v` (and in every velocity-length vector:
    /// generalised forces, accelerations, Jacobian columns).
    pub v: usize,
    /// Number of velocity coordinates.
    pub nv: usize,
}

impl BodyAddress {
    /// The body's position coordinates within `q`.
    #[inline]
    pub fn q_range(&self) -> Range<usize> {
        self.q..self.q + self.nq
    }

    /// The body's velocity coordinates within `v`.
    #[inline]
    pub fn v_range(&self) -> Range<usize> {
        self.v..self.v + self.nv
    }
}

/// The layout of `y = [q, v, z]`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StateLayout {
    /// Addresses of body `k` (its [`BodyIndex`] is `k + 1`; the ground has none).
    pub bodies: Vec<BodyAddress>,
    /// States of element `k`, within `z`.
    pub element_states: Vec<Range<usize>>,
    /// Number of position coordinates.
    pub nq: usize,
    /// Number of velocity coordinates.
    pub nv: usize,
    /// Number of continuous element states.
    pub nz: usize,
    /// Whether `q_dot = v` for every body (so `q` and `v` have the same layout).
    pub identity_position_rates: bool,
    /// Whether some body exerts forces on its own coordinates (inertial or internal).
    pub has_body_forces: bool,
}

impl StateLayout {
    /// Appends a body of kind `kind`.
    pub fn push_body(&mut self, kind: &BodyKind) {
        let (nq, nv) = (kind.nq(), kind.nv());
        if self.bodies.is_empty() {
            self.identity_position_rates = true;
        }
        self.identity_position_rates &= kind.has_identity_position_rates() && self.nq == self.nv;
        self.has_body_forces |= kind.has_body_forces();
        self.bodies.push(BodyAddress { q: self.nq, nq, v: self.nv, nv });
        self.nq += nq;
        self.nv += nv;
    }

    /// Appends the `nz` states of the next element.
    pub fn push_element_states(&mut self, nz: usize) {
        self.element_states.push(self.nz..self.nz + nz);
        self.nz += nz;
    }

    /// Length of `y`.
    #[inline]
    pub fn len(&self) -> usize {
        self.nq + self.nv + self.nz
    }

    /// True when there is no state at all.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Addresses of a body, `None` for the ground.
    #[inline]
    pub fn body(&self, body: BodyIndex) -> Option<&BodyAddress> {
        if body.is_ground() { None } else { self.bodies.get(body.0 - 1) }
    }

    /// `(q, v, z)` of a state vector.
    #[inline]
    pub fn split<'y>(&self, y: &'y [f64]) -> (&'y [f64], &'y [f64], &'y [f64]) {
        let (q, rest) = y.split_at(self.nq);
        let (v, z) = rest.split_at(self.nv);
        (q, v, z)
    }

    /// Mutable [`Self::split`].
    #[inline]
    pub fn split_mut<'y>(&self, y: &'y mut [f64]) -> (&'y mut [f64], &'y mut [f64], &'y mut [f64]) {
        let (q, rest) = y.split_at_mut(self.nq);
        let (v, z) = rest.split_at_mut(self.nv);
        (q, v, z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::PlanarRigidBody;

    fn planar() -> BodyKind {
        BodyKind::PlanarRigid(PlanarRigidBody::new(1.0, 1.0))
    }

    #[test]
    fn planar_bodies_have_q_dot_equal_to_v_and_no_body_forces() {
        let mut layout = StateLayout::default();
        layout.push_body(&planar());
        layout.push_body(&planar());
        assert!(layout.identity_position_rates && !layout.has_body_forces);
        assert_eq!(layout.body(BodyIndex(2)), Some(&BodyAddress { q: 3, nq: 3, v: 3, nv: 3 }));
    }

    #[test]
    fn addresses_follow_the_declared_sizes() {
        // (a second body of 7 and 6 coordinates, as a spatial body will have: its
        // addresses are what the layout must get right, the kinematics are not used)
        let mut layout = StateLayout::default();
        layout.push_body(&planar());
        layout.bodies.push(BodyAddress { q: layout.nq, nq: 7, v: layout.nv, nv: 6 });
        (layout.nq, layout.nv) = (layout.nq + 7, layout.nv + 6);
        layout.push_element_states(0);
        layout.push_element_states(3);
        assert_eq!(layout.body(BodyIndex(2)), Some(&BodyAddress { q: 3, nq: 7, v: 3, nv: 6 }));
        assert_eq!(layout.body(BodyIndex::GROUND), None);
        assert_eq!((layout.nq, layout.nv, layout.nz, layout.len()), (10, 9, 3, 22));
        assert_eq!(layout.element_states, vec![0..0, 0..3]);
        let y: Vec<f64> = (0..22).map(f64::from).collect();
        let (q, v, z) = layout.split(&y);
        assert_eq!((q.len(), v[0], z), (10, 10.0, &[19.0, 20.0, 21.0][..]));
    }
}
