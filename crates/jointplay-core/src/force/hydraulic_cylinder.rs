//! Hydraulic cylinder as a force element between two markers, acting along
//! their line: the cylinder law of `crate::hydraulic` fed with the stroke
//! `s = |p2 - p1| - L0` and its rate, its chamber pressures (and seal bristle
//! deflection) integrated as element states. Theory:
//! `docs/theory/hydraulic-cylinder.md`.

use crate::element::{ElementFault, ElementMemory, ElementModel, ElementWork, ForceOutput, OutputInfo};
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::{Marker, SpatialMarker};
use crate::kinematics::spatial::Vec3;
use crate::kinematics::wrench::Wrench;
use crate::dynamics::GeneralisedForces;
use crate::hydraulic::{CylinderFault, HydraulicCylinder};
use crate::motion::TimeFunction;

/// A double-acting cylinder: barrel on the first marker, rod eye on the second.
#[derive(Clone, Debug, PartialEq)]
pub struct CylinderActuator {
    /// Attachment of the barrel (cap end).
    pub first: Marker,
    /// Attachment of the rod eye.
    pub second: Marker,
    /// The cylinder law.
    pub cylinder: HydraulicCylinder,
    /// Distance between the attachments at stroke 0 (fully retracted) [m].
    pub retracted_length: f64,
    /// Stroke at the start [m] (the reference of the pressure tolerance scales).
    pub initial_stroke: f64,
    /// Flow into the cap chamber [m^3/s], if any (a valve's output later).
    pub cap_inflow: Option<TimeFunction>,
    /// Flow into the rod chamber [m^3/s], if any.
    pub rod_inflow: Option<TimeFunction>,
    /// The attachments as markers in space (a cylinder of a spatial model),
    /// read instead of `first` and `second`.
    pub spatial_attachments: Option<Box<[SpatialMarker; 2]>>,
}

/// The attachment line at one instant (in the plane z = 0 for a planar cylinder).
struct Line {
    /// Unit vector from the first attachment to the second [-].
    direction: Vec3,
    /// Attachment points [m].
    points: [Vec3; 2],
    /// Stroke s [m].
    stroke: f64,
    /// Stroke rate ds/dt [m/s].
    stroke_rate: f64,
}

impl CylinderActuator {
    /// Outputs, in the order of [`Self::CHANNELS`].
    pub const CHANNELS: [OutputInfo; 7] = [
        ("p_cap", "Pa", "cap-chamber gauge pressure"),
        ("p_rod", "Pa", "rod-chamber gauge pressure"),
        ("force", "N", "force pushing the attachments apart (pressure force minus seal friction)"),
        ("stroke", "m", "stroke (0 fully retracted)"),
        ("rate", "m/s", "stroke rate (positive extending)"),
        ("friction", "N", "seal friction resisting the stroke rate"),
        ("stick", "1", "1 while the seal sticks (|rate| below the stick velocity), else 0"),
    ];

    /// The attachment points and their velocities [m, m/s].
    fn attachments(&self, frames: &Frames<'_>) -> ([Vec3; 2], Vec3) {
        match self.spatial_attachments.as_deref() {
            Some([a, b]) => ([frames.point(a), frames.point(b)], frames.point_velocity(b) - frames.point_velocity(a)),
            None => {
                let (fi, fj) = (&frames.planar[self.first.frame], &frames.planar[self.second.frame]);
                let embed = |p: crate::kinematics::planar::Vec2| Vec3::new(p.x, p.y, 0.0);
                let relative = fj.point_velocity(self.second.local) - fi.point_velocity(self.first.local);
                ([embed(fi.point(self.first.local)), embed(fj.point(self.second.local))], embed(relative))
            }
        }
    }

    fn line(&self, frames: &Frames<'_>) -> Line {
        let (points, relative) = self.attachments(frames);
        let d = points[1] - points[0];
        let length = d.norm();
        // (coincident attachments: no direction; the compiler refuses a zero retracted length)
        let direction = if length > 0.0 { d / length } else { Vec3::zeros() };
        Line { direction, points, stroke: length - self.retracted_length, stroke_rate: direction.dot(&relative) }
    }

    /// Pushes the attachments apart with `push` [N] along the line.
    fn push_apart(&self, frames: &Frames<'_>, line: &Line, push: Vec3, forces: &mut GeneralisedForces) {
        match self.spatial_attachments.as_deref() {
            Some([a, b]) => {
                let force = |f: Vec3| Wrench { force: f, moment: Vec3::zeros() };
                forces.add_wrench(b, line.points[1], &force(push));
                forces.add_wrench(a, line.points[0], &force(-push));
            }
            None => {
                let (p, f) = (line.points.map(|p| p.xy()), push.xy());
                forces.add_point_force(&self.second, &frames.planar[self.second.frame], p[1], f);
                forces.add_point_force(&self.first, &frames.planar[self.first.frame], p[0], -f);
            }
        }
    }

