"""The ``jointplay`` command: check, run, plot and compare mechanism models.

Exit codes: 0 success; 2 bad input (a model-file problem, a missing file,
a bad option); 1 a simulation that stopped early (what was computed is
still saved). Expected errors print a message, never a traceback.
"""

from __future__ import annotations

import math
import warnings
from contextlib import contextmanager
from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.table import Table

from . import __version__
from .display import format_time, print_table, table, time_unit
from .errors import JointplayWarning, ModelError, SimulationError

EXIT_OK, EXIT_FAILED, EXIT_BAD_INPUT = 0, 1, 2

HELP = """Simulate planar and spatial mechanisms with imperfect joints (clearance, contact-impact, friction,
lubrication).

A mechanism is described in a TOML model file with units ("0.5 mm", "5000 rpm");
see docs/model-files.md and the examples/ folder. A typical session:

\b
    jointplay check examples/flores_slider_crank_dry.toml
    jointplay run examples/flores_slider_crank_dry.toml -o dry.nc
    jointplay plot dry.nc -o figures
    jointplay run examples/flores_slider_crank_dry.toml -o small.nc --set joints.B.clearance="0.1 mm"
    jointplay compare dry.nc small.nc -o comparison
    jointplay animate dry.nc -o dry.mp4
    jointplay report dry.nc small.nc -o comparison.html

Exit codes: 0 success, 2 bad input (model file, missing file, bad option),
1 simulation failure (the results computed so far are still saved)."""

app = typer.Typer(name="jointplay", help=HELP, no_args_is_help=True, add_completion=False,
                  pretty_exceptions_show_locals=False, rich_markup_mode=None)
out = Console(highlight=False)
err = Console(stderr=True, highlight=False, soft_wrap=True)

SetOption = Annotated[list[str], typer.Option(
    "--set", metavar="PATH=VALUE",
    help='Override a value of the model file by its dotted path, e.g. --set joints.B.clearance="0.1 mm" '
         "(repeatable; validated like the file).")]


def _version(value: bool) -> None:
    if value:
        out.print(f"jointplay {__version__}")
        raise typer.Exit(EXIT_OK)


@app.callback()
def _main(version: Annotated[bool, typer.Option("--version", callback=_version, is_eager=True,
                                                help="Print the version and exit.")] = False) -> None:
    """Simulate planar mechanisms with imperfect joints."""


# helpers ---------------------------------------------------------------------

def _bad_input(title: str, problems) -> typer.Exit:
    err.print(f"[bold red]error:[/] {title}")
    for p in problems:
        err.print(f"  {p}", markup=False)
    return typer.Exit(EXIT_BAD_INPUT)


def _load(model: Path, overrides: list[str], check: bool = True):
    from .modelfile import load

    try:
        return load(model, overrides, check=check)
    except ModelError as exc:
        n = len(exc.problems)
        raise _bad_input(f"{model}: {n} problem{'s' if n != 1 else ''}", exc.problems) from None


def _open(path: Path):
    from .results import open_results

    if path.is_dir():
        raise _bad_input(f"{path}: is a folder, not a results file", [])
    if not path.is_file():
        raise _bad_input(f"{path}: no such results file", [])
    try:
        return open_results(path)
    except ModelError as exc:  # located at the path: not a results file, or declaring more than memory holds
        raise _bad_input(str(exc), []) from None
    except Exception as exc:  # h5py / xarray raise many types for a file that is not ours
        raise _bad_input(f"{path}: not a jointplay results file ({type(exc).__name__}: {exc})", []) from None


def _figure_folder(option: str, folder: Path) -> Path:
    """``folder`` created if needed; exit 2 when it is a file or cannot be created or written."""
    import os

    if folder.exists() and not folder.is_dir():
        raise _bad_input(f"{option} {folder}: is a file, not a folder (figures are written into a folder)", [])
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise _bad_input(f"{option} {folder}: cannot create the folder ({exc.strerror or exc})", []) from None
    if not os.access(folder, os.W_OK | os.X_OK):
        raise _bad_input(f"{option} {folder}: cannot write into the folder (permission denied)", [])
    return folder


