"""Exact state-space systems and the results of exact operations on them."""

import json
import warnings

from . import _core
from ._convert import ExactnessWarning, system_json
from ._exact import AlgebraicNumber, Matrix, Polynomial, RationalFunction

__all__ = [
    "StateSpace",
    "ss",
    "tf",
    "jordan",
    "load",
    "from_control",
    "JordanResult",
    "MinrealResult",
    "ScbResult",
    "MnfResult",
    "ModalTable",
    "Roots",
    "TransferMatrix",
    "CheckResult",
]

_METHODS = ("kalman", "rosenbrock", "ho-kalman", "jordan")


def _latex_section(title, items):
    """A small LaTeX block (``\\text`` lines and matrices) for Jupyter."""
    parts = ["\\text{%s}" % title]
    for name, value in items:
        if isinstance(value, Matrix):
            parts.append("%s = %s" % (name, value.latex()))
        else:
            parts.append("\\text{%s: %s}" % (name, str(value).replace("_", "\\_")))
    return "$\\begin{gathered}" + " \\\\ ".join(parts) + "\\end{gathered}$"


class StateSpace:
    """An exact LTI system ``x' = A x + B u``, ``y = C x + D u`` (E given: ``E x' = ...``,
    converted to this standard form on input).

    Build one with :func:`ss`, :func:`load` or :func:`from_control`. Entries are exact:
    ``"0.08"`` is 2/25. Every method computes exactly, releases the GIL while it works, can
    be interrupted with Ctrl-C and takes ``max_seconds`` (``TimeoutError`` when exceeded).

    >>> import exactlti
    >>> G = exactlti.ss([[0, 1], [-2, -3]], [[0], [1]], [[1, 0]], [[0]])
    >>> G.nstates, G.ninputs, G.noutputs
    (2, 1, 1)
    >>> [str(p) for p in G.poles()]
    ['-2', '-1']
    >>> print(G.tf()[0, 0])
    (1)/(s^2 + 3*s + 2)
    """

    def __init__(self, core):
        if not isinstance(core, _core.System):
            raise TypeError("use exactlti.ss(A, B, C, D) to build a system")
        self._core = core
        self._m = None

    def _mats(self):
        if self._m is None:
            self._m = self._core.matrices()
        return self._m

    @property
    def A(self):
        return Matrix(self._mats()["A"])

    @property
    def B(self):
        return Matrix(self._mats()["B"])

    @property
    def C(self):
        return Matrix(self._mats()["C"])

    @property
    def D(self):
        return Matrix(self._mats()["D"])

    @property
    def E(self):
        """The descriptor matrix given on input (``None`` for a standard system)."""
        e = self._mats()["E"]
        return None if e is None else Matrix(e)

    @property
    def nstates(self):
        return self._core.shape[0]

    @property
    def ninputs(self):
        return self._core.shape[1]

    @property
    def noutputs(self):
        return self._core.shape[2]

    @property
    def field(self):
        """The ground field of the entries (``QQ`` or ``QQ(sqrt(d))``)."""
        return self._core.ground

    # -- exact operations -------------------------------------------------------------

    def minreal(self, method="kalman", max_seconds=None):
        """Exact minimal realization: a controllable and observable system with the same
        transfer matrix (Markov parameters checked exactly, ``verified``).

        ``method``: ``"kalman"`` (default), ``"rosenbrock"``, ``"ho-kalman"``, or
        ``"jordan"`` (modal form, stages ``original -> after dropping modes -> minimal``).

        >>> import exactlti
        >>> G = exactlti.ss([[-1, 0], [0, -2]], [[1], [0]], [[1, 1]], [[0]])
        >>> r = G.minreal()
        >>> r.nstates, r.verified
        (1, True)
        >>> r.A
        Matrix(1x1,
        [-1])
        """
        if method not in _METHODS:
            raise ValueError(
                "unknown method '%s' (%s)" % (method, ", ".join(_METHODS))
            )
        return MinrealResult(self._core.minreal(method, max_seconds), self)

    def zeros(self, max_seconds=None):
        """Invariant zeros as exact algebraic numbers (repeated by multiplicity).

        >>> import exactlti
        >>> G = exactlti.ss([[0, 1], [-2, -3]], [[0], [1]], [[3, 1]], [[0]])
        >>> z = G.zeros()
        >>> [str(x) for x in z], z.polynomial.coeffs
        (['-3'], [Fraction(3, 1), Fraction(1, 1)])
        """
        d = self._core.zeros(max_seconds)
        if d["roots"] is None:
            raise _core.UnsupportedError(
                "the invariant-zero polynomial %s is not rational: roots over this field "
                "are not supported yet" % d["polynomial"]["text"]
            )
        r = Roots(d["roots"])
        r.polynomial = Polynomial(d["polynomial"])
        r.normal_rank = d["normal_rank"]
        return r

    def poles(self, max_seconds=None):
        """Eigenvalues of ``A`` as exact algebraic numbers (repeated by multiplicity):
        real ones ascending, then complex ones by real and imaginary part."""
        return Roots(self._core.poles(max_seconds))

    def charpoly(self):
        """``det(sI - A)`` (exact)."""
        j = self._core.jordan(False, None)
        return Polynomial(j["charpoly"])

    def jordan(self, real=False, max_seconds=None):
        """Exact Jordan form of ``A``: ``A T = T J`` (``real=True``: real Jordan form with
        2x2 blocks ``[[a, b], [-b, a]]`` and real ``T``). See :func:`exactlti.jordan`."""
        return JordanResult(self._core.jordan(real, max_seconds))

    def scb(self, max_seconds=None):
        """Special coordinate basis (Sannuti–Saberi / Chen): the SCB system with the
        transformations ``x^ = Gamma1 x``, ``y^ = Gamma2 y``, ``u^ = Gamma3 u``; ``dims`` are
        ``(n_a, n_b, n_c, n_d)``; exact identities checked (``verified``)."""
        return ScbResult(self._core.scb(max_seconds))

    def mnf(self, max_seconds=None):
        """Mechanical normal form: ``M q'' + L q' + K q = F u`` with ``T A = A~ T``,
        ``T B = B~`` and equal Markov parameters (``verified``), or ``exists=False`` with
        the reason."""
        return MnfResult(self._core.mnf(max_seconds))

    def modes(self, max_seconds=None):
        """The modal table: eigenvalue, frequency, damping ratio, time constant, period."""
        return ModalTable(self._core.modes(max_seconds))

    def tf(self, max_seconds=None):
        """Exact transfer matrix ``G(s) = C (sI - A)^-1 B + D`` (entries in lowest terms)."""
        return TransferMatrix(self._core.tf(max_seconds))

    def markov(self, count, max_seconds=None):
        """Markov parameters ``C A^k B`` for ``k = 0 .. count-1``."""
        return [Matrix(m) for m in self._core.markov(int(count), max_seconds)]

    def ctrb(self, max_seconds=None):
        """Controllability matrix ``[B, AB, ..., A^(n-1) B]`` (exact)."""
        return Matrix(self._core.ctrb(max_seconds))

    def obsv(self, max_seconds=None):
        """Observability matrix ``[C; CA; ...; CA^(n-1)]`` (exact)."""
        return Matrix(self._core.obsv(max_seconds))

    def check(self, max_seconds=None):
        """The floating-point path beside the exact one: McMillan degree, controllability
        and observability ranks, eigenvalue error; each float answer with its ``Truth``.

        >>> import exactlti
        >>> c = exactlti.ss([[0, 1], [-2, -3]], [[0], [1]], [[1, 0]], [[0]]).check()
        >>> c.agree
        True
        """
        return CheckResult(self._core.check(max_seconds))

    def freqresp(self, omega):
        """Frequency response ``G(j w)`` in floating point at the angular frequencies
        ``omega`` (rad/s), as a complex numpy array of shape ``(noutputs, ninputs,
        len(omega))`` (python-control's layout)."""
        import numpy as np

        w = np.atleast_1d(np.asarray(omega, dtype=float))
        g = self._core.freqresp([float(x) for x in w])
        out = np.empty((self.noutputs, self.ninputs, len(w)), dtype=complex)
        for k, m in enumerate(g):
            for i, row in enumerate(m):
                for j, (re, im) in enumerate(row):
                    out[i, j, k] = complex(re, im)
        return out

    def to_control(self):
        """The system as a ``control.StateSpace`` (floating point)."""
        import control

        return control.ss(
            self.A.to_numpy(), self.B.to_numpy(), self.C.to_numpy(), self.D.to_numpy()
        )

    def to_sympy(self):
        """``(A, B, C, D)`` as SymPy matrices."""
        return tuple(m.to_sympy() for m in (self.A, self.B, self.C, self.D))

    def __repr__(self):
        return "StateSpace(nstates=%d, ninputs=%d, noutputs=%d, field=%s)" % (
            self.nstates,
            self.ninputs,
            self.noutputs,
            self.field,
        )

    def _repr_latex_(self):
        return _latex_section(
            "StateSpace over %s" % self.field,
            [("A", self.A), ("B", self.B), ("C", self.C), ("D", self.D)],
        )


