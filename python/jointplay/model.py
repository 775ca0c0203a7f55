"""Building a mechanism in Python and simulating it.

A :class:`Model` collects plain data (SI units) in the same layout the core
reads; nothing is computed until :meth:`Model.simulate` or
:meth:`Model.check`, which compile it once (all problems reported together
as a :class:`~jointplay.errors.ModelError`, located by element name:
``joints.B.clearance``).

Every physical argument of the builder is a number in SI units, a string
with a unit (``"0.5 mm"``, ``"5000 rpm"``) or a pint Quantity, read by the
same definitions as a model file's keys (:mod:`jointplay.modelfile.arguments`):
a wrong one raises a ModelError at once (``joints.B.clearance: must be > 0,
got -0.1 mm``).
"""

from __future__ import annotations

import copy
import inspect
import json
import math
import os
import textwrap
import time as _time
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from . import _core, resultsfile, runcost
from . import parameters as p
from .errors import ModelError, SimulationError
from .functions import as_function
from .model_spatial import SPATIAL_HINT, either, gravity3, kinematics_of, planar_only, spatial_only
from .results import Results

Vector = Sequence[Any]
Quantity = Any  # a number in SI units, a string with a unit ("0.5 mm") or a pint Quantity

METHODS = {**{m: m for m in p.METHODS}, **dict(p.METHOD_ALIASES)}
STABILIZATIONS = p.STABILIZATIONS
FORMULATIONS = p.FORMULATIONS
_CLEARANCE, _SIMULATION = p.CLEARANCE_REVOLUTE, p.SIMULATION
#: Largest beam (coordinates) whose natural frequencies :meth:`Model.check` computes: a dense eigensolve of
#: this size takes about a second.
_MAX_MODAL_COORDINATES = 1500


def _arg(table: str, key: str, raw: Any, where: str) -> Any:
    """A builder argument read as the model-file key ``key`` of ``table`` (a class of the schema)."""
    from .modelfile import arguments, schema

    return arguments.value(getattr(schema, table), key, raw, where)


def _where(section: str, name: str) -> str:
    from .modelfile.fields import join

    return join(section, name)


def _adds(table: p.Table, section: str, positional: int | None = None, summary: str = "",
          spec_section: str | None = None) -> Callable[..., str]:
    """The builder method that adds an element defined by ``table`` to ``section``: ``(self, name, key...)``
    with the table's keys (that the core reads) as arguments and their defaults, the first ``positional`` of
    them (all by default) positional too, the rest keyword-only (required ones first). Each value is read
    as the model-file key (units, ranges, messages); it returns the element's name. ``spec_section``: the list
    of the core's spec it goes to when not ``section`` (``spatial_bodies`` for a spatial model's ``bodies``)."""
    keys = [param for param in table.params if param.in_spec]
    n = len(keys) if positional is None else positional
    ordered = keys[:n] + sorted(keys[n:], key=lambda param: not param.required)
    arguments = [inspect.Parameter("self", inspect.Parameter.POSITIONAL_OR_KEYWORD),
                 inspect.Parameter("name", inspect.Parameter.POSITIONAL_OR_KEYWORD, annotation="str")]
    for k, param in enumerate(ordered):
        how = inspect.Parameter.POSITIONAL_OR_KEYWORD if k < n else inspect.Parameter.KEYWORD_ONLY
        default = (inspect.Parameter.empty if param.required else None if param.kind in ("points", "markers")
                   else param.default)
        arguments.append(inspect.Parameter(param.key, how, default=default))
    signature = inspect.Signature(arguments, return_annotation="str")
    hint = f"{table.name} joint: " if section == "joints" else f"{table.name}: " if table.tag else ""

    def add(self: Model, *args: Any, **kwargs: Any) -> str:
        values = signature.bind(self, *args, **kwargs).arguments
        del values["self"]
        return self._add(section, table, values.pop("name"), values, hint, spec_section)

    add.__signature__ = signature  # type: ignore[attr-defined]
    add.__name__ = f"add_{table.name}" if section != "bodies" else "add_body"
    add.__qualname__ = f"Model.{add.__name__}"
    add.__doc__ = p.docstring(table, summary) + "\n\nReturns the element's name."
    return add


