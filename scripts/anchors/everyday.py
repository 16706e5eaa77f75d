#!/usr/bin/env python3
"""Everyday models (issue 11): SymPy's jordan_form beside `cargo bench --bench everyday` on
the same matrices (tests/data/everyday/*.json, written by scripts/everyday_corpus.py).

Usage (from the repo root):  python3 scripts/anchors/everyday.py [--limit SECONDS]
Uses the venv .venv-anchors (see _common.py). Each SymPy case runs in a child process
killed after the time limit (default 60 s). Second-order files (M, L, K, F) are turned into
A = [[0, I], [-M^-1 K, -M^-1 L]] exactly, as exactlti does.
"""
import json
import multiprocessing as mp
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from _common import ROOT, ensure_venv  # noqa: E402

DATA = os.path.join(ROOT, "tests", "data", "everyday")
CASES = ["quarter_car", "damped_chain_3", "damped_chain_5_mimo", "sliding_masses_damped",
         "random_6_siso", "random_8_siso", "random_8_mimo", "random_12_siso",
         "random_12_mimo", "random_16_siso", "random_16_mimo"]


def matrix_a(name):
    import sympy as sp

    with open(os.path.join(DATA, name + ".json")) as f:
        d = json.load(f)
    params = {k: sp.Rational(v) for k, v in d.get("parameters", {}).items()}

    def val(x):
        if isinstance(x, (int, float)):
            return sp.Rational(str(x))
        return sp.nsimplify(sp.sympify(x, locals={k: sp.Symbol(k) for k in params}).subs(params),
                            rational=True)

    def mat(key):
        return sp.Matrix([[val(x) for x in row] for row in d[key]])

    if "A" in d:
        return mat("A")
    M, K = mat("M"), mat("K")
    L = mat("L") if "L" in d else sp.zeros(*M.shape)
    n = M.shape[0]
    Mi = M.inv()
    top = sp.zeros(n, n).row_join(sp.eye(n))
    bot = (-Mi * K).row_join(-Mi * L)
    return top.col_join(bot)


def sympy_case(name, q):
    a = matrix_a(name)
    t = time.perf_counter()
    try:
        a.jordan_form()
    except Exception as e:  # SymPy refuses eigenvalues it can only give as CRootOf
        q.put("fails after %.1f s: %s" % (time.perf_counter() - t, type(e).__name__))
        return
    q.put(time.perf_counter() - t)


def time_sympy(name, limit):
    q = mp.Queue()
    p = mp.Process(target=sympy_case, args=(name, q))
    p.start()
    p.join(limit)
    if p.is_alive():
        p.kill()
        p.join()
        return None
    return q.get(timeout=5) if not q.empty() else None


def main():
    ensure_venv()
    limit = 60.0
    if "--limit" in sys.argv:
        limit = float(sys.argv[sys.argv.index("--limit") + 1])
    out = subprocess.run(["cargo", "bench", "-q", "--bench", "everyday"], cwd=ROOT,
                         capture_output=True, text=True, check=True).stdout
    print(out, end="")
    ours = {}
    for line in out.splitlines():
        parts = line.split()
        if parts and parts[0] in CASES:
            ours[parts[0]] = float(parts[2])  # library complex Jordan seconds
    print(f"\n# complex Jordan form: exactlti (library) vs SymPy jordan_form (killed after {limit:.0f} s)")
    print(f"{'case':<24} {'exactlti':>10} {'sympy':>12} {'ratio':>10}")
    for name in CASES:
        s = time_sympy(name, limit)
        o = ours.get(name)
        if isinstance(s, str):
            print(f"{name:<24} {o:>9.4f}s   sympy {s}")
        elif s is None:
            print(f"{name:<24} {o:>9.4f}s {'> %.0f s' % limit:>12} {'>%.0fx' % (limit / o):>10}")
        else:
            print(f"{name:<24} {o:>9.4f}s {s:>11.3f}s {s / o:>9.0f}x")


if __name__ == "__main__":
    main()
