"""A parallelogram four-bar passing its flat position: IFToMM benchmark A02 with one window.

The IFToMM library of computational benchmark problems (M. Gonzalez, D. Dopico,
U. Lugris, J. Cuadrado, "A benchmarking system for MBS simulation software:
problem standardization and performance measurement", Multibody System
Dynamics, 2006, pp. 179-190; problem A02, "N four-bar mechanism",
http://lim.ii.udc.es/mbsbenchmark/dist/A02/A02_specification.xml) chains N
parallelogram four-bars of 2N+1 links; when the links reach the horizontal
position the mechanism passes a singular configuration, where the number of
degrees of freedom jumps from 1 to N+1.

FROM THE BENCHMARK: links 1 m long with a uniformly distributed mass of 1 kg;
gravity 9.81 m/s^2 along -y; no friction, no driver; at the start the point
B0 (the top of the first vertical link) moves along +x at 1 m/s. The start
position is given only by the specification's figure, which we have not seen;
the two public implementations we read start with the vertical links upright
and the couplers horizontal, as here: the OpenSim one
(github.com/RehabEngGroup/MBSbenchmarksInOpenSim, src/A02-NFourBarMechanism:
N = 2, link speeds -1 rad/s) and a simEngine3D course driver (N = 2, first
link at -1 rad/s).

CHOSEN here: N = 1 (the benchmark's reference solution is for N = 40 and is
not used: the motion depends on N, theta_ddot = -(3(3N+1)/(2(4N+1))) (g/L)
cos(theta)); 10 s (the OpenSim rendering's length; the benchmark's is 20 s);
rtol 1e-8: at tighter tolerances jointplay's passage through the flat
position loses accuracy (docs/theory/planar-formulation.md, "Constraint solution").

The mechanism: ground pins A0 = (0, 0) and A1 = (1, 0) m; crank A0-B0 and
rocker A1-B1 vertical, coupler B0-B1 horizontal at y = 1 m. On the
parallelogram branch the coupler translates and crank and rocker turn by the
same angle theta (from +x), so with m and L equal for all three bars

    T = (1/2) (2 m L^2/3 + m L^2) theta_dot^2,   V = 2 m g L sin(theta),
    theta_ddot = -(6 g / (5 L)) cos(theta).

Started at theta = 90 deg with theta_dot = -1 rad/s it has energy to spare at
the top (theta_dot = -1 rad/s there again), so the crank turns clockwise for
ever and the bars lie on the ground line at theta = 0 and 180 deg, twice per
turn (ten times in the 10 s run, about 5 turns).

Run: python examples/parallelogram_four_bar.py [--out DIR] [--t-end SECONDS]
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

import jointplay as jp

LENGTH = 1.0  # m, every link and the ground link
MASS = 1.0  # kg, every link
INERTIA = MASS * LENGTH**2 / 12  # kg m^2, uniform bar about its centre
GRAVITY = 9.81  # m/s^2, along -y
CRANK_SPEED = -1.0  # rad/s: B0 moves along +x at 1 m/s
T_END = 10.0  # s


def build_model() -> jp.Model:
    """The four-bar at its start: crank and rocker vertical, coupler horizontal at y = L.
    The same model, bit for bit, as examples/parallelogram_four_bar.toml."""
    half, v = LENGTH / 2, -CRANK_SPEED * LENGTH  # speed of B0 along +x [m/s]
    m = jp.Model("parallelogram_four_bar", gravity=(0.0, -GRAVITY))
    m.add_ground_point("A0", (0.0, 0.0))
    m.add_ground_point("A1", (LENGTH, 0.0))
    m.add_body("crank", mass=MASS, inertia=INERTIA, position=(0.0, half), angle=math.pi / 2,
               velocity=(v / 2, 0.0), angular_velocity=CRANK_SPEED, points={"A0": (-half, 0.0), "B0": (half, 0.0)})
    m.add_body("coupler", mass=MASS, inertia=INERTIA, position=(half, LENGTH), velocity=(v, 0.0),
               points={"B0": (-half, 0.0), "B1": (half, 0.0)})
    m.add_body("rocker", mass=MASS, inertia=INERTIA, position=(LENGTH, half), angle=math.pi / 2,
               velocity=(v / 2, 0.0), angular_velocity=CRANK_SPEED, points={"A1": (-half, 0.0), "B1": (half, 0.0)})
    m.add_revolute("A0", "ground.A0", "crank.A0")
    m.add_revolute("B0", "crank.B0", "coupler.B0")
    m.add_revolute("B1", "coupler.B1", "rocker.B1")
    m.add_revolute("A1", "ground.A1", "rocker.A1")
    return m


def simulate(model: jp.Model, t_end: float = T_END) -> jp.Results:
    """Runs the model (rtol 1e-8, atol 1e-10, samples every 10 ms), as the model file's [simulation]."""
    return model.simulate(t_end, method="dopri5", rtol=1e-8, atol=1e-10, output_step=0.01)


