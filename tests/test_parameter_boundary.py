"""A parameter is defined once across the language boundary: the registry (jointplay.parameters) against the
core's own view of the model description.

- The core's ranges are generated from the registry (crates/jointplay-core/src/spec/ranges.rs): the file is
  what the registry writes today.
- Names: every key of every table the core deserialises (read from its deserialisers, `_core.spec_tables`) is
  a key of the registry that the core reads (``in_spec``), and the other way round, once the reshaping the
  front end does (jointplay.modelfile.build) is applied: the table below says each move.
- Defaults: a key the core may leave out (an Option, none when absent) is one whose registry default is none.
- Ranges: the core itself, given the description of tests/fixtures/every_key.toml (every table and law) with
  one key set at or just beyond each bound of its registry range, refuses exactly the values the registry
  refuses, at that key, with the registry's words.
"""

from __future__ import annotations

import copy
import json
import math
from pathlib import Path

import pytest

from jointplay import _core, boundary
from jointplay import parameters as p
from jointplay.modelfile import read_document
from jointplay.modelfile.build import Builder

ROOT = Path(__file__).resolve().parents[1]
EVERY_KEY = ROOT / "tests" / "fixtures" / "every_key.toml"
#: Every key of a spatial model (the spatial tables' ranges are probed on it).
EVERY_SPATIAL_KEY = ROOT / "tests" / "data" / "spatial" / "every_key.toml"

#: Tables whose entries are named in a file by their table key (`[bodies.crank]`), the core's `name`.
NAMED = ("bodies", "beams", "modal_bodies", "drivers", "joints.", "forces.", "sensors.", "spatial_bodies", "spatial_joints.",
         "spatial_forces.", "spatial_clearance_joints")

#: How the front end reshapes a registry table into the core's: a registry key (table id, key) goes to these
#: (core table, key) pairs; None: the front end reads it and sends what follows from it (not a key of the core).
MOVED: dict[tuple[str, str], list[tuple[str, str]] | None] = {
    # the model's sections are lists of the core's model; ground points are the core's points
    ("ground", "points"): [("model", "ground_points"), ("point", "name"), ("point", "position")],
    ("bodies", "points"): [("bodies", "points"), ("point", "name"), ("point", "position")],
    # hertz_cylinder with an exponent is the core's hertz_cylinder_exponent (parameters.core_law)
    ("stiffness.hertz_cylinder", "exponent"): [("stiffness.hertz_cylinder_exponent", "exponent")],
    # the Reynolds solver's options are a table of the lubrication (parameters.core_lubrication)
    ("lubrication", "cavitation"): [("reynolds", "cavitation")],
    ("lubrication", "grid"): [("reynolds", "n_circumferential"), ("reynolds", "n_axial")],
    ("lubrication", "ambient_pressure"): [("reynolds", "ambient_pressure")],
    ("lubrication", "groove_supply_pressure"): [("reynolds", "groove_supply_pressure")],
    # a beam's mesh is a table, its material part of its section, its points named arclengths
    ("beams", "order"): [("beam_mesh", "order")],
    ("beams", "elements"): [("beam_mesh", "elements")],
    ("beams", "element_length"): [("beam_mesh", "element_length")],
    ("beams", "material"): [("section.properties", "material"), ("section.rectangle", "material"),
                            ("section.circle", "material"), ("section.tube", "material")],
    ("beams", "points"): [("beams", "points"), ("beam_point", "name"), ("beam_point", "arclength")],
    # a modal body's structure is a beam's or given by matrices; its nodes are named points
    ("modal_bodies", "start"): [("structure.beam", "start")],
    ("modal_bodies", "end"): [("structure.beam", "end")],
    ("modal_bodies", "section"): [("structure.beam", "section")],
    ("modal_bodies", "material"): [],
    ("modal_bodies", "order"): [("structure.beam", "mesh")],
    ("modal_bodies", "elements"): [],
    ("modal_bodies", "element_length"): [],
    ("modal_bodies", "matrices"): [("modal_bodies", "structure")],
    ("modal_bodies", "position"): [("structure.matrices", "position")],
    ("modal_bodies", "angle"): [("structure.matrices", "angle")],
    ("modal_bodies", "interface"): [("modal_bodies", "interface"), ("modal_point", "name"),
                                    ("modal_point", "arclength"), ("modal_point", "node")],
    ("matrices", "mass"): [("structure.matrices", "mass"), ("sparse_matrix", "size"), ("sparse_matrix", "rows"),
                           ("sparse_matrix", "columns"), ("sparse_matrix", "values")],
    ("matrices", "stiffness"): [("structure.matrices", "stiffness")],
    ("matrices", "nodes"): [("structure.matrices", "nodes")],
    # the numbers of a matrix file carry no unit: the front end converts them to SI with these
    ("matrices", "length_unit"): None,
    ("matrices", "mass_unit"): None,
    # a spatial body's points are the core's points with frames
    ("spatial_bodies", "points"): [("spatial_bodies", "points"), ("spatial_point", "name"), ("spatial_point", "position"),
                                   ("spatial_point", "axes")],
}

