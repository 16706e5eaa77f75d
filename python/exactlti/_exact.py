"""Exact values returned by exactlti: matrices, algebraic numbers, polynomials.

Rationals travel from Rust as integer pairs and become :class:`fractions.Fraction`;
entries of larger fields (``1 - sqrt(2)/2``, ``-1 + i``, polynomials in a root symbol
``r3``) travel as values (``_values``: their structure, never their text), with the
library's exact text and LaTeX for display and a floating-point approximation.
``to_sympy()`` builds SymPy from the values (``CRootOf`` for roots without a closed
form); ``to_numpy()`` gives the approximation.
"""

from fractions import Fraction

from ._values import algebraic_to_sympy, grid_to_sympy, terms_to_sympy, to_sympy as _value_sympy

__all__ = ["Matrix", "AlgebraicNumber", "Polynomial", "RationalFunction", "Conditions"]


def _frac(pq):
    p, q = pq
    return Fraction(p, q) if q != 1 else Fraction(p)


def _latex_frac(x):
    if x.denominator == 1:
        return str(x.numerator)
    sign = "-" if x < 0 else ""
    return "%s\\frac{%d}{%d}" % (sign, abs(x.numerator), x.denominator)


def _sympy():
    try:
        import sympy
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("to_sympy() needs SymPy: pip install sympy") from e
    return sympy


class Conditions(list):
    """The polynomials in the parameters a symbolic result assumes nonzero (pivots,
    divisions, discriminants), as strings; ``to_sympy()`` gives SymPy expressions (built
    from their terms). The result holds for every parameter value at which none of them
    vanishes."""

    def __init__(self, items=(), params=(), values=None):
        super().__init__(str(x) for x in items)
        self.params = tuple(params)
        self._values = list(values) if values is not None else None

    def to_sympy(self):
        if self._values is None:
            if not self:
                return []
            raise TypeError("these conditions carry no values")
        return [terms_to_sympy(t, self.params) for t in self._values]

    def __repr__(self):
        return "Conditions(%s != 0)" % ", ".join(self) if self else "Conditions()"


def _sympy_rational(sympy, p, q):
    if q == 1:
        return sympy.Integer(p)
    return sympy.Rational(p, q)


def _sympy_matrix_fast(sympy, q_rows, shape):
    """A ``sympy.Matrix`` built on SymPy's own representation of rational matrices (a
    sparse ``DomainMatrix`` over ZZ or QQ, as ``sympy.Matrix`` builds for rational
    entries), so no SymPy ``Rational`` object is created until an entry is read. The pairs
    are in lowest terms already, so the domain elements are made without a gcd."""
    from sympy.polys.domains import QQ, ZZ
    from sympy.polys.matrices import DomainMatrix
    from sympy.polys.matrices.sdm import SDM

    integral = all(q == 1 for row in q_rows for (_, q) in row)
    if integral:
        dom, mk = ZZ, ZZ.dtype
        rows = {}
        for i, row in enumerate(q_rows):
            d = {j: mk(p) for j, (p, _) in enumerate(row) if p}
            if d:
                rows[i] = d
    else:
        dom = QQ
        mk = getattr(QQ.dtype, "_new", QQ.dtype)  # PythonMPQ._new skips the gcd
        rows = {}
        for i, row in enumerate(q_rows):
            d = {j: mk(p, q) for j, (p, q) in enumerate(row) if p}
            if d:
                rows[i] = d
    return sympy.Matrix._fromrep(DomainMatrix.from_rep(SDM(rows, shape, dom)))


