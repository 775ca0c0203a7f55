"""Every file reader is guarded: a file's declared size is checked before anything is allocated, a value that is
not a finite number is named with its file and entry, a byte-order mark or a nesting too deep is named, and the
Python API reports a bad path as a ModelError at the user's path (the CLI: exit 2, no traceback)."""

from __future__ import annotations

import io
import zipfile
from pathlib import Path

import h5py
import numpy as np
import pytest
import scipy.io
import scipy.sparse
from numpy.lib import format as npy
from typer.testing import CliRunner

import jointplay as jp
from jointplay.cli import app
from jointplay.modelfile.matrices import MAX_TEXT_BYTES
from jointplay.resultsfile import LAYOUT
from small_models import pendulum, problems_of

ROOT = Path(__file__).resolve().parents[1]
IDEAL = ROOT / "examples" / "flores_slider_crank_ideal.toml"
TOO_LARGE = ("declares {what}: a structure given by matrices has at most 400 nodes (1200 x 1200 coordinates; its "
             "reduction is dense), so it is not read; reduce the structure in its own code first")


# matrix files of a modal body -----------------------------------------------------------------------------

def header_only_npy(path: Path, shape: tuple[int, ...]) -> None:
    """A .npy file whose header declares ``shape`` and which holds a few bytes: a file far smaller than it says."""
    with open(path, "wb") as f:
        npy.write_array_header_1_0(f, {"descr": "<f8", "fortran_order": False, "shape": shape})
        f.write(b"\0" * 64)


def npz_declaring(path: Path, shape: tuple[int, int]) -> None:
    """A SciPy sparse archive of a 3 x 3 identity whose ``shape`` says ``shape``."""
    scipy.sparse.save_npz(path, scipy.sparse.csr_matrix(np.eye(3)))
    with zipfile.ZipFile(path) as archive:
        members = {name: archive.read(name) for name in archive.namelist()}
    declared = io.BytesIO()
    np.save(declared, np.array(shape))
    members["shape.npy"] = declared.getvalue()
    with zipfile.ZipFile(path, "w") as archive:
        for name, data in members.items():
            archive.writestr(name, data)


def matrix_problems(folder: Path, mass: str, nodes: str = "[[0, 0], [1, 0]]") -> dict[str, str]:
    """The problems of a modal body whose mass matrix is ``mass`` (TOML) and nodes ``nodes``, by key."""
    path = folder / "link.toml"
    path.write_text(f"""
[modal_bodies.link]
matrices = {{ mass = {mass}, stiffness = {mass}, nodes = {nodes}, length_unit = "m", mass_unit = "kg" }}
interface = {{ A = 0, B = 1 }}
free = true
""")
    return dict(problems_of(lambda: jp.load(path)))


@pytest.mark.parametrize("name, write, declared", [
    ("big.npy", lambda path: header_only_npy(path, (200000, 200000)), "a 200000 x 200000 array"),
    ("huge.npz", lambda path: npz_declaring(path, (10**9, 10**9)), "a 1000000000 x 1000000000 matrix"),
])
def test_a_numpy_file_declaring_a_huge_array_is_refused_from_its_header(tmp_path, name, write, declared):
    # the files hold a header and a few bytes: reading the declared array would need 320 GB or 8 EB, so a
    # refusal that names the declared size was made from the header alone
    write(tmp_path / name)
    found = matrix_problems(tmp_path, f'"{name}"')
    assert found["modal_bodies.link.matrices.mass"] == f"'{tmp_path / name}' " + TOO_LARGE.format(what=declared)


def test_a_matrix_market_header_is_checked_before_it_is_read(tmp_path):
    (tmp_path / "big.mtx").write_text("%%MatrixMarket matrix coordinate real general\n100000 100000 1\n1 1 1.0\n")
    (tmp_path / "full.mtx").write_text("%%MatrixMarket matrix coordinate real general\n3 3 100\n1 1 1.0\n")
    found = matrix_problems(tmp_path, '"big.mtx"')
    assert found["modal_bodies.link.matrices.mass"] == (f"'{tmp_path / 'big.mtx'}' "
                                                        + TOO_LARGE.format(what="a 100000 x 100000 matrix"))
    found = matrix_problems(tmp_path, '"full.mtx"')
    assert found["modal_bodies.link.matrices.mass"] == (f"'{tmp_path / 'full.mtx'}' declares 100 entries in a 3 x 3 "
                                                        "matrix, more than it has places for")


