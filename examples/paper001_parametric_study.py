"""Paper 001's parametric study of a lubricated slider-crank, as one command.

The slider-crank of ``paper001_slider_crank_dry.py`` with its rod/slider
joint lubricated, in three series (two crank revolutions each):

- clearance 0.1 / 0.3 / 0.5 / 1 mm at 500 rpm and 400 cP;
- crank speed 300 / 500 / 800 / 1000 rpm at 0.5 mm and 400 cP;
- viscosity 400 / 300 / 180 cP at 0.5 mm and 500 rpm.

The nine distinct cases run as one study (``jointplay.Study`` around the
model built here, an explicit table of clearance, crank speed, viscosity,
end time and output step; ``--workers N`` runs them on N processes). The
minimum film is the one tracked at every step, the peak force likewise.
Writes, per series, the slider acceleration, the joint reaction force and
the minimum film thickness against crank angle, a table of the minimum
film thickness per case (Markdown and CSV), and the study's Dataset
(``paper001_study.nc``).

CHOSEN here (paper 001's joint table did not survive): the geometry of the
dry example (bearing radius 10 mm, length 40 mm, so L/D = 2, a long
bearing); the Pinkus-Sternlicht infinitely long bearing (the positive part
of the Sommerfeld pressure), which agrees with the finite-difference Reynolds
solver in mixed squeeze and wedge motion (docs/theory/lubrication-validation.md); paper 001's transition to contact from the safe film
thickness 0.00015 D; the dry contact and friction laws of the dry example;
no gravity (the paper states none, and its trends concern the inertial
loading: with gravity along -y the rod's weight dominates the joint load at
300 rpm and the film there comes out thinner than at 500 rpm). These are not
the paper's numbers; the trends are what the study shows. The film at
c = 0.1 mm cannot be thicker than 0.1 mm, so across clearances the relative
film h_min / c is the fair comparison (it is in the table).

Run: python examples/paper001_parametric_study.py [--out DIR] [--revolutions N] [--workers N]
"""

from __future__ import annotations

import argparse
import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np

import jointplay as jp
from jointplay import functions as fn
from jointplay import laws
from paper001_slider_crank_dry import build_model as build_dry_model

FILM_MODEL = "pinkus_sternlicht_long"  # chosen: L/D = 2; checked against the Reynolds solver in mixed squeeze and wedge


@dataclass(frozen=True)
class Case:
    """One run of the study."""

    clearance: float  # m
    speed_rpm: float  # rev/min
    viscosity_cp: float  # cP

    @property
    def label(self) -> str:
        return f"c = {self.clearance * 1e3:g} mm, {self.speed_rpm:g} rpm, {self.viscosity_cp:g} cP"


SERIES = {
    "clearance": [Case(c, 500, 400) for c in (0.1e-3, 0.3e-3, 0.5e-3, 1.0e-3)],
    "speed": [Case(0.5e-3, n, 400) for n in (300, 500, 800, 1000)],
    "viscosity": [Case(0.5e-3, 500, mu) for mu in (400, 300, 180)],
}


def build_model(case: Case) -> jp.Model:
    """The lubricated paper 001 slider-crank for one case."""
    model = build_dry_model(clearance=case.clearance, crank_speed=fn.rpm(case.speed_rpm))
    model.joint("B")["lubrication"] = laws.lubrication(FILM_MODEL, laws.centipoise(case.viscosity_cp))
    model.set_gravity((0.0, 0.0))  # chosen, see the module docstring
    model._spec["name"] = "paper001_slider_crank_lubricated"
    return model


def cases() -> list[Case]:
    """Every distinct case of the three series, in series order (a case shared by series runs once)."""
    return list(dict.fromkeys(case for series in SERIES.values() for case in series))


def end_time(case: Case, revolutions: float) -> float:
    """``revolutions`` crank turns at the case's speed [s]."""
    return revolutions * 60.0 / case.speed_rpm


def crank_angle_at_film_min(results) -> float:
    """Crank angle [deg, 0-360] at the thinnest sampled film (a user response of the study)."""
    k = int(np.argmin(results["B.film_min"]))
    return float(np.degrees(results["crank.angle"][k]) % 360.0)


