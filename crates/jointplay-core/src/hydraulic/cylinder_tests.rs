//! Tests of the cylinder against closed forms: volumes, pressure rates and
//! forces by hand; the closed-chamber stiffness β (A1²/V1 + A2²/V2) and the
//! natural frequency of a mass on it (Merritt 1967, hydraulic spring);
//! static pressures under a load from p = p0 - β ln(V/V0); energy balance.
//! Cylinder (chosen, not from paper 002): bore 80 mm, rod 45 mm, stroke
//! 0.5 m, dead volumes 0.1 l, β = 1 GPa, moving mass 20 kg.

use super::super::chamber::closed_pressure;
use super::*;
use crate::friction::LugreFriction;
use std::f64::consts::PI;

const BETA: f64 = 1.0e9;
const MASS: f64 = 20.0;

fn geometry() -> CylinderGeometry {
    let a1 = PI / 4.0 * 0.08 * 0.08;
    let a2 = a1 - PI / 4.0 * 0.045 * 0.045;
    CylinderGeometry::new(a1, a2, 0.5, 1.0e-4, 1.0e-4).unwrap()
}

fn frictionless() -> HydraulicCylinder {
    HydraulicCylinder::new(geometry(), BETA, SealFriction::None).unwrap()
}

/// Paper-002 seal forces (385 N, 340 N) with the chosen LuGre parameters.
fn with_seal() -> HydraulicCylinder {
    let law = LugreFriction::new(385.0, 340.0, 3.0e-5, 1.0e7, 1.0e4, 0.0).unwrap();
    HydraulicCylinder::new(geometry(), BETA, SealFriction::Lugre(law)).unwrap()
}

/// A mass on the rod end, barrel fixed: y = [s, ds/dt, p_cap, p_rod, z], an
/// applied force along the extension [N] and a test damper c [N s/m] on the mass.
struct MassOnCylinder {
    cylinder: HydraulicCylinder,
    applied: f64,
    damper: f64,
}

impl MassOnCylinder {
    fn rates(&self, y: &[f64; 5]) -> [f64; 5] {
        let e = self.cylinder.evaluate(y[0], y[1], &y[2..], (0.0, 0.0)).unwrap();
        let r = e.state_rates();
        let z_rate = if r.len() == 3 { r[2] } else { 0.0 };
        [y[1], (e.force + self.applied - self.damper * y[1]) / MASS, r[0], r[1], z_rate]
    }

    fn step(&self, y: &[f64; 5], h: f64) -> [f64; 5] {
        let add = |a: &[f64; 5], k: &[f64; 5], s: f64| std::array::from_fn(|i| a[i] + s * k[i]);
        let k1 = self.rates(y);
        let k2 = self.rates(&add(y, &k1, 0.5 * h));
        let k3 = self.rates(&add(y, &k2, 0.5 * h));
        let k4 = self.rates(&add(y, &k3, h));
        std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
    }

    fn energy(&self, y: &[f64; 5]) -> f64 {
        0.5 * MASS * y[1] * y[1] + self.cylinder.stored_energy(y[0], &y[2..])
    }
}

/// Rod pressure [Pa] that balances p_cap [Pa] with no load: p_rod A2 = p_cap A1.
fn balancing_rod_pressure(cap_pressure: f64) -> f64 {
    cap_pressure * geometry().piston_area() / geometry().rod_side_area()
}

