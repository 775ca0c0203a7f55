"""Running a study's cases: in this process, on local worker processes, or on a Dask cluster.

Every way takes the same jobs (case index, overrides) and hands each finished case's record to
``on_record`` as soon as its batch returns, in the order they finish. Nothing here schedules work of
its own: local processes are a :class:`concurrent.futures.ProcessPoolExecutor` kept warm for the
whole study (each worker receives the study's :class:`~jointplay.study.worker.Recipe` once, when it
starts), a cluster is Dask's (``Client.submit`` and ``as_completed``; the recipe is scattered to every
worker once). What is ours is the size of the batches (:class:`Feeder`): short cases go several to a
message, so that messages do not cost more than runs, and the last batches are small, so that the
workers finish together.
"""

from __future__ import annotations

import multiprocessing
from collections import deque
from collections.abc import Callable
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from queue import Empty

from .worker import FAILED, Recipe, run_batch

Job = tuple[int, dict]
OnRecord = Callable[[dict], None]

#: Wall time [s] a batch of cases is sized to take once the cases' duration is known: long beside the
#: cost of one message to a worker and back (about a millisecond), short beside a study.
BATCH_SECONDS = 0.5
#: Batches kept in flight per worker: one running, one waiting in its queue.
IN_FLIGHT_PER_WORKER = 2


