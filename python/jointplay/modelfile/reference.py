"""The reference of every table, element, law and key of a model file, written from :mod:`jointplay.parameters`.

``python -m jointplay.modelfile.reference -o docs/model-file-reference.md`` writes it;
``tests/test_parameters.py`` fails when the committed file differs from :func:`text`.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .. import parameters as p
from ..units import KINDS

HEADER = """# Model-file reference

Every table and key of a model file: its kind and SI unit, the allowed
range, the default and why, and what it means. Generated from
`python/jointplay/parameters.py`, where each key is defined once (the
schema, the Python builder, the TOML writer and this page follow from it);
do not edit by hand, run `python -m jointplay.modelfile.reference -o
docs/model-file-reference.md` (`tests/test_parameters.py` fails when this
page is out of date). How quantities, units and bare numbers are written,
examples, and what is checked: [model-files.md](model-files.md).

A quantity may be written in any unit of its kind (`"0.5 mm"`, `"5000 rpm"`);
defaults are given in SI units. In Python, the `jointplay.Model` builder
methods, `jointplay.laws` and `jointplay.functions` take the same keys as
arguments, with the same defaults."""


def kind_text(param: p.Param) -> str:
    """``length [m]``, ``point "body.point"``, ``friction law``: what a key holds."""
    kind, of = param.kind, param.of
    if kind in KINDS:
        return _quantity(kind)
    words = {
        "vector": lambda: "plain vector `[x, y]`" if of == "dimensionless" else f"{_quantity(of)} vector `[x, y]`",
        "point": lambda: 'point `"body.point"`', "body": lambda: "body name",
        "joint": lambda: "joint name", "text": lambda: "text", "flag": lambda: "`true` or `false`",
        "count": lambda: "whole number > 0", "size": lambda: 'size: bytes, or `"500 MB"`, `"2 GiB"`',
        "choice": lambda: _choices(param), "points": lambda: "table of named length vectors [m]",
        "grid": lambda: "`[n, n]` whole numbers", "law": lambda: f"table: a {of.replace('_', ' ')} law (below)",
        "table": lambda: f"table: {of.name.replace('_', ' ')} (below)",
        "variant": lambda: f"table: a {of.replace('_', ' ')} (below)",
        "arclengths": lambda: "table of named lengths [m]",
        "nodes": lambda: "table of named lengths [m] (a beam) or node numbers (`matrices`)",
        "matrix": lambda: "file name, or the values",
        "function": lambda: ("function of time: an angle [rad] or a length [m]" if of == "coordinate"
                             else f"function of time: {_quantity(of)}"),
        "value": lambda: "value", "rate": lambda: "value per second",
        "vector3": lambda: f"{_quantity(of)} vector `[x, y, z]`",
        "orientation": lambda: "orientation: `axis` and `angle`, `euler` and `sequence`, `matrix` or `quaternion`",
        "inertia_tensor": lambda: "inertia tensor [kg m^2]: `principal` and `axes`, or `tensor`",
        "markers": lambda: "table of named points [m]: `[x, y, z]` or `{ position, axes }`",
        "function3": lambda: f"three functions of time: {_quantity(of)}",
        "list": lambda: ("list: coefficient k in value/s^k" if of == "powers" else "list of values"
                         if of == "value" else f"list of {_quantity(of)}"),
    }
    return words[kind]()


def _quantity(kind: str) -> str:
    spec = KINDS[kind]
    return "number" if not spec.si else f"{spec.name} [{spec.si.replace('*', ' ')}]"


def _choices(param: p.Param) -> str:
    words = ", ".join(f"`{w}`" for w in param.of)
    aliases = ", ".join(f"`{a}` = `{w}`" for a, w in param.aliases)
    return f"one of {words}" + (f" (aliases {aliases})" if aliases else "")


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def table_text(table: p.Table, heading: str) -> str:
    """A heading, the table's doc and one row per key."""
    out = [heading, "", table.doc]
    if table.aliases:
        out[-1] += " Also written " + ", ".join(f'`{table.tag} = "{a}"`' for a in table.aliases) + "."
    if not table.params:
        out += ["", f"No keys besides `{table.tag}`." if table.tag else "No keys."]
        return "\n".join(out)
    out += ["", "| key | kind [SI unit] | range | default | meaning |", "|---|---|---|---|---|"]
    for param in table.params:
        default = p.default_text(param)
        default = f"`{default}`" if param.default_text == "" and not param.required else default
        if param.why:
            default += f" ({param.why})"
        meaning = param.doc + ("" if param.in_spec else " (read by the front end; not sent to the core)")
        out.append("| " + " | ".join(_cell(c) for c in (f"`{param.key}`", kind_text(param), p.range_text(param),
                                                             default, meaning)) + " |")
    if table.relations:
        out += ["", "Also checked: " + "; ".join(relation.text() for relation in table.relations) + "."]
    return "\n".join(out)


def _family(tables: dict[str, p.Table], level: str) -> list[str]:
    return [table_text(t, f'{level} `{t.tag} = "{t.name}"`') for t in p.variants(tables)]


def _family_heading(key: str) -> str:
    heading = f"### {key.replace('_', ' ').capitalize()} laws\n\n`{key} = {{ law = ..., ... }}`"
    if key in p.UNTAGGED_LAWS:
        heading += f" (`law` may be left out: `{p.UNTAGGED_LAWS[key]}` is the only one)"
    return heading + "."


