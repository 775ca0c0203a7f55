"""The study layer end to end: cases built from factors by their --set paths, run serially, on local
processes and on a Dask LocalCluster (identical results), stored case by case (a killed study resumes
to the same bytes), failures isolated, bad study files located, and the optimum verified by a run.

The model is a ball thrown up under gravity (tests/data/study/throw.toml): its height is known in
closed form, y(t) = v t - g t^2 / 2, so every response is checked against it."""

from __future__ import annotations

import math
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp
from jointplay.study import Study, load_study, open_study
from jointplay.study.factors import continuous, discrete
from jointplay.units import to_si

DATA = Path(__file__).parent / "data" / "study"
EXAMPLES = Path(__file__).parent.parent / "examples"
T_END = 0.2  # [s], the model file's
#: The `jointplay` script of this environment.
CLI = [str(Path(sys.executable).with_name("jointplay"))]


def height(v, g, t):
    """Height of the ball at t [s] thrown at v [m/s] under gravity g [m/s^2, > 0]."""
    return v * t - 0.5 * g * t**2


def throw_study(**kw) -> Study:
    return load_study(DATA / "throw_study.toml") if not kw else Study(DATA / "throw.toml", **kw)


def test_cases_match_the_closed_form():
    ds = throw_study().run()
    assert ds.sizes["case"] == 9 and list(ds["factor"].values) == ["speed", "g"]
    v, g = ds["speed"].values, -ds["g"].values
    np.testing.assert_allclose(ds["final_height"].values, height(v, g, T_END), rtol=0, atol=1e-9)
    apex = np.minimum(v / g, T_END)
    # "max" is taken on the 1 ms samples: below the apex by at most g dt^2 / 8 (the apex half a step away)
    shortfall = height(v, g, apex) - ds["height"].values
    assert np.all(shortfall > -1e-9) and np.all(shortfall <= g * 1e-3**2 / 8 + 1e-9)
    assert ds["speed"].attrs["units"] == "m/s" and ds["speed"].attrs["path"] == "bodies.ball.velocity.1"
    assert ds["final_height"].attrs["units"] == "m"
    assert set(ds["speed"].values) == {1.0, 2.0, 3.0}
    assert list(ds["g_label"].values[:3]) == ["-9 m/s^2", "-10 m/s^2", "-11 m/s^2"]
    assert (ds["status"].values == "done").all() and (ds["error"].values == "").all()
    # the kept channel on the study's grid, at every 10 ms
    np.testing.assert_allclose(ds["time"].values, np.arange(21) * 0.01, atol=1e-15)
    expected = height(v[:, None], g[:, None], ds["time"].values[None, :])
    np.testing.assert_allclose(ds["ball.y"].values, expected, atol=1e-9)


def test_overrides_carry_every_bit():
    """A factor's value travels as SI text and comes back the same float."""
    f = continuous("c", "joints.B.clearance", "1 um", "1 mm", "f")
    for coded in np.linspace(-1, 1, 37):
        value = f.value(coded)
        assert to_si(f.override(value), "length") == value


def test_local_processes_and_dask_give_the_serial_bytes(tmp_path):
    study = throw_study()
    study.run(tmp_path / "serial")
    study.run(tmp_path / "processes", workers=2)
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        study.run(tmp_path / "dask", client=client)
    serial = (tmp_path / "serial" / "study.nc").read_bytes()
    assert (tmp_path / "processes" / "study.nc").read_bytes() == serial
    assert (tmp_path / "dask" / "study.nc").read_bytes() == serial


def test_a_failing_case_is_recorded_and_the_others_go_on():
    study = Study(DATA / "throw.toml", factors=[{"name": "mass", "path": "bodies.ball.mass",
                                                  "levels": ["1 kg", "-1 kg", "2 kg"]}],
                  responses=[{"name": "final_height", "kind": "final", "channel": "ball.y"}])
    ds = study.run()
    assert list(ds["status"].values) == ["done", "failed", "done"]
    assert "bodies.ball.mass" in str(ds["error"].values[1]) and "> 0" in str(ds["error"].values[1])
    assert math.isnan(ds["final_height"].values[1])
    np.testing.assert_allclose(ds["final_height"].values[[0, 2]], height(2.0, 9.81, T_END), atol=1e-9)


