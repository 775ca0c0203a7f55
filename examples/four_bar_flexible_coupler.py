"""A crank-rocker four-bar whose coupler is a triangular frame from another finite-element code, read as a
modal body from its Matrix Market and CSV files, beside the same coupler rigid.

The coupler's files (examples/data/coupler.*) hold the mass and stiffness matrices of a triangle of
aluminium strips in millimetres, tonnes and seconds: a base of 240 mm from pin A (node 0) to pin B (node
6) and an apex C (node 8) 80 mm above its middle, 10 frame elements. Here they were written by the
Euler-Bernoulli frame elements of tests/physics/reference_frame_elements.py, standing in for the other
code. The rigid coupler has the mass, centre of mass and inertia of the same mass matrix (its rigid
motions), so the two runs differ only by the coupler's elasticity.

Chosen here (no paper behind it): crank 60 mm, ground 190 mm, rocker 180 mm; strips 20 mm wide and 8 mm
deep in the plane (E = 70 GPa, 2700 kg/m^3); crank and rocker rigid (0.2 kg, 1e-4 kg m^2; 0.15 kg,
4e-4 kg m^2); the crank spun up to 150 rad/s in 50 ms; 4 fixed-interface modes, 2 % modal damping.

Run: python examples/four_bar_flexible_coupler.py [--out DIR] [--time T]
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np
import scipy.io

import jointplay as jp
from jointplay import functions as fn

DATA = Path(__file__).resolve().parent / "data"
FILES = {"mass": str(DATA / "coupler.mass.mtx"), "stiffness": str(DATA / "coupler.stiffness.mtx"),
         "nodes": str(DATA / "coupler.nodes.csv")}
CRANK, GROUND, ROCKER = 0.06, 0.19, 0.18  # m
A_NODE, B_NODE, C_NODE = 0, 6, 8
SPEED, RAMP = 150.0, 0.05  # rad/s, s


def coupler_pose() -> tuple[tuple[float, float], float]:
    """Pin A [m] and the coupler's angle [rad] with the crank along x (the base AB closes the loop)."""
    base = 0.24
    a = (CRANK, 0.0)
    d = GROUND - CRANK  # from A to the rocker's pivot
    along = (base**2 - ROCKER**2 + d**2) / (2 * d)
    return a, math.atan2(math.sqrt(base**2 - along**2), along)


def rigid_coupler() -> tuple[float, float, np.ndarray]:
    """Mass [kg], inertia about the centre of mass [kg m^2] and the nodes [m] relative to the centre of mass,
    in the coupler's axes, from the files' mass matrix (mm, t: x 1e3 kg, x 1e-3 m per rotation coordinate)."""
    mass = scipy.io.mmread(FILES["mass"]).toarray()
    nodes = np.loadtxt(FILES["nodes"], delimiter=",") * 1e-3
    per_rotation = np.kron(np.ones(len(nodes)), [1.0, 1.0, 1e-3])
    mass = 1e3 * mass * np.outer(per_rotation, per_rotation)
    along_x, along_y = np.kron(np.ones(len(nodes)), [1, 0, 0]), np.kron(np.ones(len(nodes)), [0, 1, 0])
    turn = np.column_stack([-nodes[:, 1], nodes[:, 0], np.ones(len(nodes))]).ravel()
    m = along_x @ mass @ along_x
    centre = np.array([along_y @ mass @ turn, -(along_x @ mass @ turn)]) / m
    inertia = turn @ mass @ turn - m * centre @ centre
    return m, inertia, nodes - centre


