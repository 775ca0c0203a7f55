"""Where the commands write and what they read: a file where a folder is expected (and the other
way round), a folder that cannot be created, a body name that is not in the results. Each gets
one clear message and exit code 2, never a traceback."""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from jointplay.cli import app

ROOT = Path(__file__).resolve().parents[1]
DRY = str(ROOT / "examples" / "flores_slider_crank_dry.toml")
IDEAL = str(ROOT / "examples" / "flores_slider_crank_ideal.toml")


def invoke(*args: str):
    return CliRunner().invoke(app, list(args))


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """Two short results files: the dry and the ideal slider-crank."""
    folder = tmp_path_factory.mktemp("runs")
    paths = folder / "dry.nc", folder / "ideal.nc"
    for model, path in zip((DRY, IDEAL), paths):
        assert invoke("run", model, "-o", str(path), "--t-end", "2 ms", "--quiet").exit_code == 0
    return paths


def exits_2_with(result, message: str) -> None:
    assert result.exit_code == 2, result.output
    assert result.stderr.strip() == f"error: {message}"
    assert "Traceback" not in result.output and isinstance(result.exception, SystemExit)


def test_plot_into_an_existing_file_exits_2(runs, tmp_path):
    target = tmp_path / "figures.png"
    target.write_text("not a folder")
    exits_2_with(invoke("plot", str(runs[0]), "-o", str(target)),
                 f"-o {target}: is a file, not a folder (figures are written into a folder)")
    assert target.read_text() == "not a folder"


def test_plot_into_a_folder_below_a_file_exits_2(runs, tmp_path):
    (tmp_path / "file").write_text("")
    target = tmp_path / "file" / "figures"
    exits_2_with(invoke("plot", str(runs[0]), "-o", str(target)),
                 f"-o {target}: cannot create the folder (Not a directory)")


def test_compare_into_an_existing_file_exits_2(runs, tmp_path):
    target = tmp_path / "comparison"
    target.write_text("")
    exits_2_with(invoke("compare", *map(str, runs), "-o", str(target)),
                 f"-o {target}: is a file, not a folder (figures are written into a folder)")


def test_compare_with_a_misspelt_crank_exits_2_before_drawing(runs, tmp_path):
    target = tmp_path / "comparison"
    exits_2_with(invoke("compare", *map(str, runs), "--crank", "crnk", "-o", str(target)),
                 f"--crank: no body 'crnk' in {runs[0]} (bodies: crank, rod, slider)")
    assert not target.exists()


def test_compare_against_the_crank_angle_labels_and_draws_the_angle(runs, tmp_path):
    result = invoke("compare", *map(str, runs), "--crank", "crank", "-c", "slider.ax", "-o", str(tmp_path))
    assert result.exit_code == 0, result.output
    assert (tmp_path / "compare_slider_ax.png").stat().st_size > 1000


def test_compare_figures_refuses_a_crank_without_an_angle_channel(runs, tmp_path):
    from jointplay import open_results
    from jointplay.compare import compare_figures

    results = [open_results(p) for p in runs]
    with pytest.raises(ValueError, match=r"^crank: run 0 \(dry\) has no body 'crnk' \(no channel crnk.angle\)$"):
        compare_figures(results, ["dry", "ideal"], tmp_path, channels=["slider.ax"], crank="crnk")


def test_plot_with_a_misspelt_crank_exits_2(runs):
    exits_2_with(invoke("plot", str(runs[0]), "--crank", "crnk"),
                 f"--crank: no body 'crnk' in {runs[0]} (bodies: crank, rod, slider)")


def test_plot_of_a_folder_exits_2(tmp_path):
    exits_2_with(invoke("plot", str(tmp_path)), f"{tmp_path}: is a folder, not a results file")


def test_run_into_an_existing_folder_exits_2(tmp_path):
    exits_2_with(invoke("run", DRY, "-o", str(tmp_path), "--t-end", "1 ms", "--quiet"),
                 f"-o {tmp_path}: is a folder, not a results file (give a file name such as run.nc)")


def test_standard_figures_name_a_file_given_as_the_folder(runs, tmp_path):
    from jointplay import open_results
    from jointplay.plots import standard_figures

    target = tmp_path / "figures"
    target.write_text("")
    with pytest.raises(NotADirectoryError, match="figures is a file; figures are written into a folder"):
        standard_figures(open_results(runs[0]), target)


@pytest.mark.parametrize("option", ["--chart", "--pressure"])
def test_bearing_figure_onto_a_folder_exits_2(option, tmp_path):
    folder = tmp_path / "chart.png"
    folder.mkdir()
    extra = ["--radius", "10 mm", "--clearance", "0.02 mm", "--viscosity", "40 cP", "--speed", "3000 rpm"]
    exits_2_with(invoke("bearing", "--l-over-d", "1", "-e", "0.5", *extra, option, str(folder)),
                 f"{option}: {folder} is a folder, not a figure file")
