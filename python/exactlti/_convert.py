"""Python values to exact entry text for the library's system-file reader.

Every entry becomes text the reader parses exactly: ints, ``Fraction`` (``p/q``),
``Decimal`` and decimal strings (``"0.08"`` is 2/25), SymPy numbers (Rationals and
radicals such as ``sqrt(2)``), numpy integers, and expression strings over ``params``.
Binary floats are taken as the shortest decimal that prints as the same float (``0.1`` is
1/10), with an :class:`ExactnessWarning` saying so.
"""

import json
import math
import numbers
import warnings
from decimal import Decimal
from fractions import Fraction


class ExactnessWarning(UserWarning):
    """A float was read as the shortest decimal it prints as (e.g. 0.1 as 1/10)."""


class _FloatNote:
    """What the conversion noticed: floats read as decimals, SymPy symbols met.

    With ``tol`` (a number >= 0) a float ``x`` is read instead as the simplest rational
    (smallest denominator) in ``[x - tol, x + tol]`` (continued fractions), and every such
    choice is kept in ``chosen`` as ``(x, Fraction)``."""

    def __init__(self, tol=None):
        self.examples = []
        self.symbols = set()
        self._objects = {}
        if tol is not None and not (isinstance(tol, numbers.Real) and tol >= 0):
            raise ValueError("tol: expected a number >= 0, got %r" % (tol,))
        self.tol = None if tol is None else Fraction(tol)
        self.chosen = []

    def symbol(self, sym, where):
        """Records a SymPy symbol; two different symbols with one name are refused (the
        reader knows symbols by name, so ``Symbol('x')`` and ``Symbol('x', positive=True)``
        would silently become one)."""
        name = str(sym)
        prev = self._objects.setdefault(name, sym)
        if prev != sym:
            raise ValueError(
                "%s: two different SymPy symbols are both named '%s' (%s and %s, which "
                "differ in their assumptions); give them different names"
                % (where, name, _srepr(prev), _srepr(sym))
            )
        self.symbols.add(name)

    def add(self, x, text):
        if len(self.examples) < 3:
            self.examples.append("%r -> %s" % (x, text))


def simplest_rational(lo, hi):
    """The rational with the smallest denominator (then the smallest absolute value) in
    the closed interval ``[lo, hi]`` of Fractions, by the continued fraction of the
    interval's ends (Stern-Brocot descent; the recursion depth is the length of that
    continued fraction).

    >>> from fractions import Fraction as F
    >>> simplest_rational(F(3, 10) - F(1, 10**9), F(3, 10) + F(1, 10**9))
    Fraction(3, 10)
    >>> simplest_rational(F(-7, 2), F(-3, 1))
    Fraction(-3, 1)
    """
    if lo > hi:
        lo, hi = hi, lo
    if lo <= 0 <= hi:
        return Fraction(0)
    if hi < 0:
        return -simplest_rational(-hi, -lo)
    fl = math.floor(lo)
    if fl == lo or fl + 1 <= hi:
        return Fraction(fl if fl == lo else fl + 1)
    # lo and hi both lie in (fl, fl + 1): descend on the reciprocals of the fractional parts
    return fl + 1 / simplest_rational(1 / (hi - fl), 1 / (lo - fl))


def _float_text(x, where, note):
    if not math.isfinite(x):
        raise ValueError("%s: %r is not a finite number" % (where, x))
    if note.tol is not None:
        exact = Fraction(float(x))
        r = simplest_rational(exact - note.tol, exact + note.tol)
        if r != exact:
            note.chosen.append((float(x), r))
        return "%d/%d" % (r.numerator, r.denominator)
    text = repr(float(x))
    note.add(x, text)
    return text


def _srepr(sym):
    import sympy

    return sympy.srepr(sym)


def _is_sympy(x):
    t = type(x)
    return any(c.__module__.startswith("sympy") for c in t.__mro__)


def _sympy_text(x, where, note):
    if getattr(x, "free_symbols", None):
        # a symbolic parameter: the library reads rational functions of the symbols
        for sym in sorted(x.free_symbols, key=str):
            note.symbol(sym, where)
    elif getattr(x, "is_Rational", False):
        return "%d/%d" % (int(x.p), int(x.q))
    # an algebraic number such as sqrt(2)/2 or 1 + I, or an expression in symbols: the
    # reader evaluates it exactly
    import sympy

    text = sympy.sstr(x).replace("**", "^")
    if not getattr(x, "free_symbols", None):
        text = text.replace("I", "i")
    return text


