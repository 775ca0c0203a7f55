//! The structured Jacobian (`jacobian.rs`) checked against what it replaces:
//! the colouring against the contributions' reads, the coloured differences
//! of the local forces against column-by-column differences of the whole
//! applied force, the Jacobian against forward differences of the whole
//! right-hand side (equal where A = M^-1, different by exactly the neglected
//! terms under constraints), and runs with it against runs with forward differences.

use crate::body::BodyModel;
use crate::dynamics::beam_tests::{deformed, free_beam, model, slider_crank, spin_up_beam};
use super::equations::{applied_forces, constrained_accelerations, update_frames};
use super::jacobian::{Contribution, StructuredJacobian};
use crate::dynamics::*;
use crate::element::ElementMemory;
use crate::integrate::{IntegratorOptions, JacobianMethod, Method, Statistics};

/// A beam (damped, three quadratic elements) pinned to the ground, a block
/// hanging in a clearance joint at its end, a spring from the ground to its
/// middle, a hydraulic cylinder (two pressure states) from the ground to the
/// block, a point force on the beam and a torsional spring between beam and block.
pub(super) fn mixed() -> Model {
    model(serde_json::json!({
        "name": "mixed", "gravity": [0, -9.81],
        "ground_points": [{"name": "O", "position": [0, 0]}, {"name": "C", "position": [0.6, -0.5]}, {"name": "S", "position": [0.4, 0.5]}],
        "bodies": [{"name": "block", "mass": 2.0, "inertia": 0.02, "position": [1.2, 0.0], "angle": 0.1, "velocity": [0.1, -0.2], "angular_velocity": 1.0,
                    "points": [{"name": "J", "position": [-0.2, 0.0]}, {"name": "P", "position": [0.1, 0.05]}]}],
        "beams": [{"name": "arm", "start": [0.0, 0.0], "end": [1.0, 0.0],
                   "section": {"type": "resultants", "axial_stiffness": 2.0e6, "shear_stiffness": 8.0e5, "bending_stiffness": 600.0,
                               "mass_per_length": 1.5, "rotary_inertia_per_length": 2.0e-4},
                   "mesh": {"order": "quadratic", "elements": 3, "element_length": null},
                   "damping_time": 1.0e-4, "velocity": [0, 0.2], "angular_velocity": 0.5, "points": [{"name": "mid", "arclength": 0.45}]}],
        "joints": [{"type": "revolute", "name": "root", "first": "ground.O", "second": "arm.start"},
                   {"type": "clearance_revolute", "name": "hinge", "bearing": "arm.end", "journal": "block.J",
                    "bearing_radius": 0.01, "clearance": 1e-3, "length": 0.02,
                    "bearing_material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3},
                    "journal_material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3},
                    "contact": {"law": "lankarani_nikravesh", "restitution": 0.9}, "stiffness": {"law": "hertz_cylinder"},
                    "friction": {"law": "ambrosio", "coefficient": 0.1, "v0": 1e-4, "v1": 1e-3},
                    "initial_eccentricity": [0.0, 0.0], "lock_at_assembly": false, "onset_velocity_floor": 1e-4,
                    "max_penetration": null, "lubrication": null}],
        "drivers": [],
        "forces": [
            {"type": "spring_damper", "name": "tether", "first": "ground.S", "second": "arm.mid", "stiffness": 500, "damping": 3, "free_length": 0.3},
            {"type": "hydraulic_cylinder", "name": "cyl", "first": "ground.C", "second": "block.P",
             "piston_area": 2e-3, "rod_side_area": 1e-3, "stroke_length": 0.5, "cap_dead_volume": 1e-4, "rod_dead_volume": 1e-4,
             "initial_stroke": 0.1, "cap_pressure": 1e6, "rod_pressure": 2e6, "bulk_modulus": 1.5e9,
             "seal_friction": null, "cap_inflow": null, "rod_inflow": null},
            {"type": "point_force", "name": "push", "point": "arm.mid", "fx": {"kind": "constant", "value": 3.0}, "fy": {"kind": "constant", "value": -5.0}},
            {"type": "rotational_spring_damper", "name": "hinge_spring", "first": "arm", "second": "block", "stiffness": 20, "damping": 0.5, "free_angle": 0.0}
        ],
        "sensors": []
    }))
}

