"""The practical-limit model of the dry Flores slider-crank (benches/limit_slider_crank.py, numba)
against the SciPy reference (tests/physics/reference_slider_crank.py) and the engine
(examples/flores_slider_crank_dry.py).

The limit is timed as a baseline in benches/bench_flores_dry.py; these checks make sure it
integrates the same model as the other two. All three locate the contact onset and latch the
onset velocity there, so at rtol 1e-9 they agree on the first impact to round-off of the event
location and on the peak force of the first impact (sampled on one common 10 ns grid, so the
sampling is the same for all) far inside 1e-6. The slider position over the first 5 ms (15 impacts)
is compared on a 1 us grid: the three differ there by at most 1.4e-4 of the clearance (70 nm,
from the chaos of repeated impacts beginning to amplify differences of the step sequences), against
a bound of 1e-3 of the clearance, which a 1 % change of the contact stiffness (2.5e-2 of the
clearance), of the rod mass by 0.1 % (1.7e-2) or of the friction coefficient by 10 % (0.24) exceeds
many times over. Skipped when numba (an optional benchmark dependency) is not installed. The first run
compiles the model (about 5 s of CPU) and caches it next to the module.
"""

import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("numba")

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benches"))

import flores_slider_crank_dry as flores  # noqa: E402
import limit_slider_crank as limit  # noqa: E402
import reference_slider_crank as ref  # noqa: E402

RTOL, ATOL = 1e-9, 1e-12
P = ref.FloresParameters()
FINE = 1e-8  # [s] common sampling of the first impact
SHORT = 1e-3  # [s] holds the first impact (onset 0.227 ms, contact about 53 us)
EARLY = 5e-3  # [s] slider positions compared up to here
COARSE = 1e-6  # [s]


def grid(t_end: float, dt: float) -> np.ndarray:
    """The sample times of the engine's output_step: t0 + i dt by multiplication."""
    return np.arange(int(round(t_end / dt)) + 1) * dt


def first_contact_peak(t, fn, penetration, onset):
    """Peak normal force over the samples from the onset to the first later sample out of contact."""
    start = int(np.searchsorted(t, onset))
    end = start + int(np.argmax(penetration[start:] <= 0.0))
    assert end > start + 1000  # the fine grid resolves the contact (about 5000 samples)
    return float(np.max(fn[start:end]))


@pytest.fixture(scope="module")
def limit_runs():
    limit.warm_up()
    return (limit.simulate_limit(t_end=SHORT, rtol=RTOL, atol=ATOL, t_out=grid(SHORT, FINE)),
            limit.simulate_limit(t_end=EARLY, rtol=RTOL, atol=ATOL, t_out=grid(EARLY, COARSE)))


@pytest.fixture(scope="module")
def reference_runs():
    return (ref.simulate_reference(t_end=SHORT, rtol=RTOL, atol=ATOL, dense=grid(SHORT, FINE)),
            ref.simulate_reference(t_end=EARLY, rtol=RTOL, atol=ATOL, dense=grid(EARLY, COARSE)))


@pytest.fixture(scope="module")
def engine_runs():
    model = flores.build_model()
    return (model.simulate(SHORT, rtol=RTOL, atol=ATOL),
            model.simulate(SHORT, rtol=RTOL, atol=ATOL, output_step=FINE),
            model.simulate(EARLY, rtol=RTOL, atol=ATOL, output_step=COARSE))


def test_limit_matches_the_scipy_reference_on_the_first_impact_and_the_early_motion(limit_runs, reference_runs):
    (fine, early), (ref_fine, ref_early) = limit_runs, reference_runs
    assert fine.impacts[0] == pytest.approx(ref_fine.impacts[0], rel=1e-6)
    # the same onsets, in number and time, over the first 5 ms
    assert len(early.impacts) == len(ref_early.impacts) == 15
    np.testing.assert_allclose(early.impacts, ref_early.impacts, rtol=1e-4)
    assert np.array_equal(fine.t, ref_fine.t)
    peak = first_contact_peak(fine.t, fine.fn, fine.penetration, fine.impacts[0])
    expected = first_contact_peak(ref_fine.t, ref_fine.fn, ref_fine.penetration, ref_fine.impacts[0])
    assert peak == pytest.approx(expected, rel=1e-6)
    assert 4.5e4 < peak < 4.7e4  # the violent first impact, about 46 kN
    assert np.max(np.abs(early.x_s - ref_early.x_s)) < 1e-3 * P.clearance


def test_limit_matches_the_engine_on_the_first_impact_and_the_early_motion(limit_runs, engine_runs):
    (fine, early), (steps, engine_fine, engine_early) = limit_runs, engine_runs
    # with output at every step, the first sample in contact is the located onset
    onset = steps.time[np.argmax(steps["B.contact"] > 0.5)]
    assert onset == pytest.approx(fine.impacts[0], rel=1e-6)
    assert np.array_equal(engine_fine.time, fine.t)
    peak = first_contact_peak(engine_fine.time, engine_fine["B.fn"], engine_fine["B.penetration"], onset)
    assert peak == pytest.approx(first_contact_peak(fine.t, fine.fn, fine.penetration, fine.impacts[0]), rel=1e-6)
    assert np.array_equal(engine_early.time, early.t)
    assert np.max(np.abs(engine_early["slider.x"] - early.x_s)) < 1e-3 * P.clearance


def test_limit_at_the_benchmark_tolerance_does_the_work_of_the_scipy_baseline():
    # rtol 1e-6, atol 1e-9, two revolutions, output at every step: what the benchmark times
    run = limit.simulate_limit(rtol=1e-6, atol=1e-9)
    baseline = ref.simulate_reference(rtol=1e-6, atol=1e-9)
    assert run.t[-1] == 2.0 * P.crank_period
    assert np.all(np.diff(run.t) > 0.0) and run.t.size == run.accepted_steps + 1
    # FSAL: six evaluations per attempted step, one for the start, one for the starting-step
    # heuristic and one restart per located onset
    attempts = run.accepted_steps + run.rejected_steps
    assert run.rhs_evaluations == 6 * attempts + 2 + len(run.impacts)
    assert run.impacts[0] == pytest.approx(baseline.impacts[0], rel=1e-6)
    # the same method at the same tolerance: the step count is within 15 % of solve_ivp's RK45
    assert run.accepted_steps == pytest.approx(baseline.n_steps, rel=0.15)
    assert run.peak_contact_force == pytest.approx(float(np.max(run.fn)))
    assert 30 <= len(run.impacts) <= 60  # 35 to 47 between the engine, the baseline and the limit
