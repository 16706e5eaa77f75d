#!/usr/bin/env python3
"""numpy eigenvalue loops beside `cargo bench --bench study`, in the same run (issue 15).

Same points as the bench: the bicycle (Meijaard et al. 2007 matrices, data/bicycle-whipple.json
formulas) at 20,000 speeds on [0, 10]; a 20-state damped chain (m_i = 1 + i/10, springs
s (1 + i), dampers (i + 1)/10) at 2,000 stiffness scales on [0.1, 10]. numpy's loop is a
single thread; ours is rayon-parallel on the machine's cores (printed).
"""
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _common import ROOT, ensure_venv  # noqa: E402

ensure_venv()
import numpy as np  # noqa: E402

M = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
C1 = np.array([[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0 = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2 = np.array([[0.0, 76.59734589573222], [0.0, 2.65431523794604]])


def state(m, l, k):
    n = m.shape[0]
    a = np.zeros((2 * n, 2 * n))
    a[:n, n:] = np.eye(n)
    a[n:, :n] = -np.linalg.solve(m, k)
    a[n:, n:] = -np.linalg.solve(m, l)
    return a


def bicycle_loop(vals):
    return [np.linalg.eigvals(state(M, v * C1, 9.81 * K0 + v * v * K2)) for v in vals]


def chain(n, s):
    m = np.diag([1 + i / 10 for i in range(n)])
    l = np.zeros((n, n))
    k = np.zeros((n, n))
    for i in range(n):
        ks, cs = s * (i + 1), (i + 1) / 10
        k[i, i] += ks
        l[i, i] += cs
        if i > 0:
            k[i - 1, i - 1] += ks
            k[i, i - 1] -= ks
            k[i - 1, i] -= ks
            l[i - 1, i - 1] += cs
            l[i, i - 1] -= cs
            l[i - 1, i] -= cs
    return m, l, k


def chain_loop(vals):
    return [np.linalg.eigvals(state(*chain(10, s))) for s in vals]


def best(f, reps=3):
    t = []
    for _ in range(reps):
        t0 = time.perf_counter()
        f()
        t.append(time.perf_counter() - t0)
    return min(t) * 1e3


def main():
    out = subprocess.run(
        ["cargo", "bench", "--bench", "study"], cwd=ROOT, capture_output=True, text=True
    )
    if out.returncode != 0:
        print(out.stderr)
        sys.exit(1)
    ours = {m.group(1): float(m.group(2)) for m in re.finditer(r"case (\S+) ([0-9.]+)", out.stdout)}
    threads = re.search(r"threads (\d+)", out.stdout)
    numpy_ms = {
        "bicycle_sweep_20000": best(lambda: bicycle_loop(np.linspace(0, 10, 20000))),
        "chain20_sweep_2000": best(lambda: chain_loop(np.linspace(0.1, 10, 2000))),
    }
    print(f"# parameter sweeps, best-of-3 ms (ours: rayon, {threads.group(1) if threads else '?'} threads; numpy: one loop)")
    print(f"{'case':26} {'exactlti':>10} {'numpy':>10} {'numpy/us':>9}")
    for case, ms in ours.items():
        np_ms = numpy_ms.get(case)
        ratio = f"{np_ms / ms:8.1f}x" if np_ms else "        -"
        np_s = f"{np_ms:10.1f}" if np_ms else "         -"
        print(f"{case:26} {ms:10.1f} {np_s} {ratio}")


if __name__ == "__main__":
    main()