def build_study(revolutions: float = 2.0):
    """The three series as one study: a table of the distinct cases over clearance, crank speed, viscosity,
    end time (``revolutions`` turns at the case's speed) and output step (720 samples per turn)."""
    from jointplay.study import Study
    from jointplay.study.metrics import Response

    ends = [end_time(c, revolutions) for c in cases()]
    steps = [60.0 / c.speed_rpm / 720 for c in cases()]
    factors = [{"name": "clearance", "path": "joints.B.clearance", "range": ["0.1 mm", "1 mm"]},
               {"name": "speed", "path": "drivers.motor.function.rate", "range": ["300 rpm", "1000 rpm"]},
               {"name": "viscosity", "path": "joints.B.lubrication.viscosity", "range": ["180 cP", "400 cP"]},
               {"name": "t_end", "path": "simulation.t_end", "range": [f"{min(ends)!r} s", f"{max(ends)!r} s"]},
               {"name": "output_step", "path": "simulation.output_step",
                "range": [f"{min(steps)!r} s", f"{max(steps)!r} s"]}]
    rows = [[f"{c.clearance!r} m", f"{c.speed_rpm!r} rpm", f"{c.viscosity_cp!r} cP", f"{end!r} s", f"{step!r} s"]
            for c, end, step in zip(cases(), ends, steps, strict=True)]
    responses = [{"name": "film_min", "kind": "min_film", "joint": "B"},
                 {"name": "peak_force", "kind": "peak", "channel": "B.f"},
                 {"name": "contact_fraction", "kind": "contact_fraction", "joint": "B"},
                 Response.from_callable("crank_angle_at_film_min", crank_angle_at_film_min, units="deg")]
    return Study(build_model(SERIES["clearance"][0]), factors, {"kind": "table", "rows": rows}, responses,
                 t_end=max(ends), options={"rtol": 1e-7, "atol": 1e-10, "max_step": "0.1 ms"},
                 channels=["crank.angle", "slider.ax", "B.f", "B.film_min"],
                 channel_step=min(steps), name="paper001_parametric_study")


def run_study(revolutions: float = 2.0, workers: int = 1, folder: Path | None = None):
    """The study's Dataset (one case per distinct case of the series; ``folder`` keeps it resumable)."""
    return build_study(revolutions).run(folder, workers=workers, resume=folder is not None)


def series_cases(dataset) -> dict[str, list[tuple[Case, int]]]:
    """Each series' cases with their index in the study's Dataset."""
    index = {case: k for k, case in enumerate(cases())}
    assert dataset.sizes["case"] == len(index)
    return {name: [(case, index[case]) for case in series] for name, series in SERIES.items()}


def minimum_film_table(dataset) -> list[dict]:
    """One row per case and series: minimum film thickness [m] and where (crank angle [deg])."""
    rows = []
    for series, members in series_cases(dataset).items():
        for case, k in members:
            film = float(dataset["film_min"].values[k])
            rows.append({"series": series, "clearance_mm": case.clearance * 1e3, "speed_rpm": case.speed_rpm,
                         "viscosity_cP": case.viscosity_cp, "film_min_um": film * 1e6,
                         "film_min_over_clearance": film / case.clearance,
                         "crank_angle_deg": float(dataset["crank_angle_at_film_min"].values[k]),
                         "peak_force_N": float(dataset["peak_force"].values[k]),
                         "contact_fraction": float(dataset["contact_fraction"].values[k])})
    return rows


def write_figures(dataset, out: Path) -> list[Path]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    paths = []
    for series, members in series_cases(dataset).items():
        fig, axes = plt.subplots(3, 1, figsize=(8, 10), sharex=True)
        for case, k in members:
            run = dataset.isel(case=k)
            angle = np.degrees(run["crank.angle"].values)
            axes[0].plot(angle, run["slider.ax"].values, lw=0.8, label=case.label)
            axes[1].plot(angle, run["B.f"].values, lw=0.8)
            axes[2].plot(angle, run["B.film_min"].values * 1e6, lw=0.8)
        axes[0].set_ylabel("slider acceleration [m/s^2]")
        axes[1].set_ylabel("joint reaction force [N]")
        axes[2].set_ylabel("minimum film thickness [um]")
        axes[2].set_xlabel("crank angle [deg]")
        axes[0].legend(fontsize=8)
        for ax in axes:
            ax.grid(alpha=0.3)
        fig.suptitle(f"paper 001 slider-crank, lubricated joint: {series} series")
        fig.tight_layout()
        path = out / f"paper001_{series}.png"
        fig.savefig(path, dpi=120)
        plt.close(fig)
        paths.append(path)
    return paths


def write_table(rows: list[dict], out: Path) -> list[Path]:
    csv_path, md_path = out / "paper001_film_min.csv", out / "paper001_film_min.md"
    with csv_path.open("w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    md_path.write_text(markdown_table(rows) + "\n")
    return [csv_path, md_path]


def markdown_table(rows: list[dict]) -> str:
    lines = ["| series | clearance [mm] | speed [rpm] | viscosity [cP] | h_min [um] | h_min / c | at crank angle [deg] | peak force [N] | contact fraction |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['series']} | {r['clearance_mm']:g} | {r['speed_rpm']:g} | {r['viscosity_cP']:g} | "
                     f"{r['film_min_um']:.3f} | {r['film_min_over_clearance']:.3f} | {r['crank_angle_deg']:.1f} | {r['peak_force_N']:.1f} | {r['contact_fraction']:.3f} |")
    return "\n".join(lines)


def main(argv: list[str] | None = None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("out/paper001_study"))
    parser.add_argument("--revolutions", type=float, default=2.0)
    parser.add_argument("--workers", type=int, default=1, help="local worker processes running the cases")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    dataset = run_study(args.revolutions, args.workers)
    rows = minimum_film_table(dataset)
    print(markdown_table(rows))
    from jointplay.study.dataset import save

    for path in write_figures(dataset, args.out) + write_table(rows, args.out) + [save(dataset, args.out / "paper001_study.nc")]:
        print(f"wrote {path}")
    return dataset, rows


if __name__ == "__main__":
    main()
