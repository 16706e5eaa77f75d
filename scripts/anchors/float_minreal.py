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

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
VENV = os.path.join(ROOT, ".venv-anchors")
VPY = os.path.join(VENV, "bin", "python")


def ensure_venv():
    if os.path.abspath(sys.prefix) == os.path.abspath(VENV):
        return
    if not os.path.exists(VPY):
        print("creating", VENV, flush=True)
        subprocess.check_call([sys.executable, "-m", "venv", VENV])
        subprocess.check_call([VPY, "-m", "pip", "install", "-q", "numpy", "scipy", "control", "slycot"])
    os.execv(VPY, [VPY] + sys.argv)


def load(path):
    import numpy as np

    mats = {}
    with open(path) as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        if not lines[i].strip():
            i += 1
            continue
        name, r, c = lines[i].split()
        r, c = int(r), int(c)
        rows = [list(map(float, lines[i + 1 + k].split())) for k in range(r)]
        mats[name] = np.array(rows, dtype=float).reshape(r, c)
        i += 1 + r
    return mats


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
