"""Shared helpers of the anchor scripts: the venv bootstrap and the bench matrix reader."""
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
VENV = os.path.join(ROOT, ".venv-anchors")
VPY = os.path.join(VENV, "bin", "python")
# every anchor, so that any script can create the venv the others need too
PACKAGES = ["sympy", "python-flint", "numpy", "scipy", "control", "slycot"]


def ensure_venv():
    """Re-executes the calling script inside .venv-anchors, creating it when missing."""
    if os.path.abspath(sys.prefix) == os.path.abspath(VENV):
        return
    if not os.path.exists(VPY):
        print("creating", VENV, flush=True)
        subprocess.check_call([sys.executable, "-m", "venv", VENV])
        subprocess.check_call([VPY, "-m", "pip", "install", "-q"] + PACKAGES)
    os.execv(VPY, [VPY] + sys.argv)


def load(path):
    """Reads the `name rows cols` + rows text files the Rust benches write."""
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
