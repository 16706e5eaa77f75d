#!/usr/bin/env python3
"""Side-by-side timings: exactlti's exact matrix kernels vs python-flint and SymPy.

Usage (from anywhere): python3 scripts/anchors/matrix.py [--no-sympy-slow] [--no-cli]
    [--only OP[,OP...]] [--kinds int,rat] [--no-bench] [--no-sympy] [--repeat K]
    [--sizes N[,N...]]

Creates the venv `.venv-anchors` at the repository root when missing (pip install sympy
python-flint), re-runs itself inside it, and times on the SAME matrices (a shared 64-bit
LCG, see `benches/matrix.rs`):

1. the fixed cases of issue 3 (rank / rref / null space of a 100x200 rank-50 product, det,
   charpoly, inverse of a 100x100 matrix with entries -9..9), bench against FLINT and SymPy;
2. the sweep of issue 29: every operation at n = 10, 25, 50, 100, 200 (table `SWEEP`, the
   same as in `benches/matrix.rs`) on integer entries (|p| <= 10^6) and on rational entries
   p/q (|p|, q <= 10^6): the bench (`cargo bench --bench matrix`), the user's path (the
   release CLI `exactlti linalg OP FILE` on a JSON file holding the matrix, wall clock,
   parsing and printing included), python-flint (fmpz_mat for integers, fmpq_mat for
   rationals) and SymPy's DomainMatrix over QQ (n <= 25); ratios to FLINT and the scaling
   exponent (least-squares slope of log t over log n for n >= 25) per operation.

`--repeat K`: every timing is the best of at least K runs (for a loaded machine);
`--sizes`: only these n. `-h`/`--help`: this text. Environment, passed on to the bench:
`SWEEP_ONLY=1` (only the sweep), `BENCH_FILTER=TEXT` (only bench cases whose name contains
TEXT, e.g. "sweep rat"); `EXACTLTI_EXE=PATH` times that CLI binary instead of building one.
Every operation runs on a full random n x n matrix (as issue 29 measured); `rref-def` is the
RREF of a rank-deficient one (last row = row 0 + row 1), whose free column has entries of
~n^2 log2(10^6) bits (output-heavy); `solve` has the right-hand side column 0 (solution
e_1), `solve-rand` a random one (`sweep_rhs`; a solution of ~n^2 log2(10^6) bits for rational
entries). `linalg` has no solve operation: solve rows have no CLI column.
FLINT's null space over Q is its RREF (fmpq_mat has no nullspace; the basis is read off).
Times are the best of a few repetitions, in milliseconds.

What is compared (the baseline is stated, not tuned): the user's path for exactlti is the
command `exactlti linalg OP FILE`, timed as a whole from outside (process start, reading the
JSON file, the kernel, writing the report to a pipe). python-flint is timed twice on the same
case and both ratios are printed:
- `FLINT` (column `CLI x`): the kernel only, on an fmpq_mat/fmpz_mat built beforehand. This
  is the baseline of issue 29's numbers and its "within 2x" criterion; it charges the CLI for
  everything around the kernel and is the stricter of the two.
- `FLINT+rd` (column `CLI x rd`): python-flint reading the same JSON file and computing, in a
  running interpreter: `json.load`, `fmpq_mat(rows)` from the entry strings (fmpz_mat from
  their integers), then the operation. This is the fair counterpart of the command line (both
  read the file and parse every entry); the interpreter's own start and `import flint`
  (~50 ms) are NOT charged, while the CLI's process start (~1-2 ms) is.
- `cpu x`: the CPU time (user + system) of the CLI process over the CPU time of FLINT's kernel
  (same baseline as `CLI x`): on a shared, loaded machine the wall clock of a 5 ms process
  varies by 2-3x with the scheduling, its CPU time much less.
"""
import json
import math
import os
import re
import resource
import subprocess
import sys
import tempfile
import threading
import time
from fractions import Fraction

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
VENV = os.path.join(ROOT, ".venv-anchors")
VPY = os.path.join(VENV, "bin", "python")
CLI_TIMEOUT = 120.0


def ensure_venv():
    if os.path.realpath(sys.prefix) == os.path.realpath(VENV):
        return
    if not os.path.exists(VPY):
        subprocess.check_call([sys.executable, "-m", "venv", VENV])
        subprocess.check_call([VPY, "-m", "pip", "install", "-q", "sympy", "python-flint"])
    os.execv(VPY, [VPY, os.path.abspath(__file__)] + sys.argv[1:])


MASK = (1 << 64) - 1

