"""Jupyter display (``_repr_latex_``, ``_repr_html_`` made by the library's report layer) of
every result, and derivations step by step (``G.steps(...)``) with their identities
recomputed here in SymPy from the steps' data."""

import os

import pytest
import sympy

import exactlti

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
DATA = os.path.join(ROOT, "data")


def shown(x):
    """The HTML and LaTeX of a result; both must be the library's."""
    h, t = x._repr_html_(), x._repr_latex_()
    assert isinstance(h, str) and isinstance(t, str), type(x)
    assert h.startswith('<div class="exactlti'), h[:80]
    assert "<script" not in h
    return h, t


def mat(m):
    return sympy.Matrix([[sympy.sympify(str(x).replace("^", "**")) for x in r] for r in m.tolist()])


def two_states():
    return exactlti.ss([[0, 1], [-2, -3]], [[0], [1]], [[3, 1]], [[0]])


def test_every_numeric_result_renders():
    G = two_states()
    h, t = shown(G)
    assert "\\begin{bmatrix}" in h and "\\begin{array}" in t
    results = [
        G.jordan(),
        G.jordan(real=True),
        G.minreal(),
        G.minreal(method="jordan"),
        G.scb(),
        G.mnf(),
        G.zeros(),
        G.poles(),
        G.modes(),
        G.tf(),
        G.check(),
        G.dcgain(),
        G.steps("jordan"),
    ]
    for r in results:
        shown(r)
    # the Jordan form's report: its J as a matrix, the field's LaTeX entries
    h, t = shown(G.jordan())
    assert "\\begin{bmatrix}" in h and "verified" in h
    assert t.startswith("$\\begin{array}") and t.endswith("$")


def test_symbolic_results_render_with_conditions():
    G = exactlti.ss([[0, 1], ["-k/m", "-c/m"]], [[0], ["1/m"]], [[1, 0]],
                    params={"m": None, "c": None, "k": None})
    for r in (G.tf(), G.scb(), G.minreal(), G.jordan(), G.poles(), G.zeros()):
        h, _ = shown(r)
    # the symbolic transfer function's report names its field and its conditions
    h, t = shown(G.tf())
    assert "\\mathbf{Q}\\left(c, k, m\\right)" in h and "conditions" in h
    assert t.startswith("$") and "\\frac{c}{m}" in t


def test_html_escapes_user_names():
    G = exactlti.ss([[-1]], [[1]], [[1]], [[0]])
    r = G.run("tf")
    h, _ = shown(r)
    assert "<b>" not in h.replace("<strong>", "")


def chains_hold(d, A):
    """N v_1 = 0 and N v_j = v_(j-1) for every chain step, N = A - theta I with theta of
    the step's eigenvalue (the kernel-sequence step of the same part)."""
    theta = {s.part: sympy.sympify(s["theta"].replace("^", "**")) for s in d.find("kernel_sequence")}
    checked = 0
    for s in d.find("chain"):
        V = mat(s["V"])
        N = A - theta[s.part] * sympy.eye(A.rows)
        assert N * V[:, 0] == sympy.zeros(A.rows, 1)
        assert any(x != 0 for x in V[:, 0])
        for j in range(1, V.cols):
            assert N * V[:, j] == V[:, j - 1]
        checked += 1
    return checked


def test_jordan_steps_yaw_plane_chains():
    G = exactlti.load(os.path.join(DATA, "yaw-plane-single-wheel.json"))
    d = G.steps("jordan")
    assert d.verified and d.field == "QQ"
    assert d.kinds()[:2] == ["charpoly", "factorization"]
    A = G.A.to_sympy()
    assert chains_hold(d, A) == 2
    # the three zero roots in ONE block (Segre characteristic [3])
    segre = [s["segre"] for s in d.find("weyr_segre")]
    assert [3] in segre and [1] in segre
    # chi_A(A) = 0 from the step's own data
    s = sympy.Symbol("s")
    chi = sympy.Poly(sympy.sympify(d.find("charpoly")[0]["chi"].replace("^", "**")), s)
    acc = sympy.zeros(4, 4)
    for c in chi.all_coeffs():
        acc = acc * A + c * sympy.eye(4)
    assert acc == sympy.zeros(4, 4)
    h, t = shown(d)
    assert "<code>chain</code>" in h and "holds exactly" in h
    assert "\\subsection*{Step 1" in t


def test_kalman_steps_identities():
    G = exactlti.load(os.path.join(DATA, "sliding-masses.json"))
    d = G.steps("minreal", method="kalman")
    assert d.verified
    form = d.find("kalman_form")[0]
    T = mat(d.find("kalman_basis")[0]["T"])
    A, B, C = G.A.to_sympy(), G.B.to_sympy(), G.C.to_sympy()
    assert A * T == T * mat(form["At"])
    assert B == T * mat(form["Bt"])
    assert C * T == mat(form["Ct"])
    m = d.find("minimal_part")[0]
    assert m["order"] == 8
    Am, Bm, Cm = mat(m["Am"]), mat(m["Bm"]), mat(m["Cm"])
    for k in range(0, 10):
        assert C * A**k * B == Cm * Am**k * Bm


def test_symbolic_steps_carry_conditions():
    G = exactlti.load(os.path.join(DATA, "dc-motor-lugre.json"), symbolic=[])
    d = exactlti.steps(G, "scb")
    assert d.verified and d.field.startswith("QQ(")
    assert all(s.holds in (None, True) for s in d)
    shown(d)


def test_steps_refusals():
    G = two_states()
    with pytest.raises(ValueError):
        G.steps("pencil")
    with pytest.raises(exactlti.UnsupportedError):
        G.steps("standard")  # not a descriptor system: the library says why (a refusal)
    with pytest.raises(ValueError):
        G.steps("scb", method="jordan")
