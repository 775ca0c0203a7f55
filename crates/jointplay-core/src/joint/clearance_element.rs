//! The clearance revolute joint under the element contract
//! ([`crate::element::ElementModel`]): its one event (contact onset, the
//! penetration crossing zero), its one memory slot (the onset velocity
//! latched at the accepted step where contact began, and the impact count),
//! its evaluation (dry contact plus the optional film) with the scratch it
//! needs, and its channels. The laws themselves are in
//! [`super::clearance_revolute`] and [`super::lubricated_film`].

use super::{ClearanceRevolute, ContactEvaluation, FilmEvaluation, Lubrication};
use crate::dynamics::GeneralisedForces;
use crate::element::{Acceptance, ElementFault, ElementMemory, ElementModel, ElementWork, OutputInfo};
use crate::kinematics::frames::Frames;
use crate::kinematics::marker::{BodyIndex, Marker};
use crate::kinematics::planar::Frame;
use crate::lubrication::reynolds::ReynoldsSolver;

/// A penetration deeper than this fraction of the clearance is reported in
/// the acceptance as deep (a hint that the contact is soft for the clearance).
const DEEP_PENETRATION_FRACTION: f64 = 0.1;

/// Largest tilt of the bearing's or the journal's frame out of the plane
/// z = 0 [rad]: the joint's law is planar, exact while both turn about the
/// global z axis only (in a spatial model, bodies kept in the plane by their
/// joints stay within round-off of it).
const MAX_TILT: f64 = 1e-6;

/// Discrete memory of one clearance joint, changed only at its events and at accepted steps.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactMemory {
    /// Normal approach velocity latched at the accepted step where contact
    /// began [m/s]; `None` while the journal is free.
    pub onset_velocity: Option<f64>,
    /// Number of contact onsets so far.
    pub impacts: usize,
}

/// Last evaluation of one clearance joint and the scratch its film needs.
#[derive(Clone, Debug, Default)]
pub struct ClearanceWork {
    /// Dry contact.
    pub contact: ContactEvaluation,
    /// Film (default for a dry joint).
    pub film: FilmEvaluation,
    /// Reynolds solver of the exact film mode.
    pub solver: Option<ReynoldsSolver>,
}

impl ClearanceWork {
    /// Whether the last evaluation's forces are finite.
    pub fn forces_finite(&self) -> bool {
        let (c, f) = (&self.contact, &self.film);
        c.normal_force.is_finite() && c.friction_force.is_finite() && f.force_on_journal.x.is_finite() && f.force_on_journal.y.is_finite()
    }
}

/// Channels of a clearance joint: the contact quantities, then (lubricated joints only) the film's.
pub const CHANNELS: [OutputInfo; 19] = [
    ("ex", "m", "eccentricity x (journal centre from bearing centre)"),
    ("ey", "m", "eccentricity y"),
    ("eccentricity_ratio", "1", "|e| / clearance"),
    ("penetration", "m", "penetration depth |e| - c while in contact, else 0"),
    ("fn", "N", "normal contact force"),
    ("ft", "N", "friction force along the tangent t = perp(n), on the journal"),
    ("fx", "N", "force of the joint on the journal (contact plus film), x"),
    ("fy", "N", "force of the joint on the journal, y"),
    ("f", "N", "force of the joint on the journal, magnitude"),
    ("vn", "m/s", "normal relative velocity d|e|/dt (positive when approaching the wall)"),
    ("vt", "m/s", "sliding velocity of the journal surface on the bore"),
    ("contact", "1", "1 while in contact, 0 while free"),
    ("film_min", "m", "minimum film thickness c - |e| (0 in contact)"),
    ("fhx", "N", "film (hydrodynamic) force on the journal after the transition weight, x"),
    ("fhy", "N", "film force on the journal, y"),
    ("fh", "N", "film force magnitude"),
    ("peak_pressure", "Pa", "peak film pressure (gauge)"),
    ("film_weight", "1", "share of the film force in the transition to contact"),
    ("mode", "1", "0 hydrodynamic, 1 transition, 2 contact"),
];

/// Number of the contact channels (the film's follow).
const CONTACT_CHANNELS: usize = 12;

/// The joint's one memory slot.
#[inline]
fn contact(memory: &[ElementMemory]) -> &ContactMemory {
    match memory {
        [ElementMemory::Contact(memory)] => memory,
        _ => unreachable!("a clearance joint's memory is its one contact slot"),
    }
}

/// The joint's one memory slot, to change.
fn contact_mut(memory: &mut [ElementMemory]) -> &mut ContactMemory {
    match memory {
        [ElementMemory::Contact(memory)] => memory,
        _ => unreachable!("a clearance joint's memory is its one contact slot"),
    }
}

