//! The spatial rigid body checked against what it must equal independently of
//! its code: finite differences of the marker's position and orientation
//! along `displace` (orientations compared by the axial vector of the turn between them), the
//! flow of `position_rates`, Euler's equations written out here, the kinetic
//! energy from the global inertia `R J R^T`, and a torque-free tumbling body
//! integrated by a fixed-step RK4 written here: energy and global angular
//! momentum conserved, and the flip period against the Jacobi elliptic
//! closed form (Landau and Lifshitz, Mechanics, 3rd ed., §37).

use super::*;
use nalgebra::{Rotation3, Unit};

/// A non-diagonal inertia: principal moments (0.02, 0.05, 0.06) kg m^2 along turned axes.
fn turned_inertia() -> Mat3 {
    let axes = *Rotation3::from_axis_angle(&Unit::new_normalize(Vec3::new(0.3, -1.0, 0.5)), 0.7).matrix();
    axes * Mat3::from_diagonal(&Vec3::new(0.02, 0.05, 0.06)) * axes.transpose()
}

fn body() -> SpatialRigidBody {
    SpatialRigidBody::new(2.5, turned_inertia()).expect("a valid inertia")
}

/// Positions with a general orientation (unit quaternion).
fn positions() -> [f64; 7] {
    let mut q = [0.3, -0.2, 0.45, 0.8, -0.3, 0.4, 0.2];
    quaternion::normalise(&mut q[3..7]);
    q
}

const V: [f64; 6] = [1.1, -0.4, 0.7, 2.3, -1.7, 0.9];
const LOCAL: Vec3 = Vec3::new(0.12, -0.05, 0.08);

fn displaced(q: &[f64; 7], dv: &[f64]) -> [f64; 7] {
    let mut moved = *q;
    SpatialRigidBody::displace(&mut moved, dv);
    moved
}

fn unit(k: usize, h: f64) -> [f64; 6] {
    let mut e = [0.0; 6];
    e[k] = h;
    e
}

/// Global rotation vector [rad] taking the orientation `from` to `to`, a
/// small turn: the axial vector of `(D - D^T) / 2` is `sin(theta) n` for
/// `D = to from^T` (accurate where the trace's `acos` is not).
fn global_rotation(from: &Mat3, to: &Mat3) -> Vec3 {
    let d = to * from.transpose();
    let sine = Vec3::new(d[(2, 1)] - d[(1, 2)], d[(0, 2)] - d[(2, 0)], d[(1, 0)] - d[(0, 1)]) * 0.5;
    let angle = sine.norm().asin();
    if angle == 0.0 { sine } else { sine * (angle / sine.norm()) }
}

fn frame(q: &[f64], v: &[f64]) -> SpatialFrame {
    SpatialRigidBody::spatial_frame(q, v)
}

fn jacobian_rows(frame: &SpatialFrame, local: Vec3) -> ([[f64; 6]; 3], [[f64; 6]; 3]) {
    let (mut point, mut angular) = ([[0.0; 6]; 3], [[0.0; 6]; 3]);
    for i in 0..3 {
        let axis = Vec3::ith(i, 1.0);
        SpatialRigidBody::add_spatial_point_jacobian(frame, local, axis, &mut point[i]);
        SpatialRigidBody::add_spatial_angular_jacobian(frame, axis, &mut angular[i]);
    }
    (point, angular)
}

#[test]
fn jacobians_are_the_derivatives_of_the_marker_along_displace() {
    let q = positions();
    let (point, angular) = jacobian_rows(&frame(&q, &V), LOCAL);
    let h = 1e-6;
    for k in 0..6 {
        let (plus, minus) = (frame(&displaced(&q, &unit(k, h)), &V), frame(&displaced(&q, &unit(k, -h)), &V));
        let d_point = (plus.point(LOCAL) - minus.point(LOCAL)) / (2.0 * h);
        let d_angle = global_rotation(&minus.rotation, &plus.rotation) / (2.0 * h);
        for i in 0..3 {
            assert!((d_point[i] - point[i][k]).abs() < 1e-9, "point row {i}, coordinate {k}: {} vs {}", d_point[i], point[i][k]);
            assert!((d_angle[i] - angular[i][k]).abs() < 1e-9, "angle row {i}, coordinate {k}: {} vs {}", d_angle[i], angular[i][k]);
        }
    }
    // and J v is the marker's velocity and the frame's angular velocity
    let at = frame(&q, &V);
    let times_v = |rows: &[[f64; 6]; 3]| Vec3::from_fn(|i, _| rows[i].iter().zip(&V).map(|(j, v)| j * v).sum());
    assert!((times_v(&point) - at.point_velocity(LOCAL)).norm() < 1e-14);
    assert!((times_v(&angular) - at.angular_velocity).norm() < 1e-14);
}

