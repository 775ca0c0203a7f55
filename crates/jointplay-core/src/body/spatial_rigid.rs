//! Spatial rigid body with its frame at the centre of mass: positions
//! `q = (x, y, z, w, qx, qy, qz)` [m, -] (centre of mass, unit quaternion
//! scalar first, body to global), velocities `v = (vx, vy, vz, wx, wy, wz)`
//! [m/s, rad/s]: the centre of mass's velocity in global coordinates and the
//! angular velocity `omega` in BODY coordinates. The mass is constant,
//! `diag(m, m, m, J)` with `J` the inertia tensor about the centre of mass in
//! body coordinates, and the equations of motion of the angular coordinates
//! are Euler's, `J omega_dot + omega x J omega = M_body` (the Newton-Euler
//! equations as Shabana, "Dynamics of Multibody Systems", writes them).
//!
//! Why body rates: `J` is then constant (the global tensor `R J R^T` changes as
//! the body turns), so the mass block is factored once and the only velocity
//! term is the gyroscopic `-omega x (J omega)`; the orientation moves on the
//! quaternion by `q_dot = q (0, omega) / 2` (Sola, "Quaternion kinematics for
//! the error-state Kalman filter", 2017, eq. 214) and is integrated and differenced
//! by a body-frame rotation vector, as MuJoCo's free joint does
//! (`mj_integratePos`, `mj_differentiatePos`). Theory:
//! `docs/theory/spatial-rigid-body.md`.
//!
//! Its planar methods are its projection on the plane `z = 0`, exact while it
//! moves in a plane `z = const` turning about `z` (the rotation `R = R_z(phi)`):
//! the planar frame has the angle `phi = atan2(R_10, R_00)` and the angular
//! velocity `(R omega)_z`, the point Jacobian along `(a_x, a_y)` is rows x and y
//! of the spatial one (columns vx, vy and wz), the angle Jacobian the z row of
//! the angular one (column wz).

use super::{channel, ChannelName, MassBlock};
use std::ops::Range;

use super::BodyModel;
use crate::kinematics::marker::{Marker, MarkerFrames, Site, SpatialMarker};
use crate::kinematics::planar::{cross, perp, Frame, Vec2};
use crate::kinematics::euler::EulerSequence;
use crate::kinematics::quaternion;
use crate::kinematics::spatial::{Mat3, SpatialFrame, Vec3};
use crate::kinematics::wrench::Wrench;
use crate::linalg::PatternLdl;

/// Relative size [-] below which an asymmetry of the inertia tensor or a
/// violated triangle inequality is taken as round-off (of the order of the
/// error of computing a tensor by rotating principal values).
const INERTIA_ROUND_OFF: f64 = 1e-12;

/// Mass properties of a spatial rigid body and its factored mass block.
#[derive(Clone, Debug, PartialEq)]
pub struct SpatialRigidBody {
    /// Mass m [kg].
    pub mass: f64,
    /// Inertia tensor `J` about the centre of mass in body coordinates [kg m^2].
    pub inertia: Mat3,
    /// `M^-1` as the equations of motion use it.
    inverse_mass: InverseMass,
    /// The Euler sequence of its orientation channels (3-2-1, `ZYX`, by default:
    /// free of gimbal lock at the identity, where bodies often start).
    pub euler_sequence: EulerSequence,
}

/// The inverse of `diag(m, m, m, J)`.
#[derive(Clone, Debug, PartialEq)]
enum InverseMass {
    /// `J` diagonal: `(1/m, 1/m, 1/m, 1/J_xx, 1/J_yy, 1/J_zz)` [1/kg, 1/(kg m^2)].
    Diagonal([f64; 6]),
    /// `J` with products of inertia: the `L D L^T` factor of the 6x6 block
    /// (three 1x1 groups and one 3x3 group, made once).
    Factored {
        /// The factorisation's program.
        program: PatternLdl,
        /// The factor's values.
        factor: Vec<f64>,
    },
}

impl SpatialRigidBody {
    /// Position coordinates `(x, y, z, w, qx, qy, qz)`.
    pub const NQ: usize = 7;
    /// Velocity coordinates `(vx, vy, vz, wx, wy, wz)`.
    pub const NV: usize = 6;

