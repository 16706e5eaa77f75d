"""Exact values arrive as values (issue 23 item 4): the Rust layer hands every exact number
over as its structure (``python/src/values.rs``) and Python builds SymPy from it; no report
text is parsed back anywhere in the package."""

import os
import re

import pytest

import exactlti

sympy = pytest.importorskip("sympy")

PKG = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "exactlti"))


def zero(M):
    return all(sympy.simplify(x) == 0 for x in M)


def test_no_report_text_is_parsed_back_in_the_package():
    # every SymPy object of the package is built from values: no sympify / parse_expr /
    # eval of text (the package has no user-input expression parser: user entries go to
    # the library's reader as text, see _convert.py)
    forbidden = re.compile(r"\b(sympify|parse_expr|S)\s*\(|\beval\s*\(")
    hits = []
    for name in sorted(os.listdir(PKG)):
        if not name.endswith(".py"):
            continue
        with open(os.path.join(PKG, name)) as f:
            for i, line in enumerate(f, 1):
                if forbidden.search(line) and not line.lstrip().startswith("#"):
                    hits.append("%s:%d: %s" % (name, i, line.strip()))
    assert hits == [], "\n".join(hits)


def test_sqrt2_eigenvalues_are_exactly_sqrt2():
    r = exactlti.jordan([[1, 1], [1, -1]])
    s2 = sympy.sqrt(2)
    assert sorted((e.to_sympy() for e in r.eigenvalues), key=float) == [-s2, s2]
    J, T, A = r.J.to_sympy(), r.T.to_sympy(), r.A.to_sympy()
    assert J == sympy.diag(*[e.to_sympy() for e in r.eigenvalues])
    assert zero(A * T - T * J) and sympy.simplify(T.det()) != 0
    # every entry of J, T lies in Q(sqrt 2): a + b*sqrt(2) with rational a, b
    for x in list(J) + list(T):
        a, b = sympy.expand(x).as_independent(s2, as_Add=True)
        assert a.is_Rational and (b == 0 or (b / s2).is_Rational)
    p = exactlti.ss([[0, 2], [1, 0]]).poles()
    assert [x.to_sympy() for x in p] == [-s2, s2]


def test_complex_and_cubic_jordan_values():
    r = exactlti.jordan([[-2, 0, 0], [0, 0, 1], [0, -2, -2]])
    assert r.J.to_sympy() == sympy.diag(-2, -1 + sympy.I, -1 - sympy.I)
    assert r.check()  # the keep-symbols form: i stays I (degree 2 is a closed form)
    assert zero(r.A.to_sympy() * r.T.to_sympy() - r.T.to_sympy() * r.J.to_sympy())
    # x^3 - 2: one real root and a complex pair, each a CRootOf of the same polynomial
    c = exactlti.jordan([[0, 0, 2], [1, 0, 0], [0, 1, 0]])
    x = sympy.Symbol("x")
    roots = {sympy.CRootOf(x**3 - 2, k) for k in range(3)}
    J = c.J.to_sympy()
    assert {J[i, i] for i in range(3)} == roots
    assert c.check()
    # with the root symbols kept, the entries are polynomials in r<k>
    Js = c.J.to_sympy(keep_symbols=True)
    assert {str(Js[i, i]) for i in range(3)} == {e.symbol for e in c.eigenvalues}


def test_jordan_over_q_sqrt2_entries_through_the_api():
    # A over Q(sqrt 2) with irrational entries: the api's field choice (as the command line)
    G = exactlti.ss([["sqrt(2)", 1], [0, "sqrt(2)"]], [[0], [1]], [[1, 0]])
    assert G.field.startswith("QQ(sqrt")
    s2 = sympy.sqrt(2)
    A = G.A.to_sympy()
    assert A == sympy.Matrix([[s2, 1], [0, s2]])
    # the command's report: J and T built from the values beside its JSON
    rep = G.jordan()
    J, T = rep.to_sympy("J"), rep.to_sympy("T")
    assert rep.verified and J == sympy.Matrix([[s2, 1], [0, s2]])
    assert zero(A * T - T * J) and T.det() != 0
    # the binding's own Jordan form goes through the same api entry points
    r = exactlti.JordanResult(G._core.jordan(False, None))
    assert r.verified and r.J.to_sympy() == J
    assert [e.to_sympy() for e in r.eigenvalues] == [s2]


def test_symbolic_tf_numerator_equals_the_independent_expression():
    c, k, m, s = sympy.symbols("c k m s")
    G = exactlti.ss([[0, 1], ["-k/m", "-c/m"]], [[0], ["1/m"]], [["k", "c"]],
                    params={"m": None, "c": None, "k": None})
    h = G.tf()[0, 0]
    # built independently: C (sI - A)^-1 B
    A = sympy.Matrix([[0, 1], [-k / m, -c / m]])
    want = (sympy.Matrix([[k, c]]) * (s * sympy.eye(2) - A).inv() * sympy.Matrix([0, 1 / m]))[0]
    assert sympy.cancel(h.to_sympy() - want) == 0
    num, den = h.num.to_sympy(), h.den.to_sympy()
    assert sympy.cancel(num / den - want) == 0
    assert num.free_symbols <= {c, k, m, s} and den.free_symbols <= {c, k, m, s}
    # the numerator's coefficients arrive as values: c*s + k up to a factor in Q(c, k, m)
    assert sympy.cancel(num / (c * s + k)).free_symbols <= {c, k, m}


def test_symbolic_values_factors_and_conditions():
    a, b, s = sympy.symbols("a b s")
    G = exactlti.ss([["-a", 1], [0, "-b"]], [[0], [1]], [[1, 0]], params={"a": None, "b": None})
    p = G.poles()
    assert sorted(p.to_sympy(), key=str) == [-a, -b]
    assert sympy.expand(p.polynomial.to_sympy() - (s + a) * (s + b)) == 0
    k, cc = sympy.symbols("k c")
    r = exactlti.jordan([[0, 1], ["-k", "-c"]], params={"k": None, "c": None})
    (e,) = r.eigenvalues
    var = sympy.Symbol(r.var)
    assert sympy.expand(e.factor_sympy() - (var**2 + cc * var + k)) == 0
    assert r.check()
    # conditions are polynomials with integer coefficients in the parameters, as listed
    G = exactlti.ss([["-a", 0], [0, -1]], [[1], [1]], [[1, 1]], params={"a": None})
    cond = G.minreal().conditions
    assert cond.to_sympy() == [a - 1]


def test_report_to_sympy_builds_matrices_from_values():
    G = exactlti.ss([[-1, 1], [0, -2]], [[0], [1]], [[1, 0]])
    W = G.gram().to_sympy("W")
    A, B = G.A.to_sympy(), G.B.to_sympy()
    assert A * W + W * A.T + B * B.T == sympy.zeros(2, 2)
    r = G.run("jordan")
    assert r.to_sympy("J") == G.jordan().J.to_sympy()
    with pytest.raises(TypeError):
        r.to_sympy("eigenvalues")


def test_descriptor_jordan_note_is_the_apis():
    G = exactlti.ss([[0, 1], [1, 1]], [[0], [1]], [[1, 0]], [[0]], E=[[1, 0], [0, 0]])
    j = G.jordan()
    assert j.infinite_blocks == [1] and j.verified
    assert j.notes[-1] == G.run("jordan")["note"]
