"""Benchmark: what writing results and reading a model file cost against the run.

1. Targets, in interleaved rounds in one process (``benches/timing.py``): for the
   dry Flores slider-crank (examples/flores_slider_crank_dry.toml, 0.1 s, a sample
   at every accepted step) and a hanging chain of 64 bars (absolute coordinates, the
   faster formulation at this size, 1 s, a sample at every step):
   - the run kept in memory;
   - ``Results.save`` of its results to a new file (NetCDF classic), as a fraction of
     the run (target <= 10 %);
   - the run streamed to a file (``output_file``), its extra cost over the run
     (target <= 25 %);
   - the floor of any writer: as many bytes as the saved file written to a new file
     by one ``os.write``;
   and ``jointplay.load`` of the dry model file against the run it describes
   (its own ``[simulation]``: 24 ms simulated). Ratios are formed round by round
   and reported as median [min-max], CPU time of the process (the streaming
   writer's thread included) and wall time; a target is met when every round meets it.
2. ``Results.save`` of synthetic results (N channels x S samples), plain (classic)
   and compressed (NetCDF-4), against xarray's writer
   (``to_xarray().to_netcdf(engine="h5netcdf")``), and reading back with ``open_results``.
3. Peak memory (VmHWM, Linux) of the dry slider-crank sampled every 1 us, kept
   in memory against streamed to a file, each in a fresh process.

Measured on the 2-core development machine with other jobs running (load 2.8-3.5),
12 rounds, CPU time, median [min-max]; "before": the NetCDF-4 writer of layout v3
(HDF5 datasets through low-level h5py, 12 rounds, load 2-2.6):

    case                                  run [ms]          save / run          streaming adds       bytes alone / run
    dry slider-crank 0.1 s (53 x 8196)    17.8 [17.4-22.3]  16.4 % [13.8-21]    27.9 % [8.4-56]      6.7 % [5.5-24]
      second run of the benchmark         17.7 [17.4-22.3]  15 % [11.7-18.4]    24.2 % [20.3-58.3]   10.8 % [4.4-32.3]
      before (NetCDF-4, v3)               21.8 [17.6-30.2]  83 % [72-125]       97 % [64-212]
    chain of 64 bars 1 s (771 x 553)      659 [652-667]     1.43 % [1.33-1.61]  1.96 % [0.38-3.15]   0.23 % [0.17-0.91]
      second run of the benchmark         669 [655-754]     1.39 % [1.3-1.45]   2.22 % [-3.4-4.2]    0.58 % [0.14-0.86]
      before (NetCDF-4, v3)               784 [730-1060]    18.7 % [12.1-22.6]  21 % [-20-45]
    jp.load(dry model) / its 24 ms run    1.87 ms / 4.75 ms = 39 % [37-44]
    1000 channels x 3000 samples (wall)   save 0.020 s, compress=True 0.88 s, open_results + read all 0.093 s
    peak memory, dry at 1 us for 0.2 s    136 MiB in memory, 78 MiB streamed (load 2-2.9)

Targets (save <= 10 %, streaming <= 25 % of the run, in every round): the chain
meets both in every round; the dry run misses both. Its 3.6 MB written into a
new file alone cost 1-4 ms of CPU time on this machine (the "bytes alone"
column, above 10 % of the run in some rounds by itself), and the save adds about
1.5 ms to them (docs/results-file.md, "What a file costs to write").

Absolute times drift on shared machines; the ratios are what is reported.

Run: python benches/bench_results_file.py [--rounds N] [--samples S] [--channels 250,500,1000]
     [--baseline-max 500] [--t-end 0.2] [--skip-memory] [--skip-synthetic]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from itertools import count
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import jointplay as jp  # noqa: E402
from jointplay import mechanisms  # noqa: E402
from jointplay.results import Results, open_results  # noqa: E402
from timing import Case, Spread, interleave, ratio, verdict  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
DRY = ROOT / "examples" / "flores_slider_crank_dry.toml"
#: Targets: saving at most this fraction of the run, streaming at most this extra fraction.
SAVE_TARGET, STREAM_TARGET = 0.10, 0.25


def synthetic(n_channels: int, n_samples: int) -> Results:
    rng = np.random.default_rng(1)
    names = [f"body{k}.x" for k in range(n_channels)]
    return Results(np.linspace(0, 1, n_samples), names, ["m"] * n_channels, ["position x"] * n_channels,
                   rng.standard_normal((n_channels, n_samples)), {"accepted_steps": 1}, {"impacts": []},
                   spec={"name": "synthetic"})


def chain(n_bodies: int):
    """A chain of bars 0.1 m long hanging from a pin, each pinned to the next."""
    return mechanisms.hanging_chain(n_bodies)


def timed(f) -> float:
    started = time.perf_counter()
    f()
    return time.perf_counter() - started


# 1. targets --------------------------------------------------------------------------

def output_cases(label: str, run, folder: Path) -> list[Case]:
    """The run in memory, saving its results to a new file, the run streamed to a new file, and the
    floor of a save: as many bytes as the saved file written to a new file by one ``os.write``."""
    names = count()
    held: dict[str, Results] = {}

    def in_memory():
        held["results"] = run()
        return held["results"]

    def save():
        held["saved"] = held["results"].save(folder / f"{label}-save-{next(names)}.nc")
        return held["saved"]

    def streamed():
        return run(output_file=folder / f"{label}-stream-{next(names)}.nc")

    def bare_write():
        data = held.setdefault("bytes", bytes(held["saved"].stat().st_size))
        fd = os.open(folder / f"{label}-bare-{next(names)}.bin", os.O_WRONLY | os.O_CREAT | os.O_TRUNC)
        try:
            os.write(fd, data)
        finally:
            os.close(fd)

    return [Case(f"{label}: run", in_memory), Case(f"{label}: save", save), Case(f"{label}: streamed run", streamed),
            Case(f"{label}: bare write", bare_write)]


def extra(streamed: Case, run: Case, clock: str) -> Spread:
    """Per-round (streamed run - run) / run."""
    num = streamed.walls if clock == "wall" else streamed.cpus
    den = run.walls if clock == "wall" else run.cpus
    return Spread.of([a / b - 1.0 for a, b in zip(num, den) if a is not None and b])


def every(s: Spread, target: float) -> str:
    """Whether a target is met by the median and by every round (the largest ratio)."""
    return (f"median {verdict(s.median, '<=', target).strip()}, "
            f"every round {verdict(s.high, '<=', target).strip()}")


def span(s: Spread, scale: float = 100.0, unit: str = " %") -> str:
    return f"{scale * s.median:.3g}{unit} [{scale * s.low:.3g}-{scale * s.high:.3g}]"


def targets(rounds: int, folder: Path) -> None:
    dry = jp.load(DRY)
    options = dict(dry.simulation)
    options.pop("t_end", None)
    described = dry.simulation["t_end"]
    chain64 = chain(64)
    chain64.compile()
    cases = {
        "dry": output_cases("dry", lambda **kw: dry.simulate(0.1, **options, **kw), folder),
        "chain": output_cases("chain64", lambda **kw: chain64.simulate(1.0, formulation="absolute", **kw), folder),
    }
    load = Case("jp.load(dry)", lambda: jp.load(DRY))
    described_run = Case("dry run of its [simulation]", lambda: dry.simulate(described, **options))
    everything = [*cases["dry"], *cases["chain"], load, described_run]
    for case in everything:  # warm-up: imports, caches, first compile
        case.time_once()
        case.walls.clear()
        case.cpus.clear()
    interleave(everything, rounds)
    print(f"\n1. output and loading against the run: median [min-max] of {rounds} interleaved rounds")
    for label, (run, save, streamed, bare) in cases.items():
        results = run.last
        print(f"\n{label}: {len(results.channels)} channels x {len(results)} samples, "
              f"{results.statistics['formulation']} formulation, file {save.last.stat().st_size / 1e6:.2f} MB")
        for clock in ("cpu", "wall"):
            ran = Spread.of(run.values(clock))
            saving = ratio(save, run, clock)
            streaming = extra(streamed, run, clock)
            floor = ratio(bare, run, clock)
            print(f"  {clock:4s} run {span(ran, 1e3, ' ms')}; save {span(Spread.of(save.values(clock)), 1e3, ' ms')}"
                  f" = {span(saving)} of the run [{every(saving, SAVE_TARGET)}]; "
                  f"streaming adds {span(streaming)} [{every(streaming, STREAM_TARGET)}]; "
                  f"the file's bytes written alone {span(floor)} of the run")
    for clock in ("cpu", "wall"):
        fraction = ratio(load, described_run, clock)
        print(f"\njp.load({DRY.name}) {clock}: {span(Spread.of(load.values(clock)), 1e3, ' ms')}, "
              f"{span(fraction)} of the run it describes ({described * 1e3:g} ms simulated, "
              f"{span(Spread.of(described_run.values(clock)), 1e3, ' ms')})")


# 2. synthetic results against the xarray writer ----------------------------------------

def write_times(n_channels: int, n_samples: int, repeats: int, baseline: bool, folder: Path) -> dict[str, list[float]]:
    """Interleaved wall times [s] of ``save``, the xarray writer (if asked) and reading back."""
    results = synthetic(n_channels, n_samples)
    times: dict[str, list[float]] = {"save": [], "save(compress=True)": [], "open_results + read all": []}
    if baseline:
        times["xarray to_netcdf"] = []
    for k in range(repeats):
        path = folder / f"new{n_channels}-{k}.nc"
        times["save"].append(timed(lambda: results.save(path)))
        times["save(compress=True)"].append(timed(lambda: results.save(folder / f"gz{n_channels}-{k}.nc",
                                                                       compress=True)))

        def read_all():
            r = open_results(path)
            for name in r.channels:
                r[name]

        times["open_results + read all"].append(timed(read_all))
        if baseline:
            old = folder / f"old{n_channels}-{k}.nc"
            times["xarray to_netcdf"].append(timed(lambda: results.to_xarray().to_netcdf(old, engine="h5netcdf")))
    return times


def synthetic_table(args, folder: Path) -> None:
    print(f"\n2. write/read, {args.samples} samples, wall time, median [min-max] of {args.rounds} repeats")
    print(f"{'channels':>8}  {'writer':<28} {'median s':>9}  spread")
    for n in (int(c) for c in args.channels.split(",")):
        times = write_times(n, args.samples, args.rounds, n <= args.baseline_max, folder)
        for name, values in times.items():
            print(f"{n:>8}  {name:<28} {statistics.median(values):>9.4f}  [{min(values):.4f}-{max(values):.4f}]")
        if "xarray to_netcdf" in times:
            speedup = statistics.median(times["xarray to_netcdf"]) / statistics.median(times["save"])
            print(f"{'':>8}  {'speed-up of save':<28} {speedup:>9.1f}")


# 3. memory -----------------------------------------------------------------------------

# VmHWM (peak resident memory of this process image [kB]); ru_maxrss would carry the parent's over exec
PEAK = """
import sys, jointplay as jp
m = jp.load(sys.argv[1])
out = sys.argv[3] if len(sys.argv) > 3 else None
r = m.simulate(float(sys.argv[2]), output_step=1e-6, output_file=out)
peak = next(line for line in open("/proc/self/status") if line.startswith("VmHWM"))
print(len(r), int(peak.split()[1]) / 1024)
"""


def peak_memory(t_end: float, folder: Path) -> None:
    print(f"\n3. peak memory, dry slider-crank sampled every 1 us for {t_end} s")
    for case, extra_args in (("in memory", []), ("streamed to .nc", [str(folder / "long.nc")])):
        printed = subprocess.run([sys.executable, "-c", PEAK, str(DRY), str(t_end), *extra_args], check=True,
                                 capture_output=True, text=True).stdout.split()
        print(f"  {case:<16} {int(printed[0]):>9} samples  max RSS {float(printed[1]):8.1f} MiB")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=12)
    parser.add_argument("--samples", type=int, default=3000)
    parser.add_argument("--channels", default="250,1000")
    parser.add_argument("--baseline-max", type=int, default=250, help="largest channel count for the xarray writer")
    parser.add_argument("--t-end", type=float, default=0.2, help="simulated time of the memory case [s]")
    parser.add_argument("--skip-memory", action="store_true")
    parser.add_argument("--skip-synthetic", action="store_true")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        targets(args.rounds, Path(folder))
        if not args.skip_synthetic:
            synthetic_table(args, Path(folder))
        if not args.skip_memory:
            peak_memory(args.t_end, Path(folder))


if __name__ == "__main__":
    main()
