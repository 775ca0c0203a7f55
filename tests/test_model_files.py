"""Model files: validation messages, overrides, round trips builder -> TOML -> load, robustness."""

from __future__ import annotations

import copy
import importlib.util
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import jointplay as jp
from jointplay import functions as fn
from jointplay import laws
from jointplay.modelfile import from_document

ROOT = Path(__file__).resolve().parents[1]
DRY = ROOT / "examples" / "flores_slider_crank_dry.toml"


def problems(overrides: list[str], path: Path = DRY) -> list[str]:
    with pytest.raises(jp.ModelError) as info:
        jp.load(path, overrides)
    return [str(p) for p in info.value.problems]


# one test per class of bad input, message pinned --------------------------------

@pytest.mark.parametrize("override, message", [
    ('joints.B.friction={law = "stiction", static_coefficient = 0.05, kinetic_coefficient = 0.1}',
     "joints.B.friction.static_coefficient: must be at least kinetic_coefficient = 0.1 (the break-away coefficient "
     "is not below the sliding one), got 0.05"),
    ('joints.B.friction={law = "stiction", static_coefficient = 0.15, kinetic_coefficient = 0.1, '
     'stiction_velocity = "1 mm/s", transition_velocity = "0.5 mm/s"}',
     "joints.B.friction.transition_velocity: must be greater than stiction_velocity = 1 mm/s (the kinetic "
     "coefficient is reached after the static one), got 0.5 mm/s"),
    ("joints.B.clearance=-0.1 mm", "joints.B.clearance: must be > 0, got -0.1 mm"),
    ("bodies.crank.mass=0", "bodies.crank.mass: must be > 0, got 0 kg"),
    ("joints.B.contact.restitution=1.5", "joints.B.contact.restitution: must lie in [0, 1], got 1.5"),
    ("joints.B.bearing_material.poisson_ratio=0.7",
     "joints.B.bearing_material.poisson_ratio: must lie in (-1, 0.5), got 0.7"),
])
def test_out_of_range_values_name_location_and_value(override, message):
    assert problems([override]) == [message]


@pytest.mark.parametrize("override, message", [
    ("joints.B.clearence=0.1 mm", 'joints.B.clearence: unknown key (did you mean "clearance"?)'),
    ("bodies.crank.mas=1 kg", 'bodies.crank.mas: unknown key (did you mean "mass"?)'),
    ("simulaton.t_end=1", 'simulaton: unknown section (did you mean "simulation"?); '
                          "sections: model, units, ground, bodies, beams, modal_bodies, joints, drivers, forces, sensors, "
                          "simulation"),
    ("joints.A.type=revolut", "joints.A.type: must be one of revolute, translational, fixed, clearance_revolute, "
                              "got 'revolut' (did you mean \"revolute\"?)"),
    ("joints.B.contact.law=lankarani", "joints.B.contact.law: must be one of hertz, hunt_crossley, "
                                       "lankarani_nikravesh, flores, gonthier, hu_guo, got 'lankarani' "
                                       "(did you mean \"lankarani_nikravesh\"?)"),
])
def test_unknown_keys_and_words_get_a_did_you_mean_hint(override, message):
    assert problems([override]) == [message]


def test_missing_required_values_say_what_is_expected():
    assert problems(['bodies.extra={ inertia = "1 kg m^2", free = true }']) == [
        'bodies.extra.mass: missing required value (a mass, e.g. "0.3 kg")']
    text = DRY.read_text().replace('contact = { law = "lankarani_nikravesh", restitution = 0.9 }\n', "")
    with pytest.raises(jp.ModelError) as info:
        jp.loads(text)
    assert [str(p) for p in info.value.problems] == [
        "joints.B.contact: missing required value "
        "(a table such as { law = \"lankarani_nikravesh\", restitution = 0.9 })"]


