//! Planar bodies in the spatial vocabulary, as Drake keeps its planar joint in
//! a 3D plant: a planar body moves in the plane `z = 0` and turns about `z`,
//! so its spatial answers follow from its planar ones.
//!
//! - A site's spatial frame is its planar frame embedded
//!   ([`SpatialFrame::from_planar`](crate::kinematics::spatial::SpatialFrame::from_planar)).
//! - The marker point `P = (x, y, h)` moves as its projection `(x, y)` does (its
//!   height `h` above the plane does not move: the body turns about `z`), so the
//!   point Jacobian along `a` is the planar one along `(a.x, a.y)`; the point's
//!   acceleration is the planar one with `z = 0`.
//! - The frame's angular velocity is `(0, 0, omega)`: the angular Jacobian along
//!   `a` is `a.z` times the planar angle Jacobian, the angular acceleration
//!   `(0, 0, alpha)`.
//! - A wrench's generalised force is, by virtual power `f . v_P + m . omega`,
//!   that of the planar force `(f.x, f.y)` at `(p.x, p.y)` and of the moment
//!   `m.z`: the plane carries the rest.

/// The spatial methods of [`super::BodyModel`] for a planar kind, from its planar
/// methods (see the module's documentation); expands inside the kind's `impl BodyModel`.
macro_rules! embedded_in_the_plane {
    () => {
        #[inline]
        fn spatial_site_frame(&self, _site: &Site, _q: &[f64], _v: &[f64], planar: &Frame) -> SpatialFrame {
            SpatialFrame::from_planar(planar)
        }

        #[inline]
        fn add_spatial_point_jacobian(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, along: Vec3, out: &mut [f64]) {
            self.add_marker_jacobian(at.body, at.site, &marker.planar(), Vec2::new(along.x, along.y), out);
        }

        #[inline]
        fn add_spatial_angular_jacobian(&self, _at: MarkerFrames<'_>, marker: &SpatialMarker, along: Vec3, out: &mut [f64]) {
            self.add_marker_angle_jacobian(&marker.planar(), along.z, out);
        }

        #[inline]
        fn spatial_bias_acceleration(&self, at: MarkerFrames<'_>, marker: &SpatialMarker) -> (Vec3, Vec3) {
            let planar = marker.planar();
            let point = self.marker_bias_acceleration(at.body, at.site, &planar);
            let angular = self.marker_bias_angular_acceleration(at.site, &planar);
            (Vec3::new(point.x, point.y, 0.0), Vec3::new(0.0, 0.0, angular))
        }

        #[inline]
        fn spatial_marker_acceleration(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, a: &[f64]) -> (Vec3, Vec3) {
            let planar = marker.planar();
            let point = self.marker_acceleration(at.body, at.site, a, &planar);
            let angular = self.marker_angular_acceleration(at.site, a, &planar);
            (Vec3::new(point.x, point.y, 0.0), Vec3::new(0.0, 0.0, angular))
        }

        #[inline]
        fn add_wrench(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, point: Vec3, wrench: &Wrench, out: &mut [f64]) {
            let planar = marker.planar();
            let (p, f) = (Vec2::new(point.x, point.y), Vec2::new(wrench.force.x, wrench.force.y));
            self.add_point_force(at.body, at.site, &planar, p, f, out);
            self.add_moment(&planar, wrench.moment.z, out);
        }
    };
}

pub(super) use embedded_in_the_plane;