def _crank_check(crank: str | None, runs: list, paths: list[Path]) -> None:
    """Exit 2 unless every run recorded the angle of body ``crank``."""
    if crank is None:
        return
    for run, path in zip(runs, paths):
        if f"{crank}.angle" not in run and f"{crank}.qw" in run:
            raise _bad_input(f"--crank: {crank!r} in {path} is a spatial body; the crank angle is the angle of a "
                             "planar body (a spatial body's orientation is in its Euler-angle channels "
                             f"{crank}.euler_*)", [])
        if f"{crank}.angle" not in run:
            bodies = sorted(n[: -len(".angle")] for n in run.channels if n.endswith(".angle"))
            raise _bad_input(f"--crank: no body {crank!r} in {path} (bodies: {', '.join(bodies) or 'none'})", [])


def _time_option(text: str | None, option: str) -> float | None:
    if text is None:
        return None
    from .units import UnitError, to_si

    try:
        value = to_si(text, "time")
    except UnitError as exc:
        raise _bad_input(f"{option}: {exc}", []) from None
    if not value > 0:
        raise _bad_input(f"{option}: must be > 0, got {text}", [])
    return value


def _warning(message: str) -> None:
    """``warning: joints.B.clearance: ...`` on stderr; the message is printed as it is (no markup)."""
    err.print("[yellow]warning:[/] ", end="")
    err.print(message, markup=False)


@contextmanager
def _printed_warnings():
    """JointplayWarnings raised inside (plausibility, soft contact...) printed as ``warning: ...``."""
    with warnings.catch_warnings():
        warnings.simplefilter("always", JointplayWarning)
        shown = warnings.showwarning

        def show(message, category, *args, **kwargs):
            if issubclass(category, JointplayWarning):
                _warning(str(message))
            else:
                shown(message, category, *args, **kwargs)

        warnings.showwarning = show
        yield


def _count(n: int) -> str:
    """``1612`` -> ``1 612``."""
    return f"{int(n):,}".replace(",", " ")


def _summary_title(name: str, s: dict) -> str:
    """``flores: 25 samples saved (output step 1 ms) up to 24 ms; peaks and extrema from all 1 832 accepted
    steps``; times in the units that fit them."""
    step = s.get("output_step")
    saved = f"{_count(s['samples'])} samples saved " + (f"(output step {format_time(step)})" if step
                                                         else "(a sample every accepted step)")
    if s["extrema_source"] == "accepted steps":
        source = f"peaks and extrema from all {_count(s['steps'])} accepted steps"
    else:
        source = "peaks and extrema from the saved samples (results file written before they were tracked at every step)"
    end = f" up to {format_time(s['t_end'])}"
    return f"{name + ': ' if name else ''}{saved}{end}; {source}"


def _words(kind: str) -> str:
    """``RevoluteJoint`` -> ``revolute joint``."""
    return "".join(f" {c.lower()}" if c.isupper() else c for c in kind).strip()


def _fmt(value: float, unit: str = "") -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    return f"{value:.4g} {unit}".strip()


# check -----------------------------------------------------------------------

def _beam_table(spec: dict, described: dict, frequencies: dict) -> Table:
    """Each beam's mesh and its lowest natural frequencies, unstressed (free-free, and clamped at its start)."""
    t = table("beam", "length", "mass", "elements", "nodes", "free-free (Hz)", "clamped at start (Hz)",
              title="flexible links: mesh and lowest bending frequencies, unstressed")
    for b in spec["beams"]:
        d = described[b["name"]]
        modes = frequencies.get(b["name"])
        free, clamped = (("-", "-") if modes is None else
                         (", ".join(f"{f:.4g}" for f in modes["free_free"]),
                          ", ".join(f"{f:.4g}" for f in modes["clamped"])))
        t.add_row(b["name"], _fmt(d["length"], "m"), _fmt(d["mass"], "kg"), f"{d['elements']} {d['order']}",
                  str(d["nodes"]), free, clamped)
    return t


