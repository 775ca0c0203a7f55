"""The interactive plots of a run report: the standard channels of :mod:`jointplay.plots` and its spatial
companions, as plotly figures in report sections.

- the key channels of ``jointplay plot`` (:func:`jointplay.plots.default_channels`);
- per body, its position, angle (or Euler angles) and acceleration; the modal amplitudes of a modal body;
  per beam, the positions and section angles of its end nodes;
- the reactions of the ideal joints and the efforts of the drivers;
- per clearance joint, the journal-centre orbit inside the clearance circle, the contact forces and, when
  lubricated, the film; per spatial clearance joint, the contact forces at its rims and flanges and its
  motion modes (the mode over time and the time fractions tracked at every accepted step);
- the strain gauges and the hydraulic cylinders.
"""

from __future__ import annotations

from collections.abc import Sequence

from ..results import Results
from .blocks import Plot, Section
from .figures import THINNING, bars_figure, history_figure, orbit_figure


def plot_sections(results: Results) -> list[Section]:
    """The sections of plots of a run (none for a run without samples)."""
    from ..plots import default_channels

    if results.time.size == 0:
        return []
    sections = []
    key = default_channels(results)
    if key:
        sections.append(Section("Plots: key channels", [history_plot(results, "Key channels", [[c] for c in key],
                                                              "The key channels of the run, as jointplay plot "
                                                              "chooses them.")]))
    sections += [s for s in (_bodies(results), _reactions(results)) if s.blocks]
    sections += _clearance_joints(results) + _spatial_clearance_joints(results)
    sections += [s for s in (_gauges(results), _cylinders(results)) if s.blocks]
    return sections


def history_plot(results: Results, title: str, panels: Sequence[Sequence[str]], what: str) -> Plot:
    """A plot of time histories (:func:`~jointplay.report.figures.history_figure`) whose caption says what it
    shows, how the run was sampled and whether it was thinned for the browser."""
    present = [[c for c in panel if c in results] for panel in panels]
    figure, was_thinned = history_figure(results, title, [p for p in present if p])
    return Plot(figure, caption(results, what, was_thinned))


def caption(results: Results, what: str, was_thinned: bool) -> str:
    """``what``, the run's sampling and, for a thinned plot, the thinning rule."""
    from ..plots import sampling_note, stopped_note

    parts = [what, f"Curves: the {sampling_note(results)}; open circles: peaks tracked at every accepted step "
                   "(where the run recorded them)."]
    if was_thinned:
        parts.append(THINNING)
    stopped = stopped_note(results)
    if stopped:
        parts.append(stopped[0].upper() + stopped[1:] + ".")
    return " ".join(parts)


def _with(results: Results, element: str, quantities: Sequence[str]) -> list[str]:
    return [f"{element}.{q}" for q in quantities if f"{element}.{q}" in results]


def _bodies(results: Results) -> Section:
    """Position, orientation and acceleration of every rigid body; modal amplitudes of modal bodies."""
    from ..plots_spatial import GLOBAL_RATES, euler_channels, spatial_bodies

    spatial = spatial_bodies(results)
    blocks = []
    for body in spatial:
        panels = [_with(results, body, "xyz"), euler_channels(results, body), _with(results, body, GLOBAL_RATES),
                  _with(results, body, ("ax", "ay", "az"))]
        blocks.append(history_plot(results, f"Body {body}", panels, f"Body {body}: centre-of-mass position, "
                                   "intrinsic Euler angles (as recorded), angular velocity about the global axes "
                                   "and centre-of-mass acceleration."))
    planar = [n[: -len(".angle")] for n in results.channels if n.endswith(".angle") and n[: -len(".angle")]
              not in spatial and f"{n[: -len('.angle')]}.x" in results]
    for body in planar:
        modes = sorted((n for n in results.channels if n.startswith(f"{body}.eta")),
                       key=lambda n: int(n.rsplit("eta", 1)[1] or 0) if n.rsplit("eta", 1)[1].isdigit() else 0)
        panels = [_with(results, body, "xy"), [f"{body}.angle"], _with(results, body, ("ax", "ay")), modes]
        blocks.append(history_plot(results, f"Body {body}", panels, f"Body {body}: centre-of-mass position (x, y), "
                                   "angle and centre-of-mass acceleration" + (", modal amplitudes" if modes else "")
                                   + "."))
    from ..plots import beams

    for beam in beams(results):
        name = beam["name"]
        last = sum(1 for n in results.channels if n.startswith(f"{name}.node") and n.endswith("_x")) - 1
        panels = [[f"{name}.node0_x", f"{name}.node0_y"], [f"{name}.node{last}_x", f"{name}.node{last}_y"],
                  [f"{name}.node0_angle", f"{name}.node{last}_angle"]]
        blocks.append(history_plot(results, f"Beam {name}", panels, f"Beam {name}: positions of its end nodes "
                                   f"(node 0 and node {last}) and the angles of their sections."))
    return Section("Plots: bodies", blocks)