#[test]
fn test_geometry_volumes_and_messages() {
    let g = geometry();
    // V_cap = 1e-4 + A1 s, V_rod = 1e-4 + A2 (0.5 - s)
    let (cap, rod) = g.volumes(0.2);
    assert!((cap - (1e-4 + 5.026548245743669e-3 * 0.2)).abs() < 1e-15);
    assert!((rod - (1e-4 + 3.436116964863836e-3 * 0.3)).abs() < 1e-15);
    assert_eq!(g.volume_rates(2.0), (2.0 * g.piston_area(), -2.0 * g.rod_side_area()));
    let err = |r: Result<CylinderGeometry, String>| r.unwrap_err();
    assert_eq!(
        err(CylinderGeometry::new(1e-3, 1e-3, 0.5, 1e-4, 1e-4)),
        "rod side area must be < the piston area 0.001 m^2 (it is the annulus), got 0.001"
    );
    assert_eq!(
        err(CylinderGeometry::new(-1e-3, 5e-4, 0.5, 1e-4, 1e-4)),
        "piston area must be finite and > 0 m^2, got -0.001"
    );
    assert_eq!(
        err(CylinderGeometry::new(1e-3, 5e-4, 0.0, 1e-4, 1e-4)),
        "stroke length must be finite and > 0 m, got 0"
    );
    assert_eq!(
        err(CylinderGeometry::new(1e-3, 5e-4, 0.5, 0.0, 1e-4)),
        "cap dead volume must be finite and > 0 m^3, got 0"
    );
    assert_eq!(
        HydraulicCylinder::new(g, f64::INFINITY, SealFriction::None).unwrap_err(),
        "bulk modulus must be finite and > 0 Pa, got inf"
    );
}

#[test]
fn test_pressure_rates_and_force_match_closed_forms() {
    let c = frictionless();
    let g = geometry();
    let (s, v, q) = (0.2, 0.05, (1e-4, -2e-5));
    let e = c.evaluate(s, v, &[8e6, 3e6], q).unwrap();
    let (cap, rod) = g.volumes(s);
    let (a1, a2) = (g.piston_area(), g.rod_side_area());
    // dp_cap/dt = β/V_cap (Q_cap - A1 v), dp_rod/dt = β/V_rod (Q_rod + A2 v)
    assert!((e.state_rates()[0] - BETA / cap * (1e-4 - a1 * v)).abs() < 1e-6);
    assert!((e.state_rates()[1] - BETA / rod * (-2e-5 + a2 * v)).abs() < 1e-6);
    assert_eq!(e.state_rates().len(), 2);
    // 8 MPa on 50.27 cm² minus 3 MPa on 34.36 cm²
    assert!((e.pressure_force - (8e6 * a1 - 3e6 * a2)).abs() < 1e-9);
    assert!((e.force - 29904.035071357845).abs() < 1e-6, "{}", e.force);
    assert_eq!((e.friction_force, e.stick), (0.0, false));
}

#[test]
fn test_seal_friction_resists_the_stroke_rate_and_adds_its_state() {
    let c = with_seal();
    assert_eq!((c.n_states(), frictionless().n_states()), (3, 2));
    let Some(law) = (match c.seal() {
        SealFriction::Lugre(law) => Some(*law),
        SealFriction::None => None,
    }) else {
        unreachable!()
    };
    // steady extension at 0.1 m/s: z = F_C/σ0, friction 340 N taken off the pressure force
    let z = law.steady_deflection(0.1);
    let e = c.evaluate(0.25, 0.1, &[5e6, 5e6, z], (0.0, 0.0)).unwrap();
    assert!((e.friction_force - 340.0).abs() < 1e-9 && !e.stick);
    assert!((e.force - (e.pressure_force - 340.0)).abs() < 1e-9);
    assert!(e.state_rates()[2].abs() < 1e-12);
    // retraction: friction changes sign and now adds to the pressure force
    let e = c.evaluate(0.25, -0.1, &[5e6, 5e6, -z], (0.0, 0.0)).unwrap();
    assert!((e.force - (e.pressure_force + 340.0)).abs() < 1e-9);
    // at rest the seal sticks; its bristle energy is part of the stored energy
    let e = c.evaluate(0.25, 0.0, &[0.0, 0.0, 2e-5], (0.0, 0.0)).unwrap();
    assert!(e.stick && (e.friction_force - 200.0).abs() < 1e-9);
    assert!((c.stored_energy(0.25, &[0.0, 0.0, 2e-5]) - 0.5 * 1e7 * 4e-10).abs() < 1e-15);
}

