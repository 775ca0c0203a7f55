//! A planar mechanism with a clearance joint built from spatial bodies and
//! spatial joints against the planar engine: the dry slider-crank of Flores
//! et al. (the example `flores_slider_crank_dry`), its first impacts.

use super::*;
use crate::integrate::IntegratorOptions;
use crate::spec::ModelSpec;
use serde_json::{json, Value};
use std::path::PathBuf;

/// The description of the example `flores_slider_crank_dry` (the fixture its model file gives the core).
fn planar_flores() -> Value {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/fixtures/specs/toml_flores_slider_crank_dry.json");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str::<Value>(&text).expect("a fixture is JSON")["spec"].clone()
}

/// Marker axes whose z is the global x (columns of the rotation: x -> global y, y -> global z, z -> global x).
fn axes_along_x() -> Value {
    json!([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
}

/// `planar` (rigid bodies at angle 0, revolute joints, a guide along x, a
/// clearance joint and a driver) from spatial bodies in the plane z = 0: the
/// revolute joints turn about z, the guide is a spatial translational joint
/// along x, the clearance joint and the driver stay as they are. The
/// out-of-plane moments of inertia (chosen 1 % and 100 % of the planar one)
/// never act: the joints keep every body in the plane.
fn spatial_twin(planar: &Value) -> Value {
    let mut spec = planar.clone();
    let v3 = |v: &Value| json!([v[0], v[1], 0.0]);
    spec["gravity"] = v3(&planar["gravity"]);
    spec["ground_points"] = planar["ground_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| json!({"name": p["name"], "position": v3(&p["position"]), "axes": if p["name"] == "line" { axes_along_x() } else { Value::Null }}))
        .collect();
    spec["spatial_bodies"] = planar["bodies"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| {
            assert_eq!(b["angle"], 0.0, "the twin turns no body");
            let i = b["inertia"].as_f64().unwrap();
            let points: Vec<Value> = b["points"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| json!({"name": p["name"], "position": v3(&p["position"]), "axes": if b["name"] == "slider" { axes_along_x() } else { Value::Null }}))
                .collect();
            json!({"name": b["name"], "mass": b["mass"], "inertia": [[i / 100.0, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, i]],
                   "position": v3(&b["position"]), "orientation": [1.0, 0.0, 0.0, 0.0], "velocity": v3(&b["velocity"]),
                   "angular_velocity": [0.0, 0.0, b["angular_velocity"]], "points": points, "euler_sequence": "zyx"})
        })
        .collect();
    spec["bodies"] = json!([]);
    let (mut ideal, mut clearance) = (Vec::new(), Vec::new());
    for joint in planar["joints"].as_array().unwrap() {
        match joint["type"].as_str().unwrap() {
            "revolute" | "translational" => ideal.push(json!({"type": joint["type"], "name": joint["name"], "first": joint["first"], "second": joint["second"]})),
            "clearance_revolute" => clearance.push(joint.clone()),
            other => panic!("the twin builds no {other} joint"),
        }
    }
    spec["spatial_joints"] = Value::Array(ideal);
    spec["joints"] = Value::Array(clearance);
    spec["spatial_forces"] = json!([]);
    spec
}

fn compiled(spec: &Value) -> Model {
    let spec: ModelSpec = serde_json::from_value(spec.clone()).unwrap_or_else(|e| panic!("{e}"));
    compile(&spec).unwrap_or_else(|e| panic!("{e}"))
}

/// Runs `model` to `t_end` at `rtol` = `atol` = `tolerance`, sampled every `step`.
fn run(model: &Model, t_end: f64, tolerance: f64, step: f64) -> SimulationOutcome {
    let mut ws = Workspace::new(model);
    let mut state = assemble(model, 0.0, &mut ws).unwrap_or_else(|e| panic!("{e}"));
    let integrator = IntegratorOptions { rtol: tolerance, atol: tolerance, output_step: Some(step), ..Default::default() };
    let outcome = simulate(model, &mut state, t_end, &SimulationOptions { integrator, formulation: Formulation::Absolute, ..Default::default() }, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    outcome
}

/// The samples of the first contact period (channel `B.fn` positive).
fn first_contact_samples(t: &Trajectory) -> std::ops::Range<usize> {
    let force = t.channel("B.fn").unwrap();
    let onset = force.iter().position(|&f| f > 0.0).expect("an impact");
    onset..onset + force[onset..].iter().position(|&f| f == 0.0).expect("a rebound")
}

/// Onset time [s], peak normal force [N] and its time [s] of the first contact period.
fn first_impact(t: &Trajectory) -> (f64, f64, f64) {
    let (contact, force) = (first_contact_samples(t), t.channel("B.fn").unwrap());
    let peak = contact.clone().max_by(|&a, &b| force[a].total_cmp(&force[b])).unwrap();
    (t.time[contact.start], force[peak], t.time[peak])
}

#[test]
fn the_dry_slider_crank_from_spatial_bodies_has_the_planar_engines_first_impacts() {
    let planar = planar_flores();
    let (flat, solid) = (compiled(&planar), compiled(&spatial_twin(&planar)));
    assert!(solid.spatial && solid.bodies.iter().all(|b| matches!(b.kind, crate::body::BodyKind::SpatialRigid(_))));
    assert_eq!((flat.degrees_of_freedom(), solid.degrees_of_freedom()), (2, 2)); // the journal's two freedoms in its bearing
    // the first 5 ms (the first impact at 0.23 ms and those after it) sampled every microsecond, both
    // at tolerances 1e-12: what differs is the integration error of two sets of coordinates (at 1e-10
    // the peaks differ by 1e-8, at 1e-12 by 8e-12)
    let (flat_run, solid_run) = (run(&flat, 5e-3, 1e-12, 1e-6), run(&solid, 5e-3, 1e-12, 1e-6));
    let (a, b) = (&flat_run.trajectory, &solid_run.trajectory);
    assert_eq!(a.len(), b.len());
    let (onset_a, peak_a, at_a) = first_impact(a);
    let (onset_b, peak_b, at_b) = first_impact(b);
    assert_eq!((onset_a, at_a), (onset_b, at_b), "onset and peak on the same microsecond sample");
    assert!((peak_b - peak_a).abs() < 1e-9 * peak_a, "peak normal force {peak_b} N against {peak_a} N");
    assert_eq!(flat_run.diagnostics.impacts, solid_run.diagnostics.impacts);
    // the journal's path in its bearing and the joint force, through the first contact and over all 5 ms
    // (measured through the first contact: 2e-12 of the clearance, 8e-12 of the largest force; over
    // 5 ms, after the impacts amplify the integration error: 8e-7 and 1.4e-6)
    let clearance = planar["joints"][3]["clearance"].as_f64().expect("joint B's radial clearance");
    let largest = a.channel("B.f").unwrap().iter().fold(0.0_f64, |m, f| m.max(f.abs()));
    let first_contact = first_contact_samples(a);
    for (channel, scale) in [("B.ex", clearance), ("B.ey", clearance), ("B.fx", largest), ("B.fy", largest)] {
        let (x, y) = (a.channel(channel).unwrap(), b.channel(channel).unwrap());
        let worst = |range: std::ops::Range<usize>| range.map(|k| (x[k] - y[k]).abs()).fold(0.0, f64::max) / scale;
        let (first, all) = (worst(first_contact.clone()), worst(0..x.len()));
        assert!(first < 1e-9 && all < 1e-5, "{channel}: {first:e} of {scale:e} through the first contact, {all:e} over 5 ms");
    }
    // the bodies stay in the plane
    for body in ["crank", "rod", "slider"] {
        let z = b.channel(&format!("{body}.z")).unwrap();
        assert!(z.iter().all(|z| z.abs() < 1e-12), "{body} left the plane");
    }
}

#[test]
fn the_planar_clearance_joint_stops_a_run_whose_journal_tilts_out_of_the_plane() {
    // the twin with a spherical joint at A and the rod spinning about its own axis x: the journal tilts
    let mut spec = spatial_twin(&planar_flores());
    spec["spatial_joints"][1]["type"] = json!("spherical");
    spec["spatial_bodies"][1]["angular_velocity"] = json!([0.0, 5.0, 0.0]);
    let model = compiled(&spec);
    let mut ws = Workspace::new(&model);
    let mut state = assemble(&model, 0.0, &mut ws).unwrap_or_else(|e| panic!("{e}"));
    let outcome = simulate(&model, &mut state, 5e-3, &SimulationOptions::default(), None);
    match outcome.error {
        Some(crate::SimulationError::ElementOutOfRange { element, cause, time }) => {
            assert_eq!(element, "B");
            assert!(cause.contains("journal's frame tilted") && cause.contains("plane z = 0"), "{cause}");
            assert!(time > 0.0 && time < 1e-3, "stopped at {time} s, as soon as the tilt exceeds 1e-6 rad");
        }
        other => panic!("expected the tilt to stop the run, got {other:?}"),
    }
    assert!(!outcome.trajectory.is_empty(), "what was computed is kept");
}

/// The twin with the spatial clearance joint in place of the planar one: the
/// same bore, clearance, length, materials and laws, flanges with an axial
/// clearance of 1 mm (the journal stays in the plane: they never touch), a
/// bearing marker whose z is the global z.
fn spatial_joint_twin(planar: &Value) -> Value {
    let mut spec = spatial_twin(planar);
    for body in spec["spatial_bodies"].as_array_mut().unwrap() {
        let i = body["inertia"][1][1].clone();
        body["inertia"][0][0] = i;
    }
    let joint = spec["joints"][0].clone();
    assert_eq!(joint["bearing"], "slider.B", "the twin's bearing is the slider's point B");
    let slider = spec["spatial_bodies"].as_array_mut().unwrap().iter_mut().find(|b| b["name"] == "slider").unwrap();
    let at = slider["points"].as_array().unwrap().iter().find(|p| p["name"] == "B").unwrap()["position"].clone();
    slider["points"].as_array_mut().unwrap().push(json!({"name": "bore", "position": at}));
    spec["joints"] = json!([]);
    spec["spatial_clearance_joints"] = json!([{
        "type": "spatial_clearance_revolute", "name": joint["name"], "bearing": "slider.bore", "journal": joint["journal"],
        "bore_radius": joint["bearing_radius"], "clearance": joint["clearance"], "bearing_length": joint["length"],
        "axial_clearance": 1e-3, "flange_radius": 0.015, "face_radius": 0.016,
        "bearing_material": joint["bearing_material"], "journal_material": joint["journal_material"],
        "contact": joint["contact"], "stiffness": joint["stiffness"], "axial_stiffness": null, "friction": joint["friction"],
        "lock_at_assembly": true, "onset_velocity_floor": joint["onset_velocity_floor"], "max_penetration": null,
        "mode_impact_speed": 1e-3, "mode_impact_duration": 1e-3, "mode_sliding_speed": 5e-5,
    }]);
    spec
}

/// The spatial joint's normal force: the sum over its bore halves [N].
fn spatial_normal_force(t: &Trajectory) -> Vec<f64> {
    let (a, b) = (t.channel("B.fn_a").unwrap(), t.channel("B.fn_b").unwrap());
    a.iter().zip(b).map(|(a, b)| a + b).collect()
}

/// Onset time [s], peak force [N] and its time [s] of the first period where `force` is positive, and the
/// fraction of the samples with a positive force.
fn impact_of(time: &[f64], force: &[f64]) -> (f64, f64, f64, f64) {
    let onset = force.iter().position(|&f| f > 0.0).expect("an impact");
    let end = onset + force[onset..].iter().position(|&f| f == 0.0).expect("a rebound");
    let peak = (onset..end).max_by(|&a, &b| force[a].total_cmp(&force[b])).unwrap();
    let fraction = force.iter().filter(|&&f| f > 0.0).count() as f64 / force.len() as f64;
    (time[onset], force[peak], time[peak], fraction)
}

#[test]
fn the_spatial_clearance_joint_with_aligned_axes_reproduces_the_planar_joint() {
    // the dry Flores slider-crank built spatially with the spatial clearance joint (axes kept aligned by
    // the mechanism, no axial load) against the planar engine. The joint's goal is onset and peak within
    // 0.5 % and the contact fraction over the first 5 ms within a few percent; with aligned axes every
    // slice carries F(delta)/L and the sum is the planar law, so the runs agree to the integration error
    // (measured at 1e-10: the same onset and peak samples, the peak to 1e-8, the same contact fraction).
    // The twin's bodies get equal principal inertias: the redundant equations of the spatial loop (a
    // planar mechanism of spatial joints) are solved at assembly only when the inertias are within
    // about two orders of magnitude (docs/theory/spatial-clearance-revolute.md, "Limits").
    let planar = planar_flores();
    let (flat, solid) = (compiled(&planar), compiled(&spatial_joint_twin(&planar)));
    let (flat_run, solid_run) = (run(&flat, 5e-3, 1e-10, 1e-6), run(&solid, 5e-3, 1e-10, 1e-6));
    let (a, b) = (&flat_run.trajectory, &solid_run.trajectory);
    let (onset_a, peak_a, at_a, fraction_a) = impact_of(&a.time, &a.channel("B.fn").unwrap());
    let (onset_b, peak_b, at_b, fraction_b) = impact_of(&b.time, &spatial_normal_force(b));
    eprintln!("planar: onset {onset_a:e} s, peak {peak_a} N at {at_a:e} s, contact {fraction_a}");
    eprintln!("spatial: onset {onset_b:e} s, peak {peak_b} N at {at_b:e} s, contact {fraction_b}");
    assert_eq!((onset_b, at_b), (onset_a, at_a), "onset and peak on the same microsecond sample");
    assert!((peak_b - peak_a).abs() <= 1e-6 * peak_a, "peak {peak_b} N against {peak_a} N");
    assert!((fraction_b - fraction_a).abs() <= 1e-3 * fraction_a, "contact fraction {fraction_b} against {fraction_a}");
    // the mechanism keeps the axes aligned and the flanges free
    let tilt = b.channel("B.tilt").unwrap().iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    let flanges = [b.channel("B.fn_fa").unwrap(), b.channel("B.fn_fb").unwrap()];
    assert!(tilt < 1e-9 && flanges.iter().all(|f| f.iter().all(|&f| f == 0.0)), "tilt {tilt}");
}

