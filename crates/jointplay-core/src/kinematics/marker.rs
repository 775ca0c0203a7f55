//! Markers: the points with a frame on a body that joints, force elements,
//! sensors and channels attach to. They never index coordinates: a body kind
//! turns a marker into a pose, a velocity and a Jacobian
//! ([`crate::body::BodyModel`]).

use super::planar::{Frame, Vec2};
use super::spatial::{Mat3, SpatialFrame, Vec3};

/// Index of a body in a model; 0 is the ground.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BodyIndex(pub usize);

impl BodyIndex {
    /// The fixed frame.
    pub const GROUND: BodyIndex = BodyIndex(0);

    /// True for the ground.
    pub fn is_ground(self) -> bool {
        self.0 == 0
    }
}

/// Where on its body a marker's frame is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Site {
    /// The body's reference frame (a rigid body's frame at its centre of mass;
    /// a beam's first node).
    Reference,
    /// A section of a beam, interpolated from the nodes of one element.
    Section(SectionSite),
    /// A node of a modal body's structure.
    ModalNode(ModalNodeSite),
}

/// A section of a beam: an element and a point in it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SectionSite {
    /// The element (counted from the beam's first end).
    pub element: u32,
    /// The element's first velocity coordinate, counted from the body's first.
    pub first: u32,
    /// Number of nodes of the element.
    pub nodes: u8,
    /// Natural coordinate `xi` in [-1, 1] along the element.
    pub xi: f64,
    /// The shape functions' values at `xi` (unused entries zero) [-].
    pub weights: [f64; 3],
}

/// Where on a modal body a marker's frame is: a node of its structure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ModalNodeSite {
    /// The node (counted in the structure's order).
    pub node: u32,
}

/// A planar marker: a point of a body (planar elements need no axes: the
/// marker's frame is its site's).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Marker {
    /// The body it belongs to.
    pub body: BodyIndex,
    /// Index of its frame among the frames of an evaluation: the body's own
    /// (`body.0`) at the body's reference site, else a section frame of a
    /// flexible body (after the bodies' frames, see `Model::sections`).
    pub frame: usize,
    /// Where its frame is on the body.
    pub site: Site,
    /// Coordinates of the point in that frame [m].
    pub local: Vec2,
}

impl Marker {
    /// The point `local` [m] of `body`'s reference frame.
    pub const fn at(body: BodyIndex, local: Vec2) -> Self {
        Self { body, frame: body.0, site: Site::Reference, local }
    }

    /// The origin of `body`'s reference frame.
    pub const fn reference(body: BodyIndex) -> Self {
        Self::at(body, Vec2::new(0.0, 0.0))
    }
}

/// A marker with a frame: a point of a body and axes there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpatialMarker {
    /// The body it belongs to.
    pub body: BodyIndex,
    /// Index of its site's frame among the frames of an evaluation (as [`Marker::frame`]).
    pub frame: usize,
    /// Where its site's frame is on the body.
    pub site: Site,
    /// Coordinates of the point in the site's frame [m].
    pub local: Vec3,
    /// The marker's axes in the site's frame (columns x, y, z) [-].
    pub axes: Mat3,
}

impl SpatialMarker {
    /// The point `local` [m] of `body`'s reference frame with axes `axes` there.
    pub fn at(body: BodyIndex, local: Vec3, axes: Mat3) -> Self {
        Self { body, frame: body.0, site: Site::Reference, local, axes }
    }

    /// The planar marker at the same point, projected on the plane (`local.xy`).
    #[inline]
    pub fn planar(&self) -> Marker {
        Marker { body: self.body, frame: self.frame, site: self.site, local: Vec2::new(self.local.x, self.local.y) }
    }

    /// The marker's own frame (pose, velocity) on its site's frame `site`.
    #[inline]
    pub fn frame_on(&self, site: &SpatialFrame) -> SpatialFrame {
        site.compose(self.local, &self.axes)
    }
}

/// The frames of one marker at an evaluation: planar (planar bodies' fast path) and spatial.
#[derive(Clone, Copy, Debug)]
pub struct MarkerFrames<'a> {
    /// The body's reference frame, planar.
    pub body: &'a Frame,
    /// The marker's site frame, planar.
    pub site: &'a Frame,
    /// The body's reference frame in space.
    pub body3: &'a SpatialFrame,
    /// The marker's site frame in space.
    pub site3: &'a SpatialFrame,
}
