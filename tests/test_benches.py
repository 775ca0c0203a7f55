"""The benchmark scripts run (one repeat each, no exact Reynolds mode) and report
what docs/performance.md quotes. Timing is never asserted; only the structure
and the step counts, which do not depend on the machine."""

import importlib.util
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def load(name: str):
    spec = importlib.util.spec_from_file_location(name, ROOT / "benches" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_dry_benchmark_runs_engine_baseline_and_practical_limit(capsys):
    bench = load("bench_flores_dry")
    rows = bench.main(["--repeats", "1", "--markdown"])
    with_limit = importlib.util.find_spec("numba") is not None
    assert [r["name"] for r in rows] == ["jointplay dopri5", "jointplay adams", "jointplay dopri5, absolute coordinates",
                                         *([bench.LIMIT_NAME] if with_limit else []),
                                         "SciPy solve_ivp RK45 (baseline)"]
    assert all(r["steps"] > 100 and r["rhs"] > r["steps"] and r["impacts"] > 0 for r in rows)
    out = capsys.readouterr().out
    assert "| jointplay dopri5 |" in out
    if with_limit:
        assert all(r["vs_limit_cpu"].n == 1 for r in rows)
        assert f"| {bench.LIMIT_NAME} |" in out
        assert "goal (issue 10), dopri5 at most 2.5x the practical limit, CPU" in out
    else:
        assert all(r["vs_limit_cpu"] is None for r in rows)
        assert f"{bench.LIMIT_NAME}: skipped, numba is not installed (pip install numba)" in out


def test_dry_benchmark_runs_without_numba(capsys, monkeypatch):
    # numba is optional: without it the limit row is skipped and the rest still runs
    monkeypatch.setitem(sys.modules, "numba", None)  # import numba now raises ImportError
    monkeypatch.delitem(sys.modules, "limit_slider_crank", raising=False)
    bench = load("bench_flores_dry")
    assert bench.limit is None
    rows = bench.main(["--repeats", "1"])
    assert [r["name"] for r in rows] == ["jointplay dopri5", "jointplay adams", "jointplay dopri5, absolute coordinates",
                                         "SciPy solve_ivp RK45 (baseline)"]
    out = capsys.readouterr().out
    assert f"{bench.LIMIT_NAME}: skipped, numba is not installed (pip install numba)" in out
    assert "goal (issue 10), dopri5 at most 2.5x the practical limit: not measured" in out


def test_lubricated_benchmark_reports_rows_errors_and_targets(capsys):
    report = load("bench_flores_lubricated").main(["--repeats", "1", "--baseline-repeats", "1", "--no-exact"])
    names = [r["name"] for r in report["rows"]]
    assert names[0] == "jointplay dopri5, dry joint" and "SciPy solve_ivp RK45, closed form (baseline)" in names
    closed = {r["name"]: r for r in report["rows"]}
    implicit, explicit = closed["jointplay bdf, closed form (hamrock_long)"], closed["jointplay dopri5, closed form (hamrock_long)"]
    assert 5 * implicit["steps"] < explicit["steps"]  # the stiff film: the point of the implicit method
    assert [label for label, *_ in report["checks"]] == [
        "closed form within 2x of the dry case", "closed form >= 30x faster than the SciPy baseline",
        "fast mode within 3x of the closed form"]
    assert report["reference"]["film_min"] == pytest.approx(14.758e-6, rel=1e-3)
    assert "targets (issue 4)" in capsys.readouterr().out



def test_spin_up_beam_benchmark_quick_mode_reports_jointplay_and_exudyn_rows(capsys):
    # exudyn is optional (pip install exudyn): without it its rows are skipped with the reason
    bench = load("bench_spin_up_beam")
    report = bench.main(["--quick", "--markdown"])
    with_exudyn = importlib.util.find_spec("exudyn") is not None
    names = [r["name"] for r in report["rows"]]
    assert names == ["jointplay generalized-alpha, 2 linear elements", "jointplay NDF, 2 linear elements",
                     *(["Exudyn EigenSparse, 2 linear elements", "Exudyn EXUdense, 2 linear elements"]
                       if with_exudyn else [])]
    for r in report["rows"]:
        assert r["cpu"].n == 1 and r["wall"].n == 1
        assert 0 <= r["error"] < 1e-3  # both codes near the reference over the first second
    out = capsys.readouterr().out
    assert "| jointplay generalized-alpha, 2 linear elements |" in out
    if with_exudyn:
        assert "| Exudyn EigenSparse, 2 linear elements |" in out
        assert [(n, clock) for n, clock, _ in report["verdicts"]] == [(2, "cpu"), (2, "wall")]
        assert "goal, generalized-alpha faster than Exudyn, 2 elements, CPU time" in out
    else:
        assert "Exudyn rows: skipped, exudyn is not installed" in out


def test_spin_up_beam_benchmark_runs_without_exudyn(capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "exudyn", None)  # import exudyn now raises ImportError
    bench = load("bench_spin_up_beam")
    assert bench.exudyn is None
    report = bench.main(["--quick"])
    assert [r["name"] for r in report["rows"]] == ["jointplay generalized-alpha, 2 linear elements",
                                                   "jointplay NDF, 2 linear elements"]
    assert report["verdicts"] == []
    assert "Exudyn rows: skipped, exudyn is not installed" in capsys.readouterr().out


def test_scaling_benchmark_quick_mode_runs_every_series_and_fits_exponents(capsys):
    # exudyn is optional: without it the beam series has jointplay rows only
    bench = load("bench_scaling")
    report = bench.main(["--quick", "--markdown"])
    with_exudyn = importlib.util.find_spec("exudyn") is not None
    rows = {(r.series, r.size, r.variant): r for r in report["rows"]}
    beam_codes = ["absolute", *(["Exudyn"] if with_exudyn else [])]
    assert list(rows) == [
        *[("rigid_chain", n, f) for n in (2, 4) for f in ("joint_coordinates", "absolute")],
        *[("clearance_chain", k, f) for k in (1, 2) for f in ("joint_coordinates", "absolute")],
        *[("beam_mesh", n, code) for n in (2, 4) for code in beam_codes],
        ("modal_body", 2, "absolute"), ("modal_body", 4, "absolute"), ("breaker", 8, "absolute"),
        ("spatial_chain", 2, "absolute"), ("spatial_chain", 4, "absolute")]
    for r in report["rows"]:
        assert r.case.values("cpu") and r.evaluations() > 0
    # the rule of auto: a 4-bar chain in joint coordinates, bodies on clearance joints only in absolute ones
    assert rows[("rigid_chain", 4, "joint_coordinates")].chosen == "yes"
    assert rows[("clearance_chain", 2, "absolute")].chosen == "yes"
    assert rows[("clearance_chain", 2, "joint_coordinates")].chosen == "no"
    # the same model in both forms takes the same evaluations where neither has constraints to solve
    assert rows[("clearance_chain", 2, "joint_coordinates")].evaluations() == rows[("clearance_chain", 2, "absolute")].evaluations()
    # the beam rows stay near the reference (mm-level peak deflections of about 0.5 m)
    assert all(0 <= rows[("beam_mesh", n, code)].tip_error() < 1e-3 for n in (2, 4) for code in beam_codes)
    assert [(s, v) for s, v, *_ in report["exponents"]] == [
        ("rigid_chain", "joint_coordinates"), ("rigid_chain", "absolute"), ("clearance_chain", "joint_coordinates"),
        ("clearance_chain", "absolute"), *[("beam_mesh", code) for code in beam_codes], ("modal_body", "absolute"),
        ("breaker", "absolute"), ("spatial_chain", "absolute")]
    out = capsys.readouterr().out
    assert "| rigid_chain | 4 | joint_coordinates |" in out
    assert ("Exudyn / jointplay CPU time" in out) == with_exudyn
    if not with_exudyn:
        assert "Exudyn rows: skipped, exudyn is not installed" in out


def test_spatial_benchmark_quick_mode_matches_accuracy_and_reports_ratios_and_scaling(capsys):
    # exudyn is optional: without it only jointplay is calibrated and no ratio is formed
    bench = load("bench_spatial")
    report = bench.main(["--quick", "--markdown"])
    with_exudyn = importlib.util.find_spec("exudyn") is not None
    codes = ["jointplay", *(["Exudyn"] if with_exudyn else [])]
    assert [c.name for c in report["comparisons"]] == ["slider-crank", "spatial chain of 2 bars"]
    for c in report["comparisons"]:
        assert list(c.cases) == codes
        # each timed rung is within the stated tolerance of its reference, the rung before it was not
        for code in codes:
            assert 0 <= c.errors[code] <= c.tolerance
            ladder = [err for name, _, err in c.ladder if name == code]
            assert ladder[-1] == c.errors[code] and all(err > c.tolerance for err in ladder[:-1])
            assert c.cases[code].values("cpu") and c.cases[code].values("wall")
    assert [(name, clock) for name, clock, _ in report["verdicts"]] == (
        [(c.name, clock) for c in report["comparisons"] for clock in ("cpu", "wall")] if with_exudyn else [])
    rows = [(r.series, r.size, r.variant) for r in report["scaling"]["rows"]]
    assert rows == [*[("rigid_chain", n, f) for n in (2, 4) for f in ("joint_coordinates", "absolute")],
                    ("spatial_chain", 2, "absolute"), ("spatial_chain", 4, "absolute")]
    assert all(r.evaluations() > 0 for r in report["scaling"]["rows"])
    out = capsys.readouterr().out
    assert "| spatial_chain | 4 | absolute |" in out
    if with_exudyn:
        assert "goal, slider-crank, jointplay 5x faster than Exudyn, CPU time" in out
    else:
        assert "Exudyn rows: skipped, exudyn is not installed" in out


def test_spatial_benchmark_runs_without_exudyn(capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "exudyn", None)  # import exudyn now raises ImportError
    monkeypatch.delitem(sys.modules, "bench_spin_up_beam", raising=False)
    bench = load("bench_spatial")
    assert bench.exudyn is None
    report = bench.main(["--quick", "--part", "exudyn"])
    assert [list(c.cases) for c in report["comparisons"]] == [["jointplay"], ["jointplay"]]
    assert report["verdicts"] == [] and report["scaling"] is None
    assert "Exudyn rows: skipped, exudyn is not installed" in capsys.readouterr().out


def test_study_benchmark_quick_mode_runs_three_ways_with_identical_results(capsys):
    bench = load("bench_study")
    report = bench.main(["--quick"])
    speed = report["Speed-up on 2 workers"]
    assert "2 local processes: Dataset identical to serial: True" in speed
    assert "Dask LocalCluster, 2 workers: Dataset identical to serial: True" in speed
    assert sum(line.startswith("| ") and "|---" not in line for line in speed) == 4  # header and three ways
    assert any("fixed cost / whole case" in line for line in report["Fixed cost of one case"])
    memory = report["Worker memory"]
    assert sum(line.startswith("| ") and line[2].isdigit() for line in memory) == 2  # two workers
    assert "40 cases of 0.5 ms, 0 failed" in "\n".join(memory)


def test_spatial_clearance_joint_benchmark_times_the_three_builds_on_the_same_impacts(capsys, tmp_path):
    bench = load("spatial_clearance_joint")
    specs = bench.builds()
    (joint,) = specs["c"]["spatial_clearance_joints"]
    planar = specs["b"]["joints"][0]
    assert (joint["bore_radius"], joint["clearance"], joint["bearing_length"]) == (
        planar["bearing_radius"], planar["clearance"], planar["length"])
    report = bench.main(["--rounds", "1", "--t-end", "5e-4", "--where", "--output", str(tmp_path / "r.json")])
    assert [w["t_end"] for w in report["windows"]] == [5e-4, bench.FREE_T_END, 5e-4, bench.FIXED_T_END]
    first, free = report["windows"][0], report["windows"][1]
    assert [r["case"] for r in first["rows"]] == [label for label, *_ in bench.CASES]
    # the first impact (0.23 ms) is in the window of every build, none in the free window
    assert all(r["peak_force"] > 1e3 and r["evaluations"] > r["steps"] for r in first["rows"])
    assert all(r["peak_force"] == 0.0 for r in free["rows"])
    assert all(s.n == 1 for s in first["ratios"].values())
    out = capsys.readouterr().out
    assert "goal: at most 3x per evaluation, (c)/(b), CPU:" in out
    assert (tmp_path / "r.json").exists() and "| (c)/(b) |" in (tmp_path / "r.md").read_text()