def test_node_files_are_checked_before_they_are_read(tmp_path):
    header_only_npy(tmp_path / "nodes.npy", (10**7, 2))
    with open(tmp_path / "nodes.csv", "wb") as f:
        f.truncate(MAX_TEXT_BYTES + 1)  # sparse: no time to write
    found = matrix_problems(tmp_path, "[[1.0]]", '"nodes.npy"')
    assert found["modal_bodies.link.matrices.nodes"] == (f"'{tmp_path / 'nodes.npy'}' "
                                                         + TOO_LARGE.format(what="a 10000000 x 2 array"))
    found = matrix_problems(tmp_path, "[[1.0]]", '"nodes.csv"')
    assert found["modal_bodies.link.matrices.nodes"] == (
        f"'{tmp_path / 'nodes.csv'}' holds {MAX_TEXT_BYTES + 1} bytes, more than the {MAX_TEXT_BYTES} bytes a list "
        "of at most 400 nodes needs, so it is not read")


def test_nan_or_inf_in_a_matrix_file_is_named_with_its_file_and_entry(tmp_path):
    matrix = np.eye(6)
    matrix[2, 3] = np.nan
    np.save(tmp_path / "nan.npy", matrix)
    scipy.io.mmwrite(tmp_path / "inf.mtx", scipy.sparse.coo_matrix(np.diag([1.0, np.inf, 1.0, 1.0, -np.inf, 1.0])))
    found = matrix_problems(tmp_path, '"nan.npy"')
    assert found["modal_bodies.link.matrices.mass"] == (f"entry (2, 3) of '{tmp_path / 'nan.npy'}' is nan: every entry "
                                                        "must be a finite number (rows and columns count from 0)")
    found = matrix_problems(tmp_path, '"inf.mtx"')
    assert found["modal_bodies.link.matrices.mass"] == (
        f"entry (1, 1) of '{tmp_path / 'inf.mtx'}' is inf: every entry must be a finite number (rows and columns "
        "count from 0; 1 other entry is not either)")


def test_nan_in_a_matrix_given_in_python_or_inline_is_named_with_its_entry(tmp_path):
    matrix = np.eye(6)
    matrix[5, 0] = np.inf
    found = dict(problems_of(lambda: jp.Model("m").add_modal_body(
        "link", matrices={"mass": matrix, "stiffness": np.eye(6), "nodes": [[0, 0], [1, 0]]},
        interface={"A": 0, "B": 1})))
    assert found["modal_bodies.link.matrices.mass"] == ("entry (5, 0) is inf: every entry must be a finite number "
                                                        "(rows and columns count from 0)")
    found = matrix_problems(tmp_path, "{ size = 6, rows = [0], columns = [1], values = [nan] }")
    assert found["modal_bodies.link.matrices.mass"] == ("entry (0, 1) is nan: every entry must be a finite number "
                                                        "(rows and columns count from 0)")


def test_nan_in_a_node_file_is_named_with_its_file_and_node(tmp_path):
    (tmp_path / "nodes.csv").write_text("0, 0\nnan, 0\n")
    found = matrix_problems(tmp_path, "[[1.0]]", '"nodes.csv"')
    assert found["modal_bodies.link.matrices.nodes"] == (f"node 1 of '{tmp_path / 'nodes.csv'}' is not at a finite "
                                                         "position, got [nan, 0.0]")


def test_a_byte_order_mark_in_a_text_matrix_file_is_named(tmp_path):
    (tmp_path / "nodes.csv").write_bytes(b"\xef\xbb\xbf0,0\n1,0\n")
    found = matrix_problems(tmp_path, "[[1.0]]", '"nodes.csv"')
    assert found["modal_bodies.link.matrices.nodes"] == (
        f"'{tmp_path / 'nodes.csv'}' starts with a UTF-8 byte-order mark (BOM, the bytes EF BB BF), which is not read "
        "as a number; save the file as UTF-8 without BOM")


# model files ----------------------------------------------------------------------------------------------

BOM = ("starts with a UTF-8 byte-order mark (BOM, the bytes EF BB BF), which TOML does not allow; save the file as "
       "UTF-8 without BOM")


def test_a_model_file_with_a_byte_order_mark_is_named(tmp_path):
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + IDEAL.read_bytes())
    assert problems_of(lambda: jp.load(path)) == [(str(path), BOM)]
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2 and BOM in " ".join(result.stderr.split())


def test_a_utf16_model_file_is_named(tmp_path):
    path = tmp_path / "utf16.toml"
    path.write_bytes(IDEAL.read_text().encode("utf-16"))
    assert problems_of(lambda: jp.load(path)) == [(str(path), "is UTF-16 text (it starts with a UTF-16 byte-order "
                                                              "mark); a model file is TOML text in UTF-8: save it as "
                                                              "UTF-8")]


def test_a_model_file_nested_hundreds_of_levels_deep_gets_a_message(tmp_path):
    path = tmp_path / "deep.toml"
    path.write_text("[model]\nname = " + "{a = " * 500 + "1" + "}" * 500 + "\n")
    assert problems_of(lambda: jp.load(path)) == [(str(path), "is nested too deeply to be read: arrays or inline tables "
                                                              "inside one another hundreds of levels deep (a model "
                                                              "file needs at most 32)")]
    path.write_text("[model]\nname = " + "[" * 40 + "]" * 40 + "\n")
    assert problems_of(lambda: jp.load(path)) == [("model.name[0]", "holds tables and arrays nested more than 32 levels "
                                                                    "deep; a model file needs at most a few levels")]


