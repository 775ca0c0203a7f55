"""The tables of a model file, as pydantic models (one class per table or variant).

Quantities arrive as SI floats that remember their text (:class:`~.fields.Q`).
Tables tagged by ``type`` (joints, forces), ``law`` (contact, stiffness,
friction) or ``kind`` (functions of time) are dispatched by
:mod:`.build`, which then validates the matching class here. Defaults carry
their reason where they have one; docs/model-files.md lists every key.
"""

from typing import Annotated, Any

from pydantic import Field, PlainValidator

from .fields import Count, Flag, Q, Strict, choice, fail, quantity, text, vector

Length = quantity("length")
PositiveLength = quantity("length", gt=0)
ZERO_VECTOR = (Q(0.0, "0"), Q(0.0, "0"))


def _req(kind: str) -> Any:
    """A required field whose missing-value message names what is expected."""
    return Field(..., description=kind)


# model, ground, bodies ------------------------------------------------------

class ModelTable(Strict):
    """``[model]``: name, description and gravity."""

    name: text("the model") = None
    description: text("the model") = ""
    gravity: vector("acceleration") = ZERO_VECTOR


class GroundTable(Strict):
    """``[ground]``: named points of the fixed frame, global coordinates."""

    points: dict[str, Any] = Field(default_factory=dict)


class BodyTable(Strict):
    """``[bodies.NAME]``: a rigid body with its frame at the centre of mass."""

    mass: quantity("mass", gt=0) = _req('a mass, e.g. "0.3 kg"')
    inertia: quantity("inertia", gt=0) = _req('a moment of inertia about the centre of mass, e.g. "1e-4 kg m^2"')
    position: vector("length") = ZERO_VECTOR
    angle: quantity("angle") = Q(0.0, "0 rad")
    velocity: vector("velocity") = ZERO_VECTOR
    angular_velocity: quantity("angular velocity") = Q(0.0, "0 rad/s")
    points: dict[str, Any] = Field(default_factory=dict)
    free: Flag = False


# joints --------------------------------------------------------------------

POINT = 'a point "body.point", e.g. "crank.A" or "ground.O"'


class RevoluteTable(Strict):
    """``type = "revolute"``: an ideal pin."""

    type: str
    first: text("a point") = _req(POINT)
    second: text("a point") = _req(POINT)


class FixedTable(RevoluteTable):
    """``type = "fixed"``: an ideal weld."""


class TranslationalTable(RevoluteTable):
    """``type = "translational"``: an ideal slider along ``axis`` (first body's frame)."""

    axis: vector("dimensionless") = (Q(1.0, "1"), Q(0.0, "0"))


class MaterialTable(Strict):
    """An elastic material (steel by default: 207 GPa, 0.3, as the Flores papers use)."""

    youngs_modulus: quantity("pressure", gt=0) = _req('a Young\'s modulus, e.g. "207 GPa"')
    poisson_ratio: quantity("dimensionless", gt=-1, lt=0.5, interval="(-1, 0.5)") = _req("a number, e.g. 0.3")


STEEL = MaterialTable(youngs_modulus=Q(207e9, "207 GPa"), poisson_ratio=Q(0.3, "0.3"))


class ClearanceRevoluteTable(Strict):
    """``type = "clearance_revolute"``: a dry revolute joint with radial clearance."""

    type: str
    bearing: text("a point") = _req(POINT + " (centre of the bore)")
    journal: text("a point") = _req(POINT + " (centre of the pin)")
    bearing_radius: PositiveLength = _req('the bore radius, a length, e.g. "10 mm"')
    clearance: quantity("length", gt=0) = None
    journal_radius: quantity("length", gt=0) = None
    length: quantity("length", gt=0) = None
    bearing_material: MaterialTable = STEEL
    journal_material: MaterialTable = STEEL
    contact: Any = _req('a table such as { law = "lankarani_nikravesh", restitution = 0.9 }')
    stiffness: Any = None
    friction: Any = None
    initial_eccentricity: vector("length") = ZERO_VECTOR
    # true: assembly holds the journal at initial_eccentricity with the ideal mechanism's velocities
    lock_at_assembly: Flag = True
    # 1e-4 m/s: small against impact velocities of machinery, bounds delta_dot / delta_dot_minus (core default)
    onset_velocity_floor: quantity("velocity", gt=0) = Q(1e-4, "0.0001 m/s")
    max_penetration: quantity("length", gt=0) = None
    lubrication: Any = None