def test_a_study_of_a_python_model_equals_the_study_of_its_file():
    kw = dict(factors=[{"name": "speed", "path": "bodies.ball.velocity.1", "range": ["1 m/s", "3 m/s"]}],
              design={"kind": "full_factorial", "levels": 4},
              responses=[{"name": "final_height", "kind": "final", "channel": "ball.y"}])
    from_file = Study(DATA / "throw.toml", **kw).run()
    from_model = Study(jp.load(DATA / "throw.toml"), t_end="0.2 s", **kw).run()
    np.testing.assert_array_equal(from_model["final_height"].values, from_file["final_height"].values)


def test_a_stopped_study_resumes_to_the_same_result(tmp_path):
    """Stopped after 4 of 9 cases (an interrupt raised from the progress callback), then resumed."""
    whole = throw_study().run(tmp_path / "whole")

    def stop_after_four(done, total):
        if done == 4:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        throw_study().run(tmp_path / "cut", progress=stop_after_four)
    assert len(list((tmp_path / "cut" / "cases").glob("*.npz"))) == 4
    with pytest.raises(jp.ModelError, match="--resume"):
        throw_study().run(tmp_path / "cut")
    ran = []
    resumed = throw_study().run(tmp_path / "cut", resume=True, progress=lambda done, total: ran.append(done))
    assert ran == [5, 6, 7, 8, 9]
    assert resumed.identical(whole)
    assert (tmp_path / "cut" / "study.nc").read_bytes() == (tmp_path / "whole" / "study.nc").read_bytes()


