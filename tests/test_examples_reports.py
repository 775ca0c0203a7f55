"""`jointplay animate` and `jointplay report` on every example, as a user runs them: each example's model runs
briefly and is saved, then both commands work from the results file alone (through the command line); each
study example runs a few short cases and `jointplay report STUDY_DIR` reports it. The checks: the video has
its frames and size, the report embeds its animation and plots, and its summary is the run's."""

from __future__ import annotations

import importlib
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

import jointplay as jp
from jointplay.cli import app

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
#: Frames of the videos here: 3 frames of 320 x 240 (small and quick; the commands' defaults are larger).
VIDEO = ["--fps", "3", "--duration", "1 s", "--size", "320x240"]
REPORT_VIDEO = ["--video-fps", "3", "--video-duration", "1 s", "--video-size", "320x240"]
#: Simulated time of each example's short run [s] (long enough to move, short enough to be quick).
SHORT_RUNS = {"spin_up_beam": 0.05, "paper002_cylinder_rig": 0.004, "hydraulic_boom": 0.2,
              "double_parallelogram": 0.2, "parallelogram_four_bar": 0.2, "spatial_slider_crank": 0.2}
#: Models only the Python examples build, and how.
PYTHON_MODELS = {"four_bar_flexible_coupler": lambda m: m.build_model(True),
                 "flores_flexible_rod": lambda m: m.build_model(elements=2),
                 "paper000_joint_models": lambda m: m.build_model()}
#: Python examples that are studies (reported below) of the models above or of a TOML example.
STUDIES = {"paper001_parametric_study", "paper002_cylinder_study"}


def example_models():
    models = [pytest.param(path.stem, id=path.stem) for path in sorted(EXAMPLES.glob("*.toml"))]
    return models + [pytest.param(name, id=name) for name in PYTHON_MODELS]


def invoke(*args: str):
    return CliRunner().invoke(app, [str(a) for a in args], env={"COLUMNS": "200"})


def test_every_example_is_animated_and_reported_here():
    tomls = {p.stem for p in EXAMPLES.glob("*.toml")}
    assert {p.stem for p in EXAMPLES.glob("*.py")} - tomls == set(PYTHON_MODELS) | STUDIES
    assert {p.stem for p in (EXAMPLES / "studies").glob("*.toml")} == set(STUDY_FILES)


def short_run(name: str, path: Path) -> jp.Results:
    """The example's model run briefly with its own options (the implicit method for beams), saved at ``path``."""
    if name in PYTHON_MODELS:
        model = PYTHON_MODELS[name](importlib.import_module(name))
        options = {}
    else:
        model = jp.load(EXAMPLES / f"{name}.toml")
        options = {k: v for k, v in model.simulation.items() if k not in ("t_end", "output_step")}
    if model.to_spec().get("beams"):  # they vibrate fast: the implicit method
        options = {"method": "bdf", "max_order": 2, "stabilization": "baumgarte"}
    end = SHORT_RUNS.get(name, 0.002)
    return model.simulate(end, output_step=end / 10, output_file=path, **options)


@pytest.mark.parametrize("name", example_models())
def test_both_commands_work_on_the_examples_results_file(name, tmp_path):
    import imageio_ffmpeg

    results = short_run(name, tmp_path / f"{name}.nc")
    spatial = bool(results.spec.get("spatial_bodies"))
    projection = ["--projection", "iso"] if spatial else []
    done = invoke("animate", tmp_path / f"{name}.nc", "-o", tmp_path / f"{name}.mp4", *VIDEO, *projection, "-q")
    assert done.exit_code == 0, done.output
    reader = imageio_ffmpeg.read_frames(str(tmp_path / f"{name}.mp4"))
    assert next(reader)["size"] == (320, 240) and len(list(reader)) == 3

    done = invoke("report", tmp_path / f"{name}.nc", "-o", tmp_path / f"{name}.html", *REPORT_VIDEO)
    assert done.exit_code == 0, done.output
    html = (tmp_path / f"{name}.html").read_text(encoding="utf-8")
    assert html.count("<video ") == 1 and "No animation" not in html
    assert html.count('class="plotly-graph-div"') >= 1
    assert f"Model &#39;{results.spec['name']}&#39;" in html or results.spec["name"] in html
    # the summary's time span is the run's
    assert re.search(r"<td>time span</td>\s*<td[^>]*>0 to " + re.escape(f"{results.time[-1]:.6g}"), html)


# studies -------------------------------------------------------------------------------------------------

#: Each study file of examples/studies, shrunk: (replacements in its text) so that it runs a few short cases
#: (the breaker's responses need its 30 ms: 3 cases of it instead of 25).
STUDY_FILES = {
    "flores_clearance_friction": {'t_end = "24 ms"': 't_end = "2 ms"', "levels = 5": "levels = 2"},
    "paper003_breaker": {'kind = "central_composite"\nface = "faced"\ncenter = 1':
                         'kind = "latin_hypercube"\nsamples = 3'},
}


@pytest.mark.parametrize("name", list(STUDY_FILES))
def test_a_study_file_example_is_reported(name, tmp_path):
    text = (EXAMPLES / "studies" / f"{name}.toml").read_text()
    for old, new in STUDY_FILES[name].items():
        assert old in text, f"{name}: the shrinking replacement {old!r} no longer applies"
        text = text.replace(old, new)
    text = re.sub(r'model = "\.\./', f'model = "{(EXAMPLES).as_posix()}/', text)
    study_file = tmp_path / f"{name}.toml"
    study_file.write_text(text)
    done = invoke("sweep", study_file, "-o", tmp_path / "study", "--workers", "1")
    assert done.exit_code == 0, done.output
    check_study_report(tmp_path / "study")


def check_study_report(folder: Path) -> None:
    import xarray as xr

    done = invoke("report", folder)
    assert done.exit_code == 0, done.output
    html = (folder / "report.html").read_text(encoding="utf-8")
    with xr.open_dataset(folder / "study.nc") as dataset:
        cases = dataset.sizes["case"]
    assert "Design table" in html and html.count('class="plotly-graph-div"') >= 1
    start = html.index("<h2>Design table</h2>")
    design = html[start:html.index("<h2>", start + 1)]
    assert design.count("<tr>") == cases + 1  # a header and a row per case


@pytest.mark.parametrize("name, build", [
    ("paper001_parametric_study", lambda m: m.build_study(revolutions=0.02)),
    ("paper002_cylinder_study", lambda m: m.build_study(t_end=0.002, forces=[1000.0], frequencies=[5.0],
                                                        clearances=[0.2e-3, 1e-3])),
])
def test_a_python_study_example_is_reported(name, build, tmp_path):
    build(importlib.import_module(name)).run(tmp_path / "study")
    check_study_report(tmp_path / "study")
