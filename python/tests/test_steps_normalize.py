"""Issue 27 item 2 from Python: ``G.steps("jordan", normalize=...)`` (the papers'
normalisations of the chains) and ``G.steps("minreal", descriptor=True)``, with the
identities recomputed here in SymPy from the steps' data."""

import os

import pytest
import sympy

import exactlti

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def mat(m):
    return sympy.Matrix([[sympy.sympify(str(x).replace("^", "**")) for x in r] for r in m.tolist()])


def test_paper_eq_32_orthogonal_unit_chains():
    # the minimal-realization paper's A_2 (eq. 29): chains of 0 and -1, each of length 2
    A = [[0, 0, 1, 0], [0, 0, 0, 1], [-1, 0, -2, 0], [0, 0, 0, 0]]
    G = exactlti.ss(A, [[0], [0], [0], [1]], [[1, 0, 0, 0]])
    d = G.steps("jordan", normalize="paper")
    assert d.verified
    norm = d.find("normalization")
    assert len(norm) == 2
    As = sympy.Matrix(A)
    thetas = {s.part: sympy.sympify(s["theta"]) for s in d.find("kernel_sequence")}
    closed = 0
    for s in norm:
        V = mat(s["Vn"])
        N = As - thetas[s.part] * sympy.eye(4)
        x, y = V[:, 0], V[:, 1]
        assert N * x == sympy.zeros(4, 1) and N * y == x  # a chain
        assert (y.T * x)[0] == 0  # eq. 31: Y orthogonal to X
        n = sympy.sympify(str(s["n2"]))
        assert (x.T * x)[0] == n
        if "root" in s.objects:
            assert n == 1
        else:
            closed += 1  # the unit chain is V / sqrt(n), sqrt(2) not rational
            assert sympy.sqrt(n).is_rational is False
    assert closed == 1


def test_normalize_is_refused_outside_jordan():
    G = exactlti.ss([[0, 1], [-2, -3]], [[0], [1]], [[3, 1]], [[0]])
    with pytest.raises(ValueError):
        G.steps("scb", normalize="unit")
    with pytest.raises(ValueError):
        G.steps("jordan", descriptor=True)


def test_minreal_descriptor_steps():
    G = exactlti.ss([[0, 1], [-2, -3]], [[0], [1]], [[3, 1]], [[0]])
    d = G.steps("minreal", descriptor=True)
    assert d.verified
    assert d.kinds()[-1] == "minimal_descriptor"
    last = d.find("minimal_descriptor")[0]
    E, A, B, C = (mat(last[k]) for k in ("E", "A", "B", "C"))
    s = sympy.Symbol("s")
    g = sympy.simplify((C * (s * E - A).inv() * B)[0])
    assert sympy.simplify(g - (s + 3) / (s**2 + 3 * s + 2)) == 0