JOINTS: dict[str, type[Strict]] = {
    "revolute": RevoluteTable, "translational": TranslationalTable, "fixed": FixedTable,
    "clearance_revolute": ClearanceRevoluteTable,
}


# laws of a clearance joint -------------------------------------------------

Restitution = quantity("dimensionless", gt=0, le=1, interval="(0, 1]")
Coefficient = quantity("dimensionless", ge=0)
Speed = quantity("velocity", gt=0)


class HertzLaw(Strict):
    """``law = "hertz"``: elastic, no dissipation."""

    law: str


class DampedLaw(Strict):
    """Hunt-Crossley, Lankarani-Nikravesh, Flores, Gonthier, Hu-Guo: need a restitution."""

    law: str
    restitution: Restitution = _req("a coefficient of restitution in (0, 1], e.g. 0.9")


CONTACT_LAWS: dict[str, type[Strict]] = {
    "hertz": HertzLaw, "hunt_crossley": DampedLaw, "lankarani_nikravesh": DampedLaw, "flores": DampedLaw,
    "gonthier": DampedLaw, "hu_guo": DampedLaw,
}


class HertzCylinderLaw(Strict):
    """``law = "hertz_cylinder"``: K delta^n, K = (4/3) E* sqrt(R*); n = 1.5 for metals unless given."""

    law: str
    exponent: quantity("dimensionless", gt=0) = None


class LineLaw(Strict):
    """``johnson_line`` or ``rogers_andrews``: need the joint's ``length``."""

    law: str


STIFFNESS_LAWS: dict[str, type[Strict]] = {
    "hertz_cylinder": HertzCylinderLaw, "hertz_cylinder_exponent": HertzCylinderLaw,
    "johnson_line": LineLaw, "rogers_andrews": LineLaw,
}


class NoFriction(Strict):
    """``law = "none"``."""

    law: str


class CoulombLaw(Strict):
    """``law = "coulomb"``: regularised by tanh(v / velocity_tolerance)."""

    law: str
    coefficient: Coefficient = _req("a friction coefficient, e.g. 0.01")
    velocity_tolerance: Speed = Q(1e-3, "0.001 m/s")


class AmbrosioLaw(Strict):
    """``law = "ambrosio"``: none below v0, full above v1, linear between."""

    law: str
    coefficient: Coefficient = _req("a friction coefficient, e.g. 0.01")
    v0: quantity("velocity", ge=0) = Q(1e-4, "0.0001 m/s")
    v1: Speed = Q(1e-3, "0.001 m/s")


class ThrelfallLaw(Strict):
    """``law = "threlfall"``: mu F_n (1 - exp(-3|v|/v0))."""

    law: str
    coefficient: Coefficient = _req("a friction coefficient, e.g. 0.01")
    v0: Speed = Q(1e-3, "0.001 m/s")


class StictionLaw(Strict):
    """``law = "stiction"``: static and kinetic coefficients with velocity tolerances."""

    law: str
    static_coefficient: Coefficient = _req("a friction coefficient, e.g. 0.15")
    kinetic_coefficient: Coefficient = _req("a friction coefficient, e.g. 0.1")
    stiction_velocity: Speed = Q(1e-4, "0.0001 m/s")
    transition_velocity: Speed = Q(1e-3, "0.001 m/s")


FRICTION_LAWS: dict[str, type[Strict]] = {
    "none": NoFriction, "coulomb": CoulombLaw, "ambrosio": AmbrosioLaw, "threlfall": ThrelfallLaw,
    "stiction": StictionLaw,
}


# drivers and forces --------------------------------------------------------

class DriverTable(Strict):
    """``[drivers.NAME]``: prescribes a revolute joint's angle or a translational joint's displacement."""

    joint: text("a joint") = _req("the name of a revolute or translational joint")
    function: Any = _req('a function of time, e.g. { kind = "constant_speed", rate = "5000 rpm" }')


class SpringDamperTable(Strict):
    """``type = "spring_damper"``: linear spring and damper between two points, tension positive."""

    type: str
    first: text("a point") = _req(POINT)
    second: text("a point") = _req(POINT)
    stiffness: quantity("stiffness", ge=0) = Q(0.0, "0 N/m")
    damping: quantity("damping", ge=0) = Q(0.0, "0 N s/m")
    free_length: quantity("length", ge=0) = _req('a length, e.g. "100 mm"')


