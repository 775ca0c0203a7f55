"""Simulation results: named channels over time, in SI units.

``results["slider.ax"]`` is a numpy array; ``results.to_xarray()`` is a
Dataset with time as coordinate, one variable per channel, units and
descriptions as attributes, and the model and integrator statistics as
Dataset attributes. ``results.save(path)`` writes it to NetCDF.
"""

from __future__ import annotations

import difflib
import json
from typing import Any

import numpy as np


class Results:
    """Channels recorded by a simulation (possibly cut short by an error)."""

    def __init__(self, time: np.ndarray, names: list[str], units: list[str], descriptions: list[str],
                 values: np.ndarray, statistics: dict, diagnostics: dict, spec: dict | None = None,
                 options: dict | None = None, wall_time: float = float("nan"), error: dict | None = None):
        self.time = np.asarray(time, dtype=float)
        self._names = list(names)
        self._index = {n: k for k, n in enumerate(self._names)}
        self._units = list(units)
        self._descriptions = list(descriptions)
        self._values = np.asarray(values, dtype=float).reshape(len(self._names), self.time.size)
        self.statistics = dict(statistics)
        self.diagnostics = dict(diagnostics)
        self.spec = spec
        self.options = dict(options or {})
        self.wall_time = wall_time
        self.error = error

    @classmethod
    def from_core(cls, raw: dict, spec: dict | None, options: dict | None, wall_time: float) -> Results:
        """Results from the dictionary the core returns."""
        return cls(raw["time"], raw["names"], raw["units"], raw["descriptions"], raw["values"],
                   raw["statistics"], raw["diagnostics"], spec=spec, options=options, wall_time=wall_time,
                   error=raw["error"])

    # access ----------------------------------------------------------------

    @property
    def channels(self) -> list[str]:
        """Channel names, ``"<element>.<quantity>"``."""
        return list(self._names)

    def __contains__(self, name: str) -> bool:
        return name in self._index

    def __getitem__(self, name: str) -> np.ndarray:
        if name == "time":
            return self.time
        try:
            return self._values[self._index[name]]
        except KeyError:
            close = difflib.get_close_matches(name, self._names, n=3)
            hint = f"; did you mean {', '.join(close)}?" if close else ""
            raise KeyError(f"no channel {name!r}{hint}") from None

    def unit(self, name: str) -> str:
        """SI unit of a channel."""
        return self._units[self._index[name]]

    def description(self, name: str) -> str:
        """One-line description of a channel."""
        return self._descriptions[self._index[name]]

    def __len__(self) -> int:
        return self.time.size

    def __repr__(self) -> str:
        end = f"{self.time[-1]:.6g} s" if self.time.size else "nothing"
        status = "complete" if self.error is None else f"stopped early: {self.error.get('message')}"
        return f"<Results {len(self._names)} channels, {self.time.size} samples up to {end}, {status}>"

    # export ----------------------------------------------------------------

    def to_xarray(self):
        """An ``xarray.Dataset``: time coordinate, one variable per channel with ``units`` and
        ``description`` attributes; the model (JSON), options and statistics as attributes."""
        import xarray as xr

        data_vars = {
            name: ("time", self._values[k], {"units": self._units[k], "description": self._descriptions[k]})
            for k, name in enumerate(self._names)
        }
        attrs: dict[str, Any] = {
            "title": f"jointplay results: {self.spec.get('name', '') if self.spec else ''}".strip(),
            "model_json": json.dumps(self.spec) if self.spec is not None else "",
            "options_json": json.dumps(self.options),
            "wall_time_s": float(self.wall_time),
            "completed": int(self.error is None),
        }
        if self.error is not None:
            attrs["error"] = str(self.error.get("message", ""))
        for key, value in self.statistics.items():
            attrs[f"statistics_{key}"] = value
        for key, value in self.diagnostics.items():
            attrs[f"diagnostics_{key}"] = np.asarray(value) if isinstance(value, list) else value
        coords = {"time": ("time", self.time, {"units": "s", "description": "time"})}
        return xr.Dataset(data_vars, coords=coords, attrs=attrs)

    def save(self, path) -> None:
        """Writes the Dataset to a NetCDF file (h5netcdf engine)."""
        self.to_xarray().to_netcdf(path, engine="h5netcdf")

    # summary ---------------------------------------------------------------

    def summary(self) -> dict:
        """Headline numbers: peaks of accelerations, reaction and contact forces, impacts,
        contact fraction per clearance joint, integrator statistics and wall time."""
        out: dict[str, Any] = {"t_end": float(self.time[-1]) if self.time.size else 0.0,
                               "samples": int(self.time.size), "completed": self.error is None}
        peaks = {}
        for name in self._names:
            element, quantity = name.rsplit(".", 1)
            if quantity in ("ax", "ay", "alpha", "f", "fn", "torque", "force") and self.time.size:
                peaks[name] = float(np.max(np.abs(self[name])))
        out["peaks"] = peaks
        contact = {}
        impacts = self.diagnostics.get("impacts", [])
        clearance = [n.rsplit(".", 1)[0] for n in self._names if n.endswith(".contact")]
        for k, element in enumerate(clearance):
            flag = self[f"{element}.contact"]
            contact[element] = {
                "impacts": int(impacts[k]) if k < len(impacts) else None,
                "contact_fraction": contact_fraction(self.time, flag),
                "max_penetration": float(np.max(self[f"{element}.penetration"])) if self.time.size else 0.0,
            }
        out["clearance_joints"] = contact
        out["statistics"] = dict(self.statistics)
        out["wall_time"] = self.wall_time
        return out


def contact_fraction(time: np.ndarray, flag: np.ndarray) -> float:
    """Fraction of the time span during which ``flag`` is 1, each sample holding until the next."""
    if time.size < 2:
        return float(flag[0]) if flag.size else 0.0
    dt = np.diff(time)
    return float(np.sum(dt * (flag[:-1] > 0.5)) / (time[-1] - time[0]))
