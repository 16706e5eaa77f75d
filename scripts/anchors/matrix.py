#!/usr/bin/env python3
"""Side-by-side timings: exactlti's exact matrix kernels vs python-flint and SymPy.

Usage (from anywhere): python3 scripts/anchors/matrix.py [--no-sympy-slow]

Creates the venv `.venv-anchors` at the repository root when missing (pip install sympy
python-flint), re-runs itself inside it, times FLINT and SymPy's DomainMatrix over QQ on the
SAME matrices as `benches/matrix.rs` (a shared 64-bit LCG), runs
`cargo bench --bench matrix`, and prints one table with the ratios.

Cases: rank, rref, null space of L*R (L 100x50, R 50x200, factor entries -9..9, rank 50);
det, charpoly, inverse of a 100x100 matrix with entries -9..9. Times are the best of a few
repetitions, in milliseconds.
"""
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
VENV = os.path.join(ROOT, ".venv-anchors")
VPY = os.path.join(VENV, "bin", "python")


def ensure_venv():
    if os.path.realpath(sys.prefix) == os.path.realpath(VENV):
        return
    if not os.path.exists(VPY):
        subprocess.check_call([sys.executable, "-m", "venv", VENV])
        subprocess.check_call([VPY, "-m", "pip", "install", "-q", "sympy", "python-flint"])
    os.execv(VPY, [VPY, os.path.abspath(__file__)] + sys.argv[1:])


MASK = (1 << 64) - 1


class Lcg:
    """x <- (6364136223846793005 x + 1442695040888963407) mod 2^64; entry ((x>>33) % 19) - 9."""

    def __init__(self, seed):
        self.x = seed

    def entry(self):
        self.x = (self.x * 6364136223846793005 + 1442695040888963407) & MASK
        return ((self.x >> 33) % 19) - 9

    def matrix(self, m, n):
        return [[self.entry() for _ in range(n)] for _ in range(m)]


def matmul(a, b):
    bt = list(zip(*b))
    return [[sum(x * y for x, y in zip(row, col)) for col in bt] for row in a]


def best(f, reps):
    t = float("inf")
    for _ in range(reps):
        s = time.perf_counter()
        f()
        t = min(t, time.perf_counter() - s)
    return t * 1e3


def cases():
    g = Lcg(20240601)
    low = matmul(g.matrix(100, 50), g.matrix(50, 200))
    sq = g.matrix(100, 100)
    return low, sq


def time_flint(low, sq):
    import flint

    flat = lambda a: [x for row in a for x in row]
    Lq = flint.fmpq_mat(100, 200, flat(low))
    Lz = flint.fmpz_mat(100, 200, flat(low))
    Sq = flint.fmpq_mat(100, 100, flat(sq))
    Sz = flint.fmpz_mat(100, 100, flat(sq))
    assert Lq.rref()[1] == 50 and Lz.rank() == 50
    out = {
        "rank 100x200 r50": best(lambda: Lq.rref()[1], 5),
        "rref 100x200 r50": best(lambda: Lq.rref(), 5),
        "nullspace 100x200 r50": best(lambda: Lz.nullspace(), 5),
        "det 100x100": best(lambda: Sz.det(), 5),
        "charpoly 100x100": best(lambda: Sz.charpoly(), 5),
        "inverse 100x100": best(lambda: Sq.inv(), 5),
    }
    extra = {
        "rank 100x200 r50 (fmpz_mat.rank)": best(lambda: Lz.rank(), 5),
        "det 100x100 (fmpq_mat)": best(lambda: Sq.det(), 5),
    }
    check = int(Sz.det()) % 1000000007
    return out, extra, check


def time_sympy(low, sq, slow):
    from sympy import QQ
    from sympy.polys.matrices import DomainMatrix

    L = DomainMatrix([[QQ(x) for x in row] for row in low], (100, 200), QQ)
    S = DomainMatrix([[QQ(x) for x in row] for row in sq], (100, 100), QQ)
    out = {
        "rank 100x200 r50": best(lambda: L.rank(), 2),
        "rref 100x200 r50": best(lambda: L.rref(), 2),
        "nullspace 100x200 r50": best(lambda: L.nullspace(), 2),
    }
    if slow:
        out["det 100x100"] = best(lambda: S.det(), 1)
        out["charpoly 100x100"] = best(lambda: S.charpoly(), 1)
        out["inverse 100x100"] = best(lambda: S.inv(), 1)
    return out


def time_rust():
    env = dict(os.environ, CARGO_BUILD_JOBS=os.environ.get("CARGO_BUILD_JOBS", "1"))
    res = subprocess.run(
        ["cargo", "bench", "--bench", "matrix"],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        check=True,
    )
    out, check = {}, None
    for line in res.stdout.splitlines():
        m = re.match(r"^(.*): ([0-9.]+) ms$", line)
        if m:
            out[m.group(1)] = float(m.group(2))
        m = re.match(r"^check det100 mod 1000000007: (\d+)$", line)
        if m:
            check = int(m.group(1))
    return out, check


def main():
    ensure_venv()
    # SymPy's own (pure Python) domain arithmetic: with python-flint installed SymPy would
    # otherwise hand DomainMatrix work to FLINT and time FLINT twice
    os.environ["SYMPY_GROUND_TYPES"] = "python"
    slow = "--no-sympy-slow" not in sys.argv
    low, sq = cases()
    rust, rcheck = time_rust()
    flint_t, flint_extra, fcheck = time_flint(low, sq)
    sympy_t = time_sympy(low, sq, slow)
    same = "same matrices: OK" if rcheck == fcheck else f"MISMATCH {rcheck} != {fcheck}"
    print(f"# exact matrix kernels over Q, best-of times in ms ({same})")
    head = f"{'case':<24} {'exactlti':>10} {'FLINT':>10} {'x FLINT':>8} {'SymPy':>10} {'SymPy/us':>9}"
    print(head)
    print("-" * len(head))
    for case, ft in flint_t.items():
        r = rust.get(case, float("nan"))
        st = sympy_t.get(case)
        s_str = f"{st:10.1f} {st / r:8.1f}x" if st is not None else f"{'-':>10} {'-':>9}"
        print(f"{case:<24} {r:10.2f} {ft:10.2f} {r / ft:7.2f}x {s_str}")
    for case, ft in flint_extra.items():
        print(f"  FLINT {case}: {ft:.2f} ms")


if __name__ == "__main__":
    main()
