"""Every table of a model file and its keys, defined once: name, kind, default with its reason, range, doc.

A :class:`Table` lists the :class:`Param`\\ s of one table of a model file (``[bodies.NAME]``), of one
variant of a tagged table (``type = "spring_damper"``, ``law = "ambrosio"``, ``kind = "sine"``) or of a
nested table (a material). Everything else follows from these definitions:

- the pydantic classes that validate model files (:mod:`jointplay.modelfile.schema`);
- the core's spec built from a file or from the Python builder (:mod:`jointplay.modelfile.build`), so the
  front end sends every value explicitly;
- the defaults of the builder (:class:`jointplay.Model`), of the law helpers (:mod:`jointplay.laws`) and of
  the functions of time (:mod:`jointplay.functions`), and the key lists in their docstrings;
- the TOML writer (:mod:`jointplay.modelfile.writer`);
- the reference of every key, ``docs/model-file-reference.md`` (:mod:`jointplay.modelfile.reference`).

Defaults are in SI units. ``import jointplay`` reads this module, so it loads neither pint nor pydantic.

To add an element (a force element, say): define its :class:`Table` here (``tag="type"``, its keys in the
order of the core's spec) and add it to :data:`FORCES`; add one builder line to :class:`jointplay.Model`
(``add_x = _adds(p.X, "forces", positional=2)``); the core's ``ForceSpec`` gets a variant with the same keys.
A bound between two keys of a table (``rod_side_area < piston_area``) is a :class:`Relation` of the table: model
files and the builder check it, the reference lists it. A new law family goes into :data:`LAWS`, with one helper
line per law in :mod:`jointplay.laws`. Then
regenerate ``docs/model-file-reference.md`` and use every new key in ``tests/fixtures/every_key.toml``
(``tests/test_parameters.py`` says what is missing).

The ranges (``gt``, ``ge``, ``lt``, ``le``) are the core's too: ``python -m jointplay.boundary`` writes them into
``crates/jointplay-core/src/spec/ranges.rs``, whose constants the core's checks use, and
``tests/test_parameter_boundary.py`` compares the keys, the defaults and the ranges with the core's own.
"""

from __future__ import annotations

import operator
from dataclasses import dataclass
from dataclasses import replace as _replace
from typing import Any

from ._core import MAX_REYNOLDS_GRID_NODES as _MAX_GRID_NODES
from .orientation import EULER_ALIASES as _EULER_ALIASES
from .orientation import EULER_SEQUENCES as _EULER_SEQUENCES
from .resultsfile import DEFAULT_MAX_FILE_BYTES, DEFAULT_MAX_MEMORY_BYTES, format_size


class _Required:
    def __repr__(self) -> str:
        return "REQUIRED"


#: The default of a key that must be given.
REQUIRED: Any = _Required()

#: Kinds of value that are not a physical quantity of :data:`jointplay.units.KINDS` (``"length"``, ...):
#: ``vector`` (a pair of quantities of kind ``of``), ``point`` (``"body.point"``), ``body``, ``joint``,
#: ``text`` (a name, ``of`` says of what), ``flag`` (true/false), ``count`` (a positive whole number),
#: ``choice`` (one of the words ``of``), ``function`` (a function of time whose values are of kind ``of``),
#: ``law`` (a table of the law family ``of``), ``table`` (a nested table defined by the Table ``of``),
#: ``points`` (named points), ``grid`` (cells of the Reynolds solver), ``size`` (bytes), ``list`` (a list of
#: quantities; ``of`` is their kind, or ``"powers"`` for polynomial coefficients), ``variant`` (a nested table
#: of the family ``of`` of :data:`VARIANTS`, chosen by its tag: a beam's section), ``arclengths`` (named points
#: of a beam by their arclength), ``nodes`` (named nodes of a modal body: arclengths on a beam, node numbers
#: with matrices), ``matrix`` (a matrix or a list of node positions from a file or given
#: inline, read by :mod:`jointplay.modelfile.matrices`). Inside a function of time, ``value`` and ``rate`` stand for the kind the
#: function prescribes and its rate per second.
STRUCTURED = ("vector", "point", "body", "joint", "text", "flag", "count", "choice", "function", "law", "table",
              "points", "grid", "size", "list", "value", "rate", "variant", "arclengths", "nodes", "matrix",
              *("vector3", "orientation", "inertia_tensor", "markers", "function3"))
#: Kinds of spatial models (:mod:`jointplay.orientation` reads them): ``vector3`` (three quantities of kind ``of``),
#: ``orientation`` (axis and angle, Euler angles with their sequence, a rotation matrix or a quaternion; a unit
#: quaternion ``[w, x, y, z]`` in the core's spec), ``inertia_tensor`` (principal moments with their axes, or a full
#: tensor; a 3 x 3 tensor in the spec), ``markers`` (named points, each a 3-vector or a position with axes),
#: ``function3`` (three functions of time whose values are of kind ``of``).
SPATIAL_KINDS = STRUCTURED[-5:]


@dataclass(frozen=True, eq=False)
class Param:
    """One key of a table."""

    key: str
    #: a kind of physical quantity (``"length"``, ``"angular velocity"``, ``"dimensionless"``) or one of
    #: :data:`STRUCTURED`
    kind: str
    #: what the key means, one sentence or two; units follow from the kind
    doc: str
    #: value when the key is absent, in SI units; :data:`REQUIRED` when it must be given; None when absent
    #: means "not given" (``default_text`` then says what that means)
    default: Any = REQUIRED
    #: why the default is what it is (shown in the reference)
    why: str = ""
    #: what an absent optional key means, when that is not a value (``"5 % of the journal radius"``)
    default_text: str = ""
    #: the allowed range: bounds (``gt``: greater than...) and, when given, how messages write it
    gt: float | None = None
    ge: float | None = None
    lt: float | None = None
    le: float | None = None
    interval: str | None = None
    #: the kind of the items of a ``vector``, ``function`` or ``list``, the words of a ``choice``, the family
    #: of a ``law``, the :class:`Table` of a ``table``, what a ``text`` names
    of: Any = None
    #: other words accepted for a ``choice``, each mapped to one of its words
    aliases: tuple[tuple[str, str], ...] = ()
    #: what the message of a missing required key shows, e.g. ``a mass, e.g. "0.3 kg"``
    example: str = ""
    #: False for keys that only the front end reads (``free``, ``journal_radius``): not in the core's spec
    in_spec: bool = True
    #: True for a ``table`` checked on its own, after its parent (lubrication)
    apart: bool = False

    @property
    def required(self) -> bool:
        return self.default is REQUIRED

    @property
    def bounds(self) -> dict[str, Any]:
        """The range as keyword arguments of :func:`jointplay.modelfile.fields.quantity`."""
        names = ("gt", "ge", "lt", "le", "interval")
        return {n: getattr(self, n) for n in names if getattr(self, n) is not None}


#: How a :class:`Relation` compares two keys, and how its message says it.
RELATIONS = {"<": "smaller than", "<=": "at most", ">": "greater than", ">=": "at least"}
_COMPARE = {"<": operator.lt, "<=": operator.le, ">": operator.gt, ">=": operator.ge}


@dataclass(frozen=True, eq=False)
class Relation:
    """A bound of one key by another key of the same table (``rod_side_area < piston_area``) or by a fixed
    number (``rtol >= 2.2e-14``), checked once both are valid; a problem at ``key`` when it fails.

    A key in ``absent`` stands, when not given, for that value (a default the core sets without it being
    written, such as ``min_step``): the bound is then checked against it and, when only ``other`` was given,
    reported at ``other`` (the key the user set); otherwise an absent key leaves the bound unchecked."""

    key: str
    #: one of :data:`RELATIONS`
    op: str
    #: the key bounding ``key``, or a number
    other: str | float
    #: why the bound holds, for the message (``"it is the annulus"``)
    why: str = ""
    #: ``(key, value)``: what an absent key stands for
    absent: tuple[tuple[str, float], ...] = ()

    def holds(self, value: float, other: float) -> bool:
        return _COMPARE[self.op](value, other)

    def text(self) -> str:
        """``rod_side_area < piston_area (it is the annulus)``, for the reference."""
        other = f"`{self.other}`" if isinstance(self.other, str) else f"{self.other:.3g}"
        notes = [self.why] if self.why else []
        notes += [f"`{key}` not given stands for its default, {value:g}" for key, value in self.absent]
        return f"`{self.key}` {self.op} {other}" + (f" ({'; '.join(notes)})" if notes else "")

    def violation(self, given: Any, show: Any) -> tuple[str, str] | None:
        """``(key, message)`` when the bound fails, None when it holds or cannot be checked. ``given(key)``
        is a key's valid value or None (absent or invalid); ``show(key, value)`` writes a value for the
        message (as the user wrote it, or with its unit)."""
        value = given(self.key)
        other = given(self.other) if isinstance(self.other, str) else self.other
        absent = dict(self.absent)
        why = f" ({self.why})" if self.why else ""
        unset = "(its value when not given" + (f"; {self.why})" if self.why else ")")
        if value is not None and other is not None:
            if self.holds(value, other):
                return None
            bound = f"{self.other} = {show(self.other, other)}" if isinstance(self.other, str) else f"{other:.3g}"
            return self.key, f"must be {RELATIONS[self.op]} {bound}{why}, got {show(self.key, value)}"
        if value is not None and self.other in absent:
            other = absent[self.other]
            if self.holds(value, other):
                return None
            return self.key, (f"must be {RELATIONS[self.op]} {self.other} = {show(self.other, other)} {unset}, "
                              f"got {show(self.key, value)}")
        if other is not None and self.key in absent:
            value = absent[self.key]
            if self.holds(value, other):
                return None
            return self.other, (f"must be {RELATIONS[_REVERSED[self.op]]} {self.key} = {show(self.key, value)} "
                                f"{unset}, got {show(self.other, other)}")
        return None