def ss(A, B=None, C=None, D=None, E=None, params=None, name="ss"):
    """An exact state-space system ``E x' = A x + B u``, ``y = C x + D u``.

    Entries may be ints, ``Fraction``, ``Decimal``, decimal or fraction strings
    (``"0.08"`` is 2/25, ``"1/3"``), expression strings over ``params`` (``"-k/m"``,
    ``"sqrt(2)"``), SymPy numbers, numpy integer arrays, or MATLAB-style strings
    (``"[0 1; -2 -3]"``). Binary floats are read as the shortest decimals they print as,
    with an :class:`ExactnessWarning`. ``B``, ``C``, ``D`` default to empty/zero matrices.
    A descriptor system (``E``) is converted to standard form exactly.

    Bad input raises ``ValueError`` with the command line's one-line message:

    >>> import exactlti
    >>> exactlti.ss([[0, 1], ["-k", 0]])
    Traceback (most recent call last):
    ...
    ValueError: ss: key A, row 2, column 1: unknown parameter 'k'
    >>> exactlti.ss([[0, 1], ["-k", 0]], params={"k": "0.5"}).A[1, 0]
    Fraction(-1, 2)
    """
    text = system_json(name, {"A": A, "B": B, "C": C, "D": D, "E": E}, params)
    return StateSpace(_core.load_json(text, name))


