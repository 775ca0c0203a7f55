//! The element contract (`crate::element::ElementModel`) as the engine uses
//! it: the clearance joint's event function, memory, acceptance and outputs
//! through the contract, events and memory slots of several elements routed
//! to their own element in a run, and an element's several events and slots
//! addressed by their offsets.

use crate::kinematics::marker::BodyIndex;
use crate::kinematics::planar::Frame;
use super::*;
use crate::element::{ElementFault, ElementKind, ElementMemory, ElementModel, ElementWork};
use crate::kinematics::frames::Frames;
use crate::joint::ContactMemory;
use crate::spec::ModelSpec;

/// Two free bars in the plane without gravity: `upper` hangs in clearance
/// joint A (radial clearance 1 mm) from the ground, `lower` in clearance joint B
/// (0.1 mm) from `upper`; a zero torque acts on `lower`. `lower` starts moving
/// at 0.05 m/s along x, so B closes within about 2 ms while A, with ten times
/// the clearance, stays open for the 5 ms run.
fn two_clearance_joints() -> Model {
    let joint = |name: &str, bearing: &str, journal: &str, clearance: f64| {
        serde_json::json!({
            "type": "clearance_revolute", "name": name, "bearing": bearing, "journal": journal,
            "bearing_radius": 0.01, "clearance": clearance, "length": 0.02,
            "bearing_material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3},
            "journal_material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3},
            "contact": {"law": "lankarani_nikravesh", "restitution": 0.9}, "stiffness": {"law": "hertz_cylinder"},
            "friction": {"law": "ambrosio", "coefficient": 0.1, "v0": 1e-4, "v1": 1e-3},
            "initial_eccentricity": [0.0, 0.0], "lock_at_assembly": false, "onset_velocity_floor": 1e-4,
            "max_penetration": null, "lubrication": null})
    };
    let spec = serde_json::json!({
        "name": "two clearance joints", "gravity": [0, 0],
        "ground_points": [{"name": "O", "position": [0, 0]}],
        "bodies": [
          {"name": "upper", "mass": 1.0, "inertia": 0.01, "position": [0.0, -0.1], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
            "points": [{"name": "top", "position": [0, 0.1]}, {"name": "bottom", "position": [0, -0.1]}]},
          {"name": "lower", "mass": 0.5, "inertia": 0.005, "position": [0.0, -0.3], "angle": 0, "velocity": [0.05, 0], "angular_velocity": 0,
            "points": [{"name": "top", "position": [0, 0.1]}]}],
        "joints": [joint("A", "ground.O", "upper.top", 1e-3), joint("B", "upper.bottom", "lower.top", 1e-4)],
        "drivers": [],
        "beams": [], "sensors": [], "forces": [{"type": "torque", "name": "idle", "body": "lower", "torque": {"kind": "constant", "value": 0.0}}]});
    let spec: ModelSpec = serde_json::from_value(spec).expect("valid spec");
    compile(&spec).unwrap_or_else(|e| panic!("{e}"))
}

fn frame(x: f64, y: f64, angle: f64, vx: f64, vy: f64, omega: f64) -> Frame {
    Frame::from_coordinates(&[x, y, angle], &[vx, vy, omega])
}

