"""Modal bodies given by the matrices of a plane solid, two coordinates (u_x, u_y) per node, as another
finite-element code writes them for a planar link meshed with plane-stress elements (here the Q4 elements of
``reference_plane_stress.py``, written apart from the core): the body held at its chord frame vibrates at the
frequencies of the full mesh held the same way (an eigen-solve of the whole mesh by SciPy); as a pendulum
pinned at one interface node it swings with the period of the compound pendulum whose mass, centre and
inertia come from the reference's mass matrix; files in millimetres and tonnes read the same; a clamped frame,
which needs a section angle, and matrices of neither size are refused at their keys.

Chosen values: an aluminium strip 300 mm x 30 mm x 10 mm (E 70 GPa, nu 0.33, rho 2700 kg/m^3), 20 x 2
elements (63 nodes), pinned at the mid-depth nodes of its ends."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import scipy.io
import scipy.linalg
import scipy.sparse
from reference_plane_stress import node_at, strip

import jointplay as jp
from jointplay.errors import ModelError

E, NU, RHO, T = 70e9, 0.33, 2700.0, 0.01  # Pa, -, kg/m^3, m
LENGTH, DEPTH = 0.3, 0.03  # m
NODES, MASS, STIFFNESS = strip(LENGTH, DEPTH, 20, 2, E, NU, RHO, T)
A, B = node_at(NODES, 0.0, 0.0), node_at(NODES, LENGTH, 0.0)


#: the matrices and nodes here are in SI units (kg, m, s)
SI = {"length_unit": "m", "mass_unit": "kg"}

def full_mesh_held_frequencies() -> np.ndarray:
    """The full mesh's frequencies [Hz] with the chord frame's three coordinates held (A's two, B's u_y)."""
    held = [2 * A, 2 * A + 1, 2 * B + 1]
    free = [i for i in range(len(MASS)) if i not in held]
    pick = np.ix_(free, free)
    return np.sqrt(scipy.linalg.eigh(STIFFNESS[pick], MASS[pick], eigvals_only=True)) / (2 * math.pi)


def held_frequencies(model: jp.Model) -> list[float]:
    return next(b for b in model.check()["bodies"] if b["name"] == "link")["held_frequencies"]


def test_a_plane_solid_held_at_its_chord_vibrates_as_the_full_mesh():
    # 10 fixed-interface modes and the constraint mode of B's u_x: the two bending modes and the first
    # axial one of the 126-coordinate mesh (805, 3104, 3973 Hz) within 3e-4 (seen 1e-12, 1e-12, 2.1e-4)
    m = jp.Model("strip", gravity=(0, 0))
    m.add_modal_body("link", matrices={"mass": MASS, "stiffness": STIFFNESS, "nodes": NODES, **SI},
                     interface={"A": A, "B": B}, normal_modes=10)
    body = next(b for b in m.check()["bodies"] if b["name"] == "link")
    assert body["nodes"] == 63 and body["mass"] == pytest.approx(RHO * T * DEPTH * LENGTH, rel=1e-12)
    expected = full_mesh_held_frequencies()[:3]
    assert 700 < expected[0] < 900  # bending: the strip is slender (Euler-Bernoulli would say 770 Hz)
    assert held_frequencies(m)[:3] == pytest.approx(expected, rel=3e-4)


def compound_pendulum_period(amplitude: float, g: float = 9.81) -> float:
    """The period [s] of the rigid strip swinging about node A at ``amplitude`` [rad], its mass, first moment
    and inertia about A summed from the reference's mass matrix (rigid motions r: M's quadratic forms)."""
    n = len(NODES)
    x = NODES - NODES[A]
    translations = np.zeros((2 * n, 2))
    translations[0::2, 0], translations[1::2, 1] = 1.0, 1.0
    mass = (translations.T @ MASS @ translations)[0, 0]
    first_moment = translations.T @ MASS @ x.ravel()
    rotation = np.zeros(2 * n)
    rotation[0::2], rotation[1::2] = -x[:, 1], x[:, 0]
    inertia = rotation @ MASS @ rotation
    small = 2 * math.pi * math.sqrt(inertia / (g * float(np.hypot(*first_moment))))
    return small * (1 + amplitude ** 2 / 16 + 11 * amplitude ** 4 / 3072)


def test_a_plane_solid_pendulum_swings_with_the_compound_pendulum_period():
    # released 0.05 rad from hanging, generalized-alpha at 0.5 ms (the strip's first held mode, 805 Hz, is
    # damped, not followed): the period within 1e-5 of the rigid compound pendulum's (seen 1.2e-6; the strip's
    # sag under its weight changes it by less than 1e-6)
    amplitude = 0.05
    m = jp.Model("pendulum", gravity=(0, -9.81))
    m.add_ground_point("O", (0.0, 0.0))
    m.add_modal_body("link", matrices={"mass": MASS, "stiffness": STIFFNESS, "nodes": NODES, **SI},
                     interface={"A": A, "B": B}, normal_modes=4, angle=-math.pi / 2 + amplitude)
    m.add_revolute("pin", "ground.O", "link.A")
    results = m.simulate(2.0, method="generalized_alpha", step=5e-4, rtol=1e-8, atol=1e-11)
    swing, t = results["link.angle"] + math.pi / 2, results.time
    rising = np.where((swing[:-1] < 0) & (swing[1:] >= 0))[0]
    crossings = t[rising] - swing[rising] * (t[rising + 1] - t[rising]) / (swing[rising + 1] - swing[rising])
    assert len(crossings) == 2
    assert crossings[1] - crossings[0] == pytest.approx(compound_pendulum_period(amplitude), rel=1e-5)


def test_plane_solid_files_in_millimetres_and_tonnes_read_as_in_si(tmp_path: Path):
    # units mm, t, s (forces in N): lengths x 1e-3 to m, every entry x 1e3 (no rotation coordinates)
    for name, matrix in (("mass", MASS), ("stiffness", STIFFNESS)):
        scipy.io.mmwrite(tmp_path / f"strip.{name}.mtx", scipy.sparse.coo_matrix(matrix * 1e-3), symmetry="symmetric",
                         precision=17)
    np.savetxt(tmp_path / "strip.nodes.csv", NODES * 1e3, delimiter=",", fmt="%.17g")
    (tmp_path / "strip.toml").write_text(f"""
