//! Prescribed loads in space: a force at a marker's point and a torque on a
//! marker's body, each as three functions of time, in the global frame or in
//! the marker's frame (turning with the body).

use crate::element::{ElementFault, ElementMemory, ElementModel, ElementWork, ForceOutput, OutputInfo};
use crate::dynamics::GeneralisedForces;
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::{Marker, SpatialMarker};
use crate::kinematics::spatial::Vec3;
use crate::kinematics::wrench::Wrench;
use crate::motion::TimeFunction;

/// Which frame a prescribed load's components are given in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoadFrame {
    /// The global frame.
    Global,
    /// The marker's frame, turning with its body.
    Body,
}

/// What a prescribed load is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoadKind {
    /// A force at the marker's point [N].
    Force,
    /// A torque on the marker's body [N m].
    Torque,
}

/// A force or torque of prescribed components.
#[derive(Clone, Debug, PartialEq)]
pub struct PrescribedLoad {
    /// Where it acts.
    pub marker: SpatialMarker,
    /// Force or torque.
    pub kind: LoadKind,
    /// The frame of its components.
    pub frame: LoadFrame,
    /// Components x, y, z [N or N m].
    pub components: [TimeFunction; 3],
}

impl PrescribedLoad {
    /// Outputs of a force (global components).
    pub const FORCE_CHANNELS: [OutputInfo; 3] = [("fx", "N", "applied force, global x"), ("fy", "N", "applied force, global y"), ("fz", "N", "applied force, global z")];
    /// Outputs of a torque (global components).
    pub const TORQUE_CHANNELS: [OutputInfo; 3] = [("mx", "N m", "applied torque, global x"), ("my", "N m", "applied torque, global y"), ("mz", "N m", "applied torque, global z")];

    /// Output channels.
    pub fn load_channels(&self) -> &'static [OutputInfo] {
        match self.kind {
            LoadKind::Force => &Self::FORCE_CHANNELS,
            LoadKind::Torque => &Self::TORQUE_CHANNELS,
        }
    }

    /// Applies the load; outputs its global components.
    pub fn load(&self, frames: &Frames<'_>, t: f64, forces: &mut GeneralisedForces) -> ForceOutput {
        let [x, y, z] = &self.components;
        let local = Vec3::new(x.sample(t).value, y.sample(t).value, z.sample(t).value);
        let global = match self.frame {
            LoadFrame::Global => local,
            LoadFrame::Body => frames.spatial[self.marker.frame].rotation * (self.marker.axes * local),
        };
        let wrench = match self.kind {
            LoadKind::Force => Wrench { force: global, moment: Vec3::zeros() },
            LoadKind::Torque => Wrench { force: Vec3::zeros(), moment: global },
        };
        forces.add_wrench(&self.marker, frames.point(&self.marker), &wrench);
        ForceOutput::new(global.as_slice(), 0.0)
    }
}

impl ElementModel for PrescribedLoad {
    fn channels(&self) -> &'static [OutputInfo] {
        self.load_channels()
    }

    fn markers(&self) -> Vec<Marker> {
        vec![self.marker.planar()]
    }

    #[inline]
    fn apply(&self, frames: &Frames<'_>, t: f64, _states: (&[f64], &mut [f64]), _memory: &[ElementMemory], work: &mut ElementWork, _detailed: bool, forces: &mut GeneralisedForces) -> Result<(), ElementFault> {
        *work.outputs_mut() = self.load(frames, t, forces);
        Ok(())
    }
}
