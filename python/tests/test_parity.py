"""Parity of the two front ends: every operation of the command line, over Q, Q(i),
Q(sqrt 2) and Q(k, m) (a standard and a descriptor system over each), run through the
`exactlti` binary and through the Python package, must give the same key figures (orders,
block sizes, McMillan degrees, SCB dimensions, zero polynomials, ...) or the same refusal.

Cells that are not questions (a numeric plot of a system with symbols, a real Jordan form
of a non-real matrix, ...) are listed in NOT_QUESTIONS with the reason, and the refusal
must say that reason. The test prints the table of answered cells (`pytest -s`), and the
table of the front ends before the api layer (the CLI binary of $EXACTLTI_BEFORE_BIN and the
Python package's own per-method code, `_core.*`) when that binary is given.
"""

import json
import os
import shutil
import subprocess
import sys

import pytest

import exactlti
from exactlti import _core

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "parity")

FIELDS = ["q", "qi", "qsqrt2", "qp"]
FILES = [f for base in FIELDS for f in (base, base + "_descriptor")]

# operation name -> command-line arguments after the file
OPS = {
    "jordan": ["jordan"],
    "jordan --real": ["jordan", "--real"],
    "minreal": ["minreal"],
    "minreal rosenbrock": ["minreal", "--method", "rosenbrock"],
    "minreal ho-kalman": ["minreal", "--method", "ho-kalman"],
    "minreal jordan": ["minreal", "--method", "jordan"],
    "minreal era": ["minreal", "--method", "era"],
    "minreal --descriptor": ["minreal", "--descriptor"],
    "standard": ["standard"],
    "scb": ["scb"],
    "mnf": ["mnf"],
    "zeros": ["zeros"],
    "pencil": ["pencil"],
    "ctrb": ["ctrb"],
    "obsv": ["obsv"],
    "tf": ["tf"],
    "modes": ["modes"],
    "freqresp": ["freqresp", "--points", "5"],
    "pzmap": ["pzmap"],
    "step": ["step", "--points", "5", "--to", "1"],
    "impulse": ["impulse", "--points", "5", "--to", "1"],
    "check": ["check"],
    "linalg rank": ["linalg", "rank"],
    "linalg charpoly": ["linalg", "charpoly"],
    "analyze": ["analyze"],
    "bifurcations": ["bifurcations"],
    "sweep": ["sweep", "--param", "c", "--from", "1", "--to", "2", "--points", "3"],
    "critical": ["critical", "--param", "c", "--from", "0", "--to", "4"],
}

# (operation, file) -> the reason the cell is not a question (its refusal says it)
NUMBERS = "needs numbers"
NOT_QUESTIONS = {}
for _f in ("qp", "qp_descriptor"):
    for _op in ("minreal era", "freqresp", "pzmap", "step", "impulse", "check", "sweep",
                "critical"):
        NOT_QUESTIONS[(_op, _f)] = NUMBERS
for _f in FILES:
    if not _f.startswith("qp"):
        NOT_QUESTIONS[("bifurcations", _f)] = "needs symbolic parameters"
for _f in ("qi", "qi_descriptor"):
    NOT_QUESTIONS[("jordan --real", _f)] = "is not real"

# (operation, file) -> questions this version does not answer yet, with the reason given
# (none: `critical` over Q(i) and Q(sqrt 2) is computed over K(v), tests/critical_fields.rs)
NOT_YET = {}


def _bin():
    env = os.environ.get("EXACTLTI_BIN")
    if env:
        return env
    # the newest build of this checkout (a stale release binary must not answer for the code)
    built = [os.path.join(ROOT, p) for p in ("target/release/exactlti", "target/debug/exactlti")]
    built = [q for q in built if os.path.exists(q)]
    if built:
        return max(built, key=os.path.getmtime)
    return shutil.which("exactlti")


BIN = _bin()


def cli(binary, file, op):
    argv = OPS[op]
    if argv[0] == "linalg":
        argv = argv[:2] + [file] + argv[2:]
    else:
        argv = argv[:1] + [file] + argv[1:]
    p = subprocess.run(
        [binary, "--format", "json", "--max-seconds", "120"] + argv,
        capture_output=True,
        text=True,
    )
    if p.returncode in (0, 3):
        return True, json.loads(p.stdout)
    return False, p.stderr.strip().replace("exactlti: ", "", 1)


def python(file, op):
    argv = OPS[op]
    try:
        G = exactlti.load(file)
        r = G.run(argv[0], *argv[1:], max_seconds=120)
    except Exception as e:  # the refusal, compared with the command line's
        return False, str(e)
    return True, dict(r)


