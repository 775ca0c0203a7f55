//! The spatial clearance revolute joint under the element contract
//! ([`crate::element::ElementModel`]): four contact candidates (the bore's
//! halves at rims A and B, the flanges A and B), each with its event (its
//! deepest penetration crossing zero) and its onset memory, plus the tally of
//! its motion modes; its evaluation, its channels. The laws are in
//! [`super::spatial_clearance_revolute`], the modes in
//! [`super::spatial_clearance_modes`].

use super::spatial_clearance_geometry::JointPose;
use super::spatial_clearance_modes::{ModeState, ModeTally, MotionMode};
use super::spatial_clearance_revolute::{CandidateEvaluation, JointLoad, SpatialClearanceRevolute, CANDIDATES};
use super::ContactMemory;
use crate::dynamics::GeneralisedForces;
use crate::element::{Acceptance, ElementFault, ElementMemory, ElementModel, ElementWork, OutputInfo};
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::{BodyIndex, Marker};
use crate::kinematics::planar::{Frame, Vec2};
use crate::kinematics::wrench::Wrench;

/// Penetration, as a fraction of the radial clearance, above which a contact counts as deep.
const DEEP_PENETRATION_FRACTION: f64 = 0.1;

/// Memory slot of the mode tally (after the candidates' onset slots).
const TALLY_SLOT: usize = CANDIDATES;

/// Channels: quantity, unit, description, in the order [`SpatialClearanceWork::outputs`] writes them.
pub const CHANNELS: [OutputInfo; 31] = [
    ("e_a_x", "m", "journal axis offset from the bore axis at rim A (s = -L/2), bearing x"),
    ("e_a_y", "m", "journal axis offset from the bore axis at rim A (s = -L/2), bearing y"),
    ("e_m_x", "m", "journal axis offset from the bore axis at the bore's middle, bearing x"),
    ("e_m_y", "m", "journal axis offset from the bore axis at the bore's middle, bearing y"),
    ("e_b_x", "m", "journal axis offset from the bore axis at rim B (s = +L/2), bearing x"),
    ("e_b_y", "m", "journal axis offset from the bore axis at rim B (s = +L/2), bearing y"),
    ("tilt", "rad", "angle between the journal axis and the bore axis"),
    ("axial_position", "m", "journal origin from the bearing origin along the bore axis"),
    ("axial_gap_a", "m", "gap of flange A (at -z) to its bearing face, negative when penetrating"),
    ("axial_gap_b", "m", "gap of flange B (at +z) to its bearing face, negative when penetrating"),
    ("penetration_a", "m", "deepest penetration of the bore half at rim A (0 when free)"),
    ("penetration_b", "m", "deepest penetration of the bore half at rim B (0 when free)"),
    ("penetration_fa", "m", "deepest penetration of flange A (0 when free)"),
    ("penetration_fb", "m", "deepest penetration of flange B (0 when free)"),
    ("fn_a", "N", "normal force of the bore half at rim A"),
    ("fn_b", "N", "normal force of the bore half at rim B"),
    ("fn_fa", "N", "normal force of flange A"),
    ("fn_fb", "N", "normal force of flange B"),
    ("ft_a", "N", "friction force magnitude of the bore half at rim A"),
    ("ft_b", "N", "friction force magnitude of the bore half at rim B"),
    ("ft_fa", "N", "friction force magnitude of flange A"),
    ("ft_fb", "N", "friction force magnitude of flange B"),
    ("fx", "N", "joint force on the journal, global x"),
    ("fy", "N", "joint force on the journal, global y"),
    ("fz", "N", "joint force on the journal, global z"),
    ("mx", "N m", "joint moment on the journal about its marker's origin, global x"),
    ("my", "N m", "joint moment on the journal about its marker's origin, global y"),
    ("mz", "N m", "joint moment on the journal about its marker's origin, global z"),
    ("f", "N", "magnitude of the joint force on the journal"),
    ("mode", "-", "radial motion mode: 0 free, 1 impact, 2 sliding, 3 sustained contact"),
    ("axial_contact", "-", "1 while a flange touches its bearing face, else 0"),
];



/// Last evaluation of a spatial clearance joint.
#[derive(Clone, Debug, Default)]
pub struct SpatialClearanceWork {
    /// The candidates: bore halves A and B, flanges A and B.
    pub candidates: [CandidateEvaluation; CANDIDATES],
    /// The joint's load.
    pub load: JointLoad,
    /// Journal-axis offsets at rim A, the middle and rim B (bearing x, y) [m].
    pub eccentricities: [Vec2; 3],
    /// Tilt [rad].
    pub tilt: f64,
    /// Axial position [m].
    pub axial_position: f64,
    /// Radial motion mode.
    pub mode: MotionMode,
}

