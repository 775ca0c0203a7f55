"""Benchmark: writing and reading results files, and the memory of a long run.

1. Writing a synthetic results set of N channels x S samples with
   ``Results.save`` (h5py, NetCDF-4 layout, dimension lists written once)
   against the writer it replaced (``to_xarray().to_netcdf(engine="h5netcdf")``),
   interleaved, for several channel counts: the old writer grows roughly with
   the square of the channel count, the new one linearly. Reading back with
   ``open_results`` (channels on access) is timed too.
2. A hanging chain of B bodies (9 channels per body, 4 per joint): a run of
   a few samples streamed to a file, and the same results saved again.
3. Peak memory (VmHWM, Linux) of the dry Flores slider-crank sampled every 1 us,
   kept in memory against streamed to a file, each in a fresh process.

Prints medians of the repeats with the spread (min-max). Absolute times drift on
shared machines; the ratio is what is reported.

Run: python benches/bench_results_file.py [--repeats N] [--samples S] [--channels 250,500,1000]
     [--baseline-max 500] [--t-end 0.2] [--bodies 1000]
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from jointplay.results import Results, open_results

ROOT = Path(__file__).resolve().parents[1]


def synthetic(n_channels: int, n_samples: int) -> Results:
    rng = np.random.default_rng(1)
    names = [f"body{k}.x" for k in range(n_channels)]
    return Results(np.linspace(0, 1, n_samples), names, ["m"] * n_channels, ["position x"] * n_channels,
                   rng.standard_normal((n_channels, n_samples)), {"accepted_steps": 1}, {"impacts": []},
                   spec={"name": "synthetic"})


def chain(n_bodies: int):
    """A chain of bars 0.1 m long hanging from a pin, each pinned to the next."""
    import jointplay as jp

    m = jp.Model("chain", gravity=(0.0, -9.81))
    m.add_ground_point("O", (0.0, 0.0))
    previous = "ground.O"
    for k in range(n_bodies):
        m.add_body(f"bar{k}", 0.1, 1e-4, position=(0.1 * k + 0.05, 0.0), points={"a": (-0.05, 0.0), "b": (0.05, 0.0)})
        m.add_revolute(f"pin{k}", previous, f"bar{k}.a")
        previous = f"bar{k}.b"
    return m


def chain_times(n_bodies: int, repeats: int, folder: Path) -> tuple[int, int, list[float], list[float]]:
    """(channels, samples, wall times of a streamed run, of saving its results again) [s]."""
    model = chain(n_bodies)
    model.compile()
    runs, saves, results = [], [], None
    for k in range(repeats):
        started = time.perf_counter()
        results = model.simulate(1e-3, output_step=1e-4, output_file=folder / f"chain-{k}.nc")
        runs.append(time.perf_counter() - started)
        saves.append(timed(lambda: results.save(folder / f"chain-copy-{k}.nc")))
    return len(results.channels), len(results), runs, saves


def timed(f) -> float:
    started = time.perf_counter()
    f()
    return time.perf_counter() - started


def write_times(n_channels: int, n_samples: int, repeats: int, baseline: bool, folder: Path) -> dict[str, list[float]]:
    """Interleaved wall times [s] of the new writer, the old one (if asked) and reading back."""
    results = synthetic(n_channels, n_samples)
    times: dict[str, list[float]] = {"save": [], "open_results + read all": []}
    if baseline:
        times["xarray to_netcdf (before)"] = []
    for k in range(repeats):
        path = folder / f"new{n_channels}-{k}.nc"
        times["save"].append(timed(lambda: results.save(path)))

        def read_all():
            r = open_results(path)
            for name in r.channels:
                r[name]

        times["open_results + read all"].append(timed(read_all))
        if baseline:
            old = folder / f"old{n_channels}-{k}.nc"
            times["xarray to_netcdf (before)"].append(timed(lambda: results.to_xarray().to_netcdf(old, engine="h5netcdf")))
    return times


# VmHWM (peak resident memory of this process image [kB]); ru_maxrss would carry the parent's over exec
PEAK = """
import sys, jointplay as jp
m = jp.load(sys.argv[1])
out = sys.argv[3] if len(sys.argv) > 3 else None
r = m.simulate(float(sys.argv[2]), output_step=1e-6, output_file=out)
peak = next(line for line in open("/proc/self/status") if line.startswith("VmHWM"))
print(len(r), int(peak.split()[1]) / 1024)
"""


def peak_memory(t_end: float, folder: Path) -> list[tuple[str, int, float]]:
    """(case, samples, max RSS [MiB]) of the dry example at 1 us, in memory and streamed."""
    model = str(ROOT / "examples" / "flores_slider_crank_dry.toml")
    rows = []
    for case, extra in (("in memory", []), ("streamed to .nc", [str(folder / "long.nc")])):
        printed = subprocess.run([sys.executable, "-c", PEAK, model, str(t_end), *extra], check=True,
                                 capture_output=True, text=True).stdout.split()
        rows.append((case, int(printed[0]), float(printed[1])))
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--samples", type=int, default=3000)
    parser.add_argument("--channels", default="250,500,1000")
    parser.add_argument("--baseline-max", type=int, default=500, help="largest channel count for the old writer")
    parser.add_argument("--t-end", type=float, default=0.2, help="simulated time of the memory case [s]")
    parser.add_argument("--bodies", type=int, default=1000, help="bodies of the chain")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        print(f"write/read, {args.samples} samples, median [min-max] of {args.repeats} interleaved repeats")
        print(f"{'channels':>8}  {'writer':<28} {'median s':>9}  spread")
        for n in (int(c) for c in args.channels.split(",")):
            times = write_times(n, args.samples, args.repeats, n <= args.baseline_max, Path(folder))
            for name, values in times.items():
                print(f"{n:>8}  {name:<28} {statistics.median(values):>9.3f}  [{min(values):.3f}-{max(values):.3f}]")
            if len(times) == 3:
                ratio = statistics.median(times["xarray to_netcdf (before)"]) / statistics.median(times["save"])
                print(f"{'':>8}  {'speed-up of save':<28} {ratio:>9.1f}")
        channels, samples, runs, saves = chain_times(args.bodies, args.repeats, Path(folder))
        print(f"\nchain of {args.bodies} bodies: {channels} channels, {samples} samples")
        for name, values in (("run streamed to .nc", runs), ("save again", saves)):
            print(f"  {name:<28} {statistics.median(values):>9.3f}  [{min(values):.3f}-{max(values):.3f}]")
        print(f"\npeak memory, dry slider-crank sampled every 1 us for {args.t_end} s")
        for case, samples, rss in peak_memory(args.t_end, Path(folder)):
            print(f"  {case:<16} {samples:>9} samples  max RSS {rss:8.1f} MiB")


if __name__ == "__main__":
    main()
