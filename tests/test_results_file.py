"""Results files: streamed NetCDF classic (NetCDF-4 with compress=True), its layout as xarray reads it, the CF
attributes, the output budget, CSV, and the rules that keep a good file from being lost."""

from __future__ import annotations

import json
import sys
from datetime import datetime
from pathlib import Path

import h5py
import scipy.io
import numpy as np
import pytest
import xarray as xr

import jointplay as jp
from jointplay import resultsfile
from jointplay.results import Results, open_results
from jointplay.resultsfile import ResultsWriter, parse_size, partial_path
from jointplay.resultslayout import CHUNK_SAMPLES

EXAMPLES = Path(__file__).parent.parent / "examples"
DRY = EXAMPLES / "flores_slider_crank_dry.toml"


def synthetic(n_channels: int, n_samples: int) -> Results:
    """Channel k at sample j holds k + j / n_samples (each value distinct and known)."""
    time = np.linspace(0.0, 1e-2, n_samples)
    values = np.arange(n_channels)[:, None] + np.arange(n_samples)[None, :] / n_samples
    names = [f"body{k}.x" for k in range(n_channels)]
    results = Results(time, names, ["m"] * n_channels, [f"position x of body {k}" for k in range(n_channels)],
                      values, {"accepted_steps": 7}, {"impacts": []}, spec={"name": "synthetic"})
    return results


def leftovers(folder: Path) -> list[str]:
    """Temporary files left in a folder."""
    return sorted(p.name for p in folder.iterdir() if p.name.endswith(".tmp"))


@pytest.fixture(scope="module")
def dry_model():
    return jp.load(DRY)


# layout ------------------------------------------------------------------------

def test_thousand_channels_round_trip_through_xarray_and_open_results(tmp_path):
    results = synthetic(1000, 3000)
    path = results.save(tmp_path / "wide.nc")
    with xr.open_dataset(path, engine="scipy") as ds:
        assert len(ds.data_vars) == 1000
        assert ds["body999.x"].dims == ("time",)
        assert ds["body999.x"].attrs["units"] == "m"
        assert ds["body999.x"].attrs["long_name"] == "position x of body 999"
        assert ds["time"].attrs["units"] == "s"
        np.testing.assert_array_equal(ds["body123.x"].values, 123 + np.arange(3000) / 3000)
        assert ds.encoding.get("unlimited_dims") == {"time"}, "the record dimension: each sample one record"
    back = open_results(path)
    assert back.channels == results.channels
    np.testing.assert_array_equal(back.time, results.time)
    np.testing.assert_array_equal(back["body999.x"], results["body999.x"])
    assert back.statistics == {"accepted_steps": 7}
    assert back.diagnostics == {"impacts": []}


def test_more_channels_than_an_attribute_of_64_kib_can_reference(tmp_path):
    # the time dimension's REFERENCE_LIST holds 12 bytes per channel: 5600 channels need 67 kB,
    # more than an HDF5 object header holds (a chain of 1000 bodies has 12003 channels)
    path = synthetic(5600, 2).save(tmp_path / "many.nc", compress=True)  # NetCDF-4 (HDF5)
    with h5py.File(path) as f:
        assert len(f["time"].attrs["REFERENCE_LIST"]) == 5600
        assert f[f["body5599.x"].attrs["DIMENSION_LIST"][0][0]].name == "/time"
    assert open_results(path)["body5599.x"].tolist() == [5599.0, 5599.5]


def test_a_slash_in_a_channel_name_is_escaped_in_the_file(tmp_path):
    results = synthetic(2, 5)
    results._names = ["arm/left.x", "arm/left.y"]
    results._index = {"arm/left.x": 0, "arm/left.y": 1}
    path = results.save(tmp_path / "slash.nc")
    with scipy.io.netcdf_file(path, mmap=False) as f:  # ("/" is no character of a NetCDF name either)
        assert sorted(f.variables) == ["arm%2Fleft.x", "arm%2Fleft.y", "time"]
        assert f.variables["arm%2Fleft.x"].channel == b"arm/left.x"
    packed = results.save(tmp_path / "slash4.nc", compress=True)
    with h5py.File(packed) as f:
        assert sorted(f) == ["arm%2Fleft.x", "arm%2Fleft.y", "time"]
    for written in (path, packed):
        back = open_results(written)
        assert back.channels == ["arm/left.x", "arm/left.y"]
        np.testing.assert_array_equal(back["arm/left.y"], results["arm/left.y"])


