"""from_control(..., tol=): floats rationalised by continued fractions, choices reported."""

import random
import warnings
from fractions import Fraction

import pytest

import exactlti
from exactlti._convert import simplest_rational

control = pytest.importorskip("control")


def test_simplest_rational_examples_and_edges():
    F = Fraction
    assert simplest_rational(F(0), F(0)) == 0
    assert simplest_rational(F(-1, 10), F(1, 10)) == 0  # 0 in the interval
    assert simplest_rational(F(5, 2), F(5, 2)) == F(5, 2)  # a point: itself
    assert simplest_rational(F(29, 10), F(31, 10)) == 3  # an integer inside wins
    assert simplest_rational(F(-31, 10), F(-29, 10)) == -3
    assert simplest_rational(F(1, 3) - F(1, 100), F(1, 3) + F(1, 100)) == F(1, 3)
    assert simplest_rational(F(3, 4), F(1, 2)) == F(1, 2)  # ends given in either order


def test_simplest_rational_property():
    rng = random.Random(20261126)
    for _ in range(500):
        a = Fraction(rng.randint(-10**6, 10**6), rng.randint(1, 10**6))
        w = Fraction(1, rng.randint(1, 10**9))
        r = simplest_rational(a - w, a + w)
        assert a - w <= r <= a + w
        # nothing in the interval has a smaller denominator (checked by brute force for
        # small denominators)
        for q in range(1, min(r.denominator, 60)):
            lo, hi = (a - w) * q, (a + w) * q
            assert not any(lo <= p <= hi for p in range(int(lo) - 1, int(hi) + 2)), (a, w, q)


def test_round_off_comes_back_as_the_rationals_meant():
    rng = random.Random(7)
    for _ in range(40):
        vals = [Fraction(rng.randint(-99, 99), rng.randint(1, 99)) for _ in range(4)]
        A = [[float(vals[0]), float(vals[1])], [float(vals[2]), float(vals[3])]]
        P = control.ss(A, [[0], [1]], [[1, 0]], [[0]])
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            G = exactlti.from_control(P, tol=1e-12)
        assert [G.A[i, j] for i in range(2) for j in range(2)] == vals
        for x, r in G.rationalized:
            assert abs(Fraction(x) - r) <= Fraction(1e-12)


def test_choices_reported_and_warned():
    P = control.ss([[0, 1], [-1 / 3, -0.1 - 0.2]], [[0], [1]], [[1, 0]], [[0]])
    with pytest.warns(exactlti.ExactnessWarning, match="rationalised within tol"):
        G = exactlti.from_control(P, tol=1e-9)
    assert G.A[1, 0] == Fraction(-1, 3) and G.A[1, 1] == Fraction(-3, 10)
    assert [r for _, r in G.rationalized] == [Fraction(-1, 3), Fraction(-3, 10)]
    # without tol the same floats are the shortest decimals (no rationalisation)
    with pytest.warns(exactlti.ExactnessWarning, match="shortest decimals"):
        H = exactlti.from_control(P)
    assert H.A[1, 1] == Fraction("-0.30000000000000004")
    # tol = 0 keeps every float's exact binary value
    Z = exactlti.from_control(P, tol=0)
    assert Z.A[1, 0] == Fraction(-1 / 3) and Z.rationalized == []


def test_transfer_function_path_and_bad_tol():
    T = control.tf([1, 0.30000000000000004], [1, 1 / 3, 0.1 + 0.2])
    with pytest.warns(exactlti.ExactnessWarning):
        G = exactlti.from_control(T, tol=1e-12)
    import sympy

    s = sympy.Symbol("s")
    g = G.tf()[0, 0].to_sympy()
    want = (s + sympy.Rational(3, 10)) / (s**2 + sympy.Rational(1, 3) * s + sympy.Rational(3, 10))
    assert sympy.cancel(g - want) == 0
    with pytest.raises(ValueError, match="tol"):
        exactlti.from_control(T, tol=-1)
    with pytest.raises(ValueError, match="tol"):
        exactlti.from_control(T, tol="small")
