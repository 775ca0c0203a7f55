"""A double parallelogram: three parallel bars under one coupler, a redundant constraint everywhere.

The parallelogram four-bar of ``parallelogram_four_bar.py`` (IFToMM
benchmark A02 with one window) with a third parallel bar. The layout is
chosen here, not a benchmark's: ground pins A0, A1, A2 at x = 0, 1, 2 m;
bars left A0-B0, middle A1-B1 and right A2-B2, each 1 m and 1 kg (uniform,
inertia m L^2/12 about the centre); one coupler B0-B1-B2 of 2 m and 2 kg
(the bars' 1 kg/m; inertia 2/3 kg m^2), pinned to the three bar tops at its
ends and its middle. Gravity 9.81 m/s^2 along -y; no driver. The bars start
vertical, the coupler horizontal at y = 1 m, the tops moving along +x at
1 m/s (bars at -1 rad/s), as in the four-bar.

Twelve coordinates, six pins of two equations: only eleven equations are
independent at any configuration (the middle bar moves exactly as the outer
two let it), so the mechanism has one degree of freedom although counting
says none, and the statics cannot say how the load is shared between the
three ground pins: any split with the right total balances it. A solver must
choose; the least-norm multipliers share it equally between identical bars.

Equation of motion on the parallelogram branch (bars at angle theta from +x,
coupler translating): T = (1/2)(3 m L^2/3 + 2 m L^2) theta_dot^2 =
(3/2) m L^2 theta_dot^2, V = 3 m g (L/2) sin(theta) + 2 m g L sin(theta) =
(7/2) m g L sin(theta), so

    theta_ddot = -(7 g / (6 L)) cos(theta).

Like the four-bar, it turns clockwise for ever and lies flat on the ground
line twice per turn, where the Jacobian loses one more rank.

Run: python examples/double_parallelogram.py [--out DIR] [--t-end SECONDS]
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

import jointplay as jp
from parallelogram_four_bar import CRANK_SPEED, GRAVITY, INERTIA, LENGTH, MASS, energy_report, run_example
from parallelogram_four_bar import flat_passages as bar_flat_passages

COUPLER_MASS = 2 * MASS  # kg: a 2 m bar of the same section
COUPLER_INERTIA = COUPLER_MASS * (2 * LENGTH)**2 / 12  # kg m^2
BARS = {"left": ("A0", "B0"), "middle": ("A1", "B1"), "right": ("A2", "B2")}


def build_model() -> jp.Model:
    """The double parallelogram at its start; the same model, bit for bit, as
    examples/double_parallelogram.toml."""
    half, v = LENGTH / 2, -CRANK_SPEED * LENGTH  # speed of the bar tops along +x [m/s]
    m = jp.Model("double_parallelogram", gravity=(0.0, -GRAVITY))
    for k, (ground, _) in enumerate(BARS.values()):
        m.add_ground_point(ground, (k * LENGTH, 0.0))
    for k, (bar, (ground, top)) in enumerate(BARS.items()):
        m.add_body(bar, mass=MASS, inertia=INERTIA, position=(k * LENGTH, half), angle=math.pi / 2,
                   velocity=(v / 2, 0.0), angular_velocity=CRANK_SPEED, points={ground: (-half, 0.0), top: (half, 0.0)})
    m.add_body("coupler", mass=COUPLER_MASS, inertia=COUPLER_INERTIA, position=(LENGTH, LENGTH), velocity=(v, 0.0),
               points={top: ((k - 1) * LENGTH, 0.0) for k, (_, top) in enumerate(BARS.values())})
    for bar, (ground, _) in BARS.items():
        m.add_revolute(ground, f"ground.{ground}", f"{bar}.{ground}")
    for bar, (_, top) in BARS.items():
        m.add_revolute(top, f"{bar}.{top}", f"coupler.{top}")
    return m


def flat_passages(results: jp.Results) -> int:
    """How many times the left bar passed the ground line."""
    return bar_flat_passages(results, "left")


def write_figure(results: jp.Results, path: Path) -> Path:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8, 7), layout="constrained")
    FigureCanvasAgg(fig)
    angle, forces = fig.subplots(2, 1, sharex=True)
    t = results.time
    for bar in BARS:
        angle.plot(t, np.degrees(np.unwrap(results[f"{bar}.angle"])), label=bar)
    angle.set_ylabel("bar angle [deg]")
    angle.legend()
    for bar, (ground, _) in BARS.items():
        forces.plot(t, results[f"{ground}.fy"], label=f"{ground} ({bar})")
    total = sum(results[f"{ground}.fy"] for ground, _ in BARS.values())
    forces.plot(t, total, "k", lw=0.8, label="sum")
    forces.set_ylabel("vertical force of the ground\non each bar [N]")
    forces.set_xlabel("time [s]")
    forces.legend(fontsize=8)
    for ax in (angle, forces):
        ax.grid(alpha=0.3)
    fig.suptitle("double parallelogram: a redundant bar; the pins' shares are the solver's choice, the sum is not")
    fig.savefig(path, dpi=120)
    return path


def report(results: jp.Results) -> str:
    return f"flat positions passed: {flat_passages(results)}, {energy_report(results)}"


def main(argv: list[str] | None = None) -> jp.Results:
    return run_example(argv, "double_parallelogram", __doc__, build_model, report, write_figure)


if __name__ == "__main__":
    main()
