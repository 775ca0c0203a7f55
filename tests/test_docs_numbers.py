"""Every number of docs/getting-started.md that comes from a run is what that run gives today.

Each test runs the documented command (or the same model through the Python API) and looks for
the documented text, built from the run's numbers, in the page. When a change of the engine moves
a number, the test fails and shows the text the page should now say.
"""

from __future__ import annotations

import re
import shlex
import shutil
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import jointplay as jp
from jointplay.cli import app

ROOT = Path(__file__).resolve().parents[1]
PAGE = ROOT / "docs" / "getting-started.md"
EXAMPLES = ROOT / "examples"
DRY = EXAMPLES / "flores_slider_crank_dry.toml"
LUBRICATED = EXAMPLES / "flores_slider_crank_lubricated.toml"


def page() -> str:
    return PAGE.read_text(encoding="utf-8")


def prose() -> str:
    """The page with its line breaks and runs of spaces as single spaces."""
    return " ".join(page().split())


def block_starting(first_line: str) -> list[str]:
    """The lines of the page's code block whose first line starts with ``first_line``."""
    lines = page().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith(first_line) and lines[k - 1] == "```")
    end = next(k for k in range(start, len(lines)) if lines[k] == "```")
    return lines[start:end]


def count(n: int) -> str:
    return f"{n:,}".replace(",", " ")


def assert_in_page(text: str) -> None:
    assert text in prose(), f"docs/getting-started.md should say: {text!r}"


def assert_lines_in_order(documented: list[str], printed: list[str]) -> None:
    """Each documented line other than ``...`` is a printed line, in the same order."""
    position = 0
    for line in documented:
        if line.strip() == "...":
            continue
        try:
            position = printed.index(line.rstrip(), position) + 1
        except ValueError:
            raise AssertionError(f"documented line not printed (in this order): {line!r}\nprinted:\n"
                                 + "\n".join(printed)) from None


def run_cli(*args: str, columns: int = 130):
    result = CliRunner().invoke(app, [str(a) for a in args], env={"COLUMNS": str(columns)})
    return result


@pytest.fixture(scope="module")
def dry_every_step():
    model = jp.load(DRY)
    options = dict(model.simulation)
    return model, model.simulate(options.pop("t_end"), **options)


# section 3: a mistake in the model file ------------------------------------------------------

def test_the_documented_check_error_is_what_check_prints(tmp_path, monkeypatch):
    assert "mkdir -p work && cp examples/flores_slider_crank_dry.toml work/crank.toml" in page()
    assert_in_page('after changing `clearance = "0.5 mm"` to `clearence = "-0.5 mm"`')
    monkeypatch.chdir(tmp_path)
    (tmp_path / "work").mkdir()
    text = DRY.read_text(encoding="utf-8")
    assert text.count('clearance = "0.5 mm"') == 1
    (tmp_path / "work" / "crank.toml").write_text(text.replace('clearance = "0.5 mm"', 'clearence = "-0.5 mm"'))
    result = run_cli("check", "work/crank.toml")
    assert result.exit_code == 2
    assert_lines_in_order(block_starting("error: work/crank.toml"), result.output.splitlines())


# section 4: the summary ----------------------------------------------------------------------

def test_the_documented_summary_is_what_the_documented_run_prints(tmp_path):
    command = 'jointplay run work/crank.toml -o work/dry_1ms.nc --output-step "1 ms"'
    assert command in page()
    result = run_cli("run", DRY, "-o", tmp_path / "dry_1ms.nc", "--output-step", "1 ms")
    assert result.exit_code == 0, result.output
    documented = block_starting("flores_slider_crank_dry: 25 samples saved")
    assert_lines_in_order(documented, result.stdout.splitlines())


def test_the_numbers_around_the_summary_are_those_of_the_run(tmp_path, dry_every_step):
    model, every_step = dry_every_step
    assert_in_page(f"By default a sample is saved at every accepted step ({count(len(every_step))} samples for the "
                   "24 ms of this model)")
    options = {k: v for k, v in model.simulation.items() if k != "t_end"}
    coarse = model.simulate(0.024, **{**options, "output_step": 1e-3})
    peak = coarse.extrema["channels"]["B.fn"]
    sampled = float(np.max(np.abs(coarse["B.fn"])))
    assert len(coarse) == 25
    assert_in_page(f"The 25 samples above never come near the {peak['peak'] / 1e3:.1f} kN impact at "
                   f"{peak['time'] * 1e3:.2f} ms (their largest contact force is {sampled / 1e3:.3g} kN)")
    # the same peak with a sample at every step, as the page says
    assert every_step.extrema["channels"]["B.fn"]["peak"] == pytest.approx(peak["peak"], rel=1e-12)
    assert_in_page(f"a run saved every 1 ms still shows its {peak['peak'] / 1e3:.1f} kN first impact")


# section 6: which numbers to trust in a dry clearance joint -----------------------------------

def disturbed(model: jp.Model, factor: float) -> jp.Model:
    spec = model.to_spec()
    slider = next(b for b in spec["bodies"] if b["name"] == "slider")
    slider["position"][0] *= factor
    return jp.Model.from_spec(spec)