def build_model(flexible: bool = True) -> jp.Model:
    model = jp.Model("four_bar_" + ("flexible" if flexible else "rigid") + "_coupler", gravity=(0, 0))
    model.add_ground_point("O2", (0, 0))
    model.add_ground_point("O4", (GROUND, 0))
    model.add_body("crank", mass=0.2, inertia=1e-4, position=(CRANK / 2, 0),
                   points={"O": (-CRANK / 2, 0), "A": (CRANK / 2, 0)})
    a, angle = coupler_pose()
    c, s = math.cos(angle), math.sin(angle)
    if flexible:
        model.add_modal_body("coupler", matrices={**FILES, "length_unit": "mm", "mass_unit": "t"},
                             position=a, angle=angle, interface={"A": A_NODE, "B": B_NODE},
                             points={"C": C_NODE}, normal_modes=4, damping_ratio=0.02)
    else:
        m, inertia, nodes = rigid_coupler()
        centre = -nodes[A_NODE]  # from A, in the coupler's axes
        model.add_body("coupler", mass=m, inertia=inertia, angle=angle,
                       position=(a[0] + c * centre[0] - s * centre[1], a[1] + s * centre[0] + c * centre[1]),
                       points={name: tuple(nodes[k]) for name, k in (("A", A_NODE), ("B", B_NODE), ("C", C_NODE))})
    b = (a[0] + 0.24 * c, a[1] + 0.24 * s)
    pivot_to_b = (b[0] - GROUND, b[1])
    model.add_body("rocker", mass=0.15, inertia=4e-4, position=(GROUND + pivot_to_b[0] / 2, pivot_to_b[1] / 2),
                   angle=math.atan2(pivot_to_b[1], pivot_to_b[0]),
                   points={"O": (-ROCKER / 2, 0), "B": (ROCKER / 2, 0)})
    model.add_revolute("O2", "ground.O2", "crank.O")
    model.add_revolute("A", "crank.A", "coupler.A")
    model.add_revolute("B", "coupler.B", "rocker.B")
    model.add_revolute("O4", "ground.O4", "rocker.O")
    model.add_driver("motor", "O2", fn.speed_ramp(SPEED, RAMP))
    return model


def main(argv: list[str] | None = None) -> dict[str, jp.Results]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("."), help="folder for the figure")
    parser.add_argument("--time", type=float, default=0.15, help="simulated time [s]")
    args = parser.parse_args(argv)
    runs = {}
    for flexible in (False, True):
        model = build_model(flexible)
        runs["flexible" if flexible else "rigid"] = model.simulate(args.time, method="dopri5", rtol=1e-7,
                                                                   atol=1e-10, output_step=2e-4)
    rigid, flexible = runs["rigid"], runs["flexible"]
    held = next(b for b in build_model().check()["bodies"] if b["name"] == "coupler")["held_frequencies"]
    lag = np.interp(rigid.time, flexible.time, flexible["rocker.angle"]) - rigid["rocker.angle"]
    print(f"coupler from matrices: lowest frequencies held {', '.join(f'{f:.0f}' for f in held[:3])} Hz")
    print(f"rocker angle, flexible less rigid: largest {1e3 * np.max(np.abs(lag)):.3f} mrad")
    for name, r in runs.items():
        force = np.hypot(r["B.fx"], r["B.fy"])
        print(f"{name:9s} largest pin force at B {np.max(force):8.1f} N")
    args.out.mkdir(parents=True, exist_ok=True)
    figure(runs, lag, args.out / "four_bar_flexible_coupler.png")
    return runs


def figure(runs: dict[str, jp.Results], lag: np.ndarray, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    t = runs["rigid"].time
    top.plot(1e3 * t, 1e3 * lag)
    top.set_ylabel("rocker angle, flexible - rigid [mrad]")
    for name, r in runs.items():
        bottom.plot(1e3 * r.time, np.hypot(r["B.fx"], r["B.fy"]), label=f"{name} coupler")
    bottom.set_ylabel("pin force at B [N]")
    bottom.set_xlabel("time [ms]")
    bottom.legend()
    fig.suptitle("Four-bar: coupler from another code's matrices (modal body) and rigid\n"
                 f"crank spun up to {SPEED:g} rad/s in {1e3 * RAMP:g} ms", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
