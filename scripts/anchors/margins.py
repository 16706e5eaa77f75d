#!/usr/bin/env python3
"""`exactlti margin` and `exactlti stepinfo` beside python-control's `margin` and
`step_info` on the same loops (issue 28): every number side by side with its difference.

Usage (from the repo root):  python3 scripts/anchors/margins.py [--bin PATH]
Uses the venv .venv-anchors (see _common.py; with EXACTLTI_ANCHOR_PYTHON set, the running
Python, which must have python-control) and the exactlti binary (default
target/release/exactlti, else target/debug/exactlti). python-control's `step_info` is given
exactlti's time grid, so the two differ only in the step response itself.
"""
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _common import ROOT, ensure_venv  # noqa: E402

# (name, numerator, denominator), coefficients highest power first (python-control's order)
LOOPS = [
    ("1/(s(s+1)^2)", [1], [1, 2, 1, 0]),
    ("1/(s^3+2s^2+3s+4)", [1], [1, 2, 3, 4]),
    ("8/(s^3+2s^2+3s+4) unstable loop", [8], [1, 2, 3, 4]),
    ("integrator 1/s", [1], [1, 0]),
    ("2/(s-1) unstable", [2], [1, -1]),
    ("1/(s+1) no crossover", [1], [1, 1]),
    ("10(s+1)/(s(s+2)(s+5))", [10, 10], [1, 7, 10, 0]),
    ("(s+3)/(s^4+3s^3+5s^2+2s+1)", [1, 3], [1, 3, 5, 2, 1]),
    ("50/(s^3+9s^2+30s+40)", [50], [1, 9, 30, 40]),
]
STEPS = [
    ("1/(s^2+s+1)", [1], [1, 1, 1]),
    ("1/(s+1)", [1], [1, 1]),
    ("(s+3)/(s^2+2s+3)", [1, 3], [1, 2, 3]),
    ("(1-s)/(s^2+2s+1) undershoot", [-1, 1], [1, 2, 1]),
]


def poly_str(cs):
    n = len(cs) - 1
    return " + ".join("(%s)*s^%d" % (c, n - k) for k, c in enumerate(cs))


def exactlti(binary, args, num, den):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump({"G": [["(%s)/(%s)" % (poly_str(num), poly_str(den))]]}, f)
        path = f.name
    out = subprocess.run([binary] + args[:1] + [path] + args[1:] + ["--format", "json"],
                         capture_output=True, text=True)
    os.unlink(path)
    if out.returncode != 0:
        raise RuntimeError(out.stderr)
    return json.loads(out.stdout)


def num(x):
    return math.inf if x == "inf" else (math.nan if x is None else float(x))


def main():
    if os.environ.get("EXACTLTI_ANCHOR_PYTHON") is None:
        ensure_venv()
    import control as ct
    import numpy as np

    binary = None
    if "--bin" in sys.argv:
        binary = sys.argv[sys.argv.index("--bin") + 1]
    for cand in ["target/release/exactlti", "target/debug/exactlti"]:
        if binary is None and os.path.exists(os.path.join(ROOT, cand)):
            binary = os.path.join(ROOT, cand)
    worst = 0.0
    print("%-34s %-10s %18s %18s %10s" % ("loop", "quantity", "exactlti", "python-control", "rel.diff"))
    for name, n, d in LOOPS:
        j = exactlti(binary, ["margin"], n, d)
        gm, pm, wpc, wgc = ct.margin(ct.tf(n, d))
        ours = [num(j.get("gain_margin_approx", j["gain_margin"])), num(j["phase_margin_deg"]),
                num(j.get("phase_crossover_frequency_approx")),
                num(j.get("gain_crossover_frequency_approx"))]
        for q, a, b in zip(["gm", "pm (deg)", "w_pc", "w_gc"], ours, [gm, pm, wpc, wgc]):
            same = (math.isinf(a) and math.isinf(b)) or (math.isnan(a) and math.isnan(b))
            rel = 0.0 if same else abs(a - b) / max(1.0, abs(b))
            worst = max(worst, rel)
            print("%-34s %-10s %18.12g %18.12g %10.1e" % (name[:34], q, a, b, rel))
    for name, n, d in STEPS:
        j = exactlti(binary, ["stepinfo", "--to", "30", "--points", "30001"], n, d)
        ch = j["channels"][0]
        t = np.linspace(0, 30, 30001)
        info = ct.step_info(ct.tf(n, d), T=t)
        for k in ["RiseTime", "SettlingTime", "Overshoot", "Undershoot", "Peak", "PeakTime"]:
            a, b = float(ch[k]), float(info[k])
            rel = abs(a - b) / max(1.0, abs(b))
            worst = max(worst, rel)
            print("%-34s %-10s %18.12g %18.12g %10.1e" % (name[:34], k[:10], a, b, rel))
    print("largest relative difference: %.1e" % worst)


if __name__ == "__main__":
    main()
