"""Benchmark: a study of paper 003's breaker mechanism run serially, on 2 local processes and on a Dask
LocalCluster of 2 workers; the fixed cost of one case; a worker's memory over many cases.

1. **Speed-up.** A 64-case study of the breaker with flexible links and clearance joints
   (``examples/paper003_breaker.py``'s ``breaker_study("clearance")``: its four clearances E-H on a
   4 x 4 x 2 x 2 full factorial, 30 ms each; ``--cases`` changes the count) run three ways in
   interleaved rounds: serially in this process, on 2 local worker processes (a pool started by the
   study, as ``jointplay sweep --workers 2`` does), and on a Dask ``LocalCluster`` of 2 single-threaded
   worker processes started once before the rounds (a cluster outlives one study). Wall time, and
   CPU time of this process and all its child processes (psutil). Speed-up = serial / parallel, per
   round; medians with [min-max]. The machine has 2 cores, so 2 workers is its whole width. CPU time is
   this process's plus its worker processes' (psutil, sampled every 0.1 s during the run; the idle Dask
   cluster is left out of the other two ways).
2. **Fixed cost of one case**: the model built from the study's document with one case's overrides
   (validation, compilation, assembly) plus the run's start up to its first accepted step, against a
   whole run of the case; medians of interleaved repetitions.
3. **Worker memory**: ``--memory-cases`` (default 1000) short cases (the breaker to 0.5 ms) on 2 local
   processes; each case reports its worker's resident memory (a user response), and the table gives
   the resident memory after the first 50 cases and after the last, per worker.

Run: python benches/bench_study.py [--rounds N] [--cases 64] [--memory-cases 1000] [--quick] [--markdown]
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "examples"))

import timing  # noqa: E402
from study_probes import resident_memory, worker_pid  # noqa: E402

import jointplay as jp  # noqa: E402
from jointplay.study import Study  # noqa: E402
from jointplay.study.metrics import Response  # noqa: E402

def breaker_table_study(levels: list[int], t_end: str | None = None, factors_from=None) -> Study:
    """The breaker's clearance study (flexible links, clearance joints: ``breaker_study("clearance")``) with a
    full factorial of ``levels`` per factor over its four clearances, written as a table design."""
    from paper003_breaker import breaker_study, build_model

    base = factors_from or breaker_study("clearance")
    axes = [np.linspace(-1, 1, n) if n > 1 else np.zeros(1) for n in levels]
    grid = np.array(np.meshgrid(*axes, indexing="ij")).reshape(len(levels), -1).T
    rows = [[f"{float(f.value(c))!r} m" for f, c in zip(base.factors, row, strict=True)] for row in grid]
    entries = [{"name": f.name, "path": f.path, "range": [f"{f.low!r} m", f"{f.high!r} m"]} for f in base.factors]
    return Study(build_model("clearance"), entries, {"kind": "table", "rows": rows}, list(base.responses),
                 t_end=t_end or base.t_end, fixed=base.fixed)


LEVELS = {64: [4, 4, 2, 2], 16: [2, 2, 2, 2], 4: [2, 2, 1, 1]}


class WorkerCpu:
    """CPU time [s] of the processes below this one (local workers, Dask's), sampled every 0.1 s while a case
    runs, less the ``skip`` ids (a Dask cluster idling beside another way). A worker that ends between two
    samples loses at most its last 0.1 s."""

    def __init__(self, skip=frozenset()):
        import psutil

        self.me, self.skip, self.seen, self.start = psutil.Process(), set(skip), {}, {}
        self.stop = threading.Event()
        self.total = 0.0

    def _sample(self, into: dict) -> None:
        import psutil

        for child in self.me.children(recursive=True):
            if child.pid in self.skip:
                continue
            try:
                times = child.cpu_times()
                into[child.pid] = times.user + times.system
            except psutil.NoSuchProcess:
                pass

    def __enter__(self):
        self._sample(self.start)
        self.thread = threading.Thread(target=self._loop, daemon=True)
        self.thread.start()
        return self

    def _loop(self) -> None:
        while not self.stop.wait(0.1):
            self._sample(self.seen)

    def __exit__(self, *exc):
        self.stop.set()
        self.thread.join()
        self._sample(self.seen)
        self.total = sum(cpu - self.start.get(pid, 0.0) for pid, cpu in self.seen.items())
        return False


class TreeCase(timing.Case):
    """A timed case whose CPU time adds its worker processes' (``workers`` holds that part alone)."""

    def __init__(self, name, run, skip=frozenset()):
        super().__init__(name, run)
        self.skip, self.workers = skip, []

    def time_once(self) -> None:
        wall0, cpu0 = time.perf_counter(), time.process_time()
        with WorkerCpu(self.skip) as workers:
            self.last = self.run()
        self.walls.append(time.perf_counter() - wall0)
        self.workers.append(workers.total)
        self.cpus.append(time.process_time() - cpu0 + workers.total)


def ratio_values(serial: timing.Case, parallel: timing.Case) -> list[float]:
    """Per-round wall-time ratios serial / parallel."""
    return [a / b for a, b in zip(serial.walls, parallel.walls, strict=True) if a is not None and b is not None]


def speedup(args) -> list[str]:
    from distributed import Client, LocalCluster

    study = breaker_table_study(LEVELS[args.cases], args.t_end)
    lines = [f"study: {len(study)} cases of the breaker (flexible links, clearance joints), "
             f"t_end {study.t_end * 1e3:g} ms"]
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client, tempfile.TemporaryDirectory() as tmp:
        counter = iter(range(10**6))

        def fresh() -> Path:
            return Path(tmp) / f"run{next(counter)}"

        import psutil

        dask_pids = set(client.run(os.getpid).values())
        dask_pids |= {p.ppid() for p in psutil.Process().children(recursive=True) if p.pid in dask_pids}
        cases = [TreeCase("serial", lambda: study.run(fresh()), skip=dask_pids),
                 TreeCase("2 local processes", lambda: study.run(fresh(), workers=2), skip=dask_pids),
                 TreeCase("Dask LocalCluster, 2 workers", lambda: study.run(fresh(), client=client))]
        timing.interleave(cases, args.rounds)
        reference = cases[0].last
        for case in cases[1:]:
            same = case.last.identical(reference)
            lines.append(f"{case.name}: Dataset identical to serial: {same}")
    lines.append("")
    lines.append("| way | wall [s] | CPU, this process and its workers [s] | of which workers [s] | speed-up (wall) "
                 "| CPU / serial CPU | target (wall) |")
    lines.append("|---|---:|---:|---:|---:|---:|---|")
    for case in cases:
        wall = timing.Spread.of(case.values("wall")).text()
        cpu = timing.Spread.of(case.values("cpu")).text()
        workers = timing.Spread.of(case.workers).text()
        if case is cases[0]:
            lines.append(f"| {case.name} | {wall} | {cpu} | {workers} | 1 | 1 | |")
            continue
        ratio = timing.ratio(cases[0], case, clock="wall")
        cpu_ratio = timing.ratio(case, cases[0], clock="cpu")
        least = min(ratio_values(cases[0], case))
        lines.append(f"| {case.name} | {wall} | {cpu} | {workers} | {ratio.text()} | {cpu_ratio.text()} | "
                     f"{timing.verdict(ratio.median, '>=', 1.8)} (>= 1.8; least round {least:.3g}) |")
    return lines


def fixed_cost(args) -> list[str]:
    from jointplay.modelfile import from_document

    study = breaker_table_study(LEVELS[4], args.t_end)
    recipe = study.recipe()
    overrides = {**recipe.fixed, **study.overrides(0)}
    first_step = {k: v for k, v in recipe.options.items() if k not in ("output_step", "max_step")}

    def setup_and_first_step():  # a run to 0.1 us: the start and its first accepted step
        model = from_document(recipe.document, overrides, name=recipe.model_name)
        return model.simulate(1e-7, **first_step)

    def whole():
        model = from_document(recipe.document, overrides, name=recipe.model_name)
        return model.simulate(recipe.t_end, **recipe.options)

    cases = [timing.Case("spec to compiled model to first step", setup_and_first_step),
             timing.Case("whole case", whole)]
    timing.interleave(cases, max(5, args.rounds))
    share = timing.ratio(cases[0], cases[1], clock="cpu")
    return ["| part | CPU [ms] | wall [ms] |", "|---|---:|---:|"] + [
        f"| {c.name} | {timing.Spread.of(c.values('cpu')).text(1e3)} | {timing.Spread.of(c.values('wall')).text(1e3)} |"
        for c in cases] + ["", f"fixed cost / whole case (CPU): {share.text(100)} % -> "
                               f"{timing.verdict(share.median, '<=', 0.05)} (<= 5 %)"]


def memory(args) -> list[str]:
    base = breaker_table_study(LEVELS[4], "0.5 ms")
    n = args.memory_cases
    rows = [[f"{float(base.factors[j].value(c))!r} m" for j, c in enumerate(row)]
            for row in np.random.default_rng(1).uniform(-1, 1, (n, len(base.factors)))]
    entries = [{"name": f.name, "path": f.path, "range": [f"{f.low!r} m", f"{f.high!r} m"]} for f in base.factors]
    study = Study(base.document, entries, {"kind": "table", "rows": rows},
                  [Response.from_callable("rss", resident_memory, units="MiB"),
                   Response.from_callable("pid", worker_pid)], t_end="0.5 ms", fixed=base.fixed)
    with tempfile.TemporaryDirectory() as tmp:
        ds = study.run(Path(tmp) / "memory", workers=2)
    lines = ["| worker | cases | RSS after its first 50 cases [MiB] | RSS after its last case [MiB] | growth [MiB] |",
             "|---|---:|---:|---:|---:|"]
    for k, pid in enumerate(sorted(set(ds["pid"].values[np.isfinite(ds["pid"].values)]))):
        rss = ds["rss"].values[ds["pid"].values == pid]
        early = float(np.max(rss[:50]))
        lines.append(f"| {k + 1} | {rss.size} | {early:.1f} | {rss[-1]:.1f} | {rss[-1] - early:+.1f} |")
    failed = int((ds["status"].values != "done").sum())
    lines.append(f"\n{n} cases of 0.5 ms, {failed} failed")
    return lines


def main(argv=None) -> dict[str, list[str]]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--cases", type=int, default=64, choices=sorted(LEVELS))
    parser.add_argument("--memory-cases", type=int, default=1000)
    parser.add_argument("--t-end", default=None, help="end time of a case (default: the study file's)")
    parser.add_argument("--quick", action="store_true", help="a smoke test: 4 short cases, 1 round, 40 memory cases")
    parser.add_argument("--markdown", action="store_true")
    args = parser.parse_args(argv)
    if args.quick:
        args.rounds, args.cases, args.memory_cases, args.t_end = 1, 4, 40, args.t_end or "1 ms"
    print(f"jointplay {jp.__version__}, {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f}\n")
    report = {}
    for title, part in (("Speed-up on 2 workers", speedup), ("Fixed cost of one case", fixed_cost),
                        ("Worker memory", memory)):
        report[title] = part(args)
        print(f"## {title}\n")
        print("\n".join(report[title]))
        print()
    print(f"load average at the end {os.getloadavg()[0]:.2f}")
    return report


if __name__ == "__main__":
    main()
