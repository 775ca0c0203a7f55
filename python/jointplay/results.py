"""Simulation results: named channels over time, in SI units.

``results["slider.ax"]`` is a numpy array; ``results.to_xarray()`` is a
Dataset with time as coordinate, one variable per channel, units and
descriptions as attributes, and the model and integrator statistics as
Dataset attributes. ``results.save(path)`` writes it to NetCDF (classic, or NetCDF-4 compressed; or CSV);
results of a run streamed to a file read their channels from it on access
(see :mod:`jointplay.resultsfile`).
"""

from __future__ import annotations

import difflib
import json
import shlex
import sys
from datetime import datetime, timezone
from pathlib import Path
from typing import Any

import numpy as np


class Results:
    """Channels recorded by a simulation (possibly cut short by an error).

    ``extrema`` holds the summary quantities the core tracked at *every accepted step*, whatever
    the output sampling, with peaks inside a step found on the dense output (a JSON-serialisable
    dict; ``None`` for results files written before it existed)::

        {"steps": 1832,                      # accepted steps observed
         "inner_evaluations": 412,           # evaluations inside steps to find peaks there
         "fallback_searches": 0,             # peaks searched one channel at a time (a kink inside a step)
         "t_start": 0.0, "t_end": 0.024,     # [s]
         "point_accelerations": {            # |acceleration| of every named point of a moving body
             "slider.B": {"peak": 3.27e5, "time": 0.00025, "unit": "m/s^2"}, ...},
         "channels": {                       # every channel in N, N m, m/s^2, rad/s^2 or Pa
             "B.fn": {"peak": 45886.5,       # largest |value| [unit]
                      "value": 45886.5,      # the signed value there
                      "time": 0.000251,      # [s]
                      "unit": "N"}, ...},
         "clearance_joints": {
             "B": {"impacts": 43, "contact_time": 0.01516, "contact_fraction": 0.632,
                   "max_penetration": 7.80e-05, "max_penetration_time": 0.000253,  # None if never in contact
                   "max_eccentricity_ratio": 1.156,
                   # lubricated joints also:
                   "min_film": 1.2e-06, "min_film_time": 0.0093,
                   "peak_film_pressure": 3.1e8, "peak_film_pressure_time": 0.0093}}}

    Contact is penetration > 0; a separation inside a step is located on the dense output.
    """

    def __init__(self, time: np.ndarray, names: list[str], units: list[str], descriptions: list[str],
                 values: np.ndarray, statistics: dict, diagnostics: dict, spec: dict | None = None,
                 options: dict | None = None, wall_time: float = float("nan"), error: dict | None = None,
                 extrema: dict | None = None):
        self.time = np.asarray(time, dtype=float)
        self._names = list(names)
        self._index = {n: k for k, n in enumerate(self._names)}
        self._units = list(units)
        self._descriptions = list(descriptions)
        # channels x samples in memory, or a store reading them from a file (``FileChannels``)
        self._values = values if hasattr(values, "block") else np.asarray(values, dtype=float).reshape(
            len(self._names), self.time.size)
        self.statistics = dict(statistics)
        self.diagnostics = dict(diagnostics)
        self.spec = spec
        self.options = dict(options or {})
        self.wall_time = wall_time
        self.error = error
        self.extrema = extrema
        #: ``[model] description`` of the model file, its path, and the file's ``history`` line(s).
        self.description = ""
        self.model_file = ""
        self.history = ""
        #: The results file the channels are read from, or None when they are in memory.
        self.path: Path | None = None
        #: What a drawing of the mechanism needs beyond the model and the channels (saved as ``geometry_json``):
        #: ``{"modal_bodies": {name: {"nodes", "shapes", "edges"}}}``, each modal body's reference nodes in its
        #: frame [m], their translations per unit amplitude of each mode in the frame [m per unit] and the
        #: mesh's lines (node pairs). A node is drawn at ``r + A(angle) (node + shapes @ eta)``.
        self.geometry: dict = {"modal_bodies": {}}

    @classmethod
    def from_core(cls, raw: dict, spec: dict | None, options: dict | None, wall_time: float) -> Results:
        """Results from the dictionary the core returns."""
        # the core records sample after sample, (samples, channels): its transpose is a view
        return cls(raw["time"], raw["names"], raw["units"], raw["descriptions"], np.asarray(raw["values"]).T,
                   raw["statistics"], raw["diagnostics"], spec=spec, options=options, wall_time=wall_time,
                   error=raw["error"], extrema=raw.get("extrema"))

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

    def channel_block(self, start: int, stop: int) -> np.ndarray:
        """Values of every channel for samples ``start:stop``, shape (channels, samples)."""
        if hasattr(self._values, "block"):
            return self._values.block(start, stop)
        return self._values[:, start:stop]

    def read_from(self, path) -> None:
        """Reads the channels from the results file ``path`` on access from now on (its time and
        channels are those of these results)."""
        from .resultsfile import FileChannels

        self._values = FileChannels(path, self._names)
        self.path = Path(path)

    def get(self, name: str, default=None):
        """The channel's values, or ``default`` when the results have no such channel."""
        return self[name] if name in self._index else default

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
        """An ``xarray.Dataset``: time coordinate, one variable per channel with ``units``, ``long_name``
        and ``description`` attributes; the model (JSON), options and statistics as attributes. (For results
        read from a file, this reads every channel into memory.)"""
        import xarray as xr

        data_vars = {
            name: ("time", self._values[k], {"units": self._units[k], "long_name": self._descriptions[k] or name,
                                             "description": self._descriptions[k]})
            for k, name in enumerate(self._names)
        }
        attrs = {key: value for key, value in self.file_attributes().items() if key != "jointplay_layout"}
        coords = {"time": ("time", self.time, {"units": "s", "long_name": "time", "description": "time"})}
        return xr.Dataset(data_vars, coords=coords, attrs=attrs)

    def file_attributes(self) -> dict[str, Any]:
        """Global attributes of a results file: CF-style ``Conventions``, ``title``, ``history``,
        ``source``, ``date_created``; the model (JSON and TOML), its file and description, the options,
        statistics, diagnostics, ``completed``/``error`` and ``extrema_json``."""
        from . import __version__
        from .resultsfile import LAYOUT

        name = self.spec.get("name", "") if self.spec else ""
        created = datetime.now(timezone.utc).isoformat(timespec="seconds").replace("+00:00", "Z")
        line = f"{created} {shlex.join([Path(sys.argv[0]).name, *sys.argv[1:]])}"
        history = f"{self.history}\n{line}" if self.history else line  # CF: one line per program that wrote it
        attrs: dict[str, Any] = {
            "Conventions": "CF-1.10",
            "title": f"jointplay results: {name}".strip(),
            "history": history,
            "source": f"jointplay {__version__}",
            "jointplay_version": __version__,
            "jointplay_layout": LAYOUT,
            "date_created": created,
            "model_file": self.model_file,
            "description": self.description,
            "model_json": json.dumps(self.spec) if self.spec is not None else "",
            "model_toml": self.model_toml(),
            "geometry_json": json.dumps(self.geometry),
            "options_json": json.dumps(self.options),
            "wall_time_s": float(self.wall_time),
            "completed": int(self.error is None),
        }
        if self.extrema is not None:
            attrs["extrema_json"] = json.dumps(self.extrema)
        if self.error is not None:
            attrs["error"] = str(self.error.get("message", ""))
            attrs["error_json"] = json.dumps(self.error, default=str)
        for key, value in self.statistics.items():
            attrs[f"statistics_{key}"] = value
        for key, value in self.diagnostics.items():
            attrs[f"diagnostics_{key}"] = np.asarray(value) if isinstance(value, list) else value
        return attrs

    def save(self, path, *, compress: bool = False) -> Path:
        """Writes the results to ``path``: NetCDF for ``.nc``, ``.nc4``, ``.h5`` (read back by
        :func:`open_results`), CSV for ``.csv`` (``time`` and one column per channel, header
        ``name [unit]``); a ModelError (a ValueError) located at ``path`` for any other suffix or a folder
        that does not exist. NetCDF is the classic 64-bit offset format (CDF-2), channels uncompressed, or
        with ``compress`` NetCDF-4 with each channel gzip-compressed after the shuffle filter (smaller,
        several times slower to write; docs/results-file.md). The file is
        written under a temporary name and renamed into place when complete, so a good file at ``path`` is
        never left broken."""
        from .resultsfile import output_target, save_netcdf, write_csv

        if output_target(path) == "csv":
            return write_csv(self, path)
        return save_netcdf(path, self.time, self._names, self._units, self._descriptions, self.channel_block,
                           self.file_attributes(), compress=compress)

    def report(self, path, **options) -> Path:
        """Writes the report of this run to ``path`` (an ``.html`` file, self-contained: it works offline): the
        model with its parameters in units, the run's options and statistics, its summary, interactive plots
        of the standard channels and the animation of the mechanism. ``options``: those of
        :func:`jointplay.report.write_report` (``title``, ``animation``). Returns the path."""
        from .report import write_report

        return write_report(self, path, **options)

    def animate(self, path, **options) -> Path:
        """Writes an animation of the mechanism to ``path`` (``.mp4``, ``.webm``, ``.gif`` or a ``.png``
        still); ``options`` as :func:`jointplay.animation.animate` takes them."""
        from .animation import animate

        return animate(self, path, **options)

    def model_toml(self) -> str:
        """The simulated model as model-file TOML, with the run's options as its ``[simulation]`` table."""
        if self.spec is None:
            return ""
        simulation = {k: v for k, v in self.options.items() if v is not None}
        if self.error is None and self.time.size:
            simulation = {"t_end": float(self.time[-1]), "t0": float(self.time[0]), **simulation}
        return _with_simulation(self.spec, simulation)

    def point_acceleration(self, point: str) -> tuple[np.ndarray, ...]:
        """Acceleration [m/s^2] of a named body point ``"body.point"``, from the body's centre-of-mass
        acceleration, angular velocity and angular acceleration: a_P = a_G + alpha x r - omega^2 r, its
        components (ax, ay); of a spatial body's point a_P = a_G + R (alpha x r + omega x (omega x r)) with
        omega, alpha and r in the body frame and R the rotation of its quaternion, (ax, ay, az) global."""
        body, _, name = point.partition(".")
        spec = self.spec or {}
        bodies = {b["name"]: b for b in [*spec.get("bodies", []), *spec.get("spatial_bodies", [])]}
        local = next((p["position"] for p in bodies.get(body, {}).get("points", []) if p["name"] == name), None)
        if local is None:
            raise KeyError(f"no body point {point!r} in the model")
        if f"{body}.qw" in self:
            return self._spatial_point_acceleration(body, np.asarray(local, dtype=float))
        angle, omega, alpha = self[f"{body}.angle"], self[f"{body}.omega"], self[f"{body}.alpha"]
        c, s_ = np.cos(angle), np.sin(angle)
        rx, ry = c * local[0] - s_ * local[1], s_ * local[0] + c * local[1]
        ax = self[f"{body}.ax"] - alpha * ry - omega**2 * rx
        ay = self[f"{body}.ay"] + alpha * rx - omega**2 * ry
        return ax, ay

    def _spatial_point_acceleration(self, body: str, local: np.ndarray) -> tuple[np.ndarray, ...]:
        """Global acceleration components [m/s^2] of the point ``local`` [m] (body frame) of spatial ``body``."""
        from scipy.spatial.transform import Rotation

        omega = np.column_stack([self[f"{body}.w{c}"] for c in "xyz"])
        alpha = np.column_stack([self[f"{body}.alpha_{c}"] for c in "xyz"])
        relative = np.cross(alpha, local) + np.cross(omega, np.cross(omega, local))
        quaternion = np.column_stack([self[f"{body}.q{c}"] for c in "xyzw"])  # scipy: scalar last
        rotated = Rotation.from_quat(quaternion).apply(relative) if len(self) else relative
        return tuple(self[f"{body}.a{c}"] + rotated[:, k] for k, c in enumerate("xyz"))

    # summary ---------------------------------------------------------------

    def summary(self) -> dict:
        """Headline numbers: peak |value| of every force, moment, acceleration and pressure channel
        (``peaks``, with their times in ``peak_times``), per clearance joint the impacts, time and
        fraction in contact, deepest penetration and, when lubricated, thinnest film and peak film
        pressure; ``peak_forces`` and ``peak_pressures`` (hydraulic chambers) pick from ``peaks``;
        integrator statistics and wall time.

        These come from :attr:`extrema`, tracked at every accepted step whatever the output step
        (``extrema_source`` is ``"accepted steps"``, ``steps`` their number), as do the peak
        acceleration magnitudes of the named body points (``point_accelerations``, times in
        ``point_acceleration_times``). Results files written before the core tracked them fall back
        to the saved samples (``extrema_source`` ``"samples"``), which miss what happens between
        samples.
        """
        out: dict[str, Any] = {"t_end": float(self.time[-1]) if self.time.size else 0.0,
                               "samples": int(self.time.size), "completed": self.error is None,
                               "output_step": self.options.get("output_step")}
        if self.extrema is not None:
            out.update(self._tracked_summary())
        else:
            out.update(self._sampled_summary())
        points = (self.extrema or {}).get("point_accelerations")
        if points is not None:
            out["point_accelerations"] = {n: float(p["peak"]) for n, p in points.items()}
            out["point_acceleration_times"] = {n: p["time"] for n, p in points.items()}
        else:
            out["point_accelerations"], out["point_acceleration_times"] = self._sampled_point_accelerations()
        out["peak_forces"] = {n: v for n, v in out["peaks"].items() if n.rsplit(".", 1)[1] in FORCE_QUANTITIES}
        out["peak_pressures"] = {n: v for n, v in out["peaks"].items() if n.rsplit(".", 1)[1] in PRESSURE_QUANTITIES}
        out["error"] = None if self.error is None else dict(self.error)
        out["statistics"] = dict(self.statistics)
        out["wall_time"] = self.wall_time
        return out

    def _tracked_summary(self) -> dict:
        """Peaks and clearance-joint statistics from :attr:`extrema`."""
        channels = self.extrema.get("channels", {})
        joints = {}
        for name, j in self.extrema.get("clearance_joints", {}).items():
            joints[name] = {key: j[key] for key in JOINT_KEYS if key in j}
        return {"extrema_source": "accepted steps", "steps": int(self.extrema.get("steps", 0)),
                "peaks": {n: float(c["peak"]) for n, c in channels.items()},
                "peak_times": {n: c["time"] for n, c in channels.items()},
                "clearance_joints": joints}

    def _sampled_point_accelerations(self) -> tuple[dict, dict]:
        """Peak acceleration magnitude of every named body point and its time, from the samples."""
        peaks, times = {}, {}
        spec = self.spec or {}
        for body in [*spec.get("bodies", []), *spec.get("spatial_bodies", [])] if self.time.size else []:
            for p in body.get("points", []):
                name = f"{body['name']}.{p['name']}"
                try:
                    components = self.point_acceleration(name)
                except KeyError:
                    continue
                magnitude = np.linalg.norm(np.vstack(components), axis=0)
                k = int(np.argmax(magnitude))
                peaks[name], times[name] = float(magnitude[k]), float(self.time[k])
        return peaks, times

    def _sampled_summary(self) -> dict:
        """Peaks and clearance-joint statistics from the saved samples (results files written before
        the core tracked them at every step)."""
        peaks = {}
        times = {}
        for name, unit in zip(self._names, self._units):
            if unit in PEAK_UNITS and self.time.size:
                k = int(np.argmax(np.abs(self[name])))
                peaks[name], times[name] = float(abs(self[name][k])), float(self.time[k])
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
            if f"{element}.film_min" in self._index and self.time.size:
                contact[element]["min_film"] = float(np.min(self[f"{element}.film_min"]))
                contact[element]["peak_film_pressure"] = float(np.max(self[f"{element}.peak_pressure"]))
        return {"extrema_source": "samples", "steps": None, "peaks": peaks, "peak_times": times,
                "clearance_joints": contact}