class Model:
    """A planar or spatial mechanism under construction.

    Example::

        m = Model("pendulum", gravity=(0, -9.81))
        m.add_ground_point("O", (0, 0))
        m.add_body("bar", mass=1.0, inertia=0.02, position=(0.25, 0), points={"O": (-0.25, 0)})
        m.add_revolute("pin", "ground.O", "bar.O")
        results = m.simulate(2.0, output_step=1e-3)

    ``kinematics="spatial"`` builds a spatial mechanism (docs/model-files.md, "Spatial models"): gravity, positions
    and velocities have three components, a body has an inertia tensor and an orientation, points may carry axes::

        m = Model("top", gravity=(0, 0, "-9.81 m/s^2"), kinematics="spatial")
        m.add_ground_point("O", ("0 mm", "0 mm", "0 mm"))
        m.add_body("top", mass="0.5 kg", inertia={"principal": ["1e-3 kg m^2", "1e-3 kg m^2", "1.5e-3 kg m^2"]},
                   position=(0, 0, "50 mm"), orientation={"axis": (1, 0, 0), "angle": "10 deg"},
                   points={"tip": (0, 0, "-50 mm")})
        m.add_spherical("pivot", "ground.O", "top.tip")
    """

    def __init__(self, name: str = p.DEFAULT_NAME, gravity: Vector = p.MODEL.default("gravity"),
                 kinematics: str = p.MODEL.default("kinematics")):
        from .modelfile.spatial import empty_spec

        kinematics = kinematics_of(kinematics)
        if kinematics == "spatial":
            self._spec: dict[str, Any] = empty_spec(name)
            given = gravity is not p.MODEL.default("gravity")
            self._spec["gravity"] = gravity3(gravity if given else p.SPATIAL_MODEL.default("gravity"))
        else:
            self._spec = {
                "name": name, "gravity": _arg("ModelTable", "gravity", gravity, "model"),
                "ground_points": [], "bodies": [], "beams": [], "joints": [], "drivers": [], "forces": [],
                "sensors": [],
            }
        self._core: Any = None
        self._run_inputs: tuple[dict, list] | None = None

    # construction ----------------------------------------------------------

    def _changed(self) -> None:
        self._core = None
        self._run_inputs = None

    def _spec_and_findings(self) -> tuple[dict, list]:
        """A snapshot of the description for results, and its plausibility problems: made once per
        version of the model (every change calls :meth:`_changed`) and shared, read-only, by the results
        of its runs, instead of a deep copy and a check at every run."""
        if self._run_inputs is None:
            from .modelfile.plausibility import plausibility

            snapshot = self.to_spec()
            self._run_inputs = (snapshot, plausibility(snapshot))
        return self._run_inputs

    @property
    def name(self) -> str:
        """Name of the mechanism."""
        return self._spec["name"]

    @property
    def kinematics(self) -> str:
        """``"planar"`` or ``"spatial"``."""
        from .modelfile.spatial import is_spatial

        return "spatial" if is_spatial(self._spec) else "planar"

    def set_gravity(self, gravity: Vector) -> Model:
        """Gravitational acceleration [m/s^2], e.g. ``(0, -9.81)`` or ``(0, "-9.81 m/s^2")``; three components
        in a spatial model."""
        if self.kinematics == "spatial":
            self._spec["gravity"] = gravity3(gravity)
        else:
            self._spec["gravity"] = _arg("ModelTable", "gravity", gravity, "model")
        self._changed()
        return self

    def add_ground_point(self, name: str, position: Vector, axes: Any = None) -> str:
        """A named point of the ground [m]; returns its reference ``"ground.<name>"``. In a spatial model
        ``position`` has three components and ``axes`` (an orientation, as a body's: ``{"axis": (0, 1, 0),
        "angle": "90 deg"}``) gives the point a frame, whose z axis is the axis of a joint there."""
        from .modelfile import arguments

        where = _where("ground.points", name)
        if self.kinematics == "spatial":
            point = arguments.marker(position if axes is None else {"position": position, "axes": axes}, where)
            self._spec["ground_points"].append({"name": name, **point})
        elif axes is not None:
            raise ModelError([(where, f"axes are for spatial models ({SPATIAL_HINT}); a planar point has none")])
        else:
            position = arguments.point(position, where)
            self._spec["ground_points"].append({"name": name, "position": position})
        self._changed()
        return f"ground.{name}"

    # elements: their keys, defaults and docs are defined once, in jointplay.parameters
    _add_planar_body = _adds(p.BODY, "bodies", summary="A rigid body, its frame at the centre of mass: mass, inertia "
                     "about the centre of mass, approximate initial position, angle and velocities; named points "
                     "in body coordinates (``points={\"A\": (\"25 mm\", 0)}``).")
    _add_spatial_body = _adds(p.SPATIAL_BODY, "bodies", spec_section="spatial_bodies", summary="A spatial rigid "
                             "body, its frame at the centre of mass: mass, inertia tensor about the centre of mass "
                             "(``{\"principal\": [...], \"axes\": <orientation>}`` or ``{\"tensor\": [[...], "
                             "[...], [...]]}``), approximate initial position, orientation and velocities (the "
                             "angular velocity in global components); named points in body coordinates, each a "
                             "3-vector or ``{\"position\": [...], \"axes\": <orientation>}``.")
    add_body = either(_add_planar_body, _add_spatial_body)
    del _add_planar_body, _add_spatial_body
    add_beam = _adds(p.BEAM, "beams", positional=3, summary="A flexible link: a geometrically exact planar beam from "
                     "``start`` to ``end`` [m], straight and unstressed as described (a run starts it in the strain its loads give it); ``section`` from "
                     ":mod:`jointplay.sections` (``sections.rectangle(\"10 mm\", \"20 mm\")``) and ``material`` "
                     "(``sections.material(\"207 GPa\", \"7850 kg/m^3\", poisson_ratio=0.3)``) unless the section "
                     "is given by its resultants; ``elements`` or ``element_length``; named points by arclength "
                     "(``points={\"E\": \"75 mm\"}``), besides ``start`` and ``end``. Joints and forces attach to "
                     "``\"<beam>.<point>\"``.")
    add_modal_body = _adds(p.MODAL_BODY, "modal_bodies", positional=3, summary="A flexible link as a modal "
                           "body (docs/theory/modal-body.md): a floating frame plus Craig-Bampton modes of the "
                           "straight beam from ``start`` to ``end`` [m], its ``section``, ``material`` and mesh read "
                           "as :meth:`add_beam` reads them; ``interface`` names the interface nodes by arclength "
                           "(``interface={\"start\": 0, \"end\": \"300 mm\"}``, the default: the two ends), the "
                           "first carrying the frame. Joints and forces attach to ``\"<body>.<interface node>\"``. "
                           "Linear modes without geometric stiffening: a body spun faster than its first bending "
                           "frequency (``check()[\"modal_bending_frequencies\"]``) diverges, and ``simulate`` warns "
                           "of a driver that does so.")
    add_revolute = either(_adds(p.REVOLUTE, "joints"),
                           _adds(p.SPATIAL_JOINTS["revolute"], "joints", spec_section="spatial_joints"))
    add_translational = either(_adds(p.TRANSLATIONAL, "joints"),
                                _adds(p.SPATIAL_JOINTS["translational"], "joints", spec_section="spatial_joints"))
    add_fixed = either(_adds(p.FIXED, "joints"), _adds(p.SPATIAL_JOINTS["fixed"], "joints",
                                                          spec_section="spatial_joints"))
    add_spherical = spatial_only(_adds(p.SPATIAL_JOINTS["spherical"], "joints", spec_section="spatial_joints"),
                                  "joints", "spherical")
    add_cylindrical = spatial_only(_adds(p.SPATIAL_JOINTS["cylindrical"], "joints", spec_section="spatial_joints"),
                                    "joints", "cylindrical")
    add_universal = spatial_only(_adds(p.SPATIAL_JOINTS["universal"], "joints", spec_section="spatial_joints"),
                                  "joints", "universal")
    add_spatial_clearance_revolute = spatial_only(
        _adds(p.SPATIAL_CLEARANCE_REVOLUTE, "joints", positional=2, spec_section="spatial_clearance_joints"), "joints",
        "spatial_clearance_revolute")

    def add_clearance_revolute(
            self, name: str, bearing: str, journal: str, *, bearing_radius: Quantity, clearance: Quantity,
            contact: dict, length: Quantity | None = _CLEARANCE.default("length"),
            stiffness: dict | None = None, friction: dict | None = None,
            bearing_material: dict = _CLEARANCE.default("bearing_material"),
            journal_material: dict = _CLEARANCE.default("journal_material"),
            initial_eccentricity: Vector = _CLEARANCE.default("initial_eccentricity"),
            lock_at_assembly: bool = _CLEARANCE.default("lock_at_assembly"),
            onset_velocity_floor: Quantity = _CLEARANCE.default("onset_velocity_floor"),
            max_penetration: Quantity | None = _CLEARANCE.default("max_penetration"),
            lubrication: dict | None = _CLEARANCE.default("lubrication")) -> str:
        """Dry revolute joint with radial clearance: bore of radius ``bearing_radius`` [m] centred at
        ``bearing``, journal of radius ``bearing_radius - clearance`` centred at ``journal``.
        ``contact``, ``stiffness`` and ``friction`` come from :mod:`jointplay.laws`. Assembly holds the
        journal at ``initial_eccentricity`` [m] with the velocities of the ideal mechanism unless
        ``lock_at_assembly`` is False (then the bodies' own approximate positions and velocities count).
        ``onset_velocity_floor`` [m/s] bounds the damping term for grazing contacts; the run stops if the
        penetration exceeds ``max_penetration`` [m]. ``lubrication`` (:func:`jointplay.laws.lubrication`)
        fills the clearance with a lubricant film; dry contact still acts once the journal touches the bore.
        ``stiffness`` and ``friction`` None: the default law. Lengths and speeds may be strings with units
        (``bearing_radius="10 mm", clearance="0.5 mm"``) or pint quantities."""
        from .modelfile import arguments

        where = _where("joints", name)
        joint = {"type": "clearance_revolute", "name": name, "bearing": bearing, "journal": journal}
        for key, raw in (("bearing_radius", bearing_radius), ("clearance", clearance), ("length", length)):
            joint[key] = _arg("ClearanceRevoluteTable", key, raw, where)
        joint.update({
            "bearing_material": arguments.material(bearing_material, f"{where}.bearing_material"),
            "journal_material": arguments.material(journal_material, f"{where}.journal_material"),
            "contact": arguments.law(contact, "contact", where),
            "stiffness": arguments.law(stiffness, "stiffness", where),
            "friction": arguments.law(friction, "friction", where),
            "initial_eccentricity": _arg("ClearanceRevoluteTable", "initial_eccentricity", initial_eccentricity, where),
            "lock_at_assembly": bool(lock_at_assembly),
            "onset_velocity_floor": _arg("ClearanceRevoluteTable", "onset_velocity_floor", onset_velocity_floor, where),
            "max_penetration": _arg("ClearanceRevoluteTable", "max_penetration", max_penetration, where),
            "lubrication": None if lubrication is None else p.core_lubrication(copy.deepcopy(lubrication)),
        })
        return self._joint(joint)

    add_clearance_revolute.__doc__ = (add_clearance_revolute.__doc__.rstrip() + "\n\n"
                                      + textwrap.indent(p.key_list(_CLEARANCE), " " * 8))

    def _joint(self, joint: dict) -> str:
        self._spec["joints"].append(joint)
        self._changed()
        return joint["name"]

    def add_driver(self, name: str, joint: str, function: dict | Quantity) -> str:
        """Prescribes a joint coordinate over time: the relative angle of a revolute joint [rad] or the
        displacement along a translational joint [m] (in a spatial model also along a cylindrical joint);
        ``function`` from :mod:`jointplay.functions` (its values may be strings with units, as in a model file)
        or a constant."""
        kinds = {j["name"]: j["type"] for j in self._spec["joints"] + self._spec.get("spatial_joints", [])}
        kind = "length" if kinds.get(joint) in ("translational", "cylindrical") else "angle"
        self._spec["drivers"].append({"name": name, "joint": joint,
                                      "function": _function(function, kind, _where("drivers", name) + ".function")})
        self._changed()
        return name

    add_spring_damper = either(_adds(p.SPRING_DAMPER, "forces", positional=2),
                                _adds(p.SPATIAL_SPRING_DAMPER, "forces", positional=2, spec_section="spatial_forces"))
    add_rotational_spring_damper = _adds(p.ROTATIONAL_SPRING_DAMPER, "forces", positional=2)
    add_point_force = either(_adds(p.POINT_FORCE, "forces"),
                              _adds(p.SPATIAL_POINT_FORCE, "forces", spec_section="spatial_forces"))
    add_torque = either(_adds(p.TORQUE, "forces"), _adds(p.SPATIAL_TORQUE, "forces", spec_section="spatial_forces"))
    add_hydraulic_cylinder = either(_adds(p.HYDRAULIC_CYLINDER, "forces", positional=2),
                                     _adds(p.HYDRAULIC_CYLINDER, "forces", positional=2, spec_section="spatial_forces"))
    add_bushing = spatial_only(_adds(p.BUSHING, "forces", positional=2, spec_section="spatial_forces"), "forces",
                                "bushing")
    add_strain_gauge = _adds(p.STRAIN_GAUGE, "sensors")

    # planar-only elements, refused in a spatial model with the message a model file gets
    add_clearance_revolute = planar_only(add_clearance_revolute, lambda name: f"{_where('joints', name)}.type",
                                          '"clearance_revolute" is')
    add_rotational_spring_damper = planar_only(add_rotational_spring_damper,
                                                lambda name: f"{_where('forces', name)}.type",
                                                '"rotational_spring_damper" is')
    add_beam = planar_only(add_beam, lambda name: _where("beams", name), "beams are")
    add_modal_body = planar_only(add_modal_body, lambda name: _where("modal_bodies", name), "modal bodies are")
    add_strain_gauge = planar_only(add_strain_gauge, lambda name: _where("sensors", name),
                                    "sensors (strain gauges of beams and modal bodies) are")

    def _add(self, section: str, table: p.Table, name: str, values: dict[str, Any], hint: str,
             spec_section: str | None = None) -> str:
        from .modelfile import arguments

        where = _where(section, name)
        read = {"beams": arguments.beam, "modal_bodies": arguments.modal_body}.get(section, arguments.element)
        self._spec.setdefault(spec_section or section, []).append(read(table, name, values, where, hint))
        self._changed()
        return name

    # variants --------------------------------------------------------------

    def copy(self) -> Model:
        """An independent copy."""
        return Model.from_spec(self.to_spec())

    def idealized(self) -> Model:
        """A copy with every clearance joint replaced by an ideal revolute joint at the journal."""
        spec = self.to_spec()
        spec["joints"] = [
            {"type": "revolute", "name": j["name"], "first": j["bearing"], "second": j["journal"]}
            if j["type"] == "clearance_revolute" else j
            for j in spec["joints"]
        ]
        if spec.get("spatial_clearance_joints"):
            spec["spatial_joints"] = spec.get("spatial_joints", []) + [
                {"type": "revolute", "name": j["name"], "first": j["bearing"], "second": j["journal"]}
                for j in spec.pop("spatial_clearance_joints")]
        return Model.from_spec(spec)

    def joint(self, name: str) -> dict:
        """The description of a joint, for editing in place (e.g. ``m.joint("B")["clearance"] = 1e-4``)."""
        joints = self._spec["joints"] + self._spec.get("spatial_joints", []) + self._spec.get("spatial_clearance_joints", [])
        for j in joints:
            if j["name"] == name:
                self._changed()
                return j
        raise KeyError(f"no joint named {name!r}; joints: {[j['name'] for j in joints]}")

    # plain data --------------------------------------------------------------

    def to_spec(self) -> dict:
        """The model description as plain data (a deep copy): the core's spec (docs/model-files.md; a spatial
        model's under ``spatial_bodies``, ``spatial_joints``, ``spatial_forces``, a spatial spring's free length
        left out computed from the described positions)."""
        spec = copy.deepcopy(self._spec)
        if self.kinematics == "spatial":
            from .modelfile.spatial import fill_free_lengths

            fill_free_lengths(spec)
        return spec

    @classmethod
    def from_spec(cls, spec: dict) -> Model:
        """A model from plain data as produced by :meth:`to_spec`."""
        m = cls(spec.get("name", p.DEFAULT_NAME))
        m._spec.update(copy.deepcopy(spec))
        return m

    def to_json(self) -> str:
        """The description as JSON text: what :meth:`compile` sends to the core (:meth:`to_spec`)."""
        return json.dumps(self.to_spec() if self.kinematics == "spatial" else self._spec, allow_nan=True)

    # pickling: by the description --------------------------------------------

    #: What a pickle leaves out: the compiled core (not picklable; compiled again on first use, from the same
    #: description, so the copy runs the same) and the snapshot made for results (made again from the description).
    _UNPICKLED = ("_core", "_run_inputs")

    def __getstate__(self) -> dict[str, Any]:
        """The description and what a model file added (``simulation``, ``description``, ``source_file``),
        without the compiled core: ``pickle.dumps(model)`` works for a compiled model (a process pool, Dask)."""
        return {key: value for key, value in self.__dict__.items() if key not in self._UNPICKLED}

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.__dict__.update(state)
        for key in self._UNPICKLED:
            self.__dict__[key] = None

    # compile, check, simulate -----------------------------------------------

    def compile(self):
        """Compiles the description (cached until the next change); raises ModelError, located by element
        name (``joints.B.clearance``, not the core's ``joints[3].clearance``)."""
        if self._core is None:
            non_finite = _non_finite(self._spec)
            if non_finite:
                raise ModelError(non_finite)
            core, problems = _core.compile_model(self.to_json())
            if problems:
                from .modelfile import core_location

                raise ModelError([(core_location(where, self._spec), message) for where, message in problems])
            self._core = core
        return self._core

    def check(self) -> dict:
        """Compiles and assembles the initial configuration; returns the mechanism's summary
        (bodies, joints, coordinates, degrees of freedom, initial coordinates) and, under
        ``beam_frequencies``, each beam's three lowest natural frequencies [Hz], unstressed, free-free and
        clamped at its start (beams of at most 1500 coordinates: a dense eigensolve). ``n_coordinates`` counts
        velocities (6 per spatial body: its quaternion's 4 numbers hold 3 freedoms); ``degrees_of_freedom`` is
        that less the rank of the constraint equations at the assembled position, ``redundant_equations`` the
        equations beyond that rank and ``dependent_elements`` the elements they belong to; a spatial model also
        has ``gruebler_kutzbach``, the count of :func:`jointplay.mobility.gruebler_kutzbach`.

        The plausibility findings (:func:`jointplay.modelfile.plausibility`) are issued first, as
        :class:`~jointplay.errors.JointplayWarning` warnings, whatever the assembly then does; what the
        assembly did that the description does not say (a body moved far from its given place, a driver whose
        start value contradicts the given positions, a flexible body strained to close a loop) is issued
        next, the same way, and listed under ``assembly_notes`` (docs/model-files.md, "How a run starts").
        Raises :class:`~jointplay.errors.SimulationError` when no consistent start exists."""
        from .modelfile.plausibility import emit

        emit(self._spec_and_findings()[1])
        info = self._assembled()
        emit(info["assembly_notes"])
        return info

    def _assembled(self) -> dict:
        """:meth:`check` without its warnings."""
        info = dict(self.compile().describe())
        assembled = self.compile().assemble(0.0)
        if assembled["error"] is not None:
            raise SimulationError(assembled["error"], stage="assembly")
        info["assembly_notes"] = _assembly_problems(assembled["notes"], self._spec)
        # degrees of freedom from the rank of the joints' equations at the assembled configuration
        info["redundant_equations"] = assembled["redundant_equations"]
        info["dependent_elements"] = list(assembled["dependent_elements"])
        info["degrees_of_freedom"] = info["n_coordinates"] - assembled["constraint_rank"]
        if self.kinematics == "spatial":
            from .mobility import gruebler_kutzbach

            info["gruebler_kutzbach"] = gruebler_kutzbach(self._spec)
        info["initial_coordinates"] = np.asarray(assembled["coordinates"])
        info["initial_velocities"] = np.asarray(assembled["velocities"])
        info["modal_bending_frequencies"] = dict(self.compile().modal_bending_frequencies())
        info["beam_frequencies"] = {
            name: {"free_free": list(free), "clamped": list(clamped)}
            for name, (free, clamped) in self.compile().beam_frequencies(3, _MAX_MODAL_COORDINATES).items()}
        return info

    def simulate(self, t_end: float, *, method: str = _SIMULATION.default("method"),
                 rtol: float = _SIMULATION.default("rtol"), atol: float = _SIMULATION.default("atol"),
                 max_step: float | None = None, output_step: float | None = None,
                 initial_step: float | None = None, min_step: float | None = None, max_steps: int | None = None,
                 max_order: int | None = None, step: float | None = None,
                 spectral_radius: float = _SIMULATION.default("spectral_radius"),
                 jacobian: str = _SIMULATION.default("jacobian"),
                 stabilization: str = _SIMULATION.default("stabilization"),
                 formulation: str = _SIMULATION.default("formulation"), t0: float = _SIMULATION.default("t0"),
                 progress: Callable[[float], None] | None = None, output_file: str | os.PathLike | None = None,
                 max_output_bytes: int | str | None = None, initial: str = "assembly") -> Results:
        """Assembles consistent initial conditions at ``t0`` and integrates to ``t_end`` [s].

        ``method``: ``"dopri5"`` (adaptive Dormand-Prince 5(4), contact onsets located by dense
        output), ``"adams"`` (variable-step Adams predictor-corrector), ``"bdf"`` (implicit
        variable-order NDF/BDF with Newton iterations, for stiff models such as lubricated joints) or
        ``"generalized_alpha"`` (implicit, second order, a fixed nominal ``step`` [s] halved only where
        Newton fails, and the vibrations that step does not resolve damped by the factor
        ``spectral_radius`` per step, 0 to 1, default 0.9: for flexible links;
        docs/theory/integrator-generalized-alpha.md). ``rtol``/``atol``: error tolerances (of
        ``"generalized_alpha"``: of its Newton iterations only, its accuracy is the step's);
        ``max_step`` [s]; ``output_step`` [s] samples on a regular grid (default: every
        accepted step; the peaks and extrema of :attr:`Results.extrema` come from every accepted step
        whatever it is); ``max_steps``: most attempted (accepted + rejected) steps, default 10 000 000,
        beyond which the run stops with a :class:`~jointplay.errors.SimulationError` naming the option.
        ``max_order``: highest order of ``"bdf"``, 1 to 5 (default 5); 2 for undamped flexible links, whose
        vibrations the orders above 2 (not A-stable) would amplify. ``jacobian``: the Newton Jacobian of
        ``"bdf"`` and ``"generalized_alpha"``, ``"auto"``, ``"finite_difference"`` or ``"structured"``
        (docs/theory/integrator-jacobian.md).
        ``progress`` is called with the simulated time about ten times a second.

        Values that are legal but almost certainly mistakes (a clearance of 20 % of the radius, a mass
        1e4 times the others; :func:`jointplay.modelfile.plausibility`) are issued first as
        :class:`~jointplay.errors.JointplayWarning` warnings; they do not stop the run.

        ``output_file`` (``.nc``, ``.nc4``, ``.h5``): the samples are written to this NetCDF (classic) file while
        the run goes on, chunk by chunk, and the returned results read their channels from it on access,
        so memory stays bounded; the file appears (by rename) only once complete, and a run that stops
        early goes to ``NAME.partial.nc`` instead (``results.path`` says which). ``.csv``: the run is kept
        in memory and written as CSV at the end. ``max_output_bytes`` (bytes, or ``"2 GiB"``): budget of
        samples x channels x 8 bytes, by default 2 GiB with a NetCDF file and 1 GiB in memory; a run on an
        ``output_step`` grid that cannot fit is refused before it starts (ModelError), any other run stops
        with a SimulationError when it reaches the budget. An ``output_file`` in a folder that does not
        exist, or of an unknown suffix, is a ModelError located at that path.

        Every option is checked before the run with the core's bounds (:mod:`jointplay.options`): a
        ModelError at ``simulation.<key>`` (``simulation.rtol: must be at least 2.22e-14 ...``); the
        quantities may be given with units (``max_step="0.1 ms"``).

        ``initial``: ``"assembly"`` (default: the description's positions and velocities made consistent with
        the joints, docs/model-files.md "How a run starts") or ``"equilibrium"`` (at rest in the static
        equilibrium at ``t0``, :meth:`equilibrium`).

        Raises :class:`~jointplay.errors.SimulationError` (with ``.results`` up to the failure)
        when the run stops early.
        """
        from .modelfile.plausibility import emit

        spec_snapshot, findings = self._spec_and_findings()
        emit(findings)
        options = _options(t0, t_end, method, rtol, atol, max_step, output_step, initial_step, min_step,
                           max_steps, stabilization, formulation, max_order, jacobian, step, spectral_radius)
        if initial not in p.INITIAL_STATES:
            raise ModelError([("simulation.initial", f"must be \"assembly\" or \"equilibrium\", got {initial!r}")])
        options["initial"] = initial
        emit(_flexible_advice(spec_snapshot, options))
        emit(_alpha_advice(options))
        emit(_modal_spin_advice(spec_snapshot, self.compile().modal_bending_frequencies()))
        emit(runcost.reynolds_cost(spec_snapshot, options, t0, float(t_end)))
        kind = resultsfile.output_target(output_file) if output_file is not None else None
        options["max_output_bytes"] = resultsfile.budget_option(max_output_bytes, kind == "netcdf")
        core = self.compile()
        channels = core.describe()
        longest_step = options.get("step") if options["method"] == "generalized_alpha" else options.get("max_step")
        too_large = resultsfile.check_budget(t0, t_end, options["output_step"], len(channels["names"]),
                                             options["max_output_bytes"], longest_step)
        if too_large:
            raise ModelError([("simulation.max_output_bytes", too_large)])
        if options["formulation"] == "joint_coordinates" and channels.get("joint_coordinates") is None:
            raise ModelError([("simulation.formulation", "joint_coordinates needs a tree of ideal joints, but "
                                                         f"{channels.get('absolute_because')}; use \"auto\" or "
                                                         "\"absolute\"")])
        geometry = core.drawing_geometry()
        started = _time.perf_counter()

        def make_results(raw: dict) -> Results:
            results = Results.from_core(raw, spec=spec_snapshot, options=options,
                                        wall_time=_time.perf_counter() - started)
            results.description = getattr(self, "description", "")
            results.model_file = getattr(self, "source_file", "")
            results.geometry = geometry
            return results

        if kind == "netcdf":
            results, raw = resultsfile.stream_run(
                output_file, channels, lambda sink: _run(core, t0, float(t_end), options, progress, sink), make_results)
        else:
            raw = _run(core, t0, float(t_end), options, progress)
            results = make_results(raw)
            if kind == "csv":
                results.save(output_file if raw["error"] is None else resultsfile.partial_path(output_file))
        emit(_projection_advice(options, raw.get("diagnostics") or {}))
        emit(_assembly_problems(raw.get("assembly_notes", []), spec_snapshot))
        if raw["error"] is not None:
            raise SimulationError(raw["error"], results=results, stage=raw.get("stage", "integration"))
        return results

    def equilibrium(self, t0: float = _SIMULATION.default("t0"), *, tolerance: float = 1e-10,
                    max_iterations: int = 100):
        """The static equilibrium at ``t0``: the mechanism at rest under gravity, springs, loads, preloads and
        closed hydraulic chambers, its drivers held at their values at ``t0``; a
        :class:`jointplay.statics.Equilibrium` with the positions, the residual and every channel there (joint
        reactions included). ``tolerance``: largest force residual relative to the largest load.
        Raises :class:`~jointplay.errors.SimulationError` when there is none (a free body under gravity), naming
        the body (docs/theory/static-equilibrium.md)."""
        from .statics import equilibrium

        return equilibrium(self, t0, tolerance, max_iterations)

    # model files -------------------------------------------------------------

    @property
    def simulation(self) -> dict:
        """Default simulation options, SI units (``t_end``, ``method``, ``rtol``, ``max_step``...), as read
        from a model file's ``[simulation]`` table; written back by :meth:`save`. Empty for a new model."""
        return self.__dict__.setdefault("_simulation", {})

    @simulation.setter
    def simulation(self, options: dict) -> None:
        self.__dict__["_simulation"] = dict(options)

    def to_toml(self, header: str | None = None) -> str:
        """The model (and its :attr:`simulation` defaults) as model-file TOML text; ``jointplay.load``
        of that text gives the same model."""
        from .modelfile import to_toml

        return to_toml(self, header=header)

    def save(self, path) -> None:
        """Writes the model to a TOML model file; a ModelError naming ``path`` when it cannot be written there."""
        from pathlib import Path

        target = Path(path)
        if not target.parent.is_dir():
            raise ModelError([(str(target), f"cannot write the model: the folder '{target.parent}' does not exist")])
        if target.is_dir():
            raise ModelError([(str(target), "cannot write the model: it is a folder")])
        target.write_text(self.to_toml(), encoding="utf-8")


