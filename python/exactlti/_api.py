"""Every operation of the command line as a method of :class:`StateSpace`, through the
library's front door (``exactlti::api``): the same code, the same answers, over every
field the command line accepts (Q, Q(i), Q(sqrt d), Q(p1, ..., pk)).

Each method returns a :class:`Report`: the command line's JSON report as Python values
(a ``dict``; exact numbers as exact strings, every ``<key>_approx`` as floats), with
``verified`` (its exact checks passed), ``field`` and ``conditions`` over Q(p); its
matrices' exact values come beside the JSON (``Report.to_sympy``), never parsed from it.
"""

import json
from fractions import Fraction

from . import _core
from ._display import Rendered


class Report(dict, Rendered):
    """The result of one operation: the report's keys and values (a ``dict``).

    ``verified``: every exact check of the operation passed; ``agree``: the float path
    agrees with the exact one (``check``, ERA). ``title`` is the report's title.
    """

    def __init__(self, data, verified, agree=True, op=None, rendered=None, values=None):
        super().__init__(data)
        self._values = values or {}
        self._rendered = rendered
        self.verified = bool(verified)
        self.agree = bool(agree)
        self.op = op

    @property
    def field(self):
        """The field of the computation (``QQ(k, m)``) over symbolic parameters, else None."""
        return self.get("field")

    @property
    def conditions(self):
        """Polynomials the symbolic result assumes nonzero (empty when numeric)."""
        return list(self.get("conditions", []))

    def to_sympy(self, key):
        """The exact matrix under ``key`` as a ``sympy.Matrix``, built from the values the
        library hands over with the report (``_values``), or the exact rational number
        under ``key``; the report's text is for reading and is never parsed back."""
        import sympy

        from ._values import grid_to_sympy

        rows = self._values.get(key)
        if rows is not None:
            nrows = len(rows)
            ncols = len(rows[0]) if nrows else 0
            if any(v is None for r in rows for v in r):
                raise TypeError(
                    "%s: some entries are shown by text only (a compact real form)" % key
                )
            return sympy.Matrix(nrows, ncols, grid_to_sympy(rows))
        v = self[key]
        if isinstance(v, int) and not isinstance(v, bool):
            return sympy.Integer(v)
        if isinstance(v, str):
            try:
                q = Fraction(v)  # a rational literal ("-3/4"), not an expression
            except ValueError:
                pass
            else:
                return sympy.Rational(q.numerator, q.denominator)
        raise TypeError("%s: not an exact matrix or rational number of the report" % key)

    def to_numpy(self, key):
        """The approximation of the matrix or list under ``key`` (``<key>_approx``) as a
        numpy array."""
        import numpy as np

        return np.asarray(self.get(key + "_approx", self[key]), dtype=float)

    def __repr__(self):
        return "Report(%s, verified=%s, keys=%s)" % (
            self.op, self.verified, ", ".join(list(self.keys())[:8])
        )


def _arg(name, value):
    if value is None or value is False:
        return []
    if value is True:
        return ["--" + name]
    return ["--" + name, str(value)]


def run(system, op, *args, max_seconds=None):
    """Runs the command line's operation ``op`` (``"jordan"``, ``"step"``, ...) with its
    options ``args`` (as the command line spells them) on ``system``."""
    args = [str(a) for a in args]
    source, _ = system._core.source
    if op == "linalg":
        argv = [op, args[0], source] + args[1:]
    else:
        argv = [op, source] + args
    text, verified, agree, latex, html, values = system._core.command(argv, max_seconds)
    rendered = {"latex": latex, "html": html}
    return Report(
        json.loads(text), verified, agree, op=" ".join([op] + args), rendered=rendered,
        values=values,
    )


def connect(op, systems, *args, max_seconds=None):
    """Runs the command line's interconnection ``op`` (``"series"``, ``"parallel"``,
    ``"feedback"``, ``"append"``) on ``systems`` in order, with its options ``args``."""
    first, rest = systems[0], systems[1:]
    names = [s._core.source[0] for s in systems]
    argv = [op] + names + [str(a) for a in args]
    text, verified, agree, latex, html, values = first._core.connect(
        argv, [s._core for s in rest], max_seconds
    )
    return Report(
        json.loads(text),
        verified,
        agree,
        op=" ".join([op] + [str(a) for a in args]),
        rendered={"latex": latex, "html": html},
        values=values,
    )


