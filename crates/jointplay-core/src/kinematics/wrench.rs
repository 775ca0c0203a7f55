//! Wrenches: a force and a moment, the load a spatial element puts on a body.

use super::spatial::Vec3;

/// A force [N] through a point and a moment [N m].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Wrench {
    /// Force [N].
    pub force: Vec3,
    /// Moment about the reference point [N m].
    pub moment: Vec3,
}

impl Wrench {
    /// The same load about another point: a wrench with moment `m` about `a`
    /// has moment `m + (a - b) x f` about `b`.
    #[inline]
    pub fn shifted(&self, from: Vec3, to: Vec3) -> Wrench {
        Wrench { force: self.force, moment: self.moment + (from - to).cross(&self.force) }
    }

    /// The load with both vectors expressed in another basis (`rotation` maps this basis to the other).
    #[inline]
    pub fn rotated(&self, rotation: &super::spatial::Mat3) -> Wrench {
        Wrench { force: rotation * self.force, moment: rotation * self.moment }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shifting_keeps_the_power_of_a_rigid_motion() {
        // power F . v_P + M_P . omega is the same about any point of a rigid body
        let (f, m_a) = (Vec3::new(1.0, -2.0, 0.5), Vec3::new(0.3, 0.1, -0.2));
        let (a, b) = (Vec3::new(0.1, 0.2, 0.3), Vec3::new(-0.4, 0.0, 0.7));
        let (v_a, omega) = (Vec3::new(0.5, 0.5, -1.0), Vec3::new(2.0, -1.0, 0.3));
        let v_b = v_a + omega.cross(&(b - a));
        let about_b = Wrench { force: f, moment: m_a }.shifted(a, b);
        let power_a = f.dot(&v_a) + m_a.dot(&omega);
        let power_b = f.dot(&v_b) + about_b.moment.dot(&omega);
        assert!((power_a - power_b).abs() < 1e-14);
    }
}
