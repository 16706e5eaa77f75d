"""Exact values from the Rust layer as SymPy objects.

The Rust bindings hand every exact number over as its structure, never as display text
(the encoding is documented in ``python/src/values.rs``):

- a rational: ``(p, q)``;
- ``a + b*sqrt(d)``: ``("sqrt", a, b, d)``; ``x + y*i``: ``("i", x, y)``;
- a polynomial in a marked root ``t`` of ``g``: ``("ext", [c0, c1, ...], gen)`` with
  ``gen = ("gen", [g0, ..., gd], (re, im), name, radical)`` (``radical = (a0, s, f)`` when
  ``t = a0 + s*sqrt(f)``, else the root of ``g`` nearest the approximation);
- an algebraic number: ``("root", [m0, ..., md], ((re_lo, re_hi), (im_lo, im_hi)))``, the root
  of the minimal polynomial in the rational rectangle;
- ``num/den`` in ``Q(p1, ..., pk)``: ``("rf", (p1, ..., pk), num_terms, den_terms)``, terms
  ``((e1, ..., ek), c)``;
- the real or imaginary part of a value: ``("re", v)``, ``("im", v)``; its negative
  ``("neg", v)``.

Nothing here parses text: SymPy objects are built from integers.
"""

from fractions import Fraction

__all__ = ["to_sympy", "grid_to_sympy", "terms_to_sympy", "algebraic_to_sympy"]


def _sympy():
    try:
        import sympy
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("to_sympy() needs SymPy: pip install sympy") from e
    return sympy


def _rational(sympy, pq):
    p, q = pq
    return sympy.Integer(p) if q == 1 else sympy.Rational(p, q)


def terms_to_sympy(terms, names):
    """An integer polynomial given by its terms ``((e1, ..., ek), c)`` in the variables
    ``names`` (strings or SymPy symbols)."""
    sympy = _sympy()
    syms = [sympy.Symbol(n) if isinstance(n, str) else n for n in names]
    out = []
    for exps, c in terms:
        m = sympy.Integer(c)
        for s, e in zip(syms, exps):
            if e:
                m = m * s**e
        out.append(m)
    return sympy.Add(*out)


def _in_box(z, box):
    (rl, rh), (il, ih) = box
    return (
        Fraction(*rl) <= Fraction(z.real) <= Fraction(*rh)
        and Fraction(*il) <= Fraction(z.imag) <= Fraction(*ih)
    )


def _pick(candidates, approx=None, box=None):
    """The candidate root inside ``box`` (a rational rectangle isolating it), else the one
    nearest ``approx``."""
    best, best_d = None, None
    for r in candidates:
        z = complex(r.evalf(30))
        if box is not None and _in_box(z, box):
            return r
        if approx is not None:
            d = abs(z - complex(*approx))
            if best_d is None or d < best_d:
                best, best_d = r, d
    if best is None:
        if box is not None:
            (rl, rh), (il, ih) = box
            centre = (float(Fraction(*rl) + Fraction(*rh)) / 2, float(Fraction(*il) + Fraction(*ih)) / 2)
            return _pick(candidates, approx=centre)
        raise ValueError("no root matches")
    return best


def _root_of(sympy, coeffs, approx=None, box=None):
    """The root of the polynomial with coefficients ``coeffs`` (SymPy numbers, low degree
    first) marked by ``box`` or ``approx``: rational, radicals for degree 2, else
    ``CRootOf``."""
    x = sympy.Symbol("x")
    if len(coeffs) == 2:
        return -coeffs[0] / coeffs[1]
    poly = sympy.Poly(list(reversed(coeffs)), x)
    if poly.degree() == 2 or not all(c.is_Rational for c in coeffs):
        if poly.degree() > 2:
            raise NotImplementedError(
                "a root of a polynomial of degree %d with irrational coefficients" % poly.degree()
            )
        candidates = list(sympy.roots(poly, multiple=True))
    else:
        candidates = [sympy.CRootOf(poly, k) for k in range(poly.degree())]
    return _pick(candidates, approx, box)


def algebraic_to_sympy(minpoly, box=None, approx=None):
    """The algebraic number with minimal polynomial ``minpoly`` (rationals ``(p, q)``, low
    degree first) in the rational rectangle ``box`` (or nearest ``approx``)."""
    sympy = _sympy()
    return _root_of(sympy, [_rational(sympy, c) for c in minpoly], approx, box)


class _Ctx:
    def __init__(self, sympy, keep_symbols):
        self.sympy = sympy
        self.keep_symbols = keep_symbols
        self.gens = {}

    def generator(self, gen):
        _, modulus, root, name, radical = gen
        key = (repr(modulus), tuple(root), name, repr(radical))
        if key in self.gens:
            return self.gens[key]
        sympy = self.sympy
        if radical is not None:
            a0, s, f = radical
            g = _rational(sympy, a0) + _rational(sympy, s) * sympy.sqrt(f)
        elif len(modulus) > 3 and self.keep_symbols:
            g = sympy.Symbol(name)
        else:
            g = _root_of(sympy, [self.value(c) for c in modulus], approx=root)
        self.gens[key] = g
        return g

    def value(self, v):
        sympy = self.sympy
        if v is None:
            raise TypeError("no exact value")
        if not isinstance(v[0], str):
            return _rational(sympy, v)
        tag = v[0]
        if tag == "sqrt":
            _, a, b, d = v
            return _rational(sympy, a) + _rational(sympy, b) * sympy.sqrt(d)
        if tag == "i":
            return self.value(v[1]) + sympy.I * self.value(v[2])
        if tag == "ext":
            _, coeffs, gen = v
            if not coeffs:
                return sympy.Integer(0)
            if len(coeffs) == 1:
                return self.value(coeffs[0])
            g = self.generator(gen)
            return sympy.Add(*[self.value(c) * g**k for k, c in enumerate(coeffs)])
        if tag == "rf":
            _, names, num, den = v
            return terms_to_sympy(num, names) / terms_to_sympy(den, names)
        if tag == "root":
            _, minpoly, box = v
            return algebraic_to_sympy(minpoly, box)
        if tag == "re":
            return sympy.re(self.value(v[1]))
        if tag == "im":
            return sympy.im(self.value(v[1]))
        if tag == "neg":
            return -self.value(v[1])
        raise ValueError("unknown exact value %r" % (tag,))


def to_sympy(v, keep_symbols=False):
    """One exact value as SymPy; ``keep_symbols``: a root of degree >= 3 that generates
    its field stays the SymPy symbol of its name (``r3``)."""
    return _Ctx(_sympy(), keep_symbols).value(v)


def grid_to_sympy(rows, keep_symbols=False):
    """Rows of values as a flat list of SymPy values (one context: each generator once)."""
    ctx = _Ctx(_sympy(), keep_symbols)
    return [ctx.value(x) for row in rows for x in row]
