"""Animations: what a frame draws equals the channels at its time (rigid bodies, beam nodes, modal-body
nodes, journal centres, spatial bodies and spatial clearance joints, each recomputed here from the
channels and the model), the files read back with their frame count and size, every example animates (tests/test_examples_reports.py),
and `jointplay animate` refuses bad input with one line and exit code 2."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import jointplay as jp
from jointplay.animation import animate, video_bytes
from jointplay.animation.render import Renderer
from jointplay.animation.scene import Scene, round_125
from jointplay.cli import app
from jointplay.errors import ModelError

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
SMALL = (320, 240)


def at(results, name: str, t: float) -> float:
    """The channel at time t, linear between samples (as the animation states it samples)."""
    return float(np.interp(t, results.time, results[name]))


def drawn(renderer: Renderer, artist: str) -> np.ndarray:
    """The (n, 2) data of a line artist, in metres."""
    x, y = renderer.artists[artist].get_data()
    return np.column_stack([x, y]) / renderer.per_metre


def planar_pose(results, body: str, t: float, local: np.ndarray) -> np.ndarray:
    angle = at(results, f"{body}.angle", t)
    c, s = np.cos(angle), np.sin(angle)
    return np.array([at(results, f"{body}.x", t), at(results, f"{body}.y", t)]) + local @ np.array([[c, s], [-s, c]])


@pytest.fixture(scope="module")
def dry():
    """The Flores slider-crank with its dry clearance joint, 4 ms."""
    return jp.load(EXAMPLES / "flores_slider_crank_dry.toml").simulate(0.004, output_step=1e-4)


@pytest.fixture(scope="module")
def dry_file(dry, tmp_path_factory):
    path = tmp_path_factory.mktemp("dry") / "dry.nc"
    dry.save(path)
    return path


# a frame's geometry is the channels' ------------------------------------------

def test_a_rigid_body_is_drawn_through_its_points_at_its_pose(dry):
    scene = Scene(dry, fps=10, duration=1.3)  # 13 frames, times between the samples
    renderer = Renderer(scene, SMALL)
    k = 7
    renderer.draw(k)
    crank = next(b for b in dry.spec["bodies"] if b["name"] == "crank")
    local = np.array([p["position"] for p in crank["points"]])
    expected = planar_pose(dry, "crank", scene.times[k], local)
    assert scene.times[k] not in dry.time
    np.testing.assert_allclose(drawn(renderer, "body:crank"), expected, rtol=0, atol=1e-12)


def test_the_journal_centre_is_the_bearing_point_plus_the_magnified_eccentricity(dry):
    scene = Scene(dry, fps=10, duration=1.3, clearance_scale=20.0, force_scale=2e-6)
    renderer = Renderer(scene, SMALL)
    k = next(k for k, t in enumerate(scene.times) if k > 0 and at(dry, "B.f", t) > 100.0)  # in contact
    renderer.draw(k)
    t = scene.times[k]
    bearing = np.array([at(dry, "slider.x", t), at(dry, "slider.y", t)])  # slider.B is the slider's centre
    e = np.array([at(dry, "B.ex", t), at(dry, "B.ey", t)])
    journal, bore = renderer.artists["journal:B"], renderer.artists["bore:B"]
    np.testing.assert_allclose(np.array(journal.center) / renderer.per_metre, bearing + 20.0 * e, rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.array(bore.center) / renderer.per_metre, bearing, rtol=0, atol=1e-12)
    # drawn gap = scale x clearance; 10 mm of gap is more than half the 10 mm bore: the bore drawn at twice the gap
    assert (bore.radius - journal.radius) / renderer.per_metre == pytest.approx(20.0 * 0.5e-3, rel=1e-12)
    assert bore.radius / renderer.per_metre == pytest.approx(0.02, rel=1e-12)
    # the force on the journal ends at the contact point on the drawn bore, its length scale x |f|
    f = np.array([at(dry, "B.fx", t), at(dry, "B.fy", t)])
    start, tip = (np.array(p) / renderer.per_metre for p in renderer.artists["arrow:B"]._posA_posB)
    np.testing.assert_allclose(tip, bearing + 0.02 * e / np.linalg.norm(e), rtol=0, atol=1e-12)
    np.testing.assert_allclose(tip - start, 2e-6 * f, rtol=0, atol=1e-12)


def test_a_one_point_body_is_a_square_around_its_point_turned_with_it(dry):
    scene = Scene(dry, fps=10, duration=1.0)
    k = 4
    square = scene.frame(k).bodies["slider"]
    t = scene.times[k]
    corners = square[:-1]
    np.testing.assert_allclose(square[0], square[-1])  # closed
    np.testing.assert_allclose(corners.mean(axis=0), [at(dry, "slider.x", t), at(dry, "slider.y", t)], atol=1e-15)
    sides = np.linalg.norm(np.diff(square, axis=0), axis=1)
    np.testing.assert_allclose(sides, scene.scales["block"], rtol=1e-12)
    turn = np.arctan2(*(corners[1] - corners[0])[::-1])
    assert turn == pytest.approx(at(dry, "slider.angle", t), abs=1e-12)


def test_outlines_are_the_points_or_their_closed_convex_hull():
    from jointplay.animation.frame import convex_outline

    two = np.array([[1.0, 0.0], [0.0, 0.0]])
    np.testing.assert_array_equal(convex_outline(two), two)  # in the given order
    collinear = np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]])
    np.testing.assert_array_equal(convex_outline(collinear), [[0.0, 0.0], [2.0, 0.0]])
    square_and_inside = np.array([[0.0, 0.0], [1.0, 1.0], [0.5, 0.5], [1.0, 0.0], [0.0, 1.0]])
    np.testing.assert_array_equal(convex_outline(square_and_inside),
                                  [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]])
    assert len(convex_outline(np.zeros((3, 2)))) == 1  # coinciding points: drawn as a square instead


def test_the_bore_keeps_its_radius_while_the_magnified_gap_is_at_most_half_of_it(dry):
    scene = Scene(dry, fps=2, duration=1.0, clearance_scale=10.0)
    g = scene.frame(1)
    assert g.bores["B"][1] == 0.01 and g.journals["B"][1] == pytest.approx(0.005, rel=1e-12)


def test_beam_nodes_at_scale_one_are_their_channels_and_magnified_off_the_chord():
    import flores_flexible_rod as example

    results = example.build_model(elements=2).simulate(0.002, method="bdf", max_order=2, stabilization="baumgarte",
                                                       rtol=1e-6, atol=1e-9, max_step=1e-4, output_step=1e-4)
    k = 5
    true = Renderer(Scene(results, fps=5, duration=1.5, deformation_scale=1.0), SMALL)
    true.draw(k)
    t = true.scene.times[k]
    nodes = np.array([[at(results, f"rod.node{i}_x", t), at(results, f"rod.node{i}_y", t)] for i in range(5)])
    np.testing.assert_allclose(drawn(true, "beam:rod"), nodes, rtol=0, atol=1e-12)
    # magnified 50 times: the first node stays, each node's distance from the chord grows 50 times
    big = Renderer(Scene(results, fps=5, duration=1.5, deformation_scale=50.0), SMALL)
    big.draw(k)
    magnified = drawn(big, "beam:rod")
    chord = (nodes[-1] - nodes[0]) / np.linalg.norm(nodes[-1] - nodes[0])

    def off_chord(points):  # signed distance from the chord's line [m]
        relative = points - nodes[0]
        return chord[0] * relative[:, 1] - chord[1] * relative[:, 0]

    np.testing.assert_allclose(magnified[0], nodes[0], rtol=0, atol=1e-12)
    assert np.max(np.abs(off_chord(nodes))) > 1e-7  # the rod does bend
    np.testing.assert_allclose(off_chord(magnified), 50.0 * off_chord(nodes), rtol=1e-9, atol=1e-15)


def test_modal_body_nodes_at_scale_one_follow_the_files_geometry_and_modal_amplitudes():
    import four_bar_flexible_coupler as example

    results = example.build_model(True).simulate(0.03, output_step=1e-3)
    scene = Scene(results, fps=10, duration=1.0, deformation_scale=1.0)
    renderer = Renderer(scene, SMALL)
    k = 8
    renderer.draw(k)
    t = scene.times[k]
    geometry = results.geometry["modal_bodies"]["coupler"]
    shapes = np.array(geometry["shapes"])
    eta = np.array([at(results, f"coupler.eta{i + 1}", t) for i in range(shapes.shape[2])])
    assert np.max(np.abs(shapes @ eta)) > 1e-9  # the coupler is deformed
    local = np.array(geometry["nodes"]) + np.einsum("ndm,m->nd", shapes, eta)
    expected = planar_pose(results, "coupler", t, local)
    np.testing.assert_allclose(drawn(renderer, "mesh:coupler"), expected, rtol=0, atol=1e-12)
    segments = renderer.artists["mesh_lines:coupler"].get_segments()
    assert len(segments) == len(geometry["edges"])
    i, j = geometry["edges"][0]
    np.testing.assert_allclose(np.array(segments[0]) / renderer.per_metre, expected[[i, j]], rtol=0, atol=1e-12)


def test_a_hand_made_modal_body_is_drawn_at_numbers_worked_by_hand():
    from jointplay.results import Results

    # a plate of two nodes, (0, 0) and (1, 0) m in its frame; one mode moving node 1 along its y by 1 m per unit
    names = ["plate.x", "plate.y", "plate.angle", "plate.eta1"]
    values = np.array([[1.0, 1.0], [2.0, 2.0], [np.pi / 2, np.pi / 2], [0.1, 0.1]])
    results = Results([0.0, 1.0], names, ["m", "m", "rad", "1"], [""] * 4, values, {}, {},
                      spec={"name": "plate", "ground_points": [], "bodies": [], "beams": [], "joints": [],
                            "forces": [], "modal_bodies": [{"name": "plate", "interface": [], "points": []}]})
    results.geometry = {"modal_bodies": {"plate": {"nodes": [[0.0, 0.0], [1.0, 0.0]],
                                                   "shapes": [[[0.0], [0.0]], [[0.0], [1.0]]], "edges": [[0, 1]]}}}
    scene = Scene(results, fps=2, duration=1.0, deformation_scale=3.0)
    # node 1: (1, 0) + 3 x 0.1 x (0, 1) = (1, 0.3) in the frame; turned a quarter: (-0.3, 1); moved by (1, 2)
    np.testing.assert_allclose(scene.frame(1).meshes["plate"], [[1.0, 2.0], [0.7, 3.0]], rtol=0, atol=1e-15)
    assert "deformation x 3" in " ".join(scene.notes())
    # automatic: 5 % of the 1 m the plate spans is less than its 0.1 m of deformation, which is not shrunk
    assert Scene(results, fps=2, duration=1.0).scales["deformation"] == 1.0


def test_results_without_the_mesh_of_a_modal_body_are_refused_by_name():
    import four_bar_flexible_coupler as example

    results = example.build_model(True).simulate(0.002, output_step=1e-3)
    results.geometry = {"modal_bodies": {}}  # as in a file written before the meshes were saved
    with pytest.raises(ModelError, match="modal_bodies.coupler: the results carry no mesh of it"):
        Scene(results)


def test_spatial_bodies_are_posed_by_their_quaternions_and_projected():
    from scipy.spatial.transform import Rotation

    results = jp.load(EXAMPLES / "spatial_slider_crank.toml").simulate(0.3, output_step=0.01)
    for projection, columns in (("xz", [0, 2]), ("yz", [1, 2])):
        scene = Scene(results, fps=10, duration=1.0, projection=projection)
        renderer = Renderer(scene, SMALL)
        k = 6
        renderer.draw(k)
        t = scene.times[k]
        rod = next(b for b in results.spec["spatial_bodies"] if b["name"] == "rod")
        q = np.array([at(results, f"rod.q{c}", t) for c in "xyzw"])
        r = np.array([at(results, f"rod.{c}", t) for c in "xyz"])
        points = r + Rotation.from_quat(q / np.linalg.norm(q)).apply([p["position"] for p in rod["points"]])
        np.testing.assert_allclose(drawn(renderer, "body:rod"), points[:, columns], rtol=0, atol=1e-12)


def test_the_isometric_view_looks_down_the_diagonal_with_z_up():
    from jointplay.animation.spatial import PROJECTIONS

    plane = PROJECTIONS["iso"]
    np.testing.assert_allclose(plane @ [1.0, 1.0, 1.0], [0.0, 0.0], atol=1e-15)  # the view direction
    np.testing.assert_allclose(plane @ plane.T, np.eye(2), atol=1e-15)  # lengths across the view kept
    assert (plane @ [0.0, 0.0, 1.0])[1] > 0 and (plane @ [0.0, 0.0, 1.0])[0] == 0  # z points up


def test_a_spatial_clearance_joint_shows_the_journal_axis_offset_in_the_bearing_frame():
    from scipy.spatial.transform import Rotation

    import paper002_cylinder_rig as example

    results = example.build_model().simulate(0.004, output_step=2e-4)
    scene = Scene(results, fps=10, duration=1.0, projection="xz", clearance_scale=30.0)
    renderer = Renderer(scene, SMALL)
    k = 7
    renderer.draw(k)
    t = scene.times[k]
    joint = next(j for j in results.spec["spatial_clearance_joints"] if j["name"] == "rod_end")
    body, point = joint["bearing"].split(".")
    marker = next(p for p in next(b for b in results.spec["spatial_bodies"] if b["name"] == body)["points"]
                  if p["name"] == point)
    q = np.array([at(results, f"{body}.q{c}", t) for c in "xyzw"])
    rotation = Rotation.from_quat(q / np.linalg.norm(q)).as_matrix() @ np.array(marker["axes"])
    centre = np.array([at(results, f"{body}.{c}", t) for c in "xyz"]) + \
        Rotation.from_quat(q / np.linalg.norm(q)).apply(marker["position"])
    ends = []
    for s, rim in ((-0.5, "a"), (0.5, "b")):
        offset = np.array([at(results, f"rod_end.e_{rim}_x", t), at(results, f"rod_end.e_{rim}_y", t), 0.0])
        ends.append(centre + rotation @ (np.array([0.0, 0.0, s * joint["bearing_length"]]) + 30.0 * offset))
    np.testing.assert_allclose(drawn(renderer, "journal_axis:rod_end"), np.array(ends)[:, [0, 2]], rtol=0, atol=1e-12)
    # the circles at both rims: the bore's about the rims' centres, the journal's about the axis' ends; the
    # largest drawn radius of a circle seen in the xz plane is its radius times the largest singular value of
    # the plane's view of the bore's cross-section
    rims = [centre + rotation @ np.array([0.0, 0.0, s * joint["bearing_length"]]) for s in (-0.5, 0.5)]
    seen = np.linalg.svd(rotation[[0, 2], :2], compute_uv=False)[0]
    radii = {}
    for kind, centres in (("bore_rims", rims), ("journal_rims", ends)):
        rings = np.split(drawn(renderer, f"{kind}:rod_end"), [49, 50])  # two closed rings of 49 points, a NaN row
        for ring, expected in zip((rings[0], rings[2]), centres, strict=True):
            np.testing.assert_allclose(ring[:-1].mean(axis=0), expected[[0, 2]], rtol=0, atol=1e-12)
            radii.setdefault(kind, []).append(np.max(np.linalg.norm(ring - expected[[0, 2]], axis=1)))
    gap = np.array(radii["bore_rims"]) - np.array(radii["journal_rims"])
    # (48 points a ring: the sampled largest radius is within 1 - cos(pi / 48) = 2.1e-3 of the ellipse's)
    np.testing.assert_allclose(gap, 30.0 * joint["clearance"] * seen, rtol=2.2e-3)


# scales --------------------------------------------------------------------

def test_round_numbers_are_one_two_or_five_times_a_power_of_ten():
    assert [round_125(v) for v in (6.0, 0.013, 3.0, 140.0, 7.5)] == [5.0, 0.01, 2.0, 100.0, 10.0]


def test_automatic_scales_are_round_near_their_targets_and_stated(dry):
    scene = Scene(dry, fps=10, duration=2.0)
    # bore 10 mm, clearance 0.5 mm: 30 % of the bore radius is 6 clearances, rounded to 5
    assert scene.scales["clearance"] == 5.0
    longest = scene.scales["force"] * scene.largest_force()
    assert 0.15 * scene.size / 1.6 < longest < 0.15 * scene.size * 1.6
    notes = " ".join(scene.notes())
    assert "clearance x 5" in notes
    newtons, unit, millimetres = re.search(r"force ([\d.]+) (k?N) per ([\d.]+) mm", notes).groups()
    per_newton = float(millimetres) * 1e-3 / (float(newtons) * (1e3 if unit == "kN" else 1.0))
    assert per_newton == pytest.approx(scene.scales["force"], rel=1e-12)
    assert "4 ms of run in 20 frames at 10 fps (slowed x 500)" in notes


def test_default_duration_slows_a_short_run_to_five_seconds(dry):
    assert Scene(dry).times.size == 125  # 25 fps x 5 s


def test_a_long_channel_is_drawn_as_an_envelope_that_keeps_every_peak():
    from jointplay.animation.render import envelope

    t = np.linspace(0.0, 1.0, 100_001)
    values = np.sin(200 * np.pi * t)
    values[12_345], values[67_890] = 7.0, -3.0  # two spikes one sample wide
    drawn_t, drawn_values = envelope(t, values, columns=500)
    assert drawn_t.size == 1000 and np.all(np.diff(drawn_t) > 0)
    assert 7.0 in drawn_values and -3.0 in drawn_values
    assert envelope(t[:900], values[:900], columns=500)[0].size == 900  # short: every sample


# files ---------------------------------------------------------------------

def test_mp4_webm_and_gif_have_their_frames_and_size_and_png_is_one_still(dry, tmp_path):
    import imageio_ffmpeg
    from PIL import Image

    mp4 = dry.animate(tmp_path / "run.mp4", fps=8, duration=1.0, size=(322, 241))  # rounded up to 322 x 242
    reader = imageio_ffmpeg.read_frames(str(mp4))
    meta = next(reader)
    frames = list(reader)
    assert meta["size"] == (322, 242) and meta["codec"] == "h264" and len(frames) == 8
    assert meta["fps"] == 8
    webm = animate(dry, tmp_path / "run.webm", fps=4, duration=1.0, size=SMALL)
    reader = imageio_ffmpeg.read_frames(str(webm))
    meta = next(reader)
    assert meta["codec"] == "vp9" and meta["size"] == SMALL and len(list(reader)) == 4
    gif = animate(dry, tmp_path / "run.gif", fps=5, duration=1.0, size=SMALL)
    with Image.open(gif) as image:
        assert image.size == SMALL and image.n_frames == 5 and image.info["duration"] == 200
    png = animate(dry, tmp_path / "still.png", size=SMALL)
    with Image.open(png) as image:
        assert image.size == SMALL and getattr(image, "n_frames", 1) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.gif", "run.mp4", "run.webm", "still.png"]


def test_video_bytes_are_the_file_for_embedding(dry):
    data = video_bytes(dry, mime="video/mp4", fps=2, duration=1.0, size=SMALL)
    assert data[4:8] == b"ftyp"
    assert video_bytes(dry, mime="image/png", size=SMALL)[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(ModelError, match="mime: must be one of"):
        video_bytes(dry, mime="video/avi")


def test_bad_options_are_model_errors_naming_each(dry, tmp_path):
    with pytest.raises(ModelError) as caught:
        animate(dry, tmp_path / "x.mp4", fps=-1, clearance_scale=0, projection="iso", channels=["B.fz"])
    assert [p.location for p in caught.value.problems] == ["fps", "clearance_scale", "projection"]
    with pytest.raises(ModelError, match="did you mean"):
        animate(dry, tmp_path / "x.mp4", channels=["B.fz"])
    with pytest.raises(ModelError, match="must lie within the run"):
        animate(dry, tmp_path / "x.mp4", start=1.0)
    with pytest.raises(ModelError, match="unknown animation format '.avi'"):
        animate(dry, tmp_path / "x.avi")
    assert not list(tmp_path.iterdir())


def test_the_encoded_video_shows_the_crank_where_its_channels_put_it(dry, tmp_path):
    """Past the artists: in each decoded frame of the MP4, the pixel where the crank's centre of mass falls (from
    its channels, through the axes' data-to-pixel transform) has the bodies' colour, and the pixel well off the
    mechanism, the background's."""
    import imageio_ffmpeg

    path = animate(dry, tmp_path / "crank.mp4", fps=5, duration=1.0, size=SMALL)
    reader = imageio_ffmpeg.read_frames(str(path))
    width, height = next(reader)["size"]
    frames = [np.frombuffer(f, np.uint8).reshape(height, width, 3) for f in reader]
    renderer = Renderer(Scene(dry, fps=5, duration=1.0), SMALL)
    body = 0.85 * np.array([31, 119, 180]) + 0.15 * 255  # tab:blue at alpha 0.85 on white
    assert len(frames) == 5
    for k, image in enumerate(frames):
        renderer.draw(k)
        renderer.canvas.draw()
        t = renderer.scene.times[k]
        centre = np.array([at(dry, "crank.x", t), at(dry, "crank.y", t)]) * renderer.per_metre
        column, row = renderer.ax.transData.transform(centre)
        np.testing.assert_allclose(image[int(round(height - row)), int(round(column))], body, atol=30)
        corner = renderer.ax.transAxes.transform((0.02, 0.98))  # the mechanism's axes, top left: empty
        np.testing.assert_allclose(image[int(round(height - corner[1])), int(round(corner[0]))], 255, atol=12)