_REVERSED = {"<": ">", "<=": ">=", ">": "<", ">=": "<="}


@dataclass(frozen=True, eq=False)
class Table:
    """The keys of one table, or of one variant of a table tagged by ``type``, ``law`` or ``kind``."""

    #: the word of the variant (``"spring_damper"``), or the table's own name (``"bodies"``)
    name: str
    #: what it is, one or two sentences (the builder's and the reference's text)
    doc: str
    params: tuple[Param, ...] = ()
    #: the key that names the variant: ``"type"``, ``"law"``, ``"kind"``; None for a plain table
    tag: str | None = None
    #: other words for the variant, accepted in files (``hertz_cylinder_exponent``)
    aliases: tuple[str, ...] = ()
    #: True when absent keys stay absent (``[simulation]``: the defaults apply when a run starts)
    sparse: bool = False
    #: bounds between keys, checked after each key's own range
    relations: tuple[Relation, ...] = ()

    def __getitem__(self, key: str) -> Param:
        for p in self.params:
            if p.key == key:
                return p
        raise KeyError(f"{self.name} has no key {key!r}")

    def keys(self) -> list[str]:
        return [p.key for p in self.params]

    def default(self, key: str) -> Any:
        """The default of ``key`` (:data:`REQUIRED` when it has none)."""
        return self[key].default


def family(*tables: Table) -> dict[str, Table]:
    """Variants by the word that names them, aliases after their table (the order of messages)."""
    out: dict[str, Table] = {}
    for t in tables:
        out[t.name] = t
        for alias in t.aliases:
            out[alias] = t
    return out


def variants(tables: dict[str, Table]) -> list[Table]:
    """The distinct tables of a family, aliases left out."""
    return [t for name, t in tables.items() if name == t.name]


POINT = 'a point "body.point", e.g. "crank.A" or "ground.O"'


def _point(key: str, doc: str, example: str = POINT) -> Param:
    return Param(key, "point", doc, example=example)


# model, ground, bodies ------------------------------------------------------

#: The kinematics of a model: ``[model] kinematics``.
KINEMATICS = ("planar", "spatial")

MODEL = Table("model", "Name, description and gravity of the mechanism.", (
    Param("name", "text", "name of the mechanism, written into the results", None, of="the model",
          default_text="the file name"),
    Param("description", "text", "free text (not used by the engine)", "", of="the model", in_spec=False),
    Param("gravity", "vector", 'gravitational acceleration, e.g. `[0, "-9.81 m/s^2"]`', (0.0, 0.0),
          of="acceleration"),
    Param("kinematics", "choice", "`planar`: bodies move in the x-y plane; `spatial`: rigid bodies move in space, "
          "with orientations, inertia tensors and spatial joints (docs/model-files.md, \"Spatial models\")",
          "planar", of=KINEMATICS, in_spec=False, why="the engine's planar fast path"),
))

GROUND = Table("ground", "Named points of the fixed frame, in global coordinates.", (
    Param("points", "points", 'named points: `points = { O = ["0 mm", "0 mm"] }`', {}),
))

BODY = Table("bodies", "A rigid body; its frame is at its centre of mass.", (
    Param("mass", "mass", "mass of the body", gt=0, example='a mass, e.g. "0.3 kg"'),
    Param("inertia", "inertia", "moment of inertia about the centre of mass", gt=0,
          example='a moment of inertia about the centre of mass, e.g. "1e-4 kg m^2"'),
    Param("position", "vector", "approximate initial position of the centre of mass (assembly makes the "
          "configuration consistent)", (0.0, 0.0), of="length"),
    Param("angle", "angle", "approximate initial orientation", 0.0),
    Param("velocity", "vector", "approximate initial velocity of the centre of mass", (0.0, 0.0), of="velocity"),
    Param("angular_velocity", "angular velocity", "approximate initial angular velocity", 0.0),
    Param("points", "points", 'named points in body coordinates: `points = { O = ["-25 mm", 0], A = ["25 mm", 0] }`',
          {}),
    Param("free", "flag", "allow a body that no joint or force element refers to (otherwise an error)", False,
          in_spec=False),
))


# laws of a clearance joint --------------------------------------------------

MATERIAL = Table("material", "An elastic material.", (
    Param("youngs_modulus", "pressure", "Young's modulus E", gt=0, example='a Young\'s modulus, e.g. "207 GPa"'),
    Param("poisson_ratio", "dimensionless", "Poisson's ratio nu", gt=-1, lt=0.5, interval="(-1, 0.5)",
          example="a number, e.g. 0.3"),
))

#: Structural steel, E = 207 GPa, nu = 0.3: the default material of a clearance joint.
STEEL = {"youngs_modulus": 207e9, "poisson_ratio": 0.3}

#: The coefficient of restitution e of a law whose hysteresis factor D(e) divides by e (Flores, Gonthier, Hu-Guo:
#: D is infinite at e = 0, docs/theory/contact-flores.md).
RESTITUTION = Param("restitution", "dimensionless", "coefficient of restitution e", gt=0, le=1, interval="(0, 1]",
                    example="a coefficient of restitution in (0, 1], e.g. 0.9")
#: The coefficient of restitution of a law whose D(e) is finite at e = 0 (Hunt-Crossley, Lankarani-Nikravesh).
RESTITUTION_FROM_ZERO = _replace(RESTITUTION, gt=None, ge=0, interval="[0, 1]",
                                 example="a coefficient of restitution in [0, 1], e.g. 0.9")


def _damped(name: str, doc: str, restitution: Param = RESTITUTION) -> Table:
    return Table(name, doc, (restitution,), tag="law")


CONTACT_LAWS = family(
    Table("hertz", "Elastic Hertz contact, no dissipation.", tag="law"),
    _damped("hunt_crossley", "Hunt-Crossley, D = 3(1-e)/2.", RESTITUTION_FROM_ZERO),
    _damped("lankarani_nikravesh", "Lankarani-Nikravesh, D = 3(1-e^2)/4 (accurate for e near 1).",
            RESTITUTION_FROM_ZERO),
    _damped("flores", "Flores et al. 2011, D = 8(1-e)/(5e) (for any e > 0)."),
    _damped("gonthier", "Gonthier et al. 2004, D = (1-e^2)/e."),
    _damped("hu_guo", "Hu and Guo 2015, D = 3(1-e)/(2e)."),
)

#: The exponent n of the Hertz-type law K delta^n when none is given: 1.5, for metals (the core's
#: ``hertz_cylinder``; the plausibility check uses it too).
HERTZ_EXPONENT = 1.5

STIFFNESS_LAWS = family(
    Table("hertz_cylinder", "K delta^n with K = (4/3) E* sqrt(R*), the Hertz-type law of a cylinder in a bore.", (
        Param("exponent", "dimensionless", "exponent n", None, gt=0, default_text=f"{HERTZ_EXPONENT} (metals)"),
    ), tag="law", aliases=("hertz_cylinder_exponent",)),
    Table("johnson_line", "Johnson / ESDU line contact of a cylinder in a bore (needs the joint's `length`).",
          tag="law"),
    Table("rogers_andrews", "Rogers-Andrews logarithmic law (needs the joint's `length`).", tag="law"),
)

COEFFICIENT = Param("coefficient", "dimensionless", "friction coefficient mu", ge=0,
                    example="a friction coefficient, e.g. 0.01")
FLORES_BAND = "the values of the Flores-Ambrosio slider-crank, examples/flores_slider_crank_dry"

FRICTION_LAWS = family(
    Table("none", "No friction.", tag="law"),
    Table("coulomb", "Coulomb friction regularised by tanh(v / velocity_tolerance).", (
        COEFFICIENT,
        Param("velocity_tolerance", "velocity", "regularisation velocity", 1e-3, gt=0),
    ), tag="law"),
    Table("ambrosio", "Modified Coulomb law of Ambrosio: no friction below v0, full above v1, linear between.", (
        COEFFICIENT,
        Param("v0", "velocity", "end of the dead band", 1e-4, ge=0, why=FLORES_BAND),
        Param("v1", "velocity", "speed of full friction (> v0)", 1e-3, gt=0, why=FLORES_BAND),
    ), tag="law", relations=(
        Relation("v1", ">", "v0", "friction rises from none at v0 to full at v1"),)),
    Table("threlfall", "Threlfall: mu F_n (1 - exp(-3|v|/v0)).", (
        COEFFICIENT,
        Param("v0", "velocity", "speed at which 95 % of mu F_n is reached", 1e-3, gt=0),
    ), tag="law"),
    Table("stiction", "Static and kinetic coefficients with velocity tolerances.", (
        Param("static_coefficient", "dimensionless", "static coefficient (>= kinetic_coefficient)", ge=0,
              example="a friction coefficient, e.g. 0.15"),
        Param("kinetic_coefficient", "dimensionless", "kinetic coefficient", ge=0,
              example="a friction coefficient, e.g. 0.1"),
        Param("stiction_velocity", "velocity", "velocity at which the static coefficient is reached", 1e-4, gt=0),
        Param("transition_velocity", "velocity", "velocity from which the kinetic coefficient holds", 1e-3, gt=0),
    ), tag="law", relations=(
        Relation("static_coefficient", ">=", "kinetic_coefficient", "the break-away coefficient is not below the sliding one"),
        Relation("transition_velocity", ">", "stiction_velocity", "the kinetic coefficient is reached after the static one"),)),
)

