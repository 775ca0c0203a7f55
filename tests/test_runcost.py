"""What a run costs (issue 32, item 5): estimates before it starts, and a projection from its pace while
it goes (python/jointplay/runcost.py; docs/model-files.md, "What a run costs")."""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import pytest

import jointplay as jp
from jointplay import laws, runcost

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "examples"))
import flores_slider_crank_dry as flores  # noqa: E402

DRY = ROOT / "examples" / "flores_slider_crank_dry.toml"


def lubricated(n_circumferential: int, n_axial: int) -> jp.Model:
    model = flores.build_model()
    model.joint("B")["lubrication"] = laws.lubrication("reynolds_exact", laws.centipoise(400),
                                                       n_circumferential=n_circumferential, n_axial=n_axial)
    return model


def test_a_fine_reynolds_grid_is_warned_of_with_the_cost_of_a_solve_and_of_the_run():
    # 480 x 256 (61 920 nodes, within the limit of 1e6): 1.06 s measured for a cold solve, 1.4 s estimated
    spec = lubricated(480, 256).to_spec()
    options = {"method": "dopri5", "max_step": 1e-4}
    assert [str(p) for p in runcost.reynolds_cost(spec, options, 0.0, 0.01)] == [
        "joints.B.lubrication.grid: 480 x 256 (61920 nodes on the half length): one Reynolds solve takes about "
        "1.4 s, and the film is solved at every evaluation (6 or more per step of dopri5); this run takes at least "
        "600 evaluations (dopri5, 6 per step of at most 0.0001 s), about 14 min; the default 120 x 16 gives the "
        "force within about 0.3 %, and model = \"reynolds_table\" interpolates precomputed forces"]
    # without a bound on the steps: the cost of a solve alone
    found = runcost.reynolds_cost(spec, {"method": "bdf"}, 0.0, 0.01)
    assert str(found[0]).endswith("(1 or more per step of bdf); the default 120 x 16 gives the force within about "
                                  "0.3 %, and model = \"reynolds_table\" interpolates precomputed forces")


def test_the_default_grid_and_other_film_models_are_not_warned_of():
    assert runcost.reynolds_cost(lubricated(120, 16).to_spec(), {"method": "dopri5"}, 0.0, 1.0) == []
    assert runcost.reynolds_solve_seconds(120, 16) < 0.01  # measured 1 ms
    assert runcost.reynolds_cost(flores.build_model().to_spec(), {"method": "dopri5"}, 0.0, 1.0) == []


def test_simulate_issues_the_grid_warning_before_the_run():
    with pytest.warns(jp.JointplayWarning, match=r"joints\.B\.lubrication\.grid: 480 x 256 \(61920 nodes"):
        with pytest.raises(jp.ModelError, match="max_output_bytes"):  # (refused before the run: nothing solved)
            lubricated(480, 256).simulate(10.0, max_step=1e-9)


class Clock:
    """A wall clock that advances by the seconds given at each reading."""

    def __init__(self, *steps: float):
        self.now, self.steps = 0.0, list(steps)

    def __call__(self) -> float:
        self.now += self.steps.pop(0) if self.steps else 0.0
        return self.now


def test_a_run_whose_pace_projects_hours_is_warned_of_once_with_its_projected_size():
    # the issue's case: t_end = 1e12 s with a sample at every step to a results file
    samples = [0]
    pace = runcost.Pace(0.0, 1e12, samples_written=lambda: samples[0], budget=2 * 1024**3,
                        clock=Clock(0.0, 1.0, 1.5, 0.5, 1.0))
    pace.bytes_per_sample = 8 * 53
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        pace(0.5)  # 1 s: too early to tell
        samples[0] = 60_000
        pace(1.0)  # 2.5 s for 1 s of 1e12
        pace(2.0)  # once only
    assert [str(w.message) for w in seen] == [
        "simulation.t_end: at its pace so far (t = 1 s of 1e+12 s after 2.5 s), the run needs about 7.92e+04 years "
        "more and would write about 2.31e+07 TiB (a sample at every step); max_output_bytes = 2 GiB stops it "
        "before; Ctrl-C stops it and keeps what was computed (a shorter t_end, a coarser model or looser "
        "tolerances shorten it)"]


def test_a_run_whose_pace_projects_less_than_an_hour_is_not_warned_of():
    pace = runcost.Pace(0.0, 10.0, clock=Clock(0.0, 3.0))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pace(0.1)  # 3 s for 1 % of the run: 5 min to go


def test_a_run_with_a_sample_at_every_step_that_cannot_fit_is_refused_before_it_starts():
    # steps of at most 1 us over 1000 s: at least 1e9 samples, whatever the run does
    with pytest.raises(jp.ModelError, match=r"simulation\.max_output_bytes: the run would write at least 1000000001 "
                                            r"samples \(one at every step, each of at most 1e-06 s\) x 53 channels x 8 "
                                            r"bytes = 395 GiB, above max_output_bytes = 1 GiB; set an output_step, "
                                            r"raise max_output_bytes or shorten t_end"):
        jp.load(DRY).simulate(1000.0, max_step=1e-6)


@pytest.mark.parametrize("seconds, text", [(0.25, "0.25 s"), (90.0, "90 s"), (720.0, "12 min"), (3e4, "8.33 h"),
                                           (1e12, "3.17e+04 years")])
def test_durations_are_given_in_the_unit_that_fits(seconds, text):
    assert runcost.duration(seconds) == text
