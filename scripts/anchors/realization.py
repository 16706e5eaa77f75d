#!/usr/bin/env python3
"""Minimal realization, side by side: exactlti exact (Kalman, Rosenbrock, Ho-Kalman), exactlti
float (orthogonal staircase) and python-control's minreal (SLICOT TB01PD), on the same systems.

`cargo bench --bench realization` builds the cases (the sliding masses, the planted rational
non-minimal systems `planted_<n>` and their `stiff_<n>` variants whose hidden modes are 16
times larger; see tests/common/systems.rs), times the exact and the float paths, and writes
every system to target/realization-bench/<case>.txt. All entries are dyadic rationals of
moderate size, so the f64 text is the exact system: python reads the very matrices the exact
path worked on, and the true McMillan degree is known by construction. This script then times
python-control on those files:

- `control.minreal(sys)` (its default tolerance), and
- `sys.minreal(tol=sqrt(eps) * norm)`, MATLAB's default relative tolerance, as a second
  float opinion.

and prints one table: case, n, true order, exact order and time per method, our float order,
time and truth, python-control's orders and time, and the time ratios. A float order that
differs from the true one is marked with `!`.

Usage: python3 scripts/anchors/realization.py [--sizes 10,20,40,60] [--no-bench]
       [--hidden-scale 16] [--all-methods]
Creates the venv .venv-anchors at the repo root if missing (numpy scipy control slycot).
"""
import math
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from _common import ROOT, ensure_venv, load  # noqa: E402


CASE = re.compile(r"case (\S+): n (\d+), true order (\d+), file (.+)$")
TIME = re.compile(r"(exact|float) minreal (?:(\S+) )?(sliding 20x20|planted n=\d+|stiff n=\d+): ([\d.]+) ms")
EXACT = re.compile(r"result exact minreal (\S+) (.+): order (\d+), verified (\w+)")
FLOAT = re.compile(r"result float minreal (.+): order (\d+), truth (\w+)")
METHODS = ["kalman", "rosenbrock", "ho-kalman"]


def label_of(case):
    if case == "sliding":
        return "sliding 20x20"
    kind, n = case.split("_")
    return f"{kind} n={n}"


def parse_bench(stdout):
    """Returns (cases in order, {label: {...}})."""
    cases, res = [], {}
    for line in stdout.splitlines():
        m = CASE.match(line)
        if m:
            case, n, r, path = m.group(1), int(m.group(2)), int(m.group(3)), m.group(4)
            cases.append(case)
            res[label_of(case)] = {"case": case, "n": n, "true": r, "path": path}
            continue
        m = TIME.match(line)
        if m:
            kind, method, label, ms = m.group(1), m.group(2), m.group(3), float(m.group(4))
            key = method if kind == "exact" else "float"
            res.setdefault(label, {}).setdefault(key, {})["ms"] = ms
            continue
        m = EXACT.match(line)
        if m:
            d = res[m.group(2)].setdefault(m.group(1), {})
            d["order"], d["verified"] = int(m.group(3)), m.group(4) == "true"
            continue
        m = FLOAT.match(line)
        if m:
            d = res[m.group(1)].setdefault("float", {})
            d["order"], d["truth"] = int(m.group(2)), m.group(3)
    return cases, res


def time_python(mats, reps):
    import control
    import numpy as np

    sys_ = control.ss(mats["A"], mats["B"], mats["C"], mats["D"])
    norm = max(np.linalg.norm(mats[k], 2) for k in "ABC")
    out = {}
    for key, fn in [
        ("default", lambda: control.minreal(sys_, verbose=False)),
        ("sqrt_eps", lambda: sys_.minreal(tol=math.sqrt(np.finfo(float).eps) * norm)),
    ]:
        best, order = float("inf"), None
        for _ in range(reps):
            t = time.perf_counter()
            r = fn()
            best = min(best, time.perf_counter() - t)
            order = r.nstates
        out[key] = (best * 1e3, order)
    return out


def fmt_order(order, true):
    if order is None:
        return "-"
    return f"{order}" + ("" if order == true else "!")


def main():
    ensure_venv()
    args = sys.argv[1:]
    sizes = "10,20,40,60"
    if "--sizes" in args:
        sizes = args[args.index("--sizes") + 1]
    env = dict(os.environ, EXACTLTI_BENCH_SIZES=sizes)
    if "--hidden-scale" in args:
        env["EXACTLTI_HIDDEN_SCALE"] = args[args.index("--hidden-scale") + 1]
    if "--all-methods" in args:
        env["EXACTLTI_BENCH_ALL"] = "1"
    env.setdefault("CARGO_BUILD_JOBS", "1")
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
    if "--no-bench" in args:
        # reuse the last bench output if saved, else only python-control
        saved = os.path.join(target, "realization-bench", "bench.out")
        stdout = open(saved).read() if os.path.exists(saved) else ""
    else:
        out = subprocess.run(["cargo", "bench", "--bench", "realization"], cwd=ROOT, env=env,
                             capture_output=True, text=True)
        if out.returncode != 0:
            print(out.stdout)
            print(out.stderr)
            sys.exit("cargo bench failed")
        stdout = out.stdout
        os.makedirs(os.path.join(target, "realization-bench"), exist_ok=True)
        with open(os.path.join(target, "realization-bench", "bench.out"), "w") as f:
            f.write(stdout)
    print(stdout)
    cases, res = parse_bench(stdout)
    head = (f"{'case':<14} {'n':>4} {'true':>4} | " + " ".join(f"{m + ' ms':>16}" for m in METHODS)
            + f" | {'float ms':>9} {'ord':>4} {'truth':>7} | {'p-c ms':>8} {'ord':>4} {'ord@sqrt(eps)':>13}"
            + f" | {'p-c/float':>9} {'exact/p-c':>9}")
    print(head)
    print("-" * len(head))
    for case in cases:
        r = res[label_of(case)]
        n, true = r["n"], r["true"]
        reps = 20 if n <= 20 else 5 if n <= 60 else 2
        py = time_python(load(r["path"]), reps)
        cols = []
        best_exact = None
        for m in METHODS:
            d = r.get(m)
            if d and "ms" in d:
                ok = d.get("order") == true and d.get("verified")
                cols.append(f"{d['ms']:>10.1f} ({fmt_order(d.get('order'), true)}{'' if ok else '?'})")
                best_exact = d["ms"] if best_exact is None else min(best_exact, d["ms"])
            else:
                cols.append(f"{'-':>16}")
        f = r.get("float", {})
        pms, porder = py["default"]
        _, porder2 = py["sqrt_eps"]
        fms = f.get("ms")
        ratio_pf = f"{pms / fms:>8.1f}x" if fms else f"{'-':>9}"
        ratio_ep = f"{best_exact / pms:>8.0f}x" if best_exact else f"{'-':>9}"
        print(f"{case:<14} {n:>4} {true:>4} | " + " ".join(f"{c:>16}" for c in cols)
              + f" | {fms if fms is None else round(fms, 3):>9} {fmt_order(f.get('order'), true):>4}"
              f" {f.get('truth', '-'):>7} | {pms:>8.3f} {fmt_order(porder, true):>4}"
              f" {fmt_order(porder2, true):>13} | {ratio_pf} {ratio_ep}")
    print("\nexact columns: best ms (order); '!' marks an order different from the true one;"
          " p-c = python-control minreal (SLICOT TB01PD), default tol and tol = sqrt(eps)*||.||;"
          " exact/p-c uses the fastest exact method.")


if __name__ == "__main__":
    main()
