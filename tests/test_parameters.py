"""Each key of a model file is defined once (jointplay.parameters); the schema, the Python builder, the law
helpers, the TOML writer and the reference follow from that definition and agree with each other."""

from __future__ import annotations

import copy
import inspect
import math
import tomllib
from pathlib import Path

import pytest

import jointplay as jp
from jointplay import functions as fn
from jointplay import laws
from jointplay import parameters as p
from jointplay.modelfile import reference, to_toml
from jointplay.modelfile.build import Builder

ROOT = Path(__file__).resolve().parents[1]
EVERY_KEY = ROOT / "tests" / "fixtures" / "every_key.toml"
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))


# the reference -------------------------------------------------------------------

def test_reference_page_is_up_to_date():
    committed = (ROOT / "docs" / "model-file-reference.md").read_text(encoding="utf-8")
    assert committed == reference.text(), ("docs/model-file-reference.md is out of date: run "
                                           "python -m jointplay.modelfile.reference -o docs/model-file-reference.md")


def test_reference_lists_every_key_of_every_table():
    page = reference.text()
    for table in p.all_tables():
        for param in table.params:
            assert f"| `{param.key}` |" in page, (table.name, param.key)


# the builder has no defaults of its own ---------------------------------------------

BUILDER_METHODS = {"add_body": p.BODY, "add_revolute": p.REVOLUTE, "add_translational": p.TRANSLATIONAL,
                   "add_fixed": p.FIXED, "add_spring_damper": p.SPRING_DAMPER,
                   "add_rotational_spring_damper": p.ROTATIONAL_SPRING_DAMPER, "add_point_force": p.POINT_FORCE,
                   "add_torque": p.TORQUE, "add_clearance_revolute": p.CLEARANCE_REVOLUTE,
                   "add_hydraulic_cylinder": p.HYDRAULIC_CYLINDER}


def _arguments(function) -> dict[str, inspect.Parameter]:
    return {k: v for k, v in inspect.signature(function).parameters.items() if k not in ("self", "name")}


@pytest.mark.parametrize("method", sorted(BUILDER_METHODS))
def test_builder_arguments_are_the_keys_of_the_definition_with_its_defaults(method):
    table = BUILDER_METHODS[method]
    arguments = _arguments(getattr(jp.Model, method))
    assert set(arguments) == {param.key for param in table.params if param.in_spec}
    for key, argument in arguments.items():
        param = table[key]
        if param.required or (method == "add_clearance_revolute" and key == "clearance"):
            assert argument.default is inspect.Parameter.empty, key
        elif param.kind == "points" or (param.kind == "law" and method == "add_clearance_revolute"):
            assert argument.default is None, key  # None: the definition's default (no points, its law)
        else:
            assert argument.default == param.default, key


def test_model_and_simulate_defaults_are_the_definitions():
    assert inspect.signature(jp.Model).parameters["gravity"].default == p.MODEL.default("gravity")
    simulate = inspect.signature(jp.Model.simulate).parameters
    for key in ("method", "rtol", "atol", "stabilization", "t0"):
        assert simulate[key].default == p.SIMULATION.default(key), key
    assert jp.model.METHODS == {**{m: m for m in p.METHODS}, **dict(p.METHOD_ALIASES)}


def test_function_helpers_take_their_defaults_from_the_definitions():
    assert fn.constant_speed(1.0) == {"kind": "constant_rate", "initial": p.FUNCTIONS["constant_rate"].default(
        "initial"), "rate": 1.0}
    sine = fn.sine(1.0, 2.0)
    assert (sine["offset"], sine["phase"]) == (p.FUNCTIONS["sine"].default("offset"),
                                              p.FUNCTIONS["sine"].default("phase"))


LAW_HELPERS = {("contact", name): getattr(laws, name) for name in p.CONTACT_LAWS if name in vars(laws)}
LAW_HELPERS.update({("stiffness", "hertz_cylinder"): laws.hertz_cylinder,
                    ("stiffness", "johnson_line"): laws.johnson_line,
                    ("stiffness", "rogers_andrews"): laws.rogers_andrews,
                    ("stiffness", "pereira_ramalho_ambrosio"): laws.pereira_ramalho_ambrosio,
                    ("friction", "none"): laws.frictionless, ("friction", "coulomb"): laws.coulomb,
                    ("friction", "ambrosio"): laws.ambrosio, ("friction", "threlfall"): laws.threlfall,
                    ("friction", "stiction"): laws.stiction, ("transition", "switch"): laws.switch_transition,
                    ("transition", "flores"): laws.flores_transition,
                    ("transition", "wang_improved"): laws.wang_transition,
                    ("seal_friction", "lugre_seal"): laws.lugre_seal})