TRANSITION_LAWS = family(
    Table("switch", "Film force until contact, contact force after (paper 000's squeeze-film joint).", tag="law"),
    Table("flores", "Flores et al.: squeeze film only, faded out between eccentricity ratio `lubricated_limit` "
          "and contact.", (
              Param("lubricated_limit", "dimensionless", "eccentricity ratio where the fading starts", 0.95,
                    gt=0, lt=1, why="the Flores default, for want of the source value; "
                                    "docs/theory/lubricated-contact-transition.md"),
          ), tag="law"),
    Table("wang_improved", "Paper 001's transition: squeeze and wedge film faded out from the safe film thickness "
          "to contact.", (
              Param("safe_film_thickness", "length", "film thickness where the fading starts", None, gt=0,
                    default_text="0.00015 of the diameter (paper 001's design rule; set by the core)"),
          ), tag="law"),
)

PAPER002_SEAL = "paper 002, section 2.2: its rod seal"

SEAL_FRICTION_LAWS = family(
    Table("lugre_seal", "LuGre bristle friction of the cylinder's seals: stiction, presliding and the Stribeck drop "
          "from the static to the kinetic force; the bristle deflection is a state of the simulation "
          "(docs/theory/friction-lugre.md). The defaults are paper 002's seal forces with chosen bristle dynamics.", (
        Param("static_force", "force", "static (break-away) force F_S, at least `kinetic_force`", 385.0, gt=0,
              why=PAPER002_SEAL),
        Param("kinetic_force", "force", "kinetic (Coulomb) force F_C, reached in steady sliding", 340.0, gt=0,
              why=PAPER002_SEAL),
        Param("stribeck_velocity", "velocity", "Stribeck velocity v_S: the friction falls from F_S towards F_C "
              "over it", 3e-5, gt=0, why="chosen: least-squares fit to paper 002's friction curve, which falls "
                                         "from F_S at 0.01 mm/s to F_C at 0.05 mm/s"),
        Param("bristle_stiffness", "stiffness", "bristle stiffness sigma0; F_S/sigma0 is the largest bristle "
              "deflection", 1e7, gt=0, why="chosen: 38.5 um largest deflection, presliding of some tens of um "
                                          "as in elastomer seals"),
        Param("bristle_damping", "damping", "bristle damping sigma1 at rest, at most 4 sqrt(2e) F_C / "
              "`damping_velocity` (beyond it the law could create energy)", 1e4, ge=0,
              why="chosen: damping ratio 0.35 of the bristle mode of a 20 kg rod"),
        Param("viscous_coefficient", "damping", "viscous coefficient sigma2", 0.0, ge=0,
              why="chosen: paper 002's seal law has no viscous term"),
        Param("damping_velocity", "velocity", "velocity v_D over which the bristle damping fades", 1e-3, gt=0,
              why="chosen: damps the rod's vibrations on the oil spring up to mm/s, adds at most "
                  "0.91 sigma1 v_D (9 N) to the friction in a transient"),
        Param("stick_velocity", "velocity", "stroke rate below which the `stick` channel reports the seal "
              "sticking (it does not change the force)", 1e-5, gt=0,
              why="chosen: paper 002's stiction tolerance, 0.01 mm/s, reused as the stick threshold"),
    ), tag="law", aliases=("lugre",), relations=(
        Relation("static_force", ">=", "kinetic_force", "the break-away force is not below the sliding force"),)),
)

#: Law families whose core spec has no ``law`` tag, with the one law each holds: the core's seal friction
#: is the LuGre table itself. In a file the tag may be left out there too.
UNTAGGED_LAWS = {"seal_friction": "lugre_seal"}


def core_law(law: dict) -> dict:
    """A law's dict as the core reads it: the Hertz-type law with a chosen exponent is
    ``hertz_cylinder_exponent`` there (``hertz_cylinder`` with ``exponent`` in a model file), and the
    laws of :data:`UNTAGGED_LAWS` lose their tag."""
    if law["law"] in ("hertz_cylinder", "hertz_cylinder_exponent"):
        exponent = law.get("exponent")
        return {"law": "hertz_cylinder"} if exponent is None else {"law": "hertz_cylinder_exponent",
                                                                   "exponent": exponent}
    if any(law["law"] in LAWS[key] for key in UNTAGGED_LAWS):
        return {key: value for key, value in law.items() if key != "law"}
    return law


def tagged_law(law: dict, family: str) -> dict:
    """A law's dict with its ``law`` tag: an untagged one of a family of :data:`UNTAGGED_LAWS` (as the core
    reads it, or as a file may write it) is that family's law; other dicts are returned as they are."""
    if family in UNTAGGED_LAWS and "law" not in law:
        return {"law": UNTAGGED_LAWS[family], **law}
    return law


#: Law families by the key of a clearance joint, lubrication table or hydraulic cylinder that holds them.
LAWS = {"contact": CONTACT_LAWS, "stiffness": STIFFNESS_LAWS, "friction": FRICTION_LAWS,
        "transition": TRANSITION_LAWS, "seal_friction": SEAL_FRICTION_LAWS}

FILM_MODELS = ("squeeze_film_short", "squeeze_film_long", "hamrock_short", "hamrock_long", "frene_short",
               "frene_long", "pinkus_sternlicht_long", "reynolds_exact", "reynolds_table")
REYNOLDS_MODELS = ("reynolds_exact", "reynolds_table")
#: The Reynolds solver's grid when none is given, cells around x cells along the axis: the core's default
#: (Python sends null cell counts then); the steady-bearing tool (``jointplay bearing``) uses it too.
REYNOLDS_GRID = (120, 16)
CAVITATIONS = ("gumbel", "swift_stieber", "elrod_adams")
#: Keys of a lubrication table that only the Reynolds solver reads (the closed forms have no grid,
#: cavitation condition or boundary pressures).
REYNOLDS_ONLY_KEYS = ("cavitation", "grid", "ambient_pressure", "groove_supply_pressure")

LUBRICATION = Table("lubrication", "A lubricant film in the clearance (docs/theory/lubricated-clearance-joint.md); "
                    "the film uses the journal radius, the joint's `length` and its clearance.", (
    Param("model", "choice", "film model: closed forms, or `reynolds_exact` (finite-difference Reynolds solve at "
          "every evaluation) and `reynolds_table` (tables precomputed by the same solver)", of=FILM_MODELS,
          example=f"a film model, one of {', '.join(FILM_MODELS)}"),
    Param("viscosity", "viscosity", 'dynamic viscosity: `"400 cP"`, `"0.4 Pa s"`', gt=0,
          example='a viscosity, e.g. "400 cP"'),
    Param("transition", "law", "hand-over from the film force to dry contact", "wang_improved", of="transition",
          why="paper 001's improved law keeps the wedge effect, which the dynamic film models carry"),
    Param("cavitation", "choice", "Reynolds models only: cavitation condition (`elrod_adams` needs a supply: a "
          "groove)", "swift_stieber", of=CAVITATIONS,
          aliases=(("reynolds", "swift_stieber"), ("half_sommerfeld", "gumbel"), ("jfo", "elrod_adams"))),
    Param("grid", "grid", "Reynolds models only: `[cells around, cells along the axis]`, whole numbers >= 4; the "
          f"axial count must be even; at most {f'{_MAX_GRID_NODES:,}'.replace(',', ' ')} nodes "
          "`around x (along/2 + 1)` (solver memory and time)", None,
          default_text=f"the solver's, `[{REYNOLDS_GRID[0]}, {REYNOLDS_GRID[1]}]`"),
    Param("ambient_pressure", "pressure", "Reynolds models only: gauge pressure at the bearing ends, not below the "
          "cavitation pressure (gauge 0)", 0.0, ge=0),
    Param("groove_supply_pressure", "pressure", "Reynolds models only, `reynolds_exact` only: a circumferential "
          "groove at mid-length held at this pressure (paper 000), not below the cavitation pressure (gauge 0)",
          None, ge=0, default_text="no groove"),
))


def core_lubrication(lubrication: Any) -> Any:
    """A lubrication dict in the core's layout (``model``, ``viscosity``, ``transition``, ``reynolds``) with
    every key the core reads: the defaults of this definition for those not given, the transition law's keys
    included, and the Reynolds solver's options (which the closed forms ignore) for every model. Values given
    are kept as they are, unknown keys and what is not a dict too, for the core to report."""
    if not isinstance(lubrication, dict):
        return lubrication
    transition = lubrication.get("transition") or {"law": LUBRICATION.default("transition")}
    law = TRANSITION_LAWS.get(transition.get("law")) if isinstance(transition, dict) else None
    if law is not None:
        transition = {"law": transition["law"], **{param.key: param.default for param in law.params
                                                   if not param.required}, **transition}
    reynolds = lubrication.get("reynolds") or {}
    if isinstance(reynolds, dict):
        cells = LUBRICATION.default("grid") or (None, None)  # None: the solver's grid
        reynolds = {"cavitation": LUBRICATION.default("cavitation"), "n_circumferential": cells[0],
                    "n_axial": cells[1], "ambient_pressure": LUBRICATION.default("ambient_pressure"),
                    "groove_supply_pressure": LUBRICATION.default("groove_supply_pressure"), **reynolds}
    return {**lubrication, "transition": transition, "reynolds": reynolds}


# joints ---------------------------------------------------------------------

_ENDS = (_point("first", "point on the first body"), _point("second", "point on the second body"))