def entry_text(x, where, note):
    """One exact entry as reader text (``where`` names key, row, column for messages)."""
    if isinstance(x, bool):
        raise ValueError("%s: %r is a bool, not a number" % (where, x))
    if isinstance(x, str):
        return x
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, Fraction):
        return "%d/%d" % (x.numerator, x.denominator)
    if isinstance(x, Decimal):
        if not x.is_finite():
            raise ValueError("%s: %s is not a finite number" % (where, x))
        return str(x)
    if _is_sympy(x):
        return _sympy_text(x, where, note)
    if isinstance(x, numbers.Rational):
        return "%d/%d" % (x.numerator, x.denominator)
    if isinstance(x, numbers.Real):
        return _float_text(float(x), where, note)
    if isinstance(x, numbers.Complex):
        z = complex(x)
        re = _float_text(z.real, where, note)
        im = _float_text(z.imag, where, note)
        return "%s + (%s)*i" % (re, im)
    raise ValueError("%s: %r (%s) is not a number" % (where, x, type(x).__name__))


def matrix_text(m, key, note):
    """A matrix argument as rows of entry text, or a MATLAB-style string as given."""
    if m is None:
        return None
    if isinstance(m, str):
        return m
    if hasattr(m, "tolist") and hasattr(m, "shape"):  # numpy arrays and matrices
        shape = tuple(m.shape)
        dtype = getattr(m, "dtype", None)
        if dtype is not None and dtype.kind == "O":
            m = [list(r) for r in (m if len(shape) == 2 else [m])]
        else:
            m = m.tolist()
        if len(shape) == 0:
            m = [[m]]
        elif len(shape) == 1:
            m = [m]
    elif hasattr(m, "tolist") and hasattr(m, "nrows"):  # our own exact Matrix
        m = m.tolist()
    elif _is_sympy(m) and hasattr(m, "rows") and hasattr(m, "cols"):  # sympy Matrix
        m = m.tolist()
    if not isinstance(m, (list, tuple)):
        m = [[m]]  # a scalar is 1x1
    elif len(m) > 0 and not isinstance(m[0], (list, tuple)) and not hasattr(m[0], "__len__"):
        m = [list(m)]  # a flat list is one row
    rows = []
    for i, row in enumerate(m):
        rows.append(
            [
                entry_text(x, "key %s, row %d, column %d" % (key, i + 1, j + 1), note)
                for j, x in enumerate(row)
            ]
        )
    return rows


def _param_value(k, v, where, note):
    """A parameter's value as reader text, or ``None`` (JSON null) for a symbol."""
    if v is None:
        return None
    if _is_sympy(v) and getattr(v, "is_Symbol", False) and str(v) == str(k):
        note.symbol(v, where)
        return None  # {"m": Symbol("m")}: m stays a symbol
    return entry_text(v, where, note)


def system_doc(name, mats, params=None, symbols=(), warn_floats=True, stacklevel=3):
    """The system file (a dict) for matrices ``{key: value}``, ``params`` (value ``None``:
    a symbol) and ``symbols`` (names kept symbolic); ``symbolic`` is True when a symbol
    is left (SymPy symbols in the entries count)."""
    note = _FloatNote()
    doc = {"name": name}
    if params:
        doc["parameters"] = {
            str(k): _param_value(k, v, "parameter %s" % k, note) for k, v in params.items()
        }
    for key, m in mats.items():
        t = matrix_text(m, key, note)
        if t is not None:
            doc[key] = t
    given = set(doc.get("parameters", {}))
    extra = sorted((note.symbols | set(map(str, symbols))) - given)
    if extra:
        doc["symbols"] = extra
    symbolic = bool(extra) or any(v is None for v in doc.get("parameters", {}).values())
    if note.examples and warn_floats:
        warnings.warn(
            "binary floats were read as the shortest decimals they print as (%s); "
            "pass strings or Fractions to say exactly what you mean"
            % ", ".join(note.examples),
            ExactnessWarning,
            stacklevel=stacklevel,
        )
    return doc, symbolic


def system_json(name, mats, params=None, symbols=(), warn_floats=True, stacklevel=3):
    """``(JSON text, symbolic)`` of :func:`system_doc`."""
    doc, symbolic = system_doc(name, mats, params, symbols, warn_floats, stacklevel + 1)
    return json.dumps(doc), symbolic