[modal_bodies.link]
matrices = {{ mass = "strip.mass.mtx", stiffness = "strip.stiffness.mtx", nodes = "strip.nodes.csv", length_unit = "mm", mass_unit = "t" }}
interface = {{ A = {A}, B = {B} }}
normal_modes = 10
free = true
""")
    loaded = jp.load(tmp_path / "strip.toml")
    m = jp.Model("strip", gravity=(0, 0))
    m.add_modal_body("link", matrices={"mass": MASS, "stiffness": STIFFNESS, "nodes": NODES, **SI},
                     interface={"A": A, "B": B}, normal_modes=10)
    assert held_frequencies(loaded) == pytest.approx(held_frequencies(m), rel=1e-12)
    again = jp.loads(loaded.to_toml())  # written back inline in SI
    assert again.to_spec() == loaded.to_spec()


def test_a_clamped_frame_and_matrices_of_neither_size_are_refused_at_their_keys():
    m = jp.Model("strip")
    m.add_modal_body("link", matrices={"mass": MASS, "stiffness": STIFFNESS, "nodes": NODES, **SI},
                     interface={"A": A, "B": B}, frame="clamped")
    with pytest.raises(ModelError, match="holds the first interface node's section angle, which a structure with two "
                                         "coordinates per node"):
        m.compile()
    with pytest.raises(ModelError) as caught:
        jp.Model("strip").add_modal_body("link", matrices={"mass": MASS[:-1, :-1], "stiffness": STIFFNESS,
                                                           "nodes": NODES, **SI}, interface={"A": A, "B": B})
    found = {p.location: p.message for p in caught.value.problems}
    assert "must be 189 x 189: three coordinates (u_x, u_y, theta) for each of the 63 nodes of a frame, or " \
           "126 x 126: two (u_x, u_y) for each node of a plane solid, got 125 x 125" in found["modal_bodies.link.matrices.mass"]
