#!/usr/bin/env python3
"""Multivariate polynomials and Q(p): exactlti vs SymPy vs python-flint (fmpz_mpoly).

Usage (from anywhere):  python3 scripts/anchors/mpoly.py

Creates the venv .venv-anchors at the repository root if missing and re-runs itself inside
it; runs `cargo bench --bench mpoly`, which prints `name: X ms` lines and writes the inputs
to target/mpoly-bench-cases.txt; times the same cases with

* SymPy (pure-Python ground types, SYMPY_GROUND_TYPES=python): DomainMatrix.charpoly over
  ZZ[params], PolyElement.gcd / factor_list over ZZ[vars], DomainMatrix.rref over
  QQ(a, b, c);
* python-flint 0.9 fmpz_mpoly (gcd, factor), lex order;

and prints one table with the ratios (goals: charpoly >= 10x faster than SymPy; gcd and factor
within 5x of FLINT and >= 20x faster than SymPy).
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
    out = subprocess.run(["cargo", "bench", "--bench", "mpoly"], cwd=ROOT, env=env,
                         check=True, capture_output=True, text=True).stdout
    ours, notes = {}, {}
    last = None
    for line in out.splitlines():
        m = re.match(r"^(.*): ([0-9.]+) ms$", line)
        if m:
            last = m.group(1)
            ours[last] = float(m.group(2))
        elif line.startswith("  (") and last:
            notes[last] = line.strip()
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    cases = [l.split("\t") for l in (target / "mpoly-bench-cases.txt").read_text().splitlines() if l]
    return ours, notes, cases


def main():
    ensure_venv()
    os.environ["SYMPY_GROUND_TYPES"] = "python"
    import sympy
    from sympy import sympify, ZZ, QQ
    from sympy.polys.matrices import DomainMatrix
    from sympy.polys.rings import ring
    import flint

    ours, notes, cases = run_ours()
    rows = []
    for case in cases:
        kind, name, vars_ = case[0], case[1], case[2].split(",")
        syms = sympy.symbols(vars_)
        sy = fl = None
        if kind == "charpoly":
            n = int(case[3])
            ents = case[4].split(";")
            R = ZZ[tuple(syms)]
            dm = DomainMatrix([[R.from_sympy(sympify(ents[i * n + j])) for j in range(n)]
                               for i in range(n)], (n, n), R)
            sy = median_ms(lambda: dm.charpoly())
        elif kind in ("gcd", "factor"):
            Rg, *_ = ring(",".join(vars_), ZZ)
            polys = [Rg.from_expr(sympify(s)) for s in case[3:]]
            ctx = flint.fmpz_mpoly_ctx.get(tuple(vars_), "lex")
            fpolys = []
            for p in polys:
                fpolys.append(ctx.from_dict({tuple(int(e) for e in m): int(c) for m, c in p.items()}))
            if kind == "gcd":
                f, g = polys
                ff, fg = fpolys
                sy = median_ms(lambda: f.gcd(g))
                fl = median_ms(lambda: ff.gcd(fg))
            else:
                (f,) = polys
                (ff,) = fpolys
                sy = median_ms(lambda: f.factor_list())
                fl = median_ms(lambda: ff.factor())
        elif kind == "rref":
            m, n = int(case[3]), int(case[4])
            ents = case[5].split(";")
            K = QQ.frac_field(*syms)
            dm = DomainMatrix([[K.from_sympy(sympify(ents[i * n + j])) for j in range(n)]
                               for i in range(m)], (m, n), K)
            sy = median_ms(lambda: dm.rref(), budget=3.0)
        rows.append((name, ours.get(name), fl, sy))

    print("# multivariate polynomials / Q(p): median wall times in ms (same inputs)")
    print(f"{'case':58} {'exactlti':>10} {'FLINT':>10} {'x FLINT':>8} {'SymPy':>10} {'SymPy/us':>9}")
    print("-" * 110)
    for name, o, fl, sy in rows:
        fs = f"{fl:10.3f}" if fl is not None else f"{'-':>10}"
        xf = f"{o / fl:7.2f}x" if (fl and o) else f"{'-':>8}"
        ss = f"{sy:10.3f}" if sy is not None else f"{'-':>10}"
        xs = f"{sy / o:8.1f}x" if (sy and o) else f"{'-':>9}"
        os_ = f"{o:10.3f}" if o is not None else f"{'-':>10}"
        print(f"{name:58} {os_} {fs} {xf} {ss} {xs}")
        if name in notes:
            print(f"{'':58} {notes[name]}")
    print("SymPy with SYMPY_GROUND_TYPES=python; FLINT = python-flint", flint.__version__,
          "fmpz_mpoly (lex); sympy", sympy.__version__)


if __name__ == "__main__":
    main()
