//! The motion modes of a journal in its bore, as paper 002 (§4) classifies
//! them: free flight, impact and rebound, sliding contact and sustained
//! contact, with axial (flange) contact counted apart; and their time tally
//! over the accepted steps of a run (`docs/theory/spatial-clearance-revolute.md`,
//! "Motion modes").
//!
//! Each mode is decided at an accepted step's end from the joint's state there
//! and holds over that step, so the tally is independent of the output
//! sampling. The thresholds are parameters of the joint, with chosen defaults.

/// The radial motion mode of a journal in its bore.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MotionMode {
    /// No radial contact.
    #[default]
    Free = 0,
    /// The first part of a radial contact entered at speed: the impact and its rebound.
    Impact = 1,
    /// Radial contact, the surfaces sliding on each other.
    Sliding = 2,
    /// Radial contact, the surfaces (nearly) sticking.
    Sustained = 3,
}

/// Number of bins of a tally: the four radial modes, then axial contact.
pub const MODE_BINS: usize = 5;

/// Index of the axial-contact bin in [`ModeTally::times`].
pub const AXIAL_BIN: usize = 4;

/// The bins' names, as summaries and results files give them.
pub const MODE_NAMES: [&str; MODE_BINS] = ["free", "impact", "sliding", "sustained", "axial"];

/// Where the modes part.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModeThresholds {
    /// Smallest approach speed at the onset of a radial contact for it to begin with an impact [m/s].
    pub impact_speed: f64,
    /// How long after such an onset the contact counts as impact and rebound [s].
    pub impact_duration: f64,
    /// Sliding speed above which a contact that is not an impact is sliding, at or below it sustained [m/s].
    pub sliding_speed: f64,
}

/// The time a joint spent in each mode, and the radial contact under way.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ModeTally {
    /// Time in free flight, impact, sliding, sustained contact and (apart) axial contact [s].
    pub times: [f64; MODE_BINS],
    /// End of the last tallied step [s] (`None` before the first accepted state).
    pub last_time: Option<f64>,
    /// Onset of the radial contact under way: its time [s] and approach speed [m/s].
    pub radial_onset: Option<(f64, f64)>,
}

/// What the mode of one instant is decided from.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ModeState {
    /// Whether some part of the bore touches the journal.
    pub radial_contact: bool,
    /// Whether a flange touches its bearing face.
    pub axial_contact: bool,
    /// Sliding speed at the deeper radial candidate's deepest point [m/s].
    pub sliding_speed: f64,
}

impl ModeThresholds {
    /// The radial mode at time `t` [s] of `state`, with the contact onset `onset` (time [s], approach speed [m/s]).
    pub fn classify(&self, t: f64, state: &ModeState, onset: Option<(f64, f64)>) -> MotionMode {
        if !state.radial_contact {
            return MotionMode::Free;
        }
        let impact = onset.is_some_and(|(time, speed)| speed >= self.impact_speed && t - time < self.impact_duration);
        if impact {
            MotionMode::Impact
        } else if state.sliding_speed > self.sliding_speed {
            MotionMode::Sliding
        } else {
            MotionMode::Sustained
        }
    }
}

impl ModeTally {
    /// A radial contact began at time `t` [s] with approach speed `speed` [m/s] (its first onset counts).
    pub fn radial_onset_at(&mut self, t: f64, speed: f64) {
        if self.radial_onset.is_none() {
            self.radial_onset = Some((t, speed));
        }
    }

    /// Tallies the step that ended at the accepted time `t` [s] in the mode of `state` there; true when the
    /// radial contact under way began or ended (the mode channel's memory changed).
    pub fn accept(&mut self, thresholds: &ModeThresholds, t: f64, state: &ModeState, onset_speed: f64) -> bool {
        let mut changed = false;
        if state.radial_contact && self.radial_onset.is_none() {
            // a contact present without a located onset (a start in contact, or one inside a step)
            self.radial_onset = Some((t, onset_speed));
            changed = true;
        } else if !state.radial_contact && self.radial_onset.is_some() {
            self.radial_onset = None;
            changed = true;
        }
        if let Some(last) = self.last_time {
            let step = (t - last).max(0.0);
            self.times[thresholds.classify(t, state, self.radial_onset) as usize] += step;
            if state.axial_contact {
                self.times[AXIAL_BIN] += step;
            }
        }
        self.last_time = Some(t);
        changed
    }

    /// Fractions of the tallied time in each bin (radial modes sum to 1; zeros before any step).
    pub fn fractions(&self) -> [f64; MODE_BINS] {
        let total: f64 = self.times[..AXIAL_BIN].iter().sum();
        if total > 0.0 { self.times.map(|time| time / total) } else { [0.0; MODE_BINS] }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const THRESHOLDS: ModeThresholds = ModeThresholds { impact_speed: 5e-3, impact_duration: 1e-3, sliding_speed: 5e-5 };

    fn touching(sliding_speed: f64) -> ModeState {
        ModeState { radial_contact: true, axial_contact: false, sliding_speed }
    }

    #[test]
    fn a_fast_onset_is_an_impact_for_the_stated_duration_then_sliding_or_sustained() {
        let onset = Some((1.0, 0.1));
        assert_eq!(THRESHOLDS.classify(1.0005, &touching(1.0), onset), MotionMode::Impact);
        assert_eq!(THRESHOLDS.classify(1.0015, &touching(1.0), onset), MotionMode::Sliding);
        assert_eq!(THRESHOLDS.classify(1.0015, &touching(1e-5), onset), MotionMode::Sustained);
        // a gentle touch-down is no impact
        assert_eq!(THRESHOLDS.classify(1.0005, &touching(1e-5), Some((1.0, 1e-3))), MotionMode::Sustained);
        assert_eq!(THRESHOLDS.classify(1.0005, &ModeState::default(), onset), MotionMode::Free);
    }

    #[test]
    fn the_tally_adds_each_step_to_the_mode_at_its_end_and_axial_contact_apart() {
        let mut tally = ModeTally::default();
        let free = ModeState::default();
        assert!(!tally.accept(&THRESHOLDS, 0.0, &free, 0.0));
        tally.accept(&THRESHOLDS, 0.5, &free, 0.0);
        tally.radial_onset_at(0.6, 0.2);
        let axial = ModeState { radial_contact: true, axial_contact: true, sliding_speed: 1.0 };
        assert!(!tally.accept(&THRESHOLDS, 0.6005, &axial, 0.0));
        tally.accept(&THRESHOLDS, 0.7, &touching(1.0), 0.0);
        assert!(tally.accept(&THRESHOLDS, 1.0, &free, 0.0));
        let [free_time, impact, sliding, sustained, axial_time] = tally.times;
        assert!((free_time - 0.8).abs() < 1e-15 && (impact - 0.1005).abs() < 1e-15, "{:?}", tally.times);
        assert!((sliding - 0.0995).abs() < 1e-15 && sustained == 0.0 && (axial_time - 0.1005).abs() < 1e-15);
        let fractions = tally.fractions();
        assert!((fractions[..4].iter().sum::<f64>() - 1.0).abs() < 1e-15);
    }
}
