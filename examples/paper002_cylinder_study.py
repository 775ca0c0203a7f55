"""Paper 002's study of the motion modes of its cylinder rig: input force, frequency and radial clearance.

The rig of examples/paper002_cylinder_rig.toml in 48 cases, a full factorial of the input amplitude Fmax
1, 2, 3, 4 kN, its frequency 5, 10, 15, 20 Hz and the radial clearance of both joints 0.2, 0.5, 1 mm (the
axial clearance stays 0.5 mm), run as one study with the study layer (``jointplay.Study`` around the model
file, an explicit table of the cases; ``--workers N`` runs them on N processes, ``--out DIR`` keeps them
resumable there). Responses of each case, per joint: the time fractions of the motion modes (free, impact,
sliding, sustained; axial contact apart) tracked by the core at every accepted step; the irregularity of
the journal centre's path (below); the peak contact force; and the range of the rod displacement z_rod.

Paper 002 varies one factor at a time about 3 kN, 10 Hz, 0.5 mm (its Figs. 24, 27, 30); those series are
three lines through the factorial's base case, and beside them each factor's main effect (the mean over
the other two factors' levels). Its statements (§4.3-4.5), which the trends here are compared with:
- larger force: more free flight and more sustained contact, less sliding;
- higher frequency: more free flight and sustained contact, less sliding, more regular trajectories;
- larger clearance: less sustained contact, more free flight and more sliding (the issue's summary and the
  paper's closing paragraph say less sliding with force and clearance; §4.5 says more with clearance).

Irregularity (defined here, a measure of "regular trajectories"): the root mean square of the journal
centre's change over one period of the input, |e_m(t) - e_m(t - 1/f)|, over the second half of the run,
divided by the radial clearance. 0 for a motion that repeats every period; it grows as the path wanders
from period to period.

The values of the rig are CHOSEN (paper 002's tables are lost): the trends are what this model shows, not a
reproduction of the paper's numbers. Writes the fractions against each factor (PNG), the tables (Markdown
and CSV) and the study's Dataset.

Cost: a 10 s case takes about a minute of one core; the 48 cases of 2 s each took 21 minutes with
``--workers 2`` on two cores shared with other jobs (load 5-9). The fractions then include the first
drop of the journals from the centre into contact.

Run: python examples/paper002_cylinder_study.py [--out DIR] [--t-end S] [--workers N] [--max-steps N]
"""

from __future__ import annotations

import argparse
import csv
import functools
import itertools
from pathlib import Path

import numpy as np

import paper002_cylinder_rig as rig
from jointplay.plots_spatial_clearance import FRACTION_KEYS, mode_fraction, radial_clearance

#: The factors' levels [N, Hz, m], and the case the paper's one-factor series pass through.
FORCES = (1000.0, 2000.0, 3000.0, 4000.0)
FREQUENCIES = (5.0, 10.0, 15.0, 20.0)
CLEARANCES = (0.2e-3, 0.5e-3, 1.0e-3)
BASE = {"force": 3000.0, "frequency": 10.0, "clearance": 0.5e-3}
#: Each factor: the model-file path(s) it sets and its unit; the clearance sets both joints.
PATHS = {"force": ("forces.input.force.0.amplitude",), "frequency": ("forces.input.force.0.frequency",),
         "clearance": tuple(f"joints.{joint}.clearance" for joint in rig.JOINTS)}
UNITS = {"force": "N", "frequency": "Hz", "clearance": "m"}
#: The end time of each case in the full study [s] (paper 002 runs 10 s).
T_END = 10.0
#: Paper 002's statements by factor: the direction (+1 more, -1 less) of each fraction as the factor grows.
PAPER = {"force": {"free": +1, "sustained": +1, "sliding": -1},
         "frequency": {"free": +1, "sustained": +1, "sliding": -1, "irregularity": -1},
         "clearance": {"free": +1, "sustained": -1, "sliding": +1}}


