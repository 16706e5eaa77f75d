#!/usr/bin/env bash
# Runs every side-by-side comparison in one go: creates .venv-anchors with all anchors
# (SymPy, python-flint, python-control + slycot, numpy, scipy), then each script, which runs
# the matching `cargo bench` in the same run and prints a table with ratios.
# Usage: bash scripts/anchors/run_all.sh [OUTDIR]   (default bench-results/)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-bench-results}
mkdir -p "$out"
if [ ! -x .venv-anchors/bin/python ]; then
  python3 -m venv .venv-anchors
fi
.venv-anchors/bin/pip install -q sympy python-flint numpy scipy control slycot
cargo build --release --benches -q
for s in factor matrix jordan realization float_minreal pencil mpoly study everyday symbolic symbolic_jordan; do
  echo "=== $s ==="
  python3 "scripts/anchors/$s.py" 2>&1 | tee "$out/$s.txt"
done