def text() -> str:
    """The whole reference, Markdown."""
    reynolds_only = (f"`{'`, `'.join(p.REYNOLDS_ONLY_KEYS)}` are read only by the "
                     f"{' and '.join(f'`{m}`' for m in p.REYNOLDS_MODELS)} models; given with a closed-form model "
                     "they are an error.")
    laws = [block for key, tables in p.LAWS.items()
            for block in (_family_heading(key), *_family(tables, "####"))]
    blocks = [HEADER,
              table_text(p.MODEL, "## `[model]`"),
              table_text(p.GROUND, "## `[ground]`"),
              table_text(p.BODY, "## `[bodies.NAME]`"),
              table_text(p.BEAM, "## `[beams.NAME]`"),
              "### Beam sections\n\n`section = { shape = ..., ... }` of a beam.",
              *_family(p.BEAM_SECTIONS, "####"),
              table_text(p.BEAM_MATERIAL, "### Beam materials\n\n`material = { ... }` of a beam."),
              table_text(p.MODAL_BODY, "## `[modal_bodies.NAME]`\n\n`section` and `material` as a beam's."),
              table_text(p.MODAL_MATRICES, "### Structures given by matrices\n\n`matrices = { ... }` of a modal "
                                           "body (docs/theory/modal-body.md)."),
              "## `[joints.NAME]`\n\nEvery joint has a `type`.",
              *_family(p.JOINTS, "###"),
              "## Tables inside an element",
              table_text(p.MATERIAL, "### Materials\n\n`bearing_material`, `journal_material` of a clearance joint."),
              table_text(p.LUBRICATION, "### Lubrication\n\n`lubrication = { model = ..., viscosity = ..., ... }` "
                                        "of a clearance joint.") + "\n\n" + reynolds_only,
              "## Laws\n\nA law is a table tagged by `law`; `contact = \"hertz\"` is short for "
              "`contact = { law = \"hertz\" }`.",
              *laws,
              table_text(p.DRIVER, "## `[drivers.NAME]`"),
              "## Functions of time\n\n`function = { kind = ..., ... }` of a driver, `fx`, `fy` of a point "
              "force, `torque` of a torque, `cap_inflow`, `rod_inflow` of a hydraulic cylinder; a bare quantity is "
              "a constant. \"value\" has the unit of what is prescribed: rad or m for a driver, N for a point "
              "force, N m for a torque, m^3/s for an inflow.",
              *_family(p.FUNCTIONS, "###"),
              "## `[forces.NAME]`\n\nEvery force element has a `type`.",
              *_family(p.FORCES, "###"),
              "## `[sensors.NAME]`\n\nEvery sensor has a `type`; its channels are `<name>.<quantity>`.",
              *_family(p.SENSORS, "###"),
              table_text(p.SIMULATION, "## `[simulation]`"),
              *spatial_blocks()]
    return "\n\n".join(blocks) + "\n"


SPATIAL_HEADER = """## Spatial models

`[model] kinematics = "spatial"` makes the model spatial: its `[bodies.NAME]` are spatial rigid bodies, its
joints and force elements those below, gravity and every position and velocity have three components
(docs/model-files.md, "Spatial models"). Drivers and `[simulation]` are as in a planar model (a driver
prescribes the rotation of a revolute joint about its axis, or the displacement along a translational or
cylindrical joint). Clearance joints, rotational spring-dampers, beams, modal bodies and sensors are planar
only. An orientation is one of `{ axis = [0, 0, 1], angle = "30 deg" }`, `{ euler = ["10 deg", "20 deg",
"30 deg"], sequence = "ZXZ" }` (the twelve intrinsic sequences, upper case; `"3-1-3"` names `"ZXZ"`),
`{ matrix = [[...], [...], [...]] }` (orthonormal, determinant +1, within 1e-6) or `{ quaternion = [w, x, y,
z] }` (scalar first, normalised)."""


def spatial_blocks() -> list[str]:
    """The tables of spatial models, each variant that planar models do not share."""
    shared = {id(t) for t in p.all_tables()}
    return [SPATIAL_HEADER,
            table_text(p.SPATIAL_MODEL, "### `[model]` of a spatial model"),
            table_text(p.SPATIAL_GROUND, "### `[ground]` of a spatial model"),
            table_text(p.SPATIAL_BODY, "### `[bodies.NAME]` of a spatial model"),
            "### `[joints.NAME]` of a spatial model\n\nEvery joint has a `type`; `first` and `second` are points "
            "with frames where the joint needs an axis.",
            *_family(p.SPATIAL_JOINTS, "####"),
            "### `[forces.NAME]` of a spatial model\n\nEvery force element has a `type`; `hydraulic_cylinder` "
            "is the planar one's table, between two points in space.",
            *[table_text(t, f'#### `type = "{t.name}"`') for t in p.variants(p.SPATIAL_FORCES)
              if id(t) not in shared]]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m jointplay.modelfile.reference", description=__doc__)
    parser.add_argument("-o", "--output", type=Path, help="file to write (default: standard output)")
    args = parser.parse_args(argv)
    if args.output is None:
        sys.stdout.write(text())
    else:
        args.output.write_text(text(), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