SAMPLES = {"dimensionless": 0.5, "velocity": 2e-3, "length": 3e-6}  # a value of each kind, inside every range


def test_every_law_has_a_helper():
    assert set(LAW_HELPERS) == {(family, t.name) for family, tables in p.LAWS.items() for t in p.variants(tables)}


@pytest.mark.parametrize("family, name", sorted(LAW_HELPERS))
def test_law_helper_takes_the_keys_and_defaults_of_its_definition(family, name):
    table = p.LAWS[family][name]
    arguments = _arguments(LAW_HELPERS[family, name])
    assert list(arguments) == table.keys()
    for key, argument in arguments.items():
        assert argument.default == (inspect.Parameter.empty if table[key].required else table[key].default), key


@pytest.mark.parametrize("family, name", sorted(LAW_HELPERS))
def test_law_helper_gives_what_a_model_file_gives(family, name):
    table = p.LAWS[family][name]
    required = {param.key: SAMPLES[param.kind] for param in table.params if param.required}
    builder = Builder({})
    from_file = builder.law({family: {"law": name, **required}}, p.Param(family, "law", "", of=family), "x")
    assert builder.problems == []
    assert LAW_HELPERS[family, name](**required) == from_file


def test_material_helper_and_steel_are_the_definitions():
    assert laws.STEEL == p.STEEL == p.CLEARANCE_REVOLUTE.default("bearing_material")
    assert list(_arguments(laws.material)) == p.MATERIAL.keys()


BUILT_IN_PYTHON = """
m = jp.Model("defaults")
m.add_ground_point("O", (0.0, 0.0))
m.add_ground_point("rail", (0.0, -0.3))
m.add_body("bar", 1.0, 0.02, points={"O": (-0.25, 0.0), "tip": (0.25, 0.0)})
m.add_body("bob", 0.2, 1e-3, points={"top": (0.0, 0.0)})
m.add_body("block", 0.5, 1e-3, points={"c": (0.0, 0.0)})
m.add_body("weld", 0.1, 1e-4, points={"c": (0.0, 0.0)})
m.add_revolute("pivot", "ground.O", "bar.O")
m.add_clearance_revolute("gap", "bar.tip", "bob.top", bearing_radius=0.01, clearance=2e-4, contact=laws.hertz())
m.add_translational("slide", "ground.rail", "block.c")
m.add_fixed("glue", "block.c", "weld.c")
m.add_spring_damper("spring", "bar.tip", "block.c", free_length=0.4)
m.add_rotational_spring_damper("coil", "ground", "bar")
m.add_point_force("push", "bob.top")
m.add_torque("motor", "bar", 0.1)
m.add_hydraulic_cylinder("ram", "ground.rail", "block.c", piston_area=2e-3, rod_side_area=1e-3, stroke_length=0.2,
                         cap_dead_volume="0.1 L", rod_dead_volume="0.1 L", initial_stroke=0.0, bulk_modulus=1.5e9)
"""

WRITTEN_IN_A_FILE = """
[model]
name = "defaults"
[ground]
points = { O = [0, 0], rail = [0, "-0.3 m"] }
[bodies.bar]
mass = "1 kg"
inertia = "0.02 kg m^2"
points = { O = ["-0.25 m", 0], tip = ["0.25 m", 0] }
[bodies.bob]
mass = "0.2 kg"
inertia = "1e-3 kg m^2"
points = { top = [0, 0] }
[bodies.block]
mass = "0.5 kg"
inertia = "1e-3 kg m^2"
points = { c = [0, 0] }
[bodies.weld]
mass = "0.1 kg"
inertia = "1e-4 kg m^2"
points = { c = [0, 0] }
[joints.pivot]
type = "revolute"
first = "ground.O"
second = "bar.O"
[joints.gap]
type = "clearance_revolute"
bearing = "bar.tip"
journal = "bob.top"
bearing_radius = "0.01 m"
clearance = "2e-4 m"
contact = "hertz"
[joints.slide]
type = "translational"
first = "ground.rail"
second = "block.c"
[joints.glue]
type = "fixed"
first = "block.c"
second = "weld.c"
[forces.spring]
type = "spring_damper"
first = "bar.tip"
second = "block.c"
free_length = "0.4 m"
[forces.coil]
type = "rotational_spring_damper"
first = "ground"
second = "bar"
[forces.push]
type = "point_force"
point = "bob.top"
[forces.motor]
type = "torque"
body = "bar"
torque = "0.1 N m"
[forces.ram]
type = "hydraulic_cylinder"
first = "ground.rail"
second = "block.c"
piston_area = "20 cm^2"
rod_side_area = "10 cm^2"
stroke_length = "0.2 m"
cap_dead_volume = "0.1 L"
rod_dead_volume = "0.1 L"
initial_stroke = 0
bulk_modulus = "1.5 GPa"
"""


