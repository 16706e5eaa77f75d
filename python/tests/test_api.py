"""The Python API: exact input, identities on every result, errors, interrupts."""

import os
import random
import signal
import threading
import time
import warnings
from decimal import Decimal
from fractions import Fraction

import pytest

import exactlti
from exactlti import _core

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SLIDING = os.path.join(ROOT, "data", "sliding-masses.json")

sympy = pytest.importorskip("sympy")
np = pytest.importorskip("numpy")


def rand_system(n, m, p, seed, lo=-3, hi=3):
    rng = random.Random(seed)
    mk = lambda r, c: [[rng.randint(lo, hi) for _ in range(c)] for _ in range(r)]
    return mk(n, n), mk(n, m), mk(p, n), mk(p, m)


def sym(m):
    return m.to_sympy()


# ---------------------------------------------------------------- input


def test_entries_are_exact_in_every_spelling():
    A = [
        [1, Fraction(1, 3), "0.08", Decimal("1.5e-3")],
        [sympy.Rational(2, 7), np.int64(5), "-3/7", "1e2"],
        [0, 0, 0, 0],
        [0, 0, 0, 0],
    ]
    G = exactlti.ss(A)
    assert G.A.tolist()[0] == [1, Fraction(1, 3), Fraction(2, 25), Fraction(3, 2000)]
    assert G.A.tolist()[1] == [Fraction(2, 7), 5, Fraction(-3, 7), 100]
    assert G.ninputs == 0 and G.noutputs == 0 and G.field == "QQ"


def test_numpy_integer_arrays_and_matlab_strings():
    A = np.array([[0, 1], [-2, -3]], dtype=np.int32)
    G1 = exactlti.ss(A, np.array([[0], [1]]), np.array([[1, 0]]), np.array([[0]]))
    G2 = exactlti.ss("[0 1; -2 -3]", "[0; 1]", "[1 0]", "[0]")
    assert G1.A == G2.A and G1.B == G2.B and G1.C == G2.C and G1.D == G2.D


def test_floats_are_shortest_decimals_with_a_warning():
    with pytest.warns(exactlti.ExactnessWarning, match="0.1 -> 0.1"):
        G = exactlti.ss([[0.1, 0], [0, 2.5]])
    assert G.A[0, 0] == Fraction(1, 10) and G.A[1, 1] == Fraction(5, 2)


def test_sympy_radicals_give_a_quadratic_field():
    G = exactlti.ss([[0, sympy.sqrt(2)], [sympy.sqrt(2), 0]], [[1], [0]], [[1, 0]], [[0]])
    assert G.field.startswith("QQ(sqrt(2)")
    assert sympy.simplify(sym(G.A)[0, 1] - sympy.sqrt(2)) == 0
    r = G.minreal()
    assert r.verified and r.nstates == 2


def test_sympy_symbols_make_a_symbolic_system():
    k = sympy.Symbol("k")
    G = exactlti.ss([[0, 1], [-k, 0]])
    assert G.is_symbolic and G.params == ("k",)


def test_bad_input_is_a_value_error_with_the_cli_message():
    with pytest.raises(ValueError) as e:
        exactlti.ss([[0, 1], ["-k", 0]])
    assert str(e.value) == "ss: key A, row 2, column 1: unknown parameter 'k'"
    with pytest.raises(ValueError, match="ragged|columns|row"):
        exactlti.ss([[0, 1], [1]])
    with pytest.raises(ValueError, match="not a finite number"):
        exactlti.ss([[float("nan")]])
    with pytest.raises(ValueError, match="not a number"):
        exactlti.ss([[object()]])


def test_params_are_exact():
    G = exactlti.ss([["-k/m"]], params={"k": "0.5", "m": Fraction(3)})
    assert G.A[0, 0] == Fraction(-1, 6)


def test_load_reads_the_sliding_masses():
    G = exactlti.load(SLIDING)
    assert (G.nstates, G.ninputs, G.noutputs) == (20, 1, 1)


def test_descriptor_systems_are_converted_exactly():
    # E x' = A x + B u with a singular E: one algebraic state
    G = exactlti.ss([[0, 1], [1, 1]], [[0], [1]], [[1, 0]], [[0]], E=[[1, 0], [0, 0]])
    assert G.E is not None and G.E.tolist() == [[1, 0], [0, 0]]
    # x2 = -x1 - u, x1' = x2  =>  x1' = -x1 - u, y = x1: G(s) = -1/(s+1)
    h = G.tf()[0, 0].to_sympy()
    s = sympy.Symbol("s")
    assert sympy.simplify(h - (-1 / (s + 1))) == 0


