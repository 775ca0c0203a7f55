"""`jointplay run` output: CSV for .csv, refusal of unknown suffixes, the output budget, and a good
results file kept when a run stops early."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from jointplay.cli import app
from jointplay.results import open_results

DRY = Path(__file__).parent.parent / "examples" / "flores_slider_crank_dry.toml"


def invoke(*args):
    return CliRunner().invoke(app, [str(a) for a in args])


def test_run_writes_real_csv_for_a_csv_suffix(tmp_path):
    out = tmp_path / "results.csv"
    result = invoke("run", DRY, "-o", out, "--t-end", "1 ms", "-q")
    assert result.exit_code == 0, result.output
    assert not out.read_bytes().startswith(b"\x89HDF")
    header = out.read_text().splitlines()[0].split(",")
    assert header[:2] == ["time [s]", "crank.x [m]"] and "slider.ax [m/s^2]" in header
    table = np.loadtxt(out, delimiter=",", skiprows=1)
    assert table[-1, 0] == pytest.approx(1e-3, rel=1e-12)


@pytest.mark.parametrize("name", ["results.txt", "results", "results.NC.bak"])
def test_run_refuses_an_unknown_suffix_before_running(tmp_path, name):
    result = invoke("run", DRY, "-o", tmp_path / name, "--t-end", "1 ms")
    assert result.exit_code == 2
    suffix = repr(Path(name).suffix.lower()) if Path(name).suffix else "'(no suffix)'"
    assert f"-o {tmp_path / name}: unknown results format {suffix}: use .nc, .nc4 or .h5 for NetCDF, .csv for CSV" \
        in result.stderr.replace("\n", "")
    assert list(tmp_path.iterdir()) == []


def test_run_budget_option_refuses_a_grid_that_cannot_fit(tmp_path):
    result = invoke("run", DRY, "-o", tmp_path / "r.nc", "--max-output", "1 MB", "--set", 'simulation.output_step="1 us"')
    assert result.exit_code == 2
    assert "simulation.max_output_bytes: the run would write 24001 samples x 53 channels x 8 bytes = 9.7 MiB, " \
           "above max_output_bytes = 977 KiB" in result.stderr.replace("\n", "")
    bad = invoke("run", DRY, "-o", tmp_path / "r.nc", "--max-output", "a lot")
    assert bad.exit_code == 2
    assert "--max-output: must be a size such as" in bad.stderr


def test_run_whose_bounded_steps_cannot_fit_the_budget_is_refused_before_it_starts(tmp_path):
    # a sample at every step of at most 0.1 ms over 24 ms: at least 241 samples x 53 channels x 8 bytes
    result = invoke("run", DRY, "-o", tmp_path / "r.nc", "--max-output", "100 kB", "-q")
    assert result.exit_code == 2
    assert ("simulation.max_output_bytes: the run would write at least 241 samples (one at every step, each of at "
            "most 0.0001 s) x 53 channels x 8 bytes = 99.8 KiB, above max_output_bytes = 97.7 KiB") in \
        " ".join(result.stderr.split())
    assert list(tmp_path.iterdir()) == []


def test_run_stopped_by_the_budget_keeps_the_good_file(tmp_path):
    out = tmp_path / "r.nc"
    assert invoke("run", DRY, "-o", out, "--t-end", "1 ms", "-q").exit_code == 0
    before = out.read_bytes()
    # (steps of at most 0.1 ms over 24 ms: at least 241 samples, 102 kB, fit; the run's 1 800 steps do not)
    result = invoke("run", DRY, "-o", out, "--max-output", "200 kB", "-q")
    assert result.exit_code == 1
    assert "simulation failed (OutputBudgetExceeded)" in result.stderr
    assert f"saved to {tmp_path / 'r.partial.nc'} ({out} left as it was)" in result.stderr.replace("\n", "")
    assert out.read_bytes() == before
    assert open_results(tmp_path / "r.partial.nc").error["kind"] == "OutputBudgetExceeded"
