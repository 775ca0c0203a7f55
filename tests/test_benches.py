"""The benchmark scripts run (one repeat each, no exact Reynolds mode) and report
what docs/performance.md quotes. Timing is never asserted; only the structure
and the step counts, which do not depend on the machine."""

import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def load(name: str):
    spec = importlib.util.spec_from_file_location(name, ROOT / "benches" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_dry_benchmark_runs_engine_and_baseline(capsys):
    rows = load("bench_flores_dry").main(["--repeats", "1", "--markdown"])
    assert [r["name"] for r in rows] == ["jointplay dopri5", "jointplay adams", "SciPy solve_ivp RK45 (baseline)"]
    assert all(r["steps"] > 100 and r["rhs"] > r["steps"] and r["impacts"] > 0 for r in rows)
    assert "| jointplay dopri5 |" in capsys.readouterr().out


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