def _non_finite(value: Any, where: str = "") -> list[tuple[str, str]]:
    """Every NaN or infinite number of a description given as plain data (``Model.from_spec``), located by
    element name where the entry has one (``bodies.crank.mass``)."""
    if isinstance(value, float) and not math.isfinite(value):
        return [(where or "model", f"must be a finite number, got {value!r}")]
    if isinstance(value, dict):
        return [p for key, item in value.items() for p in _non_finite(item, f"{where}.{key}" if where else key)]
    if isinstance(value, (list, tuple)):
        found = []
        for k, item in enumerate(value):
            name = item.get("name") if isinstance(item, dict) else None
            found += _non_finite(item, f"{where}.{name}" if isinstance(name, str) else f"{where}[{k}]")
        return found
    return []


def _assembly_problems(notes: list, spec: dict) -> list:
    """The core's assembly notes ``(name, on_body, message)`` as problems located in the description."""
    from .errors import Problem
    from .modelfile import body_location, element_location

    return [Problem(body_location(name, spec) if on_body else element_location(name, spec), message)
            for name, on_body, message in notes]


def _flexible_advice(spec: dict, options: dict) -> list:
    """Warnings for options that a model with beams integrates badly (docs/theory/beam.md, "Time
    integration"): an explicit method must resolve the beam's highest frequencies; NDF orders above 2 are not
    A-stable; a projection after each step strains the beam and upsets the implicit method."""
    from .errors import Problem

    if not spec.get("beams"):
        return []
    advice = []
    if options["method"] not in ("bdf", "generalized_alpha"):
        advice.append(Problem("simulation.method", f"{options['method']} with a beam must resolve its highest "
                                                   "vibration frequencies and takes millions of steps: use "
                                                   "method=\"generalized_alpha\" with a step, or method=\"bdf\" "
                                                   "with max_order=2"))
    else:
        if options["method"] == "bdf" and (options.get("max_order") is None or options["max_order"] > 2):
            advice.append(Problem("simulation.max_order", "orders above 2 are not A-stable: an undamped beam's "
                                                          "vibrations make their steps collapse; use max_order=2"))
        if options["stabilization"] == "projection":
            advice.append(Problem("simulation.stabilization", "a projection after each step strains the beam and "
                                                              "upsets the implicit method's history; use "
                                                              "stabilization=\"baumgarte\""))
    return advice