def irregularity(results, joint: str) -> float:
    """RMS of |e_m(t) - e_m(t - T)| over the run's second half, over the radial clearance [-] (module doc);
    T = 1 / f of the run's input."""
    frequency = input_frequency(results)
    t = results.time
    x, y = results[f"{joint}.e_m_x"], results[f"{joint}.e_m_y"]
    pick = t >= max(t[-1] / 2, t[0] + 1.0 / frequency)
    back = t[pick] - 1.0 / frequency
    dx, dy = x[pick] - np.interp(back, t, x), y[pick] - np.interp(back, t, y)
    return float(np.sqrt(np.mean(dx * dx + dy * dy)) / radial_clearance(results, joint))


def input_frequency(results) -> float:
    """The frequency [Hz] of the run's sine input (the model's ``input`` force)."""
    for entries in (results.spec or {}).values():
        for entry in entries if isinstance(entries, list) else ():
            if isinstance(entry, dict) and entry.get("name") == "input":
                return float(entry["force"][0]["frequency"])
    raise KeyError("the run has no force named input")


def z_rod_range(results) -> float:
    """max - min of the rod displacement z_rod [m] over the run's second half."""
    z = rig.rod_displacement(results)
    return float(np.ptp(z[results.time >= results.time[-1] / 2]))


def responses() -> list:
    """Per joint the five mode fractions, the irregularity and the peak contact force; z_rod's range."""
    from jointplay.study.metrics import Response

    out = []
    for joint in rig.JOINTS:
        for mode in FRACTION_KEYS:
            out.append(Response.from_callable(
                f"{joint}_{mode}", functools.partial(mode_fraction, joint=joint, mode=mode),
                description=f"fraction of the run in the {mode} mode at joint {joint}, over every accepted step"))
        out.append(Response.from_callable(f"{joint}_irregularity", functools.partial(irregularity, joint=joint),
                                          description=f"irregularity of the journal centre's path at {joint}"))
        out.append({"name": f"{joint}_peak_force", "kind": "peak", "channel": f"{joint}.f"})
    out.append(Response.from_callable("z_rod_range", z_rod_range, units="m",
                                      description="range of z_rod over the run's second half"))
    return out


def build_study(t_end: float = T_END, forces=FORCES, frequencies=FREQUENCIES, clearances=CLEARANCES,
                max_steps: int | None = None):
    """The full factorial of the levels as a study around the model file: an explicit table of the cases
    (the clearance is one value for two paths, the joints' two factors equal in every row). ``max_steps``
    stops a case whose steps become too small (it is then marked failed, its responses missing)."""
    from jointplay.study import Study

    levels = {"force": forces, "frequency": frequencies, "clearance": clearances}
    factors, rows = [], []
    for name, paths in PATHS.items():
        for path in paths:
            factors.append({"name": path.split(".")[1] + "_" + name if name == "clearance" else name,
                            "path": path, "levels": [f"{v!r} {UNITS[name]}" for v in levels[name]]})
    for force, frequency, clearance in itertools.product(forces, frequencies, clearances):
        rows.append([f"{force!r} N", f"{frequency!r} Hz"] + [f"{clearance!r} m"] * len(PATHS["clearance"]))
    options = {} if max_steps is None else {"max_steps": max_steps}
    return Study(rig.MODEL_FILE, factors, {"kind": "table", "rows": rows}, responses(), t_end=t_end,
                 options=options, name="paper002_cylinder_study")


def run_study(t_end: float = T_END, workers: int = 1, folder: Path | None = None, max_steps: int | None = None,
              **levels):
    """The study's Dataset (``folder`` keeps the cases, resumable)."""
    return build_study(t_end, max_steps=max_steps, **levels).run(folder, workers=workers,
                                                                 resume=folder is not None)


def case_levels(ds) -> dict[str, np.ndarray]:
    """Each factor's value per case [N, Hz, m] (the clearance from the first joint's factor)."""
    return {"force": ds["force"].values, "frequency": ds["frequency"].values,
            "clearance": ds[f"{rig.JOINTS[0]}_clearance"].values}


