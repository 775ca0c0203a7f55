"""The circuit-breaker operating mechanism of paper 003 in its three variants: rigid links with ideal
joints, flexible links with ideal joints, flexible links with clearance joints.

Paper 003: Li et al., "A Study on the Dynamic Responses and Joints Clearance Optimization of the
Planar Operating Mechanism of High-Voltage Circuit Breaker" (its §4.2-4.3 compare these variants).
FROM THE PAPER: link lengths, masses and centroids (Table 1); the drive of eq. (5) on the upper
link's angle, read as degrees; shaft radius 6 mm, Lankarani-Nikravesh contact, n 1.5, restitution
0.9, Coulomb friction 0.1, E 207 GPa, nu 0.3 (Table 2); the five flexible links.

CHOSEN here, because the paper's Figure 1 is lost (these are not the paper's values): the topology,
every pivot coordinate, the rigid inertias (slender bars), the insulating link as a block sliding
across the moving contact, the buffer spring (20 kN/m), gravity along -y, joint A ideal (it is the
driven joint), the radial clearance 15 um (the paper's 30 um IT7 read as diametral), and for the
flexible links: steel (7850 kg/m^3), 10 mm thick, as deep in the plane as makes the Table 1 mass
(uniform bars: their centroid is mid-length, not Table 1's), 2 % modal damping, MODES normal modes
each (a convergence check, docs/theory/reference-breaker.md). The geometry is defined once, in
examples/paper003_breaker.toml; the variants here edit that file's document. The results are not a
reproduction of the paper's figures.

The clearance optimisation of paper 003 §4.4 (``--study``): the study file
examples/studies/paper003_breaker.toml (radial clearances of E-H between IT6 and IT8 at 12 mm, B-D at
IT8, a face-centred central composite design, the oscillation of the moving contact's acceleration and
the peaks of the force at H in the first and last 10 ms) run around the flexible-link clearance
variant built here, its quadratic surfaces, the weighted optimum verified by a run, and the changes
from the variant with every joint at the paper's IT7 (15 um radial), beside the paper's -24.8 %,
-18.4 %, -26.1 %, which come from another geometry: ours are not a reproduction. ``--study --quick``
runs the same study on the model file's rigid links (a few seconds).

Run: python examples/paper003_breaker.py [--out DIR] [--t-end S] [--quick] [--save-model FILE]
     python examples/paper003_breaker.py --study [--workers N] [--quick] [--out DIR]
"""

from __future__ import annotations

import argparse
import copy
from pathlib import Path
from textwrap import wrap

import numpy as np

import jointplay as jp
from jointplay.errors import ModelError, Problem
from jointplay.modelfile import from_document, read_document
from jointplay.modelfile.overrides import apply_overrides

MODEL_FILE = Path(__file__).resolve().with_name("paper003_breaker.toml")

#: Channels a study reads: the moving contact's position [m], velocity [m/s], acceleration [m/s^2]
#: (it slides along y).
CONTACT_X, CONTACT_Y = "moving_contact.x", "moving_contact.y"
CONTACT_VELOCITY = "moving_contact.vy"
CONTACT_ACCELERATION = "moving_contact.ay"
#: The force at joint H [N]. An ideal pin reports its reaction's magnitude as ``H.f`` (with ``H.fx``,
#: ``H.fy``); a clearance joint reports its contact force's magnitude, normal and friction together, under
#: the same name (with ``H.fn``, ``H.ft``, ``H.penetration``, ``H.contact``).
H_REACTION = "H.f"  # "rigid" and "flexible": the ideal pin's reaction
H_CONTACT_FORCE = "H.f"  # "clearance" and the model file: the contact force in the clearance joint
H_FORCE_CHANNEL = {"rigid": H_REACTION, "flexible": H_REACTION, "clearance": H_CONTACT_FORCE}
H_IN_CONTACT = "H.contact"  # 1 while the journal touches the bore, else 0 ("clearance" only)

VARIANTS = ("rigid", "flexible", "clearance")
#: Pins that carry a clearance in the "clearance" variant (A is the driven pin, always ideal).
CLEARANCE_JOINTS = ("B", "C", "D", "E", "F", "G", "H")
#: The five flexible links of the paper (§2.3), each with its end points (start, end) in the model file.
FLEXIBLE_LINKS = {"upper_link": ("A", "B"), "middle_link": ("B", "C"), "upper_arm": ("C", "E"),
                  "down_link": ("E", "G"), "down_arm": ("G", "H")}