def _projection_advice(options: dict, diagnostics: dict) -> list:
    """Warnings after a run whose constraint projection could not work to a tenth of atol
    (docs/theory/planar-formulation.md, "Projection tolerance"): an atol below the round-off of the
    coordinates, or a singular position where Newton on the joints stalled above atol."""
    from .errors import Problem

    tolerance, left = diagnostics.get("projection_tolerance"), diagnostics.get("max_projection_residual", 0.0)
    atol = options.get("atol")
    if not tolerance or not left or not atol:  # no projection in this run, or atol 0 (rtol rules)
        return []
    advice = []
    if tolerance > _core.PROJECTION_SHARE * atol * (1 + 1e-12):
        advice.append(Problem("simulation.atol", f"{atol:g} asks the constraint projection for residuals below "
                                                 f"{_core.PROJECTION_SHARE * atol:g} m, under the round-off of the "
                                                 f"coordinates; it works to {tolerance:g} m, so the joints are not "
                                                 "held to atol"))
    if left > max(atol, tolerance):
        advice.append(Problem("simulation.atol", f"the constraint projection left joint residuals up to {left:.2g} m "
                                                 f"(at t = {diagnostics.get('max_projection_residual_time', math.nan):.6g}"
                                                 f" s: a singular position, where Newton on the joints stalls), above "
                                                 f"atol = {atol:g}: the requested accuracy was not met there"))
    return advice


