"""``mnf()`` and ``modes()`` on every field a system can be over (issue 23, the front door):
Q, Q(sqrt 2), Q(i) and Q(a) go through the same library functions as the command line's
``mnf`` and ``modes`` (``mechanical_normal_form`` over the system's field; the modal table
over the field of certified eigenvalues, the modes as formulas over Q(p)). Each result is
re-checked here in SymPy, independently of the library:

* MNF: ``T A T^-1 = A~`` has the normal form's shape ``[[0, I], [-K, -L]]`` (mass ``I``),
  ``T B = B~ = [0; F]``, and the Markov parameters of ``(A~, B~, C~ = C T^-1)`` equal the
  system's;
* modes: the multiplicities add up to ``n`` (a complex pair of a real matrix counted twice),
  and each mode's eigenvalue (its ``approx``) is a root of ``det(sI - A)`` and of its
  ``minpoly``; over Q(p) the product of the factors to their multiplicities is
  ``det(sI - A)``."""

import pytest

import exactlti
from test_minreal_fields import markov_sympy  # C A^k B in SymPy, one helper for both files

sympy = pytest.importorskip("sympy")

s = sympy.Symbol("s")
a = sympy.Symbol("a")

# x1' = x2, x2' = -k x1 - c x2 + u: a mass-spring-damper in first-order form, written in
# coordinates that are not already mechanical (x2 mixed with x1)
CASES = {
    "QQ": ({"k": "2", "c": "3"}, {}),
    "QQ(sqrt(2))": ({"k": "sqrt(2)", "c": "1"}, {}),
    "QQ(i)": ({"k": "i", "c": "2"}, {}),
    "QQ(a)": ({"k": "a", "c": "1"}, {"a": None}),
}


def system(name):
    v, params = CASES[name]
    k, c = v["k"], v["c"]
    # A = P [[0, 1], [-k, -c]] P^-1 with P = [[1, 0], [1, 1]]
    A = [["-1", "1"], [f"-1 - ({k}) + ({c})", f"1 - ({c})"]]
    B = [[0], [1]]
    C = [[1, 0]]
    return exactlti.ss(A, B, C, params=params or None)


def zero(M):
    return all(sympy.simplify(sympy.cancel(x)) == 0 for x in M)


@pytest.mark.parametrize("name", sorted(CASES))
def test_mnf_identities_on_every_field(name):
    G = system(name)
    A, B, C, _ = G.to_sympy()
    n = A.shape[0]
    r = G.mnf()
    assert r.exists and r.verified
    T, At, Bt = (getattr(r, k).to_sympy() for k in ("T", "A_tilde", "B_tilde"))
    assert T.shape == (n, n) and sympy.simplify(T.det()) != 0
    # T A = A~ T and T B = B~ (the similarity), recomputed
    assert zero(T * A - At * T)
    assert zero(T * B - Bt)
    # the normal form's shape: [[0, I], [-K, -L]], B~ = [0; F] with the reported K, L, F
    h = n // 2
    K, L, F = (getattr(r, k).to_sympy() for k in ("K", "L", "F"))
    assert zero(At[:h, :h]) and zero(At[:h, h:] - sympy.eye(h))
    assert zero(At[h:, :h] + K) and zero(At[h:, h:] + L)
    assert zero(Bt[:h, :]) and zero(Bt[h:, :] - F)
    # the Markov parameters of the normal form equal the system's
    Ct = C * T.inv()
    for got, want in zip(markov_sympy(At, Bt, Ct, 2 * n), markov_sympy(A, B, C, 2 * n)):
        assert zero(got - want)


@pytest.mark.parametrize("name", ["QQ", "QQ(sqrt(2))", "QQ(i)"])
def test_modes_on_every_numeric_field(name):
    G = system(name)
    A = G.to_sympy()[0]
    n = A.shape[0]
    chi = sympy.Poly((s * sympy.eye(n) - A).det(), s)
    m = G.modes()
    assert isinstance(m, exactlti.ModalTable) and len(m) >= 1
    # each eigenvalue a root of det(sI - A) and of its minimal polynomial over Q
    count = 0
    for mode in m:
        z = complex(mode.approx)
        assert abs(complex(chi.eval(z))) < 1e-9 * (1 + abs(z)) ** n
        mp = sympy.Poly(sympy.sympify(mode.minpoly.replace("^", "**")), *sympy.sympify(
            mode.minpoly.replace("^", "**")).free_symbols)
        assert abs(complex(mp.eval(z))) < 1e-9 * (1 + abs(z)) ** mp.degree()
        # a real matrix lists a complex pair once
        pair = 2 if (name != "QQ(i)" and abs(z.imag) > 0) else 1
        count += pair * mode.multiplicity
    assert count == n


def test_modes_over_qp_factor_the_charpoly():
    G = system("QQ(a)")
    A = G.to_sympy()[0]
    n = A.shape[0]
    chi = sympy.expand((s * sympy.eye(n) - A).det())
    r = G.modes()
    prod, deg = 1, 0
    for mode in r["modes"]:
        g = sympy.sympify(mode["factor"].replace("^", "**"), locals={"s": s, "a": a})
        e = mode["multiplicity"]
        prod *= g**e
        deg += sympy.degree(g, s) * e
    assert deg == n
    assert sympy.simplify(sympy.cancel(prod - chi)) == 0
