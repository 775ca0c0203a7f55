"""Paper 000 complete: the spring-loaded slider-crank with flexible links, joint B modelled four ways.

After Liu & Lin (1990), who take the mechanism from Rogers & Andrews (1977,
after Haines 1980): a crank BC pinned to the ground at C, a coupler AB, a
slider at A, and a preloaded spring-damper on the slider. As in the paper,
both links are finite-strain (Simo) beams of 3-node elements, 3 degrees of
freedom per node (docs/theory/beam.md), so their deformation, of the order
of the bearing clearance, interacts with the play of joint B. Released from
rest, the spring drives the crank clockwise; it is neither compressed nor
stretched when the crank has turned 106 degrees, and the crank swings
between about +150 and -150 degrees measured from the inner dead centre (it
cannot make a full turn). Joint B (coupler AB to crank BC) has the
clearance, modelled four ways, as in the paper:

- ``ideal``: a perfect pin;
- ``clearance``: dry contact-impact, Rogers-Andrews logarithmic stiffness
  (the paper's eq. 10), no friction (the paper neglects it);
- ``squeeze_film``: the clearance filled with lubricant that only squeezes
  (no wedge), switching to impact once the film is used up (the paper's
  Phelan model; see docs/theory/squeeze-film-phelan.md for what we use);
- ``hydrodynamic``: the finite-difference Reynolds equation with squeeze and
  wedge action, a circumferential groove at mid-length at the supply
  pressure, and the same switch to impact.

The output, laid out like the paper's Figs. 7-14: the crank's angular
velocity (Figs. 7-10) and the axial strain at point E of link AB (Figs.
11-14) for each joint model, over the paper's window from release to the
spring's neutral position (about 7 ms, 107 degrees of crank turn here).
The same mechanism with rigid links of the same masses (``links="rigid"``,
the version of this example before the links were flexible) is kept for
comparison.

FROM THE PAPER: radial clearance 0.0025 cm; journal diameter and length
0.64 cm; journal steel, bearing babbitt; Poisson's ratio 0.3; impact loss
factor 0.02; viscosity 0.07 P (7 cP); spring unloaded 106 degrees from the
initial position; swing of about +-150 degrees; groove at mid-length with
supply pressure; switch from film to impact when the film is used up; links
as finite-strain beams of 3-node elements; the axial strain at E on AB.

CHOSEN here (our copy of the paper gives none of them; they are not the
paper's values, and the results are not a reproduction of its figures):

- links in inches, to go with the 1/4 in journal and the 0.001 in
  clearance: crank BC 1 in (25.4 mm), coupler AB 3 in (76.2 mm); masses
  crank 0.020 kg, coupler 0.040 kg, slider 0.100 kg (slider inertia
  1e-5 kg m^2, irrelevant); rigid links: slender-bar inertias m L^2 / 12;
- flexible links: steel (E = 207 GPa, nu = 0.3, 7850 kg/m^3), solid
  rectangles of the rigid links' masses, 5 mm deep in the plane of the
  mechanism (coupler 13.4 mm wide, crank 20.1 mm): the coupler's first
  pinned-pinned bending mode is then about 2 kHz and its mid-span
  deflection under the crank pin's centripetal load, estimated by hand
  (not measured), some tens of um, the order of the clearance, as the
  paper argues for its links; coupler 3
  quadratic elements, crank 2; strain-rate damping with a retardation time
  of 4 us (2.5 % of critical at 2 kHz);
- point E at the middle of AB, the strain of its axis (the section's mean
  axial strain; the paper's text does not place E further);
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
  to keep the run short (with rigid links, refining to 96 x 16 moved the
  crank speed by at most 0.13 rad/s and the peak joint force by 0.3 %);
- flexible runs: the implicit method (the links are stiff) with orders 1
  and 2 (A-stable), rtol 1e-6; rigid runs: Dormand-Prince, rtol 1e-6.

Run: python examples/paper000_joint_models.py [--out DIR] [--t-end SECONDS] [--links rigid|flexible]
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

import jointplay as jp
from jointplay import laws, sections

JOINT_MODELS = ("ideal", "clearance", "squeeze_film", "hydrodynamic")
LINKS = ("flexible", "rigid")
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

# CHOSEN flexible links: steel rectangles of the rigid links' masses, DEPTH deep in the plane
LINK_STEEL = sections.material(207e9, 7850.0, poisson_ratio=POISSON_RATIO)
DEPTH = 0.005  # section depth in the plane of the mechanism [m]
ELEMENTS = {"BC": 2, "AB": 3}  # quadratic (3-node) elements per link
DAMPING_TIME = 4e-6  # strain-rate retardation time [s]


def slider_position(crank_angle: float) -> float:
    """x of the slider pin A [m] for a crank angle [rad] (ideal joints)."""
    return CRANK * math.cos(crank_angle) + math.sqrt(COUPLER**2 - (CRANK * math.sin(crank_angle))**2)


def link_width(link: str) -> float:
    """Out-of-plane width [m] of the flexible link ``link`` ("BC" or "AB"): the rigid link's mass."""
    length = CRANK if link == "BC" else COUPLER
    return MASSES[link] / (LINK_STEEL["density"] * length * DEPTH)


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


