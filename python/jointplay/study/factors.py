"""Factors of a study: model parameters varied by their ``--set`` path.

A factor is continuous (a range ``[low, high]``, coded -1 .. +1) or discrete (a list of levels, coded
equally spaced over -1 .. +1 in their order). Values are written with units as in a model file
(``"16 um"``, ``"600 rpm"``) and held in SI; each case sets them on the model by the factor's path,
written back as SI text with the full float (``"1.6e-05 m"``), so a case's model is the same to the
last bit wherever it is built. ISO 286 grades and fits give a clearance joint's RADIAL clearance
(:mod:`jointplay.study.iso286`, ``docs/theory/iso-286-fits.md``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import ModelError, Problem
from ..units import KINDS, Kind, UnitError, format_value, to_si

#: Kinds tried, in order, to read a factor's value; the first that accepts the text's unit is the factor's.
_KIND_ORDER = [k for k in KINDS.values() if k.si] + [KINDS["dimensionless"]]


@dataclass(frozen=True)
class Factor:
    """One varied parameter.

    ``low``/``high`` bound a continuous factor; ``levels`` list a discrete one (SI). ``labels`` name the
    levels as written (``"IT7"``, ``"12 H7/g6"``). ``kind`` is the physical kind (``"length"``)."""

    name: str
    path: str
    kind: str
    low: float | None = None
    high: float | None = None
    levels: tuple[float, ...] = ()
    labels: tuple[str, ...] = ()
    description: str = ""
    #: Nominal diameter [m] of an ISO 286 factor (grade bands are reported at it), else None.
    nominal: float | None = None
    extra: dict = field(default_factory=dict, compare=False)

    @property
    def discrete(self) -> bool:
        return bool(self.levels)

    @property
    def units(self) -> str:
        return KINDS[self.kind].si

    @property
    def bounds(self) -> tuple[float, float]:
        """(smallest, largest) value [SI]."""
        if self.discrete:
            return min(self.levels), max(self.levels)
        return self.low, self.high

    def value(self, coded: float) -> float:
        """The factor's value [SI] at a coded coordinate (-1 .. +1; a discrete factor takes the nearest
        level)."""
        if self.discrete:
            return self.levels[self.level_index(coded)]
        return self.low + (coded + 1.0) * 0.5 * (self.high - self.low)

    def coded(self, value: float) -> float:
        """The coded coordinate of a value [SI] (a discrete factor: of the level nearest to it)."""
        if self.discrete:
            n = len(self.levels)
            index = int(np.argmin([abs(v - value) for v in self.levels]))
            return 0.0 if n == 1 else -1.0 + 2.0 * index / (n - 1)
        if self.high == self.low:
            return 0.0
        return -1.0 + 2.0 * (value - self.low) / (self.high - self.low)

    def level_index(self, coded: float) -> int:
        n = len(self.levels)
        if n == 1:
            return 0
        return int(min(n - 1, max(0, round((coded + 1.0) * 0.5 * (n - 1)))))

    def label(self, value: float) -> str:
        """How a value reads to a user: its level's label, or the value in SI with its unit."""
        if self.discrete and self.labels:
            return self.labels[int(np.argmin([abs(v - value) for v in self.levels]))]
        unit = self.units
        return f"{value:.6g} {unit}".strip()

    def override(self, value: float) -> Any:
        """The model-file value setting this factor to ``value`` [SI]: SI text with every digit."""
        unit = self.units.replace("*", " ")
        return f"{float(value)!r} {unit}" if unit else float(value)

    def to_dict(self) -> dict:
        """The factor as plain data (for the study's manifest and its Dataset's attributes)."""
        return {"name": self.name, "path": self.path, "kind": self.kind, "low": self.low, "high": self.high,
                "levels": list(self.levels), "labels": list(self.labels), "description": self.description,
                "nominal": self.nominal}


def quantity_kind(texts: list[Any], where: str) -> tuple[Kind, list[float]]:
    """The kind shared by quantities written with units and their SI values; bare numbers are
    dimensionless. Raises a located ModelError."""
    for kind in _KIND_ORDER:
        try:
            return kind, [_si(raw, kind) for raw in texts]
        except UnitError:
            continue
    shown = ", ".join(format_value(t) for t in texts)
    raise ModelError([Problem(where, f"must be quantities of one kind with units (e.g. [\"10 um\", \"30 um\"]), "
                                     f"got [{shown}]")])


def _si(raw: Any, kind: Kind) -> float:
    if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
        raise UnitError("not a quantity")
    if isinstance(raw, (int, float)) and kind.si:
        raise UnitError("a bare number is dimensionless")
    value = to_si(raw, kind)
    if not math.isfinite(value):
        raise UnitError("not finite")
    return value


def continuous(name: str, path: str, low: Any, high: Any, where: str, description: str = "") -> Factor:
    """A factor over ``[low, high]`` (quantities with units)."""
    kind, (lo, hi) = quantity_kind([low, high], f"{where}.range")
    if not lo < hi:
        raise ModelError([Problem(f"{where}.range", f"must be [low, high] with low < high, got "
                                                    f"[{format_value(low)}, {format_value(high)}]")])
    return Factor(name, path, kind.name, low=lo, high=hi, description=description)


def discrete(name: str, path: str, levels: list[Any], where: str, description: str = "",
             labels: list[str] | None = None) -> Factor:
    """A factor taking the listed levels (quantities with units), in their order."""
    if not levels:
        raise ModelError([Problem(f"{where}.levels", "must list at least one level")])
    kind, values = quantity_kind(list(levels), f"{where}.levels")
    if len(set(values)) != len(values):
        raise ModelError([Problem(f"{where}.levels", f"must not repeat a level, got {format_value(list(levels))}")])
    shown = labels or [raw if isinstance(raw, str) else repr(raw) for raw in levels]
    return Factor(name, path, kind.name, levels=tuple(values), labels=tuple(str(s) for s in shown),
                  description=description)
