"""The spec each example sends to the core is pinned: tests/fixtures/specs/*.json were recorded from the
code before the element parameters were defined once (jointplay.parameters), and every model file and
Python builder of the examples must still give exactly that JSON (same keys, same order, same floats).

When a change of a spec is intended, rewrite the fixtures with ``python tests/test_spec_fixtures.py``
and say why in the commit.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
FIXTURES = ROOT / "tests" / "fixtures" / "specs"


def _toml(path: Path):
    def load():
        import jointplay as jp

        model = jp.load(path)
        return model, model.simulation
    return load


def _python(module: str, *args):
    def build():
        example = __import__(module)
        if module == "paper001_parametric_study":
            args_ = (example.SERIES["clearance"][0],)
        else:
            args_ = args
        return example.build_model(*args_), None
    return build


def _kitchen_sink():
    from test_model_files import kitchen_sink

    return kitchen_sink(), None


CASES = {
    **{f"toml_{p.stem}": _toml(p) for p in sorted((ROOT / "examples").glob("*.toml"))},
    "toml_every_key": _toml(ROOT / "tests" / "fixtures" / "every_key.toml"),
    "py_flores_slider_crank_dry": _python("flores_slider_crank_dry"),
    "py_flores_slider_crank_ideal": _python("flores_slider_crank_ideal"),
    "py_flores_slider_crank_lubricated": _python("flores_slider_crank_lubricated"),
    **{f"py_paper000_{joint}": _python("paper000_joint_models", joint)
       for joint in ("clearance", "squeeze_film", "hydrodynamic")},
    "py_paper001_slider_crank_dry": _python("paper001_slider_crank_dry"),
    "py_paper001_parametric_study": _python("paper001_parametric_study"),
    "py_spin_up_beam": _python("spin_up_beam"),
    "py_kitchen_sink": _kitchen_sink,
}


def recorded(name: str) -> str:
    model, simulation = CASES[name]()
    return json.dumps({"spec": json.loads(model.to_json()), "simulation": simulation}, indent=1) + "\n"


def test_every_example_model_file_has_a_fixture():
    stems = {p.stem for p in (ROOT / "examples").glob("*.toml")}
    assert {f"toml_{s}" for s in stems} <= set(CASES)
    assert {p.stem for p in FIXTURES.glob("*.json")} == set(CASES)


@pytest.mark.parametrize("name", sorted(CASES))
def test_spec_sent_to_the_core_is_unchanged(name):
    assert recorded(name) == (FIXTURES / f"{name}.json").read_text()


if __name__ == "__main__":
    sys.path[:0] = [str(ROOT / "examples"), str(ROOT / "tests")]
    for case in CASES:
        (FIXTURES / f"{case}.json").write_text(recorded(case))
        print("wrote", FIXTURES / f"{case}.json")
