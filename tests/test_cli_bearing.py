"""`jointplay bearing`: the printed operating point is bearing.steady's, figures are written, bad input exits 2."""

from __future__ import annotations

import math
import re

import pytest
from typer.testing import CliRunner

from jointplay import bearing
from jointplay.cli import app

GEOMETRY = ["--diameter", "20 mm", "--clearance", "0.02 mm", "--viscosity", "40 cP", "--speed", "3000 rpm"]
SI = dict(radius=0.01, clearance=2e-5, viscosity=0.04, speed=50.0)  # the same in SI, speed in rev/s


def invoke(*args: str):
    return CliRunner().invoke(app, ["bearing", *args])


def value(output: str, label: str) -> float:
    """The number in the value column of the table row starting with ``label``."""
    for line in output.splitlines():
        cells = [c.strip() for c in re.split(r"[│┃]", line) if c.strip()]
        if cells and cells[0] == label:
            return float(cells[2])
    raise AssertionError(f"no row {label!r} in\n{output}")


def no_traceback(result) -> bool:
    return "Traceback" not in result.output and (result.exception is None or isinstance(result.exception, SystemExit))


def assert_dimensionless_rows(output: str, p: bearing.SteadyBearing) -> None:
    rows = {
        "eccentricity ratio": p.eccentricity_ratio,
        "attitude angle (deg)": math.degrees(p.attitude_angle),
        "Sommerfeld number": p.sommerfeld_number,
        "minimum film thickness": p.min_film_thickness_ratio,
        "peak pressure": 1 / p.pressure_ratio,
        "friction variable": p.friction_variable,
        "flow variable": p.flow_variable,
        "side-flow ratio": p.side_flow_ratio,
        "mean-to-peak pressure ratio": p.pressure_ratio,
    }
    for label, expected in rows.items():
        assert value(output, label) == pytest.approx(expected, rel=6e-4), label  # printed to 4 figures


def test_help_stands_on_its_own():
    result = CliRunner().invoke(app, ["bearing", "--help"])
    assert result.exit_code == 0
    for word in ("--l-over-d", "--eccentricity", "--load", "--chart", "--pressure", "Sommerfeld", "Raimondi",
                 "Exit codes", '"3000 rpm"'):
        assert word in result.output
    assert "bearing" in CliRunner().invoke(app, ["--help"]).output


def test_by_eccentricity_prints_the_steady_point():
    result = invoke("--l-over-d", "1/2", "--eccentricity", "0.6")
    assert result.exit_code == 0, result.output
    assert_dimensionless_rows(result.output, bearing.steady(0.5, eccentricity_ratio=0.6))
    assert "dimensional" not in result.output


def test_by_load_prints_the_steady_point_and_its_dimensional_values():
    result = invoke("--l-over-d", "1", "--load", "1.6 kN", *GEOMETRY)
    assert result.exit_code == 0, result.output
    p = bearing.steady(1.0, load=1600.0, **SI)
    assert_dimensionless_rows(result.output, p)
    assert 0.55 < p.eccentricity_ratio < 0.65
    dimensional = result.output.split("dimensional", 1)[1]  # the second table
    assert value(dimensional, "load") == pytest.approx(1.6)  # kN
    assert value(dimensional, "mean pressure") == pytest.approx(4.0)  # 1600 N / (20 mm)^2, MPa
    assert value(dimensional, "minimum film thickness") == pytest.approx(p.min_film_thickness * 1e6, rel=6e-4)
    assert value(dimensional, "peak pressure") == pytest.approx(p.peak_pressure * 1e-6, rel=6e-4)
    assert value(dimensional, "friction torque") == pytest.approx(p.friction_torque, rel=6e-4)
    assert value(dimensional, "power loss") == pytest.approx(p.power_loss, rel=6e-4)
    assert value(dimensional, "flow into the film") == pytest.approx(p.flow * 6e7, rel=6e-4)  # ml/min


def test_chart_and_pressure_figures_are_written(tmp_path):
    chart, field = tmp_path / "chart.png", tmp_path / "field.svg"
    result = invoke("--l-over-d", "1", "-e", "0.6", *GEOMETRY, "--chart", str(chart), "--pressure", str(field),
                    "--grid", "48x8")
    assert result.exit_code == 0, result.output
    assert chart.stat().st_size > 10_000 and field.stat().st_size > 5_000
    assert f"wrote {chart}" in result.output and f"wrote {field}" in result.output


