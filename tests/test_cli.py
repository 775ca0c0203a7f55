"""The jointplay command: help texts, exit codes, messages, and run -> plot -> compare end to end."""

from __future__ import annotations

from pathlib import Path

import pytest
import xarray as xr
from typer.testing import CliRunner

from jointplay.cli import app

ROOT = Path(__file__).resolve().parents[1]
DRY = str(ROOT / "examples" / "flores_slider_crank_dry.toml")
IDEAL = str(ROOT / "examples" / "flores_slider_crank_ideal.toml")
SHORT = ["--t-end", "3 ms"]


def invoke(*args: str):
    return CliRunner().invoke(app, list(args))


def no_traceback(result) -> bool:
    return "Traceback" not in result.output and result.exception is None or isinstance(result.exception, SystemExit)


@pytest.mark.parametrize("command", [[], ["check"], ["run"], ["plot"], ["compare"]])
def test_help_texts_stand_on_their_own(command):
    result = invoke(*command, "--help")
    assert result.exit_code == 0
    assert "Usage: jointplay" in result.output
    assert len(result.output.split()) > 25  # more than a bare usage line


def test_main_help_lists_commands_examples_and_exit_codes():
    text = invoke("--help").output
    for word in ("check", "run", "plot", "compare", "--set", "Exit codes"):
        assert word in text


def test_check_prints_the_assembled_mechanism():
    result = invoke("check", DRY)
    assert result.exit_code == 0
    for word in ("crank", "rod", "slider", "revolute joint", "translational joint", "angle driver",
                 "clearance joints", "degrees of freedom 2"):
        assert word in result.output
    assert result.output.rstrip().endswith("ok")


def test_check_says_which_formulation_the_simulation_uses():
    # the dry joint cuts the slider-crank's loop: a tree of ideal joints, two joint coordinates
    output = " ".join(invoke("check", DRY).output.split())
    assert "formulation (auto): joint coordinates, 2 of them" in output
    # the reason is the core's rule: a small tree (docs/theory/planar-formulation.md, "Choosing the formulation")
    assert "because the ideal joints form a tree of 2 joint coordinates (at most 8)" in output
    # the ideal slider-crank is a closed loop of ideal joints
    output = " ".join(invoke("check", IDEAL).output.split())
    assert "formulation (auto): absolute coordinates with constraints, because joint" in output
    assert "closes a loop of ideal joints" in output


def test_check_prints_a_hydraulic_cylinder_and_counts_its_states():
    result = invoke("check", str(ROOT / "examples" / "hydraulic_boom.toml"))
    assert result.exit_code == 0
    output = " ".join(result.output.replace("\u2502", " ").split())  # rich wraps long cells between borders
    for words in ("lift", "hydraulic_cylinder", "ground.C -> boom.R", "A1 31.17 cm^2", "A2 21.55 cm^2",
                  "stroke 100 of 500 mm", "18.12 / 10 bar", "LuGre seal", "cap and rod inflow",
                  "coordinates 3, element states 3", "degrees of freedom 1"):
        assert words in output, words


def test_plot_draws_the_pressures_and_stroke_of_a_hydraulic_cylinder(tmp_path):
    results = tmp_path / "boom.nc"
    assert invoke("run", str(ROOT / "examples" / "hydraulic_boom.toml"), "-o", str(results),
                  "--t-end", "1 s").exit_code == 0
    from jointplay import open_results
    from jointplay.plots import default_channels

    assert default_channels(open_results(results))[:3] == ["lift.p_cap", "lift.p_rod", "lift.stroke"]
    assert invoke("plot", str(results), "-o", str(tmp_path / "figures")).exit_code == 0
    assert (tmp_path / "figures" / "time_histories.png").stat().st_size > 10_000


def test_check_reports_each_problem_and_exits_2():
    result = invoke("check", DRY, "--set", "joints.B.clearance=-0.1 mm", "--set", "bodies.crank.mass=5 mm")
    assert result.exit_code == 2
    assert "2 problems" in result.stderr
    assert "joints.B.clearance: must be > 0, got -0.1 mm" in result.stderr
    assert "bodies.crank.mass: must be a mass (e.g. \"0.3 kg\"), got '5 mm', which is a length" in result.stderr
    assert no_traceback(result)