#: Units of the channels whose peak the summary reports (the core tracks the same).
PEAK_UNITS = ("N", "N m", "m/s^2", "rad/s^2", "Pa")
#: Quantities listed as forces (and torques) in the summary's ``peak_forces``.
FORCE_QUANTITIES = ("f", "fn", "force", "torque")
#: Quantities listed as chamber pressures in the summary's ``peak_pressures`` (a film's peak
#: pressure is reported with its clearance joint).
PRESSURE_QUANTITIES = ("p_cap", "p_rod")
#: What the summary reports per clearance joint from :attr:`Results.extrema`.
JOINT_KEYS = ("impacts", "contact_time", "contact_fraction", "max_penetration", "max_penetration_time",
              "max_eccentricity_ratio",
              "min_film", "min_film_time", "peak_film_pressure", "peak_film_pressure_time", "mode_fractions")


def contact_fraction(time: np.ndarray, flag: np.ndarray) -> float:
    """Fraction of the time span during which ``flag`` is 1, each sample holding until the next."""
    if time.size < 2:
        return float(flag[0]) if flag.size else 0.0
    dt = np.diff(time)
    return float(np.sum(dt * (flag[:-1] > 0.5)) / (time[-1] - time[0]))


def _with_simulation(spec: dict, simulation: dict) -> str:
    from .modelfile.writer import to_toml

    keep = ("t_end", "t0", "method", "rtol", "atol", "max_step", "output_step", "initial_step", "min_step",
            "max_steps", "max_order", "step", "spectral_radius", "jacobian", "stabilization", "formulation",
            "max_output_bytes")
    return to_toml(spec, {k: simulation[k] for k in keep if k in simulation})


