"""Modal bodies given by matrices from another finite-element code: every file format reads to the same
structure, units and paths are honoured, a model written back needs no other file, and every bad input is
reported at its key (the physics: tests/physics/test_modal_body_from_matrices.py)."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
import scipy.io
import scipy.sparse

import jointplay as jp
from jointplay._core import MAX_STRUCTURE_NODES
from jointplay.errors import ModelError

sys.path.insert(0, str(Path(__file__).parent / "physics"))
from reference_frame_elements import Section, straight_member, write  # noqa: E402

SECTION = Section(ea=2e6, ei=100.0, rho_a=2.0)
NODES, MASS, STIFFNESS = straight_member(1.0, 4, SECTION)


#: the matrices and nodes here are in SI units (kg, m, s)
SI = {"length_unit": "m", "mass_unit": "kg"}

def model_text(matrices: str, extra: str = "") -> str:
    """A modal body from ``matrices`` (in SI units unless they say otherwise)."""
    if "length_unit" not in matrices:
        matrices += ', length_unit = "m", mass_unit = "kg"'
    return f"""
[modal_bodies.link]
matrices = {{ {matrices} }}
interface = {{ A = 0, B = 4 }}
free = true
{extra}
"""


def structure(model: jp.Model) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The dense mass, stiffness and nodes the core is sent."""
    s = model.to_spec()["modal_bodies"][0]["structure"]
    dense = [scipy.sparse.coo_array((e["values"], (e["rows"], e["columns"])), shape=(e["size"],) * 2).toarray()
             for e in (s["mass"], s["stiffness"])]
    return dense[0], dense[1], np.asarray(s["nodes"])


def files_in_every_format(folder: Path) -> list[str]:
    """``matrices`` keys naming the same structure in each format a file may have."""
    write(folder, "sym", NODES, MASS, STIFFNESS)  # coordinate, symmetric; nodes as CSV
    scipy.io.mmwrite(folder / "general.mass.mtx", scipy.sparse.coo_matrix(MASS), precision=17)
    scipy.io.mmwrite(folder / "general.stiffness.mtx", scipy.sparse.coo_matrix(STIFFNESS), precision=17)
    scipy.io.mmwrite(folder / "dense.mass.mtx", MASS, precision=17)  # array format
    scipy.io.mmwrite(folder / "dense.nodes.mtx", NODES, precision=17)
    np.save(folder / "mass.npy", MASS)
    np.save(folder / "nodes.npy", NODES)
    scipy.sparse.save_npz(folder / "stiffness.npz", scipy.sparse.csr_matrix(STIFFNESS))
    np.savetxt(folder / "nodes.txt", NODES, fmt="%.17g")
    return ['mass = "sym.mass.mtx", stiffness = "sym.stiffness.mtx", nodes = "sym.nodes.csv"',
            'mass = "general.mass.mtx", stiffness = "general.stiffness.mtx", nodes = "nodes.txt"',
            'mass = "dense.mass.mtx", stiffness = "stiffness.npz", nodes = "dense.nodes.mtx"',
            'mass = "mass.npy", stiffness = "sym.stiffness.mtx", nodes = "nodes.npy"']


def test_every_file_format_reads_to_the_same_structure(tmp_path: Path):
    for matrices in files_in_every_format(tmp_path):
        path = tmp_path / "link.toml"
        path.write_text(model_text(matrices))
        mass, stiffness, nodes = structure(jp.load(path))
        np.testing.assert_allclose(mass, MASS, rtol=1e-15, atol=0, err_msg=matrices)
        np.testing.assert_allclose(stiffness, STIFFNESS, rtol=1e-15, atol=0, err_msg=matrices)
        np.testing.assert_array_equal(nodes, NODES)