#[test]
fn test_linearised_evaluate_gives_the_closed_chamber_stiffness() {
    // -dF/ds = -Σ ∂F/∂p_i dp_i/ds, with ∂F/∂p_i by differences of evaluate and
    // dp_i/ds = (dp_i/dt) at ds/dt = 1 m/s, no inflow; closed form β (A1²/V1 + A2²/V2)
    let c = frictionless();
    let (a1, a2) = (geometry().piston_area(), geometry().rod_side_area());
    for s in [0.01, 0.25, 0.49] {
        let p = [6e6, 4e6];
        let rates = c.evaluate(s, 1.0, &p, (0.0, 0.0)).unwrap();
        let force = |p: [f64; 2]| c.evaluate(s, 1.0, &p, (0.0, 0.0)).unwrap().pressure_force;
        let dp = 1e3;
        let d_cap = (force([p[0] + dp, p[1]]) - force([p[0] - dp, p[1]])) / (2.0 * dp);
        let d_rod = (force([p[0], p[1] + dp]) - force([p[0], p[1] - dp])) / (2.0 * dp);
        let stiffness = -(d_cap * rates.state_rates()[0] + d_rod * rates.state_rates()[1]);
        let (cap, rod) = geometry().volumes(s);
        let expected = BETA * (a1 * a1 / cap + a2 * a2 / rod);
        // the force is linear in the pressures: only round-off remains
        assert!((stiffness - expected).abs() < 1e-9 * expected, "s = {s}: {stiffness} vs {expected}");
        assert!((c.hydraulic_stiffness(s) - expected).abs() < 1e-9 * expected);
    }
}

/// Times of the upward zero crossings of x (linear interpolation between samples).
fn upward_crossings(times: &[f64], x: &[f64]) -> Vec<f64> {
    (1..x.len())
        .filter(|&k| x[k - 1] < 0.0 && x[k] >= 0.0)
        .map(|k| times[k - 1] + (times[k] - times[k - 1]) * x[k - 1] / (x[k - 1] - x[k]))
        .collect()
}

#[test]
fn test_small_free_oscillation_has_the_closed_chamber_natural_frequency() {
    // ω² = β (A1²/V1 + A2²/V2) / m; equilibrium at s0 with p_rod A2 = p_cap A1
    let sys = MassOnCylinder { cylinder: frictionless(), applied: 0.0, damper: 0.0 };
    let s0 = 0.25;
    let omega = (sys.cylinder.hydraulic_stiffness(s0) / MASS).sqrt();
    let h = 2.0 * PI / omega / 400.0;
    let mut y = [s0, 1e-3, 5e6, balancing_rod_pressure(5e6), 0.0];
    let (mut times, mut offsets) = (vec![0.0], vec![0.0]);
    for k in 1..=400 * 30 {
        y = sys.step(&y, h);
        times.push(k as f64 * h);
        offsets.push(y[0] - s0);
    }
    let crossings = upward_crossings(&times, &offsets);
    let period = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    let measured = 2.0 * PI / period;
    // amplitude ~0.8 µm: nonlinearity ~(amplitude/length)²; RK4 phase error ~(ωh)^4/120
    assert!((measured - omega).abs() < 1e-6 * omega, "ω = {measured} vs {omega} rad/s");
    assert!((omega - 1243.0).abs() < 1.0, "ω = {omega}"); // 198 Hz for this cylinder
}

