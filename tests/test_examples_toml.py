"""Every example model file loads, checks and runs; the Python example writes its figures."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
#: End times [s] of examples whose own run is too long for the suite: paper 002's rig runs 10 s, as the
#: paper, in minutes (its physics: tests/test_paper002_rig.py).
SHORT_RUNS = {"paper002_cylinder_rig": 0.05}
#: Freedoms of the undriven examples that have more than one: paper 002's rig, the slider along its guide,
#: the rod along the barrel and the barrel's six coordinates, held by the contacts of its two spatial
#: clearance joints only.
UNDRIVEN_FREEDOMS = {"paper002_cylinder_rig": 8}


def test_the_three_model_files_are_there():
    names = {p.name for p in EXAMPLES}
    assert {"flores_slider_crank_dry.toml", "flores_slider_crank_ideal.toml",
            "paper001_slider_crank_dry.toml"} <= names


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_example_loads_checks_and_runs(path, tmp_path):
    model = jp.load(path)
    info = model.check()
    n_clearance = len(info["clearance_joints"])
    elastic = sum(b["coordinates"][1] - 3 for b in info["bodies"] if b["kind"] == "beam")
    if any(e["kind"].endswith("Driver") for e in info["elements"]):
        # driven mechanisms: only the journals and the beams' deformations move freely
        assert info["degrees_of_freedom"] == 2 * n_clearance + elastic
    else:
        # the four-bars: one freedom, however many equations
        assert info["degrees_of_freedom"] == UNDRIVEN_FREEDOMS.get(path.stem, 1)
    options = dict(model.simulation)
    t_end = SHORT_RUNS.get(path.stem, options.pop("t_end"))
    results = model.simulate(t_end, **options)
    assert results.error is None
    assert results.time[-1] == pytest.approx(t_end)
    for name in results.channels:
        assert np.all(np.isfinite(results[name])), name
    results.save(tmp_path / "r.nc")
    again = jp.open_results(tmp_path / "r.nc")
    assert again.channels == results.channels
    first = results.channels[0]
    assert np.array_equal(again[first], results[first])
    assert again.unit(first) == results.unit(first)
    assert again.statistics == results.statistics
    assert again.summary()["peaks"] == results.summary()["peaks"]
    assert jp.loads(again.model_toml()).to_spec() == model.to_spec()


def test_clearance_raises_the_peak_slider_acceleration_over_the_ideal_joint():
    peaks = {}
    for variant in ("ideal", "dry"):
        model = jp.load(ROOT / "examples" / f"flores_slider_crank_{variant}.toml")
        options = dict(model.simulation)
        peaks[variant] = np.max(np.abs(model.simulate(options.pop("t_end"), **options)["slider.ax"]))
    # Flores & Ambrosio report clearance peaks an order of magnitude above the ideal mechanism's
    assert peaks["dry"] > 5 * peaks["ideal"]


def test_python_example_writes_its_figures_animation_and_report(tmp_path):
    spec = importlib.util.spec_from_file_location("flores_dry", ROOT / "examples" / "flores_slider_crank_dry.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.main(["--out", str(tmp_path), "--revolutions", "0.5"])
    written = sorted(p.name for p in tmp_path.iterdir())
    assert written == ["contact_force_B.png", "flores_dry.html", "flores_dry.mp4", "flores_dry.nc", "orbit_B.png",
                       "time_histories.png"]