/// A strained, moving state of the mixed model: the beam bent and its nodes
/// moving, the journal 5 um into contact with the bearing, moving into it.
pub(super) fn mixed_state(m: &Model) -> Vec<f64> {
    let mut y: Vec<f64> = m.initial_coordinates.iter().chain(&m.initial_velocities).chain(&m.initial_element_states).copied().collect();
    let (nq, beam) = (m.layout.nq, m.layout.bodies[1]);
    let (block, beam_kind) = (m.layout.bodies[0], &m.bodies[1].kind);
    for (k, node) in y[beam.q_range()].chunks_exact_mut(3).enumerate() {
        node[1] += 0.01 * (0.9 * k as f64).sin();
        node[2] += 0.03 * (0.6 * k as f64).cos();
    }
    for (k, rate) in y[nq + beam.v..nq + beam.v + beam.nv].chunks_exact_mut(3).enumerate() {
        rate[0] += 0.2 * (1.3 * k as f64).cos();
        rate[2] += -0.4 * (0.5 * k as f64).sin();
    }
    // the journal centre (block.J) onto the bearing's (the beam's end section) plus clearance and 5 um along x
    let mut frames = vec![crate::kinematics::planar::Frame::GROUND; m.n_frames()];
    let (q, v, _) = m.layout.split(&y);
    update_frames(m, q, v, &mut frames, &mut []);
    let (_, bearing) = m.points.iter().find(|(name, _)| name == "arm.end").unwrap();
    let (_, journal) = m.points.iter().find(|(name, _)| name == "block.J").unwrap();
    let centre = frames[bearing.frame].point(bearing.local);
    let target = centre + crate::kinematics::planar::Vec2::new(1e-3 + 5e-6, 0.0);
    let offset = target - frames[journal.frame].point(journal.local);
    y[block.q] += offset.x;
    y[block.q + 1] += offset.y;
    y[nq + block.v] -= 0.05;
    assert!(matches!(beam_kind, crate::body::BodyKind::Beam(_)));
    y
}

/// Floors of the forward-difference increments, 1 (increments of at least 1.5e-8):
/// comparisons of two differences with the same increments see their rounding,
/// about eps |f| / h, which these floors keep below 1e-8 of the derivatives here
/// (a run's floors, atol/rtol, are smaller: the Jacobian tolerates that rounding).
pub(super) fn floors(n: usize) -> Vec<f64> {
    vec![1.0; n]
}

/// `f(t, y) = [v, a, z_dot]` in absolute coordinates.
fn rhs(m: &Model, memory: &[ElementMemory], t: f64, y: &[f64], stabilization: Stabilization, ws: &mut Workspace, f: &mut [f64]) {
    accelerations(m, memory, t, y, stabilization, ws).unwrap();
    let (nq, nv) = (m.layout.nq, m.layout.nv);
    f[..nq].copy_from_slice(&y[nq..nq + nv]);
    f[nq..nq + nv].copy_from_slice(&ws.accelerations);
    f[nq + nv..].copy_from_slice(&ws.element_state_rates);
}

/// The increment of column c, as the integrator and the structured Jacobian take it.
fn increment(y: &[f64], floors: &[f64], c: usize) -> f64 {
    let step = f64::EPSILON.sqrt() * y[c].abs().max(floors[c]);
    (y[c] + step) - y[c]
}

/// Forward differences of a function of the state, column by column (row-major n_out x n).
fn differences(y: &[f64], floors: &[f64], n_out: usize, mut g: impl FnMut(&[f64], &mut [f64])) -> Vec<f64> {
    let n = y.len();
    let (mut base, mut moved, mut out) = (vec![0.0; n_out], vec![0.0; n_out], vec![0.0; n_out * n]);
    g(y, &mut base);
    let mut z = y.to_vec();
    for c in 0..n {
        let h = increment(y, floors, c);
        z[c] = y[c] + h;
        g(&z, &mut moved);
        z[c] = y[c];
        for r in 0..n_out {
            out[r * n + c] = (moved[r] - base[r]) / h;
        }
    }
    out
}