def test_files_are_found_beside_the_model_file_and_arrays_are_taken_from_python(tmp_path: Path, monkeypatch):
    (tmp_path / "model").mkdir()
    write(tmp_path, "link", NODES, MASS, STIFFNESS)
    path = tmp_path / "model" / "link.toml"
    path.write_text(model_text('mass = "../link.mass.mtx", stiffness = "../link.stiffness.mtx", '
                               'nodes = "../link.nodes.csv"'))
    monkeypatch.chdir(tmp_path / "model")
    from_file = structure(jp.load(path))
    m = jp.Model("link")
    m.add_modal_body("link", matrices={"mass": scipy.sparse.csr_matrix(MASS), "stiffness": STIFFNESS,
                                       "nodes": NODES.tolist(), **SI}, interface={"A": 0, "B": 4})
    for read, given in zip(from_file, structure(m)):
        np.testing.assert_allclose(read, given, rtol=1e-15, atol=0)


def test_millimetres_and_tonnes_are_read_into_si(tmp_path: Path):
    # mm, t, s: every entry x 1e-3 (t), x 1e3 per rotation coordinate among its two; lengths x 1e3
    per_rotation = np.kron(np.ones(len(NODES)), [1.0, 1.0, 1e3])
    scale = 1e-3 * np.outer(per_rotation, per_rotation)
    write(tmp_path, "mm", NODES * 1e3, MASS * scale, STIFFNESS * scale)
    path = tmp_path / "link.toml"
    path.write_text(model_text('mass = "mm.mass.mtx", stiffness = "mm.stiffness.mtx", nodes = "mm.nodes.csv", '
                               'length_unit = "mm", mass_unit = "t"'))
    mass, stiffness, nodes = structure(jp.load(path))
    np.testing.assert_allclose(mass, MASS, rtol=1e-14, atol=1e-14 * np.abs(MASS).max())
    np.testing.assert_allclose(stiffness, STIFFNESS, rtol=1e-14, atol=1e-14 * np.abs(STIFFNESS).max())
    np.testing.assert_allclose(nodes, NODES, rtol=1e-15, atol=1e-15)


def test_a_model_written_back_holds_its_matrices_and_needs_no_other_file(tmp_path: Path, monkeypatch):
    write(tmp_path, "link", NODES, MASS, STIFFNESS)
    path = tmp_path / "link.toml"
    path.write_text(model_text('mass = "link.mass.mtx", stiffness = "link.stiffness.mtx", nodes = "link.nodes.csv"',
                               'position = ["10 mm", "20 mm"]\nangle = "30 deg"\npoints = { C = 2 }'))
    model = jp.load(path)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    again = jp.loads(model.to_toml())
    assert again.to_spec() == model.to_spec()
    start = again.check()["initial_coordinates"]
    assert start[:3] == pytest.approx([0.01, 0.02, np.pi / 6], rel=1e-15)


def problems(text: str, folder: Path) -> dict[str, str]:
    path = folder / "bad.toml"
    path.write_text(text)
    with pytest.raises(ModelError) as caught:
        jp.load(path)
    return {p.location: p.message for p in caught.value.problems}


def test_bad_files_are_reported_at_their_key(tmp_path: Path):
    write(tmp_path, "link", NODES, MASS, STIFFNESS)
    np.save(tmp_path / "objects.npy", np.array([{"a": 1}], dtype=object), allow_pickle=True)
    scipy.io.mmwrite(tmp_path / "oblong.mtx", np.ones((15, 12)))
    found = problems(model_text('mass = "missing.mtx", stiffness = "objects.npy", nodes = "link.xlsx"'), tmp_path)
    assert "no such file" in found["modal_bodies.link.matrices.mass"]
    assert "pickles" in found["modal_bodies.link.matrices.stiffness"]
    assert "must be a file ending in .npy, .mtx, .csv, .txt" in found["modal_bodies.link.matrices.nodes"]
    found = problems(model_text('mass = "oblong.mtx", stiffness = "link.mass.mtx", nodes = [[0, 0], [1, 0]], '
                                'length_unit = "kg", colour = "red"'), tmp_path)
    assert "must be square, got 15 x 12" in found["modal_bodies.link.matrices.mass"]
    assert "must be 6 x 6" in found["modal_bodies.link.matrices.stiffness"]
    assert "unit of length" in found["modal_bodies.link.matrices.length_unit"]
    assert "unknown key" in found["modal_bodies.link.matrices.colour"]
    found = problems(model_text('mass = "link.mass.mtx", stiffness = "link.stiffness.mtx", nodes = "link.mass.mtx"'),
                     tmp_path)
    assert "one row x, y per node (n x 2), got an array of shape (15, 15)" in found["modal_bodies.link.matrices.nodes"]


