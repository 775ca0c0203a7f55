"""A boom raised by a hydraulic cylinder through a valve, with paper 002's seal friction.

A uniform rigid boom, 2 m and 200 kg, is pinned to the ground at O and starts
horizontal. A double-acting cylinder, bore 63 mm and rod 35 mm, stroke 500 mm,
pushes from the ground point C = (0.3, -0.8) m to the point R of the boom,
0.6 m from the pin. A valve feeds the cap chamber and lets the rod chamber's
oil back to tank: it opens smoothly from 0.5 s, is fully open from 1.25 s to
2.75 s (the piston commanded to 36 mm/s, 6.7 L/min into the cap chamber) and
closed again at 3.5 s; the run goes on to 4.5 s with the valve closed. Gravity
is on. The seal friction is paper 002's (static 385 N, kinetic 340 N; LuGre
law with the chosen bristle dynamics of docs/theory/friction-lugre.md).

CHOSEN here (plausible for a small crane or loader arm, not from a paper):
every value except the two seal forces; the model file
examples/hydraulic_boom.toml says why each is what it is. The cylinder's law:
docs/theory/hydraulic-cylinder.md.

What to look at: the boom starts at rest, held by the oil and the sticking
seal; the seal breaks away as the valve opens, the cap pressure rises by the
friction and the boom's changing lever, and the boom stops, with the seal
sticking again, once the valve has closed.

Run: python examples/hydraulic_boom.py [--out DIR]
(--out: writes the results as NetCDF and a figure of the pressures, stroke and seal into DIR)
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

import jointplay as jp
from jointplay import functions as fn
from jointplay import laws

T_END = 4.5  # s
#: The valve's schedule: knots 0.25 s apart and its opening there in sixths of full opening. A sum of
#: cubic B-splines takes 1/6, 5/6, 1 at the knots of each ramp, and the natural spline of a table
#: through these values is exactly that sum: smooth, never negative, zero outside [0.5, 3.5] s.
KNOT_SPACING = 0.25  # s
OPENING = (0, 0, 0, 1, 5, 6, 6, 6, 6, 6, 6, 6, 5, 1, 0, 0, 0, 0, 0)
#: Flows at 1/6, 5/6 and full opening: A1 and -A2 times the commanded piston speed of 36 mm/s.
CAP_FLOW = {1: "18.702 cm^3/s", 5: "93.51 cm^3/s", 6: "112.212 cm^3/s"}
ROD_FLOW = {1: "-12.93 cm^3/s", 5: "-64.65 cm^3/s", 6: "-77.58 cm^3/s"}
COMMANDED_SPEED = 0.036  # m/s, fully open
#: The stroke the valve commands: the speed times the integral of the opening, KNOT_SPACING per
#: B-spline (9 of them) [m].
COMMANDED_STROKE = COMMANDED_SPEED * KNOT_SPACING * 9
#: The channels the figure draws, one panel each.
FIGURE_CHANNELS = ("lift.p_cap", "lift.p_rod", "lift.stroke", "lift.rate", "lift.friction", "lift.stick")


def valve(flows: dict[int, str]) -> dict:
    """The flow through one port over time: a table on the valve's knots."""
    times = [k * KNOT_SPACING for k in range(len(OPENING))]
    return fn.table(times, [flows.get(level, 0.0) for level in OPENING])


def build_model() -> jp.Model:
    """The boom and its cylinder at the start. The same model, bit for bit, as
    examples/hydraulic_boom.toml."""
    m = jp.Model("hydraulic_boom", gravity=(0.0, -9.81))
    m.add_ground_point("O", (0.0, 0.0))
    m.add_ground_point("C", (0.3, -0.8))
    # uniform boom: inertia m L^2 / 12 about its centre
    m.add_body("boom", mass=200.0, inertia=66.67, position=(1.0, 0.0),
               points={"O": (-1.0, 0.0), "R": (-0.4, 0.0), "tip": (1.0, 0.0)})
    m.add_revolute("pivot", "ground.O", "boom.O")
    # 63/35 mm cylinder; 10 bar of back pressure, and the cap pressure that carries the boom:
    # p_cap A1 - p_rod A2 = 3492.4 N, 1962 N m of weight on the cylinder's lever of 0.5618 m
    m.add_hydraulic_cylinder("lift", "ground.C", "boom.R", piston_area="31.17 cm^2", rod_side_area="21.55 cm^2",
                             stroke_length="500 mm", cap_dead_volume="0.1 L", rod_dead_volume="0.1 L",
                             initial_stroke="100 mm", cap_pressure="18.118 bar", rod_pressure="10 bar",
                             bulk_modulus="1.5 GPa", seal_friction=laws.lugre_seal(static_force=385.0,
                                                                                   kinetic_force=340.0),
                             cap_inflow=valve(CAP_FLOW), rod_inflow=valve(ROD_FLOW))
    return m


def simulate(model: jp.Model, t_end: float = T_END) -> jp.Results:
    """Runs the model (rtol 1e-8, atol 1e-10, samples every ms), as the model file's [simulation]."""
    return model.simulate(t_end, method="dopri5", rtol=1e-8, atol=1e-10, output_step=1e-3)


def stick_periods(results: jp.Results) -> list[tuple[float, float]]:
    """The (start, end) times [s] of the periods in which the seal sticks."""
    t, stick = results.time, results["lift.stick"] > 0.5
    edges = np.flatnonzero(np.diff(stick.astype(int))) + 1
    starts = [0, *edges[~stick[edges - 1]]] if stick[0] else list(edges[~stick[edges - 1]])
    ends = list(edges[stick[edges - 1]]) + ([len(t) - 1] if stick[-1] else [])
    return [(float(t[a]), float(t[b])) for a, b in zip(starts, ends)]


def report(results: jp.Results) -> str:
    """A few lines on what happened: stroke and boom angle, pressures, the seal's stick periods."""
    stroke, angle = results["lift.stroke"], results["boom.angle"]
    p_cap, p_rod = results["lift.p_cap"] / 1e5, results["lift.p_rod"] / 1e5  # bar
    periods = ", ".join(f"{a:.3f}-{b:.3f} s" for a, b in stick_periods(results))
    return "\n".join([
        f"{results}",
        f"stroke {stroke[0] * 1e3:.1f} -> {stroke[-1] * 1e3:.1f} mm (the valve commands "
        f"{COMMANDED_STROKE * 1e3:.1f} mm); boom raised {math.degrees(angle[-1] - angle[0]):.2f} deg",
        f"cap pressure {p_cap[0]:.2f} -> {p_cap[-1]:.2f} bar (highest {p_cap.max():.2f}), "
        f"rod pressure {p_rod[0]:.2f} -> {p_rod[-1]:.2f} bar (lowest {p_rod.min():.2f})",
        f"seal sticking: {periods}; largest friction {np.max(np.abs(results['lift.friction'])):.1f} N"])


def main(argv: list[str] | None = None) -> jp.Results:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=None, help="folder for the figure and the NetCDF file")
    out = parser.parse_args(argv).out
    results = simulate(build_model())
    print(report(results))
    if out is not None:
        from jointplay import plots

        results.save(plots.figure_folder(out) / "hydraulic_boom.nc")
        print(f"wrote {plots.time_histories(results, FIGURE_CHANNELS, out / 'hydraulic_boom.png')}")
    return results


if __name__ == "__main__":
    main()