/// The structured Jacobian at (t, y) (the workspace evaluated there first, as the system does).
pub(super) fn structured(m: &Model, memory: &[ElementMemory], t: f64, y: &[f64], stabilization: Stabilization, ws: &mut Workspace) -> (StructuredJacobian, Vec<f64>) {
    let n = y.len();
    accelerations(m, memory, t, y, stabilization, ws).unwrap();
    let mut s = StructuredJacobian::new(m);
    let mut jacobian = vec![f64::NAN; n * n];
    let passes = s.fill(m, memory, t, y, &floors(n), ws, &mut jacobian).unwrap();
    assert_eq!(passes, 1 + s.n_colours());
    (s, jacobian)
}

/// Largest |entry| of column c of a row-major matrix with n columns over `rows`.
fn column_max(a: &[f64], n: usize, c: usize, rows: std::ops::Range<usize>) -> f64 {
    rows.map(|r| a[r * n + c].abs()).fold(0.0, f64::max)
}

#[test]
fn no_element_reads_two_columns_of_one_colour_and_a_beam_needs_the_columns_of_one_element() {
    for (name, m, per_element) in [("mixed", mixed(), 18), ("spin-up", spin_up_beam(6.0, 4, 0.0), 9), ("slider-crank", slider_crank(Some(3)), 18)] {
        let s = StructuredJacobian::new(&m);
        for k in 0..s.contributions().len() {
            let mut seen: Vec<usize> = s.reads(k).iter().map(|&c| s.colour_of(c).expect("a column read has a colour")).collect();
            let count = seen.len();
            seen.sort_unstable();
            seen.dedup();
            assert_eq!(seen.len(), count, "{name}: contribution {k} ({:?}) reads two columns of one colour", s.contributions()[k]);
        }
        // a quadratic element reads 9 coordinates (and 9 rates when damped): no fewer colours are possible,
        // and the greedy colouring of the chain needs no more (element-by-element differencing costs the same)
        let beam = s.contributions().iter().filter(|c| matches!(c, Contribution::BeamElement { .. })).count();
        assert!(beam >= 3, "{name}: {beam} beam elements");
        let most = (0..s.contributions().len()).map(|k| s.reads(k).len()).max().unwrap();
        assert_eq!(s.n_colours(), per_element.max(most), "{name}");
        println!("{name}: {} columns, {} colours", m.layout.len(), s.n_colours());
    }
}

#[test]
fn coloured_differences_of_the_local_forces_equal_column_by_column_differences_of_the_applied_force() {
    // the incidence (markers -> coordinates, beam elements -> nodes, element states) is
    // complete when every column's change of Q and z_dot is found on the contributions' rows
    let m = mixed();
    let y = mixed_state(&m);
    let (n, nv) = (y.len(), m.layout.nv);
    let memory = m.initial_memory();
    let mut ws = Workspace::new(&m);
    let (s, jacobian) = structured(&m, &memory, 0.3, &y, Stabilization::Projection, &mut ws);
    let mut scratch = Workspace::new(&m);
    let full = differences(&y, &floors(n), nv + m.layout.nz, |y, out| {
        let (q, v, z) = m.layout.split(y);
        update_frames(&m, q, v, &mut scratch.frames, &mut scratch.spatial_frames);
        applied_forces(&m, &memory, 0.3, (q, v, z), &mut scratch).unwrap();
        out[..nv].copy_from_slice(&scratch.generalised_force);
        out[nv..].copy_from_slice(&scratch.element_state_rates);
    });
    let magnitudes = s.row_magnitudes();
    let mut worst: f64 = 0.0;
    for c in 0..n {
        let (scale, h) = (column_max(&full, n, c, 0..nv + m.layout.nz), increment(&y, &floors(n), c));
        for r in 0..nv + m.layout.nz {
            let (expected, got) = (full[r * n + c], s.local_derivative(r, c));
            // both are differences of the same sums, added in another order: they differ by
            // the rounding of the row's terms over the increment (an element's own evaluation
            // rounds at a few eps of its largest terms: 8 eps of the row's sum bounds it here)
            let rounding = 8.0 * f64::EPSILON * magnitudes[r] / h;
            assert!((got - expected).abs() <= 1e-9 * scale + rounding, "row {r}, column {c}: {got:e} vs {expected:e} (column max {scale:e}, rounding {rounding:e})");
            worst = worst.max((got - expected).abs() / (1e-9 * scale + rounding));
        }
        if s.colour_of(c).is_none() {
            assert_eq!(scale, 0.0, "column {c} has no colour but moves the forces");
        }
    }
    println!("largest difference relative to its bound: {worst:e}");
    // the contact is on: the journal's coordinates move the bearing's rows (the beam's end node)
    let (_, journal) = m.points.iter().find(|(name, _)| name == "block.J").unwrap();
    let block = m.layout.body(journal.body).unwrap();
    let end = m.layout.bodies[1].v + m.layout.bodies[1].nv - 3;
    assert!(s.local_derivative(end, block.q).abs() > 1e5, "contact stiffness {:e} N/m", s.local_derivative(end, block.q));
    // the Jacobian's position rows are q_dot = v, its state rows the differenced rates
    let nq = m.layout.nq;
    for c in 0..n {
        for i in 0..nq {
            assert_eq!(jacobian[i * n + c], f64::from(c == nq + i), "q row {i}, column {c}");
        }
        for i in 0..m.layout.nz {
            assert_eq!(jacobian[(nq + nv + i) * n + c], s.local_derivative(nv + i, c), "z row {i}, column {c}");
        }
    }
    // the cylinder: its pressure rates read the block's velocity, its force on the block reads the pressures
    let (rate_by_velocity, force_by_pressure) = (s.local_derivative(nv, nq + block.v), s.local_derivative(block.v, nq + nv));
    assert!(rate_by_velocity.abs() > 1e6 && force_by_pressure.abs() > 1e-4, "{rate_by_velocity:e} Pa/m, {force_by_pressure:e} m^2");
}

