"""``--set PATH=VALUE``: changing any value of a model file by its dotted path.

The path is read as a TOML dotted key (``joints.B.clearance``,
``bodies."my body".mass``; an integer picks a list element:
``model.gravity.1``). The value is read as a TOML value (``0.3``,
``"0.1 mm"``, ``[0, -9.81]``, ``{ law = "hertz" }``) and, when that fails,
taken as a string, so ``--set joints.B.clearance=0.1mm`` needs no quotes.
The changed document is then validated like the file itself.
"""

from __future__ import annotations

import copy
import json
import tomllib
from typing import Any

from ..errors import ModelError, Problem

#: Sections whose entries are named by the user: overriding a key of an entry that does not exist is an error.
NAMED_SECTIONS = ("bodies", "beams", "joints", "drivers", "forces", "sensors")


def parse_assignment(text: str) -> tuple[list[str], Any]:
    """``"joints.B.clearance=0.1 mm"`` -> (["joints", "B", "clearance"], "0.1 mm")."""
    path, eq, value = text.partition("=")
    path = path.strip()
    if not eq or not path:
        raise ModelError([Problem(f"--set {text}", "must be PATH=VALUE, e.g. joints.B.clearance=\"0.1 mm\"")])
    try:
        keys = _keys(tomllib.loads(f"{path} = 0"))
    except tomllib.TOMLDecodeError:
        raise ModelError([Problem(f"--set {path}", "is not a dotted path such as joints.B.clearance")]) from None
    return keys, _value(value.strip())


def _keys(doc: dict) -> list[str]:
    keys = []
    while isinstance(doc, dict):
        (key, doc), = doc.items()
        keys.append(key)
    return keys


def _value(text: str) -> Any:
    if not text:
        return ""
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return tomllib.loads(f"v = {json.dumps(text)}")["v"]
    except RecursionError:
        raise ModelError([Problem(f"--set {text[:40]}", "is nested too deeply to be read (arrays or inline tables "
                                                        "inside one another hundreds of levels deep)")]) from None


def apply_overrides(doc: dict, overrides: list[str] | dict[str, Any]) -> dict:
    """A copy of ``doc`` with each override applied; a path that cannot be set is a ModelError."""
    doc = copy.deepcopy(doc)
    if isinstance(overrides, dict):
        items = [(parse_assignment(f"{path}=0")[0], value) for path, value in overrides.items()]
    else:
        items = [parse_assignment(text) for text in overrides]
    problems = []
    for keys, value in items:
        problem = _set(doc, keys, value)
        if problem is not None:
            problems.append(problem)
    if problems:
        raise ModelError(problems)
    return doc


def _set(doc: dict, keys: list[str], value: Any) -> Problem | None:
    where = f"--set {'.'.join(keys)}"
    node: Any = doc
    for depth, key in enumerate(keys[:-1]):
        if isinstance(node, list):
            if not (key.isdigit() and int(key) < len(node)):
                return Problem(where, f"{'.'.join(keys[:depth])} is a list of {len(node)}; {key!r} is not an index in it")
            node = node[int(key)]
            continue
        if not isinstance(node, dict):
            return Problem(where, f"{'.'.join(keys[:depth])} is a value, not a table")
        if key not in node:
            if depth == 1 and keys[0] in NAMED_SECTIONS:
                known = ", ".join(node) or "none"
                return Problem(where, f"no entry {key!r} in [{keys[0]}] (entries: {known})")
            node[key] = {}
        node = node[key]
    last = keys[-1]
    if isinstance(node, list):
        if not (last.isdigit() and int(last) < len(node)):
            return Problem(where, f"{'.'.join(keys[:-1])} is a list of {len(node)}; {last!r} is not an index in it")
        node[int(last)] = value
    elif isinstance(node, dict):
        node[last] = value
    else:
        return Problem(where, f"{'.'.join(keys[:-1])} is a value, not a table")
    return None
