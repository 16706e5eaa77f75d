"""Exact state-space systems and the results of exact operations on them."""

import json
import re
import warnings

from . import _core
from ._convert import ExactnessWarning, entry_text, matrix_text, _FloatNote, system_doc, system_json
from ._exact import AlgebraicNumber, Conditions, Matrix, Polynomial, RationalFunction
from ._values import terms_to_sympy, to_sympy as _value_sympy

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
    "SymbolicJordanResult",
    "SymbolicEigenvalue",
    "Factorization",
    "Factor",
]

from ._api import Operations, run as _run
from ._display import Rendered, report_parts
from ._toolbox import ControlOps
from ._response import ResponseOps
from ._ops import SystemOps

_METHODS = ("kalman", "rosenbrock", "ho-kalman", "jordan")


class StateSpace(Operations, ControlOps, ResponseOps, SystemOps, Rendered):
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
        return Matrix(self._mats()["A"], params=self.params)

    @property
    def B(self):
        return Matrix(self._mats()["B"], params=self.params)

    @property
    def C(self):
        return Matrix(self._mats()["C"], params=self.params)

    @property
    def D(self):
        return Matrix(self._mats()["D"], params=self.params)

    @property
    def E(self):
        """The descriptor matrix given on input (``None`` for a standard system)."""
        e = self._mats()["E"]
        return None if e is None else Matrix(e, params=self.params)

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
        """The ground field of the entries (``QQ``, ``QQ(sqrt(d))``, or ``QQ(m, c)`` with
        symbolic parameters)."""
        return self._core.ground

    @property
    def params(self):
        """The names of the symbolic parameters (empty for a numeric system)."""
        return tuple(self._core.params)

    @property
    def is_symbolic(self):
        """True when the entries are rational functions of symbolic parameters."""
        return bool(self._core.params)

    @property
    def symbols(self):
        """The symbolic parameters as SymPy Symbols."""
        import sympy

        return tuple(sympy.Symbol(p) for p in self.params)

    def subs(self, values=None, **kw):
        """The system with values for (some of) its symbolic parameters (exact: ints,
        Fractions, decimal strings, SymPy numbers); parameters left out stay symbols.

        >>> import exactlti
        >>> G = exactlti.ss([[0, 1], ["-k/m", "-c/m"]], [[0], ["1/m"]], [[1, 0]],
        ...                 params={"m": None, "c": None, "k": None})
        >>> G.field
        'QQ(c, k, m)'
        >>> H = G.subs(m=2, k="0.5")
        >>> H.field, H.A[1, 0]
        ('QQ(c)', '-1/4')
        >>> H.subs(c=1).A[1, 1]
        Fraction(-1, 2)
        """
        vals = dict(values or {})
        vals.update(kw)
        unknown = sorted(set(map(str, vals)) - set(self.params))
        if unknown:
            raise ValueError(
                "subs: unknown parameter%s %s (the system's parameters: %s)"
                % ("s" if len(unknown) > 1 else "", ", ".join(unknown),
                   ", ".join(self.params) or "none")
            )
        m = self._mats()
        mats = {k: _exact_rows(m[k]) for k in ("A", "B", "C", "D")}
        params = {p: vals.get(p) for p in self.params}
        text, symbolic = system_json("subs", mats, params, stacklevel=3)
        return StateSpace(_core.load_json(text, "subs", symbolic))

    # -- exact operations -------------------------------------------------------------

    @property
    def _extension(self):
        """Entries in a quadratic field Q(i) / Q(sqrt d) (not Q, no symbols)."""
        return not self.is_symbolic and self.field != "QQ"

    def minreal(self, method="kalman", max_seconds=None, descriptor=False):
        """Exact minimal realization: a controllable and observable system with the same
        transfer matrix (Markov parameters checked exactly, ``verified``).

        ``method``: ``"kalman"`` (default), ``"rosenbrock"``, ``"ho-kalman"``, or
        ``"jordan"`` (modal form, stages ``original -> after dropping modes -> minimal``),
        on every field through the library's one entry point (as ``minreal --method``):
        over Q, Q(sqrt d) and Q(i) the modal form; over Q(p) the primary blocks over Q(p)
        (a system, with its ``conditions``).

        >>> import exactlti
        >>> G = exactlti.ss([[-1, 0], [0, -2]], [[1], [0]], [[1, 1]], [[0]])
        >>> r = G.minreal()
        >>> r.nstates, r.verified
        (1, True)
        >>> r.A
        Matrix(1x1,
        [-1])
        """
        if descriptor:
            return _run(self, "minreal", "--descriptor", max_seconds=max_seconds)
        if method == "era":
            return self.era(max_seconds=max_seconds)
        if method not in _METHODS:
            raise ValueError(
                "unknown method '%s' (%s)" % (method, ", ".join(_METHODS + ("era",)))
            )
        res = MinrealResult(self._core.minreal(method, max_seconds), self)
        if res._rendered is None:
            res._source = (self, "minreal", "--method", method)
        if res.system is None:
            return res
        return MinrealSystem(res, self)

    def zeros(self, max_seconds=None):
        """Invariant zeros as exact algebraic numbers (repeated by multiplicity).

        >>> import exactlti
        >>> G = exactlti.ss([[0, 1], [-2, -3]], [[0], [1]], [[3, 1]], [[0]])
        >>> z = G.zeros()
        >>> [str(x) for x in z], z.polynomial.coeffs
        (['-3'], [Fraction(3, 1), Fraction(1, 1)])
        """
        if self._extension:
            return _run(self, "zeros", max_seconds=max_seconds)
        d = self._core.zeros(max_seconds)
        if self.is_symbolic:
            f = Factorization(d)
            f._source = (self, "zeros")
            return f
        if d["roots"] is None:
            raise _core.UnsupportedError(
                "the invariant-zero polynomial %s is not rational: roots over this field "
                "are not supported yet" % d["polynomial"]["text"]
            )
        r = Roots(d["roots"])
        r.report, r._rendered = report_parts(d)
        r.polynomial = Polynomial(d["polynomial"])
        r.normal_rank = d["normal_rank"]
        return r

    def poles(self, max_seconds=None):
        """Eigenvalues of ``A`` as exact algebraic numbers (repeated by multiplicity):
        real ones ascending, then complex ones by real and imaginary part. With symbolic
        parameters: the :class:`Factorization` of ``det(sI - A)`` over ``Q(params)``."""
        d = self._core.poles(max_seconds)
        r = Factorization(d) if self.is_symbolic else Roots(d)
        r._source = (self, "modes")  # shown as the modal table of the poles
        return r

    def charpoly(self):
        """``det(sI - A)`` (exact)."""
        if self.is_symbolic:
            return self.poles().polynomial
        j = self._core.jordan(False, None)
        return Polynomial(j["charpoly"])

    def jordan(self, real=False, max_seconds=None):
        """Exact Jordan form of ``A``: ``A T = T J`` (``real=True``: real Jordan form with
        2x2 blocks ``[[a, b], [-b, a]]`` and real ``T``). See :func:`exactlti.jordan`.
        For a descriptor system (``E`` given) the finite part of the pencil ``sE - A``
        (``A`` of the result is the standard form's), with ``infinite_blocks``."""
        if self._extension:
            a = ("--real",) if real else ()
            return _run(self, "jordan", *a, max_seconds=max_seconds)
        d = self._core.jordan(real, max_seconds)
        if self.is_symbolic:
            r = SymbolicJordanResult(d)
            r._source = (self, "jordan")
            return r
        return JordanResult(d)

    def scb(self, max_seconds=None):
        """Special coordinate basis (Sannuti–Saberi / Chen): the SCB system with the
        transformations ``x^ = Gamma1 x``, ``y^ = Gamma2 y``, ``u^ = Gamma3 u``; ``dims`` are
        ``(n_a, n_b, n_c, n_d)``; exact identities checked (``verified``)."""
        r = ScbResult(self._core.scb(max_seconds))
        if r._rendered is None:
            r._source = (self, "scb")
        return r

    def mnf(self, max_seconds=None):
        """Mechanical normal form: ``M q'' + L q' + K q = F u`` with ``T A = A~ T``,
        ``T B = B~`` and equal Markov parameters (``verified``), or ``exists=False`` with
        the reason. Over every field (Q, Q(sqrt d), Q(i), symbols), as the command line's
        ``mnf``."""
        r = MnfResult(self._core.mnf(max_seconds))
        if r._rendered is None:
            r._source = (self, "mnf")
        return r

    def modes(self, max_seconds=None):
        """The modal table: eigenvalue, frequency, damping ratio, time constant, period.
        Over Q, Q(sqrt d) and Q(i) a :class:`ModalTable` (each eigenvalue a certified
        algebraic number: ``eigenvalue``, ``minpoly``, ``approx``); with symbolic parameters
        (the modes as formulas: the factors of ``det(sI - A)`` over Q(p) with
        ``omega_n^2``, ``2 zeta omega_n``) a :class:`Report`."""
        if self.is_symbolic:
            return _run(self, "modes", max_seconds=max_seconds)
        return ModalTable(self._core.modes(max_seconds))

    def tf(self, max_seconds=None):
        """Exact transfer matrix ``G(s) = C (sI - A)^-1 B + D`` (entries in lowest terms);
        ``G(z)``, written in ``z``, for a discrete-time system."""
        r = TransferMatrix(self._core.tf(max_seconds), self.dt)
        r._source = (self, "tf")
        return r

    def steps(self, command, method=None, real=False, expand=False, max_seconds=None,
              normalize=None, descriptor=False):
        """The derivation of ``command`` (``"jordan"``, ``"minreal"``, ``"scb"``,
        ``"zeros"``, ``"tf"``, ``"standard"``, ``"mnf"``) step by step: a
        :class:`Derivation` (see :func:`exactlti.steps`; ``normalize`` for ``jordan``,
        ``descriptor`` for ``minreal``)."""
        from ._steps import steps

        return steps(self, command, method=method, real=real, expand=expand,
                     max_seconds=max_seconds, normalize=normalize, descriptor=descriptor)

    def markov(self, count, max_seconds=None):
        """Markov parameters ``C A^k B`` for ``k = 0 .. count-1``."""
        return [Matrix(m, params=self.params) for m in self._core.markov(int(count), max_seconds)]

    def ctrb(self, max_seconds=None):
        """Controllability matrix ``[B, AB, ..., A^(n-1) B]`` (exact)."""
        return Matrix(self._core.ctrb(max_seconds), params=self.params)

    def obsv(self, max_seconds=None):
        """Observability matrix ``[C; CA; ...; CA^(n-1)]`` (exact)."""
        return Matrix(self._core.obsv(max_seconds), params=self.params)

    def check(self, max_seconds=None):
        """The floating-point path beside the exact one: McMillan degree, controllability
        and observability ranks, eigenvalue error; each float answer with its ``Truth``.

        >>> import exactlti
        >>> c = exactlti.ss([[0, 1], [-2, -3]], [[0], [1]], [[1, 0]], [[0]]).check()
        >>> c.agree
        True
        """
        text, _verified, _agree, latex, html, _values = self._core.check(max_seconds)
        r = CheckResult.of_report(json.loads(text))
        r._rendered = {"latex": latex, "html": html}
        return r

    def freqresp(self, omega):
        """Frequency response ``G(j w)`` in floating point at the angular frequencies
        ``omega`` (rad/s; for a descriptor system on the pencil, ``C (jwE - A)^-1 B + D``), as a complex numpy array of shape ``(noutputs, ninputs,
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

    def balred(self, order):
        """Balanced truncation to ``order`` states on the float path (python-control's
        ``balred(sys, order)``, square-root method): a dict with numpy ``A``, ``B``,
        ``C``, ``D``, the ``hankel_singular_values`` (decreasing) and ``error_bound``
        (``2 sum`` of the discarded ones, a bound on the H-infinity error). Needs a
        stable continuous-time system."""
        import numpy as np

        if self.isdtime():
            raise ValueError("balred: a continuous-time system is needed (this one has dt)")
        d = self._core.balred(int(order))
        out = {k: np.array(d[k], dtype=float).reshape(len(d[k]), -1) for k in "ABCD"}
        n = int(order)
        out["A"] = out["A"].reshape(n, n)
        out["B"] = out["B"].reshape(n, self.ninputs)
        out["C"] = out["C"].reshape(self.noutputs, n)
        out["hankel_singular_values"] = list(d["hankel_singular_values"])
        out["error_bound"] = d["error_bound"]
        return out

    def to_control(self):
        """The system as a ``control.StateSpace`` (floating point), with its sample time
        ``dt`` and signal names."""
        import control

        kw = {"dt": float(self.dt)}
        ins, outs = self._core.signal_names
        if ins:
            kw["inputs"] = list(ins)
        if outs:
            kw["outputs"] = list(outs)
        return control.ss(
            self.A.to_numpy(), self.B.to_numpy(), self.C.to_numpy(), self.D.to_numpy(), **kw
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

    def _render(self):
        if self._rendered is None:
            self._rendered = self._core.render()
        return self._rendered


def _exact_rows(m):
    """Reader text of a matrix from the core's plain data (rational pairs or exact text)."""
    if m.get("q") is not None:
        return [["%d/%d" % (p, q) for (p, q) in row] for row in m["q"]]
    if m["nrows"] and not m["ncols"]:
        return [[] for _ in range(m["nrows"])]
    return [list(r) for r in m["exact"]]


