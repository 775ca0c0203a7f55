"""Paper 000's four joint models on a spring-loaded slider-crank (rigid links).

After Liu & Lin (1990), who take the mechanism from Rogers & Andrews (1977,
after Haines 1980): a crank BC pinned to the ground at C, a coupler AB, a
slider at A, and a preloaded spring-damper on the slider. Released from rest,
the spring drives the crank clockwise; it is neither compressed nor stretched
when the crank has turned 106 degrees, and the crank swings between about
+150 and -150 degrees measured from the inner dead centre (it cannot make a
full turn). Joint B (coupler AB to crank BC) has the clearance, modelled four
ways, as in the paper:

- ``ideal``: a perfect pin;
- ``clearance``: dry contact-impact, Rogers-Andrews logarithmic stiffness
  (the paper's eq. 10), no friction (the paper neglects it);
- ``squeeze_film``: the clearance filled with lubricant that only squeezes
  (no wedge), switching to impact once the film is used up (the paper's
  Phelan model; see docs/theory/squeeze-film-phelan.md for what we use);
- ``hydrodynamic``: the finite-difference Reynolds equation with squeeze and
  wedge action, a circumferential groove at mid-length at the supply
  pressure, and the same switch to impact.

The output is the crank's angular velocity for the four models over the
paper's window, from release to the spring's neutral position (about 7 ms,
107 degrees of crank turn here; the crank would go on through the inner dead
centre to about -150 degrees, where the joint loads grow steeply).

FROM THE PAPER: radial clearance 0.0025 cm; journal diameter and length
0.64 cm; journal steel, bearing babbitt; Poisson's ratio 0.3; impact loss
factor 0.02; viscosity 0.07 P (7 cP); spring unloaded 106 degrees from the
initial position; swing of about +-150 degrees; groove at mid-length with
supply pressure; switch from film to impact when the film is used up.

CHOSEN here (our copy of the paper gives none of them; they are not the
paper's values, and the results are not a reproduction of its figures):

- links in inches, to go with the 1/4 in journal and the 0.001 in
  clearance: crank BC 1 in (25.4 mm), coupler AB 3 in (76.2 mm); masses
  crank 0.020 kg, coupler 0.040 kg, slider 0.100 kg; slender-bar inertias
  m L^2 / 12 about the link centres (slider 1e-5 kg m^2, irrelevant);
- start at rest, 150 degrees from the inner dead centre (crank angle
  -30 degrees, slider on +x), journal centred in the bearing;
- spring along the slider line from a ground anchor at x = 0.15 m,
  unloaded at crank angle -136 degrees (106 degrees on), stiffness
  8 kN/m (the neutral position is reached at about 7 ms, at about
  -610 rad/s, the scale of the paper's figures), parallel damper 1 N s/m;
  no gravity (horizontal mechanism);
- babbitt E = 50 GPa (tin babbitt), steel E = 207 GPa;
- impact: the Rogers-Andrews stiffness (the paper's eq. 10) with
  Lankarani-Nikravesh damping at restitution e = exp(-pi eta / 2) = 0.969,
  the restitution of a lightly damped oscillator of loss factor eta = 0.02;
  no friction (the paper neglects it);
- squeeze film: the long-bearing pure-squeeze form. At L/D = 1 neither limit
  holds; checked against the Reynolds solver at L/D = 1 (no groove) the long
  form overestimates the squeeze force by 1.4x at eps = 0.9 and the short
  form by 6.5x, and near contact the long form has Phelan's f^(-3/2)
  structure (docs/theory/squeeze-film-phelan.md);
- Reynolds: Swift-Stieber cavitation, groove supply pressure 0.2 MPa
  (gauge), ambient 0 at the ends, grid 48 x 8 (8 intervals over the length)
  to keep the run short: refining to 96 x 16 moves the crank speed by at
  most 0.13 rad/s, the peak joint force by 0.3 % and the smallest film from
  0.23 to 0.26 um. Tightening rtol to 1e-8 moves no headline number by more
  than 1 % except the dry joint's impact count (42 -> 41) and contact
  fraction (0.32 -> 0.30): the dry run is sensitive, as impacting systems are.

What the run shows (observed, see the table it prints): the dry joint gives
the stairwise crank speed of rigid links with repeated impacts (Rogers and
Andrews' observation that the paper cites); the squeeze film removes the
impacts but leaves a lightly damped oscillation (the journal swings along
the wall like a pendulum under the joint load: a pure squeeze film resists
only radial motion); the Reynolds film with wedge action is the smoothest.

Run: python examples/paper000_joint_models.py [--out DIR] [--t-end SECONDS]
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

import jointplay as jp
from jointplay import laws

JOINT_MODELS = ("ideal", "clearance", "squeeze_film", "hydrodynamic")
COLOURS = {"ideal": "k", "clearance": "tab:red", "squeeze_film": "tab:blue", "hydrodynamic": "tab:green"}

# paper 000: joint B
CLEARANCE = 0.0025e-2  # radial clearance [m]
JOURNAL_DIAMETER = 0.64e-2  # [m]
BEARING_LENGTH = 0.64e-2  # [m]
VISCOSITY = 0.07 * 0.1  # 0.07 P in Pa s
SPRING_NEUTRAL_TURN = math.radians(106.0)  # crank turn from the start to the unloaded spring [rad]
POISSON_RATIO = 0.3

# CHOSEN (see the module docstring)
CRANK, COUPLER = 0.0254, 0.0762  # link lengths BC, AB [m]
MASSES = {"BC": 0.020, "AB": 0.040, "slider": 0.100}  # [kg]
INITIAL_CRANK_ANGLE = math.radians(-30.0)  # +150 deg from the inner dead centre [rad]
SPRING_STIFFNESS = 8.0e3  # [N/m]: the crank reaches the neutral position (106 deg) at about 7 ms
SPRING_DAMPING = 1.0  # [N s/m]: at most 9 N (slider at 9 m/s) against the 330 N preload
SPRING_ANCHOR = 0.15  # x of the spring's ground end, on the slider line [m]
BABBITT = laws.material(50e9, POISSON_RATIO)
STEEL = laws.material(207e9, POISSON_RATIO)
RESTITUTION = math.exp(-math.pi * 0.02 / 2)  # loss factor 0.02 -> e = 0.969
SUPPLY_PRESSURE = 0.2e6  # groove supply pressure, gauge [Pa]
REYNOLDS_GRID = (48, 8)  # circumferential x axial
T_END = 0.007  # [s]: release to about the spring's neutral position (106 deg), the paper's window


def slider_position(crank_angle: float) -> float:
    """x of the slider pin A [m] for a crank angle [rad] (ideal joints)."""
    return CRANK * math.cos(crank_angle) + math.sqrt(COUPLER**2 - (CRANK * math.sin(crank_angle))**2)


def _clearance_joint(joint: str) -> dict:
    """Keyword arguments of the clearance joint B for one of the non-ideal joint models."""
    options = dict(
        bearing_radius=JOURNAL_DIAMETER / 2 + CLEARANCE, clearance=CLEARANCE, length=BEARING_LENGTH,
        contact=laws.lankarani_nikravesh(RESTITUTION), stiffness=laws.rogers_andrews(),
        friction=laws.frictionless(), bearing_material=BABBITT, journal_material=STEEL,
    )
    if joint == "squeeze_film":
        options["lubrication"] = laws.lubrication("squeeze_film_long", VISCOSITY, laws.switch_transition())
    elif joint == "hydrodynamic":
        options["lubrication"] = laws.lubrication(
            "reynolds_exact", VISCOSITY, laws.switch_transition(), cavitation="swift_stieber",
            n_circumferential=REYNOLDS_GRID[0], n_axial=REYNOLDS_GRID[1], groove_supply_pressure=SUPPLY_PRESSURE)
    elif joint != "clearance":
        raise ValueError(f"unknown joint model {joint!r}; choose one of {', '.join(JOINT_MODELS)}")
    return options


def build_model(joint: str = "clearance") -> jp.Model:
    """The spring-loaded slider-crank at rest at its initial position, joint B modelled as ``joint``
    (one of :data:`JOINT_MODELS`). Bodies ``BC`` (crank), ``AB`` (coupler), ``slider``; joints ``C``,
    ``B``, ``A``, ``guide``; spring-damper ``spring``."""
    theta = INITIAL_CRANK_ANGLE
    b = (CRANK * math.cos(theta), CRANK * math.sin(theta))
    a = (slider_position(theta), 0.0)
    coupler_angle = math.atan2(a[1] - b[1], a[0] - b[0])
    m = jp.Model(f"paper000_slider_crank_{joint}")
    m.add_ground_point("C", (0.0, 0.0))
    m.add_ground_point("line", (0.0, 0.0))
    m.add_ground_point("anchor", (SPRING_ANCHOR, 0.0))
    m.add_body("BC", mass=MASSES["BC"], inertia=MASSES["BC"] * CRANK**2 / 12, angle=theta,
               position=(b[0] / 2, b[1] / 2), points={"C": (-CRANK / 2, 0.0), "B": (CRANK / 2, 0.0)})
    m.add_body("AB", mass=MASSES["AB"], inertia=MASSES["AB"] * COUPLER**2 / 12, angle=coupler_angle,
               position=((a[0] + b[0]) / 2, (a[1] + b[1]) / 2),
               points={"B": (-COUPLER / 2, 0.0), "A": (COUPLER / 2, 0.0)})
    m.add_body("slider", mass=MASSES["slider"], inertia=1e-5, position=a, points={"A": (0.0, 0.0)})
    m.add_revolute("C", "ground.C", "BC.C")
    m.add_clearance_revolute("B", "AB.B", "BC.B", **_clearance_joint("clearance" if joint == "ideal" else joint))
    m.add_revolute("A", "AB.A", "slider.A")
    m.add_translational("guide", "ground.line", "slider.A", axis=(1.0, 0.0))
    neutral_length = SPRING_ANCHOR - slider_position(theta - SPRING_NEUTRAL_TURN)
    m.add_spring_damper("spring", "ground.anchor", "slider.A", free_length=neutral_length,
                        stiffness=SPRING_STIFFNESS, damping=SPRING_DAMPING)
    return m.idealized() if joint == "ideal" else m


def simulate(model: jp.Model, t_end: float = T_END) -> jp.Results:
    """Runs one model (rtol 1e-6, max step 2 us, samples every 1 us)."""
    return model.simulate(t_end, rtol=1e-6, atol=1e-10, max_step=2e-6, output_step=1e-6)


def joint_force(results: jp.Results) -> np.ndarray:
    """Magnitude of the force in joint B [N]: the reaction of the ideal pin, or contact plus film force."""
    if "B.fh" in results:
        fx = results["B.fhx"] + _contact_components(results)[0]
        fy = results["B.fhy"] + _contact_components(results)[1]
        return np.hypot(fx, fy)
    return results["B.f"]


def _contact_components(results: jp.Results) -> tuple[np.ndarray, np.ndarray]:
    """Contact force on the journal along -n (no friction), global components [N]."""
    ex, ey = results["B.ex"], results["B.ey"]
    e = np.maximum(np.hypot(ex, ey), 1e-30)
    return -results["B.fn"] * ex / e, -results["B.fn"] * ey / e


def compare(runs: dict[str, jp.Results]) -> list[dict]:
    """One row per joint model: peak |omega - omega_ideal|, peak joint force and its excess over the
    ideal pin's reaction at the same instant, impacts, contact fraction, minimum film."""
    ideal = runs["ideal"]
    ideal_force = joint_force(ideal)
    rows = []
    for joint, results in runs.items():
        omega = np.interp(ideal.time, results.time, results["BC.omega"])
        force = np.interp(ideal.time, results.time, joint_force(results))
        clearance = results.summary()["clearance_joints"].get("B", {})
        rows.append({
            "joint": joint,
            "peak_omega": float(np.max(np.abs(results["BC.omega"]))),
            "peak_omega_deviation": float(np.max(np.abs(omega - ideal["BC.omega"]))),
            "peak_force": float(np.max(joint_force(results))),
            "peak_force_excess": float(np.max(force - ideal_force)),
            "impacts": clearance.get("impacts"),
            "contact_fraction": clearance.get("contact_fraction"),
            "film_min": float(np.min(results["B.film_min"])) if "B.film_min" in results else None,
            "wall_time": results.wall_time,
        })
    return rows