def statistics(results: jp.Results) -> dict:
    """Onset times [s] of the contact periods and the statistics of the page's table."""
    t, contact, fn = results.time, results["B.contact"] > 0.5, results["B.fn"]
    onsets = np.flatnonzero(contact[1:] & ~contact[:-1]) + 1
    first_end = next(k for k in range(onsets[0], t.size) if not contact[k])
    return {"onsets": t[onsets], "first_time": t[onsets[0]], "first_peak": fn[onsets[0]:first_end].max(),
            "peak": fn.max(), "peak_ax": np.abs(results["slider.ax"]).max(),
            "envelope": np.hypot(results["B.ex"], results["B.ey"]).max(),
            "contact_fraction": results.summary()["clearance_joints"]["B"]["contact_fraction"],
            "impacts": int(results.diagnostics["impacts"][0])}


def test_the_table_of_what_a_round_off_disturbance_changes_is_measured(dry_every_step):
    model, base_run = dry_every_step
    options = {k: v for k, v in model.simulation.items() if k != "t_end"}
    base = statistics(base_run)
    moved = [statistics(disturbed(model, 1 + sign * 1e-15).simulate(0.024, **options)) for sign in (+1, -1)]

    def change(run: dict, key: str) -> float:
        return abs(run[key] / base[key] - 1)

    assert_in_page("moving the slider's start by 1e-15 of its value")
    for run in moved:
        assert change(run, "first_time") < 1e-12
        assert max(change(run, key) for key in ("first_peak", "peak", "peak_ax")) < 1e-6
        assert change(run, "envelope") < 1e-8
    assert_in_page("| time of the first impact | below 1e-12 |")
    assert_in_page("| peak force of the first impact, peak contact force, peak slider acceleration | below 1e-6 |")
    assert_in_page("| orbit envelope (largest eccentricity) | below 1e-8 |")
    fractions = " and ".join(f"{100 * change(run, 'contact_fraction'):.1f} %" for run in moved)
    assert_in_page(f"| fraction of time in contact | {fractions} |")
    agree, until, shifted = [], [], []
    for run in moved:
        n = min(len(base["onsets"]), len(run["onsets"]))
        shift = np.abs(run["onsets"][:n] - base["onsets"][:n])
        k = int(np.argmax(shift >= 1e-6))
        agree.append(str(k))
        until.append(f"{base['onsets'][k - 1] * 1e3:.1f}")
        shifted.append(f"{shift.max() * 1e3:.1f}")
    assert_in_page(f"| impact times | equal to 1 µs for the first {' and '.join(agree)} impacts (up to "
                   f"{' and '.join(until)} ms), then shifted by up to {' and '.join(shifted)} ms |")
    assert_in_page(f"| number of impacts in two revolutions | {base['impacts']} becomes "
                   f"{' and '.join(str(run['impacts']) for run in moved)} |")


# section 8: the lubricated joint --------------------------------------------------------------

def documented_overrides(command_start: str) -> list[str]:
    """The ``--set`` values of the page's command line starting with ``command_start``."""
    line = next(line for line in page().splitlines() if line.startswith(command_start))
    words = shlex.split(line)
    return [words[k + 1] for k, word in enumerate(words) if word == "--set"]


def test_the_lubricated_example_uses_the_implicit_method_as_documented():
    model = jp.load(LUBRICATED)
    assert model.simulation["method"] == "bdf"
    rtol = f"{model.simulation['rtol']:g}".replace("e-0", "e-")  # 3e-7 as the file writes it
    assert_in_page(f'its `[simulation]` table sets `method = "bdf"`, with `rtol = {rtol}`')


def test_the_documented_explicit_run_of_the_lubricated_example_takes_the_documented_steps():
    overrides = documented_overrides("jointplay run examples/flores_slider_crank_lubricated.toml --set")
    assert "simulation.method=dopri5" in overrides
    implicit, explicit = jp.load(LUBRICATED), jp.load(LUBRICATED, overrides)
    steps = []
    for model in (implicit, explicit):
        options = dict(model.simulation)
        steps.append(model.simulate(options.pop("t_end"), **options).statistics["accepted_steps"])
    assert_in_page(f"It takes about {round(steps[1] / steps[0])} times as many accepted steps as the example's "
                   "own settings")


def test_no_doc_switches_an_example_to_the_method_it_already_uses():
    pattern = re.compile(r"jointplay run (examples/\S+\.toml)([^\n`]*)")
    found = 0
    for doc in [*(ROOT / "docs").glob("*.md"), ROOT / "README.md"]:
        for path, rest in pattern.findall(doc.read_text(encoding="utf-8")):
            method = re.search(r"--set simulation\.method=(\w+)", rest)
            if method is None or not (ROOT / path).is_file():
                continue
            found += 1
            assert jp.load(ROOT / path).simulation.get("method") != method.group(1), (
                f"{doc.name}: advises --set simulation.method={method.group(1)} for {path}, which already uses it")
    assert found >= 1


def test_the_page_runs_from_a_copy_of_the_dry_example(tmp_path):
    # work/crank.toml of the page is the dry example: the runs above use the example itself
    shutil.copy(DRY, tmp_path / "crank.toml")
    assert jp.load(tmp_path / "crank.toml").to_spec() == jp.load(DRY).to_spec()
