"""Responses of a run (docs/theory/study-metrics.md), against closed forms and numpy computed here."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp
from jointplay.results import Results
from jointplay.study.metrics import (DEFAULT_CYCLES_PER_WINDOW, Response, check_against, oscillation, parse_responses,
                                     required_output_step)

EXAMPLES = Path(__file__).parent.parent / "examples"


def synthetic(time, **channels) -> Results:
    names = list(channels)
    return Results(time, names, ["m/s^2"] * len(names), [""] * len(names), np.array([channels[n] for n in names]),
                   {}, {})


def one(table: dict) -> Response:
    return parse_responses([table])[0]


def mean_square_sine(amplitude, frequency, t0, t1):
    """Mean of (A sin(2 pi f t))^2 over [t0, t1], in closed form."""
    w = 2 * math.pi * frequency
    return amplitude**2 * (0.5 - (math.sin(2 * w * t1) - math.sin(2 * w * t0)) / (4 * w * (t1 - t0)))


def test_the_oscillation_of_a_sine_on_a_slow_trend_is_the_sine():
    """A parabola (the trend) plus a sine 8 times the cutoff: the Butterworth low-pass of order 4 run both ways
    passes 1 / (1 + 8^8)^2 ~ 6e-15 of the sine's power and keeps the parabola (4e-6 of it leaks at most near
    the ends, where the odd extension bends); the RMS about the trend is the sine's own, to 0.5 %."""
    t = np.linspace(0.0, 0.03, 30001)
    amplitude, cutoff = 2.0, 300.0
    sine = amplitude * np.sin(2 * math.pi * 8 * cutoff * t)
    x = 4e4 * t**2 - 500 * t + sine
    found = oscillation(t, x, cutoff)
    assert found == pytest.approx(math.sqrt(mean_square_sine(amplitude, 8 * cutoff, 0.0, 0.03)), rel=5e-3)
    assert oscillation(t, x, cutoff, "peak") == pytest.approx(amplitude, rel=2e-2)
    assert oscillation(t, x, cutoff, "peak_to_peak") == pytest.approx(2 * amplitude, rel=2e-2)
    assert oscillation(t, 4e4 * t**2 - 500 * t, cutoff) < 1e-3 * 5.0  # the trend alone: ~0 beside its size


def test_the_oscillation_does_not_depend_on_the_samples_once_they_are_fine():
    def signal(t):
        return np.exp(-60 * t) * np.sin(2 * math.pi * 2500 * t) + 10 * t

    values = [oscillation(t, signal(t), 300.0) for t in (np.linspace(0, 0.03, n) for n in (3001, 12001, 48001))]
    assert values[1] == pytest.approx(values[2], rel=2e-3)
    assert values[0] == pytest.approx(values[2], rel=1e-2)


def test_each_sampled_kind_is_what_numpy_says_in_its_window():
    t = np.linspace(0.0, 1.0, 1001)
    x = np.sin(7 * t) + 0.3 * t
    run = synthetic(t, **{"slider.ax": x})
    start, end = one({"name": "r", "kind": "max", "channel": "slider.ax", "window": ["200 ms", "700 ms"]}).window
    inside = (t >= start) & (t <= end)
    ti, xi = t[inside], x[inside]
    # mean and RMS over time: trapezoids of the samples (the samples here are evenly spaced, so also the
    # average of the interior samples with half weight at the ends)
    weights = np.full(xi.size, 1.0)
    weights[[0, -1]] = 0.5
    expected = {"peak": np.max(np.abs(xi)), "max": xi.max(), "min": xi.min(),
                "mean": np.sum(weights * xi) / np.sum(weights), "rms": np.sqrt(np.sum(weights * xi**2) / np.sum(weights)),
                "peak_to_peak": np.ptp(xi), "final": xi[-1]}
    for kind, value in expected.items():
        response = one({"name": "r", "kind": kind, "channel": "slider.ax", "window": ["200 ms", "700 ms"]})
        assert response.evaluate(run) == pytest.approx(value, rel=1e-10), kind
        assert response.units_in(run) == "m/s^2"
    whole = one({"name": "r", "kind": "peak", "channel": "slider.ax"})
    assert whole.evaluate(run) == pytest.approx(np.max(np.abs(x)), rel=1e-12)  # no extrema: from the samples