/// The joint's record in the workspace.
#[inline]
fn clearance_work(work: &ElementWork) -> &ClearanceWork {
    match work {
        ElementWork::Clearance(work) => work,
        _ => unreachable!("a clearance joint's work is its own"),
    }
}

/// The joint's record in the workspace, to change.
#[inline]
fn clearance_work_mut(work: &mut ElementWork) -> &mut ClearanceWork {
    match work {
        ElementWork::Clearance(work) => work,
        _ => unreachable!("a clearance joint's work is its own"),
    }
}

impl ElementModel for ClearanceRevolute {
    /// The contact channels, then (lubricated joints only) the film's.
    fn channels(&self) -> &'static [OutputInfo] {
        if self.lubrication.is_some() { &CHANNELS } else { &CHANNELS[..CONTACT_CHANNELS] }
    }

    fn markers(&self) -> Vec<Marker> {
        vec![self.bearing, self.journal]
    }

    /// One: the penetration crossing zero upwards.
    fn n_events(&self) -> usize {
        1
    }

    /// One: the contact's onset memory.
    fn n_memory_slots(&self) -> usize {
        1
    }

    fn event_bodies(&self) -> Vec<BodyIndex> {
        vec![self.bearing.body, self.journal.body]
    }

    fn start_memory(&self, memory: &mut [ElementMemory]) {
        memory[0] = ElementMemory::Contact(ContactMemory::default());
    }

    fn new_work(&self) -> ElementWork {
        ElementWork::Clearance(Box::new(ClearanceWork { solver: self.lubrication.as_ref().and_then(Lubrication::new_solver), ..Default::default() }))
    }

    /// Evaluates contact and film with the latched onset velocity of its
    /// memory, adds their generalised forces and keeps the evaluations.
    #[inline]
    fn apply(&self, frames: &Frames<'_>, _t: f64, _states: (&[f64], &mut [f64]), memory: &[ElementMemory], work: &mut ElementWork, detailed: bool, forces: &mut GeneralisedForces) -> Result<(), ElementFault> {
        self.apply_contact_and_film(frames.planar, contact(memory), clearance_work_mut(work), detailed, forces)
    }

    /// Re-evaluates the film with the outputs only samples need (the peak pressure).
    fn detail(&self, frames: &[Frame], work: &mut ElementWork) -> Result<(), ElementFault> {
        if self.lubrication.is_some() {
            let work = clearance_work_mut(work);
            work.film = self.film(frames, work.solver.as_mut(), true)?;
        }
        Ok(())
    }

    fn has_detailed_outputs(&self) -> bool {
        self.lubrication.is_some()
    }

    fn outputs(&self, which: std::ops::Range<usize>, frames: &[Frame], work: &ElementWork, out: &mut [f64]) {
        out.copy_from_slice(&self.all_outputs(frames, clearance_work(work))[which]);
    }

    fn output(&self, which: usize, frames: &[Frame], work: &ElementWork) -> f64 {
        self.all_outputs(frames, clearance_work(work))[which]
    }

    /// Elastic energy stored in the contact [J].
    fn potential_energy(&self, work: &ElementWork) -> f64 {
        self.stiffness.elastic_energy(clearance_work(work).contact.penetration.max(0.0))
    }

    fn event_functions(&self, frames: &Frames<'_>, g: &mut [f64], rates: Option<&mut [f64]>) {
        g[0] = self.penetration(frames.planar);
        if let Some(rates) = rates {
            rates[0] = self.penetration_rate(frames.planar);
        }
    }

    fn on_event(&self, frames: &Frames<'_>, _t: f64, _event: usize, memory: &mut [ElementMemory]) {
        self.latch_onset(frames.planar, contact_mut(memory));
    }

    /// Latches or clears the onset velocity at an accepted state and checks the
    /// penetration bound.
    fn accept(&self, frames: &Frames<'_>, _t: f64, memory: &mut [ElementMemory]) -> Result<Acceptance, ElementFault> {
        self.check_in_plane(frames)?;
        let memory = contact_mut(memory);
        let penetration = self.penetration(frames.planar);
        if penetration <= 0.0 {
            return Ok(Acceptance { memory_changed: memory.onset_velocity.take().is_some(), ..Default::default() });
        }
        let mut memory_changed = false;
        if memory.onset_velocity.is_none() {
            // contact present without a located onset (start in contact, or re-contact inside one step)
            self.latch_onset(frames.planar, memory);
            memory_changed = true;
        }
        if penetration > self.max_penetration {
            return Err(ElementFault::ExcessivePenetration { penetration, bound: self.max_penetration });
        }
        Ok(Acceptance { memory_changed, penetration, deep_penetration: penetration > DEEP_PENETRATION_FRACTION * self.clearance })
    }
}