    /// Inflows (Q_cap, Q_rod) [m^3/s] at `t`.
    fn inflows(&self, t: f64) -> (f64, f64) {
        let flow = |f: &Option<TimeFunction>| f.as_ref().map_or(0.0, |f| f.sample(t).value);
        (flow(&self.cap_inflow), flow(&self.rod_inflow))
    }

    /// Applies the force along the line and writes the state rates into `z_rate`
    /// (same layout as `z`: p_cap, p_rod, bristle deflection).
    pub fn load(&self, frames: &Frames<'_>, t: f64, z: &[f64], z_rate: &mut [f64], forces: &mut GeneralisedForces) -> ForceOutput {
        let line = self.line(frames);
        let e = self.cylinder.evaluate_unchecked(line.stroke, line.stroke_rate, z, self.inflows(t));
        z_rate.copy_from_slice(e.state_rates());
        self.push_apart(frames, &line, line.direction * e.force, forces);
        let stick = if e.stick { 1.0 } else { 0.0 };
        ForceOutput {
            values: [z[0], z[1], e.force, line.stroke, line.stroke_rate, e.friction_force, stick],
            potential_energy: self.cylinder.stored_energy(line.stroke, z),
        }
    }

    /// The states `z` of closed chambers brought from the states `reference` at
    /// the attachments' placement `reference_frames` to the placement `frames`:
    /// each pressure follows its chamber's volume, `p = p0 - beta ln(V / V0)`
    /// (no inflow, the liquid's mass kept); the bristle deflection is kept.
    pub fn closed_states(&self, reference_frames: &Frames<'_>, frames: &Frames<'_>, reference: &[f64], z: &mut [f64]) {
        let g = self.cylinder.geometry();
        let (from, to) = (g.volumes(self.line(reference_frames).stroke), g.volumes(self.line(frames).stroke));
        let beta = self.cylinder.bulk_modulus();
        z.copy_from_slice(reference);
        z[0] = crate::hydraulic::chamber::closed_pressure(reference[0], from.0, to.0, beta);
        z[1] = crate::hydraulic::chamber::closed_pressure(reference[1], from.1, to.1, beta);
    }

    /// Whether the state is inside the range of the law (stroke within [0, S],
    /// pressures above the floor); checked at every accepted step.
    pub fn check_state(&self, frames: &Frames<'_>, z: &[f64]) -> Result<(), CylinderFault> {
        self.cylinder.check(self.line(frames).stroke, z)
    }

    /// Absolute-tolerance scales of the states: a chamber pressure [Pa] is held to
    /// the pressure change a piston displacement of one unit of the length
    /// tolerance causes in that chamber, `beta A / V` [Pa/m] at the initial
    /// stroke; the bristle deflection is a length (1).
    pub fn state_tolerance_scales(&self, scales: &mut [f64]) {
        let g = self.cylinder.geometry();
        let (cap, rod) = g.volumes(self.initial_stroke);
        let beta = self.cylinder.bulk_modulus();
        scales[0] = beta * g.piston_area() / cap;
        scales[1] = beta * g.rod_side_area() / rod;
        scales[2..].fill(1.0);
    }
}


impl ElementModel for CylinderActuator {
    fn channels(&self) -> &'static [OutputInfo] {
        &Self::CHANNELS
    }

    fn markers(&self) -> Vec<Marker> {
        vec![self.first, self.second]
    }

    fn n_states(&self) -> usize {
        self.cylinder.n_states()
    }

    #[inline]
    fn apply(&self, frames: &Frames<'_>, t: f64, (z, z_rate): (&[f64], &mut [f64]), _memory: &[ElementMemory], work: &mut ElementWork, _detailed: bool, forces: &mut GeneralisedForces) -> Result<(), ElementFault> {
        *work.outputs_mut() = self.load(frames, t, z, z_rate, forces);
        Ok(())
    }

    /// Closed chambers: the pressures follow their volumes ([`Self::closed_states`]).
    fn static_states(&self, reference_frames: &Frames<'_>, frames: &Frames<'_>, reference: &[f64], z: &mut [f64]) {
        self.closed_states(reference_frames, frames, reference, z);
    }

    fn check(&self, frames: &Frames<'_>, z: &[f64]) -> Result<(), ElementFault> {
        self.check_state(frames, z).map_err(|fault| ElementFault::OutOfRange(fault.to_string()))
    }

    fn tolerance_scales(&self, scales: &mut [f64]) {
        self.state_tolerance_scales(scales);
    }
}

#[cfg(test)]
#[path = "hydraulic_cylinder_tests.rs"]
mod tests;