#[test]
fn position_rates_are_the_derivative_of_displace() {
    let q = positions();
    let h = 1e-6;
    let step = |s: f64| displaced(&q, &V.map(|v| v * s));
    let (plus, minus) = (step(h), step(-h));
    let mut rates = [0.0; 7];
    SpatialRigidBody::position_rates(&q, &V, &mut rates);
    for i in 0..7 {
        assert!(((plus[i] - minus[i]) / (2.0 * h) - rates[i]).abs() < 1e-9, "coordinate {i}");
    }
    // the quaternion's rate keeps its length: q . q_dot = 0
    assert!(q[3..7].iter().zip(&rates[3..7]).map(|(a, b)| a * b).sum::<f64>().abs() < 1e-15);
}

#[test]
fn difference_inverts_displace() {
    let q = positions();
    for dv in [[0.1, -0.2, 0.3, 0.4, -0.9, 1.3], [0.0; 6], [1e-9, 0.0, 0.0, -1e-8, 2e-9, 0.0], [0.0, 0.0, 0.0, 2.9, 0.4, -0.3]] {
        let moved = displaced(&q, &dv);
        let mut back = [0.0; 6];
        SpatialRigidBody::difference(&q, &moved, &mut back);
        assert!(dv.iter().zip(back).all(|(a, b)| (a - b).abs() < 1e-13), "{dv:?} came back as {back:?}");
        // and the displaced orientation is the body-frame turn R exp([dv_ang]x) (nalgebra's exp)
        let turn = *Rotation3::new(Vec3::new(dv[3], dv[4], dv[5])).matrix();
        assert!((frame(&moved, &V).rotation - frame(&q, &V).rotation * turn).norm() < 1e-14);
    }
}

#[test]
fn bias_accelerations_are_the_marker_accelerations_at_constant_velocity_coordinates() {
    // at constant v the body turns as R(t) = R exp(t [omega]x), which displace by t v follows exactly
    let q = positions();
    let h = 1e-5;
    let at = |t: f64| frame(&displaced(&q, &V.map(|v| v * t)), &V);
    let (point, angular) = SpatialRigidBody::spatial_bias_acceleration(&at(0.0), LOCAL);
    let d_point = (at(h).point_velocity(LOCAL) - at(-h).point_velocity(LOCAL)) / (2.0 * h);
    let d_angular = (at(h).angular_velocity - at(-h).angular_velocity) / (2.0 * h);
    assert!((d_point - point).norm() < 1e-8, "{d_point:?} vs {point:?}");
    assert_eq!(angular, Vec3::zeros());
    assert!(d_angular.norm() < 1e-9);
}

/// `(q, v)` after `t` [s] with the velocity coordinates `v(t) = v + a t`: RK4 on `position_rates` in `n` steps.
fn moved_with_accelerations(q: &[f64; 7], a: &[f64; 6], t: f64, n: usize) -> ([f64; 7], [f64; 6]) {
    let velocity = |s: f64| std::array::from_fn::<f64, 6, _>(|i| V[i] + a[i] * s);
    let rates = |q: &[f64; 7], s: f64| {
        let mut r = [0.0; 7];
        SpatialRigidBody::position_rates(q, &velocity(s), &mut r);
        r
    };
    let (mut y, h) = (*q, t / n as f64);
    for step in 0..n {
        let s = step as f64 * h;
        let shifted = |y: &[f64; 7], k: &[f64; 7], c: f64| std::array::from_fn::<f64, 7, _>(|i| y[i] + c * k[i]);
        let k1 = rates(&y, s);
        let k2 = rates(&shifted(&y, &k1, h / 2.0), s + h / 2.0);
        let k3 = rates(&shifted(&y, &k2, h / 2.0), s + h / 2.0);
        let k4 = rates(&shifted(&y, &k3, h), s + h);
        y = std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
    }
    (y, velocity(t))
}