def _alpha_advice(options: dict) -> list:
    """A warning when ``step`` is given to a method that controls its own step, and when generalized-alpha's
    output step is not a whole number of its steps: its samples are step ends
    (docs/theory/integrator-generalized-alpha.md), so the steps that cross an output time are shortened, which
    changes the solution within the method's error."""
    from .errors import Problem

    step, spacing = options.get("step"), options.get("output_step")
    if options["method"] != "generalized_alpha" and step is not None:
        return [Problem("simulation.step", f"only generalized_alpha takes a fixed step; {options['method']} sets its "
                                           "own from rtol and atol (max_step caps it), so the step is ignored")]
    if options["method"] != "generalized_alpha" or step is None or spacing is None:
        return []
    ratio = spacing / step
    if ratio >= 1.0 - 1e-9 and abs(ratio - round(ratio)) <= 1e-9 * ratio:
        return []
    return [Problem("simulation.output_step", f"generalized_alpha records its step ends, so {spacing:g} s, not a "
                                              f"whole number of steps of {step:g} s, shortens the steps that cross "
                                              "an output time (the results then depend on it within the method's "
                                              "error); use a multiple of the step")]


def _modal_spin_advice(spec: dict, bending: dict[str, float]) -> list:
    """A warning for each driver of a revolute joint whose rate exceeds a modal body's first bending frequency
    (times 2 pi): a linear modal body has no geometric stiffening and diverges when spun that fast
    (docs/theory/modal-body.md). Which body the driver spins is not traced: the warning names them all."""
    from .errors import Problem
    from .modelfile.plausibility import function_rate

    if not bending:
        return []
    kinds = {j["name"]: j["type"] for j in spec.get("joints", [])}
    advice = []
    for d in spec.get("drivers", []):
        rate = function_rate(d["function"])
        fast = {name: f for name, f in bending.items() if rate > 2.0 * math.pi * f}
        if kinds.get(d["joint"]) == "revolute" and fast:
            bodies = ", ".join(f"{name} ({f:.3g} Hz = {2.0 * math.pi * f:.3g} rad/s)" for name, f in fast.items())
            advice.append(Problem(_where("drivers", d["name"]), f"turns at up to {rate:.3g} rad/s, faster than the "
                                  f"first bending frequency of the modal body {bodies}: a linear modal body has no "
                                  "geometric stiffening and diverges if it is spun that fast; use a beam"))
    return advice