def test_saved_channels_are_classic_records_and_compressed_netcdf4_only_on_request(tmp_path):
    results = synthetic(3, 20000)
    plain = results.save(tmp_path / "plain.nc")
    packed = results.save(tmp_path / "packed.nc", compress=True)
    assert plain.read_bytes()[:4] == b"CDF\x02" and not h5py.is_hdf5(plain)
    with scipy.io.netcdf_file(plain, mmap=False) as f:
        assert f.dimensions == {"time": None} and f.variables["body1.x"].dimensions == ("time",)
        assert f._attributes["jointplay_layout"] == resultsfile.CLASSIC_LAYOUT.encode()
    with h5py.File(packed) as f:
        assert f.attrs["jointplay_layout"] == resultsfile.LAYOUT
        dataset = f["body1.x"]
        assert (dataset.compression, dataset.shuffle, dataset.chunks) == ("gzip", True, (CHUNK_SAMPLES,))
    assert packed.stat().st_size < 0.5 * plain.stat().st_size  # values k + j / n share most of their bytes
    for path in (plain, packed):
        back = open_results(path)
        np.testing.assert_array_equal(back["body2.x"], results["body2.x"])


def test_file_carries_cf_attributes_and_the_model_description(tmp_path, dry_model):
    results = dry_model.simulate(1e-3, output_file=tmp_path / "dry.nc")
    with xr.open_dataset(tmp_path / "dry.nc", engine="scipy") as ds:
        attrs = dict(ds.attrs)
        assert ds["slider.ax"].attrs["long_name"] == "centre of mass acceleration x"
        assert ds["slider.ax"].attrs["units"] == "m/s^2"
    assert attrs["Conventions"] == "CF-1.10"
    assert attrs["title"] == "jointplay results: flores_slider_crank_dry"
    assert attrs["source"] == f"jointplay {jp.__version__}" and attrs["jointplay_version"] == jp.__version__
    created = datetime.fromisoformat(attrs["date_created"].replace("Z", "+00:00"))
    assert created.utcoffset().total_seconds() == 0
    assert attrs["history"].startswith(attrs["date_created"] + " ")
    assert attrs["model_file"] == str(DRY)
    assert attrs["description"].startswith("Slider-crank, crank 50 mm, rod 120 mm, 5000 rpm")
    assert attrs["completed"] == 1 and "model_json" in attrs and "model_toml" in attrs
    assert attrs["statistics_accepted_steps"] == results.statistics["accepted_steps"]


def test_save_keeps_description_history_and_extrema(tmp_path, dry_model):
    first = dry_model.simulate(5e-4, output_file=tmp_path / "a.nc")
    opened = open_results(tmp_path / "a.nc")
    opened.extrema = {"B.fn": {"peak": 4.5e4, "time": 2.3e-4}}
    opened.save(tmp_path / "b.nc")
    again = open_results(tmp_path / "b.nc")
    assert again.description == first.description != ""
    assert again.model_file == str(DRY)
    assert again.history.splitlines()[0] == opened.history, "history gets one line per writer"
    assert len(again.history.splitlines()) == 2
    assert again.extrema == {"B.fn": {"peak": 4.5e4, "time": 2.3e-4}}
    with scipy.io.netcdf_file(tmp_path / "b.nc", mmap=False) as f:
        assert json.loads(f._attributes["extrema_json"]) == opened.extrema
    assert open_results(tmp_path / "a.nc").extrema == first.extrema, "the run's own extrema, as tracked"


def test_files_written_through_xarray_before_still_open(tmp_path):
    results = synthetic(4, 50)
    results.error = {"kind": "NonFinite", "message": "non-finite value in B", "time": 0.01, "element": "B"}
    results.diagnostics = {"impacts": [3]}
    results.to_xarray().to_netcdf(tmp_path / "old.nc", engine="h5netcdf")  # how files were written before
    back = open_results(tmp_path / "old.nc")
    assert back.channels == results.channels
    np.testing.assert_array_equal(back["body3.x"], results["body3.x"])
    assert back.unit("body3.x") == "m"
    assert back.error["message"] == "non-finite value in B"
    assert back.diagnostics["impacts"] == [3]
    assert back.path is None, "read whole"


# streaming ---------------------------------------------------------------------