    /// Body of mass `mass` > 0 [kg] and inertia tensor `inertia` about the centre
    /// of mass in body coordinates [kg m^2]: symmetric, positive definite, its
    /// principal moments obeying the triangle inequalities `I_a + I_b >= I_c`
    /// (what a distribution of mass can have).
    pub fn new(mass: f64, inertia: Mat3) -> Result<Self, String> {
        if !(mass.is_finite() && mass > 0.0) {
            return Err(format!("the mass must be > 0 kg, got {mass}"));
        }
        let inertia = validated_inertia(inertia)?;
        let inverse_mass = InverseMass::of(mass, &inertia)?;
        Ok(Self { mass, inertia, inverse_mass, euler_sequence: EulerSequence::ZYX })
    }

    /// Body of mass `mass` [kg] with principal moments `principal` [kg m^2] along its body axes.
    pub fn principal(mass: f64, principal: [f64; 3]) -> Result<Self, String> {
        Self::new(mass, Mat3::from_diagonal(&Vec3::from(principal)))
    }

    /// Spatial frame at the centre of mass: rotation from the quaternion,
    /// angular velocity in global coordinates `R omega`.
    #[inline]
    pub fn spatial_frame(q: &[f64], v: &[f64]) -> SpatialFrame {
        let rotation = quaternion::rotation_matrix(&q[3..7]);
        SpatialFrame {
            position: Vec3::new(q[0], q[1], q[2]),
            rotation,
            velocity: Vec3::new(v[0], v[1], v[2]),
            angular_velocity: rotation * body_rates(v),
        }
    }

    /// The projection of [`Self::spatial_frame`] on the plane `z = 0`: angle
    /// `atan2(R_10, R_00)` [rad], angular velocity `(R omega)_z` [rad/s].
    #[inline]
    pub fn frame(q: &[f64], v: &[f64]) -> Frame {
        let r = quaternion::rotation_matrix(&q[3..7]);
        let angle = r[(1, 0)].atan2(r[(0, 0)]);
        let (sin, cos) = angle.sin_cos();
        Frame {
            position: Vec2::new(q[0], q[1]),
            angle,
            cos,
            sin,
            velocity: Vec2::new(v[0], v[1]),
            angular_velocity: r.row(2).transpose().dot(&body_rates(v)),
        }
    }

    /// Adds `along . d(v_P)/d(v)` of the point `local` [m] of the body frame
    /// `frame` to `out`: `v_P = v + R (omega x s)`, so the block is
    /// `[a, s x (R^T a)]` with `s = local`, `a = along` [m/m, m/rad times the unit of `along`].
    #[inline]
    pub fn add_spatial_point_jacobian(frame: &SpatialFrame, local: Vec3, along: Vec3, out: &mut [f64]) {
        let moment_arm = local.cross(&frame.to_local(along));
        add_to(out, along, moment_arm);
    }

    /// Adds `along . d(R omega)/d(v)`, the block `[0, R^T a]`, to `out` [rad/rad times the unit of `along`].
    #[inline]
    pub fn add_spatial_angular_jacobian(frame: &SpatialFrame, along: Vec3, out: &mut [f64]) {
        add_to(out, Vec3::zeros(), frame.to_local(along));
    }

    /// Point and angular acceleration [m/s^2, rad/s^2] (global) of a marker at
    /// `local` [m] at zero coordinate accelerations: `(omega_g x (omega_g x R s), 0)`.
    ///
    /// The angular part is zero because the angular coordinates are body rates:
    /// with `omega_g = R omega` and `R_dot = R [omega]x`,
    /// `d(omega_g)/dt = R [omega]x omega + R omega_dot = R omega_dot`,
    /// linear in the coordinate accelerations with no velocity term.
    #[inline]
    pub fn spatial_bias_acceleration(frame: &SpatialFrame, local: Vec3) -> (Vec3, Vec3) {
        (frame.point_centripetal_acceleration(local), Vec3::zeros())
    }

    /// Point and angular acceleration [m/s^2, rad/s^2] (global) of a marker at
    /// `local` [m] for the coordinate accelerations `a`:
    /// `(a_G + alpha x R s + omega_g x (omega_g x R s), alpha)` with `alpha = R omega_dot`.
    #[inline]
    pub fn spatial_marker_acceleration(frame: &SpatialFrame, local: Vec3, a: &[f64]) -> (Vec3, Vec3) {
        let alpha = frame.rotate(body_rates(a));
        let arm = frame.rotate(local);
        let point = Vec3::new(a[0], a[1], a[2]) + alpha.cross(&arm) + frame.point_centripetal_acceleration(local);
        (point, alpha)
    }

