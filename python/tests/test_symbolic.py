"""Symbolic parameters: systems over Q(p), results as rational functions with conditions."""

import os
import random
from fractions import Fraction

import pytest

import exactlti

sympy = pytest.importorskip("sympy")
s = sympy.Symbol("s")
ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DC_MOTOR = os.path.join(ROOT, "data", "dc-motor-lugre.json")


def zero(M):
    return M.applyfunc(sympy.cancel).is_zero_matrix


def transfer(G):
    A, B, C, D = G.to_sympy()
    n = A.shape[0]
    return (C * (s * sympy.eye(n) - A).inv() * B + D).applyfunc(sympy.cancel)


def mass_spring():
    return exactlti.ss(
        [[0, 1], ["-k/m", "-c/m"]], [[0], ["1/m"]], [[1, 0]], [[0]],
        params={"m": None, "c": None, "k": None},
    )


def dc_motor_symbolic():
    J, s0, s1, a2 = sympy.symbols("J sigma0 sigma1 alpha2")
    A = [[0, 1, 0], [0, -(a2 + s1) / J, -s0 / J], [0, 1, 0]]
    return exactlti.ss(A, [[0], [s1 / J], [-1]], [[1, 0, 0]], [[0]]), (J, s0, s1, a2)


# ---------------------------------------------------------------- building


def test_symbols_from_none_params_strings_and_sympy():
    G = mass_spring()
    assert G.is_symbolic and G.params == ("c", "k", "m") and G.field == "QQ(c, k, m)"
    c, k, m = G.symbols
    assert zero(G.A.to_sympy() - sympy.Matrix([[0, 1], [-k / m, -c / m]]))
    H = exactlti.ss([["-k/m"]], symbols=["k", "m"])
    assert H.params == ("k", "m")
    # a parameter with a value is substituted, a Symbol named as its own value stays
    kk = sympy.Symbol("k")
    W = exactlti.ss([[kk, "a"], [0, 1]], params={"a": "1/2", "k": kk})
    assert W.params == ("k",) and W.A.to_sympy()[0, 1] == sympy.Rational(1, 2)
    # numeric systems say they are not symbolic
    assert not exactlti.ss([[1]]).is_symbolic and exactlti.ss([[1]]).params == ()


def test_bad_symbolic_input_is_a_value_error():
    with pytest.raises(ValueError, match=r"ss: key A: row 1, column 1: .*'sqrt'"):
        exactlti.ss([["sqrt(m)"]], params={"m": None})
    with pytest.raises(ValueError, match="unknown symbol 'q'"):
        exactlti.ss([["q/m"]], params={"m": None})


def test_matrices_to_sympy_and_not_to_numpy():
    G = mass_spring()
    with pytest.raises(TypeError, match="symbolic"):
        G.A.to_numpy()
    assert "frac" in G.A.latex() or "m" in G.A.latex()


def test_subs_gives_values_exactly():
    G = mass_spring()
    H = G.subs(m=2, c="0.5")
    assert H.params == ("k",)
    N = H.subs({"k": Fraction(3)})
    assert not N.is_symbolic
    assert N.A.tolist() == [[0, 1], [Fraction(-3, 2), Fraction(-1, 4)]]
    assert N.B.tolist() == [[0], [Fraction(1, 2)]]
    with pytest.raises(ValueError, match="unknown parameter"):
        G.subs(q=1)


def test_load_keeps_the_files_symbols_and_takes_values():
    G = exactlti.load(DC_MOTOR)
    assert set(G.params) == {"J", "sigma0", "sigma1", "alpha2"}
    N = exactlti.load(DC_MOTOR, at={"J": "0.0023", "sigma0": 260, "sigma1": "0.6", "alpha2": "0.176"})
    assert not N.is_symbolic and N.scb().A[0, 1] == Fraction(-16003, 27)


# ---------------------------------------------------------------- operations


def test_tf_is_the_transfer_matrix_in_lowest_terms():
    G = mass_spring()
    c, k, m = G.symbols
    t = G.tf()
    assert t.verified and t.mcmillan_degree == 2
    assert zero(t.to_sympy() - sympy.Matrix([[1 / (m * s**2 + c * s + k)]]))
    assert zero(t.to_sympy() - transfer(G))
    assert [str(x) for x in t.conditions.to_sympy()] == list(t.conditions)
    assert t.pole_polynomial.degree == 2 and len(t.pole_factors) == 1


