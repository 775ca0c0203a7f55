"""How a flexible body starts: with no velocities given, a beam or a modal body starts in the rigid motion the
assembled mechanism gives it (docs/model-files.md, "How a run starts"); given velocities are held and checked.

Reference: the slider-crank of examples/flores_slider_crank_dry.py with ideal joints, crank along x at
5000 rpm. In that position the rigid rod's motion is known in closed form: the crank pin A moves at
omega r upwards, the slider is at a dead centre (at rest), so the rod turns at -omega r / L and its every
point moves at omega r (1 - s / L) upwards, s the arclength from A.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp
from jointplay import sections

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples"))
import flores_flexible_rod as flexible_rod  # noqa: E402
import flores_slider_crank_dry as rigid  # noqa: E402

OMEGA, CRANK, ROD = rigid.CRANK_SPEED, rigid.CRANK, rigid.ROD


def slider_crank(rod: str, **rod_velocities) -> jp.Model:
    """The ideal slider-crank with its rod ``"rigid"``, a ``"beam"`` or a ``"modal"`` body (4 quadratic elements,
    the example's section), ``rod_velocities`` given to the flexible rod."""
    model = rigid.build_model().idealized()
    if rod == "rigid":
        return model
    spec = model.to_spec()
    spec["bodies"] = [b for b in spec["bodies"] if b["name"] != "rod"]
    renamed = {"rod.A": "rod.start", "rod.B": "rod.end"}
    for joint in spec["joints"]:
        for key in ("first", "second"):
            if key in joint:
                joint[key] = renamed.get(joint[key], joint[key])
    flexible = jp.Model.from_spec(spec)
    geometry = dict(section=sections.rectangle(flexible_rod.WIDTH, flexible_rod.DEPTH), material=flexible_rod.STEEL,
                    elements=4, damping_time=1e-5, **rod_velocities)
    if rod == "beam":
        flexible.add_beam("rod", (CRANK, 0.0), (CRANK + ROD, 0.0), **geometry)
    else:
        flexible.add_modal_body("rod", (CRANK, 0.0), (CRANK + ROD, 0.0), **geometry)
    return flexible


def run(model: jp.Model, t_end: float = 1e-3) -> jp.Results:
    return model.simulate(t_end, method="bdf", max_order=2, stabilization="baumgarte", rtol=1e-6, atol=1e-9,
                          max_step=1e-5, output_step=1e-5)


@pytest.mark.parametrize("kind", ["beam", "modal"])
def test_a_flexible_rod_without_velocities_starts_in_the_rigid_rods_motion(kind):
    check = slider_crank(kind).check()
    v = check["initial_velocities"]
    # the crank's 3 coordinates, the slider's 3, then the rod's
    rod = v[6:]
    # (the rod starts in its quasi-static strain, which shortens it by its axial strain, 1.7e-4 at 8.2 kN: the rates differ from the unstrained rod's by that much)
    if kind == "beam":
        nodes = rod.reshape(-1, 3)
        s = np.linspace(0.0, ROD, len(nodes))
        np.testing.assert_allclose(nodes[:, 0], 0.0, atol=1e-3)
        np.testing.assert_allclose(nodes[:, 1], OMEGA * CRANK * (1.0 - s / ROD), atol=1e-3)
        np.testing.assert_allclose(nodes[:, 2], -OMEGA * CRANK / ROD, rtol=1e-3)
    else:
        # the frame's origin at A, the frame turning with the rod, no modal rate
        np.testing.assert_allclose(rod[:3], [0.0, OMEGA * CRANK, -OMEGA * CRANK / ROD], rtol=1e-3, atol=1e-3)
        np.testing.assert_allclose(rod[3:], 0.0, atol=1e-9)


def test_given_rigid_motion_is_the_same_start_as_none_given():
    found = slider_crank("beam").check()["initial_velocities"]
    given = slider_crank("beam", velocity=(0.0, OMEGA * CRANK), angular_velocity=-OMEGA * CRANK / ROD)
    np.testing.assert_allclose(given.check()["initial_velocities"], found, rtol=1e-12, atol=1e-9)


@pytest.mark.parametrize("kind", ["beam", "modal"])
def test_given_velocities_that_contradict_the_joints_are_refused_naming_the_body(kind):
    model = slider_crank(kind, velocity=(0.0, 0.0), angular_velocity=0.0)
    with pytest.raises(jp.SimulationError) as caught:
        model.check()
    message = str(caught.value)
    assert "the initial velocities given for rod contradict its joints and drivers" in message
    # what the joints need instead: the rigid rod's motion
    assert f"rod needs about (0.0000, {OMEGA * CRANK:.4f}) m/s at its first end and {-OMEGA * CRANK / ROD:.4f} rad/s" \
        in message, message
    assert "leave the velocities out" in message


@pytest.mark.parametrize("kind", ["beam", "modal"])
def test_the_flexible_rod_has_no_start_transient(kind):
    """Before the flexible start the rod's inner nodes started at rest while its ends moved with the crank and
    slider: a 479 kN spike in the crank bearing against the rigid mechanism's 8.3 kN. Starting in the rigid
    motion alone left an elastic settling, the rod unstrained while the rigid rod carries its inertial load at
    once: +37 % in the first millisecond. Started also in its quasi-static strain, the flexible rod's crank
    bearing force stays within 1 % of the rigid one's over the first millisecond (measured 0.002 % at t = 0)."""
    rigid_run, flexible_run = run(slider_crank("rigid")), run(slider_crank(kind))
    rigid_peak = np.max(np.abs(rigid_run["O.fx"]))
    assert rigid_peak == pytest.approx(8253, rel=1e-3)
    assert np.max(np.abs(flexible_run["O.fx"])) == pytest.approx(rigid_peak, rel=0.01)
    assert flexible_run["O.fx"][0] == pytest.approx(rigid_run["O.fx"][0], rel=1e-4)
    difference = np.interp(rigid_run.time, flexible_run.time, flexible_run["O.fx"]) - rigid_run["O.fx"]
    assert np.max(np.abs(difference)) < 0.01 * rigid_peak


def test_the_rod_starts_stretched_by_the_load_it_carries():
    """The beam rod's quasi-static strain at the start: the axial force of its section at the crank pin carries
    what the rigid rod's pin carries along the rod (x, the rod along x at the start), within 2 % (the
    section's force is recovered from the strains of a 4-element mesh)."""
    model = slider_crank("beam")
    model.add_strain_gauge("E", "rod.start", fibre=0.0)
    first = run(model, 1e-5)
    rigid_run = run(slider_crank("rigid"), 1e-5)
    assert abs(first["E.axial_force"][0]) == pytest.approx(abs(rigid_run["A.fx"][0]), rel=0.02)
