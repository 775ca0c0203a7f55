//! The outcome of a run: the state it returns, and the summary tracked at
//! every accepted step whatever the output sampling.

use crate::dynamics::tests::clearance_slider_crank;
use super::*;
use crate::dynamics::assemble;
use std::f64::consts::PI;

/// Crank speed of `clearance_slider_crank` [rad/s].
const OMEGA: f64 = 5000.0 * PI / 30.0;

/// Runs the dry clearance slider-crank to `t_end` with the given output step and step limit.
fn run(t_end: f64, output_step: Option<f64>, max_steps: usize) -> (Model, State, SimulationOutcome) {
    let model = clearance_slider_crank();
    let mut ws = Workspace::new(&model);
    let mut state = assemble(&model, 0.0, &mut ws).unwrap();
    let mut options = SimulationOptions::default();
    options.integrator.output_step = output_step;
    options.integrator.max_steps = max_steps;
    let outcome = simulate(&model, &mut state, t_end, &options, None);
    (model, state, outcome)
}

#[test]
fn a_failed_run_returns_the_time_and_coordinates_of_its_last_accepted_step() {
    // samples every 10 ms: the last one is at t = 0 when the step limit stops the run
    let (_, state, outcome) = run(0.012, Some(0.01), 300);
    let error = outcome.error.expect("the step limit stops the run");
    assert!(matches!(error, SimulationError::TooManySteps { max_steps: 300, .. }), "{error:?}");
    assert_eq!(outcome.trajectory.time, vec![0.0]);
    assert!(state.time > 0.0 && state.time == error.time(), "state at {}, error at {}", state.time, error.time());
    // the driven crank angle is omega t: the coordinates belong to state.time
    let crank_angle = state.coordinates()[2];
    assert!((crank_angle - OMEGA * state.time).abs() < 1e-8, "angle {crank_angle}, omega t {}", OMEGA * state.time);
    assert_eq!(outcome.extrema.steps, 300 - outcome.statistics.rejected_steps);
    assert_eq!(outcome.extrema.t_end, state.time);
}

#[test]
fn a_completed_run_returns_the_state_at_t_end() {
    let (_, state, outcome) = run(0.002, Some(1e-3), 10_000_000);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    assert_eq!(state.time, 0.002);
    assert!((state.coordinates()[2] - OMEGA * 0.002).abs() < 1e-8);
}

#[test]
fn tracked_peaks_do_not_depend_on_the_output_step_and_bound_every_sample() {
    let (model, _, every_step) = run(0.004, None, 10_000_000);
    let (_, _, fine) = run(0.004, Some(1e-6), 10_000_000);
    let (_, _, coarse) = run(0.004, Some(1e-3), 10_000_000);
    let tracked: Vec<usize> = (0..model.channels.len()).filter(|&c| is_peak_unit(model.channels[c].info.unit)).collect();
    assert_eq!(every_step.extrema.channels.len(), tracked.len());
    for (k, peak) in every_step.extrema.channels.iter().enumerate() {
        for other in [&fine.extrema.channels[k], &coarse.extrema.channels[k]] {
            assert_eq!(other.name, peak.name);
            assert!((other.peak - peak.peak).abs() <= 1e-3 * peak.peak.max(1e-9), "{}: {} vs {}", peak.name, other.peak, peak.peak);
        }
        // no sample of the 1 us output exceeds the tracked peak
        let sampled = fine.trajectory.channel(&peak.name).unwrap().iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(sampled <= fine.extrema.channels[k].peak * (1.0 + 1e-9), "{}: sampled {sampled}, tracked {}", peak.name, fine.extrema.channels[k].peak);
    }
    let joint = &every_step.extrema.clearance_joints[0];
    assert!(joint.impacts >= 1 && joint.contact_time > 0.0, "{joint:?}");
    for other in [&fine.extrema.clearance_joints[0], &coarse.extrema.clearance_joints[0]] {
        assert!((other.max_penetration - joint.max_penetration).abs() <= 1e-3 * joint.max_penetration);
        assert!((other.contact_time - joint.contact_time).abs() <= 5e-3 * joint.contact_time);
    }
    // the contact force peaks inside a step: above the largest step-end sample
    let fn_peak = every_step.extrema.channels.iter().find(|c| c.name == "B.fn").unwrap();
    let sampled = every_step.trajectory.channel("B.fn").unwrap().iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(fn_peak.peak > sampled, "tracked {}, step ends {sampled}", fn_peak.peak);
}