#[test]
fn marker_acceleration_is_the_derivative_of_the_marker_velocity() {
    let (q, a) = (positions(), [0.5, -1.5, 2.0, -3.0, 1.2, 4.0]);
    let h = 1e-4;
    let at = |t: f64| {
        let (q, v) = moved_with_accelerations(&q, &a, t, 8);
        frame(&q, &v)
    };
    let (point, angular) = SpatialRigidBody::spatial_marker_acceleration(&frame(&q, &V), LOCAL, &a);
    let d_point = (at(h).point_velocity(LOCAL) - at(-h).point_velocity(LOCAL)) / (2.0 * h);
    let d_angular = (at(h).angular_velocity - at(-h).angular_velocity) / (2.0 * h);
    assert!((d_point - point).norm() < 1e-6, "{d_point:?} vs {point:?}");
    assert!((d_angular - angular).norm() < 1e-6, "{d_angular:?} vs {angular:?}");
}

#[test]
fn a_wrench_does_the_virtual_work_of_the_force_and_the_moment() {
    let q = positions();
    let at = frame(&q, &V);
    let p = at.point(LOCAL);
    let wrench = Wrench { force: Vec3::new(-40.0, 75.0, 12.0), moment: Vec3::new(3.0, -1.0, 2.5) };
    let mut generalised = [0.0; 6];
    SpatialRigidBody::add_wrench(&at, p, &wrench, &mut generalised);
    let power: f64 = generalised.iter().zip(&V).map(|(g, v)| g * v).sum();
    let expected = wrench.force.dot(&at.point_velocity(LOCAL)) + wrench.moment.dot(&at.angular_velocity);
    assert!((power - expected).abs() < 1e-12 * expected.abs(), "{power} vs {expected}");
}

/// Accelerations from the body's contract: `M^-1 (Q + gyroscopic forces)` with `Q` of `wrench` at `p`.
fn contract_accelerations(body: &SpatialRigidBody, q: &[f64], p: Vec3, wrench: &Wrench) -> [f64; 6] {
    let mut force = [0.0; 6];
    SpatialRigidBody::add_wrench(&frame(q, &V), p, wrench, &mut force);
    body.add_gyroscopic_forces(&V, &mut force);
    let mut a = [0.0; 6];
    body.solve_inverse_mass(&force, &mut a);
    a
}

