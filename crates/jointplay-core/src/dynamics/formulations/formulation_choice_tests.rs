//! The rule of `Formulation::Auto` on small models of each case it names, and
//! the choice and its reason as a run reports them.

use super::*;
use crate::dynamics::beam_tests::{free_beam, model};
use crate::dynamics::tests::bar_chain_spec as chain_spec;
use crate::dynamics::{assemble, simulate, SimulationOptions, Workspace};

/// A chain of `n` bars 0.1 m long hanging from a ground pin, each pinned to the
/// next; the first `clearance` pins are clearance joints instead.
fn chain(n: usize, clearance: usize) -> Model {
    model(chain_spec(n, clearance))
}

fn auto(m: &Model) -> FormulationChoice {
    choose_formulation(m, Formulation::Auto).expect("auto always chooses")
}

#[test]
fn a_small_tree_of_ideal_joints_runs_in_joint_coordinates_up_to_the_measured_size() {
    let small = auto(&chain(MAX_JOINT_COORDINATES, 0));
    assert_eq!(small.formulation, Formulation::JointCoordinates);
    assert_eq!(small.reason, "the ideal joints form a tree of 8 joint coordinates (at most 8), so no constraint equation is solved");
    let large = auto(&chain(MAX_JOINT_COORDINATES + 1, 0));
    assert_eq!(large.formulation, Formulation::Absolute);
    assert_eq!(
        large.reason,
        "the tree has 9 joint coordinates, more than 8, where its dense mass matrix costs more than the constraints it removes"
    );
}

#[test]
fn a_clearance_joint_counts_by_the_coordinates_of_the_body_it_frees() {
    // the first pin as a clearance joint frees bar0 (3 coordinates) and the others keep one
    // each: 6 bars give 8 coordinates, 7 bars 9, too many, where 7 ideal pins give 7
    assert_eq!(auto(&chain(6, 1)).formulation, Formulation::JointCoordinates);
    assert_eq!(auto(&chain(7, 0)).formulation, Formulation::JointCoordinates);
    assert!(auto(&chain(7, 1)).reason.starts_with("the tree has 9 joint coordinates"), "{}", auto(&chain(7, 1)).reason);
}

#[test]
fn bodies_held_by_clearance_joints_only_run_in_absolute_coordinates() {
    // no ideal joint: both forms integrate the same coordinates, joint coordinates only add a dense mass matrix
    let choice = auto(&chain(2, 2));
    assert_eq!(choice.formulation, Formulation::Absolute);
    assert!(choice.reason.starts_with("no ideal joint to remove"), "{}", choice.reason);
}

#[test]
fn a_flexible_body_runs_in_absolute_coordinates() {
    let choice = auto(&free_beam(2, 0.0));
    assert_eq!(choice.formulation, Formulation::Absolute);
    assert_eq!(choice.reason, "body \"beam\" is flexible (joint coordinates hold rigid bodies only)");
}

#[test]
fn a_loop_of_ideal_joints_runs_in_absolute_coordinates_and_refuses_joint_coordinates() {
    // the chain's last bar pinned back to the ground closes a loop
    let mut spec = chain_spec(2, 0);
    spec["ground_points"].as_array_mut().unwrap().push(serde_json::json!({"name": "Q", "position": [0.2, 0]}));
    spec["joints"].as_array_mut().unwrap().push(serde_json::json!({"type": "revolute", "name": "end", "first": "bar1.b", "second": "ground.Q"}));
    let looped = model(spec);
    let choice = auto(&looped);
    assert_eq!(choice.formulation, Formulation::Absolute);
    assert!(choice.reason.contains("closes a loop of ideal joints"), "{}", choice.reason);
    let refused = choose_formulation(&looped, Formulation::JointCoordinates).unwrap_err();
    assert!(refused.contains("closes a loop"), "{refused}");
}

#[test]
fn an_explicit_request_is_kept_whatever_the_rule_would_choose() {
    let large = chain(MAX_JOINT_COORDINATES + 1, 0);
    let asked = choose_formulation(&large, Formulation::JointCoordinates).unwrap();
    assert_eq!((asked.formulation, asked.reason.as_str()), (Formulation::JointCoordinates, "requested (9 joint coordinates)"));
    let asked = choose_formulation(&chain(2, 0), Formulation::Absolute).unwrap();
    assert_eq!((asked.formulation, asked.reason.as_str()), (Formulation::Absolute, "requested"));
}

#[test]
fn a_run_reports_the_formulation_it_integrated_and_why() {
    for n in [2, MAX_JOINT_COORDINATES + 1] {
        let m = chain(n, 0);
        let mut ws = Workspace::new(&m);
        let mut state = assemble(&m, 0.0, &mut ws).unwrap();
        let outcome = simulate(&m, &mut state, 0.01, &SimulationOptions::default(), None);
        assert!(outcome.error.is_none(), "{:?}", outcome.error);
        let rule = auto(&m);
        assert_eq!((outcome.formulation, &outcome.formulation_reason), (rule.formulation, &rule.reason), "{n} bars");
    }
}
