"""The circuit-breaker mechanism after paper 003 (examples/paper003_breaker.toml and .py): its freedom,
its rigid kinematics against a position analysis written here, the stroke the paper requires, and the
flexible and clearance variants.

The position analysis is independent of jointplay: it solves the loop closures of the geometry that
docs/theory/reference-breaker.md states (pivots A, D, F on the frame; the two four-bars A-B-C-D and
D-E-G-F; the moving contact at H's height, through the yoke I) with scipy's fsolve.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import fsolve

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
sys.path.insert(0, str(EXAMPLES))

import paper003_breaker as example  # noqa: E402
from jointplay.modelfile import from_document, read_document  # noqa: E402

# The geometry of docs/theory/reference-breaker.md [m]: frame pivots and link lengths (Table 1 of the
# paper for the lengths; the pivot coordinates and the arms' pivot positions are the chosen ones).
A, D, F = np.array([0.0, 0.0]), np.array([0.132714, -0.116]), np.array([0.244, -0.194])
UPPER_LINK, MIDDLE_LINK, DOWN_LINK = 0.082, 0.116, 0.078
D_TO_C, D_TO_E = 0.050714, 0.071 - 0.050714  # upper arm, 0.071 m, pivot D between C and E
F_TO_G, F_TO_H = 0.091, 0.208 - 0.091  # down arm, 0.208 m, pivot F between G and H
STROKE_TIME, STROKE_ANGLE = 0.03, math.radians(-19.0)  # eq. (5), read in degrees


def drive_angle(t: float) -> float:
    """Eq. (5) of paper 003: the upper link's angle [rad] at time t [s]."""
    s = min(t / STROKE_TIME, 1.0)
    return STROKE_ANGLE * s * s * (3 - 2 * s)


def closure(angles, theta):
    """Loop-closure residuals [m] of the two four-bars at upper-arm angle phi, down-arm angle psi."""
    phi, psi = angles
    b = A + UPPER_LINK * np.array([math.cos(theta), math.sin(theta)])
    c = D + D_TO_C * np.array([math.cos(phi), math.sin(phi)])
    e = D - D_TO_E * np.array([math.cos(phi), math.sin(phi)])
    g = F + F_TO_G * np.array([math.cos(psi), math.sin(psi)])
    return [np.hypot(*(c - b)) - MIDDLE_LINK, np.hypot(*(g - e)) - DOWN_LINK]


def contact_height(theta: float, guess=(math.pi, math.pi)) -> tuple[float, float]:
    """Height of H (= the moving contact's, through the yoke) [m] and the closure Jacobian's determinant."""
    (phi, psi), info, ok, message = fsolve(closure, guess, args=(theta,), full_output=True, xtol=1e-12)
    assert ok == 1, message
    h = F - F_TO_H * np.array([math.cos(psi), math.sin(psi)])
    jacobian = np.array([[(closure([phi + d, psi], theta)[i] - closure([phi - d, psi], theta)[i]) / (2 * d),
                          (closure([phi, psi + d], theta)[i] - closure([phi, psi - d], theta)[i]) / (2 * d)]
                         for i in range(2) for d in [1e-7]])
    return float(h[1]), float(np.linalg.det(jacobian))


def test_the_mechanism_has_one_freedom_which_the_drive_takes():
    doc = example.ideal_joints(read_document(example.MODEL_FILE))
    driven = from_document(doc, name="driven")
    assert driven.check()["degrees_of_freedom"] == 0
    del doc["drivers"]
    assert from_document(doc, name="free").check()["degrees_of_freedom"] == 1
    # the model file itself: two journal coordinates per clearance joint, nothing else free
    assert example.build_model("clearance").check()["degrees_of_freedom"] > 2 * len(example.CLEARANCE_JOINTS)
    assert from_document(read_document(example.MODEL_FILE), name="file").check()["degrees_of_freedom"] == \
        2 * len(example.CLEARANCE_JOINTS)


def test_the_loops_stay_far_from_a_locked_position_over_the_stroke():
    # a locked (toggle) position makes the closure Jacobian singular; over the stroke it keeps at least
    # a third of its starting size
    dets = [contact_height(math.radians(deg))[1] for deg in np.linspace(0.0, -19.0, 20)]
    assert min(abs(d) for d in dets) > abs(dets[0]) / 3
    assert all(np.sign(d) == np.sign(dets[0]) for d in dets)


