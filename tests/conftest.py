"""Shared test set-up: examples and the independent reference model are importable."""

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
for folder in (ROOT / "examples", ROOT / "tests" / "physics"):
    if str(folder) not in sys.path:
        sys.path.insert(0, str(folder))