REVOLUTE = Table("revolute", "Ideal pin: the points `first` and `second` coincide.", _ENDS, tag="type")
TRANSLATIONAL = Table("translational", "Ideal slider: no relative rotation; `second` moves on the line through "
                      "`first` along `axis`.", (
    *_ENDS,
    Param("axis", "vector", "sliding direction in the first body's frame (normalised)", (1.0, 0.0),
          of="dimensionless"),
), tag="type")
FIXED = Table("fixed", "Ideal weld: the points coincide and the relative angle is held.", _ENDS, tag="type")

CLEARANCE_REVOLUTE = Table("clearance_revolute", "A revolute joint with radial clearance: a bore on the bearing's "
                           "body, a pin on the journal's body, contact and friction between them, and optionally "
                           "a lubricant film (docs/theory/clearance-revolute-joint.md).", (
    _point("bearing", "centre of the bore", POINT + " (centre of the bore)"),
    _point("journal", "centre of the pin", POINT + " (centre of the pin)"),
    Param("bearing_radius", "length", "bore radius R_b", gt=0, example='the bore radius, a length, e.g. "10 mm"'),
    Param("clearance", "length", "radial clearance c = R_b - R_j, smaller than `bearing_radius`; give exactly one of "
          "`clearance` and `journal_radius`", None, gt=0, default_text="from `journal_radius`"),
    Param("journal_radius", "length", "pin radius R_j, instead of `clearance`", None, gt=0,
          default_text="from `clearance`", in_spec=False),
    Param("length", "length", "axial length of the bearing; needed by the `johnson_line` and `rogers_andrews` "
          "stiffness laws and by lubrication", None, gt=0, default_text="none"),
    Param("bearing_material", "table", "elastic material of the bearing", STEEL, of=MATERIAL,
          why="structural steel, the value the Flores papers use"),
    Param("journal_material", "table", "elastic material of the journal", STEEL, of=MATERIAL,
          why="structural steel, the value the Flores papers use"),
    Param("contact", "law", "normal force law (dissipation)", of="contact",
          example='a table such as { law = "lankarani_nikravesh", restitution = 0.9 }'),
    Param("stiffness", "law", "contact stiffness law", "hertz_cylinder", of="stiffness",
          why="the law the Flores papers use"),
    Param("friction", "law", "friction law", "none", of="friction"),
    Param("initial_eccentricity", "vector", "journal centre from bearing centre at the start (global frame), "
          "within the clearance", (0.0, 0.0), of="length"),
    Param("lock_at_assembly", "flag", "assembly holds the journal at `initial_eccentricity` and gives the bodies the "
          "velocities of the ideal mechanism; `false` keeps the journal where the bodies' approximate positions put "
          "it, with their own velocities (a free journal, e.g. a single-impact test)", True,
          why="a clearance joint starts as the ideal mechanism"),
    Param("onset_velocity_floor", "velocity", "smallest contact-onset velocity used in the damping term; guards "
          "grazing entries", 1e-4, gt=0,
          why="small against the impact velocities of machinery, 0.01-1 m/s, yet it keeps "
              "delta_dot / delta_dot_minus bounded for grazing entries"),
    Param("max_penetration", "length", "penetration at which the run stops as unphysical", None, gt=0,
          default_text="5 % of the journal radius (set by the core)"),
    Param("lubrication", "table", "lubricant film; dry contact still acts once the journal touches the bore",
          None, of=LUBRICATION, apart=True, default_text="none (a dry joint)"),
), tag="type")

JOINTS = family(REVOLUTE, TRANSLATIONAL, FIXED, CLEARANCE_REVOLUTE)


# functions of time ----------------------------------------------------------

_VALUE = 'a {kind}, e.g. "{example}"'

FUNCTIONS = family(
    Table("constant", "A constant value.", (
        Param("value", "value", "the value", example=_VALUE),
    ), tag="kind"),
    Table("constant_rate", "`initial + rate t`: a crank at constant speed, a slider at constant velocity.", (
        Param("initial", "value", "value at t = 0", 0.0),
        Param("rate", "rate", 'value per second, e.g. `"5000 rpm"`', example='a rate, e.g. "{rate_example}"'),
    ), tag="kind", aliases=("constant_speed", "constant_velocity")),
    Table("polynomial", "`sum c_k t^k`.", (
        Param("coefficients", "list", "coefficients, constant term first; coefficient k has the unit value/s^k",
              of="powers", example="a list, constant term first"),
    ), tag="kind"),
    Table("cubic_step", "Smooth step `v0 + (v1 - v0) s^2 (3 - 2 s)`, `s = (t - t_start)/(t_end - t_start)`, "
          "constant outside.", (
        Param("t_start", "time", "start of the step", example="a time"),
        Param("t_end", "time", "end of the step (> t_start)", example="a time"),
        Param("value_start", "value", "value before the step", example=_VALUE),
        Param("value_end", "value", "value after the step", example=_VALUE),
    ), tag="kind"),
    Table("sine", "`offset + amplitude sin(2 pi frequency t + phase)`.", (
        Param("offset", "value", "mean value", 0.0),
        Param("amplitude", "value", "amplitude", example=_VALUE),
        Param("frequency", "frequency", "frequency", example='a frequency, e.g. "10 Hz"'),
        Param("phase", "angle", "phase", 0.0),
    ), tag="kind"),
    Table("table", "Natural cubic spline through `(times, values)`; linear beyond the ends.", (
        Param("times", "list", "times, strictly increasing, at least 2", of="time", example="a list of times"),
        Param("values", "list", "values, as many as times", of="value", example="a list of values ({kind})"),
    ), tag="kind", aliases=("spline",)),
    Table("speed_ramp", "A spin-up: at rest until t = 0, the rate rises smoothly to `final_rate` over `ramp_time` "
          "(`(w/T)[t^2/2 + (T/2 pi)^2 (cos(2 pi t/T) - 1)]`, Simo and Vu-Quoc 1986), then `w t - w T/2`; the "
          "acceleration is zero at both ends of the ramp (docs/theory/motion-functions.md).", (
        Param("ramp_time", "time", "duration T of the ramp", gt=0, example='a time, e.g. "15 s"'),
        Param("final_rate", "rate", 'rate w after the ramp, e.g. `"6 rad/s"`', example='a rate, e.g. "{rate_example}"'),
    ), tag="kind"),
)


# drivers and forces ---------------------------------------------------------

DRIVER = Table("drivers", "Prescribes a joint coordinate over time: the relative angle of a revolute joint (second "
               "body minus first) or the displacement along a translational joint.", (
    Param("joint", "joint", "a revolute or translational joint",
          example="the name of a revolute or translational joint"),
    Param("function", "function", "the prescribed coordinate: an angle (revolute) or a length (translational)",
          of="coordinate", example='a function of time, e.g. { kind = "constant_speed", rate = "5000 rpm" }'),
))

SPRING_DAMPER = Table("spring_damper", "Linear spring and damper between two points, tension positive.", (
    *_ENDS,
    Param("stiffness", "stiffness", "spring stiffness", 0.0, ge=0, why="no spring: a pure damper"),
    Param("damping", "damping", "damping coefficient", 0.0, ge=0, why="no damper: a pure spring"),
    Param("free_length", "length", "length at which the spring is relaxed", ge=0, example='a length, e.g. "100 mm"'),
), tag="type")

ROTATIONAL_SPRING_DAMPER = Table("rotational_spring_damper", "Torsional spring and damper on the relative angle of "
                                 "two bodies.", (
    Param("first", "body", 'first body (`"ground"` allowed)', example='a body name (or "ground")'),
    Param("second", "body", "second body", example="a body name"),
    Param("stiffness", "rotational stiffness", "spring stiffness", 0.0, ge=0, why="no spring: a pure damper"),
    Param("damping", "rotational damping", "damping coefficient", 0.0, ge=0, why="no damper: a pure spring"),
    Param("free_angle", "angle", "relative angle (second minus first) at which the spring is relaxed", 0.0),
), tag="type")

POINT_FORCE = Table("point_force", "A force at a point, global components (numbers or functions of time).", (
    _point("point", "point of application"),
    Param("fx", "function", "x component", 0.0, of="force"),
    Param("fy", "function", "y component", 0.0, of="force"),
), tag="type")

TORQUE = Table("torque", "A torque on a body, counter-clockwise positive.", (
    Param("body", "body", "the body it acts on", example="a body name"),
    Param("torque", "function", "the torque (a quantity or a function of time)", of="torque",
          example='a torque or a function of time, e.g. "2 N m"'),
), tag="type")

#: The lowest gauge pressure of a chamber [Pa]: absolute zero under a standard atmosphere (the core's floor;
#: below it the liquid would be in tension and the run stops).
PRESSURE_FLOOR = -101325.0
_START_PRESSURE = ("ambient; give the pressures that balance the load at the start "
                   "(p_cap piston_area - p_rod rod_side_area = load), or the rod jumps at t = 0")

