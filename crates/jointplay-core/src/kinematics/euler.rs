//! Euler angles in the twelve sequences, intrinsic (rotations about the axes
//! of the frame being turned): `"ZXZ"` (3-1-3, the sequence of paper 002)
//! is `R = R_z(a) R_x(b) R_z(c)`.
//!
//! Extraction follows the closed forms of Diebel, "Representing attitude:
//! Euler angles, unit quaternions, and rotation vectors" (2006), §5, written
//! for any axes with the sign of the permutation; at gimbal lock the third
//! angle is set to zero.

use super::spatial::Mat3;

/// A sequence of three rotation axes (0 x, 1 y, 2 z), each different from the next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EulerSequence(pub [usize; 3]);

impl EulerSequence {
    /// 3-1-3, `R_z R_x R_z`.
    pub const ZXZ: EulerSequence = EulerSequence([2, 0, 2]);
    /// 3-2-1 (yaw, pitch, roll), `R_z R_y R_x`.
    pub const ZYX: EulerSequence = EulerSequence([2, 1, 0]);

    /// The sequence named by three letters of `XYZ` (`"ZXZ"`), each different from the next.
    pub fn parse(name: &str) -> Option<EulerSequence> {
        let axes: Vec<usize> = name.chars().filter_map(|c| "XYZ".find(c.to_ascii_uppercase())).collect();
        let valid = axes.len() == 3 && name.len() == 3 && axes[0] != axes[1] && axes[1] != axes[2];
        valid.then(|| EulerSequence([axes[0], axes[1], axes[2]]))
    }

    /// The sequence's name, `"ZXZ"`.
    pub fn name(self) -> String {
        self.0.iter().map(|&a| ['X', 'Y', 'Z'][a]).collect()
    }

    /// Whether the first and the last axis are the same (a proper Euler sequence).
    fn is_proper(self) -> bool {
        self.0[0] == self.0[2]
    }

    /// `R = R_i(a) R_j(b) R_k(c)` [-].
    pub fn matrix(self, angles: [f64; 3]) -> Mat3 {
        axis_rotation(self.0[0], angles[0]) * axis_rotation(self.0[1], angles[1]) * axis_rotation(self.0[2], angles[2])
    }

    /// The angles `[a, b, c]` [rad] of the rotation matrix `r`: `b` in
    /// `[0, pi]` for a proper sequence and in `[-pi/2, pi/2]` otherwise,
    /// `a` and `c` in `(-pi, pi]`.
    pub fn angles(self, r: &Mat3) -> [f64; 3] {
        let [i, j, k] = self.0;
        if self.is_proper() {
            let m = 3 - i - j;
            let s = permutation_sign(i, j, m);
            let b = r[(i, i)].clamp(-1.0, 1.0).acos();
            if b.sin().abs() < 1e-9 {
                return self.locked(r, b);
            }
            [r[(j, i)].atan2(-s * r[(m, i)]), b, r[(i, j)].atan2(s * r[(i, m)])]
        } else {
            let s = permutation_sign(i, j, k);
            let b = (s * r[(i, k)]).clamp(-1.0, 1.0).asin();
            if b.cos().abs() < 1e-9 {
                return self.locked(r, b);
            }
            [(-s * r[(j, k)]).atan2(r[(k, k)]), b, (-s * r[(i, j)]).atan2(r[(i, i)])]
        }
    }

    /// Angles at gimbal lock: `c = 0`, `a` from `R R_j(b)^T = R_i(a)`.
    fn locked(self, r: &Mat3, b: f64) -> [f64; 3] {
        let first = r * axis_rotation(self.0[1], b).transpose();
        let i = self.0[0];
        let (u, w) = ((i + 1) % 3, (i + 2) % 3);
        [first[(w, u)].atan2(first[(u, u)]), b, 0.0]
    }
}

/// +1 if `(i, j, k)` is a cyclic order of `(0, 1, 2)`, else -1.
fn permutation_sign(i: usize, j: usize, k: usize) -> f64 {
    if (i + 1) % 3 == j && (j + 1) % 3 == k { 1.0 } else { -1.0 }
}

/// Rotation by `angle` [rad] about coordinate axis `axis`.
pub fn axis_rotation(axis: usize, angle: f64) -> Mat3 {
    let (s, c) = angle.sin_cos();
    match axis {
        0 => Mat3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c),
        1 => Mat3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c),
        _ => Mat3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all_sequences() -> Vec<EulerSequence> {
        let mut all = Vec::new();
        for i in 0..3 {
            for j in (0..3).filter(|&j| j != i) {
                for k in (0..3).filter(|&k| k != j) {
                    all.push(EulerSequence([i, j, k]));
                }
            }
        }
        all
    }

    #[test]
    fn there_are_twelve_sequences_and_their_names_parse() {
        let all = all_sequences();
        assert_eq!(all.len(), 12);
        for s in all {
            assert_eq!(EulerSequence::parse(&s.name()), Some(s));
        }
        assert_eq!(EulerSequence::parse("zxz"), Some(EulerSequence::ZXZ));
        assert_eq!(EulerSequence::parse("ZZX"), None);
        assert_eq!(EulerSequence::parse("XYZW"), None);
    }

    #[test]
    fn angles_round_trip_in_every_sequence() {
        for s in all_sequences() {
            let b = if s.is_proper() { 1.1 } else { -0.6 };
            let angles = [0.4, b, -2.3];
            let back = s.angles(&s.matrix(angles));
            assert!(angles.iter().zip(back).all(|(a, b)| (a - b).abs() < 1e-12), "{}: {back:?}", s.name());
        }
    }

    #[test]
    fn gimbal_lock_gives_the_same_matrix() {
        for s in all_sequences() {
            let b = if s.is_proper() { 0.0 } else { std::f64::consts::FRAC_PI_2 };
            let r = s.matrix([0.7, b, 0.5]);
            let back = s.angles(&r);
            assert_eq!(back[2], 0.0);
            assert!((s.matrix(back) - r).norm() < 1e-9, "{}", s.name());
        }
    }

    #[test]
    fn three_one_three_matches_the_closed_form() {
        // Goldstein, Classical Mechanics, 3rd ed., eq. (4.46): the x-convention
        // (z, x', z'') rotation; its transpose is our body-to-global R
        let (phi, theta, psi) = (0.3_f64, 0.8_f64, -1.2_f64);
        let r = EulerSequence::ZXZ.matrix([phi, theta, psi]);
        let (cf, sf, ct, st, cp, sp) = (phi.cos(), phi.sin(), theta.cos(), theta.sin(), psi.cos(), psi.sin());
        let goldstein = Mat3::new(
            cp * cf - ct * sf * sp, cp * sf + ct * cf * sp, sp * st,
            -sp * cf - ct * sf * cp, -sp * sf + ct * cf * cp, cp * st,
            st * sf, -st * cf, ct,
        );
        assert!((r - goldstein.transpose()).norm() < 1e-15);
    }
}
