//! State and result of a misaligned (tilted) journal's film.
//!
//! In the bearing's frame (x, y across the bore, z along its axis, z = 0 at
//! the bearing's mid-plane) the journal axis crosses the plane z at
//! `e(z) = e0 + z tau`: `e0` is the eccentricity at the mid-plane [m] and
//! `tau` the misalignment [m/m], the rate at which the journal axis moves
//! away from the bore axis along z. The film is
//! `h(theta, z) = c - e(z) . u(theta)`, its rate
//! `dh/dt = -(e0_dot + z tau_dot) . u(theta)`: the rigid journal's axis is a
//! straight line, so its offset from the bore axis is linear in z (the film
//! model of the misaligned-bearing literature reviewed by Jang and Khonsari
//! 2015, "On the characteristics of misaligned journal bearings",
//! Lubricants 3, 27-53). The journal's surface speed is taken around the bore
//! axis: its axial part, of order `R omega |tau|`, is dropped with the other
//! terms of order `c / L`.
//!
//! A small tilt `(a_x, a_y)` of the journal about the bearing's x and y axes
//! gives `tau = (a_y, -a_x)`; the tilt as a rotation vector is therefore
//! `(-tau_y, tau_x)` [rad], and the film's moment resists the tilt when
//! `moment . (-tau_y, tau_x) < 0`.

use nalgebra::Vector2;

use super::outputs::FilmSolution;
use crate::lubrication::film::{FilmForce, FilmKinematics};

/// Relative motion of a tilted journal in its bearing at one instant (bearing frame).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MisalignedFilmKinematics {
    /// Eccentricity of the journal axis at the mid-plane, `e0` [m].
    pub eccentricity: Vector2<f64>,
    /// Its time derivative [m/s].
    pub eccentricity_rate: Vector2<f64>,
    /// Misalignment `tau`: journal-axis offset per unit length along the bearing [m/m].
    pub misalignment: Vector2<f64>,
    /// Its time derivative [1/s].
    pub misalignment_rate: Vector2<f64>,
    /// Absolute spin of the journal about the bearing axis [rad/s].
    pub journal_spin: f64,
    /// Absolute spin of the bearing about its axis [rad/s].
    pub bearing_spin: f64,
}

impl MisalignedFilmKinematics {
    /// The state of an aligned journal (no misalignment, no misalignment rate).
    pub fn aligned(k: &FilmKinematics) -> Self {
        Self {
            eccentricity: k.eccentricity,
            eccentricity_rate: k.eccentricity_rate,
            misalignment: Vector2::zeros(),
            misalignment_rate: Vector2::zeros(),
            journal_spin: k.journal_spin,
            bearing_spin: k.bearing_spin,
        }
    }

    /// The film at the mid-plane, as the aligned solver reads it.
    pub fn mid_plane(&self) -> FilmKinematics {
        FilmKinematics {
            eccentricity: self.eccentricity,
            eccentricity_rate: self.eccentricity_rate,
            journal_spin: self.journal_spin,
            bearing_spin: self.bearing_spin,
        }
    }

    /// True when neither the misalignment nor its rate is nonzero: the film does not vary along z.
    pub fn is_aligned(&self) -> bool {
        self.misalignment == Vector2::zeros() && self.misalignment_rate == Vector2::zeros()
    }

    /// Eccentricity of the journal axis at axial position `z` [m], `e0 + z tau`.
    pub fn eccentricity_at(&self, z: f64) -> Vector2<f64> {
        self.eccentricity + self.misalignment * z
    }

    /// Its rate at `z` [m/s], `e0_dot + z tau_dot`.
    pub fn eccentricity_rate_at(&self, z: f64) -> Vector2<f64> {
        self.eccentricity_rate + self.misalignment_rate * z
    }

    /// Checks that every value is finite; the message names the state.
    pub fn check_finite(&self) -> Result<(), String> {
        let finite = |v: &Vector2<f64>| v.x.is_finite() && v.y.is_finite();
        let vectors = [self.eccentricity, self.eccentricity_rate, self.misalignment, self.misalignment_rate];
        if vectors.iter().all(finite) && self.journal_spin.is_finite() && self.bearing_spin.is_finite() {
            Ok(())
        } else {
            Err(format!("film kinematics must be finite, got {self:?}"))
        }
    }
}

/// Results of one solve for a tilted journal (SI units, bearing frame).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MisalignedFilmSolution {
    /// Force of the film on the journal [N].
    pub force_on_journal: Vector2<f64>,
    /// Moment of the film on the journal about the bearing's centre (the
    /// axis point at z = 0), its x and y components [N m]; the z component is
    /// the friction torque. `M = integral (z e_z) x f(z) dz = (-integral z f_y dz, integral z f_x dz)`
    /// with `f(z)` the force per unit length.
    pub moment_on_journal: Vector2<f64>,
    /// Largest pressure, gauge [Pa].
    pub peak_pressure: f64,
    /// Angle theta of the peak pressure [rad] in (-pi, pi].
    pub peak_pressure_angle: f64,
    /// Axial position of the peak pressure [m].
    pub peak_pressure_position: f64,
    /// Minimum film thickness `c - max(|e(-L/2)|, |e(L/2)|)` [m].
    pub min_film_thickness: f64,
    /// Shear torque on the journal about the bearing axis, counter-clockwise positive [N m].
    pub friction_torque: f64,
    /// Shear torque on the bearing about its axis, counter-clockwise positive [N m].
    pub bearing_friction_torque: f64,
    /// Power lost in the film, `-(T_j omega_j + T_b omega_b)` [W].
    pub power_loss: f64,
    /// Relaxation sweeps used [-].
    pub iterations: usize,
}

impl MisalignedFilmSolution {
    /// The solution of an aligned journal: its moment is zero by the mid-plane symmetry.
    pub fn from_aligned(s: &FilmSolution) -> Self {
        Self {
            force_on_journal: s.force_on_journal,
            moment_on_journal: Vector2::zeros(),
            peak_pressure: s.peak_pressure,
            peak_pressure_angle: s.peak_pressure_angle,
            peak_pressure_position: 0.0,
            min_film_thickness: s.min_film_thickness,
            friction_torque: s.friction_torque,
            bearing_friction_torque: s.bearing_friction_torque,
            power_loss: s.power_loss,
            iterations: s.iterations,
        }
    }

    /// The part every film model returns.
    pub fn film_force(&self) -> FilmForce {
        FilmForce {
            force_on_journal: self.force_on_journal,
            peak_pressure: self.peak_pressure,
            peak_pressure_angle: self.peak_pressure_angle,
            friction_torque: self.friction_torque,
        }
    }
}