    /// Adds the generalised force of the force `wrench.force` [N] at the global
    /// point `point` [m] and the moment `wrench.moment` [N m] (global) to `out`:
    /// `[f, R^T (r x f + m)]` with `r = point - r_G`, by the virtual power
    /// `f . v_P + m . omega_g`.
    #[inline]
    pub fn add_wrench(frame: &SpatialFrame, point: Vec3, wrench: &Wrench, out: &mut [f64]) {
        let moment = (point - frame.position).cross(&wrench.force) + wrench.moment;
        add_to(out, wrench.force, frame.to_local(moment));
    }

    /// Rows x and y of the point Jacobian of `local` [m] in the planar frame,
    /// times `scale` (see the module's documentation).
    #[inline]
    pub fn marker_jacobian(frame: &Frame, local: Vec2, scale: f64, jx: &mut [f64], jy: &mut [f64]) {
        let s = frame.rotate(local) * scale;
        jx.copy_from_slice(&[scale, 0.0, 0.0, 0.0, 0.0, -s.y]);
        jy.copy_from_slice(&[0.0, scale, 0.0, 0.0, 0.0, s.x]);
    }

    /// Adds `along . d(v_P)/d(v)` of the planar point `local` [m] to `out`.
    #[inline]
    pub fn add_marker_jacobian(frame: &Frame, local: Vec2, along: Vec2, out: &mut [f64]) {
        out[0] += along.x;
        out[1] += along.y;
        out[5] += along.dot(&perp(frame.rotate(local)));
    }

    /// Adds `scale d(omega_z)/d(v)` (in the plane, `omega_z = wz`) to `out`.
    #[inline]
    pub fn add_marker_angle_jacobian(scale: f64, out: &mut [f64]) {
        out[5] += scale;
    }

    /// Planar acceleration [m/s^2] of the point `local` [m]: `a_G + alpha perp(A s) - omega^2 A s`.
    #[inline]
    pub fn marker_acceleration(frame: &Frame, a: &[f64], local: Vec2) -> Vec2 {
        let s = frame.rotate(local);
        let omega = frame.angular_velocity;
        Vec2::new(a[0], a[1]) + perp(s) * a[5] - s * (omega * omega)
    }

    /// Planar angular acceleration [rad/s^2] (in the plane, `wz_dot`).
    #[inline]
    pub fn marker_angular_acceleration(a: &[f64]) -> f64 {
        a[5]
    }

    /// The planar force `f` [N] at `p` [m]: on `(vx, vy)`, its moment about the centre of mass on `wz`.
    #[inline]
    pub fn add_point_force(frame: &Frame, p: Vec2, f: Vec2, out: &mut [f64]) {
        out[0] += f.x;
        out[1] += f.y;
        out[5] += cross(p - frame.position, f);
    }

    /// The planar moment `m` [N m] about `z`, on `wz`.
    #[inline]
    pub fn add_moment(m: f64, out: &mut [f64]) {
        out[5] += m;
    }

    /// The velocities of the body moving with its centre of mass at `velocity`
    /// [m/s] and turning about the global `z` at `angular_velocity` [rad/s]:
    /// `omega = R^T (0, 0, angular_velocity)`. (Their rates need no bias: in such
    /// a motion `omega_dot = -omega x omega = 0`.)
    pub fn rigid_motion_velocities(q: &[f64], velocity: Vec2, angular_velocity: f64, v: &mut [f64]) {
        let rotation = quaternion::rotation_matrix(&q[3..7]);
        let omega = rotation.transpose() * Vec3::new(0.0, 0.0, angular_velocity);
        v.copy_from_slice(&[velocity.x, velocity.y, 0.0, omega.x, omega.y, omega.z]);
    }

