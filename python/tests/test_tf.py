"""Transfer functions in: exactlti.tf(...) realizes G(s) exactly, as written by default
(tests/test_tf_as_written.py) or minimally with realize="minimal"; .tf() out."""

import random
import warnings
from fractions import Fraction

import pytest

import exactlti

sympy = pytest.importorskip("sympy")
s = sympy.Symbol("s")


def same(g_exact, g_sympy):
    """The exact transfer matrix equals a SymPy matrix of rational functions."""
    d = (g_exact.to_sympy() - sympy.Matrix(g_sympy)).applyfunc(sympy.cancel)
    return d.is_zero_matrix


def realizes(G, g_sympy):
    """G's own matrices give g: C (sI - A)^-1 B + D computed in SymPy."""
    A, B, C, D = G.to_sympy()
    n = A.shape[0]
    h = C * (s * sympy.eye(n) - A).inv() * B + D if n else D
    return (h - sympy.Matrix(g_sympy)).applyfunc(sympy.cancel).is_zero_matrix


def test_siso_coefficients_python_control_idiom():
    G = exactlti.tf([1, 1], [1, 3, 2], realize="minimal")  # (s+1)/(s^2+3s+2) = 1/(s+2)
    assert G.nstates == 1 and (G.ninputs, G.noutputs) == (1, 1)
    assert realizes(G, [[1 / (s + 2)]])
    t = G.tf()
    assert t.mcmillan_degree == 1 and t.verified
    assert t[0, 0].num.coeffs == [1] and t[0, 0].den.coeffs == [2, 1]
    assert [str(p) for p in G.poles()] == ["-2"]
    assert list(G.zeros()) == []


def test_string_with_implicit_products_and_sympy_expressions():
    a = exactlti.tf("(s+1)/(s^2+3s+2)", realize="minimal")
    b = exactlti.tf("2(s + 1)/(2s^2 + 6 s + 4)", realize="minimal")
    c = exactlti.tf((s + 1) / (s**2 + 3 * s + 2), realize="minimal")
    for G in (a, b, c):
        assert same(G.tf(), [[1 / (s + 2)]]) and G.nstates == 1


def test_exact_coefficients_in_every_spelling():
    G = exactlti.tf(["0.5", Fraction(1, 3)], [1, sympy.Rational(1, 7), "1e-3"])
    t = G.tf()
    assert t.verified and t.mcmillan_degree == 2
    num = sympy.Rational(1, 2) * s + sympy.Rational(1, 3)
    den = s**2 + sympy.Rational(1, 7) * s + sympy.Rational(1, 1000)
    assert same(t, [[num / den]])
    assert realizes(G, [[num / den]])


def test_params_take_values():
    G = exactlti.tf("k/(s + a)", params={"k": 2, "a": "0.5"})
    assert same(G.tf(), [[2 / (s + sympy.Rational(1, 2))]])


def test_mimo_entries_as_text_and_pairs():
    G = exactlti.tf([["1/(s+1)", "2/(s+1)"], [([1], [1, 2]), 0]], realize="minimal")
    g = [[1 / (s + 1), 2 / (s + 1)], [1 / (s + 2), 0]]
    assert (G.noutputs, G.ninputs) == (2, 2)
    assert realizes(G, g)
    t = G.tf()
    # residues [[1, 2], [0, 0]] at -1 and [[0, 0], [1, 0]] at -2, each of rank 1
    assert t.mcmillan_degree == 2 and G.nstates == 2 and t.verified
    assert same(t, g)


def test_mimo_python_control_num_den_lists():
    num = [[[1], [1, 0]], [[2], [1]]]
    den = [[[1, 1], [1, 1]], [[1, 3], [1, 1]]]
    G = exactlti.tf(num, den)
    g = [[1 / (s + 1), s / (s + 1)], [2 / (s + 3), 1 / (s + 1)]]
    assert realizes(G, g)
    t = G.tf()
    assert same(t, g) and t.mcmillan_degree == G.nstates == 3 and t.verified


def test_random_siso_against_sympy():
    rng = random.Random(5)
    for _ in range(8):
        dn = rng.randint(1, 4)
        den = [1] + [rng.randint(-4, 4) for _ in range(dn)]
        num = [rng.randint(-4, 4) for _ in range(rng.randint(1, dn + 1))]
        if not any(num):
            num[-1] = 1
        G = exactlti.tf(num, den, realize="minimal")
        ps = lambda cs: sum(c * s ** (len(cs) - 1 - k) for k, c in enumerate(cs))
        h = sympy.cancel(ps(num) / ps(den))
        t = G.tf()
        assert same(t, [[h]]) and realizes(G, [[h]]) and t.verified
        # McMillan degree of a SISO function: the degree of its reduced denominator
        assert t.mcmillan_degree == G.nstates == sympy.degree(sympy.denom(h), s)
        assert G.minreal().nstates == G.nstates


def test_statespace_tf_has_mcmillan_degree():
    G = exactlti.ss([[-1, 0], [0, -2]], [[1], [0]], [[1, 1]], [[0]])
    t = G.tf()
    assert t.mcmillan_degree == 1 and t.verified
    assert same(t, [[1 / (s + 1)]])


def test_bad_transfer_input():
    with pytest.raises(ValueError) as e:
        exactlti.tf("(s+1)/(s^2+")
    assert str(e.value).startswith("tf: key G, row 1, column 1:")
    with pytest.raises(ValueError, match="improper"):
        exactlti.tf([1, 0, 0], [1, 1])
    with pytest.raises(ValueError, match="unknown parameter|unknown name|'k'"):
        exactlti.tf("k/(s+1)")
    with pytest.raises(ValueError, match="same shape"):
        exactlti.tf([[[1], [1]]], [[[1, 1]]])
    with pytest.raises(NotImplementedError, match="symbolic"):
        exactlti.tf(sympy.Symbol("k") / (s + 1))


def test_from_control_transfer_function():
    control = pytest.importorskip("control")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        G = exactlti.from_control(control.tf([1, 1], [1, 3, 2]))  # integers: no warning
    # python-control's TransferFunction keeps both poles (its poles() says -1, -2): so does
    # the exact system read from it; minreal cancels
    assert G.nstates == 2 and same(G.tf(), [[1 / (s + 2)]])
    assert G.minreal().nstates == 1
    with pytest.warns(exactlti.ExactnessWarning):
        H = exactlti.tf(control.tf([0.1], [1, 0.5]))
    assert same(H.tf(), [[sympy.Rational(1, 10) / (s + sympy.Rational(1, 2))]])