def _params_arg(params, parameters):
    if params is not None and parameters is not None:
        raise TypeError("give params or parameters, not both")
    return params if params is not None else parameters


def ss(
    A,
    B=None,
    C=None,
    D=None,
    E=None,
    params=None,
    name="ss",
    parameters=None,
    symbols=(),
    dt=None,
    inputs=None,
    outputs=None,
):
    """An exact state-space system ``E x' = A x + B u``, ``y = C x + D u``.

    Entries may be ints, ``Fraction``, ``Decimal``, decimal or fraction strings
    (``"0.08"`` is 2/25, ``"1/3"``), expression strings over ``params`` (``"-k/m"``,
    ``"sqrt(2)"``), SymPy numbers, numpy integer arrays, or MATLAB-style strings
    (``"[0 1; -2 -3]"``). Binary floats are read as the shortest decimals they print as,
    with an :class:`ExactnessWarning`. ``B``, ``C``, ``D`` default to empty/zero matrices.
    A descriptor system (``E``) is converted to standard form exactly.

    Symbolic parameters: a parameter with value ``None`` (``params={"m": None}``), a name
    in ``symbols``, or a SymPy ``Symbol`` in the entries stays a symbol; the entries are
    then rational functions of the symbols (field ``QQ(m, ...)``) and the results carry
    ``conditions``, the polynomials in the parameters they assume nonzero.
    ``parameters`` is another name for ``params``.

    ``dt``: the sample time of a discrete-time system ``x[k+1] = A x[k] + B u[k]`` (an exact
    number, ``0``/``None`` continuous time; python-control's ``ss(A, B, C, D, dt)``);
    ``inputs``, ``outputs``: signal names.

    Bad input raises ``ValueError`` with the command line's one-line message:

    >>> import exactlti
    >>> exactlti.ss([[0, 1], ["-k", 0]])
    Traceback (most recent call last):
    ...
    ValueError: ss: key A, row 2, column 1: unknown parameter 'k'
    >>> exactlti.ss([[0, 1], ["-k", 0]], params={"k": "0.5"}).A[1, 0]
    Fraction(-1, 2)

    With symbols (SymPy or strings):

    >>> import sympy
    >>> m, k = sympy.symbols("m k", positive=True)
    >>> G = exactlti.ss([[0, 1], [-k / m, 0]], [[0], [1 / m]], [[1, 0]])
    >>> G.field, G.params
    ('QQ(k, m)', ('k', 'm'))
    >>> G.A.to_sympy()
    Matrix([
    [   0, 1],
    [-k/m, 0]])
    """
    params = _params_arg(params, parameters)
    text, symbolic = system_json(
        name, {"A": A, "B": B, "C": C, "D": D, "E": E}, params, symbols
    )
    G = StateSpace(_core.load_json(text, name, symbolic))
    if dt or inputs is not None or outputs is not None:
        G = G.with_signals(inputs, outputs, dt or None)
    return G