    /// The mass block: diagonal when `J` is, else factored once.
    #[inline]
    pub fn mass_block(&self) -> MassBlock<'_> {
        match &self.inverse_mass {
            InverseMass::Diagonal(w) => MassBlock::ConstantDiagonal(w),
            InverseMass::Factored { program, factor } => MassBlock::ConstantFactored { program, factor },
        }
    }

    /// `out = M^-1 f` [m/s^2, rad/s^2].
    #[inline]
    pub fn solve_inverse_mass(&self, f: &[f64], out: &mut [f64]) {
        match &self.inverse_mass {
            InverseMass::Diagonal(w) => {
                for ((o, w), f) in out.iter_mut().zip(w).zip(f) {
                    *o = w * f;
                }
            }
            InverseMass::Factored { program, factor } => {
                out.copy_from_slice(f);
                program.solve(factor, out);
            }
        }
    }

    /// Adds the gyroscopic force `-omega x (J omega)` [N m] to the angular coordinates of `out`.
    #[inline]
    pub fn add_gyroscopic_forces(&self, v: &[f64], out: &mut [f64]) {
        let omega = body_rates(v);
        add_to(out, Vec3::zeros(), -omega.cross(&(self.inertia * omega)));
    }

    /// `q_dot = (v, q (0, omega) / 2)`.
    #[inline]
    pub fn position_rates(q: &[f64], v: &[f64], qdot: &mut [f64]) {
        qdot[..3].copy_from_slice(&v[..3]);
        quaternion::rates(&q[3..7], body_rates(v), &mut qdot[3..7]);
    }

    /// Moves `q` by `dv`: the centre of mass by `dv[..3]` [m], the orientation by
    /// the body-frame rotation vector `dv[3..]` [rad], `q exp(dv_ang / 2)` normalised.
    #[inline]
    pub fn displace(q: &mut [f64], dv: &[f64]) {
        for (q, d) in q[..3].iter_mut().zip(&dv[..3]) {
            *q += d;
        }
        quaternion::integrate(&mut q[3..7], body_rates(dv));
    }

    /// The increment `dv` that [`Self::displace`] turns `from` into `to`.
    #[inline]
    pub fn difference(from: &[f64], to: &[f64], dv: &mut [f64]) {
        for k in 0..3 {
            dv[k] = to[k] - from[k];
        }
        let theta = quaternion::difference(&from[3..7], &to[3..7]);
        dv[3..6].copy_from_slice(theta.as_slice());
    }

    /// Scales the quaternion to unit length.
    #[inline]
    pub fn normalise_positions(q: &mut [f64]) {
        quaternion::normalise(&mut q[3..7]);
    }

    /// `m g` [N] on `(vx, vy, vz)`.
    #[inline]
    pub fn add_weight(&self, g: Vec3, out: &mut [f64]) {
        add_to(out, g * self.mass, Vec3::zeros());
    }

    /// `-m g . r_G` [J].
    pub fn potential_energy(&self, g: Vec3, q: &[f64]) -> f64 {
        -self.mass * g.dot(&Vec3::new(q[0], q[1], q[2]))
    }

    /// `(m |v_G|^2 + omega . J omega) / 2` [J].
    pub fn kinetic_energy_of_motion(&self, v: &[f64]) -> f64 {
        let (velocity, omega) = (Vec3::new(v[0], v[1], v[2]), body_rates(v));
        0.5 * (self.mass * velocity.norm_squared() + omega.dot(&(self.inertia * omega)))
    }

    /// Absolute-tolerance scales: 1 for metres, rad/s and m/s; 1/2 for the
    /// quaternion's components, which a rotation by `theta` [rad] moves by about
    /// `theta / 2`, so that the tolerance on the orientation is one in radians.
    pub fn tolerance_scales(q: &mut [f64], v: &mut [f64]) {
        q[..3].fill(1.0);
        q[3..7].fill(0.5);
        v.fill(1.0);
    }

    /// Position channels: centre of mass and quaternion, in coordinate order.
    pub fn position_channels() -> Vec<ChannelName> {
        vec![
            channel("x", "m", "centre of mass x"),
            channel("y", "m", "centre of mass y"),
            channel("z", "m", "centre of mass z"),
            channel("qw", "-", "orientation quaternion, scalar part"),
            channel("qx", "-", "orientation quaternion, x part"),
            channel("qy", "-", "orientation quaternion, y part"),
            channel("qz", "-", "orientation quaternion, z part"),
        ]
    }

    /// Velocity and acceleration channels, in velocity-coordinate order.
    pub fn velocity_channels() -> Vec<(ChannelName, ChannelName)> {
        vec![
            (channel("vx", "m/s", "centre of mass velocity x"), channel("ax", "m/s^2", "centre of mass acceleration x")),
            (channel("vy", "m/s", "centre of mass velocity y"), channel("ay", "m/s^2", "centre of mass acceleration y")),
            (channel("vz", "m/s", "centre of mass velocity z"), channel("az", "m/s^2", "centre of mass acceleration z")),
            (channel("wx", "rad/s", "angular velocity about the body x axis"), channel("alpha_x", "rad/s^2", "angular acceleration about the body x axis")),
            (channel("wy", "rad/s", "angular velocity about the body y axis"), channel("alpha_y", "rad/s^2", "angular acceleration about the body y axis")),
            (channel("wz", "rad/s", "angular velocity about the body z axis"), channel("alpha_z", "rad/s^2", "angular acceleration about the body z axis")),
        ]
    }

    /// Channels derived from the coordinates ([`Self::derived_values`]): the
    /// global angular velocity and the Euler angles of `sequence`.
    pub fn derived_channels(sequence: EulerSequence) -> Vec<ChannelName> {
        let name = sequence.name();
        let mut channels = vec![
            channel("wx_global", "rad/s", "angular velocity about the global x axis"),
            channel("wy_global", "rad/s", "angular velocity about the global y axis"),
            channel("wz_global", "rad/s", "angular velocity about the global z axis"),
        ];
        for (k, which) in ["first", "second", "third"].iter().enumerate() {
            let quantity = format!("euler_{}_{}", name.to_lowercase(), k + 1);
            let description = format!("{which} Euler angle of the intrinsic sequence {name}");
            channels.push((quantity.into(), "rad", description.into()));
        }
        channels
    }

    /// Values of [`Self::derived_channels`] at `q`, `v` into `out` (6 values) [rad/s, rad].
    pub fn derived_values(q: &[f64], v: &[f64], sequence: EulerSequence, out: &mut [f64]) {
        let frame = Self::spatial_frame(q, v);
        out[..3].copy_from_slice(frame.angular_velocity.as_slice());
        out[3..6].copy_from_slice(&sequence.angles(&frame.rotation));
    }
}