@pytest.fixture(scope="module")
def rigid_run():
    return example.simulate(example.build_model("rigid"))


def test_rigid_kinematics_match_the_independent_position_analysis(rigid_run):
    t = rigid_run.time
    for k in np.linspace(0, len(t) - 1, 9).astype(int):
        expected, _ = contact_height(drive_angle(t[k]))
        # the drive is prescribed, so the positions are the constraint solution's (measured within 6e-11 m);
        # a pivot moved by a micrometre shifts the contact by about as much
        assert rigid_run[example.CONTACT_Y][k] == pytest.approx(expected, abs=1e-9), t[k]
        assert rigid_run[example.CONTACT_X][k] == pytest.approx(0.361, abs=1e-9)


def test_the_moving_contact_travels_down_at_least_12_mm_within_30_ms(rigid_run):
    travel = example.travel(rigid_run)
    assert rigid_run.time[-1] == pytest.approx(0.03)
    assert travel[-1] >= 0.012  # paper 003, §2.1
    assert np.all(np.diff(travel) >= -1e-9)  # downward all the way


def test_flexible_and_clearance_variants_run_and_the_clearance_joints_touch():
    flexible = example.simulate(example.build_model("flexible"), 0.003)
    assert flexible.error is None and flexible.time[-1] == pytest.approx(0.003)
    clearance = example.simulate(example.build_model("clearance"), 0.003)
    assert clearance.error is None
    # H's force channel in this variant is the contact force: normal and friction components together
    np.testing.assert_allclose(clearance[example.H_FORCE_CHANNEL["clearance"]],
                               np.hypot(clearance["H.fn"], clearance["H.ft"]), rtol=1e-9, atol=1e-9)
    touched = [j for j in example.CLEARANCE_JOINTS if np.any(clearance[f"{j}.contact"] > 0.5)]
    assert touched, "no clearance joint touched in 3 ms"
    # at its deepest sample a contact is near its turning point, where the Lankarani-Nikravesh damping
    # (3 (1 - 0.9^2)/4 times the ratio of penetration rates) is small: the force is eq. (4)'s K delta^1.5
    joint = max(touched, key=lambda j: np.max(clearance[f"{j}.penetration"]))
    deepest = np.argmax(clearance[f"{joint}.penetration"])
    delta = clearance[f"{joint}.penetration"][deepest]
    assert clearance[f"{joint}.fn"][deepest] == pytest.approx(hertz_stiffness() * delta ** 1.5, rel=0.15)


def hertz_stiffness() -> float:
    """Paper 003's eq. (4) K [N/m^1.5] for steel (Table 2) in a 6 mm bore with 15 um radial clearance."""
    youngs, poisson, bore = 207e9, 0.3, 6e-3
    shaft = bore - 15e-6
    effective = youngs / (2 * (1 - poisson ** 2))
    return 4 / 3 * effective * math.sqrt(bore * shaft / (bore - shaft))


def test_each_clearance_is_its_own_override_path():
    model = example.build_model("clearance", overrides={"joints.E.clearance": "18 um"})
    joints = {j["name"]: j for j in model.to_spec()["joints"]}
    assert joints["E"]["clearance"] == pytest.approx(18e-6)
    assert joints["F"]["clearance"] == pytest.approx(15e-6)
    everywhere = {j["name"]: j for j in example.build_model("clearance", clearance=27e-6).to_spec()["joints"]}
    assert [everywhere[j]["clearance"] for j in example.CLEARANCE_JOINTS] == pytest.approx([27e-6] * 7)


def test_a_wrong_variant_is_named():
    from jointplay.errors import ModelError

    with pytest.raises(ModelError, match="'stiff'"):
        example.build_model("stiff")


def test_the_example_writes_its_figure_and_table(tmp_path, capsys):
    runs = example.main(["--quick", "--out", str(tmp_path)])
    assert set(runs) == set(example.VARIANTS)
    for stem in example.FIGURES:
        assert (tmp_path / f"{stem}.png").stat().st_size > 10_000
    assert "peak |a|" in capsys.readouterr().out