# (op, integer sizes, rational sizes): the table of benches/matrix.rs
SWEEP = [
    ("rank", [10, 25, 50, 100, 200], [10, 25, 50, 100, 200]),
    ("rref", [10, 25, 50, 100, 200], [10, 25, 50, 100, 200]),
    ("nullspace", [10, 25, 50, 100, 200], [10, 25, 50, 100, 200]),
    ("det", [10, 25, 50, 100, 200], [10, 25, 50, 100]),
    ("solve", [10, 25, 50, 100, 200], [10, 25, 50, 100]),
    ("solve-rand", [10, 25, 50, 100], [10, 25, 50]),
    ("inverse", [10, 25, 50, 100], [10, 25, 50]),
    ("charpoly", [10, 25, 50, 100], [10, 25, 50]),
    ("minpoly", [10, 25, 50, 100], [10, 25, 50]),
    ("rref-def", [10, 25, 50], [10, 25, 50]),
]
DEFICIENT = {"rref-def"}


class Lcg:
    """x <- (6364136223846793005 x + 1442695040888963407) mod 2^64; entry ((x>>33) % 19) - 9."""

    def __init__(self, seed):
        self.x = seed

    def u31(self):
        self.x = (self.x * 6364136223846793005 + 1442695040888963407) & MASK
        return self.x >> 33

    def entry(self):
        return (self.u31() % 19) - 9

    def matrix(self, m, n):
        return [[self.entry() for _ in range(n)] for _ in range(m)]


def sweep_matrix(rat, n, deficient):
    """The sweep matrix of benches/matrix.rs (`sweep_matrix`), rows of Fractions."""
    g = Lcg((1000 if rat else 2000) + n + (500 if deficient else 0))
    flat = []
    for _ in range(n * n):
        p = g.u31() % 2000001 - 1000000
        q = g.u31() % 1000000 + 1 if rat else 1
        flat.append(Fraction(p, q))
    a = [flat[i * n:(i + 1) * n] for i in range(n)]
    if deficient and n >= 2:
        a[n - 1] = [x + y for x, y in zip(a[0], a[1])]
    return a


def sweep_rhs(rat, n):
    """The right-hand side of `solve-rand` (`sweep_rhs` of benches/matrix.rs), Fractions."""
    g = Lcg((1000 if rat else 2000) + n + 700)
    out = []
    for _ in range(n):
        p = g.u31() % 2000001 - 1000000
        q = g.u31() % 1000000 + 1 if rat else 1
        out.append(Fraction(p, q))
    return out


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


def best_wall_cpu(f, reps):
    """(best wall-clock ms, best CPU ms of this process) over `reps` runs of `f`."""
    wall = cpu = float("inf")
    for _ in range(reps):
        s, c = time.perf_counter(), time.process_time()
        f()
        wall = min(wall, time.perf_counter() - s)
        cpu = min(cpu, time.process_time() - c)
    return wall * 1e3, cpu * 1e3


def children_cpu():
    """CPU seconds (user + system) of the waited-for child processes so far."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


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


def reps_for(n):
    return 3 if n <= 50 else 1


def flint_sweep_case(rat, op, a, reps):
    """FLINT's time on one sweep case (fmpq_mat for rationals, fmpz_mat for integers)."""
    import flint

    n = len(a)
    flat = [x for row in a for x in row]
    rhs = sweep_rhs(rat, n) if op == "solve-rand" else [row[0] for row in a]
    if rat:
        M = flint.fmpq_mat(n, n, [flint.fmpq(x.numerator, x.denominator) for x in flat])
        b = flint.fmpq_mat(n, 1, [flint.fmpq(x.numerator, x.denominator) for x in rhs])
    else:
        M = flint.fmpz_mat(n, n, [int(x) for x in flat])
        b = flint.fmpz_mat(n, 1, [int(x) for x in rhs])
    f = {
        "rank": lambda: M.rank(),
        "rref": lambda: M.rref(),
        "rref-def": lambda: M.rref(),
        "nullspace": (lambda: M.rref()) if rat else (lambda: M.nullspace()),
        "det": lambda: M.det(),
        "solve": lambda: M.solve(b),
        "solve-rand": lambda: M.solve(b),
        "inverse": lambda: M.inv(),
        "charpoly": lambda: M.charpoly(),
        "minpoly": lambda: M.minpoly(),
    }[op]
    return best_wall_cpu(f, reps)