impl InverseMass {
    /// The inverse of `diag(m, m, m, J)` for a valid `J`.
    fn of(mass: f64, inertia: &Mat3) -> Result<Self, String> {
        let off_diagonal = [(1, 0), (2, 0), (2, 1)].iter().any(|&(i, j)| inertia[(i, j)] != 0.0);
        if !off_diagonal {
            let d = inertia.diagonal();
            return Ok(Self::Diagonal([1.0 / mass, 1.0 / mass, 1.0 / mass, 1.0 / d.x, 1.0 / d.y, 1.0 / d.z]));
        }
        let mut lower: Vec<(usize, usize)> = (0..3).map(|i| (i, i)).collect();
        lower.extend((3..6).flat_map(|i| (3..=i).map(move |j| (i, j))));
        let program = PatternLdl::analyse(6, &lower);
        let mut factor = vec![0.0; program.storage_len()];
        for &(i, j) in &lower {
            factor[program.storage_index(i, j)] = if i < 3 { mass } else { inertia[(i - 3, j - 3)] };
        }
        // (the factor's rank test compares each pivot with the largest diagonal entry, the
        // mass among them: a tensor valid above fails it only for a smallest principal
        // radius of gyration below about 1e-4 m, which principal axes avoid)
        program.factor(&mut factor).map_err(|d| {
            format!(
                "the inertia tensor's products of inertia leave a pivot {:e} times the mass {mass} kg, too small to factor; give the body frame along the principal axes",
                d.relative_pivot
            )
        })?;
        Ok(Self::Factored { program, factor })
    }
}

