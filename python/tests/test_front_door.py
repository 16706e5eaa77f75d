"""The Python package on the library's front door (issue 24): dcgain and the
interconnections run through ``exactlti::api`` (not refused), a file with only ``D`` is a
static gain, a system with complex coefficients has a complex time response, and a sweep of
a file over Q(sqrt 2) reads the system at each value."""

import cmath
import json
import math
import os
import random
import tempfile
from fractions import Fraction

import exactlti


def _file(name, data):
    p = os.path.join(tempfile.mkdtemp(), name)
    with open(p, "w") as f:
        json.dump(data, f)
    return p


def test_dcgain_is_exact():
    G = exactlti.ss([[-2]], [[1]], [[3]], [[0]])
    r = G.dcgain()
    assert r.verified and r["dc_gain"] == [["3/2"]]


def test_feedback_with_a_static_gain_file():
    G = exactlti.ss([[-2]], [[1]], [[3]], [[0]])
    K = exactlti.load(_file("k.json", {"D": [["5/7"]]}))
    assert K.nstates == 0
    r = G.feedback(K)
    assert r.verified and r["states"] == 1
    # G / (1 + K G) at s = 0: (3/2) / (1 + 15/14) = 21/29
    H = exactlti.ss(r["A"], r["B"], r["C"], r["D"])
    assert H.dcgain()["dc_gain"] == [["21/29"]]


def test_series_parallel_append_property():
    rng = random.Random(24)
    for _ in range(6):
        mk = lambda r, c: [[rng.randint(-3, 3) for _ in range(c)] for _ in range(r)]
        n1, n2 = rng.randint(1, 3), rng.randint(1, 3)
        G = exactlti.ss(mk(n1, n1), mk(n1, 1), mk(1, n1), mk(1, 1))
        H = exactlti.ss(mk(n2, n2), mk(n2, 1), mk(1, n2), mk(1, 1))
        for r in (G.series(H), G.parallel(H), G.append(H)):
            assert r.verified and r["states"] == n1 + n2
        # the series' transfer function is H(s) G(s): compare Markov parameters exactly
        S = exactlti.ss(*(G.series(H)[k] for k in "ABCD"))
        g = [Fraction(x[0, 0]) for x in G.markov(4)]
        h = [Fraction(x[0, 0]) for x in H.markov(4)]
        gd, hd = Fraction(G.D[0, 0]), Fraction(H.D[0, 0])
        s = [Fraction(x[0, 0]) for x in S.markov(4)]
        # Markov parameters of H G: sum over splits, with D terms at both ends
        gm, hm = [gd] + g, [hd] + h
        want = [sum(hm[j] * gm[k + 1 - j] for j in range(k + 2)) for k in range(4)]
        assert s == want


def test_complex_system_has_a_complex_step_response():
    G = exactlti.ss([["-1/2 + i"]], [[1]], [[1]], [[0]])
    lam = complex(-0.5, 1.0)
    r = G.step(to=4, points=41)
    for k, t in enumerate(r["times_s"]):
        y = complex(r["response"][k][0][0], r["response_imag"][k][0][0])
        assert abs(y - (cmath.exp(lam * t) - 1) / lam) < 1e-10
    p = G.pzmap()
    assert p["exact"] and p["poles"][0]["value"] == "-1/2 + i"


def test_sweep_over_qsqrt2_reads_the_system_at_each_value():
    p = _file("q2.json", {"parameters": {"c": "3"}, "A": [[0, 1], [-2, "-c*sqrt(2)"]],
                          "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]})
    r = exactlti.load(p).sweep("c", 1, 3, points=3)
    for c, ev in zip([1.0, 2.0, 3.0], r["eigenvalues_approx"]):
        b = c * math.sqrt(2)
        d = cmath.sqrt(b * b - 8)
        for w in ((-b - d) / 2, (-b + d) / 2):
            assert min(abs(complex(*z) - w) for z in ev) < 1e-7