def test_streamed_run_equals_the_run_in_memory_over_several_chunks(tmp_path, dry_model):
    # 24001 samples of 53 channels: three chunks of about 4 MiB from the core
    options = {"output_step": 1e-6}
    kept = dry_model.simulate(0.024, **options)
    streamed = dry_model.simulate(0.024, output_file=tmp_path / "s.nc", **options)
    assert len(streamed) == len(kept) == 24001
    assert streamed.path == tmp_path / "s.nc"
    assert type(streamed._values).__name__ == "FileChannels", "channels are read on access"
    np.testing.assert_array_equal(streamed.time, kept.time)
    for name in ("slider.ax", "B.fn", "B.ex", "system.energy"):
        np.testing.assert_array_equal(streamed[name], kept[name])
    assert streamed.summary()["peaks"] == kept.summary()["peaks"]
    assert leftovers(tmp_path) == []


# peak resident memory of this process image [kB] (ru_maxrss would start from the parent's peak)
MEMORY = """
import sys, jointplay as jp
def peak():
    return int(next(line for line in open("/proc/self/status") if line.startswith("VmHWM")).split()[1])
m = jp.load(sys.argv[1])
m.simulate(1e-3)
before = peak()
short = m.simulate(0.25, output_step=1e-6, output_file=sys.argv[2])
grown_short = (peak() - before) / 1024
long = m.simulate(0.5, output_step=1e-6, output_file=sys.argv[2])
print(len(short), len(long), grown_short, (peak() - before) / 1024)
"""


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads the peak memory from Linux /proc")
def test_streamed_run_keeps_its_memory_bounded(tmp_path):
    # 250001 samples x 53 channels = 106 MB of samples, then twice as many: a streamed run holds a few
    # chunks of them (the core's, the one the background writer copies, the writer's buffer) and its
    # times (8 bytes a sample), so its peak memory does not grow with the samples
    import subprocess
    import sys

    printed = subprocess.run([sys.executable, "-c", MEMORY, str(DRY), str(tmp_path / "long.nc")], check=True,
                             capture_output=True, text=True).stdout.split()
    assert (int(printed[0]), int(printed[1])) == (250001, 500001)
    short, long = float(printed[2]), float(printed[3])
    assert short < 50, f"peak memory grew by {short} MiB for 106 MB of samples"
    assert long - short < 15, f"peak memory grew by {long - short} MiB more for 106 MB more samples"


def test_progress_reports_the_end_of_a_streamed_run(tmp_path, dry_model):
    seen = []
    dry_model.simulate(2e-3, output_file=tmp_path / "p.nc", progress=seen.append)
    assert seen[-1] == pytest.approx(2e-3, rel=1e-12)


def test_sink_receives_chunks_bounded_by_the_core(dry_model):
    chunks = []
    core = dry_model.compile()
    raw = core.simulate(0.0, 0.024, {"output_step": 1e-6}, None,
                        lambda t, v, start: chunks.append((t.copy(), v.shape)))
    assert raw["error"] is None and raw["time"].size == 0
    rows = (4 << 20) // (8 * 53)
    assert [shape for _, shape in chunks] == [(rows, 53), (rows, 53), (24001 - 2 * rows, 53)]
    np.testing.assert_allclose(np.concatenate([t for t, _ in chunks]), np.arange(24001) * 1e-6, atol=1e-15)


