#!/usr/bin/env python3
"""Matrices over Q(p): exactlti (kernels registered on the field) vs SymPy's DomainMatrix and
python-flint's fmpz_mpoly, and the symbolic scale commands of issue 25 (release CLI).

Usage (from anywhere):  python3 scripts/anchors/qp_matrix.py [--cli-only]

Creates the venv .venv-anchors at the repository root if missing (sympy, python-flint, ...)
and re-runs itself inside it. One run prints:

1. Dense N x N (N = 6, 7, 8), entries linear in a, b, c: `cargo bench --bench qp_matrix
   dense` (in-process, `name: X ms` lines; the inputs go to target/qp-matrix-cases.txt)
   beside SymPy's DomainMatrix on the same matrices (charpoly(), det() over ZZ[a,b,c] and
   rref() over QQ(a,b,c), with FLINT and with pure-Python ground types) and python-flint's
   fmpz_mpoly (Bareiss fraction-free elimination: det, det(xI - A) with x a fourth variable,
   and the fraction-free Gauss-Jordan form), with ratios (goal: each >= 10x faster than
   SymPy).
2. The release CLI (`cargo build --release`) on the files of scripts/qp_scale.py (dense8x3
   `linalg charpoly|det|rref` and `tf`, `minreal` (Kalman, Rosenbrock), `jordan`, `mnf`;
   chain10 `tf`/`minreal` (goal 2 s), `jordan`/`zeros`/`scb`; diag10 every command; the
   symbolic yaw plane and single-track files of data/ `minreal --method jordan`, goal 30 s) under
   /usr/bin/time: wall seconds and maximum resident set, the goal and its ratio (goal /
   time; >= 1 is met; the heavy dense8x3/chain10 commands: goal 5 s, "seconds, not tens"),
   and for dense8 linalg the ratio SymPy / CLI (SymPy has no counterpart of the system
   commands on these models: no ratio there) (the CLI time includes
   process start and reading the file). `--cli-only` skips the bench and the build (the
   release binary as it is; the `cli dense8x3` row of table 1 then has no in-process time).
   The dense8x3 `linalg` rows are timed as a user runs them: the command started and waited
   for (a blocking `wait4`, no polling, no /usr/bin/time in between), CLI_REPS runs, the
   median (and the best) wall time beside SymPy's median; the load average is printed.
3. `--dense-table`: `linalg charpoly|det|rref` on dense n x n, n = 4..10, entries linear in
   q = 2, 3 parameters (files of scripts/qp_scale.py), release CLI (median of CLI_REPS
   blocking runs) against SymPy's DomainMatrix (flint ground types) on the same matrices.
"""
import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common import ensure_venv  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
import qp_scale  # noqa: E402  (scripts/qp_scale.py: the scale input files)

ROOT = Path(__file__).resolve().parents[2]
TARGET = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))