def _modal_table(spec: dict, described: dict) -> Table:
    """Each modal body's reduction and the lowest frequencies of the reduced body held at its frame's reference
    conditions; the first is the spin above which a linear modal body diverges."""
    t = table("modal body", "from", "mass", "nodes", "interface", "frame", "modes", "damping", "held (Hz)",
              title="modal bodies: Craig-Bampton reduction; lowest frequencies held at the frame's reference "
                    "conditions (the first: the spin limit)")
    for b in spec["modal_bodies"]:
        d = described[b["name"]]
        lowest = ", ".join(f"{f:.4g}" for f in d["held_frequencies"][:3])
        t.add_row(b["name"], b["structure"]["from"], _fmt(d["mass"], "kg"), str(d["nodes"]),
                  ", ".join(node["name"] for node in b["interface"]), d["frame"], str(d["modes"]),
                  f"{d['damping_ratio']:g}", lowest)
    return t


def _acts_on(force: dict) -> str:
    """``ground.C -> boom.R``: the points and bodies a force element refers to, from its definition."""
    from . import parameters as p

    ends = [param.key for param in p.FORCES[force["type"]].params if param.kind in ("point", "body")]
    return " -> ".join(force[key] for key in ends)


def _force_details(force: dict) -> str:
    """The main parameters of a force element, in the units one reads them in."""
    kind = force["type"]
    if kind == "spring_damper":
        return f"k {_fmt(force['stiffness'], 'N/m')}, c {_fmt(force['damping'], 'N s/m')}"
    if kind == "rotational_spring_damper":
        return f"k {_fmt(force['stiffness'], 'N m/rad')}, c {_fmt(force['damping'], 'N m s/rad')}"
    if kind != "hydraulic_cylinder":
        return ""
    inflows = [side for side in ("cap", "rod") if force[f"{side}_inflow"] is not None]
    return (f"A1 {force['piston_area'] * 1e4:.4g} cm^2, A2 {force['rod_side_area'] * 1e4:.4g} cm^2, "
            f"stroke {force['initial_stroke'] * 1e3:.4g} of {force['stroke_length'] * 1e3:.4g} mm, "
            f"{force['cap_pressure'] / 1e5:.4g} / {force['rod_pressure'] / 1e5:.4g} bar, "
            f"{'LuGre seal' if force['seal_friction'] else 'no seal friction'}, "
            + (f"{' and '.join(inflows)} inflow" if inflows else "closed chambers"))