def tf(*args, **kwargs):
    """Transfer-matrix input is not available yet.

    The library reads systems in state-space, descriptor and second-order form; reading
    a transfer matrix ``G(s)`` is being added. Until then build the system with
    :func:`ss` (or convert with python-control and use :func:`from_control`), and get
    its exact transfer matrix with ``StateSpace.tf()``.
    """
    raise NotImplementedError(
        "exactlti.tf: transfer-matrix input is not available yet (the library reads "
        "state-space, descriptor and second-order systems); build the system with "
        "exactlti.ss(A, B, C, D) and use .tf() for its exact transfer matrix"
    )


def load(path):
    """Reads a system file (JSON or TOML, as the command line does).

    >>> import exactlti, json, os, tempfile
    >>> p = os.path.join(tempfile.mkdtemp(), "two.json")
    >>> _ = open(p, "w").write(json.dumps({"A": [[0, 1], [-2, "-0.5"]], "B": [[0], [1]], "C": [[1, 0]]}))
    >>> G = exactlti.load(p)
    >>> G.A[1, 1], G.nstates, G.ninputs, G.noutputs
    (Fraction(-1, 2), 2, 1, 1)
    """
    return StateSpace(_core.load_file(str(path)))


def jordan(A, real=False, max_seconds=None, params=None):
    """Exact Jordan decomposition ``A T = T J`` of a square matrix.

    Eigenvalues are exact algebraic numbers (``minpoly``, ``value``, ``approx``) with
    their multiplicities and Jordan ``blocks``; entries of ``J`` and ``T`` that are not
    rational are exact in the eigenvalue's field (symbols ``r<k>`` for roots of degree 3
    and more).

    >>> import exactlti
    >>> r = exactlti.jordan([[-2, 0, 0], [0, 0, 1], [0, -2, -2]])
    >>> [str(e) for e in r.eigenvalues], r.verified
    (['-2', '-1 + i', '-1 - i'], True)
    >>> r.J.to_sympy()
    Matrix([
    [-2,      0,      0],
    [ 0, -1 + I,      0],
    [ 0,      0, -1 - I]])
    >>> [(str(e), size) for e, size in exactlti.jordan([[1, 1], [0, 1]]).blocks]
    [('1', 2)]
    """
    text = system_json("jordan", {"A": A}, params)
    return JordanResult(_core.load_json(text, "jordan").jordan(real, max_seconds))