#[test]
fn accelerations_follow_newton_and_euler_equations() {
    // m a_G = f; J omega_dot + omega x (J omega) = M_body, M_body = R^T ((p - r_G) x f + m)
    let q = positions();
    let (p, wrench) = (Vec3::new(0.5, 0.1, -0.3), Wrench { force: Vec3::new(4.0, -7.0, 1.5), moment: Vec3::new(0.2, 0.05, -0.3) });
    for inertia in [turned_inertia(), Mat3::from_diagonal(&Vec3::new(0.02, 0.05, 0.06))] {
        let body = SpatialRigidBody::new(2.5, inertia).expect("a valid inertia");
        let a = contract_accelerations(&body, &q, p, &wrench);
        let r = quaternion::rotation_matrix(&q[3..7]);
        let omega = Vec3::new(V[3], V[4], V[5]);
        let moment_body = r.transpose() * ((p - Vec3::new(q[0], q[1], q[2])).cross(&wrench.force) + wrench.moment);
        let inverse = inertia.try_inverse().expect("an invertible inertia");
        let omega_dot = inverse * (moment_body - omega.cross(&(inertia * omega)));
        let a_g = wrench.force / 2.5;
        for i in 0..3 {
            assert!((a[i] - a_g[i]).abs() < 1e-14 * a_g.norm());
            assert!((a[i + 3] - omega_dot[i]).abs() < 1e-12 * omega_dot.norm(), "{a:?} vs {omega_dot:?}");
        }
    }
    // a diagonal inertia keeps the diagonal mass block (the constraint solver's fast path)
    let diagonal = SpatialRigidBody::principal(2.5, [0.02, 0.05, 0.06]).expect("valid");
    assert!(matches!(diagonal.mass_block(), MassBlock::ConstantDiagonal(w) if w == [0.4, 0.4, 0.4, 50.0, 20.0, 1.0 / 0.06]));
    // and the factored block solves as the body does (what a solver holding only the block does)
    let factored = body();
    let MassBlock::ConstantFactored { program, factor } = factored.mass_block() else { panic!("products of inertia factor the block") };
    let f = [1.0, -2.0, 0.5, 0.3, -0.7, 0.2];
    let (mut from_block, mut from_body) = (f, [0.0; 6]);
    program.solve(factor, &mut from_block);
    factored.solve_inverse_mass(&f, &mut from_body);
    assert_eq!(from_block, from_body);
    let mut mass = Mat3::zeros().resize(6, 6, 0.0);
    mass.view_mut((0, 0), (3, 3)).copy_from(&(Mat3::identity() * 2.5));
    mass.view_mut((3, 3), (3, 3)).copy_from(&turned_inertia());
    let back = mass * nalgebra::DVector::from_column_slice(&from_body);
    assert!(back.iter().zip(f).all(|(b, f)| (b - f).abs() < 1e-13), "M M^-1 f = {back:?}");
}

#[test]
fn kinetic_energy_is_that_of_the_global_inertia() {
    let (body, q) = (body(), positions());
    let at = frame(&q, &V);
    let global_inertia = at.rotation * body.inertia * at.rotation.transpose();
    let expected = 0.5 * 2.5 * at.velocity.norm_squared() + 0.5 * at.angular_velocity.dot(&(global_inertia * at.angular_velocity));
    assert!((body.kinetic_energy_of_motion(&V) - expected).abs() < 1e-14 * expected);
    // gravity: the force is minus the gradient of the potential along the translations
    let g = Vec3::new(0.5, -9.81, 1.0);
    let mut force = [0.0; 6];
    body.add_weight(g, &mut force);
    for (k, force) in force.iter().enumerate() {
        let h = 1e-3;
        let gradient = (body.potential_energy(g, &displaced(&q, &unit(k, h))) - body.potential_energy(g, &displaced(&q, &unit(k, -h)))) / (2.0 * h);
        assert!((force + gradient).abs() < 1e-12, "coordinate {k}");
    }
}

/// The torque-free body's state `[q, v]` after one RK4 step of `h` [s], the quaternion normalised after it.
fn torque_free_step(body: &SpatialRigidBody, y: &[f64; 13], h: f64) -> [f64; 13] {
    let rates = |y: &[f64; 13]| {
        let mut dy = [0.0; 13];
        SpatialRigidBody::position_rates(&y[..7], &y[7..], &mut dy[..7]);
        let mut force = [0.0; 6];
        body.add_gyroscopic_forces(&y[7..], &mut force);
        body.solve_inverse_mass(&force, &mut dy[7..]);
        dy
    };
    let shifted = |k: &[f64; 13], c: f64| std::array::from_fn::<f64, 13, _>(|i| y[i] + c * k[i]);
    let k1 = rates(y);
    let k2 = rates(&shifted(&k1, h / 2.0));
    let k3 = rates(&shifted(&k2, h / 2.0));
    let k4 = rates(&shifted(&k3, h));
    let mut next: [f64; 13] = std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
    SpatialRigidBody::normalise_positions(&mut next[..7]);
    next
}

/// Global angular momentum `R J omega` [kg m^2/s] of the state `y`.
fn angular_momentum(body: &SpatialRigidBody, y: &[f64; 13]) -> Vec3 {
    quaternion::rotation_matrix(&y[3..7]) * body.inertia * Vec3::new(y[10], y[11], y[12])
}

