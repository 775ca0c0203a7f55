//! Assembly that tells the truth: refusals of starts no description can mean,
//! notes on what assembly moved, and the cause of a failed assembly, each on a
//! micro-model whose numbers are known by hand.

use super::*;
use crate::dynamics::beam_tests::{model as beam_model, slider_crank as beam_slider_crank};
use crate::dynamics::tests::{clearance_joint_b_json, slider_crank_spec_json};
use crate::dynamics::{assemble, compile};
use crate::spec::ModelSpec;

fn model(json: serde_json::Value) -> Model {
    let spec: ModelSpec = serde_json::from_value(json).expect("valid spec");
    compile(&spec).unwrap_or_else(|e| panic!("{e}"))
}

/// A crank held at 90 deg (50 mm, from O at the origin to A) and a beam 100 mm long from A to a
/// ground pin P at (`reach` m, 50 mm): a rigid link closes the loop only at `reach` = 0.1.
fn beam_between_crank_and_ground(reach: f64) -> Model {
    beam_model(serde_json::json!({
        "name": "beam loop", "gravity": [0, 0],
        "ground_points": [{"name": "O", "position": [0, 0]}, {"name": "P", "position": [reach, 0.05]}],
        "bodies": [{"name": "crank", "mass": 0.1, "inertia": 1e-5, "position": [0.0, 0.025], "angle": std::f64::consts::FRAC_PI_2,
                    "velocity": [0, 0], "angular_velocity": 0,
                    "points": [{"name": "O", "position": [-0.025, 0]}, {"name": "A", "position": [0.025, 0]}]}],
        "beams": [{"name": "rod", "start": [0.0, 0.05], "end": [0.1, 0.05],
                   "section": {"type": "resultants", "axial_stiffness": 1.0e7, "shear_stiffness": 4.0e6, "bending_stiffness": 20.0,
                               "mass_per_length": 0.4, "rotary_inertia_per_length": 1e-6},
                   "mesh": {"order": "quadratic", "elements": 4, "element_length": null},
                   "damping_time": 0.0, "velocity": [0, 0], "angular_velocity": 0, "points": []}],
        "joints": [{"type": "revolute", "name": "O", "first": "ground.O", "second": "crank.O"},
                   {"type": "revolute", "name": "A", "first": "crank.A", "second": "rod.start"},
                   {"type": "revolute", "name": "B", "first": "rod.end", "second": "ground.P"}],
        "drivers": [{"name": "motor", "joint": "O", "function": {"kind": "constant_rate", "initial": std::f64::consts::FRAC_PI_2, "rate": 0.0}}],
        "forces": [], "sensors": []
    }))
}

/// The Flores slider-crank (crank 50 mm, rod 120 mm, 5000 rpm, gravity) with its clearance joint B
/// between rod and slider (bore 10 mm, clearance 0.5 mm), held at assembly when `lock`.
fn clearance_slider_crank_spec(lock: bool) -> serde_json::Value {
    let mut spec = slider_crank_spec_json();
    spec["gravity"] = serde_json::json!([0.0, -9.81]);
    spec["joints"][2] = clearance_joint_b_json(serde_json::json!({"law": "none"}), lock);
    spec["drivers"][0]["function"] = serde_json::json!({"kind": "constant_rate", "initial": 0.0, "rate": 5000.0 * std::f64::consts::PI / 30.0});
    spec
}