def test_requests_that_would_run_for_hours_or_exhaust_memory_are_refused_at_once(dry, tmp_path):
    from jointplay.animation.scene import MAX_FRAMES

    with pytest.raises(ModelError, match=f"3600000 frames; at most {MAX_FRAMES}") as caught:
        animate(dry, tmp_path / "x.mp4", fps=1000, duration=3600.0)
    assert [p.location for p in caught.value.problems] == ["duration"]
    with pytest.raises(ModelError, match="GIF of 25000 frames of 1920 x 1080 is held in memory") as caught:
        animate(dry, tmp_path / "x.gif", fps=25, duration=1000.0, size=(1920, 1080))
    with pytest.raises(ModelError, match="at most 7680 x 4320 pixels, got 100000 x 1000"):
        animate(dry, tmp_path / "x.mp4", size=(100_000, 1000))
    assert not list(tmp_path.iterdir())


# the command ---------------------------------------------------------------------

def invoke(*args: str):
    return CliRunner().invoke(app, list(args), env={"COLUMNS": "200"})


def test_animate_command_writes_the_file(dry_file, tmp_path):
    out = tmp_path / "dry.gif"
    result = invoke("animate", str(dry_file), "-o", str(out), "--fps", "4", "--duration", "1 s", "--size", "320x240",
                    "--channel", "B.fn", "--channel", "crank.angle", "--force-scale", "1 mm/N", "--start", "1 ms")
    assert result.exit_code == 0, result.output
    assert f"wrote {out}" in result.output
    from PIL import Image

    with Image.open(out) as image:
        assert image.size == (320, 240) and image.n_frames == 4


