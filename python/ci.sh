#!/usr/bin/env bash
# Builds and tests the Python package: a venv (.venv-python at the repository root, or
# $EXACTLTI_PY_VENV), `pip install ./python` (maturin from PyPI builds the PyO3 extension,
# dev profile, the root's target dir: see below), pytest with SymPy, numpy and python-control.
# Prints pytest's summary line, then executes the paper notebooks (python/examples/notebooks,
# a plain runner: every cell in order, each displayed result rendered, no Jupyter needed)
# with the time each took; fails when pytest or a notebook fails.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
VENV="${EXACTLTI_PY_VENV:-$ROOT/.venv-python}"
PY="${PYTHON:-python3}"
start=$(date +%s)
if [ ! -x "$VENV/bin/python" ]; then
    "$PY" -m venv "$VENV"
fi
"$VENV/bin/python" -m pip install -q --upgrade pip >/dev/null 2>&1 || true
"$VENV/bin/python" -m pip install -q pytest sympy numpy control slycot
# The extension is built with the dev profile into the root's target dir (maturin's
# `--profile dev`, CARGO_TARGET_DIR): after `cargo test` (.ci/run) the dependencies and the
# exactlti library are already compiled there with the same profile and features, so only
# PyO3 and the bindings compile (a release build in python/target compiled the whole
# dependency graph and the crate a third time). EXACTLTI_PY_PROFILE=release for a release
# build.
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$ROOT/target}"
export MATURIN_PEP517_ARGS="--profile ${EXACTLTI_PY_PROFILE:-dev}"
"$VENV/bin/python" -m pip install -q --force-reinstall --no-deps "$ROOT/python"
echo "python package built and installed in $(( $(date +%s) - start )) s"
# run from the repository root so that `import exactlti` finds the installed package,
# not the source folder python/exactlti (which has no compiled _core)
cd "$ROOT"
status=0
"$VENV/bin/python" -m pytest -q -p no:cacheprovider python/tests || status=$?
nb_start=$(date +%s)
"$VENV/bin/python" python/examples/notebooks/run.py || status=1
echo "notebooks executed in $(( $(date +%s) - nb_start )) s"
exit $status
