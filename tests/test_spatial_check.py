"""``jointplay check`` and ``Model.check()`` on spatial models: the Grübler-Kutzbach count (Uicker, Pennock
& Shigley, Theory of Machines and Mechanisms, 5th ed., 2017, section 1.9) counted by hand beside the
engine's degrees of freedom from the rank of the constraint equations, and the redundant equations with
the elements they belong to.

- a four-bar built from spatial bodies and four revolute joints about parallel axes: the count is
  3 x 6 - 4 x 5 = -2, the planar four-bar moves with one freedom, so 3 of its 20 equations depend on the
  others (the three out-of-plane equations a planar loop repeats);
- Bricard's six-revolute loop (IFToMM benchmark A04, data in tests/spatial_references.py): the count is
  5 x 6 - 6 x 5 = 0, the mechanism moves with one freedom, one equation redundant.
"""

from __future__ import annotations

import numpy as np
import pytest
from typer.testing import CliRunner

import jointplay as jp
from jointplay.check_spatial import euler_angles, inertia_text, kind_words
from jointplay.cli import app
from jointplay.mobility import gruebler_kutzbach
from spatial_references import BRICARD, body_marker

runner = CliRunner()


def four_bar() -> jp.Model:
    """Crank A-B, coupler B-C and rocker C-D of a planar four-bar in the plane z = 0, every revolute axis
    along the global z (the body axes, the markers' default): A = (0, 0), B = (0, 0.1), C = (0.3, 0.2),
    D = (0.3, 0) m."""
    m = jp.Model("four_bar3d", gravity=[0, -9.81, 0], kinematics="spatial")
    m.add_ground_point("A", [0.0, 0.0, 0.0])
    m.add_ground_point("D", [0.3, 0.0, 0.0])
    inertia = {"principal": [1e-4, 1e-3, 1e-3]}
    m.add_body("crank", mass=0.2, inertia=inertia, position=[0.0, 0.05, 0.0],
               points={"A": [0.0, -0.05, 0.0], "B": [0.0, 0.05, 0.0]})
    m.add_body("coupler", mass=0.5, inertia=inertia, position=[0.15, 0.15, 0.0],
               points={"B": [-0.15, -0.05, 0.0], "C": [0.15, 0.05, 0.0]})
    m.add_body("rocker", mass=0.3, inertia=inertia, position=[0.3, 0.1, 0.0],
               points={"C": [0.0, 0.1, 0.0], "D": [0.0, -0.1, 0.0]})
    m.add_revolute("A", "ground.A", "crank.A")
    m.add_revolute("B", "crank.B", "coupler.B")
    m.add_revolute("C", "coupler.C", "rocker.C")
    m.add_revolute("D", "rocker.D", "ground.D")
    return m


def bricard() -> jp.Model:
    """IFToMM A04: five rods, six revolutes, markers with their z axes along the joint axes."""
    model = jp.Model("bricard", gravity=[float(g) for g in BRICARD["gravity"]], kinematics="spatial")
    rods = {rod["name"]: rod for rod in BRICARD["rods"]}
    points: dict[str, dict] = {name: {} for name in rods}
    for joint in BRICARD["joints"]:
        for side in ("first", "second"):
            position, axes = body_marker(rods.get(joint[side]), joint["point"], joint["axis"])
            marker = {"position": position.tolist(), "axes": {"matrix": axes.tolist()}}
            if joint[side] == "ground":
                model.add_ground_point(joint["name"], position.tolist(), axes={"matrix": axes.tolist()})
            else:
                points[joint[side]][joint["name"]] = marker
    for name, rod in rods.items():
        model.add_body(name, mass=rod["mass"], inertia={"principal": [float(v) for v in rod["inertia_principal"]]},
                       position=rod["position"].tolist(), orientation={"matrix": rod["rotation"].tolist()},
                       points=points[name])
    for joint in BRICARD["joints"]:
        model.add_revolute(joint["name"], f"{joint['first']}.{joint['name']}", f"{joint['second']}.{joint['name']}")
    return model


def test_gruebler_kutzbach_counts_each_joint_type_by_its_equations():
    spec = {"spatial_bodies": [{}] * 4,
            "spatial_joints": [{"type": t} for t in ("spherical", "revolute", "universal", "cylindrical",
                                                      "translational", "fixed")],
            "drivers": [{}, {}]}
    # 4 x 6 - (3 + 5 + 4 + 4 + 5 + 6) - 2 x 1
    assert gruebler_kutzbach(spec) == 24 - 27 - 2


