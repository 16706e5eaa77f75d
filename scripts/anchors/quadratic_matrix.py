#!/usr/bin/env python3
"""Matrices over Q(sqrt 2) and Q(i): the release CLI `linalg charpoly|det` (the field's
multi-modular kernels, src/qkernels/modular/quadratic.rs) against SymPy's DomainMatrix over
QQ<sqrt(2)> / QQ<I> (`QQ.algebraic_field(...)`), with ratios.

Usage (from anywhere):  python3 scripts/anchors/quadratic_matrix.py [--no-build] [N ...]

Creates the venv .venv-anchors at the repository root if missing (scripts/anchors/_common.py)
and re-runs itself inside it. Builds the release binary (`cargo build --release`) unless
--no-build (or EXACTLTI_EXE names a binary). Inputs: dense N x N (default N = 10, 20, 40),
entries a + b*sqrt(2) with |a| <= 9, |b| <= 5 (random.seed(3), as issue 23 item 3's
q2dense40.json) and, for Q(i), a + b*i from random.seed(4), written to target/quadratic-matrix/.
The CLI is timed as a user runs it (process start, reading the file, the kernel, the JSON
report): the median of blocking runs; SymPy: the median of in-process calls on a
DomainMatrix built once (a child process per case, killed past SYMPY_LIMIT seconds: then
"> limit" and a lower bound of the ratio). ratio = SymPy / CLI (> 1: exactlti is faster).
The CLI's characteristic polynomial and determinant are checked equal to SymPy's.
"""
import json
import os
import random
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common import ensure_venv  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
TARGET = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
SYMPY_LIMIT = float(os.environ.get("SYMPY_LIMIT", "300"))
CLI_REPS = 7
FIELDS = {"sqrt2": ("sqrt(2)", 3), "i": ("i", 4)}


def write_case(n, field):
    unit, seed = FIELDS[field]
    random.seed(seed)
    a = [[f"{random.randint(-9, 9)}+{random.randint(-5, 5)}*{unit}" for _ in range(n)]
         for _ in range(n)]
    path = TARGET / "quadratic-matrix" / f"q{field}dense{n}.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps({"A": a}))
    return path, a


def cli_run(exe, op, path, reps=CLI_REPS, limit=600.0):
    """(median ms, best ms, stdout of the last run) of `exactlti linalg OP FILE`."""
    times, out = [], ""
    for _ in range(reps):
        t = time.perf_counter()
        p = subprocess.run([str(exe), "linalg", op, str(path), "--format", "json",
                            "--max-seconds", str(int(limit))],
                           capture_output=True, text=True, timeout=limit + 10)
        times.append(time.perf_counter() - t)
        if p.returncode != 0:
            raise SystemExit(f"exactlti linalg {op} {path}: exit {p.returncode}: {p.stderr}")
        out = p.stdout
        if times[-1] > 5:
            break
    times.sort()
    return times[len(times) // 2] * 1e3, times[0] * 1e3, out


SYMPY_CODE = r'''
import json, sys, time
import sympy
from sympy import QQ, sqrt, I, sympify, Poly, Symbol
from sympy.polys.matrices import DomainMatrix
n, field, op, rows = json.load(sys.stdin)
gen = sqrt(2) if field == "sqrt2" else I
K = QQ.algebraic_field(gen)
ents = [[K.from_sympy(sympify(e.replace("i", "I"))) for e in r] for r in rows]
dm = DomainMatrix(ents, (n, n), K)
f = dm.charpoly if op == "charpoly" else dm.det
ts = []
start = time.perf_counter()
while len(ts) < 1 or (time.perf_counter() - start < 2.0 and len(ts) < 50):
    t = time.perf_counter(); res = f(); ts.append(time.perf_counter() - t)
    if ts[-1] > 5: break
ts.sort()
vals = res if op == "charpoly" else [res]
print(json.dumps({"ms": ts[len(ts) // 2] * 1e3, "domain": str(K),
                  "version": sympy.__version__,
                  "values": [str(sympy.expand(K.to_sympy(v))) for v in vals]}))
'''


def sympy_run(n, field, op, rows):
    try:
        p = subprocess.run([sys.executable, "-c", SYMPY_CODE],
                           input=json.dumps([n, field, op, rows]), capture_output=True,
                           text=True, timeout=SYMPY_LIMIT)
    except subprocess.TimeoutExpired:
        return None
    if p.returncode != 0:
        raise SystemExit(f"SymPy {field} {n} {op}: {p.stderr}")
    return json.loads(p.stdout)


def values_of(op, out):
    """The CLI's coefficients (high degree first, as SymPy's) or determinant, as SymPy
    expressions (the JSON report holds `charpoly` / `det` as text in x, sqrt(2), i)."""
    import sympy
    doc = json.loads(out)
    x = sympy.Symbol("x")
    text = doc[op].replace("^", "**").replace("i", "I")
    expr = sympy.sympify(text, locals={"x": x, "I": sympy.I, "sqrt": sympy.sqrt})
    if op == "charpoly":
        return sympy.Poly(expr, x).all_coeffs()
    return [expr]


def agree(op, out, sy):
    import sympy
    mine = values_of(op, out)
    theirs = [sympy.sympify(v) for v in sy["values"]]
    ok = len(mine) == len(theirs) and all(sympy.expand(a - b) == 0
                                           for a, b in zip(mine, theirs))
    return "yes" if ok else "NO"


def main():
    ensure_venv()
    sizes = [int(a) for a in sys.argv[1:] if a.isdigit()] or [10, 20, 40]
    exe = Path(os.environ.get("EXACTLTI_EXE", TARGET / "release" / "exactlti"))
    if "--no-build" not in sys.argv and not os.environ.get("EXACTLTI_EXE"):
        subprocess.run(["cargo", "build", "--release"], cwd=ROOT, check=True,
                       capture_output=True)
    print("load average:", " ".join(f"{x:.2f}" for x in os.getloadavg()), "| exe:", exe)
    print(f"# linalg over Q(sqrt 2) / Q(i): release CLI (median of up to {CLI_REPS} blocking "
          "runs, ms) vs SymPy DomainMatrix (median ms); ratio = SymPy / CLI")
    print(f"{'case':16} {'op':9} {'CLI ms':>10} {'best':>10} {'SymPy ms':>11} {'ratio':>9} "
          f"{'equal':>6}")
    version = None
    for field in ("sqrt2", "i"):
        for n in sizes:
            path, rows = write_case(n, field)
            for op in ("charpoly", "det"):
                med, best, out = cli_run(exe, op, path)
                sy = sympy_run(n, field, op, rows)
                if sy is None:
                    s, r, eq = f"> {SYMPY_LIMIT:.0f} s", f">{SYMPY_LIMIT * 1e3 / med:7.0f}x", "-"
                else:
                    version = (sy["version"], sy["domain"]) if field == "sqrt2" else version
                    s, r = f"{sy['ms']:11.2f}", f"{sy['ms'] / med:8.1f}x"
                    eq = agree(op, out, sy)
                print(f"q{field}dense{n:<6} {op:9} {med:10.2f} {best:10.2f} {s:>11} {r:>9} "
                      f"{eq:>6}", flush=True)
    if version:
        print("SymPy", version[0], "DomainMatrix over", version[1], "(and QQ<I>)")


if __name__ == "__main__":
    main()
