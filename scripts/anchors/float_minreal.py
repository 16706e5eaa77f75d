#!/usr/bin/env python3
"""Float minreal: exactlti (Rust, orthogonal staircase) vs python-control minreal (SLICOT TB01PD).

Same matrices for both: `cargo bench --bench float` builds the random non-minimal systems
(exactlti::float::random::random_nonminimal, seed = n, 2 inputs, 2 outputs: a random minimal
part of order n/2, a controllable-unobservable part of order n/4 and an uncontrollable-
observable rest, scrambled by a random orthogonal matrix), times exactlti's minreal, and
writes each system to target/float-bench/sys_<n>.txt with round-trip exact decimals. This
script then times python-control's minreal on those files and prints both, side by side.

Usage: python3 scripts/anchors/float_minreal.py [--sizes 50,100,200,400] [--no-bench]
Creates the venv .venv-anchors at the repo root if missing (numpy scipy control slycot).
"""
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _common import ROOT, ensure_venv, load  # noqa: E402


def main():
    ensure_venv()
    import control

    sizes = [50, 100, 200, 400]
    run_bench = True
    args = sys.argv[1:]
    if "--sizes" in args:
        sizes = [int(x) for x in args[args.index("--sizes") + 1].split(",")]
    if "--no-bench" in args:
        run_bench = False
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
    rust = {}
    if run_bench:
        env = dict(os.environ, EXACTLTI_BENCH_SIZES=",".join(map(str, sizes)))
        env.setdefault("CARGO_BUILD_JOBS", "1")
        out = subprocess.run(["cargo", "bench", "--bench", "float"], cwd=ROOT, env=env,
                             capture_output=True, text=True)
        if out.returncode != 0:
            print(out.stderr)
            sys.exit("cargo bench failed")
        print(out.stdout)
        for line in out.stdout.splitlines():
            m = re.match(r"float minreal n=(\d+): ([\d.]+) ms \(order (\d+), expected (\d+), truth (\w+)\)", line)
            if m:
                rust[int(m.group(1))] = (float(m.group(2)), int(m.group(3)), int(m.group(4)), m.group(5))
    rows = []
    for n in sizes:
        path = os.path.join(target, "float-bench", f"sys_{n}.txt")
        mats = load(path)
        sys_ = control.ss(mats["A"], mats["B"], mats["C"], mats["D"])
        reps = 20 if n <= 60 else 5 if n <= 120 else 3 if n <= 250 else 1
        best, order = float("inf"), None
        for _ in range(reps):
            t = time.perf_counter()
            r = control.minreal(sys_, verbose=False)
            best = min(best, time.perf_counter() - t)
            order = r.nstates
        rows.append((n, rust.get(n), best * 1e3, order))
    print(f"{'n':>5} {'expected':>8} | {'exactlti ms':>12} {'order':>5} {'truth':>7} | "
          f"{'python-control ms':>17} {'order':>5} | {'speed-up':>8}")
    for n, r, pms, porder in rows:
        if r is None:
            print(f"{n:>5} {'?':>8} | {'-':>12} {'-':>5} {'-':>7} | {pms:>17.3f} {porder:>5} | {'-':>8}")
            continue
        rms, rorder, expected, truth = r
        print(f"{n:>5} {expected:>8} | {rms:>12.3f} {rorder:>5} {truth:>7} | {pms:>17.3f} {porder:>5} | "
              f"{pms / rms:>7.1f}x")


if __name__ == "__main__":
    main()