def _descriptor(n, seed):
    """A random descriptor system E = P diag(I, 0) Q, A = P [[A11, A12], [A21, I]] Q (index 1)
    or with E invertible (every other seed)."""
    rng = random.Random(seed)
    r = n if seed % 2 else rng.randint(1, n - 1)
    mk = lambda a, b: [[rng.randint(-3, 3) for _ in range(b)] for _ in range(a)]
    e0 = sympy.zeros(n, n)
    for i in range(r):
        e0[i, i] = rng.randint(1, 3)
        for j in range(i + 1, r):
            e0[i, j] = rng.randint(-2, 2)
    a0 = sympy.Matrix(mk(n, n))
    for i in range(r, n):
        for j in range(r, n):
            a0[i, j] = 1 if i == j else 0
    p = sympy.eye(n) + sympy.Matrix(n, n, lambda i, j: rng.randint(-1, 1) if j > i else 0)
    q = sympy.eye(n) + sympy.Matrix(n, n, lambda i, j: rng.randint(-1, 1) if j < i else 0)
    E, A = p * e0 * q, p * a0 * q
    B, C, D = sympy.Matrix(mk(n, 1)), sympy.Matrix(mk(1, n)), sympy.Matrix(mk(1, 1))
    return E, A, B, C, D


def test_descriptor_freqresp_is_the_pencils():
    # class: random index-0/1 descriptor systems; G(jw) = C (jwE - A)^-1 B + D exactly in SymPy
    for seed in range(8):
        E, A, B, C, D = _descriptor(5, seed)
        ints = lambda M: [[int(x) for x in row] for row in M.tolist()]
        G = exactlti.ss(ints(A), ints(B), ints(C), ints(D), E=ints(E))
        for w in (sympy.Rational(1, 3), sympy.Integer(2)):
            exact = (C * (sympy.I * w * E - A).inv() * B + D)[0, 0]
            got = G.freqresp([float(w)])[0, 0, 0]
            ref = complex(sympy.N(exact, 30))
            assert abs(got - ref) <= 1e-9 * max(abs(ref), 1e-300), (seed, w)


def test_descriptor_jordan_is_the_pencils_finite_part():
    # E = diag(2, 1): the finite dynamics are E^-1 A (charpoly x^2 + x + 1/2), not A
    G = exactlti.ss([[0, 1], [-1, -1]], [[0], [1]], [[1, 0]], [[0]], E=[[2, 0], [0, 1]])
    j = G.jordan()
    assert j.verified and j.infinite_blocks == []
    x = sympy.Symbol("x")
    assert sympy.expand(j.charpoly.to_sympy(x) - (x**2 + x + sympy.Rational(1, 2))) == 0
    assert any("finite part" in n for n in j.notes)
    # one algebraic state: one infinite block of size 1, one finite eigenvalue
    G = exactlti.ss([[0, 1], [1, 1]], [[0], [1]], [[1, 0]], [[0]], E=[[1, 0], [0, 0]])
    j = G.jordan()
    assert j.verified and j.infinite_blocks == [1] and j.nstates == 1


# ---------------------------------------------------------------- operations


@pytest.mark.parametrize("method", ["kalman", "rosenbrock", "ho-kalman"])
def test_minreal_keeps_the_transfer_matrix(method):
    A, B, C, D = rand_system(6, 2, 2, 7)
    # make it non-minimal: append an uncontrollable and an unobservable state
    n = 6
    A2 = [row + [0, 0] for row in A] + [[0] * n + [-5, 0], [0] * n + [0, -7]]
    B2 = B + [[0, 0], [1, 1]]
    C2 = [row + [1, 0] for row in C]
    G = exactlti.ss(A2, B2, C2, D)
    r = G.minreal(method=method)
    assert r.verified and r.nstates <= 6 and r.original_order == 8
    g1, g2 = G.tf().to_sympy(), r.system.tf().to_sympy()
    assert (g1 - g2).applyfunc(sympy.cancel).is_zero_matrix
    assert r.system.ctrb().to_sympy().rank() == r.nstates
    assert r.system.obsv().to_sympy().rank() == r.nstates


def test_minreal_rejects_unknown_methods():
    with pytest.raises(ValueError, match="unknown method"):
        exactlti.ss([[1]]).minreal(method="magic")


def test_sliding_masses_20_16_8():
    G = exactlti.load(SLIDING)
    r = G.minreal(method="jordan")
    assert r.stages == (20, 16, 8) and r.nstates == 8 and r.verified
    # the modal realization's entries are exact in real number fields
    A = r.A.to_sympy()
    assert A.shape == (8, 8)
    assert all(sympy.im(x.evalf()) == 0 for x in A)
    k = G.minreal()
    assert k.nstates == 8 and k.verified


