//! Dry revolute joint with radial clearance: a journal (pin) of radius
//! `R_j` moving freely in a bore of radius `R_b` on another body, with
//! contact-impact forces once it touches the wall.
//!
//! Kinematics (DESIGN.md §4): `e = P_j - P_i`, `n = e/|e|`,
//! `delta = |e| - c` with `c = R_b - R_j`; contact points
//! `Q_i = P_i + R_b n` on the bearing and `Q_j = P_j + R_j n` on the
//! journal; `delta_dot = (v_Qj - v_Qi) . n` and the sliding velocity
//! `v_t = (v_Qj - v_Qi) . t` with `t = perp(n)` (spins included).
//! The force on the journal is `-F_n n + F_t t` at `Q_j`; the bearing gets
//! the opposite force at `Q_i`.

use crate::contact::{ContactStiffness, NormalForceLaw};
use crate::kinematics::marker::Marker;
use crate::kinematics::planar::{perp, Frame, Vec2};
use crate::friction::FrictionLaw;

/// A dry revolute clearance joint.
#[derive(Clone, Debug)]
pub struct ClearanceRevolute {
    /// Bearing centre on the first body.
    pub bearing: Marker,
    /// Journal centre on the second body.
    pub journal: Marker,
    /// Bore radius R_b [m].
    pub bearing_radius: f64,
    /// Journal radius R_j [m].
    pub journal_radius: f64,
    /// Radial clearance c = R_b - R_j [m].
    pub clearance: f64,
    /// Elastic force as a function of penetration.
    pub stiffness: ContactStiffness,
    /// Dissipation of the normal force.
    pub normal_force_law: NormalForceLaw,
    /// Tangential friction.
    pub friction: FrictionLaw,
    /// Smallest onset velocity used in the damping term [m/s].
    pub onset_velocity_floor: f64,
    /// Penetration at which the simulation stops [m].
    pub max_penetration: f64,
    /// Initial eccentricity vector (journal from bearing centre, global) [m].
    pub initial_eccentricity: Vec2,
    /// Lubricant film, if the joint is lubricated.
    pub lubrication: Option<super::Lubrication>,
}

/// Everything one evaluation of a clearance joint produces.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ContactEvaluation {
    /// Eccentricity vector `e = P_j - P_i` [m].
    pub eccentricity: Vec2,
    /// Penetration `|e| - c` [m]; negative when the journal is free.
    pub penetration: f64,
    /// Normal relative velocity, positive when penetrating [m/s].
    pub penetration_rate: f64,
    /// Sliding velocity of the journal surface on the bore along `t` [m/s].
    pub sliding_velocity: f64,
    /// Normal contact force magnitude [N].
    pub normal_force: f64,
    /// Friction force along `t` on the journal [N].
    pub friction_force: f64,
    /// Contact force on the journal, global frame [N].
    pub force_on_journal: Vec2,
    /// Contact point on the bearing `Q_i` [m].
    pub bearing_contact_point: Vec2,
    /// Contact point on the journal `Q_j` [m].
    pub journal_contact_point: Vec2,
    /// Whether the journal touches the bore (`penetration > 0`).
    pub in_contact: bool,
}

impl ClearanceRevolute {
    /// Penetration depth `|e| - c` [m] only (event function).
    #[inline]
    pub fn penetration(&self, frames: &[Frame]) -> f64 {
        self.eccentricity(frames).norm() - self.clearance
    }

    /// Rate of the penetration `d|e|/dt` [m/s]: the radial relative velocity
    /// of the journal centre, positive when approaching the wall. At `e = 0`,
    /// where `|e|` has a kink, the rate at which `|e|` grows, `|de/dt|`.
    #[inline]
    pub fn penetration_rate(&self, frames: &[Frame]) -> f64 {
        let (fi, fj) = (&frames[self.bearing.frame], &frames[self.journal.frame]);
        let e = fj.point(self.journal.local) - fi.point(self.bearing.local);
        let e_dot = fj.point_velocity(self.journal.local) - fi.point_velocity(self.bearing.local);
        let distance = e.norm();
        if distance == 0.0 { e_dot.norm() } else { e_dot.dot(&e) / distance }
    }

    /// Eccentricity vector `P_j - P_i` [m].
    #[inline]
    pub fn eccentricity(&self, frames: &[Frame]) -> Vec2 {
        frames[self.journal.frame].point(self.journal.local) - frames[self.bearing.frame].point(self.bearing.local)
    }

    /// Contact kinematics and forces. `onset_velocity` is the latched normal
    /// approach velocity at contact onset [m/s], or `None` when contact has
    /// not been registered yet (a trial stage inside the step that finds the
    /// onset), in which case the current approach velocity is used.
    pub fn evaluate(&self, frames: &[Frame], onset_velocity: Option<f64>) -> ContactEvaluation {
        let (fi, fj) = (&frames[self.bearing.frame], &frames[self.journal.frame]);
        let pi = fi.point(self.bearing.local);
        let pj = fj.point(self.journal.local);
        let e = pj - pi;
        let distance = e.norm();
        let penetration = distance - self.clearance;
        let out = ContactEvaluation { eccentricity: e, penetration, ..Default::default() };
        if penetration <= 0.0 || distance == 0.0 {
            return out;
        }
        // contact geometry and relative velocity of the contact points
        let n = e / distance;
        let t = perp(n);
        let qi = pi + n * self.bearing_radius;
        let qj = pj + n * self.journal_radius;
        let v_rel = fj.material_velocity_at(qj) - fi.material_velocity_at(qi);
        let penetration_rate = v_rel.dot(&n);
        let sliding_velocity = v_rel.dot(&t);
        // normal force with the latched (or provisional) onset velocity
        let onset = onset_velocity.unwrap_or(penetration_rate).max(self.onset_velocity_floor);
        let elastic = self.stiffness.elastic_force(penetration);
        let normal_force = self.normal_force_law.normal_force(elastic, penetration_rate, onset);
        let friction_force = self.friction.friction_force(normal_force, sliding_velocity);
        ContactEvaluation {
            eccentricity: e,
            penetration,
            penetration_rate,
            sliding_velocity,
            normal_force,
            friction_force,
            force_on_journal: -n * normal_force + t * friction_force,
            bearing_contact_point: qi,
            journal_contact_point: qj,
            in_contact: true,
        }
    }

    /// Normal approach velocity [m/s] to latch at contact onset, floored.
    pub fn onset_velocity(&self, frames: &[Frame]) -> f64 {
        let (fi, fj) = (&frames[self.bearing.frame], &frames[self.journal.frame]);
        let pi = fi.point(self.bearing.local);
        let e = fj.point(self.journal.local) - pi;
        let distance = e.norm();
        if distance == 0.0 {
            return self.onset_velocity_floor;
        }
        let n = e / distance;
        let v_rel = fj.material_velocity_at(pi + e + n * self.journal_radius)
            - fi.material_velocity_at(pi + n * self.bearing_radius);
        v_rel.dot(&n).max(self.onset_velocity_floor)
    }
}
