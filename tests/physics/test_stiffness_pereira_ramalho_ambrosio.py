"""The Pereira-Ramalho-Ambrosio stiffness law through the whole engine, on the dry Flores slider-crank.

Before its first impact the mechanism moves the same way whatever the stiffness law, so the first impact
meets both laws with the same approach energy. For a power law F = K delta^n the peak force of an impact of
energy W is K^(1/(n+1)) ((n+1) W)^(n/(n+1)): a law r times as stiff gives a peak r^(1/(n+1)) times as high.
The fit and Johnson's law agree within a factor r in [0.8, 1.2] over the joint's penetrations (the Rust
tests of contact/pereira_ramalho_ambrosio.rs), and n is 1.163 at this clearance, so the first impact's peak
force must lie within [0.8^0.462, 1.2^0.462] = [0.902, 1.088] times Johnson's. A stiffness off by the units
(a factor 3 at this exponent) would move the peak by 3^0.462 = 1.66.
"""

from pathlib import Path

import pytest

import jointplay as jp
from jointplay import laws

ROOT = Path(__file__).resolve().parents[2]
DRY = ROOT / "examples" / "flores_slider_crank_dry.toml"
#: the fit's exponent n = Y dR^-0.005 at dR = 0.5 mm, Y = 0.0151 * 0.5 + 1.151 (docs/theory)
EXPONENT = (0.0151 * 0.5 + 1.151) * 0.5**-0.005
#: the band of the static force ratio of the two laws (contact/pereira_ramalho_ambrosio.rs)
STATIC_RATIO = (0.8, 1.2)
#: the first impact of the run is at about 0.24 ms, the window holds it and seven more
T_END = 2e-3


def first_impact_peak(stiffness: dict) -> tuple[float, float, int]:
    """Peak joint force [N], its time [s] and the number of impacts of the dry slider-crank's first 2 ms."""
    model = jp.load(DRY)
    model.joint("B")["stiffness"] = stiffness
    assert model.joint("B")["length"] == pytest.approx(0.040)
    results = model.simulate(T_END, method="dopri5", rtol=1e-6, atol=1e-9, max_step=1e-4)
    peak = results.extrema["channels"]["B.f"]
    return peak["peak"], peak["time"], results.summary()["clearance_joints"]["B"]["impacts"]


def test_first_impact_peak_follows_the_static_agreement_with_johnson():
    johnson, johnson_time, johnson_impacts = first_impact_peak(laws.johnson_line())
    fitted, fitted_time, fitted_impacts = first_impact_peak(laws.pereira_ramalho_ambrosio())
    # the peaks are those of the first impact, met by both laws from the same motion
    assert fitted_time == pytest.approx(johnson_time, abs=2e-5)
    assert fitted_time < 0.3e-3
    assert fitted_impacts >= 1 and johnson_impacts >= 1
    low, high = (r ** (1.0 / (EXPONENT + 1.0)) for r in STATIC_RATIO)
    assert low < fitted / johnson < high, f"peak {fitted:.6g} N against Johnson's {johnson:.6g} N"


def test_the_law_needs_the_bearing_length():
    text = DRY.read_text().replace('stiffness = { law = "hertz_cylinder" }',
                                   'stiffness = { law = "pereira_ramalho_ambrosio" }').replace('length = "40 mm"\n', "")
    with pytest.raises(jp.ModelError) as info:
        jp.loads(text)
    assert [str(p) for p in info.value.problems] == [
        'joints.B.length: missing required value: the pereira_ramalho_ambrosio stiffness law needs the bearing '
        'length, e.g. "40 mm"']


def test_the_core_refuses_a_clearance_outside_the_fit():
    model = jp.load(DRY)
    model.joint("B")["stiffness"] = laws.pereira_ramalho_ambrosio()
    model.joint("B")["clearance"] = 4e-6
    with pytest.raises(jp.ModelError) as info:
        model.compile()
    assert [str(p) for p in info.value.problems] == [
        "joints.B.stiffness: radial clearance must lie in [0.005, 10] mm, the range of the "
        "Pereira-Ramalho-Ambrosio fit, got 0.004 mm"]