@pytest.mark.parametrize("override, message", [
    ("joints.A.second=rod.C", "joints.A.second: body 'rod' has no point 'C' (its points: A, B), got 'rod.C'"),
    ("joints.A.second=rdo.A", "joints.A.second: no body named 'rdo' (did you mean \"rod\"?), got 'rdo.A'"),
    ("joints.A.second=rod", "joints.A.second: must be a point \"body.point\" (e.g. \"crank.A\", \"ground.O\"), "
                            "got 'rod'"),
    ("drivers.motor.joint=guid", "drivers.motor.joint: no joint named 'guid' (did you mean \"guide\"?)"),
    ('forces.B={ type = "torque", body = "crank", torque = "1 N m" }',
     "forces.B: name 'B' is already used by joints.B"),
])
def test_references_to_missing_things_are_errors(override, message):
    assert problems([override]) == [message]


@pytest.mark.parametrize("override, message", [
    ("bodies.crank.mass=5 mm", "bodies.crank.mass: must be a mass (e.g. \"0.3 kg\"), got '5 mm', which is a length"),
    ("joints.B.bearing_radius=5 kg",
     "joints.B.bearing_radius: must be a length (e.g. \"0.5 mm\"), got '5 kg', which is a mass"),
    ("drivers.motor.function.rate=3 m/s", "drivers.motor.function.rate: must be an angular velocity "
                                          "(e.g. \"5000 rpm\"), got '3 m/s', which is a velocity"),
    ("model.gravity.1=5 kg", "model.gravity: y component must be an acceleration (e.g. \"9.81 m/s^2\"), "
                             "got '5 kg', which is a mass"),
])
def test_wrong_dimensions_are_errors(override, message):
    assert problems([override]) == [message]


@pytest.mark.parametrize("override, message", [
    ("joints.B.clearance=12 mm", "joints.B.clearance: must be smaller than bearing_radius = 10 mm "
                                 "(the journal radius would be <= 0), got 12 mm"),
    ("joints.B.initial_eccentricity=[\"1 mm\", 0]",
     "joints.B.initial_eccentricity: must lie within the clearance (0.5 mm), got [1 mm, 0 m]"),
])
def test_impossible_geometry_is_an_error(override, message):
    assert problems([override]) == [message]


def test_journal_larger_than_bearing_is_an_error():
    text = DRY.read_text().replace('clearance = "0.5 mm"', 'journal_radius = "10.5 mm"')
    with pytest.raises(jp.ModelError) as info:
        jp.loads(text)
    assert [str(p) for p in info.value.problems] == [
        "joints.B.journal_radius: must be smaller than bearing_radius = 10 mm (the journal would not fit), got 10.5 mm"]


def test_journal_radius_instead_of_clearance_gives_the_same_model():
    text = DRY.read_text().replace('clearance = "0.5 mm"', 'journal_radius = "9.5 mm"')
    assert jp.loads(text).joint("B")["clearance"] == pytest.approx(0.5e-3, rel=1e-12)


def test_a_driver_against_a_weld_is_a_locked_mechanism_at_assembly():
    (message,) = problems(['joints.weld={ type = "fixed", first = "ground.O", second = "crank.O" }'])
    assert "the mechanism is locked" in message
    assert message.split(":")[0] in ("joints.O", "joints.weld", "drivers.motor")


def test_a_redundant_pin_is_checked_with_a_note_and_one_freedom_less_counted_nowhere():
    model = jp.load(DRY, ['joints.O2={ type = "revolute", first = "ground.O", second = "crank.O" }'])
    info = model.check()
    assert info["redundant_equations"] == 2
    assert set(info["dependent_elements"]) == {"O", "O2"}
    assert info["degrees_of_freedom"] == jp.load(DRY).check()["degrees_of_freedom"]


def test_body_connected_to_nothing_is_an_error_unless_free():
    assert problems(['bodies.extra={ mass = "1 kg", inertia = "1 kg m^2" }']) == [
        "bodies.extra: is connected to nothing: no joint or force element refers to it "
        "(write free = true if it is meant to move freely)"]
    model = jp.load(DRY, ['bodies.extra={ mass = "1 kg", inertia = "1 kg m^2", free = true }'])
    assert model.check()["degrees_of_freedom"] == 5


def test_every_problem_is_reported_at_once():
    found = problems(["joints.B.clearance=-0.1 mm", "bodies.crank.mass=5 mm", "joints.B.frcition=1"])
    assert len(found) == 3