def build_model(joint: str = "clearance", links: str = "flexible") -> jp.Model:
    """The spring-loaded slider-crank at rest at its initial position, joint B modelled as ``joint``
    (one of :data:`JOINT_MODELS`), the links ``"flexible"`` (beams, points ``start``/``end``, E on AB)
    or ``"rigid"`` (bodies, points ``C``, ``B`` and ``B``, ``A``). Links ``BC`` (crank), ``AB`` (coupler),
    body ``slider``; joints ``C``, ``B``, ``A``, ``guide``; spring-damper ``spring``; with flexible links
    the strain gauge ``E``."""
    if links not in LINKS:
        raise ValueError(f"unknown links {links!r}; choose one of {', '.join(LINKS)}")
    theta = INITIAL_CRANK_ANGLE
    b = (CRANK * math.cos(theta), CRANK * math.sin(theta))
    a = (slider_position(theta), 0.0)
    m = jp.Model(f"paper000_slider_crank_{joint}" + ("" if links == "flexible" else "_rigid"))
    m.add_ground_point("C", (0.0, 0.0))
    m.add_ground_point("line", (0.0, 0.0))
    m.add_ground_point("anchor", (SPRING_ANCHOR, 0.0))
    if links == "flexible":
        for name, start, end in (("BC", (0.0, 0.0), b), ("AB", b, a)):
            m.add_beam(name, start, end, section=sections.rectangle(link_width(name), DEPTH), material=LINK_STEEL,
                       elements=ELEMENTS[name], damping_time=DAMPING_TIME,
                       points={"E": COUPLER / 2} if name == "AB" else {})
        points = {"C": "BC.start", "B_crank": "BC.end", "B_coupler": "AB.start", "A": "AB.end"}
    else:
        coupler_angle = math.atan2(a[1] - b[1], a[0] - b[0])
        m.add_body("BC", mass=MASSES["BC"], inertia=MASSES["BC"] * CRANK**2 / 12, angle=theta,
                   position=(b[0] / 2, b[1] / 2), points={"C": (-CRANK / 2, 0.0), "B": (CRANK / 2, 0.0)})
        m.add_body("AB", mass=MASSES["AB"], inertia=MASSES["AB"] * COUPLER**2 / 12, angle=coupler_angle,
                   position=((a[0] + b[0]) / 2, (a[1] + b[1]) / 2),
                   points={"B": (-COUPLER / 2, 0.0), "A": (COUPLER / 2, 0.0)})
        points = {"C": "BC.C", "B_crank": "BC.B", "B_coupler": "AB.B", "A": "AB.A"}
    m.add_body("slider", mass=MASSES["slider"], inertia=1e-5, position=a, points={"A": (0.0, 0.0)})
    m.add_revolute("C", "ground.C", points["C"])
    m.add_clearance_revolute("B", points["B_coupler"], points["B_crank"],
                             **_clearance_joint("clearance" if joint == "ideal" else joint))
    m.add_revolute("A", points["A"], "slider.A")
    m.add_translational("guide", "ground.line", "slider.A", axis=(1.0, 0.0))
    neutral_length = SPRING_ANCHOR - slider_position(theta - SPRING_NEUTRAL_TURN)
    m.add_spring_damper("spring", "ground.anchor", "slider.A", free_length=neutral_length,
                        stiffness=SPRING_STIFFNESS, damping=SPRING_DAMPING)
    if links == "flexible":
        m.add_strain_gauge("E", "AB.E")
    return m.idealized() if joint == "ideal" else m


