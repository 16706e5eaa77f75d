"""``minreal(method="jordan")`` on every field a system can be over (issue 23, the front
door): Q, Q(sqrt 2), Q(i) and Q(p) all go through the library's one entry point
``realization::minimal(sys, MinrealMethod::Jordan)``, as the command line's ``minreal
--method jordan`` does. Each result is re-checked here in SymPy, independently of the
library: its order is the McMillan degree (the Kalman minimal realization's order) and its
Markov parameters ``C A^k B`` and ``D`` equal the original system's."""

import pytest

import exactlti

sympy = pytest.importorskip("sympy")

a = sympy.Symbol("a")

# each system has modes that are not excited or not seen: the McMillan degree is below n
CASES = {
    # a complex pair -1 +- i (the real modal form over Q), -3 unobservable, -4 uncontrollable
    "QQ": (
        [[0, 1, 0, 0], [-2, -2, 0, 0], [0, 0, -3, 0], [0, 0, 0, -4]],
        [[0], [1], [1], [0]],
        [[1, 0, 0, 1]],
        {},
        2,
    ),
    # a 2x2 Jordan block at sqrt(2) (entries in Q(sqrt 2)), -1 unobservable
    "QQ(sqrt(2))": (
        [["sqrt(2)", 1, 0], [0, "sqrt(2)", 0], [0, 0, -1]],
        [[0], [1], [1]],
        [[1, 0, 0]],
        {},
        2,
    ),
    # a complex matrix: eigenvalues i, -1, 2 (2 uncontrollable)
    "QQ(i)": (
        [["i", 0, 0], [1, -1, 0], [0, 0, 2]],
        [[1], [0], [0]],
        [[1, 1, "1 + i"]],
        {},
        2,
    ),
    # symbolic: -a and -1 excited and seen, -2 not excited (order 2 where a != 1)
    "QQ(a)": (
        [["-a", 0, 0], [0, -1, 0], [0, 0, -2]],
        [[1], [1], [0]],
        [[1, 1, 1]],
        {"a": None},
        2,
    ),
}


def markov_sympy(A, B, C, count):
    out, M = [], B
    for _ in range(count):
        out.append(C * M)
        M = A * M
    return out


def equal(X, Y):
    return all(sympy.simplify(sympy.cancel(x - y)) == 0 for x, y in zip(X, Y)) and X.shape == Y.shape


@pytest.mark.parametrize("name", sorted(CASES))
def test_jordan_minreal_on_every_field(name):
    A, B, C, params, degree = CASES[name]
    G = exactlti.ss(A, B, C, params=params or None)
    assert G.is_symbolic == bool(params)
    if not params:
        assert (G.field == "QQ") == (name == "QQ")
    r = G.minreal(method="jordan")
    assert r.method == "jordan" and r.verified
    # order = McMillan degree, from an independent method (the Kalman decomposition)
    kalman = G.minreal()
    assert kalman.nstates == degree < G.nstates
    order = r.nstates
    assert order == degree
    if r.system is None:
        # the modal form (over a field with certified eigenvalues): values in number fields
        Am, Bm, Cm, Dm = (getattr(r, k).to_sympy() for k in "ABCD")
        assert r.stages[0] == G.nstates and r.stages[-1] == degree
    else:
        Am, Bm, Cm, Dm = r.to_sympy()
    assert Am.shape == (degree, degree) and Bm.shape == (degree, 1) and Cm.shape == (1, degree)
    # Markov parameters C A^k B equal for k < n + r (Cayley-Hamilton on the difference
    # system), and D equal, recomputed in SymPy from both sides' exact entries
    A0, B0, C0, D0 = G.to_sympy()
    k = G.nstates + degree
    for got, want in zip(markov_sympy(Am, Bm, Cm, k), markov_sympy(A0, B0, C0, k)):
        assert equal(got, want)
    assert equal(Dm, D0)
    # a wrong realization is caught by the same comparison (the test can fail)
    bad = markov_sympy(Am, 2 * Bm, Cm, k)
    assert not all(equal(x, y) for x, y in zip(bad, markov_sympy(A0, B0, C0, k)))


def test_jordan_minreal_over_qp_keeps_the_conditions():
    A, B, C, params, _ = CASES["QQ(a)"]
    r = exactlti.ss(A, B, C, params=params).minreal(method="jordan")
    # the modes -a and -1 merge at a = 1 (the order drops there)
    assert any(sympy.expand(c - (a - 1)) == 0 or sympy.expand(c + (a - 1)) == 0
               for c in r.conditions.to_sympy())


def test_the_method_name_is_parsed_by_the_api():
    G = exactlti.ss([[-1]], [[1]], [[1]])
    with pytest.raises(ValueError, match="unknown method 'magic'"):
        G._core.minreal("magic", None)
    with pytest.raises(ValueError, match="kalman, rosenbrock, ho-kalman, jordan, era"):
        G._core.minreal("magic", None)
    for m in ("kalman", "rosenbrock", "ho-kalman", "jordan"):
        assert G._core.minreal(m, None)["method"] == m


@pytest.mark.parametrize("name", ["QQ", "QQ(sqrt(2))", "QQ(i)"])
def test_poles_on_every_numeric_field_through_the_api(name):
    # the api's eigenvalues (as pzmap): prod (s - r) over the poles is det(sI - A)
    A, B, C, _, _ = CASES[name]
    G = exactlti.ss(A, B, C)
    s = sympy.Symbol("s")
    roots = [r.to_sympy() for r in G.poles()]
    assert len(roots) == G.nstates
    A0 = G.to_sympy()[0]
    want = (s * sympy.eye(G.nstates) - A0).det()
    got = sympy.prod([s - r for r in roots])
    assert sympy.expand(got - want) == 0
    assert sympy.expand(got * (s - 7) - want) != 0


@pytest.mark.parametrize("name", ["QQ", "QQ(sqrt(2))", "QQ(i)"])
def test_check_is_the_command_lines_check(name):
    A, B, C, _, degree = CASES[name]
    G = exactlti.ss(A, B, C)
    c = G.check()
    assert c.agree and c.report["agree"] is True
    items = {i["what"]: i for i in c}
    assert items["mcmillan_degree"]["exact"] == degree
    assert items["controllability_rank"]["exact"] == G.ctrb().to_sympy().rank(simplify=True)
    assert set(items) == set(
        "mcmillan_degree" if k == "minreal_order" else k for k in c.report["comparisons"]
    )
