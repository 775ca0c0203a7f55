"""Mutated model files through the CLI: exit 0, 1 (simulation failed) or 2 (bad input), quickly; never a
traceback, an abort or a hang.

Model files are made by mutating the examples: types, units, signs, sizes, names and structure (tables
dropped, duplicated or renamed, references swapped, numbers huge, tiny, NaN or infinite, strings with odd
units, tables where scalars belong). ``check`` and short runs go through typer's CliRunner in this process;
a few runs go through a subprocess with a timeout, where an abort or a hang would show.
"""

from __future__ import annotations

import copy
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from jointplay.cli import app
from jointplay.modelfile.writer import _key, _value

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
BASES = [tomllib.loads(path.read_text()) for path in EXAMPLES]
SECTIONS = ("bodies", "joints", "drivers", "forces")

NUMBERS = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**30, 10**30),
                    st.sampled_from([0, -1, 10**400, 1e-320, 1e308]))
ODD_TEXT = st.sampled_from([
    "5 kg", "0.1 mm", "-1 mm", "3 rpm", "1e308 m", "1e-300 m", "1e999 m", "10**10**8 kg", "1" * 400 + " kg",
    "nan mm", "inf s", "-0 mm", "1 m^99", "1 m**99**99", "1 mm)", "((", "", " ", "abc", "10 Hz", "90 deg",
    "1 \u00b5m", "5 furlong", "1 mm/s/s", "2 N m/rad", "400 cP", "1 %", "ground.O", "rod.X", "crank.A",
    "revolute", "hertz", "none", "table", "reynolds_exact", "__import__('os')", "caf\u00e9", "\\u0000 x",
])
# tables are drawn as fresh copies: a mutation that edits a drawn table in place must not change what
# later draws return (hypothesis replays draws and reports the strategy flaky when they differ)
TABLES = st.sampled_from([{}, {"law": "hertz"}, {"kind": "table"}, {"a": {"b": 1}}]).map(copy.deepcopy)
ODD_VALUES = st.one_of(NUMBERS, st.booleans(), ODD_TEXT, st.lists(NUMBERS | ODD_TEXT, max_size=3), TABLES)


UNITS = st.one_of(st.dictionaries(st.sampled_from(["length", "mass", "time", "angle", "velocity", "pressure",
                                                   "angular_velocity", "lenght", "dimensionless"]),
                                   ODD_TEXT | st.sampled_from(["mm", "g", "ms", "deg", "rpm", "mm/s", "GPa", "kg"]),
                                   max_size=4),
                   ODD_VALUES)


def _number(text: str) -> float | str:
    """The number of a quantity string as a TOML number, when it is one."""
    try:
        return float(text)
    except ValueError:
        return text


def _paths(node, path=()):
    """Every path to a value in a parsed document."""
    if path:
        yield path
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _paths(v, (*path, k))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from _paths(v, (*path, i))


def _parent(doc, path):
    for key in path[:-1]:
        doc = doc[key]
    return doc


def _strings(doc) -> list[str]:
    return [v for p in _paths(doc) if isinstance(v := _parent(doc, p)[p[-1]], str)]


@st.composite
def mutated(draw) -> dict:
    doc = copy.deepcopy(draw(st.sampled_from(BASES)))
    for _ in range(draw(st.integers(1, 4))):
        paths = list(_paths(doc))
        if not paths:
            break
        path = draw(st.sampled_from(paths))
        try:
            _mutate(draw, doc, path)
        except (KeyError, IndexError, TypeError):
            pass  # an earlier mutation changed the shape under this path
    return doc