# -- transfer functions ---------------------------------------------------------------

# a number (or a closing parenthesis) directly before a name or an opening parenthesis:
# the implicit multiplication of "3s" and "2(s + 1)" (not the exponent of "1e-3")
_IMPLICIT = re.compile(r"(?<=[0-9.)])\s*(?=(?![eE][+-]?[0-9])[A-Za-z_(])")


def _expr_text(x, where, note):
    """A rational function of ``s`` as reader text: a string (``"(s+1)/(s^2+3s+2)"``,
    implicit products allowed), a SymPy expression, or a number."""
    if isinstance(x, str):
        return _IMPLICIT.sub("*", x.replace("**", "^"))
    return entry_text(x, where, note)


def _coeffs(x):
    """Coefficients (highest power first) from a list, a numpy array or a scalar."""
    if hasattr(x, "tolist"):
        x = x.tolist()
    if isinstance(x, (list, tuple)):
        return list(x)
    return [x]


def _poly_text(cs, where, note, var="s"):
    cs = _coeffs(cs)
    if not cs:
        raise ValueError("%s: an empty list of coefficients" % where)
    n = len(cs) - 1
    terms = []
    for k, c in enumerate(cs):
        t = entry_text(c, where, note)
        p = n - k
        terms.append("(%s)" % t + ("" if p == 0 else "*" + var if p == 1 else "*%s^%d" % (var, p)))
    return " + ".join(terms)


def _ratio_text(num, den, where, note, var="s"):
    return "(%s)/(%s)" % (_poly_text(num, where, note, var), _poly_text(den, where, note, var))


