"""Every example script runs, and its headline numbers are sane."""

import runpy
from pathlib import Path

import numpy as np
import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def test_every_python_example_is_covered_here():
    covered = {"flores_slider_crank_dry", "flores_slider_crank_ideal", "paper001_slider_crank_dry"}
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
