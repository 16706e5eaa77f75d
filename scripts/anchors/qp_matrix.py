#!/usr/bin/env python3
"""Matrices over Q(p): exactlti (kernels registered on the field) vs SymPy's DomainMatrix.

Usage (from anywhere):  python3 scripts/anchors/qp_matrix.py

Creates the venv .venv-anchors at the repository root if missing (sympy, python-flint, ...)
and re-runs itself inside it; runs `cargo bench --bench qp_matrix`, which prints
`name: X ms` lines and writes the dense inputs to target/qp-matrix-cases.txt; times the same
matrices with SymPy's DomainMatrix (the domain it picks from the entries, ZZ[a,b,c]):
charpoly(), det(), and rref() over the fraction field QQ(a,b,c) (to_field()); prints one
table with the ratios (goal: each >= 10x faster than SymPy). SymPy runs with its default
ground types (python-flint installed: FLINT integers) and with SYMPY_GROUND_TYPES=python.
Then runs the release CLI (`cargo build --release`) on diag(p0..p9) and the 10-mass chain
files it writes to target/, under /usr/bin/time -v: wall time and maximum resident set
(goals: diag10 tf, minreal, scb, zeros <= 1 s and <= 200 MB; chain10 tf, minreal <= 2 s).
"""
import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common import ensure_venv  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
TARGET = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))


def median_ms(fn, budget=1.5, min_runs=3, max_runs=200):
    times = []
    start = time.perf_counter()
    while len(times) < min_runs or (time.perf_counter() - start < budget and len(times) < max_runs):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
        if times[-1] > 20:
            break
    times.sort()
    return times[len(times) // 2] * 1e3


def run_ours():
    env = dict(os.environ, CARGO_BUILD_JOBS=os.environ.get("CARGO_BUILD_JOBS", "1"))
    out = subprocess.run(["cargo", "bench", "--bench", "qp_matrix", "dense"], cwd=ROOT, env=env,
                         check=True, capture_output=True, text=True).stdout
    ours = {}
    for line in out.splitlines():
        m = re.match(r"^(.*): ([0-9.]+) ms", line)
        if m:
            ours[m.group(1)] = float(m.group(2))
    cases = [l.split("\t") for l in (TARGET / "qp-matrix-cases.txt").read_text().splitlines() if l]
    return ours, cases


def sympy_times(cases):
    """One child process per ground-types setting (SymPy reads it at import)."""
    code = r'''
import json, sys, time
import sympy
from sympy import sympify
from sympy.polys.matrices import DomainMatrix
def median_ms(fn, budget=1.5, min_runs=3, max_runs=200):
    ts = []; start = time.perf_counter()
    while len(ts) < min_runs or (time.perf_counter() - start < budget and len(ts) < max_runs):
        t = time.perf_counter(); fn(); ts.append(time.perf_counter() - t)
        if ts[-1] > 20: break
    ts.sort(); return ts[len(ts) // 2] * 1e3
out = {}
for name, n, ents in json.load(sys.stdin):
    M = sympy.Matrix(n, n, [sympify(e) for e in ents.split(";")])
    dm = DomainMatrix.from_Matrix(M)
    out[name + " charpoly"] = median_ms(lambda: dm.charpoly())
    out[name + " det"] = median_ms(lambda: dm.det())
    dmf = dm.to_field()
    out[name + " rref"] = median_ms(lambda: dmf.rref(), budget=3.0)
    out["domain"] = str(dm.domain) + " / " + str(dmf.domain)
out["version"] = sympy.__version__
print(json.dumps(out))
'''
    res = {}
    for gt in ("flint", "python"):
        env = dict(os.environ, SYMPY_GROUND_TYPES=gt)
        p = subprocess.run([sys.executable, "-c", code], input=json.dumps(
            [(c[0], int(c[1]), c[2]) for c in cases]), env=env, capture_output=True, text=True,
            check=True)
        res[gt] = json.loads(p.stdout)
    return res


def write_systems():
    files = {}
    n = 10
    p = [f"p{i}" for i in range(n)]
    files["diag10"] = {"parameters": {x: None for x in p},
                       "A": [[p[i] if i == j else 0 for j in range(n)] for i in range(n)],
                       "B": [[1]] * n, "C": [[1] * n], "D": [[0]]}
    A = [[0] * (2 * n) for _ in range(2 * n)]
    for i in range(n):
        A[i][i + n] = 1
        for j in range(n):
            if i == j:
                A[n + i][j], A[n + i][n + j] = "-2*k/m", "-2*c/m"
            elif abs(i - j) == 1:
                A[n + i][j], A[n + i][n + j] = "k/m", "c/m"
    B = [[0] for _ in range(2 * n)]
    B[n] = ["1/m"]
    C = [[0] * (2 * n)]
    C[0][n - 1] = 1
    files["chain10"] = {"parameters": {"m": None, "k": None, "c": None}, "A": A, "B": B,
                        "C": C, "D": [[0]]}
    paths = {}
    for name, body in files.items():
        path = TARGET / f"qp-{name}.json"
        path.write_text(json.dumps(body))
        paths[name] = path
    return paths


def run_cli(paths):
    subprocess.run(["cargo", "build", "--release"], cwd=ROOT, check=True, capture_output=True)
    exe = TARGET / "release" / "exactlti"
    rows = []
    for name, cmds, goal in (("diag10", ("tf", "minreal", "scb", "zeros"), 1.0),
                             ("chain10", ("tf", "minreal"), 2.0)):
        for cmd in cmds:
            p = subprocess.run(["/usr/bin/time", "-v", str(exe), cmd, str(paths[name]),
                                "--format", "json", "--max-seconds", "120"],
                               capture_output=True, text=True)
            wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", p.stderr)
            secs = (int(wall.group(1) or 0) * 3600 + int(wall.group(2)) * 60
                    + float(wall.group(3))) if wall else float("nan")
            rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr)
            mb = int(rss.group(1)) / 1024 if rss else float("nan")
            rows.append((f"{name} {cmd}", secs, mb, goal, p.returncode))
    return rows


def main():
    ensure_venv()
    ours, cases = run_ours()
    sy = sympy_times(cases)
    print("# Q(p) matrices: median wall times in ms (same matrices)")
    print(f"{'case':24} {'exactlti':>10} {'SymPy(flint)':>13} {'ratio':>8} "
          f"{'SymPy(python)':>14} {'ratio':>8}")
    print("-" * 84)
    for c in cases:
        for op in ("charpoly", "det", "rref"):
            name = f"{c[0]} {op}"
            o, f, p = ours.get(name), sy["flint"].get(name), sy["python"].get(name)
            rf = f"{f / o:7.1f}x" if (o and f) else f"{'-':>8}"
            rp = f"{p / o:7.1f}x" if (o and p) else f"{'-':>8}"
            print(f"{name:24} {o:10.3f} {f:13.3f} {rf} {p:14.3f} {rp}")
    print("SymPy", sy["python"]["version"], "DomainMatrix over", sy["python"]["domain"])
    print()
    print("# CLI (release) under /usr/bin/time -v")
    print(f"{'case':24} {'wall s':>8} {'max RSS MB':>11} {'goal s':>7} {'exit':>5}")
    for name, secs, mb, goal, rc in run_cli(write_systems()):
        print(f"{name:24} {secs:8.2f} {mb:11.1f} {goal:7.1f} {rc:5d}")


if __name__ == "__main__":
    main()
