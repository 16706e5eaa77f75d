#!/usr/bin/env python3
"""Factorization over Q: exactlti vs SymPy (factor_list) vs python-flint (fmpz_poly.factor).

Usage (from anywhere):  python3 scripts/anchors/factor.py

Creates the venv .venv-anchors at the repository root if missing (pip install sympy
python-flint) and re-runs itself inside it; runs `cargo bench --bench factor`, which prints
`name: X ms` lines and writes the case polynomials to target/factor-bench-cases.txt; times
SymPy and FLINT on those same polynomials (median of repeated runs) and prints a table with
the ratios ours/flint (goal: <= 10) and sympy/ours (goal: > 1).

SymPy >= 1.13 hands ZZ[x] factorization to python-flint when that is installed; the SymPy
column is therefore measured in a child process with SYMPY_GROUND_TYPES=python (SymPy's own
Zassenhaus), which is what a SymPy user without python-flint gets.
"""
import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
VENV = ROOT / ".venv-anchors"
PY = VENV / "bin" / "python"


def ensure_venv():
    if Path(sys.prefix).resolve() == VENV.resolve():
        return
    if not PY.exists():
        subprocess.check_call([sys.executable, "-m", "venv", str(VENV)])
        subprocess.check_call([str(PY), "-m", "pip", "install", "-q", "sympy", "python-flint"])
    os.execv(str(PY), [str(PY), __file__] + sys.argv[1:])


def median_ms(fn, budget=1.0, min_runs=3, max_runs=1000):
    times = []
    start = time.perf_counter()
    while len(times) < min_runs or (time.perf_counter() - start < budget and len(times) < max_runs):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    times.sort()
    return times[len(times) // 2] * 1e3


def run_ours():
    env = dict(os.environ, CARGO_BUILD_JOBS=os.environ.get("CARGO_BUILD_JOBS", "1"))
    out = subprocess.run(["cargo", "bench", "--bench", "factor"], cwd=ROOT, env=env,
                         check=True, capture_output=True, text=True).stdout
    ours = {}
    for line in out.splitlines():
        m = re.match(r"^(.*): ([0-9.]+) ms$", line)
        if m:
            ours[m.group(1)] = float(m.group(2))
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    cases = []
    for line in (target / "factor-bench-cases.txt").read_text().splitlines():
        name, poly = line.split("\t")
        cases.append((name, poly))
    return ours, cases


def sympy_child(cases_json):
    """Times SymPy's factor_list on each distinct polynomial; prints JSON {text: ms}."""
    import sympy as sp
    x = sp.Symbol("x")
    out = {}
    for text in json.loads(Path(cases_json).read_text()):
        p = sp.Poly(sp.sympify(text.replace("^", "**"), locals={"x": x}), x)
        out[text] = median_ms(lambda: sp.factor_list(p))
    from sympy.external.gmpy import GROUND_TYPES
    print(json.dumps({"ground_types": GROUND_TYPES,
                      "version": sp.__version__, "times": out}))


def time_sympy_pure(texts):
    tmp = ROOT / "target" / "factor-sympy-cases.json"
    tmp.write_text(json.dumps(sorted(set(texts))))
    env = dict(os.environ, SYMPY_GROUND_TYPES="python")
    res = subprocess.run([sys.executable, __file__, "--sympy-child", str(tmp)], env=env,
                         check=True, capture_output=True, text=True).stdout
    return json.loads(res)


def main():
    ensure_venv()
    if len(sys.argv) == 3 and sys.argv[1] == "--sympy-child":
        sympy_child(sys.argv[2])
        return
    import flint
    import sympy as sp

    ours, cases = run_ours()
    pure = time_sympy_pure([t for _, t in cases])
    x = sp.Symbol("x")
    rows = []
    seen = {}
    for name, text in cases:
        expr = sp.sympify(text.replace("^", "**"), locals={"x": x})
        if text in seen:  # same polynomial, another of our variants: reuse anchor timings
            t_sympy, t_flint = seen[text]
        else:
            p = sp.Poly(expr, x)
            coeffs = [int(c) for c in reversed(p.all_coeffs())]
            fp = flint.fmpz_poly(coeffs)
            t_sympy = pure["times"][text]
            t_flint = median_ms(lambda: fp.factor())
            # sanity: same number of distinct factors
            n_sym = len(sp.factor_list(p)[1])
            n_fl = len(fp.factor()[1])
            assert n_sym == n_fl, (name, n_sym, n_fl)
            seen[text] = (t_sympy, t_flint)
        rows.append((name, ours.get(name, float("nan")), t_flint, t_sympy))
    print(f"sympy {pure['version']} (ground types: {pure['ground_types']}), "
          f"python-flint {flint.__version__}")
    print(f"| {'case':<46} | {'ours ms':>10} | {'flint ms':>10} | {'sympy ms':>10} | "
          f"{'ours/flint':>10} | {'sympy/ours':>10} |")
    print(f"|{'-' * 48}|{'-' * 12}|{'-' * 12}|{'-' * 12}|{'-' * 12}|{'-' * 12}|")
    for name, t_o, t_f, t_s in rows:
        print(f"| {name:<46} | {t_o:>10.3f} | {t_f:>10.3f} | {t_s:>10.3f} | "
              f"{t_o / t_f:>10.2f} | {t_s / t_o:>10.1f} |")


if __name__ == "__main__":
    main()