#: Quadratic elements per link, so that the interior pivots fall on nodes (D at 5/7, F at 7/16).
ELEMENTS = {"upper_link": 4, "middle_link": 4, "upper_arm": 7, "down_link": 4, "down_arm": 8}
STEEL_DENSITY = 7850.0  # kg/m^3, CHOSEN
YOUNGS_MODULUS = 207e9  # Pa, Table 2
POISSON_RATIO = 0.3  # Table 2
THICKNESS = 0.010  # m, out of the plane, CHOSEN
DAMPING_RATIO = 0.02  # CHOSEN
RADIAL_CLEARANCE = 15e-6  # m: the paper's "30 um" IT7 clearance read as diametral, halved (CHOSEN reading)
MODES = 2  # normal modes per link, from the convergence check of docs/theory/reference-breaker.md
#: Integrator options (chosen by measurement: docs/theory/reference-breaker.md, "Integrator and run time").
OPTIONS = {"method": "dopri5", "rtol": 1e-6, "atol": 1e-9}
T_END = 0.03  # s: the stroke of eq. (5)
QUICK_T_END = 0.003  # s: the run of --quick
OUTPUT_STEPS = 600  # samples per run, the paper's step count (§2.3)


def build_model(variant: str = "clearance", clearance: float | None = RADIAL_CLEARANCE,
                modes: int | None = None, overrides: dict | None = None) -> jp.Model:
    """The breaker in ``variant`` ("rigid", "flexible" or "clearance").

    ``clearance`` [m, radial] is set in every clearance joint (None keeps the model file's);
    ``modes`` normal modes per flexible link (None: :data:`MODES`); ``overrides``
    (``{"joints.E.clearance": "18 um"}``, the model file's ``--set`` paths) are applied after
    ``clearance``, so a study can vary one joint's clearance."""
    if variant not in VARIANTS:
        raise ModelError([Problem("variant", f"must be one of {', '.join(VARIANTS)}, not {variant!r}")])
    if clearance is not None and not clearance > 0:
        raise ModelError([Problem("clearance", f"must be a positive radial clearance in m, not {clearance!r}")])
    modes = MODES if modes is None else modes
    doc = read_document(MODEL_FILE)
    if clearance is not None:
        overrides = {**{f"joints.{j}.clearance": metres(clearance) for j in CLEARANCE_JOINTS}, **(overrides or {})}
    if overrides:
        doc = apply_overrides(doc, overrides)
    rigid_spec = from_document(doc, name="paper003_breaker", base=MODEL_FILE.parent).to_spec()
    if variant in ("rigid", "flexible"):
        doc = ideal_joints(doc)
    if variant in ("flexible", "clearance"):
        doc = flexible_links(doc, rigid_spec, modes)
    doc["model"]["name"] = f"paper003_breaker_{variant}"
    model = from_document(doc, name=doc["model"]["name"], base=MODEL_FILE.parent)
    return model


def ideal_joints(doc: dict) -> dict:
    """A copy of ``doc`` with every clearance joint an ideal pin between its bore and its journal."""
    doc = copy.deepcopy(doc)
    for name, joint in doc["joints"].items():
        if joint["type"] == "clearance_revolute":
            doc["joints"][name] = {"type": "revolute", "first": joint["bearing"], "second": joint["journal"]}
    return doc


def flexible_links(doc: dict, rigid_spec: dict, modes: int) -> dict:
    """A copy of ``doc`` with the five links as modal bodies of steel bars through the same pivots."""
    doc = copy.deepcopy(doc)
    bodies = {b["name"]: b for b in rigid_spec["bodies"]}
    doc.setdefault("modal_bodies", {})
    for link, ends in FLEXIBLE_LINKS.items():
        del doc["bodies"][link]
        doc["modal_bodies"][link] = modal_link(link, bodies[link], ends, modes)
    return doc


def modal_link(link: str, body: dict, ends: tuple[str, str], modes: int) -> dict:
    """The modal body of ``link``: a uniform bar from its first to its last pivot, of the rigid link's
    mass, its pivots as interface nodes (each on the bar's line and at a mesh node, within 1 um)."""
    cos, sin = np.cos(body["angle"]), np.sin(body["angle"])
    rotation = np.array([[cos, -sin], [sin, cos]])
    pivots = {p["name"]: np.asarray(body["position"]) + rotation @ p["position"] for p in body["points"]}
    start, end = pivots[ends[0]], pivots[ends[1]]
    length = float(np.linalg.norm(end - start))
    axis = (end - start) / length
    node_spacing = length / (2 * ELEMENTS[link])
    interface = {}
    for name, at in pivots.items():
        offset = at - start
        along, across = float(axis @ offset), float(axis[0] * offset[1] - axis[1] * offset[0])
        node = round(along / node_spacing) * node_spacing
        if abs(node - along) > 1e-6 or abs(across) > 1e-6:
            raise ModelError([Problem(f"bodies.{link}.points.{name}", f"is {along:.6g} m along and {across:.3g} m "
                                      f"across the link, not at a node of its {ELEMENTS[link]} elements")])
        interface[name] = node
    depth = body["mass"] / (STEEL_DENSITY * THICKNESS * length)  # in-plane height giving Table 1's mass
    return {"start": [metres(v) for v in start], "end": [metres(v) for v in end], "elements": ELEMENTS[link],
            "section": {"shape": "rectangle", "width": metres(THICKNESS), "height": metres(depth)},
            "material": {"youngs_modulus": f"{YOUNGS_MODULUS!r} Pa", "density": f"{STEEL_DENSITY!r} kg/m^3",
                         "poisson_ratio": POISSON_RATIO},
            "interface": {name: metres(v) for name, v in interface.items()}, "normal_modes": modes,
            "damping_ratio": DAMPING_RATIO}


