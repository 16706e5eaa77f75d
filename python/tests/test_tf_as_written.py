"""exactlti.tf keeps what the user wrote (issue 28 item 4), as python-control's tf does:
poles() of (s+1)/((s+1)(s+2)) lists -1 and -2, minreal() cancels to one state. The
as-written realization's characteristic polynomial is the product of the written column
denominators, its transfer matrix and Markov parameters equal the minimal one's exactly,
and its poles equal python-control's TransferFunction.poles() (per-input common
denominators) on random SISO and MIMO matrices with planted common factors."""

import random

import pytest

import exactlti

sympy = pytest.importorskip("sympy")
s = sympy.Symbol("s")


def test_the_issue_example():
    G = exactlti.tf("(s+1)/((s+1)*(s+2))")
    assert G.nstates == 2
    assert sorted(str(p) for p in G.poles()) == ["-1", "-2"]
    M = G.minreal()
    assert M.nstates == 1 and [str(p) for p in M.poles()] == ["-2"]
    assert exactlti.tf("(s+1)/((s+1)*(s+2))", realize="minimal").nstates == 1
    # the transfer matrix is the same exact function either way
    assert (G.tf().to_sympy() - M.tf().to_sympy()).applyfunc(sympy.cancel).is_zero_matrix
    with pytest.raises(ValueError, match="realize"):
        exactlti.tf("1/(s+1)", realize="both")


def _charpoly(G):
    A = G.to_sympy()[0]
    # over QQ like the lcm of the written denominators (a static gain: the polynomial 1)
    p = (s * sympy.eye(A.shape[0]) - A).det() if A.shape[0] else sympy.Integer(1)
    return sympy.Poly(p, s, domain="QQ")


def _markov(G, k):
    return [sympy.Matrix(m.to_sympy()) for m in G.markov(k)] if G.nstates else []


def _random_entry(rng):
    """num/den as coefficient lists with a planted common factor (s - r)."""
    dd = rng.randint(0, 2)
    den = [1] + [rng.randint(-3, 3) for _ in range(dd)]
    num = [rng.randint(-3, 3) for _ in range(rng.randint(1, dd + 1))]
    if not any(num):
        num[-1] = 1
    if rng.random() < 0.5:
        r = rng.randint(-2, 2)
        mul = lambda p: [a - r * b for a, b in zip(p + [0], [0] + p)]
        num, den = mul(num), mul(den)
    return num, den


def test_against_python_control_poles_and_the_minimal_realization():
    control = pytest.importorskip("control")
    np = pytest.importorskip("numpy")
    rng = random.Random(28)
    for trial in range(30):
        p, m = (1, 1) if trial < 12 else (rng.randint(1, 2), rng.randint(1, 3))
        ent = [[_random_entry(rng) for _ in range(m)] for _ in range(p)]
        num = [[e[0] for e in row] for row in ent]
        den = [[e[1] for e in row] for row in ent]
        G = exactlti.tf(num, den)
        Gm = exactlti.tf(num, den, realize="minimal")
        # exact: det(sI - A) = prod over columns of lcm of the written denominators
        poly = lambda c: sympy.Poly(c, s)
        want = sympy.Poly(1, s)
        for j in range(m):
            col = sympy.Poly(1, s)
            for i in range(p):
                col = sympy.lcm(col, poly(den[i][j]))
            want = want * col.monic()
        assert _charpoly(G) == want.set_domain(sympy.QQ), (num, den)
        # the same transfer matrix and Markov parameters as the minimal realization
        assert (G.tf().to_sympy() - Gm.tf().to_sympy()).applyfunc(sympy.cancel).is_zero_matrix
        k = 2 * (G.nstates + Gm.nstates) + 2
        if G.nstates and Gm.nstates:
            assert _markov(G, k) == _markov(Gm, k)
        assert G.minreal().nstates == Gm.nstates == G.tf().mcmillan_degree
        # the float side: python-control's poles of the same TransferFunction
        T = control.tf(num, den)
        theirs = np.sort_complex(np.asarray(T.poles(), dtype=complex))
        ours = np.sort_complex(np.array([complex(z.approx()) for z in G.poles()]))
        assert len(theirs) == len(ours), (num, den, theirs, ours)
        # repeated roots in floats are accurate to about sqrt(eps)
        assert np.allclose(ours, theirs, atol=1e-5), (num, den, theirs, ours)
