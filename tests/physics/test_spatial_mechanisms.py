"""Spatial mechanisms run by the engine against references outside it (tests/spatial_references.py, written
with numpy and scipy alone, and the planar engine):

- a torque-free asymmetric body: its body angular velocity against Jacobi's closed form and its period
  (Landau & Lifshitz, Mechanics, 3rd ed., 1976, section 37), energy and angular momentum conserved;
- the heavy symmetric top on a spherical joint: nutation bounds and period against the closed form in
  elliptic integrals (Goldstein, Poole & Safko, Classical Mechanics, 3rd ed., 2002, section 5.7);
- Bricard's mechanism (IFToMM benchmark A04): zero freedoms by count, one by rank, and its motion against a
  minimal-coordinate model (one joint angle, the loop closed by Newton's method);
- Haug's spatial slider-crank (Computer-Aided Kinematics and Dynamics of Mechanical Systems, 1989) in free
  motion under gravity against Lagrange's equation in the crank angle;
- a hydraulic cylinder with closed chambers at a spatial angle: its frequency against the hydraulic spring
  (Merritt, Hydraulic Control Systems, 1967), which does not depend on the direction;
- the double parallelogram of examples/double_parallelogram.toml (a redundant planar loop) built from
  spatial bodies and revolute joints about the global z axis, against the planar engine.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

import jointplay as jp
from reference_hydraulic import CylinderParameters
from spatial_models import floats, marker, slider_crank_model
from spatial_references import (
    BRICARD,
    axial_gravity,
    body_marker,
    bricard_motion,
    closed_chamber_angular_frequency,
    heavy_symmetric_top,
    slider_crank_motion,
    rotation_zxz,
    top_initial_state,
    torque_free_body,
    torque_free_period,
)

DOUBLE_PARALLELOGRAM = Path(__file__).resolve().parents[2] / "examples" / "double_parallelogram.toml"


# helpers --------------------------------------------------------------------------------------------

def rotations(results: jp.Results, body: str) -> np.ndarray:
    """Rotation matrices body -> global (n, 3, 3) from the quaternion channels (scalar first, Hamilton)."""
    w, x, y, z = (results[f"{body}.q{c}"] for c in "wxyz")
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1)], -2)


def positions(results: jp.Results, body: str) -> np.ndarray:
    return np.stack([results[f"{body}.{c}"] for c in "xyz"], -1)


def upward_crossings(t: np.ndarray, signal: np.ndarray) -> np.ndarray:
    """Times [s] where ``signal`` crosses zero upwards, located on its cubic spline through the samples."""
    spline = CubicSpline(t, signal)
    roots = spline.roots(extrapolate=False)
    return np.array([r for r in roots if spline(r, 1) > 0])


def extrema(t: np.ndarray, signal: np.ndarray) -> tuple[float, float]:
    """(smallest, largest) value of ``signal`` between the samples, on its cubic spline."""
    spline = CubicSpline(t, signal)
    turning = spline.derivative().roots(extrapolate=False)
    values = np.concatenate([signal, spline(turning)])
    return float(values.min()), float(values.max())


# torque-free asymmetric body --------------------------------------------------------------------------

INERTIA = np.array([1.0, 2.0, 3.0])  # principal moments about the centre [kg m^2]
OMEGA0 = np.array([0.02, 1.0, 0.02])  # body angular velocity near the intermediate axis [rad/s]: it flips
PERIODS = 20  # of the angular velocity, two flips each: 40 flips, 686 s


def run_tumbling():
    """(period [s], results) of the free body over PERIODS periods of its angular velocity."""
    rotation = rotation_zxz(0.3, 1.1, -0.4)  # any start orientation, body -> global
    model = jp.Model("tumbling body", gravity=(0.0, 0.0, 0.0), kinematics="spatial")
    model.add_body("body", mass=1.0, inertia={"principal": floats(INERTIA)},
                   orientation={"matrix": rotation.tolist()},
                   angular_velocity=floats(rotation @ OMEGA0))  # the builder takes global components
    period = torque_free_period(INERTIA, OMEGA0)
    results = model.simulate(PERIODS * period, rtol=1e-12, atol=1e-14, output_step=0.02)
    return period, results


@pytest.fixture(scope="module")
def tumbling():
    return run_tumbling()


def test_torque_free_body_has_the_jacobi_period_and_angular_velocity(tumbling):
    period, results = tumbling
    omega = np.stack([results[f"body.w{c}"] for c in "xyz"], -1)
    assert np.max(np.abs(omega[0] - OMEGA0)) < 1e-12  # started as asked, in body components
    # omega_y ~ sn: one upward crossing per period; measured 1e-11 relative at rtol 1e-12
    crossings = upward_crossings(results.time, omega[:, 1])
    assert len(crossings) == PERIODS
    assert np.diff(crossings) == pytest.approx(period, rel=1e-6)
    # the whole history at every sample, through 40 flips: measured 2e-9 rad/s (a 1 rad/s spin)
    assert np.max(np.abs(omega - torque_free_body(INERTIA, OMEGA0, results.time))) < 1e-8


def test_torque_free_body_conserves_energy_and_angular_momentum(tumbling):
    _, results = tumbling
    omega = np.stack([results[f"body.w{c}"] for c in "xyz"], -1)
    energy = 0.5 * np.sum(INERTIA * omega**2, axis=1)
    momentum = np.einsum("nij,nj->ni", rotations(results, "body"), INERTIA * omega)  # R J omega, global
    # measured 4e-12 (energy) and 6e-12 (momentum) relative over 40 flips at rtol 1e-12
    assert np.max(np.abs(energy / energy[0] - 1)) < 1e-10
    assert np.max(np.abs(results["system.energy"] / results["system.energy"][0] - 1)) < 1e-10
    drift = np.linalg.norm(momentum - momentum[0], axis=1) / np.linalg.norm(momentum[0])
    assert np.max(drift) < 1e-10
    # the global angular velocity channels are R omega
    global_omega = np.stack([results[f"body.w{c}_global"] for c in "xyz"], -1)
    assert np.max(np.abs(global_omega - np.einsum("nij,nj->ni", rotations(results, "body"), omega))) < 1e-12


# heavy symmetric top -------------------------------------------------------------------------------------

TOP = {"mass": 1.0, "g": 9.81, "l": 0.1, "i1": 0.02, "i3": 0.01}  # i1 about the fixed point [kg, m/s^2, m, kg m^2]
TOP_START = {"theta0": 0.5, "theta_dot0": 0.0, "phi_dot0": 0.0, "psi_dot0": 40.0}  # [rad, rad/s]


def run_top():
    """(nutation from the closed form, results) of the top over six nutation periods."""
    nutation = heavy_symmetric_top(TOP["i1"], TOP["i3"], TOP["mass"], TOP["g"], TOP["l"], **TOP_START)
    rotation, omega_body = top_initial_state(*TOP_START.values())
    centre = rotation @ np.array([0.0, 0.0, TOP["l"]])
    omega = rotation @ omega_body  # global components
    transverse = TOP["i1"] - TOP["mass"] * TOP["l"] ** 2  # about the centre of mass
    model = jp.Model("top", gravity=(0.0, 0.0, -TOP["g"]), kinematics="spatial")
    model.add_ground_point("O", [0.0, 0.0, 0.0])
    model.add_body("top", mass=TOP["mass"], inertia={"principal": [transverse, transverse, TOP["i3"]]},
                   position=floats(centre), orientation={"matrix": rotation.tolist()},
                   velocity=floats(np.cross(omega, centre)), angular_velocity=floats(omega),
                   points={"O": [0.0, 0.0, -TOP["l"]]})
    model.add_spherical("pivot", "ground.O", "top.O")
    results = model.simulate(6 * nutation.period, rtol=1e-11, atol=1e-13, output_step=nutation.period / 200)
    return nutation, results


@pytest.fixture(scope="module")
def top():
    return run_top()


def test_heavy_top_nutates_between_the_closed_form_bounds_with_its_period(top):
    nutation, results = top
    # theta: angle of the symmetry axis (body z) from the upward vertical, cos theta = R_zz
    theta = np.arccos(np.clip(rotations(results, "top")[:, 2, 2], -1.0, 1.0))
    low, high = extrema(results.time, theta)
    assert nutation.theta_max - nutation.theta_min > 0.1  # a nutation worth measuring: 0.17 rad
    # measured 3e-12 rad at rtol 1e-11
    assert low == pytest.approx(nutation.theta_min, abs=1e-10)
    assert high == pytest.approx(nutation.theta_max, abs=1e-10)
    crossings = upward_crossings(results.time, theta - 0.5 * (nutation.theta_min + nutation.theta_max))
    assert len(crossings) >= 5
    # measured 6e-13 relative
    assert np.diff(crossings) == pytest.approx(nutation.period, rel=1e-9)
    # the fixed point stays where the spherical joint holds it
    tip = positions(results, "top") + rotations(results, "top") @ np.array([0.0, 0.0, -TOP["l"]])
    assert np.max(np.abs(tip)) < 1e-10


# Bricard's mechanism (IFToMM A04) ----------------------------------------------------------------------

def bricard_model() -> jp.Model:
    """A04 from BRICARD: five rods, six revolute joints whose markers have their z axes along the joint
    axes (``body_marker``)."""
    model = jp.Model("bricard", gravity=floats(BRICARD["gravity"]), kinematics="spatial")
    rods = {rod["name"]: rod for rod in BRICARD["rods"]}
    points = {name: {} for name in rods}
    for joint in BRICARD["joints"]:
        for side in ("first", "second"):
            body = joint[side]
            position, axes = body_marker(rods.get(body), joint["point"], joint["axis"])
            if body == "ground":
                model.add_ground_point(joint["name"], floats(position), axes={"matrix": axes.tolist()})
            else:
                points[body][joint["name"]] = marker(position, axes)
    for name, rod in rods.items():
        model.add_body(name, mass=rod["mass"], inertia={"principal": floats(rod["inertia_principal"])},
                       position=floats(rod["position"]), orientation={"matrix": rod["rotation"].tolist()},
                       points=points[name])
    for joint in BRICARD["joints"]:
        model.add_revolute(joint["name"], f"{joint['first']}.{joint['name']}", f"{joint['second']}.{joint['name']}")
    return model


def test_bricard_counts_zero_freedoms_but_has_one():
    info = bricard_model().check()
    # Grubler-Kutzbach: 5 bodies x 6 - 6 revolutes x 5 = 0
    assert info["n_coordinates"] == 30 and info["n_equations"] == 30
    assert info["redundant_equations"] == 1
    assert info["degrees_of_freedom"] == 1


def test_bricard_joint_point_follows_the_minimal_coordinate_model():
    # 2 s, released from rest: through the singular position near 1.6 s where the loop's Newton stalls
    results = bricard_model().simulate(2.0, rtol=1e-10, atol=1e-10, output_step=0.01)
    reference = bricard_motion(results.time)
    rod4 = BRICARD["rods"][3]
    local = rod4["rotation"].T @ (BRICARD["points"][3] - rod4["position"])  # P3 in rod4's frame
    p3 = positions(results, "rod4") + rotations(results, "rod4") @ local
    expected = reference.joint_points[:, 3]
    assert np.ptp(expected[:, 0]) > 1.0  # P3 travels about 2 m along x
    # measured 1e-10 m at rtol = atol = 1e-10 (3e-11 m with atol 1e-12; 3.5e-7 m at 1e-8); the reference
    # at rtol 1e-11
    assert np.max(np.abs(p3 - expected)) < 1e-9


# Haug's spatial slider-crank --------------------------------------------------------------------------

def test_spatial_slider_crank_moves_as_lagrange_equation_in_the_crank_angle():
    model = slider_crank_model()
    info = model.check()
    assert info["degrees_of_freedom"] == 1 and info["redundant_equations"] == 0
    results = model.simulate(1.0, rtol=1e-10, atol=1e-12, output_step=0.005)
    reference = slider_crank_motion(results.time)
    assert reference.theta[-1] - reference.theta[0] > 2 * math.pi  # more than one turn
    # measured 3e-11 m on a 0.105 m stroke; the energy (kinetic and gravity's, 0 at z = 0) to 4e-10
    assert np.max(np.abs(results["slider.x"] - reference.slider)) < 1e-9
    assert results["system.energy"] == pytest.approx(reference.energy[0], rel=1e-8)


# closed-chamber hydraulic frequency at a spatial angle ----------------------------------------------------

CYLINDER = CylinderParameters(seal="none")
AXIS = np.array([1.0, 2.0, 2.0]) / 3.0  # the cylinder's extension, unit [-]
GRAVITY = np.array([0.0, 0.0, -9.81])  # [m/s^2]
STROKE0, LENGTH0 = 0.25, 0.6  # stroke at the start, distance of the attachments at stroke 0 [m]


def run_cylinder():
    """(period [s] of the hydraulic spring, results over ten periods) of a mass on a translational joint
    along AXIS, held by a cylinder from the ground point O with its chambers closed and its pressures
    balancing the axial weight at STROKE0; started at 10 mm/s along the axis, it rings about STROKE0."""
    z = AXIS
    x = np.cross([0.0, 0.0, 1.0], z)
    x /= np.linalg.norm(x)
    axes = {"matrix": np.column_stack([x, np.cross(z, x), z]).tolist()}  # z along the cylinder
    p = CYLINDER
    rod_pressure = 1e6
    cap_pressure = (rod_pressure * p.rod_side_area - p.mass * axial_gravity(AXIS, GRAVITY)) / p.piston_area
    model = jp.Model("cylinder at an angle", gravity=floats(GRAVITY), kinematics="spatial")
    model.add_ground_point("O", [0.0, 0.0, 0.0], axes=axes)
    model.add_body("mass", mass=p.mass, inertia={"principal": [1.0, 1.0, 1.0]},
                   position=floats((LENGTH0 + STROKE0) * AXIS), velocity=floats(0.01 * AXIS),
                   points={"P": {"position": [0.0, 0.0, 0.0], "axes": axes}})
    model.add_translational("slide", "ground.O", "mass.P")
    model.add_hydraulic_cylinder(
        "cyl", "ground.O", "mass.P", piston_area=p.piston_area, rod_side_area=p.rod_side_area,
        stroke_length=p.stroke_length, cap_dead_volume=p.cap_dead_volume, rod_dead_volume=p.rod_dead_volume,
        initial_stroke=STROKE0, cap_pressure=cap_pressure, rod_pressure=rod_pressure, bulk_modulus=p.bulk_modulus)
    omega = closed_chamber_angular_frequency(p, STROKE0)
    period = 2 * math.pi / omega
    results = model.simulate(10 * period, rtol=1e-11, atol=1e-12, output_step=period / 100)
    return period, results


def test_closed_cylinder_at_a_spatial_angle_rings_at_the_hydraulic_spring_frequency():
    """omega = sqrt(beta (A1^2/V1 + A2^2/V2) / m) whatever the cylinder's direction (amplitude 8 um)."""
    period, results = run_cylinder()
    omega = 2 * math.pi / period
    stroke = results["cyl.stroke"] - STROKE0
    assert 0.9 < np.max(np.abs(stroke)) * omega / 0.01 < 1.1  # amplitude v0 / omega: rings about STROKE0
    crossings = upward_crossings(results.time, stroke)
    assert len(crossings) >= 9
    # the amplitude's nonlinearity moves the frequency by about (a A1 / V1)^2 ~ 1e-9; measured 2e-10
    # relative. A 1e-6 error is a bulk modulus 2e-6 off, or the axis's weight carried by the wrong area
    assert np.diff(crossings) == pytest.approx(period, rel=1e-6)
    # the mass stays on the axis
    position = positions(results, "mass")
    off_axis = position - np.outer(position @ AXIS, AXIS)
    assert np.max(np.abs(off_axis)) < 1e-12


