#!/usr/bin/env python3
"""SymPy jordan_form beside `cargo bench --bench jordan`, in the same run.

Usage (from the repo root):  python3 scripts/anchors/jordan.py [--limit SECONDS]
Creates/uses the venv .venv-anchors at the repo root (pip install sympy) and re-executes
itself there. Cases come from ../shared/anchors/cases.py (or $EXACTLTI_ANCHORS) (the planted matrices use the
same distribution as benches/jordan.rs, not the same random stream). Each SymPy case runs
in a child process killed after the time limit.
"""
import multiprocessing as mp
import os
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
VENV = os.path.join(ROOT, ".venv-anchors")
CASES_DIR = os.environ.get("EXACTLTI_ANCHORS", os.path.join(ROOT, "..", "shared", "anchors"))


def ensure_venv():
    py = os.path.join(VENV, "bin", "python")
    if os.path.abspath(sys.prefix) == os.path.abspath(VENV):
        return
    if not os.path.exists(py):
        subprocess.check_call([sys.executable, "-m", "venv", VENV])
        subprocess.check_call([py, "-m", "pip", "install", "-q", "sympy"])
    os.execv(py, [py] + sys.argv)


def sympy_case(name, q):
    sys.path.insert(0, CASES_DIR)
    import sympy as sp
    import cases

    builders = {
        "seed 3x3": cases.seed_3x3,
        "point-mass A2 4x4": cases.point_mass_A2,
        "yaw-plane single wheel 4x4": cases.yaw_plane_single_wheel,
        "sympy issue 24942 3x3": lambda: sp.Matrix([[-3, 1, 2], [1, -1, 0], [1, 0, -2]]),
        "sliding masses 20x20": lambda: cases.sliding_masses()[0],
    }
    if name.startswith("planted n="):
        n = int(name.split("=")[1])
        a = cases.planted_jordan(n, n)[0]
    else:
        a = builders[name]()
    t = time.perf_counter()
    a.jordan_form()
    q.put(time.perf_counter() - t)


def time_sympy(name, limit):
    q = mp.Queue()
    p = mp.Process(target=sympy_case, args=(name, q))
    p.start()
    p.join(limit)
    if p.is_alive():
        p.kill()
        p.join()
        return None
    return q.get() if not q.empty() else None


def main():
    ensure_venv()
    limit = 120.0
    if "--limit" in sys.argv:
        limit = float(sys.argv[sys.argv.index("--limit") + 1])
    out = subprocess.run(
        ["cargo", "bench", "--bench", "jordan"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        env=dict(os.environ, CARGO_BUILD_JOBS="1"),
    )
    ours = {}
    for line in out.stdout.splitlines():
        if "\t" in line:
            k, v = line.split("\t")
            ours[k] = float(v)
    if not ours:
        print(out.stdout, out.stderr)
        sys.exit(1)
    print(f"{'case':<30} {'exactlti':>12} {'sympy':>14} {'ratio':>10}")
    for name, t in ours.items():
        s = time_sympy(name, limit)
        ss = f"> {limit:.0f} s" if s is None else f"{s:.4f} s"
        ratio = f">{limit / t:.0f}x" if s is None else f"{s / t:.0f}x"
        print(f"{name:<30} {t:>10.4f} s {ss:>14} {ratio:>10}", flush=True)


if __name__ == "__main__":
    main()
