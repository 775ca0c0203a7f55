"""Every example still computes what it computed before the engine rework (commit 8193766).

tests/baselines/examples_before_rework.json holds, per example case, the first impact of each
clearance joint (onset, time and value of the first local maximum of the contact force), the number
of impacts, the fraction of time in contact, the thinnest film of lubricated joints, and every peak
the core tracks; tests/baselines/record_examples.py measured them (and says how) and rewrites the
file. Here each case is run again with the same functions and compared.

Tolerances. Each quantity is allowed to move by

    tol = max(1e-3, 2 * spread)        (relative; absolute where the recorded value is 0)

and an impact count by 2 * spread impacts, where ``spread`` is recorded with the value: the largest
deviation seen when the case was rerun 16 times with its initial positions disturbed by 1e-15 to 1e-9
(relative) and with rtol halved and doubled. Why:

- 1e-3 where the dynamics is smooth. Up to the first impact the motion is smooth and the first
  impact is a smooth function of it, so any correct formulation gives the same onset, peak time and
  peak force up to the integration error: halving or doubling rtol moved them by at most 3e-7
  (the record's spreads), so 1e-3 leaves a reworked engine three orders of magnitude of room
  while still catching a change of the contact law, damping, mass or impact velocity (a 1e-3 change
  of the peak force is a 7e-4 change of the impact velocity: Hertz force ~ v^1.2). The same holds for
  runs that never touch: ideal joints and lubricated joints whose film never breaks.
- 2 * spread where it is not. After the first impacts free flight in a dry clearance is chaotic
  (docs/getting-started.md, "Which numbers to trust in a dry clearance joint";
  tests/test_example_pairs.py): 1e-15 on one input moves the later impacts by milliseconds, so the
  impact count (28 to 51 for the Flores dry run's 43), the contact fraction (19 %), and peaks reached
  after the first impacts (the motor torque by 49 %) are draws from a distribution, not numbers a
  new engine can reproduce. The record's 16 disturbed runs sample that distribution; a reworked engine
  is one more draw, and twice the largest deviation of 16 draws is rarely exceeded by chance, while a
  result outside it means the statistics changed. A few smooth runs need this too: the paper 000
  film joints end with the film almost used up, where the peaks move by up to 3.5 % with rtol.
- Peaks that are round-off (a channel whose true value is zero, e.g. the angular acceleration of a
  crank driven at constant speed, 2e-9 rad/s^2 against the rod's 2e6): recorded below 1e-9 of the
  largest peak of the same unit in the case, they must stay below 1e-6 of it. When every peak of
  that unit was exactly zero (the reaction moment of a slider guide loaded through the slider's
  centre, the only N m channel of the paper 000 cases), they must stay below 1e-9 in SI units: the
  joint-coordinate formulation leaves 2e-14 N m of round-off there.

Times of peaks other than the first impact's are not compared: a smooth maximum's time is
ill-conditioned, and a driven periodic run has equal peaks in each revolution.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

BASELINES = Path(__file__).resolve().parent / "baselines"
sys.path.insert(0, str(BASELINES))
import record_examples as rec  # noqa: E402

BASELINE = json.loads((BASELINES / "examples_before_rework.json").read_text(encoding="utf-8"))
CASES = BASELINE["cases"]

SMOOTH_TOLERANCE = 1e-3  # relative, see the module docstring
SPREAD_FACTOR = 2.0
ROUND_OFF = 1e-9  # a recorded peak below this fraction of the largest of its unit is round-off
STAYS_ROUND_OFF = 1e-6  # ... and must stay below this fraction
EXACT_ZERO_STAYS_BELOW = 1e-9  # SI units: a round-off peak of a unit whose recorded peaks are all zero


def test_the_record_covers_every_example_at_the_recorded_commit():
    assert BASELINE["recorded_at_commit"] == "8193766"
    assert set(CASES) == set(rec.cases())
    examples = rec.ROOT / "examples"
    for stem in rec.MODEL_FILES:
        assert (examples / f"{stem}.toml").exists()
    for stem in rec.SCRIPTS:
        assert (examples / f"{stem}.py").exists()
        assert any(name.startswith(f"{stem}.py") for name in CASES), stem


def round_off_scale(record: dict, path: str) -> float:
    """Largest peak with the unit of the peak at ``path`` in the case (point accelerations: of all points)."""
    section, name = path.split("/", 1)
    if section == "point_accelerations":
        return max(p["peak"] for p in record["point_accelerations"].values())
    unit = record["peaks"][name]["unit"]
    return max(p["peak"] for p in record["peaks"].values() if p["unit"] == unit)


def problems(recorded: dict, now: dict) -> list[str]:
    """Every compared quantity of ``now`` outside its tolerance around ``recorded``, one line each."""
    base, new = rec.compared(recorded), rec.compared(now)
    out = []
    if set(new) != set(base):
        out.append(f"quantities differ: new {sorted(set(new) - set(base))}, gone {sorted(set(base) - set(new))}")
    for path, value in base.items():
        if path not in new:
            continue
        if path.startswith(("peaks/", "point_accelerations/")):
            scale = round_off_scale(recorded, path)
            if value <= ROUND_OFF * scale:
                if new[path] > max(STAYS_ROUND_OFF * scale, EXACT_ZERO_STAYS_BELOW if scale == 0 else 0.0):
                    out.append(f"{path}: {new[path]:.6g}, was round-off ({value:.3g}; largest {scale:.6g})")
                continue
        spread = recorded["spread"][path]
        if path.endswith("/impacts"):
            tol = SPREAD_FACTOR * spread
        else:
            tol = max(SMOOTH_TOLERANCE, SPREAD_FACTOR * spread)
        off = rec.deviation(path, new[path], value)
        if off > tol:
            out.append(f"{path}: {new[path]!r}, recorded {value!r} (off by {off:.3g}, tolerance {tol:.3g})")
    return out


@pytest.mark.parametrize("name", list(CASES))
def test_example_computes_what_it_did_before_the_rework(name):
    found = problems(CASES[name], rec.measure(name))
    assert not found, "\n".join(found)
