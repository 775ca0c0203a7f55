"""A study's folder: its manifest, one file per finished case, and the assembled Dataset.

``DIR/study.json`` describes the study (factors, design, responses, run options) with a fingerprint of
everything that decides a case's result. Each case, when it finishes, is written to
``DIR/cases/case_NNNNNN.npz`` by the one process that runs the study (workers only return records),
first to a temporary name and then renamed, so a file there is always whole. A study started again
with ``resume`` checks the fingerprint, skips the cases whose files exist and runs the rest; the
Dataset is assembled from the files in case order, so it is the same to the last bit however the
study was cut and wherever its cases ran. ``DIR/study.nc`` is that Dataset.
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path

import numpy as np

from ..errors import ModelError, Problem

MANIFEST, CASES, DATASET = "study.json", "cases", "study.nc"


def fingerprint(definition: dict) -> str:
    """SHA-256 of the canonical JSON of what decides the cases' results."""
    text = json.dumps(definition, sort_keys=True, separators=(",", ":"), default=_plain)
    return hashlib.sha256(text.encode()).hexdigest()


def _plain(value):
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, (np.floating, np.integer)):
        return value.item()
    if isinstance(value, Path):
        return str(value)
    raise TypeError(f"{type(value).__name__} is not study data")


class StudyStore:
    """The folder of one study."""

    def __init__(self, folder: str | Path):
        self.folder = Path(folder)
        self.cases = self.folder / CASES

    def open(self, manifest: dict, *, resume: bool) -> set[int]:
        """Prepares the folder for ``manifest``; returns the cases already done (resume) or an empty set.
        A folder holding another study, or this one without ``resume``, is a ModelError: nothing is
        overwritten by accident."""
        path = self.folder / MANIFEST
        if path.exists():
            previous = json.loads(path.read_text())
            if previous.get("fingerprint") != manifest["fingerprint"]:
                raise ModelError([Problem(str(self.folder), "holds a different study (its model, factors, design, "
                                                            "responses or run options differ); give a new folder")])
            if not resume:
                raise ModelError([Problem(str(self.folder), f"already holds this study ({len(self.done())} cases "
                                                            "done); resume it (--resume) or give a new folder")])
            return self.done()
        if self.folder.exists() and any(self.folder.iterdir()) and not resume:
            raise ModelError([Problem(str(self.folder), "is not empty and holds no study; give a new or empty folder")])
        self.cases.mkdir(parents=True, exist_ok=True)
        _write_atomic(path, json.dumps(manifest, indent=1, sort_keys=True, default=_plain).encode())
        return set()

    def manifest(self) -> dict:
        return json.loads((self.folder / MANIFEST).read_text())

    def case_path(self, index: int) -> Path:
        return self.cases / f"case_{index:06d}.npz"

    def done(self) -> set[int]:
        """Indices of the cases with a finished file."""
        if not self.cases.is_dir():
            return set()
        return {int(p.stem.removeprefix("case_")) for p in self.cases.glob("case_*.npz")}

    def write(self, record: dict) -> None:
        """One finished case's record, whole or not at all."""
        arrays = {"status": np.array(record["status"]), "error": np.array(record["error"]),
                  "steps": np.array(record["steps"], dtype=np.int64),
                  "rhs_evaluations": np.array(record["rhs_evaluations"], dtype=np.int64),
                  "units": np.array(json.dumps(record.get("units", {}), sort_keys=True))}
        arrays.update({f"response:{k}": np.array(v, dtype=np.float64) for k, v in record["responses"].items()})
        arrays.update({f"channel:{k}": np.asarray(v, dtype=np.float64) for k, v in record["channels"].items()})
        path = self.case_path(record["case"])
        temporary = path.with_suffix(".tmp")
        with open(temporary, "wb") as handle:
            np.savez(handle, **arrays)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(temporary, path)

    def read(self, index: int) -> dict:
        """A case's record as written."""
        with np.load(self.case_path(index), allow_pickle=False) as data:
            record = {"case": index, "status": str(data["status"]), "error": str(data["error"]),
                      "steps": int(data["steps"]), "rhs_evaluations": int(data["rhs_evaluations"]),
                      "units": json.loads(str(data["units"])), "responses": {}, "channels": {}}
            for key in data.files:
                kind, _, name = key.partition(":")
                if kind == "response":
                    record["responses"][name] = float(data[key])
                elif kind == "channel":
                    record["channels"][name] = np.array(data[key])
        return record


def _write_atomic(path: Path, data: bytes) -> None:
    temporary = path.with_suffix(path.suffix + ".tmp")
    temporary.write_bytes(data)
    os.replace(temporary, path)