def test_builder_and_model_file_give_the_same_spec_when_every_default_applies():
    scope = {"jp": jp, "laws": laws}
    exec(BUILT_IN_PYTHON, scope)
    built = scope["m"].to_spec()
    loaded = jp.loads(WRITTEN_IN_A_FILE, check=False).to_spec()
    assert built == loaded
    assert {e["type"] for e in built["joints"] + built["forces"]} == set(p.JOINTS) | set(p.FORCES)


def test_builder_reports_every_problem_of_an_element_at_once():
    m = jp.Model()
    with pytest.raises(jp.ModelError) as info:
        m.add_spring_damper("s", "a.p", "b.p", free_length="-1 mm", stiffness="5 kg")
    assert [str(problem) for problem in info.value.problems] == [
        "forces.s.stiffness: must be a stiffness (e.g. \"1e4 N/m\"), got '5 kg', which is a mass",
        "forces.s.free_length: must be >= 0, got -1 mm"]


# the writer ------------------------------------------------------------------------

def test_every_key_fixture_uses_every_key_of_every_table():
    doc = tomllib.loads(EVERY_KEY.read_text())
    seen: set[tuple[int, str | None]] = set()

    def visit(table: p.Table, raw: dict) -> None:
        seen.add((id(table), None))
        for param in table.params:
            if param.key not in raw:
                continue
            seen.add((id(table), param.key))
            value = raw[param.key]
            if param.kind == "law":
                value = {"law": value} if isinstance(value, str) else value
                visit(p.LAWS[param.of][value["law"]], value)
            elif param.kind == "table":
                visit(param.of, value)
            elif param.kind == "variant":
                tables = p.VARIANTS[param.of]
                visit(tables[value[next(iter(tables.values())).tag]], value)
            elif param.kind == "function" and isinstance(value, dict):
                visit(p.FUNCTIONS[value["kind"]], value)

    visit(p.MODEL, doc["model"])
    visit(p.GROUND, doc["ground"])
    visit(p.SIMULATION, doc["simulation"])
    for section, tables in (("bodies", None), ("beams", None), ("modal_bodies", None), ("joints", p.JOINTS),
                            ("drivers", None), ("forces", p.FORCES), ("sensors", p.SENSORS)):
        plain = {"bodies": p.BODY, "beams": p.BEAM, "modal_bodies": p.MODAL_BODY, "drivers": p.DRIVER}
        for raw in doc[section].values():
            visit(tables[raw["type"]] if tables else plain[section], raw)
    missing = [(t.name, key) for t in p.all_tables() for key in [None, *t.keys()] if (id(t), key) not in seen]
    assert missing == []


@pytest.mark.parametrize("path", [EVERY_KEY, *EXAMPLES], ids=lambda path: path.stem)
def test_writer_round_trips_every_key(path):
    model = jp.load(path, check=False)
    again = jp.loads(model.to_toml(), check=False)
    assert again.to_spec() == model.to_spec()
    assert again.simulation == model.simulation


def _optional_keys(spec: dict):
    """(path to a dict in the spec, key, its definition) for each optional key the writer may find missing
    in a hand-edited spec: element keys and law keys with a default value."""
    for section, tables in (("bodies", None), ("joints", p.JOINTS), ("forces", p.FORCES)):
        for k, entry in enumerate(spec[section]):
            table = tables[entry["type"]] if tables else p.BODY
            for param in table.params:
                if param.in_spec and not param.required and param.default is not None and param.kind != "points":
                    yield (section, k), param.key, param
                if param.kind == "law" and entry[param.key] is not None:
                    law_table = p.LAWS[param.of][p.tagged_law(entry[param.key], param.of)["law"]]
                    for sub in law_table.params:
                        if not sub.required and sub.default is not None and sub.key in entry[param.key]:
                            yield (section, k, param.key), sub.key, sub