def metres(value: float) -> str:
    """``value`` [m] as a model-file length."""
    return f"{float(value)!r} m"


def simulate(model: jp.Model, t_end: float = T_END, **options) -> jp.Results:
    """``model`` run to ``t_end`` [s] with :data:`OPTIONS` (``options`` override them), sampled at
    :data:`OUTPUT_STEPS` steps."""
    return model.simulate(t_end, **{**OPTIONS, "output_step": t_end / OUTPUT_STEPS, **options})


def travel(results: jp.Results) -> np.ndarray:
    """The moving contact's downward travel from its start [m]."""
    y = results[CONTACT_Y]
    return y[0] - y


def table(runs: dict[str, jp.Results]) -> list[dict]:
    """Per variant: peak |acceleration| [m/s^2], peak force at H [N], travel at the end [m]."""
    return [{"variant": name, "peak_acceleration": float(np.max(np.abs(r[CONTACT_ACCELERATION]))),
             "peak_force_H": float(np.max(r[H_FORCE_CHANNEL[name]])), "travel_end": float(travel(r)[-1])}
            for name, r in runs.items()]


#: The figures main() draws: file stem -> the variants overlaid (the paper's Figure 6 compares rigid and
#: flexible links, its Figure 7 flexible links without and with clearances).
FIGURES = {"paper003_breaker": VARIANTS, "paper003_breaker_rigid_flexible": ("rigid", "flexible"),
           "paper003_breaker_flexible_clearance": ("flexible", "clearance")}


def figure(runs: dict[str, jp.Results], path: Path) -> Path:
    """Displacement, velocity, acceleration of the moving contact and the force at H, variants overlaid."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    panels = [(lambda r, _: 1e3 * travel(r), "travel down [mm]"),
              (lambda r, _: r[CONTACT_VELOCITY], "velocity [m/s]"),
              (lambda r, _: r[CONTACT_ACCELERATION], "acceleration [m/s^2]"),
              (lambda r, variant: r[H_FORCE_CHANNEL[variant]], "force at H [N]")]
    for ax, (quantity, label) in zip(axes.flat, panels):
        for name, r in runs.items():
            ax.plot(1e3 * r.time, quantity(r, name), label=name, lw=0.8)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("time [ms]")
    axes[0, 0].legend()
    fig.suptitle("Breaker mechanism after paper 003 (geometry chosen; not the paper's results)")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def save_variant(path: Path, variant: str = "clearance", **build) -> Path:
    """Writes ``variant`` (built by :func:`build_model` with ``build``) as a model file at ``path``, for
    tools that take a model file and ``--set`` paths, such as a study of ``joints.E.clearance``."""
    header = (f"The {variant} variant of the breaker, written by examples/paper003_breaker.py from "
              f"examples/paper003_breaker.toml: see docs/theory/reference-breaker.md for every CHOSEN value.")
    path.write_text(build_model(variant, **build).to_toml(header="\n".join(wrap(header, 100))))
    return path


def parser() -> argparse.ArgumentParser:
    """The command line: ``--out DIR``, ``--t-end S``, ``--quick``."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=None, help="folder for the figures")
    parser.add_argument("--t-end", type=float, default=T_END, help="end time [s]")
    parser.add_argument("--quick", action="store_true", help=f"run {1e3 * QUICK_T_END:g} ms only")
    parser.add_argument("--save-model", type=Path, default=None,
                        help="write the clearance variant as a model file there and stop")
    parser.add_argument("--study", action="store_true", help="run the clearance optimisation of E-H")
    parser.add_argument("--workers", type=int, default=1, help="local worker processes of the study")
    return parser