def test_markov_ctrb_obsv_against_sympy():
    A, B, C, D = rand_system(4, 2, 1, 3)
    G = exactlti.ss(A, B, C, D)
    As, Bs, Cs = sympy.Matrix(A), sympy.Matrix(B), sympy.Matrix(C)
    for k, M in enumerate(G.markov(5)):
        assert M.to_sympy() == Cs * As**k * Bs
    assert G.ctrb().to_sympy() == sympy.Matrix.hstack(*[As**k * Bs for k in range(4)])
    assert G.obsv().to_sympy() == sympy.Matrix.vstack(*[Cs * As**k for k in range(4)])


def test_jordan_identity_with_crootof_entries():
    # x^3 - 2 has one real and two complex roots without a small closed form
    r = exactlti.jordan([[0, 1, 0], [0, 0, 1], [2, 0, 0]])
    assert r.verified
    ev = [e.to_sympy() for e in r.eigenvalues]
    assert all(isinstance(x, sympy.CRootOf) for x in ev)
    assert all(x.poly == sympy.Poly(x.poly.gen**3 - 2) for x in ev)
    assert len({x.index for x in ev}) == 3
    assert r.check()  # A T = T J in SymPy, independently of the library
    # and the check can fail: a wrong J is caught
    # (J[0, 0] + 1: its value's constant coefficient moved by one; the values, not the
    # text, are what to_sympy builds from)
    tag, coeffs, gen = r.J._values[0][0]
    coeffs = list(coeffs) or [(0, 1)]
    p, q = coeffs[0]
    r.J._values[0][0] = (tag, [(p + q, q)] + coeffs[1:], gen)
    assert not r.check()
    assert np.allclose(r.A.to_numpy() @ r.T.to_numpy(), r.T.to_numpy() @ r.J.to_numpy())


def test_jordan_blocks_and_real_form():
    r = exactlti.jordan([[1, 1, 0], [0, 1, 0], [0, 0, 1]])
    assert [(str(e), b) for e, b in r.blocks] == [("1", 2), ("1", 1)]
    e = r.eigenvalues[0]
    assert (e.algebraic_multiplicity, e.geometric_multiplicity) == (3, 2)
    rr = exactlti.jordan([[0, 1], [-2, -2]], real=True)
    assert rr.verified and rr.exact
    J = rr.J.to_sympy()
    assert J == sympy.Matrix([[-1, 1], [-1, -1]]) or J == sympy.Matrix([[-1, -1], [1, -1]])
    A = sympy.Matrix([[0, 1], [-2, -2]])
    T = rr.T.to_sympy()
    assert (A * T - T * J).is_zero_matrix


def test_jordan_random_property():
    rng = random.Random(11)
    for _ in range(5):
        n = rng.randint(1, 5)
        A = [[rng.randint(-2, 2) for _ in range(n)] for _ in range(n)]
        r = exactlti.jordan(A)
        assert r.verified
        assert sum(e.algebraic_multiplicity for e in r.eigenvalues) == n
        An, Tn, Jn = np.array(A, dtype=float), r.T.to_numpy(), r.J.to_numpy()
        assert np.allclose(An @ Tn, Tn @ Jn)
        assert abs(np.linalg.det(Tn)) > 1e-9


def test_poles_divide_the_charpoly():
    A, _, _, _ = rand_system(4, 1, 1, 5)
    G = exactlti.ss(A)
    s = sympy.Symbol("x")
    cp = sympy.Matrix(A).charpoly(s).as_expr()
    poles = G.poles()
    assert len(poles) == 4
    for p in poles:
        mp = p.minpoly.to_sympy("x")
        assert sympy.rem(cp, mp, s) == 0
    assert abs(complex(sympy.N(poles[0].to_sympy(), 30)) - complex(poles[0])) < 1e-9
    assert np.allclose(sorted(poles.to_numpy(), key=lambda z: (z.real, z.imag)),
                       sorted(np.linalg.eigvals(np.array(A, dtype=float)), key=lambda z: (z.real, z.imag)))


def test_zeros_are_the_numerator_roots():
    G = exactlti.ss([[0, 1, 0], [0, 0, 1], [-6, -11, -6]], [[0], [0], [1]], [[2, 3, 1]], [[0]])
    z = G.zeros()
    # numerator s^2 + 3 s + 2 = (s + 1)(s + 2)
    assert sorted(str(x) for x in z) == ["-1", "-2"]
    assert z.polynomial.coeffs == [2, 3, 1]


def test_scb_identities():
    G = exactlti.ss(
        [[0, 1, 0], [0, 0, 1], [-6, -11, -6]], [[0], [0], [1]], [[1, 1, 0]], [[0]]
    )
    r = G.scb()
    assert r.verified and sum(r.dims) == 3
    # x^ = Gamma1 x: A_scb = Gamma1 A Gamma1^-1 up to the input/output maps
    G1 = r.Gamma1.to_sympy()
    assert G1.det() != 0
    assert r.zero_polynomial.coeffs == [1, 1]  # zero at -1
    assert r.minimum_phase is True