class Polynomial:
    """A polynomial with exact coefficients, lowest degree first.

    >>> from exactlti import ss
    >>> p = ss([[0, 1], [-2, -3]]).charpoly()
    >>> p.coeffs
    [Fraction(2, 1), Fraction(3, 1), Fraction(1, 1)]
    >>> print(p)
    s^2 + 3*s + 2
    >>> p.degree
    2
    """

    def __init__(self, data, params=()):
        q = data.get("q")
        self.coeffs = [_frac(c) for c in q] if q is not None else None
        self.text = data["text"]
        #: exact text of each coefficient (low degree first) when they are not rational
        self.exact_coeffs = data.get("coeffs")
        self._values = data.get("values")
        self.params = tuple(params)
        #: the variable of the text: ``s``, or ``z`` for a discrete-time system
        self.var = data.get("var", "s")

    @property
    def degree(self):
        if self.coeffs is not None:
            return len(self.coeffs) - 1
        if self.exact_coeffs is not None:
            return len(self.exact_coeffs) - 1
        raise ValueError("the coefficients are not rational: %s" % self.text)

    def to_sympy(self, var=None):
        """The polynomial as a SymPy expression in ``var`` (a name or a Symbol; by default
        its own variable ``s``, or ``z`` in discrete time)."""
        sympy = _sympy()
        var = self.var if var is None else var
        s = sympy.Symbol(var) if isinstance(var, str) else var
        if self.coeffs is None:
            if self._values is None:
                raise TypeError("no exact coefficients: %s" % self.text)
            return sympy.Add(*[_value_sympy(c) * s**k for k, c in enumerate(self._values)])
        return sum(
            (_sympy_rational(sympy, c.numerator, c.denominator) * s**k for k, c in enumerate(self.coeffs)),
            sympy.Integer(0),
        )

    def __call__(self, x):
        if self.coeffs is None:
            raise ValueError("the coefficients are not rational: %s" % self.text)
        acc = 0
        for c in reversed(self.coeffs):
            acc = acc * x + c
        return acc

    def __eq__(self, other):
        if isinstance(other, Polynomial):
            return self.coeffs == other.coeffs and self.text == other.text
        return NotImplemented

    def __str__(self):
        return self.text

    def __repr__(self):
        return "Polynomial(%s)" % self.text

    def _repr_latex_(self):
        return "$%s$" % self.text.replace("*", " ")


class AlgebraicNumber:
    """An exact algebraic number: its minimal polynomial over Q and which root it is.

    ``value`` is the library's exact text (a rational, a closed form up to degree 2, else
    ``root of ... near ...``); ``approx`` a complex approximation read off a certified
    isolating region; ``to_sympy()`` the number in SymPy (``CRootOf`` where needed).

    >>> from exactlti import ss
    >>> p = ss([[0, 1], [-2, 2]]).poles()
    >>> [str(x) for x in p]
    ['1 - i', '1 + i']
    >>> p[1].minpoly.coeffs
    [Fraction(2, 1), Fraction(-2, 1), Fraction(1, 1)]
    >>> p[1].to_sympy()
    1 + I
    >>> r = ss([[0, 2], [1, 0]]).poles()[1]
    >>> r.to_sympy(), r.approx(20)
    (sqrt(2), 1.4142135623730950488)
    >>> c = ss([[0, 0, 2], [1, 0, 0], [0, 1, 0]]).poles()[0]
    >>> c.to_sympy()
    CRootOf(x**3 - 2, 0)
    """

    def __init__(self, data, symbol=None):
        self.minpoly = Polynomial(data["minpoly"])
        self.value = data["value"]
        #: a rational rectangle ((re_lo, re_hi), (im_lo, im_hi)) isolating the root
        self._box = data.get("box")
        re, im = data["approx"]
        self._approx = complex(re, im)
        self.multiplicity = data.get("multiplicity", data.get("algebraic_multiplicity", 1))
        self.symbol = symbol
        self._sympy = None

    @property
    def degree(self):
        return self.minpoly.degree

    @property
    def is_real(self):
        return self._approx.imag == 0.0

    def __complex__(self):
        return self._approx

    def __float__(self):
        if not self.is_real:
            raise TypeError("%s is not real" % self.value)
        return self._approx.real

    def approx(self, digits=None):
        """A floating-point value: ``complex`` by default, or a SymPy Float/complex with
        ``digits`` significant digits (evaluated from the exact root by SymPy)."""
        if digits is None:
            return self._approx if not self.is_real else self._approx.real
        return self.to_sympy().evalf(digits)

    def to_sympy(self):
        """The exact number in SymPy: Rational, a radical form (degree 2) or ``CRootOf``."""
        if self._sympy is not None:
            return self._sympy
        c = [(a.numerator, a.denominator) for a in self.minpoly.coeffs]
        # the root in its isolating rectangle (radicals for degree 2, else CRootOf)
        self._sympy = algebraic_to_sympy(c, self._box, (self._approx.real, self._approx.imag))
        return self._sympy

    def __eq__(self, other):
        if isinstance(other, AlgebraicNumber):
            return self.minpoly.coeffs == other.minpoly.coeffs and self.value == other.value
        if isinstance(other, (int, Fraction)):
            return self.degree == 1 and -self.minpoly.coeffs[0] == Fraction(other)
        return NotImplemented

    def __hash__(self):
        return hash((tuple(self.minpoly.coeffs), self.value))

    def __str__(self):
        return self.value

    def __repr__(self):
        return "AlgebraicNumber(%s)" % self.value

    def _repr_latex_(self):
        try:
            return "$%s$" % _sympy().latex(self.to_sympy())
        except ImportError:  # pragma: no cover
            return "$%s$" % self.value