/// `J` made exactly symmetric, or why it is no inertia tensor.
fn validated_inertia(inertia: Mat3) -> Result<Mat3, String> {
    let size = inertia.abs().max();
    if !(inertia.iter().all(|c| c.is_finite()) && size > 0.0) {
        return Err(format!("the inertia tensor must be finite and nonzero, got {inertia:?} kg m^2"));
    }
    let asymmetry = (inertia - inertia.transpose()).abs().max();
    if asymmetry > INERTIA_ROUND_OFF * size {
        return Err(format!("the inertia tensor must be symmetric, its entries differ by {asymmetry:e} kg m^2 across the diagonal"));
    }
    let symmetric = (inertia + inertia.transpose()) * 0.5;
    let mut principal: Vec<f64> = symmetric.symmetric_eigenvalues().iter().copied().collect();
    principal.sort_by(f64::total_cmp);
    if principal[0] <= 0.0 {
        return Err(format!("the inertia tensor must be positive definite, its principal moments are {principal:?} kg m^2"));
    }
    if principal[0] + principal[1] < principal[2] * (1.0 - INERTIA_ROUND_OFF) {
        return Err(format!(
            "the principal moments of inertia {principal:?} kg m^2 violate the triangle inequality I_1 + I_2 >= I_3 (no distribution of mass has them)"
        ));
    }
    Ok(symmetric)
}

/// The angular part `(wx, wy, wz)` of a velocity-like vector.
#[inline]
fn body_rates(v: &[f64]) -> Vec3 {
    Vec3::new(v[3], v[4], v[5])
}

/// Adds `linear` to `out[..3]` and `angular` to `out[3..6]`.
#[inline]
fn add_to(out: &mut [f64], linear: Vec3, angular: Vec3) {
    for k in 0..3 {
        out[k] += linear[k];
        out[k + 3] += angular[k];
    }
}

#[cfg(test)]
#[path = "spatial_rigid_tests.rs"]
mod tests;

impl BodyModel for SpatialRigidBody {
    #[inline]
    fn nq(&self) -> usize {
        Self::NQ
    }

    #[inline]
    fn nv(&self) -> usize {
        Self::NV
    }

    /// The projection on the plane (see the module's documentation).
    #[inline]
    fn frame(&self, q: &[f64], v: &[f64], _previous: &Frame) -> Frame {
        Self::frame(q, v)
    }

    /// Every site is the frame at the centre of mass.
    #[inline]
    fn site_frame(&self, _site: &Site, q: &[f64], v: &[f64], _previous: &Frame) -> Frame {
        Self::frame(q, v)
    }

    #[inline]
    fn marker_jacobian(&self, _body: &Frame, frame: &Frame, marker: &Marker, scale: f64, jx: &mut [f64], jy: &mut [f64]) {
        Self::marker_jacobian(frame, marker.local, scale, jx, jy);
    }

    /// All six velocities.
    #[inline]
    fn marker_coordinates(&self, _marker: &Marker) -> Range<usize> {
        0..Self::NV
    }

    #[inline]
    fn add_marker_jacobian(&self, _body: &Frame, frame: &Frame, marker: &Marker, along: Vec2, out: &mut [f64]) {
        Self::add_marker_jacobian(frame, marker.local, along, out);
    }

    #[inline]
    fn add_marker_angle_jacobian(&self, _marker: &Marker, scale: f64, out: &mut [f64]) {
        Self::add_marker_angle_jacobian(scale, out);
    }

    /// `-omega_z^2 A s` in the plane.
    #[inline]
    fn marker_bias_acceleration(&self, _body: &Frame, frame: &Frame, marker: &Marker) -> Vec2 {
        let s = frame.rotate(marker.local);
        -s * (frame.angular_velocity * frame.angular_velocity)
    }

    #[inline]
    fn marker_bias_angular_acceleration(&self, _frame: &Frame, _marker: &Marker) -> f64 {
        0.0
    }

    #[inline]
    fn marker_acceleration(&self, _body: &Frame, frame: &Frame, a: &[f64], marker: &Marker) -> Vec2 {
        Self::marker_acceleration(frame, a, marker.local)
    }

    #[inline]
    fn marker_angular_acceleration(&self, _frame: &Frame, a: &[f64], _marker: &Marker) -> f64 {
        Self::marker_angular_acceleration(a)
    }