#[test]
fn a_beam_stretched_from_100_to_119_mm_to_close_its_loop_is_refused_with_the_strain() {
    let m = beam_between_crank_and_ground(0.119);
    let mut ws = Workspace::new(&m);
    match assemble(&m, 0.0, &mut ws) {
        Err(SimulationError::ImplausibleStart { element, cause, .. }) => {
            assert_eq!(element, "rod");
            assert!(cause.contains("stretches it from 100 mm to 119 mm between rod.start and rod.end, a strain of 19"), "{cause}");
            assert!(cause.contains("a rigid link of its given shape, which could not close the loop"), "{cause}");
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
}

#[test]
fn a_beam_stretched_by_a_fifth_of_a_percent_assembles_with_a_note() {
    let m = beam_between_crank_and_ground(0.1002);
    let mut ws = Workspace::new(&m);
    let state = assemble(&m, 0.0, &mut ws).expect("a strain of 0.2 % is within the refusal bound");
    let notes = assembly_notes(&m, 0.0, state.coordinates(), &mut ws);
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert_eq!((notes[0].name.as_str(), notes[0].on_body), ("rod", true));
    assert!(notes[0].message.contains("stretches it from 100.0 mm to 100.2 mm between rod.start and rod.end, a strain of 0.2"), "{}", notes[0].message);
    // the loop that needs no strain assembles without a note
    let m = beam_between_crank_and_ground(0.1);
    let state = assemble(&m, 0.0, &mut ws).unwrap();
    assert!(assembly_notes(&m, 0.0, state.coordinates(), &mut ws).is_empty());
}

#[test]
fn the_flexible_slider_crank_as_given_assembles_without_a_note() {
    let m = beam_slider_crank(Some(4));
    let mut ws = Workspace::new(&m);
    let state = assemble(&m, 0.0, &mut ws).unwrap();
    assert_eq!(assembly_notes(&m, 0.0, state.coordinates(), &mut ws), vec![]);
}

#[test]
fn a_driver_whose_initial_angle_contradicts_the_bodies_is_noted_with_the_bodies_it_moved() {
    let mut spec = slider_crank_spec_json();
    spec["drivers"][0]["function"] = serde_json::json!({"kind": "constant_rate", "initial": std::f64::consts::FRAC_PI_2, "rate": 10.0});
    let m = model(spec);
    let mut ws = Workspace::new(&m);
    let state = assemble(&m, 0.0, &mut ws).unwrap();
    let notes = assembly_notes(&m, 0.0, state.coordinates(), &mut ws);
    let motor = notes.iter().find(|n| n.name == "motor" && !n.on_body).expect("a note on the driver");
    assert!(motor.message.contains("differs by 90.0 deg from the relative angle its joint has between the bodies as given"), "{}", motor.message);
    // the crank's centre goes from (25, 0) to (0, 25) mm: 35.4 mm, and it turns 90 deg
    let crank = notes.iter().find(|n| n.name == "crank" && n.on_body).expect("a note on the crank");
    assert!(crank.message.contains("assembly moved it 35.4 mm and turned it 90.0 deg"), "{}", crank.message);
    // the slider is not turned and moves from 170 to sqrt(120^2 - 50^2) = 109 mm: 61 mm
    let slider = notes.iter().find(|n| n.name == "slider").expect("a note on the slider");
    assert!(slider.message.contains("assembly moved it 60.9 mm and turned it 0 deg from its given position and angle (to (109 mm, 0 mm) and 0 deg)"), "{}", slider.message);
}

#[test]
fn a_heavy_rod_that_defeats_the_mass_weighted_velocity_solve_is_not_called_locked() {
    // 250 kg m^2 for 250 kg mm^2: the joints are independent, the masses make the solve fail
    let mut spec = clearance_slider_crank_spec(true);
    spec["bodies"][1]["inertia"] = serde_json::json!(250.0);
    let m = model(spec);
    let mut ws = Workspace::new(&m);
    match assemble(&m, 0.0, &mut ws) {
        Err(SimulationError::ImplausibleStart { element, cause, .. }) => {
            assert_eq!(element, "rod");
            assert!(cause.contains("though the mechanism is not locked"), "{cause}");
            assert!(cause.contains("rod's inertia: 250 kg m^2, 6.94e4 kg at its 60.0 mm"), "{cause}");
            assert!(cause.contains("a unit slip in a mass or an inertia is the likely cause"), "{cause}");
            assert!(!cause.contains("is locked"), "{cause}");
        }
        other => panic!("unexpected {other:?}"),
    }
}

#[test]
fn a_journal_started_far_outside_its_clearance_is_refused_at_the_start() {
    // the clearance joint is not locked at assembly, and the slider is given 5 mm to the right of the
    // rod's end: a penetration of 4.5 mm against a bound of 5 % of the journal radius (0.475 mm)
    let mut spec = clearance_slider_crank_spec(false);
    spec["bodies"][2]["position"] = serde_json::json!([0.175, 0.0]);
    let m = model(spec);
    let mut ws = Workspace::new(&m);
    match assemble(&m, 0.0, &mut ws) {
        Err(SimulationError::ImplausibleStart { element, cause, .. }) => {
            assert_eq!(element, "B");
            assert!(cause.contains("the start position puts the journal 4.50 mm into its bearing (eccentricity 5.00 mm, clearance 0.500 mm)"), "{cause}");
            assert!(cause.contains("not the contact law or the step"), "{cause}");
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
}

#[test]
fn numbers_are_written_to_three_significant_digits() {
    assert_eq!(significant(119.0), "119");
    assert_eq!(significant(0.2), "0.200");
    assert_eq!(significant(35.355), "35.4");
    assert_eq!(mm(0.0005), "0.500 mm");
    assert_eq!(significant(2.5e-5), "2.50e-5");
}

#[test]
fn a_beam_given_600_mm_from_its_pin_is_moved_there_whole_not_stretched() {
    // the mass-weighted Newton alone moves the pinned end and drags the rest: 300 mm became 665 mm
    let m = beam_model(serde_json::json!({
        "name": "far beam", "gravity": [0, 0], "ground_points": [{"name": "hub", "position": [0.3, -0.3]}], "bodies": [],
        "beams": [{"name": "flex", "start": [0.3, 0.3], "end": [0.6, 0.3],
                   "section": {"type": "resultants", "axial_stiffness": 1.0e7, "shear_stiffness": 4.0e6, "bending_stiffness": 20.0,
                               "mass_per_length": 0.4, "rotary_inertia_per_length": 1e-6},
                   "mesh": {"order": "quadratic", "elements": 3, "element_length": null},
                   "damping_time": 0.0, "velocity": [0, 0], "angular_velocity": 0, "points": []}],
        "joints": [{"type": "revolute", "name": "pin", "first": "ground.hub", "second": "flex.start"}],
        "drivers": [], "forces": [], "sensors": []
    }));
    let mut ws = Workspace::new(&m);
    let state = assemble(&m, 0.0, &mut ws).expect("a rigid translation closes the joint");
    let q = state.coordinates();
    let n = q.len();
    // first node at the hub, last node 300 mm to its right: translated by -600 mm, unstretched
    assert!((q[0] - 0.3).abs() < 1e-12 && (q[1] + 0.3).abs() < 1e-12, "{q:?}");
    assert!((q[n - 3] - 0.6).abs() < 1e-9 && (q[n - 2] + 0.3).abs() < 1e-9, "{q:?}");
    let notes = assembly_notes(&m, 0.0, q, &mut ws);
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert!(notes[0].message.starts_with("assembly moved it 600 mm and turned it 0 deg"), "{}", notes[0].message);
}