def test_core_index_locations_are_mapped_to_names():
    # a bound between two tables (the film thickness against the joint's clearance) only the core checks
    film = ('joints.B.lubrication={ model = "hamrock_short", viscosity = "400 cP", transition = { law = '
            '"wang_improved", safe_film_thickness = "1 mm" } }')
    found = problems(["joints.B.length=20 mm", film])
    assert found == ["joints.B.lubrication.transition.safe_film_thickness: must be smaller than the clearance "
                     "0.0005 m, got 0.001 m"]


def test_a_full_friction_velocity_below_the_dead_band_is_refused_at_its_key():
    found = problems(["joints.B.friction.v1=1e-5 m/s"])
    assert found == ["joints.B.friction.v1: must be greater than v0 = 1e-4 m/s (friction rises from none at v0 to "
                     "full at v1), got 1e-5 m/s"]


def test_invalid_toml_and_missing_file_are_model_errors(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[model\nname = 1")
    with pytest.raises(jp.ModelError) as info:
        jp.load(bad)
    assert str(info.value).startswith(f"{bad}: is not valid TOML")
    with pytest.raises(jp.ModelError, match="no such file"):
        jp.load(tmp_path / "missing.toml")


# overrides ---------------------------------------------------------------------

def test_overrides_take_units_lists_and_inline_tables():
    m = jp.load(DRY, ["joints.B.clearance=0.1mm", "model.gravity=[0, 0]", 'joints.B.contact={ law = "hertz" }',
                      "simulation.t_end=12 ms"])
    assert m.joint("B")["clearance"] == pytest.approx(1e-4)
    assert m.joint("B")["contact"] == {"law": "hertz"}
    assert m.to_spec()["gravity"] == [0.0, 0.0]
    assert m.simulation["t_end"] == pytest.approx(0.012)


@pytest.mark.parametrize("word, method", [("bdf", "bdf"), ("ndf", "bdf"), ("adams_pc", "adams"), ("rk45", "dopri5")])
def test_simulation_method_words_and_aliases(word, method):
    assert jp.load(DRY, [f'simulation.method="{word}"']).simulation["method"] == method


def test_override_of_an_entry_that_does_not_exist_is_an_error():
    assert problems(["joints.Z.clearance=1"]) == ["--set joints.Z.clearance: no entry 'Z' in [joints] "
                                                  "(entries: O, A, guide, B)"]
    assert problems(["nonsense"]) == ['--set nonsense: must be PATH=VALUE, e.g. joints.B.clearance="0.1 mm"']


# round trips -------------------------------------------------------------------

def _flores_builder():
    spec = importlib.util.spec_from_file_location("flores_dry", ROOT / "examples" / "flores_slider_crank_dry.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.build_model()


def kitchen_sink() -> jp.Model:
    """Every joint, law, driver function and force element the engine has."""
    m = jp.Model("kitchen sink", gravity=(0.0, -9.81))
    m.add_ground_point("O", (0.0, 0.0))
    m.add_ground_point("rail", (0.0, -0.3))
    m.add_body("bar", mass=1.0, inertia=0.02, position=(0.25, 0.0), angle=0.0,
               points={"O": (-0.25, 0.0), "tip": (0.25, 0.0)})
    m.add_body("arm", mass=0.2, inertia=1e-3, position=(0.6, 0.0), points={"pin": (-0.1, 0.0), "end": (0.1, 0.0)})
    m.add_body("block", mass=0.5, inertia=1e-3, position=(0.0, -0.3), points={"c": (0.0, 0.0)})
    m.add_body("weld", mass=0.1, inertia=1e-4, position=(0.0, -0.3), points={"c": (0.0, 0.0)})
    m.add_revolute("pivot", "ground.O", "bar.O")
    m.add_clearance_revolute("gap", "bar.tip", "arm.pin", bearing_radius=0.01, clearance=2e-4, length=0.02,
                             contact=laws.hunt_crossley(0.8), stiffness=laws.johnson_line(),
                             friction=laws.stiction(0.2, 0.15), initial_eccentricity=(1e-4, 0.0),
                             max_penetration=1e-4)
    m.add_translational("rail", "ground.rail", "block.c", axis=(1.0, 0.0))
    m.add_fixed("glue", "block.c", "weld.c")
    m.add_driver("push", "rail", fn.cubic_step(0.0, 0.01, 0.0, 0.002))
    m.add_spring_damper("spring", "bar.tip", "block.c", free_length=0.4, stiffness=100.0, damping=0.5)
    m.add_rotational_spring_damper("coil", "ground", "bar", stiffness=2.0, damping=0.01, free_angle=0.1)
    m.add_point_force("wind", "arm.end", fx=fn.sine(1.0, 50.0, phase=0.3), fy=fn.polynomial([0.0, 10.0, -5.0]))
    m.add_torque("motor", "bar", fn.table([0.0, 0.005, 0.01], [0.0, 0.1, 0.0]))
    m.add_ground_point("base", (-0.5, -0.3))
    m.add_hydraulic_cylinder("ram", "ground.base", "block.c", piston_area="20 cm^2", rod_side_area="10 cm^2",
                             stroke_length="300 mm", cap_dead_volume="1 L", rod_dead_volume="1 L",
                             initial_stroke="100 mm", cap_pressure="100 bar", rod_pressure="200 bar",
                             bulk_modulus="1.5 GPa", seal_friction=laws.lugre_seal(static_force="400 N"),
                             cap_inflow=fn.sine(1e-5, 100.0), rod_inflow="-0.1 L/min")
    return m


@pytest.mark.parametrize("build", [_flores_builder, kitchen_sink], ids=["flores_dry", "kitchen_sink"])
def test_builder_to_toml_to_load_gives_identical_results(build):
    built = build()
    loaded = jp.loads(built.to_toml())
    assert loaded.to_spec() == built.to_spec()
    a = built.simulate(0.004, max_step=1e-4)
    b = loaded.simulate(0.004, max_step=1e-4)
    assert a.channels == b.channels
    assert np.array_equal(a.time, b.time)
    for name in a.channels:
        assert np.array_equal(a[name], b[name]), name


def test_kitchen_sink_keeps_laws_and_functions_through_toml():
    text = kitchen_sink().to_toml()
    doc = tomllib.loads(text)
    assert doc["joints"]["gap"]["friction"]["law"] == "stiction"
    assert doc["joints"]["gap"]["stiffness"] == {"law": "johnson_line"}
    assert doc["drivers"]["push"]["function"]["value_end"] == "0.002 m"
    assert doc["forces"]["wind"]["fy"]["coefficients"] == ["0.0 N", "10.0 N/s^1", "-5.0 N/s^2"]


def test_model_save_and_load_keep_simulation_defaults(tmp_path):
    m = jp.load(DRY)
    m.save(tmp_path / "copy.toml")
    again = jp.load(tmp_path / "copy.toml")
    assert again.to_spec() == m.to_spec()
    assert again.simulation == m.simulation == {"t_end": 0.024, "method": "dopri5", "rtol": 1e-6, "atol": 1e-9,
                                                "max_step": 1e-4}


def test_model_file_matches_the_python_example():
    loaded, built = jp.load(DRY).to_spec(), _flores_builder().to_spec()
    for body_loaded, body_built in zip(loaded["bodies"], built["bodies"]):
        body_loaded["position"] = body_built["position"] = None  # approximate initial guesses
    assert loaded == built


@pytest.mark.parametrize("stem", ["paper001_slider_crank_dry", "flores_slider_crank_lubricated"])
def test_model_file_matches_its_python_example(stem):
    example = __import__(stem)
    loaded = jp.load(DRY.parent / f"{stem}.toml").to_spec()
    built = example.build_model().to_spec()
    for spec in (loaded, built):
        for body in spec["bodies"]:
            body["position"] = None  # approximate initial guesses
    assert loaded == built


# robustness: random mutations give a model or a ModelError, nothing else ------

ODD_VALUES = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**20, 10**20), st.booleans(),
    st.sampled_from(["5 kg", "0.1 mm", "-1 mm", "3 rpm", "1e308 m", "1e-300 m", "abc", "", "10 Hz", "90 deg",
                     "ground.O", "rod.X", "crank.A", "revolute", "hertz", "none", "table", "1 mm +", "0 s"]),
    st.lists(st.floats(-1e3, 1e3), max_size=3), st.just({}), st.just({"law": "hertz"}), st.just({"kind": "table"}),
)


def _leaves(node, path=()):
    if isinstance(node, dict):
        yield path
        for k, v in node.items():
            yield from _leaves(v, (*path, k))
    elif isinstance(node, list):
        yield path
        for i, v in enumerate(node):
            yield from _leaves(v, (*path, i))
    else:
        yield path


BASES = [tomllib.loads(DRY.read_text()), tomllib.loads(kitchen_sink().to_toml())]
PATHS = [[p for p in _leaves(doc) if p] for doc in BASES]


@st.composite
def mutated(draw):
    base = draw(st.sampled_from(range(len(BASES))))
    doc = copy.deepcopy(BASES[base])
    for _ in range(draw(st.integers(1, 3))):
        path = draw(st.sampled_from(PATHS[base]))
        parent = doc
        try:
            for key in path[:-1]:
                parent = parent[key]
            action = draw(st.sampled_from(["replace", "delete", "add"]))
            if action == "replace":
                parent[path[-1]] = draw(ODD_VALUES)
            elif action == "delete" and isinstance(parent, dict):
                del parent[path[-1]]
            elif isinstance(parent, dict):
                parent[draw(st.sampled_from(["extra", "mass", "type", "law", "kind", "rate", "clearance"]))] = \
                    draw(ODD_VALUES)
        except (KeyError, IndexError, TypeError):
            pass  # an earlier mutation removed or replaced this path
    return doc


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated())
def test_random_mutations_give_a_model_or_a_model_error(doc):
    try:
        model = from_document(doc)
    except jp.ModelError as exc:
        assert exc.problems and all(p.location and p.message for p in exc.problems)
        return
    info = model.check()
    # (each coordinate: a point at 1e308 m is finite, the sum of three such is not)
    assert np.all(np.isfinite(np.asarray(info["initial_coordinates"], dtype=float)))