#[test]
fn test_static_pressures_under_a_load_follow_the_closed_chamber_law() {
    // 20 kN pushing the rod in, a test damper settles the mass; at rest
    // p_cap A1 - p_rod A2 = 20 kN and each p_i = p_i0 - β ln(V_i/V_i0)
    let (a1, a2) = (geometry().piston_area(), geometry().rod_side_area());
    let cylinder = frictionless();
    let k = cylinder.hydraulic_stiffness(0.25);
    let sys = MassOnCylinder { cylinder, applied: -2.0e4, damper: (k * MASS).sqrt() };
    let (s0, p10, p20) = (0.25, 5e6, balancing_rod_pressure(5e6));
    let mut y = [s0, 0.0, p10, p20, 0.0];
    let h = 2.0 * PI / (k / MASS).sqrt() / 200.0;
    for _ in 0..200 * 60 {
        y = sys.step(&y, h);
    }
    assert!(y[1].abs() < 1e-9, "still moving at {} m/s", y[1]);
    // the closed-form equilibrium: bisection on p_cap(s) A1 - p_rod(s) A2 = 20 kN
    let (cap0, rod0) = geometry().volumes(s0);
    let pressures = |s: f64| {
        let (cap, rod) = geometry().volumes(s);
        (closed_pressure(p10, cap0, cap, BETA), closed_pressure(p20, rod0, rod, BETA))
    };
    let (mut lo, mut hi) = (s0 - 0.01, s0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        let (p_cap, p_rod) = pressures(mid);
        if p_cap * a1 - p_rod * a2 > 2.0e4 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let (p_cap, p_rod) = pressures(lo);
    // stroke to 1e-9 m, pressures to 1 Pa in 7 MPa (RK4 round-off and the residual motion)
    assert!((y[0] - lo).abs() < 1e-9, "stroke {} vs {lo}", y[0]);
    assert!((y[2] - p_cap).abs() < 1.0 && (y[3] - p_rod).abs() < 1.0, "{y:?} vs {p_cap}, {p_rod}");
    // the rod went in by about W/k = 0.65 mm (the closed form is slightly nonlinear)
    let linear = 2.0e4 / k;
    assert!(((s0 - y[0]) - linear).abs() < 0.02 * linear, "{} vs {linear}", s0 - y[0]);
}

#[test]
fn test_energy_is_conserved_with_friction_off() {
    // a 0.5 m/s kick: a 0.4 mm swing, pressures swinging by ~MPa (nonlinear)
    let sys = MassOnCylinder { cylinder: frictionless(), applied: 0.0, damper: 0.0 };
    let mut y = [0.25, 0.5, 5e6, balancing_rod_pressure(5e6), 0.0];
    let e0 = sys.energy(&y);
    let h = 2.0 * PI / 1243.0 / 400.0;
    let mut worst: f64 = 0.0;
    for _ in 0..400 * 20 {
        y = sys.step(&y, h);
        worst = worst.max((sys.energy(&y) - e0).abs());
    }
    // RK4 at 400 steps per period drifts ~1e-11 of the energy per period
    assert!(worst < 1e-8 * e0, "energy drift {worst} J of {e0} J");
}

#[test]
fn test_stored_energy_change_is_the_work_of_the_pressure_force() {
    // prescribed stroke s = 0.25 + 2 mm sin(2π 5 t): integrate the pressures with
    // evaluate (RK4), the work ∫ F ds/dt dt by the trapezoidal rule, compare with -ΔE
    let c = frictionless();
    let stroke = |t: f64| 0.25 + 0.002 * (10.0 * PI * t).sin();
    let rate = |t: f64| 0.002 * 10.0 * PI * (10.0 * PI * t).cos();
    let eval = |t: f64, p: [f64; 2]| c.evaluate(stroke(t), rate(t), &p, (0.0, 0.0)).unwrap();
    let dp = |t: f64, p: [f64; 2]| {
        let r = eval(t, p);
        [r.state_rates()[0], r.state_rates()[1]]
    };
    let add = |a: [f64; 2], k: [f64; 2], s: f64| [a[0] + s * k[0], a[1] + s * k[1]];
    let (mut p, h) = ([1e7, 1e7], 1e-5);
    let (mut work, e0) = (0.0, c.stored_energy(stroke(0.0), &p));
    for k in 0..20_000 {
        let t = k as f64 * h;
        let k1 = dp(t, p);
        let k2 = dp(t + 0.5 * h, add(p, k1, 0.5 * h));
        let k3 = dp(t + 0.5 * h, add(p, k2, 0.5 * h));
        let k4 = dp(t + h, add(p, k3, h));
        let next = [
            p[0] + h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]),
            p[1] + h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]),
        ];
        work += 0.5 * h * (eval(t, p).force * rate(t) + eval(t + h, next).force * rate(t + h));
        p = next;
        if k % 2500 == 2499 {
            let de = c.stored_energy(stroke(t + h), &p) - e0;
            // |ΔE| reaches ~50 J; the trapezoidal error is ~(ω h)²/12 ~ 1e-8 of the work
            assert!((de + work).abs() < 1e-6 * (1.0 + de.abs()), "t = {}: ΔE {de} J, work {work} J", t + h);
        }
    }
}

