"""Plausibility: values that are legal but almost certainly a mistake (a unit slip, a digit too many).

:func:`plausibility` looks at a validated spec (SI units) and returns one
:class:`~jointplay.errors.Problem` per suspicious value, located like a
model-file error (``joints.B.clearance``). They are warnings: the run goes on
(``Model.simulate`` issues them as ``JointplayWarning``, ``jointplay run``
and ``jointplay check`` print them).

The size of the mechanism, L, is the largest distance from a body's centre
of mass to one of its points (half the longest link, about); speeds are
driver rates times L, initial velocities and the free-fall speed over L.
Each threshold is a factor far beyond what real mechanisms show, so that a
warning almost always means a slip:

- radial clearance above 20 % of the bearing radius: twice the largest
  ratio in the shipped studies (paper 001's series goes to 1 mm in the
  10 mm bore of the examples; the Flores models use 5 %; machine fits are
  near 0.1 %), while a unit slip in one of the two changes it 1000 times;
- a bearing radius larger than L (the joint is larger than its links);
- a mass 1e4 times above or below the median of the bodies (the smaller of two; a g/kg
  slip is 1e3, a t/g slip 1e6; parts of one mechanism rarely differ by 1e4);
  an inertia 1e6 times off (inertia grows as mass times size squared);
- a radius of gyration sqrt(I/m) above 10 L (a kg mm^2 value written as
  kg m^2 gives 1000 times the true radius);
- a Young's modulus outside [1 MPa, 1.2 TPa] (soft rubber to diamond), of a
  clearance joint or of a beam; a beam's density outside [10, 25 000] kg/m^3
  (foams to beyond osmium, 22 590 kg/m^3): "7.85 kg/m^3" for steel is a slip;
- a beam shorter than twice its section's depth (beam theory assumes a
  slender link; such a "link" is a block);
- a hydraulic cylinder's bulk modulus outside [10 MPa, 5 GPa] (a liquid with
  much entrained air to beyond any hydraulic liquid; mineral oil is 1.5-1.8
  GPa, water 2.2 GPa): "1.5 MPa" for "1.5 GPa" is a slip of 1000;
- a contact stiffness (linearised at a penetration of 1 % of the clearance)
  1e4 times above or below that of the other contacts (a polymer bushing
  beside steel is about 1e2; it grows as E* sqrt(R_b R_j)), a spring
  stiffness 1e6 times off the other springs (contacts and springs are not compared:
  a soft return spring beside a steel contact is normal);
- an onset-velocity floor above the speeds of the model (the floor is meant
  for grazing contacts, far below impact speeds);
- a lubricant viscosity outside [1e-5, 100] Pa s (air, 0.018 cP, to a cold
  heavy gear oil, 1e5 cP; engine oils are 10-1000 cP): "400 Pa s" for
  "400 cP" is a slip of 1000, and a film 1000 times too viscous makes the
  run very stiff and slow;
- a pressure above 100 MPa (1000 bar) in a hydraulic chamber at the start
  or in a lubricant supply: industrial hydraulics are rated to 35-70 MPa, and
  a MPa/GPa or bar/kPa slip is a factor of 1000 (10 to 100);
- a force element between two points of one body, or of the ground (a
  hydraulic cylinder from ground to ground): its force acts on nothing, and
  its length never changes;
- a body farther than 100 L from the middle (median) of the bodies and ground
  points;
- nothing that moves the mechanism (no driver, force, gravity or velocity).
"""

from __future__ import annotations

import math
import warnings
from statistics import median

from .. import parameters as p
from ..errors import JointplayWarning, Problem
from .fields import join

CLEARANCE_RATIO = 0.20
MASS_FACTOR = 1e4
INERTIA_FACTOR = 1e6
GYRATION_FACTOR = 10.0
CONTACT_FACTOR = 1e4
SPRING_FACTOR = 1e6
FAR_FACTOR = 100.0
YOUNGS_RANGE = (1e6, 1.2e12)  # [Pa]
DENSITY_RANGE = (10.0, 25e3)  # [kg/m^3]
SLENDERNESS = 2.0
BULK_MODULUS_RANGE = (1e7, 5e9)  # [Pa]
VISCOSITY_RANGE = (1e-5, 100.0)  # [Pa s]
PRESSURE_CEILING = 100e6  # [Pa]


def plausibility(spec: dict) -> list[Problem]:
    """Warnings for a core spec (as ``Model.to_spec()`` returns); an empty list when all looks right."""
    size = mechanism_size(spec)
    problems: list[Problem] = []
    problems += _clearances(spec, size)
    problems += _outliers(spec, "mass", MASS_FACTOR, "kg")
    problems += _outliers(spec, "inertia", INERTIA_FACTOR, "kg m^2")
    problems += _gyration(spec, size)
    problems += _materials(spec)
    problems += _beams(spec)
    problems += _liquids(spec)
    problems += _lubricants(spec)
    problems += _pressures(spec)
    problems += _idle_forces(spec)
    problems += _stiffnesses(spec)
    problems += _onset_floors(spec, size)
    problems += _far_bodies(spec, size)
    problems += _nothing_moves(spec)
    return problems