HYDRAULIC_CYLINDER = Table("hydraulic_cylinder", "Double-acting single-rod hydraulic cylinder between two points, "
                           "acting along their line: barrel (cap end) at `first`, rod eye at `second`. Its force "
                           "pushes the points apart when positive; the chamber pressures (and the seal's bristle "
                           "deflection) are states of the simulation (docs/theory/hydraulic-cylinder.md).", (
    _point("first", "barrel attachment (cap end)"),
    _point("second", "rod-eye attachment"),
    Param("piston_area", "area", "piston (cap-side) area A1 = pi D^2/4", gt=0,
          example='an area, e.g. "31.17 cm^2" (63 mm bore)'),
    Param("rod_side_area", "area", "rod-side (annulus) area A2 = pi (D^2 - d^2)/4, smaller than `piston_area`",
          gt=0, example='an area, e.g. "21.55 cm^2" (63 mm bore, 35 mm rod)'),
    Param("stroke_length", "length", "stroke S: the rod moves from 0 (fully retracted) to S", gt=0,
          example='a length, e.g. "500 mm"'),
    Param("cap_dead_volume", "volume", "volume of the cap chamber at stroke 0 (ports, hoses); sets the stiffness "
          "near the end", gt=0, example='a volume, e.g. "0.1 L"'),
    Param("rod_dead_volume", "volume", "volume of the rod chamber at full stroke (ports, hoses)", gt=0,
          example='a volume, e.g. "0.1 L"'),
    Param("initial_stroke", "length", "stroke at the positions given in the model (0: fully retracted), at most "
          "`stroke_length`; it fixes where the stroke is counted from", ge=0,
          example='a length, e.g. "100 mm"'),
    Param("cap_pressure", "pressure", "gauge pressure of the cap chamber at the start", 0.0, ge=PRESSURE_FLOOR,
          why=_START_PRESSURE),
    Param("rod_pressure", "pressure", "gauge pressure of the rod chamber at the start", 0.0, ge=PRESSURE_FLOOR,
          why=_START_PRESSURE),
    Param("bulk_modulus", "pressure", "effective bulk modulus beta of the liquid, with entrained air and the "
          "compliance of barrel and hoses (mineral oil 1.5-1.8 GPa, less in machines)", gt=0,
          example='a bulk modulus, e.g. "1.5 GPa"'),
    Param("seal_friction", "law", 'friction of the seals: `"lugre_seal"` (paper 002\'s seal) or `{ law = '
          '"lugre_seal", ... }`; `"none"` or left out: frictionless', None, of="seal_friction",
          default_text="none (frictionless seals)"),
    Param("cap_inflow", "function", "volume flow into the cap chamber (a valve or pump as a flow source)", None,
          of="volume flow", default_text="none (a closed chamber)"),
    Param("rod_inflow", "function", "volume flow into the rod chamber", None, of="volume flow",
          default_text="none (a closed chamber)"),
), tag="type", relations=(
    Relation("rod_side_area", "<", "piston_area", "it is the annulus, the piston area less the rod's"),
    Relation("initial_stroke", "<=", "stroke_length", "the rod cannot be beyond full extension"),
))

FORCES = family(SPRING_DAMPER, ROTATIONAL_SPRING_DAMPER, POINT_FORCE, TORQUE, HYDRAULIC_CYLINDER)

# flexible links and sensors ---------------------------------------------------

BEAM_MATERIAL = Table("beam_material", "An isotropic elastic material of a beam: Young's modulus, density and "
                      "exactly one of Poisson's ratio and the shear modulus.", (
    Param("youngs_modulus", "pressure", "Young's modulus E", gt=0, example='a Young\'s modulus, e.g. "207 GPa"'),
    Param("density", "density", "density rho", gt=0, example='a density, e.g. "7850 kg/m^3"'),
    Param("poisson_ratio", "dimensionless", "Poisson's ratio nu; G = E / (2 (1 + nu))", None, gt=-1, lt=0.5,
          interval="(-1, 0.5)", default_text="none (give `shear_modulus`)"),
    Param("shear_modulus", "pressure", "shear modulus G", None, gt=0, default_text="none (give `poisson_ratio`)"),
))

_MATERIAL_NOTE = "; the beam's `material` gives E, G and the density"

BEAM_SECTIONS = family(
    Table("rectangle", "Solid rectangle; shear factor k = 10(1 + nu)/(12 + 11 nu) (Cowper 1966)" + _MATERIAL_NOTE
          + ".", (
        Param("width", "length", "width, out of the plane of motion", gt=0, example='a length, e.g. "10 mm"'),
        Param("height", "length", "height, in the plane of bending", gt=0, example='a length, e.g. "20 mm"'),
    ), tag="shape"),
    Table("circle", "Solid circle; k = 6(1 + nu)/(7 + 6 nu) (Cowper 1966)" + _MATERIAL_NOTE + ".", (
        Param("diameter", "length", "diameter", gt=0, example='a length, e.g. "12 mm"'),
    ), tag="shape"),
    Table("tube", "Thin or thick circular tube; Cowper's (1966) shear factor of a hollow circle" + _MATERIAL_NOTE
          + ".", (
        Param("outer_diameter", "length", "outer diameter", gt=0, example='a length, e.g. "20 mm"'),
        Param("inner_diameter", "length", "inner diameter, smaller than `outer_diameter`", gt=0,
              example='a length, e.g. "16 mm"'),
    ), tag="shape", relations=(Relation("inner_diameter", "<", "outer_diameter", "the bore is inside the tube"),)),
    Table("properties", "Any section by its area, second moment and shear factor" + _MATERIAL_NOTE + ".", (
        Param("area", "area", "area A", gt=0, example='an area, e.g. "2 cm^2"'),
        Param("second_moment", "second moment of area", "second moment I about the bending axis", gt=0,
              example='a second moment of area, e.g. "1.2 cm^4"'),
        Param("shear_factor", "dimensionless", "shear factor k (5/6 for a thin rectangle)", gt=0, le=1,
              interval="(0, 1]", example="a shear factor, e.g. 0.833"),
    ), tag="shape"),
    Table("resultants", "The section's stiffnesses and inertias per length given directly (no `material`).", (
        Param("axial_stiffness", "force", "E A", gt=0, example='an axial stiffness, e.g. "2.8e7 N"'),
        Param("shear_stiffness", "force", "k G A", gt=0, example='a shear stiffness, e.g. "1e7 N"'),
        Param("bending_stiffness", "bending stiffness", "E I", gt=0, example='a bending stiffness, e.g. "1.4e4 N m^2"'),
        Param("mass_per_length", "mass per length", "rho A", gt=0, example='a mass per length, e.g. "1.2 kg/m"'),
        Param("rotary_inertia_per_length", "rotary inertia per length", "rho I", gt=0,
              example='a rotary inertia per length, e.g. "6e-4 kg m"'),
    ), tag="shape"),
)

#: Families of nested tables chosen by a tag (kind ``variant``), by the key that holds them.
VARIANTS = {"section": BEAM_SECTIONS}

ELEMENT_ORDERS = ("linear", "quadratic")
MODAL_FRAMES = ("chord", "clamped")

#: Default of a flexible body's initial velocities (docs/model-files.md, "How a run starts").
_RIGID_START = "none: the rigid motion the assembled mechanism gives the body, found as a rigid link's velocities are"

BEAM = Table("beams", "A flexible link: a geometrically exact planar (Simo-Reissner) beam, straight and unstressed "
             "as described (a run starts it in the strain its loads give it), divided into elements of equal length; its named points are `start`, `end` and those of "
             "`points` (docs/theory/beam.md).", (
    Param("start", "vector", "approximate initial position of the first end", of="length",
          example='a point, e.g. ["0 mm", "0 mm"]'),
    Param("end", "vector", "approximate initial position of the second end", of="length",
          example='a point, e.g. ["300 mm", "0 mm"]'),
    Param("section", "variant", 'cross-section: `{ shape = "rectangle", width = "10 mm", height = "20 mm" }`',
          of="section", example='a section, e.g. { shape = "rectangle", width = "10 mm", height = "20 mm" }'),
    Param("material", "table", "material of the section; required unless the section is given by its resultants",
          None, of=BEAM_MATERIAL, default_text="none (a section of `shape = \"resultants\"`)"),
    Param("order", "choice", "element interpolation: `linear` (2 nodes) or `quadratic` (3 nodes)", "quadratic",
          of=ELEMENT_ORDERS, why="paper 000's 3-node elements; about 1/5 the error of linear ones per node in bending"),
    Param("elements", "count", "number of elements (give this or `element_length`)", None,
          default_text="none (give `element_length`)"),
    Param("element_length", "length", "largest element length: the count is the length over it, rounded up", None,
          gt=0, default_text="none (give `elements`)"),
    Param("damping_time", "time", "retardation time tau of strain-rate (Kelvin-Voigt) damping: each stress resultant "
          "gains tau times its rate; a mode of circular frequency w gets the damping ratio tau w / 2", 0.0, ge=0,
          why="undamped unless chosen"),
    Param("velocity", "vector", "initial velocity of the first end; with `angular_velocity`, the rigid motion the "
          "beam starts in, held and checked against the joints", None, of="velocity", default_text=_RIGID_START),
    Param("angular_velocity", "angular velocity", "initial angular velocity, as a rigid link (see `velocity`)", None,
          default_text=_RIGID_START),
    Param("points", "arclengths", 'named points by arclength from the first end: `points = { E = "75 mm" }`', {}),
    Param("free", "flag", "allow a beam that no joint or force element refers to (otherwise an error)", False,
          in_spec=False),
))

_FROM_BEAM = "none (a body given by `matrices`)"

