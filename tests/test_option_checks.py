"""Every simulation option the core checks is checked first where it is read, with its key: from
``Model.simulate(...)``, from ``jointplay run`` (exit 2, no traceback) and in a model file's ``[simulation]``
table, with the same message; and the bounds Python checks are the core's (pinned against the core itself)."""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

import jointplay as jp
from jointplay import parameters as p
from jointplay.cli import app
from jointplay.model import _options
from small_models import pendulum

ROOT = Path(__file__).resolve().parents[1]
#: a closed loop of ideal joints; its [simulation] table has max_step = "0.1 ms" and method = "adams"
IDEAL = str(ROOT / "examples" / "flores_slider_crank_ideal.toml")

RTOL = ("simulation.rtol: must be at least 2.22e-14 (100 machine epsilons: below it the error estimate is rounding "
        "noise), got 1e-20")
MAX_STEP = ("simulation.max_step: must be greater than min_step = 1e-14 s (its value when not given; the step "
            "control works between them), got 1e-15 s")
STEP = ("simulation.step: must be at least min_step = 1e-14 s (its value when not given; a step below the smallest "
        "step stops the run at once), got 1e-15 s")
INITIAL_STEP = ("simulation.initial_step: must be at least min_step = 1e-14 s (its value when not given; a first "
                "step below the smallest step stops the run at once), got 1e-16 s")
LOOP = ('simulation.formulation: joint_coordinates needs a tree of ideal joints, but joint "B" closes a loop of ideal '
        'joints; use "auto" or "absolute"')


def simulate_problems(model: jp.Model, **options) -> list[str]:
    with pytest.raises(jp.ModelError) as caught:
        model.simulate(1e-3, **options)
    return [str(problem) for problem in caught.value.problems]


# the Python API ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("options, message", [
    (dict(rtol=1e-20), RTOL),
    (dict(max_step=1e-15), MAX_STEP),
    (dict(max_step="1e-15 s"), MAX_STEP),  # an option with a unit, as a builder argument
    (dict(min_step=1e-3, max_step=1e-4), "simulation.min_step: must be smaller than max_step = 0.0001 s (the step "
                                         "control works between them), got 0.001 s"),
    (dict(method="generalized_alpha", step=1e-15), STEP),
    (dict(initial_step=1e-16), INITIAL_STEP),
    (dict(initial_step=1e-6, min_step=1e-5), "simulation.initial_step: must be at least min_step = 1e-05 s (a first "
                                             "step below the smallest step stops the run at once), got 1e-06 s"),
    (dict(t0=float("nan")), "simulation.t0: must be a finite number of seconds, got nan"),
    (dict(t0="1 ms"), "simulation.t0: must be a finite number of seconds, got '1 ms'"),
    (dict(max_step=float("inf")), "simulation.max_step: must be finite, got inf"),
    (dict(rtol=None), "simulation.rtol: must be a number, got None"),
    (dict(max_steps=True), "simulation.max_steps: must be a positive integer, got True"),
    (dict(max_steps=2**64), "simulation.max_steps: must be at most 2^64 - 1 (the largest count the core holds), got "
                            "18446744073709551616"),
    (dict(max_output_bytes=1e30), "simulation.max_output_bytes: must be at most 2^64 - 1 bytes (16 EiB, the largest "
                                  "size the core counts), got 1e+30"),
])
def test_an_option_the_core_would_refuse_is_a_model_error_at_its_key(options, message):
    assert simulate_problems(pendulum(), **options) == [message]


def test_an_end_time_that_is_not_a_number_of_seconds_is_named():
    with pytest.raises(jp.ModelError) as caught:
        pendulum().simulate("24 ms")
    assert [str(problem) for problem in caught.value.problems] == [
        "simulation.t_end: must be a number of seconds, got '24 ms'"]


def test_joint_coordinates_of_a_closed_loop_are_refused_before_the_run():
    assert simulate_problems(jp.load(IDEAL), formulation="joint_coordinates") == [LOOP]