# a planar mechanism from spatial bodies and joints ------------------------------------------------------

def spatial_twin(planar: dict) -> jp.Model:
    """The planar spec ``planar`` of rigid bodies and revolute joints built from spatial bodies in the plane
    z = 0: each body turned by its angle about the global z axis, whose revolute joints (markers with the
    body's axes) turn about z. The out-of-plane moments (1 % and the planar one) never act."""
    model = jp.Model(planar["name"], gravity=[*planar["gravity"], 0.0], kinematics="spatial")
    for point in planar["ground_points"]:
        model.add_ground_point(point["name"], [*point["position"], 0.0])
    for body in planar["bodies"]:
        inertia = body["inertia"]
        model.add_body(body["name"], mass=body["mass"], inertia={"principal": [inertia / 100, inertia, inertia]},
                       position=[*body["position"], 0.0],
                       orientation={"axis": [0, 0, 1], "angle": f"{body['angle']} rad"},
                       velocity=[*body["velocity"], 0.0], angular_velocity=[0.0, 0.0, body["angular_velocity"]],
                       points={point["name"]: [*point["position"], 0.0] for point in body["points"]})
    for joint in planar["joints"]:
        assert joint["type"] == "revolute"
        model.add_revolute(joint["name"], joint["first"], joint["second"])
    return model


