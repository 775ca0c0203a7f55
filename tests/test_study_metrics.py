"""Responses of a run (docs/theory/study-metrics.md), against closed forms and numpy computed here.

Tolerances of the oscillation follow from its filter (a Butterworth low-pass of order 4 at f_c run forward
and backward: gain G(f) = 1 / (1 + (f / f_c)^8), zero phase) and its ends (odd extension over 3 periods of
f_c). Its slowest poles have real part -sin(pi/8) w_c (w_c = 2 pi f_c), so a start-up transient has decayed
by exp(-sin(pi/8) 2 pi 3) = 7.4e-4 when the extension reaches the window; the transient of a ramp of slope
b is of the order of b times the filter's delay at zero frequency, 2.613 / w_c (Butterworth order 4).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import jointplay as jp
from jointplay.results import Results
from jointplay.study.metrics import (DEFAULT_CYCLES_PER_WINDOW, STEPS_PER_WINDOW, Response, check_against,
                                     oscillation, parse_responses, required_output_step)

EXAMPLES = Path(__file__).parent.parent / "examples"
CUTOFF = 300.0  # [Hz]
W_C = 2 * math.pi * CUTOFF
#: Start-up transient left after the odd extension of 3 periods of the cutoff (slowest pole, see above).
TRANSIENT_LEFT = math.exp(-math.sin(math.pi / 8) * 2 * math.pi * 3)


def synthetic(time, **channels) -> Results:
    names = list(channels)
    return Results(time, names, ["m/s^2"] * len(names), [""] * len(names), np.array([channels[n] for n in names]),
                   {}, {})


def one(table: dict) -> Response:
    return parse_responses([table])[0]


def butterworth_both_ways(f: float) -> float:
    """Gain of the trend filter at f [Hz]: |H(f)|^2 of the order-4 Butterworth, 1 / (1 + (f / f_c)^8)."""
    return 1.0 / (1.0 + (f / CUTOFF) ** 8)


@pytest.fixture(scope="module")
def slider_crank():
    return jp.load(EXAMPLES / "flores_slider_crank_dry.toml")


# --- the oscillation ----------------------------------------------------------------------------------

def test_the_oscillation_of_a_sine_on_a_ramp_is_the_sine():
    """A ramp (slope b) plus a sine of amplitude A at 8 f_c, whole cycles over 30 ms: the odd extension
    continues both exactly, the filter keeps G(8 f_c) = 6e-8 of the sine, so what is left is the ramp's
    start-up transient, ~ TRANSIENT_LEFT b 2.613 / w_c = 5e-4 at most (0.03 % of the RMS of the sine, A / sqrt 2)
    and the grid's miss of the sine's crest, A (1 - cos(pi 8 f_c h)) = 6e-5 at h = 1 us."""
    t = np.linspace(0.0, 0.03, 30001)
    amplitude, slope = 2.0, -500.0
    sine = amplitude * np.sin(2 * math.pi * 8 * CUTOFF * t)
    x = 3.0 + slope * t + sine
    transient = TRANSIENT_LEFT * abs(slope) * 2.613 / W_C
    crest = amplitude * (1 - math.cos(math.pi * 8 * CUTOFF * 1e-6))
    assert butterworth_both_ways(8 * CUTOFF) < 1e-7
    assert oscillation(t, x, CUTOFF) == pytest.approx(amplitude / math.sqrt(2), abs=transient)
    assert oscillation(t, x, CUTOFF, "peak") == pytest.approx(amplitude, abs=transient + crest)
    assert oscillation(t, x, CUTOFF, "peak_to_peak") == pytest.approx(2 * amplitude, abs=2 * (transient + crest))
    assert oscillation(t, 3.0 + slope * t, CUTOFF, "peak") < transient  # the ramp alone: nothing about itself


@pytest.mark.parametrize("frequency", [300.0, 450.0, 600.0])
def test_a_sine_in_the_filter_band_keeps_one_minus_the_filter_gain(frequency):
    """A sine x of frequency f through a zero-phase filter of gain G(f) becomes G x, so x - trend is
    (1 - G(f)) x: half the sine at the cutoff, 255/256 of it at 2 f_c. The sine starts at 0, so the filter
    starts in its state (the transient is < TRANSIENT_LEFT of A)."""
    t = np.linspace(0.0, 0.03, 30001)
    amplitude = 2.0
    expected = (1 - butterworth_both_ways(frequency)) * amplitude / math.sqrt(2)
    found = oscillation(t, amplitude * np.sin(2 * math.pi * frequency * t), CUTOFF)
    assert found == pytest.approx(expected, abs=TRANSIENT_LEFT * amplitude)


def test_the_oscillation_about_a_curved_trend():
    """A parabola (curvature c = 8e4) plus a sine at 8 f_c. The odd extension flips the curvature at each
    end, a jump of 2c; a low-pass of time scale 1 / w_c departs from a curve by the order of its change in
    curvature over w_c^2, 2c / w_c^2 = 0.045 (2 % of A), within about one period of the cutoff of each end
    (2 / (f_c 30 ms) = 22 % of the window): the RMS moves by at most 0.045 sqrt(0.22) = 0.021."""
    t = np.linspace(0.0, 0.03, 30001)
    amplitude, curvature = 2.0, 8e4
    trend = curvature / 2 * t**2 - 500 * t
    sine = amplitude * np.sin(2 * math.pi * 8 * CUTOFF * t)
    end_error = 2 * curvature / W_C**2
    rms_error = end_error * math.sqrt(2 / (CUTOFF * 0.03))
    assert oscillation(t, trend + sine, CUTOFF) == pytest.approx(amplitude / math.sqrt(2), abs=rms_error)
    assert oscillation(t, trend + sine, CUTOFF, "peak") == pytest.approx(amplitude, abs=end_error)
    alone = oscillation(t, trend, CUTOFF)
    assert alone < rms_error and alone < 1e-3 * np.ptp(trend)


def test_the_oscillation_does_not_depend_on_the_samples_once_they_are_fine():
    def signal(t):
        return np.exp(-60 * t) * np.sin(2 * math.pi * 2500 * t) + 10 * t

    values = [oscillation(t, signal(t), CUTOFF) for t in (np.linspace(0, 0.03, n) for n in (3001, 12001, 48001))]
    assert values[1] == pytest.approx(values[2], rel=2e-3)
    assert values[0] == pytest.approx(values[2], rel=1e-2)
    # unevenly spaced samples of the same curve (as a run's accepted steps) give the same value
    uneven = np.sort(np.concatenate(([0.0, 0.03], np.random.default_rng(3).uniform(0, 0.03, 48000))))
    assert oscillation(uneven, signal(uneven), CUTOFF) == pytest.approx(values[2], rel=2e-3)


def test_an_oscillation_response_reads_its_window_and_default_cutoff():
    t = np.linspace(0.0, 0.06, 60001)
    x = np.where(t <= 0.03, np.sin(2 * math.pi * 8 * CUTOFF * t), 0.0)
    run = synthetic(t, **{"contact.ax": x})
    windowed = one({"name": "o", "kind": "oscillation", "channel": "contact.ax", "window": ["0 ms", "30 ms"],
                    "cutoff": f"{CUTOFF} Hz"})
    assert windowed.evaluate(run) == pytest.approx(1 / math.sqrt(2), abs=TRANSIENT_LEFT)
    default = one({"name": "o", "kind": "oscillation", "channel": "contact.ax", "window": ["0 ms", "30 ms"]})
    assert default.evaluate(run) == pytest.approx(
        oscillation(t[t <= 0.03 + 1e-12], x[t <= 0.03 + 1e-12], DEFAULT_CYCLES_PER_WINDOW / 0.03), rel=1e-12)
    assert "10 cycles per window" in default.definition and "output grid" in default.definition
    with pytest.raises(jp.ModelError, match="periods of the cutoff"):
        one({"name": "o", "kind": "oscillation", "channel": "contact.ax", "cutoff": "10 Hz"}).evaluate(run)


# --- the other channel responses -----------------------------------------------------------------------

def test_each_sampled_kind_is_what_numpy_says_in_its_window():
    t = np.linspace(0.0, 1.0, 1001)
    x = np.sin(7 * t) + 0.3 * t
    run = synthetic(t, **{"slider.ax": x})
    start, end = one({"name": "r", "kind": "max", "channel": "slider.ax", "window": ["200 ms", "700 ms"]}).window
    inside = (t >= start - 1e-12) & (t <= end + 1e-12)
    ti, xi = t[inside], x[inside]
    # mean and RMS over time: the samples here are evenly spaced and the window's ends are samples, so the
    # time mean of the piecewise-linear curve is the average with half weight at the two ends
    weights = np.full(xi.size, 1.0)
    weights[[0, -1]] = 0.5
    expected = {"peak": np.max(np.abs(xi)), "max": xi.max(), "min": xi.min(),
                "mean": np.sum(weights * xi) / np.sum(weights),
                "rms": np.sqrt(np.sum(weights * xi**2) / np.sum(weights)),
                "peak_to_peak": np.ptp(xi), "final": xi[-1]}
    for kind, value in expected.items():
        response = one({"name": "r", "kind": kind, "channel": "slider.ax", "window": ["200 ms", "700 ms"]})
        assert response.evaluate(run) == pytest.approx(value, rel=1e-10), kind
        assert response.units_in(run) == "m/s^2"
        assert "output grid" in response.definition
    whole = one({"name": "r", "kind": "peak", "channel": "slider.ax"})
    assert whole.evaluate(run) == pytest.approx(np.max(np.abs(x)), rel=1e-12)  # no extrema: from the samples


def test_a_window_between_samples_takes_the_curve_at_its_ends():
    """x = a + b t is its own piecewise-linear curve, so over [t0, t1] off the samples: mean a + b (t0 + t1) / 2,
    mean square the integral of (a + b t)^2 over the window, final a + b t1, max and min at the ends."""
    t = np.linspace(0.0, 1.0, 11)  # samples every 0.1 s
    a, b = -1.0, 4.0
    run = synthetic(t, **{"s.x": a + b * t})
    t0, t1 = 0.23, 0.78

    def value(kind):
        return one({"name": "r", "kind": kind, "channel": "s.x", "window": [f"{t0} s", f"{t1} s"]}).evaluate(run)

    assert value("mean") == pytest.approx(a + b * (t0 + t1) / 2, rel=1e-12)
    # the RMS is the time mean of the straight lines through the squared samples (trapezoids of x_k^2), the
    # window's ends included: here over t0, 0.3, ..., 0.7, t1
    nodes = [t0, 0.3, 0.4, 0.5, 0.6, 0.7, t1]
    squares = [(a + b * s) ** 2 for s in nodes]
    trapezoids = sum((squares[k] + squares[k + 1]) / 2 * (nodes[k + 1] - nodes[k]) for k in range(len(nodes) - 1))
    assert value("rms") == pytest.approx(math.sqrt(trapezoids / (t1 - t0)), rel=1e-12)
    # which exceeds the curve's own mean square by the trapezoids' error, sum of b^2 dt^3 / 6 over the steps
    exact = ((a + b * t1) ** 3 - (a + b * t0) ** 3) / (3 * b * (t1 - t0))
    excess = sum(b**2 * (nodes[k + 1] - nodes[k]) ** 3 / 6 for k in range(len(nodes) - 1)) / (t1 - t0)
    assert value("rms") ** 2 == pytest.approx(exact + excess, rel=1e-12)
    assert value("final") == pytest.approx(a + b * t1, rel=1e-12)
    assert value("max") == pytest.approx(a + b * t1, rel=1e-12)
    assert value("min") == pytest.approx(a + b * t0, rel=1e-12)
    assert value("peak_to_peak") == pytest.approx(b * (t1 - t0), rel=1e-12)


def test_mean_and_rms_weigh_uneven_samples_by_the_time_they_cover():
    """Samples crowded in the first half of a step signal do not pull the mean there: x = 1 on [0, 0.5),
    then 3; as a piecewise-linear curve through samples at 0, 0.1, ..., 0.4, 0.5-, 0.5, 1 the time mean is
    (0.5 * 1 + 0.5 * 3) = 2 and the mean square (0.5 * 1 + 0.5 * 9) = 5."""
    eps = 1e-9
    t = np.array([0.0, 0.1, 0.2, 0.3, 0.4, 0.5 - eps, 0.5, 1.0])
    x = np.array([1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 3.0, 3.0])
    run = synthetic(t, **{"s.x": x})
    assert one({"name": "m", "kind": "mean", "channel": "s.x"}).evaluate(run) == pytest.approx(2.0, abs=1e-8)
    assert one({"name": "r", "kind": "rms", "channel": "s.x"}).evaluate(run) == pytest.approx(math.sqrt(5), abs=1e-8)


# --- exact values tracked at every step, on a real run -------------------------------------------------

def test_a_whole_run_peak_is_the_one_tracked_at_every_step_whatever_the_output_step(slider_crank):
    coarse = slider_crank.simulate(0.005, output_step=1e-3)
    fine = slider_crank.simulate(0.005, output_step=1e-6)
    tracked = coarse.extrema["channels"]["B.fn"]["peak"]
    for table in ({"name": "f", "kind": "peak", "channel": "B.fn"},
                  {"name": "f", "kind": "peak", "channel": "B.fn", "window": ["0 ms", "5 ms"]}):
        assert one(table).evaluate(coarse) == one(table).evaluate(fine) == tracked
    # the peak of the fine samples: never above the tracked one, and below it by less than the largest change
    # of the channel over one output step (the samples resolve the curve)
    sampled = float(np.max(np.abs(fine["B.fn"])))
    assert 0 <= tracked - sampled <= np.max(np.abs(np.diff(fine["B.fn"])))
    # a window that does not cover the run is computed on the samples: the fine ones agree with the tracked
    # peak as closely as above, the coarse ones (1 ms apart) miss the impact peak at 0.25 ms
    part = one({"name": "f", "kind": "peak", "channel": "B.fn", "window": ["0 ms", "4 ms"]})
    assert 0 <= tracked - part.evaluate(fine) <= np.max(np.abs(np.diff(fine["B.fn"])))
    assert part.evaluate(coarse) < 0.5 * tracked


def test_the_output_step_the_study_sets_resolves_an_oscillation_of_a_real_run(slider_crank):
    """The slider's acceleration about its 2 kHz trend over 5 ms (impacts in the pin's clearance ring on
    it): at the step required_output_step gives, the same to 1 % as on a grid 25 times finer."""
    response = one({"name": "o", "kind": "oscillation", "channel": "slider.ax", "cutoff": "2 kHz"})
    step = required_output_step([response], 0.005)
    found = response.evaluate(slider_crank.simulate(0.005, output_step=step))
    finer = response.evaluate(slider_crank.simulate(0.005, output_step=step / 25))
    assert found == pytest.approx(finer, rel=1e-2) and finer > 0


def test_the_joint_statistics_are_the_summarys(slider_crank):
    coarse = slider_crank.simulate(0.005, output_step=1e-3)
    fine = slider_crank.simulate(0.005, output_step=1e-5)
    fraction = one({"name": "c", "kind": "contact_fraction", "joint": "B"})
    depth = one({"name": "d", "kind": "max_penetration", "joint": "B"})
    assert fraction.evaluate(coarse) == coarse.summary()["clearance_joints"]["B"]["contact_fraction"]
    assert fraction.evaluate(coarse) == fraction.evaluate(fine) and fraction.units_in(coarse) == ""
    # the deepest sampled penetration is never deeper than the tracked one
    assert depth.evaluate(coarse) == depth.evaluate(fine) >= np.max(fine["B.penetration"]) > 0
    assert depth.units_in(coarse) == "m" and "tracked at every step" in depth.definition
    with pytest.raises(jp.ModelError, match="lubricated"):
        one({"name": "h", "kind": "min_film", "joint": "B"}).evaluate(coarse)
    with pytest.raises(jp.ModelError, match="no clearance joint 'b'.*did you mean B"):
        one({"name": "h", "kind": "contact_fraction", "joint": "b"}).evaluate(coarse)


# --- user functions, bad input -------------------------------------------------------------------------

def last_time(results) -> float:
    return float(results.time[-1])


def test_a_callable_response_is_the_function_of_the_run():
    t = np.linspace(0, 1, 11)
    response = Response.from_callable("last_time", last_time, units="s")
    assert response.evaluate(synthetic(t, **{"a.x": t})) == 1.0 and response.units_in(None) == "s"
    assert "last_time" in response.definition
    with pytest.raises(jp.ModelError, match="function of a run"):
        Response.from_callable("x", 3.0)
    with pytest.raises(jp.ModelError, match=r"kind: must be one of .*got 'callable'"):
        parse_responses([{"name": "f", "kind": "callable", "channel": "a.x"}])  # never from a file


def test_bad_responses_get_one_located_message_each():
    with pytest.raises(jp.ModelError) as caught:
        parse_responses([{"name": "a", "kind": "peak"},
                         {"name": "b", "kind": "wobble", "channel": "x.y"},
                         {"name": "c", "kind": "rms", "channel": "x.y", "window": ["5 ms", "1 ms"]},
                         {"name": "d", "kind": "oscillation", "channel": "x.y", "cutoff": "3 kg"},
                         {"name": "e", "kind": "contact_fraction", "joint": "B", "window": ["0 s", "1 s"]},
                         {"name": "a", "kind": "max", "channel": "x.y", "colour": 1},
                         {"name": "g", "kind": "oscillation", "channel": "x.y", "window": ["0 ms", "2 ms"],
                          "cutoff": "100 Hz"},
                         {"name": "h", "kind": "mean", "channel": "x.y", "window": ["1 m", "2 m"]},
                         {"name": "i", "kind": "oscillation", "channel": "x.y", "statistic": "median"},
                         {"name": "a", "kind": "min", "channel": "x.y"}])
    found = {p.location: p.message for p in caught.value.problems}
    assert len(caught.value.problems) == len(found) == 11
    assert "channel" in found["study.responses[0].channel"]
    assert "peak, max, min, mean, rms, peak_to_peak, final, oscillation, contact_fraction" in found[
        "study.responses[1].kind"] and "'wobble'" in found["study.responses[1].kind"]
    assert "start < end" in found["study.responses[2].window"] and "5 ms" in found["study.responses[2].window"]
    assert "frequency" in found["study.responses[3].cutoff"] and "3 kg" in found["study.responses[3].cutoff"]
    assert "does not apply" in found["study.responses[4].window"]
    assert "study.responses[5].colour" in found and "study.responses[5].name" in found  # also a repeated name
    assert "0.2 periods of the cutoff" in found["study.responses[6].cutoff"]
    assert "time" in found["study.responses[7].window"] and "1 m" in found["study.responses[7].window"]
    assert "median" in found["study.responses[8].statistic"]
    assert "repeats the response name 'a' of study.responses[0]" in found["study.responses[9].name"]


def test_what_the_run_lacks_is_named_with_close_matches():
    run = synthetic(np.linspace(0, 0.01, 5), **{"slider.ax": np.zeros(5)})
    with pytest.raises(jp.ModelError) as caught:
        check_against([one({"name": "r", "kind": "rms", "channel": "slider.ay"}),
                       one({"name": "w", "kind": "max", "channel": "slider.ax", "window": ["5 ms", "20 ms"]})], run)
    found = {p.location: p.message for p in caught.value.problems}
    assert "did you mean slider.ax" in found["responses.r.channel"]
    assert "outside the run (0 s .. 0.01 s)" in found["responses.w.window"]
    with pytest.raises(jp.ModelError, match="responses.w.window"):
        one({"name": "w", "kind": "max", "channel": "slider.ax", "window": ["5 ms", "20 ms"]}).evaluate(run)


def test_the_output_step_the_responses_need():
    explicit = one({"name": "o", "kind": "oscillation", "channel": "a.x", "cutoff": "500 Hz"})
    default = one({"name": "o", "kind": "oscillation", "channel": "a.x", "window": ["0 ms", "30 ms"]})
    windowed = one({"name": "m", "kind": "max", "channel": "a.x", "window": ["10 ms", "20 ms"]})
    whole_mean = one({"name": "m", "kind": "mean", "channel": "a.x"})
    peak = one({"name": "p", "kind": "peak", "channel": "a.x"})
    joint = one({"name": "c", "kind": "contact_fraction", "joint": "B"})
    assert required_output_step([explicit], 1.0) == pytest.approx(1 / (2 * 20 * 500))
    assert required_output_step([default]) == pytest.approx(1 / (2 * 20 * DEFAULT_CYCLES_PER_WINDOW / 0.03))
    assert required_output_step([windowed, peak, joint]) == pytest.approx(0.01 / STEPS_PER_WINDOW)
    assert required_output_step([whole_mean], 0.5) == pytest.approx(0.5 / STEPS_PER_WINDOW)
    assert required_output_step([peak, joint], 1.0) is None
    assert required_output_step([Response.from_callable("t", last_time)], 1.0) is None