def _depth(x):
    d = 0
    while isinstance(x, (list, tuple)) or hasattr(x, "tolist") and hasattr(x, "shape"):
        if hasattr(x, "tolist"):
            x = x.tolist()
        if not x:
            return d + 1
        x, d = x[0], d + 1
    return d


def _tf_rows(num, den, note, var="s"):
    """Rows of entry text of the transfer matrix ``G`` (in ``var``: ``s``, or ``z`` with a
    sample time)."""
    if den is not None:
        # python-control's idiom: coefficient lists, highest power first; MIMO as lists
        # of lists of coefficient lists
        if _depth(num) >= 3 or _depth(den) >= 3:
            num, den = [[_coeffs(c) for c in r] for r in num], [[_coeffs(c) for c in r] for r in den]
            if len(num) != len(den) or any(len(a) != len(b) for a, b in zip(num, den)):
                raise ValueError("tf: num and den must have the same shape")
            return [
                [
                    _ratio_text(n, d, "G row %d, column %d" % (i + 1, j + 1), note, var)
                    for j, (n, d) in enumerate(zip(rn, rd))
                ]
                for i, (rn, rd) in enumerate(zip(num, den))
            ]
        return [[_ratio_text(num, den, "G", note, var)]]
    if isinstance(num, (list, tuple)):
        rows = num if num and isinstance(num[0], (list, tuple)) and not _is_pair(num[0]) else [num]
        out = []
        for i, row in enumerate(rows):
            r = []
            for j, x in enumerate(row):
                where = "G row %d, column %d" % (i + 1, j + 1)
                if _is_pair(x):
                    r.append(_ratio_text(x[0], x[1], where, note, var))
                else:
                    r.append(_expr_text(x, where, note))
            out.append(r)
        return out
    return [[_expr_text(num, "G", note)]]


def _is_pair(x):
    """A ``(num, den)`` pair of coefficient lists (or scalars)."""
    return isinstance(x, tuple) and len(x) == 2


def tf(num, den=None, params=None, name="tf", realize="as_written", dt=None):
    """An exact system from a transfer function or matrix ``G(s)``, realized as written
    (python-control's and MATLAB's ``tf``: nothing cancelled, ``poles()`` lists every
    written denominator's roots; ``.minreal()`` cancels) or, with ``realize="minimal"``,
    its exact minimal realization (order = McMillan degree). Both are checked against ``G``.

    As written: each input column gets the common denominator of its entries (their least
    common multiple, python-control's per-input common denominator) in controllable
    companion form, so ``det(sI - A)`` is the product of the column denominators and the
    Markov parameters are those of ``G`` exactly. Text is evaluated without cancelling
    (``(s+1)/((s+1)*(s+2))`` keeps the pole -1); a SymPy expression arrives as SymPy
    simplified it.

    * ``tf(num, den)``: coefficient lists, highest power first (python-control's idiom);
      MIMO: ``num[i][j]``, ``den[i][j]`` coefficient lists.
    * ``tf("(s+1)/(s^2+3s+2)")``: a rational function of ``s`` as text (``3s`` is
      ``3*s``) or a SymPy expression in ``s``.
    * ``tf([[g11, g12], [g21, g22]])``: MIMO, each entry text, SymPy, or a
      ``(num, den)`` pair of coefficient lists.
    * a python-control ``TransferFunction`` (floats read as the decimals they print as).

    ``dt``: the sample time of a discrete-time ``G(z)`` (python-control's ``tf(num, den,
    dt)``): coefficient lists are then in powers of ``z`` and text is written in ``z``.

    Coefficients are exact as in :func:`ss`; other names in the text take ``params``.
    ``G`` must be proper (an improper ``G`` has no state-space realization).

    >>> import exactlti
    >>> G = exactlti.tf([1, 1], [1, 3, 2])
    >>> G.nstates, [str(p) for p in G.poles()]
    (2, ['-2', '-1'])
    >>> print(G.tf()[0, 0])
    (1)/(s + 2)
    >>> Gm = G.minreal()
    >>> Gm.nstates, [str(p) for p in Gm.poles()]
    (1, ['-2'])
    >>> exactlti.tf([1, 1], [1, 3, 2], realize="minimal").nstates
    1
    >>> H = exactlti.tf("(s+1)/((s+1)*(s+2))")
    >>> H.nstates, H.tf().mcmillan_degree, H.tf().verified
    (2, 1, True)
    >>> M = exactlti.tf([["1/(s+1)", "1/(s+2)"], [([1], [1, 1]), 0]])
    >>> M.ninputs, M.noutputs, M.tf().mcmillan_degree
    (2, 2, 2)
    """
    try:
        import control
    except ImportError:  # pragma: no cover - python-control is optional
        control = None
    if realize not in ("as_written", "minimal"):
        raise ValueError(
            'tf: realize must be "as_written" (keep every written denominator, the '
            'default) or "minimal" (cancel common factors), not %r' % (realize,)
        )
    if control is not None and isinstance(num, control.TransferFunction):
        return _from_control_tf(num, name, realize=realize)
    note = _FloatNote()
    var = "z" if dt else "s"
    rows = _tf_rows(num, den, note, var)
    doc = {"name": name, "G": rows, "realize": realize}
    if dt:
        doc["dt"] = entry_text(dt, "dt", note)
    if params:
        doc["parameters"] = {str(k): entry_text(v, "parameter %s" % k, note) for k, v in params.items()}
    note.symbols.discard(var)
    if note.symbols:
        raise _core.UnsupportedError(
            "tf: symbolic parameters (%s) in a transfer matrix are not supported yet; "
            "give them values in params, or build the system with ss(...)"
            % ", ".join(sorted(note.symbols))
        )
    _warn_floats(note, 3)
    return StateSpace(_core.load_json(json.dumps(doc), name, False))


def _warn_floats(note, stacklevel):
    if note.examples:
        warnings.warn(
            "binary floats were read as the shortest decimals they print as (%s); "
            "pass strings or Fractions to say exactly what you mean"
            % ", ".join(note.examples),
            ExactnessWarning,
            stacklevel=stacklevel + 1,
        )


