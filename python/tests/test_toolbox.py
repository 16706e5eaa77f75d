"""python-control's toolbox names on exactlti systems: margin, step_info, damp, gram,
dcgain and print(G); hand values, python-control beside them where it is installed."""

import math
import random

import pytest

import exactlti


def loop(num, den):
    return exactlti.tf(num, den)


def test_margin_by_hand():
    # 1/(s (s+1)^2): gain margin 2 at w = 1, phase margin 21.386 deg at w^3 + w - 1 = 0
    G = loop([1], [1, 2, 1, 0])
    gm, pm, wcg, wcp = G.margin()
    assert gm == 2.0 and wcg == 1.0
    assert abs(pm - 21.386389751875043) < 1e-9
    assert abs(wcp - 0.6823278038280193) < 1e-12
    r = G.stability_margins()
    assert r.verified
    assert r["gain_margin"] == "2"
    assert r["gain_crossover_frequency_minpoly"] == "x^3 + x - 1"


def test_margin_infinite_and_mimo_refused():
    gm, pm, wcg, wcp = loop([1], [1, 1]).margin()
    assert math.isinf(gm) and math.isinf(pm) and math.isnan(wcg) and math.isnan(wcp)
    G = exactlti.ss([[-1]], [[1, 1]], [[1]], [[0, 0]])
    with pytest.raises(ValueError):
        G.margin()


def test_margin_against_python_control():
    ct = pytest.importorskip("control")
    rng = random.Random(28)
    for _ in range(10):
        den = [1] + [rng.randint(1, 6) for _ in range(3)]
        num = [rng.randint(1, 9)]
        ours = loop(num, den).margin()
        theirs = ct.margin(ct.tf(num, den))
        for a, b in zip(ours, theirs):
            if math.isinf(b) or math.isnan(b):
                assert math.isinf(a) == math.isinf(b) and math.isnan(a) == math.isnan(b)
            else:
                assert abs(a - b) <= 1e-6 * (1 + abs(b)), (num, den, ours, theirs)


def test_step_info_damp_gram_dcgain():
    G = exactlti.ss([[0, 1], [-1, -1]], [[0], [1]], [[1, 0]], [[0]])
    s = G.step_info(to=20, points=20001)
    assert abs(s["Overshoot"] - 100 * math.exp(-math.pi * 0.5 / math.sqrt(0.75))) < 1e-3
    assert s["SteadyStateValue"] == 1.0
    d = G.damp()
    assert [p["two_zeta_wn"] for p in d["poles"]] == ["1", "1"]
    assert all(abs(p["damping_ratio"] - 0.5) < 1e-12 for p in d["poles"])
    w = G.gram("o")
    assert w.verified and w["W"] == [["1", "1/2"], ["1/2", "1/2"]]
    with pytest.raises(ValueError):
        G.gram("x")
    assert G.dcgain()["dc_gain"] == [["1"]]


def test_print_shows_the_matrices():
    G = exactlti.ss([[0, 1], ["-0.08", "-1/3"]], [[0], [1]], [[1, 0]], [[0]])
    text = str(G)
    assert "A = " in text and "-2/25" in text and "-1/3" in text and "D = " in text
    assert repr(G).startswith("StateSpace(")
