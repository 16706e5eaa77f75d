#!/usr/bin/env python3
"""Symbolic models at scale (issue 25): the input files, and every CLI command timed on them.

Usage (from anywhere):
    python3 scripts/qp_scale.py write [DIR]           # the input files (default target/qp-scale)
    python3 scripts/qp_scale.py measure [--cases diag10,chain10,dense8x3] [--cmds tf,minreal]
                                        [--exe PATH] [--max-seconds S] [--dir DIR]

Inputs (fixed seeds; every file a system with `null` parameters, so `--symbolic` is implied):
- `diag{n}`    n = 2..10: A = diag(p0..p{n-1}), B = ones (n x 1), C = ones (1 x n), D = 0;
- `chain{n}`   n = 2..10: the n-mass chain between two walls in m, k, c, A = [[0, I], [-K/m,
  -L/m]], force on mass 1 (B = e_{n+1}/m), output the position of mass n;
- `dense{n}x{q}` n = 4..10, q = 2, 3: A dense n x n with entries c0 + c1 a + c2 b (+ c3 c),
  c_i in -5..5 (seed 1000 + 10 n + q), B and C^T integer columns in -3..3, D = 0.

`measure` runs `EXE CMD FILE --format json --max-seconds S` under /usr/bin/time (wall seconds
and maximum resident set) for every command that applies and prints one table (`-` = not run;
exit codes other than 0 are shown after the time). The release binary is taken as it is:
build it first (`cargo build --release`).
"""
import json
import random
import re
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_DIR = ROOT / "target" / "qp-scale"

# command name -> CLI arguments (after the binary; FILE is appended)
SYSTEM_CMDS = {
    "tf": ["tf"],
    "minreal": ["minreal"],
    "minreal-rosenbrock": ["minreal", "--method", "rosenbrock"],
    "minreal-ho-kalman": ["minreal", "--method", "ho-kalman"],
    "jordan": ["jordan"],
    "scb": ["scb"],
    "zeros": ["zeros"],
    "ctrb": ["ctrb"],
    "obsv": ["obsv"],
    "modes": ["modes"],
    "mnf": ["mnf"],
    "analyze": ["analyze"],
}
LINALG_CMDS = {f"linalg-{op}": ["linalg", op]
               for op in ("charpoly", "det", "rref", "rank", "inverse", "nullspace", "minpoly")}
ALL_CMDS = {**SYSTEM_CMDS, **LINALG_CMDS}


def diag(n):
    p = [f"p{i}" for i in range(n)]
    return {"parameters": {x: None for x in p},
            "A": [[p[i] if i == j else 0 for j in range(n)] for i in range(n)],
            "B": [[1] for _ in range(n)], "C": [[1] * n], "D": [[0]]}


def chain(n):
    a = [[0] * (2 * n) for _ in range(2 * n)]
    for i in range(n):
        a[i][i + n] = 1
        for j in range(n):
            if i == j:
                a[n + i][j], a[n + i][n + j] = "-2*k/m", "-2*c/m"
            elif abs(i - j) == 1:
                a[n + i][j], a[n + i][n + j] = "k/m", "c/m"
    b = [[0] for _ in range(2 * n)]
    b[n] = ["1/m"]
    c = [[0] * (2 * n)]
    c[0][n - 1] = 1
    return {"parameters": {"m": None, "k": None, "c": None}, "A": a, "B": b, "C": c,
            "D": [[0]]}


def dense_entries(n, q, seed):
    """n*n strings `c0 + c1*a + c2*b (+ c3*c)`, coefficients in -5..5."""
    rng = random.Random(seed)
    names = ["a", "b", "c"][:q]
    out = []
    for _ in range(n * n):
        cs = [rng.randint(-5, 5) for _ in range(q + 1)]
        terms = [str(cs[0])] + [f"{c}*{v}" for c, v in zip(cs[1:], names)]
        out.append(" + ".join(terms).replace("+ -", "- "))
    return out


def dense(n, q):
    seed = 1000 + 10 * n + q
    ents = dense_entries(n, q, seed)
    rng = random.Random(seed + 7)
    return {"parameters": {v: None for v in ["a", "b", "c"][:q]},
            "A": [ents[i * n:(i + 1) * n] for i in range(n)],
            "B": [[rng.randint(-3, 3)] for _ in range(n)],
            "C": [[rng.randint(-3, 3) for _ in range(n)]], "D": [[0]]}


def cases():
    out = {}
    for n in range(2, 11):
        out[f"diag{n}"] = diag(n)
    for n in range(2, 11):
        out[f"chain{n}"] = chain(n)
    for n in range(4, 11):
        for q in (2, 3):
            out[f"dense{n}x{q}"] = dense(n, q)
    return out


def write(d=DEFAULT_DIR):
    d = Path(d)
    d.mkdir(parents=True, exist_ok=True)
    paths = {}
    for name, body in cases().items():
        path = d / f"{name}.json"
        path.write_text(json.dumps(body, indent=1) + "\n")
        paths[name] = path
    return paths


def timed(argv, limit):
    """(wall seconds, max RSS MB, exit code) of one run under /usr/bin/time."""
    t0 = time.perf_counter()
    try:
        p = subprocess.run(["/usr/bin/time", "-f", "TIME %e %M"] + argv, capture_output=True,
                           text=True, timeout=limit + 30)
    except subprocess.TimeoutExpired:
        return float("nan"), float("nan"), -9
    wall = time.perf_counter() - t0  # (/usr/bin/time's %e has 10 ms resolution)
    m = re.search(r"TIME ([\d.]+) (\d+)", p.stderr)
    if not m:
        return wall, float("nan"), p.returncode
    return wall, int(m.group(2)) / 1024, p.returncode


def measure(names, cmds, exe, limit, d):
    paths = write(d)
    rows = []
    for name in names:
        for cmd in cmds:
            argv = [str(exe)] + ALL_CMDS[cmd] + [str(paths[name]), "--format", "json",
                                                  "--max-seconds", str(limit)]
            secs, mb, rc = timed(argv, limit)
            rows.append((name, cmd, secs, mb, rc))
            flag = "" if rc == 0 else f" exit {rc}"
            print(f"{name:12} {cmd:20} {secs:8.3f} s {mb:8.1f} MB{flag}", flush=True)
    return rows


def main(argv):
    if not argv or argv[0] not in ("write", "measure"):
        print(__doc__)
        return 2
    if argv[0] == "write":
        for p in write(argv[1] if len(argv) > 1 else DEFAULT_DIR).values():
            print(p)
        return 0
    opts = {"--cases": "diag10,chain10,dense8x3", "--cmds": ",".join(SYSTEM_CMDS),
            "--exe": str(ROOT / "target" / "release" / "exactlti"), "--max-seconds": "60",
            "--dir": str(DEFAULT_DIR)}
    it = iter(argv[1:])
    for k in it:
        opts[k] = next(it)
    cmds = opts["--cmds"].split(",")
    unknown = [c for c in cmds if c not in ALL_CMDS]
    if unknown:
        print("unknown commands:", unknown, "known:", list(ALL_CMDS))
        return 2
    measure(opts["--cases"].split(","), cmds, opts["--exe"], float(opts["--max-seconds"]),
            opts["--dir"])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