def test_a_whole_run_peak_is_the_one_tracked_at_every_step_whatever_the_output_step():
    model = jp.load(EXAMPLES / "flores_slider_crank_dry.toml")
    coarse = model.simulate(0.005, output_step=1e-3)
    fine = model.simulate(0.005, output_step=1e-6)
    peak = one({"name": "f", "kind": "peak", "channel": "B.fn"})
    assert peak.evaluate(coarse) == peak.evaluate(fine) == coarse.extrema["channels"]["B.fn"]["peak"]
    sampled = float(np.max(np.abs(fine["B.fn"])))
    assert sampled <= peak.evaluate(fine) * (1 + 1e-9) and sampled == pytest.approx(peak.evaluate(fine), rel=2e-2)
    # the joint's statistics come from the summary, tracked at every step
    fraction = one({"name": "c", "kind": "contact_fraction", "joint": "B"})
    depth = one({"name": "d", "kind": "max_penetration", "joint": "B"})
    assert fraction.evaluate(coarse) == coarse.summary()["clearance_joints"]["B"]["contact_fraction"]
    assert depth.evaluate(coarse) == depth.evaluate(fine) > 0 and depth.units_in(coarse) == "m"
    with pytest.raises(jp.ModelError, match="lubricated"):
        one({"name": "h", "kind": "min_film", "joint": "B"}).evaluate(coarse)
    with pytest.raises(jp.ModelError, match="no clearance joint 'Q'"):
        one({"name": "h", "kind": "contact_fraction", "joint": "Q"}).evaluate(coarse)


def test_a_callable_response_is_the_function_of_the_run():
    t = np.linspace(0, 1, 11)
    response = Response.from_callable("last_time", lambda results: results.time[-1], units="s")
    assert response.evaluate(synthetic(t, **{"a.x": t})) == 1.0 and response.units_in(None) == "s"


def test_bad_responses_get_one_located_message_each():
    with pytest.raises(jp.ModelError) as caught:
        parse_responses([{"name": "a", "kind": "peak"},
                         {"name": "b", "kind": "wobble", "channel": "x.y"},
                         {"name": "c", "kind": "rms", "channel": "x.y", "window": ["5 ms", "1 ms"]},
                         {"name": "d", "kind": "oscillation", "channel": "x.y", "cutoff": "3 kg"},
                         {"name": "e", "kind": "contact_fraction", "joint": "B", "window": ["0 s", "1 s"]},
                         {"name": "a", "kind": "max", "channel": "x.y", "colour": 1}])
    found = {p.location: p.message for p in caught.value.problems}
    assert "channel" in found["study.responses[0].channel"]
    assert "peak, max" in found["study.responses[1].kind"]
    assert "start < end" in found["study.responses[2].window"]
    assert "frequency" in found["study.responses[3].cutoff"]
    assert "does not apply" in found["study.responses[4].window"]
    assert "study.responses[5].colour" in found


def test_a_channel_missing_from_the_run_is_named_with_close_matches():
    run = synthetic(np.linspace(0, 1, 5), **{"slider.ax": np.zeros(5)})
    with pytest.raises(jp.ModelError, match="did you mean slider.ax"):
        check_against([one({"name": "r", "kind": "rms", "channel": "slider.ay"})], run)


def test_the_output_step_an_oscillation_needs():
    explicit = one({"name": "o", "kind": "oscillation", "channel": "a.x", "cutoff": "500 Hz"})
    default = one({"name": "o", "kind": "oscillation", "channel": "a.x", "window": ["0 ms", "30 ms"]})
    assert required_output_step([explicit], 1.0) == pytest.approx(0.5 / (20 * 500))
    assert required_output_step([default], 1.0) == pytest.approx(0.5 / (20 * DEFAULT_CYCLES_PER_WINDOW / 0.03))
    assert required_output_step([one({"name": "p", "kind": "peak", "channel": "a.x"})], 1.0) is None