def test_spatial_four_bar_counts_minus_two_and_moves_with_three_redundant_equations():
    info = four_bar().check()
    assert info["gruebler_kutzbach"] == -2
    assert info["n_coordinates"] == 18 and info["n_equations"] == 20
    assert info["redundant_equations"] == 3
    assert info["degrees_of_freedom"] == 1
    assert sorted(info["dependent_elements"]) == ["A", "B", "C", "D"]


def test_bricard_counts_zero_and_moves_with_one_redundant_equation():
    info = bricard().check()
    assert info["gruebler_kutzbach"] == 0
    assert info["n_coordinates"] == 30 and info["n_equations"] == 30
    assert info["redundant_equations"] == 1
    assert info["degrees_of_freedom"] == 1
    assert len(info["dependent_elements"]) == 6  # a loop of six: every joint takes part


def test_planar_check_has_no_spatial_count():
    m = jp.Model("pendulum", gravity=(0.0, -9.81))
    m.add_ground_point("O", [0.0, 0.0])
    m.add_body("bar", mass=1.0, inertia=0.01, position=[0.1, 0.0], points={"O": [-0.1, 0.0]})
    m.add_revolute("O", "ground.O", "bar.O")
    assert "gruebler_kutzbach" not in m.check()


def test_check_prints_spatial_bodies_count_and_redundant_elements(tmp_path):
    path = tmp_path / "four_bar3d.toml"
    four_bar().save(path)
    result = runner.invoke(app, ["check", str(path)], env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    text = " ".join(result.output.split())
    assert "velocities 18 (6 per body), constraint equations 20 of rank 17, degrees of freedom 1" in text
    assert "(Grübler-Kutzbach count: -2)" in text
    assert "3 constraint equation(s) are redundant" in text and "elements involved: A, B, C, D" in text
    assert "the count says -2 and the mechanism has 1" in text
    # the bodies: kind, mass, inertia tensor, position [mm] and Euler angles of the body's sequence [deg]
    row = "│ coupler │ spatial rigid │ 0.5 kg │ diag(0.0001, 0.001, 0.001) kg m^2 │ 150.000, 150.000, 0.000 │ ZYX"
    assert row in result.output
    assert "revolute joint" in text


def test_euler_angles_are_the_intrinsic_angles_of_the_quaternion():
    # 90 deg about x: ZYX angles (0, 0, 90 deg); 3-1-3 (ZXZ) angles (0, 90 deg, 0)
    half = np.sqrt(0.5)
    assert np.allclose(np.degrees(euler_angles([half, half, 0.0, 0.0], "ZYX")), [0.0, 0.0, 90.0], atol=1e-12)
    assert np.allclose(np.degrees(euler_angles([half, half, 0.0, 0.0], "zxz")), [0.0, 90.0, 0.0], atol=1e-12)


@pytest.mark.parametrize(("kind", "words"), [("SpatialJoint(Revolute)", "revolute joint"),
                                             ("SpatialAngleDriver", "angle driver")])
def test_core_kinds_read_as_words(kind, words):
    assert kind_words(kind) == words


def test_inertia_shows_the_full_tensor_when_it_has_products():
    assert inertia_text([[2, 0, 0], [0, 3, 0], [0, 0, 4]]) == "diag(2, 3, 4) kg m^2"
    assert inertia_text([[2, 0.5, 0], [0.5, 3, 0], [0, 0, 4]]) == "2, 0.5, 0; 0.5, 3, 0; 0, 0, 4 kg m^2"


def test_check_prints_the_orientation_in_the_bodys_euler_sequence(tmp_path):
    from scipy.spatial.transform import Rotation

    # the pivot 200 mm above the centre of mass, in the frame of the body turned by the 3-1-3 angles
    pivot = Rotation.from_euler("ZXZ", [20, 10, 5], degrees=True).inv().apply([0.0, 0.0, 0.2])
    m = jp.Model("hung", gravity=[0, 0, -9.81], kinematics="spatial")
    m.add_ground_point("O", [0.0, 0.0, 0.0])
    m.add_body("bob", mass=0.5, inertia={"principal": [2e-3, 2e-3, 1e-4]}, position=[0.0, 0.0, -0.2],
               orientation={"euler": ["20 deg", "10 deg", "5 deg"], "sequence": "3-1-3"}, euler_sequence="3-1-3",
               points={"O": pivot.tolist()})
    m.add_spherical("O", "ground.O", "bob.O")
    path = tmp_path / "hung.toml"
    m.save(path)
    result = runner.invoke(app, ["check", str(path)], env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    # a spherical joint leaves the orientation as given: the angles it was given, in its sequence
    assert "│ 0.000, 0.000, -200.000 │ ZXZ 20.000, 10.000, 5.000 │" in result.output
    assert "degrees of freedom 3 from the rank" in " ".join(result.output.split())
