"""Modal bodies given by the matrices of another finite-element code (here the Euler-Bernoulli frame elements
of ``reference_frame_elements.py``, written apart from the core and read back from Matrix Market and CSV
files), checked against closed forms: the simply supported frequencies of a uniform link, the tip deflection
of a clamped L-shaped frame (which no beam of jointplay's can describe) in turned axes and in millimetres and
tonnes, and the energy of such a frame spinning and vibrating in free flight."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from reference_frame_elements import Section, frame, straight_member, write

import jointplay as jp

EI, RHO_A = 100.0, 2.0  # N m^2, kg/m
SECTION = Section(ea=2e6, ei=EI, rho_a=RHO_A)


#: the matrices and nodes here are in SI units (kg, m, s)
SI = {"length_unit": "m", "mass_unit": "kg"}

def test_a_link_from_matrices_is_held_simply_supported_at_euler_bernoullis_frequencies(tmp_path: Path):
    # f_n = (n pi)^2 sqrt(EI / (rho A L^4)) / (2 pi) for a 1 m link; 20 Hermite elements and 8 fixed-interface
    # modes: the reduction is within 6e-5 of it (seen 4.5e-7, 1.1e-5, 5.7e-5)
    nodes, mass, stiffness = straight_member(1.0, 20, SECTION)
    files = write(tmp_path, "link", nodes, mass, stiffness)
    m = jp.Model("link", gravity=(0, 0))
    m.add_modal_body("link", matrices={**{key: str(tmp_path / name) for key, name in files.items()}, **SI},
                     interface={"A": 0, "B": 20}, normal_modes=8)
    body = next(b for b in m.check()["bodies"] if b["name"] == "link")
    expected = [(n * math.pi) ** 2 * math.sqrt(EI / RHO_A) / (2 * math.pi) for n in (1, 2, 3)]
    assert body["frame"] == "chord" and body["nodes"] == 21 and body["mass"] == pytest.approx(RHO_A, rel=1e-12)
    assert body["held_frequencies"][:3] == pytest.approx(expected, rel=1e-4)


def l_frame(a: float, b: float, per_leg: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """An L: a leg up the y axis from the origin, ``a`` long, then one along x, ``b`` long; nodes, M, K."""
    up = [(0.0, a * k / per_leg) for k in range(per_leg + 1)]
    across = [(b * k / per_leg, a) for k in range(1, per_leg + 1)]
    nodes = np.array(up + across)
    members = [(k, k + 1) for k in range(2 * per_leg)]
    mass, stiffness = frame(nodes, members, SECTION)
    return nodes, mass, stiffness


def turned(nodes: np.ndarray, mass: np.ndarray, stiffness: np.ndarray, angle: float):
    """The same structure described in axes turned by ``angle`` [rad] against the first ones."""
    c, s = math.cos(angle), math.sin(angle)
    r = np.array([[c, s], [-s, c]])
    t = np.kron(np.eye(len(nodes)), np.block([[r, np.zeros((2, 1))], [np.zeros((1, 2)), np.ones((1, 1))]]))
    return nodes @ r.T, t @ mass @ t.T, t @ stiffness @ t.T


def test_a_clamped_l_frame_from_turned_millimetre_files_deflects_as_castigliano_says(tmp_path: Path):
    a, b, load = 0.4, 0.3, 5.0  # m, m, N
    nodes, mass, stiffness = turned(*l_frame(a, b, 6), angle=0.6)
    # the files in mm, t, s (forces in N): lengths x 1e3, every entry x 1e-3 (t) and x 1e3 per rotation
    # coordinate among its two (N mm/rad for N m/rad)
    to_mm = np.kron(np.ones(len(nodes)), [1.0, 1.0, 1e3])
    files = write(tmp_path, "l_frame", nodes * 1e3, 1e-3 * mass * np.outer(to_mm, to_mm),
                  1e-3 * stiffness * np.outer(to_mm, to_mm))
    model_file = tmp_path / "l_frame.toml"
    model_file.write_text(f"""
[ground]
points = {{ O = ["0 m", "0 m"], below = ["{b} m", "-100 m"] }}

[modal_bodies.ell]
matrices = {{ mass = "{files['mass']}", stiffness = "{files['stiffness']}", nodes = "{files['nodes']}", length_unit = "mm", mass_unit = "t" }}
angle = "0.6 rad"
interface = {{ root = 0, tip = 12 }}
frame = "clamped"
normal_modes = 4
damping_ratio = 1.0

[joints.clamp]
type = "fixed"
first = "ground.O"
second = "ell.root"

[forces.load]
type = "point_force"
point = "ell.tip"
fx = "0 N"
fy = "{-load} N"

[forces.probe]
type = "spring_damper"
first = "ground.below"
second = "ell.tip"
stiffness = "0 N/m"
damping = "0 N s/m"
free_length = "0 m"
""")
    model = jp.load(model_file)  # the files found beside the model file
    r = model.simulate(2.0, method="bdf", max_order=2, rtol=1e-8, atol=1e-11, output_step=0.05)
    # the tip goes down by P b^3 / (3 EI) (the arm) + P b^2 a / (EI) (the upright bent by P b) + P a / EA and
    # sideways by P b a^2 / (2 EI) (the upright's bending); the tip is an interface node, so its constraint modes
    # give the static deflection of the whole mesh, and Hermite elements are exact at the nodes for end loads
    down = load * b**3 / (3 * EI) + load * b**2 * a / EI + load * a / SECTION.ea
    sideways = load * b * a**2 / (2 * EI)
    # the probe runs from (b, -100 m) to the tip: its length less the sideways shift is the tip's height
    height = math.sqrt(r["probe.length"][-1] ** 2 - sideways**2) - 100.0 - a
    assert height == pytest.approx(-down, rel=1e-6)
    assert r["clamp.fy"][-1] == pytest.approx(load, rel=1e-6)


def test_an_undamped_l_frame_spinning_and_vibrating_in_free_flight_keeps_its_energy(tmp_path: Path):
    nodes, mass, stiffness = l_frame(0.4, 0.3, 4)
    m = jp.Model("free L", gravity=(0, 0))
    m.add_modal_body("ell", matrices={"mass": mass, "stiffness": stiffness, "nodes": nodes, **SI},
                     interface={"root": 0, "tip": 8}, normal_modes=3, angular_velocity="20 rad/s",
                     velocity=("0.5 m/s", 0))
    start = m.check()["initial_velocities"].copy()
    r = m.simulate(0.5, method="dopri5", rtol=1e-9, atol=1e-11, output_step=0.01)
    energy, kinetic = r["system.energy"], r["system.kinetic_energy"]
    assert np.ptp(energy) < 1e-9 * energy[0]  # seen 2e-12
    # the spin loads the frame: it starts in that strain (its quasi-static strain, docs/theory/planar-formulation.md)
    # and keeps a strain energy of some 4.5e-4 of the whole, vibrating about it (ptp 2.4e-3 J seen)
    assert (energy - kinetic).min() > 1e-4 * energy[0]
    assert np.ptp(energy - kinetic) > 1e-5 * energy[0]
    assert start[2] == pytest.approx(20.0)