#: Keys of the core that hold a nested table the registry spells out as its own keys (above).
HOLDERS = {("model", key) for key in ("bodies", "beams", "modal_bodies", "joints", "drivers", "forces", "sensors",
                                     "spatial_bodies", "spatial_joints", "spatial_forces")} | {
    ("lubrication", "reynolds"), ("beams", "mesh"), ("beams", "section"), ("structure.beam", "section"),
    # the core's points hold the axes of a spatial model's markers (read by modelfile/spatial.py), and its spatial
    # joints are one table whose kind is a key, where the registry has one table per kind
    ("point", "axes"), ("spatial_joints", "type"), ("spatial_clearance_joints", "type"),
    ("model", "spatial_clearance_joints")}

#: Core tables that are the registry's under another name (the tag of a beam section: ``shape`` in a file).
RENAMED = {"seal_friction.lugre_seal": "seal_friction",
           **{f"spatial_joints.{kind}": "spatial_joints" for kind in p.SPATIAL_JOINTS
              if kind not in p.SPATIAL_JOINT_SECTIONS}}


def registry_keys() -> dict[str, set[str]]:
    """The keys of every table the core reads, as the registry defines them, after the front end's reshaping."""
    expected: dict[str, set[str]] = {}
    for table_id, table in boundary.spec_tables().items():
        core_id = RENAMED.get(table_id, table_id)
        keys = expected.setdefault(core_id, set())
        if table_id.startswith(NAMED):
            keys.add("name")
        for param in table.params:
            if not param.in_spec:
                continue
            moved = MOVED.get((table_id, param.key), [(core_id, param.key)])
            for target_table, target_key in moved or ():
                expected.setdefault(target_table, set()).add(target_key)
    for table, key in HOLDERS:
        expected.setdefault(table, set()).add(key)
    for table in ("ground", "matrices"):  # every key moved: to the model's ground points, to a modal structure
        assert not expected.pop(table), table
    expected.setdefault("stiffness.hertz_cylinder_exponent", set())
    return expected


def core_tables() -> dict[str, dict[str, bool]]:
    return {table: dict(keys) for table, keys in _core.spec_tables()}


def test_the_rust_ranges_are_generated_from_the_registry():
    written = (ROOT / boundary.RANGES_FILE).read_text()
    assert written == boundary.rust_ranges(), (
        f"{boundary.RANGES_FILE} differs from the registry's ranges: run `python -m jointplay.boundary`")


def test_every_table_the_core_reads_has_the_keys_the_registry_defines():
    core, expected = core_tables(), registry_keys()
    assert sorted(core) == sorted(expected), "tables of only one side: " + ", ".join(
        sorted(set(core) ^ set(expected)))
    differences = {table: (sorted(set(core[table]) - expected[table]), sorted(expected[table] - set(core[table])))
                   for table in core if set(core[table]) != expected[table]}
    assert not differences, "table: (keys of the core only, keys of the registry only): " + repr(differences)


def test_a_key_the_core_may_leave_out_has_no_value_by_default_in_the_registry():
    core = core_tables()
    for table_id, table in boundary.spec_tables().items():
        keys = core.get(RENAMED.get(table_id, table_id), {})
        for param in table.params:
            if param.key in keys and keys[param.key]:
                assert param.default is None, f"{table_id}.{param.key}: the core reads it as none when absent, " \
                                              f"the registry's default is {param.default!r}"


def test_a_key_the_registry_sends_as_none_is_one_the_core_may_leave_out():
    # keys whose absence the front end turns into a value before sending: the name (the file's), the clearance
    # (from the journal radius), the Hertz exponent (another law of the core), a spatial spring's free length (the
    # initial distance of its points, modelfile/spatial.py fill_free_lengths)
    derived = {("model", "name"), ("joints.clearance_revolute", "clearance"), ("stiffness.hertz_cylinder", "exponent"),
               ("spatial_forces.spring_damper", "free_length")}
    core = core_tables()
    for table_id, table in boundary.spec_tables().items():
        keys = core.get(RENAMED.get(table_id, table_id), {})
        for param in table.params:
            if param.in_spec and param.default is None and param.key in keys and (table_id, param.key) not in derived:
                assert keys[param.key], f"{table_id}.{param.key}: the registry sends none when absent, the core " \
                                        "requires a value"


# ranges: the core's own checks at the registry's bounds ------------------------------------------------------

#: Where a registry key sits in the core's table, from the table (the front end's reshaping).
PATH = {("lubrication", "ambient_pressure"): ("reynolds", "ambient_pressure"),
        ("lubrication", "groove_supply_pressure"): ("reynolds", "groove_supply_pressure"),
        ("beams", "element_length"): ("mesh", "element_length"),
        ("modal_bodies", "element_length"): ("structure", "mesh", "element_length")}