def emit(problems: list[Problem], stacklevel: int = 3) -> None:
    """Each problem as a :class:`~jointplay.errors.JointplayWarning`, attributed ``stacklevel`` frames up
    (3: the caller of ``Model.simulate``)."""
    for problem in problems:
        warnings.warn(str(problem), JointplayWarning, stacklevel=stacklevel)


def mechanism_size(spec: dict) -> float:
    """L [m]: the largest distance from a body's centre of mass to one of its points (0 without points)."""
    lengths = [math.hypot(*p["position"]) for b in spec.get("bodies", []) for p in b.get("points", [])]
    lengths += [0.5 * math.dist(b["start"], b["end"]) for b in spec.get("beams", [])]  # about the centre
    return max(lengths, default=0.0)


def _mm(value: float) -> str:
    return f"{value * 1e3:.3g} mm"


def _clearances(spec: dict, size: float) -> list[Problem]:
    out = []
    for j in _clearance_joints(spec):
        where, c, rb = join("joints", j["name"]), j["clearance"], j["bearing_radius"]
        if c > CLEARANCE_RATIO * rb:
            out.append(Problem(join(where, "clearance"), f"{_mm(c)} is {100 * c / rb:.3g} % of the bearing radius "
                                                         f"{_mm(rb)}; radial clearances of real joints are a few "
                                                         "percent at most: check the units"))
        if size > 0 and rb > size:
            out.append(Problem(join(where, "bearing_radius"), f"{_mm(rb)} is larger than the links of the mechanism "
                                                              f"(largest centre-to-point distance {_mm(size)}): "
                                                              "check the units"))
    return out


def _clearance_joints(spec: dict) -> list[dict]:
    return [j for j in spec.get("joints", []) if j.get("type") == "clearance_revolute"]


def _outliers(spec: dict, key: str, factor: float, unit: str) -> list[Problem]:
    """Bodies whose ``key`` is ``factor`` times above or below the typical value of the bodies."""
    entries = [(join("bodies", b["name"], key), f"{b[key]:.3g} {unit}", b[key]) for b in spec.get("bodies", [])]
    return _off_by(entries, factor, unit, "the bodies")


def _off_by(entries: list[tuple[str, str, float]], factor: float, unit: str, group: str) -> list[Problem]:
    """(location, text, value) entries more than ``factor`` from the typical value: the median of three
    or more, the smaller of two (then only the larger can be flagged)."""
    values = [v for _, _, v in entries if math.isfinite(v) and v > 0]
    if len(values) < 2:
        return []
    typical = median(values) if len(values) > 2 else min(values)
    out = []
    for where, text, value in entries:
        ratio = value / typical if math.isfinite(value) and value > 0 else 1.0
        if ratio > factor or ratio < 1.0 / factor:
            out.append(Problem(where, f"{text} is {_times(ratio)} the typical value of {group} "
                                      f"({typical:.3g} {unit}): check the units"))
    return out


def _times(ratio: float) -> str:
    return f"{ratio:.3g} times" if ratio >= 1 else f"1/{1 / ratio:.3g} of"


def _gyration(spec: dict, size: float) -> list[Problem]:
    out = []
    for b in spec.get("bodies", []):
        if size > 0 and b["mass"] > 0 and b["inertia"] > 0:
            radius = math.sqrt(b["inertia"] / b["mass"])
            if radius > GYRATION_FACTOR * size:
                out.append(Problem(join("bodies", b["name"], "inertia"),
                                   f"{b['inertia']:.3g} kg m^2 with a mass of {b['mass']:.3g} kg gives a radius of "
                                   f"gyration of {_mm(radius)}, {radius / size:.3g} times the largest "
                                   f"centre-to-point distance ({_mm(size)}): check the units (kg m^2, not kg mm^2)"))
    return out


def _materials(spec: dict) -> list[Problem]:
    low, high = YOUNGS_RANGE
    out = []
    for j in _clearance_joints(spec):
        for side in ("bearing_material", "journal_material"):
            e = j[side]["youngs_modulus"]
            if not low <= e <= high:
                out.append(Problem(join("joints", j["name"], side, "youngs_modulus"),
                                   f"{e:.3g} Pa is outside the range of solids (1 MPa for soft rubber to 1.2 TPa "
                                   "for diamond): check the units"))
    return out


