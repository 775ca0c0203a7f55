use super::*;
use crate::kinematics::spatial::{Mat3, SpatialFrame};
use crate::lubrication::reynolds::ReynoldsOptions;
use crate::lubrication::transition::TransitionLaw;
use crate::lubrication::BearingGeometry;
use nalgebra::{Rotation3, Unit};

fn rotation(axis: Vec3, angle: f64) -> Mat3 {
    *Rotation3::from_axis_angle(&Unit::new_normalize(axis), angle).matrix()
}

/// A bearing frame turned and moving in space, and a journal tilted in it, both moving.
fn frames() -> (SpatialFrame, SpatialFrame) {
    let bearing = SpatialFrame { position: Vec3::new(0.1, -0.2, 0.05), rotation: rotation(Vec3::new(1.0, 2.0, 0.5), 0.7), velocity: Vec3::new(0.3, -0.1, 0.2), angular_velocity: Vec3::new(0.5, -1.0, 2.0) };
    let offset = bearing.rotate(Vec3::new(1.2e-4, -0.8e-4, 3e-4));
    let journal = SpatialFrame {
        position: bearing.position + offset,
        rotation: rotation(Vec3::new(0.3, -1.0, 0.0), 2e-3) * bearing.rotation,
        velocity: Vec3::new(0.31, -0.12, 0.19),
        angular_velocity: Vec3::new(0.6, -0.9, 40.0),
    };
    (bearing, journal)
}

/// `frame` moved on by `dt` [s] at its velocities.
fn advanced(frame: &SpatialFrame, dt: f64) -> SpatialFrame {
    let w = frame.angular_velocity;
    let turn = if w.norm() > 0.0 { rotation(w, w.norm() * dt) } else { Mat3::identity() };
    SpatialFrame { position: frame.position + frame.velocity * dt, rotation: turn * frame.rotation, ..*frame }
}

#[test]
fn the_film_kinematics_cut_the_journal_axis_at_each_section_and_their_rates_are_their_derivatives() {
    let (bearing, journal) = frames();
    let k = misaligned_kinematics(&JointPose::new(&bearing, &journal));
    // e(z) is where the journal axis crosses the section plane z of the bearing
    for z in [-0.01, 0.0, 0.02] {
        let local = |p: Vec3| bearing.to_local(p - bearing.position);
        let (o, u) = (local(journal.position), bearing.to_local(journal.axis(2)));
        let crossing = o + u * ((z - o.z) / u.z);
        assert!((k.eccentricity + k.misalignment * z - crossing.xy()).norm() < 1e-15, "section {z}");
    }
    // rates: central differences of e0 and tau with both frames moving
    let dt = 1e-7;
    let at = |dt: f64| misaligned_kinematics(&JointPose::new(&advanced(&bearing, dt), &advanced(&journal, dt)));
    let (after, before) = (at(dt), at(-dt));
    let e0_rate = (after.eccentricity - before.eccentricity) / (2.0 * dt);
    let tau_rate = (after.misalignment - before.misalignment) / (2.0 * dt);
    assert!((k.eccentricity_rate - e0_rate).norm() < 1e-7 * e0_rate.norm().max(1e-3), "{:?} against {e0_rate:?}", k.eccentricity_rate);
    assert!((k.misalignment_rate - tau_rate).norm() < 1e-6 * tau_rate.norm(), "{:?} against {tau_rate:?}", k.misalignment_rate);
    assert!((k.journal_spin - journal.angular_velocity.dot(&bearing.axis(2))).abs() < 1e-15);
}

#[test]
fn a_tilted_journal_gets_the_misaligned_reynolds_force_and_moment_turned_into_space() {
    // the film of reynolds_exact at a tilted pose is the full-length solution of the same kinematics,
    // turned from bearing coordinates into space; its moment about the bore's centre adds the axial
    // moment of the pressure acting through the tilted axis
    let geometry = BearingGeometry { radius: 0.0095, length: 0.02, clearance: 5e-4, viscosity: 0.4 };
    let options = ReynoldsOptions::default();
    let lubrication = Lubrication { geometry, model: FilmModel::ReynoldsExact(options), transition: TransitionLaw::Switch };
    let (bearing, journal) = frames();
    let pose = JointPose::new(&bearing, &journal);
    let mut solver = ReynoldsSolver::new(geometry, options).unwrap();
    let film = evaluate(&lubrication, &pose, geometry.length, Some(&mut solver), true).unwrap();
    let mut reference = ReynoldsSolver::new(geometry, options).unwrap();
    let k = misaligned_kinematics(&pose);
    let direct = reference.solve_misaligned(&k).unwrap();
    let f = bearing.to_local(film.force_on_journal);
    assert!((f.xy() - direct.force_on_journal).norm() < 1e-9 * direct.force_on_journal.norm() && f.z.abs() < 1e-9 * f.norm());
    let m = bearing.to_local(film.moment_on_journal);
    assert!((m.xy() - direct.moment_on_journal).norm() < 1e-9 * direct.moment_on_journal.norm());
    assert!(direct.moment_on_journal.norm() > 0.0 && film.weight == 1.0 && film.peak_pressure == direct.peak_pressure);
}