def series(ds, factor: str) -> list[int]:
    """The cases of paper 002's one-factor series of ``factor``: the other factors at the base case's
    values (empty when the study has no base case), in the order of ``factor``'s levels."""
    values = case_levels(ds)
    held = np.ones(ds.sizes["case"], dtype=bool)
    for other in BASE:
        if other != factor:
            held &= np.isclose(values[other], BASE[other], rtol=1e-9)
    cases = np.flatnonzero(held)
    return [int(k) for k in cases[np.argsort(values[factor][cases])]]


def joint_mean(ds, quantity: str) -> np.ndarray:
    """``quantity`` (a fraction or the irregularity) averaged over the two joints, per case."""
    return np.mean([ds[f"{joint}_{quantity}"].values for joint in rig.JOINTS], axis=0)


def direction(values) -> str:
    """``rises``, ``falls``, ``flat`` (changes below 0.005) or ``not monotonic``, with first -> last."""
    v = np.asarray(values, dtype=float)
    steps = np.diff(v)
    span = f"{v[0]:.3f} -> {v[-1]:.3f}"
    if np.all(np.abs(steps) < 0.005):
        return f"flat ({span})"
    if np.all(steps >= -0.005):
        return f"rises ({span})"
    if np.all(steps <= 0.005):
        return f"falls ({span})"
    return f"not monotonic ({span})"


def trends(ds) -> list[str]:
    """One line per factor and quantity: the direction along the paper's series through the base case and
    of the main effect (both joints averaged), beside paper 002's statement and whether they agree."""
    lines = []
    quantities = FRACTION_KEYS + ("irregularity",)
    for factor in BASE:
        chain = series(ds, factor)
        for quantity in quantities:
            y = joint_mean(ds, quantity)
            _, effect = main_effect_of(ds, factor, y)
            along = direction(y[chain]) if len(chain) > 1 else "n/a"
            claim = PAPER[factor].get(quantity)
            said = {+1: "more", -1: "less", None: "-"}[claim]
            verdict = "" if claim is None else f" -> {agreement(effect, claim)} with the paper"
            lines.append(f"{factor:9s} {quantity:12s} series through the base: {along:28s} main effect: "
                         f"{direction(effect):28s} paper: {said}{verdict}")
    return lines