def _attr_dict(attrs: dict, prefix: str) -> dict:
    out = {}
    for key, value in attrs.items():
        if key.startswith(prefix):
            if isinstance(value, np.ndarray):
                value = value.tolist()
            elif isinstance(value, np.generic):
                value = value.item()
            out[key[len(prefix):]] = value
    return out


def open_results(path) -> Results:
    """Results from a file written by :meth:`Results.save`, ``Model.simulate(output_file=...)`` or
    ``jointplay run`` (NetCDF classic or NetCDF-4, told apart by their first bytes); the channels of a file
    in a layout jointplay writes are read on access. Files written
    by earlier versions (through xarray) are read whole. A path that is not such a file (missing, a
    folder, a model file, an HDF5 file of another program) or a file declaring more values than
    :data:`~jointplay.resultsfile.DEFAULT_MAX_MEMORY_BYTES` holds raises ModelError located at ``path``."""
    from .errors import ModelError
    from .resultsfile import FileChannels, is_streamed_layout, read_file, results_source

    source = results_source(path)
    try:
        if not is_streamed_layout(source):
            return _open_legacy(source)
        time, names, units, descriptions, attrs = read_file(source)
        results = _from_attributes(time, names, units, descriptions, FileChannels(source, names), attrs)
    except ModelError:
        raise
    except (OSError, KeyError, ValueError, TypeError) as exc:  # an HDF5 file, but not one jointplay wrote
        what = str(exc.args[0]) if isinstance(exc, KeyError) and exc.args else f"{exc}"
        raise ModelError([(str(path), f"is not a jointplay results file ({what})")]) from None
    results.path = Path(path)
    return results


