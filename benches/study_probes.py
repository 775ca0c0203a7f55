"""Responses of the study benchmark that measure the worker process itself (imported by name in the worker
processes, so they live in a module of their own)."""

from __future__ import annotations

import os


def resident_memory(results) -> float:
    """Resident memory [MiB] of the process evaluating this response."""
    import psutil

    return psutil.Process().memory_info().rss / 2**20


def worker_pid(results) -> float:
    """The id of the process evaluating this response."""
    return float(os.getpid())
