"""Operators (G * H, G + H, -G, G - H, gains), systems from series/parallel/feedback and
interconnect by names, minreal() as a system, and discrete time (dt) against
python-control on the float side."""

import random
from fractions import Fraction

import numpy as np
import pytest

import exactlti


def _rand(rng, n, m=1, p=1, dt=None):
    mk = lambda r, c: [[rng.randint(-3, 3) for _ in range(c)] for _ in range(r)]
    return exactlti.ss(mk(n, n), mk(n, m), mk(p, n), mk(p, m), dt=dt)


def _markov(G, k):
    """[D, CB, CAB, ...] of a SISO system as Fractions."""
    return [Fraction(G.D[0, 0])] + [Fraction(x[0, 0]) for x in G.markov(k)]


def _conv(a, b, k):
    return [sum(a[j] * b[i - j] for j in range(i + 1)) for i in range(k)]


def test_operators_markov_parameters_exactly():
    rng = random.Random(28)
    for _ in range(8):
        G, H = _rand(rng, rng.randint(1, 3)), _rand(rng, rng.randint(1, 3))
        g, h = _markov(G, 5), _markov(H, 5)
        # G * H is H first, then G: transfer G(s) H(s), Markov parameters the convolution
        assert _markov(G * H, 5) == _conv(g, h, 6)
        assert (G * H).nstates == G.nstates + H.nstates
        assert _markov(G + H, 5) == [x + y for x, y in zip(g, h)]
        assert _markov(-G, 5) == [-x for x in g]
        assert _markov(G - H, 5) == [x - y for x, y in zip(g, h)]
        assert _markov(3 * G, 5) == [3 * x for x in g]
        assert _markov(G * Fraction(1, 2), 5) == [x / 2 for x in g]
        assert _markov(G + 1, 5) == [g[0] + 1] + g[1:]


def test_series_order_mimo_and_feedback_system():
    rng = random.Random(5)
    G = _rand(rng, 2, m=2, p=1)  # 2 inputs -> 1 output
    H = _rand(rng, 2, m=1, p=2)  # 1 input -> 2 outputs
    S = G * H  # H first: 1 input -> 2 -> 1 output
    assert (S.ninputs, S.noutputs) == (1, 1)
    assert exactlti.series(H, G).A == S.A
    with pytest.raises(ValueError):
        H * H  # 2 outputs into 1 input
    P = exactlti.ss([[-2]], [[1]], [[3]], [[0]])
    T = exactlti.feedback(P, Fraction(5, 7))
    # P / (1 + K P) at s = 0: (3/2) / (1 + 15/14) = 21/29
    assert T.dcgain()["dc_gain"] == [["21/29"]]
    assert exactlti.feedback(P, 1, sign=1).dcgain()["dc_gain"] == [["-3"]]


def test_interconnect_by_names_equals_feedback():
    P = exactlti.ss([[0, 1], [-2, -3]], [[0], [1]], [[1, 0]], [[0]], inputs=["u"], outputs=["y"])
    C = exactlti.ss([[0]], [[1]], [[2]], [[3]], inputs=["e"], outputs=["u"])
    T = exactlti.interconnect([P, C], [["u", "u"], ["e", "-y"]], inplist=["e"], outlist=["y"])
    F = exactlti.feedback(P * C, 1)
    assert T.input_labels == ["e"] and T.output_labels == ["y"]
    assert _markov(T, 6) == _markov(F, 6)
    with pytest.raises(ValueError, match="unknown output 'z'"):
        exactlti.interconnect([P, C], [["u", "z"]], inplist=["e"], outlist=["y"])
    with pytest.raises(ValueError, match="unknown input 'w'"):
        exactlti.interconnect([P, C], [], inplist=["w"], outlist=["y"])


def test_minreal_returns_a_system_keeping_names_and_dt():
    G = exactlti.ss(
        [[-1, 0], [0, -2]], [[1], [0]], [[1, 1]], [[0]], dt="1/10", inputs=["f"], outputs=["x"]
    )
    M = G.minreal()
    assert isinstance(M, exactlti.StateSpace) and isinstance(M.result, exactlti.MinrealResult)
    assert (M.nstates, M.original_order, M.verified) == (1, 2, True)
    assert M.dt == Fraction(1, 10) and M.input_labels == ["f"] and M.output_labels == ["x"]
    assert _markov(M, 4) == _markov(G, 4)
    # a pole-zero cancellation after feedback, removed exactly
    P = exactlti.ss([[-1]], [[1]], [[1]], [[0]])
    L = exactlti.feedback(P * exactlti.ss([[-1]], [[1]], [[0]], [[1]]), 1)
    assert L.nstates == 2 and L.minreal().nstates == 1


