#!/usr/bin/env python3
"""Pencil / controllability structure: exactlti (exact) vs slycot (SLICOT, float, default tol).

`cargo bench --bench pencil` builds planted cases (a 100 x 120 pencil, a controllable-
structure n = 200, m = 5 pair, and 20 small planted cases of each kind), times exactlti and
writes the matrices to target/pencil-bench/*.txt with the planted structure printed as
`case ...` lines. This script runs on the same matrices
  * slycot.ag08bd (SLICOT AG08BD, the Kronecker structure of the system pencil; with m = p = 0
    it is the pencil A - sE itself): right/left indices, infinite elementary divisors and the
    number of finite eigenvalues,
  * slycot.ab01nd (SLICOT AB01ND, controllability staircase): block dims -> indices,
with their default tolerances, and counts how often the float structure differs from the
planted (exact) one. SLICOT TG01HD/TG01ID are not wrapped by slycot 0.7, so the descriptor
controllability counts have no anchor here.

Usage: python3 scripts/anchors/pencil.py [--no-bench]
"""
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _common import ROOT, ensure_venv, load  # noqa: E402


def ints(s):
    return [int(x) for x in s.split(",") if x != ""]


def ag08(A, E):
    import numpy as np
    import slycot

    l, n = A.shape
    z = np.zeros
    # slycot rejects empty B, C, D: a zero input and output add one L_0 and one L_0^T block
    # to the system pencil [[A - sE, 0], [0, 0]], removed again below
    r = slycot.ag08bd(l, n, 1, 1, A, E, z((l, 1)), z((1, n)), z((1, 1)))
    Af, Ef, nrank, niz, infz, kronr, infe, kronl = r
    right = sorted(int(x) for x in kronr)
    left = sorted(int(x) for x in kronl)
    for v in (right, left):
        if 0 in v:
            v.remove(0)
    inf = sorted(int(x) for x in infe)
    return right, left, inf, Af.shape[0], nrank


def ab01(A, B):
    import slycot

    n, m = B.shape
    Ac, Bc, ncont, indcon, nblk, Z, tau = slycot.ab01nd(n, m, A, B)
    blk = [int(x) for x in nblk[:indcon]]
    # indices = conjugate partition of the staircase block dims, with zeros for rank B < m
    idx = [sum(1 for b in blk if b > j) for j in range(m)]
    return sorted(idx, reverse=True), int(ncont), blk


def best(f, reps):
    t_best, out = float("inf"), None
    for _ in range(reps):
        t = time.perf_counter()
        out = f()
        t_best = min(t_best, time.perf_counter() - t)
    return t_best, out


def main():
    ensure_venv()
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
    out = ""
    if "--no-bench" not in sys.argv:
        env = dict(os.environ)
        env.setdefault("CARGO_BUILD_JOBS", "1")
        res = subprocess.run(["cargo", "bench", "--bench", "pencil"], cwd=ROOT, env=env,
                             capture_output=True, text=True)
        if res.returncode != 0:
            print(res.stderr)
            sys.exit("cargo bench failed")
        out = res.stdout
    else:
        path = os.path.join(target, "pencil-bench", "bench_output.txt")
        if os.path.exists(path):
            out = open(path).read()
    print(out)
    cases = {}
    for line in out.splitlines():
        m = re.match(r"case (\S+) (.*)", line)
        if m:
            cases[m.group(1)] = dict(kv.split("=") for kv in m.group(2).split())
    differ_p = differ_c = total_p = total_c = 0
    print(f"{'case':<14} {'exact (planted)':<44} {'slycot (default tol)':<44} {'ms':>8}")
    for name, want in cases.items():
        mats = load(os.path.join(target, "pencil-bench", f"{name}.txt"))
        if name.startswith("pencil"):
            total_p += 1
            t, (r, l, inf, nfin, nrank) = best(lambda: ag08(mats["A"], mats["E"]), 3)
            ex = (ints(want["right"]), ints(want["left"]), ints(want["inf"]), int(want["nfin"]))
            got = (r, l, inf, nfin)
            bad = got != ex
            differ_p += bad
            print(f"{name:<14} {str(ex)[:44]:<44} {str(got)[:44]:<44} {t * 1e3:8.2f}{' DIFFERENT' if bad else ''}")
        else:
            total_c += 1
            t, (idx, ncont, blk) = best(lambda: ab01(mats["A"], mats["B"]), 3)
            ex = (ints(want["indices"]), int(want["order"]))
            got = (idx, ncont)
            bad = got != ex
            differ_c += bad
            print(f"{name:<14} {str(ex)[:44]:<44} {str(got)[:44]:<44} {t * 1e3:8.2f}{' DIFFERENT' if bad else ''}")
    print(f"ag08bd: structure different from the exact one in {differ_p} of {total_p} pencils")
    print(f"ab01nd: indices/order different from the exact ones in {differ_c} of {total_c} pairs")


if __name__ == "__main__":
    main()