@pytest.mark.parametrize("args, message", [
    (["run", "missing.toml"], "missing.toml: no such file"),
    (["run", DRY, "--set", "joints.B.clearence=0.1 mm"], 'joints.B.clearence: unknown key (did you mean "clearance"?)'),
    (["run", DRY, "--t-end", "5 kg"], "--t-end: must be a time (e.g. \"24 ms\"), got '5 kg', which is a mass"),
    (["run", DRY, "--t-end", "-1 ms"], "--t-end: must be > 0, got -1 ms"),
    (["run", DRY, "--set", "simulation.rtol=-1"], "simulation.rtol: must be > 0, got -1"),
    (["run", DRY, "-o", "no/such/folder/x.nc"], "no folder no/such/folder"),
    (["plot", "missing.nc"], "missing.nc: no such results file"),
    (["plot", DRY], "not a jointplay results file"),
])
def test_bad_input_exits_2_with_a_message(args, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = invoke(*args)
    assert result.exit_code == 2, result.output
    assert message in result.stderr
    assert no_traceback(result)


def test_run_without_an_end_time_exits_2(tmp_path):
    model = tmp_path / "no_end.toml"
    model.write_text(Path(DRY).read_text().replace('t_end = "24 ms"', ""))
    result = invoke("run", str(model), "-o", str(tmp_path / "x.nc"))
    assert result.exit_code == 2
    assert "simulation.t_end: missing; set it in the [simulation] table or give --t-end" in result.stderr


def test_unknown_option_exits_2():
    assert invoke("run", DRY, "--frobnicate").exit_code == 2


def test_simulation_failure_exits_1_and_keeps_what_was_computed(tmp_path):
    out = tmp_path / "failed.nc"
    result = invoke("run", DRY, "-o", str(out), "--set", 'joints.B.max_penetration="1 um"')
    assert result.exit_code == 1
    assert "simulation failed (ExcessivePenetration) at t = " in result.stderr
    assert " in B: penetration " in result.stderr
    partial = tmp_path / "failed.partial.nc"  # a failed run never takes the name of a complete one
    assert f"saved to {partial}" in result.stderr
    assert not out.exists()
    with xr.open_dataset(partial, engine="scipy") as ds:
        assert ds.attrs["completed"] == 0
        assert ds.sizes["time"] > 1
        assert "exceeds the bound" in ds.attrs["error"]


def test_run_plot_compare_end_to_end(tmp_path):
    dry, ideal = tmp_path / "dry.nc", tmp_path / "ideal.nc"
    result = invoke("run", DRY, "-o", str(dry), *SHORT)
    assert result.exit_code == 0, result.output
    for word in ("acceleration of point slider.B", "B.fn", "impacts", "time in contact", "accepted steps",
                 "wall time"):
        assert word in result.output
    assert invoke("run", IDEAL, "-o", str(ideal), *SHORT, "--quiet").exit_code == 0
    with xr.open_dataset(dry, engine="scipy") as ds:
        assert ds["slider.ax"].attrs["units"] == "m/s^2"
        assert ds["B.fn"].attrs["units"] == "N"
        assert ds["B.fn"].attrs["description"] == "normal contact force"
        assert ds["time"].values[-1] == pytest.approx(3e-3)
        assert 'clearance = "0.0005 m"' in ds.attrs["model_toml"]
        assert ds.attrs["statistics_accepted_steps"] > 0

    figures = tmp_path / "figures"
    result = invoke("plot", str(dry), "-o", str(figures), "--format", "svg")
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in figures.iterdir()) == ["contact_force_B.svg", "orbit_B.svg", "time_histories.svg"]

    result = invoke("plot", str(dry), "-o", str(tmp_path / "one"), "-c", "slider.ax", "-c", "B.penetration")
    assert result.exit_code == 0
    assert (tmp_path / "one" / "time_histories.png").stat().st_size > 1000

    comparison = tmp_path / "comparison"
    result = invoke("compare", str(ideal), str(dry), "-o", str(comparison), "-c", "slider.ax", "-c", "B.f",
                    "-l", "ideal", "-l", "dry")
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in comparison.iterdir()) == ["compare_B_f.png", "compare_slider_ax.png"]
    assert "ideal" in result.output and "dry" in result.output


def test_plot_and_compare_name_an_unknown_channel(tmp_path):
    out = tmp_path / "r.nc"
    assert invoke("run", IDEAL, "-o", str(out), *SHORT, "-q").exit_code == 0
    result = invoke("plot", str(out), "-c", "slider.axx", "-o", str(tmp_path / "f"))
    assert result.exit_code == 2
    assert "no channel 'slider.axx'; did you mean slider.ax" in result.stderr
    result = invoke("compare", str(out), str(out), "-c", "sldier.ax", "-o", str(tmp_path / "c"))
    assert result.exit_code == 2
    result = invoke("plot", str(out), "--format", "gif")
    assert result.exit_code == 2
    assert "--format: must be one of png, svg, got 'gif'" in result.stderr


def test_override_changes_the_run(tmp_path):
    a, b = tmp_path / "a.nc", tmp_path / "b.nc"
    assert invoke("run", DRY, "-o", str(a), *SHORT, "-q").exit_code == 0
    assert invoke("run", DRY, "-o", str(b), *SHORT, "-q", "--set", "joints.B.clearance=0.1mm").exit_code == 0
    with xr.open_dataset(a, engine="scipy") as da, xr.open_dataset(b, engine="scipy") as db:
        assert 'clearance = "0.0001 m"' in db.attrs["model_toml"]
        assert float(abs(db["B.ex"]).max()) < float(abs(da["B.ex"]).max())


def test_run_with_the_implicit_method_reports_its_jacobians(tmp_path):
    lubricated = str(ROOT / "examples" / "flores_slider_crank_lubricated.toml")
    result = invoke("run", lubricated, *SHORT, "--set", "simulation.method=bdf", "-o", str(tmp_path / "r.nc"))
    assert result.exit_code == 0, result.output
    assert "jacobian evaluations" in result.output and "factorizations" in result.output
    dry = invoke("run", DRY, *SHORT, "-o", str(tmp_path / "d.nc"))
    assert dry.exit_code == 0 and "jacobian evaluations" not in dry.output


@pytest.mark.parametrize("module", ["jointplay", "jointplay.cli"])
def test_python_dash_m_knows_the_commands_registered_in_their_own_files(module):
    import subprocess
    import sys

    for command in ("report", "animate", "static", "sweep", "bearing"):
        done = subprocess.run([sys.executable, "-m", module, command, "--help"], capture_output=True, text=True,
                              timeout=120)
        assert done.returncode == 0 and f"Usage: python -m {module} {command}" in done.stdout, done.stderr