/// `K(k)` by the arithmetic-geometric mean: `pi / (2 AGM(1, sqrt(1 - k^2)))`.
fn complete_elliptic_k(k2: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - k2).sqrt());
    while (a - b).abs() > 1e-16 * a {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

#[test]
fn a_tumbling_body_keeps_energy_and_angular_momentum_and_flips_with_the_elliptic_period() {
    // I = (1, 2, 3) kg m^2, spun near the intermediate axis: it flips over and back
    let (i1, i2, i3) = (1.0, 2.0, 3.0);
    let body = SpatialRigidBody::principal(1.0, [i1, i2, i3]).expect("valid");
    let mut y = [0.0; 13];
    y[3] = 1.0;
    y[10..].copy_from_slice(&[0.02, 1.0, 0.02]);
    let (energy, momentum) = (body.kinetic_energy_of_motion(&y[7..]), angular_momentum(&body, &y));
    // Landau-Lifshitz §37 (M^2 > 2 E I_2): omega_2 ~ sn(tau, k), period 4 K(k) in tau,
    // tau = t sqrt((I3 - I2)(M^2 - 2 E I1) / (I1 I2 I3))
    let (m2, e2) = (momentum.norm_squared(), 2.0 * energy);
    let k2 = (i2 - i1) * (e2 * i3 - m2) / ((i3 - i2) * (m2 - e2 * i1));
    let period = 4.0 * complete_elliptic_k(k2) * (i1 * i2 * i3 / ((i3 - i2) * (m2 - e2 * i1))).sqrt();
    let h = 2e-3;
    let (mut t, mut crossings) = (0.0, Vec::new());
    while t < 20.0 * period {
        let next = torque_free_step(&body, &y, h);
        if y[11].signum() != next[11].signum() {
            crossings.push(t + h * y[11] / (y[11] - next[11]));
        }
        (y, t) = (next, t + h);
    }
    let relative_energy = (body.kinetic_energy_of_motion(&y[7..]) - energy).abs() / energy;
    let relative_momentum = (angular_momentum(&body, &y) - momentum).norm() / momentum.norm();
    assert!(relative_energy < 1e-10, "energy drifted by {relative_energy:e}");
    assert!(relative_momentum < 1e-10, "angular momentum drifted by {relative_momentum:e}");
    // omega_2 changes sign twice a period
    assert!(crossings.len() >= 39, "{} sign changes in 20 periods of {period} s", crossings.len());
    let measured = 2.0 * (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    assert!((measured - period).abs() < 1e-9 * period, "measured period {measured} s, closed form {period} s");
}

#[test]
fn the_planar_projection_is_the_spatial_body_turning_about_z() {
    // positions with R = R_z(0.7): the planar methods are rows x and y and the z row of the spatial ones
    let phi = 0.7_f64;
    let q = [0.3, -0.2, 0.45, (phi / 2.0).cos(), 0.0, 0.0, (phi / 2.0).sin()];
    let v = [1.1, -0.4, 0.0, 0.0, 0.0, 2.3];
    let (planar, spatial) = (SpatialRigidBody::frame(&q, &v), frame(&q, &v));
    assert!((planar.angle - phi).abs() < 1e-15 && (planar.angular_velocity - 2.3).abs() < 1e-15);
    let local = Vec2::new(0.12, -0.05);
    let local3 = Vec3::new(local.x, local.y, 0.0);
    let (mut jx, mut jy) = ([0.0; 6], [0.0; 6]);
    SpatialRigidBody::marker_jacobian(&planar, local, 1.0, &mut jx, &mut jy);
    let (point, angular) = jacobian_rows(&spatial, local3);
    let mut angle = [0.0; 6];
    SpatialRigidBody::add_marker_angle_jacobian(1.0, &mut angle);
    for k in 0..6 {
        assert!((jx[k] - point[0][k]).abs() < 1e-15 && (jy[k] - point[1][k]).abs() < 1e-15, "coordinate {k}");
        assert!((angle[k] - angular[2][k]).abs() < 1e-15, "coordinate {k}");
    }
    // accelerations in the plane
    let a = [0.5, -1.5, 0.0, 0.0, 0.0, 4.0];
    let (point_acceleration, _) = SpatialRigidBody::spatial_marker_acceleration(&spatial, local3, &a);
    let planar_acceleration = SpatialRigidBody::marker_acceleration(&planar, &a, local);
    assert!((planar_acceleration - point_acceleration.xy()).norm() < 1e-14);
    // a planar force and moment are the wrench in the plane
    let (p, f, m) = (Vec2::new(0.4, 0.1), Vec2::new(3.0, -2.0), 0.7);
    let (mut from_planar, mut from_wrench) = ([0.0; 6], [0.0; 6]);
    SpatialRigidBody::add_point_force(&planar, p, f, &mut from_planar);
    SpatialRigidBody::add_moment(m, &mut from_planar);
    let wrench = Wrench { force: Vec3::new(f.x, f.y, 0.0), moment: Vec3::new(0.0, 0.0, m) };
    SpatialRigidBody::add_wrench(&spatial, Vec3::new(p.x, p.y, q[2]), &wrench, &mut from_wrench);
    assert!(from_planar.iter().zip(from_wrench).all(|(a, b)| (a - b).abs() < 1e-14), "{from_planar:?} vs {from_wrench:?}");
    // a rigid motion about the global z: the spatial frame turns at (0, 0, omega)
    let mut rigid = [0.0; 6];
    SpatialRigidBody::rigid_motion_velocities(&positions(), Vec2::new(0.3, 0.2), 1.7, &mut rigid);
    let moving = frame(&positions(), &rigid);
    assert!((moving.angular_velocity - Vec3::new(0.0, 0.0, 1.7)).norm() < 1e-15);
}

#[test]
fn derived_channels_give_the_global_angular_velocity_and_the_euler_angles() {
    let q = positions();
    let mut values = [0.0; 6];
    SpatialRigidBody::derived_values(&q, &V, EulerSequence::ZXZ, &mut values);
    let names = SpatialRigidBody::derived_channels(EulerSequence::ZXZ);
    assert_eq!(names.len(), values.len());
    assert_eq!(names[3].0, "euler_zxz_1");
    // the global angular velocity is the rate of the orientation along the motion
    let h = 1e-6;
    let (plus, minus) = (frame(&displaced(&q, &V.map(|v| v * h)), &V), frame(&displaced(&q, &V.map(|v| -v * h)), &V));
    let rate = global_rotation(&minus.rotation, &plus.rotation) / (2.0 * h);
    assert!((rate - Vec3::new(values[0], values[1], values[2])).norm() < 1e-9);
    // the angles rebuild the rotation R_z(a) R_x(b) R_z(c) (Goldstein's x-convention)
    let rebuilt = EulerSequence::ZXZ.matrix([values[3], values[4], values[5]]);
    assert!((rebuilt - frame(&q, &V).rotation).norm() < 1e-14);
    assert_eq!(SpatialRigidBody::position_channels().len(), SpatialRigidBody::NQ);
    assert_eq!(SpatialRigidBody::velocity_channels().len(), SpatialRigidBody::NV);
}

#[test]
fn invalid_mass_properties_are_refused_with_the_reason() {
    let refused = |mass: f64, inertia: Mat3| SpatialRigidBody::new(mass, inertia).expect_err("refused");
    let diagonal = |a: f64, b: f64, c: f64| Mat3::from_diagonal(&Vec3::new(a, b, c));
    assert!(refused(0.0, diagonal(1.0, 1.0, 1.0)).contains("mass must be > 0 kg"));
    assert!(refused(1.0, diagonal(1.0, 1.0, 2.5)).contains("triangle inequality"));
    assert!(refused(1.0, diagonal(1.0, -1.0, 1.0)).contains("positive definite"));
    let mut skewed = turned_inertia();
    skewed[(0, 1)] += 1e-3;
    assert!(refused(1.0, skewed).contains("symmetric"));
    assert!(refused(1.0, diagonal(f64::NAN, 1.0, 1.0)).contains("finite"));
    // a thin plate sits on the triangle inequality and is accepted, so is a tensor rotated with round-off
    assert!(SpatialRigidBody::new(1.0, diagonal(1.0, 2.0, 3.0)).is_ok());
    assert!(SpatialRigidBody::new(1.0, turned_inertia()).is_ok());
}