def from_control(sys, name="from_control"):
    """An exact system from a python-control ``StateSpace`` (or ``TransferFunction``,
    converted by python-control's ``ss`` first). Floats are read as the shortest
    decimals they print as (``0.1`` is 1/10), with an :class:`ExactnessWarning`."""
    import control

    if isinstance(sys, control.TransferFunction):
        sys = control.ss(sys)
    if not isinstance(sys, control.StateSpace):
        raise TypeError("from_control expects a control.StateSpace or TransferFunction")
    if not sys.isctime():
        raise ValueError("from_control: only continuous-time systems are supported")
    text = system_json(
        name, {"A": sys.A, "B": sys.B, "C": sys.C, "D": sys.D}, stacklevel=3
    )
    return StateSpace(_core.load_json(text, name))


# -- results ------------------------------------------------------------------------


class Roots(list):
    """A list of :class:`AlgebraicNumber` (each repeated by its multiplicity)."""

    def __init__(self, items):
        out = []
        for d in items:
            a = AlgebraicNumber(d)
            out.extend([a] * d.get("multiplicity", 1))
        super().__init__(out)

    def to_sympy(self):
        return [a.to_sympy() for a in self]

    def to_numpy(self):
        import numpy as np

        return np.array([complex(a) for a in self], dtype=complex)

    def _repr_latex_(self):
        import sympy

        return "$%s$" % sympy.latex(self.to_sympy())


class Eigenvalue(AlgebraicNumber):
    """An eigenvalue of a Jordan form: an :class:`AlgebraicNumber` with
    ``algebraic_multiplicity``, ``geometric_multiplicity`` and Jordan ``blocks``."""

    def __init__(self, d):
        super().__init__(d, symbol=d["symbol"])
        self.algebraic_multiplicity = d["algebraic_multiplicity"]
        self.geometric_multiplicity = d["geometric_multiplicity"]
        self.blocks = list(d["blocks"])


class JordanResult:
    """``A T = T J``: ``J``, ``T`` exact, ``eigenvalues`` (:class:`Eigenvalue`),
    ``blocks`` as ``(eigenvalue, size)`` pairs, ``verified`` (the identities held
    exactly), ``exact`` (False only when a real-form block had to be approximated)."""

    def __init__(self, d):
        self.eigenvalues = [Eigenvalue(e) for e in d["eigenvalues"]]
        symbols = {e.symbol: e for e in self.eigenvalues if e.symbol}
        self.J = Matrix(d["J"], symbols)
        self.T = Matrix(d["T"], symbols)
        self.A = Matrix(d["A"])
        self.charpoly = Polynomial(d["charpoly"])
        self.verified = d["verified"]
        self.exact = d["exact"]
        self.notes = list(d["notes"])
        self.report = json.loads(d["report"])

    @property
    def nstates(self):
        return self.A.nrows

    @property
    def blocks(self):
        return [(e, b) for e in self.eigenvalues for b in e.blocks]

    def check(self):
        """Re-checks ``A T = T J`` exactly in SymPy, independently of the library: the
        entries are polynomials in the root symbols ``r<k>`` (and radicals), reduced
        modulo each symbol's minimal polynomial."""
        import sympy

        A = self.A.to_sympy()
        T = self.T.to_sympy(keep_symbols=True)
        J = self.J.to_sympy(keep_symbols=True)
        minpolys = {}
        for e in self.eigenvalues:
            if e.symbol:
                s = sympy.Symbol(e.symbol)
                minpolys[s] = e.minpoly.to_sympy(s)
        for x in A * T - T * J:
            x = sympy.expand(x)
            for s in x.free_symbols:
                if s not in minpolys:
                    return False
                x = sympy.expand(sympy.rem(x, minpolys[s], s))
            if x != 0:
                return False
        return True

    def approx(self, digits=None):
        """``(J, T)`` approximately (numpy, or SymPy with ``digits``)."""
        return self.J.approx(digits), self.T.approx(digits)

    def __repr__(self):
        return "JordanResult(n=%d, eigenvalues=[%s], verified=%s)" % (
            self.nstates,
            ", ".join(str(e) for e in self.eigenvalues),
            self.verified,
        )

    def _repr_latex_(self):
        return _latex_section(
            "Jordan form A T = T J (verified: %s)" % self.verified,
            [("J", self.J), ("T", self.T)],
        )