impl ClearanceRevolute {
    /// Evaluates contact and film with the latched onset velocity of `memory`,
    /// adds their generalised forces and keeps the evaluations in `work`;
    /// `detailed` asks for the film outputs only recorded samples need.
    pub fn apply_contact_and_film(&self, frames: &[Frame], memory: &ContactMemory, work: &mut ClearanceWork, detailed: bool, forces: &mut GeneralisedForces) -> Result<(), ElementFault> {
        let c = self.evaluate(frames, memory.onset_velocity);
        let (bi, bj) = (&self.bearing, &self.journal);
        let (fi, fj) = (&frames[bi.frame], &frames[bj.frame]);
        if c.in_contact {
            forces.add_point_force(bj, fj, c.journal_contact_point, c.force_on_journal);
            forces.add_point_force(bi, fi, c.bearing_contact_point, -c.force_on_journal);
        }
        work.contact = c;
        if self.lubrication.is_some() {
            work.film = self.film(frames, work.solver.as_mut(), detailed)?;
            Lubrication::apply(&work.film, forces, (fi, bi, fi.point(bi.local)), (fj, bj, fj.point(bj.local)));
        }
        Ok(())
    }

    fn film(&self, frames: &[Frame], solver: Option<&mut ReynoldsSolver>, detailed: bool) -> Result<FilmEvaluation, ElementFault> {
        let Some(lubrication) = &self.lubrication else { return Ok(FilmEvaluation::default()) };
        let (fi, fj) = (&frames[self.bearing.frame], &frames[self.journal.frame]);
        let kinematics = Lubrication::kinematics(fi, fj, fi.point(self.bearing.local), fj.point(self.journal.local));
        lubrication.evaluate(&kinematics, solver, detailed).map_err(ElementFault::Film)
    }

    /// In a spatial model: an error when the bearing's or the journal's frame
    /// tilts out of the plane z = 0, where the planar law no longer holds.
    fn check_in_plane(&self, frames: &Frames<'_>) -> Result<(), ElementFault> {
        if frames.spatial.is_empty() {
            return Ok(());
        }
        for (role, marker) in [("bearing", &self.bearing), ("journal", &self.journal)] {
            let tilt = frames.spatial[marker.frame].rotation[(2, 2)].clamp(-1.0, 1.0).acos();
            if tilt > MAX_TILT {
                return Err(ElementFault::OutOfRange(format!(
                    "the {role}'s frame tilted {tilt:.3e} rad out of the plane z = 0 (at most {MAX_TILT:e}): the planar clearance joint holds only while its bodies turn about the global z axis"
                )));
            }
        }
        Ok(())
    }

    /// Contact onset located: latches the approach velocity and counts the impact.
    fn latch_onset(&self, frames: &[Frame], memory: &mut ContactMemory) {
        memory.onset_velocity = Some(self.onset_velocity(frames));
        memory.impacts += 1;
    }

    /// Values of all channels ([`CHANNELS`], the film's zero for a dry joint) from the last evaluation.
    pub fn all_outputs(&self, frames: &[Frame], work: &ClearanceWork) -> [f64; CHANNELS.len()] {
        let (c, f) = (&work.contact, &work.film);
        // the joint's total force on the journal: dry contact plus film (zero for a dry joint)
        let total = c.force_on_journal + f.force_on_journal;
        [
            c.eccentricity.x,
            c.eccentricity.y,
            c.eccentricity.norm() / self.clearance,
            c.penetration.max(0.0),
            c.normal_force,
            c.friction_force,
            total.x,
            total.y,
            total.norm(),
            if c.in_contact { c.penetration_rate } else { self.free_radial_velocity(frames, c) },
            c.sliding_velocity,
            f64::from(u8::from(c.in_contact)),
            f.film_min,
            f.force_on_journal.x,
            f.force_on_journal.y,
            f.force_on_journal.norm(),
            f.peak_pressure,
            f.weight,
            f64::from(f.mode),
        ]
    }

    /// `d|e|/dt` while the journal is free [m/s] (0 at `e = 0`).
    fn free_radial_velocity(&self, frames: &[Frame], c: &ContactEvaluation) -> f64 {
        let distance = c.eccentricity.norm();
        if distance == 0.0 {
            return 0.0;
        }
        let (fi, fj) = (&frames[self.bearing.frame], &frames[self.journal.frame]);
        let e_dot = fj.point_velocity(self.journal.local) - fi.point_velocity(self.bearing.local);
        e_dot.dot(&c.eccentricity) / distance
    }
}