class Matrix:
    """An exact matrix.

    Rational matrices hold :class:`fractions.Fraction` entries; matrices over larger
    fields (Jordan forms, quadratic fields) hold the exact text of each entry with its
    approximation. Symbols ``r1``, ``r2``, ... stand for the eigenvalues listed with
    them (see :class:`JordanResult`).

    >>> from exactlti import ss
    >>> A = ss([[0, 1], ["-0.08", "1/3"]]).A
    >>> A[1, 0], A.shape
    (Fraction(-2, 25), (2, 2))
    >>> A.to_sympy()
    Matrix([
    [    0,   1],
    [-2/25, 1/3]])
    >>> A.to_numpy()
    array([[ 0.        ,  1.        ],
           [-0.08      ,  0.33333333]])
    """

    __array_priority__ = 0

    def __init__(self, data, symbols=None, params=()):
        self.nrows = data["nrows"]
        self.ncols = data["ncols"]
        self._q = data.get("q")
        self._rows = None
        self._exact = data.get("exact")
        self._latex = data.get("latex")
        self._approx = data.get("approx")
        #: the exact values of the entries (``_values``) when they are not all rational
        self._values = data.get("values")
        self.symbols = symbols or {}
        #: names of the symbolic parameters the entries may contain
        self.params = tuple(params)

    @classmethod
    def _from_strings(cls, exact, approx=None, symbols=None):
        """A matrix shown from its exact text only (a step of a derivation): ``tolist``,
        ``str`` and LaTeX; no ``to_sympy`` (the text is for reading)."""
        return cls._from_values(None, exact, approx, symbols)

    @classmethod
    def _from_values(cls, values, exact, approx=None, symbols=None):
        """A matrix from the values of its entries, with their exact text for display."""
        nrows = len(exact)
        ncols = len(exact[0]) if nrows else 0
        return cls(
            {
                "nrows": nrows,
                "ncols": ncols,
                "values": values,
                "exact": exact,
                "latex": exact,
                "approx": approx,
            },
            symbols,
        )

    @property
    def shape(self):
        return (self.nrows, self.ncols)

    @property
    def is_rational(self):
        """True when every entry is rational (entries are Fractions)."""
        return self._q is not None

    def tolist(self):
        """Rows of Fractions (rational matrices) or of exact strings."""
        if self._q is not None:
            if self._rows is None:
                self._rows = [[_frac(x) for x in row] for row in self._q]
            return [list(r) for r in self._rows]
        return [list(r) for r in self._exact]

    def __getitem__(self, ij):
        i, j = ij
        if self._q is not None:
            return _frac(self._q[i][j])
        return self._exact[i][j]

    def __eq__(self, other):
        if isinstance(other, Matrix):
            return self.shape == other.shape and self.tolist() == other.tolist()
        try:
            rows = [list(r) for r in other]
        except TypeError:
            return NotImplemented
        mine = self.tolist()
        return len(rows) == len(mine) and all(
            len(a) == len(b) and all(x == y for x, y in zip(a, b)) for a, b in zip(mine, rows)
        )

    def __hash__(self):
        return None.__hash__()  # unhashable, like lists

    def to_sympy(self, keep_symbols=False):
        """The exact matrix as a ``sympy.Matrix``.

        Non-rational entries are built from their values: radicals, ``I``, each root
        symbol ``r<k>`` as its eigenvalue (``CRootOf`` where needed), or kept as a SymPy
        ``Symbol`` with ``keep_symbols=True`` (then ``symbols`` gives each one's minimal
        polynomial); rational functions of the parameters from their terms."""
        sympy = _sympy()
        if self._q is not None:
            try:
                return _sympy_matrix_fast(sympy, self._q, self.shape)
            except (ImportError, AttributeError, TypeError):  # pragma: no cover
                pass  # SymPy's internals moved: the public (slower) constructor
            Integer, Rational = sympy.Integer, sympy.Rational
            flat = [
                Integer(p) if q == 1 else Rational(p, q) for row in self._q for (p, q) in row
            ]
            return sympy.Matrix(self.nrows, self.ncols, flat)
        if self._values is None:
            raise TypeError("this matrix carries no exact values")
        flat = grid_to_sympy(self._values, keep_symbols)
        return sympy.Matrix(self.nrows, self.ncols, flat)

    def to_numpy(self):
        """Floating-point approximation (``float64``, or ``complex128`` when needed)."""
        import numpy as np

        if self._q is not None:
            return np.array(
                [[p / q for (p, q) in row] for row in self._q], dtype=float
            ).reshape(self.nrows, self.ncols)
        if self._approx is None:
            raise TypeError(
                "the entries depend on the symbolic parameters %s: no floating-point "
                "value (give values with subs)" % ", ".join(self.params)
            )
        a = np.array(
            [[complex(re, im) for (re, im) in row] for row in self._approx], dtype=complex
        ).reshape(self.nrows, self.ncols)
        if np.all(a.imag == 0):
            return a.real.copy()
        return a

    def approx(self, digits=None):
        """``to_numpy()``; with ``digits``, a SymPy matrix evaluated to that many digits."""
        if digits is None:
            return self.to_numpy()
        return self.to_sympy().evalf(digits)

    def latex(self):
        if self._q is not None:
            rows = [[_latex_frac(x) for x in r] for r in self.tolist()]
        else:
            rows = self._latex
        body = " \\\\ ".join(" & ".join(r) for r in rows)
        return "\\begin{bmatrix} %s \\end{bmatrix}" % body

    def _repr_latex_(self):
        return "$%s$" % self.latex()

    def __str__(self):
        rows = [[str(x) for x in r] for r in self.tolist()]
        if not rows or not rows[0]:
            return "[] (%dx%d)" % self.shape
        w = max(len(x) for r in rows for x in r)
        return "\n".join("[" + "  ".join(x.rjust(w) for x in r) + "]" for r in rows)

    def __repr__(self):
        return "Matrix(%dx%d,\n%s)" % (self.nrows, self.ncols, str(self))


class RationalFunction:
    """One entry ``num(s)/den(s)`` of a transfer matrix (exact coefficients; ``z`` in
    place of ``s`` for a discrete-time system)."""

    def __init__(self, num, den, params=()):
        self.num = Polynomial(num, params)
        self.den = Polynomial(den, params)

    def to_sympy(self, var=None):
        """``num/den`` in SymPy (with symbolic parameters: cancelled to one fraction of
        polynomials in ``var`` and the parameters); ``var`` defaults to ``s`` (``z`` in
        discrete time)."""
        h = self.num.to_sympy(var) / self.den.to_sympy(var)
        if self.num.params:
            h = _sympy().cancel(h)
        return h

    def __str__(self):
        if self.den.text == "1":
            return self.num.text
        return "(%s)/(%s)" % (self.num.text, self.den.text)

    __repr__ = __str__