LUBRICATED = DRY.parent / "flores_slider_crank_lubricated.toml"
LUBRICATION_LINE = ('lubrication = { model = "pinkus_sternlicht_long", viscosity = "400 cP", '
                    'transition = { law = "wang_improved" } }')


@pytest.mark.parametrize("replacement, messages", [
    ('lubrication = { model = "hamrock_short", viscosity = "5 kg", transition = { law = "flores", lubricated_limit = 1.5 } }',
     ["joints.B.lubrication.viscosity: must be a viscosity (e.g. \"400 cP\"), got '5 kg', which is a mass",
      "joints.B.lubrication.transition.lubricated_limit:"]),
    ('lubrication = { model = "hamrok_long", viscosity = "400 cP" }',
     ['joints.B.lubrication.model: must be one of', '(did you mean "hamrock_long"?)']),
    ('lubrication = { model = "reynolds_exact", viscosity = "40 cP", cavitation = "elrod_adams" }',
     ["joints.B.lubrication.cavitation: elrod_adams (mass-conserving) needs a lubricant supply: set "
      "groove_supply_pressure or an ambient_pressure > 0"]),
    ('lubrication = { model = "reynolds_table", viscosity = "40 cP", groove_supply_pressure = "2 bar" }',
     ["joints.B.lubrication.model: force tables cover Gumbel and Swift-Stieber cavitation with ambient ends and "
      "no groove; use reynolds_exact"]),
    ('lubrication = { model = "reynolds_exact", viscosity = "40 cP", grid = [3, 3] }',
     ["joints.B.lubrication.grid: must be [cells around, cells along the axis], whole numbers >= 4, got [3, 3]"]),
])
def test_bad_lubrication_is_reported_at_its_location(replacement, messages):
    text = LUBRICATED.read_text()
    assert LUBRICATION_LINE in text
    with pytest.raises(jp.ModelError) as info:
        jp.loads(text.replace(LUBRICATION_LINE, replacement)).compile()
    for message in messages:
        assert message in str(info.value), str(info.value)