#[test]
fn on_a_free_beam_the_structured_jacobian_is_the_forward_difference_jacobian() {
    // no constraints and constant mass: a = M^-1 Q(q, v) exactly, nothing is neglected
    let m = free_beam(4, 3.0);
    let (q, v) = deformed(&m);
    let y: Vec<f64> = q.iter().chain(&v).copied().collect();
    let n = y.len();
    let memory = m.initial_memory();
    let mut ws = Workspace::new(&m);
    let (_, jacobian) = structured(&m, &memory, 0.0, &y, Stabilization::Projection, &mut ws);
    let mut scratch = Workspace::new(&m);
    let full = differences(&y, &floors(n), n, |y, f| rhs(&m, &memory, 0.0, y, Stabilization::Projection, &mut scratch, f));
    let mut worst: f64 = 0.0;
    for c in 0..n {
        let scale = column_max(&full, n, c, 0..n);
        for r in 0..n {
            let d = (jacobian[r * n + c] - full[r * n + c]).abs();
            // (the same differences with M^-1 applied before or after differencing: rounding only)
            assert!(d <= 1e-7 * scale, "row {r}, column {c}: {:e} vs {:e}", jacobian[r * n + c], full[r * n + c]);
            worst = worst.max(d / scale);
        }
    }
    println!("free beam: largest difference relative to its column {worst:e}");
}

/// `[J_fd, J_structured, J_neglected]` at (t, y): forward differences of f, the
/// structured Jacobian, and forward differences of the accelerations with Q frozen at (t, y).
fn three_jacobians(m: &Model, memory: &[ElementMemory], t: f64, y: &[f64], stabilization: Stabilization) -> [Vec<f64>; 3] {
    let n = y.len();
    let (nq, nv) = (m.layout.nq, m.layout.nv);
    let mut ws = Workspace::new(m);
    let (_, jacobian) = structured(m, memory, t, y, stabilization, &mut ws);
    let q0 = ws.generalised_force.clone();
    let mut scratch = Workspace::new(m);
    let full = differences(y, &floors(n), n, |y, f| rhs(m, memory, t, y, stabilization, &mut scratch, f));
    let neglected = differences(y, &floors(n), n, |y, f| {
        let (q, v, _) = m.layout.split(y);
        update_frames(m, q, v, &mut scratch.frames, &mut scratch.spatial_frames);
        scratch.generalised_force.copy_from_slice(&q0);
        constrained_accelerations(m, t, (q, v), stabilization, false, &mut scratch).unwrap();
        f.fill(0.0);
        f[nq..nq + nv].copy_from_slice(&scratch.accelerations);
    });
    [full, jacobian, neglected]
}