    #[inline]
    fn mass_block(&self) -> MassBlock<'_> {
        self.mass_block()
    }

    #[inline]
    fn solve_mass(&self, _q: &[f64], f: &[f64], out: &mut [f64], _scratch: &mut [f64]) {
        self.solve_inverse_mass(f, out);
    }

    /// `q_dot = N(q) v` differs from `v` (the quaternion's rates).
    #[inline]
    fn has_identity_position_rates(&self) -> bool {
        false
    }

    /// The gyroscopic force.
    #[inline]
    fn has_body_forces(&self) -> bool {
        true
    }

    #[inline]
    fn add_body_forces(&self, _q: &[f64], v: &[f64], out: &mut [f64]) {
        self.add_gyroscopic_forces(v, out);
    }

    #[inline]
    fn position_rates(&self, q: &[f64], v: &[f64], qdot: &mut [f64]) {
        Self::position_rates(q, v, qdot);
    }

    fn rigid_motion_velocities(&self, q: &[f64], velocity: Vec2, angular_velocity: f64, v: &mut [f64]) {
        Self::rigid_motion_velocities(q, velocity, angular_velocity, v);
    }

    #[inline]
    fn displace(&self, q: &mut [f64], dv: &[f64]) {
        Self::displace(q, dv);
    }

    #[inline]
    fn normalise_positions(&self, q: &mut [f64]) {
        Self::normalise_positions(q);
    }

    #[inline]
    fn difference(&self, from: &[f64], to: &[f64], dv: &mut [f64]) {
        Self::difference(from, to, dv);
    }

    #[inline]
    fn add_point_force(&self, _body: &Frame, frame: &Frame, _marker: &Marker, p: Vec2, f: Vec2, out: &mut [f64]) {
        Self::add_point_force(frame, p, f, out);
    }

    #[inline]
    fn add_moment(&self, _marker: &Marker, m: f64, out: &mut [f64]) {
        Self::add_moment(m, out);
    }

    fn gravity_load_is_constant(&self) -> bool {
        true
    }

    #[inline]
    fn add_gravity(&self, g: Vec3, _q: &[f64], out: &mut [f64]) {
        self.add_weight(g, out);
    }

    fn potential_energy(&self, g: Vec3, q: &[f64]) -> f64 {
        self.potential_energy(g, q)
    }

    fn kinetic_energy(&self, _q: &[f64], v: &[f64]) -> f64 {
        self.kinetic_energy_of_motion(v)
    }

    fn tolerance_scales(&self, q: &mut [f64], v: &mut [f64]) {
        Self::tolerance_scales(q, v);
    }

    fn position_channels(&self) -> Vec<ChannelName> {
        Self::position_channels()
    }

    fn velocity_channels(&self) -> Vec<(ChannelName, ChannelName)> {
        Self::velocity_channels()
    }

    fn derived_channels(&self) -> Vec<ChannelName> {
        Self::derived_channels(self.euler_sequence)
    }

    fn derived_value(&self, q: &[f64], v: &[f64], which: usize) -> f64 {
        let mut out = [0.0; 6];
        Self::derived_values(q, v, self.euler_sequence, &mut out);
        out[which]
    }

    #[inline]
    fn spatial_site_frame(&self, _site: &Site, q: &[f64], v: &[f64], _planar: &Frame) -> SpatialFrame {
        Self::spatial_frame(q, v)
    }

    #[inline]
    fn add_spatial_point_jacobian(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, along: Vec3, out: &mut [f64]) {
        Self::add_spatial_point_jacobian(at.site3, marker.local, along, out);
    }

    #[inline]
    fn add_spatial_angular_jacobian(&self, at: MarkerFrames<'_>, _marker: &SpatialMarker, along: Vec3, out: &mut [f64]) {
        Self::add_spatial_angular_jacobian(at.site3, along, out);
    }

    #[inline]
    fn spatial_bias_acceleration(&self, at: MarkerFrames<'_>, marker: &SpatialMarker) -> (Vec3, Vec3) {
        Self::spatial_bias_acceleration(at.site3, marker.local)
    }

    #[inline]
    fn spatial_marker_acceleration(&self, at: MarkerFrames<'_>, marker: &SpatialMarker, a: &[f64]) -> (Vec3, Vec3) {
        Self::spatial_marker_acceleration(at.site3, marker.local, a)
    }

    #[inline]
    fn add_wrench(&self, at: MarkerFrames<'_>, _marker: &SpatialMarker, point: Vec3, wrench: &Wrench, out: &mut [f64]) {
        Self::add_wrench(at.site3, point, wrench, out);
    }
}