def flint_read_case(rat, op, path, n, reps):
    """FLINT's time reading the sweep case's JSON file and computing (see the docstring)."""
    import flint

    def run():
        with open(path) as f:
            rows = json.load(f)["A"]
        if rat:
            M = flint.fmpq_mat(rows)
        else:
            M = flint.fmpz_mat([[int(x) for x in row] for row in rows])
        if op == "solve":
            b = M.__class__(n, 1, [M[i, 0] for i in range(n)])
            return M.solve(b)
        if op == "solve-rand":
            rhs = sweep_rhs(rat, n)
            if rat:
                b = flint.fmpq_mat(n, 1, [flint.fmpq(x.numerator, x.denominator) for x in rhs])
            else:
                b = flint.fmpz_mat(n, 1, [int(x) for x in rhs])
            return M.solve(b)
        f = {
            "rank": M.rank,
            "rref": M.rref,
            "rref-def": M.rref,
            "nullspace": M.rref if rat else M.nullspace,
            "det": M.det,
            "inverse": M.inv,
            "charpoly": M.charpoly,
            "minpoly": M.minpoly,
        }[op]
        return f()

    return best_wall_cpu(run, reps)[0]


def sympy_sweep_case(op, a):
    from sympy import QQ
    from sympy.polys.matrices import DomainMatrix

    n = len(a)
    M = DomainMatrix([[QQ(x.numerator, x.denominator) for x in row] for row in a], (n, n), QQ)
    rhs = sweep_rhs(True, n) if op == "solve-rand" else [row[0] for row in a]
    b = DomainMatrix([[QQ(x.numerator, x.denominator)] for x in rhs], (n, 1), QQ)
    f = {
        "rank": lambda: M.rank(),
        "rref": lambda: M.rref(),
        "rref-def": lambda: M.rref(),
        "nullspace": lambda: M.nullspace(),
        "det": lambda: M.det(),
        "solve": lambda: M.lu_solve(b),
        "solve-rand": lambda: M.lu_solve(b),
        "inverse": lambda: M.inv(),
        "charpoly": lambda: M.charpoly(),
        "minpoly": lambda: M.to_Matrix().minimal_polynomial(),
    }[op]
    return best(f, 1)


def build_cli():
    """The release CLI (`EXACTLTI_EXE` overrides it, e.g. a binary of an earlier commit)."""
    if os.environ.get("EXACTLTI_EXE"):
        return os.environ["EXACTLTI_EXE"]
    subprocess.run(
        ["cargo", "build", "--release", "--bin", "exactlti"],
        cwd=ROOT,
        check=True,
        capture_output=True,
    )
    return os.path.join(ROOT, "target", "release", "exactlti")


def matrix_file(tmp, kind, op, a):
    """The JSON file `{"A": [["p/q", ...], ...]}` of a sweep case (written once)."""
    n = len(a)
    path = os.path.join(tmp, f"{kind}_{'def' if op in DEFICIENT else 'sq'}_{n}.json")
    if not os.path.exists(path):
        with open(path, "w") as f:
            json.dump({"A": [[str(x) for x in row] for row in a]}, f)
    return path


def cli_case(exe, path, op, n, reps):
    """(wall-clock ms, CPU ms) of `exactlti linalg OP FILE`, each the best of reps; None
    past CLI_TIMEOUT.

    The wall clock is taken around a blocking wait (`Popen.wait()` without a timeout, a
    watchdog timer kills the process past CLI_TIMEOUT): `subprocess.run(timeout=...)` polls
    with sleeps of 0.5, 1, 2, 4, ... ms, which added up to 3.5 ms to a 4 ms command (measured
    2026-11-26: 7.5 ms polled against 4.1 ms blocking on the same file)."""
    if op.startswith("solve"):
        return None
    t = cpu = float("inf")
    for _ in range(reps):
        s, c = time.perf_counter(), children_cpu()
        proc = subprocess.Popen(
            [exe, "linalg", op.replace("-def", ""), path], stdout=subprocess.DEVNULL
        )
        killer = threading.Timer(CLI_TIMEOUT, proc.kill)
        killer.start()
        code = proc.wait()
        elapsed = time.perf_counter() - s
        killer.cancel()
        if code != 0:
            if code < 0:
                return None
            raise subprocess.CalledProcessError(code, proc.args)
        t = min(t, elapsed)
        cpu = min(cpu, children_cpu() - c)
    return t * 1e3, cpu * 1e3


def slope(points):
    """Least-squares slope of log t over log n (points with n >= 25 and t > 0)."""
    pts = [(math.log(n), math.log(t)) for n, t in points if n >= 25 and t and t > 0]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx


def fmt(x, w=9):
    return f"{'-':>{w}}" if x is None else f"{x:{w}.2f}"


