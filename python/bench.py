"""Call overhead of the Python package (issue 16's speed goals).

1. Sliding-mass minimal realization through Python against the command line doing the
   same work (read data/sliding-masses.json, minimal realization, verification):
   `exactlti.load(f).minreal(method)` against `exactlti minreal f --method M --format json`
   (release binary, process start included, as a user pays it). Goal: Python within 1.5x.
   Also the symbolic path: the DC motor's SCB over QQ(J, alpha2, sigma0, sigma1)
   (`exactlti.load(f).scb()` against `exactlti scb f --format json`).
2. Converting a 100x100 exact rational matrix to SymPy (`Matrix.to_sympy()`). Goal: <= 50 ms.

Run with the package installed (release build: `pip install ./python`):
    python python/bench.py [--cli target/release/exactlti] [--repeat 15]
Best-of-N wall times; on a shared machine single figures move, best-of less.
"""

import argparse
import os
import random
import subprocess
import sys
import time
from fractions import Fraction

# the installed package, not the source folder next to this script (no compiled _core)
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]
import exactlti  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
SLIDING = os.path.join(ROOT, "data", "sliding-masses.json")
DC_MOTOR = os.path.join(ROOT, "data", "dc-motor-lugre.json")


def best(f, repeat):
    ts = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t)
    return min(ts)


def find_cli(path):
    if path:
        return path
    cli = os.path.join(ROOT, "target", "release", "exactlti")
    if not os.path.exists(cli):
        print("building the release command line (cargo build --release --bin exactlti)")
        subprocess.check_call(["cargo", "build", "--release", "--bin", "exactlti"], cwd=ROOT)
    return cli


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", help="path of the exactlti binary (release)")
    ap.add_argument("--repeat", type=int, default=15)
    args = ap.parse_args()
    cli = find_cli(args.cli)

    print("# sliding masses (20 states -> 8): best-of-%d wall times in ms" % args.repeat)
    print("%-12s %12s %12s %8s  %s" % ("method", "python", "cli", "py/cli", "goal <= 1.5"))
    for method in ("kalman", "jordan"):

        def py():
            r = exactlti.load(SLIDING).minreal(method=method)
            assert r.verified and r.nstates == 8
            r.A  # the result's matrices, as a user reads them

        def run_cli():
            subprocess.run(
                [cli, "minreal", SLIDING, "--method", method, "--format", "json"],
                check=True,
                stdout=subprocess.DEVNULL,
            )

        py()
        run_cli()
        tp, tc = best(py, args.repeat), best(run_cli, args.repeat)
        print(
            "%-12s %12.2f %12.2f %8.2f  %s"
            % (method, tp * 1e3, tc * 1e3, tp / tc, "ok" if tp <= 1.5 * tc else "MISSED")
        )

    # the symbolic path: the DC motor's SCB over QQ(J, alpha2, sigma0, sigma1)
    def py_sym():
        r = exactlti.load(DC_MOTOR).scb()
        assert r.verified and r.dims == (1, 0, 0, 2)
        r.A, r.conditions  # the result's matrices and conditions, as a user reads them

    def cli_sym():
        subprocess.run(
            [cli, "scb", DC_MOTOR, "--format", "json"], check=True, stdout=subprocess.DEVNULL
        )

    py_sym()
    cli_sym()
    tp, tc = best(py_sym, args.repeat), best(cli_sym, args.repeat)
    print(
        "%-12s %12.2f %12.2f %8.2f  %s"
        % ("scb Q(p)", tp * 1e3, tc * 1e3, tp / tc, "ok" if tp <= 1.5 * tc else "MISSED")
    )

    rng = random.Random(1)
    rows = [
        [Fraction(rng.randint(-10**6, 10**6), rng.randint(1, 10**4)) for _ in range(100)]
        for _ in range(100)
    ]
    A = exactlti.ss(rows).A
    ints = exactlti.ss([[rng.randint(-999, 999) for _ in range(100)] for _ in range(100)]).A
    import sympy

    S = A.to_sympy()
    assert S[3, 7] == sympy.Rational(rows[3][7].numerator, rows[3][7].denominator)
    print()
    print("# 100x100 exact matrix to SymPy: best-of-%d in ms (goal <= 50)" % args.repeat)
    for name, M in (("rational", A), ("integer", ints)):
        t = best(M.to_sympy, args.repeat)
        print("%-12s %8.2f  %s" % (name, t * 1e3, "ok" if t <= 0.050 else "MISSED"))
    t = best(lambda: sympy.Matrix(100, 100, lambda i, j: sympy.Rational(rows[i][j].numerator, rows[i][j].denominator)), 3)
    print("%-12s %8.2f  (reference: sympy.Matrix of 10^4 sympy.Rational, not ours)" % ("sympy-own", t * 1e3))


if __name__ == "__main__":
    sys.exit(main())