def median_ms(fn, budget=1.5, min_runs=3, max_runs=200):
    times = []
    start = time.perf_counter()
    while len(times) < min_runs or (time.perf_counter() - start < budget and len(times) < max_runs):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
        if times[-1] > 20:
            break
    times.sort()
    return times[len(times) // 2] * 1e3


CLI_REPS = 15


def cli_wall(argv, reps=CLI_REPS, limit=60.0):
    """(median ms, best ms, max RSS MB, exit code) of `argv` run `reps` times, each timed
    around a blocking wait4 (a watchdog kills it past `limit` s)."""
    import threading
    times, rss, rc = [], 0.0, 0
    for _ in range(reps):
        t = time.perf_counter()
        p = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        killer = threading.Timer(limit, p.kill)
        killer.start()
        _, status, ru = os.wait4(p.pid, 0)
        times.append(time.perf_counter() - t)
        killer.cancel()
        p.returncode = os.waitstatus_to_exitcode(status)
        rss = max(rss, ru.ru_maxrss / 1024)
        rc = p.returncode or rc
        if times[-1] > 5:
            break
    times.sort()
    return times[len(times) // 2] * 1e3, times[0] * 1e3, rss, rc


def run_ours():
    env = dict(os.environ, CARGO_BUILD_JOBS=os.environ.get("CARGO_BUILD_JOBS", "1"))
    out = subprocess.run(["cargo", "bench", "--bench", "qp_matrix", "dense"], cwd=ROOT, env=env,
                         check=True, capture_output=True, text=True).stdout
    ours = {}
    for line in out.splitlines():
        m = re.match(r"^(.*): ([0-9.]+) ms", line)
        if m:
            ours[m.group(1)] = float(m.group(2))
    cases = [l.split("\t") for l in (TARGET / "qp-matrix-cases.txt").read_text().splitlines() if l]
    return ours, cases


def sympy_times(cases, ground_types=("flint", "python")):
    """One child process per ground-types setting (SymPy reads it at import)."""
    code = r'''
import json, sys, time
import sympy
from sympy import sympify
from sympy.polys.matrices import DomainMatrix
def median_ms(fn, budget=1.5, min_runs=3, max_runs=200):
    ts = []; start = time.perf_counter()
    while len(ts) < min_runs or (time.perf_counter() - start < budget and len(ts) < max_runs):
        t = time.perf_counter(); fn(); ts.append(time.perf_counter() - t)
        if ts[-1] > 20: break
    ts.sort(); return ts[len(ts) // 2] * 1e3
out = {}
for name, n, ents in json.load(sys.stdin):
    M = sympy.Matrix(n, n, [sympify(e) for e in ents.split(";")])
    dm = DomainMatrix.from_Matrix(M)
    out[name + " charpoly"] = median_ms(lambda: dm.charpoly())
    out[name + " det"] = median_ms(lambda: dm.det())
    dmf = dm.to_field()
    out[name + " rref"] = median_ms(lambda: dmf.rref(), budget=3.0)
    out["domain"] = str(dm.domain) + " / " + str(dmf.domain)
out["version"] = sympy.__version__
print(json.dumps(out))
'''
    res = {}
    for gt in ground_types:
        env = dict(os.environ, SYMPY_GROUND_TYPES=gt)
        p = subprocess.run([sys.executable, "-c", code], input=json.dumps(
            [(c[0], int(c[1]), c[2]) for c in cases]), env=env, capture_output=True, text=True,
            check=True)
        res[gt] = json.loads(p.stdout)
    return res


def flint_times(cases):
    """python-flint fmpz_mpoly: Bareiss det, det(xI - A), fraction-free Gauss-Jordan."""
    code = r'''
import json, sys, time
import flint
def median_ms(fn, budget=1.5, min_runs=3, max_runs=200):
    ts = []; start = time.perf_counter()
    while len(ts) < min_runs or (time.perf_counter() - start < budget and len(ts) < max_runs):
        t = time.perf_counter(); fn(); ts.append(time.perf_counter() - t)
        if ts[-1] > 20: break
    ts.sort(); return ts[len(ts) // 2] * 1e3
ctx = flint.fmpz_mpoly_ctx.get(("a", "b", "c", "x"), "degrevlex")
a, b, c, x = ctx.gens()
env = {"a": a, "b": b, "c": c}
def bareiss(m, full=False):
    """Fraction-free elimination in place; returns the last pivot (det up to sign)."""
    n = len(m); prev = ctx.from_dict({}) + 1; sign = 1
    for k in range(n):
        p = next((i for i in range(k, n) if m[i][k] != 0), None)
        if p is None: return 0
        if p != k: m[k], m[p] = m[p], m[k]; sign = -sign
        for i in range(n) if full else range(k + 1, n):
            if i == k: continue
            for j in range(k + 1, len(m[i])):
                m[i][j] = (m[k][k] * m[i][j] - m[i][k] * m[k][j]) / prev
            m[i][k] = 0 * prev
        prev = m[k][k]
    return sign * prev
out = {}
for name, n, ents in json.load(sys.stdin):
    A = [[eval(e.replace("^", "**"), {}, env) + 0 * x for e in ents.split(";")[i * n:(i + 1) * n]]
         for i in range(n)]
    out[name + " det"] = median_ms(lambda: bareiss([r[:] for r in A]))
    xi = [[(x if i == j else 0) - A[i][j] for j in range(n)] for i in range(n)]
    out[name + " charpoly"] = median_ms(lambda: bareiss([r[:] for r in xi]))
    out[name + " rref"] = median_ms(lambda: bareiss([r[:] for r in A], full=True))
out["version"] = flint.__version__
print(json.dumps(out))
'''
    p = subprocess.run([sys.executable, "-c", code], input=json.dumps(
        [(c[0], int(c[1]), c[2]) for c in cases]), capture_output=True, text=True)
    if p.returncode != 0:
        print("python-flint fmpz_mpoly: not available:", p.stderr.strip().splitlines()[-1:])
        return {}
    return json.loads(p.stdout)


def cli_cases():
    """The scale files of scripts/qp_scale.py: (name, command, goal seconds)."""
    rows = [("dense8x3", f"linalg-{op}", None) for op in ("charpoly", "det", "rref")]
    # the heavy commands of issue 25 on the same files ("seconds, not tens": goal 5 s)
    rows += [("dense8x3", cmd, 5.0)
             for cmd in ("tf", "minreal", "minreal-rosenbrock", "jordan", "mnf")]
    rows += [("chain10", cmd, 2.0) for cmd in ("tf", "minreal")]
    rows += [("chain10", cmd, 5.0) for cmd in ("jordan", "zeros", "scb")]
    rows += [("diag10", cmd, 1.0) for cmd in qp_scale.SYSTEM_CMDS]
    # the symbolic models of data/ (every parameter a symbol): Jordan-method minimal
    # realization over Q(p) (> 300 s before its simple factors were realized by their
    # restriction; goal 30 s)
    rows += [(name, "minreal-jordan", 30.0) for name in DATA_FILES]
    return rows


# symbolic data files (path under the repository root, extra CLI arguments)
DATA_FILES = {
    "yaw-plane": ("data/models/yaw-plane.toml", []),
    "st-front": ("data/scb/single-track-front.json", []),
    "st-rear": ("data/scb/single-track-rear.json", []),
}
DATA_CMDS = {"minreal-jordan": ["minreal", "--method", "jordan"]}


def exe_path():
    return Path(os.environ.get("EXACTLTI_EXE", TARGET / "release" / "exactlti"))


def run_cli(build=True):
    if build and not os.environ.get("EXACTLTI_EXE"):
        subprocess.run(["cargo", "build", "--release"], cwd=ROOT, check=True,
                       capture_output=True)
    exe = exe_path()
    paths = qp_scale.write(TARGET / "qp-scale")
    rows = []
    for name, cmd, goal in cli_cases():
        if name in DATA_FILES:
            path, extra = DATA_FILES[name]
            argv = [str(exe)] + DATA_CMDS[cmd] + [str(ROOT / path)] + extra + [
                "--format", "json", "--max-seconds", "60"]
            secs, mb, rc = qp_scale.timed(argv, 60)
            rows.append((name, cmd, secs, mb, goal, rc, None))
            continue
        argv = [str(exe)] + qp_scale.ALL_CMDS[cmd] + [str(paths[name]), "--format", "json",
                                                      "--max-seconds", "60"]
        if name == "dense8x3":
            med, best, mb, rc = cli_wall(argv)
            rows.append((name, cmd, med / 1e3, mb, goal, rc, best / 1e3))
            continue
        secs, mb, rc = qp_scale.timed(argv, 60)
        rows.append((name, cmd, secs, mb, goal, rc, None))
    return rows


def dense_table(exe):
    """issue 25 item 4: dense n x n, n = 4..10, q = 2, 3 (CLI median vs SymPy median)."""
    paths = qp_scale.write(TARGET / "qp-scale")
    cases = []
    for n in range(4, 11):
        for q in (2, 3):
            body = qp_scale.dense(n, q)
            cases.append([f"dense{n}x{q}", str(n), ";".join(e for r in body["A"] for e in r)])
    sy = sympy_times(cases, ground_types=("flint",))["flint"]
    print("# dense n x n over Q(a, b[, c]): release CLI (median of", CLI_REPS,
          "blocking runs, ms) vs SymPy DomainMatrix (flint, median ms); ratio = SymPy / CLI")
    print(f"{'case':10} " + " ".join(f"{op + ' CLI':>13} {'SymPy':>9} {'ratio':>7}"
                                      for op in ("charpoly", "det", "rref")))
    for c in cases:
        cells = []
        for op in ("charpoly", "det", "rref"):
            argv = [str(exe), "linalg", op, str(paths[c[0]]), "--format", "json",
                    "--max-seconds", "60"]
            med, _, _, rc = cli_wall(argv, reps=7)
            s = sy.get(f"{c[0]} {op}")
            r = f"{s / med:6.1f}x" if s and rc == 0 else f"{'-':>7}"
            cells.append(f"{med:13.2f} {s or float('nan'):9.2f} {r}")
        print(f"{c[0]:10} " + " ".join(cells), flush=True)


def dense_cli_case():
    """dense8x3 of scripts/qp_scale.py as a bench case line (name, n, entries)."""
    body = qp_scale.dense(8, 3)
    return ["cli dense8x3", "8", ";".join(e for row in body["A"] for e in row)]


def main():
    ensure_venv()
    if "--dense-table" in sys.argv:
        print("load average:", " ".join(f"{x:.2f}" for x in os.getloadavg()))
        dense_table(exe_path())
        return
    # --cli-only: no `cargo bench` and no build (the release binary as it is)
    cli_only = "--cli-only" in sys.argv
    ours, cases = ({}, []) if cli_only else run_ours()
    all_cases = cases + [dense_cli_case()]
    sy = sympy_times(all_cases)
    fl = flint_times(all_cases)
    print("# Q(p) matrices: median wall times in ms (same matrices; ratio = other / exactlti)")
    print(f"{'case':20} {'exactlti':>9} {'SymPy(flint)':>13} {'ratio':>7} "
          f"{'SymPy(python)':>14} {'ratio':>7} {'fmpz_mpoly':>11} {'ratio':>7}")
    print("-" * 96)
    fmt = lambda o, t: f"{t / o:6.1f}x" if (o and t) else f"{'-':>7}"
    for c in all_cases:
        for op in ("charpoly", "det", "rref"):
            name = f"{c[0]} {op}"
            o = ours.get(name)
            f, p, q = sy["flint"].get(name), sy["python"].get(name), fl.get(name)
            print(f"{name:20} {o or float('nan'):9.3f} {f or float('nan'):13.3f} {fmt(o, f)} "
                  f"{p or float('nan'):14.3f} {fmt(o, p)} {q or float('nan'):11.3f} {fmt(o, q)}")
    print("SymPy", sy["python"]["version"], "DomainMatrix over", sy["python"]["domain"],
          "| python-flint", fl.get("version", "-"))
    print()
    print("# release CLI (files of scripts/qp_scale.py; `--format json`): dense8x3 linalg the",
          f"median (best) of {CLI_REPS} runs timed around a blocking wait, SymPy/CLI = SymPy's",
          "median / the CLI's median; the other rows one run under /usr/bin/time")
    print("load average:", " ".join(f"{x:.2f}" for x in os.getloadavg()), "| exe:", exe_path())
    print(f"{'case':10} {'command':20} {'wall s':>7} {'max RSS MB':>11} {'goal s':>7} "
          f"{'goal/time':>9} {'SymPy/CLI':>9} {'exit':>5}")
    for name, cmd, secs, mb, goal, rc, best in run_cli(build=not cli_only):
        g = f"{goal:7.1f}" if goal else f"{'-':>7}"
        r = f"{goal / secs:8.1f}x" if goal and secs > 0 else f"{'-':>9}"
        op = cmd.removeprefix("linalg-")
        symp = sy["flint"].get(f"cli dense8x3 {op}") if name == "dense8x3" else None
        sr = f"{symp / (secs * 1e3):8.1f}x" if symp and secs > 0 else f"{'-':>9}"
        extra = f"  (best {best * 1e3:.2f} ms)" if best else ""
        print(f"{name:10} {cmd:20} {secs:7.4f} {mb:11.1f} {g} {r} {sr} {rc:5d}{extra}")


if __name__ == "__main__":
    main()
