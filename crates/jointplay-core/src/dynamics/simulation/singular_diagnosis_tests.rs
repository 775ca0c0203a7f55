//! The toggle diagnosis on a slider-crank whose slider is driven outward through
//! the outer dead centre, where no crank angle follows the slider.

use super::*;
use crate::dynamics::starts::conditioning::relative_smallest_singular_value;
use crate::dynamics::tests::{clearance_joint_b_json, slider_crank_spec_json};
use crate::dynamics::{assemble, compile, simulate, SimulationOptions};
use crate::spec::ModelSpec;

/// The Flores slider-crank with its clearance joint B (rod/slider; ideal unless `clearance`), crank at 90 deg, the slider
/// pushed outward at 1 m/s from x = sqrt(120^2 - 50^2) mm: it reaches the outer dead centre
/// (170 mm) at t = 60.9 ms and is driven on beyond the linkage's reach.
pub(crate) fn slider_pushed_through_dead_centre(clearance: bool) -> Model {
    let mut spec = slider_crank_spec_json();
    let x = (0.12f64.powi(2) - 0.05f64.powi(2)).sqrt();
    spec["bodies"][0]["position"] = serde_json::json!([0.0, 0.025]);
    spec["bodies"][0]["angle"] = serde_json::json!(std::f64::consts::FRAC_PI_2);
    spec["bodies"][1]["position"] = serde_json::json!([x / 2.0, 0.025]);
    spec["bodies"][1]["angle"] = serde_json::json!((-0.05f64).atan2(x));
    spec["bodies"][2]["position"] = serde_json::json!([x, 0.0]);
    if clearance {
        spec["joints"][2] = clearance_joint_b_json(serde_json::json!({"law": "none"}), true);
    }
    spec["drivers"] = serde_json::json!([{"name": "push", "joint": "guide", "function": {"kind": "constant_rate", "initial": x, "rate": 1.0}}]);
    let spec: ModelSpec = serde_json::from_value(spec).expect("valid spec");
    compile(&spec).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_slider_driven_beyond_its_dead_centre_is_told_as_a_toggle_position() {
    let m = slider_pushed_through_dead_centre(true);
    let mut ws = Workspace::new(&m);
    let mut state = assemble(&m, 0.0, &mut ws).unwrap();
    let outcome = simulate(&m, &mut state, 0.1, &SimulationOptions::default(), None);
    let error = outcome.error.expect("the run cannot go beyond the dead centre");
    match error {
        SimulationError::SingularConfiguration { time, element, cause } => {
            assert_eq!(element, "push");
            assert!((0.055..0.065).contains(&time), "{time}");
            assert!(cause.contains("the driver pushes the linkage through a toggle (singular) position at t = 0.0619 s"), "{cause}");
            assert!(cause.contains("the penetration in B reached 0.475 mm, beyond its bound 0.475 mm"), "{cause}");
            assert!(!cause.contains("too soft"), "{cause}");
        }
        other => panic!("expected a toggle, got {other}"),
    }
}

#[test]
fn the_toggle_measure_is_small_only_near_the_dead_centre() {
    let m = slider_pushed_through_dead_centre(true);
    let mut ws = Workspace::new(&m);
    let state = assemble(&m, 0.0, &mut ws).unwrap();
    let all = m.constraints.len();
    let at_start = relative_smallest_singular_value(&m, all, 0.0, state.coordinates(), None, &mut ws);
    assert!(at_start > 10.0 * TOGGLE_RATIO, "{at_start}");
}

#[test]
fn the_same_slider_crank_with_ideal_joints_is_told_as_a_toggle_position_too() {
    let m = slider_pushed_through_dead_centre(false);
    let mut ws = Workspace::new(&m);
    let mut state = assemble(&m, 0.0, &mut ws).unwrap();
    let outcome = simulate(&m, &mut state, 0.1, &SimulationOptions::default(), None);
    match outcome.error.expect("the run cannot go beyond the dead centre") {
        SimulationError::SingularConfiguration { time, element, cause } => {
            assert_eq!(element, "push");
            assert!((0.0605..0.0615).contains(&time), "{time}");
            assert!(cause.contains("the driver pushes the linkage through a toggle (singular) position at t = 0.0609 s"), "{cause}");
            assert!(cause.contains("so the joints cannot follow the driver: the joints' equations could not be kept"), "{cause}");
        }
        other => panic!("expected a toggle, got {other}"),
    }
}
