"""Every example script runs, and its headline numbers are sane."""

import runpy
from pathlib import Path

import numpy as np
import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def test_every_python_example_is_covered_here():
    covered = {"flores_slider_crank_dry", "flores_slider_crank_ideal", "paper001_slider_crank_dry",
               "flores_slider_crank_lubricated", "paper001_parametric_study",
               "paper000_joint_models",  # has its own tests/test_paper000_example.py
               # the physics of these two: tests/physics/test_singular_four_bar.py and
               # tests/physics/test_redundant_double_parallelogram.py
               "parallelogram_four_bar", "double_parallelogram"}
    assert {p.stem for p in EXAMPLES.glob("*.py")} == covered


def test_flores_dry_example_runs_two_revolutions_with_impacts():
    import flores_slider_crank_dry as example

    results = example.main([])
    assert results.error is None
    assert results.time[-1] == pytest.approx(example.revolutions_to_time(2.0))
    joint = results.summary()["clearance_joints"]["B"]
    assert joint["impacts"] > 10
    assert 0.2 < joint["contact_fraction"] < 0.9


def test_flores_ideal_example_runs_and_is_periodic():
    import flores_slider_crank_ideal as example

    results = example.main([])
    x, t = results["slider.x"], results.time
    one_turn = np.searchsorted(t, t[-1] / 2)
    # a kinematically driven ideal mechanism repeats itself every revolution
    assert x[one_turn] == pytest.approx(x[0], abs=1e-9)
    assert np.max(np.abs(results["B.f"])) > 0


def test_paper001_example_runs_with_the_adams_method():
    runpy.run_path(str(EXAMPLES / "paper001_slider_crank_dry.py"), run_name="not_main")
    import paper001_slider_crank_dry as example

    results = example.main(["--revolutions", "0.5"])
    assert results.error is None
    assert results.options["method"] == "adams"
    assert results.summary()["clearance_joints"]["B"]["impacts"] >= 1


def test_flores_lubricated_example_compares_dry_and_lubricated(tmp_path):
    import flores_slider_crank_lubricated as example

    runs = example.main(["--out", str(tmp_path), "--revolutions", "1"])
    assert set(runs) == {"dry", "lubricated"}
    assert (tmp_path / "flores_dry_vs_lubricated.png").stat().st_size > 10_000
    assert runs["lubricated"]["B.film_min"].min() > 0


def test_paper001_study_writes_its_figures_and_table(tmp_path):
    import paper001_parametric_study as example

    study, rows = example.main(["--out", str(tmp_path), "--revolutions", "0.5"])
    assert len(rows) == 11 and {r["series"] for r in rows} == {"clearance", "speed", "viscosity"}
    for name in ("paper001_clearance.png", "paper001_speed.png", "paper001_viscosity.png",
                 "paper001_film_min.csv", "paper001_film_min.md"):
        assert (tmp_path / name).exists()


def test_parallelogram_four_bar_example_runs_through_its_flat_positions(tmp_path):
    import parallelogram_four_bar as example

    results = example.main(["--out", str(tmp_path), "--t-end", "2"])
    assert results.error is None
    assert results.time[-1] == pytest.approx(2.0)
    assert example.flat_passages(results) >= 2  # at about 0.71 s and 1.22 s
    assert (tmp_path / "parallelogram_four_bar.png").stat().st_size > 10_000


def test_double_parallelogram_example_runs_with_its_redundant_bar(tmp_path):
    import double_parallelogram as example

    results = example.main(["--out", str(tmp_path), "--t-end", "2"])
    assert results.error is None
    assert results.time[-1] == pytest.approx(2.0)
    assert example.flat_passages(results) >= 2
    assert (tmp_path / "double_parallelogram.png").stat().st_size > 10_000