FIGURE_KEYS = {
    "n", "order", "original_order", "mcmillan_degree", "dims", "blocks", "chains",
    "zero_polynomial", "charpoly", "rank", "normal_rank", "indices", "controllability_indices",
    "observability_indices", "exists", "pole_polynomial", "finite_order", "infinite_order",
    "irreducible_order", "multiplicity", "algebraic_multiplicity", "minpoly", "field",
    "conditions", "verified", "agree", "nstates", "minimal", "title",
}


def figures(v, path=""):
    """The key figures of a report: integers, booleans and the named exact texts."""
    out = {}
    if isinstance(v, dict):
        for k, x in v.items():
            if k.endswith("_approx"):
                continue
            p = path + "/" + k
            if k in FIGURE_KEYS and not isinstance(x, (dict, list)):
                out[p] = x
            elif isinstance(x, (dict, list)):
                out.update(figures(x, p if k not in ("approx",) else path))
            elif isinstance(x, (int, bool)):
                out[p] = x
    elif isinstance(v, list):
        for i, x in enumerate(v):
            if isinstance(x, (int, bool)) and not isinstance(x, float):
                out[path + "[%d]" % i] = x
            else:
                out.update(figures(x, path + "[%d]" % i))
    return out


CELLS = [(op, f) for op in OPS for f in FILES]


@pytest.mark.skipif(BIN is None, reason="no exactlti binary (cargo build)")
@pytest.mark.parametrize("op,f", CELLS, ids=["%s|%s" % c for c in CELLS])
def test_parity(op, f):
    path = os.path.join(DATA, f + ".json")
    c_ok, c = cli(BIN, path, op)
    p_ok, p = python(path, op)
    assert c_ok == p_ok, (c, p)
    if c_ok:
        assert figures(c) == figures(p)
    else:
        assert c == p, (c, p)
        assert "::" not in p
    why = NOT_QUESTIONS.get((op, f)) or NOT_YET.get((op, f))
    if why is not None:
        assert not c_ok, "listed as unanswered but answered: %s" % why
        assert why in c, (why, c)
    else:
        assert c_ok, "a question not answered: %s" % c


def _legacy(G, op):
    """The Python package's own per-method code before the api layer (`_core.*`)."""
    k = G._core
    if op == "jordan":
        return k.jordan(False, 120)
    if op == "jordan --real":
        return k.jordan(True, 120)
    if op.startswith("minreal") and op.split()[-1] in ("minreal", "rosenbrock", "ho-kalman", "jordan"):
        m = {"minreal": "kalman"}.get(op.split()[-1], op.split()[-1])
        return k.minreal(m, 120)
    table = {"scb": k.scb, "mnf": k.mnf, "zeros": k.zeros, "modes": k.modes, "tf": k.tf,
             "check": k.check}
    if op in table:
        d = table[op](120)
        if op == "zeros" and not G.is_symbolic and d.get("roots") is None:
            raise exactlti.UnsupportedError("roots over this field")
        return d
    if op == "freqresp":
        return k.freqresp([1.0])
    if op in ("sweep", "critical"):
        path = G._core.source[0]
        if op == "sweep":
            return exactlti.sweep(path, "c", [1.0, 2.0])
        return exactlti.critical(path, "c", "0", "4", 120)
    raise exactlti.UnsupportedError("no such method")


def table(answer):
    rows = []
    for op in OPS:
        rows.append((op, [answer(op, f) for f in FILES]))
    return rows


def _print(title, rows):
    n = sum(sum(1 for x in r if x) for _, r in rows)
    total = sum(len(r) for _, r in rows)
    print("\n%s: %d of %d cells answered by both front ends" % (title, n, total))
    print("%-22s" % "" + " ".join("%-6s" % f.replace("_descriptor", "+E")[:6] for f in FILES))
    for op, r in rows:
        print("%-22s" % op + " ".join("%-6s" % ("yes" if x else "-") for x in r))
    return n


@pytest.mark.skipif(BIN is None, reason="no exactlti binary (cargo build)")
def test_answered_table():
    def after(op, f):
        path = os.path.join(DATA, f + ".json")
        return cli(BIN, path, op)[0] and python(path, op)[0]

    n_after = _print("after (api)", table(after))
    before_bin = os.environ.get("EXACTLTI_BEFORE_BIN")
    if before_bin and os.path.exists(before_bin):
        def before(op, f):
            path = os.path.join(DATA, f + ".json")
            if not cli(before_bin, path, op)[0]:
                return False
            try:
                _legacy(exactlti.load(path), op)
                return True
            except Exception:
                return False

        n_before = _print("before (CLI of %s, Python per-method code)" % before_bin, table(before))
        assert n_after >= n_before
    print("not questions: %d cells; questions not answered yet: %d cells (%s)" % (
        len(NOT_QUESTIONS), len(NOT_YET), "; ".join(sorted(set(NOT_YET.values())))))
    assert n_after == len(CELLS) - len(NOT_QUESTIONS) - len(NOT_YET)
