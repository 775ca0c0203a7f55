"""From the parsed TOML document to the core's plain-data spec, every problem reported.

Stages: the shape of each table (pydantic, units, ranges), then references
between tables (points, bodies, joints), then geometry (clearance against
the bearing radius, initial eccentricity), then connectivity (a body that
nothing refers to). The core compiles and assembles afterwards
(:func:`jointplay.modelfile.load`).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from pydantic import ValidationError
from pydantic_core import PydanticCustomError

from .. import parameters as p
from .._core import MAX_REYNOLDS_GRID_NODES, MAX_STRUCTURE_NODES
from ..errors import ModelError, Problem
from ..units import DECLARABLE, UnitError, declare_unit, model_file_units
from . import schema as s
from .fields import Q, Strict, convert, did_you_mean, join, problems_from
from .functions import function_spec

DRIVEN_KIND = {"revolute": "angle", "translational": "length"}
_FAILED = object()  # a value that could not be read (its problems are reported)


class Builder:
    """Validates one document; ``spec`` and ``simulation`` hold the result, ``problems`` what is wrong."""

    def __init__(self, doc: dict, default_name: str = p.DEFAULT_NAME, check_references: bool = True,
                 base: Path | None = None):
        self.doc = doc
        self.base = Path.cwd() if base is None else base  # where files named in the model are found
        self.check_references = check_references  # False for the Python builder: the core checks them
        self.default_name = default_name
        self.problems: list[Problem] = []
        self.spec: dict[str, Any] = {"name": default_name, "gravity": [0.0, 0.0], "ground_points": [],
                                     "bodies": [], "beams": [], "joints": [], "drivers": [], "forces": [], "sensors": []}
        self.simulation: dict[str, Any] = {}
        self.points: dict[str, list[str]] = {"ground": []}
        self.joint_types: dict[str, str] = {}
        self.names: dict[str, str] = {}
        self.referenced: set[str] = set()
        self.free: set[str] = set()
        self.flexible_names: set[str] = set()  # beams and modal bodies: where strain gauges go

    def run(self) -> Builder:
        for key in self.doc:
            if key not in s.TOP_LEVEL:
                self.problem(join(key), f"unknown section{did_you_mean(key, s.TOP_LEVEL)}; "
                                        f"sections: {', '.join(s.TOP_LEVEL)}")
        with model_file_units(self.units_table()):
            self.sections()
        return self

    def sections(self) -> None:
        from .spatial import SpatialSections, kinematics_of

        if kinematics_of(self.doc) == "spatial":
            SpatialSections(self).run()
            return
        self.model_table()
        self.ground()
        self.bodies()
        self.beams()
        self.modal_bodies()
        self.joints()
        self.drivers()
        self.forces()
        self.sensors()
        self.simulation_table()
        self.connectivity()

    def result(self) -> tuple[dict, dict]:
        if self.problems:
            raise ModelError(self.problems)
        return self.spec, self.simulation

    # helpers ---------------------------------------------------------------

    def problem(self, location: str, message: str) -> None:
        self.problems.append(Problem(location, message))

    def table(self, key: str) -> dict:
        value = self.doc.get(key, {})
        if not isinstance(value, dict):
            self.problem(key, f"must be a table ([{key}]), got {value!r}")
            return {}
        return value

    def entries(self, section: str):
        """(name, location, table) for each entry of a section of named tables."""
        for name, raw in self.table(section).items():
            where = join(section, name)
            if not isinstance(raw, dict):
                self.problem(where, f"must be a table ([{section}.{name}]), got {raw!r}")
                continue
            yield name, where, raw

    def validate(self, cls: type[Strict], raw: dict, where: str, hint: str = "") -> Strict | None:
        try:
            return cls.model_validate(raw)
        except ValidationError as exc:
            self.problems.extend(problems_from(exc, where, cls, kind_hint=hint))
            return None

    def claim(self, name: str, where: str) -> None:
        """Bodies, joints, drivers and forces share one namespace (channels are ``<name>.<quantity>``)."""
        if not name or "." in name or name == "ground" or name != name.strip():
            self.problem(where, f"must be a name without '.' or spaces, other than 'ground', got {name!r}")
        elif name in self.names:
            self.problem(where, f"name {name!r} is already used by {self.names[name]}")
        else:
            self.names[name] = where

    def tagged(self, raw: dict, tag: str, options: dict, where: str) -> str | None:
        value = raw.get(tag)
        if value is None:
            self.problem(join(where, tag), f"missing required value (one of {', '.join(options)})")
            return None
        if not isinstance(value, str) or value not in options:
            self.problem(join(where, tag), f"must be one of {', '.join(options)}, got {value!r}"
                                           f"{did_you_mean(value, options)}")
            return None
        return value

    def point(self, ref: str, where: str) -> None:
        if not self.check_references:
            return
        body, dot, name = ref.partition(".")
        if not dot or not body or not name or "." in name:
            self.problem(where, f'must be a point "body.point" (e.g. "crank.A", "ground.O"), got {ref!r}')
        elif body not in self.points:
            self.problem(where, f"no body named {body!r}{did_you_mean(body, self.points)}, got {ref!r}")
        elif name not in self.points[body]:
            known = ", ".join(self.points[body]) or "none"
            self.problem(where, f"body {body!r} has no point {name!r}{did_you_mean(name, self.points[body])} "
                                f"(its points: {known}), got {ref!r}")
        else:
            self.referenced.add(body)

    def body(self, ref: str, where: str) -> None:
        if not self.check_references:
            return
        if ref not in self.points:
            self.problem(where, f"no body named {ref!r}{did_you_mean(ref, self.points)}")
        else:
            self.referenced.add(ref)

    def element_spec(self, table: p.Table, name: str, where: str, t: Strict, raw: dict,
                     given: dict | None = None) -> dict | None:
        """The core's dict of a validated table ``t`` (``raw`` as written): every key of the definition that
        the core reads, in its order, in SI units, references checked; ``given`` holds keys read already.
        None when a function of time or a law could not be read."""
        out: dict[str, Any] = {"type": table.name, "name": name} if table.tag == "type" else {"name": name}
        self.relations(table, t, where)
        if table is p.SPATIAL_CLEARANCE_REVOLUTE:
            lubrication = self.lubrication(raw.get("lubrication"), join(where, "lubrication"), t.bearing_length, where)
            if lubrication is False:
                return None
            given = {**(given or {}), "lubrication": lubrication}
        for param in table.params:
            if not param.in_spec:
                continue
            if given is not None and param.key in given:
                out[param.key] = given[param.key]
            else:
                out[param.key] = self.spec_value(param, getattr(t, param.key), raw, where)
        return None if any(v is _FAILED for v in out.values()) else out

    def spec_value(self, param: p.Param, value: Any, raw: dict, where: str) -> Any:
        """The core's value of one validated key of the table at ``where``; _FAILED after adding problems."""
        location = join(where, param.key)
        kind = param.kind
        if kind == "law":
            if param.default is None and not param.required and raw.get(param.key) in (None, "none", {"law": "none"}):
                return None  # an optional law not given, or "none" (frictionless seals)
            law = self.law(raw, param, where)
            return _FAILED if law is None else law
        if value is None:
            return None
        if kind == "point":
            self.point(value, location)
        elif kind == "body":
            self.body(value, location)
        elif kind == "function":
            function = function_spec(value, param.of, location, self.problems)
            return _FAILED if function is None else function
        elif kind == "table":
            return {sub.key: self.spec_value(sub, getattr(value, sub.key), {}, location) for sub in param.of.params}
        elif kind == "variant":
            variant = self.variant(raw, param, where)
            return _FAILED if variant is None else variant
        elif kind == "points":
            return self.point_table(value, location)
        elif kind == "arclengths":
            return self.arclengths(value, location)
        elif kind == "vector":
            return [float(v) for v in value]
        elif kind in p.SPATIAL_KINDS:
            from .spatial import read_value

            read = read_value(self, param, value, location)
            return _FAILED if read is None else read
        elif kind == "flag":
            return bool(value)
        return float(value) if isinstance(value, float) else value

    def relations(self, table: p.Table, t: Strict, where: str) -> None:
        """The bounds between keys of a validated table (``rod_side_area < piston_area``)."""
        for relation in table.relations:
            found = relation.violation(lambda key: getattr(t, key, None), lambda key, value: _shown(value, table[key]))
            if found is not None:
                self.problem(join(where, found[0]), found[1])

    # sections --------------------------------------------------------------

    def units_table(self) -> dict[str, tuple[str, float]]:
        """``[units]``: the unit of bare numbers of each declared kind (``length = "mm"``)."""
        declared = {}
        for key, unit in self.table("units").items():
            where = join("units", key)
            if key not in DECLARABLE:
                self.problem(where, f"unknown kind of quantity{did_you_mean(key, DECLARABLE)}; "
                                    f"kinds: {', '.join(DECLARABLE)}")
                continue
            try:
                declared[key] = declare_unit(key, unit)
            except UnitError as exc:
                self.problem(where, str(exc))
        return declared

    def model_table(self) -> None:
        table = self.validate(s.ModelTable, self.table("model"), "model")
        if table is not None:
            self.spec["name"] = table.name if table.name is not None else self.default_name
            self.spec["gravity"] = [float(g) for g in table.gravity]

    def named_points(self, raw: Any, where: str, what: str):
        """(name, location, value) of each well-named entry of a table of points; ``what`` describes the table
        in the message when it is not one (``points, e.g. { O = [...] }``)."""
        if not isinstance(raw, dict):
            self.problem(where, f"must be a table of {what}, got {raw!r}")
            return
        for name, value in raw.items():
            location = join(where, name)
            if not name or "." in name or name != name.strip():
                self.problem(location, f"must be a point name without '.' or spaces, got {name!r}")
                continue
            yield name, location, value

    def point_table(self, raw: Any, where: str) -> list[dict]:
        out = []
        for name, location, value in self.named_points(raw, where, 'points, e.g. { O = ["0 mm", "0 mm"] }'):
            try:
                x, y = _pair(value, location)
            except _Bad as bad:
                self.problem(location, str(bad))
                continue
            out.append({"name": name, "position": [x, y]})
        return out

    def ground(self) -> None:
        raw = self.table("ground")
        for key in raw:
            if key != "points":
                self.problem(join("ground", key), f"unknown key{did_you_mean(key, ['points'])}; allowed: points")
        points = self.point_table(raw.get("points", {}), "ground.points")
        self.spec["ground_points"] = points
        self.points["ground"] = [p["name"] for p in points]

    def bodies(self) -> None:
        for name, where, raw in self.entries("bodies"):
            self.claim(name, where)
            table = self.validate(s.BodyTable, raw, where)
            points = self.point_table(raw.get("points", {}), join(where, "points"))
            self.points.setdefault(name, [point["name"] for point in points])
            if table is None:
                continue
            if table.free:
                self.free.add(name)
            self.spec["bodies"].append(self.element_spec(p.BODY, name, where, table, raw, {"points": points}))

    def joints(self) -> None:
        for name, where, raw in self.entries("joints"):
            self.claim(name, where)
            kind = self.tagged(raw, "type", s.JOINTS, where)
            if kind is None:
                continue
            self.joint_types[name] = kind
            table = self.validate(s.JOINTS[kind], raw, where, hint=f"{kind} joint: ")
            if table is None:
                continue
            if kind == "clearance_revolute":
                joint = self.clearance_joint(name, where, table, raw)
            else:
                joint = self.element_spec(p.JOINTS[kind], name, where, table, raw)
                if kind == "translational" and math.hypot(*joint["axis"]) == 0.0:
                    self.problem(join(where, "axis"), f"must be a non-zero direction, got {raw.get('axis')!r}")
            if joint is not None:
                self.spec["joints"].append(joint)

    def clearance_joint(self, name: str, where: str, t: s.ClearanceRevoluteTable, raw: dict) -> dict | None:
        self.point(t.bearing, join(where, "bearing"))
        self.point(t.journal, join(where, "journal"))
        clearance = self.radial_clearance(where, t)
        contact, stiffness, friction = (self.law(raw, p.CLEARANCE_REVOLUTE[key], where)
                                        for key in ("contact", "stiffness", "friction"))
        if stiffness is not None and stiffness["law"] in p.LENGTH_LAWS and t.length is None:
            self.problem(join(where, "length"), f"missing required value: the {stiffness['law']} stiffness law "
                                                "needs the bearing length, e.g. \"40 mm\"")
        if clearance is not None:
            ex, ey = t.initial_eccentricity
            if math.hypot(ex, ey) > clearance:
                self.problem(join(where, "initial_eccentricity"),
                             f"must lie within the clearance ({_text(clearance)}), got [{ex.text}, {ey.text}]")
        lubrication = self.lubrication(raw.get("lubrication"), join(where, "lubrication"), t.length, where)
        if None in (clearance, contact, stiffness, friction) or lubrication is False:
            return None
        read = {"bearing": t.bearing, "journal": t.journal, "clearance": float(clearance), "contact": contact,
                "stiffness": stiffness, "friction": friction, "lubrication": lubrication}
        return self.element_spec(p.CLEARANCE_REVOLUTE, name, where, t, raw, read)

    def lubrication(self, raw: Any, where: str, length: Any, joint_where: str) -> dict | None | bool:
        """The core's lubrication dict, None for a dry joint, False after adding problems."""
        if raw is None:
            return None
        if not isinstance(raw, dict):
            self.problem(where, f'must be a table such as {{ model = "hamrock_short", viscosity = "400 cP" }}, got {raw!r}')
            return False
        # every problem of the table is reported, so the transition is read even when the rest is bad
        table = self.validate(s.LubricationTable, raw, where)
        if table is not None and table.model not in s.REYNOLDS_MODELS:
            unused = [key for key in s.REYNOLDS_ONLY_KEYS if key in raw]
            for key in unused:
                self.problem(join(where, key), f"applies only to the {' and '.join(s.REYNOLDS_MODELS)} models, "
                                               f"not to model = {table.model!r}; remove it or choose a Reynolds model")
            if unused:
                return False
        transition = self.law(raw, p.LUBRICATION["transition"], where)
        if length is None:
            self.problem(join(joint_where, "length"), 'missing required value: a lubricated joint needs the bearing '
                                                      'length, e.g. "40 mm"')
            return False
        if table is None or transition is None:
            return False
        grid = self.grid(table.grid, join(where, "grid"))
        if grid is False:
            return False
        # the Reynolds options go to the core for every model (a closed form ignores them; it has their
        # defaults here, since giving one is an error)
        return {"model": table.model, "viscosity": float(table.viscosity), "transition": transition,
                "reynolds": {
                    "cavitation": table.cavitation, "n_circumferential": grid[0], "n_axial": grid[1],
                    "ambient_pressure": float(table.ambient_pressure),
                    "groove_supply_pressure": None if table.groove_supply_pressure is None else float(table.groove_supply_pressure),
                }}

    def grid(self, raw: Any, where: str) -> tuple[int | None, int | None] | bool:
        """``grid = [n_circumferential, n_axial]`` of the Reynolds solver, or the solver's default."""
        if raw is None:
            return (None, None)
        if (isinstance(raw, list) and len(raw) == 2 and all(isinstance(n, int) and not isinstance(n, bool) and n >= 4
                                                            for n in raw)):
            if max(raw) > MAX_REYNOLDS_GRID_NODES:  # the core checks the node count; this keeps the counts in range
                self.problem(where, f"a grid has at most {MAX_REYNOLDS_GRID_NODES} nodes, got {raw!r}")
                return False
            return (raw[0], raw[1])
        self.problem(where, f"must be [cells around, cells along the axis], whole numbers >= 4, got {raw!r}")
        return False

    def radial_clearance(self, where: str, t: s.ClearanceRevoluteTable) -> float | None:
        """c = R_b - R_j from ``clearance`` or ``journal_radius`` (exactly one of them)."""
        rb = t.bearing_radius
        if (t.clearance is None) == (t.journal_radius is None):
            what = "both" if t.clearance is not None else "neither"
            self.problem(join(where, "clearance"), f"give exactly one of clearance or journal_radius, got {what}")
            return None
        if t.journal_radius is not None:
            if t.journal_radius >= rb:
                self.problem(join(where, "journal_radius"), f"must be smaller than bearing_radius = {rb.text} "
                                                            f"(the journal would not fit), got {t.journal_radius.text}")
                return None
            return Q(float(rb) - float(t.journal_radius), f"{_text(float(rb) - float(t.journal_radius))}")
        if t.clearance >= rb:
            self.problem(join(where, "clearance"), f"must be smaller than bearing_radius = {rb.text} "
                                                   f"(the journal radius would be <= 0), got {t.clearance.text}")
            return None
        return t.clearance

    def law(self, raw: dict, param: p.Param, where: str) -> dict | None:
        """The core's dict of the law ``raw[param.key]`` (its default when absent), or None after adding
        problems (a missing required law is reported by pydantic)."""
        laws = s.LAWS[param.of]
        value = raw.get(param.key)
        location = join(where, param.key)
        if value is None:
            if param.required:
                return None
            value = param.default
        if isinstance(value, str):  # law = "hertz" shorthand: contact = "hertz"
            value = {"law": value}
        if not isinstance(value, dict):
            self.problem(location, f"must be a table such as {{ law = \"{next(iter(laws))}\" }}, got {value!r}")
            return None
        value = p.tagged_law(value, param.of)
        law = self.tagged(value, "law", laws, location)
        if law is None:
            return None
        table = self.validate(laws[law], value, location, hint=f"{law}: ")
        if table is None:
            return None
        self.relations(p.LAWS[param.of][law], table, location)
        # every key of the law, those not given with their defaults (None: "not given", sent as null)
        return p.core_law({k: (float(v) if isinstance(v, float) else v) for k, v in table.model_dump().items()})

    def drivers(self) -> None:
        for name, where, raw in self.entries("drivers"):
            self.claim(name, where)
            table = self.validate(s.DriverTable, raw, where)
            if table is None:
                continue
            kind = self.joint_types.get(table.joint)
            if kind not in DRIVEN_KIND:
                if kind is None:
                    hint = did_you_mean(table.joint, self.joint_types)
                    self.problem(join(where, "joint"), f"no joint named {table.joint!r}{hint}")
                else:
                    self.problem(join(where, "joint"), f"joint {table.joint!r} is a {kind} joint; only revolute and "
                                                       "translational joints can be driven")
                function_spec(table.function, "angle", join(where, "function"), self.problems)
                continue
            function = function_spec(table.function, DRIVEN_KIND[kind], join(where, "function"), self.problems)
            if function is not None:
                self.spec["drivers"].append({"name": name, "joint": table.joint, "function": function})

    def forces(self) -> None:
        for name, where, raw in self.entries("forces"):
            self.claim(name, where)
            kind = self.tagged(raw, "type", s.FORCES, where)
            if kind is None:
                continue
            t = self.validate(s.FORCES[kind], raw, where, hint=f"{kind}: ")
            force = None if t is None else self.element_spec(p.FORCES[kind], name, where, t, raw)
            if force is not None:
                self.spec["forces"].append(force)

    # flexible links and sensors ------------------------------------------------

    def beams(self) -> None:
        for name, where, raw in self.entries("beams"):
            self.claim(name, where)
            table = self.validate(s.BeamTable, raw, where)
            stations = self.arclengths(raw.get("points", {}), join(where, "points"))
            self.points.setdefault(name, ["start", "end", *(station["name"] for station in stations)])
            self.flexible_names.add(name)
            if table is None:
                continue
            if table.free:
                self.free.add(name)
            beam = self.beam(name, where, table, raw, stations)
            if beam is not None:
                self.spec["beams"].append(beam)

    def beam(self, name: str, where: str, t: Strict, raw: dict, stations: list[dict]) -> dict | None:
        """The core's dict of a validated beam table: section and material as one ``section``, the mesh keys as
        one ``mesh``; None after adding problems."""
        geometry = self.beam_geometry(where, t, raw, [(stations, "points")])
        if geometry is None:
            return None
        section, mesh = geometry
        return {"name": name, "start": [float(v) for v in t.start], "end": [float(v) for v in t.end],
                "section": section, "mesh": mesh, "damping_time": float(t.damping_time),
                **_rigid_motion(t),
                "points": stations}

    def beam_geometry(self, where: str, t: Strict, raw: dict,
                      named: list[tuple[list[dict], str]]) -> tuple[dict, dict] | None:
        """The core's ``section`` and ``mesh`` of a validated beam or modal body table whose named stations
        are ``named`` (each list with the key that holds it: points or interface nodes); None after adding
        problems."""
        section = self.variant(raw, p.BEAM["section"], where)
        material = self.beam_material(t, section, join(where, "material"))
        mesh_ok = self.exactly_one(t, ("elements", "element_length"), where)
        length = math.dist(t.start, t.end)
        if length == 0.0:
            self.problem(join(where, "end"), f"must differ from start = [{t.start[0].text}, {t.start[1].text}] "
                                             f"(a beam has a length), got [{t.end[0].text}, {t.end[1].text}]")
        for station, key in ((station, key) for stations, key in named for station in stations):
            if length > 0.0 and station["arclength"] > length:
                self.problem(join(where, key, station["name"]),
                             f"must lie on the beam, from 0 to its length {_text(length)}, got "
                             f"{_text(station['arclength'])}")
        if section is None or material is False or not mesh_ok or length == 0.0:
            return None
        shape = section.pop("shape")
        core_section = {"type": shape, **section, **({} if material is None else {"material": material})}
        mesh = {"order": t.order, "elements": t.elements,
                "element_length": None if t.element_length is None else float(t.element_length)}
        return core_section, mesh

    def modal_bodies(self) -> None:
        for name, where, raw in self.entries("modal_bodies"):
            self.claim(name, where)
            table = self.validate(s.ModalBodyTable, raw, where)
            stations, points = self.modal_nodes(raw, where)
            self.points.setdefault(name, [station["name"] for station in (*stations, *points)])
            self.flexible_names.add(name)
            if table is None:
                continue
            if table.free:
                self.free.add(name)
            body = self.modal_body(name, where, table, raw, (stations, points))
            if body is not None:
                self.spec.setdefault("modal_bodies", []).append(body)

    def modal_nodes(self, raw: dict, where: str) -> tuple[list[dict], list[dict]]:
        """A modal body's interface nodes and other points as the core's lists: by arclength on a beam
        (interface ``start`` and ``end`` by default), by node number with ``matrices``."""
        if raw.get("matrices") is None:
            return self.interface_nodes(raw, where), self.arclengths(raw.get("points", {}), join(where, "points"))
        if not raw.get("interface"):
            self.problem(join(where, "interface"), "missing required value: a body given by matrices names its "
                                                   "interface nodes by number, e.g. { A = 0, B = 12 }")
        return (self.node_numbers(raw.get("interface") or {}, join(where, "interface")),
                self.node_numbers(raw.get("points", {}), join(where, "points")))

    def node_numbers(self, raw: Any, where: str) -> list[dict]:
        """Named nodes of a structure given by matrices, ``{ A = 0, B = 12 }``, as the core's list."""
        out = []
        for name, location, value in self.named_points(raw, where, "node numbers, e.g. { A = 0, B = 12 }"):
            if isinstance(value, bool) or not isinstance(value, int) or value < 0:
                self.problem(location, f"must be a node number (a whole number from 0: the row of the node in "
                                       f"`nodes`), got {value!r}")
                continue
            out.append({"name": name, "node": value})
        return out

    def interface_nodes(self, raw: dict, where: str) -> list[dict]:
        """A modal beam's interface nodes by arclength (``start`` and ``end`` by default), as the core's list;
        ``end``'s default arclength is filled in by :meth:`modal_body` once the length is known."""
        given = raw.get("interface") or {"start": 0.0, "end": None}
        out = []
        for name, location, value in self.named_points(given, join(where, "interface"),
                                                       'arclengths, e.g. { start = "0 mm", end = "300 mm" }'):
            try:
                arclength = None if value is None else float(convert(value, "length", ge=0))
            except PydanticCustomError as exc:
                self.problem(location, exc.message())
                continue
            out.append({"name": name, "arclength": arclength})
        return out

    def modal_body(self, name: str, where: str, t: Strict, raw: dict,
                   named: tuple[list[dict], list[dict]]) -> dict | None:
        """The core's dict of a validated modal body table with its interface nodes and points ``named``; None
        after adding problems."""
        stations, points = named
        if t.matrices is None:
            structure = self.modal_beam(where, t, raw, named)
        else:
            structure = self.modal_matrices(where, t, raw)
        if structure is None:
            return None
        def point(station: dict) -> dict:  # the core reads both keys; one is None
            return {"name": station["name"], "arclength": station.get("arclength"), "node": station.get("node")}

        return {"name": name, "structure": structure, "interface": [point(station) for station in stations],
                "points": [point(station) for station in points], "frame": t.frame,
                "normal_modes": t.normal_modes, "damping_ratio": float(t.damping_ratio),
                "damping_time": float(t.damping_time),
                **_rigid_motion(t)}

    def modal_beam(self, where: str, t: Strict, raw: dict, named: tuple[list[dict], list[dict]]) -> dict | None:
        """The core's structure of a modal body reduced from a beam; None after adding problems."""
        missing = [key for key in ("start", "end", "section") if getattr(t, key) is None]
        for key in missing:
            self.problem(join(where, key), f"missing required value: {p.MODAL_BODY[key].example} (or give "
                                           "`matrices` for a structure from another finite-element code)")
        if t.position != (0.0, 0.0) or t.angle != 0.0:
            key = "position" if t.position != (0.0, 0.0) else "angle"
            self.problem(join(where, key), "places a structure given by `matrices`; a beam is placed by `start` "
                                           "and `end`: remove it")
            return None
        if missing:
            return None
        stations, points = named
        length = math.dist(t.start, t.end)
        for station in stations:
            if station["arclength"] is None:
                station["arclength"] = length
        geometry = self.beam_geometry(where, t, raw, [(stations, "interface"), (points, "points")])
        if geometry is None:
            return None
        section, mesh = geometry
        return {"from": "beam", "start": [float(v) for v in t.start], "end": [float(v) for v in t.end],
                "section": section, "mesh": mesh}

    def modal_matrices(self, where: str, t: Strict, raw: dict) -> dict | None:
        """The core's structure of a modal body given by matrices (read from files or given), in SI units;
        None after adding problems."""
        from . import matrices as mx

        for key in ("start", "end", "section", "material", "elements", "element_length", "order"):
            if getattr(t, key) is not None and not (key == "order" and t.order == p.MODAL_BODY.default("order")):
                self.problem(join(where, key), "is not used by a body given by `matrices` (its nodes, `position` "
                                               "and `angle` place it); remove it")
        at = join(where, "matrices")
        given = t.matrices
        if not isinstance(given, dict):
            self.problem(at, f"must be a table such as {p.MODAL_BODY['matrices'].doc.split(': ', 1)[1]}, "
                             f"got {given!r}")
            return None
        table = p.MODAL_MATRICES
        for key in given:
            if key not in table.keys():
                self.problem(join(at, key), f"unknown key{did_you_mean(key, table.keys())}; keys: "
                                            f"{', '.join(table.keys())}")
        for key in ("mass", "stiffness", "nodes"):
            if given.get(key) is None:
                self.problem(join(at, key), f"missing required value: {table[key].example}")
        read = {}
        readers = {"mass": mx.read_matrix, "stiffness": mx.read_matrix, "nodes": mx.read_nodes}
        units = {"length_unit": "length", "mass_unit": "mass"}
        for key, reader in readers.items():
            try:
                read[key] = None if given.get(key) is None else reader(given[key], self.base)
            except mx.MatrixError as exc:
                self.problem(join(at, key), str(exc))
        for key, kind in units.items():
            if given.get(key) is None:
                # the numbers of a file carry no unit: taken as SI, a structure in mm is 1000 times too large
                self.problem(join(at, key), f"missing required value: {table[key].example}; the numbers in the "
                                            f"files carry no unit, so the {kind} unit they are written in must "
                                            "be given (\"m\" and \"kg\" for SI)")
                continue
            try:
                read[key] = mx.unit_factor(given[key], kind)
            except mx.MatrixError as exc:
                self.problem(join(at, key), str(exc))
        fits = read.get("nodes") is not None and self.structure_fits(read, at)
        if not fits or len(read) < len(readers) + len(units) or any(v is None for v in read.values()):
            return None
        length, mass = read["length_unit"], read["mass_unit"]
        per_node = read["mass"].shape[0] // read["nodes"].shape[0]
        return {"from": "matrices", "mass": mx.core_entries(mx.in_si(read["mass"], length, mass, per_node)),
                "stiffness": mx.core_entries(mx.in_si(read["stiffness"], length, mass, per_node)),
                "nodes": (read["nodes"] * length).tolist(),
                "position": [float(v) for v in t.position], "angle": float(t.angle)}

    def structure_fits(self, read: dict, at: str) -> bool:
        """The matrices have three coordinates per node (frame elements) or two (plane solids), both the same,
        within the core's size for a structure."""
        n = read["nodes"].shape[0]
        if n > MAX_STRUCTURE_NODES:
            self.problem(join(at, "nodes"), f"{n} nodes: a structure given by matrices has at most "
                                            f"{MAX_STRUCTURE_NODES} (its reduction is dense); reduce it in its own "
                                            "code first")
            return False
        fits = True
        for key in ("mass", "stiffness"):
            if read.get(key) is None:
                continue
            size = read[key].shape[0]
            if size not in (3 * n, 2 * n):
                self.problem(join(at, key), f"must be {3 * n} x {3 * n}: three coordinates (u_x, u_y, theta) for "
                                            f"each of the {n} nodes of a frame, or {2 * n} x {2 * n}: two (u_x, u_y) "
                                            f"for each node of a plane solid, got {size} x {size}")
                fits = False
        if fits and read.get("mass") is not None and read.get("stiffness") is not None \
                and read["mass"].shape != read["stiffness"].shape:
            size = read["mass"].shape[0]
            self.problem(join(at, "stiffness"), f"must be {size} x {size} as the mass matrix is, got "
                                                f"{read['stiffness'].shape[0]} x {read['stiffness'].shape[0]}")
            fits = False
        return fits

    def beam_material(self, t: Strict, section: dict | None, where: str) -> dict | None | bool:
        """The core's material of a beam: None for a section given by its resultants, False after problems."""
        shape = None if section is None else section["shape"]
        if t.material is None:
            if shape is not None and shape != "resultants":
                self.problem(where, f"missing required value: a {shape} section needs a material, e.g. "
                                    '{ youngs_modulus = "207 GPa", poisson_ratio = 0.3, density = "7850 kg/m^3" }')
                return False
            return None
        if shape == "resultants":
            self.problem(where, "is not used by a section given by its resultants (they hold E A, k G A, E I, "
                                "rho A and rho I); remove it or give the section's shape")
            return False
        if not self.exactly_one(t.material, ("poisson_ratio", "shear_modulus"), where):
            return False
        return {key: None if getattr(t.material, key) is None else float(getattr(t.material, key))
                for key in p.BEAM_MATERIAL.keys()}

    def exactly_one(self, t: Strict, keys: tuple[str, str], where: str) -> bool:
        """Exactly one of two optional keys is given; a problem at the first otherwise."""
        given = [getattr(t, key) is not None for key in keys]
        if sum(given) == 1:
            return True
        what = "both" if all(given) else "neither"
        self.problem(join(where, keys[0]), f"give exactly one of {keys[0]} or {keys[1]}, got {what}")
        return False

    def variant(self, raw: dict, param: p.Param, where: str) -> dict | None:
        """The nested table ``raw[param.key]`` of the family ``param.of`` (:data:`~jointplay.parameters.VARIANTS`)
        in SI units with its tag, or None after adding problems (a missing one is reported by pydantic)."""
        tables = p.VARIANTS[param.of]
        tag = next(iter(tables.values())).tag
        value = raw.get(param.key)
        location = join(where, param.key)
        if value is None:
            return None
        if not isinstance(value, dict):
            self.problem(location, f"must be a table such as {param.example.removeprefix('a section, e.g. ')}, "
                                   f"got {value!r}")
            return None
        name = self.tagged(value, tag, tables, location)
        if name is None:
            return None
        cls = s.table_class(tables[name])
        table = self.validate(cls, value, location, hint=f"{name}: ")
        if table is None:
            return None
        self.relations(tables[name], table, location)
        return {tag: tables[name].name, **{sub.key: float(getattr(table, sub.key)) for sub in tables[name].params}}

    def arclengths(self, raw: Any, where: str) -> list[dict]:
        """Named points of a beam by arclength, ``{ E = "75 mm" }``, as the core's list."""
        out = []
        for name, location, value in self.named_points(raw, where, 'arclengths, e.g. { E = "75 mm" }'):
            if name in ("start", "end"):
                self.problem(location, f"{name!r} names the beam's {'first' if name == 'start' else 'second'} end "
                                       "already; choose another name")
                continue
            try:
                arclength = float(convert(value, "length", ge=0))
            except PydanticCustomError as exc:
                self.problem(location, exc.message())
                continue
            out.append({"name": name, "arclength": arclength})
        return out

    def sensors(self) -> None:
        for name, where, raw in self.entries("sensors"):
            self.claim(name, where)
            kind = self.tagged(raw, "type", s.SENSORS, where)
            if kind is None:
                continue
            t = self.validate(s.SENSORS[kind], raw, where, hint=f"{kind}: ")
            if t is None:
                continue
            referenced = set(self.referenced)  # a sensor observes a beam; it does not connect it
            sensor = self.element_spec(p.SENSORS[kind], name, where, t, raw)
            self.referenced = referenced
            body = t.point.partition(".")[0]
            if self.check_references and body in self.points and body not in self.flexible_names:
                self.problem(join(where, "point"), f"must be a point of a beam or modal body; {body!r} is a rigid "
                                                   f"body (beams and modal bodies: "
                                                   f"{', '.join(sorted(self.flexible_names)) or 'none'})")
            elif sensor is not None:
                self.spec["sensors"].append(sensor)

    def simulation_table(self) -> None:
        table = self.validate(s.SimulationTable, self.table("simulation"), "simulation")
        if table is None:
            return
        self.relations(p.SIMULATION, table, "simulation")
        if table.method == "generalized_alpha" and table.step is None:
            self.problem("simulation.step", 'generalized_alpha integrates with a fixed nominal step and needs one, '
                                            'for example step = "1 ms"; its accuracy is that step\'s')
        self.simulation = {k: (float(v) if isinstance(v, float) else v)
                           for k, v in table.model_dump(exclude_none=True).items()}

    def connectivity(self) -> None:
        """A model without bodies is a mistake; so is a body that no joint or force element refers to,
        unless marked ``free = true``."""
        if not self.table("bodies") and not self.table("beams") and not self.table("modal_bodies"):
            self.problem("bodies", "the model has no bodies: describe at least one as a [bodies.NAME] table "
                                   "with its mass and inertia (or a flexible link as a [beams.NAME] table)")
            return
        if any(p.location.startswith(("joints", "forces")) for p in self.problems):
            return  # references are incomplete; do not pile on
        for section in ("bodies", "beams", "modal_bodies"):
            for body in self.spec.get(section, []):
                name = body["name"]
                if name not in self.referenced and name not in self.free:
                    self.problem(join(section, name), "is connected to nothing: no joint or force element refers "
                                                      "to it (write free = true if it is meant to move freely)")


class _Bad(ValueError):
    pass


def _pair(value: Any, where: str) -> tuple[float, float]:
    from pydantic_core import PydanticCustomError

    from .fields import _vector

    try:
        x, y = _vector(value, "length")
    except PydanticCustomError as exc:
        raise _Bad(exc.message()) from None
    return float(x), float(y)


def _text(value: float) -> str:
    return f"{value * 1e3:.6g} mm"


def _shown(value: Any, param: p.Param | None = None) -> str:
    """A validated quantity as the user wrote it (a value not written by the user, such as a default the core
    sets, in the SI unit of ``param``)."""
    if isinstance(value, Q):
        return value.text
    unit = p.unit(param) if param is not None else ""
    return f"{value:g} {unit}" if unit else f"{value:g}"


def _rigid_motion(t: Strict) -> dict:
    """A flexible body's initial rigid motion as the core reads it: each key None where it was not given (neither
    given: the rigid motion the mechanism gives the body at assembly)."""
    return {"velocity": None if t.velocity is None else [float(v) for v in t.velocity],
            "angular_velocity": None if t.angular_velocity is None else float(t.angular_velocity)}