MODAL_MATRICES = Table("matrices", "A planar structure from another finite-element code: its mass and stiffness "
                       "matrices over the coordinates (u_x, u_y, theta) of node 0, then node 1, ... (frame elements), "
                       "or (u_x, u_y) of each node (plane solids: the matrices' size tells which), in the "
                       "structure's own axes, and its nodes' positions there, in one consistent set of units with "
                       "time in seconds (the force unit is the mass unit times the length unit per s^2: t, mm, s "
                       "give N). Each is a file, by its path from the model file's folder, or the values themselves "
                       "(as `Model.to_toml` writes them).", (
    Param("mass", "matrix", "mass matrix: a Matrix Market file (`.mtx`, coordinate or array, general or symmetric), "
          "a NumPy array (`.npy`) or a SciPy sparse matrix (`.npz`); or `{ size, rows, columns, values }`, the "
          "entries from 0, repeated ones added", example='a file, e.g. "link.mass.mtx"'),
    Param("stiffness", "matrix", "stiffness matrix of the free (unsupported) structure, as `mass`",
          example='a file, e.g. "link.stiffness.mtx"'),
    Param("nodes", "matrix", "node positions, one row `x y` per node: a `.npy`, `.mtx`, or a text file (`.csv`, "
          "`.txt`: numbers apart by commas or spaces, `#` comments); or a list of pairs",
          example='a file, e.g. "link.nodes.csv"'),
    Param("length_unit", "text", "unit of lengths in the files (node positions; the matrices' rotational "
          "coordinates follow); required, because the numbers of a file carry no unit and a structure in mm "
          "read as m is 1000 times too large", of="a unit of length", example='a unit of length, e.g. "mm"'),
    Param("mass_unit", "text", "unit of mass in the files (`t` with `mm`); required, as `length_unit`",
          of="a unit of mass", example='a unit of mass, e.g. "t" (with "mm") or "kg" (with "m")'),
))

MODAL_BODY = Table("modal_bodies", "A flexible link as a modal body: a floating frame plus Craig-Bampton modes, "
                   "with linear modes and no geometric stiffening, of a straight beam of jointplay's elements "
                   "(section, material and mesh as a beam's) or of a structure given by `matrices` from another "
                   "finite-element code; its named points are its interface nodes and `points` "
                   "(docs/theory/modal-body.md).", (
    *(_replace(BEAM[key], default=None, default_text=_FROM_BEAM) for key in ("start", "end", "section")),
    BEAM["material"], BEAM["order"],
    *(_replace(BEAM[key], default_text=BEAM[key].default_text.removesuffix(")") + ", or `matrices`)")
      for key in ("elements", "element_length")),
    Param("matrices", "table", "the structure's mass and stiffness matrices and nodes from another finite-element "
          'code, instead of a beam: `matrices = { mass = "link.mass.mtx", stiffness = "link.stiffness.mtx", '
          'nodes = "link.nodes.csv", length_unit = "mm", mass_unit = "t" }`', None, of=MODAL_MATRICES, apart=True,
          default_text="none (a beam: give `start`, `end`, `section`)"),
    Param("position", "vector", "with `matrices`: where the origin of the structure's axes is in the model at the "
          "start", (0.0, 0.0), of="length"),
    Param("angle", "angle", "with `matrices`: angle of the structure's axes in the model at the start", 0.0),
    Param("interface", "nodes", "interface nodes, named: by arclength from the first end on a beam, each at a "
          'node of the mesh (`interface = { start = "0 mm", end = "300 mm" }`), by node number from 0 with '
          "`matrices` (`interface = { A = 0, B = 12 }`); the first carries the body's frame, the others get static "
          "constraint modes; joints attach to `\"<body>.<node>\"`", {},
          default_text="on a beam, the two ends, named `start` and `end`; with `matrices`, required"),
    Param("points", "nodes", "other named nodes, as `interface` gives them (`points = { mid = \"150 mm\" }` "
          "on a beam, `points = { C = 6 }` with `matrices`); forces and strain gauges attach there (joints belong "
          "at interface nodes; strain gauges need a beam)", {}),
    Param("frame", "choice", "reference conditions of the body's frame: `chord` (origin at the first interface "
          "node, x axis through the second: simply supported modes, for a link pinned at two points) or `clamped` "
          "(origin and axes on the first interface node's section: cantilever modes, for a link clamped at one end)",
          None, of=MODAL_FRAMES, default_text="`chord` with two or more interface nodes, `clamped` with one",
          why="a force along the line of two pins stays along the chord frame's axis; in the clamped frame it "
              "crosses it and acts as a false geometric stiffness (docs/theory/modal-body.md)"),
    Param("normal_modes", "count", "fixed-interface normal modes kept", 4,
          why="a uniform link's three lowest clamped-free frequencies within 1e-3, free-free within 5e-3"),
    Param("damping_ratio", "dimensionless", "damping ratio of every mode of the body held at its frame's reference "
          "conditions", 0.0,
          ge=0, why="undamped unless chosen"),
    Param("damping_time", "time", "retardation time tau of stiffness-proportional damping `tau K`, added to the "
          "modal damping: a beam's strain-rate damping of the same `damping_time`, linearised (mode n gets the "
          "ratio tau w_n / 2)", 0.0, ge=0, why="undamped unless chosen"),
    Param("velocity", "vector", "initial velocity of the frame's origin (the first interface node); with "
          "`angular_velocity`, the rigid motion the body starts in (modal rates zero), held and checked against the "
          "joints", None, of="velocity", default_text=_RIGID_START),
    Param("angular_velocity", "angular velocity", "initial angular velocity of the frame (see `velocity`)", None,
          default_text=_RIGID_START),
    Param("free", "flag", "allow a modal body that no joint or force element refers to (otherwise an error)", False,
          in_spec=False),
))

STRAIN_GAUGE = Table("strain_gauge", "Stress resultants of a beam's section at a point (axial force N, shear force "
                     "Q, bending moment M), the axis strain, the curvature and the axial strain of a fibre at "
                     "`fibre` from the axis, as channels `<name>.axial_force` ... `<name>.axial_strain`; on a modal "
                     "body, recovered from its modes (elastic part: modal damping is not a section stress).", (
    _point("point", "a point of a beam or modal body", 'a point of a beam or modal body "body.point", e.g. "rod.E"'),
    Param("fibre", "length", "distance of the fibre from the axis, positive to the left of the beam's direction "
          "(start to end)", 0.0, why="the axis"),
), tag="type")

SENSORS = family(STRAIN_GAUGE)


# spatial models ---------------------------------------------------------------

#: The identity orientation, a unit quaternion ``[w, x, y, z]``.
IDENTITY_QUATERNION = (1.0, 0.0, 0.0, 0.0)
_ORIENTATION_FORMS = ('`{ axis = [0, 0, 1], angle = "30 deg" }`, `{ euler = ["10 deg", "20 deg", "30 deg"], '
                      'sequence = "ZXZ" }` (intrinsic; `"3-1-3"` also names it), `{ matrix = [[...], [...], [...]] }` '
                      "(columns: the body's axes in global coordinates) or `{ quaternion = [w, x, y, z] }` (scalar "
                      "first)")
_MARKERS = ('named points in body coordinates, each `["x", "y", "z"]` or with a frame, `{ position = [...], axes = '
            "<orientation> }` (the columns of its rotation matrix are the marker's x, y, z axes; a joint's axis is "
            "its markers' z axis): `points = { A = [\"0 mm\", \"10 mm\", \"5 mm\"] }`")

SPATIAL_MODEL = Table("model", "Name, description and gravity of a spatial mechanism (`kinematics = \"spatial\"`).", (
    MODEL["name"], MODEL["description"],
    Param("gravity", "vector3", 'gravitational acceleration, three components: `[0, 0, "-9.81 m/s^2"]`',
          (0.0, 0.0, 0.0), of="acceleration"),
    MODEL["kinematics"],
))

SPATIAL_GROUND = Table("ground", "Named points of the fixed frame of a spatial model, in global coordinates, each "
                       "with its axes if a joint needs them.", (
    Param("points", "markers", _MARKERS.replace("in body coordinates", "in global coordinates"), {}),
))

SPATIAL_BODY = Table("bodies", "A spatial rigid body; its frame is at its centre of mass (docs/model-files.md, "
                     "\"Spatial models\").", (
    BODY["mass"],
    Param("inertia", "inertia_tensor", 'inertia tensor about the centre of mass in the body frame: principal moments '
          'and their axes, `{ principal = ["1 kg m^2", "2 kg m^2", "2.5 kg m^2"], axes = <orientation> }` (axes '
          'default: the body\'s), or `{ tensor = [[...], [...], [...]] }`; each principal moment at most the sum of '
          "the other two", example='an inertia tensor, e.g. { principal = ["1 kg m^2", "2 kg m^2", "2.5 kg m^2"] }'),
    Param("position", "vector3", "approximate initial position of the centre of mass (assembly makes the "
          "configuration consistent)", (0.0, 0.0, 0.0), of="length"),
    Param("orientation", "orientation", "approximate initial orientation, body to global: " + _ORIENTATION_FORMS,
          IDENTITY_QUATERNION, default_text="identity (the body's axes are the global axes)"),
    Param("velocity", "vector3", "approximate initial velocity of the centre of mass", (0.0, 0.0, 0.0),
          of="velocity"),
    Param("angular_velocity", "vector3", "approximate initial angular velocity, in GLOBAL components",
          (0.0, 0.0, 0.0), of="angular velocity"),
    Param("points", "markers", _MARKERS, {}),
    Param("euler_sequence", "choice", "intrinsic Euler sequence of the body's orientation channels "
          "(`euler_<sequence>_1` to `_3`), e.g. `zxz` (also written `ZXZ` or `3-1-3`)", "zyx",
          why="3-2-1 (yaw, pitch, roll) has no gimbal lock at the identity, where bodies often start",
          of=tuple(s.lower() for s in _EULER_SEQUENCES),
          aliases=tuple((alias, name.lower()) for alias, name in _EULER_ALIASES.items())),
    BODY["free"],
))

_AXIS_NOTE = " The joint's axis is the common z axis of the two markers' frames (`axes` of the points)."

