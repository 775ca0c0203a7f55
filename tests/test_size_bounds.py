"""Sizes that allocate in the core are bounded with a clear message, before anything is allocated.

A Reynolds grid of 100 000 x 100 000 would need about 120 GB and abort the
process; the bound is defined once in the core (``MAX_GRID_NODES``) and read
from there by the model-file path and by ``jointplay bearing --grid``.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

import jointplay as jp
from jointplay import _core
from jointplay.cli import app

ROOT = Path(__file__).resolve().parents[1]
LUBRICATED = ROOT / "examples" / "flores_slider_crank_lubricated.toml"
LINE = 'lubrication = { model = "pinkus_sternlicht_long", viscosity = "400 cP", transition = { law = "wang_improved" } }'


def with_grid(grid: str) -> str:
    text = LUBRICATED.read_text()
    assert LINE in text
    return text.replace(LINE, f'lubrication = {{ model = "reynolds_exact", viscosity = "400 cP", grid = {grid} }}')


def test_the_bound_comes_from_the_core():
    assert _core.MAX_REYNOLDS_GRID_NODES == 1_000_000
    assert _core.MAX_FORCE_TABLE_NODES == 65_536


def test_oversized_grid_in_a_model_file_is_reported_at_its_key():
    with pytest.raises(jp.ModelError) as info:
        jp.loads(with_grid("[100000, 100000]")).compile()
    assert [str(p) for p in info.value.problems] == [
        "joints.B.lubrication.grid: grid 100000 x 100000 has 5000100000 nodes on the half length, more than the "
        "limit of 1000000 (n_circumferential x (n_axial/2 + 1); solver memory and time grow with it)"]


def test_grid_counts_beyond_any_integer_type_are_reported_at_their_key():
    with pytest.raises(jp.ModelError) as info:
        jp.loads(with_grid("[100000000000000000000000000000, 4]")).compile()
    assert [str(p) for p in info.value.problems] == [
        "joints.B.lubrication.grid: a grid has at most 1000000 nodes, got [100000000000000000000000000000, 4]"]


def test_a_grid_at_the_bound_passes_validation():
    # 2000 x (998/2 + 1) = 1 000 000 nodes: accepted (compiling sets up the solver once, 24 MB)
    jp.loads(with_grid("[2000, 998]")).compile()


def test_oversized_grid_in_a_model_file_exits_2_from_the_command(tmp_path):
    model = tmp_path / "big_grid.toml"
    model.write_text(with_grid("[100000, 100000]"))
    result = subprocess.run([sys.executable, "-m", "jointplay.cli", "check", str(model)], capture_output=True,
                            text=True, timeout=120)
    assert result.returncode == 2, result.stderr
    assert "joints.B.lubrication.grid: grid 100000 x 100000 has 5000100000 nodes" in result.stderr
    assert "Traceback" not in result.stderr


@pytest.mark.parametrize("grid, nodes", [("100000x100000", 5000100000), ("2001x998", 1000500),
                                         ("1000000000000000000000000x4", 3000000000000000000000000)])
def test_oversized_bearing_grid_exits_2_with_one_message(grid, nodes):
    result = CliRunner().invoke(app, ["bearing", "--l-over-d", "1", "-e", "0.5", "--grid", grid])
    assert result.exit_code == 2, result.output
    assert result.stderr.strip() == (
        f"error: --grid: {grid} has {nodes} nodes on the half length, more than the limit of 1000000 "
        f"(N_CIRCUMFERENTIAL x (N_AXIAL/2 + 1)), got '{grid}'")


def test_oversized_grid_through_the_python_bearing_api_is_a_value_error():
    from jointplay import bearing

    with pytest.raises(ValueError, match=r"^grid 100000 x 100000 has 5000100000 nodes on the half length"):
        bearing.steady(1.0, eccentricity_ratio=0.5, n_circumferential=100_000, n_axial=100_000)