def test_a_deep_dotted_table_and_a_deep_set_value_get_a_message(tmp_path):
    deep = "[" + ".".join(["a"] * 2000) + "]\nb = 1\n"
    assert problems_of(lambda: jp.loads(deep)) == [("a.a.a", "holds tables and arrays nested more than 32 levels deep; "
                                                             "a model file needs at most a few levels")]
    result = CliRunner().invoke(app, ["check", str(IDEAL), "--set", "model.name=" + "[" * 2000 + "]" * 2000])
    assert result.exit_code == 2, result.output
    assert "is nested too deeply to be read" in result.stderr and "Traceback" not in result.output


# results files and output paths in the Python API ---------------------------------------------------------

def test_an_output_file_in_a_missing_folder_is_a_model_error_at_the_user_s_path(tmp_path):
    target = tmp_path / "missing" / "run.nc"
    assert problems_of(lambda: pendulum().simulate(1e-3, output_file=target)) == [
        (str(target), f"cannot write the results: the folder '{tmp_path / 'missing'}' does not exist")]
    assert problems_of(lambda: pendulum().simulate(1e-3, output_file=tmp_path)) == [
        (str(tmp_path), "is a folder, not a results file (give a file name such as run.nc)")]
    results = pendulum().simulate(1e-3)
    target = tmp_path / "missing" / "run.csv"
    assert problems_of(lambda: results.save(target)) == [
        (str(target), f"cannot write the results: the folder '{tmp_path / 'missing'}' does not exist")]
    assert list(tmp_path.iterdir()) == []


def test_open_results_names_the_user_s_path_for_what_is_not_a_results_file(tmp_path):
    assert problems_of(lambda: jp.open_results(IDEAL)) == [
        (str(IDEAL), "is not a jointplay results file (not a NetCDF file): it is a model file (TOML); "
                     "jointplay.load() reads it and `jointplay run` simulates it")]
    assert problems_of(lambda: jp.open_results(tmp_path / "none.nc")) == [(str(tmp_path / "none.nc"),
                                                                           "no such results file")]
    assert problems_of(lambda: jp.open_results(tmp_path)) == [(str(tmp_path), "is a folder, not a results file")]
    with h5py.File(tmp_path / "other.h5", "w") as f:
        f.attrs["jointplay_layout"] = LAYOUT
    [(where, message)] = problems_of(lambda: jp.open_results(tmp_path / "other.h5"))
    assert where == str(tmp_path / "other.h5") and message.startswith("is not a jointplay results file (")


def test_a_results_file_declaring_more_samples_than_memory_holds_is_refused_unread(tmp_path):
    path = tmp_path / "huge.nc"
    with h5py.File(path, "w") as f:  # 2^31 samples declared, none written: a file of a few kB
        f.attrs["jointplay_layout"] = LAYOUT
        f.create_dataset("time", shape=(2**31,), dtype="f8", chunks=(4096,))
    message = "time declares 2147483648 values (16 GiB), above the memory budget of 1 GiB for reading a file"
    assert problems_of(lambda: jp.open_results(path)) == [(str(path), message)]
    result = CliRunner().invoke(app, ["plot", str(path), "-o", str(tmp_path / "figures")])
    assert result.exit_code == 2 and message in " ".join(result.stderr.split())


def test_a_channel_declaring_more_samples_than_memory_holds_is_refused_when_read(tmp_path):
    path = tmp_path / "channel.nc"
    with h5py.File(path, "w") as f:
        f.attrs["jointplay_layout"] = LAYOUT
        f.create_dataset("time", data=np.zeros(3))
        f.create_dataset("bar.x", shape=(2**31,), dtype="f8", chunks=(4096,))  # none written
    results = jp.open_results(path)
    assert problems_of(lambda: results["bar.x"]) == [
        (str(path), "channel 'bar.x' declares 2147483648 values (16 GiB), above the memory budget of 1 GiB for "
                    "reading a file")]


def test_a_non_finite_number_in_a_spec_is_located_by_element_name():
    spec = pendulum().to_spec()
    spec["bodies"][0]["mass"] = float("nan")
    spec["bodies"][0]["points"][0]["position"] = [float("inf"), 0.0]
    assert problems_of(lambda: jp.Model.from_spec(spec).compile()) == [
        ("bodies.bar.mass", "must be a finite number, got nan"),
        ("bodies.bar.points.O.position[0]", "must be a finite number, got inf")]


def test_saving_a_model_into_a_missing_folder_names_the_path(tmp_path):
    target = tmp_path / "missing" / "pendulum.toml"
    assert problems_of(lambda: pendulum().save(target)) == [
        (str(target), f"cannot write the model: the folder '{target.parent}' does not exist")]