def test_minreal_keeps_the_transfer_matrix_and_says_its_conditions():
    # a mass-spring with an extra state the input does not reach
    A = [[0, 1, 0], ["-k/m", "-c/m", 0], [0, 0, "-a"]]
    G = exactlti.ss(A, [[0], ["1/m"], [0]], [[1, 0, 1]], [[0]],
                    params={"m": None, "c": None, "k": None, "a": None})
    for method in ("kalman", "rosenbrock", "ho-kalman"):
        r = G.minreal(method=method)
        assert r.verified and r.nstates == 2 and r.original_order == 3
        assert r.system.is_symbolic and r.system.params == G.params
        assert zero(transfer(r.system) - transfer(G))
        assert all(isinstance(x, str) for x in r.conditions)
        assert r.system.ctrb().to_sympy().rank(simplify=True) == 2


def test_scb_identities_over_qp():
    G, (J, s0, s1, a2) = dc_motor_symbolic()
    r = G.scb()
    assert r.verified and r.dims == (1, 0, 0, 2) and r.chains == [2]
    # A_aa = -sigma0/sigma1 (the zero dynamics); the erratum entry over sigma1^3
    assert sympy.cancel(r.A.to_sympy()[0, 0] + s0 / s1) == 0
    want = -s0 * (s0 * J - s1 * a2) / s1**3
    assert sympy.cancel(r.A.to_sympy()[0, 1] - want) == 0
    # the library's identities (with the input/output pre-maps U, Y) as rational functions:
    # Gamma1 B_scb = B U Gamma3, Gamma2 C_scb = Y^-1 C Gamma1, Gamma2 D_scb = Y^-1 D U Gamma3
    A0, B0, C0, D0 = G.to_sympy()
    G1, G2, G3, U, Y = (m.to_sympy() for m in (r.Gamma1, r.Gamma2, r.Gamma3, r.U, r.Y))
    assert zero(G1 * r.B.to_sympy() - B0 * U * G3)
    assert zero(G2 * r.C.to_sympy() - Y.inv() * C0 * G1)
    assert zero(G2 * r.D.to_sympy() - Y.inv() * D0 * U * G3)
    assert sympy.cancel(G1.det()) != 0
    conds = r.conditions.to_sympy()
    assert s1 in conds  # the form divides by sigma1
    assert r.minimum_phase is None  # depends on the signs of the parameters
    assert [f.root_sympy() for f in r.zero_factors] == [-s0 / s1]
    # at the paper's values the symbolic SCB is the numeric one
    vals = {J: sympy.Rational(23, 10000), s0: 260, s1: sympy.Rational(3, 5), a2: sympy.Rational(22, 125)}
    N = G.subs({str(k): v for k, v in vals.items()}).scb()
    assert zero(r.A.to_sympy().subs(vals) - N.A.to_sympy())


def test_jordan_over_qp():
    a, b = sympy.symbols("a b")
    r = exactlti.jordan([[a, 1, 0], [0, a, 0], [0, 0, b]])
    assert r.verified and r.complete and r.check()
    assert sorted(r.blocks) == [("a", 2), ("b", 1)]
    assert "a - b" in r.conditions or "-a + b" in r.conditions
    G = mass_spring()
    j = G.jordan()
    assert j.verified and not j.complete and j.check()
    (e,) = j.eigenvalues
    assert e.value is None and e.degree == 2 and e.to_sympy() is None
    c, k, m = G.symbols
    x = sympy.Symbol(j.var)
    assert sympy.cancel(e.factor_sympy() - (x**2 + c / m * x + k / m)) == 0 or sympy.cancel(
        e.factor_sympy() - (m * x**2 + c * x + k)
    ) == 0


def test_jordan_random_identities():
    rng = random.Random(3)
    p = sympy.Symbol("p")
    for _ in range(4):
        M = [[rng.randint(-2, 2) + (p if rng.random() < 0.3 else 0) for _ in range(3)] for _ in range(3)]
        if not any(getattr(x, "free_symbols", None) for r in M for x in r):
            M[0][0] = p
        r = exactlti.jordan(M)
        assert r.verified and r.check()