#[test]
fn events_and_memory_of_several_elements_go_to_their_own_element() {
    let model = two_clearance_joints();
    // the elements in description order, each with its events
    let names: Vec<&str> = model.elements.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(names, ["A", "B", "idle"]);
    assert_eq!(model.acting, [0, 1, 2]);
    assert_eq!(model.event_offsets, [0, 1, 2, 2]);
    assert_eq!(model.memory_offsets, [0, 1, 2, 2]);
    assert_eq!(model.event_bodies, [BodyIndex(1), BodyIndex(2)]);
    let mut ws = Workspace::new(&model);
    let mut state = assemble(&model, 0.0, &mut ws).unwrap();
    let outcome = simulate(&model, &mut state, 5e-3, &SimulationOptions::default(), None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    // B's onsets were located on its event and counted in its memory; A never touched
    let impacts_b = outcome.diagnostics.impacts[1];
    assert_eq!(outcome.diagnostics.impacts[0], 0);
    assert!(impacts_b >= 1);
    assert_eq!(state.memory[model.memory_of(0)], [ElementMemory::Contact(ContactMemory::default())]);
    assert!(matches!(state.memory[model.memory_of(1)], [ElementMemory::Contact(m)] if m.impacts == impacts_b));
    assert!(state.memory[model.memory_of(2)].is_empty() && state.memory.len() == 2);
    // the summary reads each joint's own gap
    let [a, b] = &outcome.extrema.clearance_joints[..] else { panic!("two joints") };
    assert_eq!((a.name.as_str(), a.impacts, a.contact_time, a.max_penetration), ("A", 0, 0.0, 0.0));
    assert!(a.max_eccentricity_ratio < 0.5, "A stays open: {}", a.max_eccentricity_ratio);
    assert_eq!((b.name.as_str(), b.impacts), ("B", impacts_b));
    assert!(b.contact_time > 0.0 && b.max_penetration > 0.0);
    let contact = |name: &str| {
        let c = outcome.trajectory.channels.iter().position(|c| c.name == name).unwrap();
        (0..outcome.trajectory.len()).map(|k| outcome.trajectory.value(c, k)).sum::<f64>()
    };
    assert_eq!(contact("A.contact"), 0.0);
    assert!(contact("B.contact") > 0.0);
}

#[test]
fn contact_forces_through_the_element_contract_conserve_linear_momentum() {
    // no gravity and A open: the only force is B's contact, equal and opposite on the two
    // bars, so their total linear momentum is an invariant, kept by Runge-Kutta methods exactly
    // up to round-off (a linear invariant of the right-hand side)
    let model = two_clearance_joints();
    let mut ws = Workspace::new(&model);
    let mut state = assemble(&model, 0.0, &mut ws).unwrap();
    let outcome = simulate(&model, &mut state, 5e-3, &SimulationOptions::default(), None);
    assert!(outcome.error.is_none());
    let t = &outcome.trajectory;
    let channel = |name: &str| t.channels.iter().position(|c| c.name == name).unwrap();
    let (ux, uy, lx, ly) = (channel("upper.vx"), channel("upper.vy"), channel("lower.vx"), channel("lower.vy"));
    let mut exchanged: f64 = 0.0;
    for k in 0..t.len() {
        let px = 1.0 * t.value(ux, k) + 0.5 * t.value(lx, k);
        let py = 1.0 * t.value(uy, k) + 0.5 * t.value(ly, k);
        assert!((px - 0.025).abs() < 1e-13 && py.abs() < 1e-13, "momentum ({px}, {py}) at sample {k}");
        exchanged = exchanged.max(t.value(ux, k).abs());
    }
    assert!(exchanged > 1e-3, "the impact moved the upper bar: {exchanged} m/s");
}

#[test]
fn the_clearance_joint_as_an_element_reports_its_event_memory_and_outputs() {
    let model = two_clearance_joints();
    let element = &model.elements[1].kind;
    let ElementKind::ClearanceRevolute(joint) = element else { panic!("B is a clearance joint") };
    assert_eq!((element.n_events(), element.n_memory_slots(), element.n_states(), element.channels().len()), (1, 1, 0, 12));
    // upper at rest; lower's journal (its top point) 0.1 mm + 2 um right of the bearing, approaching
    let depth = 2e-6;
    let mut frames = vec![Frame::GROUND, frame(0.0, -0.1, 0.0, 0.0, 0.0, 0.0), frame(1e-4 + depth, -0.3, 0.0, 0.03, 0.0, -0.2)];
    let (mut g, mut rate) = ([0.0], [0.0]);
    element.event_functions(&Frames { planar: &frames, spatial: &[] }, &mut g, Some(&mut rate));
    assert!((g[0] - depth).abs() < 1e-15, "event function {} against the penetration {depth}", g[0]);
    // its rate against a central difference of the gap along the motion
    let h = 1e-7;
    let moved = |s: f64| {
        let mut f = frames.clone();
        f[2] = frame(1e-4 + depth + 0.03 * s, -0.3, -0.2 * s, 0.03, 0.0, -0.2);
        let mut g = [0.0];
        element.event_functions(&Frames { planar: &f, spatial: &[] }, &mut g, None);
        g[0]
    };
    assert!((rate[0] - (moved(h) - moved(-h)) / (2.0 * h)).abs() < 1e-8, "rate {}", rate[0]);
    // the first accepted step in contact latches the onset velocity and counts an impact, once
    let mut memory = [ElementMemory::None];
    element.start_memory(&mut memory);
    assert_eq!(memory, [ElementMemory::Contact(ContactMemory::default())]);
    let first = element.accept(&Frames { planar: &frames, spatial: &[] }, 0.0, &mut memory).unwrap();
    assert!(first.memory_changed && first.penetration == g[0] && !first.deep_penetration);
    let [ElementMemory::Contact(latched)] = memory else { panic!("contact memory") };
    assert_eq!(latched.impacts, 1);
    assert_eq!(latched.onset_velocity, Some(joint.onset_velocity(&frames)));
    assert!(!element.accept(&Frames { planar: &frames, spatial: &[] }, 0.0, &mut memory).unwrap().memory_changed);
    // the outputs read the latched memory through apply
    let mut work = element.new_work();
    let mut q = vec![0.0; model.n_velocities()];
    let frames3 = Frames { planar: &frames, spatial: &[] };
    let mut forces = GeneralisedForces::new(&mut q, &model.bodies, &model.layout, frames3);
    element.apply(&frames3, 0.0, (&[], &mut []), &memory, &mut work, false, &mut forces).unwrap();
    let direct = joint.evaluate(&frames, latched.onset_velocity);
    let names: Vec<&str> = element.channels().iter().map(|c| c.0).collect();
    let out = |name: &str| element.output(names.iter().position(|n| *n == name).unwrap(), &frames, &work);
    assert!(direct.in_contact && direct.normal_force > 0.0);
    assert_eq!((out("fn"), out("ft"), out("fx"), out("contact")), (direct.normal_force, direct.friction_force, direct.force_on_journal.x, 1.0));
    assert!((0..names.len()).all(|k| element.output(k, &frames, &work).is_finite()));
    assert!(work.is_finite() && element.potential_energy(&work) > 0.0);
    // equal and opposite forces on the two bars (Newton's third law through the contract)
    assert!((q[0] + q[3]).abs() < 1e-12 * q[3].abs() && (q[1] + q[4]).abs() < 1e-12 * q[3].abs(), "{q:?}");
    assert!(matches!(&work, ElementWork::Clearance(w) if w.contact == direct));
    // free again: the onset velocity is cleared, the impacts stay counted
    frames[2] = frame(0.0, -0.3, 0.0, 0.0, 0.0, 0.0);
    assert!(element.accept(&Frames { planar: &frames, spatial: &[] }, 0.0, &mut memory).unwrap().memory_changed);
    assert_eq!(memory, [ElementMemory::Contact(ContactMemory { onset_velocity: None, impacts: 1 })]);
    // a penetration beyond the bound stops with the depth and the bound
    frames[2] = frame(1e-4 + 2.0 * joint.max_penetration, -0.3, 0.0, 0.0, 0.0, 0.0);
    let fault = element.accept(&Frames { planar: &frames, spatial: &[] }, 0.0, &mut memory).unwrap_err();
    assert!(matches!(fault, ElementFault::ExcessivePenetration { penetration, bound } if bound == joint.max_penetration && penetration > bound));
}

#[test]
fn elements_without_events_or_memory_keep_none() {
    let model = two_clearance_joints();
    let idle = &model.elements[2].kind;
    let frames = vec![Frame::GROUND; 3];
    let frames = Frames { planar: &frames, spatial: &[] };
    assert_eq!((idle.n_events(), idle.n_memory_slots(), idle.constraints()), (0, 0, 0..0));
    let mut memory: [ElementMemory; 0] = [];
    assert_eq!(idle.accept(&frames, 0.0, &mut memory).unwrap(), Default::default());
    idle.on_event(&frames, 0.0, 0, &mut memory);
}

#[test]
fn an_elements_several_events_and_memory_slots_are_addressed_by_its_offsets() {
    // the offsets as the compiler lays them out for elements with 3, 0 and 2
    // events and 2, 0 and 3 memory slots: each event and slot belongs to one element
    let mut model = two_clearance_joints();
    model.event_offsets = vec![0, 3, 3, 5];
    model.memory_offsets = vec![0, 2, 2, 5];
    let owners: Vec<(usize, usize)> = (0..5).map(|event| model.event_owner(event)).collect();
    assert_eq!(owners, [(0, 0), (0, 1), (0, 2), (2, 0), (2, 1)]);
    assert_eq!((model.events_of(1), model.memory_of(0), model.memory_of(1), model.memory_of(2)), (3..3, 0..2, 2..2, 2..5));
    // impacts are counted over an element's slots
    let contact = |impacts| ElementMemory::Contact(ContactMemory { onset_velocity: None, impacts });
    let memory = [contact(1), contact(2), contact(4), ElementMemory::None, contact(8)];
    assert_eq!((model.impacts(0, &memory), model.impacts(1, &memory), model.impacts(2, &memory)), (3, 0, 12));
}