def _function(raw: Any, kind: str, where: str) -> dict:
    from .modelfile import arguments

    return arguments.function(as_function(raw) if isinstance(raw, (int, float)) else raw, kind, where)


def _options(t0, t_end, method, rtol, atol, max_step, output_step, initial_step, min_step, max_steps,
             stabilization, formulation=_SIMULATION.default("formulation"), max_order=None,
             jacobian=_SIMULATION.default("jacobian"), step=None,
             spectral_radius=_SIMULATION.default("spectral_radius")) -> dict:
    """The core's options, every check the core makes made first (:func:`jointplay.options.read`)."""
    from . import options

    return options.read(t0, t_end, {
        "method": method, "rtol": rtol, "atol": atol, "max_step": max_step, "output_step": output_step,
        "initial_step": initial_step, "min_step": min_step, "max_steps": max_steps, "stabilization": stabilization,
        "formulation": formulation, "max_order": max_order, "jacobian": jacobian, "step": step,
        "spectral_radius": spectral_radius})


def _run(core, t0: float, t_end: float, options: dict, progress: Callable[[float], None] | None,
         sink: Callable[[np.ndarray, np.ndarray, int], None] | None = None,
         initial_state: np.ndarray | None = None) -> dict:
    """Runs the core in this thread with the GIL released. About ten times a second the core calls
    ``progress`` and lets pending signals run: on Ctrl-C the run stops within about that time (every
    evaluation and every Reynolds sweep reach the check) and what was computed is kept (the error says it
    was interrupted). A run whose pace projects more than an hour to its end is warned of
    (:class:`runcost.Pace`). With ``sink`` the samples go to
    ``sink(times, values, start)`` in chunks instead of being returned (``start``: index of the first
    sample; a chunk interrupted by Ctrl-C is handed over again with the same ``start``)."""
    last: list[float] = []  # time of the last sample recorded [s], once there is one
    written = [0]  # samples handed to the sink
    # the pace of the run, projected to its end (runcost.Pace): with a sample at every step to a file, its size too
    pace = runcost.Pace(t0, t_end, samples_written=(lambda: written[0]) if sink is not None else None,
                        budget=options.get("max_output_bytes"))

    def forward(times: np.ndarray, values: np.ndarray, start: int) -> None:
        sink(times, values, start)
        last[:] = [float(times[-1])]
        written[0] = start + len(times)
        if options.get("output_step") is None:
            pace.bytes_per_sample = 8 * values.shape[1]

    def watch(t: float) -> None:
        if progress is not None:
            progress(t)
        pace(t)

    try:
        raw = core.simulate(t0, t_end, options, watch, None if sink is None else forward,
                            options.get("initial") == "equilibrium",
                            None if initial_state is None else [float(v) for v in initial_state])
    except ValueError as exc:  # an option the core refuses that the checks before it missed: still located
        from .options import core_refusal

        refusal = core_refusal(exc)
        if refusal is None:
            raise
        raise refusal from None
    if len(raw["time"]):
        last[:] = [float(raw["time"][-1])]
    if progress is not None and last:
        progress(last[0])
    return raw
