"""Shared test set-up: examples, the independent reference models and the shared micro-models are importable."""

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
for folder in (ROOT / "examples", ROOT / "tests" / "physics", ROOT / "tests"):
    if str(folder) not in sys.path:
        sys.path.insert(0, str(folder))


# CI (CI=true) explores the same examples every run, so that a landing does not depend on the draw;
# locally the property tests draw new examples each run
if os.environ.get("CI"):
    from hypothesis import settings

    settings.register_profile("ci", derandomize=True, print_blob=True)
    settings.load_profile("ci")