@pytest.mark.parametrize("args, message", [
    (("missing.nc", "-o", "{tmp}/x.mp4"), "error: missing.nc: no such results file"),
    (("{dry}", "-o", "{tmp}/x.avi"), "error: -o {tmp}/x.avi: unknown animation format '.avi'; give one of .mp4, "
                                     ".webm, .gif, .png"),
    (("{dry}", "-o", "{tmp}/x.mp4", "-c", "B.fz"), "error: --channel: no channel 'B.fz'; did you mean B.f, B.fy, "
                                                   "B.fx?"),
    (("{dry}", "-o", "{tmp}/x.mp4", "--projection", "top"), "error: --projection: must be one of xy, xz, yz, iso, "
                                                            "got 'top'"),
    (("{dry}", "-o", "{tmp}/x.mp4", "--size", "big"), "error: --size: must be WIDTHxHEIGHT in pixels, e.g. "
                                                      "1280x720, got 'big'"),
    (("{dry}", "-o", "{tmp}/x.mp4", "--start", "2 kg"), "error: --start: must be a time (e.g. \"24 ms\"), got "
                                                        "'2 kg', which is a mass"),
])
def test_animate_command_refuses_bad_input_in_one_line(args, message, dry_file, tmp_path):
    fill = {"dry": str(dry_file), "tmp": str(tmp_path)}
    result = invoke("animate", *(a.format(**fill) for a in args))
    assert result.exit_code == 2
    assert result.output.strip() == message.format(**fill)
    assert not list(tmp_path.iterdir())