def test_dt_mixing_is_refused_and_kept_through_operators():
    ct = exactlti.ss([[-1]], [[1]], [[1]], [[0]])
    d1 = exactlti.ss([["1/2"]], [[1]], [[1]], [[0]], dt=0.1)
    d2 = exactlti.ss([["1/3"]], [[1]], [[1]], [[0]], dt=0.2)
    assert d1.dt == Fraction(1, 10) and d1.isdtime() and ct.isctime() and ct.dt == 0
    with pytest.raises(ValueError, match="continuous time"):
        ct * d1
    with pytest.raises(ValueError, match="dt = 1/5"):
        d1 + d2
    assert (d1 * d1).dt == Fraction(1, 10) and (2 * d1).dt == Fraction(1, 10)
    assert d1.dcgain()["dc_gain"] == [["2"]]  # G(1) = 1/(1 - 1/2)
    with pytest.raises(ValueError, match="continuous-time"):
        d1.margin()


control = pytest.importorskip("control")


def test_discrete_step_impulse_freqresp_against_python_control():
    rng = random.Random(11)
    for _ in range(4):
        n = rng.randint(1, 3)
        A = [[Fraction(rng.randint(-4, 4), 10) for _ in range(n)] for _ in range(n)]
        B = [[rng.randint(-2, 2)] for _ in range(n)]
        C = [[rng.randint(-2, 2) for _ in range(n)]]
        D = [[rng.randint(-1, 1)]]
        G = exactlti.ss(A, B, C, D, dt="1/4")
        Gc = G.to_control()
        assert Gc.dt == 0.25
        N = 12
        T = np.arange(N) * 0.25
        ours = [float(Fraction(y[0][0])) for y in G.step(points=N)["exact"]]
        theirs = control.step_response(Gc, T=T).outputs
        assert np.allclose(ours, theirs, atol=1e-12)
        ours = [float(Fraction(y[0][0])) for y in G.impulse(points=N)["exact"]]
        theirs = control.impulse_response(Gc, T=T).outputs
        assert np.allclose(ours, theirs, atol=1e-12)
        w = np.linspace(0.1, np.pi / 0.25 * 0.99, 7)
        assert np.allclose(G.freqresp(w)[0, 0], Gc(np.exp(1j * w * 0.25)), atol=1e-10)
        back = exactlti.from_control(Gc)
        assert back.dt == Fraction(1, 4)


def test_c2d_tustin_exact_and_against_python_control():
    rng = random.Random(3)
    for _ in range(4):
        G = _rand(rng, rng.randint(1, 3))
        try:
            Gd = G.c2d("1/10")
        except ValueError:
            continue  # 2/T an eigenvalue of A
        assert Gd.dt == Fraction(1, 10)
        back = Gd.d2c()
        assert back.A == G.A and back.B == G.B and back.C == G.C and back.D == G.D
        ref = control.c2d(G.to_control(), 0.1, method="tustin")
        w = np.linspace(0.5, 30, 5)
        z = np.exp(1j * w * 0.1)
        assert np.allclose(Gd.freqresp(w)[0, 0], ref(z), atol=1e-9)
    G = exactlti.ss([[0, 1], [-2, -3]], [[0], [1]], [[1, 0]], [[0]])
    Z = G.c2d(0.1, method="zoh")
    ref = control.c2d(G.to_control(), 0.1, method="zoh")
    assert np.allclose(Z.A.to_numpy().astype(float), ref.A, atol=1e-12)


def test_exact_stability_against_numpy_moduli():
    rng = random.Random(17)
    seen = set()
    for _ in range(20):
        n = rng.randint(1, 3)
        A = [[Fraction(rng.randint(-9, 9), 8) for _ in range(n)] for _ in range(n)]
        G = exactlti.ss(A, [[1]] * n, [[1] * n], [[0]], dt=1)
        mods = np.abs(np.linalg.eigvals(np.array(A, dtype=float)))
        if np.any(np.abs(mods - 1) < 1e-9):
            continue
        want = bool(np.all(mods < 1))
        assert G.is_stable() == want
        seen.add(want)
    assert seen == {True, False}


