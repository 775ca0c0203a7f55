"""Spatial models in model files and in the Python builder: orientations and inertia tensors read with units
(against closed forms written here, independent of SciPy, which the front end uses), the core's spec of a whole
spatial model file against the contract written out by hand, every message of a bad input, and the writer's
round trip. The core does not run spatial models yet on this tree, so the front end is checked at the spec it
sends (``jointplay.modelfile.read_spec``, ``Model.to_spec`` / ``Model.to_json``)."""

from __future__ import annotations

import inspect
import itertools
import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp
from jointplay import orientation as o
from jointplay import parameters as p
from jointplay.modelfile import loads, read_spec, reference, to_toml
from jointplay.modelfile.build import Builder

ROOT = Path(__file__).resolve().parents[1]
EVERY_KEY = ROOT / "tests" / "data" / "spatial" / "every_key.toml"


# closed forms, written here --------------------------------------------------------

def elementary(axis: int, angle: float) -> np.ndarray:
    """The active rotation by ``angle`` [rad] about the x (0), y (1) or z (2) axis."""
    c, s = math.cos(angle), math.sin(angle)
    i, j = (axis + 1) % 3, (axis + 2) % 3  # the plane turned, in cyclic order (y turns z towards x)
    r = np.eye(3)
    r[i, i], r[i, j], r[j, i], r[j, j] = c, -s, s, c
    return r


def rodrigues(axis, angle: float) -> np.ndarray:
    """R = I + sin(t) K + (1 - cos(t)) K^2 for the unit axis k (K its cross-product matrix)."""
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    cross = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * cross + (1 - math.cos(angle)) * cross @ cross


def hamilton_matrix(q) -> np.ndarray:
    """The rotation matrix of a unit quaternion [w, x, y, z] (scalar first), by the textbook formula."""
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def problems(doc_text: str) -> list[str]:
    return [str(problem) for problem in Builder(tomllib.loads(doc_text)).run().problems]


# orientations ------------------------------------------------------------------------

def test_euler_313_at_90_90_0_deg_is_the_matrix_of_goldstein():
    # Goldstein, Classical Mechanics: the x-convention (3-1-3) matrix A at phi = theta = 90 deg, psi = 0, transposed
    # (A turns global into body components; the orientation is its transpose, the active rotation)
    q = o.quaternion({"euler": ["90 deg", "90 deg", "0 deg"], "sequence": "3-1-3"})
    assert q == pytest.approx([0.5, 0.5, 0.5, 0.5], abs=1e-15)
    assert hamilton_matrix(q) == pytest.approx(np.array([[0, 0, 1], [1, 0, 0], [0, 1, 0]]), abs=1e-15)


def test_euler_313_matches_the_closed_form_at_any_angles():
    phi, theta, psi = 0.3, 1.1, -2.4
    c, s = np.cos, np.sin
    expected = np.array([
        [c(phi) * c(psi) - s(phi) * c(theta) * s(psi), -c(phi) * s(psi) - s(phi) * c(theta) * c(psi), s(phi) * s(theta)],
        [s(phi) * c(psi) + c(phi) * c(theta) * s(psi), -s(phi) * s(psi) + c(phi) * c(theta) * c(psi), -c(phi) * s(theta)],
        [s(theta) * s(psi), s(theta) * c(psi), c(theta)]])
    q = o.quaternion({"euler": [f"{phi} rad", f"{theta} rad", f"{psi} rad"], "sequence": "ZXZ"})
    assert hamilton_matrix(q) == pytest.approx(expected, abs=1e-14)


@pytest.mark.parametrize("sequence", o.EULER_SEQUENCES)
def test_each_intrinsic_sequence_is_the_product_of_its_elementary_rotations(sequence):
    angles = (0.4, -0.9, 2.2)
    expected = np.eye(3)
    for letter, angle in zip(sequence, angles):
        expected = expected @ elementary("XYZ".index(letter), angle)
    numbers = "-".join(str("XYZ".index(letter) + 1) for letter in sequence)
    for name in (sequence, numbers):
        q = o.quaternion({"euler": [f"{a} rad" for a in angles], "sequence": name})
        assert hamilton_matrix(q) == pytest.approx(expected, abs=1e-14), name


def test_axis_and_angle_is_rodrigues_rotation_and_the_axis_need_not_be_unit():
    q = o.quaternion({"axis": [1, 2, -2], "angle": "75 deg"})
    assert hamilton_matrix(q) == pytest.approx(rodrigues([1, 2, -2], math.radians(75)), abs=1e-15)
    assert q[0] == pytest.approx(math.cos(math.radians(75) / 2), abs=1e-15)


def test_quaternion_is_scalar_first_normalised_and_keeps_its_sign():
    half = math.radians(30) / 2
    q = o.quaternion({"quaternion": [2 * math.cos(half), 0, 0, 2 * math.sin(half)]})  # 30 deg about z, not unit
    assert q == pytest.approx([math.cos(half), 0, 0, math.sin(half)], abs=1e-16)
    assert hamilton_matrix(q)[0, 1] == pytest.approx(-0.5, abs=1e-15)  # active: x turns towards y
    assert o.quaternion({"quaternion": [-1, 0, 0, 0]}) == [-1.0, 0.0, 0.0, 0.0]


def test_rotation_matrix_gives_the_quaternion_of_that_matrix():
    r = rodrigues([0.2, -1, 0.5], 2.0)
    q = o.quaternion({"matrix": r.tolist()})
    assert hamilton_matrix(q) == pytest.approx(r, abs=1e-15)
    assert q[0] >= 0
    almost = np.round(r, 7)  # seven digits, as written by hand: within 1e-6 of a rotation
    assert hamilton_matrix(o.quaternion({"matrix": almost.tolist()})) == pytest.approx(r, abs=1e-6)


