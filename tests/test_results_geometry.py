"""A results file carries what a drawing of the mechanism needs: each modal body's mesh and mode shapes, with
which its nodes are placed from the channels alone. Checked against what the joints and a spring see of the
same nodes, not against the geometry's own code."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples"))
import four_bar_flexible_coupler as four_bar  # noqa: E402
from test_modal_body import cantilever  # noqa: E402


def node_positions(results, body: str) -> np.ndarray:
    """Every node of a modal body at every sample [m], (samples, nodes, 2), from the saved geometry and the
    body's channels: r + A(angle) (node + shapes @ eta)."""
    mesh = results.geometry["modal_bodies"][body]
    nodes, shapes = np.array(mesh["nodes"]), np.array(mesh["shapes"])  # (n, 2), (n, 2, modes)
    eta = np.array([results[f"{body}.eta{k + 1}"] for k in range(shapes.shape[2])])  # (modes, samples)
    local = nodes[None, :, :] + np.einsum("nij,js->sni", shapes, eta)
    c, s = np.cos(results[f"{body}.angle"])[:, None], np.sin(results[f"{body}.angle"])[:, None]
    x = results[f"{body}.x"][:, None] + c * local[..., 0] - s * local[..., 1]
    y = results[f"{body}.y"][:, None] + s * local[..., 0] + c * local[..., 1]
    return np.stack([x, y], axis=-1)


def rigid_point(results, body: str, local: tuple[float, float]) -> np.ndarray:
    angle = results[f"{body}.angle"]
    return np.column_stack([results[f"{body}.x"] + np.cos(angle) * local[0] - np.sin(angle) * local[1],
                            results[f"{body}.y"] + np.sin(angle) * local[0] + np.cos(angle) * local[1]])


@pytest.fixture(scope="module")
def coupler_run(tmp_path_factory):
    path = tmp_path_factory.mktemp("geometry") / "four_bar.nc"
    four_bar.build_model(True).simulate(0.03, method="dopri5", rtol=1e-8, atol=1e-11, output_step=1e-3,
                                        output_file=path)
    return jp.open_results(path)


def test_the_file_places_a_modal_bodys_pins_where_the_rigid_links_hold_them(coupler_run):
    nodes = node_positions(coupler_run, "coupler")
    # pin B (node 6) on the rocker's end, pin A (node 0) on the crank's: the revolute joints' equations
    rocker_b = rigid_point(coupler_run, "rocker", (four_bar.ROCKER / 2, 0.0))
    crank_a = rigid_point(coupler_run, "crank", (four_bar.CRANK / 2, 0.0))
    assert np.max(np.abs(nodes[:, four_bar.B_NODE] - rocker_b)) < 1e-9
    assert np.max(np.abs(nodes[:, four_bar.A_NODE] - crank_a)) < 1e-9
    # the modes are excited (the crank is spun up), so the check sees them
    eta = np.array([coupler_run[f"coupler.eta{k}"] for k in range(1, 8)])
    assert np.max(np.abs(eta)) > 0


def test_the_mesh_lines_are_the_frames_elements(coupler_run):
    # the elements of the coupler's stiffness file, read here with scipy: node pairs with a coupling block
    import scipy.io

    stiffness = scipy.io.mmread(four_bar.FILES["stiffness"]).tocoo()
    elements = {(min(i, j) // 3, max(i, j) // 3) for i, j in zip(stiffness.row, stiffness.col) if i // 3 != j // 3}
    edges = {tuple(e) for e in coupler_run.geometry["modal_bodies"]["coupler"]["edges"]}
    assert edges == elements
    # a base of six elements from node 0 to node 6, and two sides of two each through the apex, node 8
    assert len(edges) == 10 and {(k, k + 1) for k in range(6)} <= edges
    assert sum(four_bar.C_NODE in e for e in edges) == 2


def test_a_modal_cantilever_tip_drawn_from_the_file_is_where_the_spring_sees_it(tmp_path):
    path = tmp_path / "cantilever.nc"
    cantilever().simulate(2.0, output_step=0.1, output_file=path)
    results = jp.open_results(path)
    mesh = results.geometry["modal_bodies"]["arm"]
    assert [tuple(e) for e in mesh["edges"]] == [(k, k + 1) for k in range(len(mesh["nodes"]) - 1)]
    tip = node_positions(results, "arm")[:, -1]
    # the probe spring runs from the ground point (1, -1) to the tip: its length is the distance
    assert np.max(np.abs(np.hypot(tip[:, 0] - 1.0, tip[:, 1] + 1.0) - results["probe.length"])) < 1e-12
    assert results["probe.length"][-1] < 1.0 - 1e-3  # the tip has gone down


def test_a_model_without_modal_bodies_carries_an_empty_geometry(tmp_path):
    model = jp.load(Path(__file__).resolve().parents[1] / "examples" / "flores_slider_crank_dry.toml")
    results = model.simulate(1e-3)
    assert results.geometry == {"modal_bodies": {}}
    assert jp.open_results(results.save(tmp_path / "r.nc")).geometry == {"modal_bodies": {}}
    assert math.isfinite(results.time[-1])