def test_a_killed_sweep_resumes_to_the_same_bytes(tmp_path):
    """The CLI killed (SIGKILL) in the middle of a sweep of the dry slider-crank, then run with --resume."""
    study_file = tmp_path / "sweep.toml"
    study_file.write_text(f"""
[study]
model = "{(EXAMPLES / 'flores_slider_crank_dry.toml').as_posix()}"
t_end = "4 ms"
[[study.factors]]
name = "clearance"
path = "joints.B.clearance"
range = ["0.1 mm", "0.5 mm"]
[study.design]
kind = "full_factorial"
levels = 24
[[study.responses]]
name = "peak_force"
kind = "peak"
channel = "B.f"
""")
    cli = CLI
    whole = subprocess.run(cli + ["sweep", str(study_file), "-o", str(tmp_path / "whole"), "-q", "--workers", "2"],
                           capture_output=True, text=True, timeout=300)
    assert whole.returncode == 0, whole.stderr
    cut = tmp_path / "cut"
    process = subprocess.Popen(cli + ["sweep", str(study_file), "-o", str(cut), "-q", "-w", "1"], stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 120
    while len(list((cut / "cases").glob("*.npz"))) < 3 and time.monotonic() < deadline and process.poll() is None:
        time.sleep(0.01)
    os.kill(process.pid, signal.SIGKILL)
    process.wait()
    done = len(list((cut / "cases").glob("*.npz")))
    assert 3 <= done < 24, f"the kill came too late to test a resume ({done} cases done)"
    resumed = subprocess.run(cli + ["sweep", str(study_file), "-o", str(cut), "--resume", "-q", "-w", "2"],
                             capture_output=True, text=True, timeout=300)
    assert resumed.returncode == 0, resumed.stderr
    assert (cut / "study.nc").read_bytes() == (tmp_path / "whole" / "study.nc").read_bytes()
    assert open_study(cut)["peak_force"].notnull().all()


def test_bad_study_files_get_one_located_message_per_problem(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("""
[study]
model = "nowhere.toml"
colour = "red"
""")
    with pytest.raises(jp.ModelError) as caught:
        load_study(bad)
    found = {p.location for p in caught.value.problems}
    assert found == {"study.model", "study.colour"}
    bad.write_text(f"""
[study]
model = "{(DATA / 'throw.toml').as_posix()}"
[[study.factors]]
path = "bodies.ball.velocity.1"
range = ["3 m/s", "1 m/s"]
[[study.factors]]
path = "bodies.ball.mass"
range = ["1 kg", "2 m"]
[[study.factors]]
path = "bodies.ball.inertia"
levels = ["1 kg m^2"]
range = ["1 kg m^2", "2 kg m^2"]
""")
    with pytest.raises(jp.ModelError) as caught:
        load_study(bad)
    messages = {p.location: p.message for p in caught.value.problems}
    assert "low < high" in messages["study.factors[0].range"] and "3 m/s" in messages["study.factors[0].range"]
    assert "one kind" in messages["study.factors[1].range"]
    assert "exactly one way" in messages["study.factors[2]"]
    result = subprocess.run(CLI + ["sweep", str(bad), "-o", str(tmp_path / "o")],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 2 and "study.factors[1].range" in result.stderr and "Traceback" not in result.stderr


def test_a_folder_holding_another_study_is_refused(tmp_path):
    throw_study().run(tmp_path / "s")
    other = Study(DATA / "throw.toml", factors=[{"name": "m", "path": "bodies.ball.mass", "levels": ["1 kg"]}],
                  responses=[{"name": "final_height", "kind": "final", "channel": "ball.y"}])
    with pytest.raises(jp.ModelError, match="different study"):
        other.run(tmp_path / "s", resume=True)


def test_the_surface_optimum_is_verified_by_a_run():
    """final_height = v T - g T^2 / 2 is linear in both factors: its maximum is at the fastest throw and the
    weakest gravity, and a quadratic surface predicts the verifying run exactly."""
    from jointplay.study.optimize import optimize_surface, parse_objectives

    study = throw_study()
    ds = study.run()
    objectives = parse_objectives(study.optimize_spec["objectives"], ["height", "final_height"])
    found = optimize_surface(study, ds, objectives)
    assert found.values["speed"] == pytest.approx(3.0, abs=1e-6)
    assert found.values["g"] == -9.0 and found.labels["g"] == "-9 m/s^2"
    assert found.verified["final_height"] == pytest.approx(height(3.0, 9.0, T_END), abs=1e-9)
    assert found.predicted["final_height"] == pytest.approx(found.verified["final_height"], abs=1e-9)


def test_the_simulator_optimum_finds_the_same_point():
    from jointplay.study.optimize import Objective, optimize_simulator

    study = Study(DATA / "throw.toml",
                  factors=[continuous("speed", "bodies.ball.velocity.1", "1 m/s", "3 m/s", "f"),
                           discrete("g", "model.gravity.1", ["-9 m/s^2", "-11 m/s^2"], "f")],
                  responses=[{"name": "final_height", "kind": "final", "channel": "ball.y"}])
    found = optimize_simulator(study, [Objective("final_height", "maximize")], budget=40, seed=3)
    assert found.values["g"] == -9.0
    assert found.values["speed"] > 2.7
    assert found.verified["final_height"] == pytest.approx(height(found.values["speed"], 9.0, T_END), abs=1e-9)


def test_sweep_cli_prints_the_summary_and_writes_figures(tmp_path):
    result = subprocess.run(CLI + ["sweep", str(DATA / "throw_study.toml"), "-o",
                             str(tmp_path / "o"), "-q"], capture_output=True, text=True, timeout=300,
                            env={**os.environ, "COLUMNS": "160"})
    assert result.returncode == 0, result.stderr
    assert "9 cases done, 0 failed" in result.stdout
    assert "best cases: smallest height" in result.stdout and "R^2" in result.stdout
    assert (tmp_path / "o" / "figures" / "main_effects_height.png").stat().st_size > 1000
    result = subprocess.run(CLI + ["optimize", str(DATA / "throw_study.toml"), "-o",
                             str(tmp_path / "o"), "-q"], capture_output=True, text=True, timeout=300,
                            env={**os.environ, "COLUMNS": "160"})
    assert result.returncode == 0, result.stderr
    assert "the optimum verified by a run" in result.stdout
    assert (tmp_path / "o" / "optimum.json").exists()


def test_a_worker_that_dies_fails_its_own_case_only(tmp_path):
    """Throws slower than 1.3 m/s end below 0.07 m and end their worker process (os._exit): those cases fail
    with the reason, the others finish on the processes that replace it."""
    from study_helpers import CrashBelow

    study = Study(DATA / "throw.toml", factors=[{"name": "speed", "path": "bodies.ball.velocity.1",
                                                  "range": ["0.5 m/s", "3 m/s"]}],
                  design={"kind": "full_factorial", "levels": 8},
                  responses=[{"name": "final_height", "kind": "final", "channel": "ball.y"},
                             CrashBelow("ball.y", 0.1)])
    ds = study.run(tmp_path / "s", workers=2, batch_size=3)
    speed = ds["speed"].values
    crashed = height(speed, 9.81, T_END) < 0.1
    assert crashed.sum() == 3
    assert list(ds["status"].values) == ["failed" if c else "done" for c in crashed]
    assert all("WorkerLost" in str(e) for e in ds["error"].values[crashed])
    np.testing.assert_allclose(ds["final_height"].values[~crashed], height(speed[~crashed], 9.81, T_END), atol=1e-9)


def test_a_pareto_front_of_two_objectives_is_non_dominated_and_its_points_are_run(tmp_path):
    """A higher final height and a lower apex conflict (both grow with the throw speed): the front spans the
    speeds; its points are non-dominated (checked pair by pair here) and the verifying runs match the closed
    form."""
    from jointplay.study.optimize import Objective, front_optima, pareto_front
    from jointplay.study.summary import front_figure

    study = throw_study()
    ds = study.run()
    objectives = [Objective("final_height", "maximize"), Objective("height", "minimize")]
    points, values = pareto_front(study, ds, objectives, samples=512)
    signed = values * np.array([-1.0, 1.0])  # both minimised
    for k in range(len(signed)):
        dominated = np.all(signed <= signed[k], axis=1) & np.any(signed < signed[k], axis=1)
        assert not dominated.any()
    assert points[:, 0].min() < -0.9 and points[:, 0].max() > 0.9  # the speed spans its range on the front
    found = front_optima(study, points, objectives, ds)
    assert 1 <= len(found) <= 3
    for o in found:
        v, g = o.values["speed"], -o.values["g"]
        assert o.verified["final_height"] == pytest.approx(height(v, g, T_END), abs=1e-9)
    assert front_figure(values, objectives, found, ds, tmp_path / "front.png").stat().st_size > 1000


def test_run_options_of_a_study_file_are_located_in_it(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(f"""
[study]
model = "{(DATA / 'throw.toml').as_posix()}"
t_end = 0.2
[study.simulation]
method = "euler"
[[study.factors]]
path = "bodies.ball.mass"
range = ["1 kg", "2 kg"]
""")
    with pytest.raises(jp.ModelError) as caught:
        load_study(bad)
    found = {p.location: p.message for p in caught.value.problems}
    assert "needs a unit" in found["study.t_end"] and "euler" in found["study.simulation.method"]


def test_the_best_case_of_the_design_is_the_case_with_the_best_weighted_objective():
    from jointplay.study.optimize import Objective, best_case

    study = throw_study()
    ds = study.run()
    found = best_case(study, ds, [Objective("final_height", "maximize")])
    k = int(np.argmax(ds["final_height"].values))
    assert found.values == {"speed": float(ds["speed"].values[k]), "g": float(ds["g"].values[k])}
    assert found.verified["final_height"] == float(ds["final_height"].values[k]) and found.predicted == {}


def test_optuna_searches_the_simulator_too():
    pytest.importorskip("optuna", reason="the optuna extra is installed by make setup")
    from jointplay.study.optimize import Objective, optimize_simulator

    study = Study(DATA / "throw.toml",
                  factors=[continuous("speed", "bodies.ball.velocity.1", "1 m/s", "3 m/s", "f"),
                           discrete("g", "model.gravity.1", ["-9 m/s^2", "-11 m/s^2"], "f")],
                  responses=[{"name": "final_height", "kind": "final", "channel": "ball.y"}])
    found = optimize_simulator(study, [Objective("final_height", "maximize")], method="optuna", budget=30, seed=2)
    assert found.values["g"] == -9.0 and found.values["speed"] > 2.5
    assert found.verified["final_height"] == pytest.approx(height(found.values["speed"], 9.0, T_END), abs=1e-9)
    with pytest.raises(jp.ModelError, match="differential_evolution or optuna"):
        optimize_simulator(study, [Objective("final_height")], method="annealing")


def test_a_progress_bar_shows_the_cases_and_the_time_left(capsys):
    throw_study().run(progress=True)
    shown = capsys.readouterr().out
    assert "cases" in shown and "9/9" in shown


def test_a_scheduler_address_runs_the_cases_on_that_cluster_and_a_bad_one_is_named(tmp_path):
    distributed = pytest.importorskip("distributed")
    study = throw_study()
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        ds = study.run(tmp_path / "s", scheduler=cluster.scheduler_address)
    assert ds.identical(study.run())
    with pytest.raises(jp.ModelError, match="cannot reach a Dask scheduler"):
        study.run(scheduler="tcp://127.0.0.1:9")
