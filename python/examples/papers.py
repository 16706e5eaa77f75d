"""Two results from the papers, reproduced exactly from Python (run: python papers.py).

1. Sliding masses (Minaker & Gonzalez, sec. 4.1; data/sliding-masses.json): two chains of
   five unit masses, 20 states. The Jordan-form minimal realization drops the modes the
   input cannot excite or the output cannot see (20 -> 16), then compacts the repeated
   ones (16 -> 8); the Kalman decomposition agrees on the McMillan degree 8.

2. DC motor with LuGre friction (Grip & Saberi, "Structural decomposition of linear
   multivariable systems using symbolic computations", sec. V): the special coordinate
   basis for sigma1 = 0.6 has dims (n_a, n_b, n_c, n_d) = (1, 0, 0, 2), the zero dynamics
   A_aa = -sigma0/sigma1 and the entry A[0, 1] = -sigma0 (sigma0 J - sigma1 alpha2) /
   sigma1^3 = -16003/27 (the paper prints sigma1^2: an erratum); for sigma1 = 0 one
   integrator chain of length 3 and no invariant zero.

3. The same SCB with every parameter a symbol (J, sigma0, sigma1, alpha2; field
   QQ(J, alpha2, sigma0, sigma1)): A_aa = -sigma0/sigma1 and A[0, 1] =
   -sigma0 (sigma0 J - sigma1 alpha2) / sigma1^3 as rational functions, valid wherever
   the listed conditions (polynomials in the parameters) do not vanish; at the paper's
   values it is the numeric SCB of 2.
"""

import os
from fractions import Fraction

import exactlti

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "data", "sliding-masses.json")


def sliding_masses():
    G = exactlti.load(DATA)
    r = G.minreal(method="jordan")
    print("sliding masses (%d states): %s (Jordan method), verified: %s"
          % (G.nstates, " -> ".join(map(str, r.stages)), r.verified))
    k = G.minreal()  # Kalman decomposition
    print("  Kalman decomposition: McMillan degree %d, verified: %s" % (k.nstates, k.verified))
    print("  modal A of the minimal realization (r_k are roots listed with it):")
    print("  " + str(r.A).replace("\n", "\n  "))
    print("  " + "; ".join(r.report["symbols"]))
    assert r.stages == (20, 16, 8) and r.verified
    assert k.nstates == 8 and k.verified
    return r


def dc_motor(sigma1):
    # J omega' = u - F, F = sigma0 z + sigma1 z' + alpha2 omega; perturbation as input
    params = {"J": "0.0023", "s0": "260", "a2": "0.176", "s1": sigma1}
    A = [[0, 1, 0], [0, "-(a2 + s1)/J", "-s0/J"], [0, 1, 0]]
    B = [[0], ["s1/J"], [-1]]
    C = [[1, 0, 0]]
    return exactlti.ss(A, B, C, [[0]], params=params, name="dc-motor")


def dc_motor_scb():
    out = {}
    for s1 in ("0.6", "0"):
        s = dc_motor(s1).scb()
        print("DC motor, sigma1 = %s: dims (n_a, n_b, n_c, n_d) = %s, chains %s, verified: %s"
              % (s1, s.dims, s.chains, s.verified))
        print("  SCB A =\n  " + str(s.A).replace("\n", "\n  "))
        print("  invariant-zero polynomial: %s, minimum phase: %s"
              % (s.zero_polynomial, s.minimum_phase))
        out[s1] = s
    s = out["0.6"]
    assert s.dims == (1, 0, 0, 2) and s.chains == [2] and s.verified
    assert s.A[0, 0] == Fraction(-260) / Fraction("0.6")  # A_aa = -sigma0/sigma1
    assert s.A[0, 1] == Fraction(-16003, 27)  # .../sigma1^3, not the paper's sigma1^2
    assert s.minimum_phase is True
    z = out["0"]
    assert z.dims == (0, 0, 0, 3) and z.chains == [3] and z.verified
    return out


def dc_motor_scb_symbolic():
    import sympy

    J, s0, s1, a2 = sympy.symbols("J sigma0 sigma1 alpha2")
    A = [[0, 1, 0], [0, -(a2 + s1) / J, -s0 / J], [0, 1, 0]]
    G = exactlti.ss(A, [[0], [s1 / J], [-1]], [[1, 0, 0]], [[0]], name="dc-motor")
    s = G.scb()
    A_scb = s.A.to_sympy()
    print("DC motor over %s: dims (n_a, n_b, n_c, n_d) = %s, chains %s, verified: %s"
          % (G.field, s.dims, s.chains, s.verified))
    print("  A_aa = %s, A[0, 1] = %s" % (A_scb[0, 0], sympy.factor(A_scb[0, 1])))
    print("  conditions (assumed nonzero): %s" % ", ".join(s.conditions))
    assert s.dims == (1, 0, 0, 2) and s.verified
    assert sympy.cancel(A_scb[0, 0] + s0 / s1) == 0
    assert sympy.cancel(A_scb[0, 1] + s0 * (s0 * J - s1 * a2) / s1**3) == 0
    paper = {J: sympy.Rational(23, 10000), s0: 260, s1: sympy.Rational(3, 5),
             a2: sympy.Rational(22, 125)}
    assert A_scb[0, 1].subs(paper) == sympy.Rational(-16003, 27)
    return s


if __name__ == "__main__":
    sliding_masses()
    print()
    dc_motor_scb()
    print()
    dc_motor_scb_symbolic()