def _from_control_tf(sys, name, tol=None, realize="as_written"):
    if sys.dt is True:
        raise ValueError(
            "from_control: the sample time is unspecified (dt=True); give the number"
        )
    note = _FloatNote(tol)
    var = "z" if sys.dt else "s"
    rows = [
        [
            _ratio_text(
                sys.num[i][j], sys.den[i][j], "G row %d, column %d" % (i + 1, j + 1), note, var
            )
            for j in range(sys.ninputs)
        ]
        for i in range(sys.noutputs)
    ]
    _warn_floats(note, 4)
    _warn_chosen(note.chosen, tol, 4)
    doc = {"name": name, "G": rows, "realize": realize}
    if sys.dt:
        doc["dt"] = entry_text(sys.dt, "dt", note)
    G = StateSpace(_core.load_json(json.dumps(doc), name, False))
    G.rationalized = note.chosen
    return G


def load(path, at=None, symbolic=None):
    """Reads a system file (JSON or TOML) as the command line does: parameters with
    value ``null`` and those named in ``symbols`` stay symbols; ``at`` gives values first
    (a dict, the command line's ``--at``); ``symbolic`` names parameters kept as symbols
    (a list; ``[]``: every parameter; the command line's ``--symbolic``).

    >>> import exactlti, json, os, tempfile
    >>> p = os.path.join(tempfile.mkdtemp(), "two.json")
    >>> _ = open(p, "w").write(json.dumps({"A": [[0, 1], [-2, "-0.5"]], "B": [[0], [1]], "C": [[1, 0]]}))
    >>> G = exactlti.load(p)
    >>> G.A[1, 1], G.nstates, G.ninputs, G.noutputs
    (Fraction(-1, 2), 2, 1, 1)
    """
    pairs = None
    if at:
        note = _FloatNote()
        pairs = [(str(k), entry_text(v, "at %s" % k, note)) for k, v in at.items()]
        _warn_floats(note, 2)
    syms = None if symbolic is None else [str(x) for x in symbolic]
    return StateSpace(_core.load_file(str(path), pairs, syms))


def jordan(A, real=False, max_seconds=None, params=None):
    """Exact Jordan decomposition ``A T = T J`` of a square matrix.

    Eigenvalues are exact algebraic numbers (``minpoly``, ``value``, ``approx``) with
    their multiplicities and Jordan ``blocks``; entries of ``J`` and ``T`` that are not
    rational are exact in the eigenvalue's field (symbols ``r<k>`` for roots of degree 3
    and more). With symbolic parameters (``params={"a": None}`` or SymPy symbols) the
    result is a :class:`SymbolicJordanResult`.

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
    >>> import sympy
    >>> a = sympy.Symbol("a")
    >>> s = exactlti.jordan([[a, 1], [0, a]])
    >>> s.J.to_sympy(), s.blocks, s.verified
    (Matrix([
    [a, 1],
    [0, a]]), [('a', 2)], True)
    """
    text, symbolic = system_json("jordan", {"A": A}, params)
    core = _core.load_json(text, "jordan", symbolic)
    d = core.jordan(real, max_seconds)
    if not symbolic:
        return JordanResult(d)
    r = SymbolicJordanResult(d)
    r._source = (StateSpace(core), "jordan")
    return r


def from_control(sys, name="from_control", tol=None):
    """An exact system from a python-control ``StateSpace`` or ``TransferFunction`` (read
    through :func:`tf`: its exact minimal realization). Floats are read as the shortest
    decimals they print as (``0.1`` is 1/10), with an :class:`ExactnessWarning`.

    ``tol`` (an absolute tolerance >= 0): rationalise instead: each float ``x`` becomes the simplest
    rational (smallest denominator, by continued fractions) within ``[x - tol, x + tol]``,
    so round-off such as ``0.30000000000000004`` or ``1/3`` computed in floats comes back
    as ``3/10`` and ``1/3``. The choices are reported: the result's ``rationalized`` is the
    list of ``(float, Fraction)`` pairs that differ from the float's exact value (empty
    when every float was already exact), and an :class:`ExactnessWarning` shows the first
    three.

    >>> import control, exactlti, warnings
    >>> P = control.ss([[0, 1], [-1/3, -0.1 - 0.2]], [[0], [1]], [[1, 0]], [[0]])
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     G = exactlti.from_control(P, tol=1e-9)
    >>> G.A[1, 0], G.A[1, 1], G.rationalized[0][1]
    (Fraction(-1, 3), Fraction(-3, 10), Fraction(-1, 3))
    """
    import control

    if isinstance(sys, control.TransferFunction):
        return _from_control_tf(sys, name, tol)
    if not isinstance(sys, control.StateSpace):
        raise TypeError("from_control expects a control.StateSpace or TransferFunction")
    if sys.dt is True:
        raise ValueError(
            "from_control: the sample time is unspecified (dt=True); give the number"
        )
    if tol is None:
        text, _ = system_json(
            name, {"A": sys.A, "B": sys.B, "C": sys.C, "D": sys.D}, stacklevel=3
        )
        chosen = []
    else:
        note = _FloatNote(tol)
        doc = {"name": name}
        for key, m in (("A", sys.A), ("B", sys.B), ("C", sys.C), ("D", sys.D)):
            rows = matrix_text(m, key, note)
            if rows is not None:
                doc[key] = rows
        chosen = note.chosen
        _warn_chosen(chosen, tol, 3)
        text = json.dumps(doc)
    G = StateSpace(_core.load_json(text, name, False))
    dt = sys.dt if sys.dt else None
    G = G.with_signals(list(sys.input_labels), list(sys.output_labels), dt)
    G.rationalized = chosen
    return G


def _warn_chosen(chosen, tol, stacklevel):
    """The :class:`ExactnessWarning` of ``from_control(..., tol=)``: the rationals chosen."""
    if chosen:
        warnings.warn(
            "floats rationalised within tol=%g (%d entries; %s); the result's "
            "`rationalized` lists them all"
            % (
                float(tol),
                len(chosen),
                ", ".join("%r -> %s" % (x, r) for x, r in chosen[:3]),
            ),
            ExactnessWarning,
            stacklevel=stacklevel + 1,
        )


