#!/usr/bin/env python3
"""Symbolic linear algebra over Q(p), side by side: exactlti (`cargo bench --bench symbolic`)
and SymPy doing the same steps on the same symbolic matrices (data/*.json).

Steps timed in SymPy (the linear algebra the exact algorithms do, not a full SCB, which SymPy
does not have):
- `scb dc motor` / `scb single track front|rear`: Grip & Saberi's Silverman steps in their
  simplest form: the observability matrix O = [C; CA; ...; CA^(n-1)] with the Markov blocks
  C A^k B, rank(O), nullspace(O^T) and rank([B; D]), then the similarity T A T^-1 with T made
  of the independent rows of O (or completed by unit rows), simplified with `cancel`;
- `minreal sliding masses` (20 states, symbols m, k): Kalman: rank and columnspace of the
  controllability matrix [B, AB, ..., A^19 B], then rank of the observability matrix of the
  controllable part (order 8).
Each SymPy step is bounded by --timeout seconds (default 120) in a child process.

Prints one table: case, exactlti best ms, SymPy ms, ratio SymPy/exactlti.

Usage: python3 scripts/anchors/symbolic.py [--no-bench] [--timeout S]
Creates the venv .venv-anchors at the repo root if missing.
"""
import json
import multiprocessing as mp
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _common import ROOT, ensure_venv  # noqa: E402

LINE = re.compile(r"^(scb dc motor|scb single track front|scb single track rear|minreal sliding masses|bifurcations dc motor): ([\d.]+) ms")
CASES = {
    "scb dc motor": "data/dc-motor-lugre.json",
    "scb single track front": "data/scb/single-track-front.json",
    "scb single track rear": "data/scb/single-track-rear.json",
    "minreal sliding masses": "data/sliding-masses-symbolic.json",
}


def load(path):
    import sympy as sp

    d = json.load(open(os.path.join(ROOT, path)))
    names = list(d["parameters"].keys())
    syms = {n: sp.Symbol(n) for n in names}

    def m(key):
        return sp.Matrix([[sp.sympify(str(x), locals=syms) for x in row] for row in d[key]])

    if "A" in d:
        return m("A"), m("B"), m("C"), m("D")
    M, L, K, F = m("M"), m("L"), m("K"), m("F")
    n = M.shape[0]
    Mi = M.inv()
    A = sp.zeros(2 * n, 2 * n)
    A[:n, n:] = sp.eye(n)
    A[n:, :n] = -Mi * K
    A[n:, n:] = -Mi * L
    B = sp.zeros(2 * n, F.shape[1])
    B[n:, :] = Mi * F
    return A, B, m("C"), m("D")


def scb_steps(A, B, C, D):
    import sympy as sp

    n = A.shape[0]
    rows = [C]
    for _ in range(n - 1):
        rows.append(sp.Matrix(rows[-1] * A).applyfunc(sp.cancel))
    O = sp.Matrix.vstack(*rows)
    markov = [sp.Matrix(r * B).applyfunc(sp.cancel) for r in rows]
    r = O.rank(simplify=True)
    sp.Matrix.vstack(B, D).rank(simplify=True)
    O.T.nullspace(simplify=True)
    # T: independent rows of O completed by unit rows
    _, piv = O.T.rref(simplify=True)
    T = sp.Matrix.vstack(*[O[i, :] for i in piv])
    for j in range(n):
        if T.shape[0] == n:
            break
        e = sp.zeros(1, n)
        e[j] = 1
        cand = sp.Matrix.vstack(T, e)
        if cand.rank(simplify=True) > T.shape[0]:
            T = cand
    (T * A * T.inv()).applyfunc(sp.cancel)
    return r, len(markov)


def kalman_steps(A, B, C, D):
    import sympy as sp

    n = A.shape[0]
    cols = [B]
    for _ in range(n - 1):
        cols.append(A * cols[-1])
    K = sp.Matrix.hstack(*cols)
    rc = K.rank()
    V = sp.Matrix.hstack(*K.columnspace())
    # controllable part: A V = V Ac (V has full column rank): Ac = V^+ A V
    Vp = (V.T * V).inv() * V.T
    Ac = (Vp * A * V).applyfunc(sp.cancel)
    Cc = C * V
    rows = [Cc]
    for _ in range(rc - 1):
        rows.append(rows[-1] * Ac)
    return sp.Matrix.vstack(*rows).rank()


def child(case, q):
    A, B, C, D = load(CASES[case])
    t = time.perf_counter()
    res = kalman_steps(A, B, C, D) if case.startswith("minreal") else scb_steps(A, B, C, D)
    q.put(((time.perf_counter() - t) * 1e3, str(res)))


def sympy_time(case, timeout):
    q = mp.Queue()
    p = mp.Process(target=child, args=(case, q))
    p.start()
    p.join(timeout)
    if p.is_alive():
        p.terminate()
        p.join()
        return None, "timeout"
    return q.get() if not q.empty() else (None, "failed")


def main():
    ensure_venv()
    timeout = 120.0
    if "--timeout" in sys.argv:
        timeout = float(sys.argv[sys.argv.index("--timeout") + 1])
    ours = {}
    if "--no-bench" not in sys.argv:
        out = subprocess.run(["cargo", "bench", "--bench", "symbolic"], cwd=ROOT,
                             capture_output=True, text=True)
        if out.returncode != 0:
            sys.exit("cargo bench failed:\n" + out.stderr[-2000:])
        print(out.stdout)
        for line in out.stdout.splitlines():
            m = LINE.match(line)
            if m:
                ours[m.group(1)] = float(m.group(2))
    print(f"{'case':28} {'exactlti ms':>12} {'SymPy ms':>12} {'ratio':>8}")
    for case in CASES:
        ms, res = sympy_time(case, timeout)
        e = ours.get(case)
        s = "timeout" if ms is None else f"{ms:.1f}"
        ratio = "" if (ms is None or not e) else f"{ms / e:.1f}x"
        if ms is None and e:
            ratio = f">{timeout * 1e3 / e:.0f}x"
        print(f"{case:28} {('%.2f' % e) if e else '-':>12} {s:>12} {ratio:>8}   ({res})")


if __name__ == "__main__":
    main()