class RotationalSpringDamperTable(Strict):
    """``type = "rotational_spring_damper"``: torsional spring and damper between two bodies."""

    type: str
    first: text("a body") = _req('a body name (or "ground")')
    second: text("a body") = _req("a body name")
    stiffness: quantity("rotational stiffness", ge=0) = Q(0.0, "0 N m/rad")
    damping: quantity("rotational damping", ge=0) = Q(0.0, "0 N m s/rad")
    free_angle: quantity("angle") = Q(0.0, "0 rad")


class PointForceTable(Strict):
    """``type = "point_force"``: a force at a point, global components (numbers or functions of time)."""

    type: str
    point: text("a point") = _req(POINT)
    fx: Any = 0.0
    fy: Any = 0.0


class TorqueTable(Strict):
    """``type = "torque"``: a torque on a body, counter-clockwise positive."""

    type: str
    body: text("a body") = _req("a body name")
    torque: Any = _req('a torque or a function of time, e.g. "2 N m"')


FORCES: dict[str, type[Strict]] = {
    "spring_damper": SpringDamperTable, "rotational_spring_damper": RotationalSpringDamperTable,
    "point_force": PointForceTable, "torque": TorqueTable,
}


# simulation ----------------------------------------------------------------

def _output_bytes(raw: Any) -> int:
    from ..resultsfile import parse_size

    try:
        return parse_size(raw)
    except ValueError as exc:
        raise fail(str(exc)) from None


class SimulationTable(Strict):
    """``[simulation]``: default options of ``jointplay run`` and ``Model.simulate``."""

    t_end: quantity("time", gt=0) = None
    t0: quantity("time") = None
    method: choice("dopri5", "adams", "bdf", aliases={"rk45": "dopri5", "dormand_prince": "dopri5",
                                                      "adams_pc": "adams", "ndf": "bdf"}) = None
    rtol: quantity("dimensionless", gt=0) = None
    atol: quantity("dimensionless", ge=0) = None
    max_step: quantity("time", gt=0) = None
    output_step: quantity("time", gt=0) = None
    initial_step: quantity("time", gt=0) = None
    min_step: quantity("time", gt=0) = None
    max_steps: Count = None
    stabilization: choice("projection", "baumgarte", "none") = None
    max_output_bytes: Annotated[int, PlainValidator(_output_bytes)] = None


TOP_LEVEL = ("model", "units", "ground", "bodies", "joints", "drivers", "forces", "simulation")


# lubrication ---------------------------------------------------------------

FILM_MODELS = ("squeeze_film_short", "squeeze_film_long", "hamrock_short", "hamrock_long", "frene_short",
               "frene_long", "pinkus_sternlicht_long", "reynolds_exact", "reynolds_table")
REYNOLDS_MODELS = ("reynolds_exact", "reynolds_table")
#: Keys of a lubrication table that only the Reynolds solver reads (the closed forms have no grid,
#: cavitation condition or boundary pressures).
REYNOLDS_ONLY_KEYS = ("cavitation", "grid", "ambient_pressure", "groove_supply_pressure")


class LubricationTable(Strict):
    """``lubrication = { model = "hamrock_short", viscosity = "400 cP" }`` in a clearance joint."""

    model: choice(*FILM_MODELS) = _req(f"a film model, one of {', '.join(FILM_MODELS)}")
    viscosity: quantity("viscosity", gt=0) = _req('a viscosity, e.g. "400 cP"')
    transition: Any = None
    cavitation: choice("gumbel", "swift_stieber", "elrod_adams", aliases={"reynolds": "swift_stieber",
                                                                          "half_sommerfeld": "gumbel",
                                                                          "jfo": "elrod_adams"}) = "swift_stieber"
    grid: Any = None
    ambient_pressure: quantity("pressure") = Q(0.0, "0 Pa")
    groove_supply_pressure: quantity("pressure") = None


class SwitchTransition(Strict):
    """``transition = { law = "switch" }``: film until contact, contact after."""

    law: str


class FloresTransition(Strict):
    """``transition = { law = "flores", lubricated_limit = 0.95 }``."""

    law: str
    lubricated_limit: quantity("dimensionless", gt=0, lt=1) = Q(0.95, "0.95")


class WangTransition(Strict):
    """``transition = { law = "wang_improved" }``: from the safe film thickness (0.00015 D by default) to contact."""

    law: str
    safe_film_thickness: quantity("length", gt=0) = None


TRANSITION_LAWS: dict[str, type[Strict]] = {
    "switch": SwitchTransition, "flores": FloresTransition, "wang_improved": WangTransition,
}