def _reactions(results: Results) -> Section:
    """Reaction force magnitudes and moments of the ideal joints; torques and forces of the drivers."""
    spec = results.spec or {}
    joints = [j["name"] for j in [*spec.get("joints", []), *spec.get("spatial_joints", [])]
              if j.get("type") not in ("clearance_revolute",)]
    forces = [f"{j}.f" for j in joints if f"{j}.f" in results]
    moments = [c for j in joints for c in _with(results, j, ("moment", "mx", "my", "mz"))]
    drivers = [d["name"] for d in spec.get("drivers", [])]
    torques = [c for d in drivers for c in _with(results, d, ("torque",))]
    pushes = [c for d in drivers for c in _with(results, d, ("force",))]
    panels = [p for p in (forces, moments, torques, pushes) if p]
    if not panels:
        return Section("Plots: joint reactions", [])
    plot = history_plot(results, "Joint reactions and driver efforts", panels, "Magnitude of the reaction force "
                        "of each ideal joint on its second body, the reaction moments, and the torque or force "
                        "of each driver.")
    return Section("Plots: joint reactions", [plot])


def _clearance_joints(results: Results) -> list[Section]:
    """Per planar clearance joint: orbit, contact forces and, when lubricated, the film."""
    from ..plots import _clearance, clearance_joints

    sections = []
    for joint in clearance_joints(results):
        if f"{joint}.ex" not in results:
            continue
        figure, was_thinned = orbit_figure(results, joint, _clearance(results, joint))
        blocks = [Plot(figure, caption(results, f"Journal-centre path in {joint} (eccentricity ex, ey in mm, "
                                       "equal scales) inside the clearance circle of radius c: the journal touches "
                                       "the bore outside it.", was_thinned))]
        blocks.append(history_plot(results, f"Contact in {joint}", [[f"{joint}.fn"], [f"{joint}.ft"],
                                                                    [f"{joint}.penetration"]],
                                   f"Contact in {joint}: normal force fn, friction force ft, penetration "
                                   "(positive in contact)."))
        if f"{joint}.film_min" in results:
            blocks.append(history_plot(results, f"Lubricant film in {joint}",
                                       [[f"{joint}.film_min"], [f"{joint}.fh"], [f"{joint}.peak_pressure"]],
                                       f"Film of {joint}: thinnest film, film force magnitude and peak film "
                                       "pressure."))
        sections.append(Section(f"Plots: clearance joint {joint}", blocks))
    return sections


def _spatial_clearance_joints(results: Results) -> list[Section]:
    """Per spatial clearance joint: journal path in the middle section, contact forces and motion modes."""
    from ..plots_spatial_clearance import FRACTION_KEYS, radial_clearance, spatial_clearance_joints

    sections = []
    summary = results.summary()["clearance_joints"] if spatial_clearance_joints(results) else {}
    for joint in spatial_clearance_joints(results):
        blocks = [history_plot(results, f"Contact in {joint}",
                               [_with(results, joint, ("fn_a", "fn_b")), _with(results, joint, ("fn_fa", "fn_fb")),
                                _with(results, joint, ("ft_a", "ft_b", "ft_fa", "ft_fb")), [f"{joint}.tilt"]],
                               f"Contact in {joint}: normal forces at the bore's rims (a, b) and on the flange "
                               "faces (fa, fb), friction forces, tilt of the journal.")]
        blocks.append(history_plot(results, f"Motion mode of {joint}", [[f"{joint}.mode"]],
                                   f"Motion mode of {joint} over time: 0 free, 1 impact, 2 sliding, 3 sustained "
                                   "contact."))
        fractions = (summary.get(joint) or {}).get("mode_fractions")
        if fractions:
            keys = [k for k in FRACTION_KEYS if k in fractions]
            figure = bars_figure(f"Motion modes of {joint}: fractions of time", keys,
                                 {joint: [float(fractions[k]) for k in keys]}, "fraction of time [-]")
            blocks.append(Plot(figure, f"Time fractions of the motion modes of {joint}, tracked at every accepted "
                                       "step (free, impact, sliding, sustained sum to 1; axial: a flange touches)."))
        c = radial_clearance(results, joint)
        if c is not None:
            blocks.insert(0, history_plot(results, f"Journal in the bore of {joint}",
                                          [_with(results, joint, ("e_m_x", "e_m_y")), [f"{joint}.axial_position"]],
                                          f"Journal centre of {joint} in the bore's middle section (radial clearance "
                                          f"c = {c * 1e3:g} mm) and its axial position."))
        sections.append(Section(f"Plots: clearance joint {joint}", blocks))
    return sections


def _gauges(results: Results) -> Section:
    from ..plots import strain_gauges

    blocks = [history_plot(results, f"Strain gauge {g}", [[f"{g}.axial_strain"], [f"{g}.axial_force"],
                                                          [f"{g}.bending_moment"]],
                           f"Strain gauge {g}: fibre strain, axial force and bending moment of the section.")
              for g in strain_gauges(results)]
    return Section("Plots: strain gauges", blocks)


def _cylinders(results: Results) -> Section:
    spec = results.spec or {}
    blocks = []
    for force in [*spec.get("forces", []), *spec.get("spatial_forces", [])]:
        name = force.get("name")
        if force.get("type") == "hydraulic_cylinder" and f"{name}.p_cap" in results:
            blocks.append(history_plot(results, f"Hydraulic cylinder {name}",
                                       [_with(results, name, ("p_cap", "p_rod")), [f"{name}.stroke"],
                                        [f"{name}.force"]],
                                       f"Hydraulic cylinder {name}: cap- and rod-side pressures, stroke and force."))
    return Section("Plots: hydraulic cylinders", blocks)
