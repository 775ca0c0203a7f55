"""Results written in bulk: every channel, attribute and coordinate of a saved or streamed file read
back through xarray (independently of jointplay's reader) against the results in memory; a streamed
file equal to a saved one; files of the version 2 layout (gzip-compressed chunks) still read; a
compiled model pickled by its description runs identically; quantities read from a model file the
same to the last bit with their parses kept."""

from __future__ import annotations

import pickle
from pathlib import Path

import h5py
import numpy as np
import pytest
import xarray as xr

import jointplay as jp
from jointplay import resultsfile
from jointplay.results import open_results

EXAMPLES = Path(__file__).parent.parent / "examples"
DRY = EXAMPLES / "flores_slider_crank_dry.toml"
VERSION_2 = Path(__file__).parent / "data" / "results_layout_v2.nc"
#: Global attributes that say when and by what command a file was written, and how long the run took.
WHEN = {"date_created", "history", "wall_time_s"}


@pytest.fixture(scope="module")
def dry_model():
    return jp.load(DRY)


def chain(n_bodies: int) -> jp.Model:
    """Bars 0.1 m long hanging from a pin, each pinned to the next."""
    m = jp.Model("chain", gravity=(0.0, -9.81))
    m.add_ground_point("O", (0.0, 0.0))
    previous = "ground.O"
    for k in range(n_bodies):
        m.add_body(f"bar{k}", 0.1, 1e-4, position=(0.1 * k + 0.05, 0.0), points={"a": (-0.05, 0.0), "b": (0.05, 0.0)})
        m.add_revolute(f"pin{k}", previous, f"bar{k}.a")
        previous = f"bar{k}.b"
    return m


