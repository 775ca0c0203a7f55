"""The parameter registry (:mod:`jointplay.parameters`) as the core sees it: every range is defined there once,
and the core's checks read it from ``crates/jointplay-core/src/spec/ranges.rs``, which this module writes.

Regenerate the Rust file after changing a range in :mod:`jointplay.parameters`::

    python -m jointplay.boundary

``tests/test_parameter_boundary.py`` fails while the file differs from what this module writes, and compares
the keys of every table the core reads with the registry's.
"""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path

from . import parameters as p

#: The generated file, from the repository's root.
RANGES_FILE = Path("crates/jointplay-core/src/spec/ranges.rs")


def spec_tables() -> dict[str, p.Table]:
    """Every table of the registry that the core's model description holds, by an id naming its family and
    variant (``"forces.spring_damper"``, ``"contact.flores"``, ``"bodies"``); ``[simulation]`` is not part of
    the description (its options go to a run)."""
    tables = {t.name: t for t in (p.MODEL, p.GROUND, p.BODY, p.BEAM, p.MODAL_BODY, p.MODAL_MATRICES,
                                  p.BEAM_MATERIAL, p.MATERIAL, p.LUBRICATION, p.DRIVER)}
    tables["spatial_bodies"] = p.SPATIAL_BODY
    families = {"joints": p.JOINTS, "forces": p.FORCES, "sensors": p.SENSORS, "function": p.FUNCTIONS,
                "section": p.BEAM_SECTIONS, "spatial_joints": p.SPATIAL_JOINTS, "spatial_forces": p.SPATIAL_FORCES,
                **p.LAWS}
    for family, variants in families.items():
        for table in p.variants(variants):
            section = p.SPATIAL_JOINT_SECTIONS.get(table.name) if family == "spatial_joints" else None
            tables[section or f"{family}.{table.name}"] = table
    return tables


def _float(value: float) -> str:
    text = repr(float(value))
    return text if any(c in text for c in ".en") else text + ".0"


def _rule(param: p.Param) -> str:
    """How a message says the range: ``be > 0``, ``be >= -101325 Pa``, ``lie in (0, 1]``."""
    if param.interval:
        return f"lie in {param.interval}"
    unit = p.unit(param)
    parts = [f"{op} {value:g}" + (f" {unit}" if value != 0 and unit else "")
             for op, value in ((">", param.gt), (">=", param.ge), ("<", param.lt), ("<=", param.le)) if value is not None]
    return "be " + " and ".join(parts)


def const_name(table_id: str, key: str) -> str:
    """The Rust constant of a key's range: ``CONTACT_FLORES_RESTITUTION``."""
    return f"{table_id}.{key}".replace(".", "_").upper()


def ranged_keys() -> list[tuple[str, p.Param]]:
    """(table id, key) of every key the core reads that has a range, in the registry's order."""
    seen: list[p.Table] = []
    keys = []
    for table_id, table in spec_tables().items():
        # (a table two families share, the hydraulic cylinder's, has one set of ranges: its first id's)
        if any(table is other for other in seen):
            continue
        seen.append(table)
        keys += [(table_id, param) for param in table.params if param.in_spec and param.bounds]
    return keys


def rust_ranges() -> str:
    """The text of :data:`RANGES_FILE`."""
    lines = [
        "//! The range of every key of the model description that has one, generated from",
        "//! `python/jointplay/parameters.py` by `python -m jointplay.boundary`: edit the ranges there,",
        "//! then regenerate (`tests/test_parameter_boundary.py` fails while this file differs).",
        "",
        "use super::range::Range;",
    ]
    for table_id, param in ranged_keys():
        unit = p.unit(param)
        bounds = "".join(f".{name}({_float(getattr(param, name))})" for name in ("gt", "ge", "lt", "le")
                         if getattr(param, name) is not None)
        lines += [
            "",
            *textwrap.wrap(f"`{table_id}.{param.key}`: {param.doc.split(';')[0].replace('`', '')}"
                           + (f" [{unit}]" if unit else " [-]") + ".", 116, initial_indent="/// ",
                           subsequent_indent="/// "),
            f'pub const {const_name(table_id, param.key)}: Range = Range::new("{param.key}", "{_rule(param)}", '
            f'"{unit}"){bounds};',
        ]
    return "\n".join(lines) + "\n"


def main(root: Path = Path(__file__).resolve().parents[2]) -> None:
    """Writes :data:`RANGES_FILE` under ``root`` (the repository)."""
    path = root / RANGES_FILE
    path.write_text(rust_ranges())
    print(f"wrote {path}")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parents[2])