def test_double_parallelogram_from_spatial_bodies_agrees_with_the_planar_engine():
    planar = jp.load(DOUBLE_PARALLELOGRAM)
    spatial = spatial_twin(planar.to_spec())
    info = spatial.check()
    assert info["degrees_of_freedom"] == 1  # 24 coordinates, 30 equations of rank 23
    assert info["redundant_equations"] == 7
    # through the flat (singular) position near 1.6 s. At rtol = atol = 1e-11 both hold the joints to atol
    # there; at 1e-10 they agree to 7e-10 and the planar projection warns that it missed atol
    options = {"rtol": 1e-11, "atol": 1e-11, "output_step": 0.01}
    flat, solid = planar.simulate(2.0, **options), spatial.simulate(2.0, **options)
    assert np.array_equal(flat.time, solid.time)
    for body in ("left", "middle", "right", "coupler"):
        # measured 6e-11 m and rad, 2.3e-10 rad/s (6e-12 and 2.4e-11 at rtol = atol = 1e-12)
        assert np.max(np.abs(solid[f"{body}.x"] - flat[f"{body}.x"])) < 1e-9
        assert np.max(np.abs(solid[f"{body}.y"] - flat[f"{body}.y"])) < 1e-9
        assert np.max(np.abs(solid[f"{body}.z"])) < 1e-12
        turn = solid[f"{body}.euler_zyx_1"] - flat[f"{body}.angle"]
        assert np.max(np.abs(np.angle(np.exp(1j * turn)))) < 1e-9
        assert np.max(np.abs(solid[f"{body}.wz_global"] - flat[f"{body}.omega"])) < 1e-8
