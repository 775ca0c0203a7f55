//! Unit quaternions `[w, x, y, z]` (scalar first, Hamilton product, active
//! rotation from body to global coordinates): the orientation coordinates of a
//! spatial rigid body, their rates from the body-frame angular velocity, and
//! moving an orientation by a rotation vector and back (as MuJoCo's
//! `mj_integratePos` and `mj_differentiatePos` do for ball joints).
//!
//! Source: Shuster, "A survey of attitude representations", J. Astronaut. Sci.
//! 41 (1993), with the Hamilton convention of Sola, "Quaternion kinematics for
//! the error-state Kalman filter" (2017), eqs. (101) and (214).

use super::spatial::{Mat3, Vec3};

/// Rotation matrix (body to global) of the unit quaternion `q` [-].
#[inline]
pub fn rotation_matrix(q: &[f64]) -> Mat3 {
    let (w, x, y, z) = (q[0], q[1], q[2], q[3]);
    Mat3::new(
        1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y),
        2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x),
        2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y),
    )
}

/// Hamilton product `a b`.
#[inline]
pub fn product(a: &[f64], b: &[f64]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// `q_dot = q (0, omega) / 2` with `omega` the angular velocity in body coordinates [1/s].
#[inline]
pub fn rates(q: &[f64], omega: Vec3, qdot: &mut [f64]) {
    let p = product(q, &[0.0, omega.x, omega.y, omega.z]);
    for (d, p) in qdot.iter_mut().zip(p) {
        *d = 0.5 * p;
    }
}

/// `exp(theta / 2)`: the unit quaternion of the rotation vector `theta` [rad].
#[inline]
pub fn from_rotation_vector(theta: Vec3) -> [f64; 4] {
    let angle = theta.norm();
    // (sin(a/2)/a by its series below 1e-4 rad: the error is below 1e-17)
    let half_sinc = if angle < 1e-4 { 0.5 - angle * angle / 48.0 } else { (0.5 * angle).sin() / angle };
    [(0.5 * angle).cos(), half_sinc * theta.x, half_sinc * theta.y, half_sinc * theta.z]
}

/// `2 log(q)`: the rotation vector [rad] of the unit quaternion `q`, the shorter way round.
#[inline]
pub fn to_rotation_vector(q: &[f64]) -> Vec3 {
    let sign = if q[0] < 0.0 { -1.0 } else { 1.0 };
    let v = Vec3::new(q[1], q[2], q[3]) * sign;
    let s = v.norm();
    if s < 1e-12 {
        // (2 atan2(s, w) / s -> 2 / w)
        return v * (2.0 / (sign * q[0]));
    }
    v * (2.0 * s.atan2(sign * q[0]) / s)
}

/// Scales `q` to unit length.
#[inline]
pub fn normalise(q: &mut [f64]) {
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    for c in q.iter_mut() {
        *c /= n;
    }
}

/// Turns the orientation `q` by the rotation vector `theta` given in body
/// coordinates [rad]: `q exp(theta / 2)`, normalised.
#[inline]
pub fn integrate(q: &mut [f64], theta: Vec3) {
    let moved = product(q, &from_rotation_vector(theta));
    q.copy_from_slice(&moved);
    normalise(q);
}

/// The body-coordinate rotation vector [rad] that turns `from` into `to`
/// (`to = from exp(theta / 2)`): the inverse of [`integrate`].
#[inline]
pub fn difference(from: &[f64], to: &[f64]) -> Vec3 {
    let conjugate = [from[0], -from[1], -from[2], -from[3]];
    to_rotation_vector(&product(&conjugate, to))
}

/// The unit quaternion of a rotation matrix (Shepperd's method: the largest
/// of the four squared components first, for accuracy at every angle).
pub fn from_rotation_matrix(r: &Mat3) -> [f64; 4] {
    let trace = r.trace();
    let candidates = [trace, r[(0, 0)], r[(1, 1)], r[(2, 2)]];
    let k = (0..4).fold(0, |best, i| if candidates[i] > candidates[best] { i } else { best });
    let mut q = match k {
        0 => [1.0 + trace, r[(2, 1)] - r[(1, 2)], r[(0, 2)] - r[(2, 0)], r[(1, 0)] - r[(0, 1)]],
        1 => [r[(2, 1)] - r[(1, 2)], 1.0 + 2.0 * r[(0, 0)] - trace, r[(0, 1)] + r[(1, 0)], r[(0, 2)] + r[(2, 0)]],
        2 => [r[(0, 2)] - r[(2, 0)], r[(0, 1)] + r[(1, 0)], 1.0 + 2.0 * r[(1, 1)] - trace, r[(1, 2)] + r[(2, 1)]],
        _ => [r[(1, 0)] - r[(0, 1)], r[(0, 2)] + r[(2, 0)], r[(1, 2)] + r[(2, 1)], 1.0 + 2.0 * r[(2, 2)] - trace],
    };
    if q[0] < 0.0 {
        q.iter_mut().for_each(|c| *c = -*c);
    }
    normalise(&mut q);
    q
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Rotation3, Unit, UnitQuaternion};

    fn sample() -> [f64; 4] {
        let mut q = [0.8, -0.3, 0.4, 0.2];
        normalise(&mut q);
        q
    }

    #[test]
    fn rotation_matrix_matches_nalgebra() {
        // nalgebra's unit quaternion stores (i, j, k, w); the matrices must agree
        let q = sample();
        let reference = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(q[0], q[1], q[2], q[3]));
        assert!((rotation_matrix(&q) - reference.to_rotation_matrix().matrix()).norm() < 1e-15);
        assert!((rotation_matrix(&q).determinant() - 1.0).abs() < 1e-14);
        let back = from_rotation_matrix(&rotation_matrix(&q));
        assert!(q.iter().zip(back).all(|(a, b)| (a - b).abs() < 1e-15));
    }

    #[test]
    fn rotation_vector_is_an_axis_and_an_angle() {
        let axis = Vec3::new(2.0, -1.0, 2.0) / 3.0;
        for angle in [0.0, 1e-9, 1e-5, 0.3, 2.0, 3.1] {
            let q = from_rotation_vector(axis * angle);
            let reference = Rotation3::from_axis_angle(&Unit::new_normalize(axis), angle);
            assert!((rotation_matrix(&q) - reference.matrix()).norm() < 1e-15, "angle {angle}");
            assert!((to_rotation_vector(&q) - axis * angle).norm() < 1e-14, "angle {angle}");
        }
    }

    #[test]
    fn rates_are_the_derivative_along_a_body_rotation() {
        // q(t) = q0 exp(omega t / 2) turns at the body angular velocity omega
        let (q0, omega) = (sample(), Vec3::new(0.7, -1.1, 0.4));
        let at = |t: f64| product(&q0, &from_rotation_vector(omega * t));
        let h = 1e-6;
        let mut analytic = [0.0; 4];
        rates(&at(0.3), omega, &mut analytic);
        for i in 0..4 {
            let numeric = (at(0.3 + h)[i] - at(0.3 - h)[i]) / (2.0 * h);
            assert!((numeric - analytic[i]).abs() < 1e-9);
        }
        // and the global angular velocity is R omega: d R/dt = [R omega]x R
        let (r, dr) = (rotation_matrix(&at(0.3)), (rotation_matrix(&at(0.3 + h)) - rotation_matrix(&at(0.3 - h))) / (2.0 * h));
        assert!((dr - super::super::spatial::skew(r * omega) * r).norm() < 1e-8);
    }

    #[test]
    fn difference_undoes_integrate() {
        let theta = Vec3::new(0.2, -0.5, 0.9);
        let from = sample();
        let mut to = from;
        integrate(&mut to, theta);
        assert!((difference(&from, &to) - theta).norm() < 1e-14);
        // the same orientation as -q: the difference is still the short rotation
        let negated = to.map(|c| -c);
        assert!((difference(&from, &negated) - theta).norm() < 1e-14);
    }
}
