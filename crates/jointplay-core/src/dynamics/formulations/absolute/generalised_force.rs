//! The generalised applied force `Q` being assembled, seen by elements:
//! they add point forces and moments at markers and never index coordinates.

use crate::body::BodyModel;
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::{Marker, SpatialMarker};
use crate::kinematics::planar::{Frame, Vec2};
use crate::kinematics::spatial::Vec3;
use crate::kinematics::wrench::Wrench;
use crate::dynamics::model::layout::StateLayout;
use crate::dynamics::model::mechanism::Body;

/// `Q` over the velocity coordinates, with the bodies that say where a force goes.
pub struct GeneralisedForces<'a> {
    /// Values in velocity-coordinate order [N, N m].
    values: &'a mut [f64],
    /// The bodies, body `k` has [`BodyIndex`]`(k + 1)`.
    bodies: &'a [Body],
    /// Their addresses.
    layout: &'a StateLayout,
    /// The frames of the evaluation (a body's reference frame is `frames.planar[body.0]`).
    frames: Frames<'a>,
}

impl<'a> GeneralisedForces<'a> {
    /// `values` (velocity length) for the bodies of `layout`, whose frames are `frames`.
    pub fn new(values: &'a mut [f64], bodies: &'a [Body], layout: &'a StateLayout, frames: Frames<'a>) -> Self {
        Self { values, bodies, layout, frames }
    }

    /// Adds the force `f` [N] at the global point `p` [m], a point moving with
    /// `marker` (whose frame is `frame`; nothing on the ground).
    #[inline]
    pub fn add_point_force(&mut self, marker: &Marker, frame: &Frame, p: Vec2, f: Vec2) {
        if let Some(address) = self.layout.body(marker.body) {
            let body = &self.frames.planar[marker.body.0];
            crate::body::planar_first!(&self.bodies[marker.body.0 - 1].kind, add_point_force(body, frame, marker, p, f, &mut self.values[address.v_range()]));
        }
    }

    /// Adds the force `wrench.force` [N] at the global point `point` [m] (a
    /// point moving with `marker`) and the moment `wrench.moment` [N m] (global)
    /// on `marker`'s body (nothing on the ground).
    #[inline]
    pub fn add_wrench(&mut self, marker: &SpatialMarker, point: Vec3, wrench: &Wrench) {
        if let Some(address) = self.layout.body(marker.body) {
            let at = self.frames.of(marker);
            self.bodies[marker.body.0 - 1].kind.add_wrench(at, marker, point, wrench, &mut self.values[address.v_range()]);
        }
    }

    /// Adds the moment `m` [N m] (counter-clockwise) on `marker`'s frame (nothing on the ground).
    #[inline]
    pub fn add_moment(&mut self, marker: &Marker, m: f64) {
        if let Some(address) = self.layout.body(marker.body) {
            crate::body::planar_first!(&self.bodies[marker.body.0 - 1].kind, add_moment(marker, m, &mut self.values[address.v_range()]));
        }
    }

    /// Adds uniform gravity `g` [m/s^2] on every body at the positions `q`.
    pub fn add_gravity(&mut self, g: Vec3, q: &[f64]) {
        for (body, address) in self.bodies.iter().zip(&self.layout.bodies) {
            body.kind.add_gravity(g, &q[address.q_range()], &mut self.values[address.v_range()]);
        }
    }
}