def format_table(rows: list[dict]) -> str:
    """The comparison as a plain-text table."""
    lines = [f"{'joint model':<14}{'peak |w|':>10}{'max |w - w_ideal|':>19}{'peak force':>12}{'above ideal':>13}"
             f"{'impacts':>9}{'contact':>9}{'min film':>10}{'wall':>8}",
             f"{'':<14}{'[rad/s]':>10}{'[rad/s]':>19}{'[N]':>12}{'[N]':>13}{'':>9}{'[frac]':>9}{'[um]':>10}{'[s]':>8}"]
    for r in rows:
        impacts = "-" if r["impacts"] is None else str(r["impacts"])
        contact = "-" if r["contact_fraction"] is None else f"{r['contact_fraction']:.3f}"
        film = "-" if r["film_min"] is None else f"{r['film_min'] * 1e6:.2f}"
        lines.append(f"{r['joint']:<14}{r['peak_omega']:>10.1f}{r['peak_omega_deviation']:>19.2f}"
                     f"{r['peak_force']:>12.1f}{r['peak_force_excess']:>13.1f}{impacts:>9}{contact:>9}{film:>10}{r['wall_time']:>8.2f}")
    return "\n".join(lines)


def write_figures(runs: dict[str, jp.Results], out: Path) -> list[Path]:
    """The crank angular velocity of the four models, and joint B's force and journal orbits."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    out.mkdir(parents=True, exist_ok=True)
    fig = Figure(figsize=(8, 7), layout="constrained")
    FigureCanvasAgg(fig)
    top, bottom = fig.subplots(2, 1, sharex=True, height_ratios=(2, 1))
    ideal = runs["ideal"]
    for joint, results in runs.items():
        t_ms = results.time * 1e3
        top.plot(t_ms, results["BC.omega"], lw=0.9, color=COLOURS[joint], label=joint.replace("_", " "))
        if joint != "ideal":
            deviation = results["BC.omega"] - np.interp(results.time, ideal.time, ideal["BC.omega"])
            bottom.plot(t_ms, deviation, lw=0.8, color=COLOURS[joint])
    top.set_ylabel("crank BC angular velocity [rad/s]")
    top.legend()
    top.set_title("spring-loaded slider-crank after Liu & Lin (1990), joint B modelled four ways\n"
                  "(rigid links; values the paper omits are chosen, not a reproduction)", fontsize=9)
    bottom.set_ylabel("difference from ideal [rad/s]")
    bottom.set_xlabel("time [ms]")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    omega_path = out / "paper000_crank_angular_velocity.png"
    fig.savefig(omega_path, dpi=130)

    fig = Figure(figsize=(10, 6.5), layout="constrained")
    FigureCanvasAgg(fig)
    grid = fig.add_gridspec(2, 3)
    force_ax = fig.add_subplot(grid[0, :])
    for joint, results in runs.items():
        force_ax.plot(results.time * 1e3, joint_force(results), lw=0.8, color=COLOURS[joint],
                      label=joint.replace("_", " "))
    force_ax.set_yscale("log")
    force_ax.set_ylim(bottom=1.0)
    force_ax.set_xlabel("time [ms]")
    force_ax.set_ylabel("force in joint B [N]")
    force_ax.legend(fontsize=8)
    force_ax.grid(alpha=0.3)
    circle = np.linspace(0.0, 2 * np.pi, 200)
    for k, joint in enumerate(j for j in runs if j != "ideal"):
        ax = fig.add_subplot(grid[1, k])
        results = runs[joint]
        ax.plot(CLEARANCE * 1e6 * np.cos(circle), CLEARANCE * 1e6 * np.sin(circle), "k", lw=0.6)
        ax.plot(results["B.ex"] * 1e6, results["B.ey"] * 1e6, lw=0.6, color=COLOURS[joint])
        ax.set_aspect("equal")
        ax.set_title(f"journal orbit, {joint.replace('_', ' ')}", fontsize=9)
        ax.set_xlabel("e_x [um]")
        ax.set_ylabel("e_y [um]")
    orbit_path = out / "paper000_joint_force_and_orbits.png"
    fig.savefig(orbit_path, dpi=130)
    return [omega_path, orbit_path]


def run_all(t_end: float = T_END) -> dict[str, jp.Results]:
    """Simulates the four joint models to ``t_end`` [s]."""
    return {joint: simulate(build_model(joint), t_end) for joint in JOINT_MODELS}


def main(argv: list[str] | None = None) -> tuple[dict[str, jp.Results], list[dict]]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("out/paper000"), help="folder for the figures")
    parser.add_argument("--t-end", type=float, default=T_END, help="simulated time [s]")
    args = parser.parse_args(argv)
    runs = run_all(args.t_end)
    rows = compare(runs)
    angle = np.degrees(runs["ideal"]["BC.angle"][-1] - runs["ideal"]["BC.angle"][0])
    print(f"crank turn in {args.t_end * 1e3:g} ms (ideal joint): {angle:.1f} deg")
    print(format_table(rows))
    for path in write_figures(runs, args.out):
        print(f"wrote {path}")
    return runs, rows


if __name__ == "__main__":
    main()