def main_effect_of(ds, factor: str, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(levels of ``factor``, mean of the per-case values ``y`` at each level over the other factors)."""
    x = case_levels(ds)[factor]
    levels = np.unique(x)
    return levels, np.array([np.nanmean(y[np.isclose(x, v, rtol=1e-9)]) for v in levels])


def agreement(effect: np.ndarray, claim: int) -> str:
    """``agrees`` when the main effect moves monotonically the paper's way (first -> last by more than
    0.005), ``agrees in the end values`` when only first -> last does, else ``does not agree``."""
    steps = np.diff(effect) * claim
    if effect.size > 1 and np.all(steps >= -0.005) and (effect[-1] - effect[0]) * claim > 0.005:
        return "agrees"
    if (effect[-1] - effect[0]) * claim > 0.005:
        return "agrees in the end values (not monotonic)"
    return "does not agree"


def table_rows(ds) -> list[dict]:
    """One row per case: factor values and every response."""
    values = case_levels(ds)
    rows = []
    for k in range(ds.sizes["case"]):
        row = {"case": k, "force_N": values["force"][k], "frequency_Hz": values["frequency"][k],
               "clearance_mm": values["clearance"][k] * 1e3}
        for joint in rig.JOINTS:
            for q in FRACTION_KEYS + ("irregularity", "peak_force"):
                row[f"{joint}_{q}"] = float(ds[f"{joint}_{q}"].values[k])
        row["z_rod_range_mm"] = float(ds["z_rod_range"].values[k]) * 1e3
        row["status"] = str(ds["status"].values[k])
        rows.append(row)
    return rows


def markdown_table(ds) -> str:
    """The paper's three series (cases through the base case) and each factor's main effect, both joints
    averaged: the mode fractions and the irregularity."""
    head = ("| factor | level | cases | free | impact | sliding | sustained | axial | irregularity |\n"
            "|---|---:|---|---:|---:|---:|---:|---:|---:|")
    lines = [head]
    quantities = FRACTION_KEYS + ("irregularity",)
    values = case_levels(ds)
    scale = {"force": 1e-3, "frequency": 1.0, "clearance": 1e3}
    unit = {"force": "kN", "frequency": "Hz", "clearance": "mm"}
    for factor in BASE:
        for k in series(ds, factor):
            cells = " | ".join(f"{joint_mean(ds, q)[k]:.3f}" for q in quantities)
            lines.append(f"| {factor} | {values[factor][k] * scale[factor]:g} {unit[factor]} | series (case {k}) | "
                         f"{cells} |")
        effects = [main_effect_of(ds, factor, joint_mean(ds, q)) for q in quantities]
        for j, level in enumerate(effects[0][0]):
            cells = " | ".join(f"{e[1][j]:.3f}" for e in effects)
            lines.append(f"| {factor} | {level * scale[factor]:g} {unit[factor]} | mean over the others | {cells} |")
    return "\n".join(lines)


def fractions_figure(ds, t_end: float):
    """Per joint (rows) and factor (columns): the fractions and the irregularity against the factor, solid
    along the paper's series through the base case, dotted the main effect."""
    from jointplay.plots import _figure, set_titles

    fig = _figure(13.0, 7.5)
    axes = fig.subplots(len(rig.JOINTS), len(BASE), squeeze=False)
    values = case_levels(ds)
    scale = {"force": 1e-3, "frequency": 1.0, "clearance": 1e3}
    unit = {"force": "kN", "frequency": "Hz", "clearance": "mm"}
    for row, joint in enumerate(rig.JOINTS):
        for col, factor in enumerate(BASE):
            ax = axes[row, col]
            chain = series(ds, factor)
            for n, quantity in enumerate(FRACTION_KEYS + ("irregularity",)):
                y = ds[f"{joint}_{quantity}"].values
                colour = f"C{n}"
                if len(chain) > 1:
                    ax.plot(values[factor][chain] * scale[factor], y[chain], "o-", color=colour, lw=1.2, ms=3,
                            label=quantity)
                levels, effect = main_effect_of(ds, factor, y)
                ax.plot(levels * scale[factor], effect, ":", color=colour, lw=1.0)
            ax.set_xlabel(f"{factor} [{unit[factor]}]")
            ax.set_ylabel(f"{joint}: fraction [-]")
            ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=7)
    set_titles(fig, f"paper002 cylinder rig, {ds.sizes['case']} cases of {t_end:g} s: motion-mode fractions and "
                    "irregularity (RMS period-to-period change of the journal centre / c) against the input "
                    "force, its frequency and the radial clearance; solid: paper 002's series through 3 kN, "
                    f"10 Hz, 0.5 mm; dotted: mean over the other factors. {rig.CHOSEN_NOTE}")
    return fig


def write_outputs(ds, out: Path, t_end: float) -> list[Path]:
    from jointplay.plots import _save
    from jointplay.study.dataset import save

    out.mkdir(parents=True, exist_ok=True)
    rows = table_rows(ds)
    csv_path, md_path = out / "paper002_study_cases.csv", out / "paper002_study_trends.md"
    with csv_path.open("w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    md_path.write_text(markdown_table(ds) + "\n\n```\n" + "\n".join(trends(ds)) + "\n```\n")
    return [_save(fractions_figure(ds, t_end), out / "paper002_study_fractions.png"), csv_path, md_path,
            save(ds, out / "paper002_study.nc")]


def main(argv: list[str] | None = None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("out/paper002_study"))
    parser.add_argument("--t-end", type=float, default=T_END, help="end time of each case [s] (default 10)")
    parser.add_argument("--workers", type=int, default=1, help="local worker processes running the cases")
    parser.add_argument("--max-steps", type=int, default=None, help="attempted steps at most per case")
    args = parser.parse_args(argv)
    ds = run_study(args.t_end, args.workers, args.out / "cases", args.max_steps)
    print(markdown_table(ds))
    print("\n".join(trends(ds)))
    for path in write_outputs(ds, args.out, args.t_end):
        print(f"wrote {path}")
    return ds


if __name__ == "__main__":
    main()
