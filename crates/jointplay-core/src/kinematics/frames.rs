//! The frames of one evaluation, as elements read them: the planar frames
//! (the fast path of planar bodies and planar elements) and the spatial
//! frames (every body, planar ones embedded), indexed alike: the ground, the
//! bodies, then the section frames of flexible bodies.

use super::marker::{MarkerFrames, SpatialMarker};
use super::planar::Frame;
use super::spatial::{SpatialFrame, Vec3};

/// Planar and spatial frames of one evaluation.
#[derive(Clone, Copy)]
pub struct Frames<'a> {
    /// Planar frames (a spatial body's is its projection on the xy plane).
    pub planar: &'a [Frame],
    /// Spatial frames (empty in a model without spatial elements).
    pub spatial: &'a [SpatialFrame],
}

impl<'a> Frames<'a> {
    /// The frames a body kind needs to move `marker`.
    #[inline]
    pub fn of(&self, marker: &SpatialMarker) -> MarkerFrames<'a> {
        let (body, site) = (marker.body.0, marker.frame);
        MarkerFrames { body: &self.planar[body], site: &self.planar[site], body3: &self.spatial[body], site3: &self.spatial[site] }
    }

    /// Global position of `marker`'s point [m].
    #[inline]
    pub fn point(&self, marker: &SpatialMarker) -> Vec3 {
        self.spatial[marker.frame].point(marker.local)
    }

    /// Global velocity of `marker`'s point [m/s].
    #[inline]
    pub fn point_velocity(&self, marker: &SpatialMarker) -> Vec3 {
        self.spatial[marker.frame].point_velocity(marker.local)
    }

    /// Axis `k` (0 x, 1 y, 2 z) of `marker`'s frame in global coordinates [-].
    #[inline]
    pub fn axis(&self, marker: &SpatialMarker, k: usize) -> Vec3 {
        self.spatial[marker.frame].rotation * marker.axes.column(k)
    }

    /// Global angular velocity of `marker`'s frame [rad/s].
    #[inline]
    pub fn angular_velocity(&self, marker: &SpatialMarker) -> Vec3 {
        self.spatial[marker.frame].angular_velocity
    }

    /// `marker`'s whole frame (pose and velocity) in space.
    #[inline]
    pub fn marker_frame(&self, marker: &SpatialMarker) -> SpatialFrame {
        self.spatial[marker.frame].compose(marker.local, &marker.axes)
    }
}