def plain(value):
    """An attribute as a comparable Python value (xarray gives numpy scalars and arrays)."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    return value


def same(a, b) -> bool:
    """Equal, NaN equal to NaN, an array of one value equal to that value (as h5netcdf reads one)."""
    a, b = (v[0] if isinstance(v, list) and len(v) == 1 else v for v in (a, b))
    if isinstance(a, float) and isinstance(b, float) and np.isnan(a) and np.isnan(b):
        return True
    return a == b


def assert_file_holds(path: Path, results) -> None:
    """The file read through xarray holds the results in memory: every channel's values, units,
    long name and description, the time coordinate, and the global attributes."""
    expected = results.file_attributes()
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        assert list(ds.data_vars) == results.channels
        np.testing.assert_array_equal(ds["time"].values, results.time)
        assert ds["time"].attrs == {"units": "s", "long_name": "time", "standard_name": "time", "axis": "T",
                                    "description": "time"}
        assert not ds.encoding.get("unlimited_dims")
        for name in results.channels:
            variable = ds[name]
            assert variable.dims == ("time",)
            np.testing.assert_array_equal(variable.values, results[name], err_msg=name)
            assert variable.attrs == {"units": results.unit(name),
                                      "long_name": results._descriptions[results._index[name]] or name,
                                      "description": results._descriptions[results._index[name]]}, name
        assert set(ds.attrs) == set(expected)
        for key, value in expected.items():
            if key not in WHEN:
                assert same(plain(ds.attrs[key]), plain(value)), key


def test_saved_dry_run_reads_back_through_xarray_channel_by_channel(tmp_path, dry_model):
    results = dry_model.simulate(0.005)
    path = results.save(tmp_path / "dry.nc")
    assert_file_holds(path, results)
    back = open_results(path)
    assert back.channels == results.channels
    for name in results.channels:
        np.testing.assert_array_equal(back[name], results[name])
    assert back.extrema == results.extrema and back.statistics == results.statistics


def test_saved_chain_of_many_channels_reads_back_through_xarray(tmp_path):
    results = chain(12).simulate(0.05, formulation="absolute")
    assert len(results.channels) > 100
    assert_file_holds(results.save(tmp_path / "chain.nc"), results)


def test_compressed_file_holds_the_same_as_a_plain_one(tmp_path, dry_model):
    results = dry_model.simulate(0.005)
    assert_file_holds(results.save(tmp_path / "gz.nc", compress=True), results)


def variables(path: Path) -> dict:
    """Every variable of a file: its values and its attributes (references as the name they point to)."""
    out = {}
    with h5py.File(path) as f:
        for name, dataset in f.items():
            attrs = {}
            for key, value in dataset.attrs.items():
                if key == "DIMENSION_LIST":
                    value = [f[ref].name for ref in value[0]]
                elif key == "REFERENCE_LIST":
                    value = [(f[ref].name, int(dim)) for ref, dim in value]
                attrs[key] = plain(value)
            out[name] = (np.asarray(dataset[()]), attrs)
        out["/"] = {key: plain(value) for key, value in f.attrs.items() if key not in WHEN}
    return out


@pytest.mark.parametrize("output_step", [None, 1e-6], ids=["written once at the end", "written in blocks"])
def test_streamed_file_equals_the_saved_file(tmp_path, dry_model, output_step):
    # at every step the 5 ms run fits the writer's buffer (one write, contiguous variables); on a 1 us
    # grid its 5001 samples x 53 channels do not (blocks written into growing chunked variables)
    t_end = 0.005 if output_step is None else 0.012
    options = {"output_step": output_step, "max_output_bytes": "1 GiB"}  # (a file's default budget is 2 GiB)
    kept = dry_model.simulate(t_end, **options)
    dry_model.simulate(t_end, output_file=tmp_path / "streamed.nc", **options)
    with h5py.File(tmp_path / "streamed.nc") as f:
        assert (f["slider.ax"].chunks is None) == (output_step is None)
    saved, written = variables(kept.save(tmp_path / "saved.nc")), variables(tmp_path / "streamed.nc")
    assert list(saved) == list(written)
    saved_globals, written_globals = saved.pop("/"), written.pop("/")
    assert list(saved_globals) == list(written_globals)
    for key, value in saved_globals.items():
        assert same(written_globals[key], value), key
    for name, (values, attrs) in saved.items():
        np.testing.assert_array_equal(written[name][0], values, err_msg=name)
        assert written[name][1] == attrs, name
    assert_file_holds(tmp_path / "streamed.nc", kept)


def test_files_of_the_version_2_layout_still_read_on_access():
    # written by the writer of the version 2 layout (gzip-compressed chunks of 4096 samples; its
    # ResultsWriter as of commit d92cab9) from 3 channels x 10 samples, one of them named with a "/"
    with h5py.File(VERSION_2) as f:
        assert f.attrs["jointplay_layout"] == "jointplay-netcdf4-v2" and f["arm.x"].compression == "gzip"
    back = open_results(VERSION_2)
    assert back.channels == ["arm.x", "arm/left.fn", "B.penetration"]
    assert type(back._values).__name__ == "FileChannels", "read on access"
    np.testing.assert_array_equal(back.time, np.linspace(0.0, 9e-3, 10))
    np.testing.assert_array_equal(back["arm.x"], np.arange(10) * 0.5)
    np.testing.assert_array_equal(back["arm/left.fn"], -np.arange(10.0))
    assert [back.unit(n) for n in back.channels] == ["m", "N", "m"]
    assert back.statistics == {"accepted_steps": 9} and back.diagnostics == {"impacts": [2]}
    assert back.options == {"method": "dopri5"} and back.spec == {"name": "version2"}


def test_version_2_file_saved_again_in_the_current_layout(tmp_path):
    path = open_results(VERSION_2).save(tmp_path / "again.nc")
    with h5py.File(path) as f:
        assert f.attrs["jointplay_layout"] == resultsfile.LAYOUT and f["arm.x"].chunks is None
    with xr.open_dataset(path, engine="h5netcdf") as ds, xr.open_dataset(VERSION_2, engine="h5netcdf") as old:
        assert list(ds.data_vars) == list(old.data_vars)
        for name in old.data_vars:
            np.testing.assert_array_equal(ds[name].values, old[name].values)
            assert ds[name].attrs == old[name].attrs


# pickling ------------------------------------------------------------------------

def assert_same_run(first, second) -> None:
    assert first.channels == second.channels
    np.testing.assert_array_equal(first.time, second.time)
    for name in first.channels:
        np.testing.assert_array_equal(first[name], second[name], err_msg=name)
    assert first.statistics == second.statistics


def test_compiled_model_from_a_file_pickles_by_its_description_and_runs_identically(dry_model):
    before = dry_model.simulate(0.004)
    copy = pickle.loads(pickle.dumps(dry_model))
    assert copy.to_spec() == dry_model.to_spec()
    assert (copy.simulation, copy.description, copy.source_file) == (
        dry_model.simulation, dry_model.description, dry_model.source_file)
    assert dry_model._core is not None, "the original stays compiled"
    assert_same_run(before, copy.simulate(0.004))


def test_pickled_model_built_in_python_runs_identically_and_changes_alone():
    model = chain(4)
    before = model.simulate(0.02)
    copy = pickle.loads(pickle.dumps(model))
    assert_same_run(before, copy.simulate(0.02))
    copy.set_gravity((0.0, -1.62))  # the copy is a model of its own
    assert not np.array_equal(copy.simulate(0.02)["bar3.y"], before["bar3.y"])
    assert_same_run(before, model.simulate(0.02))


# quantities read with their parses kept ---------------------------------------------

def test_quantities_read_again_are_pint_values_to_the_last_bit():
    import pint

    from jointplay import units

    ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    ureg.define("rev = revolution")
    for text, kind, unit in (("0.30 kg", "mass", "kg"), ("2.5e-4 kg m^2", "inertia", "kg*m^2"),
                             ("5000 rpm", "angular velocity", "rad/s"), ("0.5 mm", "length", "m"),
                             ("207 GPa", "pressure", "Pa"), ("-9.81 m/s^2", "acceleration", "m/s^2")):
        expected = float(ureg.Quantity(text).to(unit).magnitude)
        assert units.to_si(text, kind) == expected and units.to_si(text, kind) == expected, text


def test_a_kept_bare_number_still_follows_the_declared_units():
    from jointplay import units

    assert units.to_si("3", "length") == 3.0  # in Python, SI
    with units.model_file_units({"length": ("mm", 1e-3)}):
        assert units.to_si("3", "length") == 0.003
    with units.model_file_units({}), pytest.raises(units.UnitError, match="a bare number needs a unit"):
        units.to_si("3", "length")


def test_a_refused_quantity_is_refused_every_time():
    from jointplay import units

    for _ in range(2):
        with pytest.raises(units.UnitError, match="must be a length"):
            units.to_si("5 kg", "length")
        with pytest.raises(units.UnitError, match="unknown unit"):
            units.to_si("5 furlongz", "length")
