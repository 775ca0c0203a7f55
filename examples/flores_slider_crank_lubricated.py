"""The Flores-Ambrosio slider-crank with its rod/slider joint lubricated at
400 cP, next to the dry joint.

Same mechanism as ``flores_slider_crank_dry.py`` (5000 rpm, radial clearance
0.5 mm, bore radius 10 mm, length 40 mm, so L/D = 2). The film is the
Pinkus-Sternlicht infinitely long bearing (chosen for L/D = 2; it agrees with
the Reynolds solver in mixed squeeze and wedge motion; ``--film`` picks
another model, e.g. ``reynolds_table``), handed over to
the dry contact of the dry example by paper 001's transition law from the
safe film thickness (0.00015 D) to contact. Two crank revolutions; prints
peak slider acceleration, peak joint force and minimum film thickness of
both joints, and writes the comparison figure.

Run: python examples/flores_slider_crank_lubricated.py [--out DIR] [--film MODEL] [--revolutions N]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

import jointplay as jp
from flores_slider_crank_dry import build_model as build_dry_model
from flores_slider_crank_dry import revolutions_to_time, simulate
from jointplay import laws

VISCOSITY = laws.centipoise(400.0)  # Pa s
LUBRICATED_METHOD = "bdf"  # as in examples/flores_slider_crank_lubricated.toml
LUBRICATED_TOLERANCES = {"rtol": 3e-7, "atol": 3e-10}  # as there (why: see the model file's [simulation])


def build_model(film: str = "pinkus_sternlicht_long", viscosity: float = VISCOSITY) -> jp.Model:
    """The Flores slider-crank with joint B lubricated by ``film`` at ``viscosity`` [Pa s]."""
    model = build_dry_model()
    model.joint("B")["lubrication"] = laws.lubrication(film, viscosity)
    model._spec["name"] = "flores_slider_crank_lubricated"
    return model


def joint_force(results: jp.Results) -> np.ndarray:
    """Magnitude of the force in joint B: film plus dry contact [N]."""
    return results["B.f"]


def compare(revolutions: float = 2.0, film: str = "pinkus_sternlicht_long") -> dict[str, jp.Results]:
    """Dry and lubricated runs on one output grid (720 samples per revolution); the dry run with
    Dormand-Prince (impacts), the lubricated one with the implicit method (the squeeze film is stiff:
    about 7x faster at the same accuracy, docs/performance.md)."""
    grid = revolutions_to_time(1.0) / 720
    return {"dry": simulate(build_dry_model(), revolutions, output_step=grid),
            "lubricated": simulate(build_model(film), revolutions, output_step=grid, method=LUBRICATED_METHOD,
                                   **LUBRICATED_TOLERANCES)}


def write_figure(runs: dict[str, jp.Results], path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    for label, results in runs.items():
        angle = np.degrees(results["crank.angle"])
        axes[0].plot(angle, results["slider.ax"], lw=0.8, label=label)
        axes[1].plot(angle, joint_force(results), lw=0.8)
        axes[2].plot(angle, 1e6 * np.hypot(results["B.ex"], results["B.ey"]), lw=0.8)
    axes[0].set_ylabel("slider acceleration [m/s^2]")
    axes[1].set_ylabel("force in joint B [N]")
    axes[2].set_ylabel("|e| [um] (clearance 500 um)")
    axes[2].set_xlabel("crank angle [deg]")
    axes[0].legend()
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.suptitle("Flores slider-crank: dry vs lubricated joint B (400 cP)")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def main(argv: list[str] | None = None) -> dict[str, jp.Results]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=None, help="folder for the figure and the NetCDF files")
    parser.add_argument("--film", default="pinkus_sternlicht_long", choices=laws.FILM_MODELS)
    parser.add_argument("--revolutions", type=float, default=2.0)
    args = parser.parse_args(argv)
    runs = compare(args.revolutions, args.film)
    print("| joint B | peak slider acceleration [m/s^2] | peak joint force [N] | impacts | min film [um] | wall time [s] |")
    print("|---|---:|---:|---:|---:|---:|")
    for label, results in runs.items():
        film = results.get("B.film_min")
        film_text = f"{1e6 * np.min(film):.2f}" if film is not None else "-"
        print(f"| {label} | {np.max(np.abs(results['slider.ax'])):.4g} | {np.max(joint_force(results)):.4g} | "
              f"{results.diagnostics['impacts'][0]} | {film_text} | {results.wall_time:.3f} |")
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        for label, results in runs.items():
            results.save(args.out / f"flores_{label}.nc")
        print(f"wrote {write_figure(runs, args.out / 'flores_dry_vs_lubricated.png')}")
    return runs


if __name__ == "__main__":
    main()
