# The two Quick start commands: `make demo` and `make test`. Each does all
# set-up on a fresh machine with Python 3.11 and a Rust toolchain: a local
# virtual environment in .venv, the Python dependencies from pyproject.toml,
# and a release build of the Rust extension (incremental after the first).

PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
OUT ?= out/flores_dry
# `maturin develop` installs into the active environment (VIRTUAL_ENV, or
# CONDA_PREFIX of a conda environment), whatever it is: run it as if .venv
# were the active one and no conda environment were, so that the extension
# lands where $(PY) imports it.
IN_VENV := env -u CONDA_PREFIX -u CONDA_DEFAULT_ENV VIRTUAL_ENV="$(abspath $(VENV))" PATH="$(abspath $(VENV))/bin:$$PATH"

.PHONY: demo test setup bench

$(VENV)/bin/maturin:
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip "maturin>=1.5,<2"

# the `bench` extra (numba) is installed too, so that the test suite checks the
# benchmarks' practical-limit model (tests/physics/test_limit_slider_crank.py), and
# the `optuna` extra, so that it checks the search of a study's optimum with Optuna
setup: $(VENV)/bin/maturin
	$(IN_VENV) $(VENV)/bin/maturin develop --release --extras test,bench,optuna --quiet

demo: setup
	$(PY) examples/flores_slider_crank_dry.py --out $(OUT)

test: setup
	cargo test --release --quiet
	$(PY) -m pytest -q

# numba (the `bench` extra, installed by setup) runs the practical-limit baseline; the benchmark
# skips that row without numba.
bench: setup
	$(PY) benches/bench_flores_dry.py