def test_poles_zeros_mnf_over_qp():
    G = exactlti.ss([["-a", 1], [0, "-b"]], [[0], [1]], [["c", 1]], params={"a": None, "b": None, "c": None})
    p = G.poles()
    a, b, c = G.symbols
    assert p.complete and sorted(map(str, p.to_sympy())) == ["-a", "-b"]
    z = G.zeros()
    assert [zz for zz in z.to_sympy()] == [-a - c] or sympy.cancel(z.to_sympy()[0] + a + c) == 0
    m = mass_spring().mnf()
    assert m.exists and m.verified
    assert isinstance(m.conditions, exactlti.Conditions)


def test_numbers_only_operations_refuse_with_one_line():
    G = mass_spring()
    # (minreal(method="jordan") works over Q(p): python/tests/test_minreal_fields.py)
    for f in (G.check, lambda: G.freqresp([1.0])):
        with pytest.raises(ValueError, match="needs numbers") as e:
            f()
        assert "\n" not in str(e.value)
    with pytest.raises(NotImplementedError, match="real Jordan form"):
        G.jordan(real=True)


def test_modes_over_qp_are_formulas():
    # det(sI - A) factored over Q(p): m s^2 + c s + k gives omega_n^2 = k/m, 2 zeta omega_n = c/m
    G = mass_spring()
    r = G.modes()
    assert r.verified
    quad = [m for m in r["modes"] if "omega_n_squared" in m]
    assert len(quad) == 1
    assert sympy.simplify(sympy.sympify(quad[0]["omega_n_squared"]) - sympy.sympify("k/m")) == 0
    assert sympy.simplify(sympy.sympify(quad[0]["two_zeta_omega_n"]) - sympy.sympify("c/m")) == 0


def test_symbolic_reprs():
    G = mass_spring()
    for obj in (G, G.minreal(), G.jordan(), G.scb(), G.tf()):
        assert repr(obj)
        if hasattr(obj, "_repr_latex_"):
            assert obj._repr_latex_().startswith("$")


def test_two_sympy_symbols_with_one_name_are_refused():
    # Symbol('x') and Symbol('x', positive=True) are different SymPy symbols; the reader
    # knows symbols by name, so taking both would silently merge them into one
    rng = random.Random(2205)
    variants = [{}, {"positive": True}, {"real": True}, {"integer": True}, {"nonzero": True}]
    for _ in range(12):
        a, b = rng.sample(variants, 2)
        x, y = sympy.Symbol("x", **a), sympy.Symbol("x", **b)
        assert x != y
        where = rng.choice(["entries", "param"])
        with pytest.raises(ValueError, match="two different SymPy symbols are both named 'x'"):
            if where == "entries":
                exactlti.ss([[x, 1], [0, y + 1]])
            else:
                exactlti.ss([[x, 1], [0, 1]], params={"x": y})
    # one symbol used twice (equal, same assumptions) is fine
    x = sympy.Symbol("x", positive=True)
    S = exactlti.ss([[x, 1], [0, x + 1]], params={"x": sympy.Symbol("x", positive=True)})
    assert S.params == ("x",)


def test_jordan_of_a_symbolic_descriptor_is_the_finite_part(tmp_path):
    # E = diag(1, m, 0): two finite eigenvalues (roots of m s^2 + c s + k) and one
    # non-dynamic mode; the Jordan form of A alone (3 states) would be wrong, as the CLI
    import json

    import exactlti

    def model(params):
        return {"parameters": params,
                "E": [[1, 0, 0], [0, "m", 0], [0, 0, 0]],
                "A": [[0, 1, 0], [0, "-c", 1], ["-k", 0, -1]],
                "B": [[0], [0], [1]], "C": [[1, 0, 0]], "D": [[0]]}

    sym = tmp_path / "sym.json"
    sym.write_text(json.dumps(model({"m": None, "k": None, "c": None})))
    num = tmp_path / "num.json"
    num.write_text(json.dumps(model({"m": 2, "k": 3, "c": 1})))
    js = exactlti.load(str(sym)).jordan()
    jn = exactlti.load(str(num)).jordan()
    assert js.nstates == 2 and jn.nstates == 2
    assert js.verified and jn.verified
    assert js.J.nrows == 2 and js.charpoly.degree == 2
