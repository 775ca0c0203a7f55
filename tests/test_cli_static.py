"""``jointplay static``: the equilibrium of a model file printed; no equilibrium and bad input located."""

from __future__ import annotations

import math
from pathlib import Path

from typer.testing import CliRunner

from jointplay.cli import app

ROOT = Path(__file__).resolve().parents[1]
HUNG = ROOT / "tests" / "fixtures" / "hung_block.toml"


def invoke(*args: str):
    return CliRunner().invoke(app, list(args), env={"COLUMNS": "120"})


def test_static_prints_where_the_block_rests_and_what_carries_it():
    result = invoke("static", str(HUNG))
    assert result.exit_code == 0, result.output
    text = " ".join(result.output.split())
    # the Hertz-cylinder penetration of the 98.1 N load (tests/physics/test_static_equilibrium.py computes it)
    k = 4.0 / 3.0 * (207e9 / (2 * (1 - 0.3**2))) * math.sqrt(0.010 * 0.0095 / 0.0005)
    penetration = (98.1 / k) ** (1 / 1.5)
    assert f"│ block │ 0.0000 │ {-(0.5e-3 + penetration) * 1e3:.4f} │ 0.0000 │" in text
    assert "│ B │ fn │ 98.1 │ N │" in text
    assert f"│ B │ penetration │ {penetration * 1e6:.6g} │ um │" in text
    assert "static equilibrium at t0 = 0 s" in text


def test_static_names_the_body_nothing_holds(tmp_path):
    model = tmp_path / "falling.toml"
    model.write_text('[model]\ngravity = [0, "-9.81 m/s^2"]\n\n[bodies.stone]\nmass = "1 kg"\ninertia = "0.01 kg m^2"\n'
                     'position = [0, 0]\nfree = true\n', encoding="utf-8")
    result = invoke("static", str(model))
    assert result.exit_code == 1
    text = " ".join(result.output.split())
    assert "no static equilibrium at t = 0.000000e0 s: stone has an unbalanced load of 9.8100e0 N" in text
    assert "Traceback" not in result.output


def test_static_reports_a_bad_override_at_its_key():
    result = invoke("static", str(HUNG), "--set", "bodies.block.mass=-1 kg")
    assert result.exit_code == 2
    assert "bodies.block.mass" in result.output


def test_a_model_file_may_start_its_run_at_equilibrium(tmp_path):
    # the fixture's [simulation] table says initial = "equilibrium": the run stays at rest in contact. The
    # contact is stiff (98.1 N at 1.3 um of penetration: 1.1e8 N/m there), so the integrator's position error
    # (atol 1e-9 m, rtol 1e-9) of a few 1e-12 m shows as 1e-4 N
    result = invoke("run", str(HUNG), "-o", str(tmp_path / "hung.nc"))
    assert result.exit_code == 0, result.output
    import xarray as xr

    with xr.open_dataset(tmp_path / "hung.nc") as data:
        assert float(abs(data["B.fn"] - 98.1).max()) < 1e-3