def _mutate(draw, doc: dict, path: tuple) -> None:
    parent, key = _parent(doc, path), path[-1]
    action = draw(st.sampled_from(["replace", "delete", "duplicate", "rename", "swap", "scale", "nest", "add",
                                   "bare", "units"]))
    if action == "bare" and isinstance(parent[key], str):
        number = parent[key].partition(" ")[0]
        parent[key] = draw(st.sampled_from([number, _number(number)]))
    elif action == "units":
        doc["units"] = draw(UNITS)
    elif action == "replace":
        parent[key] = draw(ODD_VALUES)
    elif action == "delete" and isinstance(parent, dict):
        del parent[key]
    elif action == "duplicate" and isinstance(parent, dict):
        parent[f"{key}_copy"] = copy.deepcopy(parent[key])
    elif action == "rename" and isinstance(parent, dict):
        parent[draw(st.sampled_from(["x", "ground", "a.b", "", " B", "B", "crank", "O"]))] = parent.pop(key)
    elif action == "swap":
        strings = _strings(doc)
        if strings:
            parent[key] = draw(st.sampled_from(strings))
    elif action == "scale" and isinstance(parent[key], str):
        number, _, unit = parent[key].partition(" ")
        parent[key] = draw(st.sampled_from([f"-{number} {unit}", f"{number}e12 {unit}", f"{number}e-12 {unit}",
                                            f"0 {unit}"]))
    elif action == "nest":
        parent[key] = {"value": parent[key], "extra": {"deeper": [1, 2]}}
    elif action == "add" and isinstance(parent[key], dict):
        parent[key][draw(st.sampled_from(["extra", "mass", "type", "law", "kind", "rate", "clearance", "cavitation",
                                           "grid", "units"]))] = draw(ODD_VALUES)


def to_text(doc: dict) -> str:
    """TOML text of a document: each section as an inline table (any document can be written so)."""
    return "\n".join(f"{_key(k)} = {_value(v)}" for k, v in doc.items()) + "\n"


def _no_crash(result, allowed: set[int]) -> None:
    assert result.exit_code in allowed, (result.exit_code, result.output)
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(result.exception)
    assert "Traceback" not in result.output


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated())
def test_check_of_a_mutated_example_exits_0_or_2(tmp_path_factory, doc):
    path = tmp_path_factory.mktemp("fuzz") / "model.toml"
    path.write_text(to_text(doc), encoding="utf-8")
    _no_crash(CliRunner().invoke(app, ["check", str(path)]), {0, 2})


# bounded runs: few steps and samples, so that a run ends quickly whatever the mutation
BOUNDED = ["--t-end", "0.2 ms", "-q", "--set", "simulation.max_steps=20000",
           "--set", 'simulation.output_step="0.01 ms"']


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated())
def test_short_run_of_a_mutated_example_exits_0_1_or_2(tmp_path_factory, doc):
    folder = tmp_path_factory.mktemp("fuzz")
    (folder / "model.toml").write_text(to_text(doc), encoding="utf-8")
    result = CliRunner().invoke(app, ["run", str(folder / "model.toml"), "-o", str(folder / "out.nc"), *BOUNDED])
    _no_crash(result, {0, 1, 2})
    if result.exit_code == 1:
        assert "simulation failed" in result.stderr


EXTREME = [  # legal values far out of range: the run must end (a result, a failed run or a model error)
    ("flores_slider_crank_dry", ["bodies.rod.mass=1e-12 kg"]),
    ("flores_slider_crank_dry", ["drivers.motor.function.rate=1e9 rpm", "joints.B.clearance=1e-9 mm"]),
    ("flores_slider_crank_lubricated", ["joints.B.lubrication.viscosity=1e9 cP"]),
    ("paper001_slider_crank_dry", ["joints.B.bearing_material.youngs_modulus=1e-3 GPa",
                                   "joints.B.journal_material.youngs_modulus=1e3 TPa"]),
]


@pytest.mark.parametrize("stem, overrides", EXTREME, ids=[" ".join(o) for _, o in EXTREME])
def test_extreme_runs_in_a_process_never_abort_or_hang(tmp_path, stem, overrides):
    sets = [arg for o in overrides for arg in ("--set", o)]
    command = [sys.executable, "-m", "jointplay.cli", "run", str(ROOT / "examples" / f"{stem}.toml"),
               "-o", str(tmp_path / "out.nc"), *BOUNDED, *sets]
    done = subprocess.run(command, capture_output=True, text=True, timeout=60)
    assert done.returncode in (0, 1, 2), done.stderr
    assert "Traceback" not in done.stderr and "panicked" not in done.stderr