#: Where the chosen motion-mode thresholds of the spatial clearance joint come from.
_MODE_WHY = "chosen (docs/theory/spatial-clearance-revolute.md, \"Motion modes\")"

SPATIAL_CLEARANCE_REVOLUTE = Table(
    "spatial_clearance_revolute", "A revolute joint with radial and axial clearance: a bore of finite length on the "
    "bearing's body, a journal with two flanges on the journal's body; contact along the bore (by slices) and at the "
    "flanges, with friction (docs/theory/spatial-clearance-revolute.md). The bearing marker's origin is the bore's "
    "centre and its z axis the bore axis; the journal marker's origin lies midway between the flanges, its z axis "
    "along the journal.", (
        _point("bearing", "bore's centre, z along the bore axis", POINT + " (the bore's centre)"),
        _point("journal", "journal's centre between its flanges, z along its axis", POINT + " (the journal's centre)"),
        Param("bore_radius", "length", "bore radius R_b", gt=0, example='the bore radius, a length, e.g. "10 mm"'),
        Param("clearance", "length", "radial clearance c = R_b - R_j, smaller than `bore_radius`", gt=0,
              example='the radial clearance, a length, e.g. "0.5 mm"'),
        Param("bearing_length", "length", "length L of the bore", gt=0, example='the bore length, e.g. "20 mm"'),
        Param("axial_clearance", "length", "flange spacing minus bearing length", ge=0,
              example='the axial clearance, a length, e.g. "0.5 mm"'),
        Param("flange_radius", "length", "outer radius of the journal's flanges, larger than `bore_radius`", gt=0,
              example='the flanges\' outer radius, e.g. "15 mm"'),
        Param("face_radius", "length", "outer radius of the bearing's end faces, larger than `bore_radius`", gt=0,
              example='the end faces\' outer radius, e.g. "16 mm"'),
        Param("bearing_material", "table", "elastic material of the bearing", STEEL, of=MATERIAL,
              why="structural steel"),
        Param("journal_material", "table", "elastic material of the journal", STEEL, of=MATERIAL,
              why="structural steel"),
        Param("contact", "law", "normal force law (dissipation) of every contact", of="contact",
              example='a table such as { law = "lankarani_nikravesh", restitution = 0.9 }'),
        Param("stiffness", "law", "radial stiffness law of the whole bearing length, applied per unit length along "
              "the bore", "hertz_cylinder", of="stiffness", why="the law of the planar clearance joint"),
        Param("axial_stiffness", "stiffness", "stiffness of a whole flange ring pressed on its face, applied per "
              "unit area of the overlap", None, gt=0,
              default_text="the flat annular punch's, 2 E* sqrt(A/pi) with A the overlap's area (set by the core)"),
        Param("friction", "law", "friction law of every contact", "none", of="friction"),
        Param("lock_at_assembly", "flag", "assembly holds the journal centred and aligned in its bore and gives the "
              "bodies the velocities of the ideal mechanism; `false` keeps the journal where the bodies' approximate "
              "positions put it, with their own velocities", True, why="a clearance joint starts as the ideal "
              "mechanism"),
        Param("onset_velocity_floor", "velocity", "smallest contact-onset velocity used in the damping term",
              1e-4, gt=0, why="as the planar clearance joint"),
        Param("max_penetration", "length", "penetration at which the run stops as unphysical", None, gt=0,
              default_text="half the radial clearance (set by the core)"),
        Param("mode_impact_speed", "velocity", "smallest onset approach speed of a radial contact that begins with "
              "an impact (motion modes)", 1e-3, gt=0, why=_MODE_WHY + ": twenty times paper 002's stiction "
              "transition speed, 0.05 mm/s"),
        Param("mode_impact_duration", "time", "how long after such an onset the contact counts as impact and "
              "rebound (motion modes)", 1e-3, gt=0, why=_MODE_WHY + ": several Hertz contact times of steel parts "
              "of kilograms, short against an excitation period"),
        Param("mode_sliding_speed", "velocity", "sliding speed above which a radial contact is sliding, at or below "
              "it sustained (motion modes)", 5e-5, gt=0, why=_MODE_WHY + ": paper 002's stiction transition speed, "
              "0.05 mm/s, above which friction is kinetic"),
    ), tag="type", relations=(
        Relation("clearance", "<", "bore_radius", "the journal's radius, bore_radius - clearance, is positive"),
        Relation("flange_radius", ">", "bore_radius", "the flanges reach over the bearing's end faces"),
        Relation("face_radius", ">", "bore_radius", "the end faces surround the bore"),))

SPATIAL_JOINTS = family(
    Table("revolute", "Ideal hinge: the points coincide and only rotation about the common z axis is free." +
          _AXIS_NOTE, _ENDS, tag="type"),
    Table("spherical", "Ideal ball joint: the points coincide, every rotation is free.", _ENDS, tag="type"),
    Table("cylindrical", "Translation along and rotation about the common z axis are free." + _AXIS_NOTE, _ENDS,
          tag="type"),
    Table("translational", "Ideal prism: translation along the common z axis is free, no rotation." + _AXIS_NOTE,
          _ENDS, tag="type"),
    Table("universal", "Cardan joint: the points coincide; rotations about the first marker's x axis and the second "
          "marker's y axis are free.", _ENDS, tag="type"),
    Table("fixed", "Ideal weld: the points coincide and the markers' frames keep their relative orientation.", _ENDS,
          tag="type"),
    SPATIAL_CLEARANCE_REVOLUTE,
)

#: The spatial joints the core holds in their own section (``spatial_clearance_joints``), not in ``spatial_joints``.
SPATIAL_JOINT_SECTIONS = {"spatial_clearance_revolute": "spatial_clearance_joints"}

#: Spatial joints a driver can prescribe, with the kind of the coordinate: the rotation about the z axis, or the
#: displacement of the second marker's origin along the first marker's z axis.
SPATIAL_DRIVEN = {"revolute": "angle", "cylindrical": "length", "translational": "length"}

_FRAMES = ("global", "body")

SPATIAL_SPRING_DAMPER = Table("spring_damper", "Linear spring and damper between two points, along their line, "
                              "tension positive.", (
    *_ENDS, SPRING_DAMPER["stiffness"], SPRING_DAMPER["damping"],
    Param("free_length", "length", "length at which the spring is relaxed", None, ge=0,
          default_text="the distance of the two points as described (computed by the front end)"),
), tag="type")

BUSHING = Table("bushing", "Six-component linear bushing between two points, in the first marker's frame: forces "
                "from the relative displacement and velocity, moments from the small relative rotation (as a "
                "rotation vector) and angular velocity.", (
    *_ENDS,
    Param("stiffness", "vector3", "translational stiffnesses along x, y, z", (0.0, 0.0, 0.0), ge=0, of="stiffness",
          why="none unless given"),
    Param("damping", "vector3", "translational damping coefficients", (0.0, 0.0, 0.0), ge=0, of="damping",
          why="none unless given"),
    Param("rotational_stiffness", "vector3", "rotational stiffnesses about x, y, z", (0.0, 0.0, 0.0), ge=0,
          of="rotational stiffness", why="none unless given"),
    Param("rotational_damping", "vector3", "rotational damping coefficients", (0.0, 0.0, 0.0), ge=0,
          of="rotational damping", why="none unless given"),
), tag="type")

_FRAME_DOC = "`global`: components along the global axes; `body`: along the axes of the body, turning with it"

SPATIAL_POINT_FORCE = Table("point_force", "A force at a point, three components (numbers or functions of time).", (
    _point("point", "point of application"),
    Param("force", "function3", 'force components `[fx, fy, fz]`, e.g. `["10 N", 0, { kind = "sine", ... }]`',
          (0.0, 0.0, 0.0), of="force"),
    Param("frame", "choice", _FRAME_DOC, "global", of=_FRAMES),
), tag="type")

SPATIAL_TORQUE = Table("torque", "A torque on a body, three components (numbers or functions of time).", (
    TORQUE["body"],
    Param("torque", "function3", 'torque components `[tx, ty, tz]`', (0.0, 0.0, 0.0), of="torque"),
    Param("frame", "choice", _FRAME_DOC, "global", of=_FRAMES),
), tag="type")

SPATIAL_FORCES = family(SPATIAL_SPRING_DAMPER, BUSHING, SPATIAL_POINT_FORCE, SPATIAL_TORQUE, HYDRAULIC_CYLINDER)

#: What a spatial model does not have, by section: the words of a tagged table, or None for the whole section.
PLANAR_ONLY = {"joints": ("clearance_revolute",), "forces": ("rotational_spring_damper",), "beams": None,
               "modal_bodies": None, "sensors": None}


def spatial_tables() -> list[Table]:
    """Every table of a spatial model that :func:`all_tables` does not list (the tests check each against the
    schema, the builder and the writer)."""
    shared = {id(t) for t in all_tables()}
    tables = [SPATIAL_MODEL, SPATIAL_GROUND, SPATIAL_BODY, *variants(SPATIAL_JOINTS), *variants(SPATIAL_FORCES)]
    return [t for t in tables if id(t) not in shared]


# simulation -----------------------------------------------------------------

METHODS = ("dopri5", "adams", "bdf", "generalized_alpha")
METHOD_ALIASES = (("rk45", "dopri5"), ("dormand_prince", "dopri5"), ("adams_pc", "adams"), ("ndf", "bdf"),
                  ("generalised_alpha", "generalized_alpha"))