def _open_legacy(path) -> Results:
    """Results from a NetCDF file written through xarray/h5netcdf (before the streamed layout), or another
    program's NetCDF file of the same variables."""
    import xarray as xr

    from .netcdf_classic import is_classic
    from .resultsfile import check_declared

    with xr.open_dataset(path, engine="scipy" if is_classic(path) else "h5netcdf") as ds:
        check_declared(path, "the file", (max(1, ds.nbytes // 8),))
        ds.load()
        names = [str(n) for n in ds.data_vars]
        attrs = {key: (value.tolist() if isinstance(value, np.ndarray) else value) for key, value in ds.attrs.items()}
        time = np.asarray(ds["time"].values, dtype=float)
        values = np.array([np.asarray(ds[n].values, dtype=float) for n in names]).reshape(len(names), time.size)
        units = [str(ds[n].attrs.get("units", "")) for n in names]
        descriptions = [str(ds[n].attrs.get("description", "")) for n in names]
    return _from_attributes(time, names, units, descriptions, values, attrs)


def _from_attributes(time, names, units, descriptions, values, attrs: dict) -> Results:
    """Results from channels and the global attributes of a results file."""
    spec = json.loads(attrs["model_json"]) if attrs.get("model_json") else None
    options = json.loads(attrs.get("options_json", "{}") or "{}")
    diagnostics = _attr_dict(attrs, "diagnostics_")
    if "impacts" in diagnostics and not isinstance(diagnostics["impacts"], list):
        diagnostics["impacts"] = [diagnostics["impacts"]]
    error = None
    if not int(attrs.get("completed", 1)):
        error = json.loads(attrs["error_json"]) if attrs.get("error_json") else {"message": attrs.get("error", "")}
    extrema = json.loads(attrs["extrema_json"]) if attrs.get("extrema_json") else None
    results = Results(time, names, units, descriptions, values, _attr_dict(attrs, "statistics_"), diagnostics,
                      spec=spec, options=options, wall_time=float(attrs.get("wall_time_s", float("nan"))), error=error,
                      extrema=extrema)
    results.description = str(attrs.get("description", ""))
    results.model_file = str(attrs.get("model_file", ""))
    results.history = str(attrs.get("history", ""))
    if attrs.get("geometry_json"):
        results.geometry = json.loads(attrs["geometry_json"])
    return results
