"""Results written in bulk: every channel, attribute and coordinate of a saved or streamed file read
back through xarray, scipy and netCDF-C (when installed), independently of jointplay's reader, against
the results in memory; a streamed file equal to a saved one byte for byte, with its final header in
place or its samples moved; a file cut after a block; the format's record limit; files of the version 2 layout (gzip-compressed chunks) still read; a
compiled model pickled by its description runs identically; quantities read from a model file the
same to the last bit with their parses kept."""

from __future__ import annotations

import pickle
from pathlib import Path

import h5py
import numpy as np
import pytest
import scipy.io
import xarray as xr

import jointplay as jp
from jointplay import mechanisms, resultsfile
from jointplay.results import Results, open_results

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
    return mechanisms.hanging_chain(n_bodies)


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


def assert_file_holds(path: Path, results, engine: str = "scipy") -> None:
    """The file read through xarray (``engine``: scipy for NetCDF classic, h5netcdf for NetCDF-4) holds the
    results in memory: every channel's values, units, long name and description, the time coordinate,
    and the global attributes."""
    expected = results.file_attributes()
    with xr.open_dataset(path, engine=engine) as ds:
        assert list(ds.data_vars) == results.channels
        np.testing.assert_array_equal(ds["time"].values, results.time)
        assert ds["time"].attrs == {"units": "s", "long_name": "time", "standard_name": "time", "axis": "T",
                                    "description": "time"}
        assert bool(ds.encoding.get("unlimited_dims")) == (engine == "scipy"), "classic: time the record dimension"
        for name in results.channels:
            variable = ds[name]
            assert variable.dims == ("time",)
            np.testing.assert_array_equal(variable.values, results[name], err_msg=name)
            assert variable.attrs == {"units": results.unit(name),
                                      "long_name": results._descriptions[results._index[name]] or name,
                                      "description": results._descriptions[results._index[name]]}, name
        assert set(ds.attrs) == set(expected)
        for key, value in expected.items():
            if key not in WHEN | {"jointplay_layout"}:
                assert same(plain(ds.attrs[key]), plain(value)), key
        assert ds.attrs["jointplay_layout"] == (resultsfile.CLASSIC_LAYOUT if engine == "scipy" else resultsfile.LAYOUT)


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


def test_compressed_file_is_netcdf4_and_holds_the_same_as_a_plain_one(tmp_path, dry_model):
    results = dry_model.simulate(0.005)
    path = results.save(tmp_path / "gz.nc", compress=True)
    assert h5py.is_hdf5(path)
    assert_file_holds(path, results, engine="h5netcdf")


def test_classic_file_read_by_scipy_holds_every_channel_and_attribute(tmp_path, dry_model):
    # scipy's own reader, without xarray: values, the record dimension, NC_CHAR text, NC_INT and NC_DOUBLE
    results = dry_model.simulate(0.005)
    path = results.save(tmp_path / "dry.nc")
    expected = results.file_attributes()
    with scipy.io.netcdf_file(path, mmap=False) as f:
        assert f.version_byte == 2 and f.dimensions == {"time": None} and f._recs == len(results)
        assert list(f.variables) == ["time", *results.channels]
        np.testing.assert_array_equal(f.variables["time"][:], results.time)
        for name in results.channels:
            variable = f.variables[name]
            np.testing.assert_array_equal(variable[:], results[name], err_msg=name)
            assert variable.units.decode() == results.unit(name)
            assert variable.description.decode() == results._descriptions[results._index[name]]
        for key in ("model_json", "model_toml", "extrema_json", "title"):
            assert f._attributes[key].decode() == expected[key], key
        assert f._attributes["completed"] == 1 and f._attributes["statistics_accepted_steps"] == \
            results.statistics["accepted_steps"]
        assert f._attributes["diagnostics_max_penetration"] == results.diagnostics["max_penetration"]


def test_classic_file_read_by_netcdf_c(tmp_path, dry_model):
    netCDF4 = pytest.importorskip("netCDF4", reason="netCDF-C's Python binding (netCDF4) is not installed")
    results = dry_model.simulate(0.005)
    path = results.save(tmp_path / "dry.nc")
    with netCDF4.Dataset(path) as ds:
        assert ds.data_model == "NETCDF3_64BIT_OFFSET" and ds.dimensions["time"].isunlimited()
        for name in results.channels:
            np.testing.assert_array_equal(ds[name][:], results[name], err_msg=name)
            assert ds[name].units == results.unit(name)
        assert ds.getncattr("model_toml") == results.model_toml()


def test_non_ascii_text_and_names_with_dots_and_spaces_round_trip(tmp_path):
    results = Results(np.linspace(0.0, 1e-3, 5), ["arm 1.x (left)", "Zahnrad ü.fn", "b.θ"], ["m", "N", "rad"],
                      ["Lage in µm-Genauigkeit", "Kraft am Zahnrad – Zähne", ""], np.arange(15.0).reshape(3, 5),
                      {"accepted_steps": 4}, {"impacts": []})
    results.description = "Gelenk mit Spiel: 0,5 mm – Schmierfilm ≥ 1 µm"
    path = results.save(tmp_path / "ü.nc")
    back = open_results(path)
    assert back.channels == results.channels and back.description == results.description
    assert back._descriptions == results._descriptions
    np.testing.assert_array_equal(back["b.θ"], results["b.θ"])
    with xr.open_dataset(path, engine="scipy") as ds:  # scipy reads names as Latin-1: the bytes are UTF-8
        names = [str(n).encode("latin1").decode("utf-8") for n in ds.data_vars]
        assert names == results.channels
        assert ds.attrs["description"] == results.description
        assert ds[str("Zahnrad ü.fn".encode().decode("latin1"))].attrs["description"] == "Kraft am Zahnrad – Zähne"