#[test]
fn tracked_point_acceleration_of_the_crank_pin_is_the_centripetal_closed_form() {
    // the crank turns at constant omega: its pin A, 0.05 m from O, accelerates at omega^2 0.05 throughout
    let (_, _, outcome) = run(0.004, Some(1e-3), 10_000_000);
    let pin = outcome.extrema.point_accelerations.iter().find(|p| p.name == "crank.A").expect("crank.A tracked");
    let expected = OMEGA * OMEGA * 0.05;
    assert!((pin.peak - expected).abs() < 1e-6 * expected, "{} vs {expected}", pin.peak);
    // the slider's point B is its centre: its peak is that of |(ax, ay)| of a fine output, from above
    let (_, _, fine) = run(0.004, Some(1e-6), 10_000_000);
    let (ax, ay) = (fine.trajectory.channel("slider.ax").unwrap(), fine.trajectory.channel("slider.ay").unwrap());
    let sampled = ax.iter().zip(&ay).fold(0.0f64, |m, (x, y)| m.max(x.hypot(*y)));
    let slider = fine.extrema.point_accelerations.iter().find(|p| p.name == "slider.B").unwrap();
    assert!(sampled <= slider.peak * (1.0 + 1e-9) && sampled >= slider.peak * (1.0 - 1e-3), "sampled {sampled}, tracked {}", slider.peak);
}

#[test]
fn a_run_without_steps_has_no_extrema() {
    let (_, state, outcome) = run(0.0, None, 10_000_000);
    assert!(outcome.error.is_none());
    assert_eq!((state.time, outcome.extrema.steps), (0.0, 0));
    assert!(outcome.extrema.channels.is_empty() && outcome.extrema.point_accelerations.is_empty());
    let joint = &outcome.extrema.clearance_joints[0];
    assert_eq!((joint.impacts, joint.contact_time, joint.max_penetration), (0, 0.0, 0.0));
    assert!(joint.max_eccentricity_ratio.is_nan() && joint.max_penetration_time.is_nan());
}

#[test]
fn projection_tolerance_is_a_tenth_of_atol_between_its_floor_and_ceiling() {
    let with = |rtol: f64, atol: f64| {
        let mut options = SimulationOptions::default();
        options.integrator.rtol = rtol;
        options.integrator.atol = atol;
        options.projection_tolerance()
    };
    // the default atol 1e-9 keeps the earlier fixed 1e-10
    assert_eq!(SimulationOptions::default().projection_tolerance(), 1e-10);
    assert_eq!(with(1e-10, 1e-12), 0.1 * 1e-12);
    assert_eq!(with(1e-8, 1e-10), 0.1 * 1e-10);
    // a loose atol does not loosen it; an atol below round-off meets the floor
    assert_eq!(with(1e-3, 1e-6), PROJECTION_CEILING);
    assert_eq!(with(1e-12, 1e-16), PROJECTION_FLOOR);
    // atol 0: rtol of coordinates of order 1 m
    assert_eq!(with(1e-12, 0.0), 0.1 * 1e-12);
    // given: as given
    let given = SimulationOptions { position_tolerance: Some(3e-9), ..SimulationOptions::default() };
    assert_eq!(given.projection_tolerance(), 3e-9);
}

#[test]
fn the_run_reports_its_projection_tolerance_and_the_largest_residual_left() {
    // in absolute coordinates (joint coordinates need no projection)
    let model = clearance_slider_crank();
    let mut state = assemble(&model, 0.0, &mut Workspace::new(&model)).unwrap();
    let options = SimulationOptions { formulation: Formulation::Absolute, ..SimulationOptions::default() };
    let outcome = simulate(&model, &mut state, 0.002, &options, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    let d = &outcome.diagnostics;
    assert_eq!(d.projection_tolerance, 1e-10);
    // a regular slider-crank: every projection meets the tolerance
    assert!(d.max_projection_residual > 0.0 && d.max_projection_residual <= 1e-10, "{}", d.max_projection_residual);
    assert!(d.max_projection_residual_time > 0.0 && d.max_projection_residual_time <= 0.002);
}
