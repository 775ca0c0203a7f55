"""Responses for the tests of the study layer that workers in other processes import by name (tests/ is
on the path: tests/conftest.py, and worker processes inherit the path)."""

from __future__ import annotations

import os


class CrashBelow:
    """A response that ends its process abruptly (``os._exit``, as a crash outside Python would) when the
    final value of ``channel`` is below ``limit``, and is 1 otherwise."""

    name, definition = "crash", "ends the worker process when the final value is below a limit"

    def __init__(self, channel: str, limit: float):
        self.channel, self.limit = channel, limit

    def evaluate(self, results) -> float:
        if results[self.channel][-1] < self.limit:
            os._exit(3)
        return 1.0

    def units_in(self, results) -> str:
        return ""