#: Bounds between keys that the core checks and the registry cannot yet write as a Relation (a key against a
#: multiple of another): reported by the core, at the key, in their own words.
CORE_ONLY_BOUNDS = {
    ("beam_material", "shear_modulus"): "G > E/3: Poisson's ratio E / (2 G) - 1 of an isotropic material below 0.5",
    ("seal_friction.lugre_seal", "bristle_damping"): "sigma1 <= 4 sqrt(2e) F_C / v_D, or the law creates energy",
}

_FUNCTION_KEYS = ("function", "fx", "fy", "torque", "cap_inflow", "rod_inflow")


def _sites(node, table_id: str | None = None):
    """(registry table id, dict) of every table in the core's description ``node``."""
    if table_id is not None:
        yield table_id, node
    for key, value in node.items():
        if isinstance(value, list) and key in ("bodies", "beams", "modal_bodies", "drivers", "joints", "forces",
                                               "sensors", "spatial_bodies", "spatial_forces"):
            for entry in value:
                tag = entry.get("type")
                yield from _sites(entry, key if tag is None else f"{key}.{tag}")
        elif isinstance(value, list) and key == "spatial_clearance_joints":  # one kind: no tag in the table's id
            for entry in value:
                yield from _sites(entry, key)
        elif isinstance(value, dict):
            yield from _sites(value, _nested_id(key, value, table_id))


def _nested_id(key: str, value: dict, parent: str | None) -> str | None:
    law = value.get("law")
    if key in ("contact", "friction", "transition"):
        return f"{key}.{law}"
    if key == "stiffness" and law is not None:
        return "stiffness.hertz_cylinder" if law == "hertz_cylinder_exponent" else f"stiffness.{law}"
    if key == "seal_friction":
        return "seal_friction.lugre_seal"
    if key in ("bearing_material", "journal_material"):
        return "material"
    if key == "material" and parent is not None and parent.startswith("section."):
        return "beam_material"
    if key == "section":
        return f"section.{value['type']}"
    if key in _FUNCTION_KEYS and "kind" in value:
        return f"function.{value['kind']}"
    if key == "lubrication":
        return "lubrication"
    return None


@pytest.fixture(scope="module")
def every_key_spec() -> dict:
    specs = {}
    for kind, path in (("planar", EVERY_KEY), ("spatial", EVERY_SPATIAL_KEY)):
        specs[kind], _ = Builder(read_document(path), base=path.parent).run().result()
        assert _core.compile_model(json.dumps(specs[kind]))[1] is None, path
    return specs


def _problems_with(spec: dict, table_id: str, key: str, value: float) -> list[tuple[str, str]]:
    """The core's problems with the description where the first table ``table_id`` that holds ``key`` has
    ``value`` there."""
    spec = copy.deepcopy(spec["spatial" if table_id.startswith("spatial_") else "planar"])
    path = PATH.get((table_id, key), (key,))
    for found, table in _sites(spec):
        node = table
        for step in path[:-1]:
            node = node.get(step) if isinstance(node, dict) else None
        if found == table_id and isinstance(node, dict) and node.get(path[-1]) is not None:
            # (every component of a vector)
            node[path[-1]] = [value] * len(node[path[-1]]) if isinstance(node[path[-1]], list) else value
            return _core.compile_model(json.dumps(spec))[1] or []
    raise AssertionError(f"the every-key fixture has no {table_id} with {key}")


def _probes(param: p.Param) -> list[tuple[float, bool]]:
    """(value, in range) at and beyond each bound of ``param``'s range."""
    out = []
    for bound, op in ((param.gt, "gt"), (param.ge, "ge"), (param.lt, "lt"), (param.le, "le")):
        if bound is None:
            continue
        below, above = math.nextafter(bound, -math.inf), math.nextafter(bound, math.inf)
        out += {"gt": [(bound, False), (above, True)], "ge": [(bound, True), (below, False)],
                "lt": [(bound, False), (below, True)], "le": [(bound, True), (above, False)]}[op]
    return out


@pytest.mark.parametrize(("table_id", "param"), boundary.ranged_keys(),
                         ids=[f"{t}.{q.key}" for t, q in boundary.ranged_keys()])
def test_the_core_refuses_exactly_the_values_the_registry_refuses(every_key_spec, table_id, param):
    for value, inside in _probes(param):
        problems = _problems_with(every_key_spec, table_id, param.key, value)
        at_key = [(where, message) for where, message in problems if where.endswith(f".{param.key}")]
        if inside:
            # a bound between two keys (static_force >= kinetic_force) may still refuse it, in its own words
            related = {key for r in boundary.spec_tables()[table_id].relations for key in (r.key, r.other)}
            related |= {key for table, key in CORE_ONLY_BOUNDS if table == table_id}
            refused = [(where, message) for where, message in at_key
                       if param.key not in related or message.startswith(f"must {boundary._rule(param)}")]
            assert not refused, f"{table_id}.{param.key} = {value!r} is in the registry's range, the core refuses it"
        else:
            assert at_key, f"{table_id}.{param.key} = {value!r} is out of the registry's range, the core takes it"
            assert any(message.startswith(f"must {boundary._rule(param)}, got ") for _, message in at_key), at_key