# -- results ------------------------------------------------------------------------


class Roots(list, Rendered):
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



class Eigenvalue(AlgebraicNumber):
    """An eigenvalue of a Jordan form: an :class:`AlgebraicNumber` with
    ``algebraic_multiplicity``, ``geometric_multiplicity`` and Jordan ``blocks``."""

    def __init__(self, d):
        super().__init__(d, symbol=d["symbol"])
        self.algebraic_multiplicity = d["algebraic_multiplicity"]
        self.geometric_multiplicity = d["geometric_multiplicity"]
        self.blocks = list(d["blocks"])


class JordanResult(Rendered):
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
        self.report, self._rendered = report_parts(d)
        # a descriptor system: sizes of the Jordan blocks at s = infinity (J, T, A are the
        # finite part's)
        self.infinite_blocks = list(d.get("infinite_blocks", []))

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



class MinrealSystem(StateSpace):
    """The exact minimal realization as a system (``G.minreal()``): every
    :class:`StateSpace` method, the input/output names and ``dt`` of the original, and the
    realization's facts: ``original_order``, ``method``, ``T``, ``verified``, ``stages``,
    ``conditions``, ``result`` (the :class:`MinrealResult`, the report stays reachable).

    >>> import exactlti
    >>> G = exactlti.ss([[-1, 0], [0, -2]], [[1], [0]], [[1, 1]], [[0]], dt="1/10")
    >>> M = G.minreal()
    >>> M.nstates, M.verified, M.dt
    (1, True, Fraction(1, 10))
    """

    def __init__(self, res, original):
        ins, outs = original._core.signal_names
        StateSpace.__init__(self, res.system._core.with_signals(ins, outs, original._core.dt))
        self.result = res
        self.original_order = res.original_order
        self.method = res.method
        self.T = res.T
        self.verified = res.verified
        self.stages = res.stages
        self.report = res.report
        self.conditions = res.conditions
        self.original = original
        self.system = self

    def __repr__(self):
        return "MinrealSystem(method=%s, %d -> %d states, verified=%s)" % (
            self.method,
            self.original_order,
            self.nstates,
            self.verified,
        )

    def _render(self):
        return self.result._render()


class MinrealResult(Rendered):
    """A minimal realization: ``system`` (a :class:`StateSpace`), ``nstates`` (the McMillan
    degree), ``original_order``, ``method``, ``T`` (the state map when the method gives
    one), ``verified`` (controllable, observable, equal Markov parameters, exactly) and,
    for ``method="jordan"``, ``stages`` (e.g. 20 -> 16 -> 8 for the sliding masses).
    With symbolic parameters: ``conditions`` (see :class:`Conditions`): the result holds
    wherever none of them vanishes (here both modes ``-a`` and ``-1`` are excited and
    seen, so the order is 2 where ``a != 1``; at ``a = 1`` they merge into one mode of
    order 1).

    >>> import exactlti
    >>> G = exactlti.ss([["-a", 0], [0, -1]], [[1], [1]], [[1, 1]], params={"a": None})
    >>> r = G.minreal()
    >>> r.nstates, r.verified, r.conditions
    (2, True, Conditions(a - 1 != 0))
    """

    def __init__(self, d, original):
        sys_core = d["system"]
        self.system = StateSpace(sys_core) if sys_core is not None else None
        self.nstates = d["order"]
        self.original_order = d["original_order"]
        self.method = d["method"]
        self.params = tuple(d.get("params", ()))
        self.T = Matrix(d["T"], params=self.params) if d["T"] is not None else None
        self.verified = d["verified"]
        self.stages = tuple(d["stages"]) if "stages" in d else None
        self.report, self._rendered = report_parts(d)
        self.conditions = Conditions(d.get("conditions", ()), self.params, d.get("condition_values"))
        self.original = original
        self._values = d.get("values")

    def _mat(self, key):
        if self.system is not None:
            return getattr(self.system, key)
        # the modal (Jordan-method) realization: exact entries in real number fields, built
        # from their values (the report's text is shown only)
        approx = self.report.get(key + "_approx")
        if approx and approx and isinstance(approx[0][0] if approx[0] else 0.0, list):
            approx = [[tuple(z) for z in r] for r in approx]
        elif approx:
            approx = [[(float(x), 0.0) for x in r] for r in approx]
        return Matrix._from_values(self._values[key], self.report[key], approx)

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



class ScbResult(Rendered):
    """Special coordinate basis: ``A``..``D`` (SCB form), ``Gamma1``..``Gamma3``, ``U``,
    ``Y``, ``dims = (n_a, n_b, n_c, n_d)``, ``chains``, ``m0``, ``left_invertible``,
    ``right_invertible``, ``zero_polynomial``, ``minimum_phase``, ``verified``: the
    identities ``Gamma1 B_scb = B U Gamma3``, ``Gamma2 C_scb = Y^-1 C Gamma1``,
    ``Gamma2 D_scb = Y^-1 D U Gamma3`` and ``Gamma1 A_scb = (A - B0 C0) Gamma1`` (``B0``,
    ``C0``: the feedthrough part) hold exactly. With symbolic parameters also
    ``conditions`` and ``zero_factors`` (``minimum_phase`` is then ``None``: it depends on
    the parameters' signs)."""

    _MATS = ("A", "B", "C", "D", "Gamma1", "Gamma2", "Gamma3", "U", "Y")

    def __init__(self, d):
        self.params = tuple(d.get("params", ()))
        for k in self._MATS:
            setattr(self, k, Matrix(d[k], params=self.params))
        self.dims = tuple(d["dims"])
        self.chains = list(d["chains"])
        self.m0 = d["m0"]
        self.left_invertible = d["left_invertible"]
        self.right_invertible = d["right_invertible"]
        self.zero_polynomial = Polynomial(d["zero_polynomial"], self.params)
        #: True/False; None when it depends on the parameters (or there is no answer)
        self.minimum_phase = d.get("minimum_phase")
        self.verified = d["verified"]
        self.report, self._rendered = report_parts(d)
        self.conditions = Conditions(d.get("conditions", ()), self.params, d.get("condition_values"))
        #: symbolic: the invariant-zero polynomial's factors over Q(params)
        self.zero_factors = (
            [Factor(f, self.params) for f in d["zero_factors"]] if "zero_factors" in d else None
        )

    @property
    def nstates(self):
        return self.A.nrows

    def __repr__(self):
        return "ScbResult(dims=(n_a, n_b, n_c, n_d)=%s, chains=%s, verified=%s)" % (
            self.dims,
            self.chains,
            self.verified,
        )