def ratio(a, b):
    return None if a is None or b is None or b == 0 else a / b


def run_sweep(rust, args):
    exe = None if args["no_cli"] else build_cli()
    print("\n# issue 29 sweep: int |p| <= 10^6, rat p/q |p|,q <= 10^6; ms; x = / FLINT")
    print("# FLINT: kernel only; FLINT+rd: python-flint reading the same file and computing")
    print("# cpu x: CPU time of the CLI process / CPU time of FLINT's kernel (load-robust)")
    head = (
        f"{'kind':<4} {'op':<9} {'n':>4} {'bench':>9} {'CLI':>9} {'FLINT':>9} {'FLINT+rd':>9} "
        f"{'bench x':>8} {'CLI x':>8} {'CLI x rd':>9} {'cpu x':>8} {'SymPy':>9}"
    )
    print(head)
    print("-" * len(head))
    expo = []
    with tempfile.TemporaryDirectory() as tmp:
        for kind in args["kinds"]:
            rat = kind == "rat"
            for op, isz, rsz in SWEEP:
                if args["only"] and op not in args["only"]:
                    continue
                series = {"bench": [], "CLI": [], "FLINT": []}
                for n in rsz if rat else isz:
                    if args["sizes"] and n not in args["sizes"]:
                        continue
                    a = sweep_matrix(rat, n, op in DEFICIENT)
                    r = rust.get(f"sweep {kind} {op} {n}")
                    path = matrix_file(tmp, kind, op, a)
                    reps = max(args["repeat"], reps_for(n))
                    c = cli_case(exe, path, op, n, reps) if exe else None
                    c, ccpu = c if c else (None, None)
                    fl, flcpu = flint_sweep_case(rat, op, a, reps)
                    flr = flint_read_case(rat, op, path, n, reps)
                    sp = sympy_sweep_case(op, a) if n <= 25 and not args["no_sympy"] else None
                    for key, v in (("bench", r), ("CLI", c), ("FLINT", fl)):
                        series[key].append((n, v))
                    print(
                        f"{kind:<4} {op:<9} {n:>4} {fmt(r)} {fmt(c)} {fmt(fl)} {fmt(flr)} "
                        f"{fmt(ratio(r, fl), 7)}x {fmt(ratio(c, fl), 7)}x "
                        f"{fmt(ratio(c, flr), 8)}x {fmt(ratio(ccpu, flcpu), 7)}x {fmt(sp)}",
                        flush=True,
                    )
                expo.append((kind, op, {k: slope(v) for k, v in series.items()}))
    print("\n# scaling exponent (slope of log t over log n, n >= 25)")
    print(f"{'kind':<4} {'op':<9} {'bench':>7} {'CLI':>7} {'FLINT':>7}")
    for kind, op, s in expo:
        print(f"{kind:<4} {op:<9} {fmt(s['bench'], 7)} {fmt(s['CLI'], 7)} {fmt(s['FLINT'], 7)}")


def parse_args():
    argv = sys.argv[1:]
    only = None
    kinds = ["int", "rat"]
    repeat = 1
    sizes = None
    for i, a in enumerate(argv):
        if a == "--only":
            only = set(argv[i + 1].split(","))
        if a == "--sizes":
            sizes = {int(x) for x in argv[i + 1].split(",")}
        if a == "--repeat":
            repeat = int(argv[i + 1])
        if a == "--kinds":
            kinds = argv[i + 1].split(",")
    return {
        "slow": "--no-sympy-slow" not in argv,
        "no_cli": "--no-cli" in argv,
        "no_bench": "--no-bench" in argv,
        "no_sympy": "--no-sympy" in argv,
        "only": only,
        "kinds": kinds,
        "repeat": repeat,
        "sizes": sizes,
    }


def main():
    if "-h" in sys.argv[1:] or "--help" in sys.argv[1:]:
        print(__doc__)
        return
    ensure_venv()
    # SymPy's own (pure Python) domain arithmetic: with python-flint installed SymPy would
    # otherwise hand DomainMatrix work to FLINT and time FLINT twice
    os.environ["SYMPY_GROUND_TYPES"] = "python"
    args = parse_args()
    low, sq = cases()
    if args["no_bench"]:
        rust, rcheck = {}, None
        run_sweep(rust, args)
        return
    rust, rcheck = time_rust()
    flint_t, flint_extra, fcheck = time_flint(low, sq)
    sympy_t = time_sympy(low, sq, args["slow"]) if not args["no_sympy"] else {}
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
    run_sweep(rust, args)


if __name__ == "__main__":
    main()