STUDY_FILE = Path(__file__).resolve().parent / "studies" / "paper003_breaker.toml"
#: The paper's reported changes after its optimisation (§4.4, Figure 8), for comparison only.
PAPER_CHANGES = {"acc_oscillation": -24.8, "force_H_start": -18.4, "force_H_end": -26.1}


def breaker_study(variant: str = "clearance", **build):
    """The study of STUDY_FILE: its factors, fixed values, design and responses around the ``variant`` built
    by :func:`build_model` (``"file"``: the model file itself, rigid links)."""
    import tomllib

    from jointplay.study import Study, load_study

    if variant == "file":
        return load_study(STUDY_FILE)
    table = tomllib.loads(STUDY_FILE.read_text())["study"]
    study = Study(build_model(variant, **build), table["factors"], table["design"], table["responses"],
                  t_end=table["t_end"], fixed=table["set"], name=f"{table['name']} ({variant})", file_values=True)
    study.optimize_spec = table["optimize"]
    return study


def baseline_responses(study) -> dict[str, float]:
    """The responses with every clearance joint at the paper's IT7 reading (RADIAL_CLEARANCE), as before its
    optimisation."""
    from dataclasses import replace

    from jointplay.study.worker import simulate as run_case

    everywhere = {f"joints.{j}.clearance": f"{RADIAL_CLEARANCE!r} m" for j in CLEARANCE_JOINTS}
    results = run_case(replace(study.recipe(), fixed={}), everywhere)
    return {r.name: r.evaluate(results) for r in study.responses}, results


def run_study(args) -> dict:
    """The clearance optimisation: sweep, surfaces, optimum verified by a run, changes from all-IT7."""
    from rich.console import Console

    from jointplay.cli_study import print_optimum, print_summary
    from jointplay.study.optimize import best_case, optimize_surface, parse_objectives

    out = args.out or Path("out/paper003_study")
    study = breaker_study("file" if args.quick else "clearance")
    dataset = study.run(out / ("study_quick" if args.quick else "study"), workers=args.workers, resume=True,
                        progress=not args.quick)
    print_summary(study, dataset, out / ("study_quick" if args.quick else "study"))
    objectives = parse_objectives(study.optimize_spec["objectives"], [r.name for r in study.responses])
    optimum = optimize_surface(study, dataset, objectives, seed=study.seed)
    print_optimum(study, optimum, objectives)
    best = best_case(study, dataset, objectives)
    print_optimum(study, best, objectives)
    before, _ = baseline_responses(study)
    Console().print("change from every joint at IT7 (15 um radial) to the surface's verified optimum and to the "
                    "design's best case (paper 003's own geometry gave the paper's column; the geometry here is "
                    "chosen, so this is no reproduction):")
    changes, best_changes = {}, {}
    for name, value in before.items():
        changes[name] = 100.0 * (optimum.verified[name] - value) / value
        best_changes[name] = 100.0 * (best.verified[name] - value) / value
        print(f"  {name:<16} {value:10.4g} -> optimum {optimum.verified[name]:10.4g} ({changes[name]:+6.1f} %), best case "
              f"{best.verified[name]:10.4g} ({best_changes[name]:+6.1f} %)   paper: {PAPER_CHANGES[name]:+.1f} %")
    return {"dataset": dataset, "optimum": optimum, "best": best, "baseline": before, "changes": changes,
            "best_changes": best_changes}


def run_variants(t_end: float) -> dict[str, jp.Results]:
    """Each variant of :data:`VARIANTS` built with its defaults and run to ``t_end`` [s]."""
    return {variant: simulate(build_model(variant), t_end) for variant in VARIANTS}


def print_table(runs: dict[str, jp.Results]) -> None:
    """The table of :func:`table`, one line per variant."""
    print(f"{'variant':<10} {'peak |a| [m/s^2]':>17} {'peak F_H [N]':>13} {'travel [mm]':>12}")
    for row in table(runs):
        print(f"{row['variant']:<10} {row['peak_acceleration']:17.4g} {row['peak_force_H']:13.4g} "
              f"{1e3 * row['travel_end']:12.3f}")


def main(argv: list[str] | None = None) -> dict[str, jp.Results]:
    """Run the three variants, print their table and, with ``--out``, draw :data:`FIGURES`."""
    args = parser().parse_args(argv)
    if args.study:
        return run_study(args)
    if args.save_model is not None:
        print(f"wrote {save_variant(args.save_model)}")
        return {}
    runs = run_variants(QUICK_T_END if args.quick else args.t_end)
    print_table(runs)
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        for stem, variants in FIGURES.items():
            print(f"wrote {figure({v: runs[v] for v in variants}, args.out / f'{stem}.png')}")
    return runs


if __name__ == "__main__":
    main()