def flat_passages(results: jp.Results, bar: str = "crank") -> int:
    """How many times `bar` passed the ground line (the sine of its angle changed sign)."""
    s = np.sign(np.sin(results[f"{bar}.angle"]))
    return int(np.count_nonzero(s[1:] * s[:-1] < 0))


def write_figure(results: jp.Results, path: Path) -> Path:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8, 8), layout="constrained")
    FigureCanvasAgg(fig)
    angles, branch, energy = fig.subplots(3, 1, sharex=True)
    t = results.time
    crank = np.unwrap(results["crank.angle"])
    angles.plot(t, np.degrees(crank), label="crank")
    angles.plot(t, np.degrees(np.unwrap(results["rocker.angle"])), "--", label="rocker")
    for k in range(int(np.floor(crank.min() / np.pi)), int(np.ceil(crank.max() / np.pi)) + 1):
        angles.axhline(180 * k, color="0.7", lw=0.6)  # flat positions
    angles.set_ylabel("angle [deg]\n(grey: flat positions)")
    angles.legend()
    branch.plot(t, np.degrees(results["coupler.angle"]), label="coupler angle")
    branch.plot(t, np.degrees(results["rocker.angle"] - results["crank.angle"]), label="rocker - crank")
    branch.set_ylabel("[deg]\n(0 on the parallelogram branch)")
    branch.legend()
    e = results["system.energy"]
    energy.plot(t, (e - e[0]) / abs(e[0]))
    energy.set_ylabel("relative energy change")
    energy.set_xlabel("time [s]")
    for ax in (angles, branch, energy):
        ax.grid(alpha=0.3)
    fig.suptitle("parallelogram four-bar (IFToMM A02, N = 1) through its flat position")
    fig.savefig(path, dpi=120)
    return path


def energy_report(results: jp.Results) -> str:
    """The largest relative change of the total energy, as the examples print it."""
    e = results["system.energy"]
    return f"largest relative energy change {np.max(np.abs(e - e[0])) / abs(e[0]):.2e}"


def run_example(argv: list[str] | None, name: str, description: str, build, report, figure) -> jp.Results:
    """The command line of the parallelogram examples: run ``build()`` to ``--t-end``, print the run and
    ``report(results)``; with ``--out``, save ``<name>.nc`` and ``figure(results, <name>.png)`` there."""
    parser = argparse.ArgumentParser(description=description.splitlines()[0])
    parser.add_argument("--out", type=Path, default=None, help="folder for the figure and the NetCDF file")
    parser.add_argument("--t-end", type=float, default=T_END, help="simulated time [s]")
    args = parser.parse_args(argv)
    results = simulate(build(), args.t_end)
    print(results)
    print(report(results))
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        results.save(args.out / f"{name}.nc")
        print(f"wrote {figure(results, args.out / f'{name}.png')}")
    return results


def report(results: jp.Results) -> str:
    return (f"flat positions passed: {flat_passages(results)}, "
            f"largest |coupler angle| {np.max(np.abs(results['coupler.angle'])):.2e} rad, {energy_report(results)}")


def main(argv: list[str] | None = None) -> jp.Results:
    return run_example(argv, "parallelogram_four_bar", __doc__, build_model, report, write_figure)


if __name__ == "__main__":
    main()