STABILIZATIONS = ("projection", "baumgarte", "none")
#: How a run starts: from the assembled description, or at rest in the static equilibrium.
INITIAL_STATES = ("assembly", "equilibrium")
JACOBIANS = ("auto", "finite_difference", "structured")
FORMULATIONS = ("auto", "absolute", "joint_coordinates")
#: Smallest relative tolerance the core accepts: 100 machine epsilons, below which its error estimate is
#: dominated by rounding (``MIN_RTOL`` of crates/jointplay-core/src/integrate/options.rs).
MIN_RTOL = 100 * 2.220446049250313e-16
#: Smallest step when ``min_step`` is not given [s]: far below any contact time scale, above the rounding of t
#: (the core's default, ``IntegratorOptions::default``).
DEFAULT_MIN_STEP = 1e-14
_NOT_GIVEN_MIN_STEP = (("min_step", DEFAULT_MIN_STEP),)

SIMULATION = Table("simulation", "Default options of `jointplay run` and of `Model.simulate(**model.simulation)`; "
                   "all optional.", (
    Param("t_end", "time", "end time", None, gt=0, default_text="none (`jointplay run` then needs `--t-end`)"),
    Param("t0", "time", "start time", 0.0),
    Param("method", "choice", "Dormand-Prince 5(4) with located contact onsets; Adams predictor-corrector; implicit "
          "NDF/BDF for stiff models such as lubricated joints; implicit generalized-alpha with a fixed `step` and "
          "numerical damping of the vibrations that step does not resolve, for flexible links "
          "(docs/theory/integrator-generalized-alpha.md)", "dopri5", of=METHODS, aliases=METHOD_ALIASES),
    Param("rtol", "dimensionless", "relative error tolerance", 1e-6, gt=0),
    Param("atol", "dimensionless", "absolute error tolerance", 1e-9, ge=0),
    Param("max_step", "time", "largest step", None, gt=0, default_text="none"),
    Param("output_step", "time", "spacing of the saved samples (`jointplay run --output-step` overrides it); the "
          "summary's peaks and extrema come from every accepted step whatever it is", None, gt=0,
          default_text="every accepted step"),
    Param("initial_step", "time", "first step", None, gt=0, default_text="automatic"),
    Param("min_step", "time", "smallest step; a step the control would make smaller stops the run", None, gt=0,
          default_text=f"{DEFAULT_MIN_STEP:g} (far below any contact time scale, above the rounding of t)"),
    Param("max_steps", "count", "most attempted (accepted + rejected) steps; a run that exceeds it stops with an "
          "error naming this key, keeping what was computed", None, default_text="10 000 000 (set by the core)"),
    Param("max_order", "count", "highest order of the implicit method (`bdf`), 1 to 5: orders 1 and 2 are A-stable, "
          "which undamped flexible links need (docs/theory/integrator-ndf.md)", None, le=5, interval="1 to 5",
          default_text="5"),
    Param("step", "time", "nominal step of `generalized_alpha` (required by it; halved where its Newton iterations "
          "fail; the error-controlled methods ignore it): its accuracy is this step's, `rtol` and `atol` set only "
          "when its Newton iterations stop", None, gt=0, default_text="none"),
    Param("spectral_radius", "dimensionless", "spectral radius at infinity of `generalized_alpha`, 0 to 1: the "
          "factor by which each step multiplies a vibration it does not resolve (1: none damped, the implicit "
          "midpoint rule; 0: removed in one step)", 0.9, ge=0, le=1, interval="0 to 1"),
    Param("jacobian", "choice", "Newton Jacobian of the implicit methods (`bdf`, `generalized_alpha`): `finite_difference` (one "
          "right-hand side per state), `structured` (coloured differences of each element's forces through the "
          "constrained accelerations; absolute coordinates only; without modal bodies its Newton matrix is factored "
          "as a sparse augmented system, in cost linear in beam elements, docs/theory/integrator-jacobian.md), "
          "`auto` (structured with a beam)", "auto", of=JACOBIANS),
    Param("stabilization", "choice", "constraint drift control (absolute formulation); with flexible links, "
          "`baumgarte` (projection after a step strains a beam and breaks the implicit method's history)",
          "projection", of=STABILIZATIONS),
    Param("formulation", "choice", "form of the equations of motion: `auto` takes joint coordinates where they were "
          "measured faster, for rigid bodies whose ideal joints form a tree of at most 8 joint coordinates (every "
          "clearance joint cuts the loop it closes; no constraint equations to solve), else absolute coordinates "
          "with constraints (`jointplay check` and the results say which and why; docs/theory/planar-formulation.md, "
          "\"Choosing the formulation\"); `absolute` always uses the latter, `joint_coordinates` refuses a model "
          "with a closed loop of ideal joints", "auto", of=FORMULATIONS),
    Param("initial", "choice", "how the run starts: `assembly`, the description's positions and velocities made "
          "consistent with the joints (a flexible body in the rigid motion the mechanism gives it), or `equilibrium`, "
          "at rest in the static equilibrium at `t0` (`jointplay static`; docs/model-files.md, \"How a run starts\")",
          "assembly", of=INITIAL_STATES),
    Param("max_output_bytes", "size", 'budget of samples x channels x 8 bytes, a whole number of bytes or `"500 MB"`, '
          '`"2 GiB"`: checked before the run when `output_step` makes the sample count known, otherwise the run stops '
          "when it reaches it, keeping what was computed", None,
          default_text=f"{format_size(DEFAULT_MAX_FILE_BYTES)} with a results file, "
                       f"{format_size(DEFAULT_MAX_MEMORY_BYTES)} in memory"),
), sparse=True, relations=(
    Relation("rtol", ">=", MIN_RTOL, "100 machine epsilons: below it the error estimate is rounding noise"),
    Relation("min_step", "<", "max_step", "the step control works between them", absent=_NOT_GIVEN_MIN_STEP),
    Relation("initial_step", ">=", "min_step", "a first step below the smallest step stops the run at once",
             absent=_NOT_GIVEN_MIN_STEP),
    Relation("step", ">=", "min_step", "a step below the smallest step stops the run at once",
             absent=_NOT_GIVEN_MIN_STEP),
))


#: The sections of a model file, in the order they are written; the tables of each, by variant.
SECTIONS = ("model", "units", "ground", "bodies", "beams", "modal_bodies", "joints", "drivers", "forces", "sensors",
            "simulation")

#: The name of a mechanism built in Python without one (a model file's default is its file name).
DEFAULT_NAME = "mechanism"


# text for docstrings and the reference --------------------------------------

def unit(param: Param) -> str:
    """The SI unit of a key's values (``"m/s"``), ``""`` for plain numbers and non-quantities."""
    from .units import KINDS

    kind = param.of if param.kind in ("vector", "function", "list", "vector3", "function3") else param.kind
    spec = KINDS.get(kind) if isinstance(kind, str) else None
    return spec.si.replace("*", " ") if spec is not None else ""


def range_text(param: Param) -> str:
    """``> 0``, ``(0, 1]``: the allowed range, ``""`` when any value of its kind goes."""
    if param.interval:
        return param.interval
    parts = [f"{op} {value:g}" for op, value in ((">", param.gt), (">=", param.ge), ("<", param.lt),
                                                   ("<=", param.le)) if value is not None]
    return " and ".join(parts)


def default_text(param: Param) -> str:
    """The default as the reference writes it, in SI units without the unit: ``required``, ``0.0001``,
    ``[0, 0]``, ``{ law = "none" }``, or what an absent key means."""
    if param.required:
        return "required"
    if param.default_text:
        return param.default_text
    d = param.default
    if param.kind == "law":
        return f'{{ law = "{d}" }}'
    if isinstance(d, bool):
        return str(d).lower()
    if isinstance(d, str):
        return f'"{d}"'
    if isinstance(d, tuple):
        return "[" + ", ".join(f"{v:g}" for v in d) + "]"
    if isinstance(d, dict) and param.kind == "table":
        return "{ " + ", ".join(f"{k} = {_number(v, unit(param.of[k]))}" for k, v in d.items()) + " }"
    if isinstance(d, dict):
        return "{}"
    return f"{d:g}"


def _number(value: float, si: str) -> str:
    return f'"{value:g} {si}"' if si else f"{value:g}"


def docstring(table: Table, summary: str = "") -> str:
    """A docstring: ``summary`` (the table's doc by default), then its :func:`key_list`."""
    return f"{summary or table.doc}\n\n{key_list(table)}"


def key_list(table: Table) -> str:
    """One line per key that the core reads, with its unit, range, default and doc, from the definition."""
    lines = ["Keys, as in a model file (numbers in SI units, strings with units, pint quantities; "
             "docs/model-file-reference.md):", ""]
    for param in table.params:
        if not param.in_spec:
            continue
        si, allowed = unit(param), range_text(param)
        head = f"- ``{param.key}``" + (f" [{si}]" if si else "")
        tail = f"; {allowed}" if allowed else ""
        default = "required" if param.required else f"default {default_text(param)}"
        reason = f" ({param.why})" if param.why else ""
        lines.append(f"{head}: {param.doc}{tail}; {default}{reason}.")
    return "\n".join(lines)


def all_tables() -> list[Table]:
    """Every table defined here, each variant once (the tests check each against the schema, the builder
    and the writer)."""
    laws = [t for tables in LAWS.values() for t in variants(tables)]
    return [MODEL, GROUND, BODY, BEAM, MODAL_BODY, MODAL_MATRICES, BEAM_MATERIAL, *variants(BEAM_SECTIONS), *variants(JOINTS), MATERIAL,
            LUBRICATION, *laws, DRIVER, *variants(FUNCTIONS), *variants(FORCES), *variants(SENSORS), SIMULATION]