def test_mnf_sliding_masses():
    r = exactlti.load(SLIDING).mnf()
    assert r.exists and r.verified
    assert r.M.shape == (10, 10)


def test_modes_table():
    m = exactlti.ss([[0, 1], [-4, 0]]).modes()
    assert len(m) >= 1
    assert any(abs(x.frequency_hz - 2 / (2 * 3.141592653589793)) < 1e-12 for x in m)


def test_check_agrees_on_a_clean_system():
    c = exactlti.load(SLIDING).check()
    assert c.agree
    assert {i["what"] for i in c} >= {"mcmillan_degree", "controllability_rank"}


def test_freqresp_matches_the_formula():
    A, B, C, D = [[0, 1], [-2, -3]], [[0], [1]], [[1, 0]], [[0]]
    G = exactlti.ss(A, B, C, D)
    w = [0.0, 0.5, 2.0]
    g = G.freqresp(w)
    assert g.shape == (1, 1, 3)
    for k, wk in enumerate(w):
        expect = 1 / ((1j * wk) ** 2 + 3j * wk + 2)
        assert abs(g[0, 0, k] - expect) < 1e-12


# ---------------------------------------------------------------- conversions


def test_python_control_round_trip():
    control = pytest.importorskip("control")
    sysc = control.ss([[0, 1], [-2, -0.5]], [[0], [1]], [[1, 0]], [[0]])
    with pytest.warns(exactlti.ExactnessWarning):
        G = exactlti.from_control(sysc)
    assert G.A[1, 1] == Fraction(-1, 2)
    back = G.to_control()
    assert np.allclose(back.A, sysc.A)
    h = G.tf().to_control()
    assert np.allclose(h.num[0][0], [1.0]) and np.allclose(h.den[0][0], [1, 0.5, 2])


def test_sympy_conversion_of_a_large_matrix():
    rng = random.Random(1)
    rows = [[Fraction(rng.randint(-99, 99), rng.randint(1, 9)) for _ in range(30)] for _ in range(30)]
    M = exactlti.jordan([[1]]).A  # a tiny Matrix just to get the class
    G = exactlti.ss(rows)
    S = G.A.to_sympy()
    assert S == sympy.Matrix(30, 30, lambda i, j: sympy.Rational(rows[i][j].numerator, rows[i][j].denominator))
    assert isinstance(M, exactlti.Matrix)


def test_latex_reprs():
    G = exactlti.ss([[0, 1], ["-1/2", 0]], [[0], [1]], [[1, 0]], [[0]])
    assert G.A._repr_latex_().startswith("$\\begin{bmatrix}")
    assert "\\frac{1}{2}" in G.A._repr_latex_()
    for obj in (G, G.minreal(), G.jordan(), G.scb(), G.poles()[0], G.tf()):
        s = obj._repr_latex_()
        assert s.startswith("$") and s.endswith("$")


# ---------------------------------------------------------------- robustness


def test_timeout_error_for_max_seconds():
    t = time.time()
    with pytest.raises(TimeoutError, match="max_seconds"):
        _core._sleep_for_test(3.0, 0.2)
    assert time.time() - t < 2.0


def test_real_computation_timeout():
    A, B, C, D = rand_system(40, 3, 3, 2, -50, 50)
    G = exactlti.ss(A, B, C, D)
    with pytest.raises(TimeoutError):
        G.jordan(max_seconds=0.001)


def test_panics_become_runtime_errors():
    with pytest.raises(RuntimeError, match="panicked"):
        _core._panic_for_test()


def test_gil_is_released_during_work():
    # another Python thread runs while the worker computes (with the GIL held it could
    # not tick at all until the call returned)
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)
            time.sleep(0.005)

    th = threading.Thread(target=count)
    th.start()
    _core._sleep_for_test(1.0)
    during = len(ticks)
    stop.set()
    th.join()
    assert during >= 3


@pytest.mark.skipif(not hasattr(signal, "SIGINT") or os.name == "nt", reason="POSIX signals")
def test_ctrl_c_interrupts_exact_work():
    # the worker would run 60 s; SIGINT after 0.2 s stops the call (bounds generous for a
    # loaded machine: this is not a timing test). A shell that starts the suite as a
    # background job leaves SIGINT ignored (POSIX), and Python then installs no Ctrl-C handler:
    # the test installs Python's own for its duration, as an interactive session has it.
    old = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.2, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    t = time.time()
    try:
        with pytest.raises(KeyboardInterrupt):
            _core._sleep_for_test(60.0)
    finally:
        timer.join()
        signal.signal(signal.SIGINT, old)
    assert time.time() - t < 30.0