def test_exception_in_the_sink_stops_the_run_and_is_raised(dry_model):
    calls = []

    def sink(times, values, start):
        calls.append(times.size)
        raise OSError("No space left on device")

    with pytest.raises(OSError, match="No space left on device"):
        dry_model.compile().simulate(0.0, 0.024, {"output_step": 1e-6}, None, sink)
    assert calls == [(4 << 20) // (8 * 53)], "the run stopped at the first failing chunk"


# nothing lost --------------------------------------------------------------------

def good_file(tmp_path: Path) -> tuple[Path, bytes]:
    path = synthetic(3, 10).save(tmp_path / "out.nc")
    return path, path.read_bytes()


def test_failed_run_goes_to_partial_name_and_leaves_a_good_file(tmp_path, dry_model):
    path, before = good_file(tmp_path)
    with pytest.raises(jp.SimulationError) as caught:
        dry_model.simulate(0.024, output_file=path, max_output_bytes=100 * 53 * 8)
    assert path.read_bytes() == before
    assert caught.value.kind == "OutputBudgetExceeded"
    results = caught.value.results
    assert results.path == tmp_path / "out.partial.nc" == partial_path(path)
    assert len(results) == 100, "what fits in the budget is kept"
    partial = open_results(results.path)
    assert partial.error["kind"] == "OutputBudgetExceeded"
    np.testing.assert_array_equal(partial["slider.x"], results["slider.x"])
    assert leftovers(tmp_path) == []


def test_interrupted_run_leaves_a_good_file_and_no_temporary(tmp_path, dry_model, monkeypatch):
    # Ctrl-C inside the hand-over of the second chunk: the chunk is handed over again, the run stops as
    # interrupted, and what was computed goes to the partial file; the good file stays as it was
    path, before = good_file(tmp_path)
    append = ResultsWriter.append
    interrupts = []

    def interrupted_once_on_second_chunk(self, times, values, start=None):
        if start and not interrupts:
            interrupts.append(start)
            raise KeyboardInterrupt
        append(self, times, values, start)

    monkeypatch.setattr(ResultsWriter, "append", interrupted_once_on_second_chunk)
    with pytest.raises(jp.SimulationError) as caught:
        dry_model.simulate(0.024, output_file=path, output_step=1e-6)
    assert caught.value.kind == "Interrupted" and interrupts
    assert path.read_bytes() == before
    partial = open_results(partial_path(path))
    assert len(partial) > interrupts[0] and np.all(np.diff(partial.time) > 0), "the retried chunk is there once"
    np.testing.assert_allclose(partial.time, np.arange(len(partial)) * 1e-6, atol=1e-15)
    assert leftovers(tmp_path) == []


def test_ctrl_c_pressed_again_and_again_stops_the_run_with_what_was_written(tmp_path, dry_model, monkeypatch):
    path, before = good_file(tmp_path)
    append = ResultsWriter.append

    def always_interrupted_after_the_first_chunk(self, times, values, start=None):
        if start:
            raise KeyboardInterrupt
        append(self, times, values, start)

    monkeypatch.setattr(ResultsWriter, "append", always_interrupted_after_the_first_chunk)
    with pytest.raises(jp.SimulationError) as caught:
        dry_model.simulate(0.024, output_file=path, output_step=1e-6)
    assert caught.value.kind == "OutputSink" and "interrupted (Ctrl-C)" in caught.value.cause
    assert path.read_bytes() == before
    assert len(open_results(partial_path(path))) == (4 << 20) // (8 * 53), "the first chunk"
    assert leftovers(tmp_path) == []


def test_two_writers_of_one_path_leave_one_complete_result(tmp_path):
    names = ["a.x", "a.y"]
    first = ResultsWriter(tmp_path / "out.nc", names, ["m", "m"], ["x", "y"])
    second = ResultsWriter(tmp_path / "out.nc", names, ["m", "m"], ["x", "y"])
    assert first.temporary != second.temporary
    first.append(np.arange(5.0), np.ones((5, 2)))
    second.append(np.arange(7.0), 2 * np.ones((7, 2)))
    second.finish({"completed": 1, "jointplay_layout": resultsfile.LAYOUT})
    assert len(open_results(tmp_path / "out.nc")) == 7
    first.append(np.arange(5.0, 9.0), np.ones((4, 2)))
    first.finish({"completed": 1, "jointplay_layout": resultsfile.LAYOUT})
    last = open_results(tmp_path / "out.nc")
    assert len(last) == 9 and np.all(last["a.y"] == 1.0), "the last complete result, whole"
    assert leftovers(tmp_path) == []


def test_run_stopped_before_its_first_sample_gives_an_empty_partial_file(tmp_path):
    writer = ResultsWriter(tmp_path / "out.nc", ["a.x"], ["m"], ["x"])
    path = writer.finish({"completed": 0, "jointplay_layout": resultsfile.LAYOUT}, complete=False)
    assert path == tmp_path / "out.partial.nc"
    assert len(open_results(path)) == 0 and open_results(path)["a.x"].size == 0
    with xr.open_dataset(path, engine="scipy") as ds:
        assert ds.sizes["time"] == 0 and ds["a.x"].dims == ("time",)


def test_writer_that_cannot_start_leaves_no_temporary(tmp_path):
    with pytest.raises(ValueError):
        ResultsWriter(tmp_path / "out.nc", ["a.x", "a.x"], ["m", "m"], ["x", "x"])  # a name twice
    assert list(tmp_path.iterdir()) == []


def test_aborted_writer_removes_its_temporary_only(tmp_path):
    path, before = good_file(tmp_path)
    writer = ResultsWriter(path, ["a.x"], ["m"], ["x"])
    writer.append(np.arange(3.0), np.zeros((3, 1)))
    writer.abort()
    assert path.read_bytes() == before and leftovers(tmp_path) == []


# budget --------------------------------------------------------------------------

def test_budget_refuses_a_run_on_a_grid_that_cannot_fit(tmp_path, dry_model):
    with pytest.raises(jp.ModelError) as caught:
        dry_model.simulate(8.0, output_step=1e-6, output_file=tmp_path / "big.nc")
    assert str(caught.value) == (
        "simulation.max_output_bytes: the run would write 8000001 samples x 53 channels x 8 bytes = 3.16 GiB, "
        "above max_output_bytes = 2 GiB; raise max_output_bytes, set a coarser output_step or a shorter t_end")
    assert list(tmp_path.iterdir()) == []


def test_budget_in_memory_is_one_gibibyte_by_default(dry_model):
    with pytest.raises(jp.ModelError, match=r"= 1.58 GiB, above max_output_bytes = 1 GiB"):
        dry_model.simulate(4.0, output_step=1e-6)


def test_budget_during_a_run_keeps_what_fits(dry_model):
    with pytest.raises(jp.SimulationError) as caught:
        dry_model.simulate(0.024, max_output_bytes="10 KiB")
    samples = 10 * 1024 // (53 * 8)
    message = str(caught.value)
    assert message.startswith("during the simulation: output budget max_output_bytes = 10240 bytes reached at t = ")
    assert message.endswith(f" s ({samples} samples x 53 channels x 8 bytes); raise max_output_bytes, "
                            "set a coarser output_step or a shorter t_end")
    assert caught.value.kind == "OutputBudgetExceeded" and 0 < caught.value.time < 1e-3
    assert len(caught.value.results) == samples


@pytest.mark.parametrize(("raw", "expected"), [
    (2048, 2048), ("2 GiB", 2 * 1024**3), ("500 MB", 500 * 10**6), ("1.5 KiB", 1536), ("10B", 10)])
def test_sizes_are_read_with_binary_and_decimal_units(raw, expected):
    assert parse_size(raw) == expected


@pytest.mark.parametrize(("raw", "message"), [
    ("2 parsecs", "must be a size such as \"500 MB\" or \"2 GiB\" (units B, kB, MB, GB, TB, KiB, MiB, GiB, TiB), "
                  "got '2 parsecs'"),
    ("10**10**8 B", "must be a size such as"),
    (-5, "must be a size > 0 bytes, got -5"),
    (True, "must be a size in bytes, e.g. 2147483648 or \"2 GiB\", got True"),
])
def test_bad_sizes_are_refused_naming_the_value(raw, message):
    with pytest.raises(ValueError) as caught:
        parse_size(raw)
    assert str(caught.value).startswith(message)


def test_model_file_key_max_output_bytes(dry_model):
    text = DRY.read_text() + '\nmax_output_bytes = "1 MB"\n'
    assert jp.loads(text).simulation["max_output_bytes"] == 10**6
    with pytest.raises(jp.ModelError) as caught:
        jp.loads(DRY.read_text() + '\nmax_output_bytes = "huge"\n')
    assert str(caught.value).startswith('simulation.max_output_bytes: must be a size such as "500 MB"')


# CSV ------------------------------------------------------------------------------

def test_csv_has_time_and_one_column_per_channel_with_units(tmp_path):
    results = synthetic(3, 70000)  # more than one block
    path = results.save(tmp_path / "r.csv")
    with open(path) as f:
        assert f.readline().strip() == "time [s],body0.x [m],body1.x [m],body2.x [m]"
    table = np.loadtxt(path, delimiter=",", skiprows=1)
    assert table.shape == (70000, 4)
    np.testing.assert_array_equal(table[:, 0], results.time)
    np.testing.assert_array_equal(table[:, 3], results["body2.x"])


def test_save_refuses_an_unknown_suffix(tmp_path):
    # a ModelError (a ValueError) located at the user's path
    with pytest.raises(ValueError, match=r"r\.txt: unknown results format '.txt': use .nc, .nc4 or .h5 for NetCDF, "
                                         r".csv for CSV$"):
        synthetic(1, 3).save(tmp_path / "r.txt")
    assert list(tmp_path.iterdir()) == []



def test_a_chunk_handed_over_again_is_written_once(tmp_path):
    # after Ctrl-C interrupts the sink call, the core hands the same chunk over again with the same start
    from jointplay.resultsfile import ResultsWriter

    writer = ResultsWriter(tmp_path / "w.nc", ["a.x", "a.y"], ["m", "m"], ["x", "y"])
    times = np.arange(5.0)
    values = np.column_stack([times, -times])
    writer.append(times, values, 0)
    writer.append(times, values, 0)
    writer.append(times + 5, values, 5)
    np.testing.assert_array_equal(writer.times(), np.arange(10.0))
    target = writer.finish({})
    again = open_results(target)
    np.testing.assert_array_equal(again["a.y"], -np.r_[times, times])


@pytest.mark.skipif(sys.platform == "win32", reason="sends SIGINT to a child process")
def test_ctrl_c_during_a_streamed_run_keeps_what_was_computed(tmp_path):
    import signal
    import subprocess
    import time as clock

    out = tmp_path / "long.nc"
    command = [sys.executable, "-m", "jointplay.cli", "run", str(DRY), "-o", str(out), "-q", "--t-end", "20 s"]
    # the child gets the default SIGINT disposition, as in a terminal (a background job ignores it)
    child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    clock.sleep(3.0)
    child.send_signal(signal.SIGINT)
    _, stderr = child.communicate(timeout=60)
    assert child.returncode == 1, stderr
    assert "simulation failed (Interrupted)" in stderr and "long.partial.nc" in stderr
    assert not out.exists()
    partial = open_results(tmp_path / "long.partial.nc")
    assert len(partial) > 1000 and np.all(np.diff(partial.time) > 0), "every sample once, in order"
    assert partial.extrema["channels"]["B.fn"]["peak"] > 4e4, "the summary of what was computed is kept"


# SIGTERM and killed runs (issue 32, item 5) -------------------------------------

# a long streamed run: prints "started" once its temporary file exists, then runs for minutes
TERMINATED = """
import sys, time
from pathlib import Path
import jointplay as jp
m = jp.load(sys.argv[1])
out = Path(sys.argv[2])
def progress(t):
    if any(p.name.endswith(".tmp") for p in out.parent.iterdir()):
        print("started", flush=True)
m.simulate(1000.0, output_file=out, progress=progress)
"""


@pytest.mark.skipif(sys.platform == "win32", reason="SIGTERM ends a Windows process without a handler")
def test_sigterm_stops_a_streamed_run_and_removes_its_temporary_file(tmp_path):
    # SIGTERM (kill, a batch system's time limit) used to end the process at once and leave the
    # hidden temporary file (500 MB after a long run); now the run stops within its watch interval,
    # the temporary file is removed and the process exits with 143 (128 + SIGTERM)
    import signal
    import subprocess

    out = tmp_path / "long.nc"
    process = subprocess.Popen([sys.executable, "-c", TERMINATED, str(DRY), str(out)], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    try:
        assert process.stdout.readline().strip() == "started", process.stderr.read()
        process.send_signal(signal.SIGTERM)
        status = process.wait(timeout=60)
    finally:
        process.kill()
    assert status == resultsfile.TERMINATED_STATUS == 143
    assert leftovers(tmp_path) == [] and not out.exists()


def test_temporary_files_of_killed_runs_are_removed_by_the_next_run(tmp_path, dry_model):
    # SIGKILL cannot be caught: the next run on the same path removes what a writer whose process is
    # gone left, and leaves the temporaries of live writers (this process) and of other paths alone
    import subprocess

    gone = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True,
                          check=True).stdout.strip()
    stale = tmp_path / f".run.nc.{gone}-0123abcd.tmp"
    live = resultsfile.temporary_path(tmp_path / "run.nc")
    other = tmp_path / f".other.nc.{gone}-0123abcd.tmp"
    for p in (stale, live, other):
        p.write_bytes(b"partial")
    dry_model.simulate(1e-4, output_file=tmp_path / "run.nc")
    assert leftovers(tmp_path) == sorted([live.name, other.name])
    assert (tmp_path / "run.nc").exists()