def test_two_modes_per_link_agree_with_eight_within_the_stated_one_per_cent():
    # the cheap form of the convergence check of docs/theory/reference-breaker.md: the first 5 ms,
    # where the drive's start sets the links ringing
    few, many = (example.simulate(example.build_model("flexible", modes=n), 0.005) for n in (example.MODES, 8))
    assert np.array_equal(few.time, many.time)
    for channel in (example.CONTACT_ACCELERATION, example.H_REACTION):
        peak = np.max(np.abs(many[channel]))
        assert np.max(np.abs(few[channel] - many[channel])) < 0.01 * peak, channel
    # and the links do ring: the flexible contact's acceleration leaves the rigid one by far more
    rigid = example.simulate(example.build_model("rigid"), 0.005)
    acceleration = many[example.CONTACT_ACCELERATION]
    assert np.max(np.abs(acceleration - rigid[example.CONTACT_ACCELERATION])) > 0.2 * np.max(np.abs(acceleration))


def test_the_reaction_at_h_is_newtons_second_law_on_the_block_and_the_contact(rigid_run):
    # Rigid variant: the slider I passes no force along x and J holds the contact in x, so along x the
    # pin H alone accelerates the insulating link (0.973 kg, Table 1); along y H, the buffer spring
    # (20 kN/m, stretched by the travel) and gravity accelerate the insulating link and the moving
    # contact (2.270 kg) together, at the contact's acceleration.
    block, contact, spring_rate, g = 0.973, 2.270, 20e3, 9.81
    along_x = block * rigid_run["insulating_link.ax"]
    along_y = ((block + contact) * (rigid_run[example.CONTACT_ACCELERATION] + g)
               - spring_rate * example.travel(rigid_run))
    expected = np.hypot(along_x, along_y)
    # the same samples, the same accelerations: agreement to round-off of the constraint solution
    np.testing.assert_allclose(rigid_run[example.H_REACTION], expected, rtol=1e-6, atol=1e-6 * expected.max())


def test_the_clearance_variant_by_default_and_the_clearance_argument_sets_every_joint():
    default = {j["name"]: j for j in example.build_model().to_spec()["joints"]}
    assert [default[j]["clearance"] for j in example.CLEARANCE_JOINTS] == [15e-6] * len(example.CLEARANCE_JOINTS)
    wider = {j["name"]: j for j in example.build_model("clearance", clearance=25e-6).to_spec()["joints"]}
    assert [wider[j]["clearance"] for j in example.CLEARANCE_JOINTS] == \
        pytest.approx([25e-6] * len(example.CLEARANCE_JOINTS))
    from jointplay.errors import ModelError

    with pytest.raises(ModelError, match="-1e-05"):
        example.build_model("clearance", clearance=-1e-5)


def test_the_saved_clearance_variant_is_the_same_model_and_takes_each_clearance_path(tmp_path):
    import jointplay as jp

    path = tmp_path / "breaker.toml"
    assert example.main(["--save-model", str(path)]) == {}
    assert jp.load(path).to_spec() == example.build_model("clearance").to_spec()
    joints = {j["name"]: j for j in jp.load(path, {"joints.H.clearance": "18 um"}).to_spec()["joints"]}
    assert (joints["H"]["clearance"], joints["G"]["clearance"]) == pytest.approx((18e-6, 15e-6))


def test_the_clearance_study_runs_and_its_optimum_is_verified(tmp_path):
    """``--study --quick``: the study file on the model file's rigid links (25 cases of 30 ms), surfaces,
    the optimum run again, and the changes from all joints at IT7; each change is the verified run's value
    against the baseline run's, as printed."""
    import paper003_breaker as example

    found = example.main(["--study", "--quick", "--out", str(tmp_path)])
    ds, optimum = found["dataset"], found["optimum"]
    assert ds.sizes["case"] == 25 and (ds["status"].values == "done").all()
    assert set(optimum.verified) == {"acc_oscillation", "force_H_start", "force_H_end"}
    low, high = 8e-6, 27e-6  # IT6..IT8 bands at 12 mm, radial (paper 003 §4.4)
    assert all(low - 1e-12 <= optimum.values[f"clearance_{j}"] <= high + 1e-12 for j in "EFGH")
    for name, change in found["changes"].items():
        assert change == pytest.approx(100 * (optimum.verified[name] / found["baseline"][name] - 1))
    assert (tmp_path / "study_quick" / "study.nc").exists()