def read_globals(path: Path) -> dict:
    from jointplay.netcdf_classic import read_layout

    return read_layout(path).attributes


def test_streamed_file_equals_the_saved_file_byte_for_byte(tmp_path, dry_model):
    # on a 1 us grid 12001 samples x 53 channels come in several chunks of the core: blocks of records
    options = {"output_step": 1e-6, "max_output_bytes": "1 GiB"}
    kept = dry_model.simulate(0.012, **options)
    streamed = dry_model.simulate(0.012, output_file=tmp_path / "streamed.nc", **options)
    assert len(streamed) == len(kept) == 12001
    attrs = read_globals(tmp_path / "streamed.nc")  # the same when and how long (the rest is the same run)
    saved = resultsfile.save_netcdf(tmp_path / "saved.nc", kept.time, kept.channels, kept._units,
                                    kept._descriptions, kept.channel_block, attrs)
    assert (tmp_path / "streamed.nc").read_bytes() == saved.read_bytes()
    assert_file_holds(tmp_path / "streamed.nc", kept)


def writer_attributes(size: int) -> dict:
    return {"completed": 1, "model_json": "x" * size, "statistics_accepted_steps": 7, "wall_time_s": 0.25}


@pytest.mark.parametrize("size", [100, 300_000], ids=["header rewritten in place", "samples moved once"])
def test_final_header_in_place_or_samples_moved(tmp_path, size):
    names, times = ["a.x", "a.y"], np.linspace(0.0, 1.0, 7000)
    values = np.column_stack([np.sin(times), np.cos(times)])
    writer = resultsfile.ResultsWriter(tmp_path / "w.nc", names, ["m", "m"], ["x", "y"])
    for start in range(0, 7000, 3000):
        writer.append(times[start:start + 3000], values[start:start + 3000], start)
    path = writer.finish(writer_attributes(size))
    assert writer._file.moved == (size > resultsfile.header_reserve(2))
    saved = resultsfile.save_netcdf(tmp_path / "s.nc", times, names, ["m", "m"], ["x", "y"],
                                    lambda a, b: values[a:b].T, writer_attributes(size))
    assert path.read_bytes() == saved.read_bytes()
    with scipy.io.netcdf_file(path, mmap=False) as f:
        np.testing.assert_array_equal(f.variables["a.y"][:], values[:, 1])
        assert len(f._attributes["model_json"]) == size


def test_a_file_cut_after_a_block_reads_up_to_that_block(tmp_path):
    # a killed writer leaves its file as it was after its last block: the header's record count
    # is written after each block's samples, and the provisional global attributes say it did not finish
    from jointplay.netcdf_classic import RecordFile, records

    header = resultsfile.classic_header(["a.x", "a.y"], ["m", "m"], ["x", "y"])
    times = np.arange(10.0)
    values = np.column_stack([times * 2, -times])
    written = RecordFile(tmp_path / "w.nc", header, resultsfile.PROVISIONAL_ATTRIBUTES, 4096)
    written.append(records(times[:4], values[:4]))
    written.append(records(times[4:7], values[4:7]))
    cut = tmp_path / "cut.nc"
    cut.write_bytes((tmp_path / "w.nc").read_bytes() + records(times[7:], values[7:]).tobytes()[:20])
    written.close()  # (a third block half written after the count: not counted)
    with scipy.io.netcdf_file(cut, mmap=False) as f:
        assert f._recs == 7
        np.testing.assert_array_equal(f.variables["a.x"][:], values[:7, 0])
    back = open_results(cut)
    np.testing.assert_array_equal(back.time, times[:7])
    np.testing.assert_array_equal(back["a.y"], values[:7, 1])
    assert back.error is not None and "did not finish" in back.error["message"]


def test_more_samples_than_a_classic_file_counts(tmp_path, monkeypatch):
    from jointplay import netcdf_classic

    monkeypatch.setattr(netcdf_classic, "MAX_RECORDS", 4)
    results = Results(np.arange(5.0), ["a.x"], ["m"], ["x"], np.arange(5.0).reshape(1, 5), {}, {})
    with pytest.warns(RuntimeWarning, match="more than a NetCDF classic file holds .4.: .* NetCDF-4 instead"):
        path = results.save(tmp_path / "big.nc")
    assert h5py.is_hdf5(path)
    np.testing.assert_array_equal(open_results(path)["a.x"], np.arange(5.0))
    writer = resultsfile.ResultsWriter(tmp_path / "s.nc", ["a.x"], ["m"], ["x"])
    writer.append(np.arange(5.0), np.arange(5.0).reshape(5, 1))
    with pytest.raises(ValueError, match="5 samples are more than a NetCDF classic .* file holds .4,"):
        writer.finish({"completed": 1})
    assert not (tmp_path / "s.nc").exists() and not list(tmp_path.glob(".s.nc*"))


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
    assert read_globals(path)["jointplay_layout"] == resultsfile.CLASSIC_LAYOUT
    with xr.open_dataset(path, engine="scipy") as ds, xr.open_dataset(VERSION_2, engine="h5netcdf") as old:
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