def simulate(model: jp.Model, t_end: float = T_END) -> jp.Results:
    """Runs one model, rtol 1e-6, samples every 1 us: rigid links with Dormand-Prince (max step 2 us),
    flexible links with the implicit method of orders 1-2 (the beams are stiff)."""
    if model.to_spec().get("beams"):
        return model.simulate(t_end, method="bdf", max_order=2, stabilization="baumgarte", rtol=1e-6, atol=1e-10,
                              max_step=2e-6, output_step=1e-6)
    return model.simulate(t_end, rtol=1e-6, atol=1e-10, max_step=2e-6, output_step=1e-6)


def _crank_chord(results: jp.Results) -> tuple[np.ndarray, ...]:
    """The chord C-B of a flexible crank, from its first to its last node: x, y [m], vx, vy [m/s]."""
    last = max(int(name.split("_")[0][len("BC.node"):]) for name in results.channels if name.startswith("BC.node"))
    return tuple(results[f"BC.node{last}_{q}"] - results[f"BC.node0_{q}"] for q in ("x", "y", "vx", "vy"))


def crank_angular_velocity(results: jp.Results) -> np.ndarray:
    """Angular velocity of the crank [rad/s]: of the rigid crank, or of the chord C-B of the flexible one."""
    if "BC.omega" in results:
        return np.asarray(results["BC.omega"])
    x, y, vx, vy = _crank_chord(results)
    return np.asarray((x * vy - y * vx) / (x * x + y * y))


def crank_turn(results: jp.Results) -> float:
    """The crank's turn from the start to the end of the run [deg] (the chord C-B of a flexible crank)."""
    if "BC.angle" in results:
        angle = np.asarray(results["BC.angle"])
    else:
        x, y, _, _ = _crank_chord(results)
        angle = np.unwrap(np.arctan2(y, x))
    return float(np.degrees(angle[-1] - angle[0]))


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
    ideal pin's reaction at the same instant, impacts, contact fraction, minimum film, and the range of
    the axial strain at E (flexible links)."""
    ideal = runs["ideal"]
    ideal_omega, ideal_force = crank_angular_velocity(ideal), joint_force(ideal)
    rows = []
    for joint, results in runs.items():
        omega = np.interp(ideal.time, results.time, crank_angular_velocity(results))
        force = np.interp(ideal.time, results.time, joint_force(results))
        clearance = results.summary()["clearance_joints"].get("B", {})
        strain = np.asarray(results["E.axial_strain"]) if "E.axial_strain" in results else None
        rows.append({
            "joint": joint,
            "peak_omega": float(np.max(np.abs(crank_angular_velocity(results)))),
            "peak_omega_deviation": float(np.max(np.abs(omega - ideal_omega))),
            "peak_force": float(np.max(joint_force(results))),
            "peak_force_excess": float(np.max(force - ideal_force)),
            "impacts": clearance.get("impacts"),
            "contact_fraction": clearance.get("contact_fraction"),
            "film_min": float(np.min(results["B.film_min"])) if "B.film_min" in results else None,
            "strain_min": None if strain is None else float(np.min(strain)),
            "strain_max": None if strain is None else float(np.max(strain)),
            "wall_time": results.wall_time,
        })
    return rows


def format_table(rows: list[dict]) -> str:
    """The comparison as a plain-text table (strains at E in microstrain, samples of the run)."""
    lines = [f"{'joint model':<14}{'peak |w|':>10}{'max |w - w_ideal|':>19}{'peak force':>12}{'above ideal':>13}"
             f"{'impacts':>9}{'contact':>9}{'min film':>10}{'strain at E':>18}{'wall':>8}",
             f"{'':<14}{'[rad/s]':>10}{'[rad/s]':>19}{'[N]':>12}{'[N]':>13}{'':>9}{'[frac]':>9}{'[um]':>10}"
             f"{'[1e-6]':>18}{'[s]':>8}"]
    for r in rows:
        impacts = "-" if r["impacts"] is None else str(r["impacts"])
        contact = "-" if r["contact_fraction"] is None else f"{r['contact_fraction']:.3f}"
        film = "-" if r["film_min"] is None else f"{r['film_min'] * 1e6:.2f}"
        strain = "-" if r["strain_min"] is None else f"{r['strain_min'] * 1e6:.1f} to {r['strain_max'] * 1e6:.1f}"
        lines.append(f"{r['joint']:<14}{r['peak_omega']:>10.1f}{r['peak_omega_deviation']:>19.2f}"
                     f"{r['peak_force']:>12.1f}{r['peak_force_excess']:>13.1f}{impacts:>9}{contact:>9}{film:>10}"
                     f"{strain:>18}{r['wall_time']:>8.2f}")
    return "\n".join(lines)


def _figure(size: tuple[float, float]):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=size, layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def _links(runs: dict[str, jp.Results]) -> str:
    return "flexible" if "E.axial_strain" in runs["ideal"] else "rigid"


def write_response_figure(runs: dict[str, jp.Results], path: Path) -> Path:
    """Laid out like the paper's Figs. 7-14: one row per joint model, the crank's angular velocity on the
    left (Figs. 7-10) and the axial strain at E on the right (Figs. 11-14; flexible links only)."""
    flexible = _links(runs) == "flexible"
    fig = _figure((10, 9) if flexible else (6, 9))
    axes = np.atleast_2d(fig.subplots(len(runs), 2 if flexible else 1, sharex=True, squeeze=False))
    for row, (joint, results) in enumerate(runs.items()):
        t_ms = results.time * 1e3
        title = joint.replace("_", " ")
        axes[row, 0].plot(t_ms, crank_angular_velocity(results), lw=0.8, color=COLOURS[joint])
        axes[row, 0].set_ylabel("crank BC [rad/s]")
        axes[row, 0].set_title(f"crank angular velocity, {title} joint B", fontsize=9)
        if flexible:
            axes[row, 1].plot(t_ms, results["E.axial_strain"] * 1e6, lw=0.6, color=COLOURS[joint])
            axes[row, 1].set_ylabel("axial strain [1e-6]")
            axes[row, 1].set_title(f"axial strain at E (AB's axis at mid-length), {title} joint B", fontsize=9)
    for ax in axes.flat:
        ax.grid(alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("time [ms]")
    fig.suptitle(f"spring-loaded slider-crank after Liu & Lin (1990), {_links(runs)} links, joint B four ways; "
                 "samples every 1 us\n(values the paper omits are chosen, not a reproduction of its figures)",
                 fontsize=9)
    fig.savefig(path, dpi=130)
    return path


def write_force_figure(runs: dict[str, jp.Results], path: Path) -> Path:
    """Joint B's force for the four models and the journal orbits of the three clearance models."""
    fig = _figure((10, 6.5))
    grid = fig.add_gridspec(2, 3)
    force_ax = fig.add_subplot(grid[0, :])
    for joint, results in runs.items():
        force_ax.plot(results.time * 1e3, joint_force(results), lw=0.8, color=COLOURS[joint],
                      label=joint.replace("_", " "))
    force_ax.set_yscale("log")
    force_ax.set_ylim(bottom=1.0)
    force_ax.set_xlabel("time [ms]")
    force_ax.set_ylabel("force in joint B [N]")
    force_ax.set_title(f"{_links(runs)} links; samples every 1 us", fontsize=9)
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
    fig.savefig(path, dpi=130)
    return path