@app.command()
def check(model: Annotated[Path, typer.Argument(help="Model file (TOML).", show_default=False)],
          set_: SetOption = []) -> None:  # noqa: B006 (typer reads the default)
    """Validate a model file and print the assembled mechanism.

    Prints the bodies with their assembled initial position, the joints, the
    clearance joints, drivers and force elements, and the degrees of freedom
    (of a spatial model also by the Grübler-Kutzbach count, and the redundant
    equations with the elements they belong to).
    Exits with 2 and one line per problem when the file is not valid.
    """
    from .modelfile import assembly_error

    m = _load(model, set_, check=False)
    spec = m.to_spec()
    # the plausibility warnings first, whatever the assembly then finds; then the assembly's notes
    try:
        with _printed_warnings():
            info = m.check()
    except SimulationError as exc:
        problems = [p for p in assembly_error(exc, spec).problems if not p.message.startswith("(plausibility")]
        raise _bad_input(f"{model}: the initial configuration cannot be assembled", problems) from None
    q0 = info["initial_coordinates"]
    out.print(f"[bold]{spec['name']}[/]  ({model})")
    if m.kinematics == "spatial":
        _check_spatial(info, spec)
        return
    bodies = table("body", "mass", "inertia", "x (mm)", "y (mm)", "angle (deg)", title="bodies, assembled at t0")
    described = {b["name"]: b for b in info["bodies"]}
    for b in spec["bodies"]:
        first, _ = described[b["name"]]["coordinates"]
        x, y, phi = q0[first: first + 3]
        bodies.add_row(b["name"], _fmt(b["mass"], "kg"), _fmt(b["inertia"], "kg m^2"),
                       f"{x * 1e3:.3f}", f"{y * 1e3:.3f}", f"{math.degrees(phi):.3f}")
    if spec["bodies"]:
        print_table(out, bodies)
    if spec.get("beams"):
        print_table(out, _beam_table(spec, described, info["beam_frequencies"]))
    if spec.get("modal_bodies"):
        print_table(out, _modal_table(spec, described))
    joints = table("joint or driver", "kind", "first body", "second body", "equations", title="constraints")
    for e in info["elements"]:
        if e["kind"] != "AssemblyLock":  # clearance joints are held only while assembling
            joints.add_row(e["name"], _words(e["kind"]), e["first"], e["second"], str(e["equations"]))
    print_table(out, joints)
    clearance = [j for j in spec["joints"] if j["type"] == "clearance_revolute"]
    if clearance:
        t = table("clearance joint", "bearing", "journal", "bore radius", "clearance", "contact", "friction",
                  title="clearance joints")
        for j in clearance:
            t.add_row(j["name"], j["bearing"], j["journal"], f"{j['bearing_radius'] * 1e3:g} mm",
                      f"{j['clearance'] * 1e3:g} mm", j["contact"]["law"], j["friction"]["law"])
        print_table(out, t)
    if spec["forces"]:
        t = table("force element", "type", "acts on", "details", title="force elements")
        for f in spec["forces"]:
            t.add_row(f["name"], f["type"], _acts_on(f), _force_details(f))
        print_table(out, t)
    dof = info["degrees_of_freedom"]
    elastic = sum(b["coordinates"][1] - 3 for b in info["bodies"] if b["kind"] in ("beam", "modal"))
    flexible = {"beam": "beams", "modal": "modal bodies"}
    kinds = {flexible[b["kind"]] for b in info["bodies"] if b["kind"] in flexible}
    flexible_text = kinds.pop() if len(kinds) == 1 else "flexible bodies"
    free = dof - 2 * len(clearance) - elastic
    states = info.get("n_element_states", 0)
    out.print(f"coordinates {info['n_coordinates']}, "
              + (f"element states {states}, " if states else "")
              + f"constraint equations {info['n_equations']}, "
              f"degrees of freedom {dof} ({2 * len(clearance)} from {len(clearance)} clearance joint(s), "
              + (f"{elastic} elastic of the {flexible_text}, " if elastic else "") + f"{free} not driven)")
    if info["formulation"] == "joint_coordinates":
        out.print(f"formulation (auto): joint coordinates, {info['joint_coordinates']} of them, because "
                  f"{info['formulation_reason']}")
    else:
        out.print(f"formulation (auto): absolute coordinates with constraints, because {info['formulation_reason']}")
    _notes(info, free)
    out.print("[green]ok[/]")


def _check_spatial(info: dict, spec: dict) -> None:
    """The spatial part of ``check``: bodies with their inertia tensors and orientations, joints by kind, force
    elements, degrees of freedom by rank beside the Grübler-Kutzbach count, and the redundant equations."""
    from . import check_spatial as cs

    print_table(out, cs.bodies_table(info["bodies"], info["initial_coordinates"]))
    joints = table("joint or driver", "kind", "first body", "second body", "equations", title="constraints")
    for e in info["elements"]:
        joints.add_row(e["name"], cs.kind_words(e["kind"]), e["first"], e["second"], str(e["equations"]))
    print_table(out, joints)
    if spec.get("spatial_forces"):
        t = table("force element", "type", "acts on", title="force elements")
        for f in spec["spatial_forces"]:
            t.add_row(f["name"], f["type"], " -> ".join(f[key] for key in ("first", "second", "point", "body")
                                                        if key in f))
        print_table(out, t)
    out.print(cs.freedoms_line(info))
    out.print("formulation (auto): absolute coordinates with constraints, because "
              f"{info.get('absolute_because') or info['formulation_reason']}")
    _notes(info)
    note = cs.count_note(info)
    if note:
        out.print("[yellow]note:[/] ", end="")
        out.print(note, markup=False)
    out.print("[green]ok[/]")