class _TextRoot:
    """A root given as ``root of POLY near APPROX`` (the library's display)."""

    def __init__(self, text):
        self.text = text

    def to_sympy(self):
        import sympy

        if not self.text.startswith("root of ") or " near " not in self.text:
            return sympy.sympify(self.text.replace("^", "**"), locals={"i": sympy.I})
        poly_text, near = self.text[len("root of "):].split(" near ", 1)
        x = sympy.Symbol("x")
        poly = sympy.Poly(sympy.sympify(poly_text.replace("^", "**"), locals={"x": x}), x)
        target = complex(sympy.sympify(near.replace("i", "I")))
        roots = [sympy.CRootOf(poly, k) for k in range(poly.degree())]
        return min(roots, key=lambda r: abs(complex(r.evalf(30)) - target))


class MinrealResult:
    """A minimal realization: ``system`` (a :class:`StateSpace`), ``nstates`` (the McMillan
    degree), ``original_order``, ``method``, ``T`` (the state map when the method gives
    one), ``verified`` (controllable, observable, equal Markov parameters, exactly) and,
    for ``method="jordan"``, ``stages`` (e.g. 20 -> 16 -> 8 for the sliding masses)."""

    def __init__(self, d, original):
        sys_core = d["system"]
        self.system = StateSpace(sys_core) if sys_core is not None else None
        self.nstates = d["order"]
        self.original_order = d["original_order"]
        self.method = d["method"]
        self.T = Matrix(d["T"]) if d["T"] is not None else None
        self.verified = d["verified"]
        self.stages = tuple(d["stages"]) if "stages" in d else None
        self.report = json.loads(d["report"])
        self.original = original

    def _mat(self, key):
        if self.system is not None:
            return getattr(self.system, key)
        # the modal (Jordan-method) realization: exact entries in real number fields
        approx = self.report.get(key + "_approx")
        if approx and approx and isinstance(approx[0][0] if approx[0] else 0.0, list):
            approx = [[tuple(z) for z in r] for r in approx]
        elif approx:
            approx = [[(float(x), 0.0) for x in r] for r in approx]
        symbols = {}
        for line in self.report.get("symbols", []):
            name, _, definition = line.partition(" = ")
            symbols[name.strip()] = _TextRoot(definition)
        return Matrix._from_strings(self.report[key], approx, symbols)

    @property
    def A(self):
        return self._mat("A")

    @property
    def B(self):
        return self._mat("B")

    @property
    def C(self):
        return self._mat("C")

    @property
    def D(self):
        return self._mat("D")

    def __repr__(self):
        st = " stages=%s" % (self.stages,) if self.stages else ""
        return "MinrealResult(method=%s, %d -> %d states,%s verified=%s)" % (
            self.method,
            self.original_order,
            self.nstates,
            st,
            self.verified,
        )

    def _repr_latex_(self):
        return _latex_section(
            "minimal realization (%s): %d -> %d states, verified: %s"
            % (self.method, self.original_order, self.nstates, self.verified),
            [("A", self.A), ("B", self.B), ("C", self.C), ("D", self.D)],
        )


class ScbResult:
    """Special coordinate basis: ``A``..``D`` (SCB form), ``Gamma1``..``Gamma3``, ``U``,
    ``Y``, ``dims = (n_a, n_b, n_c, n_d)``, ``chains``, ``m0``, ``left_invertible``,
    ``right_invertible``, ``zero_polynomial``, ``minimum_phase``, ``verified``."""

    _MATS = ("A", "B", "C", "D", "Gamma1", "Gamma2", "Gamma3", "U", "Y")

    def __init__(self, d):
        for k in self._MATS:
            setattr(self, k, Matrix(d[k]))
        self.dims = tuple(d["dims"])
        self.chains = list(d["chains"])
        self.m0 = d["m0"]
        self.left_invertible = d["left_invertible"]
        self.right_invertible = d["right_invertible"]
        self.zero_polynomial = Polynomial(d["zero_polynomial"])
        self.minimum_phase = d["minimum_phase"]
        self.verified = d["verified"]
        self.report = json.loads(d["report"])

    @property
    def nstates(self):
        return self.A.nrows

    def __repr__(self):
        return "ScbResult(dims=(n_a, n_b, n_c, n_d)=%s, chains=%s, verified=%s)" % (
            self.dims,
            self.chains,
            self.verified,
        )

    def _repr_latex_(self):
        return _latex_section(
            "special coordinate basis, (n_a, n_b, n_c, n_d) = %s, verified: %s"
            % (self.dims, self.verified),
            [("A", self.A), ("B", self.B), ("C", self.C), ("D", self.D)],
        )