def _beams(spec: dict) -> list[Problem]:
    """Beam materials outside the solids' range and beams that are not slender."""
    out = []
    for b in spec.get("beams", []):
        where = join("beams", b["name"])
        material = b["section"].get("material")
        if material is not None:
            for key, (low, high), what in (("youngs_modulus", YOUNGS_RANGE, "1 MPa for soft rubber to 1.2 TPa for "
                                                                           "diamond"),
                                           ("density", DENSITY_RANGE, "10 kg/m^3 for foams to 25 000 kg/m^3")):
                if not low <= material[key] <= high:
                    unit = "Pa" if key == "youngs_modulus" else "kg/m^3"
                    out.append(Problem(join(where, "material", key), f"{material[key]:.3g} {unit} is outside the "
                                                                     f"range of solids ({what}): check the units"))
        depth = section_depth(b["section"])
        length = math.dist(b["start"], b["end"])
        if depth is not None and length < SLENDERNESS * depth:
            out.append(Problem(join(where, "section"), f"the section is {_mm(depth)} deep and the beam "
                                                       f"{_mm(length)} long: beam theory assumes a slender link "
                                                       "(length several times the depth); check the units"))
    return out


def section_depth(section: dict) -> float | None:
    """The depth of a section in the plane of bending [m]; None when given by properties or resultants."""
    return {"rectangle": section.get("height"), "circle": section.get("diameter"),
            "tube": section.get("outer_diameter")}.get(section["type"])


def _liquids(spec: dict) -> list[Problem]:
    low, high = BULK_MODULUS_RANGE
    out = []
    for force in spec["forces"]:
        beta = force.get("bulk_modulus") if force.get("type") == "hydraulic_cylinder" else None
        if beta is not None and not low <= beta <= high:
            out.append(Problem(join("forces", force["name"], "bulk_modulus"),
                               f"{beta:.3g} Pa is outside the range of hydraulic liquids (10 MPa with much entrained "
                               "air to 5 GPa; mineral oil 1.5-1.8 GPa): check the units"))
    return out


def _lubricants(spec: dict) -> list[Problem]:
    low, high = VISCOSITY_RANGE
    out = []
    for joint in _clearance_joints(spec):
        mu = (joint.get("lubrication") or {}).get("viscosity")
        if mu is not None and not low <= mu <= high:
            out.append(Problem(join("joints", joint["name"], "lubrication", "viscosity"),
                               f"{mu:.3g} Pa s ({mu * 1e3:.3g} cP) is outside the range of lubricants (1e-05 Pa s for "
                               "air to 100 Pa s for a cold heavy gear oil; engine oils 0.01-1 Pa s): check the units "
                               "(1 cP = 1 mPa s)"))
    return out


def _pressures(spec: dict) -> list[Problem]:
    """Chamber pressures at the start and lubricant supply pressures above :data:`PRESSURE_CEILING`."""
    found = [(join("forces", f["name"], key), f.get(key)) for f in spec["forces"]
             if f.get("type") == "hydraulic_cylinder" for key in ("cap_pressure", "rod_pressure")]
    for joint in _clearance_joints(spec):
        reynolds = (joint.get("lubrication") or {}).get("reynolds") or {}
        found += [(join("joints", joint["name"], "lubrication", key), reynolds.get(key))
                  for key in ("ambient_pressure", "groove_supply_pressure")]
    return [Problem(where, f"{value / 1e6:.3g} MPa ({value / 1e5:.3g} bar) is far above the rating of any hydraulic "
                           "system (industrial hydraulics: 35-70 MPa): check the units")
            for where, value in found if value is not None and value > PRESSURE_CEILING]


def _idle_forces(spec: dict) -> list[Problem]:
    """Two-point force elements whose ends are on one body (or both on the ground)."""
    out = []
    for force in spec["forces"]:
        first, second = force.get("first"), force.get("second")
        if not (isinstance(first, str) and isinstance(second, str)):
            continue
        body = first.split(".")[0]
        if body == second.split(".")[0]:
            what = "the ground" if body == "ground" else f"the body {body}"
            out.append(Problem(join("forces", force["name"], "second"),
                               f"{second} is on {what}, like the first end {first}: the element's length never "
                               "changes and its force acts on nothing; attach one end to a moving body"))
    return out


def contact_stiffness(joint: dict) -> float:
    """Linearised contact stiffness [N/m] of a clearance joint: d/d(delta) of K delta^n at a penetration
    of 1 % of the clearance, K = (4/3) E* sqrt(R*) (the Hertz cylinder-in-bore law; the line-contact
    laws are of the same order)."""
    e_star = 1.0 / sum((1.0 - m["poisson_ratio"] ** 2) / m["youngs_modulus"]
                       for m in (joint["bearing_material"], joint["journal_material"]))
    rb, c = joint["bearing_radius"], joint["clearance"]
    r_star = rb * (rb - c) / c
    exponent = (joint.get("stiffness") or {}).get("exponent", p.HERTZ_EXPONENT)
    k = 4.0 / 3.0 * e_star * math.sqrt(r_star)
    return exponent * k * (0.01 * c) ** (exponent - 1.0)