#[test]
fn test_energy_with_seal_friction_is_stored_or_dissipated() {
    // kinetic + stored energy + ∫ D dt stays constant, D the LuGre dissipation (>= 0)
    let sys = MassOnCylinder { cylinder: with_seal(), applied: 0.0, damper: 0.0 };
    let SealFriction::Lugre(law) = *sys.cylinder.seal() else { unreachable!() };
    let mut y = [0.25, 0.05, 5e6, balancing_rod_pressure(5e6), 0.0];
    let (e0, kick, h) = (sys.energy(&y), 0.5 * MASS * 0.05 * 0.05, 1e-5);
    let mut dissipated = 0.0;
    for _ in 0..50_000 {
        let before = law.dissipation_rate(y[1], y[4]);
        y = sys.step(&y, h);
        let after = law.dissipation_rate(y[1], y[4]);
        assert!(after >= -1e-9 * after.abs().max(1.0));
        dissipated += 0.5 * h * (before + after);
    }
    let e = sys.energy(&y);
    // the seal took the 25 mJ kick within 0.5 s and sticks: the rod rings at the
    // oil-spring frequency, damped by the bristle hysteresis while faster than
    // v_D = 1 mm/s and by σ1 below
    assert!(dissipated > 0.99 * kick, "dissipated {dissipated} of {kick} J");
    assert!(sys.cylinder.evaluate(y[0], y[1], &y[2..], (0.0, 0.0)).unwrap().stick, "{y:?}");
    // trapezoidal integration of D at h = 10 µs: ~2e-6 of the kick
    assert!((e + dissipated - e0).abs() < 1e-5 * kick, "{e} + {dissipated} vs {e0}");
}

#[test]
fn test_faults_name_the_stroke_and_the_chamber() {
    let c = frictionless();
    let p = [1e6, 1e6];
    for stroke in [-1e-9, 0.5 + 1e-9, f64::NAN] {
        let fault = c.evaluate(stroke, 0.0, &p, (0.0, 0.0)).unwrap_err();
        assert!(matches!(fault, CylinderFault::StrokeOutOfRange { .. }), "{fault:?}");
    }
    assert!(c.evaluate(0.0, 0.0, &p, (0.0, 0.0)).is_ok() && c.evaluate(0.5, 0.0, &p, (0.0, 0.0)).is_ok());
    assert_eq!(
        c.evaluate(0.6, 0.0, &p, (0.0, 0.0)).unwrap_err().to_string(),
        "stroke 6.000000e-1 m left [0, 0.5] m: the piston would pass an end cap (no end stop is modelled)"
    );
    let fault = c.evaluate(0.2, 0.0, &[1e6, -2e5], (0.0, 0.0)).unwrap_err();
    assert_eq!(fault, CylinderFault::PressureBelowFloor { chamber: Chamber::Rod, pressure: -2e5, floor: -101_325.0 });
    assert_eq!(
        fault.to_string(),
        "rod chamber pressure -2.000000e5 Pa fell below the floor -1.013250e5 Pa: the liquid would cavitate (the chamber is emptied faster than it is fed)"
    );
    assert!(c.evaluate(0.2, 0.0, &[f64::NAN, 0.0], (0.0, 0.0)).is_err());
    // absolute pressures: floor 0
    let absolute = c.with_pressure_floor(0.0).unwrap();
    assert!(absolute.evaluate(0.2, 0.0, &[-1.0, 1e5], (0.0, 0.0)).is_err());
    assert_eq!(c.with_pressure_floor(f64::NAN).unwrap_err(), "pressure floor must be finite, got NaN");
}