def test_a_body_given_by_matrices_refuses_beam_keys_and_points_by_length(tmp_path: Path):
    write(tmp_path, "link", NODES, MASS, STIFFNESS)
    files = ('mass = "link.mass.mtx", stiffness = "link.stiffness.mtx", nodes = "link.nodes.csv", '
             'length_unit = "m", mass_unit = "kg"')
    text = f"""
[modal_bodies.link]
matrices = {{ {files} }}
start = ["0 m", "0 m"]
order = "linear"
interface = {{ A = 0, B = "150 mm" }}
points = {{ C = -1 }}
free = true
"""
    found = problems(text, tmp_path)
    assert "is not used by a body given by `matrices`" in found["modal_bodies.link.start"]
    assert "is not used by a body given by `matrices`" in found["modal_bodies.link.order"]
    assert "must be a node number" in found["modal_bodies.link.interface.B"]
    assert "must be a node number" in found["modal_bodies.link.points.C"]
    found = problems(text.replace('start = ["0 m", "0 m"]\norder = "linear"\n', "").replace('interface = { A = 0, B = "150 mm" }\n', "")
                     .replace("C = -1", "C = 2"), tmp_path)
    assert "names its interface nodes by number" in found["modal_bodies.link.interface"]


def compile_problems(stiffness: np.ndarray, interface: dict, gauge: bool = False) -> dict[str, str]:
    """The problems the core finds in the link of ``stiffness`` with ``interface`` (and a gauge at node 2)."""
    m = jp.Model("link")
    m.add_modal_body("link", matrices={"mass": MASS, "stiffness": stiffness, "nodes": NODES, **SI},
                     interface=interface, points={"C": 2})
    if gauge:
        m.add_strain_gauge("gauge", "link.C")
    with pytest.raises(ModelError) as caught:
        m.compile()
    return {p.location: p.message for p in caught.value.problems}


def test_what_the_core_finds_wrong_is_reported_at_the_file_s_keys():
    supported = STIFFNESS.copy()
    supported[1, 1] += 1e4  # a spring from node 0 to the ground
    found = compile_problems(supported, {"A": 0, "B": 7})
    assert "must be a node of the structure, from 0 to 4, got 7" in found["modal_bodies.link.interface.B.node"]
    found = compile_problems(supported, {"A": 0, "B": 4})
    assert "resists a translation along y" in found["modal_bodies.link.matrices"]
    found = compile_problems(STIFFNESS, {"A": 0, "B": 4}, gauge=True)
    assert "without elements to recover strains on" in found["sensors.gauge.point"]


def test_a_structure_beyond_the_dense_reduction_s_size_is_refused_before_it_is_sent():
    n = MAX_STRUCTURE_NODES + 1
    identity = scipy.sparse.identity(3 * n, format="csr")
    nodes = np.column_stack([np.arange(n, dtype=float), np.zeros(n)])
    with pytest.raises(ModelError, match=f"{n} nodes: a structure given by matrices has at most"):
        jp.Model("big").add_modal_body("big", matrices={"mass": identity, "stiffness": identity, "nodes": nodes, **SI},
                                       interface={"A": 0, "B": 1})


def test_check_lists_a_body_given_by_matrices(tmp_path: Path):
    from typer.testing import CliRunner

    from jointplay.cli import app

    write(tmp_path, "link", NODES, MASS, STIFFNESS)
    path = tmp_path / "link.toml"
    path.write_text(model_text('mass = "link.mass.mtx", stiffness = "link.stiffness.mtx", nodes = "link.nodes.csv"'))
    result = CliRunner().invoke(app, ["check", str(path)], env={"COLUMNS": "160"})
    assert result.exit_code == 0, result.output
    assert "matrices" in result.output and "chord" in result.output and "11.1" in result.output