class Feeder:
    """Hands out the jobs in batches. The first batches hold one case each; once cases have come back,
    a batch holds as many as take about :data:`BATCH_SECONDS`, but never more than leave two batches per
    worker for the rest of the study. ``batch_size`` fixes the size instead."""

    def __init__(self, jobs: list[Job], workers: int, batch_size: int | None = None):
        self.jobs, self.workers, self.fixed = deque(jobs), max(1, workers), batch_size
        self.seconds, self.count = 0.0, 0

    def __bool__(self) -> bool:
        return bool(self.jobs)

    def observe(self, records: list[dict]) -> None:
        for record in records:
            if "seconds" in record:
                self.seconds += record["seconds"]
                self.count += 1

    def next(self) -> list[Job]:
        size = min(self.fixed or self.size(), len(self.jobs))
        return [self.jobs.popleft() for _ in range(size)]

    def size(self) -> int:
        if not self.count:
            return 1
        wanted = max(1, int(BATCH_SECONDS / max(self.seconds / self.count, 1e-6)))
        balanced = max(1, len(self.jobs) // (IN_FLIGHT_PER_WORKER * self.workers))
        return min(wanted, balanced)

    def put_back(self, jobs: list[Job]) -> None:
        self.jobs.extendleft(reversed(jobs))


def run_serial(recipe: Recipe, jobs: list[Job], on_record: OnRecord) -> None:
    """Each case in turn, in this process."""
    for job in jobs:
        for record in run_batch(recipe, [job]):
            on_record(record)


# --- local processes -------------------------------------------------------------------------------

_RECIPE: Recipe | None = None
_STARTED = None


def _install(recipe: Recipe, started) -> None:
    """Worker start-up: keep the study's recipe for every batch this worker will run, and the queue on
    which it says which case it starts."""
    global _RECIPE, _STARTED
    _RECIPE, _STARTED = recipe, started


def _run_installed(jobs: list[Job]) -> list[dict]:
    records = []
    for job in jobs:
        _STARTED.put(job[0])
        records.extend(run_batch(_RECIPE, [job]))
    return records


def _context():
    """Worker processes start from a fresh interpreter (``forkserver`` on Linux, ``spawn`` elsewhere):
    forking a process that holds threads (a progress bar, a Dask client) is unsafe."""
    methods = multiprocessing.get_all_start_methods()
    return multiprocessing.get_context("forkserver" if "forkserver" in methods else "spawn")


def run_processes(recipe: Recipe, jobs: list[Job], on_record: OnRecord, workers: int,
                  batch_size: int | None = None) -> None:
    """The cases on ``workers`` local processes, kept warm for the whole study. When a worker dies (killed,
    or a crash outside Python), the cases that had started and not come back are run again one by one,
    each in a process of its own: one that dies again fails with the reason; the cases not yet started
    go on in a new pool."""
    context = _context()
    feeder, recorded = Feeder(jobs, workers, batch_size), set()

    def keep(record: dict) -> None:
        recorded.add(record["case"])
        on_record(record)

    while feeder:
        started = context.Queue()
        with ProcessPoolExecutor(max_workers=workers, mp_context=context, initializer=_install,
                                 initargs=(recipe, started)) as pool:
            broken = _feed_pool(pool, feeder, keep, workers)
        begun = _drain_queue(started) - recorded if broken else set()
        left = [job for batch in broken for job in batch if job[0] not in recorded]
        for job in [job for job in left if job[0] in begun]:
            _isolated(recipe, job, keep, context)
        feeder.put_back([job for job in left if job[0] not in begun])


def _feed_pool(pool, feeder: Feeder, keep: OnRecord, workers: int) -> list[list[Job]]:
    """Keeps the pool's workers busy until the feeder is empty; the batches that the pool's breaking
    failed, or [] when all ran."""
    in_flight: dict = {}
    broken: list[list[Job]] = []
    while True:
        while not broken and feeder and len(in_flight) < IN_FLIGHT_PER_WORKER * workers:
            batch = feeder.next()
            try:
                in_flight[pool.submit(_run_installed, batch)] = batch
            except BrokenProcessPool:  # broke since the last look: the batch goes to the next pool
                feeder.put_back(batch)
                broken.append([])
        if not in_flight:
            return [batch for batch in broken if batch]
        done, _ = wait(in_flight, return_when=FIRST_COMPLETED)
        for future in done:
            batch = in_flight.pop(future)
            try:
                records = future.result()
            except BrokenProcessPool:
                broken.append(batch)
                continue
            feeder.observe(records)
            for record in records:
                keep(record)


def _drain_queue(queue) -> set[int]:
    found = set()
    while True:
        try:
            found.add(queue.get(timeout=0.05))
        except Empty:
            return found


def _isolated(recipe: Recipe, job: Job, on_record: OnRecord, context) -> None:
    """One case in a process of its own; if that process dies too, the case fails with the reason."""
    with ProcessPoolExecutor(max_workers=1, mp_context=context, initializer=_install,
                             initargs=(recipe, context.Queue())) as pool:
        try:
            records = pool.submit(_run_installed, [job]).result()
        except BrokenProcessPool:
            records = [_lost(job[0], "the worker process running it died (killed, or a crash outside Python)")]
    for record in records:
        on_record(record)


def _lost(index: int, why: str) -> dict:
    return {"case": index, "status": FAILED, "error": f"WorkerLost: {why}", "responses": {}, "channels": {},
            "steps": 0, "rhs_evaluations": 0}


# --- Dask --------------------------------------------------------------------------------------------

def run_dask(recipe: Recipe, jobs: list[Job], on_record: OnRecord, client, batch_size: int | None = None) -> None:
    """The cases on a Dask cluster through ``client`` (a ``dask.distributed.Client``): the recipe is
    scattered to every worker once, batches go by ``Client.submit`` and come back by ``as_completed``. A
    batch Dask gives up on (a worker lost too often) fails its cases with Dask's reason."""
    from dask.distributed import as_completed

    workers = max(1, len(client.scheduler_info().get("workers", {})))
    feeder = Feeder(jobs, workers, batch_size)
    if not feeder:
        return
    shared = client.scatter(recipe, broadcast=True)
    batch_of: dict[str, list[Job]] = {}

    def submit():
        batch = feeder.next()
        future = client.submit(run_batch, shared, batch, pure=False)
        batch_of[future.key] = batch
        return future

    pending = as_completed([submit() for _ in range(min(len(feeder.jobs), IN_FLIGHT_PER_WORKER * workers))])
    for future in pending:
        batch = batch_of.pop(future.key)
        try:
            records = future.result()
        except Exception as exc:  # noqa: BLE001 (Dask's KilledWorker, a lost connection: the batch fails)
            records = [_lost(index, f"{type(exc).__name__}: {exc}") for index, _ in batch]
        future.release()
        feeder.observe(records)
        for record in records:
            on_record(record)
        if feeder:
            pending.add(submit())


def connect(scheduler: str):
    """A Dask client for a scheduler address (``tcp://host:8786``); a clear error when it cannot connect."""
    from dask.distributed import Client

    from ..errors import ModelError, Problem

    try:
        return Client(scheduler, timeout="10s")
    except (OSError, TimeoutError) as exc:
        raise ModelError([Problem("--scheduler", f"cannot reach a Dask scheduler at {scheduler!r}: {exc}")]) from None


__all__ = ["Feeder", "connect", "run_dask", "run_processes", "run_serial"]
