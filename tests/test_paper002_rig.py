"""Paper 002's hydraulic cylinder rig (examples/paper002_cylinder_rig.toml and .py, and the study of
examples/paper002_cylinder_study.py): the physics it must show, checked against closed forms written here,
the figures of the spatial clearance joint from a real short run, and the study on a 2 x 2 table.

Closed forms, independent of the code under test:
- the hydraulic spring of closed chambers, k = beta (A1^2/V1 + A2^2/V2) (Merritt, Hydraulic Control Systems,
  1967; docs/theory/hydraulic-cylinder.md), with the rig's geometry: the cylinder at angle alpha to the guide
  carries F / cos(alpha) of a horizontal force F on the slider, and the slider moves ds / cos(alpha) along
  the guide for a stroke change ds;
- the statics of the barrel and rod at rest under gravity: no horizontal load, so the moments about the
  barrel pin A give the slider pin's share of the weights, B_z = (m_b g d_b + m_r g d_r) / L, and A_z the rest.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
sys.path.insert(0, str(EXAMPLES))

import paper002_cylinder_rig as rig  # noqa: E402
from jointplay.modelfile import from_document  # noqa: E402

G = 9.81  # m/s^2, the model file's gravity
#: The model file's values (its header says why each is chosen).
ALPHA = math.radians(5.0)  # inclination of the cylinder
BORE, ROD, STROKE_0, DEAD, BETA = 0.080, 0.045, 0.250, 1e-4, 1e9  # m, m, m, m^3, Pa
PIN_DISTANCE = 1.050  # m, pin A to pin B at the start
BARREL_MASS, BARREL_ARM = 16.081, 0.3060571  # kg; its centre of mass from pin A along the axis [m]
ROD_MASS, ROD_ARM = 10.643, PIN_DISTANCE - 0.3766470  # kg; its centre of mass from pin A [m]


def hydraulic_stiffness() -> float:
    """k = beta (A1^2/V1 + A2^2/V2) [N/m] at the starting stroke."""
    a1 = math.pi * BORE**2 / 4
    a2 = math.pi * (BORE**2 - ROD**2) / 4
    v1, v2 = a1 * STROKE_0 + DEAD, a2 * STROKE_0 + DEAD
    return BETA * (a1**2 / v1 + a2**2 / v2)


def weight_shares() -> tuple[float, float]:
    """Vertical pin loads (A_z, B_z) [N] carried by the barrel pin and the slider pin at rest."""
    b_z = G * (BARREL_MASS * BARREL_ARM + ROD_MASS * ROD_ARM) / PIN_DISTANCE
    return G * (BARREL_MASS + ROD_MASS) - b_z, b_z


def test_variants_change_what_they_say():
    doc = rig.document(force=1500.0, frequency=7.0, clearance=0.2e-3, axial_clearance=0.3e-3)
    sine = doc["forces"]["input"]["force"][0]
    assert (sine["amplitude"], sine["frequency"]) == ("1500.0 N", "7.0 Hz")
    ideal = rig.document(ideal=True)
    for joint in rig.JOINTS:
        assert ideal["joints"][joint]["type"] == "revolute"
    assert rig.build_model(ideal=True).check()["degrees_of_freedom"] == 1


def ramped_ideal_rig(force: float) -> dict:
    """The ideal-joint rig with frictionless seals and a horizontal force ramped smoothly to ``force`` [N]
    over 0.1 s (13 periods of the oil spring's 127 Hz: its residual vibration is about 1e-3 of the
    deflection and averages out over the window below)."""
    doc = rig.document(ideal=True)
    del doc["forces"]["cylinder"]["seal_friction"]
    doc["forces"]["input"]["force"][0] = {"kind": "cubic_step", "t_start": "0 s", "t_end": "0.1 s",
                                          "value_start": "0 N", "value_end": f"{force!r} N"}
    return doc


def test_oil_spring_deflects_the_slider_as_its_closed_form():
    runs = {}
    for force in (2000.0, -2000.0):
        model = from_document(ramped_ideal_rig(force))
        runs[force] = model.simulate(0.2, method="dopri5", rtol=1e-8, atol=1e-11, output_step=1e-4)
    window = {f: r.time >= 0.1 for f, r in runs.items()}  # after the ramp, 12.7 periods of the oil spring

    def half_difference(channel: str) -> float:
        return (np.mean(runs[2000.0][channel][window[2000.0]]) - np.mean(runs[-2000.0][channel][window[-2000.0]])) / 2

    k = hydraulic_stiffness()
    # the half difference of +-F cancels gravity and the quadratic term of the pressure law; what is left,
    # the cubic term and the angle's change, is below 1e-6 of the deflection; 1e-4 leaves room for the
    # mean of the residual vibration over a window that is not a whole number of periods
    assert half_difference("cylinder.stroke") == pytest.approx(2000.0 / (k * math.cos(ALPHA)), rel=1e-4)
    assert half_difference("slider.x") == pytest.approx(2000.0 / (k * math.cos(ALPHA) ** 2), rel=1e-4)


def test_ideal_pins_share_the_weight_as_the_statics_says():
    doc = rig.document(ideal=True)
    doc["forces"]["input"]["force"][0] = "0 N"
    results = from_document(doc).simulate(0.3, method="dopri5", rtol=1e-8, atol=1e-11, output_step=1e-3)
    a_z, b_z = weight_shares()
    # reactions on the second bodies (ground, slider): the pins push them down by the shares
    assert results["base.fz"][-1] == pytest.approx(-a_z, rel=1e-6)
    assert results["rod_end.fz"][-1] == pytest.approx(-b_z, rel=1e-6)
    assert abs(results["base.fx"][-1]) < 1e-6 * a_z


# --- with the clearance joints (the model file as it is) ---------------------------------------------------

SETTLE_END = 0.4  # s: the journals' drop into contact under gravity has died out (restitution 0.9, friction)


@pytest.fixture(scope="module")
def settled():
    """The rig under gravity alone, run until the journals rest on their bores."""
    doc = rig.document()
    doc["forces"]["input"]["force"][0] = "0 N"
    return from_document(doc).simulate(SETTLE_END, method="dopri5", rtol=1e-7, atol=1e-10, output_step=1e-3)


def test_resting_journals_carry_the_weight_shares_of_the_statics(settled):
    assert settled.error is None
    a_z, b_z = weight_shares()
    # the total force on each journal (the ground's pin, the slider's pin), global z: the same shares as the
    # ideal pins; the journals rest within c = 0.5 mm of the centre, which moves the lever arms by at most
    # c / L = 5e-4 of the pin distance
    assert settled["base.fz"][-1] == pytest.approx(-a_z, rel=1e-3)
    assert settled["rod_end.fz"][-1] == pytest.approx(-b_z, rel=1e-3)
    for joint in rig.JOINTS:
        # the bore hangs on its pin: the pin touches the bore's top (bearing y is up, square to the axis)
        e_x, e_y = settled[f"{joint}.e_m_x"][-1], settled[f"{joint}.e_m_y"][-1]
        assert np.hypot(e_x, e_y) == pytest.approx(0.5e-3, rel=2e-2)
        assert e_y > 0.99 * np.hypot(e_x, e_y)
        assert settled[f"{joint}.mode"][-1] == 3  # sustained contact


def test_mode_fractions_are_fractions_of_the_run(settled):
    for joint in rig.JOINTS:
        fractions = rig_fractions(settled, joint)
        assert set(fractions) == {"free", "impact", "sliding", "sustained", "axial"}
        assert sum(fractions[k] for k in ("free", "impact", "sliding", "sustained")) == pytest.approx(1.0, abs=1e-12)
        assert 0.0 <= fractions["axial"] <= 1.0
        # it starts free (centred), drops into contact and ends resting on the bore
        assert fractions["free"] > 0 and fractions["sustained"] > 0


def rig_fractions(results, joint: str) -> dict:
    from jointplay.plots_spatial_clearance import mode_fractions

    return mode_fractions(results, joint)


def test_example_script_runs_short_and_writes_its_figures(tmp_path):
    results = rig.main(["--t-end", "0.15", "--out", str(tmp_path)])
    assert results.error is None
    names = {p.name for p in tmp_path.iterdir()}
    for joint in rig.JOINTS:
        assert {f"paper002_rig_trajectories_{joint}.png", f"paper002_rig_point_cloud_{joint}.png"} <= names
    assert {"paper002_rig_histories.png", "paper002_rig_mode_fractions.png", "paper002_cylinder_rig.nc"} <= names
    assert all((tmp_path / name).stat().st_size > 10_000 for name in names if name.endswith(".png"))


def test_plot_functions_draw_titled_figures_from_a_run(settled, tmp_path):
    from jointplay import plots
    from jointplay import plots_spatial_clearance as psc

    assert psc.spatial_clearance_joints(settled) == list(rig.JOINTS)
    assert psc.radial_clearance(settled, "base") == pytest.approx(0.5e-3)
    assert psc.axial_limits(settled, "rod_end") == pytest.approx((-0.25, 0.25))  # mm, half of 0.5 mm
    figures = {"trajectories": psc.trajectories_figure(settled, "base", (0.1, SETTLE_END), "a note"),
               "point_cloud": psc.point_cloud_figure(settled, "rod_end"),
               "fractions": psc.mode_fractions_figure(settled)}
    for what, fig in figures.items():
        title = fig._suptitle.get_text().replace("\n", " ")
        assert "paper002_cylinder_rig" in title, what
    assert "journal axis in the bore of base" in figures["trajectories"]._suptitle.get_text().replace("\n", " ")
    assert "a note" in figures["trajectories"]._suptitle.get_text().replace("\n", " ")
    # the trajectory panels hold the three sections, the clearance circle in each
    assert [ax.get_title() for ax in figures["trajectories"].axes] == [s[0] for s in psc.SECTIONS]
    # the fraction bars: one bar per mode and joint, at the tracked fractions
    heights = [p.get_height() for p in figures["fractions"].axes[0].patches]
    expected = [rig_fractions(settled, j)[k] for j in rig.JOINTS for k in psc.FRACTION_KEYS]
    assert heights == pytest.approx(expected)
    # jointplay plot draws the trajectories and the point cloud of every spatial clearance joint
    paths = {p.name for p in plots.standard_figures(settled, tmp_path)}
    for joint in rig.JOINTS:
        assert {f"trajectories_{joint}.png", f"point_cloud_{joint}.png"} <= paths


def test_study_runs_on_a_two_by_two_table(tmp_path):
    import paper002_cylinder_study as study

    ds = study.run_study(0.1, forces=(1000.0, 3000.0), frequencies=(10.0, 20.0), clearances=(0.5e-3,))
    assert ds.sizes["case"] == 4 and list(ds["status"].values) == ["done"] * 4
    for joint in rig.JOINTS:
        total = sum(ds[f"{joint}_{mode}"].values for mode in ("free", "impact", "sliding", "sustained"))
        assert total == pytest.approx(np.ones(4), abs=1e-12)
    # the paper's series through 3 kN, 10 Hz, 0.5 mm: two cases each for force and frequency, one for clearance
    assert [len(study.series(ds, f)) for f in ("force", "frequency", "clearance")] == [2, 2, 1]
    assert len(study.trends(ds)) == 3 * 6
    paths = study.write_outputs(ds, tmp_path, 0.1)
    assert all(p.exists() for p in paths)
    assert "| force | 1 kN | series" in (tmp_path / "paper002_study_trends.md").read_text()
