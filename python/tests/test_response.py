"""Free response in closed form and modes ranked by contribution (issue 27 item 5, issue 25
free response in symbols): exact identities re-checked in SymPy."""

from fractions import Fraction

import pytest

import exactlti

sympy = pytest.importorskip("sympy")
t = sympy.Symbol("t")


def closed_form(r, n):
    """x(t) = sum t^k e^(s t) g from the report's exact strings, in SymPy."""
    loc = {"i": sympy.I, "sqrt": sympy.sqrt}
    x = sympy.zeros(n, 1)
    for term in r["terms"]:
        s = sympy.sympify(term["eigenvalue"].replace("^", "**"), locals=loc)
        g = term["g"]
        g = [row[0] if isinstance(row, list) else row for row in g]
        g = sympy.Matrix([sympy.sympify(str(v).replace("^", "**"), locals=loc) for v in g])
        x += t ** term["power"] * sympy.exp(s * t) * g
    return x


def test_free_response_over_q_solves_the_ode():
    A = [[0, 1], [-2, -3]]
    G = exactlti.ss(A, [[0], [1]], [[1, 0]], [[0]])
    r = G.free_response([1, Fraction(1, 2)], times=[0, 1])
    assert r.verified
    x = closed_form(r, 2)
    assert sympy.simplify(x.diff(t) - sympy.Matrix(A) * x) == sympy.zeros(2, 1)
    assert sympy.simplify(x.subs(t, 0) - sympy.Matrix([1, sympy.Rational(1, 2)])) == sympy.zeros(2, 1)
    assert r["values"][0]["x"] == pytest.approx([1.0, 0.5], abs=1e-14)
    want = sympy.exp(sympy.Matrix(A) * t) * sympy.Matrix([1, sympy.Rational(1, 2)])
    got = [float(v) for v in x.subs(t, 1)]
    assert r["values"][1]["x"] == pytest.approx(got, rel=1e-12)
    assert got == pytest.approx([float(v) for v in want.subs(t, 1)], rel=1e-12)


def test_free_response_in_symbols():
    # a double integrator from (a, b): x = (a + b t, b)
    G = exactlti.ss([[0, 1], [0, 0]], [[0], [1]], [[1, 0]], [[0]])
    r = G.free_response(["a", "b"])
    assert r.verified and r.field is not None
    x = closed_form(r, 2)
    a, b = sympy.symbols("a b")
    assert sympy.simplify(x - sympy.Matrix([a + b * t, b])) == sympy.zeros(2, 1)
    with pytest.raises(ValueError):
        G.free_response([1, 2, 3])


def test_contributions_and_truncation():
    G = exactlti.ss(
        [[-1, 0, 0], [0, -2, 0], [0, 0, -3]], [[1], [1], [0]], [[1, "1/10", 1]], [[0]]
    )
    r = G.contributions(keep=1)
    assert r.verified
    assert [m["h2_squared"] for m in r["modes"]] == ["1/2", "1/400", "0"]
    tr = r["truncation"]
    assert tr["order"] == 1 and tr["error_h2_squared"] == "1/400"
    # the error (1/10)/(s+2): its H2^2 = int_0^inf (e^(-2t)/10)^2 dt
    h2 = sympy.integrate((sympy.exp(-2 * t) / 10) ** 2, (t, 0, sympy.oo))
    assert sympy.Rational(tr["error_h2_squared"]) == h2
    assert r.get("truncation") and "truncation" not in G.contributions()