@pytest.mark.parametrize("args, message", [
    (["--l-over-d", "1"],
     "error: --eccentricity, --load: give one of them (the operating point by eccentricity ratio or by load), "
     "or only --chart"),
    (["--l-over-d", "1", "-e", "0.5", "--load", "2 kN", *GEOMETRY],
     "error: --eccentricity, --load: give one of them, not both"),
    (["--l-over-d", "1", "--load", "2 kg", *GEOMETRY],
     "error: --load: must be a force (e.g. \"100 N\"), got '2 kg', which is a mass"),
    (["--l-over-d", "1", "--load", "2 kN", *GEOMETRY[:2], "--clearance", "-0.05 mm", *GEOMETRY[4:]],
     "error: --clearance: must be > 0, got -0.05 mm"),
    (["--l-over-d", "1", "--load", "2 kN", "--radius", "10 mm"],
     "error: --load: needs the journal radius, clearance, viscosity and speed; missing --clearance, --viscosity, --speed"),
    (["--l-over-d", "1", "-e", "1.2"], "error: --eccentricity: must be between 0 and 1 (exclusive), got 1.2"),
    (["-e", "0.5"], "error: --l-over-d: missing; give the length over diameter of the bearing, e.g. --l-over-d 1"),
    (["--l-over-d", "1", "--load", "2000 kN", *GEOMETRY], "error: --load: load 2000000 N is too heavy"),
    (["--l-over-d", "1", "-e", "0.5", *GEOMETRY[:6], "--speed", "50 Hz"],
     "error: --speed: Hz is ambiguous for an angular speed; write rpm, rev/s or rad/s, got '50 Hz'"),
    (["--l-over-d", "1", "-e", "0.5", "--chart", "no/such/folder/c.png"], "error: --chart: no folder no/such/folder"),
])
def test_bad_input_exits_2_with_one_message(args, message):
    result = invoke(*args)
    assert result.exit_code == 2, result.output
    assert result.stderr.startswith(message), result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert no_traceback(result)


def test_every_problem_is_reported_at_once():
    result = invoke("--l-over-d", "x", "-e", "0.5", "--radius", "10 mm", "--clearance", "5 kg", "--grid", "12x7")
    assert result.exit_code == 2
    assert result.stderr.splitlines() == [
        "error: 4 problems with the options",
        "  --l-over-d: must be a plain number such as 0.5 or 1/2, got 'x'",
        "  --clearance: must be a length (e.g. \"0.5 mm\"), got '5 kg', which is a mass",
        "  dimensional results need --radius (or --diameter), --clearance, --viscosity and --speed; missing "
        "--viscosity, --speed",
        "  --grid: must be N_CIRCUMFERENTIAL x N_AXIAL with N_CIRCUMFERENTIAL >= 8 and N_AXIAL even >= 2, "
        "e.g. 120x16, got '12x7'",
    ]
    assert no_traceback(result)


def test_chart_alone_needs_no_operating_point(tmp_path):
    chart = tmp_path / "chart.png"
    result = invoke("--l-over-d", "1", "--chart", str(chart), "--grid", "48x8")
    assert result.exit_code == 0, result.output
    assert chart.stat().st_size > 10_000 and f"wrote {chart}" in result.output



def test_the_bearing_tables_never_cut_a_number_in_a_narrow_terminal():
    from typer.testing import CliRunner

    from jointplay.cli import app

    wide = CliRunner().invoke(app, ["bearing", "--l-over-d", "1", "--eccentricity", "0.6"], env={"COLUMNS": "200"})
    assert wide.exit_code == 0
    # (plain tables cut 14 cells with an ellipsis at 30 columns, 26 at 20)
    for columns in ("40", "30", "20"):
        narrow = CliRunner().invoke(app, ["bearing", "--l-over-d", "1", "--eccentricity", "0.6"],
                                    env={"COLUMNS": columns})
        assert narrow.exit_code == 0
        assert "…" not in narrow.output
        for value in ("0.1216", "50.53", "3.233", "4.331", "0.6811", "0.4126"):
            assert value in wide.output and value in narrow.output