def test_a_bound_with_the_default_min_step_is_reported_at_the_key_the_user_set():
    # min_step was not given: the problem is at max_step, not at min_step as the core would name it
    problems = simulate_problems(pendulum(), max_step=1e-15)
    assert problems[0].startswith("simulation.max_step:") and "min_step = 1e-14 s (its value when not given" in problems[0]


# the bounds are the core's --------------------------------------------------------------------------------

def core_options(**changes) -> dict:
    options = _options(0.0, 1.0, "dopri5", 1e-6, 1e-9, None, None, None, None, None, "projection")
    options.update(changes)
    return options


def test_python_s_smallest_rtol_is_the_core_s():
    core = pendulum().compile()
    with pytest.raises(ValueError, match="rtol: must be >= 2.2e-14"):
        core.simulate(0.0, 1e-6, core_options(rtol=p.MIN_RTOL * 0.999), None, None)
    assert core.simulate(0.0, 1e-6, core_options(rtol=p.MIN_RTOL), None, None)["error"] is None


def test_python_s_default_min_step_is_the_core_s():
    core = pendulum().compile()
    with pytest.raises(ValueError, match="min_step: must be < max_step"):
        core.simulate(0.0, 1e-13, core_options(max_step=p.DEFAULT_MIN_STEP), None, None)
    with pytest.raises(ValueError, match="step: must be >= min_step"):
        core.simulate(0.0, 1e-13, core_options(method="generalized_alpha", step=p.DEFAULT_MIN_STEP * 0.999), None, None)
    assert core.simulate(0.0, 1e-13, core_options(max_step=p.DEFAULT_MIN_STEP * 1.001), None, None)["error"] is None


# jointplay run, and the model file's [simulation] table ---------------------------------------------------

def run(*args: str):
    return CliRunner().invoke(app, ["run", IDEAL, "--t-end", "1 ms", "-q", *args])


@pytest.mark.parametrize("overrides, message", [
    (["simulation.rtol=1e-20"], RTOL),
    (['simulation.max_step="1e-15 s"'], MAX_STEP),
    (['simulation.min_step="1 ms"'], "simulation.min_step: must be smaller than max_step = 0.1 ms (the step control "
                                     "works between them), got 1 ms"),
    (['simulation.method="generalized_alpha"', 'simulation.step="1e-15 s"'], STEP),
    (['simulation.initial_step="1e-16 s"'], INITIAL_STEP),
    (['simulation.formulation="joint_coordinates"'], LOOP),
    (['simulation.method="generalized_alpha"'], 'simulation.step: generalized_alpha integrates with a fixed nominal '
                                                'step and needs one, for example step = "1 ms"; its accuracy is that '
                                                "step's"),
])
def test_run_exits_2_with_the_option_s_key_and_value(overrides, message, tmp_path):
    result = run("-o", str(tmp_path / "x.nc"), *(arg for o in overrides for arg in ("--set", o)))
    assert result.exit_code == 2, result.output
    assert message in " ".join(result.stderr.split())
    assert "Traceback" not in result.output and not list(tmp_path.iterdir())


def test_a_model_file_s_simulation_table_is_checked_when_it_is_read():
    text = Path(IDEAL).read_text().replace('max_step = "0.1 ms"', 'max_step = "1e-15 s"')
    with pytest.raises(jp.ModelError) as caught:
        jp.loads(text)
    assert [str(problem) for problem in caught.value.problems] == [MAX_STEP]


def test_check_reports_a_bad_simulation_table(tmp_path):
    path = tmp_path / "m.toml"
    path.write_text(Path(IDEAL).read_text().replace("rtol = 1e-6", "rtol = 1e-20"))
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2
    assert RTOL in " ".join(result.stderr.split())


def test_an_option_the_core_refuses_past_the_checks_is_still_a_located_model_error():
    from jointplay.model import _run

    core = pendulum().compile()
    with pytest.raises(jp.ModelError) as caught:
        _run(core, 0.0, 1e-3, core_options(rtol=1e-20, max_step=1e-15), None)
    assert [str(problem) for problem in caught.value.problems] == [
        "simulation.rtol: must be >= 2.2e-14 and finite, got 1e-20", "simulation.min_step: must be < max_step, got 1e-14"]