class MnfResult(Rendered):
    """Mechanical normal form: ``exists`` (and ``reason`` when not), ``M``, ``L``, ``K``,
    ``F``, ``C``, ``D``, the state map ``T`` with ``A_tilde``, ``B_tilde``, ``verified``."""

    _MATS = ("M", "L", "K", "F", "C", "D", "T", "A_tilde", "B_tilde")

    def __init__(self, d):
        self.exists = d["exists"]
        self.reason = d["reason"]
        self.verified = d["verified"]
        self.report, self._rendered = report_parts(d)
        self.params = tuple(d.get("params", ()))
        self.conditions = Conditions(d.get("conditions", ()), self.params, d.get("condition_values"))
        for k in self._MATS:
            setattr(self, k, Matrix(d[k], params=self.params) if k in d else None)

    @property
    def nstates(self):
        return None if self.T is None else self.T.nrows

    def __repr__(self):
        if not self.exists:
            return "MnfResult(exists=False, reason=%r)" % self.reason
        return "MnfResult(exists=True, n2=%d, verified=%s)" % (self.M.nrows, self.verified)



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


class ModalTable(list, Rendered):
    """The modal table: a list of :class:`Mode`."""

    def __init__(self, d):
        super().__init__(Mode(m) for m in d["modes"])
        self.report, self._rendered = report_parts(d)


class TransferMatrix(Rendered):
    """Exact transfer matrix in lowest terms: ``G[i, j]`` is a :class:`RationalFunction`;
    ``mcmillan_degree`` (the order of a verified minimal realization); ``verified`` (every
    entry's expansion at infinity equals ``D, CB, CAB, ...``). With symbolic parameters:
    ``pole_polynomial``, ``pole_factors`` and ``conditions``.

    >>> import exactlti, sympy
    >>> G = exactlti.ss([[0, 1], ["-k/m", "-c/m"]], [[0], ["1/m"]], [[1, 0]],
    ...                 params={"m": None, "c": None, "k": None}).tf()
    >>> c, k, m, s = sympy.symbols("c k m s")
    >>> sympy.cancel(G[0, 0].to_sympy() * (m*s**2 + c*s + k))
    1
    >>> G.mcmillan_degree, G.verified, G.conditions
    (2, True, Conditions(m != 0))
    """

    def __init__(self, d, dt=None):
        self.params = tuple(d.get("params", ()))
        #: ``s``, or ``z`` for a discrete-time system (sample time ``dt``)
        self.variable = d.get("variable", "s")
        self.dt = dt or 0
        self.entries = [
            [RationalFunction(n, den, self.params) for (n, den) in row] for row in d["entries"]
        ]
        self.mcmillan_degree = d["mcmillan_degree"]
        self.verified = d["verified"]
        self.conditions = Conditions(d.get("conditions", ()), self.params, d.get("condition_values"))
        self.pole_polynomial = (
            Polynomial(d["pole_polynomial"], self.params) if "pole_polynomial" in d else None
        )
        self.pole_factors = (
            [Factor(f, self.params) for f in d["pole_factors"]] if "pole_factors" in d else None
        )

    @property
    def shape(self):
        return (len(self.entries), len(self.entries[0]) if self.entries else 0)

    def __getitem__(self, ij):
        i, j = ij
        return self.entries[i][j]

    def to_sympy(self, var=None):
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
        if self.dt:
            return control.tf(num, den, float(self.dt))
        return control.tf(num, den)

    def __repr__(self):
        return "TransferMatrix(%s)" % [[str(h) for h in row] for row in self.entries]



class Factor:
    """An irreducible factor over ``Q(params)`` of a polynomial in ``s`` with its
    ``multiplicity``; ``root`` is its root (exact text) when the factor is linear."""

    def __init__(self, d, params=()):
        self.params = tuple(params)
        self.factor = Polynomial(d["factor"], self.params)
        self.multiplicity = d["multiplicity"]
        self.root = d.get("root")
        self._root_value = d.get("root_value")

    @property
    def degree(self):
        return self.factor.degree

    def to_sympy(self, var="s"):
        """The factor as a SymPy expression in ``var``."""
        return self.factor.to_sympy(var)

    def root_sympy(self):
        """The root of a linear factor in SymPy (``None`` for a factor of higher degree)."""
        if self._root_value is None:
            return None
        return _value_sympy(self._root_value)

    def __repr__(self):
        m = "^%d" % self.multiplicity if self.multiplicity > 1 else ""
        return "Factor((%s)%s)" % (self.factor, m)