def write_figures(runs: dict[str, jp.Results], out: Path) -> list[Path]:
    """The response figure (angular velocity and strain at E) and the joint force and orbit figure."""
    out.mkdir(parents=True, exist_ok=True)
    suffix = "" if _links(runs) == "flexible" else "_rigid"
    return [write_response_figure(runs, out / f"paper000_crank_velocity_and_strain{suffix}.png"),
            write_force_figure(runs, out / f"paper000_joint_force_and_orbits{suffix}.png")]


def run_all(t_end: float = T_END, links: str = "flexible") -> dict[str, jp.Results]:
    """Simulates the four joint models to ``t_end`` [s]."""
    return {joint: simulate(build_model(joint, links), t_end) for joint in JOINT_MODELS}


def main(argv: list[str] | None = None) -> tuple[dict[str, jp.Results], list[dict]]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("out/paper000"), help="folder for the figures")
    parser.add_argument("--t-end", type=float, default=T_END, help="simulated time [s]")
    parser.add_argument("--links", choices=LINKS, default="flexible", help="flexible (beams) or rigid links")
    args = parser.parse_args(argv)
    runs = run_all(args.t_end, args.links)
    rows = compare(runs)
    print(f"{args.links} links: crank turn in {args.t_end * 1e3:g} ms (ideal joint): {crank_turn(runs['ideal']):.1f} deg")
    print(format_table(rows))
    for path in write_figures(runs, args.out):
        print(f"wrote {path}")
    return runs, rows


if __name__ == "__main__":
    main()