class Operations:
    """Mixin of :class:`StateSpace`: one method per command of the command line."""

    def run(self, op, *args, max_seconds=None):
        """Any operation of the command line by name (``G.run("minreal", "--method",
        "jordan")``): a :class:`Report`."""
        return run(self, op, *args, max_seconds=max_seconds)

    def step(self, to=None, points=None, float=False, max_seconds=None):
        """Step response of every channel (exact closed form from the Jordan form over Q,
        float matrix exponential otherwise) with the exact DC gain."""
        a = _arg("to", to) + _arg("points", points) + _arg("float", float)
        return run(self, "step", *a, max_seconds=max_seconds)

    def impulse(self, to=None, points=None, float=False, max_seconds=None):
        """Impulse response ``C e^(At) B`` of every channel (exact ``C B`` at t = 0)."""
        a = _arg("to", to) + _arg("points", points) + _arg("float", float)
        return run(self, "impulse", *a, max_seconds=max_seconds)

    def pzmap(self, max_seconds=None):
        """Poles (eigenvalues of ``A``) and invariant zeros."""
        return run(self, "pzmap", max_seconds=max_seconds)

    def pencil(self, max_seconds=None):
        """Kronecker structure of the pencil ``A - sE``."""
        return run(self, "pencil", max_seconds=max_seconds)

    def standard(self, max_seconds=None):
        """A descriptor system ``E x' = A x + B u`` in standard form (verified)."""
        return run(self, "standard", max_seconds=max_seconds)

    def analyze(self, section_seconds=None, max_seconds=None):
        """Everything that applies, as one report."""
        return run(self, "analyze", *_arg("section-seconds", section_seconds),
                   max_seconds=max_seconds)

    def bifurcations(self, of="scb", depth=2, max_seconds=None):
        """Structural bifurcations of a symbolic system: the generic result, then the
        result where each condition vanishes."""
        return run(self, "bifurcations", "--of", of, "--depth", depth, max_seconds=max_seconds)

    def era(self, hankel=None, max_seconds=None):
        """The float eigensystem realization, compared with the exact McMillan degree."""
        return run(self, "minreal", "--method", "era", *_arg("hankel", hankel),
                   max_seconds=max_seconds)

    def ctrb_structure(self, max_seconds=None):
        """Controllability indices and staircase (with ``E``: finite and infinite)."""
        return run(self, "ctrb", max_seconds=max_seconds)

    def obsv_structure(self, max_seconds=None):
        """Observability indices and staircase (with ``E``: finite and infinite)."""
        return run(self, "obsv", max_seconds=max_seconds)

    def pzmap_svg(self, path, max_seconds=None):
        """Writes the pole-zero map as SVG to ``path``; the report as :meth:`pzmap`."""
        return run(self, "pzmap", "--svg", path, max_seconds=max_seconds)

    def dcgain(self, max_seconds=None):
        """Exact DC gain ``G(0) = D - C A^-1 B`` per channel (``inf`` at a pole at 0)."""
        return run(self, "dcgain", max_seconds=max_seconds)

    def series(self, other, minreal=False, max_seconds=None):
        """``other`` after ``self`` (python-control's ``series(self, other)``: ``y = H G u``),
        exact; ``minreal=True`` also reduces it."""
        return connect("series", [self, other], *_arg("minreal", minreal),
                       max_seconds=max_seconds)

    def parallel(self, other, minreal=False, max_seconds=None):
        """``self + other`` (same input, outputs added), exact."""
        return connect("parallel", [self, other], *_arg("minreal", minreal),
                       max_seconds=max_seconds)

    def feedback(self, other, positive=False, minreal=False, max_seconds=None):
        """``self`` with ``other`` in the feedback path (negative unless ``positive``),
        exact, python-control's conventions."""
        a = _arg("positive", positive) + _arg("minreal", minreal)
        return connect("feedback", [self, other], *a, max_seconds=max_seconds)

    def append(self, *others, minreal=False, max_seconds=None):
        """The block-diagonal union of ``self`` and ``others`` (inputs and outputs stacked)."""
        return connect("append", [self] + list(others), *_arg("minreal", minreal),
                       max_seconds=max_seconds)

    def sweep(self, param, lo, hi, points=200, max_seconds=None):
        """Eigenvalues along the parameter ``param`` (float), a system read from a file."""
        return run(self, "sweep", "--param", param, "--from", lo, "--to", hi,
                   "--points", points, max_seconds=max_seconds)

    def critical(self, param, lo, hi, digits=20, max_seconds=None):
        """Exact critical values of ``param`` on ``[lo, hi]`` (a system read from a file)."""
        return run(self, "critical", "--param", param, "--from", lo, "--to", hi,
                   "--digits", digits, max_seconds=max_seconds)