impl SpatialClearanceWork {
    /// Whether the last evaluation's forces are finite.
    pub fn forces_finite(&self) -> bool {
        let w = &self.load.on_journal;
        w.force.iter().chain(w.moment.iter()).all(|v| v.is_finite())
    }

    /// Values of all channels ([`CHANNELS`]).
    pub fn outputs(&self) -> [f64; CHANNELS.len()] {
        let [a, m, b] = self.eccentricities;
        let c = &self.candidates;
        let Wrench { force, moment } = self.load.on_journal;
        [
            a.x, a.y, m.x, m.y, b.x, b.y,
            self.tilt,
            self.axial_position,
            -c[2].penetration,
            -c[3].penetration,
            c[0].penetration.max(0.0), c[1].penetration.max(0.0), c[2].penetration.max(0.0), c[3].penetration.max(0.0),
            c[0].normal_force, c[1].normal_force, c[2].normal_force, c[3].normal_force,
            c[0].friction_force, c[1].friction_force, c[2].friction_force, c[3].friction_force,
            force.x, force.y, force.z,
            moment.x, moment.y, moment.z,
            force.norm(),
            f64::from(self.mode as u8),
            f64::from(u8::from(c[2].penetration > 0.0 || c[3].penetration > 0.0)),
        ]
    }

    /// The state the motion mode is decided from.
    pub fn mode_state(&self) -> ModeState {
        let [a, b, fa, fb] = &self.candidates;
        let deeper = if a.penetration >= b.penetration { a } else { b };
        ModeState {
            radial_contact: a.penetration > 0.0 || b.penetration > 0.0,
            axial_contact: fa.penetration > 0.0 || fb.penetration > 0.0,
            sliding_speed: deeper.sliding_speed,
        }
    }
}

fn contact(memory: &[ElementMemory], k: usize) -> Option<f64> {
    match &memory[k] {
        ElementMemory::Contact(contact) => contact.onset_velocity,
        _ => None,
    }
}

fn tally(memory: &[ElementMemory]) -> ModeTally {
    match memory[TALLY_SLOT] {
        ElementMemory::Modes(tally) => tally,
        _ => ModeTally::default(),
    }
}

fn work_of(work: &ElementWork) -> &SpatialClearanceWork {
    match work {
        ElementWork::SpatialClearance(work) => work,
        _ => unreachable!("a spatial clearance joint's work is made by new_work"),
    }
}

impl SpatialClearanceRevolute {
    /// The pose of the joint's markers.
    #[inline]
    pub fn pose(&self, frames: &Frames<'_>) -> JointPose {
        JointPose::new(&frames.marker_frame(&self.bearing), &frames.marker_frame(&self.journal))
    }

    /// Evaluates every candidate with the onset velocities of `memory` and the
    /// mode at time `t` [s]; keeps the evaluation in `work`.
    pub fn evaluate(&self, pose: &JointPose, t: f64, memory: &[ElementMemory], work: &mut SpatialClearanceWork) {
        let mut load = JointLoad::default();
        for half in 0..2 {
            work.candidates[half] = self.radial(pose, half, contact(memory, half), &mut load);
        }
        for side in 0..2 {
            work.candidates[2 + side] = self.flange(pose, side, contact(memory, 2 + side), &mut load);
        }
        work.load = load;
        let half = 0.5 * self.geometry.dimensions().bearing_length;
        work.eccentricities = [-half, 0.0, half].map(|s| pose.axis_foot(s).xy());
        work.tilt = pose.tilt();
        work.axial_position = pose.journal_origin.z;
        work.mode = self.modes.classify(t, &work.mode_state(), tally(memory).radial_onset);
    }
}

