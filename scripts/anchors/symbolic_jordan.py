#!/usr/bin/env python3
"""Jordan form over Q(p): exactlti vs SymPy's Matrix.jordan_form on the same symbolic matrices.

Usage (from anywhere):  python3 scripts/anchors/symbolic_jordan.py [--system] [--ours FILE]

Creates the venv .venv-anchors at the repository root if missing and re-runs itself inside it
(`--system`: use the current interpreter's SymPy instead); runs (or, with `--ours FILE`,
reads a saved output of)
`cargo bench --bench symbolic_jordan`, which prints `name: best ms (median ms, reps)` lines and
writes the inputs to target/symbolic-jordan-bench-cases.txt; times SymPy (ground types python)
on the same matrices: `Matrix.jordan_form()` (T and J), and prints one table with the ratios
(goal: the yaw-plane symbolic Jordan form <= 50 ms). SymPy's jordan_form cannot split an
irreducible quadratic over Q(p) without radicals; it returns the radical eigenvalues (the
general yaw-plane case), which is more work than our root-of-factor presentation: the ratio
there compares different outputs and is marked so.
"""
import os
import re
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common import ensure_venv  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


def best_ms(fn, budget=3.0, min_runs=3, max_runs=50):
    times = []
    start = time.perf_counter()
    while len(times) < min_runs or (time.perf_counter() - start < budget and len(times) < max_runs):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
        if times[-1] > 30:
            break
    return min(times) * 1e3


def run_ours():
    if "--ours" in sys.argv:  # a saved `cargo bench --bench symbolic_jordan` output
        out = Path(sys.argv[sys.argv.index("--ours") + 1]).read_text()
    else:
        env = dict(os.environ, CARGO_BUILD_JOBS=os.environ.get("CARGO_BUILD_JOBS", "1"))
        out = subprocess.run(["cargo", "bench", "--bench", "symbolic_jordan"], cwd=ROOT,
                             env=env, check=True, capture_output=True, text=True).stdout
    ours = {}
    for line in out.splitlines():
        m = re.match(r"^(.*): ([0-9.]+) ms", line)
        if m:
            ours[m.group(1)] = float(m.group(2))
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    cases = [l.split("\t") for l in
             (target / "symbolic-jordan-bench-cases.txt").read_text().splitlines() if l]
    return ours, cases


def main():
    if "--system" not in sys.argv:
        ensure_venv()
    os.environ["SYMPY_GROUND_TYPES"] = "python"
    import sympy
    from sympy import Matrix, sympify, simplify

    ours, cases = run_ours()
    rows = []
    for name, vars_, n, ents in cases:
        n = int(n)
        syms = {v: sympy.Symbol(v) for v in vars_.split(",")}
        ents = [sympify(e.replace("^", "**"), locals=syms) for e in ents.split(";")]
        a = Matrix(n, n, ents)

        def sy():
            p, j = a.jordan_form()
            return p, j

        p, j = sy()
        ok = simplify(a * p - p * j) == sympy.zeros(n, n)
        radical = any(e.has(sympy.Pow) and any(
            x.exp.is_Rational and not x.exp.is_Integer for x in e.atoms(sympy.Pow))
            for e in j)
        t = best_ms(sy)
        rows.append((name, ours.get(name), t, ok, radical))

    print("# Jordan form over Q(p): best wall times in ms (same inputs)")
    print(f"{'case':46} {'exactlti':>10} {'SymPy':>10} {'SymPy/us':>9}  note")
    print("-" * 100)
    for name, o, s, ok, radical in rows:
        os_ = f"{o:10.3f}" if o is not None else f"{'-':>10}"
        xs = f"{s / o:8.1f}x" if o else f"{'-':>9}"
        note = "SymPy: radical eigenvalues (different output)" if radical else ""
        if not ok:
            note += " SymPy's A P = P J not verified by simplify"
        print(f"{name:46} {os_} {s:10.3f} {xs}  {note}")
    print("SymPy", sympy.__version__, "Matrix.jordan_form, SYMPY_GROUND_TYPES=python")


if __name__ == "__main__":
    main()