def _stiffnesses(spec: dict) -> list[Problem]:
    """Contacts (linearised at a penetration of 1 % of the clearance) far from the other contacts, springs
    far from the other springs (a soft return spring beside a steel contact is normal)."""
    contacts = [(join("joints", j["name"], "stiffness"), f"contact stiffness {contact_stiffness(j):.3g} N/m",
                 contact_stiffness(j)) for j in _clearance_joints(spec)]
    springs = [(join("forces", f["name"], "stiffness"), f"{f['stiffness']:.3g} N/m", f["stiffness"])
               for f in spec.get("forces", []) if f.get("type") == "spring_damper" and f["stiffness"] > 0]
    return (_off_by(contacts, CONTACT_FACTOR, "N/m", "the contacts")
            + _off_by(springs, SPRING_FACTOR, "N/m", "the springs"))


def function_rate(f: dict) -> float:
    """About the largest rate of a function of time (its unit per second); 0 for a constant."""
    kind = f.get("kind")
    if kind == "constant_rate":
        return abs(f["rate"])
    if kind == "polynomial":
        return abs(f["coefficients"][1]) if len(f["coefficients"]) > 1 else 0.0
    if kind == "cubic_step":
        return 1.5 * abs(f["value_end"] - f["value_start"]) / (f["t_end"] - f["t_start"])
    if kind == "sine":
        return abs(f["amplitude"]) * 2.0 * math.pi * f["frequency"]
    if kind == "speed_ramp":
        return abs(f["final_rate"])
    if kind == "table":
        t, v = f["times"], f["values"]
        return max((abs(v[i + 1] - v[i]) / (t[i + 1] - t[i]) for i in range(len(t) - 1)), default=0.0)
    return 0.0


def model_speed(spec: dict, size: float) -> float:
    """A speed scale of the model [m/s]: driver rates (angles times L), initial velocities, free fall over L."""
    kinds = {j["name"]: j["type"] for j in spec.get("joints", [])}
    speeds = [function_rate(d["function"]) * (size if kinds.get(d["joint"]) == "revolute" else 1.0)
              for d in spec.get("drivers", [])]
    for b in spec.get("bodies", []) + spec.get("beams", []) + spec.get("modal_bodies", []):
        speeds += [math.hypot(*(b.get("velocity") or (0.0, 0.0))), abs(b.get("angular_velocity") or 0.0) * size]
    speeds.append(math.sqrt(2.0 * math.hypot(*spec.get("gravity", (0.0, 0.0))) * size))
    return max(speeds, default=0.0)


def _onset_floors(spec: dict, size: float) -> list[Problem]:
    speed = model_speed(spec, size)
    if not speed > 0:
        return []  # moved by forces only (or not at all): no speed to compare with
    out = []
    for j in _clearance_joints(spec):
        floor = j.get("onset_velocity_floor", p.CLEARANCE_REVOLUTE.default("onset_velocity_floor"))
        if floor > speed:
            out.append(Problem(join("joints", j["name"], "onset_velocity_floor"),
                               f"{floor:.3g} m/s is above the speeds in the model (about {speed:.3g} m/s from the "
                               "drivers' rates times the link size, the initial velocities and free fall): the "
                               "floor is meant for grazing contacts, far below impact speeds"))
    return out


def _far_bodies(spec: dict, size: float) -> list[Problem]:
    """Bodies far from the middle (the median) of the bodies' centres and the ground points."""
    bodies = spec.get("bodies", [])
    places = [b["position"] for b in bodies] + [p["position"] for p in spec.get("ground_points", [])]
    if size <= 0 or len(places) < 3:
        return []
    middle = (median(p[0] for p in places), median(p[1] for p in places))
    out = []
    for b in bodies:
        distance = math.hypot(b["position"][0] - middle[0], b["position"][1] - middle[1])
        if distance > FAR_FACTOR * size:
            out.append(Problem(join("bodies", b["name"], "position"),
                               f"is {distance:.3g} m from the middle of the mechanism, {distance / size:.3g} times "
                               f"the largest centre-to-point distance ({_mm(size)}): check the units"))
    return out


def _nothing_moves(spec: dict) -> list[Problem]:
    moving = spec.get("bodies", []) + spec.get("beams", []) + spec.get("modal_bodies", [])
    if not moving or spec.get("drivers") or spec.get("forces"):
        return []
    if any(spec.get("gravity", (0.0, 0.0))):
        return []
    if any(any(b.get("velocity") or ()) or b.get("angular_velocity") for b in moving):
        return []
    return [Problem("model", "nothing moves the mechanism: no driver, force element, gravity or initial velocity; "
                             "the run will show it at rest")]