/// Checks `J_fd = J_structured + J_neglected` column by column and returns the Newton
/// contraction by the neglected terms ([`newton_contraction`]) at c = 1e-3 s.
fn check_neglected_terms_explain_the_difference(name: &str, m: &Model, memory: &[ElementMemory], t: f64, y: &[f64], stabilization: Stabilization) -> f64 {
    let n = y.len();
    let (nq, nv) = (m.layout.nq, m.layout.nv);
    let [full, jacobian, neglected] = three_jacobians(m, memory, t, y, stabilization);
    let (mut worst, mut structured_max, mut neglected_max): (f64, f64, f64) = (0.0, 0.0, 0.0);
    for c in 0..n {
        let scale = column_max(&full, n, c, 0..n).max(column_max(&jacobian, n, c, 0..n));
        for r in 0..n {
            // second-order remainders (dA/dq times the change of Q over h) and rounding:
            // 1e-8 of the column's largest entry (1e-12 measured)
            let d = (full[r * n + c] - jacobian[r * n + c] - neglected[r * n + c]).abs();
            assert!(d <= 1e-8 * scale, "{name}: row {r}, column {c}: fd {:e}, structured {:e}, neglected {:e}", full[r * n + c], jacobian[r * n + c], neglected[r * n + c]);
            if scale > 0.0 {
                worst = worst.max(d / scale);
            }
        }
        structured_max = structured_max.max(column_max(&jacobian, n, c, nq..nq + nv));
        neglected_max = neglected_max.max(column_max(&neglected, n, c, nq..nq + nv));
    }
    let ratio = neglected_max / structured_max;
    println!("{name}: fd - structured - neglected <= {worst:e} of a column; neglected / structured (acceleration rows) {ratio:e}");
    for c in [1e-4, 1e-3, 1e-2] {
        println!("{name}: Newton contraction by the neglected terms at c = h/alpha = {c:e}: {:.3e}", newton_contraction(&jacobian, &neglected, c));
    }
    newton_contraction(&jacobian, &neglected, 1e-3)
}

/// Spectral radius of `(I - c J_s)^-1 c J_n`, by power iteration: the factor by which
/// simplified Newton with `J_s` contracts an error component that `J_s + J_n` would remove at once.
pub(super) fn newton_contraction(structured: &[f64], neglected: &[f64], c: f64) -> f64 {
    let n = (structured.len() as f64).sqrt() as usize;
    let mut matrix: Vec<f64> = structured.iter().map(|j| -c * j).collect();
    for i in 0..n {
        matrix[i * n + i] += 1.0;
    }
    let mut pivots = vec![0; n];
    crate::linalg::lu_factor(&mut matrix, n, &mut pivots).unwrap();
    let mut x: Vec<f64> = (0..n).map(|i| 1.0 + (0.37 * i as f64).sin()).collect();
    let mut growth = 0.0;
    let (iterations, counted) = (300, 100);
    for k in 0..iterations {
        let mut next: Vec<f64> = (0..n).map(|i| c * (0..n).map(|j| neglected[i * n + j] * x[j]).sum::<f64>()).collect();
        crate::linalg::lu_solve(&matrix, n, &pivots, &mut next);
        let norm = next.iter().map(|v| v * v).sum::<f64>().sqrt();
        if norm == 0.0 {
            return 0.0;
        }
        if k >= iterations - counted {
            growth += norm.ln();
        }
        x = next.iter().map(|v| v / norm).collect();
    }
    (growth / counted as f64).exp()
}