def test_discrete_tf_and_zeros_are_written_in_z():
    A, B, C, D = [[0.5, 0.1], [0, 0.8]], [[0], [1]], [[1, 2]], [[1]]
    Gc = exactlti.ss(A, B, C, D)
    Gd = exactlti.ss(A, B, C, D, dt="1/10")
    tc, td = Gc.tf(), Gd.tf()
    assert tc.variable == "s" and td.variable == "z"
    # the same rational function, the variable renamed
    assert str(td[0, 0]) == str(tc[0, 0]).replace("s", "z")
    assert "s" not in str(td[0, 0]) and "z" in str(td[0, 0])
    assert td[0, 0].num.var == "z"
    zc, zd = Gc.zeros(), Gd.zeros()
    assert str(zd.polynomial) == str(zc.polynomial).replace("s", "z")
    sympy = pytest.importorskip("sympy")
    z = sympy.Symbol("z")
    assert td[0, 0].to_sympy().free_symbols == {z}
    # G(z) at a point equals C (zI - A)^-1 B + D
    val = td[0, 0].to_sympy().subs(z, 3)
    Am = sympy.Matrix([[sympy.Rational(1, 2), sympy.Rational(1, 10)], [0, sympy.Rational(4, 5)]])
    want = (sympy.Matrix(C) * (3 * sympy.eye(2) - Am).inv() * sympy.Matrix(B))[0, 0] + 1
    assert sympy.simplify(val - want) == 0


def test_discrete_tf_to_control_keeps_dt():
    control = pytest.importorskip("control")
    G = exactlti.ss([[0.5, 0.1], [0, 0.8]], [[0], [1]], [[1, 0]], [[0]], dt="1/10")
    T = G.tf().to_control()
    assert T.dt == pytest.approx(0.1)
    ref = control.ss2tf(G.to_control())
    w = np.array([0.3, 1.0, 10.0])
    np.testing.assert_allclose(T(np.exp(1j * w * 0.1)), ref(np.exp(1j * w * 0.1)), rtol=1e-12)


def test_balred_against_python_control():
    control = pytest.importorskip("control")
    pytest.importorskip("slycot")
    A = [[-1, 1, 0, 0], [0, -2, 1, 0], [0, 0, -3, 1], [0, 0, 0, -4]]
    G = exactlti.ss(A, [[0], [1], [0], [1]], [[1, 1, 0, 0]], [[0]])
    r = G.balred(2)
    ref = control.balred(G.to_control(), 2)
    # this system has an unobservable/uncontrollable direction: its exact Gramians give
    # sigma_4 = 0 (computed over Q with SymPy), which both float paths return as round-off
    # (~1e-10 here, ~1e-9 from slycot), so it is compared with an absolute tolerance
    hsv = np.asarray(r["hankel_singular_values"])
    np.testing.assert_allclose(
        hsv, control.hsvd(G.to_control()), rtol=1e-8, atol=1e-8 * hsv[0]
    )
    assert hsv[3] < 1e-8 * hsv[0]
    mine = control.ss(r["A"], r["B"], r["C"], r["D"])
    w = np.logspace(-2, 2, 40)
    np.testing.assert_allclose(mine(1j * w), ref(1j * w), rtol=1e-7, atol=1e-12)
    # the H-infinity error is within the bound 2 * (sigma_3 + sigma_4)
    full = G.to_control()
    err = np.max(np.abs(full(1j * w) - mine(1j * w)))
    assert err <= r["error_bound"] * (1 + 1e-9)
    with pytest.raises(ValueError):
        exactlti.ss([[1]], [[1]], [[1]], [[0]]).balred(1)


def test_tf_in_z_keeps_dt_and_matches_python_control():
    """``tf(num, den, dt=)`` and ``from_control`` of a discrete TransferFunction: G(z) as
    written, dt kept, poles as python-control's, and the Markov parameters of G(z) (the
    impulse response: the coefficients of G expanded in 1/z)."""
    control = pytest.importorskip("control")
    G = exactlti.tf([1, Fraction(1, 2)], [1, Fraction(-13, 10), Fraction(2, 5)], dt="1/10")
    assert Fraction(G.dt) == Fraction(1, 10)
    assert G.tf().variable == "z"
    assert sorted(complex(p).real for p in G.poles()) == pytest.approx([0.5, 0.8])
    # (z + 1/2)/(z^2 - 13/10 z + 2/5) = z^-1 + (1/2 + 13/10) z^-2 + ...
    m = _markov(G, 3)
    assert m[0] == 0 and m[1] == 1 and m[2] == Fraction(1, 2) + Fraction(13, 10)
    H = exactlti.tf("(z+1/2)/((z-4/5)*(z-1/2))", dt="1/10")
    assert _markov(H, 3) == m
    # a python-control discrete TF: same system, dt kept, poles as python-control's
    S = control.tf([1, 0.5], [1, -1.3, 0.4], 0.1)
    with pytest.warns(exactlti.ExactnessWarning):
        E = exactlti.from_control(S)
    assert Fraction(E.dt) == Fraction(1, 10)
    assert _markov(E, 3) == m
    assert sorted(complex(p).real for p in E.poles()) == pytest.approx(
        sorted(np.real(S.poles()))
    )
    # the continuous variable is refused in a sampled system's text, naming it
    with pytest.raises(Exception, match="the variable is z"):
        exactlti.tf("1/(s+1)", dt="1/10")