def _notes(info: dict, free: int = 0) -> None:
    """The notes of ``check``: redundant constraint equations and the elements they belong to; freedoms that
    nothing drives."""
    if info.get("redundant_equations"):
        out.print(f"[yellow]note:[/] {info['redundant_equations']} constraint equation(s) are redundant (dependent on "
                  f"the others; elements involved: {', '.join(info['dependent_elements'])}). The motion is "
                  "determined; the reactions along the dependent directions are not, and jointplay reports "
                  "the least-norm choice (docs/theory/planar-formulation.md)")
    if free > 0:
        out.print(f"[yellow]note:[/] {free} degree(s) of freedom are neither driven nor clearance: "
                  "the mechanism moves under gravity, forces and initial velocities only")


# run -------------------------------------------------------------------------

@app.command()
def run(model: Annotated[Path, typer.Argument(help="Model file (TOML).", show_default=False)],
        output: Annotated[Path | None, typer.Option("-o", "--output", help="Results file: NetCDF for .nc, .nc4, "
                                                     ".h5 (written while the run goes on), CSV for .csv "
                                                     "[default: MODEL name with .nc, in the current folder].")] = None,
        t_end: Annotated[str | None, typer.Option("--t-end", help='End time, e.g. "24 ms" or 0.024 (seconds); '
                                                  "overrides simulation.t_end.")] = None,
        output_step: Annotated[str | None, typer.Option("--output-step", help='Spacing of the saved samples, e.g. '
                                                        '"1 ms" or 0.001 (seconds); overrides simulation.output_step. '
                                                        "Default: a sample at every accepted step. The summary's "
                                                        "peaks and extrema come from every step either way.")] = None,
        set_: SetOption = [],  # noqa: B006
        max_output: Annotated[str | None, typer.Option("--max-output", help='Budget of the output, samples x '
                                                       'channels x 8 bytes, e.g. "500 MB" or "4 GiB"; overrides '
                                                       "simulation.max_output_bytes [default: 2 GiB].")] = None,
        quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar and no summary.")] = False) -> None:
    """Simulate a model file, save the results (NetCDF) and print a summary.

    The summary gives peak accelerations of the named points and peak joint
    and contact forces with their times, impacts, time in contact and deepest
    penetration (thinnest film when lubricated) of each clearance joint, all
    tracked at every accepted step whatever the output step; integrator
    statistics and wall time. The file appears only once the run is complete
    (an existing file stays as it was until then); if the simulation stops
    early, what was computed is saved to OUT.partial.nc (or .partial.csv) and
    the exit code is 1.
    """
    m = _load(model, set_)
    options = dict(m.simulation)
    if output_step is not None:
        options["output_step"] = _time_option(output_step, "--output-step")
    end = _time_option(t_end, "--t-end") or options.pop("t_end", None)
    options.pop("t_end", None)
    if end is None:
        raise _bad_input(f"{model}: no end time", ["simulation.t_end: missing; set it in the [simulation] table "
                                                   "or give --t-end"])
    output = _output_path(output or Path(f"{model.stem}.nc"))
    if max_output is not None:
        options["max_output_bytes"] = _size_option(max_output, "--max-output")
    options["output_file"] = output
    try:
        with _printed_warnings():
            results = _simulate(m, end, options, quiet)
    except ModelError as exc:
        raise _bad_input(f"{model}: bad simulation options", exc.problems) from None
    except RuntimeError as exc:  # a panic in the core, caught at the binding
        err.print(f"[bold red]internal error[/] (please report it with the model file): {exc}")
        raise typer.Exit(EXIT_FAILED) from None
    except OSError as exc:
        raise _bad_input(f"-o {output}: cannot write the results ({exc})", []) from None
    except SimulationError as exc:
        where = f" in {exc.element}" if exc.element else ""
        kind = f" ({exc.kind})" if exc.kind else ""
        err.print(f"[bold red]simulation failed[/]{kind} at t = {exc.time:.6g} s{where}: ", end="")
        err.print(exc.cause, markup=False)
        if exc.results is not None:
            from .resultsfile import partial_path

            err.print(f"results up to t = {exc.time:.6g} s saved to {partial_path(output)}"
                      + (f" ({output} left as it was)" if output.exists() else ""))
        raise typer.Exit(EXIT_FAILED) from None
    if not quiet:
        print_summary(results)
    out.print(f"wrote {output}")


def _size_option(text: str, option: str) -> int:
    from .resultsfile import parse_size

    try:
        return parse_size(text)
    except ValueError as exc:
        raise _bad_input(f"{option}: {exc}", []) from None


def _output_path(output: Path) -> Path:
    """``-o``: a folder that exists and a suffix of a known format."""
    from .resultsfile import output_kind

    if not output.parent.is_dir():
        raise _bad_input(f"-o {output}: no folder {output.parent}", [])
    if output.is_dir():
        raise _bad_input(f"-o {output}: is a folder, not a results file (give a file name such as run.nc)", [])
    try:
        output_kind(output)
    except ValueError as exc:
        raise _bad_input(f"-o {output}: {exc}", []) from None
    return output


def progress_time(t: float, end: float) -> str:
    """``t = 26.7 / 100 s``: the simulated time and the end time in the unit that fits the end time."""
    unit, seconds = time_unit(end)
    return f"t = {t / seconds:.4g} / {end / seconds:.4g} {unit}"


def progress_bar(console: Console):
    """The progress bar of a run: ``simulating ━━━━━━━ t = 12 / 24 ms (3.1 s elapsed, about 3.0 s left)``
    (the simulated time in the unit that fits the end time; the time left estimated from the recent
    rate of progress). Update its task's ``t`` field with :func:`progress_time`."""
    from rich.progress import BarColumn, Progress, TextColumn

    from .display import WallTimeColumn

    return Progress(TextColumn("simulating"), BarColumn(), TextColumn("{task.fields[t]}"), WallTimeColumn(),
                    console=console, transient=True)


def _simulate(m, end: float, options: dict, quiet: bool):
    """Runs ``m`` to ``end`` [s], with :func:`progress_bar` on stderr unless ``quiet``."""
    if quiet:
        return m.simulate(end, **options)
    t0 = options.get("t0", 0.0) or 0.0
    with progress_bar(err) as bar:
        task = bar.add_task("run", total=end - t0, t=progress_time(t0, end))

        def progress(t: float) -> None:
            bar.update(task, completed=t - t0, t=progress_time(t, end))

        return m.simulate(end, progress=progress, **options)


def print_summary(results) -> None:
    """The numbers of ``Results.summary()`` as tables, under a line saying how many samples were
    saved and where the peaks and extrema come from (every accepted step, or the samples of an
    older results file)."""
    s = results.summary()
    out.print(_summary_title(results.spec.get("name", "") if results.spec else "", s))
    tracked = s["extrema_source"] == "accepted steps"

    def at(t: float | None) -> str:  # a time of the run, in the unit of the run's length
        return format_time(t, s["t_end"])

    peaks = table("quantity", "peak |value|", "at")
    for name, value in s["point_accelerations"].items():
        when = s["point_acceleration_times"].get(name)
        peaks.add_row(f"acceleration of point {name}", _fmt(value, "m/s^2"), at(when) if tracked else "(samples)")
    for name, value in [*s["peak_forces"].items(), *s["peak_pressures"].items()]:
        peaks.add_row(name, _fmt(value, results.unit(name)), at(s["peak_times"].get(name)))
    print_table(out, peaks)
    if s["clearance_joints"]:
        lubricated = any("min_film" in c for c in s["clearance_joints"].values())
        columns = ("clearance joint", "impacts", "time in contact", "max penetration")
        t = table(*columns, *(("min film", "peak film pressure") if lubricated else ()))
        for name, c in s["clearance_joints"].items():
            contact = f"{100 * c['contact_fraction']:.1f} %"
            if tracked:
                contact += f" ({at(c['contact_time'])})"
            penetration = f"{c['max_penetration'] * 1e6:.3g} um"
            if tracked and c.get("max_penetration_time") is not None:
                penetration += f" at {at(c['max_penetration_time'])}"
            cells = [name, str(c["impacts"]), contact, penetration]
            if lubricated and c.get("min_film") is not None:
                film = f"{c['min_film'] * 1e6:.3g} um"
                if tracked and c.get("min_film_time") is not None:
                    film += f" at {at(c['min_film_time'])}"
                pressure = _fmt(c.get("peak_film_pressure"), "Pa")
                if tracked and c.get("peak_film_pressure_time") is not None:
                    pressure += f" at {at(c['peak_film_pressure_time'])}"
                cells += [film, pressure]
            elif lubricated:
                cells += ["-", "-"]
            t.add_row(*cells)
        print_table(out, t)
        modes = {name: c["mode_fractions"] for name, c in s["clearance_joints"].items() if c.get("mode_fractions")}
        if modes:
            t = table("motion modes (time fractions)", "free", "impact", "sliding", "sustained", "axial contact")
            for name, f in modes.items():
                t.add_row(name, *(f"{100 * f[k]:.1f} %" for k in ("free", "impact", "sliding", "sustained", "axial")))
            print_table(out, t)
    st = s["statistics"]
    t = table("integrator", "value")
    for key in ("accepted_steps", "rejected_steps", "rhs_evaluations", "events", "restarts"):
        if key in st:
            t.add_row(key.replace("_", " "), _count(st[key]))
    for key in ("jacobian_evaluations", "jacobian_rhs_evaluations", "jacobian_force_evaluations",
                "factorizations"):  # implicit method only
        if st.get(key):
            t.add_row(key.replace("_", " "), _count(st[key]))
    for key in ("smallest_step", "largest_step"):
        if key in st:
            t.add_row(key.replace("_", " "), format_time(st[key]))
    inner = (results.extrema or {}).get("inner_evaluations")
    if inner is not None:  # the cost of finding the peaks between steps
        t.add_row("evaluations for peaks inside steps", _count(inner))
    t.add_row("wall time", format_time(s["wall_time"]) or "-")
    print_table(out, t)


# plot, compare ---------------------------------------------------------------

ChannelOption = Annotated[list[str], typer.Option("--channel", "-c", help="Channel to draw, e.g. slider.ax "
                                                  "(repeatable; default: the key channels).")]
FormatOption = Annotated[str, typer.Option("--format", "-f", help="Image format: png or svg.")]


def _note_stopped(runs: list, paths: list[Path]) -> None:
    """``note: out.partial.nc: run stopped at t = ... s: <cause>`` for each run that stopped early
    (its figures say the same)."""
    from .plots import stopped_note

    for run, path in zip(runs, paths):
        note = stopped_note(run)
        if note:
            out.print("[yellow]note:[/] ", end="")
            out.print(f"{path}: {note}", markup=False)


def _check_format(fmt: str) -> str:
    from .plots import FORMATS

    if fmt.lower() not in FORMATS:
        raise _bad_input(f"--format: must be one of {', '.join(FORMATS)}, got {fmt!r}", [])
    return fmt.lower()


@app.command()
def plot(results: Annotated[Path, typer.Argument(help="Results file written by `jointplay run`.", show_default=False)],
         channel: ChannelOption = [],  # noqa: B006
         output: Annotated[Path | None, typer.Option("-o", "--output", help="Folder for the figures "
                                                     "[default: RESULTS name + _figures].")] = None,
         fmt: FormatOption = "png",
         crank: Annotated[str | None, typer.Option("--crank", help="Body whose angle is the abscissa of the "
                                                   "contact-force figure [default: the driven body].")] = None) -> None:
    """Draw the standard figures of a results file.

    Time histories of the chosen channels, the journal-centre orbit of each
    clearance joint inside its clearance circle, and the contact force against
    the crank angle; for a spatial model, the bodies' centre-of-mass paths,
    their orientations and angular velocities, and the joint reactions.
    """
    from .plots import standard_figures

    fmt = _check_format(fmt)
    r = _open(results)
    _crank_check(crank, [r], [results])
    _note_stopped([r], [results])
    output = _figure_folder("-o", output or results.with_name(f"{results.stem}_figures"))
    try:
        paths = standard_figures(r, output, crank=crank, fmt=fmt, channels=channel or None)
    except KeyError as exc:
        raise _bad_input(f"--channel: {exc.args[0]}", []) from None
    except OSError as exc:
        raise _bad_input(f"-o {output}: cannot write the figures ({exc.strerror or exc})", []) from None
    for path in paths:
        out.print(f"wrote {path}")
    if not paths:
        out.print("[yellow]nothing to draw:[/] the results file holds no samples")


@app.command()
def compare(results: Annotated[list[Path], typer.Argument(help="Results files to overlay.", show_default=False)],
            channel: ChannelOption = [],  # noqa: B006
            output: Annotated[Path, typer.Option("-o", "--output", help="Folder for the figures.")] = Path("comparison"),
            fmt: FormatOption = "png",
            label: Annotated[list[str], typer.Option("--label", "-l", help="Legend label of each file, in order "
                                                     "[default: the file names].")] = [],  # noqa: B006
            crank: Annotated[str | None, typer.Option("--crank", help="Plot against this body's angle [deg] "
                                                      "instead of time.")] = None) -> None:
    """Overlay the same channels from several results files.

    For example the ideal, dry-clearance and lubricated variants of one
    mechanism. Writes one figure per channel and prints the peak of each
    channel in each run.
    """
    from .compare import compare_figures, default_compare_channels, nothing_to_compare, peak_table

    fmt = _check_format(fmt)
    runs = [_open(p) for p in results]
    if label and len(label) != len(results):
        raise _bad_input(f"--label: give one label per results file ({len(results)}), got {len(label)}", [])
    labels = label or [p.stem for p in results]
    _crank_check(crank, runs, results)
    _note_stopped(runs, results)
    names = channel or default_compare_channels(runs)
    if not names:
        raise _bad_input(f"nothing to compare: {nothing_to_compare(runs, labels)}", [])
    for name in names:
        if not any(name in run for run in runs):
            try:
                runs[0][name]
            except KeyError as exc:  # with a did-you-mean hint
                raise _bad_input(f"--channel: {exc.args[0]}", []) from None
    output = _figure_folder("-o", output)
    try:
        paths = compare_figures(runs, labels, output, channels=names, fmt=fmt, crank=crank)
    except KeyError as exc:
        raise _bad_input(f"--channel: {exc.args[0]}", []) from None
    except OSError as exc:
        raise _bad_input(f"-o {output}: cannot write the figures ({exc.strerror or exc})", []) from None
    peaks = table("channel", "unit", *labels,
                  title="peak |value| over every accepted step ((samples): over the saved samples only)")
    for row in peak_table(runs, names):
        peaks.add_row(*row)
    print_table(out, peaks)
    for path in paths:
        out.print(f"wrote {path}")


from . import cli_animate  # noqa: E402,F401  (registers `jointplay animate`)
from . import cli_bearing  # noqa: E402,F401  (registers `jointplay bearing`; imports `app` from here)
from . import cli_static  # noqa: E402,F401  (registers `jointplay static`)
from . import cli_study  # noqa: E402,F401  (registers `jointplay sweep` and `jointplay optimize`)
from . import cli_report  # noqa: E402,F401  (registers `jointplay report`)


def main() -> None:
    """Entry point of the ``jointplay`` script."""
    app()


if __name__ == "__main__":
    # run as `python -m jointplay.cli`, this file is a second module: the command files above registered their
    # commands on the package's `jointplay.cli.app`, so run that one
    from jointplay.cli import main as package_main

    package_main()