class MnfResult:
    """Mechanical normal form: ``exists`` (and ``reason`` when not), ``M``, ``L``, ``K``,
    ``F``, ``C``, ``D``, the state map ``T`` with ``A_tilde``, ``B_tilde``, ``verified``."""

    _MATS = ("M", "L", "K", "F", "C", "D", "T", "A_tilde", "B_tilde")

    def __init__(self, d):
        self.exists = d["exists"]
        self.reason = d["reason"]
        self.verified = d["verified"]
        self.report = json.loads(d["report"])
        for k in self._MATS:
            setattr(self, k, Matrix(d[k]) if k in d else None)

    @property
    def nstates(self):
        return None if self.T is None else self.T.nrows

    def __repr__(self):
        if not self.exists:
            return "MnfResult(exists=False, reason=%r)" % self.reason
        return "MnfResult(exists=True, n2=%d, verified=%s)" % (self.M.nrows, self.verified)

    def _repr_latex_(self):
        if not self.exists:
            return _latex_section("no mechanical normal form", [("reason", self.reason)])
        return _latex_section(
            "mechanical normal form M q'' + L q' + K q = F u (verified: %s)" % self.verified,
            [("M", self.M), ("L", self.L), ("K", self.K), ("F", self.F), ("C", self.C)],
        )


class Mode:
    """One row of the modal table."""

    def __init__(self, d):
        self.eigenvalue = d["eigenvalue"]
        self.minpoly = d["minpoly"]
        self.approx = complex(*d["approx"])
        self.multiplicity = d["multiplicity"]
        self.frequency_hz = d["frequency_hz"]
        self.damping_ratio = d["damping_ratio"]
        self.time_constant_s = d["time_constant_s"]
        self.period_s = d["period_s"]

    def __repr__(self):
        return "Mode(%s, f=%.6g Hz, zeta=%s)" % (
            self.eigenvalue,
            self.frequency_hz,
            "-" if self.damping_ratio is None else "%.6g" % self.damping_ratio,
        )


class ModalTable(list):
    """The modal table: a list of :class:`Mode`."""

    def __init__(self, d):
        super().__init__(Mode(m) for m in d["modes"])
        self.report = json.loads(d["report"])


class TransferMatrix:
    """Exact transfer matrix: ``G[i, j]`` is a :class:`RationalFunction`."""

    def __init__(self, rows):
        self.entries = [[RationalFunction(n, d) for (n, d) in row] for row in rows]

    @property
    def shape(self):
        return (len(self.entries), len(self.entries[0]) if self.entries else 0)

    def __getitem__(self, ij):
        i, j = ij
        return self.entries[i][j]

    def to_sympy(self, var="s"):
        import sympy

        return sympy.Matrix([[h.to_sympy(var) for h in row] for row in self.entries])

    def to_control(self):
        """A ``control.TransferFunction`` with float coefficients."""
        import control

        def coeffs(p):
            if p.coeffs is None:
                raise ValueError("to_control needs rational coefficients")
            return [float(c) for c in reversed(p.coeffs)]

        num = [[coeffs(h.num) for h in row] for row in self.entries]
        den = [[coeffs(h.den) for h in row] for row in self.entries]
        return control.tf(num, den)

    def __repr__(self):
        return "TransferMatrix(%s)" % [[str(h) for h in row] for row in self.entries]

    def _repr_latex_(self):
        import sympy

        return "$%s$" % sympy.latex(self.to_sympy())


class CheckResult(list):
    """Items ``{what, exact, float, float_truth, agree}``; ``agree`` is True when the
    float path agrees with the exact one on every item."""

    def __init__(self, items):
        super().__init__(items)

    @property
    def agree(self):
        return all(i["agree"] for i in self)

    def __repr__(self):
        return "CheckResult(%s)" % ", ".join(
            "%s: exact %s, float %s%s" % (
                i["what"],
                i["exact"],
                i["float"],
                "" if i["agree"] else " (DISAGREE)",
            )
            for i in self
        )


# keep the warning class reachable as exactlti.ExactnessWarning
ExactnessWarning = ExactnessWarning