/// The state of `m` after a run of `t_end` [s] with the NDF and Baumgarte terms (strained and moving).
fn state_after(m: &Model, t_end: f64, stabilization: Stabilization) -> State {
    let mut ws = Workspace::new(m);
    let mut state = assemble(m, 0.0, &mut ws).unwrap();
    let integrator = IntegratorOptions { method: Method::NumericalDifferentiation, rtol: 1e-6, atol: 1e-9, max_order: 2, ..IntegratorOptions::default() };
    let outcome = simulate(m, &mut state, t_end, &SimulationOptions { integrator, stabilization, ..SimulationOptions::default() }, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    state
}

#[test]
fn under_constraints_the_structured_jacobian_differs_from_forward_differences_by_the_neglected_terms() {
    // the spin-up beam during the ramp (hub at 4.3 rad/s, the beam bent by the angular acceleration)
    let baumgarte = Stabilization::Baumgarte { alpha: 10.0, beta: 10.0 };
    let m = spin_up_beam(6.0, 4, 0.0);
    let state = state_after(&m, 10.0, baumgarte);
    let contraction = check_neglected_terms_explain_the_difference("spin-up beam", &m, &state.memory, 10.0, &state.y, baumgarte);
    // the neglected terms are slow: the largest is the Baumgarte damping of the constraints'
    // velocity error, rate 2 alpha, which simplified Newton then removes by a factor 2 alpha c
    // per iteration (the geometric stiffness and the velocity terms, ~omega, are smaller)
    assert!((contraction / (2.0 * 10.0 * 1e-3) - 1.0).abs() < 0.1, "contraction {contraction:e}");
    // the stiff damped rod of the slider-crank, moving at 150 rad/s
    let baumgarte = Stabilization::Baumgarte { alpha: 50.0, beta: 50.0 };
    let m = slider_crank(Some(2));
    let state = state_after(&m, 0.01, baumgarte);
    let contraction = check_neglected_terms_explain_the_difference("slider-crank", &m, &state.memory, 0.01, &state.y, baumgarte);
    assert!((contraction / (2.0 * 50.0 * 1e-3) - 1.0).abs() < 0.1, "contraction {contraction:e}");
}

/// Runs `m` with the NDF (orders 1 and 2) and the given Jacobian; the trajectory's
/// channels `names` and the statistics.
pub(super) fn run(m: &Model, t_end: f64, integrator: IntegratorOptions, stabilization: Stabilization, names: &[&str]) -> (Vec<Vec<f64>>, Statistics) {
    let mut ws = Workspace::new(m);
    let mut state = assemble(m, 0.0, &mut ws).unwrap();
    let outcome = simulate(m, &mut state, t_end, &SimulationOptions { integrator, stabilization, ..SimulationOptions::default() }, None);
    assert!(outcome.error.is_none(), "{:?}", outcome.error);
    (names.iter().map(|name| outcome.trajectory.channel(name).unwrap()).collect(), outcome.statistics)
}

/// Compares a structured and a finite-difference run: samples within `bound`, fewer right-hand sides.
fn compare_runs(name: &str, m: &Model, t_end: f64, integrator: IntegratorOptions, stabilization: Stabilization, channels: &[&str], bounds: &[f64]) {
    let n = m.layout.len();
    let with = |jacobian, rtol: f64, atol: f64| run(m, t_end, IntegratorOptions { jacobian, rtol, atol, ..integrator.clone() }, stabilization, channels);
    let (rtol, atol) = (integrator.rtol, integrator.atol);
    let (fd, fd_stats) = with(JacobianMethod::FiniteDifference, rtol, atol);
    let (st, st_stats) = with(JacobianMethod::Structured, rtol, atol);
    let (auto, auto_stats) = with(JacobianMethod::Auto, rtol, atol);
    assert_eq!((auto, &auto_stats), (st.clone(), &st_stats), "{name}: Auto takes the structured Jacobian on a beam");
    // (the spread of the method itself, for the bounds: JOINTPLAY_SPREAD=1 adds runs at 1.01 rtol and rtol / 10)
    let spread = std::env::var_os("JOINTPLAY_SPREAD").is_some();
    let largest = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    let others = spread.then(|| (with(JacobianMethod::FiniteDifference, rtol * 1.01, atol).0, with(JacobianMethod::FiniteDifference, rtol / 10.0, atol / 10.0).0));
    for (k, channel) in channels.iter().enumerate() {
        let between = largest(&fd[k], &st[k]);
        println!("{name}: {channel}: structured - finite differences {between:e}");
        if let Some((nearby, tighter)) = &others {
            println!("  fd - fd at 1.01 rtol {:e}; fd - rtol/10 {:e}; structured - rtol/10 {:e}", largest(&fd[k], &nearby[k]), largest(&fd[k], &tighter[k]), largest(&st[k], &tighter[k]));
        }
        assert!(between < bounds[k], "{name}: {channel} differs by {between:e}");
    }
    println!("{name} finite differences: {fd_stats:?}");
    println!("{name} structured: {st_stats:?}");
    // what the Jacobians cost
    assert_eq!(fd_stats.jacobian_rhs_evaluations, fd_stats.jacobian_evaluations * (n + 1));
    assert_eq!((fd_stats.jacobian_force_evaluations, st_stats.jacobian_rhs_evaluations), (0, st_stats.jacobian_evaluations));
    assert!(st_stats.jacobian_force_evaluations > st_stats.jacobian_evaluations);
    assert!(st_stats.rhs_evaluations < fd_stats.rhs_evaluations, "{name}: {} right-hand sides against {}", st_stats.rhs_evaluations, fd_stats.rhs_evaluations);
}

#[test]
fn the_spin_up_beam_with_the_structured_jacobian_follows_the_finite_difference_run_with_fewer_right_hand_sides() {
    // through the ramp to steady spin, rtol 1e-5 as in the beam tests: the two runs take
    // different steps, so they differ by the global error of the undamped vibration the
    // ramp leaves. Measured: the tip positions differ by 1.1e-3 m at most, where the
    // finite-difference run differs by 1.8e-3 m from itself at 1.01 rtol and by 3.5e-4 m
    // from a run at rtol / 10 (the structured one by 1.3e-3 m): a bound of 5e-3 m (5e-4
    // of the length) is that spread with a margin. (Pointwise axial forces carry the
    // axial vibration's phase error: 900 N apart here, 1200 N at 1.01 rtol; not compared.)
    let m = spin_up_beam(6.0, 4, 0.0);
    let integrator = IntegratorOptions { method: Method::NumericalDifferentiation, rtol: 1e-5, atol: 1e-7, output_step: Some(0.02), max_order: 2, ..IntegratorOptions::default() };
    let tip = m.bodies[1].kind.position_channels().len() / 3 - 1;
    let (x, y) = (format!("beam.node{tip}_x"), format!("beam.node{tip}_y"));
    compare_runs("spin-up beam", &m, 17.0, integrator, Stabilization::Baumgarte { alpha: 10.0, beta: 10.0 }, &[&x, &y], &[5e-3, 5e-3]);
}

#[test]
fn the_stiff_rod_with_the_structured_jacobian_follows_the_finite_difference_run_with_fewer_right_hand_sides() {
    let m = slider_crank(Some(2));
    let integrator = IntegratorOptions { method: Method::NumericalDifferentiation, max_order: 2, rtol: 1e-8, atol: 1e-11, output_step: Some(1e-3), ..IntegratorOptions::default() };
    // measured: slider.x 1.0e-9 m apart (8.4e-10 between finite-difference runs at rtol and
    // 1.01 rtol, 2.7e-8 from rtol / 10), slider.ax 1.1 m/s^2 of a 1600 m/s^2 peak (1.9 and 3.0)
    compare_runs("slider-crank", &m, 0.05, integrator, Stabilization::Baumgarte { alpha: 50.0, beta: 50.0 }, &["slider.x", "slider.ax"], &[1e-8, 5.0]);
}

/// Wall time of the spin-up beam (17 s, rtol 1e-5, orders 1-2, Baumgarte 10/10) with
/// either Jacobian, interleaved runs; prints medians and ranges, asserts nothing
/// (`cargo test --release -- --ignored --nocapture spin_up_beam_wall_time`; environment:
/// JOINTPLAY_RUNS (5), JOINTPLAY_ELEMENTS (4), JOINTPLAY_ONLY=FiniteDifference or Structured).
#[test]
#[ignore]
fn spin_up_beam_wall_time() {
    let elements: usize = std::env::var("JOINTPLAY_ELEMENTS").ok().and_then(|s| s.parse().ok()).unwrap_or(4);
    let m = spin_up_beam(6.0, elements, 0.0);
    println!("{elements} elements, {} states", m.layout.len());
    let integrator = IntegratorOptions { method: Method::NumericalDifferentiation, rtol: 1e-5, atol: 1e-7, output_step: Some(0.02), max_order: 2, ..IntegratorOptions::default() };
    let runs: usize = std::env::var("JOINTPLAY_RUNS").ok().and_then(|s| s.parse().ok()).unwrap_or(5);
    let mut times = [Vec::new(), Vec::new()];
    for _ in 0..runs {
        for (k, jacobian) in [JacobianMethod::FiniteDifference, JacobianMethod::Structured].into_iter().enumerate() {
            if std::env::var("JOINTPLAY_ONLY").is_ok_and(|only| only != format!("{jacobian:?}")) {
                times[k].push(0.0);
                continue;
            }
            let start = std::time::Instant::now();
            let (_, stats) = run(&m, 17.0, IntegratorOptions { jacobian, ..integrator.clone() }, Stabilization::Baumgarte { alpha: 10.0, beta: 10.0 }, &[]);
            times[k].push(start.elapsed().as_secs_f64());
            if times[k].len() == 1 {
                println!("{jacobian:?}: {stats:?}");
            }
        }
    }
    for (k, name) in ["finite differences", "structured"].iter().enumerate() {
        times[k].sort_by(f64::total_cmp);
        println!("{name}: median {:.3} s over {runs} runs, range {:.3} to {:.3} s", times[k][runs / 2], times[k][0], times[k][runs - 1]);
    }
}

#[test]
fn a_modal_bodys_columns_are_differenced_whole_because_its_mass_moves_with_it() {
    // a free modal body spinning at 3 rad/s with every mode vibrating, deformed: no constraints, so
    // A = M(q)^-1, and what the structured columns leave out is d(M^-1)/dq Q alone, which is not
    // small for a body whose mass matrix turns with its frame and changes with its modes
    let interface = serde_json::json!([{"name": "start", "arclength": 0.0}, {"name": "end", "arclength": 1.0}]);
    let m = model(serde_json::json!({
        "name": "free modal body", "gravity": [0, 0], "ground_points": [], "bodies": [], "beams": [],
        "modal_bodies": [crate::dynamics::modal_tests::arm_json(1.0, crate::dynamics::modal_tests::SECTION, 4, interface, 3, 0.0, 3.0)],
        "joints": [], "drivers": [], "forces": [], "sensors": []
    }));
    let mut ws = Workspace::new(&m);
    let state = assemble(&m, 0.0, &mut ws).unwrap();
    let (n, nq) = (state.y.len(), m.layout.nq);
    let mut y = state.y.clone();
    for j in 3..nq {
        y[j] = 1e-3 * (1.0 + j as f64).recip(); // modal amplitudes
        y[nq + j] = 0.5 * (1.0 + j as f64).recip();
    }
    y[2] = 0.4;
    let memory = m.initial_memory();
    let stabilization = Stabilization::None;
    let (mut s, mut jacobian) = structured(&m, &memory, 0.0, &y, stabilization, &mut ws);
    let mut scratch = Workspace::new(&m);
    let full = differences(&y, &floors(n), n, |y, f| rhs(&m, &memory, 0.0, y, stabilization, &mut scratch, f));
    // (a column that moves no acceleration, x and y of a free body, is compared absolutely)
    let gap = |a: &[f64], c: usize| {
        let off = (nq..n).map(|r| (a[r * n + c] - full[r * n + c]).abs()).fold(0.0, f64::max);
        let largest = column_max(&full, n, c, nq..n);
        if largest > 0.0 { off / largest } else { off }
    };
    let before = (0..n).map(|c| gap(&jacobian, c)).fold(0.0, f64::max);
    let evaluations = s.difference_whole_columns(&y, &floors(n), &mut jacobian, |y, f| {
        rhs(&m, &memory, 0.0, y, stabilization, &mut scratch, f);
        Ok(())
    }).unwrap();
    assert_eq!(evaluations, n, "every column of the only body is differenced whole");
    let after = (0..n).map(|c| gap(&jacobian, c)).fold(0.0, f64::max);
    println!("structured columns off by {before:e} of their largest entry, differenced whole {after:e}");
    assert!(before > 1e-3, "the structured columns should miss d(M^-1)/dq Q: {before:e}");
    assert!(after < 1e-12, "{after:e}");
}

#[test]
fn auto_takes_forward_differences_on_a_modal_mechanism_without_a_beam() {
    // a modal rod in a slider-crank (no beam): the structured Jacobian neglects the constraints'
    // geometric stiffness, which a modal mechanism's Newton iterations need (docs/theory/
    // integrator-jacobian.md); Auto takes forward differences, n + 1 evaluations each
    let modal = crate::dynamics::modal_tests::slider_crank(true, false);
    let n = modal.layout.len();
    let integrator = IntegratorOptions { method: Method::NumericalDifferentiation, max_order: 2, rtol: 1e-6, atol: 1e-9, ..IntegratorOptions::default() };
    let (_, stats) = run(&modal, 0.002, integrator, Stabilization::Baumgarte { alpha: 50.0, beta: 50.0 }, &[]);
    assert!(stats.jacobian_evaluations > 0);
    assert_eq!((stats.jacobian_rhs_evaluations, stats.jacobian_force_evaluations), (stats.jacobian_evaluations * (n + 1), 0));
}