@pytest.mark.parametrize(("raw", "at", "message"), [
    ({"matrix": [[1, 0, 0], [0, 1, 0.01], [0, 0, 1]]}, ("matrix",),
     "is not a rotation: its columns must be orthonormal within 1e-06, but R^T R differs from the identity by 0.01"),
    ({"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, -1]]}, ("matrix",),
     "is not a rotation: its determinant must be +1 within 1e-06, got -1 (a reflection: one axis points the wrong "
     "way)"),
    ({"matrix": [[1, 0, 0], [0, 1], [0, 0, 1]]}, ("matrix", 1),
     "must be a row of three plain numbers (e.g. [1, 0, 0]), got [0, 1]"),
    ({"quaternion": [0, 0, 0, 0]}, ("quaternion",),
     "must not be zero: [w, x, y, z] is normalised, and a zero quaternion has no direction"),
    ({"quaternion": [1, 0, 0]}, ("quaternion",),
     "must be four plain numbers [w, x, y, z], scalar first (e.g. [1, 0, 0, 0]), got [1, 0, 0]"),
    ({"axis": [0, 0, 0], "angle": "1 deg"}, ("axis",), "must be a non-zero direction, got [0, 0, 0]"),
    ({"axis": [0, 0, 1], "angle": "1 mm"}, ("angle",), "must be an angle (e.g. \"90 deg\"), got '1 mm', which is a "
                                                        "length"),
    ({"axis": [0, 0, 1]}, ("angle",),
     'missing required value: axis form needs axis and angle, e.g. { axis = [0, 0, 1], angle = "30 deg" }'),
    ({"euler": [0, 0, 0], "sequence": "zxz"}, ("sequence",),
     "must be written in upper case, 'ZXZ': the angles are intrinsic (each about an axis of the frame being "
     "turned), got 'zxz'"),
    ({"euler": [0, 0, 0], "sequence": "ZXX"}, ("sequence",),
     'must be an intrinsic Euler sequence, one of XYX, XYZ, XZX, XZY, YXY, YXZ, YZX, YZY, ZXY, ZXZ, ZYX, ZYZ (or by '
     'axis numbers, "3-1-3" for "ZXZ"), got \'ZXX\' (did you mean "ZYX"?)'),
    ({"euler": ["1 deg", "2 deg"], "sequence": "ZXZ"}, ("euler",),
     'must be three angles (e.g. ["10 deg", "20 deg", "30 deg"]), got [\'1 deg\', \'2 deg\']'),
    ({"euler": ["1 deg", "2 kg", 0], "sequence": "ZXZ"}, ("euler", 1),
     "must be an angle (e.g. \"90 deg\"), got '2 kg', which is a mass"),
    ({"axis": [0, 0, 1], "angle": "1 deg", "quaternion": [1, 0, 0, 0]}, (),
     "give exactly one form of orientation, got axis and quaternion; the forms: "
     + ", ".join(o.FORM_EXAMPLES)),
    ({"quaternoin": [1, 0, 0, 0]}, ("quaternoin",),
     'unknown key (did you mean "quaternion"?); an orientation is one of ' + ", ".join(o.FORM_EXAMPLES)),
])
def test_a_bad_orientation_is_reported_where_it_lies(raw, at, message):
    with pytest.raises(o.OrientationError) as info:
        o.quaternion(raw)
    assert (info.value.at, info.value.message) == (at, message)


# inertia tensors ------------------------------------------------------------------------

def test_principal_moments_with_axes_give_r_diag_r_transpose():
    r = rodrigues([1, 1, 0], math.radians(40))
    moments = (2.0, 3.0, 4.5)
    tensor = np.array(o.inertia_tensor({"principal": [f"{m} kg m^2" for m in moments],
                                        "axes": {"axis": [1, 1, 0], "angle": "40 deg"}}))
    assert tensor == pytest.approx(r @ np.diag(moments) @ r.T, abs=1e-14)
    assert np.array_equal(tensor, tensor.T)
    # the tensor form of the same body reads back as given, and its eigenvalues are the principal moments
    again = np.array(o.inertia_tensor({"tensor": tensor.tolist()}))
    assert np.array_equal(again, tensor)
    assert np.linalg.eigvalsh(again) == pytest.approx(sorted(moments), rel=1e-14)


def test_principal_moments_in_other_units_and_the_body_axes_by_default():
    tensor = np.array(o.inertia_tensor({"principal": ["10 kg cm^2", "1.5 g m^2", 2e-3]}))
    assert tensor == pytest.approx(np.diag([1e-3, 1.5e-3, 2e-3]), rel=1e-15)


def test_a_thin_plate_on_the_triangle_bound_is_a_rigid_body():
    assert o.inertia_tensor({"principal": [1.0, 2.0, 3.0]})[2][2] == 3.0  # J3 = J1 + J2: all mass in z = 0


@pytest.mark.parametrize(("raw", "at", "message"), [
    ({"principal": [1, 1, 3]}, ("principal",),
     "principal moments [1, 1, 3] kg m^2 violate the triangle inequality J1 + J2 >= J3 (1 + 1 < 3 kg m^2): no "
     "rigid body has them"),
    ({"principal": [1, 5, 1]}, ("principal",),
     "principal moments [1, 5, 1] kg m^2 violate the triangle inequality J1 + J3 >= J2 (1 + 1 < 5 kg m^2): no "
     "rigid body has them"),
    ({"principal": [1, -1, 1]}, ("principal", 1), "must be > 0, got -1 kg m^2"),
    ({"tensor": [[1, 0.1, 0], [0, 1, 0], [0, 0, 1]]}, ("tensor",),
     "must be symmetric: entry [0][1] = 0.1 kg m^2 differs from [1][0] = 0 kg m^2"),
    ({"tensor": [[1, 0, 0], [0, 1, 0], [0, 0, -0.5]]}, ("tensor",),
     "must be positive definite (a body has inertia about every axis), but its smallest principal moment is -0.5 "
     "kg m^2"),
    ({"tensor": [[1, 0, 0], [0, 1, 0], [0, 0, 2.5]]}, ("tensor",),
     "principal moments [1, 1, 2.5] kg m^2 violate the triangle inequality J1 + J2 >= J3 (1 + 1 < 2.5 kg m^2): no "
     "rigid body has them"),
    ({"tensor": [[1, 0, 0], [0, 1, "2 kg"], [0, 0, 1]]}, ("tensor", 1, 2),
     "must be an inertia (e.g. \"1e-4 kg m^2\"), got '2 kg', which is a mass"),
    ({"principal": [1, 1, 1], "tensor": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}, (),
     "give exactly one of principal or tensor, got both: " + " or ".join(o.INERTIA_FORMS)),
    ({"tensor": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "axes": {"axis": [0, 0, 1], "angle": 1}}, ("axes",),
     "goes with principal moments; a full tensor holds its axes already"),
    ({"principal": [1, 1, 1], "axes": {"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, -1]]}}, ("axes", "matrix"),
     "is not a rotation: its determinant must be +1 within 1e-06, got -1 (a reflection: one axis points the wrong "
     "way)"),
])
def test_a_bad_inertia_is_reported_with_the_violated_condition(raw, at, message):
    with pytest.raises(o.OrientationError) as info:
        o.inertia_tensor(raw)
    assert (info.value.at, info.value.message) == (at, message)


# the whole model file against the contract --------------------------------------------------

R_Y90 = [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]  # 90 deg about y: body z along global x


def _body(name, mass, inertia, position, points, orientation=(1.0, 0.0, 0.0, 0.0), angular_velocity=(0, 0, 0),
          euler_sequence="zyx"):
    return {"name": name, "mass": mass, "inertia": inertia, "position": list(position),
            "orientation": list(orientation), "velocity": [0.0, 0.0, 0.0],
            "angular_velocity": list(angular_velocity), "points": points, "euler_sequence": euler_sequence}


def _point(name, position, axes=None):
    return {"name": name, "position": list(position), "axes": axes}


def _constant(value):
    return {"kind": "constant", "value": value}


EXPECTED = {
    "name": "spatial_every_key", "gravity": [0.0, 0.0, -9.81],
    "ground_points": [_point("O", (0, 0.1, 0.12), R_Y90), _point("S", (0.2, 0, 0), R_Y90),
                      _point("C", (0, -0.2, 0)), _point("T", (0, -0.2, 0.3)), _point("P", (0, 0.3, 0))],
    "bodies": [], "beams": [], "joints": [], "forces": [], "sensors": [],
    "drivers": [{"name": "motor", "joint": "crank_pin",
                 "function": {"kind": "constant_rate", "initial": 0.0, "rate": 2 * math.pi}},
                {"name": "lift", "joint": "sleeve", "function": _constant(0.005)}],
    "spatial_bodies": [
        # principal axes turned 90 deg about y: the third moment lies along global x
        _body("crank", 0.12, np.diag([1.5e-4, 1e-4, 1e-4]).tolist(), (0, 0.1, 0.1),
              [_point("O", (0, 0, -0.02), [[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]),
               _point("A", (0, 0, 0.02))],
              orientation=(0.0, 1.0, 0.0, 0.0), angular_velocity=(2 * math.pi, 0, 0)),
        _body("rod", 0.5, [[4e-3, 1e-5, 0], [1e-5, 4e-3, 0], [0, 0, 1e-4]], (0.1, 0.05, 0.04),
              [_point("A", (0, 0, -0.11)), _point("B", (0, 0, 0.11), R_Y90)], orientation=(0.5, 0.5, 0.5, 0.5), euler_sequence="zxz"),
        _body("slider", 2.0, np.diag([1e-4] * 3).tolist(), (0.2, 0, 0),
              [_point("B", (0, 0, 0)), _point("S", (0, 0, 0), R_Y90), _point("W", (0, 0, 0.01))]),
        _body("weight", 0.3, np.diag([2e-5, 2e-5, 3e-5]).tolist(), (0.2, 0, 0.01), [_point("W", (0, 0, 0))]),
        _body("collar", 0.2, np.diag([1e-5, 1e-5, 1.5e-5]).tolist(), (0, -0.2, 0),
              [_point("C", (0, 0, 0)), _point("T", (0, 0, 0.05))]),
        _body("drifter", 1.0, np.diag([0.01, 0.02, 0.025]).tolist(), (1, 1, 1), []),
        _body("pin", 0.1, np.diag([2e-5, 2e-5, 1e-5]).tolist(), (0, 0.3, 0), [_point("J", (0, 0, 0))]),
    ],
    "spatial_joints": [{"type": kind, "name": name, "first": first, "second": second} for kind, name, first, second in (
        ("revolute", "crank_pin", "ground.O", "crank.O"), ("spherical", "ball", "crank.A", "rod.A"),
        ("universal", "cardan", "rod.B", "slider.B"), ("translational", "guide", "ground.S", "slider.S"),
        ("fixed", "weld", "slider.W", "weight.W"), ("cylindrical", "sleeve", "ground.C", "collar.C"))],
    "spatial_clearance_joints": [{
        "type": "spatial_clearance_revolute", "name": "play", "bearing": "ground.P", "journal": "pin.J",
        "bore_radius": 0.01, "clearance": 5e-4, "bearing_length": 0.02, "axial_clearance": 4e-4, "flange_radius": 0.015,
        "face_radius": 0.016, "bearing_material": {"youngs_modulus": 207e9, "poisson_ratio": 0.3},
        "journal_material": {"youngs_modulus": 200e9, "poisson_ratio": 0.29},
        "contact": {"law": "lankarani_nikravesh", "restitution": 0.9}, "stiffness": {"law": "johnson_line"},
        "axial_stiffness": 2e9,
        "friction": {"law": "stiction", "static_coefficient": 0.15, "kinetic_coefficient": 0.1,
                     "stiction_velocity": 1e-5, "transition_velocity": 5e-5},
        "lock_at_assembly": True, "onset_velocity_floor": 1e-4, "max_penetration": 2e-4, "mode_impact_speed": 1e-3,
        "mode_impact_duration": 1e-3, "mode_sliding_speed": 5e-5,
        "lubrication": {"model": "hamrock_short", "viscosity": 0.4, "transition": {"law": "wang_improved", "safe_film_thickness": None},
                        "reynolds": {"cavitation": "swift_stieber", "n_circumferential": None, "n_axial": None,
                                     "ambient_pressure": 0.0, "groove_supply_pressure": None}}}],
    "spatial_forces": [
        # free length left out: the described distance of ground.T (z = 0.3 m) and collar.T (z = 0.05 m)
        {"type": "spring_damper", "name": "spring", "first": "ground.T", "second": "collar.T", "stiffness": 1000.0,
         "damping": 2.0, "free_length": 0.25},
        {"type": "spring_damper", "name": "strap", "first": "rod.A", "second": "slider.W", "stiffness": 0.0,
         "damping": 0.0, "free_length": 0.12},
        {"type": "bushing", "name": "mount", "first": "ground.S", "second": "slider.S",
         "stiffness": [1e5, 2e5, 3e5], "damping": [10.0, 20.0, 30.0], "rotational_stiffness": [100.0, 200.0, 300.0],
         "rotational_damping": [0.1, 0.2, 0.3]},
        {"type": "point_force", "name": "push", "point": "slider.B", "frame": "body",
         "force": [_constant(10.0), _constant(0.0),
                   {"kind": "sine", "offset": 0.0, "amplitude": 5.0, "frequency": 2.0, "phase": 0.0}]},
        {"type": "torque", "name": "brake", "body": "crank", "frame": "global",
         "torque": [_constant(0.0), _constant(-0.5), _constant(0.0)]},
        {"type": "hydraulic_cylinder", "name": "ram", "first": "ground.C", "second": "collar.T", "piston_area": 2e-3,
         "rod_side_area": 1e-3, "stroke_length": 0.2, "cap_dead_volume": 1e-4, "rod_dead_volume": 1e-4,
         "initial_stroke": 0.02, "cap_pressure": 0.0, "rod_pressure": 0.0, "bulk_modulus": 1.5e9,
         "seal_friction": None, "cap_inflow": None, "rod_inflow": None},
    ],
}


def assert_same(actual, expected, where="spec"):
    """The same structure, keys in the same order, every number within round-off (1e-12 relative to 1)."""
    if isinstance(expected, dict):
        assert isinstance(actual, dict) and list(actual) == list(expected), (where, list(actual), list(expected))
        for key in expected:
            assert_same(actual[key], expected[key], f"{where}.{key}")
    elif isinstance(expected, list):
        assert isinstance(actual, list) and len(actual) == len(expected), (where, actual)
        for k, (a, e) in enumerate(zip(actual, expected)):
            assert_same(a, e, f"{where}[{k}]")
    elif isinstance(expected, float) or (isinstance(expected, int) and not isinstance(expected, bool)):
        assert type(actual) is float and actual == pytest.approx(expected, rel=1e-12, abs=1e-12), (where, actual)
    else:
        assert actual == expected, (where, actual)


def _in_contract_order(spec: dict) -> dict:
    """EXPECTED's entries in the order of the contract's keys (the test's dict lists them for reading)."""
    order = {"point_force": ("type", "name", "point", "force", "frame"),
             "torque": ("type", "name", "body", "torque", "frame")}
    out = dict(EXPECTED)
    out["spatial_forces"] = [{key: f[key] for key in order.get(f["type"], f)} for f in EXPECTED["spatial_forces"]]
    return {key: out[key] for key in spec}


def test_a_spatial_model_file_gives_the_contract_spec():
    spec, simulation = read_spec(EVERY_KEY)
    assert set(spec) == set(EXPECTED)
    assert_same(spec, _in_contract_order(spec))
    assert simulation == {"t_end": 1.0, "rtol": 1e-8}
    assert json.loads(json.dumps(spec, allow_nan=False)) == spec  # plain JSON data (no NumPy numbers)


def test_the_spatial_spec_holds_unit_quaternions_and_rotation_matrices():
    spec, _ = read_spec(EVERY_KEY)
    for body in spec["spatial_bodies"]:
        assert math.fsum(v * v for v in body["orientation"]) == pytest.approx(1.0, abs=4e-16)
        for point in body["points"]:
            if point["axes"] is not None:
                axes = np.array(point["axes"])
                assert axes.T @ axes == pytest.approx(np.eye(3), abs=1e-15)
                assert np.linalg.det(axes) == pytest.approx(1.0, abs=1e-15)


def test_the_writer_round_trips_a_spatial_model_bit_for_bit():
    spec, simulation = read_spec(EVERY_KEY)
    text = to_toml(spec)
    assert 'kinematics = "spatial"' in text
    again = Builder(tomllib.loads(text), default_name="other").run()
    assert again.problems == []
    assert again.spec == spec  # exact floats: quaternions, matrices and tensors are written with every digit
    model = jp.Model.from_spec(spec)
    model.simulation = simulation
    assert model.kinematics == "spatial"
    assert read_spec_text(model.to_toml()) == (spec, simulation)


def read_spec_text(text: str) -> tuple[dict, dict]:
    return Builder(tomllib.loads(text), default_name="other").run().result()


# the Python builder -----------------------------------------------------------------------

def built_in_python() -> jp.Model:
    m = jp.Model("pendulum3d", gravity=(0, 0, "-9.81 m/s^2"), kinematics="spatial")
    m.add_ground_point("O", ("0 mm", "0 mm", "500 mm"), axes={"axis": (0, 1, 0), "angle": "90 deg"})
    m.add_body("bob", mass="2 kg", inertia={"principal": ["0.01 kg m^2", "0.02 kg m^2", "0.025 kg m^2"],
                                            "axes": {"euler": ["30 deg", 0, 0], "sequence": "ZXZ"}},
               position=(0, 0, "200 mm"), orientation={"quaternion": (1, 0, 0, 0)},
               angular_velocity=("1 rad/s", 0, 0),
               points={"P": {"position": ("0 mm", "0 mm", "300 mm"), "axes": {"matrix": R_Y90}},
                       "S": (0, 0, "-100 mm")})
    m.add_revolute("hinge", "ground.O", "bob.P")
    m.add_driver("turn", "hinge", {"kind": "constant_speed", "rate": "10 rpm"})
    m.add_spring_damper("rope", "ground.O", "bob.S", stiffness="100 N/m")
    m.add_torque("twist", "bob", torque=(0, 0, "0.1 N m"), frame="body")
    return m


WRITTEN_IN_A_FILE = """
[model]
name = "pendulum3d"
kinematics = "spatial"
gravity = [0, 0, "-9.81 m/s^2"]

[ground.points]
O = { position = ["0 mm", "0 mm", "500 mm"], axes = { axis = [0, 1, 0], angle = "90 deg" } }

[bodies.bob]
mass = "2 kg"
inertia = { principal = ["0.01 kg m^2", "0.02 kg m^2", "0.025 kg m^2"], axes = { euler = ["30 deg", 0, 0], sequence = "ZXZ" } }
position = [0, 0, "200 mm"]
orientation = { quaternion = [1, 0, 0, 0] }
angular_velocity = ["1 rad/s", 0, 0]
points = { P = { position = ["0 mm", "0 mm", "300 mm"], axes = { matrix = [[0, 0, 1], [0, 1, 0], [-1, 0, 0]] } }, S = [0, 0, "-100 mm"] }

[joints.hinge]
type = "revolute"
first = "ground.O"
second = "bob.P"

[drivers.turn]
joint = "hinge"
function = { kind = "constant_speed", rate = "10 rpm" }

[forces.rope]
type = "spring_damper"
first = "ground.O"
second = "bob.S"
stiffness = "100 N/m"

[forces.twist]
type = "torque"
body = "bob"
torque = [0, 0, "0.1 N m"]
frame = "body"
"""


def test_builder_and_model_file_give_the_same_spatial_spec():
    built = built_in_python()
    loaded, _ = read_spec_text(WRITTEN_IN_A_FILE)
    assert built.to_spec() == loaded
    assert json.loads(built.to_json()) == loaded  # what compile sends to the core
    # ground.O at z = 500 mm, bob.S at 200 mm - 100 mm
    assert loaded["spatial_forces"][0]["free_length"] == pytest.approx(0.4, abs=1e-15)
    tensor = np.array(loaded["spatial_bodies"][0]["inertia"])
    r = elementary(2, math.radians(30))
    assert tensor == pytest.approx(r @ np.diag([0.01, 0.02, 0.025]) @ r.T, abs=1e-15)


def test_a_spatial_builder_model_round_trips_through_the_writer():
    built = built_in_python()
    assert read_spec_text(built.to_toml())[0] == built.to_spec()


SPATIAL_METHODS = {"add_body": p.SPATIAL_BODY, "add_revolute": p.SPATIAL_JOINTS["revolute"],
                   "add_translational": p.SPATIAL_JOINTS["translational"], "add_fixed": p.SPATIAL_JOINTS["fixed"],
                   "add_spring_damper": p.SPATIAL_SPRING_DAMPER, "add_point_force": p.SPATIAL_POINT_FORCE,
                   "add_torque": p.SPATIAL_TORQUE, "add_hydraulic_cylinder": p.HYDRAULIC_CYLINDER}
SPATIAL_ONLY = {"add_spherical": p.SPATIAL_JOINTS["spherical"], "add_cylindrical": p.SPATIAL_JOINTS["cylindrical"],
                "add_universal": p.SPATIAL_JOINTS["universal"], "add_bushing": p.BUSHING}


@pytest.mark.parametrize("method", sorted(SPATIAL_METHODS) + sorted(SPATIAL_ONLY))
def test_spatial_builder_arguments_are_the_keys_of_the_definition_with_its_defaults(method):
    table = {**SPATIAL_METHODS, **SPATIAL_ONLY}[method]
    function = getattr(jp.Model, method)
    function = getattr(function, "spatial", function)
    arguments = {k: v for k, v in inspect.signature(function).parameters.items() if k not in ("self", "name")}
    assert set(arguments) == {param.key for param in table.params if param.in_spec}
    for key, argument in arguments.items():
        param = table[key]
        if param.required:
            assert argument.default is inspect.Parameter.empty, key
        elif param.kind == "markers":
            assert argument.default is None, key
        else:
            assert argument.default == param.default, key


def test_spatial_elements_on_a_planar_model_and_planar_ones_on_a_spatial_model_are_refused():
    spatial, planar = jp.Model(kinematics="spatial"), jp.Model()
    cases = [
        (lambda: planar.add_spherical("j", "a.p", "b.p"),
         'joints.j.type: "spherical" is available in spatial models only (Model(name, kinematics="spatial"))'),
        (lambda: planar.add_bushing("k", "a.p", "b.p"),
         'forces.k.type: "bushing" is available in spatial models only (Model(name, kinematics="spatial"))'),
        (lambda: planar.add_ground_point("O", (0, 0), axes={"axis": (0, 0, 1), "angle": 0}),
         'ground.points.O: axes are for spatial models (Model(name, kinematics="spatial")); a planar point has none'),
        (lambda: spatial.add_clearance_revolute("B", "a.p", "b.p", bearing_radius=0.01, clearance=1e-4,
                                                contact={"law": "hertz"}),
         'joints.B.type: "clearance_revolute" is not available in spatial models'),
        (lambda: spatial.add_rotational_spring_damper("R", "a", "b"),
         'forces.R.type: "rotational_spring_damper" is not available in spatial models'),
        (lambda: spatial.add_beam("rod", (0, 0), (1, 0), {"shape": "circle", "diameter": 0.01}),
         "beams.rod: beams are not available in spatial models"),
        (lambda: spatial.add_modal_body("link", (0, 0), (1, 0), {"shape": "circle", "diameter": 0.01}),
         "modal_bodies.link: modal bodies are not available in spatial models"),
        (lambda: spatial.add_strain_gauge("g", "rod.start"),
         "sensors.g: sensors (strain gauges of beams and modal bodies) are not available in spatial models"),
        (lambda: jp.Model("x", gravity=(0, -9.81), kinematics="spatial"),
         'model.gravity: gravity needs 3 components in a spatial model, [gx, gy, gz] (e.g. [0, 0, "-9.81 m/s^2"]), '
         "got [0, -9.81]"),
        (lambda: spatial.set_gravity((0, "-9.81 m/s^2")),
         'model.gravity: gravity needs 3 components in a spatial model, [gx, gy, gz] (e.g. [0, 0, "-9.81 m/s^2"]), '
         "got [0, '-9.81 m/s^2']"),
        (lambda: jp.Model("x", kinematics="spacial"),
         "model.kinematics: must be one of planar, spatial, got 'spacial' (did you mean \"spatial\"?)"),
        (lambda: spatial.add_body("b", mass=1, inertia=0.1),
         "bodies.b.inertia: must be an inertia tensor, " + " or ".join(o.INERTIA_FORMS) + ", got 0.1 (a single "
         "moment of inertia is for planar models)"),
        (lambda: spatial.add_body("b", mass=1, inertia={"principal": [1, 1, 1]}, position=(0, 0)),
         'bodies.b.position: must be three components [x, y, z] (e.g. ["0.5 mm", 0, 0]), got (0, 0)'),
        (lambda: spatial.add_ground_point("O", (0, 0, 0), axes={"axis": (0, 0, 0), "angle": 0}),
         "ground.points.O.axes.axis: must be a non-zero direction, got [0, 0, 0]"),
    ]
    for call, message in cases:
        with pytest.raises(jp.ModelError) as info:
            call()
        assert [str(problem) for problem in info.value.problems] == [message]
    assert spatial.to_spec()["spatial_bodies"] == [] and planar.to_spec().get("spatial_bodies") is None


def test_a_planar_model_keeps_its_spec():
    m = jp.Model("p", gravity=(0, -9.81))
    assert m.kinematics == "planar"
    assert set(m.to_spec()) == {"name", "gravity", "ground_points", "bodies", "beams", "joints", "drivers", "forces",
                                "sensors"}
    assert m.to_spec()["gravity"] == [0.0, -9.81]


# every message of a bad spatial model file --------------------------------------------------------

HEAD = '[model]\nkinematics = "spatial"\n[ground.points]\nO = [0, 0, 0]\n'
BODY = '[bodies.b]\nmass = "1 kg"\ninertia = { principal = [1, 1, 1] }\npoints = { A = [0, 0, 0] }\n'
HEAD = HEAD.replace("\n[ground.points]", '\n[units]\ninertia = "kg m^2"\n[ground.points]')
JOINT = '[joints.j]\ntype = "spherical"\nfirst = "ground.O"\nsecond = "b.A"\n'


@pytest.mark.parametrize(("text", "expected"), [
    ('[model]\nkinematics = "spatial"\ngravity = [0, "-9.81 m/s^2"]\n[units]\ninertia = "kg m^2"\n' + BODY + JOINT.replace("ground.O", "b.A"),
     ['model.gravity: gravity needs 3 components in a spatial model, [gx, gy, gz] (e.g. [0, 0, "-9.81 m/s^2"]), '
      "got [0, '-9.81 m/s^2']"]),
    (HEAD + BODY + '[joints.B]\ntype = "clearance_revolute"\nbearing = "ground.O"\njournal = "b.A"\n',
     ['joints.B.type: "clearance_revolute" is not available in spatial models']),
    (HEAD + BODY + JOINT + '[forces.R]\ntype = "rotational_spring_damper"\nfirst = "ground"\nsecond = "b"\n',
     ['forces.R.type: "rotational_spring_damper" is not available in spatial models']),
    (HEAD + BODY + JOINT + '[beams.rod]\nstart = [0, 0]\n[modal_bodies.link]\nstart = [0, 0]\n'
                           '[sensors.g]\ntype = "strain_gauge"\n',
     ["beams.rod: beams are not available in spatial models",
      "modal_bodies.link: modal bodies are not available in spatial models",
      "sensors.g: sensors (strain gauges of beams and modal bodies) are not available in spatial models"]),
    (HEAD + BODY.replace("{ principal = [1, 1, 1] }", '"1 kg m^2"') + JOINT,
     ["bodies.b.inertia: must be an inertia tensor, " + " or ".join(o.INERTIA_FORMS) + ", got '1 kg m^2' (a "
      "single moment of inertia is for planar models)"]),
    (HEAD + BODY.replace("[1, 1, 1]", "[1, 1, 3]") + JOINT,
     ["bodies.b.inertia.principal: principal moments [1, 1, 3] kg m^2 violate the triangle inequality J1 + J2 >= "
      "J3 (1 + 1 < 3 kg m^2): no rigid body has them"]),
    (HEAD + BODY + 'orientation = { matrix = [[1, 0, 0], [0, 0, 1], [0, 1, 0]] }\n' + JOINT,
     ["bodies.b.orientation.matrix: is not a rotation: its determinant must be +1 within 1e-06, got -1 (a "
      "reflection: one axis points the wrong way)"]),
    (HEAD + BODY + 'orientation = { euler = [0, 0, 0], sequence = "3-1-4" }\n' + JOINT,
     ['bodies.b.orientation.sequence: must be an intrinsic Euler sequence, one of XYX, XYZ, XZX, XZY, YXY, YXZ, YZX, '
      'YZY, ZXY, ZXZ, ZYX, ZYZ (or by axis numbers, "3-1-3" for "ZXZ"), got \'3-1-4\' (did you mean "3-1-3"?)']),
    (HEAD + BODY.replace("A = [0, 0, 0]", "A = { position = [0, 0, 0], axes = { quaternion = [0, 0, 0, 0] } }")
     + JOINT,
     ["bodies.b.points.A.axes.quaternion: must not be zero: [w, x, y, z] is normalised, and a zero quaternion has "
      "no direction"]),
    (HEAD + BODY.replace("A = [0, 0, 0]", "A = { position = [0, 0], axis = 1 }") + JOINT,
     ['bodies.b.points.A.axis: unknown key (did you mean "axes"?); a point with axes is { position = [x, y, z], '
      "axes = <orientation> }"]),
    (HEAD + BODY.replace("A = [0, 0, 0]", 'A = [0, "1 kg", 0]') + JOINT,
     ["bodies.b.points.A: y component must be a length (e.g. \"0.5 mm\"), got '1 kg', which is a mass"]),
    (HEAD + BODY + 'angle = "10 deg"\nposition = [0, 0]\n' + JOINT,
     ['bodies.b.position: must be three components [x, y, z] (e.g. ["0.5 mm", 0, 0]), got [0, 0]',
      'bodies.b.angle: unknown key; spatial body: allowed: mass, inertia, position, orientation, velocity, '
      "angular_velocity, points, euler_sequence, free"]),
    (HEAD + BODY + JOINT.replace("spherical", "spherica"),
     ['joints.j.type: must be one of revolute, spherical, cylindrical, translational, universal, fixed, spatial_clearance_revolute, got '
      "'spherica' (did you mean \"spherical\"?)"]),
    (HEAD + BODY + JOINT + '[drivers.d]\njoint = "j"\nfunction = 0\n',
     ["drivers.d.joint: joint 'j' is a spherical joint; only revolute, cylindrical and translational joints can "
      "be driven"]),
    (HEAD + BODY + JOINT + '[forces.f]\ntype = "point_force"\npoint = "b.A"\nforce = ["1 N", 0]\n',
     ['forces.f.force: must be three components [x, y, z], each a quantity or a function of time (e.g. '
      "[\"10 N\", 0, 0]), got ['1 N', 0]"]),
    (HEAD + BODY + JOINT + '[forces.f]\ntype = "point_force"\npoint = "b.A"\nforce = [0, "1 N m", 0]\n'
                           'frame = "local"\n',
     ["forces.f.frame: must be one of global, body, got 'local' (did you mean \"global\"?)"]),
    (HEAD + BODY + JOINT + '[forces.f]\ntype = "point_force"\npoint = "b.A"\nforce = [0, "1 N m", 0]\n',
     ["forces.f.force[1]: must be a force (e.g. \"100 N\"), got '1 N m', which is a torque"]),
    (HEAD + BODY + JOINT + '[forces.k]\ntype = "bushing"\nfirst = "ground.O"\nsecond = "b.B"\n'
                           'stiffness = ["1 N/m", "-1 N/m", 0]\n',
     ["forces.k.stiffness: y component must be >= 0, got -1 N/m"]),
    (HEAD + BODY + JOINT + '[forces.k]\ntype = "bushing"\nfirst = "ground.O"\nsecond = "b.B"\n',
     ["forces.k.second: body 'b' has no point 'B' (its points: A), got 'b.B'"]),
    (HEAD + BODY,
     ["bodies.b: is connected to nothing: no joint or force element refers to it (write free = true if it is "
      "meant to move freely)"]),
])
def test_every_bad_spatial_input_gets_its_located_message(text, expected):
    assert problems(text) == expected


# the registry covers the spatial tables -------------------------------------------------------

def test_every_spatial_key_is_in_the_reference_with_its_table():
    page = reference.text()
    assert page == (ROOT / "docs" / "model-file-reference.md").read_text(encoding="utf-8")
    for table in p.spatial_tables():
        for param in table.params:
            assert f"| `{param.key}` |" in page, (table.name, param.key)
    assert "### `[bodies.NAME]` of a spatial model" in page


def test_every_spatial_default_lies_in_its_range_and_every_kind_is_known():
    from jointplay.units import KINDS

    for table in p.spatial_tables():
        for param in table.params:
            assert param.kind in KINDS or param.kind in p.STRUCTURED, (table.name, param.key)
            defaults = param.default if param.kind == "vector3" else (param.default,)
            for d in defaults:
                if isinstance(d, float) and not param.required:
                    assert (param.gt is None or d > param.gt) and (param.ge is None or d >= param.ge), param.key
            if param.kind in ("vector3", "function3"):
                assert param.of in KINDS, (table.name, param.key)
            if param.kind == "choice" and isinstance(param.default, str):
                assert param.default in param.of, param.key


def test_the_spatial_fixture_uses_every_key_of_every_spatial_table_and_every_orientation_form():
    doc = tomllib.loads(EVERY_KEY.read_text(encoding="utf-8"))
    used = {(id(p.SPATIAL_MODEL), key) for key in doc["model"]} | {(id(p.SPATIAL_GROUND), key) for key in doc["ground"]}
    for raw in doc["bodies"].values():
        used |= {(id(p.SPATIAL_BODY), key) for key in raw}
    for section, family in (("joints", p.SPATIAL_JOINTS), ("forces", p.SPATIAL_FORCES)):
        for raw in doc[section].values():
            used |= {(id(family[raw["type"]]), key) for key in [*raw, None]}
    missing = [(t.name, key) for t in p.spatial_tables() for key in [*t.keys(), *([None] if t.tag else [])]
               if (id(t), key) not in used]
    assert missing == []
    points = [point for table in [doc["ground"], *doc["bodies"].values()] for point in table.get("points", {}).values()]
    forms = [body["orientation"] for body in doc["bodies"].values() if "orientation" in body]
    forms += [point["axes"] for point in points if isinstance(point, dict)]
    assert {key for form in forms for key in form} == {"axis", "angle", "euler", "sequence", "matrix", "quaternion"}


def test_orientation_helpers_are_inverse_of_each_other():
    for axis, angle in itertools.product(([1, 0, 0], [0, 1, 1], [-1, 2, 0.5]), (0.1, 1.5, 3.0)):
        r = rodrigues(axis, angle)
        assert o.rotation_matrix(o.matrix_quaternion(r)) == pytest.approx(r, abs=1e-15)


def test_the_example_of_the_model_file_guide_reads_and_its_313_matrix_is_right():
    guide = (ROOT / "docs" / "model-files.md").read_text(encoding="utf-8")
    section = guide[guide.index("## Spatial models"):guide.index("## How a run starts")]
    example = section[section.index("```toml") + len("```toml"):section.index("```\n\n### Conventions")]
    spec, _ = read_spec_text(example)
    assert [body["name"] for body in spec["spatial_bodies"]] == ["bob"]
    assert spec["spatial_joints"] == [{"type": "revolute", "name": "hinge", "first": "ground.O", "second": "bob.P"}]
    assert "`R = [[0, 0, 1], [1, 0, 0], [0, 1, 0]]`" in section
    q = o.quaternion({"euler": ["90 deg", "90 deg", 0], "sequence": "3-1-3"})
    assert hamilton_matrix(q) == pytest.approx(np.array([[0, 0, 1], [1, 0, 0], [0, 1, 0]]), abs=1e-15)


def test_the_builder_takes_a_scipy_rotation_as_an_orientation():
    from scipy.spatial.transform import Rotation

    rotation = Rotation.from_euler("ZXZ", [0.3, 1.1, -2.4])
    q = o.quaternion(rotation)
    assert hamilton_matrix(q) == pytest.approx(rotation.as_matrix(), abs=1e-15)
    m = jp.Model(kinematics="spatial")
    m.add_body("b", mass=1, inertia={"principal": [1, 1, 1], "axes": rotation}, orientation=rotation)
    assert m.to_spec()["spatial_bodies"][0]["orientation"] == q


def test_an_integer_beyond_the_floats_range_in_an_orientation_is_a_located_problem():
    # (found by tests/test_model_file_fuzz.py: it raised OverflowError from math.isfinite)
    text = EVERY_KEY.read_text(encoding="utf-8").replace('quaternion = [2, 0, 0, 0]', f'quaternion = [{10 ** 400}, 0, 0, 0]', 1)
    with pytest.raises(jp.ModelError) as caught:
        loads(text)
    assert any("orientation" in p.location and "finite plain number" in p.message for p in caught.value.problems), \
        caught.value.problems