def test_writer_fills_a_key_missing_from_the_spec_with_the_default_a_file_gets():
    spec = jp.load(EVERY_KEY, check=False).to_spec()
    cases = list(_optional_keys(spec))
    assert len(cases) > 30
    for path, key, param in cases:
        edited = copy.deepcopy(spec)
        node = edited[path[0]][path[1]]
        for part in path[2:]:
            node = node[part]
        del node[key]
        written = jp.loads(to_toml(edited), check=False).to_spec()
        node = written[path[0]][path[1]]
        for part in path[2:]:
            node = node[part]
        expected = param.default
        if param.kind == "law":
            expected = {"law": param.default}
        elif param.kind == "table":
            expected = dict(param.default)
        elif param.kind == "function":
            expected = {"kind": "constant", "value": param.default}
        elif isinstance(expected, tuple):
            expected = list(expected)
        assert node[key] == expected, (path, key)


# a new element needs its definition and one builder line ---------------------------

DEMO = p.Table("demo_actuator", "A demonstration force element: a point, a quantity, a law and a function.", (
    p.Param("first", "point", "where it pushes", example=p.POINT),
    p.Param("area", "length", "a length standing for an area", gt=0, example='a length, e.g. "1 mm"'),
    p.Param("gain", "dimensionless", "a plain number", 2.0, ge=0, why="two"),
    p.Param("friction", "law", "a friction law", "none", of="friction"),
    p.Param("command", "function", "a force over time", 0.0, of="force"),
), tag="type")


def test_a_new_force_element_needs_only_its_definition_and_one_builder_line(monkeypatch):
    from jointplay.modelfile import schema
    from jointplay.model import _adds

    monkeypatch.setitem(p.FORCES, "demo_actuator", DEMO)
    monkeypatch.setitem(schema.FORCES, "demo_actuator", schema.table_class(DEMO))
    monkeypatch.setattr(jp.Model, "add_demo_actuator", _adds(DEMO, "forces"), raising=False)
    expected = {"type": "demo_actuator", "name": "d", "first": "bar.tip", "area": 0.001, "gain": 2.0,
                "friction": {"law": "none"}, "command": {"kind": "constant", "value": 0.0}}

    m = jp.Model()
    m.add_demo_actuator("d", "bar.tip", area="1 mm")
    assert m.to_spec()["forces"] == [expected]
    assert "``gain``: a plain number; >= 0; default 2 (two)." in jp.Model.add_demo_actuator.__doc__

    doc = tomllib.loads('[bodies.bar]\nmass = "1 kg"\ninertia = "1 kg m^2"\npoints = { tip = [0, 0] }\n'
                        '[forces.d]\ntype = "demo_actuator"\nfirst = "bar.tip"\narea = "1 mm"\n')
    builder = Builder(doc).run()
    assert builder.problems == []
    assert builder.spec["forces"] == [expected]
    written = tomllib.loads(to_toml(m.to_spec()))["forces"]["d"]
    assert written == {"type": "demo_actuator", "first": "bar.tip", "area": "0.001 m", "gain": 2.0,
                       "friction": {"law": "none"}, "command": {"kind": "constant", "value": "0.0 N"}}
    assert "### `type = \"demo_actuator\"`" in reference.text()
    bad = Builder({**doc, "forces": {"d": {"type": "demo_actuator", "first": "bar.tip", "area": "-1 mm"}}}).run()
    assert [str(problem) for problem in bad.problems] == ["forces.d.area: must be > 0, got -1 mm"]


def test_every_default_lies_in_its_range():
    for table in p.all_tables():
        for param in table.params:
            d = param.default
            if isinstance(d, float) and not param.required:
                assert (param.gt is None or d > param.gt) and (param.ge is None or d >= param.ge), param.key
                assert (param.lt is None or d < param.lt) and (param.le is None or d <= param.le), param.key
                assert math.isfinite(d)
            if param.kind == "choice" and isinstance(d, str):
                assert d in param.of, param.key


def test_every_kind_is_a_quantity_or_a_known_structure():
    from jointplay.units import KINDS

    for table in p.all_tables():
        for param in table.params:
            assert param.kind in KINDS or param.kind in p.STRUCTURED, (table.name, param.key, param.kind)
            if param.kind in ("vector", "list") and param.of not in ("powers", "value"):
                assert param.of in KINDS, (table.name, param.key)
            if param.kind == "law":
                assert param.of in p.LAWS, (table.name, param.key)