class Factorization(Rendered):
    """A polynomial in ``s`` over ``Q(params)`` (symbolic poles or zeros): ``polynomial``,
    its irreducible ``factors`` (:class:`Factor`), ``roots`` (those in ``Q(params)``, from
    the linear factors, repeated by multiplicity) and ``conditions``.

    >>> import exactlti
    >>> G = exactlti.ss([["-a", 1], [0, "-b"]], [[0], [1]], [[1, 0]],
    ...                 params={"a": None, "b": None})
    >>> p = G.poles()
    >>> p.roots, p.complete
    (['-a', '-b'], True)
    >>> p.to_sympy()
    [-a, -b]
    """

    def __init__(self, d):
        self.params = tuple(d.get("params", ()))
        self.polynomial = Polynomial(d["polynomial"], self.params)
        self.factors = [Factor(f, self.params) for f in d["factors"]]
        self.conditions = Conditions(d.get("conditions", ()), self.params, d.get("condition_values"))
        self.normal_rank = d.get("normal_rank")

    @property
    def roots(self):
        return [f.root for f in self.factors if f.root is not None for _ in range(f.multiplicity)]

    @property
    def complete(self):
        """True when every factor is linear (every root lies in ``Q(params)``)."""
        return all(f.root is not None for f in self.factors)

    def to_sympy(self):
        """The roots in ``Q(params)`` as SymPy expressions (see ``complete``)."""
        return [
            f.root_sympy() for f in self.factors if f.root is not None for _ in range(f.multiplicity)
        ]

    def __repr__(self):
        return "Factorization(%s)" % " * ".join(repr(f) for f in self.factors)


class SymbolicEigenvalue:
    """An eigenvalue of a matrix over ``Q(params)``: ``value`` (exact text) when it lies in
    ``Q(params)``, else ``None`` and the root of the irreducible ``factor`` (text in the
    parameters and ``var``) of ``degree`` >= 2; multiplicities and Jordan ``blocks``."""

    def __init__(self, d, params, var):
        self.value = d["value"]
        self._value = d.get("value_v")
        self.factor = d["factor"]
        self._factor_terms = d.get("factor_terms")
        self.degree = d["degree"]
        self.algebraic_multiplicity = d["algebraic_multiplicity"]
        self.geometric_multiplicity = d["geometric_multiplicity"]
        self.blocks = list(d["blocks"])
        self.params = tuple(params)
        self.var = var

    def to_sympy(self):
        """The value in SymPy (``None`` for a root of a factor of degree >= 2: see
        :meth:`factor_sympy`)."""
        if self._value is None:
            return None
        return _value_sympy(self._value)

    def factor_sympy(self):
        """The irreducible factor as a SymPy expression in ``var`` and the parameters
        (built from its terms)."""
        return terms_to_sympy(self._factor_terms, self.params + (self.var,))

    def __str__(self):
        return self.value if self.value is not None else "root of %s" % self.factor

    def __repr__(self):
        return "SymbolicEigenvalue(%s)" % self


class SymbolicJordanResult(Rendered):
    """The Jordan structure of a matrix over ``Q(params)``: ``A T = T J`` with ``J``, ``T``
    exact rational functions (``to_sympy()``); ``eigenvalues``
    (:class:`SymbolicEigenvalue`); ``blocks`` as ``(eigenvalue, size)`` pairs;
    ``complete`` (every eigenvalue in ``Q(params)``: ``J`` is the Jordan matrix; else the
    block of a factor of degree >= 2 is ``A`` restricted to its generalized eigenspace);
    ``conditions`` (the result holds where none of them vanishes); ``verified``
    (``A T = T J`` as rational functions and ``det T != 0``).

    >>> import exactlti
    >>> r = exactlti.jordan([[0, 1], ["-k", "-c"]], params={"k": None, "c": None})
    >>> r.complete, [str(e) for e in r.eigenvalues], r.verified
    (False, ['root of c*s + s^2 + k'], True)
    """

    def __init__(self, d):
        self.params = tuple(d.get("params", ()))
        self.var = d["var"]
        self.eigenvalues = [SymbolicEigenvalue(e, self.params, self.var) for e in d["eigenvalues"]]
        self.A = Matrix(d["A"], params=self.params)
        self.J = Matrix(d["J"], params=self.params)
        self.T = Matrix(d["T"], params=self.params)
        self.charpoly = Polynomial(d["charpoly"], self.params)
        self.complete = d["complete"]
        self.verified = d["verified"]
        self.exact = True
        self.conditions = Conditions(d.get("conditions", ()), self.params, d.get("condition_values"))
        self.field = d.get("field")
        self.notes = list(d.get("notes", []))
        # a descriptor system: sizes of the Jordan blocks at s = infinity
        self.infinite_blocks = list(d.get("infinite_blocks", []))

    @property
    def nstates(self):
        return self.A.nrows

    @property
    def blocks(self):
        return [(str(e), b) for e in self.eigenvalues for b in e.blocks]

    def check(self):
        """Re-checks ``A T = T J`` in SymPy (rational functions), independently of the
        library."""
        import sympy

        A, T, J = self.A.to_sympy(), self.T.to_sympy(), self.J.to_sympy()
        return all(sympy.cancel(x) == 0 for x in A * T - T * J) and sympy.cancel(T.det()) != 0

    def __repr__(self):
        return "SymbolicJordanResult(n=%d, field=%s, eigenvalues=[%s], verified=%s)" % (
            self.nstates,
            self.field,
            ", ".join(str(e) for e in self.eigenvalues),
            self.verified,
        )



class CheckResult(list, Rendered):
    """Items ``{what, exact, float, float_truth, agree, detail}``, one per comparison of the
    command line's ``check`` (``mcmillan_degree``, ``controllability_rank``,
    ``observability_rank``, ``era_order``, ``jordan_structure``, ...; ``exact``, ``float``
    and ``float_truth`` are ``None`` where a comparison has no single count, ``detail`` is
    the comparison as the report gives it); ``agree`` is True when the float path agrees
    with the exact one on every item. ``report``: the command's report."""

    #: the report's name of a comparison -> the item's ``what`` (the McMillan degree is the
    #: exact minimal order)
    _NAMES = {"minreal_order": "mcmillan_degree"}

    def __init__(self, items, report=None):
        super().__init__(items)
        self.report = report

    @classmethod
    def of_report(cls, report):
        """The items of ``check``'s report (its ``comparisons``)."""
        items = []
        for name, d in report.get("comparisons", {}).items():
            items.append({
                "what": cls._NAMES.get(name, name),
                "exact": d.get("exact"),
                "float": d.get("float"),
                "float_truth": d.get("float_truth"),
                "agree": bool(d.get("agree")),
                "detail": d,
            })
        return cls(items, report)

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
