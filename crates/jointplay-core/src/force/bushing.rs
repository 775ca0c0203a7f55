//! A bushing: six linear springs and dampers between two marker frames, in
//! the first marker's frame. The relative displacement is `R_i^T (P_j - P_i)`,
//! the relative rotation the rotation vector of `R_i^T R_j`; the force
//! `-(K d + C d_dot)` and moment `-(K_r theta + C_r theta_dot)` act on the
//! second marker (about its point) and their opposites on the first, at the
//! same point. For small rotations the moment is conservative; for larger
//! ones the rotation vector is a finite measure of the twist (as in Adams'
//! and Exudyn's rigid-body spring-dampers, `docs/theory/spatial-force-elements.md`).

use crate::element::{ElementFault, ElementMemory, ElementModel, ElementWork, ForceOutput, OutputInfo};
use crate::dynamics::GeneralisedForces;
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::{Marker, SpatialMarker};
use crate::kinematics::quaternion;
use crate::kinematics::spatial::Vec3;
use crate::kinematics::wrench::Wrench;

/// Six-component linear spring-damper between two marker frames.
#[derive(Clone, Debug, PartialEq)]
pub struct Bushing {
    /// Marker on the first body (its axes are the bushing's).
    pub first: SpatialMarker,
    /// Marker on the second body.
    pub second: SpatialMarker,
    /// Translational stiffnesses along the first marker's x, y, z [N/m].
    pub stiffness: Vec3,
    /// Translational damping [N s/m].
    pub damping: Vec3,
    /// Rotational stiffnesses about x, y, z [N m/rad].
    pub rotational_stiffness: Vec3,
    /// Rotational damping [N m s/rad].
    pub rotational_damping: Vec3,
}

impl Bushing {
    /// Outputs (in the first marker's frame).
    pub const CHANNELS: [OutputInfo; 6] = [
        ("fx", "N", "force on the second marker, first marker's x"),
        ("fy", "N", "force on the second marker, first marker's y"),
        ("fz", "N", "force on the second marker, first marker's z"),
        ("mx", "N m", "moment on the second marker, first marker's x"),
        ("my", "N m", "moment on the second marker, first marker's y"),
        ("mz", "N m", "moment on the second marker, first marker's z"),
    ];

    /// Applies the wrench to both markers; outputs it in the first marker's frame.
    pub fn load(&self, frames: &Frames<'_>, forces: &mut GeneralisedForces) -> ForceOutput {
        let (fi, fj) = (frames.marker_frame(&self.first), frames.marker_frame(&self.second));
        let to_first = fi.rotation.transpose();
        // relative motion of the second marker seen in the first marker's (turning) frame
        let d = fj.position - fi.position;
        let displacement = to_first * d;
        let rate = to_first * (fj.velocity - fi.velocity - fi.angular_velocity.cross(&d));
        let relative = to_first * fj.rotation;
        let rotation = quaternion::to_rotation_vector(&quaternion::from_rotation_matrix(&relative));
        let angular_rate = to_first * (fj.angular_velocity - fi.angular_velocity);
        let force = -(self.stiffness.component_mul(&displacement) + self.damping.component_mul(&rate));
        let moment = -(self.rotational_stiffness.component_mul(&rotation) + self.rotational_damping.component_mul(&angular_rate));
        let on_second = Wrench { force, moment }.rotated(&fi.rotation);
        let on_first = Wrench { force: -on_second.force, moment: -on_second.moment };
        forces.add_wrench(&self.second, fj.position, &on_second);
        forces.add_wrench(&self.first, fj.position, &on_first);
        let energy = 0.5 * (displacement.dot(&self.stiffness.component_mul(&displacement)) + rotation.dot(&self.rotational_stiffness.component_mul(&rotation)));
        ForceOutput::new(&[force.x, force.y, force.z, moment.x, moment.y, moment.z], energy)
    }
}

impl ElementModel for Bushing {
    fn channels(&self) -> &'static [OutputInfo] {
        &Self::CHANNELS
    }

    fn markers(&self) -> Vec<Marker> {
        vec![self.first.planar(), self.second.planar()]
    }

    #[inline]
    fn apply(&self, frames: &Frames<'_>, _t: f64, _states: (&[f64], &mut [f64]), _memory: &[ElementMemory], work: &mut ElementWork, _detailed: bool, forces: &mut GeneralisedForces) -> Result<(), ElementFault> {
        *work.outputs_mut() = self.load(frames, forces);
        Ok(())
    }
}