impl ElementModel for SpatialClearanceRevolute {
    fn channels(&self) -> &'static [OutputInfo] {
        &CHANNELS
    }

    fn markers(&self) -> Vec<Marker> {
        vec![self.bearing.planar(), self.journal.planar()]
    }

    /// One per candidate: its deepest penetration crossing zero upwards.
    fn n_events(&self) -> usize {
        CANDIDATES
    }

    /// One onset memory per candidate, and the mode tally.
    fn n_memory_slots(&self) -> usize {
        CANDIDATES + 1
    }

    fn event_bodies(&self) -> Vec<BodyIndex> {
        vec![self.bearing.body, self.journal.body]
    }

    fn start_memory(&self, memory: &mut [ElementMemory]) {
        memory[..CANDIDATES].fill(ElementMemory::Contact(ContactMemory::default()));
        memory[TALLY_SLOT] = ElementMemory::Modes(ModeTally::default());
    }

    fn new_work(&self) -> ElementWork {
        ElementWork::SpatialClearance(Box::default())
    }

    /// Evaluates the candidates and adds the joint's wrench to both bodies.
    fn apply(&self, frames: &Frames<'_>, t: f64, _states: (&[f64], &mut [f64]), memory: &[ElementMemory], work: &mut ElementWork, _detailed: bool, forces: &mut GeneralisedForces) -> Result<(), ElementFault> {
        let ElementWork::SpatialClearance(work) = work else { unreachable!("a spatial clearance joint's work is made by new_work") };
        let pose = self.pose(frames);
        self.evaluate(&pose, t, memory, work);
        let load = &work.load;
        if work.candidates.iter().any(|c| c.penetration > 0.0) {
            forces.add_wrench(&self.journal, pose.journal.position, &load.on_journal);
            forces.add_wrench(&self.bearing, pose.bearing.position, &Wrench { force: -load.on_journal.force, moment: load.bearing_moment });
        }
        Ok(())
    }

    fn outputs(&self, which: std::ops::Range<usize>, _frames: &[Frame], work: &ElementWork, out: &mut [f64]) {
        out.copy_from_slice(&work_of(work).outputs()[which]);
    }

    fn output(&self, which: usize, _frames: &[Frame], work: &ElementWork) -> f64 {
        work_of(work).outputs()[which]
    }

    /// Elastic energy stored in the contacts [J].
    fn potential_energy(&self, work: &ElementWork) -> f64 {
        work_of(work).candidates.iter().map(|c| c.elastic_energy).sum()
    }

    fn event_functions(&self, frames: &Frames<'_>, g: &mut [f64], rates: Option<&mut [f64]>) {
        let pose = self.pose(frames);
        let deepest = [0, 1, 2, 3].map(|k| self.deepest(&pose, k));
        for (g, contact) in g.iter_mut().zip(&deepest) {
            *g = contact.penetration;
        }
        if let Some(rates) = rates {
            for (rate, contact) in rates.iter_mut().zip(&deepest) {
                *rate = pose.relative_motion(contact).approach_rate;
            }
        }
    }

    /// Candidate `event`'s onset: latches its approach velocity, counts the
    /// impact and, for the bore, starts the radial contact's mode clock.
    fn on_event(&self, frames: &Frames<'_>, t: f64, event: usize, memory: &mut [ElementMemory]) {
        let pose = self.pose(frames);
        let onset = self.onset_velocity(&pose, event);
        if let ElementMemory::Contact(contact) = &mut memory[event] {
            contact.onset_velocity = Some(onset);
            contact.impacts += 1;
        }
        if event < 2 {
            if let ElementMemory::Modes(tally) = &mut memory[TALLY_SLOT] {
                tally.radial_onset_at(t, onset);
            }
        }
    }

    /// Latches or clears each candidate's onset at an accepted state, tallies
    /// the step's mode and checks the penetration bound.
    fn accept(&self, frames: &Frames<'_>, t: f64, memory: &mut [ElementMemory]) -> Result<Acceptance, ElementFault> {
        let pose = self.pose(frames);
        let mut memory_changed = false;
        let mut work = SpatialClearanceWork::default();
        let mut deepest = f64::NEG_INFINITY;
        for k in 0..CANDIDATES {
            let penetration = self.deepest(&pose, k).penetration;
            deepest = deepest.max(penetration);
            let ElementMemory::Contact(contact) = &mut memory[k] else { continue };
            if penetration <= 0.0 {
                memory_changed |= contact.onset_velocity.take().is_some();
            } else if contact.onset_velocity.is_none() {
                // contact present without a located onset (a start in contact, or re-contact inside one step)
                contact.onset_velocity = Some(self.onset_velocity(&pose, k));
                contact.impacts += 1;
                memory_changed = true;
            }
            work.candidates[k].penetration = penetration;
        }
        let radial_onset = (0..2).filter(|&k| work.candidates[k].penetration > 0.0).map(|k| self.onset_velocity(&pose, k)).fold(0.0, f64::max);
        for k in 0..2 {
            if work.candidates[k].penetration > 0.0 {
                work.candidates[k].sliding_speed = pose.relative_motion(&self.radial_deepest(&pose, k)).tangential_velocity.norm();
            }
        }
        if let ElementMemory::Modes(tally) = &mut memory[TALLY_SLOT] {
            memory_changed |= tally.accept(&self.modes, t, &work.mode_state(), radial_onset);
        }
        if deepest > self.max_penetration {
            return Err(ElementFault::ExcessivePenetration { penetration: deepest, bound: self.max_penetration });
        }
        let clearance = self.geometry.radial_clearance();
        let penetration = deepest.max(0.0);
        Ok(Acceptance { memory_changed, penetration, deep_penetration: penetration > DEEP_PENETRATION_FRACTION * clearance })
    }
}

impl SpatialClearanceRevolute {
    /// Time spent in each mode so far ([`super::spatial_clearance_modes::MODE_BINS`] bins) [s].
    pub fn mode_times(memory: &[ElementMemory]) -> Option<ModeTally> {
        memory.iter().find_map(|slot| match slot {
            ElementMemory::Modes(tally) => Some(*tally),
            _ => None,
        })
    }
}
