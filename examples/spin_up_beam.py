"""The spin-up beam of Simo and Vu-Quoc (1986), built in Python: a flexible beam clamped to a hub
whose angle follows a smooth speed ramp to 6 rad/s over 15 s.

Beam data from Simo and Vu-Quoc (1986, Part II, §5.1): L = 10 m, EA = 2.8e7 N, GA = 1e7 N,
EI = 1.4e4 N m^2, rho A = 1.2 kg/m, rho I = 6e-4 kg m; undamped; no gravity. Chosen here: the hub's
mass and inertia (the prescribed rotation makes them irrelevant to the beam), the mesh of 4
quadratic elements, the root gauge's fibre at 50 mm, and the integration: generalized-alpha with a
10 ms step. The same model, bit for bit, as
examples/spin_up_beam.toml.

At a steady spin w a bar carries N(s) = rho A w^2 (L^2 - s^2) / 2, so its tip moves out by
rho A w^2 L^3 / (3 EA) and its root carries rho A w^2 L^2 / 2; the script compares the run with
both over the last 2 s, and draws the hub's rate, the tip's deflection seen from the hub, the
root's axial force and the deformed shapes.

Run: python examples/spin_up_beam.py [--out DIR] [--t-end SECONDS]
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

import jointplay as jp
from jointplay import functions as fn
from jointplay import sections

LENGTH, AXIAL, MASS_PER_LENGTH, FINAL_RATE = 10.0, 2.8e7, 1.2, 6.0  # m, N, kg/m, rad/s
#: generalized-alpha at 10 ms (docs/theory/integrator-generalized-alpha.md): the step follows the bending
#: (first clamped frequency 0.6 Hz), not the axial and shear vibrations, which it damps (rho_inf 0.9);
#: rtol and atol set where its Newton iterations stop
SIMULATION = {"t_end": 20.0, "method": "generalized_alpha", "step": 0.01, "spectral_radius": 0.9,
              "stabilization": "baumgarte", "rtol": 1e-5, "atol": 1e-7, "output_step": 0.02}


def build_model(elements: int = 4) -> jp.Model:
    """The hub, the clamped beam of ``elements`` quadratic elements, the ramp and the root gauge."""
    m = jp.Model("spin_up_beam", gravity=(0, 0))
    m.add_ground_point("O", (0, 0))
    m.add_body("hub", mass=1.0, inertia=1.0, points={"O": (0, 0)})
    m.add_beam("beam", (0, 0), (LENGTH, 0),
               section=sections.resultants(AXIAL, 1e7, 1.4e4, MASS_PER_LENGTH, 6e-4),
               order="quadratic", elements=elements, points={"middle": 0.5 * LENGTH})
    m.add_revolute("axis", "ground.O", "hub.O")
    m.add_fixed("clamp", "hub.O", "beam.start")
    m.add_driver("spin", "axis", fn.speed_ramp(FINAL_RATE, 15.0))
    m.add_strain_gauge("root", "beam.start", fibre=0.05)
    m.description = "Simo and Vu-Quoc's spin-up beam: L = 10 m, hub ramped to 6 rad/s over 15 s"
    m.simulation = dict(SIMULATION)
    return m


def tip_in_hub_frame(results: jp.Results) -> tuple[np.ndarray, np.ndarray]:
    """The tip's position seen from the hub [m]: along the hub's direction and across it."""
    x, y = _tip(results)
    angle = results["hub.angle"]
    return x * np.cos(angle) + y * np.sin(angle), -x * np.sin(angle) + y * np.cos(angle)


def _tip(results: jp.Results) -> tuple[np.ndarray, np.ndarray]:
    from jointplay.plots import beam_nodes

    x, y = beam_nodes(results, "beam")
    return x[:, -1], y[:, -1]


def steady_state(results: jp.Results, last: float = 2.0) -> dict:
    """Averages over the last ``last`` seconds (at 6 rad/s) against the closed forms of a spinning bar."""
    along, _ = tip_in_hub_frame(results)
    steady = results.time >= results.time[-1] - last
    w = FINAL_RATE
    return {"stretch": float(np.mean(along[steady] - LENGTH)),
            "stretch_closed_form": MASS_PER_LENGTH * w ** 2 * LENGTH ** 3 / (3 * AXIAL),
            "root_force": float(np.mean(results["root.axial_force"][steady])),
            "root_force_closed_form": 0.5 * MASS_PER_LENGTH * w ** 2 * LENGTH ** 2}


def figures(results: jp.Results, out: Path) -> list[Path]:
    """The hub's rate, the tip's deflection seen from the hub, the root's axial force; and the shapes."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from jointplay import plots

    out = plots.figure_folder(out)
    along, across = tip_in_hub_frame(results)
    closed = steady_state(results)
    t = results.time
    fig = Figure(figsize=(7.5, 7.0), layout="constrained")
    FigureCanvasAgg(fig)
    axes = fig.subplots(3, 1, sharex=True)
    axes[0].plot(t, results["hub.omega"], lw=1)
    axes[0].set_ylabel("hub rate [rad/s]")
    axes[1].plot(t, across * 1e3, lw=1)
    axes[1].set_ylabel("tip deflection\nacross the hub [mm]")
    axes[2].plot(t, results["root.axial_force"], lw=1, label="root gauge")
    axes[2].axhline(closed["root_force_closed_form"], color="k", ls="--", lw=0.8,
                    label="rho A w^2 L^2 / 2 at 6 rad/s")
    axes[2].set_ylabel("root axial force [N]")
    axes[2].legend(fontsize=7)
    axes[-1].set_xlabel("time [s]")
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.suptitle(f"Spin-up beam, {plots.sampling_note(results)}; stretch at 6 rad/s "
                 f"{closed['stretch'] * 1e3:.4g} mm (closed form {closed['stretch_closed_form'] * 1e3:.4g} mm)",
                 fontsize=9)
    paths = [out / "spin_up_beam.png"]
    fig.savefig(paths[0], dpi=130)
    beam = results.spec["beams"][0]
    paths.append(plots.deformed_shapes(results, beam, out / "spin_up_beam_shapes.png",
                                       times=[0.0, 3.0, 6.0, 9.0, 12.0, 15.0]))
    return paths


def main(argv: list[str] | None = None) -> jp.Results:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=None, help="folder for the figures and the NetCDF file")
    parser.add_argument("--t-end", type=float, default=SIMULATION["t_end"], help="end time [s]")
    args = parser.parse_args(argv)
    model = build_model()
    options = dict(model.simulation)
    options.pop("t_end")
    results = model.simulate(args.t_end, **options)
    print(results)
    if args.t_end >= 17.0:
        s = steady_state(results)
        print(f"tip stretch at 6 rad/s {s['stretch'] * 1e3:.4f} mm (closed form {s['stretch_closed_form'] * 1e3:.4f} mm); "
              f"root axial force {s['root_force']:.1f} N (closed form {s['root_force_closed_form']:.1f} N)")
    if args.out is not None:
        for path in figures(results, args.out):
            print(f"wrote {path}")
        results.save(args.out / "spin_up_beam.nc")
    return results


if __name__ == "__main__":
    main()
